"""``ball_bearing`` (deep groove ball bearing from the catalogue) and ``plain_bushing`` (p, v, pv)."""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import bearings as bc
from mechverify.checks.result import CheckResult
from mechverify.components.bearings import BallBearing, PlainBushing, bearing, reliability_factor, sliding_speed
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError
from mechverify.units import Q, fmt


@dataclasses.dataclass(frozen=True)
class BearingInstallation:
    """A catalogue ball bearing with its life requirement and reliability (from the design file)."""

    bearing: BallBearing
    required_life: pint.Quantity | None = None
    reliability: float = 0.9


def _build_bearing(p: dict[str, Any], ctx: dict[str, Any]) -> BearingInstallation:
    b = bearing(p["model"])
    changes = pick(p, C="dynamic_load_rating", C0="static_load_rating", limiting_speed="limiting_speed")
    if changes:
        b = dataclasses.replace(b, **changes)
    R = float(p["reliability"])
    if not 0.9 <= R <= 0.9995:
        raise InputError(f"reliability must be within 0.90 .. 0.9995 (ISO 281 Table 12), got {R:g}")
    if "required_life" in p and p["required_life"].magnitude <= 0:
        raise InputError(f"required_life must be positive, got {fmt(p['required_life'])}")
    return BearingInstallation(b, p.get("required_life"), R)


def _forces(loads: dict[str, Any]) -> tuple[pint.Quantity, pint.Quantity]:
    Fr, Fa = loads.get("radial_force", Q(0, "N")), loads.get("axial_force", Q(0, "N"))
    for name, f in (("radial_force", Fr), ("axial_force", Fa)):
        if f.magnitude < 0:
            raise InputError(f"{name} must be >= 0 (a magnitude), got {fmt(f)}")
    return Fr.to("N"), Fa.to("N")


def _life(inst: BearingInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    Fr, Fa = _forces(loads)
    required = inst.required_life if inst.required_life is not None else ctx.requirements["bearing_life"]
    r = bc.check_bearing_life(inst.bearing, Fr, Fa, loads["speed"], required, reliability=inst.reliability)
    source = "component's required_life" if inst.required_life is not None else "requirements.bearing_life"
    return dataclasses.replace(r, notes=(*r.notes, f"required life from the {source}"),
                               details={**r.details, "a1": reliability_factor(inst.reliability)})


BALL = REGISTRY.register(ComponentType(
    name="ball_bearing",
    doc="A single-row deep groove ball bearing from the catalogue by designation (608, 6200-2Z, 6001-2RS1): "
        "ISO 281 rating life, ISO 76 static safety, speed.",
    fields=(
        Field("model", "str", "catalogue designation, e.g. '608-2Z' (see `mechverify bearings`)", required=True),
        Field("required_life", "time", "required rating life of this bearing, instead of requirements.bearing_life"),
        Field("reliability", "float", "reliability of the rating life (ISO 281 Table 12: 0.90 .. 0.9995)",
              default=0.9),
        Field("dynamic_load_rating", "force", "C, instead of the catalogue's"),
        Field("static_load_rating", "force", "C0, instead of the catalogue's"),
        Field("limiting_speed", "angular_velocity", "limiting speed, instead of the catalogue's (e.g. the lower "
                                                    "one of a contact-sealed variant)"),
    ),
    build=lambda p, ctx: _build_bearing(p, ctx),
    loads=(
        Field("radial_force", "force", "radial load Fr on this bearing"),
        Field("axial_force", "force", "axial load Fa on this bearing"),
        Field("speed", "angular_velocity", "rotational speed of the inner ring relative to the outer"),
    ),
    checks=(
        CheckSpec.of(bc.check_bearing_life, _life, needs=("radial_force|axial_force", "speed")),
        CheckSpec.of(bc.check_bearing_static_safety, lambda c, loads, ctx: bc.check_bearing_static_safety(
            c.bearing, *_forces(loads), required_s0=ctx.required_sf), needs=("radial_force|axial_force",)),
        CheckSpec.of(bc.check_bearing_speed, lambda c, loads, ctx: bc.check_bearing_speed(c.bearing, loads["speed"]),
                     needs=("speed",)),
    ),
))


# ------------------------------------------------------------------------------------------- plain bushing
def _sliding(b: PlainBushing, loads: dict[str, Any]) -> pint.Quantity:
    if "sliding_speed" in loads:
        return abs(loads["sliding_speed"]).to("m/s")
    return sliding_speed(b.d, loads["speed"]).to("m/s")


_LIMIT_UNITS = {"p_max": ("pressure", "MPa"), "v_max": ("velocity", "m/s"), "pv_max": ("pv", "MPa*m/s")}


def _build_bushing(p: dict[str, Any], ctx: dict[str, Any]) -> PlainBushing:
    return PlainBushing(d=p["bore"], length=p["length"], name=p["_name"], **pick(p, "material", *_LIMIT_UNITS))


def _radial(loads: dict[str, Any]) -> pint.Quantity:
    F = loads["radial_force"].to("N")
    if F.magnitude < 0:
        raise InputError(f"radial_force must be >= 0 (a magnitude), got {fmt(F)}")
    return F


BUSHING = REGISTRY.register(ComponentType(
    name="plain_bushing",
    doc="A plain journal bushing or linear slide bush: projected pressure, sliding speed and pv against the "
        "material's (or given) limits (Shigley 10th ed. Sec. 12-15).",
    fields=(
        Field("bore", "length", "bore (shaft or rod) diameter d", required=True),
        Field("length", "length", "bushing length L", required=True),
        Field("material", "material", "bushing material (its p_max, v_max, pv_max are used when not given)"),
        Field("p_max", "pressure", "allowable projected pressure, instead of the material's"),
        Field("v_max", "velocity", "allowable sliding speed, instead of the material's"),
        Field("pv_max", "pv", "pv limit, instead of the material's"),
    ),
    build=lambda p, ctx: _build_bushing(p, ctx),
    loads=(
        Field("radial_force", "force", "load across the bushing"),
        Field("sliding_speed", "velocity", "sliding speed (linear bush: rod speed)"),
        Field("speed", "angular_velocity", "shaft speed (instead of sliding_speed): v = omega d/2"),
    ),
    checks=(
        CheckSpec.of(bc.check_bushing_pressure, lambda c, loads, ctx: bc.check_bushing_pressure(c, _radial(loads)),
                     needs=("radial_force",)),
        CheckSpec.of(bc.check_bushing_velocity, lambda c, loads, ctx: bc.check_bushing_velocity(c, _sliding(c, loads)),
                     needs=("sliding_speed|speed",)),
        CheckSpec.of(bc.check_bushing_pv,
                     lambda c, loads, ctx: bc.check_bushing_pv(c, _radial(loads), _sliding(c, loads)),
                     needs=("radial_force", "sliding_speed|speed")),
    ),
))
