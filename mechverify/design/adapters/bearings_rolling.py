"""``rolling_bearing`` (angular contact ball, matched pairs, thrust ball, tapered, cylindrical and needle roller
bearings from the catalogue) and ``adjusted_bearing_pair`` (two bearings adjusted against each other, with the
induced axial forces: ISO/SKF or Timken's rule)."""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import bearings as bc
from mechverify.components.bearings import EquivalentLoad
from mechverify.components.bearings_rolling import (
    ARRANGEMENTS,
    AdjustedPairLoads,
    RollingBearing,
    adjusted_pair_loads,
    rolling_bearing,
)
from mechverify.design.adapters.bearing_parsing import LUBRICANT_FIELDS
from mechverify.design.adapters.bearings import (
    ROLLING_CHECKS,
    BearingInstallation,
    _duty_cycle,
    _lubrication,
)
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError
from mechverify.units import Q, fmt

_OVERRIDES = dict(C="dynamic_load_rating", C0="static_load_rating", limiting_speed="limiting_speed")


def _bearing(model: str, p: dict[str, Any], arrangement: str = "single") -> RollingBearing:
    b = rolling_bearing(model, arrangement)
    changes = pick(p, **_OVERRIDES)
    if "K" in p:
        if not float(p["K"]) > 0:  # checked here, once: a bad K surfaced only when the checks ran
            raise InputError(f"K: expected a positive Timken thrust factor, got {p['K']!r}")
        changes["K"] = float(p["K"])
    return dataclasses.replace(b, **changes) if changes else b


def _reliability(p: dict[str, Any]) -> float:
    R = float(p["reliability"])
    if not 0.9 <= R <= 0.9995:
        raise InputError(f"reliability: must be within 0.90 .. 0.9995 (ISO 281 Table 12), got {p['reliability']!r}")
    return R


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> BearingInstallation:
    b = _bearing(p["model"], p, p["arrangement"])
    if "required_life" in p and p["required_life"].magnitude <= 0:
        raise InputError(f"required_life: must be positive, got {fmt(p['required_life'])}")
    return BearingInstallation(b, p.get("required_life"), _reliability(p), _lubrication(p), _duty_cycle(p))


_COMMON = (
    Field("required_life", "time", "required rating life, instead of requirements.bearing_life"),
    Field("reliability", "float", "reliability of the rating life (ISO 281 Table 12: 0.90 .. 0.9995)", default=0.9),
    Field("dynamic_load_rating", "force", "C, instead of the catalogue's"),
    Field("static_load_rating", "force", "C0, instead of the catalogue's"),
    Field("limiting_speed", "angular_velocity", "limiting speed, instead of the catalogue's"),
)

ROLLING = REGISTRY.register(ComponentType(
    name="rolling_bearing",
    doc="A catalogue angular contact ball (single or matched pair), thrust ball, tapered roller, cylindrical "
        "roller or needle roller bearing (see `mechverify.components.bearings_rolling`): rating life with the "
        "maker's X, Y factors and the life exponent (3 ball, 10/3 roller), static safety, speed.",
    fields=(
        Field("model", "str", "catalogue designation, e.g. '7206 B', '30205', '51105', 'NU 205 ECP', 'NK 20/16'",
              required=True),
        Field("arrangement", "choice", "angular contact ball bearings: single, or a matched pair back_to_back, "
                                       "face_to_face, tandem (C x1.62, C0 x2, pair factors)",
              default="single", choices=ARRANGEMENTS),
        *_COMMON,
        Field("viscosity", "str", "lubricant viscosity at the operating temperature (enables "
                                  "bearing_modified_life; not for thrust bearings)"),
        *LUBRICANT_FIELDS,
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("radial_force", "force", "radial load Fr on the bearing (or matched pair)"),
        Field("axial_force", "force", "axial load Fa on the bearing (or matched pair)"),
        Field("speed", "angular_velocity", "rotational speed"),
    ),
    checks=ROLLING_CHECKS,
))


# ------------------------------------------------------------------------------ adjusted pair
@dataclasses.dataclass(frozen=True)
class AdjustedPair:
    """Bearings A and B adjusted against each other; the external axial force loads A."""

    A: RollingBearing
    B: RollingBearing
    rule: str
    required_life: pint.Quantity | None
    reliability: float


def _build_pair(p: dict[str, Any], ctx: dict[str, Any]) -> AdjustedPair:
    mA, mB = p.get("model_A", p.get("model")), p.get("model_B", p.get("model"))
    if mA is None or mB is None:
        raise InputError("adjusted_bearing_pair: give model (both bearings) or model_A and model_B")
    A, B = _bearing(mA, p), _bearing(mB, p)
    for b in (A, B):
        if b.kind not in ("tapered_roller", "angular_contact_ball"):
            raise InputError(f"adjusted_bearing_pair: {b.designation} is a {b.kind.replace('_', ' ')} bearing; "
                             "adjusted pairs are tapered roller or angular contact ball bearings")
        if p["rule"] == "timken" and b.K is None:
            raise InputError(f"adjusted_bearing_pair: Timken's rule needs K for {b.designation} (give K)")
    return AdjustedPair(A, B, p["rule"], p.get("required_life"), _reliability(p))


def _pair_loads(c: AdjustedPair, loads: dict[str, Any]) -> tuple[AdjustedPairLoads, Any, Any]:
    FrA, FrB = (loads.get(k, Q(0, "N")).to("N") for k in ("radial_force_A", "radial_force_B"))
    Ka = loads.get("axial_force", Q(0, "N")).to("N")
    if FrA.magnitude < 0 or FrB.magnitude < 0 or Ka.magnitude < 0:
        raise InputError("adjusted_bearing_pair: radial forces and axial_force are magnitudes (>= 0); the axial "
                         "force is taken toward bearing A (name the bearings so that it is)")
    return adjusted_pair_loads(c.A, c.B, FrA, FrB, Ka, c.rule), FrA, FrB


def _note(pl: AdjustedPairLoads, rule: str) -> str:
    how = "0.47 Fr/K (Timken)" if rule == "timken" else "the rows' factors (0.5 Fr/Y tapered, R Fr angular contact)"
    return (f"induced axial forces F_iA = {fmt(pl.Fi_A)}, F_iB = {fmt(pl.Fi_B)} from {how}; {pl.case}: "
            f"Fa_A = {fmt(pl.Fa_A)}, Fa_B = {fmt(pl.Fa_B)}; P_A = {fmt(pl.P_A)}, P_B = {fmt(pl.P_B)}")


def _worse(results: list[Any], names: tuple[str, str], note: str) -> Any:
    worst = max(range(2), key=lambda i: results[i].utilisation)
    other = results[1 - worst]
    return dataclasses.replace(results[worst], notes=(
        f"bearing {names[worst]} governs; bearing {names[1 - worst]}: u = {other.utilisation:.3g}", note,
        *results[worst].notes))


def _timken_equivalent(b: RollingBearing, Fr: Any, P: Any) -> EquivalentLoad:
    """Timken's F_e = 0.4 F_r + K F_a (X = 0.4, Y = K), or F_e = F_r (X = 1, Y = 0) ([4] Eq. 11-19)."""
    thrust = P.m_as("N") > Fr.m_as("N") * (1 + 1e-12)
    return EquivalentLoad(P=P, X=0.4 if thrust else 1.0, Y=float(b.K or 0.0) if thrust else 0.0, e=float("nan"),
                          relative_axial_load=0.0)


def _pair_life(c: AdjustedPair, loads: dict[str, Any], ctx: Any) -> Any:
    pl, FrA, FrB = _pair_loads(c, loads)
    req = c.required_life if c.required_life is not None else ctx.requirements["bearing_life"]
    rs = [bc.check_bearing_life(b, Fr, Fa, loads["speed"], req, reliability=c.reliability,
                                equivalent=_timken_equivalent(b, Fr, P) if c.rule == "timken" else None)
          for b, Fr, Fa, P in ((c.A, FrA, pl.Fa_A, pl.P_A), (c.B, FrB, pl.Fa_B, pl.P_B))]
    return _worse(rs, ("A", "B"), _note(pl, c.rule))


def _pair_static(c: AdjustedPair, loads: dict[str, Any], ctx: Any) -> Any:
    pl, FrA, FrB = _pair_loads(c, loads)
    rs = [bc.check_bearing_static_safety(b, Fr, Fa, required_s0=ctx.required_sf)
          for b, Fr, Fa in ((c.A, FrA, pl.Fa_A), (c.B, FrB, pl.Fa_B))]
    return _worse(rs, ("A", "B"), _note(pl, c.rule))


def _pair_speed(c: AdjustedPair, loads: dict[str, Any], ctx: Any) -> Any:
    rs = [bc.check_bearing_speed(b, loads["speed"]) for b in (c.A, c.B)]
    return _worse(rs, ("A", "B"), "both bearings turn at the shaft speed")


PAIR = REGISTRY.register(ComponentType(
    name="adjusted_bearing_pair",
    doc="Two tapered roller or angular contact ball bearings adjusted against each other (direct or indirect "
        "mounting): the induced axial forces (ISO/SKF 0.5 Fr/Y, R Fr; or Timken 0.47 Fr/K, Shigley 10th ed. "
        "Sec. 11-9) give each bearing's axial and equivalent load; life, static safety and speed of the worse.",
    fields=(
        Field("model", "str", "catalogue designation of both bearings (or model_A and model_B)"),
        Field("model_A", "str", "bearing A: the one the external axial force pushes against"),
        Field("model_B", "str", "bearing B"),
        Field("rule", "choice", "induced-load rule: iso (the rows' factors, SKF) or timken (0.47 Fr/K, "
                                "F_e = 0.4 F_r + K F_a)", default="iso", choices=("iso", "timken")),
        Field("K", "float", "Timken thrust factor K of both bearings, instead of the catalogue's"),
        *_COMMON,
    ),
    build=lambda p, ctx: _build_pair(p, ctx),
    loads=(
        Field("radial_force_A", "force", "radial load on bearing A"),
        Field("radial_force_B", "force", "radial load on bearing B"),
        Field("axial_force", "force", "external axial force on the shaft, toward bearing A (>= 0)"),
        Field("speed", "angular_velocity", "shaft speed"),
    ),
    checks=(
        CheckSpec.of(bc.check_bearing_life, _pair_life, needs=("radial_force_A|radial_force_B", "speed")),
        CheckSpec.of(bc.check_bearing_static_safety, _pair_static, needs=("radial_force_A|radial_force_B",)),
        CheckSpec.of(bc.check_bearing_speed, _pair_speed, needs=("speed",)),
    ),
))
