"""``ball_bearing`` (deep groove ball bearing from the catalogue) and ``plain_bushing`` (p, v, pv)."""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import bearings as bc
from mechverify.components.bearings import (
    BallBearing,
    DutyCycleLoad,
    Lubrication,
    PlainBushing,
    bearing,
    duty_cycle_load,
    reliability_factor,
    sliding_speed,
)
from mechverify.components.bearings_rolling import RollingBearing
from mechverify.design.adapters.bearing_parsing import LUBRICANT_FIELDS
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError
from mechverify.units import Q, fmt


@dataclasses.dataclass(frozen=True)
class BearingInstallation:
    """A catalogue ball bearing with its life requirement and reliability (from the design file)."""

    bearing: BallBearing | RollingBearing
    required_life: pint.Quantity | None = None
    reliability: float = 0.9
    lubrication: Lubrication | None = None
    duty_cycle: dict[str, float] | None = None


_LUB_KEYS = ("viscosity", "viscosity_40", "viscosity_100", "iso_vg", "operating_temperature", "viscosity_index")
_LUB_WORDS = (("ISO VG", "iso_vg"), ("operating temperature", "operating_temperature"),
              ("viscosity index", "viscosity_index"), ("no ASTM D2270", "viscosity_index"))


def _lubrication(p: dict[str, Any]) -> Lubrication | None:
    if not any(k in p for k in _LUB_KEYS):
        return None
    cont: str | float = p.get("contamination", "normal_cleanliness")
    if "contamination_factor" in p:
        cont = float(p["contamination_factor"])
    oil = [k for k in _LUB_KEYS[1:] if k in p]
    for key, others in (("viscosity", oil), ("iso_vg", ["viscosity_40"]), ("viscosity_index", ["viscosity_100"])):
        if key in p and any(k in p for k in others):  # one of them would win silently
            raise InputError(f"{key}: give {key} or {' + '.join(k for k in others if k in p)}, not both")
    lub = Lubrication(**{k: p[k] for k in _LUB_KEYS if k in p}, contamination=cont)
    try:  # bad or missing lubricant data is reported at build time, at its key where the message names one
        lub.operating_viscosity()
    except MechverifyError as exc:
        key = next((k for w, k in _LUB_WORDS if str(exc).startswith(w) and k in p), None)
        if key is None:
            raise
        raise InputError(f"{key}: {exc}") from exc
    return lub


def _duty_cycle(p: dict[str, Any]) -> dict[str, float] | None:
    dc = p.get("duty_cycle")
    if dc is None:
        return None
    if not isinstance(dc, dict) or not dc:
        raise InputError("duty_cycle: give a table of load case = time share, e.g. { run = 0.7, start = 0.3 }")
    try:
        shares = {str(k): float(v) for k, v in dc.items()}
    except (TypeError, ValueError) as exc:
        raise InputError(f"duty_cycle: shares must be numbers, got {dc!r}") from exc
    if any(not (v >= 0) for v in shares.values()) or not sum(shares.values()) > 0:
        raise InputError(f"duty_cycle: shares must be >= 0 with a positive total, got {shares}")
    return shares


def _build_bearing(p: dict[str, Any], ctx: dict[str, Any]) -> BearingInstallation:
    b = bearing(p["model"])
    changes = pick(p, C="dynamic_load_rating", C0="static_load_rating", limiting_speed="limiting_speed")
    if changes:
        b = dataclasses.replace(b, **changes)
    R = float(p["reliability"])
    if not 0.9 <= R <= 0.9995:
        raise InputError(f"reliability: must be within 0.90 .. 0.9995 (ISO 281 Table 12), got {p['reliability']!r}")
    if "required_life" in p and p["required_life"].magnitude <= 0:
        raise InputError(f"required_life: must be positive, got {fmt(p['required_life'])}")
    return BearingInstallation(b, p.get("required_life"), R, _lubrication(p), _duty_cycle(p))


def _forces(loads: dict[str, Any]) -> tuple[pint.Quantity, pint.Quantity]:
    Fr = loads["radial_force"] if "radial_force" in loads else Q(0, "N")  # (the default made only when needed)
    Fa = loads["axial_force"] if "axial_force" in loads else Q(0, "N")
    for name, f in (("radial_force", Fr), ("axial_force", Fa)):
        if f.magnitude < 0:
            raise InputError(f"{name} must be >= 0 (a magnitude), got {fmt(f)}")
    return Fr.to("N"), Fa.to("N")


def _cycle(inst: BearingInstallation, ctx: Any) -> DutyCycleLoad | None:
    """The duty cycle's equivalent load over its load cases (time shares, speeds from each case)."""
    if inst.duty_cycle is None:
        return None
    cases = ctx.design.data.load_cases
    P, shares, speeds = [], [], []
    for case, share in inst.duty_cycle.items():
        loads = cases.get(case, {}).get(ctx.component)
        if loads is None or "speed" not in loads:
            raise InputError(f"duty_cycle: load case {case!r} gives no loads (with a speed) for {ctx.component!r}; "
                             f"cases: {', '.join(cases)}")
        P.append(inst.bearing.equivalent_load(*_forces(loads)).P)
        shares.append(share)
        speeds.append(loads["speed"])
    return duty_cycle_load(P, shares, speeds=speeds, exponent=float(getattr(inst.bearing, "life_exponent", 3.0)))


def _first_cycle_case(inst: BearingInstallation, ctx: Any) -> bool:
    """With a duty cycle the life is one result for the whole cycle: reported once, in its first case."""
    return inst.duty_cycle is None or ctx.load_case == next(iter(inst.duty_cycle))


def _required(inst: BearingInstallation, ctx: Any) -> Any:
    return inst.required_life if inst.required_life is not None else ctx.requirements["bearing_life"]


def _modified(inst: BearingInstallation, loads: dict[str, Any], ctx: Any) -> Any:
    if inst.lubrication is None:
        if ctx.design.data.components[ctx.component].checks.get("bearing_modified_life", {}).get("enabled"):
            raise InputError("bearing_modified_life needs the lubricant: give viscosity (at the operating "
                             "temperature), or viscosity_40 or iso_vg with viscosity_100 and operating_temperature; "
                             "and contamination (ISO 281 Table 13 level) or contamination_factor")
        return []
    if not _first_cycle_case(inst, ctx):
        return []
    Fr, Fa = _forces(loads)
    dc = _cycle(inst, ctx)
    return bc.check_bearing_modified_life(inst.bearing, Fr, Fa, loads["speed"], _required(inst, ctx),
                                          inst.lubrication, reliability=inst.reliability, duty_cycle=dc)


def _life(inst: BearingInstallation, loads: dict[str, Any], ctx: Any) -> Any:
    if not _first_cycle_case(inst, ctx):
        return []
    Fr, Fa = _forces(loads)
    required = _required(inst, ctx)
    r = bc.check_bearing_life(inst.bearing, Fr, Fa, loads["speed"], required, reliability=inst.reliability,
                              duty_cycle=_cycle(inst, ctx))
    source = "component's required_life" if inst.required_life is not None else "requirements.bearing_life"
    details = r.details  # figure data and the substituted line stay uncomputed until read (a study never reads them)
    return r.replace(notes=(*r.notes, f"required life from the {source}"),
                     details=lambda: {**details, "a1": reliability_factor(inst.reliability)})


#: The checks of every rolling-bearing type (ball_bearing, rolling_bearing): life, modified life, static safety, speed.
ROLLING_CHECKS = (
    CheckSpec.of(bc.check_bearing_life, _life, needs=("radial_force|axial_force", "speed")),
    CheckSpec.of(bc.check_bearing_modified_life, _modified, needs=("radial_force|axial_force", "speed")),
    CheckSpec.of(bc.check_bearing_static_safety, lambda c, loads, ctx: bc.check_bearing_static_safety(
        c.bearing, *_forces(loads), required_s0=ctx.required_sf), needs=("radial_force|axial_force",)),
    CheckSpec.of(bc.check_bearing_speed, lambda c, loads, ctx: bc.check_bearing_speed(c.bearing, loads["speed"]),
                 needs=("speed",)),
)


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
        Field("viscosity", "str", "lubricant (grease base oil) kinematic viscosity at the operating temperature, "
                                  "e.g. '20 mm^2/s' (enables bearing_modified_life)"),
        *LUBRICANT_FIELDS,
    ),
    build=lambda p, ctx: _build_bearing(p, ctx),
    loads=(
        Field("radial_force", "force", "radial load Fr on this bearing"),
        Field("axial_force", "force", "axial load Fa on this bearing"),
        Field("speed", "angular_velocity", "rotational speed of the inner ring relative to the outer"),
    ),
    checks=ROLLING_CHECKS,
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
