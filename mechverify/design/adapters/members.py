"""``link``: a structural member between two pins, with its closed-form checks.

* ``link`` — a straight member between two pin holes, or a bar with end conditions
  (:class:`~mechverify.components.links.Link`): body section by kind and dimensions (flat keys),
  material, optional pin eye (lug) and pin, end condition (buckling and beam case), optional
  print-orientation knock-down. Loads per case: axial force, bending moments, a transverse point or
  distributed load (Shigley Table A-9 case picked from the end condition), torsion, pin force.

(The Roark ``plate`` type is in :mod:`mechverify.design.adapters.plates`; section parsing, shared with
``frame``, in :mod:`mechverify.design.adapters.sections`.)

The checks are those of :mod:`mechverify.checks.members`, the section forces those of
:mod:`mechverify.components.links`; this module only maps design-file values onto them and adds plot
data (beam diagram, column curve) to the results.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import pint

from mechverify.checks import members as mc
from mechverify.checks.result import CheckResult
from mechverify.components.links import (
    BEAM_SUPPORT,
    Link,
    Lug,
    beam_case,
    link_pin_force,
    link_section_forces,
    link_transverse_case,
)
from mechverify.design.adapters.sections import (  # noqa: F401  (frame imports them from here)
    SECTION_ALIASES,
    SECTION_DIMENSIONS,
    SECTION_KINDS,
    build_section,
    why,
)
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError, MechverifyError
from mechverify.materials import Material
from mechverify.units import Q, fmt, to_si


# ------------------------------------------------------------------------------------------ the link
@dataclasses.dataclass(frozen=True)
class LinkMember:
    """A link as declared in a design file: the :class:`Link`, the pin's material and shear planes,
    and the deflection limit (a length, ``"L/250"`` or a fraction of the length)."""

    link: Link
    pin_material: Material
    pin_material_given: bool
    shear_planes: int
    deflection_limit: Any
    lug_defaults: tuple[str, ...] = ()


def _build_link(p: dict[str, Any], ctx: dict[str, Any]) -> LinkMember:
    name = p["_name"]
    if p["length"].magnitude <= 0:
        raise InputError(f"length: must be positive, got {fmt(p['length'])}")
    section = build_section(p)
    lug_keys = ("lug_width", "lug_thickness", "edge_distance", "pin_diameter", "pin_material", "rounded_end")
    lug = None
    defaults: list[str] = []
    if "hole_diameter" in p:
        w, t = p.get("lug_width"), p.get("lug_thickness")
        if w is None or t is None:
            kind = SECTION_ALIASES.get(p["section"], p["section"])
            if kind != "rectangle":
                miss = "lug_width" if w is None else "lug_thickness"
                raise InputError(f"{miss}: missing; give lug_width and lug_thickness of the eye (they default to "
                                 "the bar's larger and smaller dimension only for a rectangle section)")
            big, small = sorted((p["width"], p["height"]), key=lambda q: q.m_as("m"), reverse=True)
            if w is None:
                w = big
                defaults.append(f"lug_width = {fmt(big, 'mm')} (the bar's larger dimension)")
            if t is None:
                t = small
                defaults.append(f"lug_thickness = {fmt(small, 'mm')} (the bar's smaller dimension)")
        R = p.get("edge_distance")
        if R is None:
            R = w / 2
            defaults.append(f"edge_distance = {fmt(R.to('mm'), 'mm')} (half the lug width: a full round end)")
        try:
            lug = Lug(p["hole_diameter"], w, t, R, p["rounded_end"])
        except InputError as exc:
            msg = str(exc).removeprefix("lug: ")
            key = "edge_distance" if "edge distance" in msg else "hole_diameter"
            raise InputError(f"{key}: {msg}") from None
    else:
        given = [k for k in lug_keys if k in p and not (k == "rounded_end" and p[k] is True)]
        if given:
            raise InputError(f"{given[0]}: a pin eye needs hole_diameter (no hole given)")
    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", ctx["requirements"].get("deflection_limit", 0.002))
    try:
        mc.deflection_limit(limit, p["length"])
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the length: "
                         + why(exc, limit)) from None
    if not 0 < p["strength_factor"] <= 1:
        raise InputError(f"strength_factor: must lie in (0, 1], got {p['strength_factor']!r}")
    if p["pin_shear_planes"] < 1:
        raise InputError(f"pin_shear_planes: a positive whole number, got {p['pin_shear_planes']!r}")
    try:
        link = Link(p["length"], section, p["material"], lug=lug, pin_diameter=p.get("pin_diameter"), end=p["end"],
                    strength_factor=p["strength_factor"], print_orientation=p.get("print_orientation", ""),
                    name=name)
    except InputError as exc:
        msg = str(exc).removeprefix(f"{name}: ").removeprefix(f"{name}.")
        key = "pin_diameter" if "pin diameter" in msg else "length" if "overlap" in msg else ""
        raise InputError(f"{key}: {msg}" if key else msg) from None
    return LinkMember(link, p.get("pin_material", p["material"]), "pin_material" in p, p["pin_shear_planes"], limit,
                      tuple(defaults))


def _transverse(m: LinkMember, loads: dict[str, Any]) -> tuple[str, float, pint.Quantity] | None:
    """(Table A-9 case, load in SI, load as given) of a transverse load, or None."""
    tr = link_transverse_case(m.link, loads.get("transverse_load"), loads.get("distributed_load"))
    if tr is None:
        return None
    return (*tr, loads.get("transverse_load", loads.get("distributed_load")))


def _dim_of(case: str) -> str:
    return "force" if beam_case(case).load_kind == "force" else "force_per_length"


def _end_reaction(m: LinkMember, loads: Any) -> pint.Quantity:
    """The largest end reaction of the transverse load (Table A-9): the radial load on the bearing at that end."""
    return link_pin_force(m.link, "0 N", transverse_load=(loads or {}).get("transverse_load"),
                          distributed_load=(loads or {}).get("distributed_load"))[0]


def _pin_force(m: LinkMember, loads: dict[str, Any]) -> tuple[pint.Quantity, str]:
    return link_pin_force(m.link, loads.get("axial_force", "0 N"), transverse_load=loads.get("transverse_load"),
                          distributed_load=loads.get("distributed_load"), pin_force=loads.get("pin_force"))


def _with(r: CheckResult, notes: list[str] = (), details: dict[str, Any] | None = None, **kw: Any) -> CheckResult:
    return dataclasses.replace(r, notes=(*r.notes, *notes), details={**r.details, **(details or {})}, **kw)


def _body_strength(m: LinkMember, loads: dict[str, Any], ctx: Any) -> CheckResult:
    f = link_section_forces(m.link, loads.get("axial_force", "0 N"), loads.get("bending_moment", "0 N*m"),
                            loads.get("lateral_moment", "0 N*m"), loads.get("torque", "0 N*m"),
                            transverse_load=loads.get("transverse_load"),
                            distributed_load=loads.get("distributed_load"))
    M, V, notes = f.moment_y.m_as("N*m"), f.shear.m_as("N"), list(f.notes)
    r = mc.check_member_body_strength(m.link, f.axial, f.moment_y, f.moment_z, f.torque, f.shear,
                                      required_sf=ctx.required_sf)
    if m.link.lug is None:
        notes.append("no hole_diameter given: the eye, lug and pin checks do not apply")
    else:
        notes.append("stress at the pin holes: see the eye net-section check (Kt policy there)")
    inputs = {**r.inputs, "My": Q(M, "N*m").to("N*m")}
    details: dict[str, Any] = {}
    tr = _transverse(m, loads)
    if V:
        inputs["V"] = Q(V, "N")
    if tr is not None:
        E, I = m.link.material.require("E"), m.link.section.Iy
        details = {"beam_case": tr[0], "load_si": tr[1], "length": m.link.length.to("mm"),
                   "EI": (E * I).to("N*m**2")}
        N = to_si(loads.get("axial_force", "0 N"), "force", "axial_force")
        if N < 0:
            pe = (math.pi**2 * E * I / m.link.length**2).m_as("N")  # Euler load in the plane of the transverse load
            notes.append(f"compression with a transverse load: the beam-column amplification of the moment, about "
                         f"1/(1 - P/P_e) = {1 / max(1 - abs(N) / pe, 1e-9):.3g} (P_e = pi^2 E I_y/l^2 = {pe:.4g} N; "
                         "Timoshenko & Gere, Theory of Elastic Stability, Sec. 1.11), is not included")
    return _with(r, notes, details, inputs=inputs)


def _eye(m: LinkMember, loads: dict[str, Any], ctx: Any) -> list[CheckResult]:
    if m.link.lug is None:
        return []
    F, how = _pin_force(m, loads)
    r = mc.check_eye_net_section(m.link, F, required_sf=ctx.required_sf)
    notes = [how, *m.lug_defaults]
    if to_si(loads.get("axial_force", "0 N"), "force", "axial_force") < 0:
        notes.append("compressive axial force: the eye bears on the pin; checked as net-section tension "
                     "(conservative)")
    return [_with(r, notes)]


def _lug(m: LinkMember, loads: dict[str, Any], ctx: Any, mode: str) -> list[CheckResult]:
    """A BTH-1 lug mode with the design's factor as Nd: the 1.20 of the plate modes goes into the capacity."""
    if m.link.lug is None:
        return []
    F, how = _pin_force(m, loads)
    r = next(r for r in mc.lug_checks(m.link, F, design_factor=ctx.required_sf) if r.check == mode)
    if r.check == "lug_bearing":
        r = _with(r, [how])
    else:
        r = _with(r, [how, "capacity = BTH-1 nominal strength / 1.20, so the required SF is Nd (BTH-1 "
                           "Sec. 3-3.3.1: allowable = P / (1.20 Nd))"],
                  capacity=(r.capacity / 1.2).to("N"), formula=r.formula + r",\ \ P_{allow} = P / (1.20\,N_d)")
    nd = (f"Nd = the required SF {ctx.required_sf:g} (BTH-1: 2.0 for Design Category A, 3.0 for Category B; "
          f"set it with checks.{mode} = {{ required_sf = ... }})")
    return [dataclasses.replace(r, notes=tuple(nd if n.startswith("Nd =") else n for n in r.notes))]


def _pin(m: LinkMember, loads: dict[str, Any], ctx: Any) -> list[CheckResult]:
    if m.link.pin_diameter is None:
        return []
    F, how = _pin_force(m, loads)
    r = mc.check_pin_shear(m.link, F, m.pin_material, planes=m.shear_planes, required_sf=ctx.required_sf)
    notes = [how]
    if not m.pin_material_given:
        notes.append(f"pin_material not given: the link's material ({m.pin_material.name}) assumed for the pin")
    return [_with(r, notes)]


def _buckling(m: LinkMember, loads: dict[str, Any], ctx: Any) -> list[CheckResult]:
    if "axial_force" not in loads:
        return []
    N = to_si(loads["axial_force"], "force", "axial_force")
    r = mc.check_member_buckling(m.link, Q(-N, "N"), required_sf=ctx.required_sf)
    b = m.link.buckling()
    s = m.link.section
    return [_with(r, ["axial_force is positive in tension; a negative axial_force compresses the link"],
                  details={"C": b.C, "E": m.link.material.require("E").to("GPa"),
                           "Sy": m.link.yield_strength.to("MPa"), "area": s.area.to("mm**2"),
                           "critical_stress": (b.critical_load / s.area).to("MPa")})]


def _deflection(m: LinkMember, loads: dict[str, Any], ctx: Any) -> list[CheckResult]:
    tr = _transverse(m, loads)
    if tr is None:
        return []
    case, P, q = tr
    load = Q(P, "N" if _dim_of(case) == "force" else "N/m")
    r = mc.check_link_deflection(m.link, case, load, m.deflection_limit)
    E, I = m.link.material.require("E"), m.link.section.Iy
    c = beam_case(case)
    return [_with(r, [f"{c.table_case} {case.replace('_', ' ')}: largest deflection at {c.where.split(';')[0]}",
                     "load in the plane of the section's height (bending about the section's y axis, I_y)"],
                 inputs={**r.inputs, "load": q, "E": E.to("GPa"), "I": I.to("mm**4")},
                 details={"beam_case": case, "load_si": P, "length": m.link.length.to("mm"), "EI": (E * I).to("N*m**2"),
                          "limit": r.capacity})]


ANY_LINK_LOAD = "axial_force|bending_moment|lateral_moment|transverse_load|distributed_load|torque|pin_force"

LINK = REGISTRY.register(ComponentType(
    name="link",
    doc="A straight member between two pin holes, or a bar with end conditions: body section (kind and its "
        "dimensions), material, length between pin centres, pin eye and pin, end condition, optional "
        "3D-print knock-down.",
    fields=(
        Field("length", "length", "length between the pin centres (the span)", required=True),
        Field("section", "choice", "body section kind", required=True,
              choices=(*SECTION_KINDS, *SECTION_ALIASES)),
        Field("width", "length", "section width (along the section's y axis; rectangle, hollow rectangle, I/T/L/C)"),
        Field("height", "length", "section height, in the bending plane of transverse loads"),
        Field("diameter", "length", "diameter of a circle section"),
        Field("outer_diameter", "length", "outer diameter of a tube"),
        Field("inner_diameter", "length", "inner diameter of a tube (instead of thickness)"),
        Field("thickness", "length", "wall thickness of a tube, hollow rectangle or angle"),
        Field("web_thickness", "length", "web thickness of an I, T or C section"),
        Field("flange_thickness", "length", "flange thickness of an I, T or C section"),
        Field("root_radius", "length", "root fillet radius of an I, T, L or C section"),
        Field("outer_radius", "length", "outer corner radius of a hollow rectangle"),
        Field("toe_radius", "length", "toe radius of an angle"),
        Field("material", "material", "link material", required=True),
        Field("end", "choice", "end condition: buckling constant C (Shigley Table 4-2, recommended) and the "
                               "Table A-9 beam case of transverse loads",
              choices=tuple(BEAM_SUPPORT), default="pinned-pinned"),
        Field("hole_diameter", "length", "pin-hole diameter of the eyes (same at both ends)"),
        Field("lug_width", "length", "eye width across the hole (default for a rectangle: its larger dimension)"),
        Field("lug_thickness", "length", "eye thickness along the pin (default for a rectangle: its smaller "
                                         "dimension)"),
        Field("edge_distance", "length", "hole centre to the end of the eye along the link (default lug_width/2)"),
        Field("rounded_end", "bool", "the eye's end is rounded (radius = edge_distance)", default=True),
        Field("pin_diameter", "length", "pin diameter (default: the hole diameter)"),
        Field("pin_material", "material", "pin material (default: the link's material)"),
        Field("pin_shear_planes", "int", "shear planes of the pin (2: link in a clevis)", default=2),
        Field("strength_factor", "float", "knock-down of the material strengths, 0 < f <= 1 (e.g. a printed "
                                          "orientation weaker than the datasheet)", default=1.0),
        Field("print_orientation", "str", "label reported with strength_factor, e.g. 'Z (across layers)'"),
        Field("deflection_limit", "str", "deflection limit as a length ('1 mm') or 'L/250' "
                                         "(default: requirements.deflection_limit)"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the length (0.01)"),
    ),
    build=lambda p, ctx: _build_link(p, ctx),
    loads=(
        Field("axial_force", "force", "axial force, positive in tension, negative in compression"),
        Field("bending_moment", "torque", "bending moment in the plane of the section's height (about y)"),
        Field("lateral_moment", "torque", "bending moment in the plane of the section's width (about z)"),
        Field("transverse_load", "force", "point load across the link in the height plane (centre of a "
                                          "supported span, tip of a cantilever)"),
        Field("distributed_load", "force_per_length", "uniform load across the link in the height plane"),
        Field("torque", "torque", "torsion about the link axis"),
        Field("pin_force", "force", "force through each pin (default: resultant of the axial force and the end "
                                    "reaction of the transverse load)"),
    ),
    checks=(
        CheckSpec.of(mc.check_member_body_strength, _body_strength, needs=(ANY_LINK_LOAD,)),
        CheckSpec.of(mc.check_eye_net_section, _eye, needs=(ANY_LINK_LOAD,)),
        *(CheckSpec.of(fn, lambda c, loads, ctx, mode=fn.check_def.name: _lug(c, loads, ctx, mode),
                       needs=(ANY_LINK_LOAD,), aliases=("lug",))
          for fn in (mc.check_lug_tension, mc.check_lug_fracture_beyond, mc.check_lug_shear_out, mc.check_lug_bearing)),
        CheckSpec.of(mc.check_pin_shear, _pin, needs=(ANY_LINK_LOAD,)),
        CheckSpec.of(mc.check_member_buckling, _buckling, needs=(ANY_LINK_LOAD,)),
        CheckSpec.of(mc.check_link_deflection, _deflection, needs=(ANY_LINK_LOAD,)),
    ),
    outputs=(  # values other components read as "<link>.<name>" (design/parameters.py)
        Output("end_reaction", "force", "largest end reaction of the transverse or distributed load (Shigley 10th ed. "
               "Table A-9): the radial load on the bearing or pin at that end", _end_reaction,
               needs=("transverse_load|distributed_load",)),
        Output("pin_force", "force", "force through each pin: pin_force, or the resultant of the axial force and "
               "the end reaction", lambda c, loads: _pin_force(c, dict(loads or {}))[0], needs=(ANY_LINK_LOAD,)),
    ),
))
