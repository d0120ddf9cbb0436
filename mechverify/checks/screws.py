"""Checks of lead-screw drives: self-locking, holding torque, nut flank pressure and pv, screw strength,
buckling and critical (whirling) speed.

Friction given as a range is used conservatively per question: the lowest ``mu`` where friction
helps (self-locking, holding the load), the highest where it hurts (drive torque, hence the
torsional stress in the screw). Every result says in its notes which value it used and why.

References
----------
Citations come from :mod:`mechverify.references`: ``shigley10`` Sec. 8-2 (power screws; the formulas were
checked in the 9th ed. text, where they are Eqs. 8-1..8-6; the 10th-ed. numbers are not cited because that text
was not available) and Secs. 4-11 to 4-13 (columns),
``hamrock3`` Sec. 16.3, ``blevins`` Table 8-1, ``thk`` (permissible speed 0.8 n_c, compressive load 0.5 P_cr),
``din103`` and ``roloff_matek`` (flank pressure).
"""

from __future__ import annotations

from typing import Any

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components.memo import once
from mechverify.components.power_screw import (
    LeadScrew,
    Nut,
    flank_pressure,
    friction_angle,
    pv_value,
    whirl_factor,
)
from mechverify.errors import InputError
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, as_quantity, fmt

SHIGLEY_SCREWS = ref("shigley10", "Sec. 8-2")
HAMROCK = ref("hamrock3", "Sec. 16.3")
_FLANK_SOURCE = f"{ref('din103')}; {ref('roloff_matek')} (mean flank pressure); {SHIGLEY_SCREWS} (bearing stress)"
_PV_SOURCE = (f"{ref('din103')}; {ref('roloff_matek')} (flank pressure); polymer-bearing pv rating "
              "(nut maker's datasheet)")
_WHIRL_SOURCE = f"{ref('blevins', 'Table 8-1')}; {ref('thk', 'permissible rotational speed')}"


def _force(F: Any, name: str = "F") -> Any:
    f = as_quantity(F, "force", name)
    if f.magnitude < 0:
        raise InputError(f"{name}: give the magnitude of the axial force (>= 0), got {fmt(f)}")
    return f.to("N")


def _mu_note(nut: Nut, which: str, why: str) -> str:
    lo, hi = nut.require_mu()
    used = lo if which == "min" else hi
    rng = f"{lo:g}..{hi:g}" if lo != hi else f"{lo:g} (single value)"
    return f"mu = {used:g} used ({'lowest' if which == 'min' else 'highest'} of the nut's range {rng}): {why}"


@check("self_locking", title="Self-locking", sf_kind="self_locking",
       source=f"{HAMROCK}, Sec. 16.3.3; {SHIGLEY_SCREWS}, Eq. (8-3)",
       explain=("Lead angle against the friction angle at the lowest mu of the nut's range: the load must not back-"
                'drive the screw (Shigley 10th ed. Sec. 8-2, Hamrock 3rd ed. Sec. 16.3).'))
def check_self_locking(screw: LeadScrew, nut: Nut, *, required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """The load must not back-drive the screw: lead angle ``lambda`` <= effective friction angle ``rho'`` at ``mu_min``.

    Margins are reported both in angle (``rho' - lambda``) and in friction (``mu_min - mu*``,
    ``mu* = cos(alpha_n) tan(lambda)``). Collar friction is not counted.
    """
    mu_lo, _ = nut.require_mu()
    th = screw.thread
    lam = th.lead_angle.to("deg")
    rho = friction_angle(mu_lo, th.normal_flank_angle).to("deg")
    mu_star = float(screw.self_locking_mu().m_as(""))
    notes = [
        _mu_note(nut, "min", "friction helps self-locking, so the least friction the nut may show decides it"),
        f"margin in angle: rho' - lambda = {fmt(rho - lam, 'deg')}; in friction: mu_min - mu* = {mu_lo - mu_star:+.4g} "
        f"(the screw back-drives for mu < mu* = {mu_star:.4g})",
        "thread alone: collar or bearing friction, which may add holding, is not counted",
    ]
    warnings = []
    if th.form == "ball":
        notes.append("a ball screw is never self-locking: use a brake or a holding torque")
    if lam < rho and (rho - lam).m_as("deg") < 1.0:
        warnings.append("self-locking margin below 1 deg: vibration and static/dynamic friction scatter can release it")
    return CheckResult(
        check="self_locking", component=screw.name, demand=lam, capacity=rho, required_sf=required_sf,
        title=f"Self-locking of {th.designation} ({nut.name})",
        formula=r"\lambda = \arctan\frac{l}{\pi d_2} \;\le\; \rho' = \arctan\frac{\mu_{min}}{\cos\alpha_n},"
                r"\quad \tan\alpha_n = \tan\alpha\cos\lambda",
        source=f"{HAMROCK} (self-locking condition mu > cos(alpha_n) tan(lambda)); {SHIGLEY_SCREWS}, Eq. (8-3)",
        inputs={"lead": th.lead, "d2": th.d2, "flank_angle": th.flank_angle, "mu_min": Q(mu_lo, "")},
        substituted=lambda: (
            rf"\lambda = \arctan\frac{{{tex(th.lead, 'mm')}}}{{\pi\cdot {tex(th.d2, 'mm')}}} = {tex(lam)}"
            rf",\quad \rho' = \arctan\frac{{{tex(mu_lo)}}}{{\cos({tex(th.normal_flank_angle, 'deg')})}}"
            rf" = {tex(rho)}"),
        notes=tuple(notes), warnings=tuple(warnings), load_case=load_case,
        details=lambda: {"lead_angle": lam, "friction_angle": rho,
                         "normal_flank_angle": th.normal_flank_angle.to("deg"), "self_locking_mu": Q(mu_star, ""),
                         "angle_margin": (rho - lam).to("deg"), "mu_margin": Q(mu_lo - mu_star, "")},
    )


@check("holding_torque", title="Back-drive holding torque", sf_kind="static",
       source=f"{HAMROCK}, Eq. (16.12); {SHIGLEY_SCREWS}, Eq. (8-2)",
       explain=('Torque the load puts back on the screw at mu_min against the torque available at rest (motor holding'
                ' torque or brake); zero demand when the thread self-locks.'))
def check_holding_torque(screw: LeadScrew, nut: Nut, F: Any, holding_torque: QuantityLike, *, required_sf: float = 1.0,
                         load_case: str = "") -> CheckResult:
    """The torque available at the screw when stopped (motor holding torque, brake) must hold the load.

    Demand ``max(0, -T_L)`` at ``mu_min``: ``T_L = F d2/2 (mu - cos(alpha_n) tan(lambda)) / (cos(alpha_n) + mu
    tan(lambda))``; zero when the thread self-locks.
    """
    f = _force(F)
    cap = as_quantity(holding_torque, "torque", "holding_torque").to("N*m")
    mu_lo, _ = nut.require_mu()
    need = screw.holding_torque(f, mu_lo).to("N*m")
    notes = [*once("holding_torque.notes", (nut,), lambda: (
        _mu_note(nut, "min", "friction helps holding: the least friction gives the largest back-driving torque"),
        "collar/bearing friction not counted (conservative)"))]
    if need.magnitude == 0:
        notes.append("the thread self-locks at mu_min: no holding torque is needed")
    return CheckResult(
        check="holding_torque", component=screw.name, demand=need, capacity=cap, required_sf=required_sf,
        title=f"Back-drive holding torque, {screw.thread.designation}",
        formula=r"T_{hold} = \max\left(0,\; F\frac{d_2}{2}\,\frac{\cos\alpha_n\tan\lambda - \mu_{min}}"
                r"{\cos\alpha_n + \mu_{min}\tan\lambda}\right) \le T_{available}",
        source=f"{HAMROCK}, Eq. (16.12) (lowering torque); {SHIGLEY_SCREWS}, Eq. (8-2)",
        inputs={"F": f, "mu_min": Q(mu_lo, ""), "holding_torque": cap, "lead": screw.lead, "d2": screw.thread.d2},
        substituted=lambda: _holding_substituted(screw, f, mu_lo, need),
        notes=tuple(notes), load_case=load_case,
        details=lambda: {"lower_torque": screw.lower_torque(f, mu_lo).to("N*m"),
                         "backdrive_efficiency": screw.backdrive_efficiency(mu_lo)},
    )


def _holding_substituted(screw: LeadScrew, f: Any, mu: float, need: Any) -> str:
    """T_hold = max(0, F d2/2 (cos(alpha_n) tan(lambda) - mu)/(cos(alpha_n) + mu tan(lambda))) with the numbers."""
    th = screw.thread
    an, lam = tex(th.normal_flank_angle, "deg"), tex(th.lead_angle, "deg")
    return (rf"T_{{hold}} = \max\left(0\,\mathrm{{N\cdot m}},\; {tex(f, 'N')}\cdot \frac{{{tex(th.d2, 'mm')}}}{{2}}"
            rf"\cdot \frac{{\cos({an})\cdot \tan({lam}) - {tex(mu)}}}{{\cos({an}) + {tex(mu)}\cdot \tan({lam})}}"
            rf"\right) = {tex(need, 'N*m')}")


def _nut_geometry(screw: LeadScrew, nut: Nut) -> tuple[float, Any]:
    th = screw.thread
    if th.form == "ball" or th.H1 is None:
        raise InputError(f"{nut.name}: flank pressure and pv do not apply to a ball nut; check its load rating instead")
    return nut.engaged(th), th.H1


@check("nut_flank_pressure", title="Nut flank pressure", sf_kind="pressure",
       source=f"{ref('din103')}; {ref('roloff_matek')} (mean flank pressure)",
       explain=("Mean flank pressure p = F/(pi d2 H1 n) against the nut's allowable pressure (DIN 103)."))
def check_nut_flank_pressure(screw: LeadScrew, nut: Nut, F: Any, *, required_sf: float = 1.0,
                             load_case: str = "") -> CheckResult:
    """Mean flank pressure ``p = F / (pi d2 H1 n)`` against the nut's allowable pressure."""
    f = _force(F)
    n, H1, cap, title, notes = once("nut_flank_pressure", (screw, nut), lambda: _flank_constants(screw, nut))
    th = screw.thread
    p = flank_pressure(f, th.d2, H1, n).to("MPa")
    return CheckResult(
        check="nut_flank_pressure", component=nut.name, demand=p, capacity=cap,
        required_sf=required_sf, title=title,
        formula=r"p = \frac{F}{\pi d_2 H_1 n},\quad n = \frac{m}{P}",
        source=_FLANK_SOURCE,
        inputs={"F": f, "d2": th.d2, "H1": H1, "engaged_threads": Q(n, "")},
        substituted=lambda: (
            rf"p = \frac{{{tex(f, 'N')}}}{{\pi\cdot {tex(th.d2, 'mm')}\cdot {tex(H1, 'mm')}\cdot {tex(n)}}}"
            rf" = {tex(p, 'MPa')}"),
        notes=notes, load_case=load_case, details={"engaged_threads": Q(n, "")},
    )


def _flank_constants(screw: LeadScrew, nut: Nut) -> tuple[float, Any, Any, str, tuple[str, ...]]:
    """What the flank-pressure check takes from the screw and the nut alone: engaged turns, H1, the allowable
    pressure [MPa], the title and the notes (the errors of a nut without a limit or of a ball nut, in order)."""
    if nut.p_allow is None:
        raise InputError(f"{nut.name}: no allowable flank pressure (p_allow, or a material with p_max)")
    n, H1 = _nut_geometry(screw, nut)
    th = screw.thread
    how = (f"nut length {fmt(nut.length, 'mm')} / P {fmt(th.pitch, 'mm')}" if nut.engaged_threads is None
           else "as given")
    return (n, H1, nut.p_allow.to("MPa"), f"Nut flank pressure on {th.designation}",
            (f"n = {n:.4g} engaged turns ({how}); load shared equally (mean pressure, as nut makers rate it)",
             "Shigley notes the first turn carries about 0.38 F in metal nuts; polymer nuts share more evenly"))


@check("nut_pv", title="Nut pv", sf_kind="pressure",
       source=f"{ref('din103')}; {ref('roloff_matek')} (flank pressure); nut maker's pv rating",
       explain=("Flank pressure times sliding speed at d2 against the nut material's pv limit."))
def check_nut_pv(screw: LeadScrew, nut: Nut, F: Any, *, rotational_speed: QuantityLike | None = None, speed: Any = None,
                 required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """``pv`` (mean flank pressure x sliding speed at d2) against the nut material's pv limit.

    Give the screw's ``rotational_speed`` (``"540 rpm"``) or the nut's linear ``speed`` (``"18 mm/s"``).
    """
    f = _force(F)
    if nut.pv_allow is None:
        raise InputError(f"{nut.name}: no pv limit (pv_allow, or a material with pv_max)")
    if (rotational_speed is None) == (speed is None):
        raise InputError("check_nut_pv: give exactly one of rotational_speed or speed")
    n_rot = (as_quantity(rotational_speed, "angular_velocity", "rotational_speed") if rotational_speed is not None
             else screw.rotational_speed(speed)).to("rpm")
    n, H1 = once("nut_geometry", (screw, nut), lambda: _nut_geometry(screw, nut))
    th = screw.thread
    p = flank_pressure(f, th.d2, H1, n).to("MPa")
    m = n_rot.magnitude  # what depends on the speed alone, per speed (an int and its float give the same values;
    # 0.0 and -0.0 are one key but two texts)
    v, title, speed_note = (once(("nut_pv.speed", m), (screw,), lambda: _pv_speed(screw, n_rot))
                            if (type(m) is float or type(m) is int) and m != 0 else _pv_speed(screw, n_rot))
    pv = pv_value(p, v).to("MPa*m/s")
    return CheckResult(
        check="nut_pv", component=nut.name, demand=pv,
        capacity=once("nut_pv.capacity", (nut,), lambda: nut.pv_allow.to("MPa*m/s")), required_sf=required_sf,
        title=title,
        formula=r"pv = \frac{F}{\pi d_2 H_1 n}\cdot\frac{\pi d_2 n_{rot}}{\cos\lambda}",
        source=_PV_SOURCE,
        inputs={"F": f, "rotational_speed": n_rot, "d2": th.d2, "H1": H1, "engaged_threads": Q(n, "")},
        substituted=lambda: (rf"pv = {tex(p, 'MPa')}\cdot {tex(v, 'm/s')} = {tex(pv, 'MPa*m/s')}"),
        notes=(f"p = {fmt(p, 'MPa')} with n = {n:.4g} engaged turns; sliding speed at d2 v = {fmt(v, 'm/s')}",
               speed_note),
        load_case=load_case, details={"pressure": p, "sliding_speed": v},
    )


def _pv_speed(screw: LeadScrew, n_rot: Any) -> tuple[Any, str, str]:
    """What the pv check takes from the screw speed [rpm] alone: the sliding speed at d2 [m/s], the title and the
    note of the nut's speed."""
    return (screw.sliding_speed(n_rot).to("m/s"), f"Nut pv on {screw.thread.designation} at {fmt(n_rot, 'rpm')}",
            f"nut speed {fmt(screw.linear_speed(n_rot), 'mm/s')}")


@check("screw_strength", title="Screw body stress", sf_kind="static",
       source=f"{SHIGLEY_SCREWS} (body stresses), Eq. (5-15) (von Mises)",
       explain=('Von Mises stress at the minor diameter from the axial force and the raising torque at mu_max against'
                ' the yield strength.'))
def check_screw_strength(screw: LeadScrew, F: Any, *, nut: Nut | None = None, torque: QuantityLike | None = None,
                         required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """Von Mises stress at the minor diameter from the axial force and the drive torque, against yield.

    Without ``torque`` the raising torque at the nut's ``mu_max`` is used (the largest torque the
    motor must put through the screw).
    """
    f = _force(F)
    notes = []
    if torque is None:
        if nut is None:
            raise InputError("check_screw_strength: give the torque, or the nut (its mu_max sets the drive torque)")
        _, mu_hi = nut.require_mu()
        T = screw.raise_torque(f, mu_hi).to("N*m")
        notes.append(once("screw_strength.note", (nut,), lambda: _mu_note(
            nut, "max", "the highest friction gives the largest drive torque through the screw")))
    else:
        T = as_quantity(torque, "torque", "torque").to("N*m")
        notes.append(f"torque as given: {fmt(T, 'N*m')}")
    s = screw.stresses(f, T)
    Sy = once("screw_strength.Sy", (screw,), lambda: screw.material_property("yield_strength").to("MPa"))
    d3 = once("screw_strength.d3", (screw,), lambda: fmt(screw.thread.d3, "mm"))
    notes.append(f"axial {fmt(s.axial, 'MPa')}, torsion {fmt(s.torsion, 'MPa')} at d3 = {d3}")
    return CheckResult(
        check="screw_strength", component=screw.name, demand=s.von_mises, capacity=Sy, required_sf=required_sf,
        title=f"Screw body stress, {screw.thread.designation}",
        formula=r"\sigma' = \sqrt{\left(\frac{4F}{\pi d_3^2}\right)^2 + 3\left(\frac{16T}{\pi d_3^3}\right)^2}"
                r" \le S_y",
        source=f"{SHIGLEY_SCREWS} (body stresses), Eq. 5-15 (von Mises)",
        inputs={"F": f, "torque": T, "d3": screw.thread.d3, "yield_strength": Sy},
        substituted=lambda: _strength_substituted(f, T, screw.thread.d3, s.von_mises),
        notes=tuple(notes), load_case=load_case,
        details={"axial": s.axial, "torsion": s.torsion},
    )


def _strength_substituted(f: Any, T: Any, d3: Any, vm: Any) -> str:
    F, t, d = tex(f, "N"), tex(T, "N*mm"), tex(d3, "mm")
    return (rf"\sigma' = \sqrt{{\left(\frac{{4\cdot {F}}}{{\pi\cdot ({d})^{{2}}}}\right)^{{2}} + 3\cdot "
            rf"\left(\frac{{16\cdot {t}}}{{\pi\cdot ({d})^{{3}}}}\right)^{{2}}}} = {tex(vm, 'MPa')}")


@check("screw_buckling", title="Screw buckling", sf_kind="buckling",
       aliases=('lead_screw.buckling',),
       source=ref("shigley10", "Secs. 4-11 to 4-13, Eqs. (4-43), (4-46), Table 4-2"),
       explain=('Axial force against the Euler/Johnson critical load of the root section with the end-fixity constant'
                ' of Shigley 10th ed. Table 4-2 (recommended values).'))
def check_screw_buckling(screw: LeadScrew, F: Any, *, length: QuantityLike | None = None, basis: str = "recommended",
                         required_sf: float = 2.0, load_case: str = "") -> CheckResult:
    """Compressive axial force against the column critical load of the root section (Euler or Johnson).

    The default required factor 2 is the THK rule (permissible load 0.5 P_cr).
    """
    f = _force(F)
    if length is None:  # the screw's own length: everything but the force depends on the screw alone
        b, L, cap, title, notes, stress = once(f"screw_buckling.{basis}", (screw,),
                                               lambda: _buckling_constants(screw, None, basis))
    else:
        b, L, cap, title, notes, stress = _buckling_constants(screw, length, basis)
    return CheckResult(
        check="screw_buckling", component=screw.name, demand=f, capacity=cap,
        required_sf=required_sf, title=title,
        formula=(r"P_{cr} = \frac{C\pi^2 E I}{l^2}" if b.regime == "euler" else
                 r"P_{cr} = A\left[S_y - \left(\frac{S_y l}{2\pi k}\right)^2\frac{1}{CE}\right]"),
        source=b.source,
        inputs={"F": f, "length": L.to("mm"), "d3": screw.thread.d3, "E": screw.material_property("E"),
                "yield_strength": screw.material_property("yield_strength")},
        substituted=lambda: _buckling_substituted(b, L, screw.thread.d3, screw.material_property("E"),
                                          screw.material_property("yield_strength")),
        notes=notes, load_case=load_case,
        details={"regime": b.regime, "C": b.C, "slenderness": b.slenderness, "critical_stress": stress},
    )


def _buckling_constants(screw: LeadScrew, length: Any, basis: str) -> tuple[Any, ...]:
    """What the buckling check takes from the screw (and the length) alone: the column result, the length, the
    critical load [N], the title, the notes and the critical stress [MPa]."""
    b = screw.buckling(length, basis)
    L = screw.length if length is None else as_quantity(length, "length", "length")
    notes = (f"end case {b.end}: C = {b.C:g}, the {basis} value of Shigley Table 4-2"
             + (" (design value: real fixed ends are never fully fixed)" if basis == "recommended" else ""),
             f"{b.regime} regime: l/k = {b.slenderness:.4g}, transition (l/k)_1 = {b.transition_slenderness:.4g}",
             "root section (d3) used for A and I; the length is the unsupported length under compression")
    return (b, L, b.critical_load.to("N"), f"Buckling of {screw.thread.designation}, {b.end}", notes,
            b.critical_stress.to("MPa"))


def _buckling_substituted(b: Any, L: Any, d3: Any, E: Any, Sy: Any) -> str:
    l, d, e, sy = tex(L, "mm"), tex(d3, "mm"), tex(E, "MPa"), tex(Sy, "MPa")
    if b.regime == "euler":  # I = pi d3^4 / 64
        return (rf"P_{{cr}} = \frac{{{tex(b.C)}\cdot \pi^{{2}}\cdot {e}\cdot \pi\cdot ({d})^{{4}}/64}}{{({l})^{{2}}}}"
                rf" = {tex(b.critical_load, 'N')}")
    return (rf"P_{{cr}} = \frac{{\pi\cdot ({d})^{{2}}}}{{4}}\cdot \left({sy} - \left(\frac{{{sy}\cdot {l}}}"  # k = d3/4
            rf"{{2\cdot \pi\cdot ({d})/4}}\right)^{{2}}\cdot \frac{{1}}{{{tex(b.C)}\cdot {e}}}\right)"
            rf" = {tex(b.critical_load, 'N')}")


@check("screw_critical_speed", title="Critical (whirling) speed", sf_kind="speed",
       aliases=('lead_screw.critical_speed',),
       source=f"{ref('blevins', 'Table 8-1')}; {ref('thk', 'permissible rotational speed')}",
       explain=('Operating speed against the first bending (whirling) speed of the screw between its supports '
                '(Blevins Table 8-1; THK runs below 0.8 of it).'))
def check_screw_critical_speed(screw: LeadScrew, rotational_speed: QuantityLike, *, length: QuantityLike | None = None,
                               required_sf: float = 1.25, load_case: str = "") -> CheckResult:
    """Operating speed against the first whirling speed of the screw between its supports.

    Default required factor 1.25 = the THK rule of running below 0.8 of the critical speed.
    """
    n = as_quantity(rotational_speed, "angular_velocity", "rotational_speed").to("rpm")
    n = abs(n)
    if length is None:  # the screw's own length: the critical speed depends on the screw alone
        nc, lam, L = once("screw_critical_speed", (screw,), lambda: _whirl_constants(screw, None))
    else:
        nc, lam, L = _whirl_constants(screw, length)
    return CheckResult(
        check="screw_critical_speed", component=screw.name, demand=n, capacity=nc, required_sf=required_sf,
        title=f"Critical (whirling) speed of {screw.thread.designation}",
        formula=r"n_c = \frac{\lambda_1^2}{2\pi L^2}\sqrt{\frac{E I}{\rho A}},\quad \frac{I}{A} = \frac{d_3^2}{16}",
        source=_WHIRL_SOURCE,
        inputs={"rotational_speed": n, "length": L.to("mm"), "d3": screw.thread.d3, "E": screw.material_property("E"),
                "density": screw.material_property("density")},
        substituted=lambda: (rf"n_c = \frac{{({tex(lam)})^{{2}}}}{{2\cdot \pi\cdot ({tex(L, 'mm')})^{{2}}}}"
                     rf"\cdot \sqrt{{\frac{{"
                     rf"{tex(screw.material_property('E'), 'MPa')}\cdot ({tex(screw.thread.d3, 'mm')})^{{2}}}}"
                     rf"{{16\cdot "
                     rf"{tex(screw.material_property('density'), 'kg/m**3')}}}}} = {tex(Q(nc.m_as('rpm') / 60, '1/s'))}"
                     rf" = {tex(nc, 'rpm')}"),  # revolutions per second (pint reads 1/s as rad/s, so both printed)
        notes=(f"end case {screw.end_supports}: lambda_1 = {lam:.5g} (first bending mode of a uniform shaft)",
               "root section (d3); the nut's support is ignored, which is conservative"),
        load_case=load_case, details={"lambda_1": lam, "critical_speed_rad_s": nc.to("rad/s")},
    )


def _whirl_constants(screw: LeadScrew, length: Any) -> tuple[Any, float, Any]:
    """The critical speed [rpm], lambda_1 and the length of the critical-speed check (the screw's alone)."""
    nc = screw.critical_speed(length).to("rpm")
    lam = whirl_factor(screw.end_supports)
    L = screw.length if length is None else as_quantity(length, "length", "length")
    return nc, lam, L


__all__ = ["check_self_locking", "check_holding_torque", "check_nut_flank_pressure", "check_nut_pv",
           "check_screw_strength", "check_screw_buckling", "check_screw_critical_speed"]
