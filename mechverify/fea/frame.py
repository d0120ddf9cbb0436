"""Beams and frames: 3D frames and grillages of straight members (axial, biaxial bending, torsion).

A :class:`Frame` is a set of named nodes, straight :class:`Member` s between them (each with a
:class:`~mechverify.components.sections.Section` and a material), :class:`Support` s and
:class:`Hinge` s declared at named nodes or at points, never at degree-of-freedom numbers.
``Frame.solve(loads)`` takes :class:`PointLoad`, :class:`DistributedLoad` and :class:`SelfWeight`
and returns :class:`FrameResults`: node displacements and rotations, support reactions (global
equilibrium is asserted), internal force and moment diagrams along every member, stresses at
section fibres, maxima with their locations and a report figure.

The element is the two-node 3D beam with the exact (interdependent) stiffness of a prismatic
member: Euler-Bernoulli, or Timoshenko with the shear areas ``Asy``/``Asz`` of the section
(shear parameters ``Phi = 12 E I / (G A_s L^2)``, ref. 1 Sec. 5.6, ref. 2 Sec. 4.5). Uniform loads
enter as the fixed-end forces of the member (the same ``wL/2``, ``wL^2/12`` for both theories), so
nodal displacements are exact for point and uniform loads at any number of elements. Between the
nodes the fields follow from the end forces by integrating ``M = E I theta'`` and
``v' = theta + V / (G A_s)`` (exact polynomials), so deflections and diagrams are exact along the
members too.

Conventions: member local axis x runs from its start to its end node; local z is the component of
``orientation`` (default global Z; global X for a vertical member) normal to x, and y = z × x.
The section's y-z plane is the local y-z plane (a rectangle's ``height`` lies along local z, so a
horizontal member bends about y under vertical loads with ``Iy``). A section with a product of
inertia is analysed about its principal axes. Internal resultants are those on the cut face whose
outward normal is +x: ``N`` > 0 in tension, ``sigma = N/A + My z / Iy - Mz y / Iz``. Loads act at
the centroidal axis (the shear-centre offset of open sections is not modelled) and members are
rigidly connected at shared nodes unless a :class:`Hinge` releases one rotation there.

References
----------
1. J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968 (Dover 1985),
   Sec. 5.6 (beam element with shear deformation), Sec. 5.7 (fixed-end forces).
2. W. McGuire, R. H. Gallagher, R. D. Ziemian, *Matrix Structural Analysis*, 2nd ed., Wiley 2000,
   Sec. 4.3-4.5 (3D frame element, transformation, shear deformation).
3. S. P. Timoshenko, J. M. Gere, *Mechanics of Materials*, 1st ed., Van Nostrand 1972, Sec. 7.8
   (deflection of beams due to shear), and Budynas & Nisbett, *Shigley's Mechanical Engineering
   Design*, 10th ed., Eq. 5-15 (von Mises stress of a beam fibre, ``sqrt(sigma^2 + 3 tau^2)``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pint
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.components.sections import Section
from mechverify.errors import InputError, ModelError, UnknownNameError
from mechverify.fea.progress import Steps
from mechverify.materials.material import Material
from mechverify.units import Q, to_si

#: Local DOF names of a node, in order (translations then rotations, global axes).
DOF_NAMES = ("x", "y", "z", "rx", "ry", "rz")
_DOF_WORDS = {"x": "translation along x", "y": "translation along y", "z": "translation along z",
              "rx": "rotation about x", "ry": "rotation about y", "rz": "rotation about z"}
SUPPORT_KINDS = ("fixed", "pinned", "roller", "spring", "custom")
THEORIES = ("timoshenko", "euler")
STANDARD_GRAVITY = 9.80665
_ROUND_KINDS = ("circle", "tube")
#: Frames above this many unknowns show progress on stderr.
PROGRESS_THRESHOLD = 20_000
#: Dense null-space check of the stiffness up to this many unknowns (mechanism named precisely).
DENSE_CHECK_LIMIT = 3000


# ----------------------------------------------------------------------------------------- inputs
def _material(m: Any, name: str) -> Material:
    if isinstance(m, Material):
        return m
    if isinstance(m, str):
        from mechverify.materials.database import get

        return get(m)
    raise InputError(f"{name}: expected a Material or its name, got {m!r}")


def _vector(v: Any, dim: str, name: str) -> np.ndarray:
    """Three components with units (a quantity array, or three strings/quantities) as SI floats."""
    if isinstance(v, pint.Quantity) or isinstance(v, str):
        arr = np.atleast_1d(np.asarray(to_si(v, dim, name), dtype=float))
    else:
        try:
            items = list(v)
        except TypeError:
            raise InputError(f"{name}: expected three components, got {v!r}") from None
        arr = np.array([to_si(c, dim, f"{name}[{i}]") for i, c in enumerate(items)], dtype=float)
    if arr.shape != (3,):
        raise InputError(f"{name}: expected three components (x, y, z), got {arr.size}")
    return arr


def _axis(axis: str, name: str) -> int:
    a = str(axis).lower().removeprefix("r")
    if a not in ("x", "y", "z"):
        raise InputError(f"{name}: expected a global axis 'x', 'y' or 'z', got {axis!r}")
    return "xyz".index(a)


Where = str | Any  # a node name, or a point (three lengths)


@dataclass(frozen=True)
class Member:
    """A straight prismatic member from node ``start`` to node ``end`` (names or points).

    ``orientation``: a vector in the local x-z plane (default global Z; global X for a vertical
    member). ``theory``: "timoshenko" or "euler" (default: the frame's). ``divisions``: elements
    along the member (results are exact with one; more only refine the figure).
    """

    start: Where
    end: Where
    section: Section
    material: Material | str
    name: str = ""
    orientation: Any = None
    theory: str | None = None
    divisions: int = 1

    def __post_init__(self) -> None:
        if not isinstance(self.section, Section):
            raise InputError(f"member {self.name}: section must be a Section (mechverify.components.sections), "
                             f"got {type(self.section).__name__}")
        object.__setattr__(self, "material", _material(self.material, f"member {self.name}: material"))
        if self.theory is not None and self.theory not in THEORIES:
            raise InputError(f"member {self.name}: theory must be one of {THEORIES}, got {self.theory!r}")
        if not isinstance(self.divisions, int) or self.divisions < 1:
            raise InputError(f"member {self.name}: divisions must be a whole number >= 1, got {self.divisions!r}")
        if self.orientation is not None:
            o = np.asarray(self.orientation, dtype=float)
            if o.shape != (3,) or not np.linalg.norm(o) > 0:
                raise InputError(f"member {self.name}: orientation must be a non-zero 3-vector, "
                                 f"got {self.orientation!r}")
            object.__setattr__(self, "orientation", tuple(float(c) for c in o))


@dataclass(frozen=True)
class Support:
    """A support at a node or point.

    ``kind``: ``"fixed"`` (all six motions held), ``"pinned"`` (three translations held, rotations
    free), ``"roller"`` (the translation along ``direction`` held), ``"spring"`` (elastic: ``springs``
    maps ``"x"``..``"rz"`` to a stiffness in N/m or N·m/rad), ``"custom"`` (the motions listed in
    ``hold`` held, e.g. ``("x", "y", "z", "rz")``); ``springs`` may be added to any kind.
    """

    at: Where
    kind: str = "fixed"
    direction: str = "z"
    hold: tuple[str, ...] = ()
    springs: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in SUPPORT_KINDS:
            from mechverify.errors import suggest

            hint = suggest(self.kind, SUPPORT_KINDS, 1)
            raise InputError(f"support kind must be one of {', '.join(SUPPORT_KINDS)}, got {self.kind!r}"
                             + (f"; did you mean {hint[0]!r}?" if hint else ""))
        hold = tuple(str(h).lower() for h in self.hold)
        for h in hold:
            if h not in DOF_NAMES:
                raise InputError(f"support hold: expected names among {', '.join(DOF_NAMES)}, got {h!r}")
        if self.kind == "custom" and not hold:
            raise InputError("support kind 'custom' needs hold = the motions it prevents, e.g. ('x', 'y', 'z')")
        if self.kind != "custom" and hold:
            raise InputError(f"support hold: only for kind 'custom' (kind is {self.kind!r})")
        _axis(self.direction, "support direction")
        springs: dict[str, float] = {}
        for k, v in dict(self.springs).items():
            kk = str(k).lower()
            if kk not in DOF_NAMES:
                raise InputError(f"support springs: keys must be among {', '.join(DOF_NAMES)}, got {k!r}")
            dim = "force_per_length" if kk in ("x", "y", "z") else "torsional_stiffness"
            val = to_si(v, dim, f"springs.{kk}")
            if val <= 0:
                raise InputError(f"support springs.{kk}: stiffness must be positive, got {v!r}")
            springs[kk] = val
        if self.kind == "spring" and not springs:
            raise InputError("support kind 'spring' needs springs = {direction: stiffness}, e.g. {'z': '2e5 N/m'}")
        object.__setattr__(self, "hold", hold)
        object.__setattr__(self, "springs", springs)

    def held(self) -> tuple[int, ...]:
        """Indices (0..5) of the held motions."""
        if self.kind == "fixed":
            return tuple(range(6))
        if self.kind == "pinned":
            return (0, 1, 2)
        if self.kind == "roller":
            return (_axis(self.direction, "direction"),)
        return tuple(DOF_NAMES.index(h) for h in self.hold)


@dataclass(frozen=True)
class Hinge:
    """A pin joint at a node: the members meeting there rotate independently about the global ``axis``
    (one of x, y, z) and share the other five motions."""

    at: Where
    axis: str = "z"

    def __post_init__(self) -> None:
        _axis(self.axis, "hinge axis")


@dataclass(frozen=True)
class PointLoad:
    """A force (N, three global components) and/or a moment (N·m) at a node or at a point on a member."""

    at: Where
    force: Any = None
    moment: Any = None

    def vectors(self) -> tuple[np.ndarray, np.ndarray]:
        f = np.zeros(3) if self.force is None else _vector(self.force, "force", "force")
        m = np.zeros(3) if self.moment is None else _vector(self.moment, "torque", "moment")
        return f, m


@dataclass(frozen=True)
class DistributedLoad:
    """A uniform load per length (N/m, three components) over the whole length of member ``member``,
    in ``axes`` "global" (default) or "local" (the member's x, y, z)."""

    member: str
    load: Any
    axes: str = "global"

    def __post_init__(self) -> None:
        if self.axes not in ("global", "local"):
            raise InputError(f"distributed load axes must be 'global' or 'local', got {self.axes!r}")
        _vector(self.load, "force_per_length", "load")


@dataclass(frozen=True)
class SelfWeight:
    """The weight of every member, rho A g per length, along ``direction`` (default -Z) times ``factor``."""

    g: Any = "9.80665 m/s**2"
    direction: tuple[float, float, float] = (0.0, 0.0, -1.0)
    factor: float = 1.0

    def vector(self) -> np.ndarray:
        d = np.asarray(self.direction, dtype=float)
        if d.shape != (3,) or not np.linalg.norm(d) > 0:
            raise InputError(f"self-weight direction must be a non-zero 3-vector, got {self.direction!r}")
        return to_si(self.g, "acceleration", "g") * self.factor * d / np.linalg.norm(d)


Load = PointLoad | DistributedLoad | SelfWeight


# ----------------------------------------------------------------------------------- element math
def local_axes(p1: np.ndarray, p2: np.ndarray, orientation: Any = None, roll: float = 0.0) -> np.ndarray:
    """Rows e_x, e_y, e_z of a member's local frame (global components); ``roll`` turns y, z about x."""
    ex = p2 - p1
    ex = ex / np.linalg.norm(ex)
    if orientation is None:
        ref = np.array([0.0, 0.0, 1.0]) if abs(ex[2]) < 1.0 - 1e-9 else np.array([1.0, 0.0, 0.0])
    else:
        ref = np.asarray(orientation, dtype=float)
    ez = ref - np.dot(ref, ex) * ex
    if np.linalg.norm(ez) < 1e-9 * np.linalg.norm(ref):
        raise InputError("member orientation is parallel to the member; give a vector across it")
    ez /= np.linalg.norm(ez)
    ey = np.cross(ez, ex)
    if roll:
        c, s = math.cos(roll), math.sin(roll)
        ey, ez = c * ey + s * ez, -s * ey + c * ez
    return np.vstack((ex, ey, ez))


def local_stiffness(L: float, E: float, G: float, A: float, Iy: float, Iz: float, J: float,
                    Asy: float | None, Asz: float | None) -> np.ndarray:
    """12x12 stiffness of a prismatic 3D beam in local axes (DOFs u, v, w, θx, θy, θz at each end).

    Timoshenko with shear areas ``Asy``, ``Asz`` (``None``: Euler-Bernoulli); ref. 1 Sec. 5.6:
    bending in x-y: ``E Iz/((1+Φy) L³) [12, 6L, -12, 6L; 6L, (4+Φy)L², -6L, (2-Φy)L²; ...]``,
    ``Φy = 12 E Iz / (G Asy L²)``; x-z likewise with ``Iy``, ``Φz`` and the signs of θy = -dw/dx.
    """
    k = np.zeros((12, 12))
    ea, gj = E * A / L, G * J / L
    k[0, 0] = k[6, 6] = ea
    k[0, 6] = k[6, 0] = -ea
    k[3, 3] = k[9, 9] = gj
    k[3, 9] = k[9, 3] = -gj
    py = 12 * E * Iz / (G * Asy * L**2) if Asy else 0.0
    pz = 12 * E * Iy / (G * Asz * L**2) if Asz else 0.0
    for (iv, ir, jv, jr), EI, phi, sgn in (((1, 5, 7, 11), E * Iz, py, 1.0), ((2, 4, 8, 10), E * Iy, pz, -1.0)):
        c = EI / ((1 + phi) * L**3)
        kb = c * np.array([[12, 6 * L * sgn, -12, 6 * L * sgn],
                           [6 * L * sgn, (4 + phi) * L**2, -6 * L * sgn, (2 - phi) * L**2],
                           [-12, -6 * L * sgn, 12, -6 * L * sgn],
                           [6 * L * sgn, (2 - phi) * L**2, -6 * L * sgn, (4 + phi) * L**2]])
        idx = (iv, ir, jv, jr)
        k[np.ix_(idx, idx)] = kb
    return k


def fixed_end_forces(L: float, q: np.ndarray) -> np.ndarray:
    """Nodal loads equivalent to a uniform local load ``q = (qx, qy, qz)`` [N/m]: the reactions of the
    clamped member reversed (ref. 1 Sec. 5.7): ``qL/2`` at each end, ``±q L²/12`` end moments."""
    qx, qy, qz = q
    f = np.zeros(12)
    f[[0, 6]] = qx * L / 2
    f[[1, 7]] = qy * L / 2
    f[[2, 8]] = qz * L / 2
    f[5], f[11] = qy * L**2 / 12, -qy * L**2 / 12
    f[4], f[10] = -qz * L**2 / 12, qz * L**2 / 12
    return f


@dataclass(frozen=True)
class _Props:
    E: float
    G: float
    A: float
    Iy: float
    Iz: float
    J: float
    Asy: float | None
    Asz: float | None
    rho: float
    roll: float  # principal-axis rotation of the section [rad]


def _props(member: Member, theory: str) -> _Props:
    s = member.section.si()
    mat = member.material
    E = to_si(mat.require("E"), "pressure", "E")
    if mat.G is None:
        raise InputError(f"member {member.name}: material {mat.name!r} has no shear modulus G (nor nu)")
    G = to_si(mat.G, "pressure", "G")
    rho = to_si(mat.density, "density", "density") if mat.density is not None else float("nan")
    Iy, Iz, roll = s["Iy"], s["Iz"], 0.0
    if abs(s["Iyz"]) > 1e-9 * (s["Iy"] + s["Iz"]):
        Iy, Iz, roll = s["I1"], s["I2"], s["principal_angle"]
    tim = theory == "timoshenko"
    return _Props(E, G, s["area"], Iy, Iz, s["J"], s["Asy"] if tim else None, s["Asz"] if tim else None, rho, roll)


# ---------------------------------------------------------------------------------------- the frame
@dataclass(frozen=True)
class _Mesh:
    """The analysis model of one load case: nodes (split at load and support points), elements."""

    points: np.ndarray  # [n, 3]
    names: dict[int, str]  # analysis node -> user name
    dofs: np.ndarray  # [ne, 12] global DOF indices
    ndof: int
    elem_nodes: np.ndarray  # [ne, 2]
    elem_member: np.ndarray  # [ne]
    elem_s0: np.ndarray  # [ne] start position along the member [m]
    R: np.ndarray  # [ne, 3, 3]
    L: np.ndarray  # [ne]
    props: list[_Props]
    dof_owner: list[tuple[int, int]]  # DOF -> (node, local 0..5)


class Frame:
    """A 3D frame: ``Frame(nodes, members, supports, hinges=(), theory="timoshenko")``.

    ``nodes`` maps names to points (three lengths); members, supports, hinges and loads refer to
    nodes by name or by a point (a point on a member that is not a node splits it).
    """

    def __init__(self, nodes: Mapping[str, Any] | None, members: Sequence[Member], supports: Sequence[Support],
                 hinges: Sequence[Hinge] = (), theory: str = "timoshenko", name: str = "frame"):
        if theory not in THEORIES:
            raise InputError(f"theory must be one of {THEORIES}, got {theory!r}")
        self.name, self.theory = name, theory
        self.nodes: dict[str, np.ndarray] = {}
        for n, p in (nodes or {}).items():
            self.nodes[str(n)] = _vector(p, "length", f"nodes.{n}")
        if not members:
            raise InputError("a frame needs at least one member")
        self.members: list[Member] = []
        names: set[str] = set()
        for i, m in enumerate(members):
            nm = m.name or f"M{i + 1}"
            if nm in names:
                raise InputError(f"member name {nm!r} used twice")
            names.add(nm)
            self.members.append(m if m.name else Member(m.start, m.end, m.section, m.material, nm, m.orientation,
                                                        m.theory, m.divisions))
        self.ends = [(self.point(m.start, f"member {m.name}: start"), self.point(m.end, f"member {m.name}: end"))
                     for m in self.members]
        pts = np.array([p for e in self.ends for p in e] + list(self.nodes.values()))
        self.size = float(np.max(np.ptp(pts, axis=0))) or 1.0
        self.tol = 1e-6 * self.size
        for m, (a, b) in zip(self.members, self.ends, strict=True):
            if np.linalg.norm(b - a) <= self.tol:
                raise InputError(f"member {m.name}: start and end coincide (zero length)")
            local_axes(a, b, m.orientation)  # orientation across the member
        self.supports = tuple(supports)
        self.hinges = tuple(hinges)
        for s in self.supports:
            self._on_frame(s.at, "support")
        for h in self.hinges:
            self._on_frame(h.at, "hinge")
        self.member_index = {m.name: i for i, m in enumerate(self.members)}

    # --------------------------------------------------------------------------- geometry helpers
    def point(self, where: Where, what: str = "point") -> np.ndarray:
        """The coordinates [m] of a node name or a point."""
        if isinstance(where, str):
            if where not in self.nodes:
                raise UnknownNameError("node", where, self.nodes)
            return self.nodes[where]
        return _vector(where, "length", what)

    def _locate(self, p: np.ndarray) -> list[tuple[int, float]]:
        """Members the point lies on, with the position along each (0..1)."""
        out = []
        for i, (a, b) in enumerate(self.ends):
            d = b - a
            t = float(np.dot(p - a, d) / np.dot(d, d))
            if -1e-9 <= t <= 1 + 1e-9 and np.linalg.norm(a + t * d - p) <= self.tol:
                out.append((i, min(max(t, 0.0), 1.0)))
        return out

    def _on_frame(self, where: Where, what: str) -> np.ndarray:
        p = self.point(where, what)
        if not self._locate(p):
            loc = ", ".join(f"{c * 1e3:.4g}" for c in p)
            raise InputError(f"{what} at {where if isinstance(where, str) else f'({loc}) mm'} is not on any member")
        return p

    # ------------------------------------------------------------------------------- the mesh
    def _mesh(self, loads: Sequence[Load]) -> _Mesh:
        splits: list[list[float]] = [[0.0, 1.0] + [k / m.divisions for k in range(1, m.divisions)]
                                     for m in self.members]
        special = [s.at for s in self.supports] + [h.at for h in self.hinges]
        special += [ld.at for ld in loads if isinstance(ld, PointLoad)]
        for where in special:
            p = self._on_frame(where, "load or support")
            for i, t in self._locate(p):
                splits[i].append(t)
        pts: list[np.ndarray] = []

        def node_of(p: np.ndarray) -> int:
            for k, q in enumerate(pts):
                if np.linalg.norm(q - p) <= self.tol:
                    return k
            pts.append(p)
            return len(pts) - 1

        for p in self.nodes.values():
            node_of(p)
        enodes, emember, es0 = [], [], []
        for i, (a, b) in enumerate(self.ends):
            ts = sorted(set(round(t, 12) for t in splits[i]))
            ts = [t for k, t in enumerate(ts) if k == 0 or (t - ts[k - 1]) * np.linalg.norm(b - a) > self.tol]
            ts[-1] = 1.0
            ids = [node_of(a + t * (b - a)) for t in ts]
            for k in range(len(ts) - 1):
                enodes.append((ids[k], ids[k + 1]))
                emember.append(i)
                es0.append(ts[k] * float(np.linalg.norm(b - a)))
        points = np.array(pts)
        names = {}
        for n, p in self.nodes.items():
            names[node_of(p)] = n
        n = len(points)
        dofs = np.array([[6 * i + k for k in range(6)] + [6 * j + k for k in range(6)] for i, j in enodes])
        owner = [(i, k) for i in range(n) for k in range(6)]
        ndof = 6 * n
        for h in self.hinges:
            node = node_of(self.point(h.at))
            ax = 3 + _axis(h.axis, "hinge axis")
            first = True
            for e, (i, j) in enumerate(enodes):
                for end, nd in ((0, i), (1, j)):
                    if nd != node:
                        continue
                    if first:
                        first = False
                        continue
                    dofs[e, 6 * end + ax] = ndof
                    owner.append((node, ax))
                    ndof += 1
        R, L, props = [], [], []
        cache: dict[int, _Props] = {}
        for e, (i, j) in enumerate(enodes):
            m = self.members[emember[e]]
            if emember[e] not in cache:
                cache[emember[e]] = _props(m, m.theory or self.theory)
            pr = cache[emember[e]]
            R.append(local_axes(points[i], points[j], m.orientation, pr.roll))
            L.append(float(np.linalg.norm(points[j] - points[i])))
            props.append(pr)
        return _Mesh(points, names, dofs, ndof, np.array(enodes), np.array(emember), np.array(es0), np.array(R),
                     np.array(L), props, owner)

    # ------------------------------------------------------------------------------- assembly
    def _loads(self, mesh: _Mesh, loads: Sequence[Load]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(nodal load vector, local uniform load per element [ne, 3], applied force total, applied moment about
        the origin)."""
        f = np.zeros(mesh.ndof)
        q = np.zeros((len(mesh.L), 3))
        F = np.zeros(3)
        Mo = np.zeros(3)
        for ld in loads:
            if isinstance(ld, PointLoad):
                fv, mv = ld.vectors()
                p = self.point(ld.at)
                k = next(i for i, x in enumerate(mesh.points) if np.linalg.norm(x - p) <= self.tol)
                f[6 * k:6 * k + 3] += fv
                f[6 * k + 3:6 * k + 6] += mv
                F += fv
                Mo += mv + np.cross(mesh.points[k], fv)
            elif isinstance(ld, DistributedLoad):
                if ld.member not in self.member_index:
                    raise UnknownNameError("member", ld.member, self.member_index)
                w = _vector(ld.load, "force_per_length", "load")
                mi = self.member_index[ld.member]
                for e in np.flatnonzero(mesh.elem_member == mi):
                    q[e] += w if ld.axes == "local" else mesh.R[e] @ w
            elif isinstance(ld, SelfWeight):
                g = ld.vector()
                for e, pr in enumerate(mesh.props):
                    if not np.isfinite(pr.rho):
                        m = self.members[mesh.elem_member[e]]
                        raise InputError(f"member {m.name}: material {m.material.name!r} has no density "
                                         "(needed for self-weight)")
                    q[e] += mesh.R[e] @ (pr.rho * pr.A * g)
            else:
                raise InputError(f"unknown load {ld!r}: use PointLoad, DistributedLoad or SelfWeight")
        for e in range(len(mesh.L)):
            if not np.any(q[e]):
                continue
            Le = mesh.L[e]
            fe = fixed_end_forces(Le, q[e])
            T = np.kron(np.eye(4), mesh.R[e])
            np.add.at(f, mesh.dofs[e], T.T @ fe)
            wg = mesh.R[e].T @ q[e]
            a, b = mesh.points[mesh.elem_nodes[e]]
            F += wg * Le
            Mo += np.cross((a + b) / 2, wg * Le)
        return f, q, F, Mo

    def _stiffness(self, mesh: _Mesh) -> tuple[sp.csr_matrix, list[np.ndarray]]:
        rows, cols, vals, klocal = [], [], [], []
        for e, pr in enumerate(mesh.props):
            k = local_stiffness(mesh.L[e], pr.E, pr.G, pr.A, pr.Iy, pr.Iz, pr.J, pr.Asy, pr.Asz)
            klocal.append(k)
            T = np.kron(np.eye(4), mesh.R[e])
            kg = T.T @ k @ T
            d = mesh.dofs[e]
            rows.append(np.repeat(d, 12))
            cols.append(np.tile(d, 12))
            vals.append(kg.ravel())
        K = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(mesh.ndof, mesh.ndof))
        return K, klocal

    def _restraints(self, mesh: _Mesh) -> tuple[np.ndarray, dict[int, float], list[tuple[Support, int]]]:
        held: set[int] = set()
        springs: dict[int, float] = {}
        at: list[tuple[Support, int]] = []
        for s in self.supports:
            p = self.point(s.at)
            k = next(i for i, x in enumerate(mesh.points) if np.linalg.norm(x - p) <= self.tol)
            at.append((s, k))
            held.update(6 * k + d for d in s.held())
            for dname, val in s.springs.items():
                springs[6 * k + DOF_NAMES.index(dname)] = springs.get(6 * k + DOF_NAMES.index(dname), 0.0) + val
        return np.array(sorted(held), dtype=np.int64), springs, at

    # -------------------------------------------------------------------------- support checks
    def _rigid_modes(self, mesh: _Mesh) -> tuple[np.ndarray, np.ndarray]:
        """The six rigid-body motions over all DOFs ``[ndof, 6]`` (rotations scaled by the model size)."""
        c = mesh.points.mean(axis=0)
        B = np.zeros((mesh.ndof, 6))
        for dof, (node, k) in enumerate(mesh.dof_owner):
            X = (mesh.points[node] - c) / self.size
            for j in range(3):
                B[dof, j] = 1.0 if k == j else 0.0
                w = np.zeros(3)
                w[j] = 1.0
                B[dof, 3 + j] = np.cross(w, X)[k] if k < 3 else w[k - 3]
        return B, c

    def _check_supported(self, mesh: _Mesh, held: np.ndarray, springs: Mapping[int, float]) -> None:
        if not len(held) and not springs:
            raise ModelError(f"frame {self.name!r} has no supports: add a fixed, pinned, roller or spring support")
        B, c = self._rigid_modes(mesh)
        dofs = np.union1d(held, np.array(list(springs), dtype=np.int64))
        G = B[dofs].T @ B[dofs]
        w, V = np.linalg.eigh(G)
        free = V[:, w <= 1e-10 * max(float(w.max()), 1.0)]
        if free.shape[1]:
            from mechverify.fea.linsolve import describe_mode

            names = ["translation along x", "translation along y", "translation along z",
                     "rotation about x", "rotation about y", "rotation about z"]
            motions = [describe_mode(free[:, k], names, c, self.size) for k in range(free.shape[1])]
            raise ModelError(f"frame {self.name!r} is not fully supported: the supports leave free "
                             + "; ".join(motions) + ". Add a support that prevents this motion.")

    def _mechanism(self, mesh: _Mesh, Kff: sp.spmatrix, free: np.ndarray) -> None:
        """Name an internal mechanism (e.g. a member free to spin about its axis between pins)."""
        if len(free) > DENSE_CHECK_LIMIT:
            return
        A = Kff.toarray()
        d = np.sqrt(np.abs(np.diag(A)))
        zero = np.flatnonzero(d == 0)
        if not len(zero):
            A = A / d[:, None] / d[None, :]
            w, V = np.linalg.eigh(A)
            idx = np.flatnonzero(w <= 1e-12 * max(float(w.max()), 1.0))
            if not len(idx):
                return
            v = V[:, idx[0]]
            big = np.flatnonzero(np.abs(v) >= 0.5 * np.max(np.abs(v)))
        else:
            big = zero
        words = []
        for i in big[:4]:
            node, k = mesh.dof_owner[free[i]]
            nm = mesh.names.get(node, "(" + ", ".join(f"{c * 1e3:.4g}" for c in mesh.points[node]) + ") mm")
            words.append(f"{_DOF_WORDS[DOF_NAMES[k]]} at node {nm}")
        raise ModelError(f"frame {self.name!r} is a mechanism: nothing resists the " + ", ".join(words)
                         + " (e.g. a member between pins free to twist about its axis, or hinges in line). "
                           "Hold that motion with a support or remove a hinge.")

    # ---------------------------------------------------------------------------------- solve
    def solve(self, loads: Iterable[Load] = (), *, name: str = "", progress: bool | None = None) -> FrameResults:
        """Linear static solution of one load case."""
        loads = tuple(loads)
        mesh = self._mesh(loads)
        with Steps(progress if progress is not None else mesh.ndof > PROGRESS_THRESHOLD, "frame") as step:
            step("assembling")
            K, klocal = self._stiffness(mesh)
            f, q, F_applied, M_applied = self._loads(mesh, loads)
            held, springs, at = self._restraints(mesh)
            self._check_supported(mesh, held, springs)
            Ks = K.tolil(copy=True)
            for dof, kv in springs.items():
                Ks[dof, dof] += kv
            Ks = Ks.tocsr()
            free = np.setdiff1d(np.arange(mesh.ndof), held)
            Kff = Ks[free][:, free]
            self._mechanism(mesh, Kff, free)
            step(f"solving {len(free)} unknowns")
            u = np.zeros(mesh.ndof)
            try:
                u[free] = spl.spsolve(Kff.tocsc(), f[free])
            except RuntimeError as exc:
                raise ModelError(f"frame {self.name!r}: the stiffness matrix is singular ({exc})") from None
            if not np.all(np.isfinite(u)):
                raise ModelError(f"frame {self.name!r}: the solve gave non-finite displacements (a mechanism)")
        r = K @ u - f  # forces the supports exert on the frame (before springs)
        reactions: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        RF, RM = np.zeros(3), np.zeros(3)
        for s, k in at:
            fr = r[6 * k:6 * k + 6].copy()
            for dname in s.springs:
                i = DOF_NAMES.index(dname)
                fr[i] = -springs[6 * k + i] * u[6 * k + i] if i not in s.held() else fr[i]
            mask = np.zeros(6, dtype=bool)
            mask[list(s.held())] = True
            mask[[DOF_NAMES.index(d) for d in s.springs]] = True
            fr[~mask] = 0.0
            label = s.at if isinstance(s.at, str) else mesh.names.get(k, f"support {len(reactions) + 1}")
            if label in reactions:
                label = f"{label} ({len(reactions) + 1})"
            reactions[label] = (fr[:3], fr[3:])
            RF += fr[:3]
            RM += fr[3:] + np.cross(mesh.points[k], fr[:3])
        scaleF = max(np.linalg.norm(F_applied), np.linalg.norm(RF), 1e-30)
        scaleM = max(np.linalg.norm(M_applied), np.linalg.norm(RM), scaleF * self.size, 1e-30)
        if np.linalg.norm(F_applied + RF) > 1e-6 * scaleF or np.linalg.norm(M_applied + RM) > 1e-6 * scaleM:
            raise ModelError(f"frame {self.name!r}: reactions do not balance the loads (forces {F_applied + RF} N, "
                             f"moments {M_applied + RM} N·m); the model is ill-conditioned")
        # element end forces in local axes (acting on the element), f = k u_local - f_fixed_end
        end = np.zeros((len(mesh.L), 12))
        for e in range(len(mesh.L)):
            T = np.kron(np.eye(4), mesh.R[e])
            end[e] = klocal[e] @ (T @ u[mesh.dofs[e]]) - fixed_end_forces(mesh.L[e], q[e])
        return FrameResults(self, mesh, u, end, q, reactions, F_applied, M_applied, name, loads)


# ------------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class Diagram:
    """Fields along one member: position ``s`` from its start, internal resultants (local axes), global
    displacement, and stresses at the section fibres (max over the fibres per position)."""

    member: str
    s: pint.Quantity
    N: pint.Quantity
    Vy: pint.Quantity
    Vz: pint.Quantity
    T: pint.Quantity
    My: pint.Quantity
    Mz: pint.Quantity
    displacement: pint.Quantity  # [n, 3] global
    points: pint.Quantity  # [n, 3] undeformed positions
    normal_stress: pint.Quantity  # [n, nfibre]
    shear_stress: pint.Quantity  # [n]
    von_mises: pint.Quantity  # [n, nfibre]
    fibres: pint.Quantity  # [nfibre, 2] section (y, z) from the centroid

    @property
    def bending_moment(self) -> pint.Quantity:
        """Resultant bending moment ``sqrt(My² + Mz²)``."""
        return (self.My**2 + self.Mz**2) ** 0.5


@dataclass(frozen=True)
class Extreme:
    """A maximum along the frame: value, member, position along it, point in space (and fibre)."""

    value: pint.Quantity
    member: str
    position: pint.Quantity
    location: pint.Quantity
    fibre: pint.Quantity | None = None

    def __str__(self) -> str:
        loc = ", ".join(f"{c:.4g}" for c in self.location.m_as("mm"))
        return f"{self.value:.4g~P} in member {self.member} at s = {self.position.m_as('mm'):.4g} mm ({loc}) mm"


def section_fibres(section: Section, n_round: int = 180) -> np.ndarray:
    """Candidate extreme fibres ``[k, 2]`` (y, z from the centroid) [m]: the vertices of the section's
    convex hull (the normal stress is linear over the section, so its extremes lie there); a circle of
    ``n_round`` points for round sections."""
    s = section.si()
    if section.kind in _ROUND_KINDS:
        r = s["c_y_pos"]
        a = np.linspace(0, 2 * math.pi, n_round, endpoint=False)
        return np.column_stack((r * np.cos(a), r * np.sin(a)))
    if section.geometry is None:
        return np.array([[s["c_y_pos"], 0], [-s["c_y_neg"], 0], [0, s["c_z_pos"]], [0, -s["c_z_neg"]]])
    hull = np.asarray(section.geometry.convex_hull.exterior.coords)[:-1]
    return hull - np.array([s["centroid_y"], s["centroid_z"]])


class FrameResults:
    """Results of one load case; SI arrays inside, quantities out."""

    def __init__(self, frame: Frame, mesh: _Mesh, u: np.ndarray, end_forces: np.ndarray, q: np.ndarray,
                 reactions: dict[str, tuple[np.ndarray, np.ndarray]], applied_force: np.ndarray,
                 applied_moment: np.ndarray, name: str, loads: tuple[Load, ...]):
        self.frame, self.mesh, self.u, self.end_forces, self.q = frame, mesh, u, end_forces, q
        self._reactions = reactions
        self.applied_force = Q(applied_force, "N")
        self.applied_moment = Q(applied_moment, "N*m")
        self.name, self.loads = name, loads
        self._diagrams: dict[tuple[str, int], Diagram] = {}

    # ------------------------------------------------------------------------------- nodes
    def _node(self, where: Where) -> int:
        p = self.frame.point(where)
        for k, x in enumerate(self.mesh.points):
            if np.linalg.norm(x - p) <= self.frame.tol:
                return k
        raise InputError(f"{where!r} is not a node of the analysis; use displacement_at(member, s)")

    def displacement(self, where: Where) -> pint.Quantity:
        """Translation (three global components) of a node."""
        k = self._node(where)
        return Q(self.u[6 * k:6 * k + 3].copy(), "m").to("mm")

    def rotation(self, where: Where) -> pint.Quantity:
        """Rotation (three global components) of a node (at a hinge: of the first member there)."""
        k = self._node(where)
        return Q(self.u[6 * k + 3:6 * k + 6].copy(), "rad")

    @property
    def reactions(self) -> dict[str, tuple[pint.Quantity, pint.Quantity]]:
        """Per support: (force [N], moment [N·m]) the support exerts on the frame, global components."""
        return {k: (Q(f, "N"), Q(m, "N*m")) for k, (f, m) in self._reactions.items()}

    # ------------------------------------------------------------------------- along members
    def _element_fields(self, e: int, s: np.ndarray) -> dict[str, np.ndarray]:
        """Internal resultants and local displacements at positions ``s`` (0..L) of element ``e``."""
        m = self.mesh
        pr = m.props[e]
        F1 = self.end_forces[e][:3]
        M1 = self.end_forces[e][3:6]
        qx, qy, qz = self.q[e]
        T = np.kron(np.eye(4), m.R[e])
        ul = (T @ self.u[m.dofs[e]])[:6]
        N = -F1[0] - qx * s
        Vy = -F1[1] - qy * s
        Vz = -F1[2] - qz * s
        Tx = -M1[0] + 0 * s
        My = -M1[1] - s * F1[2] - qz * s**2 / 2
        Mz = -M1[2] + s * F1[1] + qy * s**2 / 2
        sy = 1 / (pr.G * pr.Asy) if pr.Asy else 0.0
        sz = 1 / (pr.G * pr.Asz) if pr.Asz else 0.0
        a0, a1, a2 = -M1[2], F1[1], qy / 2  # Mz = a0 + a1 s + a2 s^2
        b0, b1, b2 = -M1[1], -F1[2], -qz / 2  # My = b0 + b1 s + b2 s^2
        u = ul[0] + (-F1[0] * s - qx * s**2 / 2) / (pr.E * pr.A)
        v = ul[1] + ul[5] * s + (a0 * s**2 / 2 + a1 * s**3 / 6 + a2 * s**4 / 12) / (pr.E * pr.Iz) \
            + (-F1[1] * s - qy * s**2 / 2) * sy
        w = ul[2] - ul[4] * s - (b0 * s**2 / 2 + b1 * s**3 / 6 + b2 * s**4 / 12) / (pr.E * pr.Iy) \
            + (-F1[2] * s - qz * s**2 / 2) * sz
        disp = np.column_stack((u, v, w)) @ m.R[e]  # local -> global
        return {"N": N, "Vy": Vy, "Vz": Vz, "T": Tx, "My": My, "Mz": Mz, "disp": disp}

    def diagram(self, member: str, points_per_element: int = 41, fibres: Any = None) -> Diagram:
        """Internal forces, displacements and fibre stresses along ``member``.

        ``fibres``: points of the section (y, z from the centroid, lengths ``[k, 2]``) where stresses
        are wanted; default the convex-hull vertices (every extreme fibre).
        """
        key = (member, points_per_element)
        if fibres is None and key in self._diagrams:
            return self._diagrams[key]
        fr = self.frame
        if member not in fr.member_index:
            raise UnknownNameError("member", member, fr.member_index)
        mi = fr.member_index[member]
        mem = fr.members[mi]
        els = np.flatnonzero(self.mesh.elem_member == mi)
        els = els[np.argsort(self.mesh.elem_s0[els])]
        parts: dict[str, list[np.ndarray]] = {k: [] for k in ("s", "N", "Vy", "Vz", "T", "My", "Mz", "disp", "pts")}
        for e in els:
            Le = self.mesh.L[e]
            s = np.linspace(0.0, Le, points_per_element)
            f = self._element_fields(e, s)
            a = self.mesh.points[self.mesh.elem_nodes[e, 0]]
            parts["s"].append(self.mesh.elem_s0[e] + s)
            parts["pts"].append(a + np.outer(s, self.mesh.R[e][0]))
            parts["disp"].append(f["disp"])
            for k in ("N", "Vy", "Vz", "T", "My", "Mz"):
                parts[k].append(f[k])
        c = {k: np.concatenate(v) for k, v in parts.items()}
        sec = mem.section.si()
        pr = self.mesh.props[els[0]]
        yz = section_fibres(mem.section) if fibres is None else np.atleast_2d(to_si(fibres, "length", "fibres"))
        cr, sr = math.cos(pr.roll), math.sin(pr.roll)
        yp = cr * yz[:, 0] + sr * yz[:, 1]  # fibre in principal axes
        zp = -sr * yz[:, 0] + cr * yz[:, 1]
        sigma = c["N"][:, None] / pr.A + np.outer(c["My"], zp) / pr.Iy - np.outer(c["Mz"], yp) / pr.Iz
        tau = np.abs(c["T"]) / sec["Wt"] + np.hypot(c["Vy"] / sec["Asy"], c["Vz"] / sec["Asz"])
        vm = np.sqrt(sigma**2 + 3 * tau[:, None] ** 2)
        d = Diagram(member, Q(c["s"], "m").to("mm"), Q(c["N"], "N"), Q(c["Vy"], "N"), Q(c["Vz"], "N"),
                    Q(c["T"], "N*m"), Q(c["My"], "N*m"), Q(c["Mz"], "N*m"), Q(c["disp"], "m").to("mm"),
                    Q(c["pts"], "m").to("mm"), Q(sigma, "Pa").to("MPa"), Q(tau, "Pa").to("MPa"),
                    Q(vm, "Pa").to("MPa"), Q(yz, "m").to("mm"))
        if fibres is None:
            self._diagrams[key] = d
        return d

    def diagrams(self) -> list[Diagram]:
        return [self.diagram(m.name) for m in self.frame.members]

    # ------------------------------------------------------------------------------- maxima
    def _extreme(self, values: Any, with_fibre: bool = False) -> Extreme:
        best: tuple[float, Diagram, int, int] | None = None
        for d in self.diagrams():
            v = np.asarray(values(d))
            idx = np.unravel_index(int(np.argmax(v)), v.shape)
            if best is None or v[idx] > best[0]:
                best = (float(v[idx]), d, int(idx[0]), int(idx[1]) if len(idx) > 1 else -1)
        assert best is not None
        val, d, i, j = best
        return Extreme(val, d.member, d.s[i], d.points[i], d.fibres[j] if with_fibre and j >= 0 else None)

    @property
    def max_displacement(self) -> Extreme:
        """The largest translation (magnitude) anywhere along the members."""
        e = self._extreme(lambda d: np.linalg.norm(d.displacement.m_as("mm"), axis=1))
        return Extreme(Q(e.value, "mm"), e.member, e.position, e.location)

    @property
    def max_von_mises(self) -> Extreme:
        """The largest von Mises stress at any fibre of any member (with the fibre)."""
        e = self._extreme(lambda d: d.von_mises.m_as("MPa"), with_fibre=True)
        return Extreme(Q(e.value, "MPa"), e.member, e.position, e.location, e.fibre)

    @property
    def max_bending_moment(self) -> Extreme:
        e = self._extreme(lambda d: d.bending_moment.m_as("N*m"))
        return Extreme(Q(e.value, "N*m"), e.member, e.position, e.location)

    def min_safety_factor(self) -> tuple[float, Extreme]:
        """Smallest yield safety factor ``Sy / sigma_vm`` over all members (each with its material) and where."""
        best: tuple[float, Extreme] | None = None
        for d in self.diagrams():
            m = self.frame.members[self.frame.member_index[d.member]]
            Sy = m.material.require("yield_strength").m_as("MPa")
            vm = d.von_mises.m_as("MPa")
            i, j = np.unravel_index(int(np.argmax(vm)), vm.shape)
            n = Sy / vm[i, j] if vm[i, j] > 0 else math.inf
            if best is None or n < best[0]:
                best = (n, Extreme(Q(vm[i, j], "MPa"), d.member, d.s[i], d.points[i], d.fibres[j]))
        assert best is not None
        return best

    # ------------------------------------------------------------------------------- figure
    def figure(self, path: str | Path | None = None, scale: float | None = None, title: str | None = None) -> Any:
        """Deformed shape (maximum marked) beside the bending-moment diagram of every member."""
        return frame_figure(self, path, scale, title)


def frame_figure(res: FrameResults, path: str | Path | None = None, scale: float | None = None,
                 title: str | None = None) -> Any:
    """The report figure of a frame solution: undeformed (grey) and deformed shape with the largest
    displacement marked (★), and the bending moments along each member."""
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    ds = res.diagrams()
    mx = res.max_displacement
    umax = mx.value.m_as("m")
    size = res.frame.size
    if scale is None:
        scale = 0.1 * size / umax if umax > 0 else 1.0
    pts = np.vstack([d.points.m_as("m") for d in ds])
    dis = np.vstack([d.displacement.m_as("m") for d in ds])
    span = np.ptp(np.vstack((pts, pts + scale * dis)), axis=0)
    flat = [i for i in range(3) if span[i] <= 1e-9 * size]
    fig = plt.figure(figsize=(10.0, 4.2))
    if flat:
        a, b = [i for i in range(3) if i != flat[0]]
        ax = fig.add_subplot(1, 2, 1)
        for d in ds:
            p, u = d.points.m_as("mm"), d.displacement.m_as("mm")
            ax.plot(p[:, a], p[:, b], color="0.7", lw=1.5)
            ax.plot(p[:, a] + scale * u[:, a], p[:, b] + scale * u[:, b], lw=2)
        i = int(np.argmin(np.linalg.norm(pts - mx.location.m_as("m"), axis=1)))
        tip = (pts[i] + scale * dis[i]) * 1e3
        ax.plot(tip[a], tip[b], "k*", ms=12)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{'xyz'[a]} [mm]")
        ax.set_ylabel(f"{'xyz'[b]} [mm]")
    else:
        ax = fig.add_subplot(1, 2, 1, projection="3d")
        for d in ds:
            p, u = d.points.m_as("mm"), d.displacement.m_as("mm")
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color="0.7", lw=1.5)
            ax.plot(*(p + scale * u).T, lw=2)
        i = int(np.argmin(np.linalg.norm(pts - mx.location.m_as("m"), axis=1)))
        ax.scatter(*((pts[i] + scale * dis[i]) * 1e3), color="k", marker="*", s=120, depthshade=False)
        both = np.vstack((pts, pts + scale * dis)) * 1e3
        lo, hi = both.min(axis=0), both.max(axis=0)
        mid, half = (lo + hi) / 2, float(np.max(hi - lo)) / 2 or 1.0
        ax.set_xlim(mid[0] - half, mid[0] + half)
        ax.set_ylim(mid[1] - half, mid[1] + half)
        ax.set_zlim(mid[2] - half, mid[2] + half)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_zlabel("z [mm]")
    ax.set_title(f"deformed shape x{scale:.3g}; max {mx.value.m_as('mm'):.4g} mm (★) in {mx.member}", fontsize=9)
    ax2 = fig.add_subplot(1, 2, 2)
    for d in ds:
        s = d.s.m_as("mm")
        my, mz = d.My.m_as("N*m"), d.Mz.m_as("N*m")
        if np.max(np.abs(my)) >= np.max(np.abs(mz)):
            ax2.plot(s, my, lw=1.8, label=f"{d.member}: M_y")
        else:
            ax2.plot(s, mz, lw=1.8, ls="--", label=f"{d.member}: M_z")
    ax2.axhline(0.0, color="0.5", lw=0.8)
    mm = res.max_bending_moment
    ax2.set_title(f"bending moment along each member; max |M| {mm.value.m_as('N*m'):.4g} N·m in {mm.member}",
                  fontsize=9)
    ax2.set_xlabel("position along the member from its start [mm]")
    ax2.set_ylabel("moment [N·m]")
    ax2.legend(fontsize=7, ncol=2 if len(ds) > 6 else 1)
    ax2.grid(alpha=0.3)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=120)
        plt.close(fig)
    return fig
