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
report figure (:mod:`mechverify.fea.plate_figure`):

* ``plate_stress_fea`` — the largest von Mises stress at the plate surfaces (bending) against the yield
  strength, with the governing location in the notes;
* ``plate_deflection_fea`` — the largest deflection against a limit (a length, ``"L/250"`` or a fraction
  of the span: the ``span`` field, else the shorter side of the plate's bounding box);
* ``natural_frequency`` (with ``min_frequency`` or ``excitation_band``) and ``buckling_load_factor`` (load cases
  with ``in_plane`` edge loads: :func:`mechverify.fea.plate_buckling.plate_buckling` on the same mesh).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.checks import fea as feac
from mechverify.checks import members as mc
from mechverify.checks import plates as pc
from mechverify.checks.result import CheckResult
from mechverify.components import plates as pl
from mechverify.design.adapters import modal_parsing as mp
from mechverify.design.adapters.bolts import plate_bolt_outputs
from mechverify.design.adapters.plate_parsing import _cutouts, _holes, _loads, _points, _si, _supports
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
    modal: mp.ModalSettings | None = None
    convergence: float | None = None  # the two-mesh check's tolerance when convergence_check is on
    solved: dict[str, tuple[pl.PlateModel, FieldResults]] = dataclasses.field(default_factory=dict)

    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> tuple[pl.PlateModel, FieldResults]:
        """The plate model and its FEA result of one load case, lateral and in-plane loads together (solved on
        first use, then cached)."""
        if case not in self.solved:
            model = self.model(loads, case, g)
            from mechverify.fea.plate import solve_plate

            self.solved[case] = (model, solve_plate(model, self.mesh_size, self.hole_mesh_size,
                                                    self.in_plane(loads, case)))
        return self.solved[case]

    def in_plane(self, loads: Mapping[str, Any], case: str) -> Any:
        """The case's in-plane edge loads (:class:`mechverify.fea.plate_buckling.InPlaneLoad`) or None."""
        if "in_plane" not in loads:
            return None
        return mp.in_plane_load(loads["in_plane"], f"load_cases.{case}.{self.name}.in_plane")

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
    tol = float(p.get("convergence_tolerance", 0.05))
    if not 0 < tol < 1:
        raise InputError(f"convergence_tolerance: a fraction between 0 and 1 (0.05 = 5 %), got {tol:g}")
    return PlateFEA(name, plate, supports, p.get("mesh_size"), p.get("hole_mesh_size"), limit, span,
                    unit, mp.modal_settings(p), tol if p.get("convergence_check") else None)


# ------------------------------------------------------------------------------------------------------ checks
def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _mm(xy: Any) -> str:
    return f"({xy[0] * 1e3:.4g}, {xy[1] * 1e3:.4g}) mm"


#: The two-mesh check's second mesh has elements this many times smaller (as solid_fea's).
REFINE = 1.5


def _stress(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    notes, warns = _mesh_notes(c, res), []
    if c.convergence is not None:  # convergence_check: the peak again on a mesh REFINE times finer
        from mechverify.fea.plate import solve_plate

        x0, y0, x1, y1 = c.plate.region.bounds
        h = min(x1 - x0, y1 - y0) / 16 if c.mesh_size is None else c.mesh_size.m_as("m")
        hh = h / 3 if c.hole_mesh_size is None else c.hole_mesh_size.m_as("m")
        fine = solve_plate(model, Q(h / REFINE, "m"), Q(hh / REFINE, "m"), c.in_plane(loads, ctx.load_case))
        res, more, warns = pc.plate_convergence(model, res, fine, REFINE, c.convergence, (h, hh))
        notes += more
    return pc.check_plate_stress_fea(model, res, component=c.name, notes=notes, warnings=warns)


def _deflection(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    lateral = [] if model.loads else ["no lateral load in this case: in-plane loads alone deflect a plate by nothing "
                                      "in linear theory (until it buckles: buckling_load_factor)"]
    return pc.check_plate_deflection_fea(model, res, c.deflection_limit, span=c.span, component=c.name,
                                         notes=[*lateral, *_mesh_notes(c, res)])


def _frequency(c: PlateFEA, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    if c.modal is None:  # natural_frequency runs when min_frequency or excitation_band is given
        return []
    from mechverify.fea.plate_modal import plate_modes

    res = c.modal.solve(plate_modes, pl.PlateModel(c.plate, c.supports), c.mesh_size, c.hole_mesh_size,
                        hint="lower mesh_size (finer mesh) or ask fewer modes")
    return c.modal.check(res, c.name)


def _buckling(c: PlateFEA, loads: Any, ctx: Any) -> list[CheckResult]:
    """buckling_load_factor of every load case that gives in_plane edge loads (lateral loads cause no membrane
    force); none: the check does not run. A case whose in-plane load compresses nothing passes with a note."""
    from mechverify.fea.frame.modal import NoCompressionError
    from mechverify.fea.plate_buckling import plate_buckling

    out = []
    for case, comps in ctx.design.data.load_cases.items():
        if "in_plane" in (comps.get(c.name) or {}):
            path = f"load_cases.{case}.{c.name}.in_plane"
            load = mp.in_plane_load(comps[c.name]["in_plane"], path)
            try:
                res = plate_buckling(pl.PlateModel(c.plate, c.supports), load, 3, c.mesh_size, c.hole_mesh_size)
            except NoCompressionError as exc:  # a pull: the envelope is governed by the compressive cases
                out.append(feac.no_buckling_result(float("inf"), str(exc), component=c.name, load_case=case))
                continue
            except MechverifyError as exc:
                raise type(exc)(f"{path}: {exc}") from None
            out.append(feac.check_buckling_load_factor(res, component=c.name, load_case=case))
    return out


def _mesh_notes(c: PlateFEA, res: FieldResults) -> list[str]:
    size = "shorter side / 16 (default)" if c.mesh_size is None else fmt(c.mesh_size, "mm")
    hole = "mesh size / 3 (default)" if c.hole_mesh_size is None else fmt(c.hole_mesh_size, "mm")
    return [f"mesh: {len(res.surface)} Morley triangles, {res.points.shape[0]} vertices; element size {size}, "
            f"at holes and cut-outs {hole}"]


def _figures(c: PlateFEA, results: list[CheckResult]) -> list[tuple[str, Any]]:
    gov = next((r for r in results if r.check == "plate_stress_fea"), None) or next(iter(results), None)
    if gov is None or gov.load_case not in c.solved:
        return []
    from mechverify.fea.plate_figure import loads_caption, plate_figure

    model, res = c.solved[gov.load_case]
    vm, k = res.max_von_mises, int(res.max_von_mises.node)
    loads = tuple(getattr(model, "loads", ()) or ())
    caption = (f"{c.name}, load case '{gov.load_case}': von Mises stress at the plate surfaces (largest "
               f"{fmt(vm.value, 'MPa')} at {_mm(res.points[k, :2])}, ★) and deflection (largest "
               f"{fmt(res.max_displacement.value, 'mm')}); supports in magenta (solid: fixed, dashed: pinned)")
    if loads_caption(loads):
        caption += f"; {loads_caption(loads)}"
    return [(caption, plate_figure(c.plate, c.supports, res, f"{c.name}, load case '{gov.load_case}'", loads))]


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
        *mp.MODAL_FIELDS,
        Field("convergence_check", "bool", "also solve at mesh_size / 1.5 and hole_mesh_size / 1.5 and WARN when the "
                                           "peak stress changes more than convergence_tolerance (with the mesh sizes "
                                           "needed, or naming a singular peak); the larger peak is the demand"),
        Field("convergence_tolerance", "float", "tolerance of the two-mesh check", default=0.05),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("point_loads", "list", "concentrated loads: {at = \"x, y\", force (along +z), moment_x, moment_y}",
              item="table"),
        Field("patch_loads", "list", "loads spread over a patch: {center = \"x, y\", size = \"dx, dy\" | polygon = "
                                     "[points], force (total) | pressure} (along +z)", item="table"),
        Field("pressure", "pressure", "uniform pressure over the whole plate (along +z)"),
        Field("self_weight", "bool", "add the plate's weight rho g t (requirements.g) along -z"),
        mp.IN_PLANE_FIELD,
    ),
    checks=(
        CheckSpec.of(pc.check_plate_stress_fea, lambda c, loads, ctx: _stress(c, loads, ctx),
                     needs=("point_loads|patch_loads|pressure|self_weight|in_plane",)),
        CheckSpec.of(pc.check_plate_deflection_fea, lambda c, loads, ctx: _deflection(c, loads, ctx),
                     needs=("point_loads|patch_loads|pressure|self_weight|in_plane",)),
        CheckSpec.of(feac.check_natural_frequency, _frequency),
        CheckSpec.of(feac.check_buckling_load_factor, _buckling),
    ),
    outputs=plate_bolt_outputs(),  # bolt-hole support forces for bolted_joint / bolt_group (adapters/bolts.py)
    figures=_figures,
))
