"""Pose sweeps: governing poses against closed forms; hand-off to the motor-fit load model."""

import math

import numpy as np
import pytest

from mechverify import Q
from mechverify.errors import ModelError
from mechverify.mechanisms import FiveBar, LeverArm, lever_arm_closed_form, sweep_statics
from mechverify.mechanisms.adapters import rotary_load

ARM = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")
W = Q(20, "N")


def arm_poses():
    return [ARM.forward(Q(vp, "deg"), Q(ph, "deg"), Q(ps, "deg"))
            for vp in (40, 60, 80, 100) for ph in (-20, 10, 35) for ps in (-30, 0, 30)]


def test_lever_arm_governing_poses_match_closed_form():
    poses = arm_poses()
    res = sweep_statics(poses, lambda p: ARM.statics(p, W))
    act = res.actuator_demands()
    # closed forms: |tau_shoulder| = W b |cos varphi| peaks at varphi = 40 deg (of the sampled values)
    assert act["shoulder"].peak.m_as("N*m") == pytest.approx(20 * 0.2 * math.cos(math.radians(40)), rel=1e-9)
    assert "varphi=40.0 deg" in act["shoulder"].peak_pose
    assert act["wrist"].peak.m_as("N*m") == pytest.approx(20 * 0.05, rel=1e-9)  # psi = 0
    expected = max(abs(lever_arm_closed_form(ARM, p, W)["HI"].m_as("N")) for p in poses)
    mem = res.member_demands()
    got = max(mem["HI"].tension.m_as("N"), mem["HI"].compression.m_as("N"))
    assert got == pytest.approx(expected, rel=1e-9)
    assert abs(mem["HI"].axial.m_as("N")) == pytest.approx(expected, rel=1e-9)
    assert len(act["elbow"].series.magnitude) == len(poses)


def test_five_bar_path_sweep_and_singular_poses():
    fb = FiveBar(*["100 mm"] * 5)
    pts = [(Q(x, "mm"), Q(150, "mm")) for x in np.linspace(-20, 120, 15)]
    poses = [fb.inverse(p, "-+") for p in pts]
    F = (Q(0, "N"), Q(-10, "N"))
    res = sweep_statics(poses, lambda p: fb.statics(p, F))
    tau = [abs(fb.holding_torques(p, F)[0].m_as("N*m")) for p in poses]
    assert res.actuator_demands()["motor_left"].peak.m_as("N*m") == pytest.approx(max(tau), rel=1e-9)
    assert res.actuator_demands()["motor_left"].peak_pose == poses[int(np.argmax(tau))].label()
    singular = fb.forward("120 deg", "60 deg")
    with pytest.raises(ModelError, match="pose theta_left=120.00"):
        sweep_statics([poses[0], singular], lambda p: fb.statics(p, F))
    res2 = sweep_statics([poses[0], singular], lambda p: fb.statics(p, F), skip_singular=True)
    assert len(res2.solutions) == 1 and len(res2.skipped) == 1


def test_rotary_load_adapter():
    res = sweep_statics(arm_poses()[:3], lambda p: ARM.statics(p, W))
    load = rotary_load(res.actuator_demands()["elbow"], inertia="1e-4 kg*m**2")
    assert load.external_torque.m_as("N*m") == pytest.approx(20 * 0.15 * math.cos(math.radians(20)), rel=1e-9)
