"""Benchmark: mechverify's solid solver against CalculiX 2.x on the same quadratic-tetrahedron mesh.

A steel lug (120 x 40 x 30 mm block, 16 mm through-hole near the free end) clamped at x = 0 and
pulled down by 5 kN on the hole's wall, meshed by gmsh at about 50k and 200k DOF. Each side runs
in its own process so that peak memory (max RSS) is comparable:

- mechverify: assembly + solve + stress recovery (``SolidModel.solve``), timed inside a child
  Python process; its peak RSS includes the interpreter and libraries (~150 MB).
- CalculiX: the ``ccx`` process on the identical deck (same nodes, C3D10 elements, supports and
  nodal loads), wall time and max RSS via ``wait4``; run with 1 and 2 threads, the faster counts.

Prints a table and writes ``benchmarks/results/fea_vs_calculix.json``. Usage::

    python benchmarks/fea_vs_calculix.py [--dofs 50000 200000] [--baseline]
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


def lug_mesh(h: float):
    """gmsh mesh of the lug with element size ``h`` [m]; named regions ``clamp`` and ``hole``."""
    from mechverify.fea import mesh

    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        block = occ.addBox(0, 0, 0, 0.12, 0.04, 0.03)
        hole = occ.addCylinder(0.1, 0.02, -0.01, 0, 0, 0.05, 0.008)
        occ.cut([(3, block)], [(3, hole)])
        occ.synchronize()
        clamp, wall = [], []
        for _, tag in gmsh.model.getEntities(2):
            com = occ.getCenterOfMass(2, tag)
            if abs(com[0]) < 1e-9:
                clamp.append(tag)
            elif abs(com[0] - 0.1) < 1e-6 and abs(com[1] - 0.02) < 1e-6:
                wall.append(tag)
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, clamp), "clamp")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, wall), "hole")
        gmsh.model.addPhysicalGroup(3, [e[1] for e in gmsh.model.getEntities(3)])
        gmsh.model.mesh.generate(3)
        return mesh.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def model_of(m):
    from mechverify.fea.loads import Fixed, Force
    from mechverify.fea.regions import Named
    from mechverify.fea.solid import SolidModel

    return SolidModel(m, "Structural Steel", supports=(Fixed(Named("clamp")),),
                      loads=(Force(Named("hole"), ("0 N", "0 N", "-5 kN")),))


def mesh_for(target: int):
    """Mesh whose DOF count is near ``target`` (one size correction after a first try)."""
    h = 0.12 * (target / 3.0 / 4.0) ** (-1 / 3) * 0.9
    for _ in range(4):
        m = lug_mesh(h)
        ratio = m.n_dofs / target
        if abs(ratio - 1) < 0.08:
            break
        h *= ratio ** (1 / 3)
    return m


def child(path: str) -> None:
    """Solve the saved mesh in this fresh process and print timings and peak memory as JSON."""
    from mechverify.fea import mesh

    data = np.load(path, allow_pickle=False)
    named = {k[6:]: data[k] for k in data.files if k.startswith("named_")}
    m = mesh.from_arrays(data["points"], data["tets"], named)
    model = model_of(m)
    _ = m.basis  # P2 numbering is mesh bookkeeping shared with the writer of the ccx deck
    t0 = time.perf_counter()
    res = model.solve(progress=False)
    wall = time.perf_counter() - t0
    np.save(path + ".u.npy", res.u)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"wall": wall, "peak": peak, "timings": dict(res.timings), "iterations": res.info.iterations,
                      "method": res.info.method, "max_vm": float(res.max_von_mises.value.m_as("MPa"))}))


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
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"wall": wall, "peak": peak}))


def run_case(target: int, baseline: bool = False) -> dict:
    from mechverify.fea import calculix

    m = mesh_for(target)
    model = model_of(m)
    with tempfile.TemporaryDirectory(prefix="mv-bench-") as tmp:
        path = os.path.join(tmp, "mesh.npz")
        np.savez(path, points=m.mesh.p.T, tets=m.mesh.t.T, **{f"named_{k}": v for k, v in m.named.items()})
        out = subprocess.run([sys.executable, __file__, "--child", path], capture_output=True, text=True, check=True)
        mine = json.loads(out.stdout.strip().splitlines()[-1])
        u = np.load(path + ".u.npy")
        base = None
        if baseline:
            out = subprocess.run([sys.executable, __file__, "--baseline-child", path], capture_output=True,
                                 text=True, check=True)
            base = json.loads(out.stdout.strip().splitlines()[-1])
    ccx = {}
    for threads in (1, 2):
        r = calculix.run_model(model, threads=threads)
        ccx[threads] = {"wall": r.wall_time, "peak": r.peak_memory}
        err = float(np.abs(r.displacement - u).max() / np.abs(u).max())
    best = min(ccx, key=lambda k: ccx[k]["wall"])
    return {"dofs": m.n_dofs, "elements": m.mesh.nelements, "mechverify": mine, "calculix": ccx,
            "ratio": mine["wall"] / ccx[best]["wall"], "memory_ratio": mine["peak"] / ccx[best]["peak"],
            "ccx_threads": best, "max_displacement_difference": err, "plain_scikit_fem": base}


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dofs", type=int, nargs="*", default=[50_000, 200_000])
    ap.add_argument("--baseline", action="store_true",
                    help="also time plain scikit-fem + SciPy direct on the smallest mesh")
    ap.add_argument("--child")
    ap.add_argument("--baseline-child")
    args = ap.parse_args(argv)
    if args.child:
        child(args.child)
        return []
    if args.baseline_child:
        baseline_child(args.baseline_child)
        return []
    rows = [run_case(t, args.baseline and i == 0) for i, t in enumerate(args.dofs)]
    print(f"{'DOF':>8} {'mechverify s':>13} {'ccx s (thr)':>12} {'ratio':>6} {'mv MB':>7} {'ccx MB':>7}  iters")
    for r in rows:
        c = r["calculix"][r["ccx_threads"]]
        print(f"{r['dofs']:>8} {r['mechverify']['wall']:>13.2f} {c['wall']:>9.2f} ({r['ccx_threads']}) "
              f"{r['ratio']:>6.2f} {r['mechverify']['peak'] / 1e6:>7.0f} {c['peak'] / 1e6:>7.0f}  "
              f"{r['mechverify']['iterations']}")
        if r.get("plain_scikit_fem"):
            b = r["plain_scikit_fem"]
            print(f"{'':>8} plain scikit-fem + SciPy direct: {b['wall']:.2f} s, {b['peak'] / 1e6:.0f} MB "
                  f"(ratio to CalculiX {b['wall'] / c['wall']:.2f})")
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    (out / "fea_vs_calculix.json").write_text(json.dumps(rows, indent=2, default=str))
    return rows


if __name__ == "__main__":
    main()
