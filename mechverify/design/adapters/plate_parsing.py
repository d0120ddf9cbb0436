"""Parsing of the ``plate_fea`` design-file values: points ``"x, y"``, hole groups, cut-outs, supports and loads.

Used by :mod:`mechverify.design.adapters.plate_fea` (``parse_point``, shared with the bolt adapters, is in
``common``); declares no component type.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.components import plates as pl
from mechverify.design.adapters.common import inline_table, parse_point
from mechverify.errors import InputError, MechverifyError, suggest
from mechverify.units import Q, as_quantity, fmt

SUPPORT_TYPES = {"fixed": "clamped", "clamped": "clamped", "pinned": "simply_supported",
                 "simply_supported": "simply_supported"}
RECT_EDGES = {"bottom": 0, "right": 1, "top": 2, "left": 3}


def _points(v: Any, unit: str, path: str, minimum: int = 3) -> list[tuple[Any, Any]]:
    if not isinstance(v, list):
        raise InputError(f"{path}: expected a list of points \"x, y\", got {v!r}")
    pts = [parse_point(p, unit, f"{path}[{i}]") for i, p in enumerate(v)]
    if len(pts) < minimum:
        raise InputError(f"{path}: a polygon needs at least {minimum} points, got {len(pts)}")
    return pts


def _si(pt: tuple[Any, Any]) -> tuple[float, float]:
    return pt[0].m_as("m"), pt[1].m_as("m")


def _q(v: Any, dim: str, path: str) -> Any:
    if isinstance(v, bool) or not isinstance(v, str):
        raise InputError(f"{path}: expected a {dim.replace('_', ' ')} as a string with units, got {v!r}")
    try:
        return as_quantity(v, dim, path)
    except MechverifyError as exc:
        raise InputError(f"{path}: {str(exc).split(': ', 1)[-1]}") from None


def _positive(v: Any, dim: str, path: str) -> Any:
    q = _q(v, dim, path)
    if not q.magnitude > 0:
        raise InputError(f"{path}: must be positive, got {v!r}")
    return q


def _holes(p: Mapping[str, Any], unit: str, shell: ShapelyPolygon) -> tuple[list[pl.Hole], dict[str, list[str]]]:
    holes: list[pl.Hole] = []
    groups: dict[str, list[str]] = {}
    for g, t in enumerate(p.get("holes", [])):
        path = f"holes[{g}]"
        t = inline_table(t, path, ("name", "diameter", "centers"), ("diameter", "centers"))
        d = _positive(t["diameter"], "length", f"{path}.diameter")
        name = str(t.get("name", f"hole{g + 1}"))
        if name in groups:
            raise InputError(f"{path}.name: {name!r} is used by another hole group")
        centers = t["centers"]
        if not isinstance(centers, list) or not centers:
            raise InputError(f"{path}.centers: expected a list of points \"x, y\", got {centers!r}")
        groups[name] = []
        for k, c in enumerate(centers):
            cpath = f"{path}.centers[{k}]"
            pt = parse_point(c, unit, cpath)
            hname = name if len(centers) == 1 else f"{name}_{k + 1}"
            disc = ShapelyPoint(_si(pt)).buffer(d.m_as("m") / 2, quad_segs=32)
            if not shell.contains(disc):
                where = "outside the plate" if not shell.intersects(disc) else "across the plate's edge"
                raise InputError(f"{cpath}: the hole of {fmt(d, 'mm')} at ({c}) lies {where}")
            holes.append(pl.Hole(pt, d, hname))
            groups[name].append(hname)
    return holes, groups


def _cutouts(p: Mapping[str, Any], unit: str, shell: ShapelyPolygon) -> list[Any]:
    out = []
    for i, t in enumerate(p.get("cutouts", [])):
        path = f"cutouts[{i}]"
        t = inline_table(t, path, ("center", "size", "corner_radius", "polygon"))
        if ("polygon" in t) == ("center" in t):
            raise InputError(f"{path}: give either polygon = [points] or center and size (a rectangle)")
        if "polygon" in t:
            if "size" in t or "corner_radius" in t:
                raise InputError(f"{path}: size and corner_radius belong to a rectangle (center and size), "
                                 "not to a polygon")
            poly = ShapelyPolygon([_si(q) for q in _points(t["polygon"], unit, f"{path}.polygon")])
            if not poly.is_valid or poly.area <= 0:
                raise InputError(f"{path}.polygon: the cut-out crosses itself or encloses no area")
        else:
            if "size" not in t:
                raise InputError(f"{path}.size: missing (\"dx, dy\" of the rectangle)")
            c, sz = parse_point(t["center"], unit, f"{path}.center"), parse_point(t["size"], unit, f"{path}.size")
            r = _positive(t["corner_radius"], "length", f"{path}.corner_radius") if "corner_radius" in t else None
            try:
                poly = ShapelyPolygon(pl.rectangle_cutout(c, sz, r).m_as("m"))
            except InputError as exc:
                raise InputError(f"{path}.{exc}") from None
        if not shell.contains(poly):
            raise InputError(f"{path}: the cut-out is not inside the plate outline")
        out.append(Q(np.asarray(poly.exterior.coords)[:-1], "m"))
    return out


def _supports(p: Mapping[str, Any], plate: pl.Plate, groups: dict[str, list[str]], unit: str) -> tuple[Any, ...]:
    out: list[Any] = []
    n_edges = len(plate.outline)
    for i, t in enumerate(p["supports"]):
        path = f"supports[{i}]"
        t = inline_table(t, path, ("edges", "point", "holes", "type", "washer_diameter"))
        where = [k for k in ("edges", "point", "holes") if k in t]
        if len(where) != 1:
            raise InputError(f"{path}: give exactly one of edges, point or holes")
        kind = t.get("type", "fixed")
        if kind not in SUPPORT_TYPES:
            hint = suggest(str(kind), tuple(SUPPORT_TYPES), 1)
            raise InputError(f"{path}.type: expected fixed or pinned, got {kind!r}"
                             + (f"; did you mean {hint[0]!r}?" if hint else ""))
        cond = SUPPORT_TYPES[kind]
        if "washer_diameter" in t and "holes" not in t:
            raise InputError(f"{path}.washer_diameter: only a hole support has a washer")
        if "edges" in t:
            out.append(pl.EdgeSupport(_edges(t["edges"], plate, n_edges, f"{path}.edges"), cond))
        elif "point" in t:
            pt = parse_point(t["point"], unit, f"{path}.point")
            if plate.region.distance(ShapelyPoint(_si(pt))) > 1e-9 * math.sqrt(plate.region.area):
                raise InputError(f"{path}.point: ({t['point']}) is not on the plate (outside it or in a hole)")
            out.append(pl.PointSupport(pt, cond))
        else:
            names = _hole_names(t["holes"], groups, f"{path}.holes")
            washer = None
            if "washer_diameter" in t:
                washer = _positive(t["washer_diameter"], "length", f"{path}.washer_diameter")
                for h in names:
                    if washer.m_as("m") <= plate.hole(h).diameter:
                        raise InputError(f"{path}.washer_diameter: {fmt(washer, 'mm')} must exceed the diameter of "
                                         f"hole {h!r}")
            out.append(pl.HoleSupport(names, cond, washer))
    return tuple(out)


def _edges(v: Any, plate: pl.Plate, n: int, path: str) -> Any:
    if v == "all":
        return "all"
    items = v if isinstance(v, list) else [v]
    idx = []
    for k, e in enumerate(items):
        if isinstance(e, str):
            if not plate.is_rectangle() or e not in RECT_EDGES:
                allowed = "bottom, right, top, left or indices" if plate.is_rectangle() else f"indices 0..{n - 1}"
                raise InputError(f"{path}[{k}]: expected {allowed} (edge i runs from outline point i to i+1), "
                                 f"got {e!r}")
            idx.append(RECT_EDGES[e])
        elif isinstance(e, int) and not isinstance(e, bool) and 0 <= e < n:
            idx.append(e)
        else:
            raise InputError(f"{path}[{k}]: expected an edge index 0..{n - 1} (edge i runs from outline point i to "
                             f"i+1), got {e!r}")
    if not idx:
        raise InputError(f"{path}: give \"all\" or at least one edge")
    return tuple(idx)


def _hole_names(v: Any, groups: dict[str, list[str]], path: str) -> Any:
    if v == "all":
        if not groups:
            raise InputError(f"{path}: the plate has no holes")
        return [h for g in groups.values() for h in g]
    items = v if isinstance(v, list) else [v]
    known = {h for g in groups.values() for h in g}
    out: list[str] = []
    for k, name in enumerate(items):
        if name in groups:
            out += groups[name]
        elif name in known:
            out.append(name)
        else:
            hint = suggest(str(name), (*groups, *sorted(known)), 1)
            raise InputError(f"{path}[{k}]: no hole or hole group {name!r}"
                             + (f"; did you mean {hint[0]!r}?" if hint else f" (holes: {', '.join(groups) or 'none'})"))
    return out


def _loads(loads: Mapping[str, Any], base: str, unit: str, g: Any) -> list[Any]:
    out: list[Any] = []
    for i, t in enumerate(loads.get("point_loads", [])):
        path = f"{base}.point_loads[{i}]"
        t = inline_table(t, path, ("at", "force", "moment_x", "moment_y"), ("at",))
        if not any(k in t for k in ("force", "moment_x", "moment_y")):
            raise InputError(f"{path}: give force and/or moment_x, moment_y")
        kw = {"force": _q(t.get("force", "0 N"), "force", f"{path}.force"),
              "moment_x": _q(t.get("moment_x", "0 N*m"), "torque", f"{path}.moment_x"),
              "moment_y": _q(t.get("moment_y", "0 N*m"), "torque", f"{path}.moment_y")}
        try:
            out.append(pl.PlatePointLoad(parse_point(t["at"], unit, f"{path}.at"), **kw))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    for i, t in enumerate(loads.get("patch_loads", [])):
        path = f"{base}.patch_loads[{i}]"
        t = inline_table(t, path, ("center", "size", "polygon", "force", "pressure"))
        if ("force" in t) == ("pressure" in t):
            raise InputError(f"{path}: give exactly one of force (total) or pressure")
        if ("polygon" in t) == ("center" in t):
            raise InputError(f"{path}: give either polygon = [points] or center and size (a rectangle)")
        kw = ({"force": _q(t["force"], "force", f"{path}.force")} if "force" in t
              else {"pressure": _q(t["pressure"], "pressure", f"{path}.pressure")})
        if "polygon" in t:
            kw["polygon"] = _points(t["polygon"], unit, f"{path}.polygon")
        else:
            if "size" not in t:
                raise InputError(f"{path}.size: missing (\"dx, dy\" of the rectangle)")
            kw["center"] = parse_point(t["center"], unit, f"{path}.center")
            kw["size"] = parse_point(t["size"], unit, f"{path}.size")
        try:
            out.append(pl.PatchLoad(**kw))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    if "pressure" in loads:
        out.append(pl.PressureLoad(loads["pressure"]))
    if loads.get("self_weight"):
        out.append(pl.PlateSelfWeight(g=g))
    if not out and "in_plane" not in loads:  # in-plane edge loads alone: membrane stress, no bending
        raise InputError(f"{base}: no load (point_loads, patch_loads, pressure, self_weight = true or in_plane)")
    return out


