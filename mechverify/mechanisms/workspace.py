"""Workspaces with joint limits and the payload the motors can hold over them (five-bar and lever-arm presets).

A workspace is sampled on a grid of tool positions; a point belongs to it when the inverse kinematics closes
(:class:`~mechverify.mechanisms.fivebar.FiveBar` or :class:`~mechverify.mechanisms.lever_arm.LeverArm`), every
joint angle lies within its limits and the pose is not within ``singular_tol`` of a singularity. Over those points
the motor holding torques per unit payload come from virtual work (five-bar: ``tau = -J^T F``,
:meth:`FiveBar.holding_torques`; lever arm: ``lever_arm_closed_form``, massless links), so the largest payload the
motors hold everywhere is, with the torques linear in the load,

    W_max = min over points and motors of T_motor / |tau per unit load|.

Limits are angle pairs (lo, hi); an angle is brought into the limits by whole turns when it can be.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.units import QuantityLike, fmt, from_si, to_si

#: joint names of each preset, in the order of its motors
FIVE_BAR_JOINTS = ("theta_left", "theta_right")
LEVER_ARM_JOINTS = ("shoulder", "elbow", "wrist")


def joint_limits(limits: Mapping[str, Sequence[QuantityLike]] | None, joints: Sequence[str]) -> dict[str, tuple]:
    """{joint: (lo, hi) [rad]} from angle pairs; unknown joint names and empty ranges are named."""
    out: dict[str, tuple[float, float]] = {}
    for k, v in (limits or {}).items():
        if k not in joints:
            raise InputError(f"joint limits: unknown joint {k!r} (joints: {', '.join(joints)})")
        if len(v) != 2:
            raise InputError(f"joint limits.{k}: expected (low, high), got {v!r}")
        lo, hi = to_si(v[0], "angle", f"{k} low"), to_si(v[1], "angle", f"{k} high")
        if not hi > lo:
            shown = ", ".join(x if isinstance(x, str) else fmt(x) if hasattr(x, "units") else f"{x:g}" for x in v)
            raise InputError(f"joint limits.{k}: low must be below high, got ({shown})")
        out[k] = (lo, hi)
    return out


def within(angle: float, lim: tuple[float, float] | None, tol: float = 1e-9) -> bool:
    """The angle (shifted by whole turns) inside [lo, hi]."""
    if lim is None:
        return True
    lo, hi = lim
    a = lo + (angle - lo) % (2 * math.pi)
    return a <= hi + tol or abs(a - 2 * math.pi - lo) <= tol


@dataclass(frozen=True)
class WorkspaceCapacity:
    """Grid points (SI), which belong to the limited workspace, the motor torque per unit load at each (N m per
    N, nan outside), and the largest load every motor holds everywhere with where it governs."""

    points: np.ndarray  # (n, 2) tool positions [m] in the preset's plane
    inside: np.ndarray  # bool (n,)
    excluded: dict[str, int]  # reason -> number of grid points left out (unreachable, limit, singular)
    torque_per_load: np.ndarray  # (n, motors) [m]
    motors: tuple[str, ...]
    max_load: float  # [N]
    governing_point: int
    governing_motor: str

    @property
    def fraction(self) -> float:
        """Share of the grid inside the limited workspace."""
        return float(np.mean(self.inside))


#: Largest grid points x motors of one workspace sweep. The sweep solves each point in Python (~0.2 ms a point on
#: a 2-core 2026 box, measured: n = 200, 40 000 points, 8.5 s) and holds ~100 bytes per value (positions, the
#: per-point arrays): 10^6 values is about 100 MB and under two minutes (five-bar n <= 707, lever arm n <= 577).
MAX_GRID_VALUES = 1_000_000


def check_grid_size(n: Any, motors: int, where: str = "n") -> int:
    """``n`` samples per axis as an int in [2, sqrt(MAX_GRID_VALUES / motors)]; a named InputError otherwise."""
    if isinstance(n, bool) or not isinstance(n, int | np.integer):
        raise InputError(f"{where}: expected a whole number of samples per axis, got {n!r}")
    if n < 2:
        raise InputError(f"{where}: need at least 2 samples per axis, got {n}")
    if n * n * motors > MAX_GRID_VALUES:
        top = math.isqrt(MAX_GRID_VALUES // motors)
        raise InputError(f"{where}: {n} samples per axis is {n * n} grid points x {motors} motors, more than the limit "
                         f"of {MAX_GRID_VALUES:,} values (memory and time of the sweep); use at most {top}")
    return int(n)


def _tol(singular_tol: Any) -> float:
    if isinstance(singular_tol, bool) or not isinstance(singular_tol, int | float) or not 0 <= singular_tol < 1:
        raise InputError(f"singular_tol: expected a number in [0, 1) (a singularity measure such as |sin|), got "
                         f"{singular_tol!r}")
    return float(singular_tol)


def _grid(x_range: Sequence[QuantityLike], y_range: Sequence[QuantityLike], n: int, motors: int = 2) -> np.ndarray:
    n = check_grid_size(n, motors)
    x0, x1 = (to_si(v, "length", "x_range") for v in x_range)
    y0, y1 = (to_si(v, "length", "y_range") for v in y_range)
    if x1 < x0 or y1 < y0:
        raise InputError("x_range/y_range: give (low, high) with low <= high")
    X, Y = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
    return np.c_[X.ravel(), Y.ravel()]


def _capacity(points: np.ndarray, per_load: list[np.ndarray | None], reasons: list[str], motors: tuple[str, ...],
              torques: Sequence[float]) -> WorkspaceCapacity:
    inside = np.array([p is not None for p in per_load])
    tpl = np.array([p if p is not None else np.full(len(motors), np.nan) for p in per_load])
    excluded = {r: reasons.count(r) for r in dict.fromkeys(reasons) if r}
    if not np.any(inside):
        raise InputError("no grid point lies in the workspace with these limits "
                         f"({', '.join(f'{k}: {v}' for k, v in excluded.items())})")
    T = np.asarray(torques, float)
    with np.errstate(divide="ignore"):
        cap = np.where(np.abs(tpl) > 0, T / np.abs(tpl), np.inf)  # load each motor holds at each point
    cap[~inside] = np.inf
    k = int(np.argmin(cap))
    i, j = divmod(k, len(motors))
    return WorkspaceCapacity(points, inside, excluded, tpl, motors, float(cap[i, j]), i, motors[j])


def five_bar_capacity(fb: Any, x_range: Sequence[QuantityLike], y_range: Sequence[QuantityLike],
                      motor_torques: Sequence[QuantityLike], *, direction: QuantityLike = "-90 deg", n: int = 31,
                      working_mode: str = "-+", limits: Mapping[str, Sequence[QuantityLike]] | None = None,
                      singular_tol: float = 0.05) -> WorkspaceCapacity:
    """Five-bar: the largest force along ``direction`` (angle from +x; -90 deg = a weight in a vertical plane) at
    the tool that both motors (``motor_torques`` left, right) hold at every point of the grid inside the
    workspace, the joint ``limits`` ({"theta_left": (lo, hi), ...}) and away from singularities (measures >
    ``singular_tol``)."""
    lim = joint_limits(limits, FIVE_BAR_JOINTS)
    singular_tol = _tol(singular_tol)
    T = [to_si(t, "torque", "motor_torques") for t in motor_torques]
    if len(T) != 2 or min(T) <= 0:
        raise InputError(f"motor_torques: give the two motors' holding torques (> 0), got {motor_torques!r}")
    a = to_si(direction, "angle", "direction")
    unit = (from_si(math.cos(a), "force"), from_si(math.sin(a), "force"))
    pts = _grid(x_range, y_range, n)
    per, reasons = [], []
    for x, y in pts:
        try:
            pose = fb.inverse((from_si(x, "length"), from_si(y, "length")), working_mode)
        except UnreachablePoseError:
            per.append(None)
            reasons.append("unreachable")
            continue
        th = (pose.theta_left.m_as("rad"), pose.theta_right.m_as("rad"))
        if not all(within(t, lim.get(j)) for t, j in zip(th, FIVE_BAR_JOINTS, strict=True)):
            per.append(None)
            reasons.append("outside the joint limits")
            continue
        m = fb.singularity_measures(pose)
        if min(m.values()) <= singular_tol:
            per.append(None)
            reasons.append("near a singularity")
            continue
        tl, tr = fb.holding_torques(pose, unit)
        per.append(np.array([tl.m_as("N*m"), tr.m_as("N*m")]))
        reasons.append("")
    return _capacity(pts, per, reasons, FIVE_BAR_JOINTS, T)


def lever_arm_capacity(arm: Any, u_range: Sequence[QuantityLike], z_range: Sequence[QuantityLike],
                       motor_torques: Sequence[QuantityLike], *, wrist: QuantityLike = "0 deg", n: int = 31,
                       elbow_branch: str = "up", limits: Mapping[str, Sequence[QuantityLike]] | None = None,
                       singular_tol: float = 0.05) -> WorkspaceCapacity:
    """Lever arm: the largest weight at C that the shoulder, elbow and wrist motors (``motor_torques`` in that
    order) hold at every point of the (u, z) grid in the arm plane with the wrist at ``wrist``, inside the
    joint ``limits`` ({"shoulder": (lo, hi), ...}) and away from flattened parallelograms (|sin| > ``singular_tol``)."""
    lim = joint_limits(limits, LEVER_ARM_JOINTS)
    singular_tol = _tol(singular_tol)
    T = [to_si(t, "torque", "motor_torques") for t in motor_torques]
    if len(T) != 3 or min(T) <= 0:
        raise InputError(f"motor_torques: give the shoulder, elbow and wrist holding torques (> 0), got "
                         f"{motor_torques!r}")
    from mechverify.mechanisms.lever_arm import lever_arm_closed_form

    pts = _grid(u_range, z_range, n, 3)
    per, reasons = [], []
    for u, z in pts:
        try:
            pose = arm.inverse((from_si(u, "length"), from_si(0.0, "length"), from_si(z, "length")), wrist,
                               elbow_branch)
        except UnreachablePoseError:
            per.append(None)
            reasons.append("unreachable")
            continue
        ang = (pose.shoulder.m_as("rad"), pose.elbow.m_as("rad"), pose.wrist.m_as("rad"))
        if not all(within(t, lim.get(j)) for t, j in zip(ang, LEVER_ARM_JOINTS, strict=True)):
            per.append(None)
            reasons.append("outside the joint limits")
            continue
        try:
            arm.check_singularity(pose, singular_tol)
        except SingularPoseError:
            per.append(None)
            reasons.append("near a singularity")
            continue
        f = lever_arm_closed_form(arm, pose, "1 N")
        per.append(np.array([f[k].m_as("N*m") for k in LEVER_ARM_JOINTS]))
        reasons.append("")
    return _capacity(pts, per, reasons, LEVER_ARM_JOINTS, T)


__all__ = ["WorkspaceCapacity", "five_bar_capacity", "lever_arm_capacity", "joint_limits", "within",
           "FIVE_BAR_JOINTS", "LEVER_ARM_JOINTS"]
