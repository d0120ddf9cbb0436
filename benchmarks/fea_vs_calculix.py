"""Benchmark: mechverify's solid solver against CalculiX 2.x on the same quadratic-tetrahedron mesh.

A steel lug (120 x 40 x 30 mm block, 16 mm through-hole near the free end) clamped at x = 0 and
pulled down by 5 kN on the hole's wall, meshed by gmsh at about 50k and 200k DOF. Each side runs
in its own process so that peak memory (max RSS) is comparable:

- mechverify: assembly + solve + stress recovery (``SolidModel.solve``), timed inside a child
  Python process; its peak RSS includes the interpreter and libraries (~150 MB).
- CalculiX: the ``ccx`` process on the identical deck (same nodes, C3D10 elements, supports and
  nodal loads), wall time and max RSS via ``wait4``; run with 1 and 2 threads, the faster counts.

Prints a table and writes ``benchmarks/results/fea_vs_calculix.json``. Usage::

    python benchmarks/fea_vs_calculix.py [--dofs 50000 200000] [--baseline] [--method auto|amg|direct]
        [--ccx-threads 1 2] [--repeat 3] [--out path.json]

``--repeat k`` runs each side k times and keeps the least CPU time (the box is shared: CPU time is the steadier
figure). Each row records the mesh (gmsh's CPU time, slivers repaired, worst tetrahedron quality).

Meshes, models and the CalculiX runs come from ``ccx_common.py`` (shared with the other FEA benchmarks).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from ccx_common import (  # noqa: E402
    LUG,
    ccx_static,
    load_average,
    load_mesh,
    peak_rss,
    run_child,
    save_mesh,
    sized_mesh,
    write_rows,
)
from ccx_common import mesh_for as part_mesh_for  # noqa: E402
from ccx_common import model_of as part_model_of  # noqa: E402


def model_of(m):
    """The lug's static model (kept for ``fea_modal.py``)."""
    return part_model_of(LUG, m)


def mesh_for(target: int):
    """Lug mesh whose DOF count is near ``target`` (kept for ``fea_modal.py``)."""
    return part_mesh_for(LUG, target)


def child(path: str, method: str = "auto") -> None:
    """Solve the saved mesh in this fresh process and print timings and peak memory as JSON."""
    m = load_mesh(path)
    model = model_of(m)
    t0, c0 = time.perf_counter(), time.process_time()
    res = model.solve(method=method, progress=False)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    np.save(path + ".u.npy", res.u)
    print(json.dumps({"wall": wall, "cpu": cpu, "peak": peak_rss(), "timings": dict(res.timings),
                      "iterations": res.info.iterations, "method": res.info.method,
                      "max_vm": float(res.max_von_mises.value.m_as("MPa"))}))


def baseline_child(path: str) -> None:
    """Plain scikit-fem on the same mesh (generic vector P2 assembly, SciPy direct solve, projection of
    von Mises): the starting point this work was measured against."""
    from scipy.sparse.linalg import spsolve
    from skfem import Basis, ElementTetP2, ElementVector, MeshTet, asm, condense, solve
    from skfem.helpers import ddot, sym_grad, trace
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    data = np.load(path, allow_pickle=False)
    t0 = time.perf_counter()
    m = MeshTet(data["points"].T, data["tets"].T)
    ib = Basis(m, ElementVector(ElementTetP2()))
    lam, mu = lame_parameters(200e9, 0.3)
    K = asm(linear_elasticity(lam, mu), ib)
    clamp = ib.get_dofs(lambda X: np.isclose(X[0], 0.0)).all()
    f = np.zeros(K.shape[0])
    zdofs = ib.get_dofs(lambda X: np.isclose(np.hypot(X[0] - 0.1, X[1] - 0.02), 0.008, rtol=0.05)).all("u^3")
    f[zdofs] = -5000.0 / max(len(zdofs), 1)  # a load of the same size; the timing is what matters
    u = solve(*condense(K, f, D=clamp), solver=spsolve)
    sb = ib.with_element(ElementTetP2())
    from skfem import BilinearForm, LinearForm

    @LinearForm
    def vm_rhs(v, w):
        e = sym_grad(w["u"])
        s = 2 * mu * e + lam * trace(e) * np.eye(3)[:, :, None, None] * 1.0
        dev = s - trace(s) / 3 * np.eye(3)[:, :, None, None]
        return np.sqrt(1.5 * ddot(dev, dev)) * v

    @BilinearForm
    def mass(a, b, w):
        return a * b

    M = asm(mass, sb)
    rhs = asm(vm_rhs, sb, u=ib.interpolate(u))
    solve(M, rhs)
    wall = time.perf_counter() - t0
    print(json.dumps({"wall": wall, "peak": peak_rss()}))


def least_cpu(runs: list[dict]) -> dict:
    """The run with the least CPU time, with every run's CPU and wall seconds beside it."""
    best = dict(min(runs, key=lambda r: r["cpu"]))
    best["all_cpu"], best["all_wall"] = [r["cpu"] for r in runs], [r["wall"] for r in runs]
    return best


def run_case(target: int, baseline: bool = False, method: str = "auto", threads: tuple[int, ...] = (1, 2),
             repeat: int = 1) -> dict:
    m, mesh_info = sized_mesh(LUG, target)
    model = model_of(m)
    with tempfile.TemporaryDirectory(prefix="mv-bench-") as tmp:
        path = os.path.join(tmp, "mesh.npz")
        save_mesh(m, path)
        mine = least_cpu([run_child(__file__, path, method) for _ in range(repeat)])
        u = np.load(path + ".u.npy")
        base = None
        if baseline:
            out = subprocess.run([sys.executable, __file__, "--baseline-child", path], capture_output=True,
                                 text=True, check=True)
            base = json.loads(out.stdout.strip().splitlines()[-1])
    runs = [ccx_static(model, list(threads), u) for _ in range(repeat)]
    ccx = runs[0]
    for t in threads:  # each thread count's least-CPU run
        ccx["calculix"][t] = least_cpu([r["calculix"][t] for r in runs])
    best = min(threads, key=lambda t: ccx["calculix"][t]["wall"])
    return {"dofs": m.n_dofs, "elements": m.mesh.nelements, "mesh": mesh_info, "mechverify": mine,
            "calculix": ccx["calculix"], "ratio": mine["wall"] / ccx["calculix"][best]["wall"],
            "cpu_ratio": mine["cpu"] / min(r["cpu"] for r in ccx["calculix"].values()),
            "memory_ratio": mine["peak"] / ccx["calculix"][best]["peak"], "repeat": repeat,
            "ccx_threads": best, "max_displacement_difference": ccx["max_displacement_difference"],
            "plain_scikit_fem": base, "load_average": load_average()}


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dofs", type=int, nargs="*", default=[50_000, 200_000])
    ap.add_argument("--baseline", action="store_true",
                    help="also time plain scikit-fem + SciPy direct on the smallest mesh")
    ap.add_argument("--method", default="auto", choices=["auto", "amg", "direct"])
    ap.add_argument("--ccx-threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--out", default=str(HERE / "results" / "fea_vs_calculix.json"))
    ap.add_argument("--repeat", type=int, default=1, help="runs of each side; the least CPU time counts")
    ap.add_argument("--baseline-child")
    args = ap.parse_args(argv)
    if args.baseline_child:
        baseline_child(args.baseline_child)
        return []
    rows = []
    for i, t in enumerate(args.dofs):
        rows.append(run_case(t, args.baseline and i == 0, args.method, tuple(args.ccx_threads), args.repeat))
        write_rows(rows, args.out)
    print(f"{'DOF':>8} {'mechverify s':>13} {'ccx s (thr)':>12} {'ratio':>6} {'CPU':>5} {'mv MB':>7} {'ccx MB':>7}  "
          "iters  load")
    for r in rows:
        c = r["calculix"][r["ccx_threads"]]
        print(f"{r['dofs']:>8} {r['mechverify']['wall']:>13.2f} {c['wall']:>9.2f} ({r['ccx_threads']}) "
              f"{r['ratio']:>6.2f} {r['cpu_ratio']:>5.2f} {r['mechverify']['peak'] / 1e6:>7.0f} "
              f"{c['peak'] / 1e6:>7.0f}  "
              f"{r['mechverify']['iterations']:>5}  {r['load_average']:.1f}")
        if r.get("plain_scikit_fem"):
            b = r["plain_scikit_fem"]
            print(f"{'':>8} plain scikit-fem + SciPy direct: {b['wall']:.2f} s, {b['peak'] / 1e6:.0f} MB "
                  f"(ratio to CalculiX {b['wall'] / c['wall']:.2f})")
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(*sys.argv[2:4])
    else:
        main()
