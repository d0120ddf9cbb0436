"""The two fatigue-strength paths of ``check_fatigue`` a user reaches besides the Sut estimate: a fatigue
strength given by the user (``Se``) and the material's S-N table (``sn_curve``).

Expected values are hand calculations from the formulas, on data read from their sources:
- Goodman, Shigley 10th ed. Eq. (6-41): 1/n_f = sigma_a/Se + sigma_m/Sut; Langer first-cycle yield,
  Eq. (6-49): n_y = Sy/(sigma_a + sigma_m);
- the S-N table of "ANSYS Structural Steel" (mechverify/materials/data/fea_tool_defaults.toml: ANSYS
  Engineering Data, from 1998 ASME BPV Code Sec. VIII Div. 2 Table 5-110.1; Sut = 460 MPa, Sy = 250 MPa),
  interpolated log-log between its points as ANSYS does: S(N) = S1 (N/N1)^(log(S2/S1)/log(N2/N1)).
None of these are printed results of a worked example.
"""

import math

import pytest

from mechverify.checks.fatigue import check_fatigue
from mechverify.errors import InputError, ValidityError

STEEL = "ANSYS Structural Steel"  # Sut 460 MPa, Sy 250 MPa


def test_user_given_endurance_limit_goodman():
    """Se = 150 MPa given: 1/n = 60/150 + 40/460 -> n_f = 2.054; Langer n_y = 250/100 = 2.5; fatigue governs."""
    r = check_fatigue("shaft", "60 MPa", "40 MPa", STEEL, Se="150 MPa", criterion="goodman")
    hand = 1 / (60 / 150 + 40 / 460)
    assert hand == pytest.approx(2.0536, abs=1e-4)
    assert r.safety_factor == pytest.approx(hand, rel=1e-9)
    assert r.details["n_yield"] == pytest.approx(2.5)
    assert r.details["governing_mode"] == "fatigue"
    assert "given by the user" in r.source and any("150 MPa given" in n for n in r.notes)


def test_user_given_endurance_limit_with_kf_and_langer_governing():
    """Kf = 1.5 multiplies both stresses: 1/n_f = 1.5(60/400 + 90/460) -> n_f = 1.929; Langer
    n_y = 250/(1.5·150) = 1.111 governs."""
    r = check_fatigue("shaft", "60 MPa", "90 MPa", STEEL, Se="400 MPa", Kf=1.5, criterion="goodman")
    n_f = 1 / (1.5 * (60 / 400 + 90 / 460))
    n_y = 250 / (1.5 * 150)
    assert r.details["n_fatigue"] == pytest.approx(n_f, rel=1e-9)
    assert r.safety_factor == pytest.approx(n_y, rel=1e-9)
    assert r.details["governing_mode"] != "fatigue"


def test_user_given_endurance_limit_must_be_positive():
    with pytest.raises(InputError, match="Se"):
        check_fatigue("shaft", "60 MPa", "0 MPa", STEEL, Se="0 MPa")


def test_sn_table_finite_life_log_log_interpolation():
    """N = 5e4 between the table points (2e4, 214 MPa) and (1e5, 138 MPa): S = 214 (2.5)^(log(138/214)/log 5)
    = 166.7 MPa; fully reversed 100 MPa -> n_f = 1.667."""
    S = 214 * (5e4 / 2e4) ** (math.log(138 / 214) / math.log(1e5 / 2e4))
    assert S == pytest.approx(166.70, abs=0.01)
    r = check_fatigue("shaft", "100 MPa", "0 MPa", STEEL, life=5e4)
    assert r.details["fatigue_strength"].m_as("MPa") == pytest.approx(S, rel=1e-9)
    assert r.safety_factor == pytest.approx(S / 100, rel=1e-9)
    assert any("S-N table" in n for n in r.notes)


def test_sn_table_at_a_table_point_and_beyond_the_last():
    """At N = 1e5 the table's 138 MPa; beyond 1e6 cycles ANSYS holds the last value, 86.2 MPa (also for
    infinite life)."""
    r = check_fatigue("shaft", "50 MPa", "0 MPa", STEEL, life=1e5)
    assert r.details["fatigue_strength"].m_as("MPa") == pytest.approx(138, rel=1e-9)
    for life in (1e7, None):
        r = check_fatigue("shaft", "50 MPa", "0 MPa", STEEL, life=life)
        assert r.details["fatigue_strength"].m_as("MPa") == pytest.approx(86.2, rel=1e-9)
        assert r.safety_factor == pytest.approx(86.2 / 50, rel=1e-9)


def test_sn_table_with_mean_stress_goodman():
    """Infinite life, S = 86.2 MPa: 1/n = 40/86.2 + 30/460 -> n_f = 1.891."""
    r = check_fatigue("shaft", "40 MPa", "30 MPa", STEEL, criterion="goodman")
    assert r.safety_factor == pytest.approx(1 / (40 / 86.2 + 30 / 460), rel=1e-9)


def test_sn_table_below_its_first_life_is_a_validity_error():
    """The table starts at 10 cycles: a shorter life is outside the data."""
    with pytest.raises(ValidityError, match="starts at 10 cycles"):
        check_fatigue("shaft", "50 MPa", "0 MPa", STEEL, life=5)


def test_user_se_takes_precedence_over_the_sn_table():
    r_table = check_fatigue("shaft", "50 MPa", "0 MPa", STEEL)
    r_user = check_fatigue("shaft", "50 MPa", "0 MPa", STEEL, Se="100 MPa")
    assert r_table.safety_factor == pytest.approx(86.2 / 50)
    assert r_user.safety_factor == pytest.approx(100 / 50)
