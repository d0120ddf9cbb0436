"""Checks of rolling bearings (rating life, static safety, speed) and plain bushings (p, v, pv).

Each returns a :class:`CheckResult` oriented so that it passes while demand <= capacity / required_sf.
"""

from __future__ import annotations

import math
from typing import Any

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components.bearings import (
    BallBearing,
    DutyCycleLoad,
    EquivalentLoad,
    Lubrication,
    PlainBushing,
    basic_rating_life,
    life_hours,
    modified_rating_life,
    reliability_factor,
)
from mechverify.components.bearings_rolling import RollingBearing
from mechverify.components.memo import once
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, exceeds, fmt, si_to, to_si

ISO281 = ref("iso281", "Eq. (1), Table 3 (X, Y, e), Table 12 (a1)")
ISO76 = ref("iso76", "Sec. 6.2.2 (P0 = 0.6 Fr + 0.5 Fa >= Fr); s0 = C0/P0")
BUSHING = f"{ref('shigley10', 'Sec. 12-15')}; bushing maker's limits"


AnyBearing = BallBearing | RollingBearing


def _exponent(b: AnyBearing) -> float:
    """The life exponent p: 3 (ball), 10/3 (roller)."""
    return float(getattr(b, "life_exponent", 3.0))


def _p_tex(p: float) -> str:
    return "3" if p == 3 else r"\frac{10}{3}"


def _life_substituted(a1: float, C: Any, P: Any, p: float, n: Any, Lh: Any, a_iso: float | None = None) -> str:
    """L = a1 [a_ISO] (C/P)^p 10^6 rev / n, in hours (evaluates back with its units)."""
    factors = tex(a1) + (rf"\cdot {tex(a_iso)}" if a_iso is not None else "")
    return (rf"L_{{h}} = {factors}\cdot \left(\frac{{{tex(C, 'kN')}}}{{{tex(P, 'kN')}}}\right)^{{{_p_tex(p)}}}"
            rf"\cdot \frac{{10^{{6}}\,\mathrm{{turn}}}}{{{tex(n, 'rpm')}}} = {tex(Lh, 'hour')}")


def provenance_warning(b: AnyBearing) -> tuple[str, ...]:
    """The caveat of a catalogue row not verified against its source (empty for a verified row)."""
    if not b.unverified:
        return ()
    return (f"data not verified against source: bearing {b.designation} ({b.unverified}; {b.source})",)


def _axial_warning(b: AnyBearing, Fa: Any) -> tuple[str, ...]:
    fa = to_si(Fa, "force", "Fa")
    limit, limit_root, provenance = once("bearing.axial_limit", (b,), lambda: _axial_limit(b))
    if limit is not None and fa * _N_ROOT > limit_root:  # what pint's Q(fa, "N") > limit compares (root units)
        return (f"axial load {fmt(Q(fa, 'N').to('kN'))} exceeds {fmt(limit)} recommended for "
                f"deep groove ball bearing {b.designation} (SKF 17000 EN: 0.25 C0 small/light series, else 0.5 C0)",
                *provenance)
    return provenance


def _axial_limit(b: AnyBearing) -> tuple[Any, float | None, tuple[str, ...]]:
    """The bearing's recommended axial load limit, its magnitude in pint's root units and the provenance
    warning."""
    limit = b.axial_load_limit
    return limit, None if limit is None else limit.to_root_units().magnitude, provenance_warning(b)


_N_ROOT = Q(1.0, "N").to_root_units().magnitude  # pint's factor from N to its root units (g·m/s²)


def _e_text(e: float) -> str:
    """The note's limit ratio e: no e where P comes from an adjusted pair's rule (Timken: F_e = 0.4 Fr + K Fa
    when that exceeds Fr; e is NaN), none where the bearing takes no axial load (e = inf)."""
    if math.isnan(e):
        return "no e limit: P from the adjusted pair's rule, F_e = max(0.4 Fr + K·Fa, Fr)"
    if math.isinf(e):
        return "no axial load: P = Fr"
    return f"e = {e:.3g}"


@check("bearing_life", title="Bearing rating life", sf_kind="bearing",
       aliases=('ball_bearing.life',),
       source=ISO281,
       explain=('L10h = a1 (C/P)^p 10^6/(60 n), p = 3 ball, 10/3 roller bearings, P = X Fr + Y Fa with the '
                "ISO 281 factors (deep groove) or the maker's (other types) (ISO 281 Eq. (1), Table 3), against "
                'the required life.'))
def check_bearing_life(b: AnyBearing, Fr: QuantityLike, Fa: QuantityLike, speed: QuantityLike,
                       required_life: QuantityLike, *, reliability: float = 0.9,
                       duty_cycle: DutyCycleLoad | None = None, equivalent: EquivalentLoad | None = None,
                       load_case: str = "") -> CheckResult:
    """Rating life L_nh = a1·(C/P)^p/(60 n) against the required life in hours.

    With ``duty_cycle`` its equivalent load and mean speed replace those of (Fr, Fa, speed); ``equivalent``
    replaces the bearing's own equivalent load (two bearings adjusted against each other, Timken's rule).
    """
    eq = equivalent if equivalent is not None else b.equivalent_load(Fr, Fa)
    a1 = reliability_factor(reliability)
    p = _exponent(b)
    if duty_cycle is not None:
        speed = duty_cycle.mean_speed if duty_cycle.mean_speed is not None else speed
        P = duty_cycle.P
    else:
        P = eq.P
    L0 = basic_rating_life(b.C, P, p)
    L = Q(L0.magnitude * a1, L0.units)  # a1·L0 (as pint's product: the same float, without its arithmetic)
    Lh = life_hours(L, speed)
    n = si_to(abs(to_si(speed, "angular_velocity", "speed")), "angular_velocity", "rpm")
    req = si_to(to_si(required_life, "time", "required_life"), "time", "hour")
    inputs: dict[str, Any] = {"Fr": Q(to_si(Fr, "force", "Fr"), "N"), "Fa": Q(to_si(Fa, "force", "Fa"), "N"),
                              "n": n, "C": b.C, "C0": b.C0, "p": p, "reliability": reliability}
    if getattr(b, "f0", None) is not None:
        inputs["f0"] = b.f0
    rel = f"f0·Fa/C0 = {eq.relative_axial_load:.3g}, " if isinstance(b, BallBearing) else ""
    return CheckResult(
        check="bearing_life", component=b.designation, demand=req, capacity=Lh,
        title="Bearing rating life", formula=r"L_{nh} = a_1 \left(\frac{C}{P}\right)^p \frac{10^6}{60 n},\ "
                                             r"P = X F_r + Y F_a",
        source=ISO281, inputs=inputs,
        notes=((f"P = {eq.X:g}·Fr + {eq.Y:.3g}·Fa = {fmt(eq.P.to('N'))} ({rel}{_e_text(eq.e)})") if duty_cycle is None
               else (f"duty cycle: P = (sum f_i P_i^p)^(1/p) = {fmt(duty_cycle.P.to('N'))} over revolution shares "
                     + ", ".join(f"{f:.3g}" for f in duty_cycle.shares) + f"; mean speed {fmt(n)}"),
               f"a1 = {a1:.3g} for reliability {reliability:g}; life exponent p = {p:.4g}",
               "basic rating life only: no aISO/aSKF factor for lubrication or contamination "
               "(see bearing_modified_life)"),
        warnings=_axial_warning(b, Fa), load_case=load_case,
        details={"P": P, "X": eq.X, "Y": eq.Y, "e": eq.e, "L_rev": L},
        substituted=lambda: _life_substituted(a1, b.C, P, p, n, Lh))


@check("bearing_static_safety", title="Bearing static safety (s0)", sf_kind="bearing",
       aliases=('ball_bearing.static_safety',),
       source=ISO76,
       explain=('s0 = C0/P0, P0 = max(0.6 Fr + 0.5 Fa, Fr) for deep groove ball bearings (ISO 76), the maker\'s '
                'X0, Y0 for other types (thrust: P0 = Fa); the required s0 is the bearing class factor '
                '(SKF: 1 normal, 1.5 shock loads, 2 quiet running).'))
def check_bearing_static_safety(b: AnyBearing, Fr: QuantityLike, Fa: QuantityLike = "0 N", *,
                                required_s0: float = 1.0, load_case: str = "") -> CheckResult:
    """Static safety s0 = C0/P0 against the required s0 (SKF guideline for rotating ball bearings: 1,
    1.5 with shock loads, 2 where low noise matters; ISO 76)."""
    P0 = b.static_load(Fr, Fa).to("N")
    p0 = to_si(P0, "force")
    C0, C0_si = once("bearing_static_safety.C0", (b,), lambda: (b.C0.to("N"), to_si(b.C0, "force")))
    s0 = C0_si / p0 if p0 > 0 else None
    return CheckResult(
        check="bearing_static_safety", component=b.designation, demand=P0, capacity=C0,
        required_sf=required_s0, title="Bearing static safety (s0)",
        formula=(r"s_0 = C_0 / P_0,\ P_0 = \max(0.6 F_r + 0.5 F_a,\ F_r)" if isinstance(b, BallBearing)
                 else r"s_0 = C_0 / P_0,\ P_0 = \max(X_0 F_r + Y_0 F_a,\ F_r)"), source=ISO76,
        inputs={"Fr": Q(to_si(Fr, "force", "Fr"), "N"), "Fa": Q(to_si(Fa, "force", "Fa"), "N"), "C0": b.C0},
        notes=(f"required s0 = {required_s0:g} (SKF 17000 EN guideline: >= 1 normal, 1.5 shock, 2 quiet running)",),
        warnings=_axial_warning(b, Fa), load_case=load_case,
        substituted=lambda: (
            rf"s_0 = \frac{{{tex(b.C0, 'kN')}}}{{{tex(P0, 'kN')}}} = {tex(s0)}" if s0 is not None else ""))


SEAL_SPEED_FRACTION = 0.25  # contact-seal speed caveat above this fraction of the open bearing's limiting speed


@check("bearing_speed", title="Bearing speed", sf_kind="speed",
       aliases=('ball_bearing.speed',),
       source=ref("skf17000", "product tables: limiting and reference speeds"),
       explain=('Speed against the catalogue limiting speed (the reference speed is noted).'))
def check_bearing_speed(b: AnyBearing, speed: QuantityLike, *, load_case: str = "") -> CheckResult:
    """Speed against the limiting (mechanical) speed of the catalogue; the reference (thermal) speed is noted."""
    n = si_to(to_si(speed, "angular_velocity", "speed"), "angular_velocity", "rpm")
    warnings: tuple[str, ...] = ()
    note, capacity, provenance = once("bearing_speed", (b,), lambda: (
        f"limiting speed {fmt(b.limiting_speed.to('rpm'))} (open bearing); reference speed "
        f"{fmt(b.reference_speed.to('rpm'))} (thermal, oil)", b.limiting_speed.to("rpm"), provenance_warning(b)))
    notes = [note]
    if b.variant == "sealed":  # contact seals limit the speed well below the open bearing's: a caveat only near it
        seal = (f"{b.designation} has contact seals: the catalogue limiting speed used here is the open bearing's; "
                "contact-sealed variants are limited much lower (see the catalogue)")
        if abs(n) > SEAL_SPEED_FRACTION * b.limiting_speed:
            warnings = (seal,)
        else:
            notes.append(f"{seal}; at {fmt(abs(n), 'rpm')}, below {SEAL_SPEED_FRACTION:g} of the open bearing's limit, "
                         "this does not govern (threshold chosen conservatively, not a catalogue value)")
    if exceeds(n, b.reference_speed):
        notes.append("above the reference speed: check the permissible speed for the actual load and lubrication")
    return CheckResult(
        check="bearing_speed", component=b.designation, demand=Q(abs(n.magnitude), n.units), capacity=capacity,
        title="Bearing speed", formula=r"n \le n_{lim}", source=b.source, inputs={"n": n},
        notes=tuple(notes), warnings=(*warnings, *provenance), load_case=load_case,
        substituted=lambda: (rf"S = \frac{{{tex(b.limiting_speed, 'rpm')}}}{{{tex(abs(n), 'rpm')}}} = "
                     rf"{tex(b.limiting_speed.m_as('rpm') / abs(n.m_as('rpm')))}" if n.magnitude != 0 else ""))


ISO281_MOD = ref("iso281", "Sec. 9 (L_nm = a1 a_ISO L10; nu1, kappa, a_ISO for radial ball and radial roller "
                           "bearings), Table 13 (e_C)")


@check("bearing_modified_life", title="Bearing modified rating life (ISO 281 a_ISO)", sf_kind="bearing",
       source=ISO281_MOD,
       explain=("L_nmh = a1 a_ISO (C/P)^p 10^6/(60 n) (p = 3 ball, 10/3 roller) against the required life: a_ISO "
                "(ISO 281's radial-ball formula for deep groove and angular contact ball bearings, its radial-roller "
                "formula for cylindrical, tapered and needle roller bearings; thrust bearings not covered) from the "
                "viscosity ratio "
                "kappa = nu/nu1 (nu the lubricant's viscosity at the operating temperature, from its 40/100 degC "
                "values by ASTM D341; nu1 the ISO 281 rated viscosity for the speed and mean diameter), the "
                "contamination factor e_C (ISO 281 Table 13) and the fatigue load limit Pu (catalogue), capped at 50 "
                "(ISO 281:2007 Sec. 9). P is the governing case's equivalent load, or a duty cycle's."))
def check_bearing_modified_life(b: AnyBearing, Fr: QuantityLike, Fa: QuantityLike, speed: QuantityLike,
                                required_life: QuantityLike, lubrication: Lubrication, *,
                                reliability: float = 0.9, duty_cycle: DutyCycleLoad | None = None,
                                load_case: str = "") -> CheckResult:
    """Modified rating life L_nmh = a1·a_ISO·L10 in hours against the required life (ISO 281 Sec. 9).

    With ``duty_cycle`` its equivalent load and mean speed replace (Fr, Fa, speed); ``Fr``/``Fa`` are
    then only used for the axial-load warning.
    """
    notes: list[str] = []
    if duty_cycle is not None:
        P = duty_cycle.P
        n = duty_cycle.mean_speed if duty_cycle.mean_speed is not None else speed
        notes.append(f"duty cycle: P = (sum f_i P_i^p)^(1/p) = {fmt(P.to('N'))} over revolution shares "
                     + ", ".join(f"{f:.3g}" for f in duty_cycle.shares))
    else:
        eq = b.equivalent_load(Fr, Fa)
        P, n = eq.P, speed
        notes.append(f"P = {eq.X:g}·Fr + {eq.Y:.3g}·Fa = {fmt(eq.P.to('N'))}")
    m = modified_rating_life(b, P, n, lubrication, reliability)
    Lh = life_hours(m.L_rev, n)
    req = Q(to_si(required_life, "time", "required_life"), "s").to("hour")
    notes += [f"nu = {fmt(m.nu)} at operating temperature, nu1 = {fmt(m.nu1)} (ISO 281 rated viscosity, d_m = "
              f"{fmt((b.d + b.D).to('mm') / 2)}), kappa = {m.kappa:.3g}",
              f"e_C = {m.eC:g}, e_C·Pu/P = {m.eC * float((m.Pu / m.P).m_as('')):.3g}, a_ISO = {m.a_iso:.3g}, "
              f"a1 = {m.a1:.3g} (a_ISO formula: ISO 281 {m.family.replace('_', ' ')} bearings)",
              "ISO 281 a_ISO; SKF's a_SKF and rated-viscosity diagram differ from it (SKF's nu1 is lower)"]
    return CheckResult(
        check="bearing_modified_life", component=b.designation, demand=req, capacity=Lh,
        title="Bearing modified rating life (ISO 281 a_ISO)",
        formula=(rf"L_{{nmh}} = a_1 a_{{ISO}} \left(\frac{{C}}{{P}}\right)^{{{_p_tex(m.exponent)}}}"
                 r" \frac{10^6}{60 n}"),
        source=ISO281_MOD,
        inputs={"P": m.P, "n": Q(to_si(n, "angular_velocity", "speed"), "rad/s").to("rpm"), "C": b.C, "Pu": b.Pu,
                "nu": m.nu, "reliability": reliability},
        notes=tuple(notes), warnings=(*m.warnings, *_axial_warning(b, Fa)), load_case=load_case,
        details={"kappa": m.kappa, "a_iso": m.a_iso, "a1": m.a1, "eC": m.eC, "nu1": m.nu1, "L10h": life_hours(
            m.L10_rev, n)},
        substituted=lambda: _life_substituted(m.a1, b.C, m.P, m.exponent,
                                      Q(abs(to_si(n, "angular_velocity", "speed")), "rad/s").to("rpm"), Lh, m.a_iso))


def _bushing_inputs(bush: PlainBushing, F: Any, v: Any) -> dict[str, Any]:
    return {"F": Q(to_si(F, "force", "F"), "N"), "v": Q(to_si(v, "velocity", "v"), "m/s"), "d": bush.d,
            "L": bush.length}


def _bushing_notes(bush: PlainBushing) -> tuple[str, ...]:
    m = bush.material_record
    return (f"limits from {'material ' + repr(m.name) if m is not None else 'the given values'}; "
            "p = F/(d L) is the mean projected pressure",)


@check("bushing_pressure", title="Bushing pressure", sf_kind="pressure",
       aliases=('plain_bushing.pressure',),
       source=BUSHING,
       explain=('p = F/(dL) against p_max.'))
def check_bushing_pressure(bush: PlainBushing, F: QuantityLike, *, load_case: str = "") -> CheckResult:
    """Projected pressure p = F/(dL) against p_max."""
    return CheckResult(
        check="bushing_pressure", component=bush.name, demand=bush.pressure(F), capacity=bush.limit("p_max"),
        title="Bushing pressure", formula=r"p = \frac{F}{d L} \le p_{max}",
        source=BUSHING,
        inputs={"F": Q(to_si(F, "force", "F"), "N"), "d": bush.d, "L": bush.length},
        notes=_bushing_notes(bush), load_case=load_case,
        substituted=lambda: _pressure_substituted(bush, F))


def _pressure_substituted(bush: PlainBushing, F: Any) -> str:
    d, L = (Q(to_si(x, "length"), "m") for x in (bush.d, bush.length))
    return (rf"p = \frac{{{tex(Q(to_si(F, 'force', 'F'), 'N'), 'N')}}}{{{tex(d, 'mm')}\cdot {tex(L, 'mm')}}} = "
            rf"{tex(bush.pressure(F), 'MPa')}")


@check("bushing_velocity", title="Bushing sliding speed", sf_kind="speed",
       aliases=('plain_bushing.velocity',),
       source=BUSHING,
       explain=('Sliding speed against v_max.'))
def check_bushing_velocity(bush: PlainBushing, v: QuantityLike, *, load_case: str = "") -> CheckResult:
    """Sliding speed against v_max."""
    vv = Q(abs(to_si(v, "velocity", "v")), "m/s")
    return CheckResult(
        check="bushing_velocity", component=bush.name, demand=vv, capacity=bush.limit("v_max"),
        title="Bushing sliding speed", formula=r"v \le v_{max}",
        source=BUSHING,
        inputs={"v": vv}, notes=_bushing_notes(bush), load_case=load_case,
        substituted=lambda: (rf"S = \frac{{{tex(bush.limit('v_max'), 'm/s')}}}{{{tex(vv, 'm/s')}}} = "
                     rf"{tex(bush.limit('v_max').m_as('m/s') / vv.m_as('m/s'))}" if vv.magnitude > 0 else ""))


@check("bushing_pv", title="Bushing pv", sf_kind="pressure",
       aliases=('plain_bushing.pv',),
       source=BUSHING,
       explain=("p v against the material's pv limit (wear and heating of dry-running bushings)."))
def check_bushing_pv(bush: PlainBushing, F: Any, v: Any, *, load_case: str = "") -> CheckResult:
    """p·v against pv_max (the wear/heating limit of dry-running bushings)."""
    return CheckResult(
        check="bushing_pv", component=bush.name, demand=bush.pv(F, v), capacity=bush.limit("pv_max"),
        title="Bushing pv", formula=r"p\,v = \frac{F}{d L} v \le (pv)_{max}",
        source=BUSHING,
        inputs=_bushing_inputs(bush, F, v), notes=_bushing_notes(bush), load_case=load_case,
        substituted=lambda: (
            rf"pv = {tex(bush.pressure(F), 'MPa')}\cdot {tex(Q(abs(to_si(v, 'velocity', 'v')), 'm/s'), 'm/s')}"
            rf" = {tex(bush.pv(F, v), 'MPa*m/s')}"))


__all__ = ["check_bearing_life", "check_bearing_modified_life", "check_bearing_static_safety", "check_bearing_speed",
           "check_bushing_pressure",
           "check_bushing_velocity", "check_bushing_pv"]
