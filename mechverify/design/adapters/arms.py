"""``planar_arm`` (an RP or RR arm walking a path) and the ``joint_motion`` profile that hands a joint to a drive.

The arm's ``path`` table: a polar curve ``r`` in ``phi`` (``"8 cm - 1.5 cm * cos(4*phi)"``) about ``centre``,
a Cartesian curve ``x``, ``y`` in ``u``, or sampled ``points`` (a C2 spline through them); walked at constant
``speed``, or from rest to rest with a trapezoidal speed profile when ``acceleration`` is given too. Parsing only:
the arm, its motion, efforts and inertias are :mod:`mechverify.mechanisms.arm_on_path` (``rp_arm_on_path``,
``rr_arm_on_path``, ``five_bar_on_path``; kinematics and dynamics in :mod:`mechverify.mechanisms.paths`).

A profile ``{ type = "joint_motion", mechanism = "arm", joint = "q1" }`` is the joint's motion along the path
together with the joint's effort from the arm's dynamics (Lagrange); a ``drive`` on that profile adds it to its
own load, so the motor checks follow from the path. Outputs: ``q1_peak_torque``, ``q2_peak_force`` (RP),
``q2_peak_torque`` (RR), ``q1_inertia`` (largest inertia about q1 on the path), ``path_length``, ``path_time``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from mechverify.design.adapters.path_parsing import parse_bodies, walk_path
from mechverify.design.spec import REGISTRY, ComponentType, Field, Output
from mechverify.errors import InputError, MechverifyError
from mechverify.mechanisms.arm_on_path import ArmOnPath, five_bar_on_path, rp_arm_on_path, rr_arm_on_path
from mechverify.motion.profiles import ProfileSamples
from mechverify.units import Q, Quantity

# ------------------------------------------------------------------------------------------ the arm

def _build_arm(p: Mapping[str, Any], ctx: Any) -> ArmOnPath:
    name = p["_name"]
    cache = ctx.setdefault("planar_arms", {}) if isinstance(ctx, dict) else {}
    if name not in cache:  # a joint_motion profile may have built it already
        cache[name] = _arm_on_path(p, ctx)
    return cache[name]


_FIVE_BAR = ("base", "proximal_left", "distal_left", "distal_right", "proximal_right")
_NOT_A_KEY = {"rp": (("l1", "l2", "elbow", "q2_min", "q2_max"), "its stroke is reach_min, reach_max"),
              "rr": (("reach_min", "reach_max", "carriage_mass", "arm_inertia"),
                     "links l1, l2; bodies with link = 1 or 2; payload"),
              "five_bar": (("reach_min", "reach_max", "carriage_mass", "arm_inertia", "l1", "l2", "elbow", "bodies"),
                           "links base, proximal_left, distal_left, distal_right, proximal_right; payload at the "
                           "tool")}


def _arm_on_path(p: Mapping[str, Any], ctx: Any) -> ArmOnPath:
    """Parse and call :mod:`mechverify.mechanisms.arm_on_path` (bodies, arm, motion, efforts, inertias)."""
    name, kind = p["_name"], p["kind"]
    g = p.get("gravity", (ctx.get("requirements", {}) if isinstance(ctx, Mapping) else {}).get("g", "9.80665 m/s^2"))
    params = ctx.get("parameters", {}) if isinstance(ctx, Mapping) else {}
    try:
        path = walk_path(p["path"], params)
    except MechverifyError as exc:
        msg = str(exc)
        raise InputError(msg if msg.startswith("path") else f"path: {msg}") from None
    lim = {k: p[k] for k in ("q1_min", "q1_max") if k in p}
    if kind != "five_bar":
        for k in (*_FIVE_BAR, "working_mode"):
            if k in p:
                raise InputError(f"{k}: a key of a five_bar arm, not of an {kind.upper()} arm")
    for k in _NOT_A_KEY[kind][0]:
        if k in p:
            what = "a five_bar arm" if kind == "five_bar" else f"an {kind.upper()} arm"
            raise InputError(f"{k}: not a key of {what} ({_NOT_A_KEY[kind][1]})")
    if kind == "rp":
        return rp_arm_on_path(path, parse_bodies(p, None), reach_min=p.get("reach_min", "0 m"),
                              reach_max=p.get("reach_max"), carriage_mass=p.get("carriage_mass", "0 kg"),
                              payload=p.get("payload", "0 kg"), arm_inertia=p.get("arm_inertia", "0 kg*m^2"),
                              gravity=g, name=name, **lim)
    if kind == "rr":
        if "l1" not in p or "l2" not in p:
            raise InputError("l1, l2: an RR arm needs both link lengths")
        return rr_arm_on_path(path, p["l1"], p["l2"], link1_bodies=parse_bodies(p, 1), link2_bodies=parse_bodies(p, 2),
                              elbow=p.get("elbow", "down"), payload=p.get("payload", "0 kg"), gravity=g, name=name,
                              **lim, **{k: p[k] for k in ("q2_min", "q2_max") if k in p})
    from mechverify.mechanisms.fivebar import FiveBar

    missing = [k for k in _FIVE_BAR if k not in p]
    if missing:
        raise InputError(f"{missing[0]}: a five_bar arm needs its five lengths")
    fb = FiveBar(*(p[k] for k in _FIVE_BAR), name=name)
    limits = {j: (p.get(f"{q}_min"), p.get(f"{q}_max"))
              for j, q in (("theta_left", "q1"), ("theta_right", "q2")) if f"{q}_min" in p or f"{q}_max" in p}
    return five_bar_on_path(fb, path, working_mode=p.get("working_mode", "-+"), payload=p.get("payload", "0 kg"),
                            gravity=g, limits=limits, name=name)


def _peak(i: int, what: str) -> Any:
    def fn(a: ArmOnPath, loads: Any) -> Any:
        if (what == "force") != (a.kinds[i] == "length"):
            raise InputError(f"{a.name}: q{i + 1} is {'prismatic' if a.kinds[i] == 'length' else 'revolute'}; "
                             f"ask for q{i + 1}_peak_{'force' if a.kinds[i] == 'length' else 'torque'}")
        return Q(float(np.max(np.abs(a.efforts[i]))), "N" if what == "force" else "N*m")
    return fn


def _q2_speed(a: ArmOnPath) -> Any:
    if a.kinds[1] != "length":
        raise InputError(f"{a.name}: q2 is revolute; q2_peak_speed is the prismatic joint's speed (RP arms)")
    return Q(float(np.max(np.abs(a.motion.dq2))), "m/s")


_LIMIT = "joint limit (an angle); the first path sample outside it is named"
PLANAR_ARM = REGISTRY.register(ComponentType(
    name="planar_arm",
    doc="An RP or RR arm in a vertical (or, with gravity = '0 m/s^2', horizontal) plane walking a path: inverse "
        "kinematics with joint limits, joint rates and accelerations, joint torques and forces from Lagrange's "
        "equations (inertial, Coriolis, centripetal, gravity). Drives get a joint through a joint_motion profile.",
    fields=(
        Field("kind", "choice", "rp (revolute + prismatic), rr (two revolute joints) or five_bar (q1, q2 = left, "
                                "right motor; massless links)", required=True, choices=("rp", "rr", "five_bar")),
        Field("path", "table", "the tool path: curve = polar (r in phi, centre, phi = [from, to]) | cartesian (x, y "
                               "in u, u = [from, to]) | points (points = [[x, y], ...], closed); speed; optional "
                               "acceleration (trapezoidal from rest to rest) and samples (default 400)",
              required=True),
        Field("reach_min", "length", "RP: shortest extension of the prismatic joint"),
        Field("reach_max", "length", "RP: longest extension of the prismatic joint (default: no limit)"),
        Field("carriage_mass", "mass", "RP: the carriage with the tool, a point mass at the extension q2"),
        Field("arm_inertia", "inertia", "RP: inertia about q1 besides the bodies (e.g. a motor rotor)"),
        Field("l1", "length", "RR: first link length"),
        Field("l2", "length", "RR: second link length"),
        Field("elbow", "choice", "RR: elbow down (q2 > 0) or up (q2 < 0)", choices=("down", "up")),
        *(Field(k, "length", f"five_bar: {d}") for k, d in (
            ("base", "distance between the motor axes"), ("proximal_left", "left crank"),
            ("distal_left", "left distal link"), ("distal_right", "right distal link"),
            ("proximal_right", "right crank"))),
        Field("working_mode", "choice", "five_bar: inverse-kinematics branch per leg (default -+)",
              choices=("++", "+-", "-+", "--")),
        Field("bodies", "list", "bodies on the links: tables with shape = rod | cylinder | tube | point, mass, length, "
                                "radius, inner_radius, start (distance from the joint), link (RR: 1 or 2)",
              item="table"),
        Field("payload", "mass", "a point mass at the tool (RP: on the carriage)"),
        Field("gravity", "acceleration", "gravity in the plane, along -y (default requirements.g)"),
        Field("q1_min", "angle", "q1 " + _LIMIT),
        Field("q1_max", "angle", "q1 " + _LIMIT),
        Field("q2_min", "angle", "RR, five_bar: q2 " + _LIMIT),
        Field("q2_max", "angle", "RR, five_bar: q2 " + _LIMIT),
    ),
    build=lambda p, ctx: _build_arm(p, ctx),
    outputs=(
        Output("q1_peak_torque", "torque", "largest |joint torque| of q1 along the path", _peak(0, "torque")),
        Output("q2_peak_force", "force", "RP: largest |joint force| of the prismatic joint", _peak(1, "force")),
        Output("q2_peak_torque", "torque", "RR: largest |joint torque| of q2", _peak(1, "torque")),
        Output("q1_peak_speed", "angular_velocity", "largest |q1'| along the path",
               lambda a, loads: Q(float(np.max(np.abs(a.motion.dq1))), "rad/s")),
        Output("q2_peak_speed", "velocity", "RP: largest |q2'| of the prismatic joint along the path",
               lambda a, loads: _q2_speed(a)),
        Output("q1_inertia", "inertia", "largest inertia about q1 on the path (links and payload)",
               lambda a, loads: Q(float(np.max(a.q1_inertia)), "kg*m^2")),
        Output("path_length", "length", "length of the path", lambda a, loads: Q(a.path.length, "m")),
        Output("path_time", "time", "time to walk the path", lambda a, loads: Q(float(a.path.t[-1] - a.path.t[0]),
                                                                                  "s")),
    ),
))


# ------------------------------------------------------------------------------------------ the joint_motion profile

class JointMotionProfile:
    """A joint of a ``planar_arm`` along its path, resolved when first used (the arm is a component, built after
    the profiles): the joint's motion (exact rates from the inverse kinematics) and its effort from the arm's
    dynamics, ``joint_effort`` (t [s], effort [N m or N]); ``joint_inertia`` the largest inertia (or, for a
    prismatic joint, the mass) the joint moves, for the inertia ratio."""

    def __init__(self, name: str, mechanism: str, joint: str, ctx: Mapping[str, Any]):
        self.name, self.mechanism, self.joint, self._ctx = name, mechanism, joint, ctx
        self._arm: ArmOnPath | None = None

    def _resolve(self) -> ArmOnPath:
        if self._arm is None:
            from mechverify.errors import suggest

            comps = self._ctx.get("components", {})
            entry = comps.get(self.mechanism)
            if entry is None or entry.type.name != "planar_arm":
                arms = [k for k, e in comps.items() if e.type.name == "planar_arm"]
                hint = suggest(self.mechanism, arms, 1)
                raise InputError(f"profile {self.name!r}: mechanism {self.mechanism!r} is not a planar_arm component"
                                 + (f"; did you mean {hint[0]!r}?" if hint
                                    else f" (arms: {', '.join(arms) or 'none'})"))
            if entry.obj is None:
                if "kind" not in entry.params or "path" not in entry.params:
                    raise InputError(f"profile {self.name!r}: the arm {self.mechanism!r} is invalid (see its errors)")
                try:
                    entry.obj = entry.type.build({**entry.params, "_name": self.mechanism}, self._ctx)
                except MechverifyError:  # reported at the arm's own keys: not repeated here
                    raise InputError(f"profile {self.name!r}: the arm {self.mechanism!r} is invalid "
                                     "(see its errors)") from None
            self._arm = entry.obj
        return self._arm

    @property
    def kind(self) -> str:
        return self._resolve().joint(self.joint)[0]

    @property
    def duration(self) -> Quantity:
        t = self._resolve().path.t
        return Q(float(t[-1] - t[0]), "s")

    @property
    def distance(self) -> Quantity:
        kind, q, *_ = self._resolve().joint(self.joint)
        return Q(float(q[-1] - q[0]), "m" if kind == "length" else "rad")

    @property
    def peak_velocity(self) -> Quantity:
        kind, _q, dq, *_ = self._resolve().joint(self.joint)
        return Q(float(np.max(np.abs(dq))), "m/s" if kind == "length" else "rad/s")

    @property
    def joint_effort(self) -> tuple[np.ndarray, np.ndarray]:
        a = self._resolve()
        return a.path.t - a.path.t[0], a.joint(self.joint)[4]

    @property
    def joint_inertia(self) -> float:
        return self._resolve().joint_inertia(self.joint)

    def sample(self, points_per_segment: int = 0) -> ProfileSamples:
        kind, q, dq, ddq, _ = self._resolve().joint(self.joint)
        t = self._resolve().path.t
        t = t - t[0]
        j = np.gradient(ddq, t, edge_order=2)
        return ProfileSamples(kind, t, q.copy(), dq.copy(), ddq.copy(), j, tuple(f"sample {i}" for i in range(len(t))))


REGISTRY.register(ComponentType(
    "joint_motion", "A joint of a planar_arm along the arm's path: the joint's motion, and its torque or force from "
                    "the arm's dynamics, which a drive on this profile adds to its own load.",
    fields=(Field("mechanism", "str", "the planar_arm component", required=True),
            Field("joint", "choice", "q1 (first joint) or q2", required=True, choices=("q1", "q2"))),
    build=lambda p, ctx: JointMotionProfile(p["_name"], p["mechanism"], p["joint"], ctx), section="profiles"))

__all__ = ["ArmOnPath", "JointMotionProfile", "walk_path", "PLANAR_ARM"]
