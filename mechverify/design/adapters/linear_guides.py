"""``linear_guide`` (profile-rail carriages or linear ball bushings: rated travel life and static safety of the
most loaded block) and ``sliding_carriage`` (a carriage on plain bushings: the drive force under a moment,
binding)."""

from __future__ import annotations

from typing import Any

import pint

from mechverify.checks import linear_guides as lc
from mechverify.components.linear_guides import (
    BUSHING_ROW_FACTOR,
    block_equivalent_load,
    guide_block_loads,
    sliding_carriage_drive_force,
)
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.units import Q, fmt, to_si


def _distance(v: Any, name: str) -> pint.Quantity:
    q = Q(v) if isinstance(v, str) else v
    if not isinstance(q, pint.Quantity) or not to_si(q, "length", name) > 0:
        raise InputError(f"{name}: give a positive distance such as '50 km', got {v!r}")
    return q.to("km")


def _build_guide(p: dict[str, Any], ctx: Any) -> dict[str, Any]:
    for key in ("rails", "blocks_per_rail"):  # here, not when a check runs: once, at the key
        if p[key] not in (1, 2):
            raise InputError(f"{key}: expected 1 or 2, got {p[key]!r}")
    for key in ("rail_spacing", "block_spacing"):
        if key in p and not to_si(p[key], "length", key) > 0:
            raise InputError(f"{key}: must be positive, got {fmt(p[key])}")
    rows = p.get("ball_rows")
    f = 1.0
    if rows is not None:
        if int(rows) not in BUSHING_ROW_FACTOR:
            raise InputError(f"ball_rows must be one of {sorted(BUSHING_ROW_FACTOR)} (THK linear bushing Table 1), "
                             f"got {rows!r}")
        f = BUSHING_ROW_FACTOR[int(rows)]
    g = lc.LinearGuide(C=f * p["dynamic_load_rating"], C0=f * p["static_load_rating"],
                       rating_distance=_distance(p["rating_distance"], "rating_distance"), kind=p["rolling"],
                       fH=float(p["fH"]), fT=float(p["fT"]), fC=float(p["fC"]), fW=float(p["fW"]),
                       M0_roll=p.get("M0_roll"), M0_pitch=p.get("M0_pitch"), M0_yaw=p.get("M0_yaw"), name=p["_name"])
    layout = dict(rails=int(p["rails"]), blocks_per_rail=int(p["blocks_per_rail"]),
                  rail_spacing=p.get("rail_spacing"), block_spacing=p.get("block_spacing"))
    if "required_travel" in p:
        travel = _distance(p["required_travel"], "required_travel")
        per_hour = None
        if "stroke" in p and "cycles_per_minute" in p:
            per_hour = to_si(p["stroke"], "length") * 2 * float(p["cycles_per_minute"]) * 60 / 1e3
    elif "required_life" in p:
        if "stroke" not in p or "cycles_per_minute" not in p:
            raise InputError("required_life (hours) needs stroke and cycles_per_minute (L_h = L/(2 l_s n_1 60))")
        per_hour = to_si(p["stroke"], "length") * 2 * float(p["cycles_per_minute"]) * 60 / 1e3
        travel = Q(p["required_life"].m_as("hour") * per_hour, "km")
    else:
        travel, per_hour = None, None
    return {"guide": g, "layout": layout, "travel": travel, "per_hour": per_hour}


def _block(c: dict[str, Any], loads: dict[str, Any]) -> pint.Quantity:
    g = c["guide"]
    for key in ("force", "lateral_force"):  # the method takes magnitudes (|F|): a sign would be dropped silently
        if key in loads and loads[key].magnitude < 0:
            raise InputError(f"{key}: expected a magnitude >= 0 (the sign is not a direction here: the block "
                             f"loads use |F|), got {fmt(loads[key])}")
    Fr, Ft, M_roll, M_pitch = guide_block_loads(loads.get("force", Q(0, "N")),
                                                offset_x=loads.get("offset_x", Q(0, "m")),
                                                offset_y=loads.get("offset_y", Q(0, "m")),
                                                lateral=loads.get("lateral_force", Q(0, "N")), **c["layout"])
    return block_equivalent_load(Fr, Ft, C0=g.C0, M_roll=M_roll, M_pitch=M_pitch, M0_roll=g.M0_roll,
                                 M0_pitch=g.M0_pitch).to("N")


def _life(c: dict[str, Any], loads: dict[str, Any], ctx: Any) -> Any:
    if c["travel"] is None:
        raise InputError("linear_guide_life needs required_travel (e.g. '5000 km'), or required_life with stroke "
                         "and cycles_per_minute")
    return lc.check_linear_guide_life(c["guide"], _block(c, loads), c["travel"], km_per_hour=c["per_hour"])


_GUIDE_FIELDS = (
    Field("dynamic_load_rating", "force", "C of one block (carriage or bushing), from the maker", required=True),
    Field("static_load_rating", "force", "C0 of one block", required=True),
    Field("rating_distance", "str", "the distance C is rated for: '50 km' (THK, HIWIN) or '100 km'",
          default="50 km"),
    Field("rolling", "choice", "rolling elements: ball (p = 3) or roller (10/3)", default="ball",
          choices=("ball", "roller")),
    Field("fH", "float", "hardness factor (1 for 58..64 HRC raceways)", default=1.0),
    Field("fT", "float", "temperature factor (1 below 100 degC)", default=1.0),
    Field("fC", "float", "contact factor (blocks close together: 0.81 for 2, THK)", default=1.0),
    Field("fW", "float", "load factor (1..1.5 no shock, 1.5..2 vibration, 2..3.5 shock; THK)", default=1.0),
    Field("M0_roll", "torque", "static rolling-moment rating of one block (for a single rail)"),
    Field("M0_pitch", "torque", "static pitching-moment rating of one block (for a single block per rail)"),
    Field("M0_yaw", "torque", "static yawing-moment rating of one block"),
    Field("ball_rows", "int", "linear ball bushing: number of ball rows, with the load between two rows (THK "
                              "Table 1 factor on C and C0: 4 rows 1.41, 5 rows 1.46, 6 rows 1.28, 8 rows 1.25)"),
    Field("rails", "int", "number of rails (or shafts): 1 or 2", default=2),
    Field("blocks_per_rail", "int", "blocks (or bushings) per rail: 1 or 2", default=2),
    Field("rail_spacing", "length", "distance between the two rails"),
    Field("block_spacing", "length", "distance between the two blocks on a rail"),
    Field("required_travel", "str", "required travel life, e.g. '5000 km'"),
    Field("required_life", "time", "required life in hours, with stroke and cycles_per_minute"),
    Field("stroke", "length", "stroke length l_s"),
    Field("cycles_per_minute", "float", "reciprocating cycles per minute n_1"),
)

GUIDE = REGISTRY.register(ComponentType(
    name="linear_guide",
    doc="Profile-rail carriages or linear ball bushings on one or two rails (THK, HIWIN method): the most loaded "
        "block's equivalent load from the force, its offsets and the lateral force, its rated travel life "
        "(L = (fH fT fC/fW C/P)^p L_C) and static safety fS = C0/P0.",
    fields=_GUIDE_FIELDS,
    build=lambda p, ctx: _build_guide(p, ctx),
    loads=(
        Field("force", "force", "load normal to the rails (magnitude), at offset_x/offset_y from the block pattern's "
                                "centre"),
        Field("offset_x", "length", "offset of the force across the rails"),
        Field("offset_y", "length", "offset of the force along the rails"),
        Field("lateral_force", "force", "force along the rails' width (shared by the blocks)"),
    ),
    checks=(
        CheckSpec.of(lc.check_linear_guide_life, _life, needs=("force|lateral_force",)),
        CheckSpec.of(lc.check_linear_guide_static_safety, lambda c, loads, ctx: lc.check_linear_guide_static_safety(
            c["guide"], _block(c, loads), required_fs=ctx.required_sf), needs=("force|lateral_force",)),
    ),
))


# ------------------------------------------------------------------------------------------ sliding carriage
def _build_sliding(p: dict[str, Any], ctx: Any) -> lc.SlidingGuide:
    mu = float(p["friction"])
    if not 0 <= mu < 5:
        raise InputError(f"friction: expected a coefficient in 0..5, got {p['friction']!r}")
    return lc.SlidingGuide(mu=mu, length=p["contact_length"], load_offset=p.get("load_offset", Q(0, "m")),
                           drive_offset=p.get("drive_offset", Q(0, "m")), available_force=p.get("available_force"),
                           name=p["_name"])


def _resisting(loads: dict[str, Any]) -> pint.Quantity:
    R = loads["resisting_force"].to("N")
    if R.magnitude < 0:
        raise InputError(f"resisting_force must be >= 0 (a magnitude), got {fmt(R)}")
    return R


def _drive_force(c: lc.SlidingGuide, loads: Any) -> pint.Quantity:
    if loads is None or "resisting_force" not in loads:
        raise InputError("drive_force needs the carriage's resisting_force in the load case")
    return sliding_carriage_drive_force(_resisting(loads), mu=c.mu, length=c.length, load_offset=c.load_offset,
                                        drive_offset=c.drive_offset).F


SLIDING = REGISTRY.register(ComponentType(
    name="sliding_carriage",
    doc="A carriage on plain bushings (rods or rails): the drive force needed when the load or the drive acts off "
        "the guide axis (edge loads N = |M|/L, friction 2 mu |M|/L; the igus/PBC 2:1 rule), against the force the "
        "drive provides; jamming when 2 mu e/L >= 1.",
    fields=(
        Field("friction", "float", "friction coefficient of the bushings on the rods (the upper value of a range: "
                                   "it is the conservative one here)", required=True),
        Field("contact_length", "length", "bushing length, or the span between two bushings on one rod",
              required=True),
        Field("load_offset", "length", "offset of the resisting force (load, weight) from the guide axis, across "
                                       "it, in the plane of the moment"),
        Field("drive_offset", "length", "offset of the drive force (nut, belt clamp) from the guide axis, same axis"),
        Field("available_force", "force", "drive force available (what the drive was sized for)"),
    ),
    build=lambda p, ctx: _build_sliding(p, ctx),
    loads=(Field("resisting_force", "force", "force along the guide the drive works against (load, weight)"),),
    outputs=(Output("drive_force", "force", "drive force needed (load plus the guide friction from the moment)",
                    _drive_force, needs=("resisting_force",)),),
    checks=(
        CheckSpec.of(lc.check_carriage_binding, lambda c, loads, ctx: lc.check_carriage_binding(
            c, _resisting(loads)), needs=("resisting_force",)),
    ),
))
