"""Paths walked in time (Cartesian, sampled points, a trapezoidal speed profile) and the RR arm; joint limits.

Sources: closed forms (circle: |a| = v^2/R; trapezoidal move: Biagiotti & Melchiorri, Trajectory Planning for
Automatic Machines and Robots, 2008, Sec. 3.2, t_a = v/a, T = L/v + v/a); the planar elbow manipulator's Lagrange
equations (Spong, Hutchinson & Vidyasagar, Robot Modeling and Control, Sec. 7.4.2) checked against the power
balance tau . q' = d(T + V)/dt with T + V computed from the centres of mass' velocities (independent of the d_ij
terms), and the static gravity torques in closed form. Body inertias: the standard table forms (rod about its end
m L^2/3, seed 003 Eq. 8: 1/3 0.099 0.25^2 = 2.06e-3 kg m^2; hand calculation, the document prints 2.1e-3).
Every expected value is a hand calculation, not a printed value, unless named.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.paths import (
    LinkBody,
    RPArm,
    RRArm,
    Timing,
    compose_bodies,
    curve_length,
    spline_through,
    walk_curve,
    walk_polar,
)


def circle(R, xc=0.0, yc=0.0):
    return lambda u: (xc + R * np.cos(u), yc + R * np.sin(u))


def test_cartesian_circle_equals_closed_form():
    """x = R cos u, y = R sin u at v: |v| = v, |a| = v^2/R, a . (p - c) = -v^2, length 2 pi R."""
    R, v = 0.05, 0.02
    p = walk_curve(circle(R, 0.3, 0.1), (0.0, 2 * math.pi), "2 cm/s", samples=100)
    assert p.length == pytest.approx(2 * math.pi * R, rel=1e-9)
    assert np.hypot(p.vx, p.vy) == pytest.approx(np.full(101, v), rel=1e-8)
    assert np.hypot(p.ax, p.ay) == pytest.approx(np.full(101, v * v / R), rel=1e-6)
    assert p.ax * (p.x - 0.3) + p.ay * (p.y - 0.1) == pytest.approx(np.full(101, -v * v), rel=1e-6)


def test_trapezoidal_timing_along_a_line():
    """A 0.3 m line walked from rest to rest, v = 0.1 m/s, a = 0.5 m/s^2: t_a = v/a = 0.2 s, T = L/v + v/a = 3.2 s
    (Biagiotti & Melchiorri Sec. 3.2); the tool's velocity is along the line with the profile's speed."""
    from mechverify.motion.profiles import trapezoidal
    from mechverify.units import Q

    def line(u):
        return 0.1 + 0.3 * u * 0.6, 0.2 + 0.3 * u * 0.8

    def timing(length):
        prof = trapezoidal(Q(length, "m"), max_velocity="0.1 m/s", acceleration="0.5 m/s^2")
        t = np.linspace(0, prof.duration.m_as("s"), 321)
        s = prof.at(Q(t, "s"))
        return Timing(t, s["x"].m_as("m"), s["v"].m_as("m/s"), s["a"].m_as("m/s^2"))

    p = walk_curve(line, (0.0, 1.0), timing=timing)
    assert p.length == pytest.approx(0.3, rel=1e-9)
    assert p.t[-1] == pytest.approx(0.3 / 0.1 + 0.1 / 0.5)
    speed = np.hypot(p.vx, p.vy)
    assert speed[0] == pytest.approx(0, abs=1e-12) and speed[-1] == pytest.approx(0, abs=1e-9)
    assert speed.max() == pytest.approx(0.1, rel=1e-9)
    assert p.vx * 0.8 - p.vy * 0.6 == pytest.approx(np.zeros(321), abs=1e-10)  # along the line
    i = int(np.searchsorted(p.t, 0.1))  # accelerating: |a| = 0.5 along the line
    assert math.hypot(p.ax[i], p.ay[i]) == pytest.approx(0.5, rel=1e-6)


def test_timing_longer_than_the_path_is_named():
    with pytest.raises(Exception, match="outside the path's length"):
        walk_curve(circle(0.05), (0, math.pi), timing=Timing(np.array([0, 1.0]), np.array([0, 1.0]),
                                                             np.zeros(2), np.zeros(2)))


def test_spline_through_circle_points_approaches_the_circle():
    """A periodic cubic spline through 48 points of a circle: length within 1e-5 of 2 pi R (spline error
    O(h^4)), speed constant to 1e-3, |a| = v^2/R to 1 %."""
    R = 0.05
    u = np.linspace(0, 2 * math.pi, 48, endpoint=False)
    curve, rng = spline_through(np.c_[R * np.cos(u), R * np.sin(u)], closed=True)
    assert curve_length(curve, rng) == pytest.approx(2 * math.pi * R, rel=1e-5)
    p = walk_curve(curve, rng, "1 cm/s", samples=200)
    assert np.hypot(p.vx, p.vy) == pytest.approx(np.full(201, 0.01), rel=1e-3)
    assert np.hypot(p.ax, p.ay) == pytest.approx(np.full(201, 0.01**2 / R), rel=0.01)


def test_spline_repeated_point_is_named():
    with pytest.raises(Exception, match="point 2 repeats"):
        spline_through(np.array([[0, 0], [1, 0], [1, 0], [2, 1.0]]))


# ---------------------------------------------------------------- RR arm
ARM = RRArm("0.3 m", "0.25 m", link1_mass="1 kg", link2_mass="0.8 kg", link1_inertia="0.01 kg*m^2",
            link2_inertia="0.005 kg*m^2", payload="0.5 kg")


def clover(ph):
    return 0.08 - 0.015 * np.cos(4 * ph)


def test_rr_inverse_round_trip_and_rates():
    """Forward kinematics of the inverse returns the path; J q' = v; both elbow branches."""
    p = walk_polar(clover, "5 cm/s", centre=(0.3, 0.2), samples=1500)
    for elbow in ("down", "up"):
        arm = RRArm("0.3 m", "0.25 m", elbow=elbow)
        j = arm.inverse(p)
        x, y = arm.forward(j.q1, j.q2)
        assert np.max(np.abs(x - p.x)) < 1e-12 and np.max(np.abs(y - p.y)) < 1e-12
        assert np.all(j.q2 > 0) if elbow == "down" else np.all(j.q2 < 0)
        l1, l2 = 0.3, 0.25
        vx = -l1 * np.sin(j.q1) * j.dq1 - l2 * np.sin(j.q1 + j.q2) * (j.dq1 + j.dq2)
        vy = l1 * np.cos(j.q1) * j.dq1 + l2 * np.cos(j.q1 + j.q2) * (j.dq1 + j.dq2)
        assert vx == pytest.approx(p.vx, abs=1e-12) and vy == pytest.approx(p.vy, abs=1e-12)
        # accelerations: finite differences of the exact rates
        ddq1 = np.gradient(j.dq1, j.t, edge_order=2)
        assert np.max(np.abs(ddq1 - j.ddq1)[2:-2]) < 1e-3 * np.max(np.abs(j.ddq1))


def test_rr_lagrange_power_balance():
    """tau1 q1' + tau2 q2' = d(T + V)/dt (energy from the centres of mass' velocities), gravity on and off,
    at 50 cm/s (inertial terms dominate without gravity): relative error < 1e-3 of the peak power."""
    p = walk_polar(clover, "50 cm/s", centre=(0.3, 0.2), samples=4000)
    for g in ("9.80665 m/s^2", "0 m/s^2"):
        arm = RRArm("0.3 m", "0.25 m", link1_mass="1 kg", link2_mass="0.8 kg", link1_inertia="0.01 kg*m^2",
                    link2_inertia="0.005 kg*m^2", payload="0.5 kg", gravity=g)
        j = arm.inverse(p)
        t1, t2 = arm.joint_loads(j)
        P = t1 * j.dq1 + t2 * j.dq2
        dE = np.gradient(arm.energy(j), j.t, edge_order=2)
        assert np.max(np.abs(P - dE)) < 1e-3 * np.max(np.abs(P))
    # dropping the Coriolis/centripetal terms breaks the balance (the test can fail)
    h = -(0.8 + 0.5) * 0.3 * ((0.8 * 0.125 + 0.5 * 0.25) / 1.3) * np.sin(j.q2)
    P_wrong = (t1 - 2 * h * j.dq1 * j.dq2 - h * j.dq2**2) * j.dq1 + (t2 + h * j.dq1**2) * j.dq2
    assert np.max(np.abs(P_wrong - dE)) > 1e-2 * np.max(np.abs(P))


def test_rr_static_gravity_torques():
    """At rest (one point), arm horizontal, elbow at 90 deg: tau2 = (m2 lc2 + mp l2) g cos(q1 + q2) = 0 and
    tau1 = (m1 lc1 + (m2 + mp) l1) g; with q2 = 0 impossible (singular), use q1 = 0, q2 = 90 deg."""
    from mechverify.mechanisms.paths import JointMotion

    z = np.zeros(1)
    m = JointMotion(z, z, np.array([math.pi / 2]), z, z, z, z)
    t1, t2 = ARM.joint_loads(m)
    g = 9.80665
    assert t1[0] == pytest.approx((1 * 0.15 + 1.3 * 0.3) * g, rel=1e-12)
    assert t2[0] == pytest.approx(0.0, abs=1e-12)
    m = JointMotion(z, np.array([math.pi / 2]), np.array([-math.pi / 2]), z, z, z, z)  # link 1 up, link 2 right
    t1, t2 = ARM.joint_loads(m)
    assert t2[0] == pytest.approx((0.8 * 0.125 + 0.5 * 0.25) * g, rel=1e-12)
    assert t1[0] == pytest.approx(t2[0], rel=1e-12)


def test_rr_unreachable_and_singular_samples_are_named():
    """A circle of radius 0.6 m > l1 + l2 = 0.55 m; a path through the stretched pose (|p| = l1 + l2)."""
    p = walk_polar(lambda ph: np.full_like(ph, 0.6), "5 cm/s", samples=20)
    with pytest.raises(UnreachablePoseError, match=r"sample 0 .*reach 50 to 550 mm"):
        ARM.inverse(p)
    line = walk_curve(lambda u: (0.4 + 0.2 * u, 0 * u), (0.0, 1.0), "1 cm/s", samples=20)  # passes x = 0.55
    with pytest.raises((SingularPoseError, UnreachablePoseError), match=r"sample 15 "):
        ARM.inverse(line)
    stretched = walk_curve(lambda u: (0.45 + 0.1 * u, 0 * u), (0.0, 1.0), "1 cm/s", samples=10)  # ends at 0.55
    with pytest.raises(SingularPoseError, match=r"sample 10 .*stretched"):
        ARM.inverse(stretched)


def test_joint_limits_name_the_first_sample():
    """RP arm with q1 in [0, 70 deg] on the clover (q1 57.9 to 83.3 deg): the first sample above 70 deg is named."""
    p = walk_polar(clover, "1.4 cm/s", centre=(0.125, 0.375), samples=400)
    q1 = np.degrees(np.arctan2(p.y, p.x))
    first = int(np.argmax(q1 > 70 + 1e-9))
    arm = RPArm(reach_max="0.6 m", q1_min="0 deg", q1_max="70 deg")
    with pytest.raises(UnreachablePoseError, match=rf"sample {first} .*q1 = .*outside its limits 0 to 70 deg"):
        arm.inverse(p)
    ok = RPArm(reach_max="0.6 m", q1_min="-360 deg", q1_max="-270 deg").inverse(p)  # one turn down
    assert np.degrees(ok.q1[0]) == pytest.approx(q1[0] - 360)


def test_document_q2_domain_does_not_hold_its_own_path():
    """Seed 003: Eq. 27's domain q2 in [22, 44] cm vs the clover of Eq. 3 and 5 (pen 30.9-48.4 cm from the axis)."""
    p = walk_polar(clover, "1.4 cm/s", centre=(0.125, 0.375), samples=400)
    first = int(np.argmax(np.hypot(p.x, p.y) > 0.44))
    with pytest.raises(UnreachablePoseError, match=rf"sample {first} .*outside the stroke 220 to 440 mm"):
        RPArm(reach_min="22 cm", reach_max="44 cm").inverse(p)


def test_link_bodies_standard_forms():
    """Rod from the joint: m L^2/3 (seed 003 Eq. 8: 2.0625e-3 kg m^2, printed 2.1e-3); a rod starting 0.1 m out:
    m L^2/12 + m (0.1 + L/2)^2; point: m s^2; solid cylinder along the link: m (3 r^2 + L^2)/12 + m c^2."""
    m, c, J = compose_bodies([LinkBody("rod", "99 g", "25 cm")])
    assert (m, c, J) == pytest.approx((0.099, 0.125, 0.099 * 0.25**2 / 3))
    assert J == pytest.approx(2.1e-3, rel=0.02)
    _, _, J = compose_bodies([LinkBody("rod", "1 kg", "0.2 m", start="0.1 m")])
    assert J == pytest.approx(0.2**2 / 12 + 0.2**2)
    m, c, J = compose_bodies([LinkBody("point", "2 kg", start="0.3 m"), LinkBody("cylinder", "1 kg", "0.2 m",
                                                                                   radius="0.05 m")])
    assert m == 3 and c == pytest.approx((0.6 + 0.1) / 3)
    assert J == pytest.approx(2 * 0.09 + (3 * 0.05**2 + 0.04) / 12 + 0.01)
    with pytest.raises(Exception, match="radius"):
        compose_bodies([LinkBody("tube", "1 kg", "0.2 m")])


# ---------------------------------------------------------------- five-bar along a path
def test_five_bar_along_a_circle_rates_and_payload_power():
    """Seed 002's five-bar (all links 100 mm) on a circle: the exact motor rates and accelerations (velocity
    equation and its derivative) agree with finite differences of the inverse kinematics (second order in the
    800-sample step: 2e-3 of the peak rate, 1e-2 of the peak acceleration); the payload
    torques (virtual work, d'Alembert force m (g - a)) satisfy tau . q' = d/dt (m v^2/2 + m g y) (1e-3)."""
    from mechverify.mechanisms.fivebar import FiveBar
    from mechverify.mechanisms.paths import five_bar_inverse, five_bar_payload_torques

    fb = FiveBar("100 mm", "100 mm", "100 mm", "100 mm", "100 mm")
    p = walk_polar(lambda ph: 0.03 + 0.01 * np.cos(3 * ph), "10 cm/s", centre=(0.05, 0.12), samples=800)
    j = five_bar_inverse(fb, p)
    for q, dq, ddq in ((j.q1, j.dq1, j.ddq1), (j.q2, j.dq2, j.ddq2)):
        assert np.max(np.abs(np.gradient(q, j.t, edge_order=2) - dq)) < 2e-3 * np.max(np.abs(dq))
        assert np.max(np.abs(np.gradient(dq, j.t, edge_order=2) - ddq)[2:-2]) < 1e-2 * np.max(np.abs(ddq))
    tl, tr = five_bar_payload_torques(fb, p, j, "0.5 kg")
    E = 0.5 * 0.5 * (p.vx**2 + p.vy**2) + 0.5 * 9.80665 * p.y
    P = tl * j.dq1 + tr * j.dq2
    assert np.max(np.abs(P - np.gradient(E, p.t, edge_order=2))) < 1e-3 * np.max(np.abs(P))


def test_five_bar_path_errors_name_the_sample():
    """A circle leaving the reach (|P - A1| > 200 mm) and a limit on the left motor: the first sample is named."""
    from mechverify.mechanisms.fivebar import FiveBar
    from mechverify.mechanisms.paths import five_bar_inverse

    fb = FiveBar("100 mm", "100 mm", "100 mm", "100 mm", "100 mm")
    far = walk_polar(lambda ph: np.full_like(ph, 0.06), "10 cm/s", centre=(0.05, 0.15), samples=100)
    with pytest.raises(UnreachablePoseError, match=r"sample \d+ \(t = .* is out of reach"):
        five_bar_inverse(fb, far)
    p = walk_polar(lambda ph: np.full_like(ph, 0.03), "10 cm/s", centre=(0.05, 0.12), samples=100)
    j = five_bar_inverse(fb, p)
    top = float(np.degrees(np.max(j.q1)))
    first = int(np.argmax(np.degrees(j.q1) > top - 5))
    with pytest.raises(UnreachablePoseError, match=rf"sample {first} .*theta_left"):
        five_bar_inverse(fb, p, limits={"theta_left": ("0 deg", f"{top - 5} deg")})
