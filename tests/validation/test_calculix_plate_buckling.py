"""Cross-check of plate buckling (mechverify.fea.plate_buckling, Morley triangles) against CalculiX 2.20 *BUCKLE.

A 400 x 200 x 2 mm steel plate (E = 200 GPa, ν = 0.3), simply supported (deflection held on all edges), under
uniform compression Nx = 10 N/mm on its short edges: ccx S4 shells (expanded by ccx to C3D8I bricks, CalculiX 2.20
User's Manual sec. 6.2.6 and 6.9.10) on an 80 x 40 grid, the load as consistent nodal forces on the x = a edge, the
x = 0 edge held along x and one corner along y. Timoshenko & Gere eq. 9-9 (hand calculation): k = (m b/a + a/(mb))²
= 4 (m = 2), 4.694 (m = 3), 6.25 (m = 4), N_cr = k π² D/b², factor = N_cr / 10 N/mm = 14.46 for k = 4.
Measured with 5 mm elements in both codes: ccx 14.433, 16.942, 22.570; mechverify 14.440, 16.953, 22.52 (at 10 mm
they bracket the closed form from either side: ccx +0.9 %, Morley -0.6 %). The two codes must agree to 0.5 % on
the first three factors and both lie within 0.5 % of the closed form for the first.
"""

import math
import os
import shutil
import subprocess

import numpy as np
import pytest

from mechverify.components import plates as P
from mechverify.fea.plate_buckling import InPlaneLoad, plate_buckling

pytestmark = [pytest.mark.ccx, pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) not installed")]

A, B, T, NX, NY = 400.0, 200.0, 2.0, 80, 40  # mm; the ccx grid (5 mm)


def _deck() -> str:
    def nid(i: int, j: int) -> int:
        return j * (NX + 1) + i + 1

    lines = ["*NODE"]
    lines += [f"{nid(i, j)}, {i * A / NX}, {j * B / NY}, 0" for j in range(NY + 1) for i in range(NX + 1)]
    lines.append("*ELEMENT, TYPE=S4, ELSET=PL")
    e = 1
    for j in range(NY):
        for i in range(NX):
            lines.append(f"{e}, {nid(i, j)}, {nid(i + 1, j)}, {nid(i + 1, j + 1)}, {nid(i, j + 1)}")
            e += 1
    edge = [nid(i, j) for j in range(NY + 1) for i in range(NX + 1) if i in (0, NX) or j in (0, NY)]
    lines += ["*NSET, NSET=EDGE", *(f"{n}," for n in edge), "*NSET, NSET=LEFT",
              *(f"{nid(0, j)}," for j in range(NY + 1)),
              "*MATERIAL, NAME=ST", "*ELASTIC", "200000, 0.3", "*SHELL SECTION, ELSET=PL, MATERIAL=ST", f"{T}",
              "*BOUNDARY", "EDGE, 3, 3", "LEFT, 1, 1", f"{nid(0, 0)}, 2, 2", "*STEP", "*BUCKLE", "3", "*CLOAD"]
    h = B / NY
    lines += [f"{nid(NX, j)}, 1, {-10.0 * h * (0.5 if j in (0, NY) else 1.0)}" for j in range(NY + 1)]
    return "\n".join([*lines, "*END STEP"]) + "\n"


def _ccx_factors(tmp_path) -> np.ndarray:
    (tmp_path / "pb.inp").write_text(_deck())
    subprocess.run([shutil.which("ccx") or "ccx", "-i", "pb"], cwd=tmp_path, check=True, capture_output=True,
                   timeout=300, env={**os.environ, "OMP_NUM_THREADS": "1"})
    text = (tmp_path / "pb.dat").read_text()
    rows = text.split("FACTOR", 1)[1].split()
    return np.array([float(rows[1]), float(rows[3]), float(rows[5])])


def test_simply_supported_plate_against_ccx_buckle(tmp_path):
    plate = P.Plate.rectangle(f"{A} mm", f"{B} mm", f"{T} mm", "Structural Steel")
    E, nu = plate.material.E.m_as("MPa"), plate.material.nu.m_as("")
    assert E == pytest.approx(200000.0) and nu == pytest.approx(0.3)  # the deck's material
    D = E * T**3 / (12 * (1 - nu**2))  # N·mm
    factor_k4 = 4 * math.pi**2 * D / B**2 / 10.0  # T&G eq. 9-9, hand: 14.46
    assert factor_k4 == pytest.approx(14.46, abs=0.01)
    ccx = _ccx_factors(tmp_path)
    res = plate_buckling(P.PlateModel(plate, supports=(P.EdgeSupport("all"),)), InPlaneLoad(nx="-10 N/mm"), 3,
                         mesh_size="5 mm")
    assert res.factors == pytest.approx(ccx, rel=5e-3)
    assert ccx[0] == pytest.approx(factor_k4, rel=5e-3) and res.factors[0] == pytest.approx(factor_k4, rel=5e-3)
