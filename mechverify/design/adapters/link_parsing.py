"""Parsing of a ``link`` component (:mod:`mechverify.design.adapters.members`): section, pin eye with its
defaults, pin, deflection limit; builds the :class:`~mechverify.components.links.Link`. Declares no type."""

from __future__ import annotations

import dataclasses
from typing import Any

from mechverify.checks import members as mc
from mechverify.components.links import Link, Lug
from mechverify.design.adapters.sections import SECTION_ALIASES, build_section, why
from mechverify.errors import InputError, MechverifyError
from mechverify.materials import Material
from mechverify.units import fmt


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


def build_link(p: dict[str, Any], ctx: dict[str, Any]) -> LinkMember:
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
