"""``compression_spring``, ``extension_spring``, ``torsion_spring``: helical springs of round wire.

The checks are those of :mod:`mechverify.checks.springs`: compression springs (static and solid
stress, buckling, fatigue, clash), extension springs (body, hook bending and torsion against Shigley
10th ed. Table 10-7) and torsion springs (bending stress, Eq. (10-57); clearance on the arbor). This
module maps design-file values onto them and adds the other load cases' operating points to the
force-deflection figure data; the shared wire fields are in :mod:`.spring_parsing`.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import springs as sc
from mechverify.checks.result import CheckResult
from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring
from mechverify.design.adapters.common import pick
from mechverify.design.adapters.spring_parsing import (
    CRITERIA,
    END_CONDITIONS,
    END_TYPES,
    nonnegative,
    wire_fields,
    wire_kwargs,
)
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.units import Q, fmt


# ------------------------------------------------------------------------------------- compression spring
@dataclasses.dataclass(frozen=True)
class SpringInstallation:
    """A compression spring with how it is mounted and checked (from the design file)."""

    spring: CompressionSpring
    end_condition: str = "fixed-fixed"
    fatigue_criterion: str = "gerber"
    clash_method: str = "shigley"


def _build_compression(p: dict[str, Any], ctx: dict[str, Any]) -> SpringInstallation:
    if ("active_coils" in p) == ("total_coils" in p):
        raise InputError("give exactly one of active_coils or total_coils")
    spring = CompressionSpring(L0=p["free_length"], end=p["ends"], **wire_kwargs(p),
                               **pick(p, "set_removed", "peened", "density", Na="active_coils", Nt="total_coils"))
    return SpringInstallation(spring, p["end_condition"], p["fatigue_criterion"], p["clash_method"])


def _max_force(s: CompressionSpring, loads: dict[str, Any]) -> pint.Quantity:
    """Largest working force: ``force``, or k·``deflection`` (a deflection beyond solid is an error)."""
    if "force" in loads:
        return nonnegative(loads["force"].to("N"), "force (compression)")
    return s.force(nonnegative(loads["deflection"], "deflection")).to("N")


def _min_force(s: CompressionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "force_min" in loads:
        return nonnegative(loads["force_min"].to("N"), "force_min")
    return s.force(nonnegative(loads["deflection_min"], "deflection_min")).to("N")


def _operating_points(inst: SpringInstallation, ctx: Any) -> dict[str, Any]:
    """Forces of every load case on this spring (for the force-deflection figure)."""
    names, forces = [], []
    k = inst.spring.rate.m_as("N/mm")
    for case, comps in ctx.design.data.load_cases.items():
        loads = comps.get(ctx.component) or {}
        for key, label in (("force", ""), ("deflection", ""), ("force_min", " (min)"), ("deflection_min", " (min)")):
            if key in loads:
                q = loads[key]
                forces.append(q.m_as("N") if key.startswith("force") else k * q.m_as("mm"))
                names.append(case + label)
    return {"operating_cases": names, "operating_forces": Q(forces, "N")}


def _static(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    return sc.check_spring_static_stress(inst.spring, _max_force(inst.spring, loads), required_sf=ctx.required_sf)


def _buckling(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    end = loads.get("end_condition", inst.end_condition)
    r = sc.check_spring_buckling(inst.spring, _max_force(inst.spring, loads), end=end, required_sf=ctx.required_sf)
    return dataclasses.replace(r, details={**r.details, **_operating_points(inst, ctx)})  # for the figure


def _fatigue(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    s = inst.spring
    return sc.check_spring_fatigue(s, _min_force(s, loads), _max_force(s, loads), criterion=inst.fatigue_criterion,
                                   required_sf=ctx.required_sf)


def _clash(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    dynamic = "force_min" in loads or "deflection_min" in loads
    return sc.check_spring_clash(inst.spring, _max_force(inst.spring, loads), method=inst.clash_method, dynamic=dynamic)


COMPRESSION = REGISTRY.register(ComponentType(
    name="compression_spring",
    doc="A helical compression spring of round wire (Shigley 10th ed. Ch. 10): wire and coil diameters, coils, "
        "end type, free length, wire material; mounted with an end condition for buckling.",
    fields=(
        *wire_fields((
            Field("active_coils", "float", "active coils Na (or give total_coils)"),
            Field("total_coils", "float", "total coils Nt (Na = Nt - end coils of the end type)"),
        )),
        Field("free_length", "length", "free length L0", required=True),
        Field("ends", "choice", "end type (Shigley Table 10-1)", choices=END_TYPES, default="squared-ground"),
        Field("density", "density", "wire density, instead of the material's"),
        Field("set_removed", "bool", "set removed: K_s with the higher Table 10-6 allowable", default=False),
        Field("peened", "bool", "shot-peened (Zimmerli fatigue data)", default=False),
        Field("end_condition", "choice", "how the ends are held, for buckling (Shigley Table 10-2); "
                                         "fixed-fixed = between flat parallel plates",
              choices=END_CONDITIONS, default="fixed-fixed"),
        Field("fatigue_criterion", "choice", "mean-stress criterion of the fatigue check", choices=CRITERIA,
              default="gerber"),
        Field("clash_method", "choice", "clash allowance: Shigley's 15 % overrun or EN 13906-1's minimum gap sum",
              choices=("shigley", "en13906"), default="shigley"),
    ),
    build=lambda p, ctx: _build_compression(p, ctx),
    loads=(
        Field("force", "force", "largest working force (the top of the fatigue cycle)"),
        Field("deflection", "length", "largest working deflection from free length (instead of force)"),
        Field("force_min", "force", "smallest force of the fatigue cycle"),
        Field("deflection_min", "length", "smallest deflection of the fatigue cycle (instead of force_min)"),
        Field("end_condition", "choice", "end condition in this load case, instead of the component's",
              choices=END_CONDITIONS),
    ),
    checks=(
        CheckSpec.of(sc.check_spring_static_stress, _static, needs=("force|deflection",)),
        CheckSpec.of(sc.check_spring_solid_stress,
                     lambda c, loads, ctx: sc.check_spring_solid_stress(c.spring, required_sf=ctx.required_sf)),
        CheckSpec.of(sc.check_spring_buckling, _buckling, needs=("force|deflection",)),
        CheckSpec.of(sc.check_spring_fatigue, _fatigue, needs=("force|deflection", "force_min|deflection_min"),
                     default=False),
        CheckSpec.of(sc.check_spring_clash, _clash, needs=("force|deflection",)),
    ),
    outputs=(  # values other components read as "<spring>.<name>" (design/parameters.py)
        Output("rate", "force_per_length", "spring rate k = d^4 G/(8 D^3 Na) (Shigley 10th ed. Eq. 10-9)",
               lambda c, loads: c.spring.rate.to("N/mm")),
        Output("force", "force", "working force of the case: force, or k times deflection", lambda c, loads: (
            loads["force"] if "force" in loads else (c.spring.rate * loads["deflection"]).to("N")),
            needs=("force|deflection",)),
    ),
))


# --------------------------------------------------------------------------------------- extension spring
def _build_extension(p: dict[str, Any], ctx: dict[str, Any]) -> ExtensionSpring:
    return ExtensionSpring(Nb=p["body_coils"], **wire_kwargs(p),
                           **pick(p, Fi="initial_tension", r1="hook_bend_radius", r2="hook_side_radius"))


def _extension_force(s: ExtensionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "force" in loads:
        return nonnegative(loads["force"].to("N"), "force (tension)")
    return s.force(nonnegative(loads["extension"], "extension")).to("N")


EXTENSION = REGISTRY.register(ComponentType(
    name="extension_spring",
    doc="A helical extension spring with full-loop hooks (Shigley 10th ed. Sec. 10-11): static body and hook "
        "stresses against Table 10-7.",
    fields=(
        *wire_fields((Field("body_coils", "float", "body coils Nb", required=True),)),
        Field("initial_tension", "force", "initial tension Fi", default="0 N"),
        Field("hook_bend_radius", "length", "mean radius r1 of the hook bend at A (default D/2, full loop)"),
        Field("hook_side_radius", "length", "side-bend radius r2 at B (the hook torsion check needs it)"),
    ),
    build=lambda p, ctx: _build_extension(p, ctx),
    loads=(
        Field("force", "force", "largest working force"),
        Field("extension", "length", "largest extension from free length (instead of force): F = Fi + k y"),
    ),
    checks=(
        CheckSpec.of(sc.check_extension_body_stress, lambda c, loads, ctx: sc.check_extension_body_stress(
            c, _extension_force(c, loads), required_sf=ctx.required_sf), needs=("force|extension",)),
        CheckSpec.of(sc.check_extension_hook_bending, lambda c, loads, ctx: sc.check_extension_hook_bending(
            c, _extension_force(c, loads), required_sf=ctx.required_sf), needs=("force|extension",)),
        CheckSpec.of(sc.check_extension_hook_torsion, lambda c, loads, ctx: sc.check_extension_hook_torsion(
            c, _extension_force(c, loads), required_sf=ctx.required_sf), needs=("force|extension",)),
    ),
))


# ----------------------------------------------------------------------------------------- torsion spring
@dataclasses.dataclass(frozen=True)
class TorsionInstallation:
    spring: TorsionSpring
    arbor_diameter: pint.Quantity | None = None


def _build_torsion(p: dict[str, Any], ctx: dict[str, Any]) -> TorsionInstallation:
    s = TorsionSpring(Nb=p["body_turns"], **wire_kwargs(p, shear=False), **pick(p, l1="leg1_length", l2="leg2_length"))
    arbor = p.get("arbor_diameter")
    if arbor is not None:
        inside = (s.mean_diameter - s.wire_diameter).to("mm")
        if arbor.magnitude <= 0 or arbor >= inside:
            raise InputError(f"arbor_diameter {fmt(arbor.to('mm'))} must be positive and below the coil's inside "
                             f"diameter {fmt(inside)}")
    return TorsionInstallation(s, arbor)


def _moment(s: TorsionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "moment" in loads:
        return nonnegative(loads["moment"].to("N*m"), "moment (winding up the coils)")
    theta = nonnegative(loads["angle"].to("rad"), "angle (winding up the coils)")
    return Q(s.rate().m_as("N*m/rad") * theta.m_as("rad"), "N*m")


TORSION = REGISTRY.register(ComponentType(
    name="torsion_spring",
    doc="A helical torsion spring (Shigley 10th ed. Sec. 10-12): static bending stress against S_y (Eq. 10-57) "
        "and, with an arbor, the clearance of the wound-up coil on it.",
    fields=(
        *[f for f in wire_fields((Field("body_turns", "float", "body turns Nb", required=True),))
          if f.name != "shear_modulus"],
        Field("leg1_length", "length", "length of leg 1 from the coil centre to the load", default="0 mm"),
        Field("leg2_length", "length", "length of leg 2", default="0 mm"),
        Field("arbor_diameter", "length", "diameter of the pin the spring winds onto (clearance check)"),
    ),
    build=lambda p, ctx: _build_torsion(p, ctx),
    loads=(
        Field("moment", "torque", "largest working moment, winding up the coils"),
        Field("angle", "angle", "largest wind-up angle (instead of moment): M = k' theta"),
    ),
    checks=(
        CheckSpec.of(sc.check_torsion_spring_stress, lambda c, loads, ctx: sc.check_torsion_spring_stress(
            c.spring, _moment(c.spring, loads), required_sf=ctx.required_sf), needs=("moment|angle",)),
        CheckSpec.of(sc.check_torsion_spring_arbor, lambda c, loads, ctx: sc.check_torsion_spring_arbor(
            c.spring, c.arbor_diameter, _moment(c.spring, loads), required_sf=ctx.required_sf)
            if c.arbor_diameter is not None else [], needs=("moment|angle",)),
    ),
))
