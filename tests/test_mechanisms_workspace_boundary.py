"""A point exactly on the workspace boundary is reachable (issue 20): the closure tolerates round-off.

Closed form (hand calculation, not a printed value): a five-bar leg of crank l1 and distal link l2 reaches
|P - A1| = l1 + l2 only stretched, crank and distal link collinear, theta = atan2(P); the lever arm's wrist
pivot B reaches |B| = b + c only with OA and AB collinear. The points below are chosen so that, computed in
floating point, they land an ulp OUTSIDE the boundary (the case that raised "cannot close" before); they
must assemble, and a point 1e-6 beyond must still be a reach error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechverify.mechanisms import FiveBar, LeverArm, UnreachablePoseError
from mechverify.units import Q


def _fivebar_outside_by_roundoff(n: int = 4) -> list[float]:
    """Angles in (0, 55) deg whose float point 0.2 (cos a, sin a) has hypot > 0.2 (round-off outside)."""
    out = []
    for k in range(1, 5000):
        a = math.radians(55.0 * k / 5000)
        if float(np.hypot(0.2 * math.cos(a), 0.2 * math.sin(a))) > 0.2:
            out.append(a)
        if len(out) == n:
            break
    return out


@pytest.mark.parametrize("a", _fivebar_outside_by_roundoff())
def test_fivebar_point_on_the_outer_boundary_is_reachable(a):
    fb = FiveBar(*(["100 mm"] * 5))
    P = 0.2 * np.array([math.cos(a), math.sin(a)])
    assert float(np.hypot(*P)) > 0.2  # the point is (by round-off) outside the reach l1 + l2
    pose = fb.inverse(Q(P, "m"), "-+")
    assert pose.theta_left.m_as("rad") == pytest.approx(a, abs=1e-6)  # stretched leg: crank along A1 -> P
    far = 0.2 * (1 + 1e-6) * np.array([math.cos(a), math.sin(a)])
    with pytest.raises(UnreachablePoseError, match="cannot close"):
        fb.inverse(Q(far, "m"), "-+")


def _lever_outside_by_roundoff(n: int = 3) -> list[float]:
    out = []
    for k in range(1, 5000):
        a = math.radians(80.0 * k / 5000)
        C = (0.35 * math.cos(a) + 0.05, 0.35 * math.sin(a))
        if math.hypot(C[0] - 0.05, C[1]) > 0.35:  # as LeverArm.inverse computes t with psi = 0
            out.append(a)
        if len(out) == n:
            break
    return out


@pytest.mark.parametrize("a", _lever_outside_by_roundoff())
def test_lever_arm_tool_on_the_reach_boundary_is_reachable(a):
    arm = LeverArm(b="200 mm", c="150 mm", d="50 mm", p="30 mm", q="30 mm", r="30 mm")
    C = np.array([0.35 * math.cos(a) + 0.05, 0.0, 0.35 * math.sin(a)])
    pose = arm.inverse(Q(C, "m"), "0 deg")
    assert np.asarray(pose.tool.m_as("m")) == pytest.approx(C, abs=1e-6)
    C_far = np.array([0.35 * (1 + 1e-6) * math.cos(a) + 0.05, 0.0, 0.35 * (1 + 1e-6) * math.sin(a)])
    with pytest.raises(UnreachablePoseError):
        arm.inverse(Q(C_far, "m"), "0 deg")


def test_the_boundary_cases_exist():
    """The parametrised cases are not empty (else the tests above would pass vacuously)."""
    assert len(_fivebar_outside_by_roundoff()) == 4 and len(_lever_outside_by_roundoff()) == 3
