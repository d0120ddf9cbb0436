"""``link``: a structural member between two pins, with its closed-form checks.

* ``link`` — a straight member between two pin holes, or a bar with end conditions
  (:class:`~mechverify.components.links.Link`): body section by kind and dimensions (flat keys),
  material, optional pin eye (lug) and pin, end condition (buckling and beam case), optional
  print-orientation knock-down. Loads per case: axial force, bending moments, a transverse point or
  distributed load (Shigley Table A-9 case picked from the end condition), torsion, pin force.

(The Roark ``plate`` type is in :mod:`mechverify.design.adapters.plates`; section parsing, shared with
``frame``, in :mod:`mechverify.design.adapters.sections`; the link's fields in :mod:`.link_parsing`.)

The checks are those of :mod:`mechverify.checks.members`, the section forces those of
:mod:`mechverify.components.links`; this module only maps design-file values onto them and adds the
beam-diagram data of a transverse load to the body-strength result.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import members as mc
from mechverify.checks.result import CheckResult
from mechverify.components.links import (
    BEAM_SUPPORT,
    beam_case,
    link_pin_force,
    link_section_forces,
    link_transverse_case,
)
from mechverify.design.adapters.link_parsing import LinkMember, build_link
from mechverify.design.adapters.sections import (  # noqa: F401  (frame imports them from here)
    SECTION_ALIASES,
    SECTION_DIMENSIONS,
    SECTION_KINDS,
    build_section,
    why,
)
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.units import Q, to_si


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
    if tr is not None:  # beam-diagram figure
        E, I = m.link.material.require("E"), m.link.section.Iy
        details = {"beam_case": tr[0], "load_si": tr[1], "length": m.link.length.to("mm"),
                   "EI": (E * I).to("N*m**2")}
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
    r = next(r for r in mc.lug_checks(m.link, F, design_factor=ctx.required_sf, allowable=True) if r.check == mode)
    nd = (f"Nd = the required SF {ctx.required_sf:g} (BTH-1: 2.0 for Design Category A, 3.0 for Category B; "
          f"set it with checks.{mode} = {{ required_sf = ... }})")
    return [dataclasses.replace(r, notes=(*(nd if n.startswith("Nd =") else n for n in r.notes), how))]


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
    return [_with(r, ["axial_force is positive in tension; a negative axial_force compresses the link"])]


def _deflection(m: LinkMember, loads: dict[str, Any], ctx: Any) -> list[CheckResult]:
    tr = _transverse(m, loads)
    if tr is None:
        return []
    case, P, q = tr
    r = mc.check_link_deflection(m.link, case, Q(P, "N" if _dim_of(case) == "force" else "N/m"), m.deflection_limit)
    c = beam_case(case)
    return [_with(r, [f"{c.table_case} {case.replace('_', ' ')}: largest deflection at {c.where.split(';')[0]}",
                     "load in the plane of the section's height (bending about the section's y axis, I_y)"],
                 inputs={**r.inputs, "load": q})]


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
    build=lambda p, ctx: build_link(p, ctx),
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
