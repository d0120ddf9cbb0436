"""Five-bar (DexTAR-type) kinematics and statics against closed-form configurations.

Closed forms used (J.-P. Merlet, *Parallel Robots*, 2nd ed., Springer, 2006, Sec. 3.1 and 6.1-6.2;
statics of two-force members, Meriam & Kraige, *Statics*, 7th ed., Art. 4/6):

* symmetric pose of an equal-link five-bar (all links l, base l, cranks vertical): P = (l/2,
  l + l sin 60 deg); a vertical load W is shared equally by the distal links, each in compression
  W / (2 sin 60 deg), and each motor holds W l cos 60 deg / (2 sin 60 deg);
* fully extended legs (seed 002's "critical pose", both chains straight): P lies at distance 2l
  from both motor axes, P = (l/2, sqrt(4 l^2 - l^2/4)); theta_left = atan2(y, l/2); the motors
  hold no torque for any in-plane force (type-1 singularity of both legs) and the legs carry it as
  two struts;
* virtual work: the solver's motor torques equal -J^T F with J from the loop-closure Jacobian.
"""

import math

import numpy as np
import pytest
from hypothesis import assume, given, reject, settings
from hypothesis import strategies as st

from mechverify import Q
from mechverify.mechanisms import FiveBar
from mechverify.mechanisms.errors import UnreachablePoseError

L = 0.1  # seed 002: all five lengths 100 mm
FB = FiveBar(*["100 mm"] * 5)


def test_symmetric_pose_closed_form():
    pose = FB.forward("90 deg", "90 deg", "+")
    assert pose.P * 1e3 == pytest.approx([50.0, 100 + 100 * math.sin(math.radians(60))], abs=1e-9)
    assert pose.working_mode == "-+"  # seed 002's working mode: theta2 > theta3, theta5 < theta4
    W = 10.0
    sol = FB.statics(pose, ("0 N", f"-{W} N")).solve()
    comp = W / (2 * math.sin(math.radians(60)))
    assert sol.axial_forces["distal_right"].m_as("N") == pytest.approx(-comp, rel=1e-12)
    assert sol.member_loads["distal_left"].axial.m_as("N") == pytest.approx(-comp, rel=1e-12)
    tau = W * L * math.cos(math.radians(60)) / (2 * math.sin(math.radians(60)))
    assert sol.actuator_efforts["motor_left"].m_as("N*m") == pytest.approx(-tau, rel=1e-12)
    assert sol.actuator_efforts["motor_right"].m_as("N*m") == pytest.approx(tau, rel=1e-12)


def test_fully_extended_pose_of_seed_002():
    y = math.sqrt((2 * L) ** 2 - (L / 2) ** 2)
    pose = FB.inverse((Q(50, "mm"), Q(y, "m")), "-+")
    # the correct critical angles; seed 002 prints theta2 = 76.4 deg, theta5 = 103.6 deg
    assert pose.theta_left.m_as("deg") == pytest.approx(math.degrees(math.atan2(y, L / 2)), abs=1e-6)
    assert pose.theta_left.m_as("deg") == pytest.approx(75.5225, abs=1e-4)
    assert pose.theta_right.m_as("deg") == pytest.approx(104.4775, abs=1e-4)
    m = FB.singularity_measures(pose)
    assert m["type1_left"] < 1e-6 and m["type1_right"] < 1e-6
    F = np.array([3.0, -7.0])
    sol = FB.statics(pose, (Q(F[0], "N"), Q(F[1], "N"))).solve()
    assert abs(sol.actuator_efforts["motor_left"].m_as("N*m")) < 1e-9
    assert abs(sol.actuator_efforts["motor_right"].m_as("N*m")) < 1e-9
    u1 = pose.P / np.linalg.norm(pose.P)
    u2 = (pose.P - pose.A2) / np.linalg.norm(pose.P - pose.A2)
    c1, c2 = np.linalg.solve(np.column_stack([u1, u2]), -F)  # compressions: c1 u1 + c2 u2 + F = 0
    assert sol.member_loads["crank_left"].axial.m_as("N") == pytest.approx(-c1, rel=1e-9)
    assert sol.axial_forces["distal_right"].m_as("N") == pytest.approx(-c2, rel=1e-9)


def test_seed_002_printed_critical_angles_do_not_extend_the_legs():
    pose = FB.forward("76.4 deg", "103.6 deg")
    bend = pose.theta_distal_left.m_as("deg") - 76.4
    assert bend == pytest.approx(-1.76, abs=0.01)  # each leg still bent by 1.76 deg at the printed angles
    assert pose.P[1] * 1e3 == pytest.approx(193.62, abs=0.01)  # vs 193.65 mm fully extended


def _fd_jacobian(t1, t2, asm="+", h=1e-7):
    def P(a, b):
        return FB.forward(Q(a, "rad"), Q(b, "rad"), asm).P
    return np.column_stack([(P(t1 + h, t2) - P(t1 - h, t2)) / (2 * h), (P(t1, t2 + h) - P(t1, t2 - h)) / (2 * h)])


angles = st.tuples(st.floats(0.3, 2.6), st.floats(0.5, 2.9))


@settings(max_examples=40, deadline=None)
@given(angles, st.floats(-20, 20), st.floats(-20, 20))
def test_virtual_work_oracle(ts, fx, fy):
    t1, t2 = ts
    try:
        pose = FB.forward(Q(t1, "rad"), Q(t2, "rad"))
    except UnreachablePoseError:  # outside the workspace: not this property's concern
        reject()
    m = FB.singularity_measures(pose)
    assume(min(m.values()) >= 0.05)  # away from singular poses, where finite differences lose accuracy
    J = _fd_jacobian(t1, t2)
    np.testing.assert_allclose(FB.jacobian(pose).m_as("m"), J, rtol=1e-5, atol=1e-9)
    sol = FB.statics(pose, (Q(fx, "N"), Q(fy, "N"))).solve()
    tau = -J.T @ np.array([fx, fy])
    got = [sol.actuator_efforts["motor_left"].m_as("N*m"), sol.actuator_efforts["motor_right"].m_as("N*m")]
    np.testing.assert_allclose(got, tau, rtol=1e-5, atol=1e-8)
    np.testing.assert_allclose([t.m_as("N*m") for t in FB.holding_torques(pose, (Q(fx, "N"), Q(fy, "N")))], tau,
                               rtol=1e-5, atol=1e-8)


def test_workspace_matches_reach_circles():
    """Equal links: a leg reaches P iff |P - A_i| <= 2 l (and > 0)."""
    ws = FB.workspace(("-100 mm", "200 mm"), ("0 mm", "200 mm"), n=31)
    x, y = ws.x.m_as("m"), ws.y.m_as("m")
    r1, r2 = np.hypot(x, y), np.hypot(x - L, y)
    clear = (np.abs(r1 - 2 * L) > 1e-6) & (np.abs(r2 - 2 * L) > 1e-6) & (r1 > 1e-9) & (r2 > 1e-9)
    expected = (r1 < 2 * L) & (r2 < 2 * L)
    assert np.array_equal(ws.reachable[clear], expected[clear])
    assert np.all(np.isnan(ws.type2[~ws.reachable]))
