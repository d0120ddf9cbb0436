"""Motion profiles: exact distances (hypothesis), closed-form trapezoid timing, impossible profiles.

Closed forms: Biagiotti & Melchiorri, Trajectory Planning for Automatic Machines and Robots (2008),
§3.2 eqs. 3.8-3.12 (trapezoid: T = D/v + v/a; triangle: v_peak = sqrt(D·a)) and §3.4 (double S).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechverify.errors import InputError, UnitError
from mechverify.motion.profiles import dwell, s_curve, sampled, sequence, trapezoidal, triangular
from mechverify.units import Q

pos = st.floats(min_value=1e-3, max_value=1e3, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(D=pos, v=pos, a=pos)
def test_trapezoid_reaches_distance_exactly(D, v, a):
    p = trapezoidal(Q(D, "mm"), max_velocity=Q(v, "mm/s"), acceleration=Q(a, "mm/s**2"))
    x, vend, aend = p.end_state
    assert x == pytest.approx(D * 1e-3, rel=1e-12, abs=1e-15)
    assert vend == pytest.approx(0.0, abs=1e-9 * v * 1e-3)
    s = p.sample()
    assert np.max(np.abs(s.v)) <= v * 1e-3 * (1 + 1e-9)
    assert np.max(np.abs(s.a)) <= a * 1e-3 * (1 + 1e-9)


@settings(max_examples=60, deadline=None)
@given(D=pos, T=st.floats(min_value=0.01, max_value=100), k=st.floats(min_value=1.0, max_value=50))
def test_trapezoid_with_duration_and_acceleration(D, T, k):
    a = k * 4 * D / T**2  # k >= 1: reachable
    p = trapezoidal(Q(D, "m"), duration=Q(T, "s"), acceleration=Q(a, "m/s**2"))
    assert p.duration.m_as("s") == pytest.approx(T, rel=1e-9)
    assert p.end_state[0] == pytest.approx(D, rel=1e-9)


@settings(max_examples=40, deadline=None)
@given(D=pos, v=pos, a=pos, jr=st.floats(min_value=0.1, max_value=100))
def test_s_curve_reaches_distance_within_limits(D, v, a, jr):
    J = jr * a
    p = s_curve(Q(-D, "deg"), max_velocity=Q(v, "deg/s"), acceleration=Q(a, "deg/s**2"), jerk=Q(J, "deg/s**3"))
    assert p.distance.m_as("deg") == pytest.approx(-D, rel=1e-9)
    s = p.sample()
    assert np.max(np.abs(s.v)) <= math.radians(v) * (1 + 1e-6)
    assert np.max(np.abs(s.a)) <= math.radians(a) * (1 + 1e-6)
    assert abs(s.v[-1]) <= 1e-6 * math.radians(v)


def test_trapezoid_closed_form_timing():
    # D = 100 mm, v = 50 mm/s, a = 200 mm/s^2: T = D/v + v/a = 2 + 0.25 = 2.25 s [Biagiotti eq. 3.10]
    p = trapezoidal("100 mm", max_velocity="50 mm/s", acceleration="200 mm/s**2")
    assert p.duration.m_as("s") == pytest.approx(2.25, rel=1e-12)
    assert p.reached_max_velocity


def test_short_move_becomes_triangular():
    # D = 1 mm < v^2/a = 12.5 mm: v_peak = sqrt(D a) = sqrt(1*200) = 14.14 mm/s, T = 2 sqrt(D/a)
    p = trapezoidal("1 mm", max_velocity="50 mm/s", acceleration="200 mm/s**2")
    assert not p.reached_max_velocity
    assert p.peak_velocity.m_as("mm/s") == pytest.approx(math.sqrt(200), rel=1e-9)
    assert p.duration.m_as("s") == pytest.approx(2 * math.sqrt(1 / 200), rel=1e-9)
    with pytest.raises(InputError, match="too short to reach max_velocity"):
        trapezoidal("1 mm", max_velocity="50 mm/s", acceleration="200 mm/s**2", allow_triangular=False)


def test_triangular_from_duration():
    p = triangular("90 deg", duration="1 s")
    assert p.peak_acceleration.m_as("rad/s**2") == pytest.approx(4 * math.pi / 2, rel=1e-12)
    assert p.peak_velocity.m_as("rad/s") == pytest.approx(math.pi, rel=1e-9)


def test_sequence_and_dwell():
    out = trapezoidal("50 mm", max_velocity="100 mm/s", acceleration="1 m/s**2")
    back = trapezoidal("-50 mm", max_velocity="100 mm/s", acceleration="1 m/s**2")
    cyc = sequence(out, dwell("0.5 s"), back, dwell("0.5 s"))
    assert cyc.distance.m_as("mm") == pytest.approx(0.0, abs=1e-12)
    assert cyc.duration.m_as("s") == pytest.approx(2 * out.duration.m_as("s") + 1.0, rel=1e-12)
    assert cyc.at("1.0 s")["x"].m_as("mm") == pytest.approx(50.0, rel=1e-9)
    assert "dwell" in cyc.sample().labels


def test_sampled_profile_derivatives():
    t = np.linspace(0, 1, 201)
    p = sampled(Q(t, "s"), Q(0.5 * 2.0 * t**2, "m"))  # x = a t^2 / 2, a = 2 m/s^2
    s = p.sample()
    assert np.allclose(s.a, 2.0, rtol=1e-6)
    assert s.v[-1] == pytest.approx(2.0, rel=1e-6)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"duration": "1 s", "acceleration": "0.2 m/s**2"}, "not reachable in 1 s"),
    ({"duration": "1 s", "max_velocity": "0.05 m/s"}, "not reachable in 1 s"),
    ({"duration": "1 s", "max_velocity": "0.5 m/s"}, "between D/T"),
    ({"max_velocity": "0.05 m/s"}, "exactly two"),
])
def test_impossible_trapezoids(kwargs, message):
    with pytest.raises(InputError, match=message):
        trapezoidal("100 mm", **kwargs)


def test_bad_inputs():
    with pytest.raises(UnitError, match="max_velocity"):
        trapezoidal("100 mm", max_velocity="1 rad/s", acceleration="1 m/s**2")
    with pytest.raises(InputError, match="distance"):
        trapezoidal("0 mm", max_velocity="1 m/s", acceleration="1 m/s**2")
    with pytest.raises(InputError, match="strictly increasing"):
        sampled(Q([0, 1, 1], "s"), Q([0, 1, 2], "mm"))
    with pytest.raises(InputError, match="mix linear and rotary"):
        sequence(trapezoidal("1 mm", max_velocity="1 m/s", acceleration="1 m/s**2"), triangular("1 deg", duration="1 s"))
