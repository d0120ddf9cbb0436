"""Parsing of a ``plate_fea`` plate's geometry: a rectangle (``width`` x ``height``) or an ``outline`` polygon, the
thickness and material, hole groups and cut-outs, into a :class:`mechverify.components.plates.Plate`; and its
deflection limit. Used by :mod:`mechverify.design.adapters.plate_fea`; declares no component type.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.components import plates as pl
from mechverify.design.adapters.plate_parsing import _cutouts, _holes, _points, _si
from mechverify.errors import InputError, MechverifyError
from mechverify.units import Q, fmt


def parse_plate(p: dict[str, Any], name: str, unit: str) -> tuple[pl.Plate, dict[str, list[str]]]:
    """The plate of a ``plate_fea`` component's values ``p`` and its hole groups (group name -> hole names); bad
    values are an :class:`InputError` naming the key."""
    try:
        Q(1.0, unit).to("m")
    except Exception:
        raise InputError(f"unit: expected a length unit such as \"mm\", got {unit!r}") from None
    rect = "width" in p or "height" in p
    if rect and "outline" in p:
        raise InputError("outline: give either width and height (a rectangle) or outline, not both")
    if rect:
        for k in ("width", "height"):
            if k not in p:
                raise InputError(f"{k}: missing; a rectangular plate needs width and height")
            if not p[k].magnitude > 0:
                raise InputError(f"{k}: must be positive, got {fmt(p[k], 'mm')}")
        w, h = p["width"], p["height"]
        outline = [(Q(0.0, "m"), Q(0.0, "m")), (w, Q(0.0, "m")), (w, h), (Q(0.0, "m"), h)]
    elif "outline" in p:
        outline = _points(p["outline"], unit, "outline")
        ring = shapely.LinearRing([_si(q) for q in outline])
        if not ring.is_simple:
            raise InputError("outline: the outline crosses itself")
    else:
        raise InputError("width: missing; give width and height (a rectangle) or outline (a polygon)")
    if not p["thickness"].magnitude > 0:
        raise InputError(f"thickness: must be positive, got {fmt(p['thickness'], 'mm')}")
    shell = ShapelyPolygon([_si(q) for q in outline])
    if shell.area <= 0:
        raise InputError("outline: the outline encloses no area")
    holes, groups = _holes(p, unit, shell)
    cutouts = _cutouts(p, unit, shell)
    try:
        plate = pl.Plate(Q(np.array([[a.m_as("m"), b.m_as("m")] for a, b in outline]), "m"), p["thickness"],
                         p["material"], holes, cutouts, name=name)
    except MechverifyError as exc:
        raise InputError(str(exc).replace(f"{name}.", "", 1)) from None
    return plate, groups


def parse_limit(p: dict[str, Any], plate: pl.Plate, default: Any) -> tuple[Any, Any]:
    """The deflection limit (``deflection_limit`` or ``deflection_limit_fraction``, else ``default``) and the span a
    fractional limit applies to (``span``, else None: the check derives it from the supports,
    :func:`mechverify.fea.plate_span.plate_span`; the shorter side of the bounding box only checks the limit here)."""
    from mechverify.checks import members as mc

    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", default)
    x0, y0, x1, y1 = plate.region.bounds
    span = p.get("span")
    try:
        mc.deflection_limit(limit, span or Q(min(x1 - x0, y1 - y0), "m").to("mm"))
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the span: "
                         + str(exc).split(": ", 1)[-1]) from None
    return limit, span
