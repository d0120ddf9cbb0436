"""Checks of helical compression springs: static stress, solid stress, buckling, fatigue, clash.

Each returns a :class:`CheckResult` oriented so that it passes while demand <= capacity / required_sf.
Defaults follow Shigley 10th ed. Ch. 10: static and solid design factor 1.2 (Sec. 10-7, "solid-safe"
with n_s >= 1.2), fatigue design factor 1.5 (Sec. 10-10), fractional overrun to closure xi = 0.15
(Sec. 10-7, robust linearity).
"""

from __future__ import annotations

from typing import Any

import pint

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components.spring_formulas import bergstrasser_factor, torsion_spring_factors
from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring, en13906_min_gap_sum
from mechverify.components.springs_extension import hook_bending_factor, hook_torsion_factor
from mechverify.errors import UnknownNameError
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, to_si

SHIGLEY = ref("shigley10")


def _inputs(spring: CompressionSpring) -> dict[str, Any]:
    return {"d": spring.wire_diameter, "D": spring.mean_diameter, "Na": spring.active_coils,
            "L0": spring.free_length, "end": spring.end.value, "C": spring.index, "Sut": spring.tensile_strength}


def _deflection(spring: CompressionSpring, F: Any) -> Any:
    """F/k without the travel limit: a force beyond the solid force must fail the check, not raise."""
    return Q(to_si(F, "force", "F_max") / spring.rate.m_as("N/m"), "m").to("mm")


def _factor_note(spring: CompressionSpring) -> str:
    if spring.set_removed:
        return (f"set removed: stress with K_s = {spring.direct_shear_factor:.4g} against "
                f"{spring.wire_class} allowable of Table 10-6 (set removed, low end of the range)")
    return (f"set not removed: stress with K_B = {spring.bergstrasser_factor:.4g} against the "
            f"{spring.wire_class} allowable of Table 10-6")


def _stress_substituted(spring: CompressionSpring, F: Any, tau: Any, sub: str = "") -> str:
    """tau = K 8 F D / (pi d^3) with the numbers (K: K_s with set removed, else K_B, as the check uses)."""
    K = spring.stress_factor
    return (rf"\tau{'_' + sub if sub else ''} = {tex(K)}\cdot \frac{{8\cdot {tex(F, 'N')}\cdot "
            rf"{tex(spring.mean_diameter, 'mm')}}}{{\pi\cdot ({tex(spring.wire_diameter, 'mm')})^{{3}}}}"
            rf" = {tex(tau, 'MPa')}")


def _wire_stress(K: float, F: Any, D: Any, d: Any, result: Any, lhs: str = r"\tau", k: int = 8) -> str:
    """``lhs = K·k F D/(pi d^3) = result`` with the numbers (helical body and hook torsion: k = 8)."""
    return (rf"{lhs} = {tex(K)}\cdot \frac{{{k}\cdot {tex(F, 'N')}\cdot {tex(D, 'mm')}}}"
            rf"{{\pi\cdot ({tex(d, 'mm')})^{{3}}}} = {tex(result, 'MPa')}")


def _deflection_tex(spring: CompressionSpring, F: Any) -> str:
    """``\frac{F}{k}`` with the numbers (k in N/mm)."""
    return rf"\frac{{{tex(Q(to_si(F, 'force', 'F_max'), 'N'), 'N')}}}{{{tex(spring.rate, 'N/mm')}}}"


def _buckling_substituted(spring: CompressionSpring, alpha: float, y_cr: Any) -> str:
    """y_cr = L0 C1' [1 - sqrt(1 - C2'/lambda^2)], C1' = E/(2(E - G)), C2' = 2 pi^2 (E - G)/(2G + E),
    lambda = alpha L0/D (Shigley Eqs. (10-10) to (10-12))."""
    E, G = tex(spring.elastic_modulus, "GPa"), tex(spring.shear_modulus, "GPa")
    L0, D = tex(spring.free_length, "mm"), tex(spring.mean_diameter, "mm")
    return (rf"y_{{cr}} = {L0}\cdot \frac{{{E}}}{{2\cdot ({E} - {G})}}\cdot \left(1 - \sqrt{{1 - "
            rf"\frac{{2\cdot \pi^{{2}}\cdot ({E} - {G})}}{{(2\cdot {G} + {E})\cdot "
            rf"\left(\frac{{{tex(alpha)}\cdot {L0}}}{{{D}}}\right)^{{2}}}}}}\right) = {tex(y_cr, 'mm')}")


@check("spring_static_stress", title='Spring shear stress at maximum working force', sf_kind="spring",
       aliases=('compression_spring.static_stress',),
       source=ref("shigley10", "Eqs. (10-5), (10-7), Table 10-6"),
       explain=('tau = K_B 8FD/(pi d^3) (K_s with set removed) against S_sy of Shigley Table 10-6; Shigley Sec. 10-7 '
                'designs springs for n_s >= 1.2.'))
def check_spring_static_stress(spring: CompressionSpring, F_max: QuantityLike, *, required_sf: float = 1.2,
                         load_case: str = "") -> CheckResult:
    """Working shear stress at the largest operating force against S_sy (Shigley Table 10-6)."""
    tau = spring.shear_stress(F_max)
    Ssy = spring.allowable_static_stress
    return CheckResult(
        check="spring_static_stress", component=spring.name, demand=tau, capacity=Ssy, required_sf=required_sf,
        title="Spring shear stress at maximum working force",
        formula=r"\tau = K_B \frac{8 F D}{\pi d^3} \le S_{sy}/n_s",
        source=f"{SHIGLEY}, Eqs. (10-5), (10-7), Table 10-6",
        inputs={**_inputs(spring), "F_max": Q(to_si(F_max, "force", "F_max"), "N")},
        substituted=_stress_substituted(spring, Q(to_si(F_max, "force", "F_max"), "N"), tau),
        notes=(_factor_note(spring), f"required factor {required_sf:g} (Shigley Sec. 10-7 recommends n_s >= 1.2)"),
        load_case=load_case)


@check("spring_solid_stress", title='Spring shear stress at solid length', sf_kind="spring",
       aliases=('compression_spring.solid_stress',),
       source=ref("shigley10", "Sec. 10-7, Table 10-1, Eq. (10-7), Table 10-6"),
       explain=('Stress when closed solid, F = k(L0 - Ls), against S_sy: a solid-safe spring takes no set if it is '
                'closed by accident (Shigley Sec. 10-7).'))
def check_spring_solid_stress(spring: CompressionSpring, *, required_sf: float = 1.2) -> CheckResult:
    """Shear stress when the spring is closed solid against S_sy ("solid-safe", Shigley Sec. 10-7)."""
    return CheckResult(
        check="spring_solid_stress", component=spring.name, demand=spring.solid_stress,
        capacity=spring.allowable_static_stress, required_sf=required_sf,
        title="Spring shear stress at solid length",
        formula=r"\tau_s = K_B \frac{8 k (L_0 - L_s) D}{\pi d^3} \le S_{sy}/n_s",
        source=f"{SHIGLEY}, Table 10-1, Eq. (10-7), Table 10-6",
        inputs={**_inputs(spring), "Ls": spring.solid_length, "F_solid": spring.solid_force.to("N")},
        substituted=_stress_substituted(spring, spring.solid_force, spring.solid_stress, "s"),
        notes=(_factor_note(spring), "a solid-safe spring cannot take a set when closed by accident",
               f"required factor {required_sf:g} (Shigley Sec. 10-7: n_s >= 1.2)"),
        load_case="closed solid")


@check("spring_buckling", title='Spring buckling (critical deflection)', sf_kind="deflection",
       aliases=('compression_spring.buckling',),
       source=f"{ref('shigley10', 'Eqs. (10-10) to (10-13), Table 10-2')}; {ref('en13906_1', 'Sec. 9')}",
       explain=('Working deflection against the critical deflection of Shigley Eq. (10-10) with alpha of Table 10-2 '
                '(= EN 13906-1); an absolutely stable spring is held to its travel.'))
def check_spring_buckling(spring: CompressionSpring, F_max: QuantityLike, *, end: str = "fixed-fixed",
                    required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """Working deflection against the critical (buckling) deflection for the given end condition.

    An absolutely stable spring (Shigley Eq. (10-13)) cannot buckle before it closes: the capacity is
    then the travel to solid, and a note says so.
    """
    y = _deflection(spring, F_max)
    y_cr = spring.critical_deflection(end)
    alpha = spring.end_condition_constant(end)
    notes = [f"end condition {end!r}, alpha = {alpha:g} (Shigley Table 10-2; EN 13906-1 nu)"]
    if y_cr is None or y_cr > spring.solid_deflection:
        capacity = spring.solid_deflection
        notes.append(f"absolutely stable: L0 = {fmt(spring.free_length, 'mm')} <= critical free length "
                     f"{fmt(spring.critical_free_length(end), 'mm')} (or buckling only beyond solid)")
    else:
        capacity = y_cr
    if capacity is y_cr:
        sub = _buckling_substituted(spring, alpha, y_cr)
    else:  # absolutely stable: held to its travel
        sub = (rf"L_0 - L_s = {tex(spring.free_length, 'mm')} - {tex(spring.solid_length, 'mm')}"
               rf" = {tex(capacity, 'mm')}")
    return CheckResult(
        check="spring_buckling", component=spring.name, demand=y, capacity=capacity, required_sf=required_sf,
        title="Spring buckling (critical deflection)",
        formula=r"y_{cr} = L_0 C_1' \left[1 - \sqrt{1 - C_2'/\lambda_{eff}^2}\right],\ \lambda_{eff} = \alpha L_0/D",
        source=f"{SHIGLEY}, Eqs. (10-10)..(10-13), Table 10-2; EN 13906-1:2013 Sec. 9",
        inputs={**_inputs(spring), "F_max": Q(to_si(F_max, "force", "F_max"), "N"), "E": spring.elastic_modulus,
                "G": spring.shear_modulus},
        substituted=sub, notes=tuple(notes), load_case=load_case,
        details={"rate": spring.rate, "solid_deflection": spring.solid_deflection,
                 "solid_force": spring.solid_force.to("N"), "end_condition": end,
                 **({"critical_deflection": y_cr} if y_cr is not None else {})})  # force-deflection figure


@check("spring_fatigue", title='Spring fatigue (infinite life)', sf_kind="fatigue",
       aliases=('compression_spring.fatigue',),
       source=ref("shigley10", "Secs. 10-9, 10-10, Eq. (10-30)"),
       explain=('Zimmerli endurance data with a mean-stress criterion (Gerber by default) along the proportional load'
                ' line (Shigley Secs. 10-9, 10-10).'))
def check_spring_fatigue(spring: CompressionSpring, F_min: QuantityLike, F_max: QuantityLike, *,
                         criterion: str = "gerber",
                   required_sf: float = 1.5, load_case: str = "") -> CheckResult:
    """Infinite-life fatigue with Zimmerli data and a mean-stress criterion (Shigley Secs. 10-9, 10-10).

    Demand: the stress amplitude τ_a; capacity: the strength amplitude S_sa on the proportional load
    line (so the safety factor equals n_f). The first-cycle yield factor n_y is reported in details.
    """
    f = spring.fatigue(F_min, F_max, criterion)
    notes = [f"criterion {criterion} with Zimmerli data ({'peened' if spring.peened else 'unpeened'}: "
             f"S_sa = {fmt(f.zimmerli.Ssa, 'MPa')}, S_sm = {fmt(f.zimmerli.Ssm, 'MPa')}), S_su = 0.67 S_ut; "
             "Gerber is Shigley's choice for springs (Sec. 10-9)",
             f"proportional load line; first-cycle torsional yield factor n_y = {f.n_y:.3g} (Langer, S_sy)",
             f"required factor {required_sf:g} (Shigley Sec. 10-10 design factor n_f = 1.5)"]
    warnings = []
    if f.n_y < 1:
        warnings.append(f"first-cycle yield: n_y = {f.n_y:.3g} < 1")
    return CheckResult(
        check="spring_fatigue", component=spring.name, demand=f.tau_a, capacity=f.Ssa, required_sf=required_sf,
        title="Spring fatigue (infinite life)",
        formula=r"\tau_a = K_B \frac{8 F_a D}{\pi d^3},\ \tau_m = K_B \frac{8 F_m D}{\pi d^3},\ "
                r"n_f = S_{sa}/\tau_a",  # S_sa: the Zimmerli point projected on the criterion
        source=f"{SHIGLEY}, Secs. 10-9, 10-10, Eq. (10-30); mean-stress criterion from mechverify.fatigue.criteria",
        inputs={**_inputs(spring), "F_min": Q(to_si(F_min, "force", "F_min"), "N"),
                "F_max": Q(to_si(F_max, "force", "F_max"), "N")},
        substituted=_wire_stress(spring.bergstrasser_factor,
                                 Q((to_si(F_max, "force", "F_max") - to_si(F_min, "force", "F_min")) / 2, "N"),
                                 spring.mean_diameter, spring.wire_diameter, f.tau_a, r"\tau_a"),
        notes=tuple(notes), warnings=tuple(warnings), load_case=load_case,
        details={"tau_m": f.tau_m, "Ssu": f.Ssu, "Sse": f.Sse, "Ssy": f.Ssy, "n_f": f.n_f, "n_y": f.n_y,
                 "criterion": criterion, "tau_a": f.tau_a, "Ssa_zimmerli": f.zimmerli.Ssa.to("MPa"),
                 "Ssm_zimmerli": f.zimmerli.Ssm.to("MPa")})


@check("spring_clash", title='Spring clash allowance', sf_kind="deflection",
       aliases=('compression_spring.clash',),
       source=f"{ref('shigley10', 'Sec. 10-7')}; {ref('en13906_1', 'Sec. 10')}",
       explain=("(1 + 0.15) y_max <= L0 - Ls (Shigley Sec. 10-7), or EN 13906-1's minimum sum of gaps between coils "
                '(doubled when the case gives a fatigue cycle).'))
def check_spring_clash(spring: CompressionSpring, F_max: QuantityLike, *, method: str = "shigley", xi: float = 0.15,
                 dynamic: bool = False, load_case: str = "") -> CheckResult:
    """Clash allowance: the spring must not approach solid at the largest working force.

    ``method="shigley"``: (1 + ξ)·y_max <= L0 - Ls with the fractional overrun ξ = 0.15 (Shigley Sec. 10-7).
    ``method="en13906"``: working length - Ls >= Sa = (0.0015 D²/d + 0.1 d)·n (EN 13906-1 Sec. 10;
    doubled for ``dynamic`` loading).
    """
    y = _deflection(spring, F_max)
    travel = spring.solid_deflection
    if method == "shigley":
        demand, capacity = ((1 + xi) * y).to("mm"), travel
        formula = r"(1 + \xi)\, y_{max} \le L_0 - L_s"
        source = f"{SHIGLEY}, Sec. 10-7 (fractional overrun to closure, xi = {xi:g})"
        note = f"fractional overrun to closure xi = {xi:g} keeps the spring in its linear range"
        sub = rf"(1 + \xi)\, y_{{max}} = (1 + {tex(xi)})\cdot {_deflection_tex(spring, F_max)} = {tex(demand, 'mm')}"
    elif method == "en13906":
        Sa = en13906_min_gap_sum(spring.wire_diameter, spring.mean_diameter, spring.active_coils, dynamic)
        demand, capacity = (y + Sa).to("mm"), travel
        formula = r"y_{max} + S_a \le L_0 - L_s,\ S_a = (0.0015 D^2/d + 0.1 d)\, n"
        source = "EN 13906-1:2013, Sec. 10 (minimum sum of gaps between active coils)"
        note = f"minimum sum of gaps S_a = {fmt(Sa, 'mm')} ({'dynamic, doubled' if dynamic else 'static'})"
        dd, DD = tex(spring.wire_diameter, "mm"), tex(spring.mean_diameter, "mm")
        two = "2\\cdot " if dynamic else ""
        sub = (rf"y_{{max}} + S_a = {_deflection_tex(spring, F_max)} + {two}"
               rf"\left(\frac{{0.0015\cdot ({DD})^{{2}}}}{{{dd}}} + 0.1\cdot {dd}\right)\cdot "
               rf"{tex(spring.active_coils)} = {tex(demand, 'mm')}")
    else:
        raise UnknownNameError("clash method", method, ["shigley", "en13906"])
    return CheckResult(
        check="spring_clash", component=spring.name, demand=demand, capacity=capacity, title="Spring clash allowance",
        formula=formula, source=source,
        inputs={**_inputs(spring), "F_max": Q(to_si(F_max, "force", "F_max"), "N"), "Ls": spring.solid_length},
        substituted=sub, notes=(note,), load_case=load_case)



# --------------------------------------------------------------------------------------- extension springs
def _ext_inputs(s: ExtensionSpring, F: pint.Quantity) -> dict[str, Any]:
    return {"d": s.wire_diameter, "D": s.mean_diameter, "C": s.index, "Nb": s.body_coils,
            "Fi": s.initial_tension, "Sut": s.tensile_strength, "F": F}


def _initial_tension_note(s: ExtensionSpring) -> str:
    lo, hi = s.initial_stress_range()
    return (f"initial stress tau_i = {fmt(s.initial_stress, 'MPa')}; preferred range for C = {s.index:.3g}: "
            f"{fmt(lo, 'MPa')} .. {fmt(hi, 'MPa')} (Shigley Sec. 10-11, Fig. 10-7)")


@check("extension_body_stress", title='Extension spring body stress', sf_kind="static",
       aliases=('extension_spring.body_stress',),
       source=ref("shigley10", "Sec. 10-11, Eq. (10-7), Table 10-7"),
       explain=('tau = K_B 8FD/(pi d^3) against the body allowable of Shigley Table 10-7.'))
def check_extension_body_stress(s: ExtensionSpring, F: QuantityLike, *, required_sf: float = 1.0) -> CheckResult:
    """Body shear stress τ = K_B·8FD/(πd³) against the Table 10-7 body allowable (Shigley 10th ed. Sec. 10-11)."""
    Fq = Q(to_si(F, "force", "F"), "N")
    return CheckResult(
        check="extension_body_stress", component=s.name, demand=s.body_stress(Fq), capacity=s.allowable("body"),
        required_sf=required_sf, title="Extension spring body stress",
        formula=r"\tau = K_B \frac{8 F D}{\pi d^3} \le S_{sy}", source=f"{SHIGLEY}, Eq. (10-7), Table 10-7",
        inputs=_ext_inputs(s, Fq), notes=(_initial_tension_note(s),),
        substituted=_wire_stress(bergstrasser_factor(s.index), Fq, s.mean_diameter, s.wire_diameter,
                                 s.body_stress(Fq)))


@check("extension_hook_bending", title='Extension spring hook bending (A)', sf_kind="static",
       aliases=('extension_spring.hook_bending',),
       source=ref("shigley10", "Sec. 10-11, Table 10-7"),
       explain=("Bending plus tension at the hook's section A against the end-bending allowable (Shigley Sec. 10-11, "
                'Table 10-7).'))
def check_extension_hook_bending(s: ExtensionSpring, F: QuantityLike, *, required_sf: float = 1.0) -> CheckResult:
    """Bending and tension at hook section A against the Table 10-7 end-bending allowable."""
    Fq = Q(to_si(F, "force", "F"), "N")
    notes = ["hook bend radius r1 = " + fmt(s.hook_bend_radius) + " (default D/2: full loop)"]
    if s.r2 is None:
        notes.append("hook torsion at B not checked: give hook_side_radius (r2)")
    return CheckResult(
        check="extension_hook_bending", component=s.name, demand=s.hook_bending_stress(Fq),
        capacity=s.allowable("end_bending"), required_sf=required_sf, title="Extension spring hook bending (A)",
        formula=r"\sigma_A = F \left[(K)_A \frac{16 D}{\pi d^3} + \frac{4}{\pi d^2}\right],\ "
                r"(K)_A = \frac{4 C_1^2 - C_1 - 1}{4 C_1 (C_1 - 1)},\ C_1 = 2 r_1/d",
        source=f"{SHIGLEY}, Sec. 10-11, Table 10-7",
        inputs={**_ext_inputs(s, Fq), "r1": s.hook_bend_radius}, notes=tuple(notes),
        substituted=_hook_bending_substituted(s, Fq))


def _hook_bending_substituted(s: ExtensionSpring, F: Any) -> str:
    C1 = float((2 * s.hook_bend_radius / s.wire_diameter).m_as(""))
    d, D = tex(s.wire_diameter, "mm"), tex(s.mean_diameter, "mm")
    return (rf"\sigma_A = {tex(F, 'N')}\cdot \left({tex(hook_bending_factor(C1))}\cdot \frac{{16\cdot {D}}}"
            rf"{{\pi\cdot ({d})^{{3}}}} + \frac{{4}}{{\pi\cdot ({d})^{{2}}}}\right) = "
            rf"{tex(s.hook_bending_stress(F), 'MPa')}")


@check("extension_hook_torsion", title='Extension spring hook torsion (B)', sf_kind="static",
       aliases=('extension_spring.hook_torsion',),
       source=ref("shigley10", "Sec. 10-11, Table 10-7"),
       explain=("Torsion at the hook's side bend B against the end-torsion allowable; runs when hook_side_radius is "
                'given.'))
def check_extension_hook_torsion(s: ExtensionSpring, F: QuantityLike, *, required_sf: float = 1.0) -> list[CheckResult]:
    """Torsion at hook section B against the Table 10-7 end-torsion allowable (only when r2 is known)."""
    if s.r2 is None:
        return []
    Fq = Q(to_si(F, "force", "F"), "N")
    return [CheckResult(
        check="extension_hook_torsion", component=s.name, demand=s.hook_torsion_stress(Fq),
        capacity=s.allowable("end_torsion"), required_sf=required_sf, title="Extension spring hook torsion (B)",
        formula=r"\tau_B = (K)_B \frac{8 F D}{\pi d^3},\ (K)_B = \frac{4 C_2 - 1}{4 C_2 - 4},\ C_2 = 2 r_2/d",
        source=f"{SHIGLEY}, Sec. 10-11, Table 10-7",
        inputs={**_ext_inputs(s, Fq), "r2": s.hook_side_radius},
        substituted=_wire_stress(hook_torsion_factor(float((2 * s.hook_side_radius / s.wire_diameter).m_as(""))),
                                 Fq, s.mean_diameter, s.wire_diameter, s.hook_torsion_stress(Fq), r"\tau_B"))]


# ----------------------------------------------------------------------------------------- torsion springs
def _tor_inputs(s: TorsionSpring, M: pint.Quantity) -> dict[str, Any]:
    return {"d": s.wire_diameter, "D": s.mean_diameter, "C": s.index,
            "Na": s.active_turns, "Sut": s.tensile_strength, "M": M.to("N*mm")}


@check("torsion_spring_stress", title='Torsion spring bending stress', sf_kind="static",
       aliases=('torsion_spring.bending_stress',),
       source=ref("shigley10", "Sec. 10-12, Eqs. (10-43), (10-57)"),
       explain=('sigma = K_i 32M/(pi d^3) against S_y = 0.78 S_ut (music wire; Shigley Eq. (10-57)).'))
def check_torsion_spring_stress(s: TorsionSpring, M: QuantityLike, *, required_sf: float = 1.0) -> CheckResult:
    """Inner-fibre bending stress σ = K_i·32M/(πd³) against S_y of Shigley 10th ed. Eq. (10-57)."""
    Mq = Q(to_si(M, "torque", "M"), "N*m")
    Ki, _ = torsion_spring_factors(s.index)
    return CheckResult(
        check="torsion_spring_stress", component=s.name, demand=s.bending_stress(Mq), capacity=s.yield_strength,
        required_sf=required_sf, title="Torsion spring bending stress",
        formula=r"\sigma = K_i \frac{32 M}{\pi d^3} \le S_y,\ K_i = \frac{4 C^2 - C - 1}{4 C (C - 1)}",
        source=f"{SHIGLEY}, Sec. 10-12, Eq. (10-43) (K_i), Eq. (10-57) (S_y)", inputs=_tor_inputs(s, Mq),
        substituted=(rf"\sigma = {tex(Ki)}\cdot \frac{{32\cdot {tex(Mq, 'N*mm')}}}{{\pi\cdot "
                     rf"({tex(s.wire_diameter, 'mm')})^{{3}}}} = {tex(s.bending_stress(Mq), 'MPa')}"),
        notes=(f"K_i = {Ki:.4g} (inner fibre, where the stress is highest when the spring winds up)",
               "the load must close (wind up) the coils; unwinding loads need the residual-stress-free allowable"))


@check("torsion_spring_arbor", title='Torsion spring clearance on its arbor', sf_kind="deflection",
       aliases=('torsion_spring.arbor_clearance',),
       source=ref("shigley10", "Sec. 10-12"),
       explain=('Arbor diameter against the inside diameter of the wound-up coil (Shigley Sec. 10-12); runs when '
                'arbor_diameter is given.'))
def check_torsion_spring_arbor(s: TorsionSpring, arbor_diameter: QuantityLike, M: QuantityLike, *,
                               required_sf: float = 1.0,
                            load_case: str = "") -> CheckResult:
    """The coil must not close onto its arbor: arbor diameter against the loaded inside diameter."""
    arbor = Q(to_si(arbor_diameter, "length", "arbor_diameter"), "m")
    Mq = Q(to_si(M, "torque", "M"), "N*m")
    Di = s.loaded_inside_diameter(Mq)
    return CheckResult(
        check="torsion_spring_arbor", component=s.name, demand=arbor.to("mm"), capacity=Di,
        required_sf=required_sf, load_case=load_case,
        title="Torsion spring clearance on its arbor",
        formula=r"D_{arbor} \le D_i' = \frac{D N_b}{N_b + \theta_c'} - d",
        source=f"{SHIGLEY}, Sec. 10-12 (coil diameter under load)",
        inputs={**_tor_inputs(s, Mq), "angle": s.angle(Mq)},
        substituted=_arbor_substituted(s, Mq, Di),
        notes=("theta_c' = body turns of wind-up (legs excluded), friction-corrected rate (Eq. (10-51))",
               "to keep a diametral clearance margin, set a required_sf (1.1 = 10 %)"))


def _arbor_substituted(s: TorsionSpring, M: Any, Di: Any) -> str:
    """D_i' = D N_b/(N_b + theta_c') - d, theta_c' = (theta/360 deg) N_b/N_a body turns."""
    Nb = s.Nb
    turns = float(s.angle(M).m_as("deg")) / 360 * Nb / s.active_turns
    return (rf"D_i' = \frac{{{tex(s.mean_diameter, 'mm')}\cdot {tex(Nb)}}}{{{tex(Nb)} + {tex(turns)}}} - "
            rf"{tex(s.wire_diameter, 'mm')} = {tex(Di, 'mm')}")


__all__ = ["check_spring_static_stress", "check_spring_solid_stress", "check_spring_buckling", "check_spring_fatigue",
           "check_spring_clash", "check_extension_body_stress", "check_extension_hook_bending",
           "check_extension_hook_torsion", "check_torsion_spring_stress", "check_torsion_spring_arbor"]
