"""Lead-screw checks: friction choice per question, orientation of demand/capacity, verdicts.

Numbers come from Shigley's Mechanical Engineering Design, 9th ed., Example 8-1 (square thread
32 x 4 mm, double, f = 0.08, F = 6.4 kN: not self-locking, T_L thread = -0.466 N m, tau = 6.07 MPa,
sigma = 10.39 MPa) and Hamrock et al., Fundamentals of Machine Elements, 3rd ed., Problem 16.1.
"""

import math

import pytest

from mechverify.checks.result import Verdict
from mechverify.checks.screws import (
    check_holding_torque,
    check_nut_flank_pressure,
    check_nut_pv,
    check_screw_buckling,
    check_screw_critical_speed,
    check_screw_strength,
    check_self_locking,
)
from mechverify.components.power_screw import LeadScrew, Nut, ball_nut
from mechverify.components.threads import ball_screw, square
from mechverify.errors import InputError
from mechverify.materials.material import Material

STEEL = Material("test steel", "steel", E="207 GPa", nu=0.3, density="7850 kg/m^3", yield_strength="300 MPa",
                 ultimate_strength="500 MPa")


@pytest.fixture
def shigley():
    return LeadScrew(square("32 mm", "4 mm", starts=2), "500 mm", STEEL, "fixed-pinned", name="screw")


def test_self_locking_uses_mu_min(shigley):
    """Shigley Ex. 8-1: at f = 0.08 'the screw alone is not self-locking' (tan(lambda) = 8/(30 pi) = 0.0849)."""
    r = check_self_locking(shigley, Nut(length="20 mm", mu_min=0.08, mu_max=0.30))
    assert r.verdict is Verdict.FAIL
    assert r.demand.m_as("deg") == pytest.approx(math.degrees(math.atan(8 / (30 * math.pi))))
    assert r.capacity.m_as("deg") == pytest.approx(math.degrees(math.atan(0.08)))
    assert "0.08 used (lowest" in r.notes[0]
    assert r.details["self_locking_mu"].m_as("") == pytest.approx(8 / (30 * math.pi))


def test_holding_torque_demand_is_minus_lowering_torque(shigley):
    """Shigley Ex. 8-1 (b): thread lowering torque -0.466 N m -> 0.466 N m must be held."""
    nut = Nut(length="20 mm", mu_min=0.08, mu_max=0.30)
    r = check_holding_torque(shigley, nut, "6.4 kN", "0.4 N*m")
    assert r.demand.m_as("N*m") == pytest.approx(0.466, abs=5e-4)
    assert r.verdict is Verdict.FAIL
    assert check_holding_torque(shigley, nut, "6.4 kN", "1 N*m").verdict is Verdict.PASS


def test_strength_uses_mu_max_or_given_torque(shigley):
    """Shigley Ex. 8-1 (d): with T = 26.18 N m, tau = 6.07, sigma = 10.39 MPa -> sqrt(s^2 + 3 t^2)."""
    r = check_screw_strength(shigley, "6.4 kN", torque="26.18 N*m")
    assert r.demand.m_as("MPa") == pytest.approx(math.hypot(10.39, math.sqrt(3) * 6.07), abs=0.01)
    lo = check_screw_strength(shigley, "6.4 kN", nut=Nut(length="20 mm", mu_min=0.08, mu_max=0.08))
    hi = check_screw_strength(shigley, "6.4 kN", nut=Nut(length="20 mm", mu_min=0.08, mu_max=0.2))
    assert hi.demand > lo.demand
    assert "highest" in hi.notes[0]


def test_flank_pressure_and_pv(shigley):
    nut = Nut(length="20 mm", mu=0.1, p_allow="10 MPa", pv_allow="1 MPa*m/s")
    r = check_nut_flank_pressure(shigley, nut, "6.4 kN")
    # n = 20/4 = 5 turns, H1 = 2 mm, d2 = 30 mm
    assert r.demand.m_as("MPa") == pytest.approx(6400 / (math.pi * 30 * 2 * 5))
    pv = check_nut_pv(shigley, nut, "6.4 kN", rotational_speed="100 rpm")
    v = math.pi * 0.030 * 100 / 60 / math.cos(math.atan(8 / (30 * math.pi)))
    assert pv.demand.m_as("MPa*m/s") == pytest.approx(r.demand.m_as("MPa") * v)
    by_speed = check_nut_pv(shigley, nut, "6.4 kN", speed="800 mm/min").demand  # 100 rpm x 8 mm lead
    assert by_speed.m_as("MPa*m/s") == pytest.approx(pv.demand.m_as("MPa*m/s"))


def test_buckling_and_critical_speed_report_end_case(shigley):
    b = check_screw_buckling(shigley, "6.4 kN")
    assert "fixed-pinned" in b.notes[0] and "C = 1.2" in b.notes[0]
    assert b.required_sf == 2.0
    c = check_screw_critical_speed(shigley, "1000 rpm")
    assert "lambda_1 = 3.9266" in c.notes[0]
    assert c.required_sf == 1.25


def test_ball_nut_has_no_flank_pressure():
    s = LeadScrew(ball_screw("16 mm", "5 mm", "12.9 mm"), "400 mm", STEEL)
    nut = ball_nut(length="40 mm", p_allow="10 MPa")
    with pytest.raises(InputError, match="ball nut"):
        check_nut_flank_pressure(s, nut, "1 kN")
    # THK: positive efficiency (1 - mu tan b)/(1 + mu/tan b), mu = 0.003..0.01
    tb = 5 / (math.pi * 16)
    assert s.efficiency(nut.mu_max).m_as("") == pytest.approx((1 - 0.01 * tb) / (1 + 0.01 / tb))
    assert check_self_locking(s, nut).verdict is Verdict.FAIL


def test_bad_inputs(shigley):
    with pytest.raises(InputError, match="magnitude"):
        check_screw_buckling(shigley, "-1 kN")
    with pytest.raises(InputError, match="exactly one"):
        check_nut_pv(shigley, Nut(length="20 mm", mu=0.1, pv_allow="1 MPa*m/s"), "1 kN")
    with pytest.raises(InputError, match="friction"):
        check_self_locking(shigley, Nut(length="20 mm"))
