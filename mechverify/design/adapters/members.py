"""``link`` and ``plate``: structural members with their closed-form checks.

* ``link`` — a straight member between two pin holes, or a bar with end conditions
  (:class:`~mechverify.components.links.Link`): body section by kind and dimensions (flat keys),
  material, optional pin eye (lug) and pin, end condition (buckling and beam case), optional
  print-orientation knock-down. Loads per case: axial force, bending moments, a transverse point or
  distributed load (Shigley Table A-9 case picked from the end condition), torsion, pin force.
* ``plate`` — a rectangular or circular plate on Roark's closed-form cases (all edges simply
  supported or clamped; uniform pressure or a central load): bending stress and deflection. Plates
  on bolts or with cut-outs are outside these cases and need the FEA plate model.

The checks are those of :mod:`mechverify.checks.members`; this module only maps design-file
values onto them and adds plot data (beam diagram, column curve) to the results.
"""

from __future__ import annotations

import dataclasses
import inspect
import math
from typing import Any

import numpy as np
import pint

from mechverify.checks import members as mc
from mechverify.checks import plates as pc
from mechverify.checks.result import CheckResult
from mechverify.components import sections
from mechverify.components.links import (
    BEAM_SUPPORT,
    Link,
    Lug,
    beam_case,
    link_pin_force,
    link_section_forces,
    link_transverse_case,
)
from mechverify.components.plates import Plate, PlateEstimate, roark_circular_plate, roark_rectangular_plate
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError, MechverifyError
from mechverify.materials import Material
from mechverify.units import Q, fmt, to_si

# ------------------------------------------------------------------------------------------ sections
#: Section kinds a design file may name, with the constructor of :mod:`~mechverify.components.sections`.
SECTION_KINDS = tuple(k for k in sections.section_kinds() if k != "polygon")
SECTION_ALIASES = {"rect": "rectangle", "bar": "rectangle", "flat": "rectangle", "round": "circle", "rod": "circle",
                   "pipe": "tube", "chs": "tube", "rhs": "hollow_rectangle", "shs": "hollow_rectangle",
                   "box": "hollow_rectangle", "ipe": "i_section", "tee": "t_section", "angle": "l_section",
                   "channel": "c_section"}
SECTION_DIMENSIONS = ("width", "height", "diameter", "outer_diameter", "inner_diameter", "thickness",
                      "web_thickness", "flange_thickness", "root_radius", "outer_radius", "toe_radius")


def _section_parameters(kind: str) -> tuple[list[str], list[str]]:
    """(required, optional) dimension keys of a section constructor."""
    sig = inspect.signature(getattr(sections, kind))
    req = [n for n, p in sig.parameters.items() if p.default is inspect.Parameter.empty]
    opt = [n for n, p in sig.parameters.items() if p.default is not inspect.Parameter.empty]
    return req, opt


def build_section(p: dict[str, Any]) -> sections.Section:
    """The body section from the flat keys ``section`` (kind) and its dimensions."""
    kind = SECTION_ALIASES.get(p["section"], p["section"])
    req, opt = _section_parameters(kind)
    given = {k: p[k] for k in SECTION_DIMENSIONS if k in p}
    extra = [k for k in given if k not in req + opt]
    if extra:
        raise InputError(f"{extra[0]}: not a dimension of a {kind} section (it takes {', '.join(req + opt)})")
    if kind == "tube" and "thickness" not in given and "inner_diameter" not in given:
        raise InputError("thickness: missing; a tube needs outer_diameter and thickness (or inner_diameter)")
    missing = [k for k in req if k not in given]
    if missing:
        raise InputError(f"{missing[0]}: missing; a {kind} section needs {', '.join(req)}")
    return sections.make_section(kind, **given)


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


def _why(exc: Exception, limit: Any) -> str:
    return str(exc).split(": ", 1)[-1] if isinstance(exc, MechverifyError) else f"got {limit!r}"


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
                         + _why(exc, limit)) from None
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


# ------------------------------------------------------------------------------------------ the plate
FEA_NOTE = ("Roark's closed forms cover a whole plate on its edges only: a plate on bolts or corner supports, or "
            "with holes or cut-outs, needs the FEA plate model")


@dataclasses.dataclass(frozen=True)
class RoarkPlate:
    """A plate as a design file declares it for Roark's closed forms: ``plate`` (outline geometry,
    thickness, material), its shape and size, edge condition, central-load radius, deflection limit."""

    plate: Plate
    shape: str  # "rectangle" or "circle"
    size: tuple[pint.Quantity, ...]  # (width, height) or (diameter,)
    edges: str
    load_radius: pint.Quantity
    deflection_limit: Any

    @property
    def span(self) -> pint.Quantity:
        """The span of the deflection limit: the shorter side, or the diameter."""
        return min(self.size, key=lambda q: q.m_as("m"))

    def estimate(self, load: pint.Quantity, loading: str) -> PlateEstimate:
        E = self.plate.material.require("E")
        t = self.plate.thickness_q
        if self.shape == "rectangle":
            return roark_rectangular_plate(*self.size, t, E, load, self.edges, loading, self.load_radius)
        nu = self.plate.material.nu
        if nu is None:
            raise InputError(f"material {self.plate.material.name!r} has no Poisson's ratio (needed for a circular "
                             "plate)")
        return roark_circular_plate(self.size[0] / 2, t, E, nu, load, self.edges, loading, self.load_radius)


def _circle_outline(d: pint.Quantity, n: int = 96) -> pint.Quantity:
    r = d.m_as("m") / 2
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    return Q(np.column_stack((r + r * np.cos(a), r + r * np.sin(a))), "m")


def _build_plate(p: dict[str, Any], ctx: dict[str, Any]) -> RoarkPlate:
    name, shape = p["_name"], p["shape"]
    needs = ("width", "height") if shape == "rectangle" else ("diameter",)
    other = ("diameter",) if shape == "rectangle" else ("width", "height")
    for k in needs:
        if k not in p:
            raise InputError(f"{k}: missing; a {shape} plate needs {' and '.join(needs)}")
    for k in other:
        if k in p:
            raise InputError(f"{k}: not a dimension of a {shape} plate (it takes {' and '.join(needs)})")
    for k in (*needs, "thickness"):
        if p[k].magnitude <= 0:
            raise InputError(f"{k}: must be positive, got {fmt(p[k])}")
    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", ctx["requirements"].get("deflection_limit", 0.002))
    size = tuple(p[k] for k in needs)
    try:
        mc.deflection_limit(limit, min(size, key=lambda q: q.m_as("m")))
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the span: "
                         + _why(exc, limit)) from None
    if p["load_radius"].magnitude < 0:
        raise InputError(f"load_radius: must be zero or positive, got {fmt(p['load_radius'])}")
    if shape == "circle" and p["material"].nu is None:
        raise InputError(f"material: {p['material'].name!r} has no Poisson's ratio, which a circular plate needs; "
                         "define a derived material with nu = ...")
    if shape == "rectangle":
        plate = Plate.rectangle(p["width"], p["height"], p["thickness"], p["material"], name=name)
    else:
        plate = Plate(_circle_outline(p["diameter"]), p["thickness"], p["material"], name=name)
    return RoarkPlate(plate, shape, size, p["edges"], p["load_radius"], limit)


def _plate_load(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> tuple[pint.Quantity, str, list[str]]:
    """(load, loading, notes): pressure (+ self-weight) or central force."""
    if "pressure" in loads and "central_force" in loads:
        raise InputError("give pressure or central_force, not both (Roark's cases take one load)")
    notes: list[str] = []
    if "central_force" in loads:
        if loads.get("self_weight"):
            raise InputError("self_weight: only with a pressure load (Roark's cases take one load)")
        return loads["central_force"].to("N"), "central", notes
    q = loads["pressure"].to("Pa")
    if loads.get("self_weight"):
        g = ctx.requirements.get("g", Q(9.80665, "m/s**2"))
        qw = (rp.plate.material.require("density") * rp.plate.thickness_q * g).to("Pa")
        notes.append(f"self-weight rho g t = {fmt(qw, 'Pa')} added to the pressure {fmt(q, 'Pa')}")
        q = q + qw
    return q, "uniform", notes


def _plate_stress(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> CheckResult:
    load, loading, notes = _plate_load(rp, loads, ctx)
    est = rp.estimate(load, loading)
    r = pc.check_plate_stress_roark(rp.plate, est, required_sf=ctx.required_sf)
    inputs = {**r.inputs, ("q" if loading == "uniform" else "W"): load.to("kPa" if loading == "uniform" else "N"),
              "E": rp.plate.material.require("E").to("GPa")}
    inputs.update({k: v.to("mm") for k, v in zip(("a", "b") if rp.shape == "rectangle" else ("d",), rp.size,
                                                  strict=True)})
    formula = {("rectangle", "uniform"): r"\sigma_{max} = \beta \frac{q b^2}{t^2} \le S_y",
               ("rectangle", "central"): r"\sigma_{max} = \frac{3 W}{2 \pi t^2}\left[(1 + \nu)"
                                         r"\ln\frac{2 b}{\pi r_0'} + \beta\right] \le S_y",
               ("circle", "uniform"): r"\sigma_{max} = \frac{3 (3 + \nu) q a^2}{8 t^2}\ \mathrm{or}\ "
                                      r"\frac{3 q a^2}{4 t^2} \le S_y",
               ("circle", "central"): r"\sigma_{max} = \frac{3 W}{2 \pi t^2}\left[(1 + \nu)\ln\frac{a}{r_0'}"
                                      r" + 1\right]\ \mathrm{or}\ \ldots \le S_y"}[(rp.shape, loading)]
    coefs = ", ".join(f"{k} = {v:.4g}" for k, v in est.coefficients.items() if k != "r0_equivalent")
    if coefs:
        notes.append(f"coefficients {coefs} (nu = 0.3 table)")
    nu = rp.plate.material.nu
    if rp.shape == "rectangle" and nu is not None and abs(nu.m_as("") - 0.3) > 0.02:
        notes.append(f"Roark's Table 11.4 coefficients are for nu = 0.3; the material's nu = {nu.m_as(''):.3g}")
    return _with(r, [*notes, FEA_NOTE], inputs=inputs, formula=formula)


def _plate_deflection(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> CheckResult:
    load, loading, notes = _plate_load(rp, loads, ctx)
    est = rp.estimate(load, loading)
    r = pc.check_plate_deflection_roark(rp.plate, est, rp.deflection_limit, span=rp.span)
    formula = (r"y_{max} = \alpha \frac{q b^4}{E t^3} \le \delta_{lim}" if rp.shape == "rectangle" and
               loading == "uniform" else r"y_{max} = \alpha \frac{W b^2}{E t^3} \le \delta_{lim}"
               if rp.shape == "rectangle" else r"y_{max} = \frac{q a^4}{64 D}\,\frac{5 + \nu}{1 + \nu}\ \mathrm{etc.},"
               r"\ D = \frac{E t^3}{12 (1 - \nu^2)}")
    return _with(r, [*notes, est.case, f"span for the limit: {fmt(rp.span, 'mm')} (shorter side or diameter)",
                     FEA_NOTE], formula=formula)


PLATE = REGISTRY.register(ComponentType(
    name="plate",
    doc="A rectangular or circular plate of uniform thickness on Roark's closed-form cases: all edges simply "
        "supported or clamped, uniform pressure or a central load. Plates on bolts or with cut-outs need the FEA "
        "plate model.",
    fields=(
        Field("shape", "choice", "plate outline", choices=("rectangle", "circle"), default="rectangle"),
        Field("width", "length", "side of a rectangular plate"),
        Field("height", "length", "other side of a rectangular plate"),
        Field("diameter", "length", "diameter of a circular plate"),
        Field("thickness", "length", "plate thickness", required=True),
        Field("material", "material", "plate material (E, yield strength; Poisson's ratio for a circle)",
              required=True),
        Field("edges", "choice", "all edges simply supported or clamped", choices=("simply_supported", "clamped"),
              default="simply_supported"),
        Field("load_radius", "length", "radius of the central load's contact (0: a point, Roark's r0')",
              default="0 mm"),
        Field("deflection_limit", "str", "deflection limit as a length ('0.5 mm') or 'L/250' of the shorter side "
                                         "(default: requirements.deflection_limit)"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the shorter side"),
    ),
    build=lambda p, ctx: _build_plate(p, ctx),
    loads=(
        Field("pressure", "pressure", "uniform pressure over the whole plate"),
        Field("central_force", "force", "total force on a small central circle (radius load_radius)"),
        Field("self_weight", "bool", "add the plate's weight rho g t to the pressure", default=False),
    ),
    checks=(
        CheckSpec.of(pc.check_plate_stress_roark, _plate_stress, needs=("pressure|central_force",)),
        CheckSpec.of(pc.check_plate_deflection_roark, _plate_deflection, needs=("pressure|central_force",)),
    ),
))
