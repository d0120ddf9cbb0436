"""Flat plates: declarative geometry, supports and loads (meshed by the FEA plate model), and Roark checks.

Geometry lives in the plate's own x-y plane; the plate normal is +z and out-of-plane loads are
positive along +z (self-weight acts along -z unless ``PlateSelfWeight.direction`` says otherwise).

* :class:`Plate` — an outline polygon with circular holes (bolt holes, named) and polygonal
  cut-outs (lightening), a thickness and a material; :meth:`Plate.rectangle` builds a rectangle
  with a hole pattern (see :func:`corner_holes`, :func:`hole_grid`).
* supports — :class:`EdgeSupport` (outline edges by index), :class:`PointSupport` (a point, e.g.
  a corner), :class:`HoleSupport` (the rim of bolt holes); each ``"clamped"`` or ``"simply_supported"``.
* loads — :class:`PlatePointLoad` (force along z and optional moments), :class:`PatchLoad` (a force or
  pressure on a rectangle or polygon patch), :class:`PressureLoad` (uniform over the whole plate),
  :class:`PlateSelfWeight`.
* :class:`PlateModel` — plate + supports + loads, validated (supports and loads lie on the plate).

All coordinates are stored as SI floats (metres) in tuples; :attr:`Plate.region` is the shapely
polygon (holes as polygons with ``HOLE_SEGMENTS`` sides) for meshing.

The closed-form Roark estimates for rectangular and circular plates are at the end of this module
(:func:`roark_rectangular_plate`, :func:`roark_circular_plate`).
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cache, cached_property
from pathlib import Path
from typing import Any

import numpy as np
import pint
import shapely
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.errors import InputError, UnknownNameError, ValidityError, renamed
from mechverify.frozen import set_fields
from mechverify.materials import Material
from mechverify.materials import get as get_material
from mechverify.units import Q, QuantityLike, from_si, to_si

HOLE_SEGMENTS = 48  # sides of the polygon that stands for a circular hole in `Plate.region`
G0 = 9.80665  # standard gravity [m/s^2]
SUPPORT_CONDITIONS = ("clamped", "simply_supported")
_CONDITION_ALIASES = {"clamped": "clamped", "fixed": "clamped", "built_in": "clamped", "encastre": "clamped",
                      "bolted": "clamped", "simply_supported": "simply_supported", "simple": "simply_supported",
                      "pinned": "simply_supported", "hinged": "simply_supported", "ss": "simply_supported"}


# ------------------------------------------------------------------------------------ input helpers
def _point(p: Any, name: str, unit: str | None = None) -> tuple[float, float]:
    if isinstance(p, pint.Quantity):
        arr = np.asarray(to_si(p, "length", name), dtype=float).ravel()
        if arr.size != 2:
            raise InputError(f"{name}: expected a point (x, y), got {p!r}")
        return float(arr[0]), float(arr[1])
    if isinstance(p, str) or len(p) != 2:
        raise InputError(f"{name}: expected a point (x, y), got {p!r}")
    if unit is not None and all(isinstance(c, int | float) and not isinstance(c, bool) for c in p):
        return Q(float(p[0]), unit).m_as("m"), Q(float(p[1]), unit).m_as("m")
    return to_si(p[0], "length", f"{name}.x"), to_si(p[1], "length", f"{name}.y")


def _points(pts: Any, name: str, unit: str | None = None) -> tuple[tuple[float, float], ...]:
    if isinstance(pts, pint.Quantity):
        arr = np.atleast_2d(np.asarray(to_si(pts, "length", name), dtype=float))
        if arr.ndim != 2 or arr.shape[1] != 2:
            raise InputError(f"{name}: expected points (x, y), got shape {arr.shape}")
        out = tuple((float(a), float(b)) for a, b in arr)
    else:
        out = tuple(_point(p, f"{name}[{i}]", unit) for i, p in enumerate(pts))
    if len(out) >= 2 and out[0] == out[-1]:
        out = out[:-1]  # closed rings are accepted
    return out


def _length(v: Any, name: str, unit: str | None = None, *, allow_zero: bool = False) -> float:
    if unit is not None and isinstance(v, int | float) and not isinstance(v, bool):
        v = Q(float(v), unit)
    x = to_si(v, "length", name)
    if x < 0 or (x == 0 and not allow_zero):
        raise InputError(f"{name}: must be {'zero or ' if allow_zero else ''}positive, got {fmt_mm(x)}")
    return x


def fmt_mm(x: float) -> str:
    return f"{x * 1e3:g} mm"


def _condition(c: str, name: str) -> str:
    key = str(c).strip().lower().replace("-", "_").replace(" ", "_")
    if key not in _CONDITION_ALIASES:
        raise UnknownNameError(f"support condition ({name})", c, [*SUPPORT_CONDITIONS, *_CONDITION_ALIASES])
    return _CONDITION_ALIASES[key]


def _collinear(pts: Sequence[tuple[float, float]]) -> bool:
    a = np.asarray(pts, dtype=float)
    a = a - a.mean(axis=0)
    scale = np.abs(a).max()
    return scale == 0 or np.linalg.matrix_rank(a / scale, tol=1e-12) < 2


def _circle(center: tuple[float, float], d: float, n: int = HOLE_SEGMENTS) -> ShapelyPolygon:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return ShapelyPolygon(np.c_[center[0] + d / 2 * np.cos(t), center[1] + d / 2 * np.sin(t)])


# ------------------------------------------------------------------------------------------ geometry
@dataclass(frozen=True)
class Hole:
    """A circular hole: ``center`` (x, y) and ``diameter``; ``name`` lets supports and loads refer to it."""

    center: Any
    diameter: Any
    name: str = ""
    unit: str | None = None

    def __post_init__(self) -> None:
        set_fields(self, center=_point(self.center, f"hole {self.name or ''}.center".replace(" .", "."),
                                       self.unit))
        set_fields(self, diameter=_length(self.diameter, "hole.diameter", self.unit), unit="m")

    @property
    def radius(self) -> float:
        return self.diameter / 2

    def polygon(self, n: int = HOLE_SEGMENTS) -> ShapelyPolygon:
        return _circle(self.center, self.diameter, n)

    def __repr__(self) -> str:
        n = f"{self.name!r}, " if self.name else ""
        return f"Hole({n}center=({fmt_mm(self.center[0])}, {fmt_mm(self.center[1])}), d={fmt_mm(self.diameter)})"


def _as_hole(h: Any, i: int, unit: str | None) -> Hole:
    if isinstance(h, Hole):
        return h
    if isinstance(h, dict):
        return Hole(unit=h.get("unit", unit), **{k: v for k, v in h.items() if k != "unit"})
    raise InputError(f"holes[{i}]: expected a Hole or a table with center and diameter, got {h!r}")


def corner_holes(width: Any, height: Any, inset: Any, diameter: Any, origin: Any = ("0 m", "0 m"),
                 prefix: str = "corner") -> tuple[Hole, ...]:
    """Four holes ``inset`` from both edges at the corners of a ``width`` x ``height`` rectangle.

    Named ``<prefix>_sw``, ``_se``, ``_ne``, ``_nw`` (counter-clockwise from the origin corner).
    """
    w, h, e = _length(width, "width"), _length(height, "height"), _length(inset, "inset")
    d = _length(diameter, "diameter")
    x0, y0 = _point(origin, "origin")
    pts = {"sw": (e, e), "se": (w - e, e), "ne": (w - e, h - e), "nw": (e, h - e)}
    return tuple(Hole((Q(x0 + x, "m"), Q(y0 + y, "m")), Q(d, "m"), f"{prefix}_{k}") for k, (x, y) in pts.items())


def hole_grid(first_center: Any, nx: int, ny: int, pitch_x: Any, pitch_y: Any, diameter: Any,
              prefix: str = "hole") -> tuple[Hole, ...]:
    """A rectangular pattern of ``nx`` x ``ny`` holes starting at ``first_center``; names ``<prefix>_<i>_<j>``."""
    if int(nx) < 1 or int(ny) < 1:
        raise InputError(f"hole_grid: nx and ny must be >= 1, got {nx}, {ny}")
    x0, y0 = _point(first_center, "first_center")
    px = _length(pitch_x, "pitch_x", allow_zero=nx == 1)
    py = _length(pitch_y, "pitch_y", allow_zero=ny == 1)
    d = _length(diameter, "diameter")
    return tuple(Hole((Q(x0 + i * px, "m"), Q(y0 + j * py, "m")), Q(d, "m"), f"{prefix}_{i}_{j}")
                 for j in range(int(ny)) for i in range(int(nx)))


def rectangle_cutout(center: Any, size: Any, corner_radius: Any = None, unit: str | None = None) -> pint.Quantity:
    """A rectangular cut-out of sides ``size`` = (dx, dy) centred at ``center``, its corners rounded to
    ``corner_radius`` (arcs of 6 segments per quarter circle), as outline points [m] for ``Plate(cutouts=[...])``.

    Raises:
        InputError: a side not positive (``size: ...``), a corner radius not positive or not below half the
            shorter side (``corner_radius: ...``).
    """
    cx, cy = _point(center, "center", unit)
    dx, dy = _point(size, "size", unit)
    if not (dx > 0 and dy > 0):
        raise InputError(f"size: both sides must be positive, got {fmt_mm(dx)}, {fmt_mm(dy)}")
    poly = shapely.box(cx - dx / 2, cy - dy / 2, cx + dx / 2, cy + dy / 2)
    if corner_radius is not None:
        r = _length(corner_radius, "corner_radius", unit)
        if not 2 * r < min(dx, dy):
            raise InputError("corner_radius: must be less than half the shorter side")
        poly = poly.buffer(-r, join_style="mitre").buffer(r, quad_segs=6)
    return Q(np.asarray(poly.exterior.coords)[:-1], "m")


@dataclass(frozen=True)
class Plate:
    """A flat plate of uniform ``thickness``: outline polygon, circular ``holes``, polygonal ``cutouts``.

    Points are quantity arrays of shape (n, 2), sequences of (x, y) quantities/strings, or numbers
    with ``unit`` (``unit="mm"``, convenient from TOML). ``material`` is a :class:`Material` or a
    name in the material database. Raises :class:`InputError` for a self-intersecting outline or
    cut-out, holes or cut-outs outside the plate or overlapping each other, zero thickness.
    """

    outline: Any
    thickness: Any
    material: Any
    holes: Sequence[Any] = ()
    cutouts: Sequence[Any] = ()
    name: str = "plate"
    unit: str | None = None

    def __post_init__(self) -> None:
        u = self.unit
        outline = _points(self.outline, f"{self.name}.outline", u)
        if len(outline) < 3:
            raise InputError(f"{self.name}.outline: a polygon needs at least 3 points, got {len(outline)}")
        t = _length(self.thickness, f"{self.name}.thickness", u)
        mat = self.material if isinstance(self.material, Material) else get_material(self.material)
        holes = tuple(_as_hole(h, i, u) for i, h in enumerate(self.holes))
        cutouts = tuple(_points(c, f"{self.name}.cutouts[{i}]", u) for i, c in enumerate(self.cutouts))
        names = [h.name for h in holes if h.name]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise InputError(f"{self.name}.holes: hole names must be unique, repeated: {sorted(dup)}")
        set_fields(self, outline=outline, thickness=t, material=mat, holes=holes, cutouts=cutouts, unit="m")
        self.region  # noqa: B018 - the geometry is checked at construction

    @cached_property
    def region(self) -> ShapelyPolygon:
        """The plate as a shapely polygon [m]: outline minus holes and cut-outs (checked: simple, holes and
        cut-outs inside and apart)."""
        if _collinear(self.outline):
            raise InputError(f"{self.name}.outline: the outline encloses no area (its points are collinear)")
        ring = shapely.LinearRing(self.outline)
        if not ring.is_simple:
            raise InputError(f"{self.name}.outline: the outline crosses itself (self-intersecting polygon)")
        shell = ShapelyPolygon(self.outline)
        if shell.area <= 0:
            raise InputError(f"{self.name}.outline: the outline encloses no area")
        voids: list[tuple[str, ShapelyPolygon]] = []
        for i, h in enumerate(self.holes):
            label = f"{self.name}.holes[{i}]" + (f" ({h.name})" if h.name else "")
            disc = ShapelyPoint(h.center).buffer(h.radius, quad_segs=32)
            if not shell.contains(disc):
                where = "outside the plate" if not shell.intersects(disc) else "across the plate edge"
                raise InputError(f"{label}: hole of {fmt_mm(h.diameter)} at ({fmt_mm(h.center[0])}, "
                                 f"{fmt_mm(h.center[1])}) lies {where}")
            voids.append((label, disc))
        for i, c in enumerate(self.cutouts):
            label = f"{self.name}.cutouts[{i}]"
            if len(c) < 3 or not shapely.LinearRing(c).is_simple:
                raise InputError(f"{label}: the cut-out outline crosses itself or has fewer than 3 points")
            cp = ShapelyPolygon(c)
            if cp.area <= 0:
                raise InputError(f"{label}: the cut-out encloses no area")
            if not shell.contains(cp):
                raise InputError(f"{label}: the cut-out is not inside the plate outline")
            voids.append((label, cp))
        for i, (li, pi) in enumerate(voids):
            for lj, pj in voids[:i]:
                if pi.intersects(pj):
                    raise InputError(f"{li}: overlaps or touches {lj}")
        interiors = [h.polygon().exterior.coords for h in self.holes] + [ShapelyPolygon(c).exterior.coords
                                                                         for c in self.cutouts]
        region = ShapelyPolygon(shell.exterior.coords, interiors)
        if not region.is_valid:
            raise InputError(f"{self.name}: invalid plate region ({shapely.is_valid_reason(region)})")
        return region

    # ---------------------------------------------------------------- constructors
    @classmethod
    def rectangle(cls, width: Any, height: Any, thickness: Any, material: Any, holes: Sequence[Any] = (),
                  cutouts: Sequence[Any] = (), name: str = "plate", unit: str | None = None) -> Plate:
        """A ``width`` (x) by ``height`` (y) rectangle with its lower-left corner at the origin."""
        w, h = _length(width, "width", unit), _length(height, "height", unit)
        outline = Q(np.array([[0, 0], [w, 0], [w, h], [0, h]], dtype=float), "m")
        cut = [c if unit is None else Q(np.asarray(c, dtype=float), unit) for c in cutouts]
        hs = [_as_hole(x, i, unit) for i, x in enumerate(holes)]
        t = thickness if unit is None or not isinstance(thickness, int | float) else Q(thickness, unit)
        return cls(outline, t, material, hs, cut, name)

    # ---------------------------------------------------------------- derived quantities
    @property
    def area(self) -> pint.Quantity:
        """Net area (outline minus holes and cut-outs; holes counted as exact circles) [m^2]."""
        gross = ShapelyPolygon(self.outline).area
        voids = sum(math.pi * h.radius**2 for h in self.holes) + sum(ShapelyPolygon(c).area for c in self.cutouts)
        return from_si(gross - voids, "area")

    @property
    def mass(self) -> pint.Quantity:
        rho = to_si(self.material.require("density"), "density", "density")
        return from_si(self.area.m_as("m**2") * self.thickness * rho, "mass")

    @property
    def weight(self) -> pint.Quantity:
        return from_si(self.mass.m_as("kg") * G0, "force")

    @property
    def bounds(self) -> tuple[pint.Quantity, pint.Quantity, pint.Quantity, pint.Quantity]:
        """(xmin, ymin, xmax, ymax) [m]."""
        return tuple(from_si(v, "length") for v in ShapelyPolygon(self.outline).bounds)  # type: ignore[return-value]

    @property
    def thickness_q(self) -> pint.Quantity:
        return from_si(self.thickness, "length")

    def edges(self) -> tuple[tuple[tuple[float, float], tuple[float, float]], ...]:
        """Outline edges; edge ``i`` runs from vertex ``i`` to vertex ``i+1`` [m]."""
        n = len(self.outline)
        return tuple((self.outline[i], self.outline[(i + 1) % n]) for i in range(n))

    def hole(self, key: int | str) -> Hole:
        """A hole by index or name (``UnknownNameError`` with suggestions)."""
        if isinstance(key, int) and not isinstance(key, bool):
            if not 0 <= key < len(self.holes):
                raise InputError(f"{self.name}: hole index {key} out of range (plate has {len(self.holes)} holes)")
            return self.holes[key]
        for h in self.holes:
            if h.name == key:
                return h
        raise UnknownNameError(f"hole of {self.name}", str(key), [h.name for h in self.holes if h.name])

    def is_rectangle(self) -> bool:
        """True for an axis-aligned rectangle outline (whatever the holes)."""
        p = ShapelyPolygon(self.outline)
        return len(self.outline) == 4 and abs(p.area - p.envelope.area) <= 1e-12 * p.area

    def __repr__(self) -> str:
        x0, y0, x1, y1 = ShapelyPolygon(self.outline).bounds
        return (f"<Plate {self.name!r} {fmt_mm(x1 - x0)} x {fmt_mm(y1 - y0)} x {fmt_mm(self.thickness)} "
                f"{self.material.name}, {len(self.holes)} holes, {len(self.cutouts)} cut-outs>")


# ------------------------------------------------------------------------------------------ supports
@dataclass(frozen=True)
class EdgeSupport:
    """Outline edges (indices, edge ``i`` from vertex ``i`` to ``i+1``, or ``"all"``), clamped or simply supported."""

    edges: Any = "all"
    condition: str = "simply_supported"

    def __post_init__(self) -> None:
        set_fields(self, condition=_condition(self.condition, "EdgeSupport"))
        if isinstance(self.edges, str):
            if self.edges != "all":
                raise InputError(f"EdgeSupport.edges: expected 'all' or edge indices, got {self.edges!r}")
        else:
            idx = tuple(self.edges) if isinstance(self.edges, Sequence) else (self.edges,)
            if not idx or not all(isinstance(i, int) and not isinstance(i, bool) and i >= 0 for i in idx):
                raise InputError(f"EdgeSupport.edges: expected non-negative edge indices, got {self.edges!r}")
            set_fields(self, edges=idx)

    def edge_indices(self, plate: Plate) -> tuple[int, ...]:
        n = len(plate.outline)
        if self.edges == "all":
            return tuple(range(n))
        bad = [i for i in self.edges if i >= n]
        if bad:
            raise InputError(f"EdgeSupport: edge {bad[0]} does not exist; {plate.name} has edges 0..{n - 1}")
        return self.edges


@dataclass(frozen=True)
class PointSupport:
    """A support at a point of the plate (a corner, a standoff), clamped or simply supported (pinned)."""

    point: Any
    condition: str = "simply_supported"
    unit: str | None = None

    def __post_init__(self) -> None:
        set_fields(self, point=_point(self.point, "PointSupport.point", self.unit),
                   condition=_condition(self.condition, "PointSupport"), unit="m")


@dataclass(frozen=True)
class HoleSupport:
    """Support on the rim of holes (bolts): by index or name, or ``"all"``. ``"clamped"`` (bolted, default)
    fixes the rim's rotation as well; ``"simply_supported"`` only its deflection.

    ``washer_diameter`` (optional) widens the supported ring to the washer/head contact.
    """

    holes: Any = "all"
    condition: str = "clamped"
    washer_diameter: Any = None

    def __post_init__(self) -> None:
        set_fields(self, condition=_condition(self.condition, "HoleSupport"))
        if self.holes != "all":
            hs = (self.holes,) if isinstance(self.holes, str | int) else tuple(self.holes)
            if not hs:
                raise InputError("HoleSupport.holes: give at least one hole (index or name) or 'all'")
            set_fields(self, holes=hs)
        if self.washer_diameter is not None:
            set_fields(self, washer_diameter=_length(self.washer_diameter, "washer_diameter"))

    def resolve(self, plate: Plate) -> tuple[Hole, ...]:
        if self.holes == "all":
            if not plate.holes:
                raise InputError(f"HoleSupport: {plate.name} has no holes")
            return plate.holes
        hs = tuple(plate.hole(k) for k in self.holes)
        if self.washer_diameter is not None:
            for h in hs:
                if self.washer_diameter <= h.diameter:
                    raise InputError(f"HoleSupport.washer_diameter {fmt_mm(self.washer_diameter)} must exceed "
                                     f"the hole diameter {fmt_mm(h.diameter)}")
        return hs


# ----------------------------------------------------------------------------------------- loads
@dataclass(frozen=True)
class PlatePointLoad:
    """A concentrated load at ``point``: force along z (``force``, +z up) and optional moments about x and y."""

    point: Any
    force: QuantityLike = "0 N"
    moment_x: QuantityLike = "0 N*m"
    moment_y: QuantityLike = "0 N*m"
    unit: str | None = None

    def __post_init__(self) -> None:
        set_fields(self, point=_point(self.point, "PlatePointLoad.point", self.unit),
                   force=to_si(self.force, "force", "PlatePointLoad.force"),
                   moment_x=to_si(self.moment_x, "torque", "PlatePointLoad.moment_x"),
                   moment_y=to_si(self.moment_y, "torque", "PlatePointLoad.moment_y"), unit="m")
        if self.force == 0 and self.moment_x == 0 and self.moment_y == 0:
            raise InputError("PlatePointLoad: force and moments are all zero")


@dataclass(frozen=True)
class PatchLoad:
    """A load spread over a patch: a ``polygon`` or a rectangle (``center``, ``size`` = (dx, dy)).

    Give either ``force`` (total, along z) or ``pressure`` (along z).
    """

    center: Any = None
    size: Any = None
    polygon: Any = None
    force: QuantityLike | None = None
    pressure: QuantityLike | None = None
    unit: str | None = None

    def __post_init__(self) -> None:
        if (self.polygon is None) == (self.center is None):
            raise InputError("PatchLoad: give either polygon or center and size")
        if self.polygon is None:
            if self.size is None:
                raise InputError("PatchLoad: a rectangular patch needs size = (dx, dy)")
            cx, cy = _point(self.center, "PatchLoad.center", self.unit)
            dx, dy = (_length(s, f"PatchLoad.size[{i}]", self.unit) for i, s in enumerate(self.size))
            poly = ((cx - dx / 2, cy - dy / 2), (cx + dx / 2, cy - dy / 2), (cx + dx / 2, cy + dy / 2),
                    (cx - dx / 2, cy + dy / 2))
        else:
            poly = _points(self.polygon, "PatchLoad.polygon", self.unit)
            if len(poly) < 3 or not shapely.LinearRing(poly).is_simple or ShapelyPolygon(poly).area <= 0:
                raise InputError("PatchLoad.polygon: the patch outline crosses itself or encloses no area")
        if (self.force is None) == (self.pressure is None):
            raise InputError("PatchLoad: give exactly one of force (total) or pressure")
        area = ShapelyPolygon(poly).area
        if self.force is not None:
            force = to_si(self.force, "force", "PatchLoad.force")
            pressure = force / area
        else:
            pressure = to_si(self.pressure, "pressure", "PatchLoad.pressure")
            force = pressure * area
        set_fields(self, polygon=poly, center=None, size=None, force=force, pressure=pressure, unit="m")

    @property
    def area(self) -> float:
        return ShapelyPolygon(self.polygon).area


@dataclass(frozen=True)
class PressureLoad:
    """A uniform pressure over the whole plate (its net area), along +z."""

    pressure: QuantityLike

    def __post_init__(self) -> None:
        set_fields(self, pressure=to_si(self.pressure, "pressure", "PressureLoad.pressure"))


@dataclass(frozen=True)
class PlateSelfWeight:
    """The plate's weight, ``factor`` x g x density x thickness per unit area, along ``direction`` (-1: -z)."""

    factor: float = 1.0
    g: QuantityLike = "9.80665 m/s**2"
    direction: int = -1

    def __post_init__(self) -> None:
        set_fields(self, g=to_si(self.g, "acceleration", "PlateSelfWeight.g"))
        if self.direction not in (-1, 1):
            raise InputError(f"PlateSelfWeight.direction: -1 (down, -z) or +1, got {self.direction!r}")
        if not self.factor > 0:
            raise InputError(f"PlateSelfWeight.factor: must be positive, got {self.factor!r}")

    def pressure(self, plate: Plate) -> float:
        """Equivalent pressure along z [Pa] (negative when acting along -z)."""
        rho = to_si(plate.material.require("density"), "density", "density")
        return self.direction * self.factor * self.g * rho * plate.thickness


PlateSupport = EdgeSupport | PointSupport | HoleSupport
PlateLoad = PlatePointLoad | PatchLoad | PressureLoad | PlateSelfWeight


@dataclass(frozen=True)
class PlateModel:
    """A plate with its supports and loads (one load case), validated for the FEA plate model.

    Supports and loads must lie on the plate: point supports and point loads inside the region or
    on its boundary (not in a hole), patches inside the outline (they may overlap holes: the load on
    the hole part is lost, and a warning is in :meth:`warnings`).
    """

    plate: Plate
    supports: Sequence[Any] = ()
    loads: Sequence[Any] = ()
    name: str = ""

    def __post_init__(self) -> None:
        set_fields(self, supports=tuple(self.supports), loads=tuple(self.loads))
        if not self.supports:
            raise InputError(f"{self.plate.name}: a plate model needs at least one support")
        region = self.plate.region
        tol = 1e-9 * math.sqrt(region.area)
        for i, s in enumerate(self.supports):
            if isinstance(s, EdgeSupport):
                s.edge_indices(self.plate)
            elif isinstance(s, HoleSupport):
                s.resolve(self.plate)
            elif isinstance(s, PointSupport):
                if region.distance(ShapelyPoint(s.point)) > tol:
                    raise InputError(f"supports[{i}]: point ({fmt_mm(s.point[0])}, {fmt_mm(s.point[1])}) is not on "
                                     f"{self.plate.name}")
            else:
                raise InputError(f"supports[{i}]: expected EdgeSupport, PointSupport or HoleSupport, "
                                 f"got {type(s).__name__}")
        for i, ld in enumerate(self.loads):
            if isinstance(ld, PlatePointLoad):
                if region.distance(ShapelyPoint(ld.point)) > tol:
                    raise InputError(f"loads[{i}]: point load at ({fmt_mm(ld.point[0])}, {fmt_mm(ld.point[1])}) is "
                                     f"not on {self.plate.name} (outside it or in a hole)")
            elif isinstance(ld, PatchLoad):
                if not ShapelyPolygon(self.plate.outline).buffer(tol).contains(ShapelyPolygon(ld.polygon)):
                    raise InputError(f"loads[{i}]: the load patch extends beyond the outline of {self.plate.name}")
            elif not isinstance(ld, PressureLoad | PlateSelfWeight):
                raise InputError(f"loads[{i}]: expected PlatePointLoad, PatchLoad, PressureLoad or PlateSelfWeight, "
                                 f"got {type(ld).__name__}")

    def total_force(self) -> pint.Quantity:
        """Resultant force along z of all loads (patches counted on the plate's net area) [N]."""
        region = self.plate.region
        total = 0.0
        for ld in self.loads:
            if isinstance(ld, PlatePointLoad):
                total += ld.force
            elif isinstance(ld, PatchLoad):
                total += ld.pressure * ShapelyPolygon(ld.polygon).intersection(region).area
            elif isinstance(ld, PressureLoad):
                total += ld.pressure * self.plate.area.m_as("m**2")
            elif isinstance(ld, PlateSelfWeight):
                total += ld.pressure(self.plate) * self.plate.area.m_as("m**2")
        return from_si(total, "force")

    def warnings(self) -> tuple[str, ...]:
        out = []
        for i, ld in enumerate(self.loads):
            if isinstance(ld, PatchLoad):
                on = ShapelyPolygon(ld.polygon).intersection(self.plate.region).area
                if on < ld.area * (1 - 1e-6):
                    out.append(f"loads[{i}]: {100 * (1 - on / ld.area):.1f} % of the patch lies over a hole or "
                               "cut-out; that part of the load is not applied")
        return tuple(out)


# ------------------------------------------------------------------------------ Roark closed forms
ROARK_SOURCE = "Roark's Formulas for Stress and Strain, 8th ed. (Young, Budynas, Sadegh 2012)"
_ROARK_DATA = Path(__file__).parent / "data" / "roark_plates.toml"
PLATE_LOADINGS = ("uniform", "central")


@cache
def _roark_table() -> dict[str, Any]:
    with _ROARK_DATA.open("rb") as fh:
        return tomllib.load(fh)


@dataclass(frozen=True)
class PlateEstimate:
    """Closed-form plate result: the largest bending stress and deflection, where, and from which case."""

    max_stress: pint.Quantity  # magnitude of the largest surface bending stress [Pa]
    max_deflection: pint.Quantity  # magnitude of the largest deflection [m]
    stress_location: str
    case: str
    source: str
    coefficients: dict[str, float] = field(default_factory=dict)
    stresses: dict[str, pint.Quantity] = field(default_factory=dict)  # by location
    warnings: tuple[str, ...] = ()
    #: the case's inputs (SI floats; for the report's substituted formula): shape ("rectangle"/"circle"), kind
    #: ("uniform"/"central"), edge, load (q [Pa] or W [N]), span b (rectangle, shorter side) or radius a, t, nu, E
    inputs: dict[str, Any] = field(default_factory=dict)


def equivalent_contact_radius(r0: float, t: float) -> float:
    """Roark's ``r0' = sqrt(1.6 r0^2 + t^2) - 0.675 t`` for ``r0 < 0.5 t``, else ``r0`` [m].

    Roark 8th ed., Sec. 11.2 / Table 11.2 notation (after Westergaard); Timoshenko & Woinowsky-Krieger Sec. 19.
    """
    return math.sqrt(1.6 * r0 * r0 + t * t) - 0.675 * t if r0 < 0.5 * t else r0


def _central_load(load: Any, load_radius: Any, t: float) -> tuple[float, float]:
    """Magnitude of a central force [N] and Roark's equivalent radius of its contact patch [m]."""
    r0 = to_si(load_radius, "length", "load_radius")
    if r0 < 0:
        raise InputError("load_radius: must be zero or positive")
    return abs(to_si(load, "force", "load")), equivalent_contact_radius(r0, t)


def _normalise(value: str, known: Sequence[str], aliases: dict[str, str], kind: str) -> str:
    key = str(value).strip().lower().replace("-", "_").replace(" ", "_")
    key = aliases.get(key, key)
    if key not in known:
        raise UnknownNameError(kind, value, [*known, *aliases])
    return key


_LOADING_ALIASES = {"pressure": "uniform", "distributed": "uniform", "point": "central", "center": "central",
                    "centre": "central", "concentrated": "central"}


def _plate_warnings(y: float, t: float, span: float) -> tuple[str, ...]:
    out = []
    if y > 0.5 * t:
        out.append(f"deflection {y * 1e3:.3g} mm exceeds half the thickness ({t * 1e3:.3g} mm): small-deflection "
                   "plate theory overestimates stress and deflection (membrane action; Roark 8th ed. Sec. 11.11)")
    if t > 0.1 * span:
        out.append(f"thickness {t * 1e3:.3g} mm exceeds a tenth of the span {span * 1e3:.3g} mm: thin-plate "
                   "theory ignores transverse shear (Roark 8th ed. Sec. 11.1)")
    return tuple(out)


def roark_rectangular_plate(a: QuantityLike, b: QuantityLike, thickness: QuantityLike, E: QuantityLike,
                            load: QuantityLike, edges: str = "simply_supported",
                            loading: str = "uniform", load_radius: Any = "0 m") -> PlateEstimate:
    """Rectangular plate, all four edges simply supported or clamped (Roark 8th ed., Table 11.4, nu = 0.3).

    ``loading="uniform"``: ``load`` is a pressure q (cases 1a, 8a); ``loading="central"``: ``load`` is
    the total force W on a small central circle of radius ``load_radius`` (cases 1b, 8b; ``r0'``
    from :func:`equivalent_contact_radius`). ``a``, ``b`` in either order (the longer is ``a``).
    Coefficients between tabulated a/b are interpolated linearly in b/a.

    * uniform: ``sigma = beta q b^2 / t^2``, ``y = alpha q b^4 / (E t^3)``
    * central: ``sigma = 3W/(2 pi t^2) [(1+nu) ln(2b/(pi r0')) + beta]``, ``y = alpha W b^2/(E t^3)``
    * clamped: also ``sigma_edge = beta_edge q b^2/t^2`` (uniform) or ``beta_edge W/t^2`` (central)
    """
    A, B = to_si(a, "length", "a"), to_si(b, "length", "b")
    t, e = to_si(thickness, "length", "thickness"), to_si(E, "pressure", "E")
    for v, n in ((A, "a"), (B, "b"), (t, "thickness"), (e, "E")):
        if v <= 0:
            raise InputError(f"roark_rectangular_plate: {n} must be positive")
    A, B = max(A, B), min(A, B)
    edge = _normalise(edges, SUPPORT_CONDITIONS, {k: v for k, v in _CONDITION_ALIASES.items() if v != k},
                      "plate edge condition")
    kind = _normalise(loading, PLATE_LOADINGS, _LOADING_ALIASES, "plate loading")
    data = _roark_table()
    row = data[edge][kind]
    nu = float(data["nu"])
    x = [0.0 if r == 0 else 1.0 / r for r in row["a_over_b"]]  # b/a, increasing after reversal
    order = np.argsort(x)
    ba = B / A

    def coef(name: str) -> float:
        return float(np.interp(ba, np.asarray(x)[order], np.asarray(row[name], dtype=float)[order]))

    coefs = {k: coef(k) for k in ("alpha", "beta", "beta_edge") if k in row}
    stresses: dict[str, float] = {}
    if kind == "uniform":
        q = to_si(load, "pressure", "load")
        y = coefs["alpha"] * abs(q) * B**4 / (e * t**3)
        stresses["centre"] = coefs["beta"] * abs(q) * B**2 / t**2
        if "beta_edge" in coefs:
            stresses["centre of long edge"] = coefs["beta_edge"] * abs(q) * B**2 / t**2
    else:
        W, r0e = _central_load(load, load_radius, t)
        y = coefs["alpha"] * W * B**2 / (e * t**3)
        stresses["centre"] = abs(3 * W / (2 * math.pi * t**2) * ((1 + nu) * math.log(2 * B / (math.pi * r0e))
                                                                  + coefs["beta"]))
        if "beta_edge" in coefs:
            stresses["centre of long edge"] = coefs["beta_edge"] * W / t**2
        coefs["r0_equivalent"] = r0e
    where = max(stresses, key=stresses.get)
    case = f"Table 11.4 case {row['case']}: rectangular plate, all edges {edge.replace('_', ' ')}, {row['loading']}"
    return PlateEstimate(max_stress=from_si(stresses[where], "pressure"), max_deflection=from_si(y, "length"),
                         stress_location=where, case=case, source=f"{ROARK_SOURCE}, Table 11.4 case {row['case']}",
                         coefficients=coefs, stresses={k: from_si(v, "pressure") for k, v in stresses.items()},
                         warnings=_plate_warnings(y, t, B),
                         inputs={"shape": "rectangle", "kind": kind, "edge": edge, "nu": nu, "t": t, "b": B, "E": e,
                                 "load": abs(q) if kind == "uniform" else W})


def roark_circular_plate(radius: QuantityLike, thickness: QuantityLike, E: QuantityLike, nu: QuantityLike,
                         load: QuantityLike, edges: str = "simply_supported",
                         loading: str = "uniform", load_radius: Any = "0 m") -> PlateEstimate:
    """Solid circular plate of outer ``radius`` a, edge simply supported or clamped (Roark 8th ed., Table 11.2).

    With ``D = E t^3 / (12 (1 - nu^2))``:

    * uniform q, simply supported (case 10a): ``y = q a^4 (5+nu) / (64 D (1+nu))``, ``sigma_c = 3(3+nu) q a^2/(8 t^2)``
    * uniform q, clamped (case 10b): ``y = q a^4/(64 D)``, ``sigma_edge = 3 q a^2/(4 t^2)``,
      ``sigma_c = 3(1+nu) q a^2/(8 t^2)``
    * central W on radius r0, simply supported (case 16): ``sigma_c = 3W/(2 pi t^2) [(1+nu) ln(a/r0') + 1]``,
      ``y = W a^2 (3+nu) / (16 pi D (1+nu))``
    * central W, clamped (case 17): ``sigma_c = 3W(1+nu)/(2 pi t^2) ln(a/r0')``, ``sigma_edge = 3W/(2 pi t^2)``,
      ``y = W a^2 / (16 pi D)``

    Same results in Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., Secs. 15, 16, 19.
    """
    a, t = to_si(radius, "length", "radius"), to_si(thickness, "length", "thickness")
    e, v = to_si(E, "pressure", "E"), to_si(nu, "dimensionless", "nu")
    for val, n in ((a, "radius"), (t, "thickness"), (e, "E")):
        if val <= 0:
            raise InputError(f"roark_circular_plate: {n} must be positive")
    if not -1 < v < 0.5:
        raise InputError(f"roark_circular_plate: nu must lie in (-1, 0.5), got {v}")
    edge = _normalise(edges, SUPPORT_CONDITIONS, {k: x for k, x in _CONDITION_ALIASES.items() if x != k},
                      "plate edge condition")
    kind = _normalise(loading, PLATE_LOADINGS, _LOADING_ALIASES, "plate loading")
    D = e * t**3 / (12 * (1 - v * v))
    stresses: dict[str, float] = {}
    coefs: dict[str, float] = {}
    if kind == "uniform":
        q = abs(to_si(load, "pressure", "load"))
        if edge == "simply_supported":
            case, y = "10a", q * a**4 * (5 + v) / (64 * D * (1 + v))
            stresses["centre"] = 3 * (3 + v) * q * a**2 / (8 * t**2)
        else:
            case, y = "10b", q * a**4 / (64 * D)
            stresses["edge"] = 3 * q * a**2 / (4 * t**2)
            stresses["centre"] = 3 * (1 + v) * q * a**2 / (8 * t**2)
    else:
        W, r0e = _central_load(load, load_radius, t)
        coefs["r0_equivalent"] = r0e
        if r0e >= a:
            raise ValidityError(f"load radius {r0e * 1e3:.3g} mm is not small against the plate radius")
        if edge == "simply_supported":
            case, y = "16", W * a**2 * (3 + v) / (16 * math.pi * D * (1 + v))
            stresses["centre"] = 3 * W / (2 * math.pi * t**2) * ((1 + v) * math.log(a / r0e) + 1)
        else:
            case, y = "17", W * a**2 / (16 * math.pi * D)
            stresses["centre"] = 3 * W * (1 + v) / (2 * math.pi * t**2) * math.log(a / r0e)
            stresses["edge"] = 3 * W / (2 * math.pi * t**2)
    where = max(stresses, key=stresses.get)
    return PlateEstimate(max_stress=from_si(stresses[where], "pressure"), max_deflection=from_si(y, "length"),
                         stress_location=where,
                         case=f"Table 11.2 case {case}: circular plate, edge {edge.replace('_', ' ')}, {kind} load",
                         source=f"{ROARK_SOURCE}, Table 11.2 case {case}", coefficients=coefs,
                         stresses={k: from_si(x, "pressure") for k, x in stresses.items()},
                         warnings=_plate_warnings(y, t, 2 * a),
                         inputs={"shape": "circle", "kind": kind, "edge": edge, "nu": v, "t": t, "a": a, "E": e,
                                 "load": q if kind == "uniform" else W})


__all__ = ["Plate", "Hole", "corner_holes", "hole_grid", "rectangle_cutout", "EdgeSupport", "PointSupport",
           "HoleSupport", "PlatePointLoad", "PatchLoad", "PressureLoad", "PlateSelfWeight", "PlateModel",
           "SUPPORT_CONDITIONS", "HOLE_SEGMENTS", "PlateEstimate", "roark_rectangular_plate", "roark_circular_plate",
           "equivalent_contact_radius"]

# Former names (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"PointLoad": "PlatePointLoad", "SelfWeight": "PlateSelfWeight"})
