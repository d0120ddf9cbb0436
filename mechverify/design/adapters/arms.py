"""``planar_arm`` (an RP or RR arm walking a path) and the ``joint_motion`` profile that hands a joint to a drive.

The arm's ``path`` table: a polar curve ``r`` in ``phi`` (``"8 cm - 1.5 cm * cos(4*phi)"``) about ``centre``,
a Cartesian curve ``x``, ``y`` in ``u``, or sampled ``points`` (a C2 spline through them); walked at constant
``speed``, or from rest to rest with a trapezoidal speed profile when ``acceleration`` is given too. Parsing only:
kinematics and dynamics are :mod:`mechverify.mechanisms.paths` (``walk_curve``, ``RPArm``, ``RRArm``).

A profile ``{ type = "joint_motion", mechanism = "arm", joint = "q1" }`` is the joint's motion along the path
together with the joint's effort from the arm's dynamics (Lagrange); a ``drive`` on that profile adds it to its
own load, so the motor checks follow from the path. Outputs: ``q1_peak_torque``, ``q2_peak_force`` (RP),
``q2_peak_torque`` (RR), ``q1_inertia`` (largest inertia about q1 on the path), ``path_length``, ``path_time``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

import numpy as np

from mechverify.design.adapters.path_parsing import walk_path
from mechverify.design.spec import REGISTRY, ComponentType, Field, Output
from mechverify.errors import InputError, MechverifyError
from mechverify.mechanisms import paths as mp
from mechverify.motion.profiles import ProfileSamples
from mechverify.units import Q, Quantity, to_si

# ------------------------------------------------------------------------------------------ the arm

@dataclasses.dataclass(frozen=True)
class ArmOnPath:
    """The built arm, the path it walks, its joint motion and joint efforts (SI arrays)."""

    name: str
    arm: Any
    path: mp.PathSamples
    motion: Any
    efforts: tuple[np.ndarray, np.ndarray]
    q1_inertia: np.ndarray  # inertia about the first joint at every sample [kg m^2]
    kinds: tuple[str, str]  # "angle" / "length" of q1, q2
    q2_inertia: np.ndarray | None = None  # five-bar: the payload's inertia about the right motor

    def joint(self, name: str) -> tuple[str, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(kind, q, q', q'', effort) of joint ``q1`` or ``q2``."""
        i = {"q1": 0, "q2": 1}[name]
        m = self.motion
        q, dq, ddq = ((m.q1, m.dq1, m.ddq1), (m.q2, m.dq2, m.ddq2))[i]
        return self.kinds[i], q, dq, ddq, self.efforts[i]


def _bodies(p: Mapping[str, Any], link: int | None) -> list[mp.LinkBody]:
    out = []
    for i, b in enumerate(p.get("bodies", [])):
        where = f"bodies[{i}]"
        if not isinstance(b, dict):
            raise InputError(f"{where}: expected a table such as {{ shape = \"rod\", mass = \"99 g\", length = "
                             f"\"25 cm\" }}")
        extra = [k for k in b if k not in ("shape", "mass", "length", "radius", "inner_radius", "start", "name",
                                           "link")]
        if extra:
            raise InputError(f"{where}.{extra[0]}: unknown key (allowed: shape, mass, length, radius, inner_radius, "
                             "start, name, link)")
        if "shape" not in b or "mass" not in b:
            raise InputError(f"{where}: needs shape and mass")
        on = int(b.get("link", 1))
        if link is None and on != 1:
            raise InputError(f"{where}.link: an RP arm's bodies turn with q1 (link 1); the carriage is carriage_mass")
        if link is not None and on not in (1, 2):
            raise InputError(f"{where}.link: expected 1 or 2, got {b.get('link')!r}")
        if link is None or on == link:
            out.append(mp.LinkBody(b["shape"], b["mass"], b.get("length"), b.get("radius"), b.get("inner_radius"),
                                   b.get("start", "0 m"), b.get("name", where)))
    return out


def _build_arm(p: Mapping[str, Any], ctx: Any) -> ArmOnPath:
    name = p["_name"]
    cache = ctx.setdefault("planar_arms", {}) if isinstance(ctx, dict) else {}
    if name not in cache:  # a joint_motion profile may have built it already
        cache[name] = _arm_on_path(p, ctx)
    return cache[name]


def _arm_on_path(p: Mapping[str, Any], ctx: Any) -> ArmOnPath:
    name, kind = p["_name"], p["kind"]
    g = p.get("gravity", (ctx.get("requirements", {}) if isinstance(ctx, Mapping) else {}).get("g", "9.80665 m/s^2"))
    params = ctx.get("parameters", {}) if isinstance(ctx, Mapping) else {}
    try:
        path = walk_path(p["path"], params)
    except MechverifyError as exc:
        msg = str(exc)
        raise InputError(msg if msg.startswith("path") else f"path: {msg}") from None
    lim = {k: p[k] for k in ("q1_min", "q1_max") if k in p}
    fb_keys = ("base", "proximal_left", "distal_left", "distal_right", "proximal_right", "working_mode")
    if kind != "five_bar":
        for k in fb_keys:
            if k in p:
                raise InputError(f"{k}: a key of a five_bar arm, not of an {kind.upper()} arm")
    else:
        return _five_bar_on_path(p, path, g)
    if kind == "rp":
        for k in ("l1", "l2", "elbow", "q2_min", "q2_max"):
            if k in p:
                raise InputError(f"{k}: not a key of an RP arm (its stroke is reach_min, reach_max)")
        m_a, r_a, J_a = mp.compose_bodies(_bodies(p, None))
        J = J_a + (to_si(p["arm_inertia"], "inertia", "arm_inertia") if "arm_inertia" in p else 0.0)
        mc = to_si(p.get("carriage_mass", "0 kg"), "mass", "carriage_mass") + to_si(p.get("payload", "0 kg"), "mass",
                                                                                     "payload")
        arm = mp.RPArm(reach_min=p.get("reach_min", "0 m"), reach_max=p.get("reach_max"),
                       carriage_mass=Q(mc, "kg"),
                       arm_inertia=Q(J, "kg*m^2"), arm_mass=Q(m_a, "kg"), arm_com=Q(r_a, "m"), gravity=g, name=name,
                       **lim)
        motion = arm.inverse(path)
        J1 = J + mc * motion.q2**2
        kinds = ("angle", "length")
    else:
        for k in ("reach_min", "reach_max", "carriage_mass", "arm_inertia"):
            if k in p:
                raise InputError(f"{k}: not a key of an RR arm (links l1, l2; bodies with link = 1 or 2; payload)")
        if "l1" not in p or "l2" not in p:
            raise InputError("l1, l2: an RR arm needs both link lengths")
        l1 = to_si(p["l1"], "length", "l1")
        links = []
        for k in (1, 2):
            m, c, Jj = mp.compose_bodies(_bodies(p, k))
            links.append((m, c, Jj - m * c * c))  # centroidal
        arm = mp.RRArm(p["l1"], p["l2"], p.get("elbow", "down"), Q(links[0][0], "kg"), Q(links[1][0], "kg"),
                       Q(links[0][1], "m") if links[0][0] > 0 else None,
                       Q(links[1][1], "m") if links[1][0] > 0 else None,
                       Q(links[0][2], "kg*m^2"), Q(links[1][2], "kg*m^2"), p.get("payload", "0 kg"), g,
                       name=name, **lim, **{k: p[k] for k in ("q2_min", "q2_max") if k in p})
        motion = arm.inverse(path)
        _l1, _l2, m1, lc1, I1, M2, lc2, I2, _g = arm._si()
        J1 = m1 * lc1**2 + M2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * np.cos(motion.q2)) + I1 + I2  # d11
        kinds = ("angle", "angle")
    return ArmOnPath(name, arm, path, motion, arm.joint_loads(motion), np.asarray(J1, float), kinds)


def _five_bar_on_path(p: Mapping[str, Any], path: mp.PathSamples, g: Any) -> ArmOnPath:
    """A five-bar (massless links, the payload a point mass at the tool) along the path: q1 = left motor,
    q2 = right motor; torques by virtual work of the payload's d'Alembert force."""
    from mechverify.mechanisms.fivebar import FiveBar

    for k in ("reach_min", "reach_max", "carriage_mass", "arm_inertia", "l1", "l2", "elbow", "bodies"):
        if k in p:
            raise InputError(f"{k}: not a key of a five_bar arm (links base, proximal_left, distal_left, "
                             "distal_right, proximal_right; payload at the tool)")
    missing = [k for k in ("base", "proximal_left", "distal_left", "distal_right", "proximal_right") if k not in p]
    if missing:
        raise InputError(f"{missing[0]}: a five_bar arm needs its five lengths")
    fb = FiveBar(p["base"], p["proximal_left"], p["distal_left"], p["distal_right"], p["proximal_right"],
                 name=p["_name"])
    mode = p.get("working_mode", "-+")
    limits = {j: (p.get(f"{q}_min"), p.get(f"{q}_max"))
              for j, q in (("theta_left", "q1"), ("theta_right", "q2")) if f"{q}_min" in p or f"{q}_max" in p}
    motion = mp.five_bar_inverse(fb, path, mode, limits)
    payload = p.get("payload", Q(0, "kg"))
    efforts = mp.five_bar_payload_torques(fb, path, motion, payload, g, mode)
    m = to_si(payload, "mass", "payload")
    J = np.zeros((len(path.t), 2))
    for i in range(len(path.t)):  # the payload's inertia about each motor: m |dP/dtheta_k|^2
        jac = fb.jacobian(fb.inverse((Q(path.x[i], "m"), Q(path.y[i], "m")), mode)).m_as("m")
        J[i] = m * np.sum(jac**2, axis=0)
    return ArmOnPath(p["_name"], fb, path, motion, efforts, J[:, 0], ("angle", "angle"), J[:, 1])


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
                except MechverifyError as exc:
                    raise InputError(f"profile {self.name!r}: arm {self.mechanism!r}: {exc}") from None
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
        a = self._resolve()
        if self.joint == "q1":
            return float(np.max(a.q1_inertia))
        if a.q2_inertia is not None:
            return float(np.max(a.q2_inertia))
        if a.kinds[1] == "length":
            return to_si(a.arm.carriage_mass, "mass", "carriage_mass")
        _l1, _l2, _m1, _lc1, _I1, M2, lc2, I2, _g = a.arm._si()
        return M2 * lc2**2 + I2  # d22

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
