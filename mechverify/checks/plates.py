"""Checks of flat plates: Roark's closed-form cases and the plate-bending FEA model.

Two methods check the same things, so each has its own name: ``plate_stress_roark`` and
``plate_deflection_roark`` (a whole plate on its edges, Roark 8th ed. Tables 11.2 and 11.4),
``plate_stress_fea`` and ``plate_deflection_fea`` (any outline with holes, cut-outs and supports on
edges, points or hole rims: :func:`mechverify.fea.plate.solve_plate`, Kirchhoff, Morley triangles).
Each returns a :class:`CheckResult` oriented so that it passes while demand <= capacity / required_sf.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.checks.members import deflection_check
from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components import plates as pl
from mechverify.references import ref
from mechverify.units import Q, fmt, to_si

if TYPE_CHECKING:  # annotations only: importing the checks does not import the FEA layer
    from mechverify.fea.results import FieldResults

FEA_SOURCE = (f"Kirchhoff plate bending, Morley triangles ({ref('morley1971')}; "
              f"{ref('timoshenko_woinowsky', 'ch. 4')}); verified against {ref('roark8', 'Tables 11.2 and 11.4')}")
VM_SOURCE = (f"surface stresses sigma = N / t +- 6 M / t^2, membrane + bending "
             f"({ref('timoshenko_woinowsky', 'Eq. (101)')}); von Mises criterion, {ref('shigley10', 'Eq. (5-13)')}; "
             f"membrane stress by plane-stress FEA on the plate mesh, verified against {ref('roark8', 'Table 17.1')} "
             "(hole in tension)")


# ------------------------------------------------------------------------------------------------ Roark
@check("plate_stress_roark", title="Plate bending stress (Roark)", sf_kind="static", aliases=("plate.stress",),
       source=ref("roark8", "Tables 11.2 and 11.4"),
       explain=("Largest surface bending stress of Roark 8th ed. Table 11.4 (rectangle: cases 1a, 1b, 8a, 8b) or "
                "Table 11.2 (circle: cases 10a, 10b, 16, 17) against S_y. The closed forms cover a whole plate "
                "on its edges only; plates on bolts or with cut-outs need plate_stress_fea."))
def check_plate_stress_roark(plate: pl.Plate, estimate: pl.PlateEstimate, *, required_sf: float = 1.0,
                             load_case: str = "") -> CheckResult:
    """A Roark plate estimate's largest bending stress against the plate's yield strength."""
    sy = plate.material.require("yield_strength")
    warnings = list(estimate.warnings)
    if plate.holes or plate.cutouts:
        warnings.append("the plate has holes/cut-outs: Roark's closed form ignores them (use the FEA plate model)")
    return CheckResult(
        check="plate_stress_roark", component=plate.name, demand=estimate.max_stress.to("MPa"),
        capacity=sy.to("MPa"), required_sf=required_sf, title="Plate bending stress (Roark)",
        formula=r"\sigma_{max} \le S_y", source=estimate.source, inputs={"t": Q(plate.thickness, "m").to("mm")},
        substituted=roark_stress_substituted(estimate),
        notes=(estimate.case, f"largest stress at the {estimate.stress_location}"), warnings=tuple(warnings),
        load_case=load_case, details={k: v.to("MPa") for k, v in estimate.stresses.items()})


def roark_stress_substituted(est: pl.PlateEstimate) -> str:
    """The governing Roark stress with the numbers (Roark 8th ed. Table 11.4 cases 1a, 1b, 8a, 8b; Table 11.2
    cases 10a, 10b, 16, 17; the formulas of :func:`~mechverify.components.plates.roark_rectangular_plate` and
    :func:`~mechverify.components.plates.roark_circular_plate`); empty for an estimate without its inputs."""
    i, c, where = est.inputs, est.coefficients, est.stress_location
    if not i:
        return ""
    t, nu, kind = tex(Q(i["t"] * 1e3, "mm")), tex(i["nu"]), i["kind"]
    load = tex(Q(i["load"], "Pa"), "kPa") if kind == "uniform" else tex(Q(i["load"], "N"))
    result = tex(est.max_stress, "MPa")
    if i["shape"] == "rectangle":
        b = tex(Q(i["b"] * 1e3, "mm"))
        if kind == "uniform":
            beta = c["beta_edge"] if where != "centre" else c["beta"]
            return rf"\sigma_{{max}} = \frac{{{tex(beta)}\cdot {load}\cdot ({b})^{{2}}}}{{({t})^{{2}}}} = {result}"
        if where != "centre":
            return rf"\sigma_{{max}} = \frac{{{tex(c['beta_edge'])}\cdot {load}}}{{({t})^{{2}}}} = {result}"
        r0 = tex(Q(c["r0_equivalent"] * 1e3, "mm"))
        return (rf"\sigma_{{max}} = \frac{{3\cdot {load}}}{{2\cdot \pi\cdot ({t})^{{2}}}}\cdot \left((1 + {nu})\cdot "
                rf"\ln\frac{{2\cdot {b}}}{{\pi\cdot {r0}}} + {tex(c['beta'])}\right) = {result}")
    a = tex(Q(i["a"] * 1e3, "mm"))
    if kind == "uniform":
        if where == "edge":  # 10b
            return rf"\sigma_{{max}} = \frac{{3\cdot {load}\cdot ({a})^{{2}}}}{{4\cdot ({t})^{{2}}}} = {result}"
        k = f"(3 + {nu})" if i["edge"] == "simply_supported" else f"(1 + {nu})"
        return rf"\sigma_{{max}} = \frac{{3\cdot {k}\cdot {load}\cdot ({a})^{{2}}}}{{8\cdot ({t})^{{2}}}} = {result}"
    if where == "edge":  # 17
        return rf"\sigma_{{max}} = \frac{{3\cdot {load}}}{{2\cdot \pi\cdot ({t})^{{2}}}} = {result}"
    r0 = tex(Q(c["r0_equivalent"] * 1e3, "mm"))
    if i["edge"] == "simply_supported":  # 16
        return (rf"\sigma_{{max}} = \frac{{3\cdot {load}}}{{2\cdot \pi\cdot ({t})^{{2}}}}\cdot \left((1 + {nu})\cdot "
                rf"\ln\frac{{{a}}}{{{r0}}} + 1\right) = {result}")
    return (rf"\sigma_{{max}} = \frac{{3\cdot {load}\cdot (1 + {nu})}}{{2\cdot \pi\cdot ({t})^{{2}}}}\cdot "
            rf"\ln\frac{{{a}}}{{{r0}}} = {result}")


@check("plate_deflection_roark", title="Plate deflection (Roark)", sf_kind="deflection",
       aliases=("plate.deflection",), source=ref("roark8", "Tables 11.2 and 11.4"),
       explain=("Largest deflection of the same Roark case against the limit (a length, 'L/250' or a fraction "
                "of the shorter side)."))
def check_plate_deflection_roark(plate: pl.Plate, estimate: pl.PlateEstimate, limit: Any, *, span: Any = None,
                                 load_case: str = "") -> CheckResult:
    """A Roark plate estimate's largest deflection against ``limit`` (a length, ``"L/250"`` or a fraction of
    ``span``, the shorter side or the diameter)."""
    r = deflection_check(estimate.max_deflection, limit, span=span, component=plate.name, load_case=load_case,
                         source=estimate.source)
    sub = roark_deflection_substituted(estimate)
    return dataclasses.replace(r, check="plate_deflection_roark", title="Plate deflection (Roark)",
                               notes=(*r.notes, estimate.case), warnings=tuple(estimate.warnings),
                               substituted=r",\quad ".join(x for x in (sub, r.substituted) if x))


def roark_deflection_substituted(est: pl.PlateEstimate) -> str:
    """The Roark deflection with the numbers (Table 11.4: ``alpha q b^4/(E t^3)``, ``alpha W b^2/(E t^3)``;
    Table 11.2 with ``D = E t^3/(12 (1 - nu^2))``)."""
    i = est.inputs
    if not i:
        return ""
    t, nu, E, kind = tex(Q(i["t"] * 1e3, "mm")), tex(i["nu"]), tex(Q(i["E"] / 1e9, "GPa")), i["kind"]
    load = tex(Q(i["load"], "Pa"), "kPa") if kind == "uniform" else tex(Q(i["load"], "N"))
    y = tex(est.max_deflection, "mm")
    if i["shape"] == "rectangle":
        b, alpha = tex(Q(i["b"] * 1e3, "mm")), tex(est.coefficients["alpha"])
        n = 4 if kind == "uniform" else 2
        return rf"y_{{max}} = \frac{{{alpha}\cdot {load}\cdot ({b})^{{{n}}}}}{{{E}\cdot ({t})^{{3}}}} = {y}"
    a = tex(Q(i["a"] * 1e3, "mm"))
    D = rf"\frac{{{E}\cdot ({t})^{{3}}}}{{12\cdot (1 - ({nu})^{{2}})}}"
    ss = i["edge"] == "simply_supported"
    if kind == "uniform":
        num = rf"{load}\cdot ({a})^{{4}}" + (rf"\cdot (5 + {nu})" if ss else "")
        den = rf"64\cdot {D}" + (rf"\cdot (1 + {nu})" if ss else "")
    else:
        num = rf"{load}\cdot ({a})^{{2}}" + (rf"\cdot (3 + {nu})" if ss else "")
        den = rf"16\cdot \pi\cdot {D}" + (rf"\cdot (1 + {nu})" if ss else "")
    return rf"y_{{max}} = \frac{{{num}}}{{{den}}} = {y}"


# -------------------------------------------------------------------------------------------------- FEA
def _mm(xy: Any) -> str:
    return f"({xy[0] * 1e3:.4g}, {xy[1] * 1e3:.4g}) mm"


def nearest_feature(model: pl.PlateModel, xy: np.ndarray) -> str:
    """Where a point of the plate lies: on a hole rim, a cut-out edge, the outline, at a load, or inside."""
    plate = model.plate
    pt = ShapelyPoint(xy)
    tol = 0.02 * math.sqrt(plate.region.area)
    cands: list[tuple[float, str]] = []
    for hole in plate.holes:
        cands.append((abs(float(np.hypot(*(xy - np.asarray(hole.center)))) - hole.radius),
                      f"at the rim of hole {hole.name!r} (d = {hole.diameter * 1e3:.4g} mm)"))
    for i, cut in enumerate(plate.cutouts):
        cands.append((ShapelyPolygon(cut).exterior.distance(pt), f"at the edge of cut-out {i}"))
    for i, (a, b) in enumerate(plate.edges()):
        cands.append((shapely.LineString([a, b]).distance(pt), f"at outline edge {i} (from {_mm(a)} to {_mm(b)})"))
    for i, ld in enumerate(model.loads):
        if isinstance(ld, pl.PlatePointLoad):
            cands.append((float(np.hypot(*(xy - np.asarray(ld.point)))), f"at point load {i}"))
    for s in model.supports:
        if isinstance(s, pl.HoleSupport) and s.washer_diameter:
            for hole in s.resolve(plate):
                cands.append((abs(float(np.hypot(*(xy - np.asarray(hole.center)))) - s.washer_diameter / 2),
                              f"at the edge of the washer (d = {s.washer_diameter * 1e3:.4g} mm) of hole "
                              f"{hole.name!r}"))
        if isinstance(s, pl.PointSupport):
            cands.append((float(np.hypot(*(xy - np.asarray(s.point)))), f"at the point support {_mm(s.point)}"))
    d, what = min(cands, key=lambda x: x[0])
    return what if d <= tol else "inside the plate, away from holes and edges"


def singular_features(model: pl.PlateModel, in_plane_supports: Sequence[Any] = ()
                      ) -> list[tuple[str, np.ndarray, float]]:
    """Where the Kirchhoff model's stress is singular (it grows or wanders without converging as the mesh is
    refined): point loads and point supports (a concentrated force on a plate gives an infinite moment, Timoshenko
    & Woinowsky-Krieger sec. 19) and the edge of a washer disc, which the model holds rigidly over the mesh edges
    inside the washer circle: that jagged edge of a rigid support has re-entrant corners, singular in plate bending
    (Williams 1952); and the ends of outline edges held in the plate's plane (``in_plane_supports``,
    :class:`mechverify.fea.plate_stress.InPlaneSupport`): a rigidly held edge meeting a free one is a singular corner
    of plane elasticity (Williams 1952; measured: 63, 74, 87 MPa at 10, 5, 2.5 mm for 50 MPa nominal). Each is
    ``(description, centre [m], radius [m])``, radius 0 for a point."""
    out: list[tuple[str, np.ndarray, float]] = []
    for s in in_plane_supports:
        if getattr(s, "edges", ()) not in ((), [], None):
            edges = model.plate.edges()
            for i in pl.EdgeSupport(s.edges).edge_indices(model.plate):
                for end in edges[i]:
                    out.append((f"end {_mm(end)} of outline edge {i}, held in the plate's plane",
                                np.asarray(end, dtype=float), 0.0))
    for ld in model.loads:
        if isinstance(ld, pl.PlatePointLoad):
            out.append((f"point load at {_mm(ld.point)}", np.asarray(ld.point, dtype=float), 0.0))
    for s in model.supports:
        if isinstance(s, pl.PointSupport):
            out.append((f"point support at {_mm(s.point)}", np.asarray(s.point, dtype=float), 0.0))
        elif isinstance(s, pl.HoleSupport) and s.washer_diameter:
            for hole in s.resolve(model.plate):
                out.append((f"edge of the washer (d = {s.washer_diameter * 1e3:.4g} mm) of hole {hole.name!r}",
                            np.asarray(hole.center, dtype=float), s.washer_diameter / 2))
    return out


def local_size(res: FieldResults, node: int) -> float:
    """The mean length of the element edges at ``node`` [m] (the mesh's median edge where it has none)."""
    tri = np.asarray(res.surface)
    pts = res.points[:, :2]
    rows = tri[np.any(tri == node, axis=1)]
    if rows.size == 0:
        rows = tri
    edges = np.linalg.norm(pts[rows] - pts[np.roll(rows, 1, axis=1)], axis=2)
    return float(np.mean(edges))


def _distance(xy: np.ndarray, centre: np.ndarray, radius: float) -> np.ndarray:
    """Distance [m] of points ``xy[..., 2]`` from a singular feature (0 inside a washer disc)."""
    return np.maximum(np.linalg.norm(xy - centre, axis=-1) - radius, 0.0)


def singular_at(model: pl.PlateModel, res: FieldResults, node: int, in_plane_supports: Sequence[Any] = ()
                ) -> tuple[str, float] | None:
    """The singular feature (:func:`singular_features`) within 2.5 local element sizes of ``node``, with that
    size [m]; None when the node lies away from all of them."""
    h = local_size(res, node)
    xy = res.points[node, :2]
    near = [(float(_distance(xy, c, r)), what) for what, c, r in singular_features(model, in_plane_supports)]
    near = [x for x in near if x[0] <= 2.5 * h]
    return (min(near)[1], h) if near else None


def peak_away(model: pl.PlateModel, res: FieldResults, distance: float, in_plane_supports: Sequence[Any] = ()
              ) -> tuple[float, int] | None:
    """The largest von Mises stress [Pa] and its node among the nodes farther than ``distance`` [m] from every
    singular feature (:func:`singular_features`); None when there is no such node."""
    xy = res.points[:, :2]
    ok = np.ones(len(xy), dtype=bool)
    for _, c, r in singular_features(model, in_plane_supports):
        ok &= _distance(xy, c, r) > distance
    if not ok.any():
        return None
    vm = np.asarray(res.von_mises.m_as("Pa"))
    k = int(np.flatnonzero(ok)[np.argmax(vm[ok])])
    return float(vm[k]), k


def away_distance(model: pl.PlateModel, h: float) -> float:
    """How far from a singular feature the stress is judged [m]: one plate thickness (within about a thickness of
    a support or load, plate theory itself does not hold) and at least two local element sizes ``h``."""
    return max(model.plate.thickness, 2.0 * h)


def _stress_away(model: pl.PlateModel, res: FieldResults, h: float, in_plane_supports: Sequence[Any],
                 what: str) -> str:
    """The warning's clause naming the largest stress at least a plate thickness from ``what``, or "" if none."""
    d = away_distance(model, h)
    away = peak_away(model, res, d, in_plane_supports)
    return "" if away is None else (f" (the largest {d * 1e3:.3g} mm or more from {what}: {away[0] / 1e6:.4g} MPa "
                                    f"at {_mm(res.points[away[1], :2])})")


def _singular_warning(model: pl.PlateModel, res: FieldResults, node: int, in_plane_supports: Sequence[Any] = ()
                      ) -> tuple[str, ...]:
    hit = singular_at(model, res, node, in_plane_supports)
    if hit is None:
        return ()
    what, h = hit
    if what.endswith("held in the plate's plane"):
        there = _stress_away(model, res, h, in_plane_supports, "every singular point")
        return (f"the largest stress is at the {what}: a rigidly held edge meeting a free one is a stress singularity "
                "of the membrane (plane-stress) model, so this peak grows as the mesh is refined and refining will not "
                f"settle it; judge the stress about one plate thickness away{there}, or hold the plate where it is "
                "really held (bolt or pin holes: in_plane_supports holes)",)
    if not what.startswith("edge of the washer"):
        return (f"the largest stress is at a {what}: plate theory makes the stress under a concentrated force or "
                "support infinite, so this value depends on the mesh; spread the load over its real footprint "
                "(patch_loads) or support on a hole rim or edge",)
    there = _stress_away(model, res, h, in_plane_supports, "every washer edge")
    return (f"the largest stress is at the {what}: the model holds the plate rigidly over the washer disc, and the "
            "edge of that rigid clamp is a stress singularity of the Kirchhoff plate model, so this peak does not "
            "converge - it grows and wanders as the mesh is refined, and refining will not settle it; judge the "
            f"stress at a distance of about one plate thickness{there}, or model the clamp (pinned hole rims with "
            "the washer's clamping spread as a patch load)",)


#: Hole rims: the element size (a fraction of the hole's radius) at which the rim peak's accuracy was measured (the
#: code's own results on refined meshes against hand values, not a book's printed numbers; task plateacc, rims meshed
#: on their circles: mechverify.fea.plate.mesh_region): a 20 mm hole in a bent plate (400 x 200 x 4 mm steel, pinned,
#: 10 kPa) at hole_mesh_size 2 / 1 / 0.5 / 0.25 / 0.125 / 0.0625 mm gave 26.51 / 27.07 / 27.66 / 27.93 / 28.08 /
#: 28.15 MPa (converging to about 28.2 MPa; the infinite-plate hand value, T&WK moments times the bent-plate hole
#: factor (5 + 3 nu) / (3 + nu), is 28.75 MPa: the finite plate is about 2 % lower, as the same hole in a
#: 4000 x 2000 x 40 mm plate converges to 28.8-28.9 MPa); a 10 mm hole in tension (nx 100 N/mm, t 2 mm) at
#: 2 / 1 / 0.5 mm gave 146.8 / 148.9 / 150.6 MPa against 150.1 MPa (Roark Table 17.1 case 1a). The default hole
#: mesh (radius / 30: mechverify.fea.plate.RIM_DIVISIONS) gives 27.84 and 151.0 MPa.
#: A rim peak WARNs when hole_mesh_size exceeds this fraction of the radius (bending: 1 mm on R 10 mm was -4.0 %
#: against the converged 28.2 MPa, 0.5 mm -2.0 %; membrane: 1 mm on R 5 mm was -0.8 %, 2 mm -2.2 % against 150.1 MPa).
RIM_SIZE_LIMIT = {"bending": 0.05, "membrane": 0.2}
#: hole_mesh_size = radius / n advised at a rim: bending R/30 (the default; -1.3 % against the converged value),
#: membrane R/5 (-0.8 %).
RIM_ADVICE = {"bending": 30.0, "membrane": 5.0}
#: What was measured at the advised size (the words of the warning).
ACCURACY_AT_ADVICE = {"bending": "-1.3 % at radius / 30, -0.2 % at radius / 160",
                      "membrane": "-0.8 % at radius / 5"}
#: A finer mesh's peak lower than the coarse one's by more than this fraction moves away from a rim peak's trend
#: (:func:`plate_convergence`); smaller differences are round-off of a converged pair.
AWAY_NOISE = 1e-3


def _boundary_radius(pts: np.ndarray, xy: np.ndarray, poly: ShapelyPolygon) -> float:
    """The radius [m] of a cut-out's boundary near ``xy``: the circle through the outline vertex nearest to it and
    its two neighbours (a rounded corner's radius), at most the cut-out's largest inscribed circle (a straight side
    or a sharp corner: the cut-out's own size)."""
    if len(pts) > 1 and np.allclose(pts[0], pts[-1]):
        pts = pts[:-1]
    k = int(np.argmin(np.linalg.norm(pts - xy, axis=1)))
    a, b, c = pts[k - 1], pts[k], pts[(k + 1) % len(pts)]
    la, lb, lc = (float(np.linalg.norm(u - v)) for u, v in ((b, c), (a, c), (a, b)))
    area2 = abs(float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])))
    inscribed = float(shapely.maximum_inscribed_circle(poly, tolerance=1e-3 * math.sqrt(poly.area)).length)
    return inscribed if area2 == 0.0 else min(la * lb * lc / (2.0 * area2), inscribed)


def rim_feature(model: pl.PlateModel, res: FieldResults, node: int) -> tuple[str, float] | None:
    """The hole or cut-out on whose boundary ``node`` lies (within half a local element size), as
    ``(name, radius [m])``; a cut-out's radius is that of its boundary near the node (:func:`_boundary_radius`).
    None when the node is not on a hole rim or cut-out boundary."""
    plate = model.plate
    xy = res.points[node, :2]
    tol = 0.5 * local_size(res, node)
    best: tuple[float, str, float] | None = None
    for hole in plate.holes:
        d = abs(float(np.hypot(*(xy - np.asarray(hole.center)))) - hole.radius)
        if d <= tol and (best is None or d < best[0]):
            best = (d, f"hole {hole.name!r} (d = {hole.diameter * 1e3:.4g} mm)", hole.radius)
    for i, cut in enumerate(plate.cutouts):
        poly = ShapelyPolygon(cut)
        d = poly.exterior.distance(ShapelyPoint(xy))
        if d <= tol and (best is None or d < best[0]):
            r = _boundary_radius(np.asarray(cut, dtype=float), xy, poly)
            best = (d, f"cut-out {i} (radius of its boundary there {r * 1e3:.4g} mm)", r)
    return None if best is None else (best[1], best[2])


def _longest_edge(res: FieldResults, node: int) -> float:
    """The longest element edge [m] of the triangles at ``node`` (at a rim: about the radial element size, which the
    rim's polygon does not shorten)."""
    tri = np.asarray(res.surface)
    pts = res.points[:, :2]
    rows = tri[np.any(tri == node, axis=1)]
    if rows.size == 0:
        return local_size(res, node)
    return float(np.max(np.linalg.norm(pts[rows] - pts[np.roll(rows, 1, axis=1)], axis=2)))


def rim_accuracy_warning(model: pl.PlateModel, res: FieldResults, node: int, hole_mesh_size: float | None = None,
                         in_plane_supports: Sequence[Any] = ()) -> tuple[str, ...]:
    """A WARN when the peak at ``node`` lies on a hole rim or cut-out boundary (:func:`rim_feature`) whose element
    size ``hole_mesh_size`` [m] (the mesh's, default: the longest element edge at the node) exceeds
    :data:`RIM_SIZE_LIMIT` times its radius (for the part, bending or membrane, that dominates there): the rim's
    stress gradient is then not resolved and the peak is low (the measured accuracy of :data:`RIM_SIZE_LIMIT`'s
    comment). Nothing at a singular feature (:func:`singular_at`: a washer edge, a point load or support), whose
    own warning says that refining will not settle it."""
    hit = rim_feature(model, res, node)
    if hit is None or singular_at(model, res, node, in_plane_supports) is not None:
        return ()
    what, r = hit
    h = _longest_edge(res, node) if hole_mesh_size is None else float(hole_mesh_size)
    from mechverify.fea.plate_stress import governing_stress

    g = governing_stress(res, node)
    kind = "membrane" if np.linalg.norm(g.membrane) > np.linalg.norm(g.bending) else "bending"
    limit = RIM_SIZE_LIMIT[kind]
    if h <= limit * r * (1.0 + 1e-9):
        return ()
    n = RIM_ADVICE[kind]
    return (f"the largest stress is at the rim of {what}, meshed with hole_mesh_size {h * 1e3:.3g} mm, "
            f"{h / r:.2g} of its radius (above {limit:g} for a {kind} peak): the rim's stress gradient is not "
            "resolved and the peak may be low - measured on this model, the bending peak at a 20 mm hole was 26.51 / "
            "27.07 / 27.66 / 27.93 MPa at hole_mesh_size 2 / 1 / 0.5 / 0.25 mm, converging to about 28.2 MPa, the "
            "membrane peak at a 10 mm hole 146.8 / 148.9 / 150.6 MPa at 2 / 1 / 0.5 mm against 150.1 MPa; for about "
            f"1-2 % ({kind} governs here: measured {ACCURACY_AT_ADVICE[kind]}) set hole_mesh_size to about radius / "
            f"{n:g} = {r / n * 1e3:.3g} mm (or leave it out: the default is radius / 30 at round holes)",)


def roark_bent_hole_kt(two_r_over_t: float) -> float:
    """Stress concentration factor of a circular hole in an infinite plate of finite thickness under out-of-plane
    simple bending (M_2 = 0), nu = 0.3 (Roark 8th ed. Table 17.1, as printed on eng-calculations.com's Roark page):
    ``K_t = 1.79 + 0.25/(0.39 + 2r/t) + 0.81/(1 + (2r/t)^2) - 0.26/(1 + (2r/t)^3)`` [-]; its thin-plate limit
    (2r/t -> infinity) 1.79 is the Kirchhoff value (5 + 3 nu)/(3 + nu) = 1.788 the plate FEA reproduces."""
    x = float(two_r_over_t)
    return 1.79 + 0.25 / (0.39 + x) + 0.81 / (1 + x**2) - 0.26 / (1 + x**3)


#: A bending peak at a hole whose Roark factor exceeds the thin-plate 1.79 by more than this fraction WARNs
#: (:func:`thin_plate_hole_warning`): 2r/t below about 10.
THIN_PLATE_HOLE_LIMIT = 0.02


def thin_plate_hole_warning(model: pl.PlateModel, res: FieldResults, node: int,
                            in_plane_supports: Sequence[Any] = ()) -> tuple[str, ...]:
    """A WARN when the bending-dominated peak at ``node`` lies on a round hole's rim and the hole is not large against
    the plate's thickness: Kirchhoff theory gives the thin-plate hole factor 1.79 at any hole, while a plate of finite
    thickness concentrates more (:func:`roark_bent_hole_kt`, e.g. 1.87 at 2r/t = 5, 1.97 at 2.5), which no mesh of
    this model shows. The factor applies to the deviatoric (uniaxial) part of the moment; an isotropic moment gives
    2 in both theories, so the ratio is an upper bound of the increase. Nothing at a singular feature."""
    hit = rim_feature(model, res, node)
    if hit is None or not hit[0].startswith("hole") or singular_at(model, res, node, in_plane_supports) is not None:
        return ()
    from mechverify.fea.plate_stress import governing_stress

    g = governing_stress(res, node)
    if np.linalg.norm(g.membrane) > np.linalg.norm(g.bending):
        return ()
    x = 2.0 * hit[1] / model.plate.thickness
    ratio = roark_bent_hole_kt(x) / 1.79
    if ratio <= 1.0 + THIN_PLATE_HOLE_LIMIT:
        return ()
    return (f"THIN-PLATE HOLE FACTOR: the peak is a bending stress at {hit[0]}, whose diameter is only {x:.3g} plate "
            "thicknesses: the Kirchhoff plate model gives the thin-plate hole factor 1.79 (simple bending) at any "
            f"hole, while Roark's Table 17.1 gives {roark_bent_hole_kt(x):.3g} for 2r/t = {x:.3g} (nu = 0.3), so the "
            f"real peak may be up to {100 * (ratio - 1):.3g} % higher than this (less where the moment is nearly "
            "isotropic, factor 2 in both theories); raise the demand by that factor, or model the part as a solid "
            "(solid_fea)",)


def plate_convergence(model: pl.PlateModel, runs: Sequence[FieldResults], ratio: float, tolerance: float,
                      sizes: tuple[float, float], in_plane_supports: Sequence[Any] = ()
                      ) -> tuple[FieldResults, list[str], list[str]]:
    """Mesh-convergence check of the peak von Mises stress on two or three meshes ``runs`` (coarse to fine, each
    ``ratio`` times finer; the first is the design's, element sizes ``sizes`` = (mesh_size, hole_mesh_size) [m]):
    :class:`mechverify.fea.plate_convergence.MeshSequence`. With three meshes the order of convergence is OBSERVED
    (the Morley rim peak converges as h^1 to h^1.5, not the h^2 the two-mesh check assumed: review 3 finding 9b) and
    Richardson's error estimate is given only when the peaks are monotone and the order is between 0.5 and 4; the
    mesh advice comes from the observed order. With two meshes order 2 is assumed. Returns the result with the
    largest peak (the demand), the notes and the warnings: the design mesh's or the demand's estimated error above
    ``tolerance``; a
    sequence not in the asymptotic range that changes by more than half the tolerance; a peak on a hole rim or
    cut-out boundary (:func:`rim_feature`) that FALLS on finer meshes (by more than :data:`AWAY_NOISE`: a rim peak
    rises as the rim is resolved). A peak at a singular feature (:func:`singular_features`) is named as such instead
    of asking for a finer mesh that would not settle it."""
    from mechverify.fea.plate_convergence import MeshSequence

    vals = [float(r.max_von_mises.value.m_as("MPa")) for r in runs]
    seq = MeshSequence(tuple(vals), ratio, 2.0)
    g = int(np.argmax(vals))
    gov = runs[g]
    hits = [singular_at(model, r, int(r.max_von_mises.node), in_plane_supports) for r in runs]
    hit = next((x for x in hits if x is not None), None)
    rim = None if hit is not None else rim_feature(model, runs[0], int(runs[0].max_von_mises.node))
    kind = "three" if len(runs) == 3 else "two"
    notes = [f"{kind}-mesh check of the peak von Mises stress: {seq.words('MPa')}; the largest is the demand"]
    warnings: list[str] = []
    if rim is not None and vals[-1] < vals[0] * (1.0 - AWAY_NOISE):
        # a rim peak rises towards the answer as the mesh resolves the rim's gradient (review 3 finding 9); a finer
        # mesh that gives LESS is not in the asymptotic range, and Richardson's estimate of such a pair means nothing
        warnings.append(f"mesh convergence: the peak at the rim of {rim[0]} fell from {vals[0]:.4g} to {vals[-1]:.4g} "
                        f"MPa on meshes {ratio ** (len(runs) - 1):.3g}x finer, while a rim peak rises towards the "
                        "answer as the rim is resolved: the meshes are not in the asymptotic range, so their change "
                        f"({100 * seq.change:.3g} %) says nothing about the error; refine the hole mesh (about "
                        f"hole_mesh_size = radius / {RIM_ADVICE['bending']:g} = "
                        f"{rim[1] / RIM_ADVICE['bending'] * 1e3:.3g} mm) and check again")
        return gov, notes, warnings
    if hit is not None:
        d = away_distance(model, max(x[1] for x in hits if x is not None))
        pa, pb = (peak_away(model, r, d, in_plane_supports) for r in (runs[0], runs[-1]))
        if pa is not None and pb is not None:
            notes.append(f"the peak is at the {hit[0]} (singular); {d * 1e3:.3g} mm or more from every singular "
                         f"point the largest stress is {pa[0] / 1e6:.4g} MPa and {pb[0] / 1e6:.4g} MPa on the design's "
                         f"and the finest mesh (change {100 * abs(pb[0] - pa[0]) / max(pb[0], 1e-300):.3g} %)")
        if seq.change > tolerance or not seq.asymptotic:
            warnings.append(f"mesh convergence: the peak von Mises stress went {' / '.join(f'{v:.4g}' for v in vals)} "
                            f"MPa on meshes {ratio:g}x finer each (change {100 * seq.change:.3g} %, "
                            f"{'monotone' if seq.monotone else 'not monotone'}; tolerance {100 * tolerance:.3g} %); "
                            f"it sits at the {hit[0]}, a singularity of the plate model: a finer mesh will not "
                            "converge it (see the warning on the singular point)")
        return gov, notes, warnings
    err = seq.error(g)
    if err is None:
        if seq.change > tolerance / 2:
            peaks = " / ".join(f"{v:.4g}" for v in vals)
            warnings.append(f"mesh convergence: the peak von Mises stress is {peaks} MPa on meshes {ratio:g}x finer "
                            "each, not in the asymptotic range (not monotone, or an observed order outside 0.5-4), so "
                            "its error is unknown (changes up to "
                            f"{100 * seq.change:.3g} %); refine mesh_size and hole_mesh_size and check again")
        return gov, notes, warnings
    e0 = seq.error(0) or 0.0
    if max(err, e0) > tolerance:
        k = seq.refinement_needed(tolerance)
        warnings.append(f"mesh convergence: the peak is {vals[0]:.4g} MPa on the design's mesh, {vals[g]:.4g} MPa (the "
                        f"demand) on the finer, extrapolated {seq.extrapolated:.4g} MPa (Richardson, "
                        f"{'observed' if len(runs) == 3 else 'assumed'} order {seq.used_order:.2g}): estimated errors "
                        f"{100 * e0:.3g} % and {100 * err:.3g} % (tolerance {100 * tolerance:.3g} %); for the "
                        f"design's mesh to be within the tolerance use about mesh_size = {sizes[0] / k * 1e3:.3g} mm "
                        f"and hole_mesh_size = {sizes[1] / k * 1e3:.3g} mm ({k:.2g}x smaller than the design's)")
    return gov, notes, warnings


def describe_support(s: Any) -> str:
    """A support of a plate model in words (``"fixed edges [0, 2]"``)."""
    kind = "fixed" if s.condition == "clamped" else "pinned"
    if isinstance(s, pl.EdgeSupport):
        return f"{kind} edges {s.edges}"
    if isinstance(s, pl.PointSupport):
        return f"{kind} point {_mm(s.point)}"
    washer = f" to washer d = {s.washer_diameter * 1e3:.4g} mm" if s.washer_diameter else ""
    return f"{kind} rims of holes {s.holes}{washer}"


def _load_notes(model: pl.PlateModel, res: FieldResults) -> list[str]:
    sup = "; ".join(describe_support(s) for s in model.supports)
    return [f"supports: {sup}",
            f"applied load {res.applied[2]:.4g} N along z, reactions {res.reaction[2]:.4g} N (equilibrium checked)"]


@check("plate_stress_fea", title="Plate stress (FEA)", sf_kind="static", aliases=("plate_fea.stress",),
       source=f"{VM_SOURCE}; {FEA_SOURCE}",
       explain=("Largest von Mises stress at the plate's two faces, sigma = N/t +- 6 M/t^2: the membrane stress of "
                "the case's in_plane edge loads (plane stress on the plate mesh, so it concentrates at holes) plus "
                "the bending stress of its lateral loads (Kirchhoff plate FEA, Morley triangles), against the yield "
                "strength; Timoshenko & Woinowsky-Krieger eq. 101, Shigley 10th ed. Eq. 5-13."))
def check_plate_stress_fea(model: pl.PlateModel, res: FieldResults, *, component: str = "",
                           required_sf: float = 1.0, load_case: str = "", notes: Sequence[str] = (),
                           warnings: Sequence[str] = (), in_plane_supports: Sequence[Any] = (),
                           hole_mesh_size: float | None = None) -> CheckResult:
    """The largest surface von Mises stress of a solved plate model (:func:`mechverify.fea.plate.solve_plate`:
    membrane + bending, sigma = N/t ± 6 M/t² on each face) against the yield strength; the governing location,
    face, moments and the membrane and bending parts there are in the notes and details
    (:func:`mechverify.fea.plate_stress.governing_stress`). ``notes`` and ``warnings`` are added (e.g. the mesh
    used, a two-mesh check: :func:`plate_convergence`); ``in_plane_supports`` (those of the solve) name the singular
    ends of held edges (:func:`singular_features`); ``hole_mesh_size`` [m] (the element size at holes of the mesh
    ``res`` was solved on) judges a peak on a hole rim (:func:`rim_accuracy_warning`)."""
    from mechverify.fea.plate_stress import governing_stress

    plate = model.plate
    mx = res.max_von_mises
    sy = plate.material.require("yield_strength").to("MPa")
    node = int(mx.node)
    g = governing_stress(res, node)
    xy = g.point
    mom = [res.extra[k][node] for k in ("moment_xx_N", "moment_yy_N", "moment_xy_N")]
    t = plate.thickness_q.to("mm")
    has_membrane = bool(np.any(g.membrane))

    def comps(v: np.ndarray) -> str:
        return f"sigma_x = {v[0] / 1e6:.4g}, sigma_y = {v[1] / 1e6:.4g}, tau_xy = {v[2] / 1e6:.4g} MPa"

    there = (f"there M_xx = {mom[0]:.4g}, M_yy = {mom[1]:.4g}, M_xy = {mom[2]:.4g} N·m/m; on the {g.face} face "
             f"(z = {'+' if g.face == 'top' else '-'}t/2)")
    if has_membrane:
        parts = (f"{there}: membrane N/t {comps(g.membrane)}; bending {'+' if g.face == 'top' else '-'}6M/t^2 "
                 f"{comps(g.bending)}; total {comps(g.total)}; principal sigma_1 = {g.principal[0] / 1e6:.4g}, "
                 f"sigma_2 = {g.principal[1] / 1e6:.4g} MPa")
    else:
        parts = (f"{there} bending stresses {comps(g.total)} (no in-plane loads: the other face differs in sign "
                 "only)")
    all_notes = [f"governing location {_mm(xy)}, {nearest_feature(model, xy)}", parts,
                 *res.notes, *notes, *_load_notes(model, res)]
    MPa = [Q(float(v), "Pa").to("MPa") for v in (*g.total, *g.membrane, *g.bending)]
    return CheckResult(
        check="plate_stress_fea", component=component or plate.name, demand=mx.value.to("MPa"), capacity=sy,
        required_sf=required_sf, title="Plate stress (FEA, membrane + bending)",
        formula=r"\sigma = \frac{N}{t} \pm \frac{6 M}{t^2},\ "
                r"\sigma_{vM} = \sqrt{\sigma_x^2 - \sigma_x \sigma_y + \sigma_y^2 + 3 \tau_{xy}^2} \le S_y",
        source=f"{VM_SOURCE}; {FEA_SOURCE}",
        inputs={"t": t, "sigma_x": MPa[0], "sigma_y": MPa[1], "tau_xy": MPa[2],
                **({"sigma_m_x": MPa[3], "sigma_m_y": MPa[4], "tau_m_xy": MPa[5],
                    "sigma_b_x": MPa[6], "sigma_b_y": MPa[7], "tau_b_xy": MPa[8]} if has_membrane else {}),
                "Sy": sy, "E": plate.material.require("E").to("GPa"), "nu": plate.material.require("nu")},
        substituted=_vm_substituted(g.membrane, g.bending, mx.value),
        notes=tuple(all_notes),
        warnings=(*model.warnings(), *_singular_warning(model, res, node, in_plane_supports),
                  *rim_accuracy_warning(model, res, node, hole_mesh_size, in_plane_supports),
                  *thin_plate_hole_warning(model, res, node, in_plane_supports), *res.warnings, *warnings),
        load_case=load_case,
        details={"location": Q(xy, "m").to("mm"), "node": node, "face": g.face,
                 "membrane_stress": Q(g.membrane, "Pa").to("MPa"), "bending_stress": Q(g.bending, "Pa").to("MPa"),
                 "principal_stresses": Q(g.principal, "Pa").to("MPa")})


def _vm_substituted(membrane: np.ndarray, bending: np.ndarray, vm: Any) -> str:
    """sigma_vM = sqrt(sx^2 - sx sy + sy^2 + 3 txy^2) at the governing point and face, each component written as
    membrane + bending (N/t ± 6 M/t²) when there is a membrane part, else the (signed) bending stress alone."""
    if np.any(membrane):
        x, y, t = (rf"{tex(Q(m / 1e6, 'MPa'))} + ({tex(Q(b / 1e6, 'MPa'))})" for m, b in zip(membrane, bending))
    else:
        x, y, t = (tex(Q(v / 1e6, "MPa")) for v in bending)
    return (rf"\sigma_{{vM}} = \sqrt{{({x})^{{2}} - ({x})\cdot ({y}) + ({y})^{{2}} + 3\cdot ({t})^{{2}}}}"
            rf" = {tex(vm, 'MPa')}")


@check("plate_deflection_fea", title="Plate deflection (FEA)", sf_kind="deflection",
       aliases=("plate_fea.deflection",), source=FEA_SOURCE,
       explain=("Largest deflection of the plate (Kirchhoff plate FEA) against the limit: a length, 'L/250' or "
                "a fraction of the span (requirements.deflection_limit by default)."))
def check_plate_deflection_fea(model: pl.PlateModel, res: FieldResults, limit: Any, *, span: Any = None,
                               component: str = "", load_case: str = "", notes: Sequence[str] = ()) -> CheckResult:
    """The largest deflection of a solved plate model against ``limit`` (a length, ``"L/250"`` or a fraction
    of ``span``: where not given, the span the supports make through the point of largest deflection,
    :func:`mechverify.fea.plate_span.plate_span`; review 4 finding 30)."""
    from mechverify.fea.plate_span import plate_span

    w = res.u[:, 2]
    k = int(np.argmax(np.abs(w)))
    if span is None:
        span_m, how = plate_span(model, res.points[k, :2])
        span = Q(span_m * 1e3, "mm")
    else:
        how = f"span {fmt(Q(to_si(span, 'length', 'span'), 'm'), 'mm')}: the 'span' field"
    r = deflection_check(Q(abs(w[k]), "m"), limit, span=span, component=component or model.plate.name,
                         load_case=load_case, source=f"limit set by the design; deflection by {FEA_SOURCE}")
    return dataclasses.replace(
        r, check="plate_deflection_fea", title="Plate deflection (FEA)",
        formula=r"\delta_{max} = \max |w(x, y)| \le \delta_{lim}",
        notes=(*r.notes, f"largest deflection w = {w[k] * 1e3:.4g} mm at {_mm(res.points[k, :2])}, "
                         f"{nearest_feature(model, res.points[k, :2])}",
               f"for a fractional limit, {how}",
               *notes, *_load_notes(model, res)),
        warnings=(*r.warnings, *res.warnings), details={"location": Q(res.points[k, :2], "m").to("mm"), "node": k})


__all__ = ["check_plate_stress_roark", "check_plate_deflection_roark", "check_plate_stress_fea",
           "check_plate_deflection_fea", "nearest_feature", "describe_support", "singular_features", "singular_at",
           "peak_away", "plate_convergence", "rim_feature", "rim_accuracy_warning", "FEA_SOURCE", "VM_SOURCE"]
