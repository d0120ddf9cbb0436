"""Benchmark: mechverify's modal analysis (10 modes) against CalculiX ``*FREQUENCY``, and its linear buckling
against ``*BUCKLE``, on the same P2 meshes.

Modal: the lug of ``ccx_common.LUG`` (120 x 40 x 30 mm steel block with a 16 mm hole, clamped at x = 0),
meshed by gmsh near the target sizes. For each ``--methods`` entry, in a fresh child process (its peak RSS
includes the interpreter): stiffness and consistent mass assembly, then either one factorisation of K (CHOLMOD,
or SuperLU) driving ARPACK's shift-invert Lanczos, or LOBPCG preconditioned by the static solver's multigrid
(``mechverify.fea.modal.modal(method=...)``). CalculiX: ``ccx`` on the identical deck with ``*DENSITY`` and
``*FREQUENCY`` (10 eigenvalues), wall time and max RSS, with 1 and 2 threads (``--ccx-threads``); the faster
counts. The frequencies are compared mode by mode.

Buckling (``--buckling-dofs``): a 400 x 20 x 20 mm steel column (structured box mesh), clamped at x = 0, 1 kN
compression on its free end; ``mechverify.fea.buckling.buckling`` (one CHOLMOD factorisation, ARPACK in
buckling mode) against ``*BUCKLE`` (3 factors).

Prints a table and writes ``benchmarks/results/fea_modal.json`` after every row. Usage::

    python benchmarks/fea_modal.py [--dofs 50000 200000] [--methods cholmod lobpcg] [--ccx-threads 1 2]
                                   [--buckling-dofs 100000]
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from ccx_common import LUG, RESULTS, load_average, load_mesh, mesh_for, model_of, peak_rss, run_child, save_mesh  # noqa: E402

N_MODES = 10
N_BUCKLING = 3


def child(path: str, method: str) -> None:
    """Modal analysis of the saved mesh in this fresh process; prints timings, peak memory and frequencies."""
    from mechverify.fea import modal

    model = model_of(LUG, load_mesh(path))
    t0, c0 = time.perf_counter(), time.process_time()
    res = modal.modal(model, N_MODES, method=method)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    print(json.dumps({"wall": wall, "cpu": cpu, "peak": peak_rss(), "method": res.method,
                      "iterations": res.iterations, "residual": res.residual, "unknowns": res.unknowns,
                      "frequencies": res.frequencies.m.tolist(), "solver_note": res.solver_note}))


def buckling_child(divisions: str) -> None:
    """Buckling of the column in this fresh process."""
    from mechverify.fea import buckling

    model = column(tuple(int(x) for x in divisions.split(",")))
    t0, c0 = time.perf_counter(), time.process_time()
    res = buckling.buckling(model, N_BUCKLING)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    print(json.dumps({"wall": wall, "cpu": cpu, "peak": peak_rss(), "unknowns": res.unknowns,
                      "factors": res.factors.tolist()}))


def column(divisions: tuple[int, int, int]):
    """The 400 x 20 x 20 mm steel column, clamped at x = 0, 1 kN compression at x = 400 mm."""
    from mechverify.fea import mesh, solid
    from mechverify.fea.loads import Fixed, Force
    from mechverify.fea.regions import Plane

    return solid.SolidModel(mesh.box(("400 mm", "20 mm", "20 mm"), divisions), "Structural Steel",
                            supports=(Fixed(Plane(x="0 mm")),),
                            loads=(Force(Plane(x="400 mm"), ("-1 kN", "0 N", "0 N")),))


def reused(path: str | None, dofs: int, case: str = "modal") -> dict:
    """The CalculiX runs of an earlier results file's row of the same case and DOF count (gmsh meshes the part
    identically for the same size), or {}: to rerun mechverify's side without ccx's long runs."""
    if not path or not Path(path).exists():
        return {}
    for row in json.loads(Path(path).read_text()):
        if row.get("case", "modal") == case and row["dofs"] == dofs:
            return {int(k): dict(v, reused_from=str(path)) for k, v in row["calculix"].items()}
    return {}


def run_case(target: int, methods: list[str], ccx_threads: list[int], reuse: str | None = None) -> dict:
    from mechverify.fea import calculix_eigen

    m = mesh_for(LUG, target)
    model = model_of(LUG, m)
    mine = {}
    with tempfile.TemporaryDirectory(prefix="mv-bench-") as tmp:
        path = os.path.join(tmp, "mesh.npz")
        save_mesh(m, path)
        for method in methods:
            mine[method] = run_child(__file__, path, method)
            mine[method]["load_average"] = load_average()
            print(f"  {method}: {mine[method]['wall']:.1f} s", flush=True)
    ccx = reused(reuse, int(m.n_dofs))
    for threads in ([] if ccx else ccx_threads):
        f, wall, peak = calculix_eigen.frequencies(model, N_MODES, threads=threads, with_memory=True)
        ccx[threads] = {"wall": wall, "cpu": calculix_eigen.last_cpu_seconds, "peak": peak,
                        "frequencies": f.tolist(), "load_average": load_average()}
        print(f"  ccx {threads} thread(s): {wall:.1f} s", flush=True)
    best = min(ccx, key=lambda k: ccx[k]["wall"])
    fc = np.array(ccx[best]["frequencies"])
    row = {"case": "modal", "dofs": int(m.n_dofs), "elements": int(m.mesh.nelements), "modes": N_MODES,
           "mechverify": mine, "calculix": ccx, "ccx_threads": best}
    for r in mine.values():
        r["ratio"] = r["wall"] / ccx[best]["wall"]
        if "cpu" in ccx[best]:
            r["cpu_ratio"] = r["cpu"] / min(c["cpu"] for c in ccx.values() if "cpu" in c)
        r["bytes_per_dof"] = r["peak"] / m.n_dofs
        r["max_frequency_difference"] = float(np.max(np.abs(np.array(r["frequencies"]) - fc) / fc))
    if len(mine) > 1:
        f = [np.array(r["frequencies"]) for r in mine.values()]
        row["methods_agree"] = float(np.max(np.abs(f[1] - f[0]) / f[0]))
    return row


def run_buckling(target: int, ccx_threads: list[int]) -> dict:
    from mechverify.fea import calculix_eigen

    # structured box: (nx+1)(ny+1)(nz+1) vertices + edges: about 3 * 8 * nx * ny * nz P2 unknowns with nx = 20 ny
    ny = max(2, round((target / (3 * 8 * 20)) ** (1 / 3)))
    div = (20 * ny, ny, ny)
    mine = run_child(__file__, "buckling", ",".join(map(str, div)))
    print(f"  buckling: {mine['wall']:.1f} s", flush=True)
    model = column(div)
    ccx = {}
    for threads in ccx_threads:
        mu, wall, peak = calculix_eigen.buckling_factors(model, N_BUCKLING, threads=threads, with_memory=True)
        ccx[threads] = {"wall": wall, "cpu": calculix_eigen.last_cpu_seconds, "peak": peak, "factors": mu.tolist(),
                        "load_average": load_average()}
        print(f"  ccx *BUCKLE {threads} thread(s): {wall:.1f} s", flush=True)
    best = min(ccx, key=lambda k: ccx[k]["wall"])
    fc = np.array(ccx[best]["factors"])
    fm = np.array(mine["factors"])
    return {"case": "buckling", "dofs": mine["unknowns"], "divisions": div, "mechverify": mine, "calculix": ccx,
            "ccx_threads": best, "ratio": mine["wall"] / ccx[best]["wall"],
            "cpu_ratio": mine["cpu"] / min(c["cpu"] for c in ccx.values()),
            "bytes_per_dof": mine["peak"] / mine["unknowns"],
            "max_factor_difference": float(np.max(np.abs(fm - fc) / fc))}


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dofs", type=int, nargs="*", default=[50_000, 200_000])
    ap.add_argument("--methods", nargs="+", default=["cholmod", "lobpcg"],
                    choices=["auto", "cholmod", "superlu", "lobpcg"])
    ap.add_argument("--ccx-threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--buckling-dofs", type=int, nargs="*", default=[])
    ap.add_argument("--out", default=str(RESULTS / "fea_modal.json"))
    ap.add_argument("--reuse-ccx", metavar="JSON", help="take CalculiX's modal runs from this earlier results file "
                    "where it has a row of the same DOF count (mechverify's side rerun only)")
    args = ap.parse_args(argv)
    from ccx_common import write_rows

    rows: list[dict] = []
    for target in args.dofs:
        r = run_case(target, args.methods, args.ccx_threads, args.reuse_ccx)
        rows.append(r)
        write_rows(rows, args.out)
        c = r["calculix"][r["ccx_threads"]]
        for method, x in r["mechverify"].items():
            cpu_ratio = x.get("cpu_ratio", float("nan"))
            print(f"{r['dofs']:>8} DOF  {method:8s} {x['wall']:7.1f} s (cpu {x['cpu']:.1f} s, "
                  f"{x['peak'] / 1e6:.0f} MB, {x['bytes_per_dof'] / 1e3:.1f} kB/DOF, {x['iterations']} it)  ccx "
                  f"{c['wall']:7.1f} s ({r['ccx_threads']} thr, {c['peak'] / 1e6:.0f} MB)  ratio {x['ratio']:.2f} "
                  f"(cpu {cpu_ratio:.2f})  max |df|/f {x['max_frequency_difference']:.1e}", flush=True)
    for target in args.buckling_dofs:
        r = run_buckling(target, args.ccx_threads)
        rows.append(r)
        write_rows(rows, args.out)
        c = r["calculix"][r["ccx_threads"]]
        print(f"{r['dofs']:>8} DOF  buckling {r['mechverify']['wall']:7.1f} s ({r['bytes_per_dof'] / 1e3:.1f} kB/DOF)  "
              f"ccx {c['wall']:7.1f} s ({r['ccx_threads']} thr)  ratio {r['ratio']:.2f}  max |dmu|/mu "
              f"{r['max_factor_difference']:.1e}", flush=True)
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--child":
        if sys.argv[2] == "buckling":
            buckling_child(sys.argv[3])
        else:
            child(sys.argv[2], sys.argv[3])
    else:
        main()
