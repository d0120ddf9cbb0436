"""Column buckling against Shigley's worked examples and Table 4-2.

Sources:
- Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed. (2011), Example 4-17
  (round pinned column, 1.5 m, 22 kN, n_d = 4, Sy = 500 MPa, E = 207 GPa: d = 37.48 mm from
  Euler, chosen 40 mm, l/k = 150, (l/k)_1 = 90.4, an Euler column). The same equations are
  Eqs. (4-43), (4-45), (4-46) of the 10th ed.
- Shigley 9th ed. Instructor's Solutions Manual, Problem 4-77(b): d = 0.875 in, l = 18 in,
  Sy = 37.5 kpsi, E = 30 Mpsi, C = 1: k = 0.2188 in, l/k = 82.3, Johnson P_cr = 17 714 lbf.
- Shigley 10th ed. Table 4-2, end-condition constants.
"""

import math

import pytest

from mechverify import Q
from mechverify.components import columns
from mechverify.errors import InputError, UnitError, UnknownNameError, ValidityError


def _round(d):
    d = Q(d)
    return math.pi / 4 * d**2, math.pi / 64 * d**4


def test_example_4_17_euler_diameter_gives_88_kN():
    """Shigley 9th ed. Ex. 4-17: d = 37.48 mm is the Euler diameter for P_cr = 4 x 22 kN = 88 kN."""
    _, I = _round("37.48 mm")
    P = columns.euler_critical_load("207 GPa", I, "1.5 m", end="rounded-rounded")
    assert P.m_as("kN") == pytest.approx(88.0, rel=1e-3)


def test_example_4_17_slenderness_and_transition():
    """Shigley 9th ed. Ex. 4-17: for d = 40 mm, l/k = 150 and (l/k)_1 = 90.4 -> Euler column."""
    A, I = _round("40 mm")
    r = columns.column_buckling("207 GPa", "500 MPa", A, I, "1.5 m", end="pinned-pinned")
    assert r.slenderness == pytest.approx(150.0, rel=1e-9)
    assert r.transition_slenderness == pytest.approx(90.4, abs=0.05)
    assert r.regime == "euler"
    assert columns.transition_slenderness("207 GPa", "500 MPa").m_as("") == pytest.approx(90.4, abs=0.05)
    # 40 mm is stronger than the 88 kN required
    assert r.critical_load.m_as("kN") > 88.0


def test_solutions_manual_4_77b_johnson():
    """Shigley 9th ed. solutions manual Prob. 4-77(b): l/k = 82.3, Johnson P_cr = 17 714 lbf."""
    A, I = _round("0.875 in")
    r = columns.column_buckling("30 Mpsi", "37.5 kpsi", A, I, "18 in", end="pinned-pinned")
    assert r.slenderness == pytest.approx(82.3, abs=0.05)
    assert r.regime == "johnson"
    assert r.critical_load.m_as("lbf") == pytest.approx(17714, rel=1e-3)
    assert columns.johnson_critical_load("30 Mpsi", "37.5 kpsi", A, I, "18 in").m_as("lbf") == pytest.approx(
        17714, rel=1e-3)


@pytest.mark.parametrize(("end", "theoretical", "conservative", "recommended"), [
    ("fixed-free", 0.25, 0.25, 0.25),
    ("rounded-rounded", 1.0, 1.0, 1.0),
    ("fixed-rounded", 2.046, 1.0, 1.2),
    ("fixed-fixed", 4.0, 1.0, 1.2),
])
def test_table_4_2(end, theoretical, conservative, recommended):
    """Shigley 10th ed. Table 4-2, the three columns of C."""
    assert columns.end_condition_constant(end, "theoretical") == theoretical
    assert columns.end_condition_constant(end, "conservative") == conservative
    assert columns.end_condition_constant(end) == recommended


def test_effective_length_factor_theoretical():
    """K = 1/sqrt(C): 2 for a cantilever, 0.5 for fixed-fixed (theoretical, Shigley Sec. 4-12)."""
    assert columns.effective_length_factor("cantilever", "theoretical") == pytest.approx(2.0)
    assert columns.effective_length_factor("fixed-fixed", "theoretical") == pytest.approx(0.5)


def test_euler_equals_johnson_at_transition():
    """At (l/k)_1 both curves give S_y/2 (Shigley 10th ed. Eq. (4-44), (4-45), tangent point)."""
    A, I = _round("20 mm")
    k = 5e-3
    lk1 = columns.transition_slenderness("200 GPa", "300 MPa", "fixed-pinned").m_as("")
    L = Q(lk1 * k, "m")
    e = columns.euler_critical_load("200 GPa", I, L, "fixed-pinned")
    j = columns.johnson_critical_load("200 GPa", "300 MPa", A, I, L, "fixed-pinned")
    assert e.m_as("N") == pytest.approx(j.m_as("N"), rel=1e-9)
    assert (e / A).m_as("MPa") == pytest.approx(150.0, rel=1e-9)


def test_errors():
    A, I = _round("10 mm")
    with pytest.raises(UnknownNameError, match="did you mean 'fixed-free'"):
        columns.euler_critical_load("200 GPa", I, "1 m", end="fixed-fre")
    with pytest.raises(UnknownNameError):
        columns.end_condition_constant("pinned-pinned", basis="typical")
    with pytest.raises(ValidityError, match="Johnson"):
        columns.johnson_critical_load("200 GPa", "300 MPa", A, I, "2 m")
    with pytest.raises(InputError):
        columns.euler_critical_load("200 GPa", I, "0 m")
    with pytest.raises(InputError):
        columns.end_condition_constant(-1.0)
    with pytest.raises(UnitError, match="length"):
        columns.euler_critical_load("200 GPa", I, 1.0)
    assert columns.euler_critical_load("200 GPa", I, "1 m", end=2.0) == 2 * columns.euler_critical_load(
        "200 GPa", I, "1 m")
