"""Regions of a model's boundary, selected in physical terms: a plane, a box, a cylinder (hole or bolt
surface), a circle in 2D, or a region named in the mesh (a gmsh physical group).

A region decides, for given points (SI coordinates ``[dim, n]``), whether each lies in it. A facet
(boundary triangle or edge) belongs to the region when all its nodes do; nothing is ever chosen
by node number.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.units import to_si


def _vec(value: Any, name: str, dim: str = "length") -> tuple[float, ...]:
    if isinstance(value, str) or not isinstance(value, Sequence):
        raise InputError(f"{name}: expected a sequence of 2 or 3 {dim}s, got {value!r}")
    if len(value) not in (2, 3):
        raise InputError(f"{name}: expected 2 or 3 components, got {len(value)}")
    return tuple(to_si(v, dim, f"{name}[{i}]") for i, v in enumerate(value))


class Region:
    """Base class: ``contains(points, tol)`` -> bool mask over the columns of ``points``."""

    def contains(self, points: np.ndarray, tol: float) -> np.ndarray:  # pragma: no cover - interface
        raise NotImplementedError

    def describe(self) -> str:  # pragma: no cover - interface
        raise NotImplementedError


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
        object.__setattr__(self, "point", tuple(pt))
        object.__setattr__(self, "normal", tuple(nrm))

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
        object.__setattr__(self, "lo", lo_)
        object.__setattr__(self, "hi", hi_)

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

    def __init__(self, center: Any, radius: Any, axis: Any = (0, 0, 1), rel_tol: float = 0.05):
        c = _vec(center, "center")
        r = to_si(radius, "length", "radius")
        if r <= 0:
            raise InputError(f"Cylinder: radius must be positive, got {radius!r}")
        a = np.asarray(_vec(axis, "axis", "dimensionless") + (0.0,) * (3 - len(axis)), float)
        if np.linalg.norm(a) == 0:
            raise InputError("Cylinder: axis must not be zero")
        object.__setattr__(self, "center", c + (0.0,) * (3 - len(c)))
        object.__setattr__(self, "radius", r)
        object.__setattr__(self, "axis", tuple(a / np.linalg.norm(a)))
        object.__setattr__(self, "rel_tol", float(rel_tol))

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


@dataclass(frozen=True)
class Named(Region):
    """A region named in the mesh (a gmsh physical group, or a name the mesh builder gave)."""

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
