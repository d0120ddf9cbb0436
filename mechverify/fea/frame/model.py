"""Frame model inputs: members (with end releases), supports (with springs), hinges, two-node springs,
loads (nodal, along members, partial and trapezoidal, self-weight, support displacements) and load
combinations. Everything is validated here; lengths and forces accept quantities or strings.

Conventions are those of :mod:`mechverify.fea.frame` (member local x from start to end, local z the
component of ``orientation`` normal to x, y = z × x; principal axes for a section with a product of
inertia).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pint

from mechverify.components.sections import Section
from mechverify.errors import InputError, renamed, suggest
from mechverify.frozen import set_fields
from mechverify.materials.material import Material
from mechverify.units import BOUNDS, QuantityLike, from_si, to_si

#: Node DOF names, in order (translations then rotations, global axes).
DOF_NAMES = ("x", "y", "z", "rx", "ry", "rz")
DOF_WORDS = {"x": "translation along x", "y": "translation along y", "z": "translation along z",
             "rx": "rotation about x", "ry": "rotation about y", "rz": "rotation about z"}
#: Member end forces that can be released (local axes): axial force, shears, torque, bending moments.
RELEASE_NAMES = ("N", "Vy", "Vz", "T", "My", "Mz")
_RELEASE_ALIASES = {"fx": "N", "fy": "Vy", "fz": "Vz", "mx": "T", "n": "N", "vy": "Vy", "vz": "Vz", "t": "T",
                    "my": "My", "mz": "Mz"}
SUPPORT_KINDS = ("fixed", "pinned", "roller", "spring", "custom")
THEORIES = ("timoshenko", "euler")
STANDARD_GRAVITY = 9.80665
#: Flags in ``Section.method`` of a tabulated section without fibre distances / shear areas.
NO_FIBRES = "no fibre distances"
NO_SHEAR_AREAS = "no shear areas"

Where = str | Any  # a node name, or a point (three lengths)


# ----------------------------------------------------------------------------------------- helpers
def _material(m: Any, name: str) -> Material:
    if isinstance(m, Material):
        return m
    if isinstance(m, str):
        from mechverify.materials.database import get

        return get(m)
    raise InputError(f"{name}: expected a Material or its name, got {m!r}")


_UNIT_FACTORS: dict[tuple[Any, str], float] = {}


def _si(v: Any, dim: str, name: str) -> Any:
    """:func:`~mechverify.units.to_si` with the unit factor of a quantity cached (large frames convert
    thousands of loads and points): the dimension is checked once per unit, the bounds on every value."""
    if isinstance(v, pint.Quantity):
        key = (v._units, dim)
        f = _UNIT_FACTORS.get(key)
        if f is None:
            f = _UNIT_FACTORS[key] = to_si(v.__class__(1.0, v.units), dim, name)
        mag = np.asarray(v.magnitude, dtype=float) * f
        if np.all(np.isfinite(mag)) and np.all(np.abs(mag) <= BOUNDS[dim][1]):
            return float(mag) if mag.ndim == 0 else mag
    return to_si(v, dim, name)  # strings, numbers without units, values out of bounds: the named errors


def _vector(v: Any, dim: str, name: str) -> np.ndarray:
    """Three components with units (a quantity array, or three strings/quantities) as SI floats."""
    if isinstance(v, pint.Quantity | str):
        arr = np.atleast_1d(np.asarray(_si(v, dim, name), dtype=float))
    else:
        try:
            items = list(v)
        except TypeError:
            raise InputError(f"{name}: expected three components, got {v!r}") from None
        arr = np.array([_si(c, dim, f"{name}[{i}]") for i, c in enumerate(items)], dtype=float)
    if arr.shape != (3,):
        raise InputError(f"{name}: expected three components (x, y, z), got {arr.size}")
    return arr


def _axis(axis: str, name: str) -> int:
    a = str(axis).lower().removeprefix("r")
    if a not in ("x", "y", "z"):
        raise InputError(f"{name}: expected a global axis 'x', 'y' or 'z', got {axis!r}")
    return "xyz".index(a)


def _dof(name: Any, what: str) -> int:
    k = str(name).lower()
    if k not in DOF_NAMES:
        raise InputError(f"{what}: expected names among {', '.join(DOF_NAMES)}, got {name!r}")
    return DOF_NAMES.index(k)


def _dof_value(dof: int, v: Any, what: str, kind: str) -> float:
    """A stiffness (kind "stiffness") or a displacement (kind "displacement") of DOF ``dof`` in SI."""
    rot = dof >= 3
    dim = {"stiffness": ("torsional_stiffness" if rot else "force_per_length"),
           "displacement": ("angle" if rot else "length")}[kind]
    return to_si(v, dim, what)


# ------------------------------------------------------------------------------------------ members
@dataclass(frozen=True)
class Release:
    """End forces released at one member end (local axes): ``N`` (axial), ``Vy``, ``Vz`` (shears), ``T``
    (torque), ``My``, ``Mz`` (bending moments). ``Release.parse("My,Mz")`` reads a list; a pin is
    ``Release(My=True, Mz=True)``. A released force is zero at that end whatever the node does."""

    N: bool = False
    Vy: bool = False
    Vz: bool = False
    T: bool = False
    My: bool = False
    Mz: bool = False

    @classmethod
    def parse(cls, v: Any, what: str = "releases") -> Release:
        if v is None:
            return cls()
        if isinstance(v, Release):
            return v
        items = [s.strip() for s in v.replace(";", ",").split(",")] if isinstance(v, str) else list(v)
        names = {}
        for it in items:
            if it == "":
                continue
            key = _RELEASE_ALIASES.get(str(it).lower())
            if key is None:
                hint = suggest(str(it), RELEASE_NAMES, 1)
                raise InputError(f"{what}: expected end forces among {', '.join(RELEASE_NAMES)}, got {it!r}"
                                 + (f"; did you mean {hint[0]!r}?" if hint else ""))
            names[key] = True
        return cls(**names)

    @property
    def indices(self) -> tuple[int, ...]:
        """Local DOF indices (0..5) released."""
        return tuple(i for i, n in enumerate(RELEASE_NAMES) if getattr(self, n))

    def __bool__(self) -> bool:
        return bool(self.indices)

    def __str__(self) -> str:
        return ", ".join(RELEASE_NAMES[i] for i in self.indices) or "none"


@dataclass(frozen=True)
class Member:
    """A straight prismatic member from node ``start`` to node ``end`` (names or points).

    ``orientation``: a vector in the local x-z plane (default global Z; global X for a vertical
    member). ``theory``: "timoshenko" or "euler" (default: the frame's). ``divisions``: elements
    along the member (results are exact with one; more only refine the figure).
    ``releases_start`` / ``releases_end``: end forces released at each end (a :class:`Release`, or
    names such as ``"My,Mz"`` for a pin; ``"T"`` for a torsion release, ``"N"`` for a slotted end).
    """

    start: Where
    end: Where
    section: Section
    material: Material | str
    name: str = ""
    orientation: Any = None
    theory: str | None = None
    divisions: int = 1
    releases_start: Release | str | Sequence[str] | None = None
    releases_end: Release | str | Sequence[str] | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.section, Section):
            raise InputError(f"member {self.name}: section must be a Section (mechverify.components.sections), "
                             f"got {type(self.section).__name__}")
        set_fields(self, material=_material(self.material, f"member {self.name}: material"))
        if self.theory is not None and self.theory not in THEORIES:
            raise InputError(f"member {self.name}: theory must be one of {THEORIES}, got {self.theory!r}")
        if not isinstance(self.divisions, int) or self.divisions < 1:
            raise InputError(f"member {self.name}: divisions must be a whole number >= 1, got {self.divisions!r}")
        if self.orientation is not None:
            o = np.asarray(self.orientation, dtype=float)
            if o.shape != (3,) or not np.linalg.norm(o) > 0:
                raise InputError(f"member {self.name}: orientation must be a non-zero 3-vector, "
                                 f"got {self.orientation!r}")
            set_fields(self, orientation=tuple(float(c) for c in o))
        set_fields(self, releases_start=Release.parse(self.releases_start,
                                                      f"member {self.name}: releases_start"))
        set_fields(self, releases_end=Release.parse(self.releases_end, f"member {self.name}: releases_end"))

    def renamed(self, name: str) -> Member:
        import dataclasses

        return dataclasses.replace(self, name=name)


def section_from_properties(area: QuantityLike, Iy: QuantityLike, Iz: QuantityLike, J: QuantityLike, *,
                            Asy: QuantityLike | None = None, Asz: QuantityLike | None = None,
                            c_y: QuantityLike | None = None, c_z: QuantityLike | None = None,
                            Wt: QuantityLike | None = None, Iyz: QuantityLike = "0 mm**4",
                            name: str = "tabulated", source: str = "") -> Section:
    """A :class:`Section` from tabulated properties (a steel table, a manufacturer's sheet).

    ``area`` A, ``Iy``/``Iz`` (bending about local y/z), ``J`` (torsion constant); optional shear areas
    ``Asy``/``Asz`` (without them shear deformation is neglected — Euler-Bernoulli for that member — and
    the shear stress uses V/A), extreme fibre distances ``c_y``/``c_z`` (symmetric, the corners of the
    bounding box are the fibres; without them stresses are not computed and asking for one is an
    error), torsion modulus ``Wt`` (default ``J / sqrt(c_y² + c_z²)``: exact for round sections,
    conservative for rectangles and open profiles). Wpl is not known (zero).
    """
    A = to_si(area, "area", "area")
    vals = {"Iy": to_si(Iy, "second_moment", "Iy"), "Iz": to_si(Iz, "second_moment", "Iz"),
            "J": to_si(J, "second_moment", "J"), "Iyz": to_si(Iyz, "second_moment", "Iyz")}
    for k, v in (("area", A), *vals.items()):
        if k != "Iyz" and not v > 0:
            raise InputError(f"section property {k} must be positive, got {v!r}")
    flags = []
    if c_y is None or c_z is None:
        flags.append(NO_FIBRES)
    if Asy is None or Asz is None:
        flags.append(NO_SHEAR_AREAS)
    cy = to_si(c_y, "length", "c_y") if c_y is not None else 0.0
    cz = to_si(c_z, "length", "c_z") if c_z is not None else 0.0
    asy = to_si(Asy, "area", "Asy") if Asy is not None else A
    asz = to_si(Asz, "area", "Asz") if Asz is not None else A
    if Wt is not None:
        wt = to_si(Wt, "volume", "Wt")
    else:
        wt = vals["J"] / math.hypot(cy, cz) if cy or cz else vals["J"] ** 0.75
    from mechverify.components.sections import _FIELDS, _principal

    I1, I2, phi = _principal(vals["Iy"], vals["Iz"], vals["Iyz"])
    si = {"area": A, "centroid_y": 0.0, "centroid_z": 0.0, **vals, "I1": I1, "I2": I2, "principal_angle": phi,
          "Wt": wt, "Asy": asy, "Asz": asz, "Wel_y": vals["Iy"] / cz if cz else 0.0,
          "Wel_z": vals["Iz"] / cy if cy else 0.0, "Wpl_y": 0.0, "Wpl_z": 0.0, "c_y_pos": cy, "c_y_neg": cy,
          "c_z_pos": cz, "c_z_neg": cz, "shear_center_y": 0.0, "shear_center_z": 0.0}
    q = {k: from_si(si[k], dim) for k, dim in _FIELDS.items()}
    return Section(kind="properties", dimensions={}, method="; ".join(["tabulated properties", *flags]),
                   source=source or f"tabulated ({name})", **q)


# ----------------------------------------------------------------------------------------- supports
@dataclass(frozen=True)
class FrameSupport:
    """A support at a node or point.

    ``kind``: ``"fixed"`` (all six motions held), ``"pinned"`` (three translations held, rotations
    free), ``"roller"`` (the translation along ``direction`` held), ``"spring"`` (elastic: ``springs``
    maps ``"x"``..``"rz"`` to a stiffness in N/m or N·m/rad), ``"custom"`` (the motions listed in
    ``hold`` held, e.g. ``("x", "y", "z", "rz")``); ``springs`` may be added to any kind.
    ``one_way`` makes springs act in one direction only: ``{"z": "+"}`` — the support can push the
    node along +z but never pull (a bearing pad it rests on); solved by active-set iteration.
    """

    at: Where
    kind: str = "fixed"
    direction: str = "z"
    hold: tuple[str, ...] = ()
    springs: Mapping[str, Any] = field(default_factory=dict)
    one_way: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in SUPPORT_KINDS:
            hint = suggest(self.kind, SUPPORT_KINDS, 1)
            raise InputError(f"support kind must be one of {', '.join(SUPPORT_KINDS)}, got {self.kind!r}"
                             + (f"; did you mean {hint[0]!r}?" if hint else ""))
        hold = tuple(str(h).lower() for h in self.hold)
        for h in hold:
            _dof(h, "support hold")
        if self.kind == "custom" and not hold:
            raise InputError("support kind 'custom' needs hold = the motions it prevents, e.g. ('x', 'y', 'z')")
        if self.kind != "custom" and hold:
            raise InputError(f"support hold: only for kind 'custom' (kind is {self.kind!r})")
        _axis(self.direction, "support direction")
        springs: dict[str, float] = {}
        for k, v in dict(self.springs).items():
            i = _dof(k, "support springs")
            val = _dof_value(i, v, f"springs.{DOF_NAMES[i]}", "stiffness")
            if val <= 0:
                raise InputError(f"support springs.{DOF_NAMES[i]}: stiffness must be positive, got {v!r}")
            springs[DOF_NAMES[i]] = val
        if self.kind == "spring" and not springs:
            raise InputError("support kind 'spring' needs springs = {direction: stiffness}, e.g. {'z': '2e5 N/m'}")
        one: dict[str, int] = {}
        for k, v in dict(self.one_way).items():
            kk = DOF_NAMES[_dof(k, "support one_way")]
            if kk not in springs:
                raise InputError(f"support one_way.{kk}: only a spring can act one way; give springs.{kk} too")
            if v not in ("+", "-"):
                raise InputError(f"support one_way.{kk}: '+' (the support pushes along +{kk}) or '-', got {v!r}")
            if DOF_NAMES.index(kk) in self._held(hold):
                raise InputError(f"support one_way.{kk}: that motion is held rigidly by the support kind")
            one[kk] = 1 if v == "+" else -1
        set_fields(self, hold=hold, springs=springs, one_way=one)

    def _held(self, hold: tuple[str, ...]) -> tuple[int, ...]:
        if self.kind == "fixed":
            return tuple(range(6))
        if self.kind == "pinned":
            return (0, 1, 2)
        if self.kind == "roller":
            return (_axis(self.direction, "direction"),)
        return tuple(DOF_NAMES.index(h) for h in hold)

    def held(self) -> tuple[int, ...]:
        """Indices (0..5) of the held motions."""
        return self._held(self.hold)


@dataclass(frozen=True)
class Hinge:
    """A pin joint at a node: the member ends meeting there rotate independently about the global
    ``axis`` (one of x, y, z). Sugar over member end releases: every member end at the node except
    the first is released about the axis; with one member end at the node, that end is released (a
    pinned connection to a fixed support). A hinge that releases nothing effective is an error."""

    at: Where
    axis: str = "z"

    def __post_init__(self) -> None:
        _axis(self.axis, "hinge axis")


@dataclass(frozen=True)
class Spring:
    """A two-node spring element between nodes ``start`` and ``end``.

    ``axial``: a stiffness [N/m] along the line between the nodes (a truss-like spring, Logan Ch. 2).
    ``stiffness``: a six-component spring in global axes, ``{"x": "1e6 N/m", "rz": "5e3 N*m/rad"}``
    (translational components need coincident nodes, or a component along the line: a force across
    an offset would not be in equilibrium). Give one of the two.
    """

    start: Where
    end: Where
    axial: Any = None
    stiffness: Mapping[str, Any] = field(default_factory=dict)
    name: str = ""

    def __post_init__(self) -> None:
        what = f"spring {self.name}" if self.name else "spring"
        if (self.axial is None) == (not self.stiffness):
            raise InputError(f"{what}: give axial (a stiffness along the line) or stiffness = "
                             "{component: value}, one of the two")
        if self.axial is not None:
            k = to_si(self.axial, "force_per_length", f"{what}: axial")
            if not k > 0:
                raise InputError(f"{what}: axial stiffness must be positive, got {self.axial!r}")
            set_fields(self, axial=k)
        comps: dict[str, float] = {}
        for key, v in dict(self.stiffness).items():
            i = _dof(key, f"{what}: stiffness")
            val = _dof_value(i, v, f"{what}: stiffness.{DOF_NAMES[i]}", "stiffness")
            if not val > 0:
                raise InputError(f"{what}: stiffness.{DOF_NAMES[i]} must be positive, got {v!r}")
            comps[DOF_NAMES[i]] = val
        set_fields(self, stiffness=comps)

    def renamed(self, name: str) -> Spring:
        """This spring under another name (a new instance: the frame names unnamed springs S1, S2, ...)."""
        import dataclasses

        axial = None if self.axial is None else from_si(self.axial, "force_per_length")
        stiffness = {k: from_si(v, "torsional_stiffness" if DOF_NAMES.index(k) >= 3 else "force_per_length")
                     for k, v in self.stiffness.items()}
        return dataclasses.replace(self, name=name, axial=axial, stiffness=stiffness)


# -------------------------------------------------------------------------------------------- loads
def _axes(axes: str, what: str) -> None:
    if axes not in ("global", "local"):
        raise InputError(f"{what} axes must be 'global' or 'local', got {axes!r}")


@dataclass(frozen=True)
class FramePointLoad:
    """A force (N, three global components) and/or a moment (N·m) at a node or at a point on a member."""

    at: Where
    force: Any = None
    moment: Any = None

    def vectors(self) -> tuple[np.ndarray, np.ndarray]:
        f = np.zeros(3) if self.force is None else _vector(self.force, "force", "force")
        m = np.zeros(3) if self.moment is None else _vector(self.moment, "torque", "moment")
        return f, m


@dataclass(frozen=True)
class MemberPointLoad:
    """A force and/or moment at ``position`` (a length from the member's start) on member ``member``, in
    the member's ``axes`` "local" (default: x along the member, y, z its section axes) or "global"."""

    member: str
    position: Any
    force: Any = None
    moment: Any = None
    axes: str = "local"

    def __post_init__(self) -> None:
        _axes(self.axes, "member point load")
        to_si(self.position, "length", "position")
        if self.force is None and self.moment is None:
            raise InputError(f"member point load on {self.member}: give force and/or moment")

    def vectors(self) -> tuple[np.ndarray, np.ndarray]:
        return FramePointLoad(None, self.force, self.moment).vectors()


@dataclass(frozen=True)
class DistributedLoad:
    """A load per length (N/m, three components) on member ``member``, in ``axes`` "global" (default) or
    "local" (the member's x, y, z). Uniform over the whole member by default; ``start``/``end``
    (lengths from the member's start) limit it to part of the member, and ``load_end`` (the value at
    ``end``) makes it vary linearly from ``load`` at ``start`` (trapezoidal or triangular)."""

    member: str
    load: Any
    axes: str = "global"
    start: Any = None
    end: Any = None
    load_end: Any = None

    def __post_init__(self) -> None:
        _axes(self.axes, "distributed load")
        _vector(self.load, "force_per_length", "load")
        if self.load_end is not None:
            _vector(self.load_end, "force_per_length", "load_end")
        a = 0.0 if self.start is None else to_si(self.start, "length", "start")
        if a < 0:
            raise InputError(f"distributed load on {self.member}: start must be >= 0, got {self.start!r}")
        if self.end is not None and not to_si(self.end, "length", "end") > a:
            raise InputError(f"distributed load on {self.member}: end must lie beyond start, got {self.end!r}")

    def values(self) -> tuple[np.ndarray, np.ndarray]:
        w0 = _vector(self.load, "force_per_length", "load")
        return w0, (w0 if self.load_end is None else _vector(self.load_end, "force_per_length", "load_end"))


@dataclass(frozen=True)
class FrameSelfWeight:
    """The weight of every member, rho A g per length, along ``direction`` (default -Z) times ``factor``."""

    g: Any = "9.80665 m/s**2"
    direction: tuple[float, float, float] = (0.0, 0.0, -1.0)
    factor: float = 1.0

    def vector(self) -> np.ndarray:
        d = np.asarray(self.direction, dtype=float)
        if d.shape != (3,) or not np.linalg.norm(d) > 0:
            raise InputError(f"self-weight direction must be a non-zero 3-vector, got {self.direction!r}")
        return to_si(self.g, "acceleration", "g") * self.factor * d / np.linalg.norm(d)


@dataclass(frozen=True)
class SupportDisplacement:
    """An enforced displacement of a support (settlement) as a load: ``values`` maps held motions to
    their imposed values, ``{"z": "-10 mm", "ry": "0.002 rad"}`` (global axes). Only motions that a
    support holds can be imposed."""

    at: Where
    values: Mapping[str, Any]

    def __post_init__(self) -> None:
        vals: dict[str, float] = {}
        if not self.values:
            raise InputError("support displacement: give values = {motion: value}, e.g. {'z': '-10 mm'}")
        for k, v in dict(self.values).items():
            i = _dof(k, "support displacement")
            vals[DOF_NAMES[i]] = _dof_value(i, v, f"support displacement.{DOF_NAMES[i]}", "displacement")
        set_fields(self, values=vals)


Load = FramePointLoad | MemberPointLoad | DistributedLoad | FrameSelfWeight | SupportDisplacement


@dataclass(frozen=True)
class LoadCombination:
    """A factored sum of load cases, ``LoadCombination("ULS 1", {"dead": 1.35, "live": 1.5})``."""

    name: str
    factors: Mapping[str, float]

    def __post_init__(self) -> None:
        if not self.factors:
            raise InputError(f"load combination {self.name!r}: no factors")
        out = {}
        for k, v in dict(self.factors).items():
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
                raise InputError(f"load combination {self.name!r}: factor of {k!r} must be a number, got {v!r}")
            out[str(k)] = float(v)
        set_fields(self, factors=out)


__all__ = ["DOF_NAMES", "RELEASE_NAMES", "SUPPORT_KINDS", "THEORIES", "STANDARD_GRAVITY", "Where", "Release",
           "Member", "FrameSupport", "Hinge", "Spring", "FramePointLoad", "MemberPointLoad", "DistributedLoad",
           "FrameSelfWeight", "SupportDisplacement", "Load", "LoadCombination", "section_from_properties", ]

# Former names (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"PointLoad": "FramePointLoad", "Support": "FrameSupport",
                                 "SelfWeight": "FrameSelfWeight"})
