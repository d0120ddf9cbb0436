"""Motion profiles (section ``profiles`` of a design file): the moves a ``drive`` follows.

Each type builds a profile of :mod:`mechverify.motion.profiles` (trapezoidal, triangular, s-curve,
dwell, sequence, sampled); a ``drive`` (:mod:`mechverify.design.adapters.drives`) names one, and a
load case may name another.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from mechverify.design.spec import REGISTRY, ComponentType, Field
from mechverify.errors import InputError, UnitError
from mechverify.motion import profiles as pr
from mechverify.units import Q, as_quantity, to_si


def _trapezoidal(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    kw = {k: p[k] for k in ("max_velocity", "acceleration", "duration", "deceleration") if k in p}
    return pr.trapezoidal(p["distance"], allow_triangular=p.get("allow_triangular", True), **kw)


def _triangular(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.triangular(p["distance"], **{k: p[k] for k in ("duration", "acceleration") if k in p})


def _s_curve(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.s_curve(p["distance"], max_velocity=p["max_velocity"], acceleration=p["acceleration"], jerk=p["jerk"])


def _dwell(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.dwell(p["duration"], "angle" if p.get("axis") == "rotary" else "length")


def _profile_obj(name: str, ctx: Mapping[str, Any], stack: tuple[str, ...]) -> Any:
    """The built profile ``name``, building it first when it comes later in the file."""
    entry = ctx["profiles"][name]
    if entry.obj is None:
        if any(f.required and f.name not in entry.params for f in entry.type.fields):
            raise InputError(f"steps: profile {name!r} is invalid (see its own errors)")
        if name in stack:
            raise InputError(f"steps: sequence refers to itself through {' -> '.join((*stack, name))}")
        if entry.type.name == "sequence":
            entry.obj = _sequence({**entry.params, "_name": name}, ctx, (*stack, name))
        else:
            entry.obj = entry.type.build({**entry.params, "_name": name}, ctx)
    return entry.obj


def _sequence(p: Mapping[str, Any], ctx: Any, stack: tuple[str, ...] = ()) -> pr.Profile:
    parts = []
    for i, name in enumerate(p["steps"]):
        obj = _profile_obj(name, ctx, stack or (p["_name"],))
        if not isinstance(obj, pr.Profile):
            raise InputError(f"steps[{i}]: {name!r} is a sampled profile; a sequence joins analytic moves only")
        parts.append(obj)
    return pr.sequence(*parts)


def _sampled(p: Mapping[str, Any], ctx: Any) -> pr.SampledProfile:
    x = p["x"]
    kind = "length"
    try:
        as_quantity(x[0], "length", "x[0]")
    except UnitError:
        kind = "angle"
    xs = Q(np.array([to_si(v, kind, f"x[{i}]") for i, v in enumerate(x)]), "m" if kind == "length" else "rad")
    ts = Q(np.array([to_si(v, "time", f"t[{i}]") for i, v in enumerate(p["t"])]), "s")
    return pr.sampled(ts, xs)


_DIST = Field("distance", "str", "move length or angle, e.g. '200 mm' or '90 deg' (negative moves backwards)",
              required=True)
_VMAX = "peak speed: 'mm/s' for a linear move, 'rpm' or 'deg/s' for a rotary one"
_ACC = "acceleration: 'm/s^2' or 'rad/s^2'"
for _ct in (
    ComponentType("trapezoidal", "Trapezoidal velocity move over a distance; give two of max_velocity, acceleration "
                  "and duration (Biagiotti & Melchiorri, Trajectory Planning for Automatic Machines, 2008, Sec. 3.2).",
                  fields=(_DIST, Field("max_velocity", "str", _VMAX), Field("acceleration", "str", _ACC),
                          Field("duration", "time", "move time"),
                          Field("deceleration", "str", "deceleration if it differs (with max_velocity and "
                                                       "acceleration)"),
                          Field("allow_triangular", "bool", "a move too short to reach max_velocity becomes "
                                                            "triangular (false: an error)", default=True)),
                  build=_trapezoidal, section="profiles"),
    ComponentType("triangular", "Triangular velocity move: accelerate half the time, decelerate the other half; "
                  "give duration or acceleration (Biagiotti & Melchiorri 2008, Sec. 3.2).",
                  fields=(_DIST, Field("duration", "time", "move time"), Field("acceleration", "str", _ACC)),
                  build=_triangular, section="profiles"),
    ComponentType("s_curve", "Jerk-limited (double-S, seven-segment) move from rest to rest (Biagiotti & Melchiorri "
                  "2008, Sec. 3.4).",
                  fields=(_DIST, Field("max_velocity", "str", _VMAX, required=True),
                          Field("acceleration", "str", _ACC, required=True),
                          Field("jerk", "str", "jerk: 'm/s^3' or 'rad/s^3'", required=True)),
                  build=_s_curve, section="profiles"),
    ComponentType("dwell", "Standing still (holding the load) for a time.",
                  fields=(Field("duration", "time", "dwell time", required=True),
                          Field("axis", "choice", "linear or rotary (only matters when the dwell stands alone)",
                                choices=("linear", "rotary"), default="linear")),
                  build=_dwell, section="profiles"),
    ComponentType("sequence", "Profiles one after another, each starting where the previous ended.",
                  fields=(Field("steps", "list", "names of other profiles, in order", required=True, item="ref",
                                ref="profiles"),),
                  build=lambda p, ctx: _sequence(p, ctx), section="profiles"),
    ComponentType("sampled", "A measured or planned move as samples; velocity and acceleration by central "
                  "differences (numpy.gradient), so smooth noisy data first.",
                  fields=(Field("t", "list", "times, strictly increasing", required=True, item="time"),
                          Field("x", "list", "positions (lengths or angles), as many as t", required=True,
                                item="str")),
                  build=_sampled, section="profiles"),
):
    REGISTRY.register(_ct)
