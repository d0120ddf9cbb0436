"""``frame``: a 3D frame or grillage of straight members solved by :mod:`mechverify.fea.frame`.

Members are declared by their end points (node names or coordinates), each with a section (the
component's default section, or its own table) and a material; supports (fixed, pinned, roller,
spring, custom) and hinges at nodes or points. Load cases give point loads, uniform loads on members
and self-weight. Checks: the largest von Mises stress at the section fibres against the yield strength
of the member where it occurs, the largest deflection against a limit, and (off by default) fatigue
at every point along the members against the material's S-N curve, with the loading stated (fully
reversed, or zero to max with a mean-stress criterion). The report shows the deformed shape and the
moment diagrams of the governing load case.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.checks import members as mc
from mechverify.checks.fatigue import fatigue_field_check
from mechverify.checks.result import CheckResult
from mechverify.components.sections import Section
from mechverify.design.adapters.common import inline_table
from mechverify.design.adapters.members import SECTION_ALIASES, SECTION_DIMENSIONS, SECTION_KINDS, build_section
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError
from mechverify.fea.frame import (  # the solver itself (scipy) is imported in _build, when a frame is built
    THEORIES,
    DistributedLoad,
    FrameResults,
    Hinge,
    Member,
    PointLoad,
    SelfWeight,
    Support,
)
from mechverify.materials.material import Material
from mechverify.units import Q, as_quantity, fmt

if TYPE_CHECKING:
    from mechverify.fea.frame import Frame

FATIGUE_LOADINGS = ("fully_reversed", "zero_to_max")
FATIGUE_CRITERIA = ("goodman", "gerber", "soderberg", "asme_elliptic", "morrow")
VM_SOURCE = ("Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., Eq. 5-15 (von Mises of a beam "
             "fibre); member forces by the exact 3D beam element (Przemieniecki 1968, Sec. 5.6)")


@dataclasses.dataclass(frozen=True, eq=False)
class FrameComponent:
    """A frame as a design file declares it, with its limits and a cache of solved load cases."""

    frame: Frame
    deflection_limit: Any
    span: Any
    fatigue_life: float | None
    fatigue_loading: str
    fatigue_criterion: str
    fatigue_kf: float
    solved: dict[str, FrameResults] = dataclasses.field(default_factory=dict)

    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> FrameResults:
        if case in self.solved:
            return self.solved[case]
        res = self.frame.solve(_loads(loads, case, self.frame.name, g), name=case)
        self.solved[case] = res
        return res


# --------------------------------------------------------------------------------------------- parsing
def _where(v: Any, path: str) -> Any:
    if isinstance(v, str):
        return v
    if isinstance(v, list) and len(v) == 3:
        return [as_quantity(c, "length", f"{path}[{i}]") for i, c in enumerate(v)]
    raise InputError(f"{path}: expected a node name or three lengths [x, y, z], got {v!r}")


def _vec(v: Any, dim: str, path: str) -> list[Any]:
    if not isinstance(v, list) or len(v) != 3:
        raise InputError(f"{path}: expected three components [x, y, z] with units, got {v!r}")
    return [as_quantity(c, dim, f"{path}[{i}]") for i, c in enumerate(v)]


def _section_table(t: Any, path: str) -> Section:
    t = inline_table(t, path, ("kind", *SECTION_DIMENSIONS), ("kind",))
    kind = t["kind"]
    if kind not in (*SECTION_KINDS, *SECTION_ALIASES):
        raise InputError(f"{path}.kind: expected one of {', '.join(SECTION_KINDS)}, got {kind!r}")
    p = {"section": kind, **{k: as_quantity(v, "length", f"{path}.{k}") for k, v in t.items() if k != "kind"}}
    try:
        return build_section(p)
    except MechverifyError as exc:
        raise InputError(f"{path}.{exc}") from None


def _members(p: dict[str, Any], ctx: dict[str, Any]) -> list[Member]:
    default_section = None
    if "section" in p:
        try:
            default_section = build_section(p)
        except MechverifyError as exc:
            raise InputError(str(exc)) from None
    out = []
    for i, t in enumerate(p["members"]):
        path = f"members[{i}]"
        t = inline_table(t, path, ("name", "start", "end", "section", "material", "orientation", "theory", "divisions"),
                   ("start", "end"))
        if "section" in t:
            sec = _section_table(t["section"], f"{path}.section")
        elif default_section is not None:
            sec = default_section
        else:
            raise InputError(f"{path}.section: missing, and the frame gives no default section (section = ...)")
        mat: Any = p.get("material")
        if "material" in t:
            try:
                mat = ctx["materials"].get(t["material"])
            except MechverifyError as exc:
                raise InputError(f"{path}.material: {exc}") from None
        if mat is None:
            raise InputError(f"{path}.material: missing, and the frame gives no default material")
        theory = t.get("theory")
        if theory is not None and theory not in THEORIES:
            raise InputError(f"{path}.theory: expected one of {', '.join(THEORIES)}, got {theory!r}")
        orient = t.get("orientation")
        if orient is not None and (not isinstance(orient, list) or len(orient) != 3
                                   or not all(isinstance(c, int | float) for c in orient)):
            raise InputError(f"{path}.orientation: expected three numbers (a direction), got {orient!r}")
        div = t.get("divisions", 1)
        if not isinstance(div, int) or isinstance(div, bool) or div < 1:
            raise InputError(f"{path}.divisions: expected a whole number >= 1, got {div!r}")
        try:
            out.append(Member(_where(t["start"], f"{path}.start"), _where(t["end"], f"{path}.end"), sec, mat,
                              str(t.get("name", f"M{i + 1}")), orient, theory, div))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    return out


def _supports(p: dict[str, Any]) -> list[Support]:
    out = []
    for i, t in enumerate(p.get("supports", [])):
        path = f"supports[{i}]"
        t = inline_table(t, path, ("at", "type", "direction", "hold", "springs"), ("at",))
        kind = t.get("type", "fixed")
        springs = t.get("springs", {})
        if not isinstance(springs, dict):
            raise InputError(f"{path}.springs: expected a table {{z = \"2e5 N/m\", rx = \"10 N*m/rad\"}}")
        try:
            out.append(Support(_where(t["at"], f"{path}.at"), kind, t.get("direction", "z"), tuple(t.get("hold", ())),
                               springs))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    return out


def _hinges(p: dict[str, Any]) -> list[Hinge]:
    out = []
    for i, t in enumerate(p.get("hinges", [])):
        path = f"hinges[{i}]"
        t = inline_table(t, path, ("at", "axis"), ("at",))
        try:
            out.append(Hinge(_where(t["at"], f"{path}.at"), t.get("axis", "z")))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    return out


def _loads(loads: Mapping[str, Any], case: str, comp: str, g: Any) -> list[Any]:
    base = f"load_cases.{case}.{comp}"
    out: list[Any] = []
    for i, t in enumerate(loads.get("point_loads", [])):
        path = f"{base}.point_loads[{i}]"
        t = inline_table(t, path, ("at", "force", "moment"), ("at",))
        if "force" not in t and "moment" not in t:
            raise InputError(f"{path}: give force and/or moment")
        out.append(PointLoad(_where(t["at"], f"{path}.at"),
                             _vec(t["force"], "force", f"{path}.force") if "force" in t else None,
                             _vec(t["moment"], "torque", f"{path}.moment") if "moment" in t else None))
    for i, t in enumerate(loads.get("distributed_loads", [])):
        path = f"{base}.distributed_loads[{i}]"
        t = inline_table(t, path, ("member", "load", "axes"), ("member", "load"))
        try:
            out.append(DistributedLoad(str(t["member"]), _vec(t["load"], "force_per_length", f"{path}.load"),
                                       t.get("axes", "global")))
        except MechverifyError as exc:
            raise InputError(f"{path}: {exc}") from None
    if loads.get("self_weight"):
        out.append(SelfWeight(g))
    return out


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> FrameComponent:
    name = p["_name"]
    nodes = p.get("nodes", {})
    parsed_nodes = {str(k): _vec(v, "length", f"nodes.{k}") for k, v in nodes.items()}
    members = _members(p, ctx)
    from mechverify.fea.frame import Frame

    try:
        frame = Frame(parsed_nodes, members, _supports(p), _hinges(p), p["theory"], name=name)
    except MechverifyError as exc:
        raise InputError(str(exc)) from None
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
                          p["fatigue_criterion"], float(p["fatigue_kf"]))


def _reach(frame: Frame) -> float:
    """The largest distance from a support to any member end [m] (the default span of the deflection limit)."""
    sup = [frame.point(s.at) for s in frame.supports] or [frame.ends[0][0]]
    pts = [p for e in frame.ends for p in e]
    return max(float(np.linalg.norm(a - b)) for a in sup for b in pts)


# ---------------------------------------------------------------------------------------------- checks
def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _where_text(e: Any) -> str:
    loc = ", ".join(f"{c:.4g}" for c in e.location.m_as("mm"))
    return f"member {e.member} at s = {e.position.m_as('mm'):.4g} mm from its start, point ({loc}) mm"


def _stress(c: FrameComponent, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    res = c.solve(loads, ctx.load_case, _g(ctx))
    best = None
    for d in res.diagrams():
        m = c.frame.members[c.frame.member_index[d.member]]
        Sy = m.material.require("yield_strength")
        vm = d.von_mises.m_as("MPa")
        i, j = np.unravel_index(int(np.argmax(vm)), vm.shape)
        n = Sy.m_as("MPa") / vm[i, j] if vm[i, j] > 0 else math.inf
        if best is None or n < best[0]:
            best = (n, d, int(i), int(j), m)
    assert best is not None
    _, d, i, j, m = best
    sec = m.section
    fib = d.fibres[j].m_as("mm")
    loc = ", ".join(f"{v:.4g}" for v in d.points[i].m_as("mm"))
    notes = [f"at member {d.member}, s = {d.s[i].m_as('mm'):.4g} mm from its start, point ({loc}) mm",
             f"governing fibre (y, z) = ({fib[0]:.3g}, {fib[1]:.3g}) mm from the centroid, section {sec.kind}, "
             f"material {m.material.name}",
             f"there N = {d.N[i].m_as('N'):.4g} N, M_y = {d.My[i].m_as('N*m'):.4g} N·m, "
             f"M_z = {d.Mz[i].m_as('N*m'):.4g} N·m, T = {d.T[i].m_as('N*m'):.4g} N·m, "
             f"V = ({d.Vy[i].m_as('N'):.4g}, {d.Vz[i].m_as('N'):.4g}) N",
             "tau = |T|/W_t + |V|/A_s taken at the same fibre (conservative: the transverse shear is zero at the "
             "extreme fibres of solid sections)",
             f"{c.frame.theory} beam elements; loads at the centroidal axis; stress raisers at joints and holes are "
             "not in a beam model"]
    return CheckResult(
        check="frame_stress", component=c.frame.name, demand=Q(float(d.von_mises[i, j].m_as("MPa")), "MPa"),
        capacity=m.material.require("yield_strength").to("MPa"), title="Frame member stress (von Mises)",
        formula=r"\sigma_{vM} = \sqrt{\left(\frac{N}{A} + \frac{M_y z}{I_y} - \frac{M_z y}{I_z}\right)^2"
                r" + 3\left(\frac{|T|}{W_t} + \frac{|V|}{A_s}\right)^2} \le S_y",
        source=VM_SOURCE,
        inputs={"N": d.N[i].to("N"), "My": d.My[i].to("N*m"), "Mz": d.Mz[i].to("N*m"), "T": d.T[i].to("N*m"),
                "sigma": d.normal_stress[i, j].to("MPa"), "tau": d.shear_stress[i].to("MPa"),
                "Sy": m.material.require("yield_strength").to("MPa")},
        notes=tuple(notes), details={"member": d.member, "position": d.s[i], "location": d.points[i]})


def _deflection(c: FrameComponent, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    res = c.solve(loads, ctx.load_case, _g(ctx))
    mx = res.max_displacement
    r = mc.deflection_check(mx.value, c.deflection_limit, span=c.span, component=c.frame.name,
                            source="limit set by the design; deflection by the exact 3D beam element")
    u = res.diagram(mx.member).displacement
    k = int(np.argmin(np.abs(res.diagram(mx.member).s.m_as("mm") - mx.position.m_as("mm"))))
    comps = ", ".join(f"{v:.4g}" for v in u[k].m_as("mm"))
    return dataclasses.replace(
        r, check="frame_deflection", title="Frame deflection",
        formula=r"\delta_{max} = \max |\mathbf{u}(s)| \le \delta_{lim}",
        notes=(*r.notes, f"largest translation (magnitude, components ({comps}) mm) at {_where_text(mx)}",
               "span for a fractional limit: the 'span' field, else the largest distance from a support to a "
               "member end"))


def _fatigue(c: FrameComponent, loads: Mapping[str, Any], ctx: Any) -> CheckResult:
    res = c.solve(loads, ctx.load_case, _g(ctx))
    groups: dict[str, tuple[Material, list[np.ndarray], list[np.ndarray]]] = {}
    for d in res.diagrams():
        m = c.frame.members[c.frame.member_index[d.member]]
        g = groups.setdefault(m.material.name, (m.material, [], []))
        g[1].append(np.max(d.von_mises.m_as("Pa"), axis=1))
        g[2].append(d.points.m_as("m"))
    worst = None
    for mat, vms, pts in groups.values():
        vm = np.concatenate(vms)
        xyz = np.vstack(pts)
        if c.fatigue_loading == "fully_reversed":
            sa, sm = vm, np.zeros_like(vm)
        else:
            sa = sm = vm / 2
        r = fatigue_field_check(c.frame.name, Q(sa, "Pa"), Q(sm, "Pa"), mat, coordinates=Q(xyz, "m"),
                                life=c.fatigue_life, criterion=c.fatigue_criterion, Kf=c.fatigue_kf,
                                required_sf=ctx.required_sf)
        if worst is None or r.factored_utilisation > worst.factored_utilisation:
            worst = r
    assert worst is not None
    how = ("fully reversed (R = -1): amplitude = the peak von Mises stress, no mean stress" if
           c.fatigue_loading == "fully_reversed" else
           f"zero to max (R = 0): amplitude = mean = half the peak von Mises stress, {c.fatigue_criterion} "
           "mean-stress criterion")
    return dataclasses.replace(worst, check="frame_fatigue", title="Frame fatigue",
                               notes=(*worst.notes, f"loading {how}", "stress at each point along the members: the "
                                      "largest fibre von Mises stress of the load case (Kf = "
                                      f"{c.fatigue_kf:g}; joints, holes and surface finish not modelled)"))


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
    doc="A 3D frame or grillage of straight members (beam FEA: axial, biaxial bending with Euler or Timoshenko "
        "theory, torsion): members by their end points with a section and material, supports and hinges at nodes "
        "or points; point, distributed and self-weight loads per load case.",
    fields=(
        Field("nodes", "table", "named points: NAME = [\"x\", \"y\", \"z\"] (lengths)"),
        Field("members", "list", "members: {name, start, end (node names or [x, y, z]), section = {kind, ...}, "
                                 "material, orientation = [x, y, z] (a direction in the local x-z plane), theory, "
                                 "divisions}", required=True, item="table"),
        Field("supports", "list", "supports: {at (node or [x, y, z]), type = fixed|pinned|roller|spring|custom, "
                                  "direction (roller: x|y|z), hold = [\"x\", \"rz\", ...] (custom), "
                                  "springs = {z = \"2e5 N/m\", rx = \"10 N*m/rad\"}}", required=True, item="table"),
        Field("hinges", "list", "pin joints: {at, axis = x|y|z}: the members there turn freely about the axis",
              item="table"),
        Field("material", "material", "default material of the members"),
        Field("section", "choice", "default section kind of the members (dimensions as for a link)",
              choices=(*SECTION_KINDS, *SECTION_ALIASES)),
        *(Field(k, "length", f"default section: {k.replace('_', ' ')}") for k in SECTION_DIMENSIONS),
        Field("theory", "choice", "beam theory", choices=THEORIES, default="timoshenko"),
        Field("deflection_limit", "str", "deflection limit as a length ('1 mm') or 'L/250' of the span"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the span (0.01)"),
        Field("span", "length", "span of a fractional deflection limit (default: the largest distance from a support "
                                "to a member end)"),
        Field("fatigue_life", "float", "required life in cycles for the fatigue check (default: infinite life)"),
        Field("fatigue_loading", "choice", "fully_reversed (R = -1, amplitude = peak) or zero_to_max (R = 0, "
                                           "amplitude = mean = peak/2)", choices=FATIGUE_LOADINGS,
              default="zero_to_max"),
        Field("fatigue_criterion", "choice", "mean-stress criterion for zero_to_max", choices=FATIGUE_CRITERIA,
              default="goodman"),
        Field("fatigue_kf", "float", "fatigue stress-concentration factor Kf applied to the beam stresses",
              default=1.0),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("point_loads", "list", "point loads: {at (node or [x, y, z] on a member), force = [Fx, Fy, Fz], "
                                     "moment = [Mx, My, Mz]} (global axes)", item="table"),
        Field("distributed_loads", "list", "uniform loads: {member, load = [wx, wy, wz] per length, axes = "
                                           "global|local}", item="table"),
        Field("self_weight", "bool", "add the members' weight rho A g (requirements.g, along -z)"),
    ),
    checks=(
        CheckSpec("stress", lambda c, loads, ctx: _stress(c, loads, ctx), "Frame member stress",
                  needs=("point_loads|distributed_loads|self_weight",), sf_kind="static",
                  explain="Largest von Mises stress sqrt(sigma^2 + 3 tau^2) over the section fibres along every "
                          "member (sigma from N and biaxial bending, tau = |T|/W_t + |V|/A_s) against the yield "
                          "strength of that member's material; Shigley 10th ed. Eq. 5-15."),
        CheckSpec("deflection", lambda c, loads, ctx: _deflection(c, loads, ctx), "Frame deflection",
                  needs=("point_loads|distributed_loads|self_weight",), sf_kind="deflection",
                  explain="Largest translation anywhere along the members against the limit (a length, 'L/250' or "
                          "a fraction of the span; requirements.deflection_limit by default)."),
        CheckSpec("fatigue", lambda c, loads, ctx: _fatigue(c, loads, ctx), "Frame fatigue",
                  needs=("point_loads|distributed_loads|self_weight",), sf_kind="fatigue", default=False,
                  explain="Every point along the members: amplitude and mean of the fibre von Mises stress for the "
                          "stated loading (fully reversed, or zero to max with Goodman etc.) against the material's "
                          "S-N curve at fatigue_life (or its endurance estimate), Langer yield included; "
                          "mechverify.checks.fatigue, Shigley 10th ed. Sec. 6-12."),
    ),
    figures=_figures,
))
