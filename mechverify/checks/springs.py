"""Checks of helical compression springs: static stress, solid stress, buckling, fatigue, clash.

Each returns a :class:`CheckResult` oriented so that it passes while demand <= capacity / required_sf.
Defaults follow Shigley 10th ed. Ch. 10: static and solid design factor 1.2 (Sec. 10-7, "solid-safe"
with n_s >= 1.2), fatigue design factor 1.5 (Sec. 10-10), fractional overrun to closure xi = 0.15
(Sec. 10-7, robust linearity).
"""

from __future__ import annotations

from typing import Any

from mechverify.checks.result import CheckResult
from mechverify.components.springs_compression import CompressionSpring, en13906_min_gap_sum
from mechverify.errors import UnknownNameError
from mechverify.units import Q, fmt, to_si

SHIGLEY = "Shigley's Mechanical Engineering Design, 10th ed. (2015)"


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


def spring_static_stress(spring: CompressionSpring, F_max: Any, *, required_sf: float = 1.2,
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
        notes=(_factor_note(spring), f"required factor {required_sf:g} (Shigley Sec. 10-7 recommends n_s >= 1.2)"),
        load_case=load_case)


def spring_solid_stress(spring: CompressionSpring, *, required_sf: float = 1.2) -> CheckResult:
    """Shear stress when the spring is closed solid against S_sy ("solid-safe", Shigley Sec. 10-7)."""
    return CheckResult(
        check="spring_solid_stress", component=spring.name, demand=spring.solid_stress,
        capacity=spring.allowable_static_stress, required_sf=required_sf,
        title="Spring shear stress at solid length",
        formula=r"\tau_s = K_B \frac{8 k (L_0 - L_s) D}{\pi d^3} \le S_{sy}/n_s",
        source=f"{SHIGLEY}, Table 10-1, Eq. (10-7), Table 10-6",
        inputs={**_inputs(spring), "Ls": spring.solid_length, "F_solid": spring.solid_force.to("N")},
        notes=(_factor_note(spring), "a solid-safe spring cannot take a set when closed by accident",
               f"required factor {required_sf:g} (Shigley Sec. 10-7: n_s >= 1.2)"),
        load_case="closed solid")


def spring_buckling(spring: CompressionSpring, F_max: Any, *, end: str = "fixed-fixed",
                    required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """Working deflection against the critical (buckling) deflection for the given end condition.

    An absolutely stable spring (Shigley Eq. (10-13)) cannot buckle before it closes: the capacity is
    then the travel to solid, and a note says so.
    """
    y = _deflection(spring, F_max)
    y_cr = spring.critical_deflection(end)
    notes = [f"end condition {end!r}, alpha = {spring._alpha(end):g} (Shigley Table 10-2; EN 13906-1 nu)"]
    if y_cr is None or y_cr > spring.solid_deflection:
        capacity = spring.solid_deflection
        notes.append(f"absolutely stable: L0 = {fmt(spring.free_length, 'mm')} <= critical free length "
                     f"{fmt(spring.critical_free_length(end), 'mm')} (or buckling only beyond solid)")
    else:
        capacity = y_cr
    return CheckResult(
        check="spring_buckling", component=spring.name, demand=y, capacity=capacity, required_sf=required_sf,
        title="Spring buckling (critical deflection)",
        formula=r"y_{cr} = L_0 C_1' \left[1 - \sqrt{1 - C_2'/\lambda_{eff}^2}\right],\ \lambda_{eff} = \alpha L_0/D",
        source=f"{SHIGLEY}, Eqs. (10-10)..(10-13), Table 10-2; EN 13906-1:2013 Sec. 9",
        inputs={**_inputs(spring), "F_max": Q(to_si(F_max, "force", "F_max"), "N"), "E": Q(spring._si["E"], "Pa"),
                "G": Q(spring._si["G"], "Pa")},
        notes=tuple(notes), load_case=load_case)


def spring_fatigue(spring: CompressionSpring, F_min: Any, F_max: Any, *, criterion: str = "gerber",
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
        formula=r"\tau_a = K_B \frac{8 F_a D}{\pi d^3},\ S_{se}: \text{Zimmerli point on the criterion},\ "
                r"n_f = S_{sa}/\tau_a",
        source=f"{SHIGLEY}, Secs. 10-9, 10-10, Eq. (10-30); mean-stress criterion from mechverify.fatigue.criteria",
        inputs={**_inputs(spring), "F_min": Q(to_si(F_min, "force", "F_min"), "N"),
                "F_max": Q(to_si(F_max, "force", "F_max"), "N")},
        notes=tuple(notes), warnings=tuple(warnings), load_case=load_case,
        details={"tau_m": f.tau_m, "Ssu": f.Ssu, "Sse": f.Sse, "Ssy": f.Ssy, "n_f": f.n_f, "n_y": f.n_y})


def spring_clash(spring: CompressionSpring, F_max: Any, *, method: str = "shigley", xi: float = 0.15,
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
    elif method == "en13906":
        Sa = en13906_min_gap_sum(spring.wire_diameter, spring.mean_diameter, spring.active_coils, dynamic)
        demand, capacity = (y + Sa).to("mm"), travel
        formula = r"y_{max} + S_a \le L_0 - L_s,\ S_a = (0.0015 D^2/d + 0.1 d)\, n"
        source = "EN 13906-1:2013, Sec. 10 (minimum sum of gaps between active coils)"
        note = f"minimum sum of gaps S_a = {fmt(Sa, 'mm')} ({'dynamic, doubled' if dynamic else 'static'})"
    else:
        raise UnknownNameError("clash method", method, ["shigley", "en13906"])
    return CheckResult(
        check="spring_clash", component=spring.name, demand=demand, capacity=capacity, title="Spring clash allowance",
        formula=formula, source=source,
        inputs={**_inputs(spring), "F_max": Q(to_si(F_max, "force", "F_max"), "N"), "Ls": spring.solid_length},
        notes=(note,), load_case=load_case)


__all__ = ["spring_static_stress", "spring_solid_stress", "spring_buckling", "spring_fatigue", "spring_clash"]
