"""Power screws: properties that must hold for any thread and friction, conversions, and bad input."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mechverify.components.power_screw import (
    LeadScrew,
    Nut,
    backdrive_efficiency,
    efficiency,
    lower_torque,
    nut_length_required,
    raise_torque,
    reflected_inertia,
    self_locking_mu,
)
from mechverify.components.threads import acme, generic, thread, trapezoidal
from mechverify.errors import InputError, UnitError, UnknownNameError, ValidityError
from mechverify.units import Q

leads = st.floats(0.5, 40.0)  # mm
diams = st.floats(5.0, 60.0)  # mm
flanks = st.sampled_from([0.0, 14.5, 15.0, 30.0])
mus = st.floats(0.0, 0.5)


@settings(max_examples=150, deadline=None)
@given(lead=leads, d2=diams, flank=flanks, mu=st.floats(0.001, 0.5))
def test_raise_exceeds_lower(lead, d2, flank, mu):
    """T_R > T_L wherever the thread can be driven; where it wedges (cos(alpha_n) - mu tan(lambda) <= 0,
    computed here independently: lambda = atan(l/(pi d2)), alpha_n = atan(tan(alpha) cos(lambda)), Shigley
    Sec. 8-2, Hamrock Eq. 16.8) the formula raises ValidityError instead of returning a number."""
    l, d, a = lead * 1e-3, d2 * 1e-3, math.radians(flank)
    lam = math.atan(l / (math.pi * d))
    wedges = math.cos(math.atan(math.tan(a) * math.cos(lam))) - mu * math.tan(lam) <= 0
    if wedges:
        with pytest.raises(ValidityError, match="wedges"):
            raise_torque.si(100.0, d, l, mu, a)
        return
    assert raise_torque.si(100.0, d, l, mu, a) > lower_torque.si(100.0, d, l, mu, a)


@settings(max_examples=150, deadline=None)
@given(lead=leads, d2=diams, flank=flanks)
def test_lower_torque_changes_sign_at_self_locking_mu(lead, d2, flank):
    l, d, a = lead * 1e-3, d2 * 1e-3, math.radians(flank)
    mu_star = self_locking_mu.si(d, l, a)
    assume(mu_star < 1.0)  # friction coefficients above 1 are outside the accepted range
    assert lower_torque.si(100.0, d, l, mu_star, a) == pytest.approx(0.0, abs=1e-12)
    assert lower_torque.si(100.0, d, l, mu_star * 1.001 + 1e-9, a) > 0
    if mu_star > 1e-6:
        assert lower_torque.si(100.0, d, l, mu_star * 0.999, a) < 0
        assert backdrive_efficiency.si(d, l, mu_star * 0.999, a) > 0
    assert backdrive_efficiency.si(d, l, mu_star * 1.001 + 1e-9, a) == 0.0


@settings(max_examples=100, deadline=None)
@given(lead=leads, d2=diams, flank=flanks)
def test_frictionless_screw_is_ideal(lead, d2, flank):
    """mu = 0: T_R = F l / (2 pi) and e = 1 (energy balance, Shigley 9th ed., Eq. 8-4 with f = 0)."""
    l, d, a = lead * 1e-3, d2 * 1e-3, math.radians(flank)
    assert raise_torque.si(100.0, d, l, 0.0, a) == pytest.approx(100.0 * l / (2 * math.pi), rel=1e-12)
    assert efficiency.si(d, l, 0.0, a) == pytest.approx(1.0, rel=1e-12)


def test_speed_rpm_resolution_inertia():
    s = LeadScrew("Tr10x2", "450 mm")
    assert s.linear_speed("540 rpm").m_as("mm/s") == pytest.approx(18.0)
    assert s.rotational_speed("18 mm/s").m_as("rpm") == pytest.approx(540.0)
    assert s.resolution("1.8 deg").m_as("mm") == pytest.approx(0.01)
    assert s.resolution("1.8 deg", microsteps=16).m_as("mm") == pytest.approx(0.01 / 16)
    # m (l / 2 pi)^2 for 98 g on an 8 mm lead
    assert reflected_inertia("98 g", "8 mm").m_as("kg*m**2") == pytest.approx(0.098 * (0.008 / (2 * math.pi)) ** 2)


def test_nut_length_required_meets_both_limits():
    L = nut_length_required("350 N", "9 mm", "1 mm", "2 mm", "23 MPa", "0.27 MPa*m/s", "0.2551 m/s")
    p_lim = 0.27 / 0.2551
    assert L.m_as("mm") == pytest.approx(2 * 350 / (math.pi * 9 * 1 * p_lim), rel=1e-9)


def test_generic_thread_catalogue_screw():
    t = generic("8 mm", 4, "7 mm", "15 deg", d="8 mm")
    assert t.pitch.m_as("mm") == pytest.approx(2.0)
    assert t.lead.m_as("mm") == pytest.approx(8.0)
    assert t.d3.m_as("mm") == pytest.approx(8 - 2 - 0.5)
    assert any("assumed" in n for n in t.notes)


def test_acme_preferred_pitches():
    """Shigley 9th ed., Table 8-3: 1/2 in -> p = 1/10 in; 2 in -> 1/4 in; 3 in -> 1/2 in."""
    assert thread("1/2-10 ACME").pitch.m_as("in") == pytest.approx(0.1)
    assert thread("2-4 ACME").pitch.m_as("in") == pytest.approx(0.25)
    assert acme("3 in", 2).flank_angle.m_as("deg") == pytest.approx(14.5)
    t = thread("1/2-0.1P-0.2L-ACME")
    assert t.starts == 2


# ---------------------------------------------------------------------- bad input
def test_unknown_designation_suggests():
    with pytest.raises(UnknownNameError) as info:
        thread("Tr10x4")
    assert "Tr10x2" in info.value.suggestions
    with pytest.raises(UnknownNameError, match="unknown thread 'M10'"):
        thread("M10")
    with pytest.raises(UnknownNameError, match="1/2-10 ACME"):
        thread("1/2-12 ACME")


def test_lead_not_a_multiple_of_pitch():
    with pytest.raises(InputError, match="whole multiple"):
        thread("Tr16x6P4")


def test_negative_length():
    with pytest.raises(InputError, match="length: must be positive"):
        LeadScrew("Tr10x2", "-450 mm")
    with pytest.raises(InputError, match="nut.length: must be positive"):
        Nut(length="-10 mm", mu=0.1)


def test_mu_range_reversed():
    with pytest.raises(InputError, match="friction range reversed"):
        Nut(length="15 mm", mu_min=0.25, mu_max=0.09)


def test_units_and_missing_data():
    with pytest.raises(UnitError, match="length"):
        LeadScrew("Tr10x2", 450)
    with pytest.raises(InputError, match="no material"):
        LeadScrew("Tr10x2", "450 mm").critical_speed()
    with pytest.raises(InputError, match="engaged"):
        Nut(mu=0.1).engaged(thread("Tr10x2"))
    with pytest.raises(InputError, match="collar"):
        raise_torque("1 kN", "9 mm", "2 mm", 0.1, "15 deg", 0.1)
    with pytest.raises(UnknownNameError, match="end condition"):
        LeadScrew("Tr10x2", "450 mm", end_supports="glued-free")
    with pytest.raises(UnknownNameError, match="trapezoidal"):
        trapezoidal("13 mm", "2 mm")


def test_quantity_api_accepts_strings():
    t = raise_torque("350 N", "9 mm", "2 mm", "0.25", "15 deg")
    assert t.units == Q(1, "N*m").units
