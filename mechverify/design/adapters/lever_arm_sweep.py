"""``lever_arm_sweep``: the parallelogram lever arm (seed 000) swept over its joint ranges with the links' self-weight
and a payload ``W`` at the tool point; its outputs are the loads of the motors and members that other components
check (``"arm.shoulder_peak_torque"``, ``"arm.OA_tension"``, ...), so a parameter ``W`` moves every check
(``mechverify size design.toml --vary parameters.W --until governing``). Parsing only: the sweep is
:func:`mechverify.mechanisms.lever_arm.sweep_envelope` (linear in ``W``: solved once per geometry and masses)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from mechverify.design.spec import REGISTRY, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.mechanisms import lever_arm as la
from mechverify.mechanisms.sweep import ActuatorDemand, LinearSweep, MemberDemand
from mechverify.units import Q, fmt

_DIMS = ("b", "c", "d", "p", "q", "r")
_BODIES = tuple(dict.fromkeys(body for body, _ in la.MEMBERS.values()))


@dataclass(frozen=True, eq=False)
class LeverArmSweep:
    """The built component: the arm, its sweep and the governing loads at its payload."""

    name: str
    arm: la.LeverArm
    payload: Any
    masses: dict[str, Any]
    sweep: LinearSweep
    members: dict[str, MemberDemand]
    motors: dict[str, ActuatorDemand]

    def notes(self) -> list[str]:
        """The governing pose of every output, one line each."""
        out = [f"{len(self.sweep.labels)} poses, W = {fmt(self.payload)}; link masses: "
               + ", ".join(f"{b} {fmt(m, 'g')}" for b, m in self.masses.items())]
        out += [f"{m} motor: peak {fmt(d.peak, 'N*m')} at {d.peak_pose}" for m, d in self.motors.items()]
        out += [f"{k}: tension {fmt(d.tension, 'N')} at {d.tension_pose}; compression {fmt(d.compression, 'N')} "
                f"at {d.compression_pose}; moment {fmt(d.moment, 'N*m')} at {d.moment_pose}"
                for k, d in self.members.items()]
        return out


def _range(p: Mapping[str, Any], key: str) -> tuple[float, float]:
    v = p[key]
    if not isinstance(v, list) or len(v) != 2:
        raise InputError(f"{key}: expected [low, high] angles, got {v!r}")
    return float(v[0].m_as("deg")), float(v[1].m_as("deg"))


def _link_masses(p: Mapping[str, Any], arm: la.LeverArm, ctx: Any) -> dict[str, Any]:
    """Mass of each body from the link components named in ``links`` (their section, material and length)."""
    table = p["links"]
    if not isinstance(table, Mapping):
        raise InputError(f"links: expected a table member = \"component\", got {table!r}")
    unknown = sorted(set(table) - set(la.MEMBERS))
    if unknown:
        raise InputError(f"links.{unknown[0]}: not a member of the lever arm ({', '.join(la.MEMBERS)})")
    missing = [m for m in la.MEMBERS if m not in table]
    if missing:
        raise InputError(f"links: every member needs its link component; missing {', '.join(missing)}")
    entries = (ctx or {}).get("components") or {}
    out: dict[str, Any] = {}
    for member, comp in table.items():
        e = entries.get(comp) if isinstance(comp, str) else None
        if e is None or e.type.name != "link":
            raise InputError(f"links.{member}: {comp!r} is not a link component of this design")
        obj = e.obj
        if obj is None:
            if any(type(v).__name__ == "Deferred" for v in e.params.values()):
                raise InputError(f"links.{member}: {comp}'s fields read other components' outputs; give them "
                                 "directly (the arm reads the link's section, material and length)")
            obj = e.type.build({**e.params, "_name": e.name}, ctx)
        link = obj.link
        want = la.member_length(arm, member)
        if abs(float(link.length.m_as("m")) - float(want.m_as("m"))) > 1e-6 * float(want.m_as("m")):
            raise InputError(f"links.{member}: {comp} is {fmt(link.length, 'mm')} long, the arm's {member} is "
                             f"{fmt(want, 'mm')} between pin centres")
        body = la.MEMBERS[member][0]
        out[body] = out.get(body, Q(0, "kg")) + link.mass()
    return out


def _masses(p: Mapping[str, Any], arm: la.LeverArm, ctx: Any) -> dict[str, Any]:
    if "links" in p and "masses" in p:
        raise InputError("masses: give links (the link components) or masses (per body), not both")
    if "links" in p:
        return _link_masses(p, arm, ctx)
    table = p.get("masses") or {}
    if not isinstance(table, Mapping):
        raise InputError(f"masses: expected a table body = \"mass\", got {table!r}")
    out = {}
    for body, v in table.items():
        if body not in _BODIES:
            raise InputError(f"masses.{body}: not a body of the lever arm ({', '.join(_BODIES)})")
        out[body] = Q(v) if isinstance(v, str) else v
        if not out[body].check("[mass]"):
            raise InputError(f"masses.{body}: expected a mass, got {v!r}")
    return out


def _build(p: Mapping[str, Any], ctx: Any) -> LeverArmSweep:
    arm = la.LeverArm(*(p[k] for k in _DIMS), name=p["_name"])
    masses = _masses(p, arm, ctx)
    g = ((ctx or {}).get("requirements") or {}).get("g") or "9.80665 m/s**2"
    W = p["payload"]
    if W.m_as("N") < 0:
        raise InputError(f"payload: must be zero or positive (a weight), got {fmt(W)}")
    sweep = la.sweep_envelope(arm, _range(p, "shoulder_range"), _range(p, "elbow_range"), _range(p, "wrist_range"),
                              float(p["step"].m_as("deg")), float(p["min_transmission_angle"].m_as("deg")),
                              masses=masses, gravity=g)
    s = float(W.m_as("N"))
    return LeverArmSweep(p["_name"], arm, W, masses, sweep, sweep.member_demands(s), sweep.actuator_demands(s))


def _motor(m: str) -> Output:
    return Output(f"{m}_peak_torque", "torque", f"largest |holding torque| of the {m} motor over the sweep",
                  lambda c, loads: c.motors[m].peak)


def _member(member: str, what: str) -> Output:
    kind, doc = {"tension": ("force", "largest tension (>= 0)"), "compression": ("force", "largest compression "
                 "(a magnitude >= 0; use '-arm.<member>_compression' as an axial_force)"),
                 "moment": ("torque", "largest in-plane bending moment |M|")}[what]
    return Output(f"{member}_{what}", kind, f"{member}: {doc} over the sweep",
                  lambda c, loads: getattr(c.members[member], what))


REGISTRY.register(ComponentType(
    name="lever_arm_sweep",
    doc="The parallelogram lever arm (seed 000; mechverify.mechanisms.lever_arm) swept over its joint ranges with "
        "its links' self-weight and the payload W at C (nine-body statics at every pose, linear in W); outputs: "
        "each plane motor's peak holding torque and each member's governing tension, compression and in-plane "
        "moment, for the drives and links that check them.",
    fields=(*(Field(k, "length", f"seed 000 dimension {k}", required=True) for k in _DIMS),
            Field("payload", "force", "weight W at the tool point C (e.g. \"W\", a parameter)", required=True),
            Field("shoulder_range", "list", "[low, high] of the shoulder angle varphi", required=True, item="angle"),
            Field("elbow_range", "list", "[low, high] of the elbow angle phi", required=True, item="angle"),
            Field("wrist_range", "list", "[low, high] of the wrist angle psi", required=True, item="angle"),
            Field("step", "angle", "grid step of the three joints (ends included)", default="10 deg"),
            Field("min_transmission_angle", "angle", "poses with a parallelogram nearer flat than this are left out "
                  "(the coupler forces grow as 1/sin)", default="40 deg"),
            Field("links", "table", "member = \"link component\" for each of the 12 members (OA, OD, DE, EAB_EA, "
                  "EAB_AB, OF, FG, GAH_AG, GAH_AH, HI, IBC_BI, IBC_BC): their section, material and length give "
                  "the self-weight"),
            Field("masses", "table", "instead of links: body = \"mass\" (OA, OD, DE, EAB, OF, FG, GAH, HI, IBC); "
                  "neither: massless links")),
    build=_build,
    outputs=(*(_motor(m) for m in la.MOTORS),
             *(_member(k, w) for k in la.MEMBERS for w in ("tension", "compression", "moment")))))
