"""Seed 000's parallelogram lever arm: statics solver against virtual work and hand equilibrium.

* Virtual work (J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Statics*, 7th ed., Wiley,
  2012, Art. 7/3, Eq. 7/3): with the crank angles as generalised coordinates, the motor torques
  that hold a load F at C are tau_k = -F . dC/dq_k; dC/dq_k is taken here by finite differences of
  the forward kinematics, independent of the solver.
* Equilibrium of the levers IBC (about B), GAH and EAB (about A), Art. 4/6, gives the coupler forces
  (derived in ``lever_arm_closed_form``; the versions printed in seed 000, Eqs. 28-40, are wrong).

Dimensions of seed 000, Sec. 2.2: b = 200, c = 150, d = 50, p = q = r = 30 mm.
"""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mechverify import Q
from mechverify.mechanisms import LeverArm, lever_arm_closed_form

ARM = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")


def crank_angles(vp, ph, ps):
    """Absolute angles of the cranks OA, OD, OF from +u: pi - varphi, pi - phi, psi."""
    return math.pi - vp, math.pi - ph, ps


def tool_from_cranks(a):
    return ARM.forward(Q(math.pi - a[0], "rad"), Q(math.pi - a[1], "rad"), Q(a[2], "rad")).plane["C"]


def virtual_work_torques(vp, ph, ps, F, h=1e-7):
    a = np.array(crank_angles(vp, ph, ps))
    tau = []
    for k in range(3):
        da = np.zeros(3)
        da[k] = h
        dC = (tool_from_cranks(a + da) - tool_from_cranks(a - da)) / (2 * h)
        tau.append(-float(np.dot(F, dC)))
    return np.array(tau)


poses = st.tuples(st.floats(0.3, 1.4), st.floats(-0.6, 0.9), st.floats(-0.8, 0.8))


@settings(max_examples=40, deadline=None)
@given(poses, st.floats(1, 50))
def test_motor_torques_equal_virtual_work(angles, W):
    vp, ph, ps = angles
    pose = ARM.forward(Q(vp, "rad"), Q(ph, "rad"), Q(ps, "rad"))
    assume(min(ARM.singularity_measures(pose).values()) >= 0.05)
    sol = ARM.statics(pose, Q(W, "N")).solve()
    got = [sol.actuator_efforts[k].m_as("N*m") for k in ("shoulder", "elbow", "wrist")]
    np.testing.assert_allclose(got, virtual_work_torques(vp, ph, ps, np.array([0.0, -W])), rtol=1e-6, atol=1e-9)
    cf = lever_arm_closed_form(ARM, pose, Q(W, "N"))
    for k in ("HI", "FG", "DE"):
        assert sol.axial_forces[k].m_as("N") == pytest.approx(cf[k].m_as("N"), rel=1e-9)
    assert sol.residual_force.m_as("N") < 1e-9 * W


def test_self_weight_by_virtual_work():
    """Link masses: the gravity torques again equal -sum(m g . d(com)/dq), com = segment centroids."""
    masses = {"OA": 0.12, "EAB": 0.09, "IBC": 0.03, "DE": 0.05}
    vp, ph, ps = 1.1, 0.3, -0.2
    pose = ARM.forward(Q(vp, "rad"), Q(ph, "rad"), Q(ps, "rad"))
    sol = ARM.statics(pose, "0 N", masses={k: Q(v, "kg") for k, v in masses.items()}).solve()

    def potential(a):
        p = ARM.forward(Q(math.pi - a[0], "rad"), Q(math.pi - a[1], "rad"), Q(a[2], "rad")).plane
        segs = {"OA": [("O", "A")], "EAB": [("E", "A"), ("A", "B")], "IBC": [("B", "I"), ("B", "C")], "DE": [("D", "E")]}
        V = 0.0
        for body, m in masses.items():
            lens = [np.linalg.norm(p[b] - p[a_]) for a_, b in segs[body]]
            zc = sum(ln * (p[a_][1] + p[b][1]) / 2 for ln, (a_, b) in zip(lens, segs[body], strict=True)) / sum(lens)
            V += m * 9.80665 * zc
        return V

    a0, h = np.array(crank_angles(vp, ph, ps)), 1e-6
    expected = [(potential(a0 + h * e) - potential(a0 - h * e)) / (2 * h) for e in np.eye(3)]
    got = [sol.actuator_efforts[k].m_as("N*m") for k in ("shoulder", "elbow", "wrist")]
    np.testing.assert_allclose(got, expected, rtol=1e-6, atol=1e-9)


def test_seed_000_printed_shoulder_torque_is_wrong():
    """Seed 000 Eq. (36a): M_OA = [cos varphi + d sin(phi - varphi) cos psi / (r cos(phi + psi))] W d.
    The correct value is W b cos varphi (in magnitude)."""
    vp, ph, ps, W = math.radians(70), math.radians(20), math.radians(10), 10.0
    b, c, d, r = 0.2, 0.15, 0.05, 0.03
    pose = ARM.forward(Q(vp, "rad"), Q(ph, "rad"), Q(ps, "rad"))
    tau = ARM.statics(pose, Q(W, "N")).solve().actuator_efforts["shoulder"].m_as("N*m")
    assert abs(tau) == pytest.approx(W * b * math.cos(vp), rel=1e-9)  # 0.6840 N m
    printed = (math.cos(vp) + d * math.sin(ph - vp) * math.cos(ps) / (r * math.cos(ph + ps))) * W * d
    assert printed == pytest.approx(-0.5549, abs=1e-4)  # by hand: (0.3420 - 1.4518) * 0.5 N m; not 0.6840
    # the elbow and wrist torques of Eqs. (40a), (38a) are right in magnitude: W c cos phi, W d cos psi
    sol = ARM.statics(pose, Q(W, "N")).solve()
    assert abs(sol.actuator_efforts["elbow"].m_as("N*m")) == pytest.approx(W * c * math.cos(ph), rel=1e-9)
    assert abs(sol.actuator_efforts["wrist"].m_as("N*m")) == pytest.approx(W * d * math.cos(ps), rel=1e-9)
