"""Benchmark: a thin plate with a hole (the slow case of multigrid CG) against CalculiX on the same P2 mesh.

A 6 mm steel plate, 200 x 100 mm, 20 mm hole centred at (150, 50) mm, clamped at x = 0 and bent by 500 N
along -z on the hole's wall, meshed by gmsh at several sizes (about 34k to 550k DOF: ``--dofs``).
mechverify: ``SolidModel.solve()`` with ``method="auto"`` (CG on the p-multigrid; with CHOLMOD installed a CG
whose measured convergence predicts more than 80 iterations gives way to a factorisation), timed in a child
process; CalculiX: ``ccx`` on the identical deck, 1 and/or 2 threads (``--ccx-threads``), the faster counts.
Also reported: the same solve with ``method="amg"`` forced (iterations) when ``--amg`` is given.

Prints a table and writes ``benchmarks/results/fea_thin_plate.json``. Usage::

    python benchmarks/fea_thin_plate.py [--dofs 34000 74000 200000 550000] [--ccx-threads 1 2] [--amg]
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


def plate_mesh(h: float):
    from mechverify.fea import mesh

    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        block = occ.addBox(0, 0, 0, 0.2, 0.1, 0.006)
        hole = occ.addCylinder(0.15, 0.05, -0.01, 0, 0, 0.03, 0.01)
        occ.cut([(3, block)], [(3, hole)])
        occ.synchronize()
        clamp, wall = [], []
        for _, tag in gmsh.model.getEntities(2):
            com = occ.getCenterOfMass(2, tag)
            if abs(com[0]) < 1e-9:
                clamp.append(tag)
            elif abs(com[0] - 0.15) < 1e-6 and abs(com[1] - 0.05) < 1e-6:
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
                      loads=(Force(Named("hole"), ("0 N", "0 N", "-500 N")),))


def mesh_for(target: int):
    h = (0.2 * 0.1 * 0.006 * 40 / target) ** (1 / 3)
    for _ in range(4):
        m = plate_mesh(h)
        ratio = m.n_dofs / target
        if abs(ratio - 1) < 0.1:
            break
        h *= ratio ** (1 / 3)
    return m


def child(path: str, method: str) -> None:
    from mechverify.fea import mesh

    data = np.load(path, allow_pickle=False)
    named = {k[6:]: data[k] for k in data.files if k.startswith("named_")}
    m = mesh.from_arrays(data["points"], data["tets"], named)
    model = model_of(m)
    _ = m.basis
    t0 = time.perf_counter()
    res = model.solve(method=method, progress=False)
    wall = time.perf_counter() - t0
    np.save(path + ".u.npy", res.u)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"wall": wall, "peak": peak, "timings": dict(res.timings), "iterations": res.info.iterations,
                      "method": res.info.method}))


def run_case(target: int, ccx_threads: list[int], amg: bool) -> dict:
    from mechverify.fea import calculix

    m = mesh_for(target)
    model = model_of(m)
    out: dict = {"dofs": int(m.n_dofs), "elements": int(m.mesh.nelements)}
    with tempfile.TemporaryDirectory(prefix="mv-bench-") as tmp:
        path = os.path.join(tmp, "mesh.npz")
        np.savez(path, points=m.mesh.p.T, tets=m.mesh.t.T, **{f"named_{k}": v for k, v in m.named.items()})
        for method in ("auto", "amg") if amg else ("auto",):
            r = subprocess.run([sys.executable, __file__, "--child", path, method], capture_output=True, text=True,
                               check=True)
            out[f"mechverify_{method}"] = json.loads(r.stdout.strip().splitlines()[-1])
        u = np.load(path + ".u.npy")
    ccx = {}
    for threads in ccx_threads:
        r = calculix.run_model(model, threads=threads)
        ccx[threads] = {"wall": r.wall_time, "peak": r.peak_memory}
        out["max_displacement_difference"] = float(np.abs(r.displacement - u).max() / np.abs(u).max())
    best = min(ccx, key=lambda k: ccx[k]["wall"])
    out.update(calculix=ccx, ccx_threads=best, ratio=out["mechverify_auto"]["wall"] / ccx[best]["wall"],
               memory_ratio=out["mechverify_auto"]["peak"] / ccx[best]["peak"], load_average=os.getloadavg()[0])
    return out


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dofs", type=int, nargs="+", default=[34_000, 74_000, 200_000, 550_000])
    ap.add_argument("--ccx-threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--amg", action="store_true")
    ap.add_argument("--out", default=str(HERE / "results" / "fea_thin_plate.json"))
    a = ap.parse_args(argv)
    rows = []
    for t in a.dofs:
        r = run_case(t, a.ccx_threads, a.amg)
        rows.append(r)
        mv = r["mechverify_auto"]
        extra = f"  (amg forced: {r['mechverify_amg']['wall']:.1f} s, {r['mechverify_amg']['iterations']} it)" \
            if a.amg else ""
        print(f"{r['dofs']:>8} DOF  mechverify {mv['wall']:6.1f} s [{mv['method']}, {mv['iterations']} it, "
              f"{mv['peak'] / 1e6:.0f} MB]  ccx {r['calculix'][r['ccx_threads']]['wall']:6.1f} s  ratio "
              f"{r['ratio']:.2f}  |du|/|u| {r['max_displacement_difference']:.1e}  load {r['load_average']:.1f}"
              + extra, flush=True)
        Path(a.out).write_text(json.dumps(rows, indent=2, default=str))
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(sys.argv[2], sys.argv[3])
    else:
        main()
