"""Paths at constant speed and the RP arm's kinematics and dynamics (mechverify.mechanisms.paths).

Sources: closed forms (a circle walked at speed v: |a| = v^2/R; polar kinematics of the RP arm), Lagrange's
equations for the polar RP arm (Spong, Hutchinson & Vidyasagar, Robot Modeling and Control, Sec. 7.3) checked
against an independent d'Alembert (Newton) solution and the power balance tau1 q1' + F2 q2' = d(T + V)/dt by
finite differences of the energy. The clover r = 8 - 1.5 cos(4 phi) cm at 1.4 cm/s is seed 003's path; every
expected value here is a hand calculation or an independent numerical integral, not a printed value.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.paths import RPArm, walk_polar


def clover(phi):
    return 0.08 - 0.015 * np.cos(4 * phi)


ARM = RPArm(reach_min="0.2 m", reach_max="0.6 m", carriage_mass="98 g", arm_inertia="0.026 kg*m^2",
            arm_mass="0.3 kg", arm_com="0.2 m")


def test_circle_walked_at_constant_speed():
    """r = R: period 2 pi R / v, |v| = v, |a| = v^2/R towards the centre (closed form)."""
    R, v = 0.05, 0.014
    p = walk_polar(lambda ph: np.full_like(ph, R), "1.4 cm/s", centre=(0.1, 0.2), samples=200)
    assert p.length == pytest.approx(2 * math.pi * R, rel=1e-9)
    assert p.t[-1] == pytest.approx(2 * math.pi * R / v, rel=1e-9)
    assert np.hypot(p.vx, p.vy) == pytest.approx(np.full(201, v), rel=1e-8)
    assert np.hypot(p.ax, p.ay) == pytest.approx(np.full(201, v * v / R), rel=1e-6)
    # centripetal: a . (p - c) = -v^2
    assert p.ax * (p.x - 0.1) + p.ay * (p.y - 0.2) == pytest.approx(np.full(201, -v * v), rel=1e-6)


def test_clover_length_speed_and_no_tangential_acceleration():
    """Arc length by an independent adaptive integral of sqrt(r^2 + r'^2); constant speed means |v| = v and
    a . v = 0 at every sample."""
    L, _ = quad(lambda ph: math.hypot(clover(ph), 0.06 * math.sin(4 * ph)), 0, 2 * math.pi, limit=200)
    p = walk_polar(clover, "1.4 cm/s", centre=(0.125, 0.375), samples=400)
    assert p.length == pytest.approx(L, rel=1e-8)
    assert np.hypot(p.vx, p.vy) == pytest.approx(np.full(401, 0.014), rel=1e-7)
    amax = float(np.max(np.hypot(p.ax, p.ay)))
    assert np.max(np.abs(p.ax * p.vx + p.ay * p.vy)) < 1e-6 * amax * 0.014


def test_rp_inverse_on_a_circle_about_the_axis():
    """Circle of radius R about the revolute axis at speed v: q2 = R, q2' = 0, q1' = v/R, q1'' = 0; then
    tau1 = (m_a r_a + m R) g cos q1, F2 = -m R (v/R)^2 + m g sin q1 (Lagrange, closed form)."""
    R, v, m, g = 0.3, 0.014, 0.098, 9.80665
    p = walk_polar(lambda ph: np.full_like(ph, R), "1.4 cm/s", phi_range=(0.0, math.pi), samples=50)
    j = ARM.inverse(p)
    assert j.q2 == pytest.approx(np.full(51, R), rel=1e-12)
    assert j.dq1 == pytest.approx(np.full(51, v / R), rel=1e-8)
    assert np.max(np.abs(j.dq2)) < 1e-12 and np.max(np.abs(j.ddq1)) < 1e-9
    tau, F = ARM.joint_loads(j)
    assert tau == pytest.approx((0.3 * 0.2 + m * R) * g * np.cos(j.q1), abs=1e-9)
    assert F == pytest.approx(-m * R * (v / R) ** 2 + m * g * np.sin(j.q1), abs=1e-9)


def test_lagrange_equals_dalembert_on_the_clover():
    """d'Alembert: the carriage needs F = m (a + g j); along the arm F2 = F . e_r, about the axis its moment is
    q2 F . e_theta, plus J q1'' and the arm's weight moment m_a r_a g cos q1. Independent of the Lagrange form."""
    p = walk_polar(clover, "1.4 cm/s", centre=(0.125, 0.375), samples=400)
    j = ARM.inverse(p)
    tau, F2 = ARM.joint_loads(j)
    m, g = 0.098, 9.80665
    Fx, Fy = m * p.ax, m * (p.ay + g)
    er = np.stack([np.cos(j.q1), np.sin(j.q1)])
    et = np.stack([-np.sin(j.q1), np.cos(j.q1)])
    F2_n = Fx * er[0] + Fy * er[1]
    tau_n = j.q2 * (Fx * et[0] + Fy * et[1]) + 0.026 * j.ddq1 + 0.3 * 0.2 * g * np.cos(j.q1)
    assert F2 == pytest.approx(F2_n, rel=1e-9, abs=1e-12)
    assert tau == pytest.approx(tau_n, rel=1e-9, abs=1e-12)


def test_power_balance_by_finite_differences_of_the_energy():
    """tau1 q1' + F2 q2' = d(T + V)/dt, the derivative by central differences of the energy along a fast walk
    (10x the document's speed, so the dynamic terms matter)."""
    p = walk_polar(clover, "14 cm/s", centre=(0.125, 0.375), samples=20000)
    j = ARM.inverse(p)
    tau, F2 = ARM.joint_loads(j)
    power = tau * j.dq1 + F2 * j.dq2
    dE = np.gradient(ARM.energy(j), p.t)
    assert power[5:-5] == pytest.approx(dE[5:-5], abs=1e-4 * float(np.max(np.abs(power))))


def test_unreachable_and_singular_samples_are_named():
    p = walk_polar(clover, "1.4 cm/s", centre=(0.125, 0.375), samples=100)
    with pytest.raises(UnreachablePoseError, match="sample 0 .*outside the stroke"):
        RPArm(reach_max="0.3 m").inverse(p)
    with pytest.raises(SingularPoseError, match="revolute axis"):
        RPArm().inverse(walk_polar(lambda ph: np.full_like(ph, 0.05), "1 cm/s", centre=(0.05, 0.0), samples=8))
