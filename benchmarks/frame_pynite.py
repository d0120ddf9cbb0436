"""Frame solver against PyNite on a generated space frame (issue 28).

A multi-storey space frame — ``nx × ny`` columns per storey, ``nz`` storeys, beams along x and y on
every floor, fixed column bases — with a uniform load on every beam (global -Z) and a lateral load
at every roof node, built and solved once by ``mechverify.fea.frame`` (``Frame`` + ``solve``) and
once by PyNite (``FEModel3D`` + ``analyze_linear``). Square hollow sections (Iy = Iz) make the
result independent of each program's local-axis convention; Euler-Bernoulli members (PyNite has no
shear deformation). The two runs' node displacements and support reactions are compared.

PyNite (``PyNiteFEA`` from PyPI) is **not** a project dependency: it runs in its own virtual
environment, given with ``--pynite-python`` (default ``benchmarks/.venv-pynite/bin/python``, then
``/tmp/venv-pynite/bin/python``); create it with
``python -m venv benchmarks/.venv-pynite && benchmarks/.venv-pynite/bin/pip install PyNiteFEA``.

Usage: ``python benchmarks/frame_pynite.py [--size 16 16 16] [--pynite-python PATH]``; results in
``benchmarks/results/frame_pynite.json``.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
E, NU = 200e9, 0.3
G = E / (2 * (1 + NU))
BAY, STOREY = 4.0, 3.0
# a 200 x 200 x 8 mm square hollow section (thin-wall values, both axes equal)
B, T = 0.2, 0.008
A = B**2 - (B - 2 * T) ** 2
I = (B**4 - (B - 2 * T) ** 4) / 12
J = (B - T) ** 3 * T  # Bredt: 4 A_m^2 t / perimeter = (B-T)^3 t
W = 10e3  # N/m on every beam
H = 5e3  # N at every roof node, along x


def spec(nx: int, ny: int, nz: int) -> dict:
    nodes = {f"N{i}_{j}_{k}": (i * BAY, j * BAY, k * STOREY) for k in range(nz + 1) for j in range(ny)
             for i in range(nx)}
    members = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                members.append((f"C{i}_{j}_{k}", f"N{i}_{j}_{k}", f"N{i}_{j}_{k + 1}"))
    beams = []
    for k in range(1, nz + 1):
        for j in range(ny):
            for i in range(nx):
                if i + 1 < nx:
                    beams.append((f"BX{i}_{j}_{k}", f"N{i}_{j}_{k}", f"N{i + 1}_{j}_{k}"))
                if j + 1 < ny:
                    beams.append((f"BY{i}_{j}_{k}", f"N{i}_{j}_{k}", f"N{i}_{j + 1}_{k}"))
    supports = [f"N{i}_{j}_0" for j in range(ny) for i in range(nx)]
    roof = [f"N{i}_{j}_{nz}" for j in range(ny) for i in range(nx)]
    return {"nodes": nodes, "members": members + beams, "beams": [b[0] for b in beams], "supports": supports,
            "roof": roof, "unknowns": 6 * (len(nodes) - len(supports))}


PYNITE = r'''
import json, sys, time
import numpy as np
from Pynite import FEModel3D
s = json.load(open(sys.argv[1]))
c = s["constants"]
t0 = time.perf_counter()
m = FEModel3D()
for n, (x, y, z) in s["nodes"].items():
    m.add_node(n, x, y, z)
m.add_material("steel", c["E"], c["G"], c["nu"], 7850.0)
m.add_section("shs", c["A"], c["I"], c["I"], c["J"])
for name, i, j in s["members"]:
    m.add_member(name, i, j, "steel", "shs")
for n in s["supports"]:
    m.def_support(n, True, True, True, True, True, True)
for b in s["beams"]:
    m.add_member_dist_load(b, "FZ", -c["W"], -c["W"])
for n in s["roof"]:
    m.add_node_load(n, "FX", c["H"])
t1 = time.perf_counter()
m.analyze_linear(check_stability=False, check_statics=False)
t2 = time.perf_counter()
disp = {n: [m.nodes[n].DX["Combo 1"], m.nodes[n].DY["Combo 1"], m.nodes[n].DZ["Combo 1"],
            m.nodes[n].RX["Combo 1"], m.nodes[n].RY["Combo 1"], m.nodes[n].RZ["Combo 1"]] for n in s["nodes"]}
rxn = {n: [m.nodes[n].RxnFX["Combo 1"], m.nodes[n].RxnFY["Combo 1"], m.nodes[n].RxnFZ["Combo 1"],
           m.nodes[n].RxnMX["Combo 1"], m.nodes[n].RxnMY["Combo 1"], m.nodes[n].RxnMZ["Combo 1"]]
       for n in s["supports"]}
json.dump({"build": t1 - t0, "analyse": t2 - t1, "total": t2 - t0, "disp": disp, "rxn": rxn}, open(sys.argv[2], "w"))
'''


def run_mechverify(s: dict) -> dict:
    from mechverify.fea.frame import (
        DistributedLoad,
        Frame,
        FramePointLoad,
        FrameSupport,
        Member,
        section_from_properties,
    )
    from mechverify.materials.material import Material
    from mechverify.units import Q

    t0 = time.perf_counter()
    steel = Material("steel", "steel", E=Q(E, "Pa"), G=Q(G, "Pa"), nu=Q(NU, ""), density=Q(7850.0, "kg/m**3"))
    sec = section_from_properties(Q(A, "m**2"), Q(I, "m**4"), Q(I, "m**4"), Q(J, "m**4"), c_y=Q(B / 2, "m"),
                                  c_z=Q(B / 2, "m"))
    nodes = {n: Q(np.array(p), "m") for n, p in s["nodes"].items()}
    members = [Member(i, j, sec, steel, name) for name, i, j in s["members"]]
    fr = Frame(nodes, members, [FrameSupport(n) for n in s["supports"]], theory="euler")
    w, h = Q(np.array([0.0, 0.0, -W]), "N/m"), Q(np.array([H, 0.0, 0.0]), "N")
    loads = [DistributedLoad(b, w) for b in s["beams"]] + [FramePointLoad(n, force=h) for n in s["roof"]]
    t1 = time.perf_counter()
    res = fr.solve(loads, progress=False)
    t2 = time.perf_counter()
    disp = {n: np.concatenate((res.displacement(n).m_as("m"), res.rotation(n).m_as("rad"))) for n in s["nodes"]}
    reactions = res.reactions
    rxn = {n: np.concatenate([v.m_as(u) for v, u in zip(reactions[n], ("N", "N*m"), strict=True)])
           for n in s["supports"]}
    return {"build": t1 - t0, "analyse": t2 - t1, "total": t2 - t0, "disp": disp, "rxn": rxn}


def _python(arg: str | None) -> str:
    for p in ([arg] if arg else []) + [str(HERE / ".venv-pynite/bin/python"), "/tmp/venv-pynite/bin/python"]:
        if p and Path(p).exists():
            return p
    raise SystemExit("PyNite's environment not found: python -m venv benchmarks/.venv-pynite && "
                     "benchmarks/.venv-pynite/bin/pip install PyNiteFEA (or give --pynite-python)")


def run_pynite(s: dict, python: str) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        src, out, script = Path(tmp) / "spec.json", Path(tmp) / "out.json", Path(tmp) / "run.py"
        src.write_text(json.dumps({**s, "constants": {"E": E, "G": G, "nu": NU, "A": A, "I": I, "J": J, "W": W,
                                                      "H": H}}))
        script.write_text(PYNITE)
        subprocess.run([python, str(script), str(src), str(out)], check=True)
        return json.loads(out.read_text())


def compare(a: dict, b: dict, key: str, names: list[str]) -> float:
    x = np.array([a[key][n] for n in names], dtype=float)
    y = np.array([b[key][n] for n in names], dtype=float)
    # per group of components: translations and rotations (forces and moments), each by its largest value
    scale = np.repeat([max(np.max(np.abs(y[:, :3])), 1e-300), max(np.max(np.abs(y[:, 3:])), 1e-300)], 3)
    return float(np.max(np.abs(x - y) / scale))


def main(argv: list[str] | None = None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--size", type=int, nargs=3, default=[16, 16, 16], metavar=("NX", "NY", "NZ"))
    ap.add_argument("--pynite-python", default=None)
    args = ap.parse_args(argv)
    s = spec(*args.size)
    print(f"space frame {args.size}: {len(s['nodes'])} nodes, {len(s['members'])} members, {s['unknowns']} unknowns")
    mv = run_mechverify(s)
    print(f"mechverify: build {mv['build']:.2f} s, solve {mv['analyse']:.2f} s, total {mv['total']:.2f} s")
    py = run_pynite(s, _python(args.pynite_python))
    print(f"PyNite:     build {py['build']:.2f} s, analyse {py['analyse']:.2f} s, total {py['total']:.2f} s")
    dd = compare(mv, py, "disp", list(s["nodes"]))
    dr = compare(mv, py, "rxn", s["supports"])
    ratio = mv["total"] / py["total"]
    print(f"largest difference (relative to the largest translation/rotation, force/moment): displacements {dd:.2e}, "
          f"reactions {dr:.2e}; time ratio mechverify/PyNite {ratio:.2f}")
    out = {"size": args.size, "nodes": len(s["nodes"]), "members": len(s["members"]), "unknowns": s["unknowns"],
           "mechverify": {k: mv[k] for k in ("build", "analyse", "total")},
           "pynite": {k: py[k] for k in ("build", "analyse", "total")}, "ratio": ratio,
           "max_rel_diff_displacement": dd, "max_rel_diff_reaction": dr}
    (HERE / "results").mkdir(exist_ok=True)
    (HERE / "results" / "frame_pynite.json").write_text(json.dumps(out, indent=2))
    return out


if __name__ == "__main__":
    main()
