"""Verification table: mechverify's plane and solid models on published linear-elasticity benchmarks,
on mesh sequences, straight-sided and curved elements on the same gmsh second-order mesh, each stress
recovery, and CalculiX 2.20 on the same mesh (same nodes, loads and supports; its nodal stress by
extrapolate-and-average).

Benchmarks (models and sources in :mod:`mechverify.fea.verification`):

- Kirsch: hole in a plate with the exact tractions of Kirsch's solution, σxx = 3σ at the top of the hole
  (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., sec. 35);
- Lamé: thick cylinder under internal pressure, plane strain, σθ at the bore (Shigley 10th ed., eq. 3-50);
- NAFEMS LE1: elliptic membrane, σyy at D = 92.7 MPa (NAFEMS TNSB Rev. 3, 1990);
- Lamé ring: the Lamé cylinder as a quarter ring of quadratic tetrahedra (3D).

Writes ``benchmarks/results/verification.json`` and the table between the markers of
``docs/verification.md``. Usage::

    python benchmarks/verification.py [--quick]
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from mechverify.fea import calculix  # noqa: E402
from mechverify.fea import verification as V  # noqa: E402

BEGIN, END = "<!-- verification table: begin (benchmarks/verification.py) -->", "<!-- verification table: end -->"


def _ccx_value(model, point, component):
    """CalculiX's nodal stress (extrapolate-and-average) at the node nearest ``point``, and its run time."""
    if shutil.which("ccx") is None:
        return None, None
    t0 = time.perf_counter()
    out = calculix.run_model(model)
    wall = time.perf_counter() - t0
    X = model.nodes.T
    k = int(np.argmin(np.linalg.norm(X - np.asarray(point)[: X.shape[1]], axis=1)))
    s = out.stress[k]  # xx yy zz xy yz zx
    T = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
    return component(T), wall


def run_case(name, model, point, component, reference, h):
    """One mesh: curved and straight elements (same mesh), SPR and average, and CalculiX."""
    rows = []
    variants = [("curved", model), ("straight", replace(model, curved=False))]
    for geom, mdl in variants:
        dofs = int(mdl.basis.N * 2) if hasattr(mdl, "plane") else int(mdl.mesh.n_dofs)
        row = {"benchmark": name, "h_mm": h * 1e3, "elements": geom, "dofs": dofs}
        for rec in ("spr", "average"):
            t0 = time.perf_counter()
            res = mdl.solve(recovery=rec)
            row[f"time_{rec}_s"] = time.perf_counter() - t0
            v = component(res.stress_at([point]).m_as("Pa")[0])
            row[f"{rec}_MPa"] = v / 1e6
            row[f"{rec}_err_pct"] = 100 * (v / reference - 1)
            row["zz_pct"] = 100 * res.error_estimate
        v, wall = _ccx_value(mdl, point, component)
        if v is not None:
            row["ccx_MPa"], row["ccx_err_pct"], row["ccx_time_s"] = v / 1e6, 100 * (v / reference - 1), wall
        rows.append(row)
        print(f"{name:10s} h={h * 1e3:7.3f} mm {geom:8s} dofs={row['dofs']:7d} SPR {row['spr_err_pct']:+.3f} % "
              f"avg {row['average_err_pct']:+.3f} % ccx {row.get('ccx_err_pct', float('nan')):+.3f} % "
              f"ZZ {row['zz_pct']:.3f} % {row['time_spr_s']:.2f} s", flush=True)
    return rows


def cases(quick: bool):
    k = [(0.01, 0.002), (0.005, 0.001)] + ([] if quick else [(0.0025, 0.0005)])
    lm = [0.004, 0.002] + ([] if quick else [0.001])
    le = [(0.3, 0.1), (0.15, 0.05)] + ([] if quick else [(0.075, 0.025)])
    ring = [0.006] + ([] if quick else [0.004, 0.003])
    for h, hh in k:
        b = V.kirsch(h, hh, order=2)
        yield "Kirsch", b.model, b.point, b.component, b.reference, hh
    for h in lm:
        b = V.lame(h, order=2)
        yield "Lamé", b.model, b.point, b.component, b.reference, h
    for h, hh in le:
        b = V.le1(h, hh, order=2)
        yield "NAFEMS LE1", b.model, b.point, b.component, b.reference, hh
    for h in ring:
        model, hoop = V.lame_solid(h)
        yield "Lamé ring (3D)", model, (0.02, 0.0, 0.005), (lambda s: s[1, 1]), hoop, h


def table(rows):
    head = ("| benchmark | h at the peak [mm] | elements | DOF | SPR error | average error | CalculiX (same mesh) "
            "| ZZ estimate | time (SPR) |\n|---|---|---|---|---|---|---|---|---|\n")
    body = "".join(
        f"| {r['benchmark']} | {r['h_mm']:g} | {r['elements']} | {r['dofs']} | {r['spr_err_pct']:+.3f} % | "
        f"{r['average_err_pct']:+.3f} % | {r.get('ccx_err_pct', float('nan')):+.3f} % | {r['zz_pct']:.3f} % | "
        f"{r['time_spr_s']:.2f} s |\n" for r in rows)
    return head + body


def main(argv: list[str]) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="two meshes per benchmark")
    args = ap.parse_args(argv)
    rows = []
    for case in cases(args.quick):
        rows += run_case(*case)
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    (out / "verification.json").write_text(json.dumps(rows, indent=2))
    doc = ROOT / "docs" / "verification.md"
    text = doc.read_text()
    if BEGIN in text and END in text:
        pre, rest = text.split(BEGIN, 1)
        _, post = rest.split(END, 1)
        doc.write_text(pre + BEGIN + "\n" + table(rows) + END + post)
    print(table(rows))


if __name__ == "__main__":
    main(sys.argv[1:])
