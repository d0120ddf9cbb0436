"""The span of a plate as its supports make it (review 4 finding 30): the ``L`` of a fractional deflection limit
("L/250") and of the thin-plate test (span / thickness < 10) of ``plate_fea``.

The bounding box's shorter side was taken whatever the supports: a 400 x 40 mm strip held on its two SHORT edges
spans 400 mm, not 40 (its limit was 10x too tight and a false THICK PLATE warning came), and a 400 x 400 plate with a
row of point supports along x = 200 spans 200 mm, not 400 (its limit was 2x too loose: unconservative).

:func:`plate_span` looks from the point of largest deflection ``P`` along straight lines (every
180/:data:`DIRECTIONS` degrees) across the plate's outline (holes and cut-outs do not end a line: the plate spans
round them). On each line, on each side of ``P``, the first support met is found: a supported outline edge where the
line leaves the outline, or a point-like support (a point support, a supported hole's rim or washer) the line passes
within its *reach* - half the clear distance from it to the nearest other support, at least its radius: a row of
point supports or bolts at a pitch s holds like a line for lines passing between them, four corner posts are met by
a line half-way between two of them. A line that meets supports on both sides gives the clear distance between the
two supports met (between the edge points, the point supports, the washers' rims); a line that meets one support and
leaves the outline at a free edge on the other side gives a cantilever's length (from that support to the free
edge, through ``P``).
The span is the SHORTEST clear span between supports (the plate carries its load mostly the short way; the shorter
span also gives the tighter, conservative limit): on a plate supported all round it is the shorter side, as before.
Only where no line bridges two supports is it the shortest cantilever (a line from a point on a free edge along
that edge leaves the plate at once on one side, which is no cantilever while another line bridges supports).

Geometry only (the supports' conditions do not enter: a pinned edge "cantilever" is one all the same). Where no
line meets a support the shorter side of the bounding box is kept, said in the description. Measured: the strip
400 x 40 on its short edges 400 mm, a 400 x 400 plate with a middle row of point supports at 50 mm pitch 200 mm, four
corner bolts 270 mm apart with 11 mm washers 259 mm, four corner posts of a square its side (tests/test_plate_span.py).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import shapely

#: number of line directions through the governing point over 180 degrees (1 degree apart; 0 and 90 exact)
DIRECTIONS = 180


def _support_geometry(model: Any) -> tuple[list[tuple[np.ndarray, np.ndarray]], list[tuple[np.ndarray, float]]]:
    """(supported outline edge segments, point-like supports (centre, radius)) of ``model`` [m]: a point support
    has radius 0, a supported hole its rim's or washer's radius."""
    from mechverify.components import plates as pl

    plate = model.plate
    edges, spots = [], []
    outline = plate.edges()
    for s in model.supports:
        if isinstance(s, pl.EdgeSupport):
            edges += [(np.asarray(outline[i][0], float), np.asarray(outline[i][1], float))
                      for i in s.edge_indices(plate)]
        elif isinstance(s, pl.HoleSupport):
            for h in s.resolve(plate):
                r = h.radius if s.washer_diameter is None else max(h.radius, s.washer_diameter / 2)
                spots.append((np.asarray(h.center, float), float(r)))
        elif isinstance(s, pl.PointSupport):
            spots.append((np.asarray(s.point, float), 0.0))
    return edges, spots


def _seg_dist(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    ab = b - a
    L2 = float(ab @ ab)
    t = 0.0 if L2 == 0 else min(1.0, max(0.0, float((p - a) @ ab) / L2))
    return float(np.linalg.norm(p - (a + t * ab)))


def _reaches(spots: list[tuple[np.ndarray, float]], edges: list[Any]) -> list[float]:
    """Each point-like support's reach: half the clear distance to the nearest other support (edge, point or
    hole), at least its own radius."""
    out = []
    for i, (p, r) in enumerate(spots):
        d = [max(0.0, float(np.linalg.norm(p - q)) - r - rq) for j, (q, rq) in enumerate(spots) if j != i]
        d += [max(0.0, _seg_dist(p, a, b) - r) for a, b in edges]
        d = [x for x in d if x > 0]
        out.append(max(r, r + 0.5 * min(d)) if d else r)
    return out


def _chord(region: Any, p: np.ndarray, d: np.ndarray, size: float, tol: float) -> tuple[float, float] | None:
    """(t_lo <= 0 <= t_hi): the piece of the line p + t d inside the plate that holds p, or None."""
    line = shapely.LineString([p - 2 * size * d, p + 2 * size * d])
    cut = region.intersection(line)
    spans = []  # the pieces as intervals of t, merged where they touch (a line along an edge comes in pieces)
    for g in getattr(cut, "geoms", [cut]):
        if g.geom_type == "LineString" and not g.is_empty:
            ts = [float((np.asarray(c) - p) @ d) for c in g.coords]
            spans.append([min(ts), max(ts)])
    spans.sort()
    merged: list[list[float]] = []
    for a, b in spans:
        if merged and a <= merged[-1][1] + tol:
            merged[-1][1] = max(merged[-1][1], b)
        else:
            merged.append([a, b])
    for lo, hi in merged:
        if lo - tol <= 0 <= hi + tol and hi - lo > tol:
            return min(lo, 0.0), max(hi, 0.0)
    return None


def plate_span(model: Any, point: Any) -> tuple[float, str]:
    """(span [m], how it was found) of ``model`` (a :class:`mechverify.components.plates.PlateModel`) seen from
    ``point`` [m] (x, y), the point of largest deflection: the shortest clear distance between supports on a
    straight line through the point, or the shortest cantilever (a support to the free edge through the point);
    the rule is in the module's docstring."""
    plate = model.plate
    region = plate.region
    x0, y0, x1, y1 = region.bounds
    size = math.hypot(x1 - x0, y1 - y0)
    tol = 1e-9 * size
    p = np.asarray(point, float)[:2]
    edges, spots = _support_geometry(model)
    reach = _reaches(spots, edges)
    # holes and cut-outs do not end a line (the plate spans round them); grown by a hair so that a line along an
    # edge stays inside in floating point
    outline = shapely.Polygon(plate.outline).buffer(2 * tol, join_style="mitre")
    best: tuple[float, str, float] | None = None
    for k in range(DIRECTIONS):
        th = math.pi * k / DIRECTIONS
        d = np.array([math.cos(th), math.sin(th)])
        d[np.abs(d) < 1e-12] = 0.0  # 90 degrees exactly
        ch = _chord(outline, p, d, size, tol)
        if ch is None:
            continue
        lo, hi = ch
        hits: dict[int, tuple[np.ndarray, float]] = {}  # side (+1/-1): the first support's (location, radius)
        for side, end in ((1, hi), (-1, lo)):
            e = p + end * d
            cand = ([(abs(end), e, 0.0)] if abs(end) > tol and any(_seg_dist(e, a, b) <= 1e3 * tol for a, b in edges)
                    else [])
            for (c, r), rc in zip(spots, reach, strict=True):
                q = float((c - p) @ d) * side
                perp = math.sqrt(max(0.0, float(np.linalg.norm(c - p)) ** 2 - q * q))
                if tol < q <= abs(end) + rc + tol and perp <= rc * (1 + 1e-9) + tol:
                    cand.append((q, c, r))
            if cand:
                _, loc, r = min(cand, key=lambda x: x[0])
                hits[side] = (loc, r)
        if len(hits) == 2:
            (a, ra), (b, rb) = hits[1], hits[-1]
            span, kind = float(np.linalg.norm(a - b)) - ra - rb, "between"
        elif hits:
            side = next(iter(hits))
            a, ra = hits[side]
            span, kind = float(np.linalg.norm(a - (p + (lo if side == 1 else hi) * d))) - ra, "cantilever"
        else:
            continue
        # a line that bridges supports beats any cantilever (a line from a point on a free edge along that edge
        # leaves the plate at once on one side: no cantilever while another line bridges)
        rank = (kind != "between", span)
        if best is None or rank < ((best[1] != "between"), best[0] - tol):
            best = (span, kind, math.degrees(th))
    if best is None:
        s = min(x1 - x0, y1 - y0)
        return s, (f"span {s * 1e3:.4g} mm: the shorter side of the bounding box (no support found on a line "
                   "through the point of largest deflection)")
    span, kind, deg = best
    at = f"({p[0] * 1e3:.4g}, {p[1] * 1e3:.4g}) mm"
    if kind == "between":
        how = (f"span {span * 1e3:.4g} mm: the shortest clear distance between supports on a line through the "
               f"point of largest deflection {at} (at {deg:.0f} deg to x)")
    else:
        how = (f"span {span * 1e3:.4g} mm: a cantilever - the shortest distance from a support through the point "
               f"of largest deflection {at} to the free edge (at {deg:.0f} deg to x)")
    return span, how


__all__ = ["plate_span", "DIRECTIONS"]
