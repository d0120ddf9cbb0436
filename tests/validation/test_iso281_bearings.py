"""Rolling-bearing life and static safety against ISO 281:2007, ISO 76:2006 and the SKF catalogue.

Sources: ISO 281:2007 Table 3 (X, Y, e of radial ball bearings) and Table 12 (a1); ISO 76:2006
Sec. 6.2.2; SKF Rolling bearings catalogue, "Selecting bearing size - Calculation examples", Example 1
(SKF Explorer 6309 at 3 000 r/min, F_r = 10 kN; C = 55,3 kN: L10 = 169 million revolutions,
L10h = 940 operating hours) - text verified 2026-11-22 in the copy at yumpu.com/en/document/view/55668573
(viewer page 92), an edition of the catalogue earlier than 17000 EN (the example is the same);
SKF product data for the 608 as quoted in reference project 004, Table 9.
"""

import pytest

from mechverify.components.bearings import (
    basic_rating_life,
    bearing,
    equivalent_dynamic_load,
    equivalent_static_load,
    iso281_factors,
    life_hours,
    reliability_factor,
)


def test_skf_example_6309_basic_rating_life():
    """SKF catalogue calculation example 1 (verified text, see module docstring): L10 = (55.3/10)³ = 169 Mrev; L10h = 10⁶/(60·3000)·169 = 940 h."""
    L10 = basic_rating_life("55.3 kN", "10 kN")
    assert L10.m_as("revolution") / 1e6 == pytest.approx(169, rel=2e-3)
    assert life_hours(L10, "3000 rpm").m_as("hour") == pytest.approx(940, rel=2e-3)


@pytest.mark.parametrize(("rel", "e", "Y"), [
    (0.172, 0.19, 2.30), (0.345, 0.22, 1.99), (0.689, 0.26, 1.71), (1.03, 0.28, 1.55), (1.38, 0.30, 1.45),
    (2.07, 0.34, 1.31), (3.45, 0.38, 1.15), (5.17, 0.42, 1.04), (6.89, 0.44, 1.00)])
def test_iso281_table3_rows(rel, e, Y):
    """ISO 281:2007 Table 3, single-row radial ball bearings, normal clearance (X = 0.56 for Fa/Fr > e)."""
    assert iso281_factors(rel) == pytest.approx((e, Y))


def test_iso281_table3_linear_interpolation():
    """ISO 281 Table 3 note: intermediate values by linear interpolation (midway 2.07..3.45)."""
    e, Y = iso281_factors((2.07 + 3.45) / 2)
    assert e == pytest.approx(0.36) and Y == pytest.approx(1.23)


def test_equivalent_load_switches_at_e():
    """ISO 281 Table 3: Fa/Fr <= e -> P = Fr; above e -> P = 0.56 Fr + Y Fa.
    608 (C0 = 1.37 kN, f0 = 12) with Fa = 114.17 N: f0 Fa/C0 = 1.0 (e = 0.2776, Y = 1.5612)."""
    Fa = 1.37e3 / 12
    low = equivalent_dynamic_load("1000 N", f"{Fa} N", "1.37 kN", 12)
    assert low.P.m_as("N") == pytest.approx(1000) and low.X == 1 and low.Y == 0
    high = equivalent_dynamic_load("200 N", f"{Fa} N", "1.37 kN", 12)
    e = 0.26 + (1.0 - 0.689) / (1.03 - 0.689) * 0.02
    Y = 1.71 - (1.0 - 0.689) / (1.03 - 0.689) * 0.16
    assert high.e == pytest.approx(e) and high.Y == pytest.approx(Y)
    assert high.P.m_as("N") == pytest.approx(0.56 * 200 + Y * Fa)


@pytest.mark.parametrize(("R", "a1"), [(0.90, 1.0), (0.95, 0.64), (0.96, 0.55), (0.97, 0.47), (0.98, 0.37),
                                       (0.99, 0.25), (0.995, 0.175), (0.9995, 0.053)])
def test_iso281_table12_reliability_factor(R, a1):
    """ISO 281:2007 Table 12 (99.5 % lies between the 99.4 and 99.6 rows, 0.19 and 0.16)."""
    assert reliability_factor(R) == pytest.approx(a1, abs=0.003 if R == 0.995 else 1e-9)


def test_iso76_static_equivalent_load():
    """ISO 76 Sec. 6.2.2: P0 = 0.6 Fr + 0.5 Fa, not less than Fr."""
    assert equivalent_static_load("0 N", "350 N").m_as("N") == pytest.approx(175)
    assert equivalent_static_load("1000 N", "200 N").m_as("N") == pytest.approx(1000)  # 700 < Fr
    assert equivalent_static_load("1000 N", "1000 N").m_as("N") == pytest.approx(1100)


def test_skf_608_catalogue_row():
    """SKF 608 data (as quoted in reference project 004, Table 9): 8x22x7 mm, C = 3.45 kN, C0 = 1.37 kN,
    Pu = 0.057 kN, reference speed 75 000 r/min, limiting speed 48 000 r/min, f0 = 12."""
    b = bearing("608")
    assert (b.d.m_as("mm"), b.D.m_as("mm"), b.B.m_as("mm")) == (8, 22, 7)
    assert (b.C.m_as("kN"), b.C0.m_as("kN"), b.Pu.m_as("kN")) == (3.45, 1.37, 0.057)
    assert (b.reference_speed.m_as("rpm"), b.limiting_speed.m_as("rpm"), b.f0) == (75000, 48000, 12)
    # s0 for the project's 350 N axial screw load: P0 = 0.5·350 = 175 N, s0 = 1370/175 = 7.83
    assert b.static_safety("0 N", "350 N") == pytest.approx(1370 / 175)


@pytest.mark.parametrize(("name", "d", "D", "B"), [
    ("6200", 10, 30, 9), ("6201", 12, 32, 10), ("6202", 15, 35, 11),
    ("6203", 17, 40, 12), ("6204", 20, 47, 14), ("6205", 25, 52, 15)])
def test_62xx_boundary_dimensions(name, d, D, B):
    """Boundary dimensions of diameter series 2 (ISO 15), as printed in a maker's open deep-groove table
    (gist.github.com/nagae/8756dc2de16082219e1ae6a80a73dfb3); only d, D, B are maker-independent."""
    b = bearing(name)
    assert (b.d.m_as("mm"), b.D.m_as("mm"), b.B.m_as("mm")) == (d, D, B)
