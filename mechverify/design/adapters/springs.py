"""``compression_spring``, ``extension_spring``, ``torsion_spring``: helical springs of round wire.

Compression springs get the checks of :mod:`mechverify.checks.springs` (static and solid stress,
buckling, fatigue, clash). Extension and torsion springs get their static checks (Shigley 10th ed.
Table 10-7 and Eq. (10-57)), written here because :mod:`mechverify.checks.springs` covers
compression springs only.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import pint

from mechverify.checks import springs as sc
from mechverify.checks.result import CheckResult
from mechverify.components.spring_formulas import SPRING_CLASSES, torsion_spring_factors
from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError
from mechverify.units import Q, fmt, to_si

SHIGLEY = "Shigley's Mechanical Engineering Design, 10th ed. (2015)"
END_TYPES = ("squared-ground", "squared", "plain-ground", "plain")
END_CONDITIONS = ("fixed-fixed", "fixed-pinned", "pinned-pinned", "fixed-guided", "fixed-free")
CRITERIA = ("gerber", "goodman", "sines", "asme_elliptic", "soderberg")
DIAMETERS = {"mean_diameter": "D", "outside_diameter": "OD", "inside_diameter": "ID"}


# ------------------------------------------------------------------------------------------ shared fields
def _wire_fields(coils: tuple[Field, ...]) -> tuple[Field, ...]:
    return (
        Field("wire_diameter", "length", "wire diameter d", required=True),
        Field("mean_diameter", "length", "mean coil diameter D (or give outside_diameter or inside_diameter)"),
        Field("outside_diameter", "length", "outside coil diameter OD = D + d"),
        Field("inside_diameter", "length", "inside coil diameter ID = D - d"),
        *coils,
        Field("material", "material", "spring wire (Sut from its wire-strength table at d)",
              default="ASTM A228 music wire"),
        Field("shear_modulus", "pressure", "G, instead of the material's (Shigley Table 10-5 lists it by size)"),
        Field("elastic_modulus", "pressure", "E, instead of the material's"),
        Field("tensile_strength", "pressure", "minimum tensile strength Sut of the wire, instead of the table's"),
        Field("spring_class", "choice", "Shigley Table 10-6 wire class, instead of the one found from the "
                                        "material's ASTM code", choices=SPRING_CLASSES),
    )


def _common(p: dict[str, Any], *, shear: bool = True) -> dict[str, Any]:
    given = [k for k in DIAMETERS if k in p]
    if len(given) != 1:
        raise InputError(f"give exactly one of mean_diameter, outside_diameter or inside_diameter "
                         f"(got {', '.join(given) or 'none'})")
    out = {"d": p["wire_diameter"], DIAMETERS[given[0]]: p[given[0]], "name": p["_name"]}
    out.update(pick(p, "material", "spring_class", E="elastic_modulus", Sut="tensile_strength"))
    if shear:
        out.update(pick(p, G="shear_modulus"))
    return out


def _one_of(loads: dict[str, Any], *names: str) -> str:
    return next(n for n in names if n in loads)


def _nonnegative(q: pint.Quantity, what: str) -> pint.Quantity:
    if q.magnitude < 0:
        raise InputError(f"{what} must be >= 0, got {fmt(q)}")
    return q


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
    spring = CompressionSpring(L0=p["free_length"], end=p["ends"], **_common(p),
                               **pick(p, "set_removed", "peened", "density", Na="active_coils", Nt="total_coils"))
    return SpringInstallation(spring, p["end_condition"], p["fatigue_criterion"], p["clash_method"])


def _max_force(s: CompressionSpring, loads: dict[str, Any]) -> pint.Quantity:
    """Largest working force: ``force``, or k·``deflection`` (a deflection beyond solid is an error)."""
    if "force" in loads:
        return _nonnegative(loads["force"].to("N"), "force (compression)")
    return s.force(_nonnegative(loads["deflection"], "deflection")).to("N")


def _min_force(s: CompressionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "force_min" in loads:
        return _nonnegative(loads["force_min"].to("N"), "force_min")
    return s.force(_nonnegative(loads["deflection_min"], "deflection_min")).to("N")


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


def _figure_data(inst: SpringInstallation, ctx: Any, end: str) -> dict[str, Any]:
    s = inst.spring
    y_cr = s.critical_deflection(end)
    data = {"rate": s.rate, "solid_deflection": s.solid_deflection, "solid_force": s.solid_force.to("N"),
            "end_condition": end, **_operating_points(inst, ctx)}
    if y_cr is not None:
        data["critical_deflection"] = y_cr
    return data


def _static(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    return sc.spring_static_stress(inst.spring, _max_force(inst.spring, loads), required_sf=ctx.required_sf)


def _buckling(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    end = loads.get("end_condition", inst.end_condition)
    r = sc.spring_buckling(inst.spring, _max_force(inst.spring, loads), end=end, required_sf=ctx.required_sf)
    inputs = {k: (v.to("GPa") if k in ("E", "G") else v) for k, v in r.inputs.items()}
    return dataclasses.replace(r, inputs=inputs, details={**r.details, **_figure_data(inst, ctx, end)})


def _fatigue(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    s = inst.spring
    r = sc.spring_fatigue(s, _min_force(s, loads), _max_force(s, loads), criterion=inst.fatigue_criterion,
                          required_sf=ctx.required_sf)
    f = s.fatigue(_min_force(s, loads), _max_force(s, loads), inst.fatigue_criterion)
    # the check's formula has \text{...} with spaces, which the report's mathtext rewrite runs together
    formula = (r"\tau_a = K_B \frac{8 F_a D}{\pi d^3},\ \tau_m = K_B \frac{8 F_m D}{\pi d^3},\ "
               r"n_f = S_{sa}/\tau_a")
    return dataclasses.replace(r, formula=formula,
                               details={**r.details, "criterion": inst.fatigue_criterion, "tau_a": f.tau_a,
                                           "Ssa_zimmerli": f.zimmerli.Ssa.to("MPa"),
                                           "Ssm_zimmerli": f.zimmerli.Ssm.to("MPa")})


def _clash(inst: SpringInstallation, loads: dict[str, Any], ctx: Any) -> CheckResult:
    dynamic = "force_min" in loads or "deflection_min" in loads
    return sc.spring_clash(inst.spring, _max_force(inst.spring, loads), method=inst.clash_method, dynamic=dynamic)


COMPRESSION = REGISTRY.register(ComponentType(
    name="compression_spring",
    doc="A helical compression spring of round wire (Shigley 10th ed. Ch. 10): wire and coil diameters, coils, "
        "end type, free length, wire material; mounted with an end condition for buckling.",
    fields=(
        *_wire_fields((
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
        CheckSpec("static_stress", _static, "Spring shear stress at maximum working force",
                  needs=("force|deflection",), sf_kind="spring",
                  explain="tau = K_B 8FD/(pi d^3) (K_s with set removed) against S_sy of Shigley Table 10-6; "
                          "Shigley Sec. 10-7 designs springs for n_s >= 1.2."),
        CheckSpec("solid_stress", lambda c, loads, ctx: sc.spring_solid_stress(c.spring, required_sf=ctx.required_sf),
                  "Spring shear stress at solid length", sf_kind="spring",
                  explain="Stress when closed solid, F = k(L0 - Ls), against S_sy: a solid-safe spring takes no "
                          "set if it is closed by accident (Shigley Sec. 10-7)."),
        CheckSpec("buckling", _buckling, "Spring buckling (critical deflection)", needs=("force|deflection",),
                  sf_kind="deflection",
                  explain="Working deflection against the critical deflection of Shigley Eq. (10-10) with alpha "
                          "of Table 10-2 (= EN 13906-1); an absolutely stable spring is held to its travel."),
        CheckSpec("fatigue", _fatigue, "Spring fatigue (infinite life)",
                  needs=("force|deflection", "force_min|deflection_min"), sf_kind="fatigue", default=False,
                  explain="Zimmerli endurance data with a mean-stress criterion (Gerber by default) along the "
                          "proportional load line (Shigley Secs. 10-9, 10-10)."),
        CheckSpec("clash", _clash, "Spring clash allowance", needs=("force|deflection",), sf_kind="deflection",
                  explain="(1 + 0.15) y_max <= L0 - Ls (Shigley Sec. 10-7), or EN 13906-1's minimum sum of "
                          "gaps between coils (doubled when the case gives a fatigue cycle)."),
    ),
))


# --------------------------------------------------------------------------------------- extension spring
def _build_extension(p: dict[str, Any], ctx: dict[str, Any]) -> ExtensionSpring:
    return ExtensionSpring(Nb=p["body_coils"], **_common(p),
                           **pick(p, Fi="initial_tension", r1="hook_bend_radius", r2="hook_side_radius"))


def _extension_force(s: ExtensionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "force" in loads:
        return _nonnegative(loads["force"].to("N"), "force (tension)")
    return s.force(_nonnegative(loads["extension"], "extension")).to("N")


def _ext_inputs(s: ExtensionSpring, F: pint.Quantity) -> dict[str, Any]:
    return {"d": Q(s._si["d"], "m").to("mm"), "D": Q(s._si["D"], "m").to("mm"), "C": s.index, "Nb": s._si["Nb"],
            "Fi": s.initial_tension, "Sut": s.tensile_strength, "F": F}


def _initial_tension_note(s: ExtensionSpring) -> str:
    lo, hi = s.initial_stress_range()
    return (f"initial stress tau_i = {fmt(s.initial_stress, 'MPa')}; preferred range for C = {s.index:.3g}: "
            f"{fmt(lo, 'MPa')} .. {fmt(hi, 'MPa')} (Shigley Sec. 10-11, Fig. 10-7)")


def extension_body_stress(s: ExtensionSpring, F: Any, *, required_sf: float = 1.0) -> CheckResult:
    """Body shear stress τ = K_B·8FD/(πd³) against the Table 10-7 body allowable (Shigley 10th ed. Sec. 10-11)."""
    Fq = Q(to_si(F, "force", "F"), "N")
    return CheckResult(
        check="extension_body_stress", component=s.name, demand=s.body_stress(Fq), capacity=s.allowable("body"),
        required_sf=required_sf, title="Extension spring body stress",
        formula=r"\tau = K_B \frac{8 F D}{\pi d^3} \le S_{sy}", source=f"{SHIGLEY}, Eq. (10-7), Table 10-7",
        inputs=_ext_inputs(s, Fq), notes=(_initial_tension_note(s),))


def extension_hook_bending(s: ExtensionSpring, F: Any, *, required_sf: float = 1.0) -> CheckResult:
    """Bending and tension at hook section A against the Table 10-7 end-bending allowable."""
    Fq = Q(to_si(F, "force", "F"), "N")
    notes = ["hook bend radius r1 = " + fmt(Q(s._si["r1"], "m").to("mm")) + " (default D/2: full loop)"]
    if s.r2 is None:
        notes.append("hook torsion at B not checked: give hook_side_radius (r2)")
    return CheckResult(
        check="extension_hook_bending", component=s.name, demand=s.hook_bending_stress(Fq),
        capacity=s.allowable("end_bending"), required_sf=required_sf, title="Extension spring hook bending (A)",
        formula=r"\sigma_A = F \left[(K)_A \frac{16 D}{\pi d^3} + \frac{4}{\pi d^2}\right],\ "
                r"(K)_A = \frac{4 C_1^2 - C_1 - 1}{4 C_1 (C_1 - 1)},\ C_1 = 2 r_1/d",
        source=f"{SHIGLEY}, Sec. 10-11, Table 10-7",
        inputs={**_ext_inputs(s, Fq), "r1": Q(s._si["r1"], "m").to("mm")}, notes=tuple(notes))


def extension_hook_torsion(s: ExtensionSpring, F: Any, *, required_sf: float = 1.0) -> list[CheckResult]:
    """Torsion at hook section B against the Table 10-7 end-torsion allowable (only when r2 is known)."""
    if s.r2 is None:
        return []
    Fq = Q(to_si(F, "force", "F"), "N")
    return [CheckResult(
        check="extension_hook_torsion", component=s.name, demand=s.hook_torsion_stress(Fq),
        capacity=s.allowable("end_torsion"), required_sf=required_sf, title="Extension spring hook torsion (B)",
        formula=r"\tau_B = (K)_B \frac{8 F D}{\pi d^3},\ (K)_B = \frac{4 C_2 - 1}{4 C_2 - 4},\ C_2 = 2 r_2/d",
        source=f"{SHIGLEY}, Sec. 10-11, Table 10-7",
        inputs={**_ext_inputs(s, Fq), "r2": Q(s._si["r2"], "m").to("mm")})]


EXTENSION = REGISTRY.register(ComponentType(
    name="extension_spring",
    doc="A helical extension spring with full-loop hooks (Shigley 10th ed. Sec. 10-11): static body and hook "
        "stresses against Table 10-7.",
    fields=(
        *_wire_fields((Field("body_coils", "float", "body coils Nb", required=True),)),
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
        CheckSpec("body_stress", lambda c, loads, ctx: extension_body_stress(
            c, _extension_force(c, loads), required_sf=ctx.required_sf),
            "Extension spring body stress", needs=("force|extension",), sf_kind="static",
            explain="tau = K_B 8FD/(pi d^3) against the body allowable of Shigley Table 10-7."),
        CheckSpec("hook_bending", lambda c, loads, ctx: extension_hook_bending(
            c, _extension_force(c, loads), required_sf=ctx.required_sf),
            "Extension spring hook bending (A)", needs=("force|extension",), sf_kind="static",
            explain="Bending plus tension at the hook's section A against the end-bending allowable "
                    "(Shigley Sec. 10-11, Table 10-7)."),
        CheckSpec("hook_torsion", lambda c, loads, ctx: extension_hook_torsion(
            c, _extension_force(c, loads), required_sf=ctx.required_sf),
            "Extension spring hook torsion (B)", needs=("force|extension",), sf_kind="static",
            explain="Torsion at the hook's side bend B against the end-torsion allowable; runs when "
                    "hook_side_radius is given."),
    ),
))


# ----------------------------------------------------------------------------------------- torsion spring
@dataclasses.dataclass(frozen=True)
class TorsionInstallation:
    spring: TorsionSpring
    arbor_diameter: pint.Quantity | None = None


def _build_torsion(p: dict[str, Any], ctx: dict[str, Any]) -> TorsionInstallation:
    s = TorsionSpring(Nb=p["body_turns"], **_common(p, shear=False), **pick(p, l1="leg1_length", l2="leg2_length"))
    arbor = p.get("arbor_diameter")
    if arbor is not None:
        inside = Q(s._si["D"] - s._si["d"], "m").to("mm")
        if arbor.magnitude <= 0 or arbor >= inside:
            raise InputError(f"arbor_diameter {fmt(arbor.to('mm'))} must be positive and below the coil's inside "
                             f"diameter {fmt(inside)}")
    return TorsionInstallation(s, arbor)


def _moment(s: TorsionSpring, loads: dict[str, Any]) -> pint.Quantity:
    if "moment" in loads:
        return _nonnegative(loads["moment"].to("N*m"), "moment (winding up the coils)")
    theta = _nonnegative(loads["angle"].to("rad"), "angle (winding up the coils)")
    return Q(s.rate().m_as("N*m/rad") * theta.m_as("rad"), "N*m")


def _tor_inputs(s: TorsionSpring, M: pint.Quantity) -> dict[str, Any]:
    return {"d": Q(s._si["d"], "m").to("mm"), "D": Q(s._si["D"], "m").to("mm"), "C": s.index,
            "Na": s.active_turns, "Sut": s.tensile_strength, "M": M.to("N*mm")}


def torsion_bending_stress(s: TorsionSpring, M: Any, *, required_sf: float = 1.0) -> CheckResult:
    """Inner-fibre bending stress σ = K_i·32M/(πd³) against S_y of Shigley 10th ed. Eq. (10-57)."""
    Mq = Q(to_si(M, "torque", "M"), "N*m")
    Ki, _ = torsion_spring_factors(s.index)
    return CheckResult(
        check="torsion_spring_stress", component=s.name, demand=s.bending_stress(Mq), capacity=s.yield_strength,
        required_sf=required_sf, title="Torsion spring bending stress",
        formula=r"\sigma = K_i \frac{32 M}{\pi d^3} \le S_y,\ K_i = \frac{4 C^2 - C - 1}{4 C (C - 1)}",
        source=f"{SHIGLEY}, Sec. 10-12, Eq. (10-43) (K_i), Eq. (10-57) (S_y)", inputs=_tor_inputs(s, Mq),
        notes=(f"K_i = {Ki:.4g} (inner fibre, where the stress is highest when the spring winds up)",
               "the load must close (wind up) the coils; unwinding loads need the residual-stress-free allowable"))


def torsion_arbor_clearance(inst: TorsionInstallation, M: Any) -> CheckResult:
    """The coil must not close onto its arbor: arbor diameter against the loaded inside diameter."""
    s = inst.spring
    Mq = Q(to_si(M, "torque", "M"), "N*m")
    Di = s.loaded_inside_diameter(Mq)
    return CheckResult(
        check="torsion_spring_arbor", component=s.name, demand=inst.arbor_diameter.to("mm"), capacity=Di,
        title="Torsion spring clearance on its arbor",
        formula=r"D_{arbor} \le D_i' = \frac{D N_b}{N_b + \theta_c'} - d",
        source=f"{SHIGLEY}, Sec. 10-12 (coil diameter under load)", inputs={**_tor_inputs(s, Mq), "angle": s.angle(Mq)},
        notes=("theta_c' = body turns of wind-up (legs excluded), friction-corrected rate (Eq. (10-51))",
               "to keep a diametral clearance margin, set a required_sf (1.1 = 10 %)"))


TORSION = REGISTRY.register(ComponentType(
    name="torsion_spring",
    doc="A helical torsion spring (Shigley 10th ed. Sec. 10-12): static bending stress against S_y (Eq. 10-57) "
        "and, with an arbor, the clearance of the wound-up coil on it.",
    fields=(
        *[f for f in _wire_fields((Field("body_turns", "float", "body turns Nb", required=True),))
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
        CheckSpec("bending_stress", lambda c, loads, ctx: torsion_bending_stress(
            c.spring, _moment(c.spring, loads), required_sf=ctx.required_sf),
            "Torsion spring bending stress", needs=("moment|angle",), sf_kind="static",
            explain="sigma = K_i 32M/(pi d^3) against S_y = 0.78 S_ut (music wire; Shigley Eq. (10-57))."),
        CheckSpec("arbor_clearance", lambda c, loads, ctx: torsion_arbor_clearance(c, _moment(c.spring, loads))
                  if c.arbor_diameter is not None else [],
                  "Torsion spring clearance on its arbor", needs=("moment|angle",), sf_kind="deflection",
                  explain="Arbor diameter against the inside diameter of the wound-up coil (Shigley Sec. 10-12); "
                          "runs when arbor_diameter is given."),
    ),
))
