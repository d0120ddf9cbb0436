"""More rolling-bearing types: angular contact ball (single and matched pairs), thrust ball (511, 512),
tapered roller, cylindrical roller and needle roller bearings; the induced axial force of two adjusted
bearings (ISO/SKF rule and Timken's rule).

Each catalogue row (``components/data/bearings_rolling.toml``) carries the maker's calculation factors
with the ratings, so the equivalent loads are the maker's:

* radial bearings: P = Fr for Fa/Fr <= e, else P = X·Fr + Y·Fa; matched pairs back-to-back or
  face-to-face: P = Fr + Y1·Fa for Fa/Fr <= e, else P = X2·Fr + Y2·Fa [1, 3];
* static: P0 = X0·Fr + Y0·Fa, and P0 = Fr when that is larger [2, 3];
* thrust ball bearings: P = P0 = Fa; they take no radial load [3];
* non-locating cylindrical roller (NU, N) and needle roller bearings: P = P0 = Fr; no axial load [3];
* rating life L10 = (C/P)^p with p = 3 for ball and 10/3 for roller bearings [1].

Matched pairs mounted next to each other (SKF, for bearing sets): C = 1.62·C_single, C0 = 2·C0_single,
Pu = 2·Pu_single [3] (tandem Explorer bearings may use 2·C: 1.62 is kept, the conservative value).

Two single bearings adjusted against each other (tapered roller or angular contact, at two shaft
positions): a radial load induces an axial force F_i in each, F_i = 0.5·Fr/Y (tapered, ISO/SKF) or
R·Fr (angular contact: R = e for the row, SKF's 1.14 for 40° bearings), or Timken's F_i = 0.47·Fr/K
[4, 5]. With the external axial force Ka directed so that it loads bearing A:
F_iA <= F_iB + Ka -> Fa_A = F_iB + Ka, Fa_B = F_iB; otherwise Fa_A = F_iA, Fa_B = F_iA − Ka [3, 4].
Timken/Shigley's equivalent loads: F_eA = 0.4·F_rA + K_A·(F_iB + Ka), F_eB = F_rB (first case), or
F_eB = 0.4·F_rB + K_B·(F_iA − Ka), F_eA = F_rA; an equivalent load below the radial load is taken as the
radial load (the SKF Fa/Fr <= e branch) [4, 5].

References
----------
[1] ISO 281:2007, Eq. (1) (L10 = (C/P)^p, p = 3 ball, 10/3 roller), Sec. 6 (P = X Fr + Y Fa).
[2] ISO 76:2006 (static equivalent load, s0 = C0/P0).
[3] SKF, Rolling bearings, PUB BU/P1 17000/1 EN, 2018: angular contact ball bearings (loads, load
    carrying capacity of bearing pairs, calculating the axial load), tapered roller bearings (loads,
    Fa = 0.5 Fr/Y rule), thrust ball bearings, cylindrical roller bearings (locating: P = 0.92 Fr + Y Fa).
[4] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, Sec. 11-9
    (tapered roller bearings, Timken's induced load F_i = 0.47 F_r/K, Eqs. 11-18 and 11-19).
[5] The Timken Company, Timken Engineering Manual (bearing ratings, induced thrust 0.47 Fr/K).
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import pint

from mechverify.components.bearings import EquivalentLoad, life_hours, reliability_factor
from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.units import Q, QuantityLike, fmt, to_si

_DATA = Path(__file__).parent / "data" / "bearings_rolling.toml"

#: bearing kinds and their life exponents p (ISO 281 Eq. (1))
KINDS: dict[str, float] = {
    "angular_contact_ball": 3.0,
    "thrust_ball": 3.0,
    "tapered_roller": 10.0 / 3.0,
    "cylindrical_roller": 10.0 / 3.0,
    "needle_roller": 10.0 / 3.0,
}
#: matched-pair arrangements of angular contact ball bearings
ARRANGEMENTS = ("single", "back_to_back", "face_to_face", "tandem")
#: SKF ratings of a matched pair mounted immediately adjacent (x single bearing) [3]
PAIR_C, PAIR_C0, PAIR_PU = 1.62, 2.0, 2.0
_SUFFIX = {"back_to_back": "DB", "face_to_face": "DF", "tandem": "DT"}


@dataclass(frozen=True)
class LoadFactors:
    """The maker's calculation factors: P = Fr + Y1·Fa (Fa/Fr <= e), X·Fr + Y·Fa (Fa/Fr > e);
    P0 = max(X0·Fr + Y0·Fa, Fr). Y1 = 0 for single bearings (P = Fr below e)."""

    e: float
    X: float
    Y: float
    Y1: float = 0.0
    X0: float = 1.0
    Y0: float = 0.0


@dataclass(frozen=True)
class RollingBearing:
    """A catalogue rolling bearing of one of :data:`KINDS` with its maker's factors (quantities)."""

    designation: str
    kind: str
    d: pint.Quantity
    D: pint.Quantity
    B: pint.Quantity
    C: pint.Quantity
    C0: pint.Quantity
    limiting_speed: pint.Quantity
    reference_speed: pint.Quantity
    factors: LoadFactors | None = None  # None: pure radial (NU, needle) or pure axial (thrust) bearing
    pair_factors: LoadFactors | None = None  # angular contact: back-to-back / face-to-face pairs
    Pu: pint.Quantity | None = None
    #: induced axial force per radial load, F_i = induced·Fr (tapered: 0.5/Y; angular contact: R)
    induced: float = 0.0
    #: Timken's thrust factor K (Y of the equivalent load, F_i = 0.47 Fr/K), when the maker gives it
    K: float | None = None
    arrangement: str = "single"
    locating: bool = False  # cylindrical roller NJ/NUP: takes some axial load with its factors
    variant: str = "open"
    f0: float | None = None
    source: str = ""
    unverified: str = ""
    aliases: tuple[str, ...] = field(default=(), compare=False)
    #: what of the pair factors is not verified ("" when verified), added to ``unverified`` for pairs
    pair_unverified: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise UnknownNameError("bearing kind", self.kind, list(KINDS))
        if self.arrangement not in ARRANGEMENTS:
            raise UnknownNameError("bearing arrangement", self.arrangement, list(ARRANGEMENTS))
        for name, dim in (("d", "length"), ("D", "length"), ("B", "length"), ("C", "force"), ("C0", "force"),
                          ("limiting_speed", "angular_velocity"), ("reference_speed", "angular_velocity")):
            if not to_si(getattr(self, name), dim, f"{self.designation}.{name}") > 0:
                raise InputError(f"bearing {self.designation}: {name} must be positive")
        if not to_si(self.D, "length") > to_si(self.d, "length"):
            raise InputError(f"bearing {self.designation}: outside diameter D must exceed bore d")

    # ------------------------------------------------------------------ properties
    @property
    def life_exponent(self) -> float:
        """p in L10 = (C/P)^p: 3 for ball, 10/3 for roller bearings [1]."""
        return KINDS[self.kind]

    @property
    def is_ball(self) -> bool:
        return self.kind.endswith("_ball")

    @property
    def axial_load_limit(self) -> pint.Quantity | None:
        return None

    def paired(self, arrangement: str) -> RollingBearing:
        """This angular contact bearing as a matched pair: C x1.62, C0 x2, Pu x2 and the pair factors [3]."""
        if arrangement == "single":
            return self
        if self.kind != "angular_contact_ball":
            raise InputError(f"bearing {self.designation}: matched-pair arrangements apply to angular contact ball "
                             f"bearings, not {self.kind.replace('_', ' ')} bearings")
        if arrangement not in ARRANGEMENTS:
            raise UnknownNameError("bearing arrangement", arrangement, list(ARRANGEMENTS))
        if arrangement != "tandem" and self.pair_factors is None:
            raise InputError(f"bearing {self.designation}: no back-to-back/face-to-face factors in the catalogue row")
        return dataclasses.replace(
            self, designation=f"{self.designation}/{_SUFFIX[arrangement]}", C=PAIR_C * self.C, C0=PAIR_C0 * self.C0,
            Pu=None if self.Pu is None else PAIR_PU * self.Pu, arrangement=arrangement,
            unverified="; ".join(x for x in (self.unverified, self.pair_unverified) if x))

    # ------------------------------------------------------------------ loads and life
    def _active_factors(self) -> LoadFactors | None:
        if self.arrangement in ("back_to_back", "face_to_face"):
            return self.pair_factors
        return self.factors

    def _carried(self, Fr: QuantityLike, Fa: QuantityLike) -> tuple[float, float]:
        """(Fr, Fa) in N; :class:`ValidityError` for a load the bearing cannot take (a radial load on a thrust
        ball bearing, an axial load on a non-locating roller bearing), for the dynamic and the static load alike."""
        fr, fa = _forces(Fr, Fa)
        if self.kind == "thrust_ball" and fr > 0:
            raise ValidityError(f"thrust ball bearing {self.designation} takes no radial load (Fr = {fr:g} N): "
                                "carry it on a radial bearing")
        if self.kind != "thrust_ball" and self._active_factors() is None and fa > 0:
            raise ValidityError(f"{self.kind.replace('_', ' ')} bearing {self.designation} takes no axial load "
                                f"(Fa = {fa:g} N): non-locating design; locate the shaft on another bearing")
        return fr, fa

    def equivalent_load(self, Fr: QuantityLike, Fa: QuantityLike = "0 N") -> EquivalentLoad:
        """The maker's equivalent dynamic load P (see the module text) [1, 3]."""
        fr, fa = self._carried(Fr, Fa)
        if self.kind == "thrust_ball":
            return EquivalentLoad(P=Q(fa, "N"), X=0.0, Y=1.0, e=0.0, relative_axial_load=0.0)
        f = self._active_factors()
        if f is None:
            return EquivalentLoad(P=Q(fr, "N"), X=1.0, Y=0.0, e=math.inf, relative_axial_load=0.0)
        if fa == 0 or (fr > 0 and fa / fr <= f.e):
            return EquivalentLoad(P=Q(fr + f.Y1 * fa, "N"), X=1.0, Y=f.Y1, e=f.e, relative_axial_load=0.0)
        return EquivalentLoad(P=Q(f.X * fr + f.Y * fa, "N"), X=f.X, Y=f.Y, e=f.e, relative_axial_load=0.0)

    def static_load(self, Fr: QuantityLike, Fa: QuantityLike = "0 N") -> pint.Quantity:
        """P0 = max(X0·Fr + Y0·Fa, Fr); thrust ball P0 = Fa; pure radial P0 = Fr [2, 3]; :class:`ValidityError`
        for a load the bearing cannot take (as :meth:`equivalent_load`)."""
        fr, fa = self._carried(Fr, Fa)
        if self.kind == "thrust_ball":
            return Q(fa, "N")
        f = self._active_factors()
        if f is None:
            return Q(fr, "N")
        if self.arrangement in ("back_to_back", "face_to_face"):
            return Q(fr + f.Y0 * fa, "N")
        return Q(max(f.X0 * fr + f.Y0 * fa, fr), "N")

    def static_safety(self, Fr: QuantityLike, Fa: QuantityLike = "0 N") -> float:
        P0 = to_si(self.static_load(Fr, Fa), "force")
        return math.inf if P0 == 0 else to_si(self.C0, "force") / P0

    def rating_life(self, Fr: QuantityLike, Fa: QuantityLike = "0 N", reliability: float = 0.9) -> pint.Quantity:
        """L_n = a1·(C/P)^p in revolutions [1]."""
        from mechverify.components.bearings import basic_rating_life
        return reliability_factor(reliability) * basic_rating_life(self.C, self.equivalent_load(Fr, Fa).P,
                                                                   self.life_exponent)

    def rating_life_hours(self, Fr: QuantityLike, Fa: QuantityLike, speed: QuantityLike,
                          reliability: float = 0.9) -> pint.Quantity:
        return life_hours(self.rating_life(Fr, Fa, reliability), speed)

    def induced_axial_force(self, Fr: QuantityLike, rule: str = "iso") -> pint.Quantity:
        """F_i = induced·Fr (ISO/SKF: 0.5 Fr/Y tapered, R·Fr angular contact) or Timken's 0.47·Fr/K [3, 4]."""
        fr = to_si(Fr, "force", "Fr")
        if rule == "timken":
            if self.K is None:
                raise InputError(f"bearing {self.designation}: Timken's rule needs the thrust factor K (give K)")
            return Q(0.47 * fr / self.K, "N")
        if rule != "iso":
            raise UnknownNameError("induced-load rule", rule, ["iso", "timken"])
        if not self.induced > 0:
            raise InputError(f"bearing {self.designation}: no induced axial force factor (a {self.kind} bearing "
                             "does not induce one)")
        return Q(self.induced * fr, "N")

    def __repr__(self) -> str:
        return (f"<RollingBearing {self.designation} ({self.kind}) {fmt(self.d, 'mm')}x{fmt(self.D, 'mm')}"
                f"x{fmt(self.B, 'mm')} C={fmt(self.C, 'kN')} C0={fmt(self.C0, 'kN')}>")


def _forces(Fr: QuantityLike, Fa: QuantityLike) -> tuple[float, float]:
    fr, fa = to_si(Fr, "force", "Fr"), to_si(Fa, "force", "Fa")
    if fr < 0 or fa < 0:
        raise InputError(f"bearing loads must be >= 0 (Fr = {fr:g} N, Fa = {fa:g} N)")
    return fr, fa


# ---------------------------------------------------------------------------------------- catalogue
@cache
def _data() -> dict[str, Any]:
    return tomllib.loads(_DATA.read_text(encoding="utf-8"))


def _factors(row: dict, key: str) -> LoadFactors | None:
    t = row.get(key)
    return None if t is None else LoadFactors(**{k: float(v) for k, v in t.items()})


@cache
def _catalogue() -> dict[str, RollingBearing]:
    data = _data()
    refs = data["references"]
    out: dict[str, RollingBearing] = {}
    for row in data["bearing"]:
        b = RollingBearing(
            designation=row["designation"], kind=row["kind"], d=Q(row["d"], "mm"), D=Q(row["D"], "mm"),
            B=Q(row["B"], "mm"), C=Q(row["C"], "kN"), C0=Q(row["C0"], "kN"),
            limiting_speed=Q(row["limiting_speed"], "rpm"), reference_speed=Q(row["reference_speed"], "rpm"),
            factors=_factors(row, "factors"), pair_factors=_factors(row, "pair_factors"),
            Pu=Q(row["Pu"], "kN") if "Pu" in row else None, induced=float(row.get("induced", 0.0)),
            K=float(row["K"]) if "K" in row else None, locating=bool(row.get("locating", False)),
            source=refs[row["source"]],
            unverified="" if row.get("verified") is True else row.get(
                "verification", "catalogue row not checked against a published maker's table"),
            aliases=tuple(row.get("aliases", ())),
            pair_unverified="" if "pair_factors" not in row or row.get("pair_factors_verified") is True else row.get(
                "pair_verification", "pair factors not checked against a published maker's table"))
        for key in (b.designation, *b.aliases):
            out[_key(key)] = b
    return out


def _key(name: str) -> str:
    return re.sub(r"[\s\-/]", "", name.upper())


def rolling_bearing_names() -> list[str]:
    return sorted({b.designation for b in _catalogue().values()})


def rolling_bearing(name: str, arrangement: str = "single") -> RollingBearing:
    """A catalogue bearing of the other types: ``rolling_bearing("7206 BE")``, ``("30205")``, ``("51105")``,
    ``("NU 205 ECP")``; ``arrangement`` makes an angular contact bearing a matched pair."""
    if not isinstance(name, str):
        raise InputError(f"rolling bearing: expected a designation string, got {type(name).__name__}")
    b = _catalogue().get(_key(name))
    if b is None:
        raise UnknownNameError("rolling bearing", name, rolling_bearing_names())
    return b.paired(arrangement)


def rolling_bearing_catalogue(kind: str | None = None) -> list[RollingBearing]:
    """Every catalogue bearing once (optionally of one kind), in catalogue order."""
    if kind is not None and kind not in KINDS:
        raise UnknownNameError("bearing kind", kind, list(KINDS))
    rows = list({id(b): b for b in _catalogue().values()}.values())
    return [b for b in rows if kind is None or b.kind == kind]


def select_rolling_bearing(kind: str, Fr: QuantityLike, Fa: QuantityLike, speed: QuantityLike,
                           required_life: QuantityLike, *, required_s0: float = 1.0, reliability: float = 0.9,
                           arrangement: str = "single", min_bore: QuantityLike | None = None) -> list[RollingBearing]:
    """Catalogue bearings of ``kind`` that meet the rating life L_nh = a1 (C/P)^p/(60 n), the static safety s0 and
    the limiting speed for the loads, smallest first (outside diameter, then width): ``[0]`` is the selection.
    Bearings whose type cannot carry the load (radial on a thrust bearing, axial on NU/needle) are skipped."""
    req_h = to_si(required_life, "time", "required_life") / 3600
    n = abs(to_si(speed, "angular_velocity", "speed"))
    dmin = to_si(min_bore, "length", "min_bore") if min_bore is not None else 0.0
    out = []
    for b in rolling_bearing_catalogue(kind):
        if to_si(b.d, "length") < dmin - 1e-12:
            continue
        try:
            b = b.paired(arrangement)
            if n > to_si(b.limiting_speed, "angular_velocity") or b.static_safety(Fr, Fa) < required_s0:
                continue
            if life_hours(b.rating_life(Fr, Fa, reliability), speed).m_as("hour") >= req_h:
                out.append(b)
        except (ValidityError, InputError):
            continue
    return sorted(out, key=lambda b: (b.D.m_as("mm"), b.B.m_as("mm"), b.d.m_as("mm")))


# ------------------------------------------------------------------ two bearings adjusted against each other
@dataclass(frozen=True)
class AdjustedPairLoads:
    """Axial and equivalent loads of two bearings adjusted against each other (A loaded by Ka)."""

    Fi_A: pint.Quantity
    Fi_B: pint.Quantity
    Fa_A: pint.Quantity
    Fa_B: pint.Quantity
    P_A: pint.Quantity
    P_B: pint.Quantity
    case: str  # "A takes the thrust" or "B takes the thrust"


def adjusted_pair_axial_loads(Fi_A: QuantityLike, Fi_B: QuantityLike, Ka: QuantityLike) -> tuple[float, float, str]:
    """Axial loads (Fa_A, Fa_B) [N] of two bearings adjusted to zero clearance, the external axial force
    Ka >= 0 directed so that it loads bearing A ([3] calculating the axial load; [4] Sec. 11-9):
    F_iA <= F_iB + Ka -> (F_iB + Ka, F_iB); otherwise (F_iA, F_iA − Ka)."""
    fa, fb, ka = to_si(Fi_A, "force", "Fi_A"), to_si(Fi_B, "force", "Fi_B"), to_si(Ka, "force", "Ka")
    if fa < 0 or fb < 0 or ka < 0:
        raise InputError("induced forces and the external axial force must be >= 0 (give Ka toward bearing A)")
    if fa <= fb + ka:
        return fb + ka, fb, "A takes the thrust"
    return fa, fa - ka, "B takes the thrust"


def adjusted_pair_loads(A: RollingBearing, B: RollingBearing, Fr_A: QuantityLike, Fr_B: QuantityLike,
                        Ka: QuantityLike = "0 N", rule: str = "iso") -> AdjustedPairLoads:
    """Induced, axial and equivalent loads of bearings A and B adjusted against each other (Ka loads A).

    ``rule="iso"``: F_i from the rows' factors (tapered 0.5 Fr/Y, angular contact R·Fr), P from each
    row's X, Y and e [3]. ``rule="timken"``: F_i = 0.47 Fr/K and F_e = 0.4 Fr + K·Fa for the bearing that
    takes the thrust, F_e = F_r for the other; F_e >= F_r ([4] Eq. 11-19, [5]).
    """
    FiA, FiB = A.induced_axial_force(Fr_A, rule), B.induced_axial_force(Fr_B, rule)
    faA, faB, case = adjusted_pair_axial_loads(FiA, FiB, Ka)
    frA, frB = to_si(Fr_A, "force", "Fr_A"), to_si(Fr_B, "force", "Fr_B")
    if rule == "timken":
        assert A.K is not None and B.K is not None
        if case == "A takes the thrust":
            PA, PB = max(0.4 * frA + A.K * faA, frA), frB
        else:
            PA, PB = frA, max(0.4 * frB + B.K * faB, frB)
    else:
        PA = to_si(A.equivalent_load(Q(frA, "N"), Q(faA, "N")).P, "force")
        PB = to_si(B.equivalent_load(Q(frB, "N"), Q(faB, "N")).P, "force")
    return AdjustedPairLoads(Fi_A=FiA, Fi_B=FiB, Fa_A=Q(faA, "N"), Fa_B=Q(faB, "N"), P_A=Q(PA, "N"),
                             P_B=Q(PB, "N"), case=case)


__all__ = ["KINDS", "ARRANGEMENTS", "LoadFactors", "RollingBearing", "rolling_bearing", "rolling_bearing_names",
           "rolling_bearing_catalogue", "select_rolling_bearing",
           "AdjustedPairLoads", "adjusted_pair_axial_loads", "adjusted_pair_loads"]
