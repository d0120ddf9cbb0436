"""The ``drive`` component: motor, gearhead, transmission, load (profiles: :mod:`.profiles`).

A ``drive`` is the unit the motor-fit checks run on: one motor (catalogue name or inline data), an
optional gearhead, transmission stages from the motor side (``screw`` naming a ``lead_screw``
component, ``drum``, ``belt``, ``direct``) and a linear or rotary load moved along a profile. The
drive is a :class:`mechverify.motion.drive.Drive` (load composition, friction variants, demands per load
case); the checks are those of :mod:`mechverify.checks.motors`, run per case and variant by
:mod:`mechverify.checks.drives`, one design-file check each. Table parsing: :mod:`.drive_parsing`.

Load cases: the motor-fit checks need no load-case data (the drive runs its own profile once). When
load cases name the drive, every such case runs instead, with its replacements (profile, mass,
external force, ...) applied to the drive's own load; the framework keeps the governing case.
A screw whose nut gives a friction range is evaluated at both ends (mu_max: motoring torque,
mu_min: braking torque when the load back-drives the screw) and the worse governs.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Mapping
from typing import Any

from mechverify.checks import drives as dc
from mechverify.checks.result import CheckResult
from mechverify.design.adapters.drive_parsing import parse_gearhead, parse_motor, parse_stages
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError, MechverifyError
from mechverify.motion.drive import LINEAR_KEYS, ROTARY_KEYS, CaseDemands, Drive, load_kind
from mechverify.units import Q


def _demands(drive: Drive, ctx: Any) -> list[CaseDemands]:
    """The drive's demands in every load case that names it (or its own profile once)."""
    design = getattr(ctx, "design", None) if ctx is not None else None
    if design is None:
        return drive.demands()
    cases = [(case, comps[drive.name]) for case, comps in design.data.load_cases.items() if drive.name in comps]
    return drive.demands(cases, design.profiles)


def demands(drive: Drive, ctx: Any) -> list[CaseDemands]:
    """:func:`_demands`, computed once per design (every motor check of a verify asks for the same). The memo holds
    the design weakly: the design holds the drive, and a cycle would leave every study sample to the garbage
    collector (its collections cost 15-20 % of a Monte Carlo sample of the lift)."""
    design = getattr(ctx, "design", None) if ctx is not None else None
    memo = drive.memo.get("demands")
    if design is not None and memo is not None and memo[0]() is design:
        return memo[1]
    out = _demands(drive, ctx)
    if design is not None:
        drive.memo["demands"] = (weakref.ref(design), out)
    return out


def _joint_load(p: Mapping[str, Any], ctx: Mapping[str, Any]) -> Mapping[str, Any]:
    """``p`` with a zero load (``inertia`` 0 on a revolute joint, ``mass`` 0 on a prismatic one) when the drive's
    profile is a ``joint_motion`` and neither is given: the joint's effort along the path (the arm's inertia,
    Coriolis, centripetal and gravity terms) and its inertia come with the profile, and the drive's own load only
    adds to them (``DriveTrain.demand``: effort = load + joint effort, inertia = load + joint inertia)."""
    if "mass" in p or "inertia" in p:
        return p
    prof = ctx.get("profile_objects", {}).get(p.get("profile"))
    if getattr(type(prof), "joint_effort", None) is None:  # not a mechanism's joint motion
        return p
    return {**p, **({"inertia": Q(0.0, "kg*m**2")} if prof.kind == "angle" else {"mass": Q(0.0, "kg")})}


def _build_drive(p: Mapping[str, Any], ctx: Mapping[str, Any]) -> Drive:
    errors: list[str] = []

    def attempt(f: Callable[[], Any]) -> Any:
        try:
            return f()
        except MechverifyError as exc:
            errors.append(str(exc))
            return None

    with_joint = attempt(lambda: _joint_load(p, ctx))  # None: the profile's arm is invalid (said once, here)
    p = p if with_joint is None else with_joint
    m = attempt(lambda: parse_motor(p))
    g = attempt(lambda: parse_gearhead(p))
    stages = attempt(lambda: parse_stages(list(p.get("transmission", [])), ctx))
    kind = None if with_joint is None else attempt(lambda: load_kind(p))  # not again as a missing mass
    limit = p.get("inertia_ratio_limit")
    if limit is not None and not limit > 0:
        errors.append(f"inertia_ratio_limit: must be positive, got {limit!r}")
    if errors:
        raise InputError("; ".join(errors))
    load = {k: p[k] for k in (*LINEAR_KEYS, *ROTARY_KEYS) if k in p}
    for key, unit in (("ambient_temperature", "degC"), ("bus_capacitance", "F")):
        if key in p:
            try:
                Q(p[key]).to(unit)
            except Exception:  # pint raises several types for text that is not such a quantity
                raise InputError(f"{key}: expected a value in {unit} units, got {p[key]!r}") from None
    d = Drive(p["_name"], m, g, tuple(tuple(s) for s in stages), load, kind, p["profile"],
              p.get("cycle_time"), p.get("supply_voltage"), p.get("driver_current"), limit,
              ambient_temperature=p.get("ambient_temperature"), bus_capacitance=p.get("bus_capacitance"),
              overvoltage_limit=p.get("overvoltage_limit"))
    d.memo["profiles"] = dict(ctx.get("profile_objects", {}))  # for outputs, which get no design context
    # validate the chain (linear/rotary) and the own profile now, so the errors carry the drive's key path
    tr = d.trains()[0][1]
    prof = ctx.get("profile_objects", {}).get(p["profile"])
    if prof is not None and prof.kind != tr.load.kind:
        words = {"length": "linear", "angle": "rotary"}
        raise InputError(f"profile: {p['profile']!r} is a {words[prof.kind]} move but the load is "
                         f"{words[tr.load.kind]} ({'mass' if kind == 'length' else 'inertia'} given)")
    if prof is not None and "cycle_time" in p and p["cycle_time"] < prof.duration * (1 - 1e-9):
        raise InputError(f"cycle_time: {p['cycle_time']:~P} is shorter than the profile {p['profile']!r} "
                         f"({prof.duration:~P})")
    return d



def _output_torque_peak(d: Drive, loads: Any) -> Any:
    """Largest |torque| over the profile (and the friction variants) at the output of the last stage with a rotary
    output - the shaft that drives the last linear stage (a drum, a screw) or carries a rotary load - or at the motor
    shaft when no stage has a rotary output. Read by a ``shaft`` as its ``torque`` (issue 21)."""
    import numpy as np

    cases = [("", dict(loads))] if loads else []
    ((_, _, variants),) = d.demands(cases, d.memo.get("profiles", {}))
    peak = 0.0
    for _, dem in variants:
        rotary = [s for s in dem.stages if s.output_kind == "angle"]
        peak = max(peak, float(np.max(np.abs(rotary[-1].output_effort if rotary else dem.motor_torque))))
    return Q(peak, "N*m")


def _run(fn: Callable[..., CheckResult]) -> Callable[[Drive, Any, Any], list[CheckResult]]:
    """The design-file runner of drive check ``fn``: every load case and friction variant, the worst per case."""

    def run(drive: Drive, loads: Any, ctx: Any) -> list[CheckResult]:
        try:
            dem = demands(drive, ctx)
        except MechverifyError as exc:  # report a bad load case at one check, not at every one
            if drive.memo.setdefault("reported", {}).setdefault(str(exc), fn) is not fn:
                return []
            raise
        entry = ctx.design.data.components.get(ctx.component) if getattr(ctx, "design", None) is not None else None
        asked = entry is not None and entry.checks.get(fn.__name__.removeprefix("check_"), {}).get("enabled") is True
        return dc.run_drive_check(fn, drive, dem, required_sf=float(getattr(ctx, "required_sf", 1.0) or 1.0),
                                  asked=asked)

    return run


DRIVE = REGISTRY.register(ComponentType(
    name="drive",
    doc="A motor (catalogue name or inline data) with an optional gearhead and transmission stages moving a linear "
        "or rotary load along a motion profile; the motor-fit checks run on the torque the profile demands.",
    fields=(
        Field("motor", "str", "catalogue motor name or alias (see `mechverify motors`)"),
        Field("motor_data", "table", "inline motor: type = dc | stepper | servo | gearmotor and its datasheet values"),
        Field("gearhead", "str", "catalogue gearhead name or alias"),
        Field("gearhead_data", "table", "inline gearhead: ratio, efficiency, continuous_torque, ..."),
        Field("transmission", "list", "stages from the motor side: screw, drum, belt, direct (tables with type)",
              item="table"),
        Field("profile", "ref", "the move (a name in [profiles])", required=True, ref="profiles"),
        Field("cycle_time", "time", "duty cycle for the RMS torque (standstill after the move included)"),
        Field("mass", "mass", "linear load: moving mass (default 0 on a prismatic joint's joint_motion profile)"),
        Field("incline", "angle", "linear load: axis angle above horizontal (90 deg = vertical lift, +x upward)"),
        Field("friction_coefficient", "dimensionless", "linear load: guide friction coefficient (mu·m·g·cos)"),
        Field("friction_force", "force", "linear load: constant friction force against the motion"),
        Field("external_force", "force", "linear load: constant force against positive motion"),
        Field("inertia", "inertia", "rotary load: inertia about the output axis (default 0 on a revolute joint's "
                                    "joint_motion profile)"),
        Field("gravity_torque", "torque", "rotary load: unbalance m·g·r (torque = gravity_torque·cos(x + phase))"),
        Field("gravity_phase", "angle", "rotary load: arm angle above horizontal at the profile's start"),
        Field("friction_torque", "torque", "rotary load: constant friction torque against the motion"),
        Field("external_torque", "torque", "rotary load: constant torque against positive motion"),
        Field("supply_voltage", "voltage", "DC motors: supply (driver output) voltage"),
        Field("driver_current", "current", "maximum current of the driver"),
        Field("inertia_ratio_limit", "float", "allowed load-to-rotor inertia ratio (default 10)"),
        Field("ambient_temperature", "str", "motor ambient temperature (motor_winding_temperature; default '25 degC')"),
        Field("bus_capacitance", "str", "supply/driver bus capacitance for drive_regeneration, e.g. '2200 uF'"),
        Field("overvoltage_limit", "voltage", "driver's overvoltage limit for drive_regeneration"),
    ),
    build=lambda p, ctx: _build_drive(p, ctx),
    loads=(
        Field("profile", "ref", "the move in this case (replaces the drive's)", ref="profiles"),
        Field("cycle_time", "time", "duty cycle in this case"),
        Field("mass", "mass", "load mass (replaces)"),
        Field("payload", "mass", "mass added to the load"),
        Field("inertia", "inertia", "load inertia (replaces)"),
        Field("external_force", "force", "external force (replaces)"),
        Field("external_torque", "torque", "external torque (replaces)"),
        Field("gravity_torque", "torque", "gravity torque (replaces)"),
        Field("load_factor", "float", "multiplies mass or inertia, external force or torque and gravity torque"),
    ),
    checks=tuple(CheckSpec.of(fn, _run(fn)) for fn in dc.DRIVE_CHECKS),  # in report order
    outputs=(Output("output_torque_peak", "torque", "largest torque at the output of the last rotary stage (the shaft "
                    "driving a drum or screw, or carrying a rotary load) over the profile; the motor torque without "
                    "a rotary stage", _output_torque_peak),),
))
