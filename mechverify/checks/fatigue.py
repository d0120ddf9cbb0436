"""Fatigue checks: safety factor of a component (one stress state) or of an FEA stress field (per node).

Public API::

    check_fatigue(component, sigma_a, sigma_m, material, *, life=None, criterion="goodman",
                  load_line="proportional", Kf=1.0, Se=None, marin=None, polymer_fraction=None,
                  required_sf=1.0, load_case="") -> CheckResult
    check_fatigue_field(component, sigma_a, sigma_m, material, *, coordinates=None, ...same...) -> CheckResult

``sigma_a``/``sigma_m``: nominal alternating and mean (von Mises) stresses; Kf multiplies both
(Shigley's practice for ductile materials). ``life``: cycles required; ``None`` asks for infinite life
(an endurance limit; refused for materials that have none). The fatigue strength at the life comes
from, in order: ``Se`` given by the caller; the material's S-N table (``sn_curve``, amplitudes at
R = -1, used as given, times the Marin factors if ``marin`` is given); an estimate from Sut
(steels: Se' = 0.5 Sut with Marin factors ``marin`` = keyword arguments of
:func:`mechverify.fatigue.endurance.corrected_endurance_limit`, and the Basquin line for finite
life; 3D-printed polymers: a stated conservative fraction of Sut, flagged as a warning).

The result's safety factor is the smaller of the fatigue factor (criterion along the load line) and
Langer's first-cycle-yield factor; ``details`` say which governs and give both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.errors import InputError, ValidityError
from mechverify.fatigue import criteria
from mechverify.fatigue.endurance import (
    DEFAULT_POLYMER_FRACTION,
    corrected_endurance_limit,
    estimate_fatigue_strength,
)
from mechverify.fatigue.life import BasquinCurve
from mechverify.materials.database import get as get_material
from mechverify.materials.material import Material
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, from_si, to_si

SHIGLEY = ref("shigley10", "Sec. 6-12, Tables 6-6 to 6-8")
_FORMULA = {
    "goodman": r"\frac{1}{n_f} = \frac{K_f\sigma_a}{S_e} + \frac{K_f\sigma_m}{S_{ut}}",
    "soderberg": r"\frac{1}{n_f} = \frac{K_f\sigma_a}{S_e} + \frac{K_f\sigma_m}{S_y}",
    "morrow": r"\frac{1}{n_f} = \frac{K_f\sigma_a}{S_e} + \frac{K_f\sigma_m}{\sigma_f'}",
    "gerber": r"\frac{n_f K_f\sigma_a}{S_e} + \left(\frac{n_f K_f\sigma_m}{S_{ut}}\right)^2 = 1",
    "asme_elliptic": r"\left(\frac{n_f K_f\sigma_a}{S_e}\right)^2 + \left(\frac{n_f K_f\sigma_m}{S_y}\right)^2 = 1",
    "walker": r"\sigma_{ar} = \sigma_{max}^{1-\gamma}\sigma_a^{\gamma},\ n_f = S_e/\sigma_{ar}",
    "smith_watson_topper": r"\sigma_{ar} = \sqrt{\sigma_{max}\sigma_a},\ n_f = S_e/\sigma_{ar}",
}
_LANGER = r"n_y = \frac{S_y}{K_f(\sigma_a + |\sigma_m|)}"


@dataclass(frozen=True)
class _Strength:
    S: float  # fully reversed fatigue strength at the life [Pa]
    Sut: float
    Sy: float | None
    source: str
    notes: tuple[str, ...]
    warnings: tuple[str, ...]
    factors: dict[str, float]
    curve: Any = None  # something with life_at(stress), for the predicted life


def _material(material: Any) -> Material:
    return material if isinstance(material, Material) else get_material(material)


def _strength(mat: Material, life: float | None, Se: Any, marin: dict | None,
              polymer_fraction: float | None) -> _Strength:
    sut = to_si(mat.require("ultimate_strength"), "pressure", "ultimate_strength")
    sy = None if mat.yield_strength is None else to_si(mat.yield_strength, "pressure", "yield_strength")
    notes: list[str] = []
    warnings: list[str] = []
    life_text = "infinite life" if life is None else f"{life:.3g} cycles"
    if Se is not None:
        s = to_si(Se, "pressure", "Se")
        if s <= 0:
            raise InputError("Se: must be positive")
        return _Strength(s, sut, sy, "fatigue strength given by the user", (f"S = {fmt(Q(s, 'Pa'), 'MPa')} "
                         f"given for {life_text}",), (), {})
    category = mat.category.lower()
    sn = mat.sn_curve
    if sn is not None:
        n_req = life if life is not None else None
        if n_req is None:
            if not sn.constant_beyond_last:
                raise InputError(f"{mat.name}: its S-N table has no endurance limit; give the required life")
            s = sn.stress[-1]
            notes.append(f"S-N table of {mat.name}: endurance value {fmt(Q(s, 'Pa'), 'MPa')} held beyond "
                         f"{sn.cycles[-1]:g} cycles")
        else:
            s = to_si(sn.stress_at(n_req), "pressure", "S")
            notes.append(f"S-N table of {mat.name} at {n_req:.3g} cycles (log-log interpolation): "
                         f"{fmt(Q(s, 'Pa'), 'MPa')}")
        factors: dict[str, float] = {}
        if marin:
            el = corrected_endurance_limit(from_si(sut, "pressure"), Se_prime=from_si(s, "pressure"),
                                           material_class="steel" if "steel" in category else category, **marin)
            factors = el.factors.as_dict()
            s = to_si(el.Se, "pressure", "Se")
            notes.append(f"Marin factors applied to the S-N value: product {el.factors.product:.3g}")
        else:
            notes.append("S-N data used as given (no surface, size or reliability factor applied)")
        if sn.stress_ratio != -1:
            warnings.append(f"the S-N table was measured at R = {sn.stress_ratio:g}, not fully reversed")
        return _Strength(s, sut, sy, sn.source or mat.source_of("ultimate_strength"), tuple(notes),
                         tuple(warnings), factors, sn)
    is_polymer = any(k in category for k in ("polymer", "plastic", "pla", "petg", "abs", "nylon"))
    if is_polymer:
        frac = DEFAULT_POLYMER_FRACTION if polymer_fraction is None else polymer_fraction
        est = estimate_fatigue_strength(from_si(sut, "pressure"), "polymer", frac)
        warnings.append(f"{mat.name}: no S-N data; fatigue strength ASSUMED {frac:g} x Sut = "
                        f"{fmt(est.strength, 'MPa')} (polymers have no endurance limit). Give the material an "
                        "S-N curve measured on printed specimens.")
        if life is not None and life > est.cycles:
            warnings.append(f"required life {life:.3g} cycles exceeds the {est.cycles:g} cycles of the assumption")
        return _Strength(to_si(est.strength, "pressure", "S"), sut, sy, est.source, est.notes, tuple(warnings), {})
    if "alumin" in category:
        est = estimate_fatigue_strength(from_si(sut, "pressure"), "aluminium")
        if life is None or life > est.cycles:
            raise InputError(f"{mat.name}: aluminium has no endurance limit; give a required life of at most "
                             f"{est.cycles:g} cycles, S-N data, or Se")
        el = corrected_endurance_limit(from_si(sut, "pressure"), Se_prime=est.strength, **(marin or {}))
        return _Strength(to_si(el.Se, "pressure", "S"), sut, sy, est.source,
                         (*est.notes, "strength at 5e8 cycles used for any shorter life (conservative)", *el.notes),
                         (), el.factors.as_dict())
    if "steel" not in category and "iron" not in category:
        raise InputError(f"{mat.name} ({mat.category}): no S-N data and no endurance estimate for this class; "
                         "give Se or an S-N curve")
    if "iron" in category:
        raise InputError(f"{mat.name}: cast iron needs test data (Se' = 0.5 Sut holds for steels); give Se")
    el = corrected_endurance_limit(from_si(sut, "pressure"), **(marin or {}))
    se = to_si(el.Se, "pressure", "Se")
    notes.extend(el.notes)
    notes.append(f"Se' = {fmt(el.Se_prime, 'MPa')} estimated from Sut; Se = {fmt(el.Se, 'MPa')} after Marin "
                 f"factors (product {el.factors.product:.3g})")
    curve = BasquinCurve.from_ultimate(from_si(sut, "pressure"), el.Se) if se < 0.9 * sut else None
    if life is not None and life < 1e6:
        if curve is None:
            raise ValidityError("Se too close to Sut for a Basquin line; give Se at the required life")
        s = curve.stress_si(life)
        notes.append(f"finite life {life:.3g} cycles: S_f = {fmt(Q(s, 'Pa'), 'MPa')} from S = a N^b "
                     f"(a = {fmt(Q(curve.a, 'Pa'), 'MPa')}, b = {curve.b:.4g}; Shigley Eqs. (6-13)..(6-16))")
    else:
        s = se
    return _Strength(s, sut, sy, el.source, tuple(notes), (), el.factors.as_dict(), curve)


def _criterion_strength(criterion: str, st: _Strength, sigma_f: Any, gamma: Any) -> dict[str, Any]:
    need = criteria.require_criterion(criterion)
    if need == "Sy" and st.Sy is None:
        raise InputError(f"the {criterion} criterion needs the yield strength, which the material lacks")
    if need == "sigma_f" and sigma_f is None:
        raise InputError("the morrow criterion needs sigma_f (true fracture strength)")
    if need == "gamma" and gamma is None:
        raise InputError("the walker criterion needs gamma")
    return {"Sut": st.Sut, "Sy": st.Sy,
            "sigma_f": None if sigma_f is None else to_si(sigma_f, "pressure", "sigma_f"),
            "gamma": None if gamma is None else to_si(gamma, "dimensionless", "gamma")}


def _evaluate(sa: Any, sm: Any, st: _Strength, criterion: str, load_line: str, sigma_f: Any,
              gamma: Any) -> tuple[Any, Any]:
    kw = _criterion_strength(criterion, st, sigma_f, gamma)
    nf = criteria.safety_factor.si(criterion, sa, sm, st.S, load_line=load_line, **kw)
    ny = criteria.langer.si(sa, sm, st.Sy, load_line=load_line) if st.Sy is not None else np.full_like(
        np.asarray(sa, float), np.inf)
    return nf, ny


def _predicted_life(st: _Strength, criterion: str, sa: float, sm: float, sigma_f: Any, gamma: Any) -> float | None:
    if st.curve is None:
        return None
    try:
        kw = _criterion_strength(criterion, st, sigma_f, gamma)
        srev = criteria.equivalent_amplitude.si(criterion, sa, sm, **kw)
        if not math.isfinite(srev):
            return 0.0
        return float(st.curve.life_at(Q(srev, "Pa")))
    except (ValidityError, InputError):
        return None


def _common(component: str, st: _Strength, criterion: str, load_line: str, Kf: float, life: float | None,
            nf: float, ny: float, sa: float, sm: float, required_sf: float, load_case: str,
            sigma_f: Any, gamma: Any, extra_details: dict, extra_notes: tuple[str, ...], check: str) -> CheckResult:
    governing = "fatigue" if nf <= ny else "first-cycle yield (Langer)"
    n = min(nf, ny)
    if sa > 0:
        demand = sa
    elif sm != 0:
        demand = abs(sm)
    else:
        demand = 0.0
    capacity = n * demand if demand > 0 else st.S
    why = ("Shigley's default: stress ratio constant as the load grows" if load_line == "proportional"
           else "mean stress fixed, amplitude grows")
    notes = [f"criterion: {criterion.replace('_', ' ')} along a {load_line.replace('_', ' ')} load line ({why})",
             f"Kf = {Kf:g} applied to alternating and mean stress",
             f"n_f = {nf:.4g} (fatigue), n_y = {ny:.4g} (Langer first-cycle yield); governs: {governing}",
             *st.notes, *extra_notes]
    if sm < 0:
        notes.append("compressive mean stress: fatigue strength taken as independent of the mean (S_a = S_e)")
    predicted = _predicted_life(st, criterion, sa, sm, sigma_f, gamma)
    details = {"criterion": criterion, "load_line": load_line, "n_fatigue": nf, "n_yield": ny,
               "governing_mode": governing, "Kf": Kf, "fatigue_strength": Q(st.S, "Pa"),
               "marin_factors": st.factors, "required_life": life if life is not None else "infinite",
               **({"predicted_life": predicted} if predicted is not None else {}), **extra_details}
    inputs = {"sigma_a": Q(sa / Kf, "Pa"), "sigma_m": Q(sm / Kf, "Pa"), "S_f": Q(st.S, "Pa"),
              "Sut": Q(st.Sut, "Pa"), **({"Sy": Q(st.Sy, "Pa")} if st.Sy is not None else {}), "Kf": Q(Kf, "")}
    life_text = "infinite life" if life is None else f"{life:.3g} cycles"
    return CheckResult(
        check=check, component=component, demand=from_si(demand, "pressure").to("MPa"),
        capacity=from_si(capacity, "pressure").to("MPa"), required_sf=required_sf,
        title=f"Fatigue ({criterion.replace('_', ' ')}, {life_text})",
        formula=_FORMULA[criterion] + r",\quad " + _LANGER, source=f"{SHIGLEY}; strength: {st.source}",
        inputs=inputs, notes=tuple(notes), warnings=st.warnings, load_case=load_case, details=details,
        substituted=_substituted(st, criterion, load_line, nf, ny, sa, sm, sigma_f, gamma))


def _substituted(st: _Strength, criterion: str, load_line: str, nf: float, ny: float, sa: float, sm: float,
                 sigma_f: Any, gamma: Any) -> str:
    """The governing safety factor with the numbers: Langer's n_y when first-cycle yield governs, else the
    criterion's n_f (proportional load line: Shigley 10th ed. Tables 6-6 to 6-8, Walker/SWT n = S_e/sigma_ar;
    constant mean: S_a from the criterion at the mean stress over sigma_a; a compressive mean counts as zero).
    ``sa``, ``sm`` include Kf. Empty where no closed form is printed (Walker/SWT at constant mean, zero amplitude)."""
    P = lambda x: tex(Q(x / 1e6, "MPa"))  # noqa: E731
    a, m, S = P(sa), P(sm), P(st.S)
    if ny < nf and st.Sy is not None:
        if load_line == "proportional":
            return rf"n_y = \frac{{{P(st.Sy)}}}{{{a} + {P(abs(sm))}}} = {tex(ny)}"
        return rf"n_y = \frac{{{P(st.Sy)} - {P(abs(sm))}}}{{{a}}} = {tex(ny)}"
    if not (sa > 0 and math.isfinite(nf) and nf > 0):
        return ""
    if sm <= 0:  # every criterion takes a compressive mean as zero: S_a = S_e
        return rf"n_f = \frac{{{S}}}{{{a}}} = {tex(nf)}"
    sf = None if sigma_f is None else to_si(sigma_f, "pressure", "sigma_f")
    B = {"goodman": st.Sut, "gerber": st.Sut, "soderberg": st.Sy, "asme_elliptic": st.Sy, "morrow": sf}.get(criterion)
    if criterion in ("walker", "smith_watson_topper"):
        if load_line != "proportional":
            return ""
        g = 0.5 if criterion == "smith_watson_topper" else to_si(gamma, "dimensionless", "gamma")
        return (rf"n_f = \frac{{{S}}}{{({a} + {m})^{{{tex(1 - g)}}}\cdot ({a})^{{{tex(g)}}}}} = {tex(nf)}")
    if B is None:
        return ""
    b = P(B)
    linear = criterion in ("goodman", "soderberg", "morrow")
    if load_line == "proportional":
        if linear:
            return rf"n_f = \frac{{1}}{{\frac{{{a}}}{{{S}}} + \frac{{{m}}}{{{b}}}}} = {tex(nf)}"
        if criterion == "gerber":
            return (rf"n_f = \frac{{1}}{{2}}\cdot \left(\frac{{{b}}}{{{m}}}\right)^{{2}}\cdot \frac{{{a}}}{{{S}}}\cdot "
                    rf"\left(-1 + \sqrt{{1 + \left(\frac{{2\cdot {m}\cdot {S}}}{{{b}\cdot {a}}}\right)^{{2}}}}\right)"
                    rf" = {tex(nf)}")
        return (rf"n_f = \sqrt{{\frac{{1}}{{\left(\frac{{{a}}}{{{S}}}\right)^{{2}} + "
                rf"\left(\frac{{{m}}}{{{b}}}\right)^{{2}}}}}} = {tex(nf)}")
    if linear:
        return rf"n_f = \frac{{{S}\cdot \left(1 - \frac{{{m}}}{{{b}}}\right)}}{{{a}}} = {tex(nf)}"
    if criterion == "gerber":
        return rf"n_f = \frac{{{S}\cdot \left(1 - \left(\frac{{{m}}}{{{b}}}\right)^{{2}}\right)}}{{{a}}} = {tex(nf)}"
    return (rf"n_f = \frac{{{S}\cdot \sqrt{{1 - \left(\frac{{{m}}}{{{b}}}\right)^{{2}}}}}}{{{a}}} = {tex(nf)}")


def _prepare(material: Any, life: float | None, Kf: float, criterion: str, load_line: str) -> Material:
    if life is not None and not life >= 1:
        raise InputError(f"life: required cycles must be >= 1, got {life!r}")
    if not Kf >= 1:
        raise InputError(f"Kf: fatigue notch factor must be >= 1, got {Kf!r}")
    criteria.require_criterion(criterion)
    criteria.require_load_line(load_line)
    return _material(material)


@check("fatigue", title='Fatigue (one stress state)', sf_kind="fatigue",
       source=SHIGLEY,
       explain=('Alternating and mean stress (times Kf) against the fatigue strength by a mean-stress criterion '
                '(Goodman by default; Gerber, Soderberg, ASME elliptic, Morrow, SWT, Walker) along a proportional or '
                "constant-mean load line, with Langer first-cycle yield; endurance limit from Se' and the Marin "
                'factors, or a finite-life strength from the S-N line (Shigley 10th ed. Secs. 6-7 to 6-12).'))
def check_fatigue(component: str, sigma_a: QuantityLike, sigma_m: QuantityLike, material: Any, *,
                  life: float | None = None,
                  criterion: str = "goodman", load_line: str = "proportional", Kf: float = 1.0, Se: Any = None,
                  marin: dict | None = None, polymer_fraction: float | None = None, sigma_f: Any = None,
                  gamma: Any = None, required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """Fatigue safety factor of one stress state (see the module docstring)."""
    mat = _prepare(material, life, Kf, criterion, load_line)
    sa = to_si(sigma_a, "pressure", "sigma_a") * Kf
    sm = to_si(sigma_m, "pressure", "sigma_m") * Kf
    if sa < 0:
        raise InputError("sigma_a: stress amplitude must be >= 0")
    st = _strength(mat, life, Se, marin, polymer_fraction)
    nf, ny = _evaluate(sa, sm, st, criterion, load_line, sigma_f, gamma)
    return _common(component, st, criterion, load_line, Kf, life, float(nf), float(ny), sa, sm, required_sf,
                   load_case, sigma_f, gamma, {}, (), "fatigue")


@check("fatigue_field", title='Fatigue (FEA stress field)', sf_kind="fatigue",
       source=SHIGLEY,
       explain=('The fatigue check of every node of an FEA field of von Mises alternating and mean stresses; the node'
                ' with the smallest safety factor governs and the whole safety-factor field is kept for the figure.'))
def check_fatigue_field(component: str, sigma_a: QuantityLike, sigma_m: QuantityLike, material: Any, *,
                        coordinates: QuantityLike | None = None,
                        life: float | None = None, criterion: str = "goodman", load_line: str = "proportional",
                        Kf: float = 1.0, Se: Any = None, marin: dict | None = None,
                        polymer_fraction: float | None = None, sigma_f: Any = None, gamma: Any = None,
                        required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """Fatigue safety factor of an FEA field: per-node von Mises alternating/mean stresses (arrays).

    The governing node is the one with the smallest safety factor; ``details`` hold the whole
    safety-factor field (``safety_factor_field``), the governing node index and, with
    ``coordinates`` (n x dim array of lengths), its position.
    """
    mat = _prepare(material, life, Kf, criterion, load_line)
    sa = np.atleast_1d(np.asarray(to_si(sigma_a, "pressure", "sigma_a"), float)) * Kf
    sm = np.atleast_1d(np.asarray(to_si(sigma_m, "pressure", "sigma_m"), float)) * Kf
    if sa.shape != sm.shape or sa.ndim != 1 or sa.size == 0:
        raise InputError(f"sigma_a, sigma_m: need two 1-D arrays of equal length, got {sa.shape} and {sm.shape}")
    if np.any(sa < 0):
        raise InputError("sigma_a: stress amplitudes must be >= 0")
    st = _strength(mat, life, Se, marin, polymer_fraction)
    nf, ny = _evaluate(sa, sm, st, criterion, load_line, sigma_f, gamma)
    n = np.minimum(nf, ny)
    i = int(np.argmin(n))
    extra: dict[str, Any] = {"safety_factor_field": n, "governing_node": i, "nodes": int(sa.size)}
    notes = [f"governing node {i} of {sa.size}"]
    if coordinates is not None:
        xyz = np.asarray(to_si(coordinates, "length", "coordinates"), float)
        if xyz.shape[0] != sa.size:
            raise InputError(f"coordinates: {xyz.shape[0]} rows for {sa.size} nodes")
        extra["governing_location"] = Q(xyz[i], "m")
        notes.append("at " + ", ".join(f"{v * 1e3:.4g}" for v in xyz[i]) + " mm")
    return _common(component, st, criterion, load_line, Kf, life, float(nf[i]), float(ny[i]), float(sa[i]),
                   float(sm[i]), required_sf, load_case, sigma_f, gamma, extra, tuple(notes), "fatigue_field")


#: Former names, kept for callers not yet renamed (the frame adapter): use :func:`check_fatigue` and
#: :func:`check_fatigue_field`.
fatigue_check = check_fatigue
fatigue_field_check = check_fatigue_field

__all__ = ["check_fatigue", "check_fatigue_field", "fatigue_check", "fatigue_field_check"]
