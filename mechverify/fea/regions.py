"""Regions of a model's boundary, selected in physical terms: a plane, a box, a cylinder (hole or bolt
surface), a circle or an arc in 2D, any curve as a polyline, or a region named in the mesh (a gmsh
physical group of any dimension: points, curves, surfaces).

A region decides, for given points (SI coordinates ``[dim, n]``), whether each lies in it. A facet
(boundary triangle or edge) belongs to the region when all its vertices do; nothing is ever chosen
by node number.

Region protocol (for your own regions)
--------------------------------------
Subclass :class:`Region` (a frozen dataclass is best, so models stay hashable) and define

- ``contains(points, tol) -> bool[n]``: which of the points ``[dim, n]`` (metres; dim = 2 for plane
  models, 3 for solids) lie in the region, ``tol`` (m) being the model's geometric tolerance;
- ``describe() -> str``: a short phrase for messages ("arc r = 5 mm about (0, 0) mm");
- optionally ``measure(dim) -> float | None``: the region's true size when the geometry knows it - a
  length [m] for a curve (``dim`` = 2) or an area [m²] for a surface (``dim`` = 3), ``None`` otherwise.

Every load and support reports what its region caught (:class:`mechverify.fea.loads.RegionReport`:
facet count, length or area, resultant) and warns when that differs by more than
:data:`MEASURE_RTOL` from ``measure(dim)`` or from an ``expect_length=`` / ``expect_area=`` stated on
the load or support.

    >>> import numpy as np
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Slot(Region):              # the straight edge 0 <= x <= 10 mm at y = 0
    ...     def contains(self, points, tol):
    ...         return (np.abs(points[1]) <= tol) & (points[0] >= -tol) & (points[0] <= 0.01 + tol)
    ...     def describe(self):
    ...         return "slot edge"
    ...     def measure(self, dim):
    ...         return 0.01 if dim == 2 else None
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.frozen import set_fields
from mechverify.units import QuantityLike, to_si

#: Relative difference between what a region caught and its known size above which a warning is given.
#: Faceting a curve with 8 straight segments per half circle shortens it by 0.6 %; 3 % leaves room for
#: coarse meshes and still flags a region that misses an element's worth of an edge.
MEASURE_RTOL = 0.03


def _vec(value: Any, name: str, dim: str = "length") -> tuple[float, ...]:
    if isinstance(value, str) or not isinstance(value, Sequence):
        raise InputError(f"{name}: expected a sequence of 2 or 3 {dim}s, got {value!r}")
    if len(value) not in (2, 3):
        raise InputError(f"{name}: expected 2 or 3 components, got {len(value)}")
    return tuple(to_si(v, dim, f"{name}[{i}]") for i, v in enumerate(value))


class Region:
    """Base class: ``contains(points, tol)`` -> bool mask over the columns of ``points`` (see the module
    docstring for the protocol)."""

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:  # pragma: no cover - interface
        raise NotImplementedError

    def describe(self) -> str:  # pragma: no cover - interface
        raise NotImplementedError

    def measure(self, dim: int) -> float | None:
        """The region's true length [m] (``dim`` = 2) or area [m²] (``dim`` = 3), when known."""
        return None


@dataclass(frozen=True, init=False)
class Plane(Region):
    """Points on a plane: ``Plane(x="0 mm")`` or ``Plane(point=(...), normal=(1, 0, 0))``.

    In 2D models the "plane" is a line (``Plane(y="0 mm")``).
    """

    point: tuple[float, ...]
    normal: tuple[float, ...]

    def __init__(self, x: Any = None, y: Any = None, z: Any = None, *, point: Any = None, normal: Any = None):
        given = [(k, v) for k, v in (("x", x), ("y", y), ("z", z)) if v is not None]
        if given and (point is not None or normal is not None):
            raise InputError("Plane: give either one coordinate (x=, y= or z=) or point= and normal=")
        if len(given) > 1:
            raise InputError("Plane: give only one of x=, y=, z=")
        if given:
            k, v = given[0]
            axis = "xyz".index(k)
            pt = [0.0, 0.0, 0.0]
            pt[axis] = to_si(v, "length", k)
            nrm = [0.0, 0.0, 0.0]
            nrm[axis] = 1.0
        elif point is not None and normal is not None:
            pt = list(_vec(point, "point")) + [0.0] * (3 - len(point))
            n = np.asarray(_vec(normal, "normal", "dimensionless") + (0.0,) * (3 - len(normal)), float)
            if np.linalg.norm(n) == 0:
                raise InputError("Plane: normal must not be zero")
            nrm = list(n / np.linalg.norm(n))
        else:
            raise InputError("Plane: give one coordinate (x=, y= or z=) or point= and normal=")
        set_fields(self, point=tuple(pt), normal=tuple(nrm))

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        d = points.shape[0]
        dist = (points - np.asarray(self.point[:d])[:, None]).T @ np.asarray(self.normal[:d])
        return np.abs(dist) <= tol

    def describe(self) -> str:
        return f"plane through {tuple(round(c * 1e3, 4) for c in self.point)} mm, normal {self.normal}"


@dataclass(frozen=True, init=False)
class Box(Region):
    """Points inside an axis-aligned box (bounds inclusive): ``Box(("0 mm",)*3, ("10 mm", "5 mm", "5 mm"))``."""

    lo: tuple[float, ...]
    hi: tuple[float, ...]

    def __init__(self, lo: Any, hi: Any):
        lo_, hi_ = _vec(lo, "lo"), _vec(hi, "hi")
        if len(lo_) != len(hi_):
            raise InputError("Box: lo and hi must have the same number of components")
        if any(a > b for a, b in zip(lo_, hi_)):
            raise InputError(f"Box: lo must not exceed hi in any component, got lo={lo!r}, hi={hi!r}")
        set_fields(self, lo=lo_, hi=hi_)

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        d = min(points.shape[0], len(self.lo))
        lo = np.asarray(self.lo[:d])[:, None] - tol
        hi = np.asarray(self.hi[:d])[:, None] + tol
        return np.all((points[:d] >= lo) & (points[:d] <= hi), axis=0)

    def describe(self) -> str:
        return f"box {tuple(round(c * 1e3, 4) for c in self.lo)}-{tuple(round(c * 1e3, 4) for c in self.hi)} mm"


@dataclass(frozen=True, init=False)
class Cylinder(Region):
    """Points on a cylindrical surface (a hole wall, a bolt or pin surface) of ``radius`` about an axis.

    ``Cylinder(center=("50 mm", "20 mm", "0 mm"), radius="3 mm", axis=(0, 0, 1))``. In 2D this is a
    circle. Points within ``rel_tol * radius`` of the surface count (straight-sided elements cut
    the chord of a curved hole, so an exact test would miss nodes).
    """

    center: tuple[float, ...]
    radius: float
    axis: tuple[float, ...]
    rel_tol: float

    def __init__(self, center: Any, radius: QuantityLike, axis: Any = (0, 0, 1), rel_tol: float = 0.05):
        c = _vec(center, "center")
        r = to_si(radius, "length", "radius")
        if r <= 0:
            raise InputError(f"Cylinder: radius must be positive, got {radius!r}")
        a = np.asarray(_vec(axis, "axis", "dimensionless") + (0.0,) * (3 - len(axis)), float)
        if np.linalg.norm(a) == 0:
            raise InputError("Cylinder: axis must not be zero")
        set_fields(self, center=c + (0.0,) * (3 - len(c)), radius=r, axis=tuple(a / np.linalg.norm(a)),
                   rel_tol=float(rel_tol))

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        d = points.shape[0]
        rel = points - np.asarray(self.center[:d])[:, None]
        if d == 3:
            a = np.asarray(self.axis)[:, None]
            rel = rel - a * (a.T @ rel)
        r = np.linalg.norm(rel, axis=0)
        return np.abs(r - self.radius) <= self.rel_tol * self.radius + tol

    def describe(self) -> str:
        return f"cylinder r = {self.radius * 1e3:g} mm about {tuple(round(c * 1e3, 4) for c in self.center)} mm"


@dataclass(frozen=True, init=False)
class Arc(Region):
    """Points on a circular arc about ``center`` from angle ``start`` to ``end`` (counter-clockwise,
    measured from +x; degrees unless given as quantities) - a fillet, part of a hole's rim. In 3D the arc
    is swept along z (a partial cylinder wall about a z-parallel axis). Radial tolerance as
    :class:`Cylinder`; ``measure`` is the arc length ``r (end - start)`` in 2D.
    """

    center: tuple[float, ...]
    radius: float
    start: float  # rad
    end: float  # rad
    rel_tol: float

    def __init__(self, center: Any, radius: QuantityLike, start: Any, end: Any, rel_tol: float = 0.05):
        c = _vec(center, "center")
        r = to_si(radius, "length", "radius")
        if r <= 0:
            raise InputError(f"Arc: radius must be positive, got {radius!r}")
        a0, a1 = (float(np.deg2rad(v)) if isinstance(v, int | float) else to_si(v, "angle", k)
                  for k, v in (("start", start), ("end", end)))
        if not 0 < a1 - a0 <= 2 * np.pi + 1e-12:
            raise InputError(f"Arc: end must exceed start by at most a full turn, got {start!r} to {end!r}")
        set_fields(self, center=c + (0.0,) * (3 - len(c)), radius=r, start=a0, end=a1, rel_tol=float(rel_tol))

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        dx = points[0] - self.center[0]
        dy = points[1] - self.center[1]
        r = np.hypot(dx, dy)
        on = np.abs(r - self.radius) <= self.rel_tol * self.radius + tol
        ang = np.mod(np.arctan2(dy, dx) - self.start, 2 * np.pi)
        slack = tol / self.radius + 1e-12
        within = (ang <= self.end - self.start + slack) | (ang >= 2 * np.pi - slack)
        return on & within

    def measure(self, dim: int) -> float | None:
        return self.radius * (self.end - self.start) if dim == 2 else None

    def describe(self) -> str:
        return (f"arc r = {self.radius * 1e3:g} mm about {tuple(round(c * 1e3, 4) for c in self.center[:2])} mm "
                f"from {np.rad2deg(self.start):g} to {np.rad2deg(self.end):g} deg")


@dataclass(frozen=True, init=False)
class Polyline(Region):
    """Points within ``tol`` of a polyline through ``points`` (lengths, ``[(x, y), ...]`` or 3D): any curve
    - an ellipse, a spline, a cam profile - given as enough samples that its chords stay within ``tol``
    of it. ``tol`` defaults to 1 % of the polyline's length. ``measure`` is the polyline's length (2D).
    """

    vertices: tuple[tuple[float, ...], ...]
    tol: float

    def __init__(self, points: QuantityLike, tol: QuantityLike | None = None):
        if hasattr(points, "units") and np.ndim(points.magnitude) == 2:  # a quantity array [n, d]
            arr = np.asarray(to_si(points, "length", "points"), float)
            points = [tuple(r) for r in arr]
            pts = tuple(tuple(float(v) for v in r) for r in arr)
        elif isinstance(points, str) or not isinstance(points, Sequence) or len(points) < 2:
            raise InputError(f"Polyline: expected at least two points, got {points!r}")
        else:
            pts = tuple(_vec(p, f"points[{i}]") for i, p in enumerate(points))
        if len(pts) < 2 or len(pts[0]) not in (2, 3):
            raise InputError("Polyline: expected at least two points of 2 or 3 coordinates")
        if len({len(p) for p in pts}) != 1:
            raise InputError("Polyline: all points need the same number of coordinates")
        length = float(np.linalg.norm(np.diff(np.asarray(pts), axis=0), axis=1).sum())
        if length <= 0:
            raise InputError("Polyline: the points must not all coincide")
        set_fields(self, vertices=pts, tol=0.01 * length if tol is None else to_si(tol, "length", "tol"))

    def distance(self, points: np.ndarray) -> np.ndarray:
        """Distance [m] of each point ``[dim, n]`` from the polyline."""
        d = min(points.shape[0], len(self.vertices[0]))
        V = np.asarray(self.vertices)[:, :d]
        A, B = V[:-1], V[1:]
        P = points[:d].T
        best = np.full(P.shape[0], np.inf)
        for a, b in zip(A, B):
            ab = b - a
            s = np.clip((P - a) @ ab / max(float(ab @ ab), 1e-300), 0.0, 1.0)
            best = np.minimum(best, np.linalg.norm(P - (a + s[:, None] * ab), axis=1))
        return best

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        return self.distance(points) <= self.tol + tol

    def measure(self, dim: int) -> float | None:
        return float(np.linalg.norm(np.diff(np.asarray(self.vertices), axis=0), axis=1).sum()) if dim == 2 else None

    def describe(self) -> str:
        a, b = self.vertices[0], self.vertices[-1]
        return (f"polyline of {len(self.vertices)} points from {tuple(round(c * 1e3, 4) for c in a)} "
                f"to {tuple(round(c * 1e3, 4) for c in b)} mm")


@dataclass(frozen=True)
class Named(Region):
    """A region named in the mesh: a gmsh physical group of any dimension (points, curves, surfaces;
    :func:`mechverify.fea.mesh.from_gmsh_model`, :func:`mechverify.fea.mesh2d.from_gmsh_model`), a name
    the mesh builder gave, or in 2D a scikit-fem named boundary (``MeshTri.with_boundaries``). Its
    measure is the geometry's (gmsh's CAD length or area) where the mesh recorded it."""

    name: str

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:  # resolved by the mesh instead
        raise InputError(f"named region {self.name!r} is resolved from the mesh, not from coordinates")

    def describe(self) -> str:
        return f"region {self.name!r}"


@dataclass(frozen=True)
class Everywhere(Region):
    """The whole boundary (useful for a body load or a check)."""

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:
        return np.ones(points.shape[1], dtype=bool)

    def describe(self) -> str:
        return "the whole boundary"
