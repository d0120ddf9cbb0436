"""Lug (pin-connected plate) strengths after ASME BTH-1 against a published worked calculation.

Sources:
- ASME BTH-1-2008 Sec. 3-3.3.1, Eqs. (3-45)-(3-52), Commentary Eq. (C3-2) (Duerr 2006).
- Worked example "Lifting Lug Design per ASME BTH-1" (published calculation sheet, scribd doc. 410423529):
  t = 0.19685 in (5 mm), Dh = 0.47244 in (12 mm), Dp = 0.39370 in (10 mm), be = a = 0.25591 in
  (6.5 mm), rounded end R = 0.49213 in, A36 (Fy = 36 ksi, Fu = 58 ksi), Nd = 2:
  Cr = 0.848, phi = 45.833 deg, Z' = 0.021 in, Av = 0.12 in^2, allowable (/(1.20 Nd)):
  Pt = 2.06 kip, Pb = 1.78 kip, Pv = 1.96 kip; bearing (/Nd) Pp = 1.74 kip.
"""

import pytest

from mechverify import Q
from mechverify.components.links import Lug, bth1_pin_clearance_factor, lug_strength


@pytest.fixture(scope="module")
def example():
    lug = Lug(hole_diameter=Q(0.47244094, "in"), width=Q(0.47244094 + 2 * 0.25590551, "in"),
              thickness=Q(0.19685039, "in"), edge_distance=Q(0.49212598, "in"), rounded_end=True)
    return lug, lug_strength(lug, Q(0.39370079, "in"), "36 ksi", "58 ksi")


def test_clearance_factor_and_shear_plane(example):
    _, s = example
    assert s.Cr == pytest.approx(0.848, abs=0.0005)
    assert s.phi.m_as("deg") == pytest.approx(45.833, abs=0.001)
    assert s.b_eff.m_as("in") == pytest.approx(0.2559, abs=0.0001)  # be governs (< 4t, < Eq. 3-48 limit 0.34 in)
    assert s.shear_area.m_as("in**2") == pytest.approx(0.12, abs=0.005)


@pytest.mark.parametrize(("mode", "factor", "kip"), [("tension", 2.4, 2.06), ("fracture_beyond", 2.4, 1.78),
                                                     ("shear_out", 2.4, 1.96), ("bearing", 2.0, 1.74)])
def test_allowable_loads(example, mode, factor, kip):
    _, s = example
    assert (getattr(s, mode) / factor).m_as("kip") == pytest.approx(kip, abs=0.005)


def test_governing_mode(example):
    _, s = example
    assert s.governing[0] == "fracture_beyond"


def test_square_end_has_no_curved_edge_reduction(example):
    lug, s = example
    square = Lug(lug.hole_diameter, lug.width, lug.thickness, lug.edge_distance, rounded_end=False)
    sq = lug_strength(square, Q(0.39370079, "in"), "36 ksi", "58 ksi")
    # Av = 2 [a + Dp/2 (1 - cos phi)] t = 2 (0.3156) 0.19685 in^2 (Eq. 3-51 without Z')
    assert sq.shear_area.m_as("in**2") == pytest.approx(2 * 0.3156 * 0.19685, rel=0.002)
    assert sq.shear_out > s.shear_out


def test_cr_is_one_for_a_fitted_pin():
    assert bth1_pin_clearance_factor("10 mm", "10 mm").m_as("") == 1.0
