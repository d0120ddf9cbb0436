"""Five-bar and lever-arm presets: forward/inverse round trips, branches, reachability, singularities."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, reject, settings
from hypothesis import strategies as st

from mechverify import Q
from mechverify.errors import InputError, ModelError, UnitError
from mechverify.mechanisms import FiveBar, LeverArm, SingularPoseError, UnreachablePoseError

FB = FiveBar("100 mm", "100 mm", "100 mm", "100 mm", "100 mm")
FB2 = FiveBar("80 mm", "120 mm", "150 mm", "140 mm", "110 mm")
ARM = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")


def _angdiff(a, b):
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))


@settings(max_examples=60, deadline=None)
@given(st.floats(-3.1, 3.1), st.floats(-3.1, 3.1), st.sampled_from("+-"), st.sampled_from([FB, FB2]))
def test_five_bar_round_trip(t1, t2, asm, fb):
    try:
        pose = fb.forward(Q(t1, "rad"), Q(t2, "rad"), asm)
    except UnreachablePoseError:
        reject()
    assume(min(fb.singularity_measures(pose).values()) > 1e-3)
    assert pose.assembly_mode == asm
    back = fb.inverse(pose.tool, pose.working_mode)
    assert _angdiff(back.theta_left.m_as("rad"), t1) < 1e-9
    assert _angdiff(back.theta_right.m_as("rad"), t2) < 1e-9
    assert np.linalg.norm(back.P - pose.P) < 1e-12
    assert back.assembly_mode == asm


def test_five_bar_working_modes_give_four_solutions():
    P = (Q(50, "mm"), Q(120, "mm"))
    poses = {m: FB.inverse(P, m) for m in ("++", "+-", "-+", "--")}
    assert {p.working_mode for p in poses.values()} == {"++", "+-", "-+", "--"}
    for p in poses.values():
        assert np.linalg.norm(p.P - np.array([0.05, 0.12])) < 1e-12
        assert math.dist(p.B1, p.A1) == pytest.approx(0.1) and math.dist(p.B1, p.P) == pytest.approx(0.1)


def test_five_bar_reachability_errors():
    with pytest.raises(UnreachablePoseError, match=r"left leg: cannot close.*0 to 200 mm"):
        FB.inverse((Q(-150, "mm"), Q(150, "mm")), "-+")
    with pytest.raises(UnreachablePoseError, match="forward kinematics"):
        FB.forward("180 deg", "0 deg")  # elbows 300 mm apart, distal links reach 200 mm
    with pytest.raises(InputError, match="working_mode"):
        FB.inverse((Q(50, "mm"), Q(120, "mm")), "+")
    with pytest.raises(UnitError, match="theta_left"):
        FB.forward(90, "90 deg")
    with pytest.raises(InputError, match="base"):
        FiveBar("0 mm", "1 mm", "1 mm", "1 mm", "1 mm")


def test_five_bar_type2_singularity():
    """theta = 120/60 deg: elbows 200 mm apart, the distal links aligned (Merlet 2006, Sec. 6.2)."""
    pose = FB.forward("120 deg", "60 deg")
    assert FB.singularity_measures(pose)["type2"] < 1e-6
    with pytest.raises(SingularPoseError, match="type-2"):
        FB.holding_torques(pose, ("0 N", "-1 N"))
    with pytest.raises(ModelError, match="singular configuration"):
        FB.statics(pose, ("0 N", "-1 N")).solve()


def test_five_bar_type1_singularity_check():
    pose = FB.inverse((Q(200, "mm"), Q(0, "mm")), "-+")  # left leg fully stretched along +x
    with pytest.raises(SingularPoseError, match="type-1 .* left leg"):
        FB.check_singularity(pose)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.1, 2.0), st.floats(-1.2, 1.2), st.floats(-1.5, 1.5), st.floats(-3.0, 3.0))
def test_lever_arm_round_trip(vp, ph, ps, th):
    pose = ARM.forward(Q(vp, "rad"), Q(ph, "rad"), Q(ps, "rad"), Q(th, "rad"))
    A, B, C = pose.plane["A"], pose.plane["B"], pose.plane["C"]
    assume(abs(A[0] * B[1] - A[1] * B[0]) > 1e-6 and abs(C[0]) > 1e-6)
    elbow = "up" if (B[0] * A[1] - B[1] * A[0]) > 0 else "down"
    base = "front" if C[0] > 0 else "back"
    back = ARM.inverse(pose.tool, Q(ps, "rad"), elbow_branch=elbow, base_branch=base)
    for got, want in ((back.shoulder, vp), (back.elbow, ph), (back.wrist, ps), (back.base, th)):
        assert _angdiff(got.m_as("rad"), want) < 1e-9
    np.testing.assert_allclose(back.tool.m_as("m"), pose.tool.m_as("m"), atol=1e-12)


def test_lever_arm_geometry_is_parallelograms():
    pose = ARM.forward("75 deg", "15 deg", "20 deg", "10 deg")
    p = pose.plane
    np.testing.assert_allclose(p["E"] - p["D"], p["A"] - p["O"], atol=1e-15)  # OAED
    np.testing.assert_allclose(p["G"] - p["F"], p["A"] - p["O"], atol=1e-15)  # OFGA
    np.testing.assert_allclose(p["I"] - p["H"], p["B"] - p["A"], atol=1e-15)  # ABIH
    assert np.dot(p["G"] - p["A"], p["H"] - p["A"]) == pytest.approx(0.0, abs=1e-15)  # angle GAH = 90 deg
    x, y, z = pose.tool.m_as("m")
    assert math.atan2(y, x) == pytest.approx(math.radians(10))


def test_lever_arm_reach_and_branch_errors():
    with pytest.raises(UnreachablePoseError, match=r"out of reach.*50 to 350 mm"):
        ARM.inverse((Q(401, "mm"), Q(0, "mm"), Q(0, "mm")), "0 deg")  # 400 mm is on the boundary: reachable
    with pytest.raises(UnreachablePoseError):
        ARM.inverse((Q(60, "mm"), Q(0, "mm"), Q(0, "mm")), "0 deg")  # B 10 mm from O: inside the dead zone
    with pytest.raises(InputError, match="elbow_branch"):
        ARM.inverse((Q(200, "mm"), Q(0, "mm"), Q(0, "mm")), "0 deg", elbow_branch="left")
    up = ARM.inverse((Q(200, "mm"), Q(0, "mm"), Q(50, "mm")), "0 deg", "up")
    down = ARM.inverse((Q(200, "mm"), Q(0, "mm"), Q(50, "mm")), "0 deg", "down")
    assert up.plane["A"][1] > down.plane["A"][1]


def test_lever_arm_flattened_parallelogram():
    pose = ARM.forward("60 deg", "60 deg", "0 deg")  # OD parallel to OA: OAED flat
    with pytest.raises(SingularPoseError, match="OAED"):
        ARM.check_singularity(pose)
    with pytest.raises(ModelError, match="cannot solve"):
        ARM.statics(pose, "10 N").solve()
