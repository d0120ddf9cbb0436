"""Rolling bearings (deep groove ball bearings from a catalogue) and plain bushings.

Rolling bearings: equivalent dynamic load P = X·Fr + Y·Fa with the ISO 281 factors interpolated on
f0·Fa/C0; basic rating life L10 = (C/P)^p (p = 3 for ball bearings) in revolutions and hours; the
reliability factor a1; the static equivalent load P0 and static safety factor s0 = C0/P0 (ISO 76);
the speed against the limiting speed. Plain bushings: p = F/(dL), v, and pv against the material's
limits.

References
----------
[1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life: Eq. (1) L10 = (C/P)^p,
    Table 3 (X, Y, e for radial ball bearings), Table 12 (a1).
[2] ISO 76:2006, Rolling bearings - Static load ratings: Sec. 6.2.2 (P0 = 0.6 Fr + 0.5 Fa >= Fr), s0 = C0/P0.
[3] SKF, Rolling bearings, PUB BU/P1 17000/1 EN, 2018: product tables (components/data/bearings_ball.toml),
    axial load limits of deep groove ball bearings (Fa <= 0.25 C0 for d <= 12 mm and light series,
    0.5 C0 otherwise), static safety factor guideline s0 >= 1 (normal, rotating ball bearings).
[4] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, Sec. 12-15
    (boundary-lubricated bearings: pressure P = F/(DL), velocity V, the PV limit).
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.materials import database as _materials
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike, fmt, from_si, si_function, to_si

_DATA = Path(__file__).parent / "data" / "bearings_ball.toml"


@cache
def _data() -> dict[str, Any]:
    return tomllib.loads(_DATA.read_text(encoding="utf-8"))


# ------------------------------------------------------------------------------------- catalogue
@dataclass(frozen=True)
class BallBearing:
    """A single-row deep groove ball bearing with its catalogue data (quantities)."""

    designation: str
    d: pint.Quantity
    D: pint.Quantity
    B: pint.Quantity
    C: pint.Quantity
    C0: pint.Quantity
    Pu: pint.Quantity
    reference_speed: pint.Quantity
    limiting_speed: pint.Quantity
    f0: float
    kr: float = 0.025
    mass: pint.Quantity | None = None
    variant: str = "open"  # open, shielded, sealed (contact seals)
    source: str = ""
    aliases: tuple[str, ...] = field(default=(), compare=False)
    #: what of this row is not verified against its source ("" when the row is verified); the checks
    #: that use the bearing carry it as a warning
    unverified: str = ""

    def __post_init__(self) -> None:
        for name, dim in (("d", "length"), ("D", "length"), ("B", "length"), ("C", "force"), ("C0", "force"),
                          ("Pu", "force"), ("reference_speed", "angular_velocity"),
                          ("limiting_speed", "angular_velocity")):
            v = to_si(getattr(self, name), dim, f"{self.designation}.{name}")
            if v <= 0:
                raise InputError(f"bearing {self.designation}: {name} must be positive")
        if not to_si(self.D, "length") > to_si(self.d, "length"):
            raise InputError(f"bearing {self.designation}: outside diameter D must exceed bore d")
        if not self.f0 > 0:
            raise InputError(f"bearing {self.designation}: f0 must be positive")

    @property
    def axial_load_limit(self) -> pint.Quantity:
        """Largest recommended axial load: 0.25·C0 for d <= 12 mm or light series (60, 618), else 0.5·C0 [3]."""
        light = self.d.m_as("mm") <= 12 or self.designation.startswith(("60", "618"))
        return ((0.25 if light else 0.5) * self.C0).to("kN")

    def equivalent_load(self, Fr: Any, Fa: Any = "0 N") -> EquivalentLoad:
        """P = X·Fr + Y·Fa with this bearing's C0 and f0 ([1] Table 3)."""
        return equivalent_dynamic_load(Fr, Fa, self.C0, self.f0)

    def rating_life(self, Fr: Any, Fa: Any = "0 N", reliability: float = 0.9) -> pint.Quantity:
        """L_n = a1·(C/P)³ in revolutions ([1] Eq. (1), Table 12)."""
        P = self.equivalent_load(Fr, Fa).P
        return reliability_factor(reliability) * basic_rating_life(self.C, P)

    def rating_life_hours(self, Fr: Any, Fa: Any, speed: Any, reliability: float = 0.9) -> pint.Quantity:
        """L_nh = L_n / n [h]."""
        return life_hours(self.rating_life(Fr, Fa, reliability), speed)

    def static_load(self, Fr: Any, Fa: Any = "0 N") -> pint.Quantity:
        return equivalent_static_load(Fr, Fa)

    def static_safety(self, Fr: Any, Fa: Any = "0 N") -> float:
        """s0 = C0/P0 ([2])."""
        return float((self.C0 / self.static_load(Fr, Fa)).m_as(""))

    def __repr__(self) -> str:
        return (f"<BallBearing {self.designation} {fmt(self.d, 'mm')}x{fmt(self.D, 'mm')}x{fmt(self.B, 'mm')} "
                f"C={fmt(self.C, 'kN')} C0={fmt(self.C0, 'kN')}>")


def _unverified(row: dict) -> str:
    """The row's verification caveat: "" for ``verified = true``, else its note (or a general one)."""
    if row.get("verified") is True:
        return ""
    return row.get("verification") or "catalogue row not checked against the published SKF table"


@cache
def _catalogue() -> dict[str, BallBearing]:
    data = _data()
    src = data["references"]["skf17000"]
    out: dict[str, BallBearing] = {}
    for row in data["bearing"]:
        b = BallBearing(
            designation=row["designation"], d=Q(row["d"], "mm"), D=Q(row["D"], "mm"), B=Q(row["B"], "mm"),
            C=Q(row["C"], "kN"), C0=Q(row["C0"], "kN"), Pu=Q(row["Pu"], "kN"),
            reference_speed=Q(row["reference_speed"], "rpm"), limiting_speed=Q(row["limiting_speed"], "rpm"),
            f0=float(row["f0"]), kr=float(row.get("kr", 0.025)), mass=Q(row["mass"], "kg"), source=src,
            aliases=tuple(row.get("aliases", ())), unverified=_unverified(row))
        for key in (b.designation, *b.aliases):
            out[key] = b
    return out


def bearing_names() -> list[str]:
    """Catalogue designations (with aliases such as 6800 for SKF 61800)."""
    return list(_catalogue())


def bearing_catalogue() -> list[BallBearing]:
    """Every catalogue bearing once, in catalogue order (for listings: designation, d x D x B, C, C0, speeds)."""
    return list({id(b): b for b in _catalogue().values()}.values())


_SHIELD = {"Z", "ZZ", "2Z", "LB", "LLB", "VV", "RZ", "2RZ", "Z1", "2Z1"}
_SEAL = {"RS", "2RS", "RS1", "2RS1", "RSH", "2RSH", "RSR", "2RSR", "LU", "LLU", "DDU", "DD", "RSL", "2RSL"}


def bearing(name: str) -> BallBearing:
    """A catalogue bearing by designation: ``bearing("608")``, ``bearing("6200-2Z")``, ``bearing("608LU")``.

    Shield suffixes (Z, 2Z, ZZ, LB, VV...) and contact-seal suffixes (RS, 2RS1, 2RSH, LU, LLU, DDU...)
    and a clearance class (C3) are accepted: the load ratings are those of the open bearing and the
    variant is recorded (contact seals lower the limiting speed: see the speed check). A brand prefix
    such as "KML " is ignored. Unknown designations raise :class:`UnknownNameError` with suggestions.
    """
    if not isinstance(name, str):
        raise InputError(f"bearing: expected a designation string, got {type(name).__name__}")
    cat = _catalogue()
    raw = name.strip().upper().replace(" ", "")
    m = re.fullmatch(r"([A-Z]*?)(\d{3,5})(?:[-/]?([A-Z0-9]*?))?(?:[-/]?C[2-5])?", raw)
    if m is None or m.group(2) not in cat:
        base = m.group(2) if m else raw
        raise UnknownNameError("bearing", name if m is None else base, list(cat))
    suffix = (m.group(3) or "").upper()
    b = cat[m.group(2)]
    if suffix in ("", None):
        return b
    if suffix in _SHIELD:
        variant = "shielded"
    elif suffix in _SEAL:
        variant = "sealed"
    else:
        raise UnknownNameError("bearing suffix", suffix, sorted(_SHIELD | _SEAL))
    import dataclasses
    return dataclasses.replace(b, designation=f"{b.designation}-{suffix}", variant=variant)


# ------------------------------------------------------------------------------ ISO 281 and ISO 76
@dataclass(frozen=True)
class EquivalentLoad:
    """Equivalent dynamic load and the ISO 281 factors used."""

    P: pint.Quantity
    X: float
    Y: float
    e: float
    relative_axial_load: float  # f0·Fa/C0


def iso281_factors(relative_axial_load: float) -> tuple[float, float]:
    """(e, Y) for Fa/Fr > e, linearly interpolated on f0·Fa/C0 ([1] Table 3; X = 0.56 there).

    Below the first row (0.172) the first row applies; beyond the last (6.89) :class:`ValidityError`.
    """
    t = _data()["iso281_radial_ball"]
    x = float(relative_axial_load)
    if x < 0:
        raise InputError(f"f0*Fa/C0 must be >= 0, got {x:g}")
    if x > t["f0_fa_c0"][-1]:
        raise ValidityError(f"relative axial load f0*Fa/C0 = {x:.3g} beyond ISO 281 Table 3 ({t['f0_fa_c0'][-1]})")
    return float(np.interp(x, t["f0_fa_c0"], t["e"])), float(np.interp(x, t["f0_fa_c0"], t["Y"]))


def equivalent_dynamic_load(Fr: QuantityLike, Fa: QuantityLike, C0: QuantityLike, f0: float) -> EquivalentLoad:
    """P = X·Fr + Y·Fa for a single-row radial ball bearing ([1] Sec. 6.2, Table 3).

    Fa/Fr <= e: X = 1, Y = 0; Fa/Fr > e: X = 0.56, Y(f0·Fa/C0). Fr, Fa [N], C0 [N], f0 [-].
    """
    fr, fa, c0 = to_si(Fr, "force", "Fr"), to_si(Fa, "force", "Fa"), to_si(C0, "force", "C0")
    if fr < 0 or fa < 0:
        raise InputError(f"bearing loads must be >= 0 (Fr = {fr:g} N, Fa = {fa:g} N)")
    if c0 <= 0 or not f0 > 0:
        raise InputError("C0 and f0 must be positive")
    rel = float(f0) * fa / c0
    e, Y = iso281_factors(rel)
    if fa == 0 or (fr > 0 and fa / fr <= e):
        return EquivalentLoad(P=Q(fr, "N"), X=1.0, Y=0.0, e=e, relative_axial_load=rel)
    X = float(_data()["iso281_radial_ball"]["X"])
    return EquivalentLoad(P=Q(X * fr + Y * fa, "N"), X=X, Y=Y, e=e, relative_axial_load=rel)


def basic_rating_life(C: QuantityLike, P: QuantityLike, exponent: float = 3.0) -> pint.Quantity:
    """L10 = (C/P)^p ·10⁶ revolutions; p = 3 for ball, 10/3 for roller bearings ([1] Eq. (1))."""
    c, p = to_si(C, "force", "C"), to_si(P, "force", "P")
    if c <= 0 or p < 0:
        raise InputError(f"C must be positive and P >= 0 (C = {c:g} N, P = {p:g} N)")
    if p == 0:
        return Q(math.inf, "revolution")
    return Q((c / p) ** exponent * 1e6, "revolution")


def life_hours(revolutions: Any, speed: QuantityLike) -> pint.Quantity:
    """Life in hours L_h = L / (60·n) with L in revolutions and n in r/min."""
    n = to_si(speed, "angular_velocity", "speed")
    if n <= 0:
        raise InputError(f"speed must be positive, got {fmt(from_si(n, 'angular_velocity').to('rpm'))}")
    L = revolutions.m_as("revolution") if isinstance(revolutions, pint.Quantity) else float(revolutions)
    return Q(L * 2 * math.pi / n, "s").to("hour")


def reliability_factor(reliability: float) -> float:
    """Life modification factor for reliability a1 ([1] Table 12: 0.90 -> 1, 0.95 -> 0.64, 0.99 -> 0.25 ...).

    Between table rows, interpolated linearly in ln(ln(1/R)) (the Weibull life axis). Reliability
    outside 0.90..0.9995 raises :class:`ValidityError`.
    """
    t = _data()["iso281_a1"]
    R = float(reliability)
    if R > 1:
        R /= 100.0  # given in percent
    if not (t["reliability"][0] - 1e-12 <= R <= t["reliability"][-1] + 1e-12):
        raise ValidityError(f"reliability {R:g} outside ISO 281 Table 12 (0.90..0.9995)")
    x = np.log(np.log(1 / np.asarray(t["reliability"])))
    return float(np.interp(math.log(math.log(1 / R)), x[::-1], np.asarray(t["a1"])[::-1]))


def equivalent_static_load(Fr: QuantityLike, Fa: QuantityLike = "0 N") -> pint.Quantity:
    """P0 = X0·Fr + Y0·Fa (X0 = 0.6, Y0 = 0.5), and P0 = Fr if that is larger ([2] Sec. 6.2.2)."""
    fr, fa = to_si(Fr, "force", "Fr"), to_si(Fa, "force", "Fa")
    if fr < 0 or fa < 0:
        raise InputError("bearing loads must be >= 0")
    t = _data()["iso76_radial_ball"]
    return Q(max(t["X0"] * fr + t["Y0"] * fa, fr), "N")


# ------------------------------------------------------------------------------------ plain bushings
@si_function(returns="pressure", F="force", d="length", length="length")
def bushing_pressure(F: float, d: float, length: float) -> float:
    """Mean projected pressure p = F/(d·L) [Pa] of a journal bushing (F radial load, d bore, L length)."""
    if d <= 0 or length <= 0:
        raise InputError("bushing bore and length must be positive")
    return F / (d * length)


@si_function(returns="velocity", d="length", speed="angular_velocity")
def sliding_speed(d: float, speed: float) -> float:
    """Surface speed of a shaft rotating in a bushing v = ω·d/2 [m/s] (= π·d·n)."""
    return abs(speed) * d / 2


@dataclass(frozen=True)
class PlainBushing:
    """A plain journal bushing (or a linear slide bush): bore ``d``, length ``length``, and the limits
    ``p_max``, ``v_max``, ``pv_max`` (taken from ``material`` when not given; the material may be a name
    or a :class:`Material` with p_max, v_max, pv_max, mu_min, mu_max)."""

    d: Any
    length: Any
    material: str | Material | None = None
    p_max: Any = None
    v_max: Any = None
    pv_max: Any = None
    name: str = "bushing"

    def __post_init__(self) -> None:
        for nm in ("d", "length"):
            if to_si(getattr(self, nm), "length", nm) <= 0:
                raise InputError(f"{self.name}: {nm} must be positive")
        mat = self.material
        if isinstance(mat, str):
            mat = _materials.get(mat)
        object.__setattr__(self, "_material", mat)
        for nm, dim in (("p_max", "pressure"), ("v_max", "velocity"), ("pv_max", "pv")):
            v = getattr(self, nm)
            if v is None and mat is not None:
                v = getattr(mat, nm)
            if v is not None:
                v = from_si(to_si(v, dim, nm), dim).to({"pressure": "MPa", "velocity": "m/s", "pv": "MPa*m/s"}[dim])
                if v.magnitude <= 0:
                    raise InputError(f"{self.name}: {nm} must be positive")
            object.__setattr__(self, nm, v)

    @property
    def material_record(self) -> Material | None:
        return self._material  # type: ignore[attr-defined]

    def pressure(self, F: Any) -> pint.Quantity:
        return bushing_pressure(F, self.d, self.length).to("MPa")

    def pv(self, F: Any, v: QuantityLike) -> pint.Quantity:
        """p·v [MPa·m/s] for radial load F and sliding speed v."""
        return (self.pressure(F) * Q(to_si(v, "velocity", "v"), "m/s")).to("MPa*m/s")

    def limit(self, name: str) -> pint.Quantity:
        v = getattr(self, name)
        if v is None:
            raise InputError(f"{self.name}: no {name} known; give {name}= or a material that has it")
        return v


__all__ = ["BallBearing", "EquivalentLoad", "PlainBushing", "bearing", "bearing_names", "bearing_catalogue",
           "iso281_factors", "equivalent_dynamic_load", "basic_rating_life", "life_hours", "reliability_factor",
           "equivalent_static_load", "bushing_pressure", "sliding_speed"]
