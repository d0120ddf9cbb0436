"""One number formatter for report tables, figures, Markdown and the console.

``quantity(q)`` picks the display unit from the quantity's *kind* (its dimensionality), scales it into
engineering notation with an SI prefix (exponent a multiple of 3, mantissa 1 … 999) and rounds to the
significant digits of that kind. Unit symbols are the conventional ones: ``N·m``, ``kg·m²``, ``rpm``,
``MPa``; no ``1.35e+04 N`` and no ``g*cm^2``.

A unit the design file used (``kgf*cm``) is kept: pass it as ``unit=`` and the value is shown in that
unit, with the same significant-digit rule (no prefix change).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import Any

import pint

from mechverify.units import Q, Quantity, rate_to, ureg

# kind: (dimensionality as a unit string, base unit for display, prefixable?, significant digits)
# Order matters only for readability; kinds are matched by dimensionality.
_KINDS: list[tuple[str, str, str, bool, int]] = [
    ("force", "N", "N", True, 3),
    ("torque", "N*m", "N·m", True, 3),
    ("stress", "Pa", "Pa", True, 3),
    ("length", "m", "m", False, 3),  # lengths: mm below 10 m (engineering drawings use mm), m, km from 10 km
    ("mass", "kg", "kg", False, 3),
    ("inertia", "kg*m**2", "kg·m²", False, 3),
    ("speed", "rpm", "rpm", False, 3),  # shares its dimension with frequency: rotational speed wins
    ("velocity", "m/s", "m/s", False, 3),
    ("power", "W", "W", True, 3),
    ("energy", "J", "J", True, 3),
    ("time", "s", "s", False, 3),
    ("stiffness", "N/m", "N/m", True, 3),
    ("area", "m**2", "m²", False, 3),
    ("voltage", "V", "V", True, 3),
    ("current", "A", "A", True, 3),
    ("temperature", "K", "K", False, 3),
    ("frequency", "Hz", "Hz", True, 3),
    ("pv", "MPa*m/s", "MPa·m/s", False, 3),  # plain-bearing and nut pv rating
]

_FREQUENCY = next(k for k in _KINDS if k[0] == "frequency")
_PER_TIME = ureg.get_dimensionality("1/[time]")
_PREFIX = {-12: "p", -9: "n", -6: "µ", -3: "m", 0: "", 3: "k", 6: "M", 9: "G", 12: "T"}
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _dims() -> dict[Any, tuple[str, str, str, bool, int]]:
    global _DIMS_CACHE
    if _DIMS_CACHE is None:
        cache: dict[Any, tuple[str, str, str, bool, int]] = {}
        for k in _KINDS:  # the first kind of a dimensionality wins: torque before energy, rpm before Hz
            cache.setdefault(Q(1, k[1]).dimensionality, k)
        _DIMS_CACHE = cache
    return _DIMS_CACHE


_DIMS_CACHE: dict[Any, tuple[str, str, str, bool, int]] | None = None


def number(x: float, digits: int = 3) -> str:
    """A plain number to ``digits`` significant digits without exponent for 1e-3 ≤ |x| < 1e6,
    else in engineering form ``12.3×10⁶``. ``inf`` is ``∞``, NaN is ``n/a``."""
    x = float(x)
    if math.isnan(x):
        return "n/a"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    if x == 0:
        return "0"
    x = float(f"{x:.{digits}g}")  # round to significant digits first: 999.96 -> 1000
    e = math.floor(math.log10(abs(x)))
    if -3 <= e < 6:
        decimals = max(0, digits - 1 - e)
        text = f"{round(x, decimals):.{decimals}f}"
        if "." in text and e >= digits - 1:
            text = text.split(".")[0]
        return text.replace("-", "−")
    e3 = 3 * math.floor(e / 3)
    return f"{number(x / 10 ** e3, digits)}×10{str(e3).translate(_SUPERSCRIPT)}"


def _engineering(m: float, digits: int) -> tuple[str, int]:
    """(mantissa text, exponent multiple of 3) with 1 ≤ |mantissa| < 1000."""
    if m == 0 or not math.isfinite(m):
        return number(m, digits), 0
    e3 = 3 * math.floor(math.log10(abs(m)) / 3)
    mant = m / 10 ** e3
    text = number(mant, digits)
    if abs(float(text.replace("−", "-"))) >= 1000:  # 999.7 rounds to 1000
        e3 += 3
        text = number(m / 10 ** e3, digits)
    return text, e3


def unit_symbol(u: str | pint.Unit) -> str:
    """``N*m`` → ``N·m``, ``kg*m**2`` → ``kg·m²``, ``revolution/minute`` → ``rpm``, ``um`` → ``µm``."""
    text = f"{(Q(1, u).units if isinstance(u, str) else u):~P}"
    return "rpm" if text in ("turn/min", "rpm", "1/min") else text.replace(" ", "")


_ANGLE_UNITS = {"degree", "radian", "arcminute", "arcsecond", "turn", "revolution", "gradian"}


def is_temperature_difference(q: Any) -> bool:
    """True for a temperature difference: a quantity in ``delta_degC``/``delta_degF`` (pint's difference units).
    A value in plain kelvin stays an absolute temperature (shown in °C); give a rise as ``Q(40, "delta_degC")``."""
    return isinstance(q, Quantity) and any(str(u).startswith("delta_") for u in q.units._units)


def quantity(q: Any, unit: str | None = None, digits: int | None = None) -> str:
    """A quantity for people: kind-chosen unit, SI prefix, significant digits by kind.

    ``quantity(Q(13500, "N")) == "13.5 kN"``; ``quantity(Q(82, "g*cm**2")) == "82.0 g·cm²"`` (small
    inertias as on motor data sheets, larger ones in ``kg·m²``). ``unit`` keeps a unit the
    design file used (shown in that unit, no prefix change).
    """
    if not isinstance(q, Quantity):
        return number(q, digits or 4) if isinstance(q, int | float) and not isinstance(q, bool) else str(q)
    if q.ndim if hasattr(q, "ndim") else False:
        return ", ".join(quantity(x, unit, digits) for x in q)
    if unit:
        v = rate_to(q, unit).m_as(unit) if q.dimensionality == _PER_TIME else q.m_as(unit)  # rpm <-> Hz: 60
        return f"{number(float(v), digits or 3)} {unit_symbol(unit)}"
    if q.dimensionless:
        if _ANGLE_UNITS & set(q.units._units):  # an angle: degrees, never its value in radians
            return f"{number(float(q.m_as('deg')), digits or 3)}°"
        return number(float(q.m_as("")), digits or 3)
    kind = _dims().get(q.dimensionality)
    if kind is None:  # an uncommon kind (pv, N/mm², ...): in the units the check gave it
        return f"{number(float(q.magnitude), digits or 3)} {unit_symbol(q.units)}"
    if kind[0] == "speed" and "hertz" in q.units._units:  # a frequency the check gave in Hz (natural frequencies,
        kind = _FREQUENCY  # excitation): Hz, as structures are read; rpm stays for speeds and critical speeds
    name, base, symbol, prefixable, d = kind
    d = digits or d
    m = float(q.m_as(base))
    if name == "length":
        mm = m * 1e3
        if 0 < abs(mm) < 1e-5:  # a few nm (a stiff solid under a small load): 1.98 nm, not 0.00198 µm
            return f"{number(mm * 1e6, d)} nm"
        if 0 < abs(mm) < 1e-2:  # a few µm: 0.74 µm, not 740×10⁻⁶ mm
            return f"{number(mm * 1e3, d)} µm"
        if abs(mm) < 1e4 or not math.isfinite(mm):
            return f"{number(mm, d)} mm"
        if abs(m) >= 1e4:  # travel lives, rating distances: 50 km, not 50000 m or 5.00×10⁶ m
            return f"{number(m / 1e3, d)} km"
        return f"{number(m, d)} m"
    if name == "time":
        if abs(m) >= 3600 * 10:
            return f"{number(m / 3600, d)} h"
        if abs(m) < 1 and m != 0:
            mant, e3 = _engineering(m, d)
            return f"{mant} {_PREFIX.get(e3, '')}s" if e3 in _PREFIX else f"{number(m, d)} s"
        return f"{number(m, d)} s"
    if name == "stress":  # moduli in GPa, stresses in MPa, small pressures in kPa (55.9 kPa, not 55900 Pa) and Pa
        if abs(m) >= 1e10:
            return f"{number(m / 1e9, d)} GPa"
        if abs(m) >= 1e5 or m == 0:
            return f"{number(m / 1e6, d)} MPa"
        return f"{number(m / 1e3, d)} kPa" if abs(m) >= 1e3 else f"{number(m, d)} Pa"
    if name == "area" and abs(m) < 1:
        return f"{number(m * 1e6, d)} mm²"
    if name == "temperature":
        if is_temperature_difference(q):  # a rise or a difference: kelvin (= Δ°C), never an absolute °C value
            return f"{number(m, d)} K"
        return f"{number(float(q.m_as('degC')), d)} °C"
    if name == "inertia" and 0 < abs(m) < 1e-3:  # motor and gear data sheets: g·cm²
        return f"{number(m * 1e7, d)} g·cm²"
    if name == "mass" and 0 < abs(m) < 1:
        return f"{number(m * 1e3, d)} g"
    if not prefixable:
        return f"{number(m, d)} {symbol}"
    mant, e3 = _engineering(m, d)
    if e3 not in _PREFIX:
        return f"{number(m, d)} {symbol}"
    return f"{mant} {_PREFIX[e3]}{symbol}"


_QTY_TEXT = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*([^\d\s].*?)\s*$")
_PREFIXES = ("p", "n", "µ", "u", "m", "c", "k", "M", "G", "T")


@lru_cache(maxsize=512)
def _user_unit(text: str) -> tuple[Any, str] | None:
    """(dimensionality, unit) of a unit text the design file wrote, or ``None`` for one that needs no second
    column: unknown, dimensionless, a temperature (offset units) or the SI unit of its kind with any prefix
    (``kN`` beside ``N``, ``mm/s`` beside ``m/s``)."""
    try:
        q = Q(1, text)
    except Exception:  # any unit pint does not know is simply not offered
        return None
    if q.dimensionless or not q._is_multiplicative:
        return None
    kind = _dims().get(q.dimensionality)
    if kind is not None and kind[0] == "temperature":
        return None
    sym = unit_symbol(q.units)
    if kind is not None:
        bases = {kind[2], unit_symbol(kind[1]), "g" if kind[0] == "mass" else kind[2], "h" if kind[0] == "time" else ""}
        if sym in bases or (len(sym) > 1 and sym[0] in _PREFIXES and sym[1:] in bases):
            return None
        if kind[0] == "stress" and sym in ("N/mm²", "MPa", "GPa"):
            return None
    return q.dimensionality, text


def design_units(raw: Any, limit: int = 100_000) -> dict[Any, str]:
    """The units a design file wrote, by kind: every ``"<number> <unit>"`` string in ``raw`` (the parsed TOML),
    the first unit of each dimensionality that is not the report's own (``kgf*cm`` for torque, ``lbf``,
    ``in``); at most ``limit`` strings are read (a huge generated file)."""
    out: dict[Any, str] = {}
    stack, seen = [raw], 0
    while stack and seen < limit:
        v = stack.pop()
        if isinstance(v, dict):
            stack.extend(reversed(list(v.values())))
        elif isinstance(v, list | tuple):
            stack.extend(reversed(list(v)))
        elif isinstance(v, str):
            seen += 1
            m = _QTY_TEXT.match(v)
            if m:
                hit = _user_unit(m.group(1))
                if hit is not None:
                    out.setdefault(hit[0], hit[1])
    return out


def quantity_in(q: Any, units: dict[Any, str] | None) -> str:
    """:func:`quantity`, followed by the same value in the design file's own unit of that kind when it wrote one
    (``2.94 N·m (30.0 kgf·cm)``)."""
    text = quantity(q)
    if not units or not isinstance(q, Quantity) or (hasattr(q, "ndim") and q.ndim):
        return text
    unit = units.get(q.dimensionality)
    if unit is None or text.endswith(" " + unit_symbol(unit)):
        return text
    return f"{text} ({quantity(q, unit=unit)})"


__all__ = ["number", "quantity", "unit_symbol", "design_units", "quantity_in", "is_temperature_difference"]
