"""``plate_fea``: a flat plate of any outline solved by plate FEA (parsing only; the keys are in
docs/design-files.md).

A rectangle or an ``outline`` polygon with hole groups and cut-outs (:mod:`plate_parsing`), supports on edges, points
or bolt-hole rims, and per load case lateral loads (point, patch, pressure, self-weight) and ``in_plane`` membrane
loads on the outline and on hole rims, held by ``in_plane_supports`` (:mod:`plate_in_plane`). Each load case is solved
once by :func:`mechverify.fea.plate.solve_plate` (Kirchhoff bending, Morley triangles, plus the membrane stress of
:mod:`mechverify.fea.plate_stress`) for ``plate_stress_fea`` and ``plate_deflection_fea``
(:mod:`mechverify.checks.plates`) and the figure (:mod:`mechverify.fea.plate_figure`); ``natural_frequency`` and
``buckling_load_factor`` use :mod:`mechverify.fea.plate_modal` and :mod:`mechverify.fea.plate_buckling`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from mechverify.checks import fea as feac
from mechverify.checks import plates as pc
from mechverify.checks.result import CheckResult
from mechverify.components import plates as pl
from mechverify.design.adapters import modal_parsing as mp
from mechverify.design.adapters import plate_fea_eigen as pe
from mechverify.design.adapters import plate_in_plane as ip
from mechverify.design.adapters.bolts import plate_bolt_outputs
from mechverify.design.adapters.plate_fea_eigen import REFINE
from mechverify.design.adapters.plate_geometry import parse_limit, parse_plate
from mechverify.design.adapters.plate_parsing import _loads, _supports
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
    convergence: float | None = None  # the mesh-convergence tolerance when convergence_check is on
    in_plane_supports: tuple[Any, ...] = ()  # fea.plate_stress.InPlaneSupport
    hole_groups: dict[str, list[str]] = dataclasses.field(default_factory=dict)
    tolerance: float = 0.05  # convergence_tolerance (also of the frequencies' two-mesh estimate, always made)
    solved: dict[str, tuple[pl.PlateModel, FieldResults]] = dataclasses.field(default_factory=dict)

    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> tuple[pl.PlateModel, FieldResults]:
        """The plate model and its FEA result of one load case, lateral and in-plane loads together (solved on
        first use, then cached)."""
        if case not in self.solved:
            model = self.model(loads, case, g)
            self.solved[case] = (model, self.solve_model(model, loads, case))
        return self.solved[case]

    def solve_model(self, model: pl.PlateModel, loads: Mapping[str, Any], case: str, refine: float = 1.0) -> Any:
        """:func:`mechverify.fea.plate.solve_plate` of ``model`` with the case's in-plane loads, the element sizes
        divided by ``refine``."""
        from mechverify.fea.plate import solve_plate

        try:
            return solve_plate(model, self.mesh_size, self.hole_mesh_size, self.in_plane(loads, case),
                               in_plane_supports=self.in_plane_supports, refine=refine, span=self.span)
        except MechverifyError as exc:
            if "in_plane" not in loads or "in-plane" not in str(exc):
                raise
            raise type(exc)(f"load_cases.{case}.{self.name}.in_plane: {exc}") from None

    def in_plane(self, loads: Mapping[str, Any], case: str) -> Any:
        """The case's in-plane loads (:class:`mechverify.fea.plate_buckling.InPlaneLoad`) or None."""
        if "in_plane" not in loads:
            return None
        return ip.in_plane_load(loads["in_plane"], f"load_cases.{case}.{self.name}.in_plane", self.hole_groups)

    def model(self, loads: Mapping[str, Any], case: str, g: Any) -> pl.PlateModel:
        plate_loads = _loads(loads, f"load_cases.{case}.{self.name}", self.unit, g)
        try:
            return pl.PlateModel(self.plate, self.supports, plate_loads, name=case)
        except MechverifyError as exc:
            raise InputError(f"load_cases.{case}.{self.name}.{exc}") from None


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> PlateFEA:
    name, unit = p["_name"], p["unit"]
    plate, groups = parse_plate(p, name, unit)
    supports = _supports(p, plate, groups, unit)
    try:
        pl.PlateModel(plate, supports)
    except MechverifyError as exc:
        raise InputError(f"supports: {exc}") from None
    if p["material"].nu is None:
        raise InputError(f"material: {p['material'].name!r} has no Poisson's ratio, which plate bending needs")
    limit, span = parse_limit(p, plate, ctx["requirements"].get("deflection_limit", 0.002))
    for k in ("mesh_size", "hole_mesh_size", "span"):
        if k in p and not p[k].magnitude > 0:
            raise InputError(f"{k}: must be positive, got {fmt(p[k], 'mm')}")
    tol = float(p.get("convergence_tolerance", 0.05))
    if not 0 < tol < 1:
        raise InputError(f"convergence_tolerance: a fraction between 0 and 1 (0.05 = 5 %), got {tol:g}")
    modal = mp.modal_settings(p)
    _require_memory(p, plate, modal)
    return PlateFEA(name, plate, supports, p.get("mesh_size"), p.get("hole_mesh_size"), limit, span,
                    unit, modal, tol if p.get("convergence_check") else None,
                    ip.in_plane_supports(p, plate, groups), groups, tolerance=tol)


def _require_memory(p: dict[str, Any], plate: pl.Plate, modal: mp.ModalSettings | None) -> None:
    """Refuse, before meshing, a mesh the memory cannot hold (review 4 finding 13:
    :func:`mechverify.fea.plate_memory.require_plate_memory`; its error names mesh_size or hole_mesh_size)."""
    from mechverify.fea.plate_memory import require_plate_memory

    h, hh = (None if p.get(k) is None else p[k].m_as("m") for k in ("mesh_size", "hole_mesh_size"))
    require_plate_memory(plate, h, hh, convergence=bool(p.get("convergence_check")),
                         modes=0 if modal is None else modal.modes)


# ------------------------------------------------------------------------------------------------------ checks
def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _stress(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    from mechverify.fea.plate import mesh_sizes

    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    notes, warns, held = _mesh_notes(c, res), [], c.in_plane_supports if "in_plane" in loads else ()
    h_hh = mesh_sizes(c.plate, c.mesh_size, c.hole_mesh_size)
    # the rim check measures the element size at the peak where the sizes are the defaults (one per hole)
    hh = None if c.hole_mesh_size is None else h_hh[1]
    if c.convergence is not None:  # convergence_check: the peak again on meshes REFINE and REFINE² times finer
        runs = [res, *(c.solve_model(model, loads, ctx.load_case, REFINE**k) for k in (1, 2))]
        res, more, warns = pc.plate_convergence(model, runs, REFINE, c.convergence, h_hh, held)
        hh = None if hh is None else hh / REFINE ** runs.index(res)
        notes += more
    return pc.check_plate_stress_fea(model, res, component=c.name, notes=notes, warnings=warns, in_plane_supports=held,
                                     hole_mesh_size=hh)


def _deflection(c: PlateFEA, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    model, res = c.solve(loads, ctx.load_case, _g(ctx))
    lateral = [] if model.loads else ["no lateral load in this case: in-plane loads alone deflect a plate by nothing "
                                      "in linear theory (until it buckles: buckling_load_factor)"]
    return pc.check_plate_deflection_fea(model, res, c.deflection_limit, span=c.span, component=c.name,
                                         notes=[*lateral, *_mesh_notes(c, res)])


def _mesh_notes(c: PlateFEA, res: FieldResults) -> list[str]:
    size = "shorter side / 16 (default)" if c.mesh_size is None else fmt(c.mesh_size, "mm")
    hole = ("a round hole's or rounded corner's radius / 30, at most mesh size / 3, elsewhere mesh size / 3 "
            "(default)" if c.hole_mesh_size is None else fmt(c.hole_mesh_size, "mm"))
    return [f"mesh: {len(res.surface)} Morley triangles, {res.points.shape[0]} vertices; element size {size}, "
            f"at holes and cut-outs {hole}"]


def _figures(c: PlateFEA, results: list[CheckResult]) -> list[tuple[str, Any]]:
    gov = next((r for r in results if r.check == "plate_stress_fea"), None) or next(iter(results), None)
    if gov is None or gov.load_case not in c.solved:
        return []
    from mechverify.fea.plate_figure import design_figure

    model, res = c.solved[gov.load_case]
    return [design_figure(c.name, model, c.supports, res, gov.load_case)]


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
        Field("hole_mesh_size", "length", "element size at holes and cut-outs (default: a round hole's or a cut-out "
                                          "corner's radius / 30, at most mesh_size / 3; straight sides mesh_size / 3)"),
        Field("deflection_limit", "str", "deflection limit as a length ('1 mm') or 'L/250' of the span "
                                         "(default: requirements.deflection_limit)"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the span (0.005)"),
        Field("span", "length", "span of a fractional deflection limit and of the thin-plate test (default: the "
                                "shortest clear distance between supports, or a cantilever's length, on a line "
                                "through the point of largest deflection)"),
        *mp.MODAL_FIELDS,
        Field("convergence_check", "bool", "also solve with elements 1.5x and 2.25x smaller: observed order, "
                                           "Richardson error of the peak stress and the frequencies, WARN above "
                                           "convergence_tolerance (with the mesh sizes needed, or naming a singular "
                                           "peak); the largest peak is the demand"),
        Field("convergence_tolerance", "float", "tolerance of the convergence check (and of the frequencies' "
                                                "two-mesh estimate, always made)", default=0.05),
        ip.IN_PLANE_SUPPORTS_FIELD,
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
        CheckSpec.of(feac.check_natural_frequency, pe.frequency),
        CheckSpec.of(feac.check_buckling_load_factor, pe.buckling, reads=("in_plane",)),
    ),
    outputs=plate_bolt_outputs(),  # bolt-hole support forces for bolted_joint / bolt_group (adapters/bolts.py)
    figures=_figures,
))
