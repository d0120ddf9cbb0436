"""Checks of shafts (Shigley 10th ed. Ch. 7): fatigue at every feature and at the section of largest moment by
the distortion-energy criteria (DE-Goodman, DE-Gerber, DE-ASME-elliptic, DE-Soderberg), first-cycle yield,
slope at the bearings, deflection at gears, critical speed, and key shear and crushing.

Each check takes the :class:`~mechverify.components.shafts.Shaft` and its
:class:`~mechverify.fea.shafts.ShaftAnalysis`; :func:`section_stresses` gives the stresses at every section
(feature or max-moment section), which the fatigue and yield checks and the report figure share.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components import shafts as s
from mechverify.errors import InputError
from mechverify.fatigue import criteria, notch
from mechverify.fatigue.endurance import corrected_endurance_limit
from mechverify.fea.shafts import CriticalSpeed, ModalCriticalSpeeds, ShaftAnalysis
from mechverify.references import ref
from mechverify.units import Q

CRITERIA = ("goodman", "gerber", "asme_elliptic", "soderberg")
_FORMULA = {
    "goodman": r"\frac{1}{n} = \frac{\sigma_a'}{S_e} + \frac{\sigma_m'}{S_{ut}}",
    "gerber": r"\frac{n\sigma_a'}{S_e} + \left(\frac{n\sigma_m'}{S_{ut}}\right)^2 = 1",
    "asme_elliptic": r"\left(\frac{n\sigma_a'}{S_e}\right)^2 + \left(\frac{n\sigma_m'}{S_y}\right)^2 = 1",
    "soderberg": r"\frac{1}{n} = \frac{\sigma_a'}{S_e} + \frac{\sigma_m'}{S_y}",
}
_DE = r",\ \sigma_a' = \sqrt{\left(\frac{32K_fM_a}{\pi d^3}\right)^2 + 3\left(\frac{16K_{fs}T_a}{\pi d^3}\right)^2}"
_EQ = {"goodman": "Eq. 7-7", "gerber": "Eq. 7-9", "asme_elliptic": "Eq. 7-11", "soderberg": "Eq. 7-13"}


@dataclass(frozen=True)
class SectionStress:
    """Stresses and fatigue factors at one section of the shaft (SI)."""

    name: str
    x: float
    d: float
    Kt: float
    Kts: float
    Kf: float
    Kfs: float
    kt_source: str
    M: float
    T: float
    N: float
    sigma_a: float  # von Mises alternating (Eq. 7-5 form with axial in the mean)
    sigma_m: float
    sigma_max: float  # Eq. 7-15
    Se: float
    factors: dict[str, float]
    bore: float = 0.0
    Ta: float = 0.0
    Ma: float = 0.0
    Mm: float = 0.0

    def n(self, criterion: str, Sut: float, Sy: float) -> float:
        """Fatigue safety factor by a DE criterion (proportional load line), Shigley Eqs. 7-7..7-14."""
        if self.sigma_a <= 0:
            return math.inf if self.sigma_m <= 0 else (Sut if criterion in ("goodman", "gerber") else Sy) / self.sigma_m
        fn = {"goodman": criteria.goodman, "gerber": criteria.gerber, "asme_elliptic": criteria.asme_elliptic,
              "soderberg": criteria.soderberg}[criterion]
        S = Sut if criterion in ("goodman", "gerber") else Sy
        return float(fn(Q(self.sigma_a, "Pa"), Q(self.sigma_m, "Pa"), Q(self.Se, "Pa"), Q(S, "Pa")))


def de_stresses(Ma: float, Mm: float, Ta: float, Tm: float, D: float, Kf: float, Kfs: float, *, bore: float = 0.0,
                N: float = 0.0) -> tuple[float, float, float]:
    """(sigma_a', sigma_m', sigma'_max) [Pa] of a round section, Shigley 10th ed. Eqs. 7-5, 7-6, 7-15:
    ``sigma_a' = sqrt((Kf 32 Ma/(pi d^3))^2 + 3 (Kfs 16 Ta/(pi d^3))^2)``, the same with the mean values
    (plus a steady axial stress Kf N/A), and the peak ``sqrt((sigma_a + sigma_m)^2 + 3 (tau_a + tau_m)^2)``;
    hollow sections use W = pi (D^4 - d^4)/(32 D)."""
    W, Wt = s.section_moduli(D, bore)
    A = math.pi / 4 * (D**2 - bore**2)
    sa, sm = Kf * Ma / W, Kf * Mm / W + Kf * N / A
    ta, tm = Kfs * Ta / Wt, Kfs * Tm / Wt
    return math.hypot(sa, math.sqrt(3) * ta), math.hypot(sm, math.sqrt(3) * tm), \
        math.hypot(sa + sm, math.sqrt(3) * (ta + tm))


def _section(shaft: s.Shaft, a: ShaftAnalysis, name: str, x: float, D: float, bore: float, Kt: float, Kts: float,
             r: float, src: str) -> SectionStress:
    Sut = shaft.material.require("ultimate_strength").m_as("Pa")
    Kf = notch.neuber_kf(Kt, Q(r, "m"), Q(Sut, "Pa"), "bending").m if Kt > 1 and r > 0 else Kt
    Kfs = notch.neuber_kf(Kts, Q(r, "m"), Q(Sut, "Pa"), "torsion").m if Kts > 1 and r > 0 else Kts
    v = a.at(x)
    M, T, N = v["M"], v["T"], max(v["N"], 0.0)
    if M < 1e-9 * float(a.M.max()):  # round-off of a section the loads do not bend
        M = 0.0
    Ma, Mm = (M, 0.0) if shaft.rotating else (0.0, M)
    Ta, Tm = shaft.torque_alternating_fraction * T, T
    sa, sm, smax = de_stresses(Ma, Mm, Ta, Tm, D, Kf, Kfs, bore=bore, N=N)
    if sa < 1e-9 * max(sm, smax):  # round-off of a section the loads do not bend
        sa = 0.0
    el = corrected_endurance_limit(Q(Sut, "Pa"), finish=shaft.finish, d=Q(D, "m"), loading="bending",
                                   reliability=shaft.reliability)
    return SectionStress(name, x, D, Kt, Kts, Kf, Kfs, src, M, T, N, sa, sm, smax, el.Se.m_as("Pa"),
                         el.factors.as_dict(), bore, Ta, Ma, Mm)


MAX_MOMENT_SECTION = "the section of maximum moment"  # name of the plain section at the largest moment


def section_stresses(shaft: s.Shaft, a: ShaftAnalysis) -> list[SectionStress]:
    """Stresses at every feature (Kt from :meth:`Shaft.stress_concentration`, Kf/Kfs by Neuber, Shigley Eqs.
    6-32..6-35) and at the section of the largest moment (Kt = 1 unless a feature sits there)."""
    out = []
    for f in shaft.features:
        Kt, Kts, src = shaft.stress_concentration(f)
        D, bore = shaft.net_diameter(f)
        out.append(_section(shaft, a, f.label, f.x, D, bore, Kt, Kts,
                            shaft.notch_radius(f), src))
    xm, _ = a.max_moment()
    if not any(abs(f.x - xm) < 1e-9 for f in shaft.features):
        seg = shaft.segment_at(xm)
        out.append(_section(shaft, a, f"{MAX_MOMENT_SECTION} (x = {xm * 1e3:.4g} mm)", xm, seg.diameter, seg.bore,
                            1.0, 1.0, 0.0, "plain section"))
    return out


def layout(shaft: s.Shaft, a: ShaftAnalysis) -> dict[str, object]:
    """What the report figure needs (SI floats): segments, features, supports, loads and the diagrams."""
    b = shaft.boundaries
    return {"segments": [(b[i], b[i + 1], g.diameter, g.bore) for i, g in enumerate(shaft.segments)],
            "features": [(f.x, f.kind, f.name) for f in shaft.features],
            "supports": [(sp.x, sp.name) for sp in shaft.supports],
            "loads": [(ld.x, ld.kind, ld.name) for ld in shaft.loads],
            "x": a.x.tolist(), "My": a.My.tolist(), "Mz": a.Mz.tolist(), "M": a.M.tolist(), "T": a.T.tolist(),
            "deflection": a.deflection.tolist()}


def _strengths(shaft: s.Shaft) -> tuple[float, float]:
    return shaft.material.require("ultimate_strength").m_as("Pa"), shaft.material.require("yield_strength").m_as("Pa")


def _MPa(v: float) -> object:
    return Q(v / 1e6, "MPa")


def _feature_warnings(shaft: s.Shaft) -> tuple[str, ...]:
    """Caveats of unverified Table 7-1 rows the features' Kt come from (deduplicated)."""
    return tuple(dict.fromkeys(w for f in shaft.features for w in shaft.data_warnings(f)))


def _n_substituted(criterion: str, g: SectionStress, Sut: float, Sy: float, n: float) -> str:
    """The DE criterion with the section's stresses and strengths substituted, = n (Shigley Eqs. 7-7 to 7-14)."""
    a, m, e = tex(_MPa(g.sigma_a), "MPa"), tex(_MPa(g.sigma_m), "MPa"), tex(_MPa(g.Se), "MPa")
    S = tex(_MPa(Sut if criterion in ("goodman", "gerber") else Sy), "MPa")
    res = tex(n)
    if g.sigma_a <= 0:
        return rf"n = \frac{{{S}}}{{{m}}} = {res}"
    if g.sigma_m <= 0:
        return rf"n = \frac{{{e}}}{{{a}}} = {res}"
    if criterion in ("goodman", "soderberg"):
        return rf"n = \frac{{1}}{{\frac{{{a}}}{{{e}}} + \frac{{{m}}}{{{S}}}}} = {res}"
    if criterion == "asme_elliptic":
        return (rf"n = \frac{{1}}{{\sqrt{{\left(\frac{{{a}}}{{{e}}}\right)^{{2}} + "
                rf"\left(\frac{{{m}}}{{{S}}}\right)^{{2}}}}}} = {res}")
    # Gerber, Eq. 7-9 solved for n: n = (1/2)(Sut/sm)^2 (sa/Se) [-1 + sqrt(1 + (2 sm Se/(Sut sa))^2)]
    return (rf"n = \frac{{1}}{{2}}\cdot \left(\frac{{{S}}}{{{m}}}\right)^{{2}}\cdot \frac{{{a}}}{{{e}}}\cdot "
            rf"\left(-1 + \sqrt{{1 + \left(\frac{{2\cdot {m}\cdot {e}}}{{{S}\cdot {a}}}\right)^{{2}}}}\right) = {res}")


def _smax_substituted(g: SectionStress) -> str:
    """sigma'_max of Eq. 7-15 with the section's Kf, Kfs, moments and diameter substituted (solid: 32/(pi d^3),
    hollow: the section modulus W = pi (D^4 - d^4)/(32 D) as a number; a tensile axial force adds Kf N/A)."""
    D = tex(Q(g.d * 1e3, "mm"), "mm")
    M = tex(Q(g.Ma + g.Mm, "N*m"), "N*m")
    T = tex(Q(g.T + g.Ta, "N*m"), "N*m")
    kf, kfs = tex(g.Kf), tex(g.Kfs)
    if g.bore:
        W = math.pi * (g.d**4 - g.bore**4) / (32 * g.d)
        Wt = tex(Q(2 * W * 1e9, "mm**3"), "mm**3")
        Ws = tex(Q(W * 1e9, "mm**3"), "mm**3")
        bend, tors = rf"\frac{{{kf}\cdot {M}}}{{{Ws}}}", rf"\frac{{{kfs}\cdot {T}}}{{{Wt}}}"
    else:
        bend = rf"\frac{{32\cdot {kf}\cdot {M}}}{{\pi\cdot ({D})^{{3}}}}"
        tors = rf"\frac{{16\cdot {kfs}\cdot {T}}}{{\pi\cdot ({D})^{{3}}}}"
    if g.N > 0:
        A = math.pi / 4 * (g.d**2 - g.bore**2)
        bend += rf" + \frac{{{kf}\cdot {tex(Q(g.N, 'N'), 'N')}}}{{{tex(Q(A * 1e6, 'mm**2'), 'mm**2')}}}"
    return (rf"\sigma'_{{max}} = \sqrt{{\left({bend}\right)^{{2}} + 3\cdot \left({tors}\right)^{{2}}}} = "
            rf"{tex(_MPa(g.sigma_max), 'MPa')}")


@check("shaft_fatigue", title="Shaft fatigue (distortion energy)", sf_kind="fatigue",
       source=ref("shigley10", "Sec. 7-4, Eqs. 7-7 to 7-14; Eqs. 6-18, 6-32 to 6-35"),
       explain=("At every feature (shoulder fillet, keyseat, groove, ...) and at the section of largest bending "
                "moment: von Mises alternating and mean stresses sigma_a' = sqrt((Kf 32 Ma/pi d^3)^2 + "
                "3 (Kfs 16 Ta/pi d^3)^2) and sigma_m' likewise (a rotating shaft turns the bending moment into a "
                "fully reversed stress, the torque is steady), Kf and Kfs from Kt by Neuber's notch sensitivity, "
                "the Marin-corrected endurance limit Se; the safety factor by the chosen criterion (DE-Goodman by "
                "default, or DE-Gerber, DE-ASME-elliptic, DE-Soderberg), reported at the governing section."))
def check_shaft_fatigue(shaft: s.Shaft, a: ShaftAnalysis, *, criterion: str = "goodman", required_sf: float = 1.5,
                        load_case: str = "") -> CheckResult:
    """Lowest fatigue safety factor over the sections, Shigley Eqs. 7-7 to 7-14."""
    if criterion not in CRITERIA:
        raise InputError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    Sut, Sy = _strengths(shaft)
    secs = section_stresses(shaft, a)
    ns = [sec.n(criterion, Sut, Sy) for sec in secs]
    k = min(range(len(secs)), key=lambda i: ns[i])
    g, n = secs[k], ns[k]
    demand = g.sigma_a if g.sigma_a > 0 else g.sigma_m
    return CheckResult(
        check="shaft_fatigue", component=shaft.name, demand=_MPa(demand),
        capacity=_MPa(demand * n if math.isfinite(n) else 1e12), required_sf=required_sf,
        title=f"Shaft fatigue, DE-{criterion.replace('_', '-')}, at {g.name}",
        formula=_FORMULA[criterion] + _DE,
        source=ref("shigley10", f"Sec. 7-4, {_EQ[criterion]}"),
        inputs={"d": Q(g.d * 1e3, "mm"), "M": Q(g.M, "N*m"), "T": Q(g.T, "N*m"), "Kt": Q(g.Kt, ""),
                "Kts": Q(g.Kts, ""), "Kf": Q(g.Kf, ""), "Kfs": Q(g.Kfs, ""), "Se": _MPa(g.Se), "Sut": _MPa(Sut),
                "Sy": _MPa(Sy), "sigma_a'": _MPa(g.sigma_a), "sigma_m'": _MPa(g.sigma_m)},
        notes=(f"Kt source: {g.kt_source}",
               "Marin factors: " + ", ".join(f"{k}={v:.3f}" for k, v in g.factors.items())),
        substituted=_n_substituted(criterion, g, Sut, Sy, n) if math.isfinite(n) else "",
        warnings=_feature_warnings(shaft),
        load_case=load_case,
        details={"sections": [{"name": sec.name, "label": sec.name.replace(MAX_MOMENT_SECTION, "max. M"), "x": sec.x,
                               "n": ns[i], "Kf": sec.Kf, "Kfs": sec.Kfs}
                              for i, sec in enumerate(secs)], "criterion": criterion, **layout(shaft, a)})


@check("shaft_static_yield", title="Shaft first-cycle yield (von Mises, peak loads)", sf_kind="static",
       source=ref("shigley10", "Sec. 7-4, Eqs. 7-15, 7-16"),
       explain=("The von Mises peak stress sigma'_max = sqrt((sigma_m + sigma_a)^2 + 3 (tau_m + tau_a)^2) with the "
                "fatigue stress-concentration factors, at every feature and at the largest-moment section, against "
                "the yield strength: n_y = Sy / sigma'_max (Shigley Eqs. 7-15, 7-16)."))
def check_shaft_static_yield(shaft: s.Shaft, a: ShaftAnalysis, *, required_sf: float = 2.0,
                             load_case: str = "") -> CheckResult:
    """Largest sigma'_max against Sy (Shigley Eqs. 7-15, 7-16)."""
    _, Sy = _strengths(shaft)
    secs = section_stresses(shaft, a)
    g = max(secs, key=lambda v: v.sigma_max)
    return CheckResult(
        check="shaft_static_yield", component=shaft.name, demand=_MPa(g.sigma_max), capacity=_MPa(Sy),
        required_sf=required_sf, title=f"Shaft yield at {g.name}",
        formula=r"\sigma'_{max} = \sqrt{(\sigma_m + \sigma_a)^2 + 3(\tau_m + \tau_a)^2} \le S_y",
        source=ref("shigley10", "Eqs. 7-15, 7-16"),
        inputs={"d": Q(g.d * 1e3, "mm"), "M": Q(g.M, "N*m"), "T": Q(g.T, "N*m"), "Kf": Q(g.Kf, ""),
                "Kfs": Q(g.Kfs, "")}, load_case=load_case, substituted=_smax_substituted(g),
        warnings=_feature_warnings(shaft),
        details={"sections": [{"name": v.name, "x": v.x, "n": Sy / v.sigma_max if v.sigma_max else math.inf}
                              for v in secs]})


@check("shaft_bearing_slope", title="Shaft slope at the bearings", sf_kind="deflection",
       source=ref("shigley10", "Sec. 7-5, Table 7-2"),
       explain=("The resultant slope of the shaft at each bearing (frame FEA, Timoshenko elements) against the upper "
                "value of the typical maximum slope of its bearing type (Shigley Table 7-2: deep-groove ball "
                "0.001-0.003 rad, cylindrical roller 0.0008-0.0012, tapered roller 0.0005-0.0012, self-aligning "
                "0.026-0.052); the governing bearing is reported."))
def check_shaft_bearing_slope(shaft: s.Shaft, a: ShaftAnalysis, *, required_sf: float = 1.0,
                              load_case: str = "") -> CheckResult:
    """Slope / allowance, governing bearing."""
    ratios = []
    for sup in shaft.supports:
        allow = s.slope_allowance(sup.bearing)[1]
        ratios.append((a.slopes[sup.name] / allow, sup, allow))
    u, sup, allow = max(ratios, key=lambda t: t[0])
    return CheckResult(
        check="shaft_bearing_slope", component=shaft.name, demand=Q(a.slopes[sup.name], "rad"),
        capacity=Q(allow, "rad"), required_sf=required_sf, title=f"Shaft slope at bearing {sup.name} ({sup.bearing})",
        formula=r"\theta = \sqrt{\theta_y^2 + \theta_z^2} \le \theta_{allow}\ \mathrm{(Table\ 7\text{-}2)}",
        source=ref("shigley10", "Table 7-2"), inputs={"bearing": sup.bearing}, load_case=load_case,
        substituted=_slope_substituted(a, sup.name),
        notes=("Table 7-2 values checked against the printed table (see components/data/shafts.toml)",),
        warnings=s.table_caveat("slope_allowance", sup.bearing, "Table 7-2 slope"),
        details={"slopes": {k: v for k, v in a.slopes.items()}})


def _slope_substituted(a: ShaftAnalysis, name: str) -> str:
    ty, tz = a.slope_components.get(name, (a.slopes[name], 0.0))
    label = name.replace("_", r"\_")
    return (rf"\theta_{{\mathrm{{{label}}}}} = \sqrt{{({tex(Q(ty, 'rad'), 'rad')})^{{2}} + "
            rf"({tex(Q(tz, 'rad'), 'rad')})^{{2}}}} = {tex(Q(a.slopes[name], 'rad'), 'rad')}")


@check("shaft_gear_deflection", title="Shaft deflection at the gears", sf_kind="deflection",
       source=ref("shigley10", "Sec. 7-5, Table 7-2"),
       explain=("The resultant transverse deflection at each spur or helical gear against Shigley Table 7-2's "
                "typical maximum by diametral pitch (0.010 in for P <= 10, 0.005 in for 11-19, 0.003 in for "
                "20-50; P = 25.4/m for a module m in mm)."))
def check_shaft_gear_deflection(shaft: s.Shaft, a: ShaftAnalysis, *, required_sf: float = 1.0,
                                load_case: str = "") -> list[CheckResult]:
    """Deflection / allowance at each gear with a module."""
    out = []
    for ld in shaft.loads:
        if ld.kind != "gear" or not ld.module > 0:
            continue
        P = 0.0254 / ld.module
        allow = s.gear_deflection_allowance(P)
        v = a.at(ld.x)
        y = v["deflection"]
        out.append(CheckResult(
            check="shaft_gear_deflection", component=shaft.name, demand=Q(y * 1e3, "mm"),
            capacity=Q(allow * 1e3, "mm"), required_sf=required_sf, title=f"Shaft deflection at gear {ld.name}",
            formula=r"y = \sqrt{y_y^2 + y_z^2} \le y_{allow}(P)",
            source=ref("shigley10", "Table 7-2"), inputs={"module": Q(ld.module * 1e3, "mm"), "P": Q(P, "1/in")},
            substituted=(rf"y = \sqrt{{({tex(Q(v['uy'] * 1e3, 'mm'), 'mm')})^{{2}} + "
                         rf"({tex(Q(v['uz'] * 1e3, 'mm'), 'mm')})^{{2}}}} = {tex(Q(y * 1e3, 'mm'), 'mm')}"),
            warnings=s.table_caveat("gear_deflection_allowance_in", what="Table 7-2 gear deflection"),
            load_case=load_case))
    return out


@check("shaft_critical_speed", title="Shaft first critical speed", sf_kind="speed",
       source=ref("shigley10", "Sec. 7-6, Eqs. 7-23, 7-24"),
       explain=("The operating speed against the first lateral critical speed: the first lateral natural frequency "
                "of the shaft on its bearings from the frame's modal solution K phi = omega^2 M phi (consistent "
                "mass of the shaft's members and the mounted masses; Shigley Sec. 7-6 identifies the first critical "
                "speed with it; a shaft without its own mass uses the shaft's planar consistent-mass eigenproblem), "
                "with Rayleigh's estimate (Eq. 7-23, static deflections under the weights, an "
                "upper bound of the lumped system) and Dunkerley's (Eq. 7-24, influence coefficients, a lower "
                "bound) from the same frame model as cross-checks; without the modal solution the lower of the "
                "two closed forms decides. The margin omega_c/omega is asked to exceed the speed safety factor "
                "(Shigley suggests 2)."))
def check_shaft_critical_speed(shaft: s.Shaft, cs: CriticalSpeed, *, modal: ModalCriticalSpeeds | None = None,
                               required_sf: float = 1.25, load_case: str = "") -> CheckResult:
    """Operating speed against the modal first critical speed (or min(Rayleigh, Dunkerley) without ``modal``)."""
    wc = modal.first if modal is not None else min(cs.rayleigh, cs.dunkerley)
    rpm = 60 / (2 * math.pi)
    g = s.G_STANDARD
    S1 = sum(m * g * y for m, y in zip(cs.masses, cs.deflections, strict=True))
    S2 = sum(m * g * y * y for m, y in zip(cs.masses, cs.deflections, strict=True))
    inputs: dict[str, object] = {"Rayleigh": Q(cs.rayleigh * rpm, "rpm"), "Dunkerley": Q(cs.dunkerley * rpm, "rpm"),
                                 "masses": len(cs.masses)}
    notes: tuple[str, ...] = ()
    if modal is not None:
        inputs = {"modal": Q(modal.first * rpm, "rpm"), **inputs}
        notes = (f"capacity: first lateral natural frequency of the consistent-mass model ({modal.elements} elements, "
                 f"{modal.theory}); Rayleigh/Dunkerley on {len(cs.masses)} lumped masses as cross-checks",)
    return CheckResult(
        check="shaft_critical_speed", component=shaft.name, demand=Q(shaft.speed * rpm, "rpm"),
        capacity=Q(wc * rpm, "rpm"), required_sf=required_sf, title="Shaft first critical speed",
        formula=(r"K\phi = \omega^2 M\phi,\quad " if modal is not None else "")
        + r"\omega_1 = \sqrt{\frac{g\sum w_i y_i}{\sum w_i y_i^2}},\quad "
          r"\frac{1}{\omega_1^2} = \sum \frac{1}{\omega_{ii}^2}",
        substituted=(rf"\omega_{{R}} = \sqrt{{\frac{{{tex(Q(g, 'm/s**2'), 'm/s**2')}\cdot {tex(Q(S1, 'N*m'), 'N*m')}}}"
                     rf"{{{tex(Q(S2, 'N*m**2'), 'N*m**2')}}}}} = {tex(Q(cs.rayleigh, 'rad/s'), 'rad/s')}"),
        source=ref("shigley10", "Sec. 7-6, Eqs. 7-23, 7-24"), notes=notes,
        inputs=inputs, load_case=load_case)


def _keys(shaft: s.Shaft, a: ShaftAnalysis) -> list[tuple[s.Feature, float, float, float, float, float, float, float,
                                                         tuple[str, ...]]]:
    out = []
    for f in shaft.features:
        if f.kind != "keyseat":
            continue
        d = shaft.segment_at(f.x).diameter
        std = s.standard_key(d, shaft.key_standard)
        caveat = s.key_caveat(d, shaft.key_standard) if not (f.width and f.depth) else ()
        b = f.width or std["b"]
        t1 = f.depth or std["t1"]
        h = std["h"] if not f.width else std["h"] * b / std["b"]
        if not f.length > 0:
            raise InputError(f"shaft {shaft.name}: keyseat {f.label}: give the key length for the key checks")
        T = a.at(f.x)["T"]
        tau, p = s.key_stresses(T, d, b, h, t1, f.length)
        out.append((f, d, b, h, tau, p, T, t1, caveat))
    return out


def _key_results(check_name: str, shaft: s.Shaft, a: ShaftAnalysis, *, crushing: bool, key_yield: float | None,
                 required_sf: float, load_case: str) -> list[CheckResult]:
    """One result per keyseat: shear tau = 2T/(d b l) against 0.577 Sy, or crushing p = 2T/(d (h - t1) l) against
    Sy (Shigley 10th ed., Sec. 7-7)."""
    Sy = key_yield or _strengths(shaft)[1]
    out = []
    for f, d, b, h, tau, p, T, t1, caveat in _keys(shaft, a):
        if crushing:  # the key's part in the hub, h - t1, bears the force
            what, sym, stress, allow, allow_tex = "crushing", "p", p, Sy, "S_y"
            w, w_tex, (w_in, w_in_value) = h - t1, "(h - t_1)", ("h", h)
        else:  # the key's width b shears
            what, sym, stress, allow, allow_tex = "shear", r"\tau", tau, 0.577 * Sy, r"0.577\,S_y"
            w, w_tex, (w_in, w_in_value) = b, "b", ("b", b)
        out.append(CheckResult(
            check=check_name, component=shaft.name, demand=_MPa(stress), capacity=_MPa(allow),
            required_sf=required_sf, title=f"Key {what} at {f.label}",
            formula=rf"{sym} = \frac{{2T}}{{d\,{w_tex}\,l}} \le {allow_tex}",
            substituted=(rf"{sym} = \frac{{2\cdot {tex(Q(T, 'N*m'))}}}{{{tex(Q(d * 1e3, 'mm'))}\cdot "
                         rf"{tex(Q(w * 1e3, 'mm'))}\cdot {tex(Q(f.length * 1e3, 'mm'))}}} = "
                         rf"{tex(Q(stress / 1e6, 'MPa'))}"),
            source=ref("shigley10", "Sec. 7-7"),
            inputs={"d": Q(d * 1e3, "mm"), w_in: Q(w_in_value * 1e3, "mm"), "l": Q(f.length * 1e3, "mm")},
            warnings=caveat, load_case=load_case))
    return out


@check("shaft_key_shear", title="Parallel key shear", sf_kind="static",
       source=ref("shigley10", "Sec. 7-7, Ex. 7-6") + "; " + ref("din6885"),
       explain=("The force F = 2T/d at the shaft surface shears the key over its width times length, tau = F/(b l), "
                "against the shear yield strength 0.577 Sy of the key material (distortion energy, Shigley Sec. "
                "7-7); key sizes from DIN 6885-1 when not given."))
def check_shaft_key_shear(shaft: s.Shaft, a: ShaftAnalysis, *, key_yield: float | None = None,
                          required_sf: float = 2.0, load_case: str = "") -> list[CheckResult]:
    """tau = 2T/(d b l) against 0.577 Sy per keyseat."""
    return _key_results("shaft_key_shear", shaft, a, crushing=False, key_yield=key_yield, required_sf=required_sf,
                        load_case=load_case)


@check("shaft_key_crushing", title="Parallel key crushing (bearing)", sf_kind="static",
       source=ref("shigley10", "Sec. 7-7, Ex. 7-6") + "; " + ref("din6885"),
       explain=("The force F = 2T/d bears on the part of the key standing in the hub, height h - t1, over its "
                "length: p = F/((h - t1) l) against the yield strength Sy of the key material (Shigley Ex. 7-6 "
                "compares the bearing stress with Sy); DIN 6885-1 sizes when not given."))
def check_shaft_key_crushing(shaft: s.Shaft, a: ShaftAnalysis, *, key_yield: float | None = None,
                             required_sf: float = 2.0, load_case: str = "") -> list[CheckResult]:
    """p = 2T/(d (h - t1) l) against Sy per keyseat."""
    return _key_results("shaft_key_crushing", shaft, a, crushing=True, key_yield=key_yield, required_sf=required_sf,
                        load_case=load_case)
