"""``plate_fea``: a flat plate of any outline solved by the FEA plate-bending model.

The plate lies in its own x-y plane (loads along z): a rectangle (``width`` x ``height``, lower-left
corner at the origin) or an ``outline`` polygon, with groups of circular ``holes`` (one diameter, a
list of centres) and ``cutouts`` (rectangles with an optional corner radius, or polygons). Points
are strings ``"x, y"``: two numbers in the component's ``unit`` (default mm) or two lengths with
units (``"12 mm, 0.1 m"``). Supports hold outline edges, points or the rims of bolt holes, fixed
(clamped: deflection and slope held) or pinned (simply supported: deflection held). Load cases give
point forces and moments, patch loads, a uniform pressure and self-weight.

The plate is solved once per load case with :func:`mechverify.fea.plate.solve_plate` (Kirchhoff,
Morley triangles) and the result is kept for both checks (:mod:`mechverify.checks.plates`) and the
report figure:

* ``plate_stress_fea`` — the largest von Mises stress at the plate surfaces (bending) against the yield
  strength, with the governing location in the notes;
* ``plate_deflection_fea`` — the largest deflection against a limit (a length, ``"L/250"`` or a fraction
  of the span: the ``span`` field, else the shorter side of the plate's bounding box).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.checks import members as mc
from mechverify.checks import plates as pc
from mechverify.checks.result import CheckResult
from mechverify.components import plates as pl
from mechverify.design.adapters.bolts import plate_bolt_outputs
from mechverify.design.adapters.plate_parsing import (  # noqa: F401  (parse_point: the bolt adapters import it here)
    _cutouts,
    _holes,
    _loads,
    _points,
    _si,
    _supports,
    parse_point,
)
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError
from mechverify.units import Q, fmt

if TYPE_CHECKING:  # the FEA layer (scipy, scikit-fem) is imported when a plate is solved
    from mechverify.fea.results import FieldResults

# --------------------------------------------------------------------------------------------- the component
@dataclasses.dataclass(frozen=True, eq=False)
class PlateFEA:
    """A plate as a design file declares it, with its supports, mesh, limits and the solved load cases."""

    name: str
    plate: pl.Plate
    supports: tuple[Any, ...]
    mesh_size: Any
    hole_mesh_size: Any
    deflection_limit: Any
    span: Any
    unit: str = "mm"
    solved: dict[str, tuple[pl.PlateModel, FieldResults]] = dataclasses.field(default_factory=dict)

    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> tuple[pl.PlateModel, FieldResults]:
        """The plate model and its FEA result of one load case (solved on first use, then cached)."""
        if case not in self.solved:
            model = self.model(loads, case, g)
            from mechverify.fea.plate import solve_plate

            self.solved[case] = (model, solve_plate(model, self.mesh_size, self.hole_mesh_size))
        return self.solved[case]

    def model(self, loads: Mapping[str, Any], case: str, g: Any) -> pl.PlateModel:
        plate_loads = _loads(loads, f"load_cases.{case}.{self.name}", self.unit, g)
        try:
            return pl.PlateModel(self.plate, self.supports, plate_loads, name=case)
        except MechverifyError as exc:
            raise InputError(f"load_cases.{case}.{self.name}.{exc}") from None


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> PlateFEA:
    name = p["_name"]
    unit = p["unit"]
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
    supports = _supports(p, plate, groups, unit)
    try:
        pl.PlateModel(plate, supports)
    except MechverifyError as exc:
        raise InputError(f"supports: {exc}") from None
    if p["material"].nu is None:
        raise InputError(f"material: {p['material'].name!r} has no Poisson's ratio, which plate bending needs")
    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", ctx["requirements"].get("deflection_limit", 0.002))
    x0, y0, x1, y1 = shell.bounds
    span = p.get("span") or Q(min(x1 - x0, y1 - y0), "m").to("mm")
    try:
        mc.deflection_limit(limit, span)
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the span: "
                         + str(exc).split(": ", 1)[-1]) from None
    for k in ("mesh_size", "hole_mesh_size", "span"):
        if k in p and not p[k].magnitude > 0:
            raise InputError(f"{k}: must be positive, got {fmt(p[k], 'mm')}")
    return PlateFEA(name, plate, supports, p.get("mesh_size"), p.get("hole_mesh_size"), limit, span,
                    unit)


# ------------------------------------------------------------------------------------------------------ checks
def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _mm(xy: Any) -> str:
    return f"({xy[0] * 1e3:.4g}, {xy[1] * 1e3:.4g}) mm"


def _stress(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    return pc.check_plate_stress_fea(model, res, component=c.name, notes=_mesh_notes(c, res))


def _deflection(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    return pc.check_plate_deflection_fea(model, res, c.deflection_limit, span=c.span, component=c.name,
                                         notes=_mesh_notes(c, res))


def _mesh_notes(c: PlateFEA, res: FieldResults) -> list[str]:
    size = "shorter side / 16 (default)" if c.mesh_size is None else fmt(c.mesh_size, "mm")
    hole = "mesh size / 3 (default)" if c.hole_mesh_size is None else fmt(c.hole_mesh_size, "mm")
    return [f"mesh: {len(res.surface)} Morley triangles, {res.points.shape[0]} vertices; element size {size}, "
            f"at holes and cut-outs {hole}"]


# ------------------------------------------------------------------------------------------------------ figure
def plate_figure(c: PlateFEA, res: FieldResults, case: str, loads: tuple[Any, ...] = ()) -> Any:
    """Von Mises contour (left) and deflection (right) on the plate, the maxima marked with a star; the
    supports in magenta and where the ``loads`` act in red (point forces as triangles, patches hatched)."""
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure
    from matplotlib.tri import Triangulation

    del plt  # the object-oriented API only: no global figure state
    x, y = res.points[:, 0] * 1e3, res.points[:, 1] * 1e3
    tri = Triangulation(x, y, res.surface)
    x0, y0, x1, y1 = c.plate.region.bounds
    wide = (x1 - x0) >= (y1 - y0)
    fig = Figure(figsize=(9.0, 3.6) if wide else (9.0, 5.0))
    axes = fig.subplots(1, 2)
    fields = ((res.von_mises.m_as("MPa"), "von Mises stress at the surfaces [MPa]", "turbo", True),
              (res.u[:, 2] * 1e3, "deflection w [mm]", "viridis", False))
    for ax, (vals, label, cmap, is_stress) in zip(axes, fields, strict=True):
        cs = ax.tripcolor(tri, vals, shading="gouraud", cmap=cmap, rasterized=True)
        k = int(np.argmax(vals if is_stress else np.abs(vals)))
        for ring in (c.plate.region.exterior, *c.plate.region.interiors):
            rx, ry = np.asarray(ring.coords).T * 1e3
            ax.plot(rx, ry, color="k", lw=0.6)
        for s in c.supports:
            _draw_support(ax, c.plate, s)
        for ld in loads:
            _draw_load(ax, ld)
        ax.plot(x[k], y[k], marker="*", color="white", mec="k", ms=14)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_title(f"max {abs(vals[k]):.3g} {'MPa' if is_stress else 'mm'} (★)", fontsize=9)
        fig.colorbar(cs, ax=ax, label=label, shrink=0.8)
    fig.suptitle(f"{c.name}, load case '{case}'", fontsize=10)
    fig.tight_layout()
    return fig


def _draw_load(ax: Any, ld: Any) -> None:
    """Where a load acts: a point force as a red triangle pointing along its sign (▼ along -z, ▲ along +z; a
    pure moment as a red circle), a patch as its hatched red outline. Uniform pressure and self-weight act
    everywhere and are named in the caption."""
    if hasattr(ld, "point"):
        f = float(getattr(ld, "force", 0.0) or 0.0)
        marker = "v" if f < 0 else "^" if f > 0 else "o"
        ax.plot(ld.point[0] * 1e3, ld.point[1] * 1e3, marker=marker, color="red", mec="k", ms=9, zorder=5)
    elif getattr(ld, "polygon", None) is not None:
        from matplotlib.patches import Polygon as MplPolygon

        pts = np.asarray(ld.polygon) * 1e3
        ax.add_patch(MplPolygon(pts, closed=True, fill=False, edgecolor="red", hatch="////", lw=1.2, zorder=5))


def _loads_text(loads: tuple[Any, ...]) -> str:
    """The caption's words for the loads: what is drawn and what acts over the whole plate."""
    drawn = [ld for ld in loads if hasattr(ld, "point") or getattr(ld, "polygon", None) is not None]
    spread = [type(ld).__name__ for ld in loads if ld not in drawn]
    parts = []
    if drawn:
        parts.append("loads in red (▼ force along -z, ▲ along +z, ● moment only, hatched: patch load)")
    if any("Pressure" in n for n in spread):
        parts.append("uniform pressure over the whole plate")
    if any("Weight" in n for n in spread):
        parts.append("self-weight")
    return "; ".join(parts)


def _draw_support(ax: Any, plate: pl.Plate, s: Any) -> None:
    style = {"color": "magenta", "lw": 2.5 if s.condition == "clamped" else 1.5,
             "ls": "-" if s.condition == "clamped" else "--"}
    if isinstance(s, pl.EdgeSupport):
        edges = plate.edges()
        for i in s.edge_indices(plate):
            (ax_, ay), (bx, by) = edges[i]
            ax.plot([ax_ * 1e3, bx * 1e3], [ay * 1e3, by * 1e3], **style)
    elif isinstance(s, pl.PointSupport):
        ax.plot(s.point[0] * 1e3, s.point[1] * 1e3, marker="^", color="magenta", mec="k", ms=8)
    else:
        for h in s.resolve(plate):
            r = (s.washer_diameter or h.diameter) / 2
            th = np.linspace(0, 2 * np.pi, 49)
            ax.plot((h.center[0] + r * np.cos(th)) * 1e3, (h.center[1] + r * np.sin(th)) * 1e3, **style)


def _figures(c: PlateFEA, results: list[CheckResult]) -> list[tuple[str, Any]]:
    gov = next((r for r in results if r.check == "plate_stress_fea"), None) or next(iter(results), None)
    if gov is None or gov.load_case not in c.solved:
        return []
    model, res = c.solved[gov.load_case]
    vm, k = res.max_von_mises, int(res.max_von_mises.node)
    loads = tuple(getattr(model, "loads", ()) or ())
    caption = (f"{c.name}, load case '{gov.load_case}': von Mises stress at the plate surfaces (largest "
               f"{fmt(vm.value, 'MPa')} at {_mm(res.points[k, :2])}, ★) and deflection (largest "
               f"{fmt(res.max_displacement.value, 'mm')}); supports in magenta (solid: fixed, dashed: pinned)")
    if _loads_text(loads):
        caption += f"; {_loads_text(loads)}"
    return [(caption, plate_figure(c, res, gov.load_case, loads))]


PLATE_FEA = REGISTRY.register(ComponentType(
    name="plate_fea",
    doc="A flat plate of any outline (rectangle or polygon) with bolt holes and cut-outs, solved by plate-bending "
        "FEA (Kirchhoff, Morley triangles): supports on edges, points or hole rims (fixed or pinned); point "
        "forces and moments, patch loads, pressure and self-weight per load case.",
    fields=(
        Field("width", "length", "side along x of a rectangular plate (lower-left corner at the origin)"),
        Field("height", "length", "side along y of a rectangular plate"),
        Field("outline", "list", "outline polygon instead of width/height: points \"x, y\" (edge i runs from point i "
                                 "to point i+1)", item="str"),
        Field("unit", "str", "unit of bare numbers in points \"x, y\"", default="mm"),
        Field("thickness", "length", "plate thickness", required=True),
        Field("material", "material", "plate material (E, nu, yield strength; density for self-weight)",
              required=True),
        Field("holes", "list", "hole groups: {name, diameter, centers = [\"x, y\", ...]}; the holes of a group of "
                               "several are named <name>_1, <name>_2, ...", item="table"),
        Field("cutouts", "list", "cut-outs: {center = \"x, y\", size = \"dx, dy\", corner_radius} (a rectangle) or "
                                 "{polygon = [\"x, y\", ...]}", item="table"),
        Field("supports", "list", "supports: {edges = \"all\" | [indices or bottom/right/top/left] | point = \"x, y\" "
                                  "| holes = \"all\" | [group or hole names], type = fixed | pinned, "
                                  "washer_diameter}", required=True, item="table"),
        Field("mesh_size", "length", "element size (default: shorter side / 16)"),
        Field("hole_mesh_size", "length", "element size at holes and cut-outs (default: mesh_size / 3)"),
        Field("deflection_limit", "str", "deflection limit as a length ('1 mm') or 'L/250' of the span "
                                         "(default: requirements.deflection_limit)"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the span (0.005)"),
        Field("span", "length", "span of a fractional deflection limit (default: the shorter side of the plate)"),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("point_loads", "list", "concentrated loads: {at = \"x, y\", force (along +z), moment_x, moment_y}",
              item="table"),
        Field("patch_loads", "list", "loads spread over a patch: {center = \"x, y\", size = \"dx, dy\" | polygon = "
                                     "[points], force (total) | pressure} (along +z)", item="table"),
        Field("pressure", "pressure", "uniform pressure over the whole plate (along +z)"),
        Field("self_weight", "bool", "add the plate's weight rho g t (requirements.g) along -z"),
    ),
    checks=(
        CheckSpec.of(pc.check_plate_stress_fea, lambda c, loads, ctx: _stress(c, loads, ctx),
                     needs=("point_loads|patch_loads|pressure|self_weight",)),
        CheckSpec.of(pc.check_plate_deflection_fea, lambda c, loads, ctx: _deflection(c, loads, ctx),
                     needs=("point_loads|patch_loads|pressure|self_weight",)),
    ),
    outputs=plate_bolt_outputs(),  # bolt-hole support forces for bolted_joint / bolt_group (adapters/bolts.py)
    figures=_figures,
))
