"""Plane-stress / plane-strain FEA (P2 triangles, gmsh) against closed forms.

Sources:
- [Pilkey] Pilkey & Pilkey, Peterson's Stress Concentration Factors, 3rd ed., 2008, eq. (4.1) /
  Chart 4.1: circular hole in a finite-width plate in tension, Ktn = 3.00 - 3.13 (d/H) + 3.66 (d/H)^2
  - 1.53 (d/H)^3 on the net section; Ktg = Ktn / (1 - d/H). d/H = 0.1: Ktn = 2.722, Ktg = 3.024
  (Kirsch's infinite-plate value is 3).
- [Shigley] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, eq. (3-50):
  thick-walled cylinder (Lamé) under internal pressure p_i, sigma_t = p_i r_i^2 (1 + r_o^2/r^2) / (r_o^2 - r_i^2),
  sigma_r = p_i r_i^2 (1 - r_o^2/r^2) / (r_o^2 - r_i^2); plane strain sigma_z = nu (sigma_r + sigma_t).
"""

import numpy as np
import pytest
from shapely.geometry import Polygon

from mechverify.fea.loads import Force, Pressure, Restraint
from mechverify.fea.plane import PlaneModel, mesh_region
from mechverify.fea.regions import Cylinder, Plane

pytest.importorskip("gmsh")


def quarter_arc(r, n, start=0.0, stop=np.pi / 2):
    s = np.linspace(start, stop, n + 1)
    return [(r * np.cos(a), r * np.sin(a)) for a in s]


def test_plate_with_hole_in_tension_kt():
    """Quarter of a 400 x 200 mm plate, 20 mm hole (d/H = 0.1), 10 MPa gross tension along x."""
    r, half_len, half_w, t = 0.01, 0.2, 0.1, 0.005
    outline = [(r, 0.0), (half_len, 0.0), (half_len, half_w), (0.0, half_w), (0.0, r)]
    arc = quarter_arc(r, 48)[::-1][1:-1]  # from (0, r) back to (r, 0), interior points
    region = Polygon(outline + arc)
    mesh = mesh_region(region, "12 mm", "0.6 mm")
    sigma = 10e6
    model = PlaneModel(mesh, f"{t} m", "Structural Steel",
                       supports=(Restraint(Plane(x="0 m"), x=True), Restraint(Plane(y="0 m"), y=True)),
                       loads=(Force(Plane(x=f"{half_len} m"), (f"{sigma * half_w * t} N", "0 N")),))
    res = model.solve()
    peak = res.max_principal
    assert peak.value.m_as("Pa") / sigma == pytest.approx(3.024, rel=0.02)
    assert peak.location.m_as("mm")[:2] == pytest.approx([0.0, 10.0], abs=0.5)  # top of the hole
    assert res.reactions.m_as("N")[0] == pytest.approx(-sigma * half_w * t, rel=1e-9)


@pytest.mark.parametrize("plane", ["strain", "stress"])
def test_lame_thick_cylinder(plane):
    """Quarter of a cylinder r_i = 20 mm, r_o = 40 mm, p_i = 50 MPa, with symmetry rollers."""
    ri, ro, p = 0.02, 0.04, 50e6
    region = Polygon(quarter_arc(ri, 48) [::-1] + quarter_arc(ro, 96))
    mesh = mesh_region(region, "3 mm", "3 mm")
    model = PlaneModel(mesh, "1 m", "Structural Steel", plane=plane,
                       supports=(Restraint(Plane(x="0 m"), x=True), Restraint(Plane(y="0 m"), y=True)),
                       loads=(Pressure(Cylinder(("0 m", "0 m"), f"{ri} m"), f"{p} Pa"),))
    res = model.solve()
    x, y = res.points[:, 0], res.points[:, 1]
    r = np.hypot(x, y)
    c, s = x / r, y / r
    sx, sy, txy = res.sigma[:, 0, 0], res.sigma[:, 1, 1], res.sigma[:, 0, 1]
    st = sx * s**2 + sy * c**2 - 2 * txy * s * c
    k = p * ri**2 / (ro**2 - ri**2)
    exact_t = k * (1 + ro**2 / r**2)
    inner = np.isclose(r, ri, rtol=1e-3)
    assert st[inner].max() == pytest.approx(k * (1 + ro**2 / ri**2), rel=0.01)  # 83.33 MPa
    mid = (r > 0.025) & (r < 0.035)
    assert np.abs(st[mid] - exact_t[mid]).max() <= 0.01 * exact_t.max()
    if plane == "strain":
        nu = 0.3
        sr = sx * c**2 + sy * s**2 + 2 * txy * s * c
        assert res.sigma[mid, 2, 2] == pytest.approx(nu * (sr[mid] + st[mid]), rel=1e-9)
        assert np.mean(res.sigma[mid, 2, 2]) == pytest.approx(2 * nu * k, rel=0.01)
