"""Benchmark: mechverify's modal analysis (10 modes) against CalculiX ``*FREQUENCY`` on the same P2 mesh.

The lug of ``fea_vs_calculix.py`` (120 x 40 x 30 mm steel block with a 16 mm hole, clamped at x = 0),
meshed by gmsh near the target sizes. mechverify: stiffness and consistent mass assembly, one factorisation
of K (CHOLMOD when scikit-sparse is installed, else SuperLU: ``--method``), ARPACK shift-invert Lanczos
(``mechverify.fea.modal.modal``), timed in a child process (its peak RSS includes the interpreter).
CalculiX: ``ccx`` on the identical deck with ``*DENSITY`` and ``*FREQUENCY`` (10 eigenvalues), wall time
and max RSS; run with 1 and/or 2 threads (``--ccx-threads``), the faster counts. The frequencies of the
two are compared mode by mode.

Prints a table and writes ``benchmarks/results/fea_modal.json``. Usage::

    python benchmarks/fea_modal.py [--dofs 50000 200000] [--method auto] [--ccx-threads 1 2]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
N_MODES = 10


def child(path: str, method: str) -> None:
    """Modal analysis of the saved mesh in this fresh process; prints timings, peak memory and frequencies."""
    from fea_vs_calculix import model_of

    from mechverify.fea import mesh, modal

    data = np.load(path, allow_pickle=False)
    named = {k[6:]: data[k] for k in data.files if k.startswith("named_")}
    m = mesh.from_arrays(data["points"], data["tets"], named)
    model = model_of(m)
    _ = m.basis
    t0 = time.perf_counter()
    res = modal.modal(model, N_MODES, method=method)
    wall = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    from mechverify.fea.factor import cholmod_available

    used = method if method != "auto" else ("cholmod" if cholmod_available() else "superlu")
    print(json.dumps({"wall": wall, "peak": peak, "method": used, "frequencies": res.frequencies.m.tolist()}))


def run_case(target: int, method: str, ccx_threads: list[int]) -> dict:
    from fea_vs_calculix import mesh_for, model_of

    from mechverify.fea import calculix_eigen

    m = mesh_for(target)
    model = model_of(m)
    with tempfile.TemporaryDirectory(prefix="mv-bench-") as tmp:
        path = os.path.join(tmp, "mesh.npz")
        np.savez(path, points=m.mesh.p.T, tets=m.mesh.t.T, **{f"named_{k}": v for k, v in m.named.items()})
        out = subprocess.run([sys.executable, __file__, "--child", path, method], capture_output=True, text=True,
                             check=True)
        mine = json.loads(out.stdout.strip().splitlines()[-1])
    ccx = {}
    for threads in ccx_threads:
        f, wall = calculix_eigen.frequencies(model, N_MODES, threads=threads)
        ccx[threads] = {"wall": wall, "frequencies": f.tolist()}
    best = min(ccx, key=lambda k: ccx[k]["wall"])
    fm, fc = np.array(mine["frequencies"]), np.array(ccx[best]["frequencies"])
    return {"dofs": int(m.n_dofs), "elements": int(m.mesh.nelements), "modes": N_MODES, "mechverify": mine,
            "calculix": ccx, "ccx_threads": best, "ratio": mine["wall"] / ccx[best]["wall"],
            "max_frequency_difference": float(np.max(np.abs(fm - fc) / fc)),
            "load_average": os.getloadavg()[0]}


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dofs", type=int, nargs="+", default=[50_000, 200_000])
    ap.add_argument("--method", default="auto", choices=["auto", "cholmod", "superlu"])
    ap.add_argument("--ccx-threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--out", default=str(HERE / "results" / "fea_modal.json"))
    args = ap.parse_args(argv)
    rows = []
    for target in args.dofs:
        r = run_case(target, args.method, args.ccx_threads)
        rows.append(r)
        print(f"{r['dofs']:>8} DOF  mechverify {r['mechverify']['wall']:7.1f} s ({r['mechverify']['method']}, "
              f"{r['mechverify']['peak'] / 1e6:.0f} MB)  ccx {r['calculix'][r['ccx_threads']]['wall']:7.1f} s "
              f"({r['ccx_threads']} thr)  ratio {r['ratio']:.2f}  max |df|/f {r['max_frequency_difference']:.1e}  "
              f"load {r['load_average']:.1f}", flush=True)
    Path(args.out).write_text(json.dumps(rows, indent=2))
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(sys.argv[2], sys.argv[3])
    else:
        main()
