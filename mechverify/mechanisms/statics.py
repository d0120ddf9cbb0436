"""Planar rigid-body statics: bodies, pin and slider joints, actuators, loads and self-weight.

Every body gives three equilibrium equations (sum of forces in x and y, sum of moments about the
origin); every joint brings its reaction unknowns (a pin: two force components; a slider: the
normal force and the reaction moment) and, if actuated, the actuator torque (pin) or force
(slider). The equations are assembled into ``A x = b`` and solved. Before solving, the rank of
``A`` is checked (singular values): a rank below the number of equations means the mechanism can
move (under-constrained, the free motion is named body by body); a rank below the number of
unknowns means some reactions are statically indeterminate (over-constrained, they are named). A
counting-determinate model with a rank drop is in a singular configuration (e.g. a flattened
parallelogram or aligned distal links) and is reported as such.

Sign conventions: a pin joint's reaction is the force that ``body_a`` exerts on ``body_b`` (the
force on ``body_a`` is its negative); an actuator torque is the torque ``body_a`` (stator) exerts
on ``body_b`` (rotor), counter-clockwise positive; axial forces of members are tension-positive.

References
----------
1. J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Statics*, 7th ed., Wiley, 2012,
   Ch. 3 (equilibrium, Eqs. 3/3) and Art. 4/6 (frames and machines).
2. R. C. Hibbeler, *Engineering Mechanics: Statics*, 13th ed., Pearson, 2013, Sec. 5.3, 6.6.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, ModelError, UnknownNameError, renamed
from mechverify.frozen import set_fields
from mechverify.units import as_quantity, from_si, to_si

GROUND = "ground"
STANDARD_GRAVITY = 9.80665  # m/s^2 (3rd CGPM, 1901)
_RANK_TOL = 1e-9  # singular value / largest singular value below which a direction counts as lost


# --------------------------------------------------------------------------------------- inputs
def point_si(value: Any, name: str) -> np.ndarray:
    """An (x, y) position as SI floats; accepts a pair of lengths or a length quantity of shape (2,)."""
    if isinstance(value, pint.Quantity):
        arr = np.atleast_1d(to_si(value, "length", name))
        if arr.shape != (2,):
            raise InputError(f"{name}: expected an (x, y) position, got shape {arr.shape}")
        return arr.astype(float)
    if isinstance(value, (tuple, list)) and len(value) == 2:
        return np.array([to_si(value[0], "length", f"{name}[x]"), to_si(value[1], "length", f"{name}[y]")])
    raise InputError(f"{name}: expected an (x, y) pair of lengths, got {value!r}")


def vector_si(value: Any, dim: str, name: str) -> np.ndarray:
    """An (x, y) vector of dimension ``dim`` as SI floats."""
    if isinstance(value, pint.Quantity):
        arr = np.atleast_1d(to_si(value, dim, name))
        if arr.shape != (2,):
            raise InputError(f"{name}: expected an (x, y) vector, got shape {arr.shape}")
        return arr.astype(float)
    if isinstance(value, (tuple, list)) and len(value) == 2:
        return np.array([to_si(value[0], dim, f"{name}[x]"), to_si(value[1], dim, f"{name}[y]")])
    raise InputError(f"{name}: expected an (x, y) pair, got {value!r}")


def _cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


@dataclass(frozen=True)
class Body:
    """A rigid body of a planar mechanism at one pose.

    ``points`` names positions on the body (global coordinates at this pose) that joints and loads
    may refer to by name. ``mass`` gives self-weight: it acts at ``com`` if given, otherwise it is
    spread uniformly along the ``segments`` (for a slender link this is the right model for its
    bending moment). ``segments`` are the straight parts of the body as pairs of point names
    forming a tree; along them :class:`MemberLoad` diagrams (axial force, shear, bending moment) are
    computed. Default: the line between the two points of a two-point body, or the chain of a body
    whose points are collinear.
    """

    name: str
    points: Mapping[str, Any]
    mass: Any = "0 kg"
    com: Any = None
    segments: tuple[tuple[str, str], ...] | None = None

    def __post_init__(self) -> None:
        if not self.name or self.name == GROUND:
            raise InputError(f"body name must be non-empty and not {GROUND!r}, got {self.name!r}")
        pts = {str(k): point_si(v, f"body {self.name!r} point {k!r}") for k, v in dict(self.points).items()}
        set_fields(self, points=pts)
        m = to_si(self.mass, "mass", f"body {self.name!r} mass")
        if m < 0:
            raise InputError(f"body {self.name!r} mass: must be zero or positive, got {m} kg")
        set_fields(self, mass=from_si(m, "mass"))
        if self.com is not None:
            set_fields(self, com=point_si(self.com, f"body {self.name!r} com"))
        segs = self.segments if self.segments is not None else _default_segments(pts)
        segs = tuple((str(a), str(b)) for a, b in segs)
        for a, b in segs:
            for p in (a, b):
                if p not in pts:
                    raise UnknownNameError(f"point of body {self.name!r}", p, pts)
            if np.linalg.norm(pts[a] - pts[b]) == 0:
                raise InputError(f"body {self.name!r}: segment ({a}, {b}) has zero length")
        _check_tree(self.name, segs)
        set_fields(self, segments=segs)
        if m > 0 and self.com is None and not segs:
            raise InputError(f"body {self.name!r}: give com (centre of mass) for its mass, or segments to spread it on")

    @property
    def mass_si(self) -> float:
        return float(self.mass.m_as("kg"))

    def weight_centre(self) -> np.ndarray | None:
        """Where the self-weight acts: ``com`` or the length-weighted centroid of the segments."""
        if self.com is not None:
            return self.com
        if not self.segments:
            return None
        lengths = np.array([np.linalg.norm(self.points[b] - self.points[a]) for a, b in self.segments])
        mids = np.array([(self.points[a] + self.points[b]) / 2 for a, b in self.segments])
        return (lengths[:, None] * mids).sum(axis=0) / lengths.sum()


def _default_segments(pts: Mapping[str, np.ndarray]) -> tuple[tuple[str, str], ...]:
    names = list(pts)
    if len(names) == 2:
        return ((names[0], names[1]),)
    if len(names) < 2:
        return ()
    p0 = pts[names[0]]
    far = max(names, key=lambda n: np.linalg.norm(pts[n] - p0))
    e = pts[far] - p0
    scale = np.linalg.norm(e)
    if scale == 0:
        return ()
    e = e / scale
    if any(abs(_cross(e, pts[n] - p0)) > 1e-9 * scale for n in names):
        return ()  # not collinear: no default member diagram
    order = sorted(names, key=lambda n: float(np.dot(pts[n] - p0, e)))
    return tuple((order[i], order[i + 1]) for i in range(len(order) - 1)
                 if np.linalg.norm(pts[order[i + 1]] - pts[order[i]]) > 0)


def _check_tree(body: str, segs: Sequence[tuple[str, str]]) -> None:
    parent: dict[str, str] = {}

    def find(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    for a, b in segs:
        ra, rb = find(a), find(b)
        if ra == rb:
            raise InputError(f"body {body!r}: segments must form a tree (no closed loop), ({a}, {b}) closes one")
        parent[ra] = rb


@dataclass(frozen=True)
class Pin:
    """A revolute joint between ``body_a`` and ``body_b`` (either may be ``"ground"``) at ``at``.

    ``at`` is an (x, y) position or the name of a point of either body. ``actuated=True`` adds the
    actuator torque that ``body_a`` exerts on ``body_b`` as an unknown.
    """

    name: str
    body_a: str
    body_b: str
    at: Any
    actuated: bool = False


@dataclass(frozen=True)
class Slider:
    """A prismatic joint: ``body_b`` slides on ``body_a`` along ``direction`` (an angle) through ``at``.

    Unknowns: the normal force (perpendicular to the slide) and the reaction moment; if
    ``actuated``, also the drive force along the slide. All act from ``body_a`` on ``body_b``.
    """

    name: str
    body_a: str
    body_b: str
    at: Any
    direction: Any = "0 deg"
    actuated: bool = False


@dataclass(frozen=True)
class AppliedForce:
    """An applied force (Fx, Fy) on ``body`` at ``at`` (position or point name)."""

    body: str
    at: Any
    force: Any
    name: str = ""


@dataclass(frozen=True)
class Couple:
    """An applied couple (counter-clockwise positive) on ``body``."""

    body: str
    moment: Any
    name: str = ""


Joint = Pin | Slider
Load = AppliedForce | Couple


@dataclass(frozen=True)
class Mechanism:
    """Bodies, joints and loads of a planar mechanism at one pose; :meth:`solve` gives the statics."""

    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    loads: tuple[Load, ...] = ()
    gravity: Any = ("0 m/s**2", "-9.80665 m/s**2")
    name: str = "mechanism"

    def __post_init__(self) -> None:
        set_fields(self, bodies=tuple(self.bodies), joints=tuple(self.joints), loads=tuple(self.loads))
        names = [b.name for b in self.bodies]
        if len(set(names)) != len(names):
            raise InputError(f"{self.name}: body names must be unique, got {names}")
        jn = [j.name for j in self.joints]
        if len(set(jn)) != len(jn):
            raise InputError(f"{self.name}: joint names must be unique, got {jn}")
        if not self.bodies:
            raise InputError(f"{self.name}: a mechanism needs at least one body")

    def solve(self) -> StaticsSolution:
        return solve_statics(self)


# -------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class MemberLoad:
    """Internal forces along one straight segment of a body (tension-positive axial force).

    ``axial`` is the axial force of largest magnitude (signed), ``tension``/``compression`` the
    largest tensile and compressive values (>= 0), ``shear`` and ``moment`` the largest magnitudes,
    ``moment_at`` the distance from the segment's first point where ``|M|`` peaks. ``stations``,
    ``N``, ``V``, ``M`` hold the diagrams (quantity arrays) for plots.
    """

    body: str
    segment: tuple[str, str]
    length: pint.Quantity
    axial: pint.Quantity
    tension: pint.Quantity
    compression: pint.Quantity
    shear: pint.Quantity
    moment: pint.Quantity
    moment_at: pint.Quantity
    stations: pint.Quantity
    N: pint.Quantity
    V: pint.Quantity
    M: pint.Quantity

    @property
    def member(self) -> str:
        """``body`` for a one-segment body, else ``body:A-B``."""
        return f"{self.body}:{self.segment[0]}-{self.segment[1]}"


@dataclass(frozen=True)
class StaticsSolution:
    """All joint reactions, actuator efforts, axial forces of two-force members and member diagrams."""

    mechanism: str
    joint_forces: dict[str, pint.Quantity]  # joint -> (Fx, Fy) on body_b from body_a; slider: normal-force vector
    joint_moments: dict[str, pint.Quantity]  # slider reaction moments
    actuator_efforts: dict[str, pint.Quantity]  # torque (pin) or force (slider), from body_a on body_b
    axial_forces: dict[str, pint.Quantity]  # two-force members, tension positive
    member_loads: dict[str, MemberLoad]  # keyed by MemberLoad.member or body name
    residual_force: pint.Quantity
    residual_moment: pint.Quantity
    condition_number: float
    _joint_bodies: dict[str, tuple[str, str]] = field(default_factory=dict, repr=False)

    def force_on(self, joint: str, body: str) -> pint.Quantity:
        """The force joint ``joint`` exerts on ``body`` (one of its two bodies)."""
        if joint not in self._joint_bodies:
            raise UnknownNameError("joint", joint, self._joint_bodies)
        a, b = self._joint_bodies[joint]
        if body == b:
            return self.joint_forces[joint]
        if body == a:
            return -self.joint_forces[joint]
        raise InputError(f"joint {joint!r} connects {a!r} and {b!r}, not {body!r}")


# --------------------------------------------------------------------------------------- solver
@dataclass
class _Attachment:
    body: str
    pos: np.ndarray | None  # None for a couple
    force_cols: np.ndarray  # (2, n) coefficients of unknowns (force on this body), or zeros
    force_const: np.ndarray  # (2,) known force
    moment_cols: np.ndarray  # (n,) coefficients of unknowns for a pure couple on this body
    moment_const: float
    label: str


def solve_statics(mech: Mechanism) -> StaticsSolution:
    """Assemble and solve the equilibrium equations of ``mech`` (see module docstring)."""
    bodies = {b.name: b for b in mech.bodies}
    index = {name: i for i, name in enumerate(bodies)}
    g = vector_si(mech.gravity, "acceleration", f"{mech.name} gravity")

    def body_of(name: str, where: str) -> str:
        if name != GROUND and name not in bodies:
            raise UnknownNameError(f"body ({where})", name, [*bodies, GROUND])
        return name

    def position(at: Any, names: Sequence[str], where: str) -> np.ndarray:
        if isinstance(at, str):
            found = [bodies[n].points[at] for n in names if n != GROUND and at in bodies[n].points]
            if not found:
                known = sorted({p for n in names if n != GROUND for p in bodies[n].points})
                raise UnknownNameError(f"point ({where})", at, known)
            for other in found[1:]:
                if np.linalg.norm(other - found[0]) > 1e-9 * max(1.0, np.linalg.norm(found[0])):
                    raise InputError(f"{where}: point {at!r} is at {found[0]} m on one body and {other} m on the other")
            return found[0]
        return point_si(at, where)

    # unknown layout
    labels: list[str] = []
    joint_info: list[tuple[Joint, np.ndarray, list[int]]] = []
    for j in mech.joints:
        a, b = body_of(j.body_a, f"joint {j.name!r}"), body_of(j.body_b, f"joint {j.name!r}")
        if a == b:
            raise InputError(f"joint {j.name!r}: connects body {a!r} to itself")
        p = position(j.at, (a, b), f"joint {j.name!r}")
        start = len(labels)
        if isinstance(j, Pin):
            labels += [f"pin {j.name!r} Rx", f"pin {j.name!r} Ry"]
            if j.actuated:
                labels.append(f"actuator {j.name!r} torque")
        else:
            labels += [f"slider {j.name!r} normal force", f"slider {j.name!r} moment"]
            if j.actuated:
                labels.append(f"actuator {j.name!r} force")
        joint_info.append((j, p, list(range(start, len(labels)))))
    n_unk, n_eq = len(labels), 3 * len(bodies)

    all_pts = [p for b in mech.bodies for p in b.points.values()] + [p for _, p, _ in joint_info]
    origin = np.mean(all_pts, axis=0) if all_pts else np.zeros(2)
    lref = max([float(np.linalg.norm(p - origin)) for p in all_pts] + [1e-12])
    lref = lref if lref > 0 else 1.0

    # attachments per body (force on that body as linear function of unknowns)
    atts: list[_Attachment] = []
    col_scale = np.ones(n_unk)
    for j, p, cols in joint_info:
        if isinstance(j, Pin):
            fc = np.zeros((2, n_unk))
            fc[0, cols[0]] = 1.0
            fc[1, cols[1]] = 1.0
            mc = np.zeros(n_unk)
            if j.actuated:
                mc[cols[2]] = 1.0
                col_scale[cols[2]] = lref
        else:
            ang = to_si(j.direction, "angle", f"slider {j.name!r} direction")
            u = np.array([math.cos(ang), math.sin(ang)])
            nrm = np.array([-u[1], u[0]])
            fc = np.zeros((2, n_unk))
            fc[:, cols[0]] = nrm
            mc = np.zeros(n_unk)
            mc[cols[1]] = 1.0
            col_scale[cols[1]] = lref
            if j.actuated:
                fc[:, cols[2]] = u
        for body, sign in ((j.body_b, 1.0), (j.body_a, -1.0)):
            if body != GROUND:
                atts.append(_Attachment(body, p, sign * fc, np.zeros(2), sign * mc, 0.0, f"joint {j.name}"))
    for k, ld in enumerate(mech.loads):
        body = body_of(ld.body, f"load {ld.name or k}")
        if body == GROUND:
            continue
        label = f"load {ld.name or k}"
        if isinstance(ld, AppliedForce):
            p = position(ld.at, (body,), label)
            f = vector_si(ld.force, "force", f"{label} force")
            atts.append(_Attachment(body, p, np.zeros((2, n_unk)), f, np.zeros(n_unk), 0.0, label))
        else:
            m = to_si(ld.moment, "torque", f"{label} moment")
            atts.append(_Attachment(body, None, np.zeros((2, n_unk)), np.zeros(2), np.zeros(n_unk), m, label))
    for b in mech.bodies:
        if b.mass_si > 0 and np.any(g != 0):
            atts.append(_Attachment(b.name, b.weight_centre(), np.zeros((2, n_unk)), b.mass_si * g,
                                    np.zeros(n_unk), 0.0, "self-weight"))

    # assemble: rows per body (Fx, Fy, Mz/lref about origin); A x + c = 0
    A = np.zeros((n_eq, n_unk))
    c = np.zeros(n_eq)
    for at in atts:
        i = 3 * index[at.body]
        A[i:i + 2] += at.force_cols
        c[i:i + 2] += at.force_const
        if at.pos is not None:
            r = at.pos - origin
            A[i + 2] += (r[0] * at.force_cols[1] - r[1] * at.force_cols[0]) / lref
            c[i + 2] += _cross(r, at.force_const) / lref
        A[i + 2] += at.moment_cols / lref
        c[i + 2] += at.moment_const / lref
    As = A * col_scale  # unknown k scaled so that x_k = lref * x_scaled_k for torques/moments

    _rank_check(mech.name, As, labels, list(bodies), n_eq, n_unk)
    xs = np.linalg.solve(As, -c)
    x = xs * col_scale
    res = A @ x + c
    per_body = res.reshape(-1, 3)
    residual_force = float(np.max(np.abs(per_body[:, :2]))) if len(per_body) else 0.0
    residual_moment = float(np.max(np.abs(per_body[:, 2]))) * lref if len(per_body) else 0.0
    sv = np.linalg.svd(As, compute_uv=False)
    cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf

    joint_forces: dict[str, pint.Quantity] = {}
    joint_moments: dict[str, pint.Quantity] = {}
    efforts: dict[str, pint.Quantity] = {}
    for j, _p, cols in joint_info:
        if isinstance(j, Pin):
            joint_forces[j.name] = from_si(np.array([x[cols[0]], x[cols[1]]]), "force")
            if j.actuated:
                efforts[j.name] = from_si(float(x[cols[2]]), "torque")
        else:
            ang = to_si(j.direction, "angle", "direction")
            nrm = np.array([-math.sin(ang), math.cos(ang)])
            joint_forces[j.name] = from_si(x[cols[0]] * nrm, "force")
            joint_moments[j.name] = from_si(float(x[cols[1]]), "torque")
            if j.actuated:
                efforts[j.name] = from_si(float(x[cols[2]]), "force")

    # realised attachments per body: (pos, force, moment)
    realised: dict[str, list[tuple[np.ndarray | None, np.ndarray, float, str]]] = {n: [] for n in bodies}
    for at in atts:
        f = at.force_cols @ x + at.force_const
        m = float(at.moment_cols @ x + at.moment_const)
        realised[at.body].append((at.pos, f, m, at.label))

    axial = _two_force_members(mech, realised)
    members: dict[str, MemberLoad] = {}
    for b in mech.bodies:
        for seg in b.segments:
            ml = _member_diagram(b, seg, realised[b.name], g)
            members[b.name if len(b.segments) == 1 else ml.member] = ml

    return StaticsSolution(
        mechanism=mech.name, joint_forces=joint_forces, joint_moments=joint_moments, actuator_efforts=efforts,
        axial_forces=axial, member_loads=members, residual_force=from_si(residual_force, "force"),
        residual_moment=from_si(residual_moment, "torque"), condition_number=cond,
        _joint_bodies={j.name: (j.body_a, j.body_b) for j in mech.joints},
    )


def _rank_check(name: str, A: np.ndarray, labels: list[str], bodies: list[str], n_eq: int, n_unk: int) -> None:
    if n_unk == 0:
        raise ModelError(f"{name}: no joints, nothing holds the bodies {bodies}; every body is free")
    U, s, Vt = np.linalg.svd(A, full_matrices=True)
    tol = _RANK_TOL * (s[0] if len(s) and s[0] > 0 else 1.0)
    rank = int(np.sum(s > tol))
    if rank == n_eq == n_unk:
        return
    problems: list[str] = []
    if rank < n_eq:
        modes = U[:, rank:].T
        descr = [_describe_mode(mode, bodies) for mode in modes[:3]]
        problems.append(f"under-constrained: {n_eq - rank} free motion(s) that no joint or actuator resists: "
                        + "; ".join(descr) + " -- add a support or an actuator, or move away from this pose")
    if rank < n_unk:
        null = Vt[rank:]
        involved = [labels[k] for k in range(n_unk) if np.max(np.abs(null[:, k])) > 1e-6]
        problems.append(f"over-constrained: {n_unk - rank} combination(s) of unknowns are statically indeterminate "
                        f"(not fixed by equilibrium): {', '.join(involved)}")
    hint = ""
    if n_eq == n_unk:
        hint = (f" The unknowns and equations balance ({n_unk} each) but the equations have rank {rank}: "
                "the mechanism is in a singular configuration (e.g. aligned links or a flattened parallelogram).")
    raise ModelError(f"{name}: cannot solve the statics, " + "; ".join(problems) + "." + hint)


def _describe_mode(mode: np.ndarray, bodies: list[str]) -> str:
    comps = mode.reshape(-1, 3)
    scale = np.max(np.abs(comps)) or 1.0
    parts = []
    for name, (vx, vy, w) in zip(bodies, comps / scale, strict=True):
        if max(abs(vx), abs(vy), abs(w)) < 1e-6:
            continue
        if abs(w) > 1e-6:
            parts.append(f"body {name!r} rotates")
        else:
            ang = math.degrees(math.atan2(vy, vx))
            parts.append(f"body {name!r} translates along {ang:.1f} deg")
    return ", ".join(parts) if parts else "a free motion"


def _two_force_members(mech: Mechanism, realised: Mapping[str, list]) -> dict[str, pint.Quantity]:
    out: dict[str, pint.Quantity] = {}
    pins = {j.name: j for j in mech.joints if isinstance(j, Pin) and not j.actuated}
    for b in mech.bodies:
        items = realised[b.name]
        if b.mass_si > 0 or len(items) != 2:
            continue
        names = [lab.removeprefix("joint ") for *_, lab in items]
        if not all(n in pins for n in names) or any(abs(m) > 0 for _, _, m, _ in items):
            continue
        (p1, f1, _, _), (p2, _, _, _) = items
        d = p1 - p2
        length = float(np.linalg.norm(d))
        if length == 0:
            continue
        out[b.name] = from_si(float(np.dot(f1, d / length)), "force")
    return out


def _member_diagram(body: Body, seg: tuple[str, str], items: list, g: np.ndarray, n: int = 101) -> MemberLoad:
    pts = body.points
    p, q = pts[seg[0]], pts[seg[1]]
    L = float(np.linalg.norm(q - p))
    e = (q - p) / L
    nrm = np.array([-e[1], e[0]])
    # nodes on the far side of this segment (component of q after removing the segment)
    adj: dict[str, set[str]] = {}
    for a, b in body.segments:
        if (a, b) == seg:
            continue
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    far_nodes, stack = {seg[1]}, [seg[1]]
    while stack:
        for nb in adj.get(stack.pop(), ()):
            if nb not in far_nodes:
                far_nodes.add(nb)
                stack.append(nb)
    far_segs = [s for s in body.segments if s != seg and s[0] in far_nodes and s[1] in far_nodes]

    # classify attachments: node name, or position along some segment
    def locate(pos: np.ndarray) -> tuple[str, float | None]:
        for name, pt in pts.items():
            if np.linalg.norm(pt - pos) <= 1e-9 * max(L, 1e-12):
                return ("node:" + name, None)
        best, best_d, best_t = "", math.inf, 0.0
        for a, b in body.segments:
            pa, pb = pts[a], pts[b]
            ls = float(np.linalg.norm(pb - pa))
            t = float(np.clip(np.dot(pos - pa, (pb - pa) / ls), 0.0, ls))
            dist = float(np.linalg.norm(pa + t * (pb - pa) / ls - pos))
            if dist < best_d:
                best, best_d, best_t = f"seg:{a}|{b}", dist, t
        return (best, best_t)

    located = []
    for pos, f, m, _lab in items:
        if pos is None:  # a couple without position acts at the first point of the body's first segment
            located.append((None, f, m, ("node:" + body.segments[0][0], None)))
        elif _lab == "self-weight" and body.com is None:
            continue  # distributed below
        else:
            located.append((pos, f, m, locate(pos)))

    s_vals = np.unique(np.concatenate([np.linspace(0.0, L, n)] + [
        [t] for *_, (where, t) in located if where == f"seg:{seg[0]}|{seg[1]}" and t is not None]))
    total_len = sum(float(np.linalg.norm(pts[b] - pts[a])) for a, b in body.segments)
    w = body.mass_si * g / total_len if (body.mass_si > 0 and body.com is None and total_len > 0) else np.zeros(2)
    far_seg_keys = {f"seg:{a}|{b}" for a, b in far_segs}
    # every station at once (the same arithmetic per station as a loop over them: cut, then the free body beyond it)
    cut = p + s_vals[:, None] * e  # (n, 2)
    Rx, Ry, Mc = (np.zeros_like(s_vals) for _ in range(3))
    for pos, f, m, (where, t) in located:
        if where.startswith("node:"):
            inside = np.full(s_vals.shape, where[5:] in far_nodes)
        elif where == f"seg:{seg[0]}|{seg[1]}":
            inside = t > s_vals
        else:
            inside = np.full(s_vals.shape, where in far_seg_keys)
        if not inside.any():
            continue
        Rx = np.where(inside, Rx + f[0], Rx)
        Ry = np.where(inside, Ry + f[1], Ry)
        if pos is not None:
            d = pos - cut
            Mc = np.where(inside, Mc + (m + (d[:, 0] * f[1] - d[:, 1] * f[0])), Mc)
        else:
            Mc = np.where(inside, Mc + (m + 0.0), Mc)
    if np.any(w):
        part = (L - s_vals)[:, None] * w
        Rx, Ry = Rx + part[:, 0], Ry + part[:, 1]
        d = p + e * (s_vals + (L - s_vals) / 2)[:, None] - cut
        Mc = Mc + (d[:, 0] * part[:, 1] - d[:, 1] * part[:, 0])
        for a, b in far_segs:
            ls = float(np.linalg.norm(pts[b] - pts[a]))
            lw = ls * w
            Rx, Ry = Rx + lw[0], Ry + lw[1]
            d = (pts[a] + pts[b]) / 2 - cut
            Mc = Mc + (d[:, 0] * lw[1] - d[:, 1] * lw[0])
    N, V, M = Rx * e[0] + Ry * e[1], Rx * nrm[0] + Ry * nrm[1], Mc
    kN = int(np.argmax(np.abs(N)))
    kM = int(np.argmax(np.abs(M)))
    return MemberLoad(
        body=body.name, segment=seg, length=from_si(L, "length"), axial=from_si(float(N[kN]), "force"),
        tension=from_si(max(float(N.max()), 0.0), "force"), compression=from_si(max(float(-N.min()), 0.0), "force"),
        shear=from_si(float(np.abs(V).max()), "force"), moment=from_si(float(np.abs(M).max()), "torque"),
        moment_at=from_si(float(s_vals[kM]), "length"), stations=from_si(s_vals, "length"),
        N=from_si(N, "force"), V=from_si(V, "force"), M=from_si(M, "torque"),
    )


def as_point(x: Any, y: Any) -> tuple[pint.Quantity, pint.Quantity]:
    """Convenience: a point (x, y) of two lengths (quantities or strings)."""
    return (as_quantity(x, "length", "x"), as_quantity(y, "length", "y"))


def points_m(**coords: Iterable[float]) -> dict[str, tuple[pint.Quantity, pint.Quantity]]:
    """Convenience for presets: ``points_m(A=(0, 0.1))`` -> ``{"A": (0 m, 0.1 m)}`` from SI floats."""
    return {k: (from_si(float(v[0]), "length"), from_si(float(v[1]), "length")) for k, v in
            ((k, list(v)) for k, v in coords.items())}

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"PointLoad": "AppliedForce"})
