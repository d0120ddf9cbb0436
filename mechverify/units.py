"""One pint registry for the whole package, and the helpers that guard every public function.

Public functions take pint quantities (or strings such as ``"350 N"``) and return quantities of
this registry. Inside, numbers are plain SI floats: :func:`to_si` converts at the edge, and
:func:`si_function` wraps a formula written in SI floats so that it takes and returns quantities.

Dimension names accepted by the helpers are the keys of :data:`DIMENSIONS` (``"length"``,
``"force"``, ``"pressure"``, ``"torque"``, ...); each maps to its SI unit.
"""

from __future__ import annotations

import functools
import inspect
import math
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeAlias

import numpy as np
import pint

from mechverify import pint_cache as _pint_cache
from mechverify.errors import InputError, UnitError


def cache_folder(name: str) -> Path | None:
    """A writable folder ``name`` under mechverify's cache: ``$MECHVERIFY_CACHE_DIR`` or the user cache dir.

    Holds what is costly to rebuild at every start: pint's parsed definitions (building the registry
    from pint's text definitions takes ~0.2 s, from the cache ~0.04 s: docs/performance.md) and the
    index of design-file component types. ``MECHVERIFY_CACHE_DIR=off`` disables it (None); an
    unwritable folder is skipped (None).
    """
    root = os.environ.get("MECHVERIFY_CACHE_DIR", "")
    if root.lower() in ("off", "none", "0"):
        return None
    try:
        if not root:
            import platformdirs  # a dependency of pint

            root = str(platformdirs.user_cache_path("mechverify", appauthor=False))
        folder = Path(root) / name
        folder.mkdir(parents=True, exist_ok=True)
        return folder if os.access(folder, os.W_OK) else None
    except (OSError, ImportError):
        return None


def _cache_folder() -> Path | None:
    """Where pint keeps its parsed definitions (see :func:`cache_folder`)."""
    return cache_folder(f"pint-{pint.__version__}")


def _make_registry() -> pint.UnitRegistry:
    folder = _cache_folder()
    if folder is not None:
        try:
            return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=folder)
        except Exception:  # a damaged cache file: build from the text definitions instead
            pass
    return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


ureg = _make_registry()
ureg.formatter.default_format = "~P"
ureg.formatter.default_sort_func = None  # keep units as written: N·m, not m·N
Quantity = ureg.Quantity
#: What public functions accept where a physical quantity is expected: a quantity or a string ("350 N").
QuantityLike: TypeAlias = pint.Quantity | str

# Units met in datasheets that pint lacks or names differently.
# pint already has kgf, gf, ozf (force_ounce), lbf, ksi, rpm; Mpsi (spring-wire tables) it lacks.
ureg.define("mega_psi = 1e6 * psi = Mpsi")
ureg.define("@alias turn = rev")  # "5000 rev": revolutions (a count of turns, i.e. an angle)
pint.set_application_registry(ureg)
_pint_cache.install(ureg)  # parsed unit strings and conversion factors cached (issue 19; mechverify/pint_cache.py)

#: Dimension name -> (pint dimensionality, SI unit used inside the package).
DIMENSIONS: dict[str, tuple[str, str]] = {
    "dimensionless": ("", "dimensionless"),
    "length": ("[length]", "m"),
    "area": ("[length]**2", "m**2"),
    "volume": ("[length]**3", "m**3"),
    "second_moment": ("[length]**4", "m**4"),
    "mass": ("[mass]", "kg"),
    "time": ("[time]", "s"),
    "force": ("[force]", "N"),
    "force_per_length": ("[force]/[length]", "N/m"),  # spring rate, line load
    "pressure": ("[pressure]", "Pa"),  # also stress, modulus
    "torque": ("[force]*[length]", "N*m"),  # also moment, energy
    "energy": ("[energy]", "J"),
    "power": ("[power]", "W"),
    "velocity": ("[velocity]", "m/s"),
    "acceleration": ("[acceleration]", "m/s**2"),
    "angle": ("", "rad"),
    "angular_velocity": ("1/[time]", "rad/s"),
    "angular_acceleration": ("1/[time]**2", "rad/s**2"),
    "frequency": ("1/[time]", "Hz"),
    "density": ("[mass]/[length]**3", "kg/m**3"),
    "inertia": ("[mass]*[length]**2", "kg*m**2"),
    "torsional_stiffness": ("[force]*[length]", "N*m/rad"),
    "pv": ("[pressure]*[velocity]", "Pa*m/s"),
    "current": ("[current]", "A"),
    "voltage": ("[electric_potential]", "V"),
    "resistance": ("[resistance]", "ohm"),
    "inductance": ("[inductance]", "H"),
    "torque_constant": ("[force]*[length]/[current]", "N*m/A"),
    "speed_constant": ("1/[time]/[electric_potential]", "rad/s/V"),
    "thermal_resistance": ("[temperature]/[power]", "K/W"),
    "temperature": ("[temperature]", "K"),
    "viscous_damping": ("[force]*[length]*[time]", "N*m*s/rad"),
}

#: Physically meaningful magnitudes (SI, absolute value; zero is always allowed): outside them a value
#: is a mistake (a unit prefix or an exponent typed wrongly) and an :class:`InputError`, before it can
#: overflow or divide by zero in a formula. The upper bounds are generous physical limits (far above a
#: crane); they apply to every value. The lower bound applies to values given as text (design files,
#: ``"350 N"``) and only stops magnitudes that would underflow in a formula (``"1e-300 mm"``): tiny values
#: such as a coordinate computed as 6e-18 m (a rounded zero) stay valid.
BOUNDS: dict[str, tuple[float, float]] = {
    "dimensionless": (0.0, 1e30), "length": (1e-30, 1e7), "area": (1e-40, 1e14), "volume": (1e-50, 1e21),
    "second_moment": (1e-60, 1e28), "mass": (1e-30, 1e9), "time": (1e-30, 1e13), "force": (1e-30, 1e12),
    "force_per_length": (1e-30, 1e15), "pressure": (1e-30, 1e13), "torque": (1e-30, 1e12),
    "energy": (1e-30, 1e15), "power": (1e-30, 1e12), "velocity": (1e-30, 1e6), "acceleration": (1e-30, 1e9),
    "angle": (1e-30, 1e9), "angular_velocity": (1e-30, 1e7), "angular_acceleration": (1e-30, 1e10),
    "frequency": (1e-30, 1e12), "density": (1e-30, 1e5), "inertia": (1e-40, 1e9),
    "torsional_stiffness": (1e-30, 1e12), "pv": (1e-30, 1e12), "current": (1e-30, 1e6), "voltage": (1e-30, 1e7),
    "resistance": (1e-30, 1e12), "inductance": (1e-30, 1e3), "torque_constant": (1e-30, 1e4),
    "speed_constant": (1e-30, 1e7), "thermal_resistance": (1e-30, 1e6), "temperature": (1e-30, 1e5),
    "viscous_damping": (1e-30, 1e9),
}

#: Largest magnitudes plausible in a small machine (SI): a value given as text above them is accepted with a
#: :class:`PlausibilityWarning` ("300 km" for a screw length is more likely a wrong prefix than a design).
PLAUSIBLE: dict[str, float] = {"length": 1e3, "force": 1e8, "mass": 1e5, "velocity": 1e3, "pressure": 1e12,
                               "angular_velocity": 1e5}


class PlausibilityWarning(UserWarning):
    """A value within the physical bounds but implausible for a small machine (probably a wrong unit)."""


def _check_bounds(q: Any, dim: str, name: str, from_text: bool, factor: float | None = None) -> None:
    lo, hi = BOUNDS[dim]
    m = q.magnitude
    if factor is not None and isinstance(m, float | int) and not isinstance(m, bool):
        # the common case, a scalar in a multiplicative unit: plain floats (no pint conversion, no arrays)
        try:
            mag = abs(float(m) * factor)
        except OverflowError:
            mag = float("inf")
        if math.isfinite(mag) and mag <= hi and not (from_text and 0 < mag < lo) and not (
                from_text and dim in PLAUSIBLE and mag > PLAUSIBLE[dim]):
            return
    try:
        mag = np.abs(np.asarray(q.to(_unit(DIMENSIONS[dim][1])).magnitude, dtype=float))
    except (OverflowError, ZeroDivisionError, FloatingPointError):
        raise InputError(f"{name}: {_describe(q)} is outside any physically meaningful range") from None
    if not np.all(np.isfinite(mag)) or np.any(mag > hi) or (from_text and np.any((mag > 0) & (mag < lo))):
        raise InputError(f"{name}: {_describe(q)} is outside the physically meaningful range of "
                         f"{_ARTICLE[dim]} ({lo:g} to {hi:g} {DIMENSIONS[dim][1]} in magnitude, or zero); "
                         "check the unit prefix and the exponent")
    if from_text and dim in PLAUSIBLE and np.any(mag > PLAUSIBLE[dim]):
        import warnings

        warnings.warn(f"{name}: {_describe(q)} is implausible for {_ARTICLE[dim]} in a small machine "
                      f"(expected at most {PLAUSIBLE[dim]:g} {DIMENSIONS[dim][1]}); is the unit right?",
                      PlausibilityWarning, stacklevel=4)


@functools.lru_cache(maxsize=4096)
def _unit_info(units: Any, dim: str) -> tuple[bool, bool, float | None]:
    """For a pint units container and a dimension name: (dimension matches, unitless, SI factor).

    The factor is the multiplier to the SI unit of ``dim`` (the same one pint applies in ``.to()``),
    or None for units with an offset (degC) or a non-matching dimension. Cached: a design file uses a few
    dozen distinct units, and pint's dimension analysis and conversion cost ~50 us per call.
    """
    q = Quantity(1.0, units)
    if not _dimension_matches(q, dim):
        return False, q.unitless, None
    si = _unit(DIMENSIONS[dim][1])
    try:
        one, two = q.to(si).magnitude, Quantity(2.0, units).to(si).magnitude
        zero = Quantity(0.0, units).to(si).magnitude
    except Exception:  # offset units refuse some arithmetic; take pint's slow path
        return True, q.unitless, None
    factor = float(one) if (zero == 0.0 and two == 2.0 * one) else None
    return True, q.unitless, factor


# Readable names of dimensions for error messages ("expected a length").
_ARTICLE = {name: ("an " if name[0] in "aeiou" else "a ") + name.replace("_", " ") for name in DIMENSIONS}


def Q(value: Any, unit: str | None = None) -> pint.Quantity:
    """Make a quantity: ``Q("10 mm")``, ``Q(10, "mm")``, ``Q(np.array([1, 2]), "N")``."""
    if unit is None:
        if isinstance(value, Quantity):
            return value
        if isinstance(value, str):
            return _parse(value, "value")
        return Quantity(value, "dimensionless")
    return Quantity(value, _unit(unit) if isinstance(unit, str) else unit)


@functools.lru_cache(maxsize=1024)
def _unit(text: str) -> pint.Unit:
    """A unit string parsed once (pint parses the string on every ``Quantity(value, "mm")`` and ``.to("m")``)."""
    return ureg.Unit(text)


def _parse(text: str, name: str) -> pint.Quantity:
    try:
        magnitude, units = _parse_cached(text.strip())
    except Exception as exc:  # pint raises several unrelated types for bad strings
        raise UnitError(f"{name}: cannot read {text!r} as a quantity ({exc})") from None
    return Quantity(magnitude, units)  # a new object each time: callers may modify it


#: ``"<number> <unit>"`` with a plain unit text (names, ``*``, ``/``, ``^`` or ``**`` powers): what a study's drawn
#: values look like (``"14.751431137084994 kg"``, a new string every sample)
_NUMBER_UNIT = re.compile(r"([-+]?(?:\d+\.?\d*|\.\d+))([eE][-+]?\d+)?[ \t]+([A-Za-z_µ][A-Za-z_µ0-9]*"
                          r"(?:[ \t]*(?:\*\*|\^|[*/])[ \t]*[A-Za-z_µ0-9]+)*)")
_OFFSET_TEXT = ("deg", "celsius", "fahrenheit", "rankine", "reaumur")


@functools.lru_cache(maxsize=4096)
def _parse_cached(text: str) -> tuple[Any, Any]:
    """``"350 N"`` -> (350, <Unit N>), parsed once per distinct string (design files repeat them). A number and a
    plain unit text take the number as pint's tokenizer does (an int without a point or exponent, else a float)
    and the unit parsed once per unit text (issue 19: a study's drawn values are new strings every sample; pint's
    full parse of each cost ~0.2 ms); tests/test_units.py compares this with pint's parse."""
    m = _NUMBER_UNIT.fullmatch(text)
    if m is not None and not any(k in m.group(3).lower() for k in _OFFSET_TEXT):
        num, exp = m.group(1), m.group(2)
        u = m.group(3)  # pint divides by a unit: an int over one becomes a float
        return (float(num + exp) if exp else float(num) if "." in num or "/" in u else int(num)), _unit(u)
    q = ureg.Quantity(text)
    if not isinstance(q, Quantity):  # a bare number in a string: "12"
        return q, ureg.dimensionless
    return q.magnitude, q.units


def _describe(value: Any) -> str:
    if isinstance(value, Quantity):
        return f"{value:~P}" if np.ndim(value.magnitude) == 0 else f"an array in {value.units:~P}"
    return repr(value)


#: (units container, dimension name) -> (SI factor, upper bound of the dimension): the units a quantity (not text)
#: has already passed :func:`as_quantity` with, so that the next float magnitude in them only needs its bound
#: checked (issue 19: ~20 000 calls per Monte Carlo sample of the lift; the checks are those of the full path).
_CHECKED: dict[tuple[Any, str], tuple[float, float]] = {}
_EXACT = 2**53  # an int magnitude below it converts to float exactly (and never overflows)


def as_quantity(value: Any, dim: str, name: str = "value") -> pint.Quantity:
    """Check ``value`` has dimension ``dim`` and return it as a quantity (any unit of that dimension).

    Accepts a quantity or a string (``"350 N"``). Dimensionless parameters also accept bare
    numbers; angles need a unit (degrees and radians are both common). Raises :class:`UnitError`
    naming the parameter, the expected dimension and what was given.
    """
    if type(value) is Quantity:  # the common case: a number quantity in units seen before (finite and in bounds)
        m = value._magnitude
        if type(m) is float or (type(m) is int and -_EXACT < m < _EXACT):
            known = _CHECKED.get((value._units, dim))
            if known is not None and abs(float(m) * known[0]) <= known[1]:
                return value
    return _as_quantity(value, dim, name)


def _as_quantity(value: Any, dim: str, name: str) -> pint.Quantity:
    """:func:`as_quantity`'s full checks (and the note in :data:`_CHECKED` of the units that passed them)."""
    if dim not in DIMENSIONS:
        raise KeyError(f"unknown dimension name {dim!r}")
    expected, _ = DIMENSIONS[dim]
    original = value
    if isinstance(value, str):
        value = _parse(value, name)
    elif not isinstance(value, Quantity):
        if dim == "dimensionless" and _is_number(value):
            value = Quantity(value, "dimensionless")
        elif _is_number(value):
            hint = " (say 'deg' or 'rad')" if dim == "angle" else ""
            raise UnitError(f"{name}: expected {_ARTICLE[dim]}, got the bare number {original!r}; give a unit{hint}")
        else:
            raise UnitError(f"{name}: expected {_ARTICLE[dim]}, got {type(original).__name__} {original!r}")
    if dim in _RATE_DIMS:
        value = _rate_for(value, dim)
    matches, unitless, factor = _unit_info(value._units, dim)
    if not matches:
        hint = ""
        if dim == "time" and value.dimensionless and not value.unitless:
            hint = ("; a number of revolutions is not a time: give the life in hours, the speed of each "
                    "load case converts it")
        got = original if isinstance(original, str) else _describe(value)
        raise UnitError(f"{name}: expected {_ARTICLE[dim]}, got {got}{hint}")
    if dim == "angle" and unitless:
        raise UnitError(f"{name}: expected an angle, got {_describe(original)}; give a unit (say 'deg' or 'rad')")
    m = value.magnitude
    if isinstance(m, float | int) and not isinstance(m, bool):
        if not math.isfinite(m):
            raise UnitError(f"{name}: expected a finite {dim.replace('_', ' ')}, got {_describe(value)}")
    elif not np.all(np.isfinite(np.asarray(m, dtype=float))):
        raise UnitError(f"{name}: expected a finite {dim.replace('_', ' ')}, got {_describe(value)}")
    _check_bounds(value, dim, name, isinstance(original, str), factor)
    if factor is not None and not (dim == "angle" and unitless) and len(_CHECKED) < 4096:
        _CHECKED[value._units, dim] = (factor, BOUNDS[dim][1])
    return value


_RATE_DIMS = ("frequency", "angular_velocity")
_RATE_KIND: dict[Any, str | None] = {}


def rate_kind(units: Any) -> str | None:
    """``"angle"`` for an angle per time (rpm, rad/s, deg/s, cycle/s: pint keeps the radian in their root units),
    ``"cycles"`` for hertz (Hz, kHz: cycles per second), None for anything else (a bare ``1/s`` stays pint's)."""
    key = units._units if hasattr(units, "_units") else units
    if key not in _RATE_KIND:
        u = ureg.Unit(units) if not isinstance(units, pint.Unit) else units
        root = ureg.get_root_units(u)[1]
        if u.dimensionality != ureg.get_dimensionality("1/[time]"):
            kind = None
        elif "radian" in root._units:
            kind = "angle"
        elif any("hertz" in k for k in u._units):
            kind = "cycles"
        else:
            kind = None
        _RATE_KIND[key] = kind
    return _RATE_KIND[key]


def rate_to(q: pint.Quantity, unit: Any) -> pint.Quantity:
    """``q.to(unit)`` for rates, with a revolution (cycle) being 2 pi rad: ``rate_to(Q(1200, "rpm"), "Hz")`` is
    20 Hz and ``rate_to(Q(9, "Hz"), "rpm")`` 540 rpm. pint reads Hz as 1/s and the radian as dimensionless, so its
    own conversion is 2 pi off between an angle per time and hertz (review 3 finding 17)."""
    src, dst = rate_kind(q.units), rate_kind(ureg.Unit(unit) if isinstance(unit, str) else unit)
    if src == "angle" and dst == "cycles":
        return Quantity(q.m_as("rad/s") / (2 * math.pi), "Hz").to(unit)
    if src == "cycles" and dst == "angle":
        return Quantity(q.m_as("Hz") * (2 * math.pi), "rad/s").to(unit)
    return q.to(unit)


def _rate_for(value: pint.Quantity, dim: str) -> pint.Quantity:
    """A frequency given as an angle per time (``"1200 rpm"``: 20 Hz) in Hz, an angular velocity given in hertz
    (``"9 Hz"``: 9 rev/s) in rpm; anything else unchanged (see :func:`rate_to`)."""
    try:
        kind = rate_kind(value.units)
    except Exception:  # not a unit pint can root (an offset unit): the dimension check names it
        return value
    if dim == "frequency" and kind == "angle":
        return rate_to(value, "Hz")
    if dim == "angular_velocity" and kind == "cycles":
        return rate_to(value, "rpm")
    return value


def to_si(value: Any, dim: str, name: str = "value") -> Any:
    """The SI magnitude (float or ndarray) of ``value`` after :func:`as_quantity` checks it."""
    if type(value) is Quantity:  # as as_quantity's fast path, and the factor it found
        m = value._magnitude
        if type(m) is float or (type(m) is int and -_EXACT < m < _EXACT):
            known = _CHECKED.get((value._units, dim))
            if known is not None:
                m, factor = float(m), known[0]
                if abs(m * factor) <= known[1]:
                    return m * factor if factor != 1.0 else m
    elif type(value) is float and dim == "dimensionless" and abs(value) <= BOUNDS["dimensionless"][1]:
        return value  # a bare number (finite and in bounds: what the full path returns)
    q = as_quantity(value, dim, name)
    m = q.magnitude
    if isinstance(m, float | int) and not isinstance(m, bool):
        factor = _unit_info(q._units, dim)[2]
        if factor is not None:
            return float(m) * factor if factor != 1.0 else float(m)
    mag = q.to(_unit(DIMENSIONS[dim][1])).magnitude
    return float(mag) if _is_scalar(mag) else np.asarray(mag, dtype=float)


def from_si(value: Any, dim: str) -> pint.Quantity:
    """Wrap an SI magnitude as a quantity in the SI unit of ``dim``."""
    return Quantity(value, _unit(DIMENSIONS[dim][1]))


def si_to(value: Any, dim: str, unit: str) -> pint.Quantity:
    """``from_si(value, dim).to(unit)``: an SI magnitude as a quantity in ``unit``, the same magnitude bit for bit
    (pint's conversion factor applied to a float once, without the intermediate quantity)."""
    if type(value) is float:
        conv = _SI_TO.get((dim, unit))
        if conv is None:
            conv = _SI_TO[dim, unit] = _si_to(dim, unit)
        if conv[0] is not None and not ureg._active_ctx.contexts and not (ureg.force_ndarray
                                                                          or ureg.force_ndarray_like):
            q = object.__new__(Quantity)
            q._magnitude, q._units = (value if conv[0] == "same" else value * conv[0]), conv[1]
            return q
    return from_si(value, dim).to(unit)


def _si_to(dim: str, unit: str) -> tuple[Any, Any]:
    """(factor or "same" or None, target units container) of :func:`si_to` for ``dim`` -> ``unit``: what the
    registry's conversion (mechverify.pint_cache) multiplies an SI float by; None for offset units."""
    src, dst = _unit(DIMENSIONS[dim][1])._units, from_si(1.0, dim).to(unit)._units
    f = _pint_cache.factor_of(ureg, src, dst)
    return (None if f is None else f), dst


def require_positive(value: float, name: str, *, allow_zero: bool = False, dim: str | None = None) -> float:
    """Raise :class:`InputError` unless the SI value is > 0 (or >= 0 with ``allow_zero``).

    ``dim`` (a :data:`DIMENSIONS` name): the message shows the value in its SI unit (``got -0.002 m``);
    without it, a bare number marked ``(SI)``."""
    if type(value) is float and (value > 0.0 or (allow_zero and value == 0.0)):
        return value
    bad = np.any(np.asarray(value) < 0) if allow_zero else np.any(np.asarray(value) <= 0)
    if bad:
        rel = "zero or positive" if allow_zero else "positive"
        shown = f"{value!r} (SI)" if dim is None else fmt(from_si(value, dim))
        raise InputError(f"{name}: must be {rel}, got {shown}")
    return value


def si_function(returns: str | tuple[str, ...] | None = None, **dims: str) -> Callable:
    """Decorator: write a formula in SI floats, call it with quantities.

    ``dims`` maps parameter names to dimension names; those arguments are converted with
    :func:`to_si` (so they are checked). The return value is wrapped as a quantity of ``returns``
    (a tuple of names for a tuple result). The raw SI function stays available as ``f.si`` for
    hot loops. Parameters not named in ``dims`` pass through untouched.
    """

    def decorate(f: Callable) -> Callable:
        sig = inspect.signature(f)
        for p in dims:
            if p not in sig.parameters:
                raise TypeError(f"si_function: {f.__name__} has no parameter {p!r}")

        fast = _fast_binding(sig, dims)

        @functools.wraps(f)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            call = fast(args, kwargs) if fast is not None else None
            if call is None:  # pint's binding: the general case, and the TypeError of a wrong call
                bound = sig.bind(*args, **kwargs)
                bound.apply_defaults()
                for p, d in dims.items():
                    v = bound.arguments.get(p)
                    if v is not None:
                        bound.arguments[p] = to_si(v, d, p)
                call = bound.args, bound.kwargs
            out = f(*call[0], **call[1])
            if returns is None:
                return out
            if isinstance(returns, tuple):
                return tuple(from_si(o, d) for o, d in zip(out, returns, strict=True))
            return from_si(out, returns)

        wrapper.si = f  # type: ignore[attr-defined]
        return wrapper

    return decorate


def _fast_binding(sig: inspect.Signature, dims: dict[str, str]) -> Callable | None:
    """For :func:`si_function`: a binder of ``(args, kwargs)`` to the call of the SI function, with the arguments
    named in ``dims`` converted (:func:`to_si`) and their non-None defaults too, as ``sig.bind`` +
    ``apply_defaults`` + the conversion does (that costs ~10 us a call); None for a signature with ``*args``,
    ``**kwargs`` or positional-only parameters. The binder returns None for a call it cannot bind (a missing or
    unknown argument, one given twice, too many): the caller then binds with ``sig`` and gets its TypeError."""
    P = inspect.Parameter
    params = list(sig.parameters.values())
    if any(p.kind not in (P.POSITIONAL_OR_KEYWORD, P.KEYWORD_ONLY) for p in params):
        return None
    positional = [p.name for p in params if p.kind is P.POSITIONAL_OR_KEYWORD]
    index = {p.name: (i if p.kind is P.POSITIONAL_OR_KEYWORD else len(params) + 1) for i, p in enumerate(params)}
    required = [(index[p.name], p.name) for p in params if p.default is P.empty]
    convert = [(index[name], name, d, None if sig.parameters[name].default is P.empty else sig.parameters[name].default)
               for name, d in dims.items()]  # in the order of dims, as the general path converts them
    npos = len(positional)

    def bind(args: tuple[Any, ...], kwargs: dict[str, Any]) -> tuple[tuple[Any, ...], dict[str, Any]] | None:
        n = len(args)
        if n > npos:
            return None
        for k in kwargs:
            i = index.get(k)
            if i is None or i < n:
                return None
        for i, name in required:
            if i >= n and name not in kwargs:
                return None
        a, kw = list(args), dict(kwargs)
        for i, name, d, default in convert:
            if i < n:
                v = a[i]
                if v is not None:
                    a[i] = to_si(v, d, name)
            elif name in kw:
                v = kw[name]
                if v is not None:
                    kw[name] = to_si(v, d, name)
            elif default is not None:
                kw[name] = to_si(default, d, name)
        return tuple(a), kw

    return bind


def exceeds(a: pint.Quantity, b: pint.Quantity) -> bool:
    """``a > b`` as pint compares two quantities (the magnitudes in the same units, else in root units), without
    pint's comparison machinery for float magnitudes in multiplicative units (the same floats are compared)."""
    if type(a) is Quantity and type(b) is Quantity and type(a._magnitude) is float and type(b._magnitude) is float:
        if a._units == b._units:
            return a._magnitude > b._magnitude
        ra, rb = _root_factor(a._units), _root_factor(b._units)
        if ra is not None and rb is not None and ra[1] == rb[1]:
            return a._magnitude * ra[0] > b._magnitude * rb[0]
    return bool(a > b)


@functools.lru_cache(maxsize=1024)
def _root_factor(units: Any) -> tuple[float, Any] | None:
    """(factor, root units) of ``q.to_root_units()`` for a multiplicative unit (None otherwise): pint multiplies
    the magnitude by this factor (``1.0 * factor`` is the factor itself)."""
    q = Quantity(1.0, units)
    if not q._is_multiplicative or Quantity(0.0, units).to_root_units().magnitude != 0.0:
        return None
    r = q.to_root_units()
    return float(r.magnitude), r._units


def same_units(a: pint.Quantity, b: pint.Quantity) -> bool:
    """True when two quantities are in the same units (no conversion is needed between them)."""
    return a._units == b._units


def _positional_numpy(m: float, digits: int) -> str:
    return np.format_float_positional(m, precision=digits, unique=False, fractional=False, trim="-")


def _positional_dragon4(m: float, digits: int) -> str:
    """numpy's format_float_positional without its argument checks (fmt's arguments are always valid)."""
    return _dragon4(m, precision=digits, unique=False, fractional=False, trim="-", sign=False, pad_left=-1,
                    pad_right=-1, min_digits=-1)


try:  # numpy's formatter behind format_float_positional (a private name: checked, else the public function)
    from numpy._core.multiarray import dragon4_positional as _dragon4

    _positional = (_positional_dragon4 if all(_positional_dragon4(x, d) == _positional_numpy(x, d)
                                              for x in (0.1, 12.5, 2526.0, 1e-3, 9999.95, 1 / 3) for d in (3, 4, 6))
                   else _positional_numpy)
except (ImportError, TypeError, ValueError):  # another numpy
    _positional = _positional_numpy


#: (dimension name, unit text) -> (factor, units container) of :func:`si_to`
_SI_TO: dict[tuple[str, str], tuple[Any, Any]] = {}

#: (units container, sort function) -> the text of ``f"{q.units:~P}"`` (:func:`fmt`)
_UNIT_TEXT: dict[tuple[Any, Any], str] = {}


def fmt(q: pint.Quantity, unit: str | None = None, digits: int = 4) -> str:
    """Format a quantity for people: ``fmt(Q(0.0123, "m"), "mm") -> '12.3 mm'``."""
    if unit:
        q = q.to(unit)
    m = q.magnitude
    if type(m) is float or _is_scalar(m):
        m = float(m)
        if m != 0 and 1e-3 <= abs(m) < 1e7:  # no exponent where people would not write one: 10000 h, 0.2526
            text = _positional(m, digits)
        else:
            text = f"{m:.{digits}g}"
    else:
        text = np.array2string(np.asarray(m), precision=digits)
    key = (q._units, ureg.formatter.default_sort_func) if type(q) is Quantity else None
    u = _UNIT_TEXT.get(key) if key is not None else None
    if u is None:
        u = f"{q.units:~P}"
        if key is not None and len(_UNIT_TEXT) < 4096:
            _UNIT_TEXT[key] = u
    return f"{text} {u}".strip() if u else text


_DIMENSIONALITY = {k: (ureg.get_dimensionality(v[0]) if v[0] else None) for k, v in DIMENSIONS.items()}


def _dimension_matches(q: pint.Quantity, dim: str) -> bool:
    expected = _DIMENSIONALITY[dim]
    return q.dimensionless if expected is None else q.dimensionality == expected


def _is_number(v: Any) -> bool:
    return isinstance(v, int | float | np.number) and not isinstance(v, bool) or (
        isinstance(v, np.ndarray) and v.dtype.kind in "if"
    )


def _is_scalar(m: Any) -> bool:
    return np.ndim(m) == 0


__all__ = ["ureg", "Quantity", "QuantityLike", "Q", "DIMENSIONS", "BOUNDS", "PlausibilityWarning", "as_quantity",
           "to_si", "from_si", "si_to", "rate_to", "rate_kind", "si_function", "require_positive", "fmt", "same_units",
           "exceeds"]
