"""A pin load along its hole's axis (review 3 finding 21): the part across the hole is the bearing (cosine) pressure,
the part along the axis a uniform shear on the wall.

Before the fix, a pin force along the hole's axis drove the cosine distribution with facet noise and its bearing
pressure exploded: 2510 MPa at the hole where beam theory gives 87 MPa. Reference: Euler-Bernoulli cantilever (Gere &
Goodno, Mechanics of Materials, Table H-1 case 4, a load P at distance a from the clamp), worked by hand here:
300 x 20 x 10 mm steel bar clamped at x = 0, 100 N along -z at the hole at x = 290 mm (bending about y, the 10 mm
side: I = 20 * 10^3 / 12 = 1666.7 mm^4, E = 200 GPa). Deflection at the load PL^3/3EI = 2.439 mm, slope PL^2/2EI =
0.01262, tip (10 mm further) 2.565 mm; root stress M c / I = 100 * 290 * 5 / 1666.7 = 87.0 MPa.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from mechverify.design import load
from mechverify.fea.loads import pin_tractions

BAR = textwrap.dedent("""
    [design]
    name = "pin along its hole"
    [components.beam]
    type = "solid_fea"
    box = "300, 20, 10"
    holes = [{ center = "290, 10", diameter = "6 mm" }]
    material = "Structural Steel"
    mesh_size = "4 mm"
    supports = [{ named = "xmin" }]
    deflection_limit = "20 mm"
    [load_cases.pin.beam]
    pin_loads = [{ named = "hole0", force = "0, 0, -100" }]
    """)


def test_pin_pushed_along_its_hole_bends_the_bar_as_beam_theory(tmp_path):
    p = tmp_path / "pinz.toml"
    p.write_text(BAR)
    res = {r.check: r for r in load(p).verify().results}
    tip = res["solid_deflection"].demand.m_as("mm")
    stress = res["solid_stress"].demand.m_as("MPa")
    assert tip == pytest.approx(2.565, rel=0.03)   # hand: 2.565 mm (P2 tetrahedra converge from below)
    assert stress == pytest.approx(87.0, rel=0.10)  # hand: 87.0 MPa at the root (it was 2510 MPa at the hole)


def test_pin_tractions_split_across_and_along_the_axis():
    """A cylindrical wall (axis z) of 64 facets: a force across it keeps the cosine distribution, along the axis it is
    a uniform shear, and an oblique force is the sum of the two; the resultant is exact in every case."""
    k = 64
    ang = (np.arange(k) + 0.5) * 2 * np.pi / k
    normal = np.c_[-np.cos(ang), -np.sin(ang), np.zeros(k)]  # the body's outward normal points into the hole
    area = np.full(k, 1e-6)
    across, along = pin_tractions((100.0, 0.0, 0.0), area, normal), pin_tractions((0.0, 0.0, -30.0), area, normal)
    both = pin_tractions((100.0, 0.0, -30.0), area, normal)
    np.testing.assert_allclose(along, np.broadcast_to([0.0, 0.0, -30.0 / area.sum()], (k, 3)))
    np.testing.assert_allclose((area[:, None] * both).sum(axis=0), [100.0, 0.0, -30.0], atol=1e-9)
    np.testing.assert_allclose(both[:, :2], across[:, :2], atol=1e-6)  # the bearing part unchanged by the axial part
    assert np.abs(both).max() < 2 * np.abs(across).max()
