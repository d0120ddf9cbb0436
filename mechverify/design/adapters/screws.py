"""``lead_screw``: a lead screw with its nut (thread, supports, nut material, friction range, limits)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from mechverify.checks import screws as sc
from mechverify.components.power_screw import LeadScrew, Nut
from mechverify.components.threads import generic
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError

END_CASES = ("fixed-free", "pinned-pinned", "supported-supported", "fixed-pinned", "fixed-supported", "fixed-fixed")


@dataclass(frozen=True)
class ScrewAndNut:
    """A lead screw and the nut that runs on it."""

    screw: LeadScrew
    nut: Nut


GENERIC = ("lead", "starts", "pitch_diameter", "flank_angle", "major_diameter", "minor_diameter", "flank_engagement")


def _thread(p: dict[str, Any]) -> Any:
    """The designation, or a catalogue screw from lead, starts and pitch diameter (components.threads.generic)."""
    given = [k for k in GENERIC if k in p]
    if "thread" in p:
        if given:
            raise InputError(f"give either thread (a designation) or {', '.join(given)}, not both")
        return p["thread"]
    missing = [k for k in ("lead", "starts", "pitch_diameter") if k not in p]
    if missing:
        raise InputError("give thread (a designation such as 'Tr10x2'), or lead, starts and pitch_diameter for a "
                         f"catalogue screw (missing: {', '.join(missing)})")
    return generic(p["lead"], p["starts"], p["pitch_diameter"], p.get("flank_angle", "15 deg"),
                   **pick(p, d="major_diameter", d3="minor_diameter", H1="flank_engagement"))


def _build(p: dict[str, Any], ctx: dict[str, Any]) -> ScrewAndNut:
    screw = LeadScrew(name=p["_name"], thread=_thread(p), **pick(p, "length", "material", "end_supports"))
    nut = Nut(name=f"{p['_name']} nut", **pick(p, "mu_min", "mu_max", material="nut_material", length="nut_length",
                                                  engaged_threads="nut_engaged_threads", p_allow="nut_p_allow",
                                                  pv_allow="nut_pv_allow"))
    return ScrewAndNut(screw, nut)


def _rotational_speed(c: ScrewAndNut, loads: Any) -> Any:
    return loads["rotational_speed"] if "rotational_speed" in loads else c.screw.rotational_speed(loads["speed"])


def _drive_torque(c: ScrewAndNut, loads: Any) -> Any:
    return c.screw.raise_torque(loads["axial_force"], c.nut.require_mu()[1])


OUTPUTS = (  # values other components read as "<screw>.<name>" (design/parameters.py)
    Output("rotational_speed", "angular_velocity", "screw speed (from the nut's linear speed when not given): "
           "the speed of the bearings that carry the screw", _rotational_speed, needs=("speed|rotational_speed",)),
    Output("support_axial_force", "force", "axial force the screw passes to its thrust bearing (= axial_force)",
           lambda c, loads: abs(loads["axial_force"]), needs=("axial_force",)),
    Output("drive_torque", "torque", "torque to raise the axial force at mu_max (Hamrock 3rd ed. Eq. 16.10): "
           "the external torque of a drive that turns the screw without a screw stage", _drive_torque,
           needs=("axial_force",)),
)


def _speed(loads: dict[str, Any]) -> dict[str, Any]:
    return pick(loads, "rotational_speed") if "rotational_speed" in loads else {"speed": loads["speed"]}


TYPE = REGISTRY.register(ComponentType(
    name="lead_screw",
    doc="A lead screw and its nut: thread by designation (Tr10x2, Tr16x8P4, 1/2-10 ACME) or, for a catalogue "
        "screw, by lead, starts and pitch diameter; length between the supports, end supports, nut material, "
        "friction range and limits.",
    fields=(
        Field("thread", "str", "thread designation, e.g. 'Tr10x2' (or give lead, starts, pitch_diameter)"),
        Field("lead", "length", "catalogue screw: lead (axial advance per turn)"),
        Field("starts", "int", "catalogue screw: number of starts"),
        Field("pitch_diameter", "length", "catalogue screw: pitch diameter d2"),
        Field("flank_angle", "angle", "catalogue screw: half thread angle (15 deg trapezoidal, 14.5 deg Acme)"),
        Field("major_diameter", "length", "catalogue screw: major diameter d (default d2 + P/2)"),
        Field("minor_diameter", "length", "catalogue screw: minor diameter d3 (default by ISO 2904 proportions)"),
        Field("flank_engagement", "length", "catalogue screw: flank engagement H1 (default P/2)"),
        Field("length", "length", "length between the end supports", required=True),
        Field("material", "material", "screw material"),
        Field("end_supports", "choice", "end fixity for buckling and whirling", choices=END_CASES,
              default="fixed-pinned"),
        Field("nut_material", "material", "nut material (friction and limits are taken from it when not given)"),
        Field("nut_length", "length", "length of the nut's thread"),
        Field("nut_engaged_threads", "float", "engaged turns (instead of nut_length)"),
        Field("mu_min", "dimensionless", "lowest friction coefficient nut/screw (self-locking, holding)"),
        Field("mu_max", "dimensionless", "highest friction coefficient nut/screw (drive torque)"),
        Field("nut_p_allow", "pressure", "allowable flank pressure of the nut"),
        Field("nut_pv_allow", "pv", "pv limit of the nut material"),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("axial_force", "force", "axial force on the screw (magnitude)"),
        Field("speed", "velocity", "linear speed of the nut"),
        Field("rotational_speed", "angular_velocity", "screw speed"),
        Field("holding_torque", "torque", "torque available to hold the load at rest (motor detent/holding, brake)"),
        Field("compressive", "bool", "the axial force compresses the screw between its supports", default=True),
    ),
    checks=(
        CheckSpec.of(sc.check_self_locking, lambda c, loads, ctx: sc.check_self_locking(c.screw, c.nut)),
        CheckSpec.of(sc.check_holding_torque, lambda c, loads, ctx: sc.check_holding_torque(
            c.screw, c.nut, loads["axial_force"], loads["holding_torque"]),
            needs=("axial_force", "holding_torque"), default=False),
        CheckSpec.of(sc.check_nut_flank_pressure, lambda c, loads, ctx: sc.check_nut_flank_pressure(
            c.screw, c.nut, loads["axial_force"]), needs=("axial_force",)),
        CheckSpec.of(sc.check_nut_pv, lambda c, loads, ctx: sc.check_nut_pv(c.screw, c.nut, loads["axial_force"],
                                                                            **_speed(loads)),
                     needs=("axial_force", "speed|rotational_speed")),
        CheckSpec.of(sc.check_screw_strength, lambda c, loads, ctx: sc.check_screw_strength(
            c.screw, loads["axial_force"], nut=c.nut), needs=("axial_force",)),
        CheckSpec.of(sc.check_screw_buckling, lambda c, loads, ctx: sc.check_screw_buckling(
            c.screw, loads["axial_force"]) if loads.get("compressive", True) else [], needs=("axial_force",)),
        CheckSpec.of(sc.check_screw_critical_speed, lambda c, loads, ctx: sc.check_screw_critical_speed(
            c.screw, c.screw.rotational_speed(loads["speed"]) if "speed" in loads else loads["rotational_speed"]),
            needs=("speed|rotational_speed",)),
    ),
    outputs=OUTPUTS,
))
