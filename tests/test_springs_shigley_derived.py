"""Helical springs on the inputs of Shigley's Mechanical Engineering Design, 10th ed. (Budynas & Nisbett,
2015), Examples 10-1 and 10-4: HAND-DERIVED expected values, not the book's printed answers.

The example inputs were written from memory of the 10th edition. Searches of the public corpora
(2026-11-22 and 2026-11-24, by the examples' data) did not find the printed examples, so the expected
values below are hand calculations from Shigley's equations (Eqs. 10-3 to 10-14, 10-26 to 10-30,
Table 10-4 power law for music wire A = 201 kpsi·in^m, m = 0.145, Table 10-5 moduli) on those inputs, to
the precision asserted; they check the formulas' implementation, not agreement with the book. A test
against values printed in a citable source is in ``tests/validation/test_shigley_springs.py``
(Shigley 10th ed. Problem 10-3, from the Solutions Manual).
"""

import math

import pytest

from mechverify.checks.springs import check_spring_fatigue
from mechverify.components.springs import (
    CompressionSpring,
    bergstrasser_factor,
    torsion_spring_factors,
    wahl_factor,
)
from mechverify.units import Q


def music_wire_sut(d_in: float) -> Q:
    """Shigley Table 10-4: Sut = A/d^m, music wire A = 201 kpsi·in^m, m = 0.145."""
    return Q(201 / d_in**0.145, "ksi")


@pytest.fixture
def ex10_1():
    """Inputs of Example 10-1: no. 16 music wire (d = 0.037 in), OD = 7/16 in, squared ends, 12.5 total turns."""
    return CompressionSpring(d="0.037 in", OD=f"{7 / 16} in", Nt=12.5, end="squared", L0="2.06 in",
                             G="11.85 Mpsi", Sut=music_wire_sut(0.037))


def test_example_10_1_strength_index_and_static_load(ex10_1):
    """Hand calculation on the inputs of Ex. 10-1 (a)-(b): Sut = 324 kpsi, Ssy = 0.45 Sut = 146 kpsi, D = 0.4005 in, C = 10.82, K_B = 1.124,
    F = πd³Ssy/(8K_B D) = 6.46 lbf."""
    s = ex10_1
    assert s.tensile_strength.m_as("ksi") == pytest.approx(324, rel=2e-3)
    assert s.allowable_static_stress.m_as("ksi") == pytest.approx(146, rel=3e-3)
    assert s.mean_diameter.m_as("in") == pytest.approx(0.4005, rel=1e-4)
    assert s.index == pytest.approx(10.82, rel=1e-3)
    assert s.bergstrasser_factor == pytest.approx(1.124, abs=5e-4)
    F = Q(6.46, "lbf")
    assert s.shear_stress(F).m_as("ksi") == pytest.approx(146, rel=5e-3)


def test_example_10_1_rate_solid_length_pitch(ex10_1):
    """Hand calculation on the inputs of Ex. 10-1 (c)-(h): Na = 10.5, k = d⁴G/(8D³Na) = 4.12 lbf/in, Ls = (Nt + 1)d = 0.500 in,
    y = 6.46/4.12 = 1.57 in, L0 = 2.06 in, pitch p = (L0 - 3d)/Na = 0.186 in."""
    s = ex10_1
    assert s.active_coils == 10.5
    assert s.rate.m_as("lbf/in") == pytest.approx(4.12, rel=3e-3)
    assert s.solid_length.m_as("in") == pytest.approx(0.4995, abs=1e-4)
    assert (Q(6.46, "lbf") / s.rate).m_as("in") == pytest.approx(1.57, rel=5e-3)
    assert s.pitch.m_as("in") == pytest.approx(0.186, rel=3e-3)


def test_example_10_1_buckling_steel_constant():
    """Hand calculation on the inputs of Ex. 10-1 (g) with Eq. (10-14): for steels (L0)cr = 2.63 D/α; fixed-fixed (α = 0.5) gives
    2.63(0.4005)/0.5 = 2.11 in. Eq. (10-13) reduces to 2.63 with E = 30 Mpsi, G = 11.5 Mpsi."""
    s = CompressionSpring(d="0.037 in", OD=f"{7 / 16} in", Nt=12.5, end="squared", L0="2.06 in",
                          E="30 Mpsi", G="11.5 Mpsi", Sut=music_wire_sut(0.037))
    assert s.critical_free_length("fixed-fixed").m_as("in") == pytest.approx(2.11, rel=5e-3)
    assert s.critical_deflection("fixed-fixed") is None  # absolutely stable: L0 < (L0)cr


@pytest.fixture
def ex10_4():
    """Inputs of Example 10-4: music wire d = 0.092 in, OD = 9/16 in, L0 = 4 3/8 in, Na = 21, squared and ground,
    unpeened; preload 5 lbf, maximum 35 lbf. G = 11.75 Mpsi (Table 10-5), γ = 0.284 lbf/in³."""
    return CompressionSpring(d="0.092 in", OD=f"{9 / 16} in", L0="4.375 in", Na=21, end="squared-ground",
                             G="11.75 Mpsi", Sut=music_wire_sut(0.092), density="0.284 lb/in**3")


def test_example_10_4_stresses(ex10_4):
    """Hand calculation on the inputs of Ex. 10-4: D = 0.4705 in, C = 5.11, K_B = 1.287, τa = 29.7 kpsi, τm = 39.6 kpsi,
    Sut = 284.1 kpsi, Ssu = 0.67 Sut = 190.3 kpsi."""
    f = ex10_4.fatigue("5 lbf", "35 lbf", "gerber")
    assert ex10_4.index == pytest.approx(5.11, rel=1e-3)
    assert ex10_4.bergstrasser_factor == pytest.approx(1.287, abs=1e-3)
    assert f.tau_a.m_as("ksi") == pytest.approx(29.7, rel=3e-3)
    assert f.tau_m.m_as("ksi") == pytest.approx(39.6, rel=3e-3)
    assert ex10_4.tensile_strength.m_as("ksi") == pytest.approx(284.1, rel=1e-3)
    assert f.Ssu.m_as("ksi") == pytest.approx(190.3, rel=1e-3)


@pytest.mark.parametrize(("criterion", "Sse", "n_f"), [
    ("gerber", 38.2, 1.21),   # (a) Gerber with Zimmerli data
    ("sines", 35.0, 1.18),    # (b) Sines: Ssa = 35 kpsi, no mean-stress effect
    ("goodman", 49.2, 1.23),  # (c) Goodman with Zimmerli data
])
def test_example_10_4_fatigue_factors(ex10_4, criterion, Sse, n_f):
    """Hand calculation on the inputs of Ex. 10-4 (a)-(c): Sse = Ssa/(1 - (Ssm/Ssu)²) = 38.2 kpsi, nf = 1.21; Sines nf = 35/29.7 = 1.18;
    Goodman Sse = Ssa/(1 - Ssm/Ssu) = 49.2 kpsi, nf = 1.23."""
    f = ex10_4.fatigue("5 lbf", "35 lbf", criterion)
    assert f.Sse.m_as("ksi") == pytest.approx(Sse, rel=3e-3)
    assert f.n_f == pytest.approx(n_f, abs=0.006)


def test_example_10_4_surge_frequency(ex10_4):
    """Hand calculation on the inputs of Ex. 10-4 (d): k = 48.1 lbf/in, W = π²d²DNaγ/4 = 0.0586 lbf, fn = ½√(kg/W) = 281 Hz."""
    assert ex10_4.rate.m_as("lbf/in") == pytest.approx(48.1, rel=2e-3)
    assert ex10_4.active_mass.m_as("lb") == pytest.approx(0.0586, rel=3e-3)
    assert ex10_4.surge_frequency().m_as("Hz") == pytest.approx(281, rel=3e-3)


def test_example_10_4_fatigue_check_reports_gerber_factor(ex10_4):
    """The fatigue check's safety factor is the hand-derived Gerber nf = 1.21; the design factor 1.5 is not met."""
    r = check_spring_fatigue(ex10_4, "5 lbf", "35 lbf")
    assert r.safety_factor == pytest.approx(1.21, abs=0.006)
    assert r.verdict == "fail"


def test_stress_factors_eqs_10_4_10_5():
    """Eqs. (10-4), (10-5): at C = 10, K_W = 39/36 + 0.0615 = 1.1448, K_B = 42/37 = 1.1351 (within 1 %)."""
    assert wahl_factor(10) == pytest.approx(39 / 36 + 0.0615)
    assert bergstrasser_factor(10) == pytest.approx(42 / 37)
    assert abs(wahl_factor(10) / bergstrasser_factor(10) - 1) < 0.01


def test_torsion_spring_factor_eq_10_43():
    """Eq. (10-43) for Ex. 10-9's index C = (19/32 - 0.072)/0.072 = 7.247: K_i = 1.115."""
    C = (19 / 32 - 0.072) / 0.072
    Ki, Ko = torsion_spring_factors(C)
    assert Ki == pytest.approx(1.115, abs=1e-3)
    assert Ko == pytest.approx((4 * C * C + C - 1) / (4 * C * (C + 1)))
    assert math.isclose(C, 7.247, rel_tol=1e-3)
