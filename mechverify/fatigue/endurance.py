"""Endurance limit from the ultimate strength, and the Marin factors that correct it for the real part.

Public API (quantities in, quantities out; each factor is dimensionless)::

    estimate_fatigue_strength(Sut, material_class="steel", polymer_fraction=None) -> FatigueStrengthEstimate
    surface_factor(Sut, finish)                 # ka, Table 6-2 / Eq. (6-19)
    size_factor(d, loading="bending")           # kb, Eqs. (6-20), (6-21)
    equivalent_diameter_round_nonrotating(d)    # de = 0.370 d, Table 6-3
    equivalent_diameter_rectangle(h, b)         # de = 0.808 sqrt(h b), Table 6-3
    load_factor(loading)                        # kc, Eq. (6-26)
    temperature_factor(T)                       # kd, Table 6-4
    reliability_factor(reliability)             # ke, Table 6-5 / Eq. (6-29)
    corrected_endurance_limit(Sut, finish=..., d=..., loading=..., ...) -> EnduranceLimit

References
----------
1. Budynas, Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015, Secs. 6-7 and 6-9:
   Eq. (6-8) (Se' of steels), Eqs. (6-18)..(6-29), Tables 6-2..6-5.
2. Norton, *Machine Design: An Integrated Approach*, 4th ed., 2011, Sec. 6.6: wrought aluminium has no
   endurance limit; its fatigue strength at 5e8 cycles is about 0.4 Sut (Sut < 330 MPa), else 130 MPa.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from statistics import NormalDist
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.fatigue._data import load
from mechverify.units import Q, fmt, from_si, to_si

SOURCE = "Shigley's Mechanical Engineering Design, 10th ed."
STEELS = ("steel", "alloy steel", "carbon steel", "stainless steel", "wrought steel")
ALUMINIUMS = ("aluminium", "aluminum")
POLYMERS = ("polymer", "3d printed polymer", "printed polymer", "plastic", "pla", "petg", "abs")
LOADINGS = ("bending", "axial", "torsion")

#: Conservative fraction of the tensile strength assumed as fatigue strength of printed polymers
#: when no S-N data are given. A mechverify assumption, not a published endurance limit.
DEFAULT_POLYMER_FRACTION = 0.2


@dataclass(frozen=True)
class FatigueStrengthEstimate:
    """An estimated fully reversed fatigue strength of polished specimens (rotating beam).

    ``cycles`` is ``inf`` for a true endurance limit (steels), or the life the strength belongs to.
    """

    strength: pint.Quantity
    cycles: float
    material_class: str
    source: str
    notes: tuple[str, ...] = ()

    @property
    def is_endurance_limit(self) -> bool:
        return math.isinf(self.cycles)


def _class(material_class: str) -> str:
    key = str(material_class).strip().lower().replace("_", " ").replace("-", " ")
    if key in STEELS:
        return "steel"
    if key in ALUMINIUMS:
        return "aluminium"
    if key in POLYMERS:
        return "polymer"
    raise UnknownNameError("material class for a fatigue-strength estimate", material_class,
                           [*STEELS, *ALUMINIUMS, *POLYMERS])


def estimate_fatigue_strength(Sut: Any, material_class: str = "steel",
                              polymer_fraction: float | None = None) -> FatigueStrengthEstimate:
    """Fatigue strength of polished specimens estimated from the ultimate strength, where no test data exist.

    * steels: endurance limit ``Se' = 0.5 Sut`` for Sut <= 1400 MPa, ``700 MPa`` above (Ref. 1, Eq. (6-8));
    * wrought aluminium: no endurance limit; ``Sf' = 0.4 Sut`` (Sut < 330 MPa) or ``130 MPa`` at 5e8
      cycles (Ref. 2);
    * polymers (3D-printed included): no endurance limit and no accepted estimate; only with an
      explicit ``polymer_fraction`` (e.g. :data:`DEFAULT_POLYMER_FRACTION`) is ``Sf = fraction * Sut``
      returned, at 1e6 cycles, marked as an assumption. Give S-N data of the printed material instead.
    """
    sut = to_si(Sut, "pressure", "Sut")
    if sut <= 0:
        raise InputError(f"Sut: must be positive, got {fmt(Q(sut, 'Pa'), 'MPa')}")
    cls = _class(material_class)
    if cls == "steel":
        se = 0.5 * sut if sut <= 1400e6 else 700e6
        return FatigueStrengthEstimate(from_si(se, "pressure"), math.inf, cls, f"{SOURCE}, Eq. (6-8)",
                                       ("Se' = 0.5 Sut (700 MPa above Sut = 1400 MPa): steels only, "
                                        "polished rotating-beam specimens",))
    if cls == "aluminium":
        sf = 0.4 * sut if sut < 330e6 else 130e6
        return FatigueStrengthEstimate(from_si(sf, "pressure"), 5e8, cls,
                                       "Norton, Machine Design, 4th ed., Sec. 6.6",
                                       ("aluminium has no endurance limit: strength at 5e8 cycles",))
    if polymer_fraction is None:
        raise InputError("polymer: no endurance limit exists for polymers (3D-printed or not) and no "
                         "estimate from Sut is accepted; give S-N data of the printed material, or pass "
                         f"polymer_fraction (e.g. {DEFAULT_POLYMER_FRACTION}) to assume a conservative fraction")
    if not 0 < polymer_fraction <= 0.5:
        raise InputError(f"polymer_fraction: must lie in (0, 0.5], got {polymer_fraction!r}")
    return FatigueStrengthEstimate(
        from_si(polymer_fraction * sut, "pressure"), 1e6, cls, "mechverify assumption (no published estimate)",
        (f"ASSUMED fatigue strength {polymer_fraction:g} x Sut at 1e6 cycles: polymers have no endurance limit; "
         "replace with S-N data of the printed material (orientation, infill and layer height matter)",))


# --------------------------------------------------------------------------------------------- Marin factors
def surface_factor(Sut: Any, finish: str) -> pint.Quantity:
    """Surface factor ``ka = a Sut^b`` [-] (Sut in MPa), Ref. 1 Eq. (6-19), Table 6-2.

    finish: ``ground``, ``machined``, ``cold_drawn``, ``hot_rolled``, ``as_forged``.
    """
    table = load("marin")["surface"]
    key = str(finish).strip().lower().replace(" ", "_").replace("-", "_")
    if key not in table or key == "source":
        raise UnknownNameError("surface finish", finish, [k for k in table if k != "source"])
    sut = to_si(Sut, "pressure", "Sut") / 1e6
    if sut <= 0:
        raise InputError("Sut: must be positive")
    row = table[key]
    return Q(row["a_MPa"] * sut ** row["b"], "")


def size_factor(d: Any, loading: str = "bending") -> pint.Quantity:
    """Size factor kb [-] for round bars in bending or torsion, Ref. 1 Eq. (6-20); 1 in axial, Eq. (6-21).

    ``kb = (d/7.62)^-0.107`` for 2.79 <= d <= 51 mm, ``1.51 d^-0.157`` for 51 < d <= 254 mm (d in mm).
    For non-rotating or non-round sections pass the equivalent diameter (Table 6-3).
    """
    kind = _loading(loading)
    dm = to_si(d, "length", "d") * 1e3
    if dm <= 0:
        raise InputError(f"d: must be positive, got {dm:g} mm")
    if kind == "axial":
        return Q(1.0, "")
    if 2.79 <= dm <= 51:
        return Q((dm / 7.62) ** -0.107, "")
    if 51 < dm <= 254:
        return Q(1.51 * dm ** -0.157, "")
    raise ValidityError(f"d = {dm:.4g} mm: the size factor of Eq. (6-20) holds for 2.79 mm <= d <= 254 mm")


def equivalent_diameter_round_nonrotating(d: Any) -> pint.Quantity:
    """Equivalent diameter of a non-rotating round bar in bending, ``de = 0.370 d`` [m], Ref. 1 Table 6-3."""
    dm = to_si(d, "length", "d")
    if dm <= 0:
        raise InputError("d: must be positive")
    return from_si(0.370 * dm, "length")


def equivalent_diameter_rectangle(h: Any, b: Any) -> pint.Quantity:
    """Equivalent diameter of a rectangular section in bending, ``de = 0.808 sqrt(h b)`` [m], Ref. 1 Table 6-3."""
    hm, bm = to_si(h, "length", "h"), to_si(b, "length", "b")
    if hm <= 0 or bm <= 0:
        raise InputError("h, b: must be positive")
    return from_si(0.808 * math.sqrt(hm * bm), "length")


def _loading(loading: str) -> str:
    key = str(loading).strip().lower()
    if key not in LOADINGS:
        raise UnknownNameError("loading type", loading, LOADINGS)
    return key


def load_factor(loading: str) -> pint.Quantity:
    """Load factor kc [-]: bending 1, axial 0.85, torsion 0.59 (Ref. 1, Eq. (6-26)).

    For combined loading use the von Mises equivalent stress with kc = 1 (Ref. 1, Sec. 6-14).
    """
    return Q({"bending": 1.0, "axial": 0.85, "torsion": 0.59}[_loading(loading)], "")


def temperature_factor(T: Any) -> pint.Quantity:
    """Temperature factor ``kd = ST/SRT`` [-] from Ref. 1 Table 6-4 (steels), linear between rows.

    Valid 20..600 degC; outside, :class:`ValidityError`.
    """
    t = to_si(T, "temperature", "T") - 273.15
    table = load("marin")["temperature"]
    tc, ratio = table["celsius"], table["ratio_c"]
    if not tc[0] - 1e-9 <= t <= tc[-1] + 1e-9:
        raise ValidityError(f"T = {t:.4g} degC: Table 6-4 covers {tc[0]}..{tc[-1]} degC")
    return Q(float(np.interp(t, tc, ratio)), "")


def reliability_factor(reliability: float) -> pint.Quantity:
    """Reliability factor ``ke = 1 - 0.08 za`` [-], za the standard normal variate of the reliability.

    reliability as a fraction (0.99) in [0.5, 0.999999]. Ref. 1 Eq. (6-29), Table 6-5.
    """
    r = float(reliability)
    if not 0.5 <= r <= 0.999999 + 1e-12:
        raise ValidityError(f"reliability: Table 6-5 covers 0.5..0.999999, got {r!r}")
    za = NormalDist().inv_cdf(r) if r > 0.5 else 0.0
    return Q(1.0 - 0.08 * za, "")


@dataclass(frozen=True)
class MarinFactors:
    """The six Marin factors and where each came from."""

    ka: float = 1.0
    kb: float = 1.0
    kc: float = 1.0
    kd: float = 1.0
    ke: float = 1.0
    kf: float = 1.0
    sources: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name in ("ka", "kb", "kc", "kd", "ke", "kf"):
            v = getattr(self, name)
            if not (isinstance(v, int | float) and 0 < v <= 1.5):
                raise InputError(f"{name}: a Marin factor must lie in (0, 1.5], got {v!r}")

    @property
    def product(self) -> float:
        return self.ka * self.kb * self.kc * self.kd * self.ke * self.kf

    def as_dict(self) -> dict[str, float]:
        return {k: getattr(self, k) for k in ("ka", "kb", "kc", "kd", "ke", "kf")}


@dataclass(frozen=True)
class EnduranceLimit:
    """A Marin-corrected endurance limit (or fatigue strength at ``cycles``), ``Se = ka kb kc kd ke kf Se'``."""

    Se: pint.Quantity
    Se_prime: pint.Quantity
    factors: MarinFactors
    cycles: float = math.inf
    source: str = ""
    notes: tuple[str, ...] = ()


def corrected_endurance_limit(Sut: Any, *, finish: str = "machined", d: Any = None, loading: str = "bending",
                              T: Any = None, reliability: float = 0.5, kf_misc: float = 1.0,
                              Se_prime: Any = None, material_class: str = "steel",
                              polymer_fraction: float | None = None) -> EnduranceLimit:
    """Marin equation ``Se = ka kb kc kd ke kf Se'`` (Ref. 1, Eq. (6-18)).

    Se_prime: test value of the specimen endurance limit; estimated from Sut when omitted
    (:func:`estimate_fatigue_strength`). d: diameter (or equivalent diameter) for kb; ``None`` means
    kb = 1 (stated in the notes). T: temperature for kd (room temperature when ``None``).
    """
    notes: list[str] = []
    if Se_prime is None:
        est = estimate_fatigue_strength(Sut, material_class, polymer_fraction)
        se_p, cycles, notes = est.strength, est.cycles, [*est.notes]
        src = est.source
    else:
        se_p, cycles, src = as_q(Se_prime), math.inf, "test value of Se'"
    if _class(material_class) == "polymer":
        # Marin factors are calibrated on steels; for polymers the fraction already stands for the part.
        f = MarinFactors(kf=float(kf_misc), sources={"kf": "user"})
        notes.append("Marin factors ka..ke are steel correlations; not applied to a polymer")
    else:
        ka = surface_factor(Sut, finish).m
        kb = 1.0 if d is None else size_factor(d, loading).m
        if d is None and _loading(loading) != "axial":
            notes.append("kb = 1: no size given")
        kc = load_factor(loading).m
        kd = 1.0 if T is None else temperature_factor(T).m
        if T is None:
            notes.append("kd = 1: room temperature")
        ke = reliability_factor(reliability).m
        f = MarinFactors(ka, kb, kc, kd, ke, float(kf_misc), sources={
            "ka": f"{SOURCE}, Table 6-2 ({finish})", "kb": f"{SOURCE}, Eq. (6-20)/(6-21)",
            "kc": f"{SOURCE}, Eq. (6-26) ({loading})", "kd": f"{SOURCE}, Table 6-4",
            "ke": f"{SOURCE}, Table 6-5 (R = {reliability:g})", "kf": "miscellaneous (user)"})
    se = (se_p * f.product).to("Pa")
    return EnduranceLimit(se, se_p.to("Pa"), f, cycles, f"{SOURCE}, Eq. (6-18); Se': {src}", tuple(notes))


def as_q(v: Any) -> pint.Quantity:
    """``v`` checked as a pressure, as a quantity in Pa."""
    return from_si(to_si(v, "pressure", "Se_prime"), "pressure")


__all__ = ["FatigueStrengthEstimate", "estimate_fatigue_strength", "surface_factor", "size_factor",
           "equivalent_diameter_round_nonrotating", "equivalent_diameter_rectangle", "load_factor",
           "temperature_factor", "reliability_factor", "MarinFactors", "EnduranceLimit",
           "corrected_endurance_limit", "DEFAULT_POLYMER_FRACTION"]
