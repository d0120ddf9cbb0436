"""Fatigue methods against Shigley's worked examples and the Shigley solutions manual.

Sources (every number below is printed in them):
- Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed. (2011), Examples 6-2, 6-3, 6-4, 6-5,
  6-6, 6-8 and Sec. 6-16 (Miner's rule illustration, Fig. 6-34). The 10th ed. (2015) repeats these
  examples with the same data; its Tables 6-2..6-5 and Eqs. (6-40)..(6-48) are those used here.
- Shigley's Mechanical Engineering Design, 8th ed., Instructor's Solutions Manual (Budynas & Nisbett, 2006),
  Problems 6-12, 6-15 and 6-23.
"""

import math

import pytest

from mechverify import Q
from mechverify.fatigue import criteria, endurance, life, notch

KPSI = "ksi"


def test_example_6_2_basquin_line_1050HR():
    """Ex. 6-2: Sut = 90 kpsi, Se' = 45 kpsi, f = 0.86 -> a = 133.1 kpsi, b = -0.0785, Sf(1e4) = 64.6 kpsi,
    N(55 kpsi) = 77 500 cycles."""
    est = endurance.estimate_fatigue_strength(Q(90, KPSI))
    assert est.strength.m_as(KPSI) == pytest.approx(45.0)
    c = life.BasquinCurve.from_ultimate(Q(90, KPSI), est.strength, f=0.86)
    assert Q(c.a, "Pa").m_as(KPSI) == pytest.approx(133.1, abs=0.05)
    assert c.b == pytest.approx(-0.0785, abs=5e-5)
    assert c.stress_at(1e4).m_as(KPSI) == pytest.approx(64.6, abs=0.05)
    assert c.life_at(Q(55, KPSI)) == pytest.approx(77_500, rel=0.005)
    # the 10th ed. fit of Fig. 6-18 gives the f = 0.86 that Ex. 6-2 reads from the chart
    assert life.fatigue_strength_fraction(Q(90, KPSI)).m == pytest.approx(0.86, abs=0.005)


def test_example_6_3_surface_factor():
    """Ex. 6-3: Sut = 520 MPa, machined: ka = 4.51(520)^-0.265 = 0.860."""
    assert endurance.surface_factor("520 MPa", "machined").m == pytest.approx(0.860, abs=5e-4)


def test_example_6_4_size_factor_rotating_and_nonrotating():
    """Ex. 6-4: d = 32 mm: rotating kb = 0.858; non-rotating de = 0.370 d = 11.84 mm, kb = 0.954."""
    assert endurance.size_factor("32 mm").m == pytest.approx(0.858, abs=5e-4)
    de = endurance.equivalent_diameter_round_nonrotating("32 mm")
    assert de.m_as("mm") == pytest.approx(11.84, abs=0.005)
    assert endurance.size_factor(de).m == pytest.approx(0.954, abs=5e-4)


def test_example_6_5_temperature_factor_450F():
    """Ex. 6-5: 1035 steel, Sut = 70 kpsi at 450 degF: kd = 1.007 (Table 6-4 interpolation),
    (a) Se = 1.007(39.0) = 39.3 kpsi; (b) Sut = 70.5 kpsi, Se' = 35.2 kpsi."""
    kd = endurance.temperature_factor(Q(450, "degF")).m
    assert kd == pytest.approx(1.007, abs=5e-4)
    assert 39.0 * kd == pytest.approx(39.3, abs=0.05)
    est = endurance.estimate_fatigue_strength(Q(70 * kd, KPSI))
    assert est.strength.m_as(KPSI) == pytest.approx(35.2, abs=0.05)


def test_example_6_6_notch_sensitivity_shoulder():
    """Ex. 6-6: Sut = 690 MPa, fillet r = 3 mm, Kt = 1.65 (Fig. A-15-9): sqrt(a) = 0.0622 sqrt(in), Kf = 1.55."""
    assert notch.neuber_constant(Q(100, KPSI)).m_as("in**0.5") == pytest.approx(0.0622, abs=2e-4)
    assert notch.neuber_kf(1.65, "3 mm", "690 MPa").m == pytest.approx(1.55, abs=0.005)


def test_example_6_8_marin_chain_and_fatigue_strength():
    """Ex. 6-8: 1015 HR machined, axial, 550 degF (Sut -> 49.0 kpsi), 99 % reliability:
    ka = 0.963, kc = 0.85, ke = 0.814, Se = 16.3 kpsi; a = 119.3 kpsi, Sf(70 000) = 23.9 kpsi."""
    ratio = (0.995 + 0.963) / 2  # Table 6-4 at 550 degF, as the example takes it
    assert 50 * ratio == pytest.approx(49.0, abs=0.06)
    sut = Q(49.0, KPSI)  # the example carries the rounded value
    el = endurance.corrected_endurance_limit(sut, finish="machined", loading="axial", reliability=0.99)
    assert el.factors.ka == pytest.approx(0.963, abs=2e-3)
    assert el.factors.kc == 0.85 and el.factors.kb == 1.0
    assert el.factors.ke == pytest.approx(0.814, abs=5e-4)
    assert el.Se.m_as(KPSI) == pytest.approx(16.3, abs=0.06)
    c = life.BasquinCurve.from_ultimate(sut, Q(16.3, KPSI))  # f = 0.9 since Sut < 70 kpsi
    assert c.f == 0.9
    assert Q(c.a, "Pa").m_as(KPSI) == pytest.approx(119.3, abs=0.1)
    assert c.stress_at(70_000).m_as(KPSI) == pytest.approx(23.9, abs=0.05)


def test_example_6_10_gerber_asme_langer():
    """1050 CD bar, 1.5 in, 0..16 kip, Kf = 1.85, Se = 0.797(0.85)(50) = 33.9 kpsi, Sut = 100, Sy = 84 kpsi
    (9th/10th ed. Example 6-10): sigma_a = sigma_m = 8.38 kpsi; Gerber n_f = 3.66, ASME-elliptic
    n_f = 3.75, Langer n_y = 5.01."""
    area = math.pi * 1.5 ** 2 / 4
    s = 1.85 * 8 / area
    assert s == pytest.approx(8.38, abs=0.005)
    se = 0.5 * 100 * endurance.surface_factor(Q(100, KPSI), "machined").m * 0.85
    assert se == pytest.approx(33.9, abs=0.05)
    sa = sm = Q(s, KPSI)
    assert criteria.gerber(sa, sm, Q(se, KPSI), Q(100, KPSI)).m == pytest.approx(3.66, abs=0.01)
    assert criteria.asme_elliptic(sa, sm, Q(se, KPSI), Q(84, KPSI)).m == pytest.approx(3.75, abs=0.01)
    assert criteria.langer(sa, sm, Q(84, KPSI)).m == pytest.approx(5.01, abs=0.01)


def test_solutions_manual_problem_6_12_three_criteria():
    """8th ed. Solutions Manual, Prob. 6-12: Se = 276, Sy = 413, Sut = 551 MPa; alternating bending 172 MPa,
    steady torsion 103 MPa -> sigma_m' = sqrt(3)(103) = 178.4 MPa. Goodman n_f = 1.06, Gerber 1.31,
    ASME-elliptic 1.32; yield n_y = 413/247.8 = 1.67 (von Mises of the peak state)."""
    sa, sm = Q(172, "MPa"), Q(math.sqrt(3) * 103, "MPa")
    se, sy, sut = Q(276, "MPa"), Q(413, "MPa"), Q(551, "MPa")
    assert criteria.goodman(sa, sm, se, sut).m == pytest.approx(1.06, abs=0.005)
    assert criteria.gerber(sa, sm, se, sut).m == pytest.approx(1.31, abs=0.005)
    assert criteria.asme_elliptic(sa, sm, se, sy).m == pytest.approx(1.32, abs=0.005)
    from mechverify.fatigue.stress import von_mises
    peak = von_mises(Q([172, 0, 0, 103, 0, 0], "MPa"))
    assert peak.m_as("MPa") == pytest.approx(247.8, abs=0.05)


def test_solutions_manual_problem_6_15_fully_reversed_finite_life():
    """8th ed. Solutions Manual, Prob. 6-15: sigma_a' = sqrt(3)(207) = 358.5 MPa, sigma_m = 0, Se = 276, Sut = 551:
    all criteria n_f = 0.77; with f = 0.9: a = 891.0 MPa, b = -0.084828, N = 45 800 cycles."""
    sa, sm = Q(math.sqrt(3) * 207, "MPa"), Q(0, "MPa")
    for name in ("goodman", "gerber"):
        assert criteria.safety_factor(name, sa, sm, "276 MPa", Sut="551 MPa").m == pytest.approx(0.77, abs=0.005)
    assert criteria.asme_elliptic(sa, sm, "276 MPa", "413 MPa").m == pytest.approx(0.77, abs=0.005)
    c = life.BasquinCurve.from_ultimate("551 MPa", "276 MPa", f=0.9)
    assert Q(c.a, "Pa").m_as("MPa") == pytest.approx(891.0, abs=0.1)
    assert c.b == pytest.approx(-0.084828, abs=1e-6)
    assert c.life_at(sa) == pytest.approx(45_800, rel=0.005)


def test_solutions_manual_problem_6_23_compressive_mean():
    """8th ed. Solutions Manual, Prob. 6-23 (fillet): sigma_a = 15.2, sigma_m = -9.12 kpsi, Se = 24.4, Sy = 54 kpsi:
    compressive mean so S_a = S_e, n_f = 24.4/15.2 = 1.61; yield n_y = |Sy/sigma_min| = 54/12.8 = 4.22 (nominal)."""
    nf = criteria.goodman(Q(15.2, KPSI), Q(-9.12, KPSI), Q(24.4, KPSI), Q(64, KPSI)).m
    assert nf == pytest.approx(1.61, abs=0.005)
    # Langer on the nominal extremes (3.2, -12.8 kpsi): sigma_a = 8.0, sigma_m = -4.8
    assert criteria.langer(Q(8.0, KPSI), Q(-4.8, KPSI), Q(54, KPSI)).m == pytest.approx(4.22, abs=0.005)


def test_miner_rule_shigley_sec_6_16_fig_6_34():
    """9th ed. Sec. 6-16, Fig. 6-34: Sut = 80, Se,0 = 40 kpsi, f = 0.9 -> a = 129.6 kpsi, b = -0.085 091;
    N1 = 8520 cycles at 60 kpsi; after n1 = 3000 cycles at 60 kpsi, Miner allows n2 = 0.648e6 cycles at
    40 kpsi (D = 1), and the damaged line a' = 60 / 5520^b = 124.898 kpsi gives Se,1 = 38.6 kpsi."""
    c = life.BasquinCurve.from_ultimate(Q(80, KPSI), Q(40, KPSI), f=0.9)
    assert Q(c.a, "Pa").m_as(KPSI) == pytest.approx(129.6, abs=0.05)
    assert c.b == pytest.approx(-0.085091, abs=1e-6)
    n1 = c.life_at(Q(60, KPSI))
    assert n1 == pytest.approx(8520, rel=0.001)
    res = life.miner_damage([(Q(60, KPSI), 3000), (Q(40, KPSI), 0.648e6)], c)
    assert res.damage == pytest.approx(1.0, abs=0.002)
    a_new = 60 / (n1 - 3000) ** c.b
    assert a_new == pytest.approx(124.898, rel=5e-4)
    assert a_new * 1e6 ** c.b == pytest.approx(38.6, abs=0.05)
