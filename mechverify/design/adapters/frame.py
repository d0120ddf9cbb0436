"""``frame``: a 3D frame of straight members (:mod:`mechverify.fea.frame`): parse, solve, call the checks.

A load case with ``combination = {case = factor}`` is the factored sum of other cases; all cases and
combinations of a frame are solved on one factorisation; checks (:mod:`mechverify.checks.frames`) run
per case and the governing one is reported (the envelope). Keys: docs/design-files.md; parsing in
:mod:`.frame_parsing`.
"""

from __future__ import annotations

import contextlib
import dataclasses
from collections.abc import Iterator
from typing import Any

import numpy as np

from mechverify.checks import fea as feac
from mechverify.checks import frames as fc
from mechverify.checks import members as mc
from mechverify.checks.result import CheckResult
from mechverify.design.adapters import frame_parsing
from mechverify.design.adapters.frame_parsing import case_loads, frame_cases, items, make, parse_members, vec, where
from mechverify.design.adapters.modal_parsing import MODAL_FIELDS, ModalSettings, modal_settings
from mechverify.design.adapters.sections import SECTION_ALIASES, SECTION_DIMENSIONS, SECTION_KINDS
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError, ModelError
from mechverify.fea import frame as fe
from mechverify.fea.frame import spans
from mechverify.units import Q, fmt

FATIGUE_CRITERIA = ("goodman", "gerber", "soderberg", "asme_elliptic", "morrow")
LOADS = "point_loads|member_loads|distributed_loads|self_weight|settlements|combination"


@dataclasses.dataclass(frozen=True, eq=False)
class FrameComponent:
    """A frame as a design file declares it, with its limits and its solved load cases (one analysis)."""

    frame: fe.Frame
    deflection_limit: Any
    span: Any
    fatigue_life: float | None
    fatigue_loading: str
    fatigue_criterion: str
    fatigue_kf: float
    modal: ModalSettings | None = None
    masses: tuple[Any, ...] = ()
    solved: dict[str, fe.FrameResults] = dataclasses.field(default_factory=dict)
    modes: list[Any] = dataclasses.field(default_factory=list)
    span_given: bool = False

    def span_of(self, res: fe.FrameResults) -> tuple[Any, str]:
        """(span, how it was found) of a fractional deflection limit in one load case (:func:`spans.span_of`)."""
        return spans.span_of(self.frame, res, self.span, self.span_given)

    def results(self, ctx: Any) -> fe.FrameResults:
        """The results of ``ctx.load_case``; the first call solves every case and combination of this frame."""
        if ctx.load_case not in self.solved:
            g = ctx.requirements.get("g", Q(9.80665, "m/s**2"))
            cases, combos = frame_cases(ctx.design.data.load_cases, self.frame.name, g, ctx.load_case)
            with at_supports():
                self.solved.update(self.frame.analyse(cases, combos).results)
        return self.solved[ctx.load_case]


@contextlib.contextmanager
def at_supports() -> Iterator[None]:
    """A frame its supports leave a rigid motion (a mechanism) is one error at ``supports``, the same text from every
    analysis, instead of one per check and load case at the checks' keys (task fix23)."""
    try:
        yield
    except ModelError as exc:
        if "is not fully supported" in str(exc):
            raise InputError(f"supports: {exc}") from None
        raise


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> FrameComponent:
    nodes = {str(k): vec(v, "length", f"nodes.{k}") for k, v in p.get("nodes", {}).items()}
    sups = [make(path, fe.FrameSupport, where(t["at"], f"{path}.at"), t.get("type", "fixed"), t.get("direction", "z"),
                  tuple(t.get("hold", ())), t.get("springs", {}), t.get("one_way", {}))
            for path, t in items(p, "supports", ("at", "type", "direction", "hold", "springs", "one_way"), ("at",))]
    hinges = [make(path, fe.Hinge, where(t["at"], f"{path}.at"), t.get("axis", "z"))
              for path, t in items(p, "hinges", ("at", "axis"), ("at",))]
    springs = [make(path, fe.Spring, where(t["start"], f"{path}.start"), where(t["end"], f"{path}.end"),
                     t.get("axial"), t.get("stiffness", {}), str(t.get("name", "")))
               for path, t in items(p, "springs", ("name", "start", "end", "axial", "stiffness"), ("start", "end"))]
    members = parse_members(p, ctx) if p.get("members") else []
    frame = make(p["_name"], fe.Frame, nodes, members, sups, hinges, p["theory"], name=p["_name"], springs=springs)
    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", ctx["requirements"].get("deflection_limit", 0.002))
    span = p.get("span") or Q(_reach(frame), "m").to("mm")
    try:
        mc.deflection_limit(limit, span)
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the span: "
                         + str(exc).split(": ", 1)[-1]) from None
    life = p.get("fatigue_life")
    if life is not None and not life > 0:
        raise InputError(f"fatigue_life: a positive number of cycles, got {life!r}")
    if not p["fatigue_kf"] >= 1:
        raise InputError(f"fatigue_kf: a fatigue stress-concentration factor >= 1, got {p['fatigue_kf']!r}")
    return FrameComponent(frame, limit, span, None if life is None else float(life), p["fatigue_loading"],
                          p["fatigue_criterion"], float(p["fatigue_kf"]), modal_settings(p),
                          frame_parsing.point_masses(p), span_given=p.get("span") is not None)


def _reach(frame: fe.Frame) -> float:
    """The largest distance from a support to any member end [m] (the default span of the deflection limit)."""
    pts = [p for e in frame.ends + frame.spring_ends for p in e]
    sup = [frame.point(s.at) for s in frame.supports] or pts[:1]
    return max(float(np.linalg.norm(a - b)) for a in sup for b in pts)


# ---------------------------------------------------------------------------------------------- checks
def _deflection(c: FrameComponent, ctx: Any) -> CheckResult:
    res = c.results(ctx)
    span, how = c.span_of(res)
    r = fc.check_frame_deflection(res, c.deflection_limit, span=span, load_case=ctx.load_case, span_rule=how)
    note, warn = spans.moving_supports(c.frame, res)
    return r.replace(notes=(*r.notes, note), warnings=(*r.warnings, warn)) if warn else \
        r.replace(notes=(*r.notes, note)) if note else r




def _frequency(c: FrameComponent, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    """natural_frequency when the frame gives min_frequency or excitation_band (fea/frame/modal.py)."""
    if c.modal is None:
        return []
    if not c.modes:
        with at_supports():
            c.modes.append(c.modal.solve(fe.frame_modes, c.frame, masses=c.masses, hint=(
                "raise the members' divisions (members[i].divisions; at least 10 elements per member are used) or "
                "ask fewer modes")))
    r = c.modal.check(c.modes[0], c.frame.name)
    linearised = tuple(n for n in c.modes[0].notes if n.startswith("one-way springs"))  # review 3 finding 25
    return r.replace(notes=(*r.notes, *linearised)) if linearised else r


def _buckling(c: FrameComponent, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    """buckling_load_factor of one load case; of a combination case, the factored sum of its cases' axial forces.
    A case that puts no member in compression cannot buckle: it passes with a note and an infinite capacity, so the
    compressive cases govern the envelope (review finding 8: it was left out without a word)."""
    from mechverify.fea.frame.modal import NoCompressionError

    name, g = c.frame.name, ctx.requirements.get("g", Q(9.80665, "m/s**2"))
    try:
        with at_supports():
            if "combination" in loads:
                cases, combos = frame_cases(ctx.design.data.load_cases, name, g, ctx.load_case)
                combo = next(x for x in combos if x.name == ctx.load_case)
                res = fe.frame_buckling(c.frame, {k: cases[k] for k in combo.factors}, 1, combination=combo.factors)
            else:
                res = fe.frame_buckling(c.frame, case_loads(loads, ctx.load_case, name, g), 1)
    except NoCompressionError as exc:
        return feac.no_buckling_result(float("inf"), str(exc), component=name, load_case=ctx.load_case)
    return feac.check_buckling_load_factor(res, component=name, load_case=ctx.load_case)


def _figures(c: FrameComponent, results: list[CheckResult]) -> list[tuple[str, Any]]:
    gov = next((r for r in results if r.check == "frame_stress"), None) or next(iter(results), None)
    if gov is None or gov.load_case not in c.solved:
        return []
    res = c.solved[gov.load_case]
    mx, vm = res.max_displacement, res.max_von_mises
    caption = (f"{c.frame.name}, load case '{gov.load_case}': deformed shape (largest displacement "
               f"{fmt(mx.value, 'mm')} in {mx.member}, ★) and bending moments along the members; largest von Mises "
               f"stress {fmt(vm.value, 'MPa')} in {vm.member} at s = {vm.position.m_as('mm'):.4g} mm")
    return [(caption, res.figure())]


FRAME = REGISTRY.register(ComponentType(
    name="frame",
    doc="A 3D frame or grillage of straight members (beam FEA, Euler or Timoshenko): members with end releases, "
        "supports (springs, one-way), hinges, two-node springs; point, member, distributed (partial, trapezoidal), "
        "self-weight and settlement loads; load combinations as load cases.",
    fields=(
        Field("nodes", "table", "named points: NAME = [\"x\", \"y\", \"z\"] (lengths)"),
        Field("members", "list", "members: {name, start, end (node or [x, y, z]), section = {kind, ...} or {kind = "
              "\"properties\", area, Iy, Iz, J, Asy, Asz, c_y, c_z, Wt}, material, orientation, theory, divisions, "
              "releases_start/releases_end = \"My,Mz\" (N, Vy, Vz, T, My, Mz)}", required=True, item="table"),
        Field("supports", "list", "supports: {at, type = fixed|pinned|roller|spring|custom, direction (roller), hold "
              "(custom), springs = {z = \"2e5 N/m\"}, one_way = {z = \"+\"} (pushes along +z only)}", required=True,
              item="table"),
        Field("hinges", "list", "pin joints {at, axis = x|y|z}: member ends there (but the first) turn freely",
              item="table"),
        Field("springs", "list", "two-node springs: {name, start, end, axial = \"1e6 N/m\" or stiffness = {x = ..., "
              "rz = ...} (coincident nodes)}", item="table"),
        Field("material", "material", "default material of the members"),
        Field("section", "choice", "default section kind of the members (dimensions as for a link)",
              choices=(*SECTION_KINDS, *SECTION_ALIASES)),
        *(Field(k, "length", f"default section: {k.replace('_', ' ')}") for k in SECTION_DIMENSIONS),
        Field("theory", "choice", "beam theory", choices=fe.THEORIES, default="timoshenko"),
        Field("deflection_limit", "str", "deflection limit as a length ('1 mm') or 'L/250' of the span"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the span (0.01)"),
        Field("span", "length", "span of a fractional deflection limit (default: on a straight beam the span holding "
                                "the largest deflection, between two supports or an overhang; else the largest "
                                "support-to-end distance)"),
        Field("fatigue_life", "float", "required life in cycles for the fatigue check (default: infinite life)"),
        Field("fatigue_loading", "choice", "fully_reversed (R = -1, amplitude = peak) or zero_to_max (R = 0, "
              "amplitude = mean = peak/2)", choices=fc.FATIGUE_LOADINGS, default="zero_to_max"),
        Field("fatigue_criterion", "choice", "mean-stress criterion for zero_to_max", choices=FATIGUE_CRITERIA,
              default="goodman"),
        Field("fatigue_kf", "float", "fatigue stress-concentration factor Kf on the beam stresses", default=1.0),
        *MODAL_FIELDS,
        Field("masses", "list", "point masses for natural_frequency: {at (node or [x, y, z] on a member), mass, "
              "inertia (one value or [Ix, Iy, Iz] about global axes)}", item="table"),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("point_loads", "list", "point loads: {at (node or [x, y, z] on a member), force, moment} (global)",
              item="table"),
        Field("member_loads", "list", "loads along a member: {member, position, force, moment, axes = local|global}",
              item="table"),
        Field("distributed_loads", "list", "loads per length: {member, load = [wx, wy, wz], axes = global|local, "
              "start, end (partial), load_end (linear to it)}", item="table"),
        Field("self_weight", "bool", "add the members' weight rho A g (requirements.g, along -z)"),
        Field("settlements", "list", "enforced support displacements: {at, values = {z = \"-5 mm\"}} (held motions)",
              item="table"),
        Field("combination", "table", "this case is a factored sum of other cases: {dead = 1.35, live = 1.5}"),
    ),
    checks=(
        CheckSpec.of(fc.check_frame_stress, lambda c, loads, ctx: fc.check_frame_stress(
            c.results(ctx), required_sf=ctx.required_sf, load_case=ctx.load_case), needs=(LOADS,)),
        CheckSpec.of(fc.check_frame_deflection, lambda c, loads, ctx: _deflection(c, ctx), needs=(LOADS,)),
        CheckSpec.of(fc.check_frame_fatigue, lambda c, loads, ctx: fc.check_frame_fatigue(
            c.results(ctx), loading=c.fatigue_loading, life=c.fatigue_life, criterion=c.fatigue_criterion,
            Kf=c.fatigue_kf, required_sf=ctx.required_sf, load_case=ctx.load_case), needs=(LOADS,), default=False),
        CheckSpec.of(feac.check_natural_frequency, _frequency),
        CheckSpec.of(feac.check_buckling_load_factor, _buckling, needs=(LOADS,), default=False),
    ),
    figures=_figures,
))
