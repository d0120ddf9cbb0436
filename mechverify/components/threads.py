"""Thread geometry of power screws: ISO trapezoidal (Tr), Acme, square, generic lead screws, ball screws.

A :class:`Thread` holds the dimensions every power-screw formula needs: nominal (major) diameter
``d``, pitch ``P``, number of starts, lead ``l = starts * P``, flank angle (half the thread angle, in
the axial plane), pitch diameter ``d2``, minor diameter of the screw ``d3``, minor and major
diameters of the nut ``D1``/``D4`` and the flank engagement height ``H1``.

Build one from a designation with :func:`thread`::

    thread("Tr10x2")          # ISO 2904, single start
    thread("Tr16x8P4")        # lead 8 mm, pitch 4 mm -> 2 starts (also "Tr16x8(P4)")
    thread("1/2-10 ACME")     # ASME B1.5 general purpose; "1/2-0.1P-0.2L-ACME" for 2 starts

or with :func:`trapezoidal`, :func:`acme`, :func:`square`, :func:`generic` (catalogue screws known by
lead, starts and pitch diameter) and :func:`ball_screw`.

Basic dimensions of the trapezoidal thread (ISO 2904 / DIN 103-4)::

    H1 = 0.5 P,  h3 = H1 + ac,  d2 = D2 = d - 0.5 P,  d3 = d - 2 h3,  D1 = d - P,  D4 = d + 2 ac

with the crest clearance ``ac`` by pitch (0.15 mm for P = 1.5; 0.25 for 2..5; 0.5 for 6..12; 1 for 14..44).

References
----------
1. ISO 2902:1977, ISO metric trapezoidal screw threads - General plan.
2. ISO 2904:1977, ISO metric trapezoidal screw threads - Basic dimensions (= DIN 103-4).
3. ASME B1.5-1997, Acme Screw Threads.
4. R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill Education, 2015,
   Sec. 8-1 (thread profiles, preferred Acme pitches).
5. THK General Catalog, Ball Screw (efficiency with friction coefficient 0.003..0.01).
"""

from __future__ import annotations

import functools
import math
import re
import tomllib
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache, cached_property
from pathlib import Path
from typing import Any

import pint

from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.frozen import set_fields
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, as_quantity, fmt, to_si

_DATA = Path(__file__).parent / "data"
FORMS = ("trapezoidal", "acme", "square", "generic", "ball")
INCH = 0.0254


@dataclass(frozen=True)
class Thread:
    """Geometry of one power-screw thread. Lengths are quantities; ``starts`` an integer.

    ``flank_angle`` is half the thread angle measured in the axial plane (15 deg for Tr, 14.5 deg
    for Acme, 0 for square threads and for ball screws, whose efficiency formula has no flank term).
    ``H1`` is the radial height over which screw and nut flanks touch (None for ball screws).
    """

    designation: str
    form: str
    d: pint.Quantity
    pitch: pint.Quantity
    starts: int
    flank_angle: pint.Quantity
    d2: pint.Quantity
    d3: pint.Quantity
    D1: pint.Quantity | None = None
    D4: pint.Quantity | None = None
    H1: pint.Quantity | None = None
    left_hand: bool = False
    standard: str = ""
    source: str = ""
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        if self.form not in FORMS:
            raise UnknownNameError("thread form", self.form, FORMS)
        for name in ("d", "pitch", "d2", "d3", "D1", "D4", "H1"):
            v = getattr(self, name)
            if v is None:
                continue
            q = as_quantity(v, "length", f"{self.designation}.{name}")
            if q.magnitude <= 0:
                raise InputError(f"{self.designation}.{name}: must be positive, got {fmt(q)}")
            set_fields(self, **{name: q})
        fa = as_quantity(self.flank_angle, "angle", f"{self.designation}.flank_angle")
        if not (0 <= fa.m_as("deg") < 45):
            raise InputError(f"{self.designation}.flank_angle: must lie in [0, 45) deg, got {fmt(fa)}")
        set_fields(self, flank_angle=fa)
        if isinstance(self.starts, bool) or not isinstance(self.starts, int) or self.starts < 1:
            raise InputError(f"{self.designation}.starts: must be a whole number >= 1, got {self.starts!r}")
        d, d2, d3 = (to_si(getattr(self, n), "length") for n in ("d", "d2", "d3"))
        if not d3 < d2 <= d:
            raise InputError(f"{self.designation}: need d3 < d2 <= d, got d3 = {fmt(self.d3, 'mm')}, "
                             f"d2 = {fmt(self.d2, 'mm')}, d = {fmt(self.d, 'mm')}")
        set_fields(self, notes=tuple(self.notes))

    # ------------------------------------------------------------------ derived geometry
    # (cached_property: computed once per thread, mechverify.frozen; a study sample reads them many times)
    @cached_property
    def lead(self) -> pint.Quantity:
        """Axial advance per revolution ``l = starts * P`` [m]."""
        return (self.pitch * self.starts).to("mm")

    @cached_property
    def lead_angle(self) -> pint.Quantity:
        """Lead angle at the pitch diameter, ``lambda = atan(l / (pi d2))`` (Shigley 10th ed., Sec. 8-2)."""
        return Q(math.degrees(math.atan(to_si(self.lead, "length") / (math.pi * to_si(self.d2, "length")))), "deg")

    @cached_property
    def normal_flank_angle(self) -> pint.Quantity:
        """Flank angle in the plane normal to the thread, ``tan(alpha_n) = tan(alpha) cos(lambda)``."""
        a, lam = to_si(self.flank_angle, "angle"), to_si(self.lead_angle, "angle")
        return Q(math.degrees(math.atan(math.tan(a) * math.cos(lam))), "deg")

    @cached_property
    def minor_area(self) -> pint.Quantity:
        """Cross-section at the minor diameter, ``pi d3^2 / 4`` [m^2]."""
        return (math.pi * self.d3**2 / 4).to("mm**2")

    @cached_property
    def minor_second_moment(self) -> pint.Quantity:
        """Second moment of area at the minor diameter, ``pi d3^4 / 64`` [m^4]."""
        return (math.pi * self.d3**4 / 64).to("mm**4")

    def tooth_width(self, diameter: QuantityLike, part: str = "screw") -> pint.Quantity:
        """Axial width of one thread tooth at ``diameter`` [m].

        The tooth is ``P/2`` wide at the pitch diameter and widens by ``2 tan(alpha)`` per unit of
        radial depth towards its root: screw ``P/2 + (d2 - x) tan(alpha)`` (valid d3 <= x <= d),
        nut ``P/2 + (x - d2) tan(alpha)`` (valid D1 <= x <= D4). For the ISO trapezoidal thread
        this gives ``0.634 P + 0.536 ac`` at the screw root d3 and ``0.634 P`` at the nut's d.
        """
        if part not in ("screw", "nut"):
            raise UnknownNameError("thread part", part, ("screw", "nut"))
        x = to_si(diameter, "length", "diameter")
        d2, P = to_si(self.d2, "length"), to_si(self.pitch, "length")
        t = math.tan(to_si(self.flank_angle, "angle"))
        if part == "screw":
            lo, hi = to_si(self.d3, "length"), to_si(self.d, "length")
            w = P / 2 + (d2 - x) * t
        else:
            lo = to_si(self.D1 if self.D1 is not None else self.d3, "length")
            hi = to_si(self.D4 if self.D4 is not None else self.d, "length")
            w = P / 2 + (x - d2) * t
        if not lo * (1 - 1e-9) <= x <= hi * (1 + 1e-9):
            raise ValidityError(f"{self.designation}: the {part} tooth spans diameters "
                                f"{lo * 1e3:.4g}..{hi * 1e3:.4g} mm; asked for {x * 1e3:.4g} mm")
        return Q(w * 1e3, "mm")

    @property
    def nut_major_diameter(self) -> pint.Quantity:
        """Diameter at which the nut thread shears off (``D4``, or ``d`` if not known)."""
        return self.D4 if self.D4 is not None else self.d

    def __str__(self) -> str:
        return self.designation

    def __repr__(self) -> str:
        return (f"<Thread {self.designation} ({self.form}) d={fmt(self.d, 'mm')} P={fmt(self.pitch, 'mm')} "
                f"starts={self.starts} lead={fmt(self.lead, 'mm')} d2={fmt(self.d2, 'mm')} d3={fmt(self.d3, 'mm')}>")


# ---------------------------------------------------------------------- data
def _expand(src: str, refs: dict[str, str]) -> str:
    return refs.get(src, src)


@cache
def _trapezoidal_table() -> dict[str, Any]:
    with (_DATA / "threads_trapezoidal.toml").open("rb") as fh:
        data = tomllib.load(fh)
    refs = data["references"]
    prof = data["profile"]
    unit = prof.get("unit", "mm")
    pairs: dict[tuple[float, float], dict[str, Any]] = {}
    for d, pitches in data["sizes"].items():
        if d == "source":
            continue
        for i, p in enumerate(pitches):
            pairs[(float(d), float(p))] = {"source": _expand(data["sizes"]["source"], refs), "preferred": i == 0,
                                           "ac": None, "standard": "ISO 2902/2904"}
    for row in data.get("commercial", []):
        pairs[(float(row["d"]), float(row["pitch"]))] = {
            "source": _expand(row["source"], refs), "preferred": False, "ac": float(row["ac"]),
            "standard": "catalogue (not ISO 2902)"}
    clearance = [(float(r["pitch"][0]), float(r["pitch"][1]), float(r["ac"])) for r in prof["crest_clearance"]]
    return {"pairs": pairs, "clearance": clearance, "flank_angle": prof["flank_angle"], "unit": unit,
            "source": _expand(prof["source"], refs)}


@cache
def _acme_table() -> dict[str, Any]:
    with (_DATA / "threads_acme.toml").open("rb") as fh:
        data = tomllib.load(fh)
    refs = data["references"]
    rows = {}
    for r in data["size"]:
        rows[_parse_inches(r["d"])] = {"label": r["d"], "tpi": float(r["tpi"]), "preferred": bool(r.get("preferred"))}
    return {"rows": rows, "flank_angle": data["profile"]["flank_angle"],
            "source": _expand(data["profile"]["source"], refs), "shigley": refs["shigley"]}


def crest_clearance(pitch: QuantityLike) -> pint.Quantity:
    """ISO 2904 crest clearance ``ac`` for a trapezoidal pitch [m] (ValidityError outside the table)."""
    P = to_si(pitch, "length", "pitch") * 1e3
    for lo, hi, ac in _trapezoidal_table()["clearance"]:
        if lo - 1e-9 <= P <= hi + 1e-9:
            return Q(ac, "mm")
    raise ValidityError(f"ISO 2904 gives no crest clearance for pitch {P:g} mm (table: 1.5, 2..5, 6..12, 14..44 mm)")


def _num(x: float) -> str:
    return f"{x:g}"


def trapezoidal_designations() -> list[str]:
    """Single-start designations of every tabulated trapezoidal size (``"Tr8x1.5"``, ...)."""
    return [f"Tr{_num(d)}x{_num(p)}" for d, p in sorted(_trapezoidal_table()["pairs"])]


def acme_designations() -> list[str]:
    """Designations of every tabulated Acme size (``"1/2-10 ACME"``, ...)."""
    return [f"{r['label']}-{_num(r['tpi'])} ACME" for _, r in sorted(_acme_table()["rows"].items())]


def known_designations() -> list[str]:
    return trapezoidal_designations() + acme_designations()


# ---------------------------------------------------------------------- builders
def trapezoidal(d: QuantityLike, pitch: QuantityLike, starts: int = 1, left_hand: bool = False) -> Thread:
    """ISO metric trapezoidal thread ``Tr d x (starts*P) P P`` from its table (ISO 2902/2904).

    ``d`` and ``pitch`` must be a tabulated pair (ISO 2902 plus a few catalogue sizes); an
    unknown pair raises :class:`UnknownNameError` listing the nearest designations.
    """
    dm, Pm = to_si(d, "length", "d") * 1e3, to_si(pitch, "length", "pitch") * 1e3
    if isinstance(starts, bool) or not isinstance(starts, int) or starts < 1:
        raise InputError(f"starts: must be a whole number >= 1, got {starts!r}")
    tab = _trapezoidal_table()
    key = (round(dm, 6), round(Pm, 6))
    row = tab["pairs"].get(key)
    name = _tr_name(dm, Pm, starts, left_hand)
    if row is None:
        same_d = [f"Tr{_num(a)}x{_num(b)}" for a, b in sorted(tab["pairs"]) if a == key[0]]
        raise UnknownNameError("trapezoidal thread", name.replace("LH", ""), same_d or trapezoidal_designations())
    ac = row["ac"] if row["ac"] is not None else crest_clearance(Q(Pm, "mm")).m_as("mm")
    H1 = 0.5 * Pm
    notes = []
    if row["standard"].startswith("catalogue"):
        notes.append(f"Tr{_num(dm)}x{_num(Pm)} is not in ISO 2902; profile by the ISO 2904 formulas "
                     f"with ac = {ac:g} mm")
    return Thread(designation=name, form="trapezoidal", d=Q(dm, "mm"), pitch=Q(Pm, "mm"), starts=starts,
                  flank_angle=Q(tab["flank_angle"]), d2=Q(dm - 0.5 * Pm, "mm"), d3=Q(dm - 2 * (H1 + ac), "mm"),
                  D1=Q(dm - Pm, "mm"), D4=Q(dm + 2 * ac, "mm"), H1=Q(H1, "mm"), left_hand=left_hand,
                  standard=row["standard"], source=f"{tab['source']}; sizes: {row['source']}", notes=tuple(notes))


def _tr_name(d: float, P: float, starts: int, lh: bool) -> str:
    base = f"Tr{_num(d)}x{_num(P)}" if starts == 1 else f"Tr{_num(d)}x{_num(P * starts)}P{_num(P)}"
    return base + ("LH" if lh else "")


def acme(d: QuantityLike, tpi: float | None = None, *, pitch: QuantityLike | None = None, starts: int = 1,
         left_hand: bool = False) -> Thread:
    """General-purpose Acme thread (ASME B1.5) by nominal diameter and threads per inch (or ``pitch``).

    Basic dimensions (Shigley 10th ed., Sec. 8-1, Acme profile): depth ``P/2``, ``d2 = d - P/2``, ``d3 = d - P``.
    ``d`` must be a tabulated size with its standard pitch.
    """
    dq = as_quantity(d, "length", "d")
    din = dq.m_as("in")
    if (tpi is None) == (pitch is None):
        raise InputError("acme: give exactly one of tpi or pitch")
    P_in = 1.0 / float(tpi) if tpi is not None else as_quantity(pitch, "length", "pitch").m_as("in")
    if P_in <= 0:
        raise InputError("acme: pitch must be positive")
    if isinstance(starts, bool) or not isinstance(starts, int) or starts < 1:
        raise InputError(f"starts: must be a whole number >= 1, got {starts!r}")
    tab = _acme_table()
    row = next((r for k, r in tab["rows"].items() if abs(k - din) < 1e-6), None)
    label = row["label"] if row else f"{din:g}"
    name = f"{label}-{_num(round(1 / P_in, 4))} ACME" if starts == 1 else \
        f"{label}-{_num(round(P_in, 4))}P-{_num(round(P_in * starts, 4))}L-ACME"
    if row is None or abs(1.0 / row["tpi"] - P_in) > 1e-6:
        raise UnknownNameError("Acme thread", name, acme_designations())
    src = tab["source"] + ("; preferred pitch: " + tab["shigley"] if row["preferred"] else "")
    return Thread(designation=name + ("-LH" if left_hand else ""), form="acme", d=Q(din, "in"), pitch=Q(P_in, "in"),
                  starts=starts, flank_angle=Q(tab["flank_angle"]), d2=Q(din - P_in / 2, "in"),
                  d3=Q(din - P_in, "in"), D1=Q(din - P_in, "in"), D4=Q(din, "in"), H1=Q(P_in / 2, "in"),
                  left_hand=left_hand, standard="ASME B1.5", source=src,
                  notes=("basic dimensions; the design minor diameter is smaller by the root clearance",))


def square(d: QuantityLike, pitch: QuantityLike, starts: int = 1) -> Thread:
    """Square thread (Shigley 10th ed., Sec. 8-1): depth = width = ``P/2``, ``d2 = d - P/2``, ``d3 = d - P``."""
    dm, P = to_si(d, "length", "d") * 1e3, to_si(pitch, "length", "pitch") * 1e3
    if dm <= 0 or P <= 0 or P >= dm:
        raise InputError(f"square thread: need 0 < P < d, got d = {dm:g} mm, P = {P:g} mm")
    name = f"Sq{_num(dm)}x{_num(P)}" + (f" {starts}-start" if starts > 1 else "")
    return Thread(designation=name, form="square", d=Q(dm, "mm"), pitch=Q(P, "mm"), starts=starts,
                  flank_angle=Q(0.0, "deg"), d2=Q(dm - P / 2, "mm"), d3=Q(dm - P, "mm"), D1=Q(dm - P, "mm"),
                  D4=Q(dm, "mm"), H1=Q(P / 2, "mm"), standard="square",
                  source=ref("shigley10", "Sec. 8-1, square thread"))


def generic(lead: QuantityLike, starts: int, d2: QuantityLike, flank_angle: QuantityLike = "15 deg", *,
            d: QuantityLike | None = None, d3: QuantityLike | None = None,
            H1: QuantityLike | None = None, designation: str = "") -> Thread:
    """A catalogue lead screw known by lead, starts and pitch diameter (e.g. an 8 mm-lead 4-start Ø8).

    Missing dimensions follow the ISO 2904 proportions of the pitch ``P = lead/starts``:
    ``d = d2 + P/2``, ``d3 = d - P - 2 ac``, ``H1 = P/2`` (each such assumption is listed in ``notes``).
    """
    if isinstance(starts, bool) or not isinstance(starts, int) or starts < 1:
        raise InputError(f"starts: must be a whole number >= 1, got {starts!r}")
    l_mm = to_si(lead, "length", "lead") * 1e3
    d2_mm = to_si(d2, "length", "d2") * 1e3
    if l_mm <= 0 or d2_mm <= 0:
        raise InputError("generic thread: lead and d2 must be positive")
    P = l_mm / starts
    notes = []
    if d is None:
        d_mm = d2_mm + P / 2
        notes.append(f"major diameter d = d2 + P/2 = {d_mm:.4g} mm assumed (ISO 2904 proportions)")
    else:
        d_mm = to_si(d, "length", "d") * 1e3
    if d3 is None:
        try:
            ac = crest_clearance(Q(P, "mm")).m_as("mm")
        except ValidityError:
            ac = 0.25 if P < 6 else (0.5 if P <= 12 else 1.0)
        d3_mm = d_mm - P - 2 * ac
        notes.append(f"minor diameter d3 = d - P - 2ac = {d3_mm:.4g} mm assumed (ISO 2904 proportions, ac = {ac:g} mm)")
    else:
        d3_mm = to_si(d3, "length", "d3") * 1e3
    if H1 is None:
        H1_mm = P / 2
        notes.append(f"flank engagement H1 = P/2 = {H1_mm:.4g} mm assumed")
    else:
        H1_mm = to_si(H1, "length", "H1") * 1e3
    name = designation or f"lead {l_mm:g} mm, {starts}-start, d2 {d2_mm:g} mm"
    return Thread(designation=name, form="generic", d=Q(d_mm, "mm"), pitch=Q(P, "mm"), starts=starts,
                  flank_angle=as_quantity(flank_angle, "angle", "flank_angle"), d2=Q(d2_mm, "mm"), d3=Q(d3_mm, "mm"),
                  H1=Q(H1_mm, "mm"), standard="catalogue", source="user data", notes=tuple(notes))


def ball_screw(d0: QuantityLike, lead: QuantityLike, root_diameter: QuantityLike, starts: int = 1,
               designation: str = "") -> Thread:
    """Ball screw: nominal (ball-circle) diameter ``d0``, lead, root (minor) diameter from the catalogue.

    The flank angle is zero: the efficiency of a ball screw is ``(1 - mu tan(lambda)) / (1 + mu/tan(lambda))``
    (THK General Catalog), the square-thread formula with the rolling friction coefficient
    (0.003..0.01, see :func:`mechverify.components.power_screw.ball_nut`).
    """
    d0_mm = to_si(d0, "length", "d0") * 1e3
    l_mm = to_si(lead, "length", "lead") * 1e3
    dr = to_si(root_diameter, "length", "root_diameter") * 1e3
    if min(d0_mm, l_mm, dr) <= 0:
        raise InputError("ball screw: d0, lead and root diameter must be positive")
    name = designation or f"ball screw {d0_mm:g}x{l_mm:g}"
    return Thread(designation=name, form="ball", d=Q(d0_mm, "mm"), pitch=Q(l_mm / starts, "mm"), starts=starts,
                  flank_angle=Q(0.0, "deg"), d2=Q(d0_mm, "mm"), d3=Q(dr, "mm"), standard="catalogue",
                  source="THK General Catalog, Ball Screw")


# ---------------------------------------------------------------------- designations
_NUM = r"\d+(?:[.,]\d+)?"
_TR = re.compile(rf"^\s*tr\s*(?P<d>{_NUM})\s*[x×*]\s*(?P<l>{_NUM})\s*(?:\(?\s*p\s*(?P<p>{_NUM})\s*\)?)?"
                 rf"\s*(?:-?\s*(?P<lh>lh))?\s*(?:-\s*\d+[a-z]+)?\s*$", re.IGNORECASE)
_INCH = r"(?:\d+(?:\.\d+)?(?:[\s-]+\d+/\d+)?|\d+/\d+|\.\d+)"
_ACME = re.compile(rf"^\s*(?P<d>{_INCH})\s*-\s*(?:(?P<p>\d*\.\d+)\s*P\s*-\s*(?P<l>\d*\.\d+)\s*L|(?P<tpi>{_NUM}))"
                   rf"\s*-?\s*acme(?:\s*-\s*\d+[gcn])?(?:\s*-?\s*(?P<lh>lh))?\s*$", re.IGNORECASE)


def _parse_inches(text: str) -> float:
    t = text.strip().replace(",", ".")
    parts = re.split(r"[\s-]+", t)
    try:
        return float(sum(Fraction(p) for p in parts if p))
    except (ValueError, ZeroDivisionError):
        raise InputError(f"cannot read {text!r} as a size in inches") from None


def thread(designation: str | Thread) -> Thread:
    """A thread from its designation: ``"Tr10x2"``, ``"Tr16x8P4"``, ``"Tr16x8(P4)LH"``, ``"1/2-10 ACME"``,
    ``"1/2-0.1P-0.2L-ACME"``. A :class:`Thread` passes through.

    Unknown designations raise :class:`UnknownNameError` with the closest known ones. One :class:`Thread` per
    designation (it is immutable; its derived geometry is then computed once, not per design or study sample).
    """
    if isinstance(designation, Thread):
        return designation
    if not isinstance(designation, str):
        raise InputError(f"thread: expected a designation string, got {type(designation).__name__}")
    return _thread(designation)


@functools.lru_cache(maxsize=512)
def _thread(designation: str) -> Thread:
    """:func:`thread` of a designation string (errors are raised each time, not cached)."""
    m = _TR.match(designation)
    if m:
        d = float(m["d"].replace(",", "."))
        lead = float(m["l"].replace(",", "."))
        P = float(m["p"].replace(",", ".")) if m["p"] else lead
        starts = lead / P
        if P <= 0 or abs(starts - round(starts)) > 1e-9 or round(starts) < 1:
            raise InputError(f"thread {designation!r}: the lead {lead:g} mm must be a whole multiple "
                             f"of the pitch {P:g} mm")
        return trapezoidal(Q(d, "mm"), Q(P, "mm"), int(round(starts)), left_hand=bool(m["lh"]))
    m = _ACME.match(designation)
    if m:
        d_in = _parse_inches(m["d"])
        if m["tpi"]:
            return acme(Q(d_in, "in"), float(m["tpi"].replace(",", ".")), left_hand=bool(m["lh"]))
        P, lead = float(m["p"]), float(m["l"])
        starts = lead / P
        if abs(starts - round(starts)) > 1e-6 or round(starts) < 1:
            raise InputError(f"thread {designation!r}: the lead {lead:g} in must be a whole multiple "
                             f"of the pitch {P:g} in")
        return acme(Q(d_in, "in"), pitch=Q(P, "in"), starts=int(round(starts)), left_hand=bool(m["lh"]))
    raise UnknownNameError("thread", designation, known_designations())


__all__ = ["Thread", "FORMS", "thread", "trapezoidal", "acme", "square", "generic", "ball_screw", "crest_clearance",
           "trapezoidal_designations", "acme_designations", "known_designations"]
