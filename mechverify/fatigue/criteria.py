"""Mean-stress criteria: the fatigue safety factor of an (alternating, mean) stress state along a load line.

Every criterion is one function, usable two ways:

* with quantities (or strings): ``goodman("100 MPa", "50 MPa", Se="200 MPa", Sut="600 MPa")``
  returns a dimensionless quantity (scalar, or an array when any stress is an array);
* with SI floats or numpy arrays, vectorised (for FEA fields and springs' hot loops):
  ``goodman.si(sa, sm, Se, Sut)`` returns a float or an ndarray.

Signatures (stresses in Pa for ``.si``; amplitudes >= 0; strengths > 0)::

    goodman(sigma_a, sigma_m, Se, Sut, load_line="proportional")
    gerber(sigma_a, sigma_m, Se, Sut, load_line="proportional")
    asme_elliptic(sigma_a, sigma_m, Se, Sy, load_line="proportional")
    soderberg(sigma_a, sigma_m, Se, Sy, load_line="proportional")
    morrow(sigma_a, sigma_m, Se, sigma_f, load_line="proportional")
    walker(sigma_a, sigma_m, Se, gamma, load_line="proportional")       # gamma dimensionless, 0 < gamma <= 1
    smith_watson_topper(sigma_a, sigma_m, Se, load_line="proportional")  # Walker with gamma = 0.5
    langer(sigma_a, sigma_m, Sy, load_line="proportional")               # first-cycle yield
    safety_factor(criterion, sigma_a, sigma_m, Se, Sut=None, Sy=None, sigma_f=None, gamma=None,
                  load_line="proportional")                              # dispatch by name
    equivalent_amplitude(criterion, sigma_a, sigma_m, Sut=None, Sy=None, sigma_f=None, gamma=None)
        # fully reversed stress amplitude equivalent to (sigma_a, sigma_m): compare with an S-N curve

The same functions serve torsion (springs): pass shear amplitudes and torsional strengths
(Sse, Ssu, Ssy) in place of the normal ones.

Load lines (``load_line``):

* ``"proportional"`` (default, Shigley's choice in Tables 6-6..6-8): the stress ratio
  r = sigma_a/sigma_m stays constant as the load grows; n = S_a/sigma_a = S_m/sigma_m at the
  intersection of the load line with the failure curve.
* ``"constant_mean"``: the mean stress is fixed (e.g. a preload or dead weight) and only the
  amplitude grows; n = S_a(sigma_m)/sigma_a.

Compressive mean stress (sigma_m < 0): fatigue strength is taken as independent of the mean
(S_a = S_e, the horizontal line of Shigley 10th ed. Fig. 6-27 / Sec. 6-12); Langer's line bounds
yielding. The fatigue criteria return ``inf`` for a state with no alternating and no tensile mean
stress. Safety factors of 0 mean the mean stress alone reaches the static strength.

References
----------
1. Budynas, Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015, Sec. 6-12,
   Eqs. (6-41)..(6-46), Tables 6-6 (Goodman, Langer), 6-7 (Gerber, Langer), 6-8 (ASME elliptic, Langer).
2. Dowling, *Mechanical Behavior of Materials*, 4th ed., 2013, Sec. 9.7: Morrow Eq. (9.18),
   Smith-Watson-Topper Eq. (9.16), Walker Eq. (9.19).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from mechverify.errors import InputError, UnknownNameError
from mechverify.units import si_function

LOAD_LINES = ("proportional", "constant_mean")

#: Criterion name -> the strength it needs besides Se.
CRITERIA: dict[str, str | None] = {
    "goodman": "Sut",
    "gerber": "Sut",
    "asme_elliptic": "Sy",
    "soderberg": "Sy",
    "morrow": "sigma_f",
    "walker": "gamma",
    "smith_watson_topper": None,
}


# --------------------------------------------------------------------------------------------- helpers
def _arr(x: Any) -> np.ndarray:
    return np.asarray(x, dtype=float)


def _out(x: np.ndarray) -> Any:
    return float(x) if np.ndim(x) == 0 else x


def _check(sigma_a: Any, load_line: str, **strengths: Any) -> None:
    if load_line not in LOAD_LINES:
        raise UnknownNameError("load line", str(load_line), LOAD_LINES)
    if np.any(_arr(sigma_a) < 0):
        raise InputError(f"sigma_a: stress amplitude must be >= 0, got {np.min(sigma_a)!r} Pa")
    for name, v in strengths.items():
        if v is None:
            raise InputError(f"{name}: this criterion needs it")
        if np.any(_arr(v) <= 0):
            raise InputError(f"{name}: strength must be positive, got {v!r} Pa")


def _div(num: np.ndarray, den: np.ndarray) -> np.ndarray:
    """num/den with x/0 -> inf for x > 0 (and 0/0 -> inf: no stress, no failure)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        q = num / den
    return np.where(den == 0, np.inf, q)


def _linear(sa: Any, sm: Any, Se: Any, S: Any, load_line: str) -> Any:
    """Failure line Sa/Se + Sm/S = 1 (Goodman with S = Sut, Soderberg with Sy, Morrow with sigma_f)."""
    sa, sm, Se, S = _arr(sa), np.maximum(_arr(sm), 0.0), _arr(Se), _arr(S)
    if load_line == "proportional":
        return _out(_div(np.ones_like(sa * sm * Se * S), sa / Se + sm / S))
    return _out(_div(np.maximum(Se * (1.0 - sm / S), 0.0), sa))


# --------------------------------------------------------------------------------------------- criteria
@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", Sut="pressure")
def goodman(sigma_a: Any, sigma_m: Any, Se: Any, Sut: Any, load_line: str = "proportional") -> Any:
    """Modified Goodman: ``sigma_a/Se + sigma_m/Sut = 1/n`` [-].

    sigma_a, sigma_m: alternating and mean stress [Pa]; Se: (Marin-corrected) endurance limit or
    fatigue strength at the life of interest [Pa]; Sut: ultimate tensile strength [Pa].
    Ref. 1, Eq. (6-41), Table 6-6.
    """
    _check(sigma_a, load_line, Se=Se, Sut=Sut)
    return _linear(sigma_a, sigma_m, Se, Sut, load_line)


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", Sy="pressure")
def soderberg(sigma_a: Any, sigma_m: Any, Se: Any, Sy: Any, load_line: str = "proportional") -> Any:
    """Soderberg: ``sigma_a/Se + sigma_m/Sy = 1/n`` [-] (Sy: yield strength [Pa]). Ref. 1, Eq. (6-40)."""
    _check(sigma_a, load_line, Se=Se, Sy=Sy)
    return _linear(sigma_a, sigma_m, Se, Sy, load_line)


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure",
             sigma_f="pressure")
def morrow(sigma_a: Any, sigma_m: Any, Se: Any, sigma_f: Any, load_line: str = "proportional") -> Any:
    """Morrow: ``sigma_a/Se + sigma_m/sigma_f' = 1/n`` [-].

    sigma_f: true fracture strength (fatigue strength coefficient) sigma_f' [Pa]; for steels with
    HB <= 500 it is about Sut + 345 MPa (Ref. 1, Sec. 6-7). Ref. 2, Eq. (9.18).
    """
    _check(sigma_a, load_line, Se=Se, sigma_f=sigma_f)
    return _linear(sigma_a, sigma_m, Se, sigma_f, load_line)


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", Sut="pressure")
def gerber(sigma_a: Any, sigma_m: Any, Se: Any, Sut: Any, load_line: str = "proportional") -> Any:
    """Gerber parabola: ``n sigma_a/Se + (n sigma_m/Sut)^2 = 1`` [-].

    Proportional line, Ref. 1 Eq. (6-47) / Table 6-7:
    ``n = (1/2)(Sut/sigma_m)^2 (sigma_a/Se) [-1 + sqrt(1 + (2 sigma_m Se/(Sut sigma_a))^2)]``,
    evaluated here as the stable root ``n = 2/(b + sqrt(b^2 + 4a))``, a = (sigma_m/Sut)^2, b = sigma_a/Se.
    Constant mean: ``n = Se (1 - (sigma_m/Sut)^2) / sigma_a``.
    """
    _check(sigma_a, load_line, Se=Se, Sut=Sut)
    sa, sm, Se, Sut = _arr(sigma_a), np.maximum(_arr(sigma_m), 0.0), _arr(Se), _arr(Sut)
    if load_line == "proportional":
        a, b = (sm / Sut) ** 2, sa / Se
        return _out(_div(2.0 * np.ones_like(a * b), b + np.sqrt(b * b + 4.0 * a)))
    return _out(_div(np.maximum(Se * (1.0 - (sm / Sut) ** 2), 0.0), sa))


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", Sy="pressure")
def asme_elliptic(sigma_a: Any, sigma_m: Any, Se: Any, Sy: Any, load_line: str = "proportional") -> Any:
    """ASME elliptic: ``(n sigma_a/Se)^2 + (n sigma_m/Sy)^2 = 1`` [-].

    Proportional: ``n = 1/sqrt((sigma_a/Se)^2 + (sigma_m/Sy)^2)`` (Ref. 1, Eq. (6-48), Table 6-8);
    constant mean: ``n = Se sqrt(1 - (sigma_m/Sy)^2) / sigma_a``.
    """
    _check(sigma_a, load_line, Se=Se, Sy=Sy)
    sa, sm, Se, Sy = _arr(sigma_a), np.maximum(_arr(sigma_m), 0.0), _arr(Se), _arr(Sy)
    if load_line == "proportional":
        return _out(_div(np.ones_like(sa * sm * Se * Sy), np.hypot(sa / Se, sm / Sy)))
    return _out(_div(Se * np.sqrt(np.maximum(1.0 - (sm / Sy) ** 2, 0.0)), sa))


def _walker_si(sa: Any, sm: Any, Se: Any, gamma: Any, load_line: str) -> Any:
    sa, sm, Se, g = _arr(sa), np.maximum(_arr(sm), 0.0), _arr(Se), _arr(gamma)
    if np.any((g <= 0) | (g > 1)):
        raise InputError(f"gamma: Walker exponent must lie in (0, 1], got {gamma!r}")
    if load_line == "proportional":
        # sigma_ar is homogeneous of degree 1 in the load, so n = Se / sigma_ar
        return _out(_div(Se * np.ones_like(sa * g), (sa + sm) ** (1.0 - g) * sa ** g))
    # constant mean: solve (Sa + sm)^(1-g) Sa^g = Se for Sa in [0, Se] by bisection (vectorised)
    lo, hi = np.zeros(np.broadcast(sa, sm, Se, g).shape), np.broadcast_to(Se, np.broadcast(sa, sm, Se, g).shape)
    hi = np.array(hi, dtype=float)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        over = (mid + sm) ** (1.0 - g) * mid ** g > Se
        hi, lo = np.where(over, mid, hi), np.where(over, lo, mid)
    return _out(_div(0.5 * (lo + hi), sa))


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", gamma="dimensionless")
def walker(sigma_a: Any, sigma_m: Any, Se: Any, gamma: Any, load_line: str = "proportional") -> Any:
    """Walker: equivalent fully reversed amplitude ``sigma_ar = sigma_max^(1-gamma) sigma_a^gamma`` [-].

    gamma: material exponent fitted to test data (about 0.65 for steels, 0.45 for 2024-T3 aluminium; Ref. 2 Sec. 9.7
    ); gamma = 0.5 is Smith-Watson-Topper. n is the factor on the load that makes
    sigma_ar = Se. Ref. 2, Eq. (9.19).
    """
    _check(sigma_a, load_line, Se=Se)
    return _walker_si(sigma_a, sigma_m, Se, gamma, load_line)


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure")
def smith_watson_topper(sigma_a: Any, sigma_m: Any, Se: Any, load_line: str = "proportional") -> Any:
    """Smith-Watson-Topper: ``sigma_ar = sqrt(sigma_max sigma_a)`` (Walker with gamma = 0.5) [-]. Ref. 2, Eq. (9.16)."""
    _check(sigma_a, load_line, Se=Se)
    return _walker_si(sigma_a, sigma_m, Se, 0.5, load_line)


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Sy="pressure")
def langer(sigma_a: Any, sigma_m: Any, Sy: Any, load_line: str = "proportional") -> Any:
    """Langer first-cycle yield: ``n_y = Sy / (sigma_a + |sigma_m|)`` [-].

    The largest stress of the cycle, sigma_max = sigma_a + |sigma_m|, against the yield strength
    (Ref. 1, Eq. (6-44), Tables 6-6..6-8). Constant mean: ``n_y = (Sy - |sigma_m|)/sigma_a``.
    """
    _check(sigma_a, load_line, Sy=Sy)
    sa, sm, Sy = _arr(sigma_a), np.abs(_arr(sigma_m)), _arr(Sy)
    if load_line == "proportional":
        return _out(_div(Sy * np.ones_like(sa * sm), sa + sm))
    return _out(_div(np.maximum(Sy - sm, 0.0), sa))


# --------------------------------------------------------------------------------------------- dispatch
def require_criterion(criterion: str) -> str | None:
    """Validate a criterion name; the strength it needs besides S_e and S_ut/S_y (``"sigma_f"``, ...) or ``None``.

    Raises:
        UnknownNameError: not a key of :data:`CRITERIA`.
    """
    return _needs(criterion)


def require_load_line(load_line: str) -> str:
    """Validate a load-line name (a key of :data:`LOAD_LINES`) and return it.

    Raises:
        UnknownNameError: not a known load line.
    """
    if load_line not in LOAD_LINES:
        raise UnknownNameError("load line", str(load_line), LOAD_LINES)
    return load_line


def _needs(criterion: str) -> str | None:
    if criterion not in CRITERIA:
        raise UnknownNameError("mean-stress criterion", str(criterion), CRITERIA)
    return CRITERIA[criterion]


@si_function(returns="dimensionless", sigma_a="pressure", sigma_m="pressure", Se="pressure", Sut="pressure",
             Sy="pressure", sigma_f="pressure", gamma="dimensionless")
def safety_factor(criterion: str, sigma_a: Any, sigma_m: Any, Se: Any, Sut: Any = None, Sy: Any = None,
                  sigma_f: Any = None, gamma: Any = None, load_line: str = "proportional") -> Any:
    """The fatigue safety factor of ``criterion`` (a key of :data:`CRITERIA`) along ``load_line`` [-]."""
    need = _needs(criterion)
    given = {"Sut": Sut, "Sy": Sy, "sigma_f": sigma_f, "gamma": gamma}
    if need is not None and given[need] is None:
        raise InputError(f"{need}: the {criterion} criterion needs it")
    fn: Callable[..., Any] = {"goodman": goodman.si, "gerber": gerber.si, "asme_elliptic": asme_elliptic.si,
                              "soderberg": soderberg.si, "morrow": morrow.si, "walker": walker.si,
                              "smith_watson_topper": smith_watson_topper.si}[criterion]
    if need is None:
        return fn(sigma_a, sigma_m, Se, load_line=load_line)
    return fn(sigma_a, sigma_m, Se, given[need], load_line=load_line)


@si_function(returns="pressure", sigma_a="pressure", sigma_m="pressure", Sut="pressure", Sy="pressure",
             sigma_f="pressure", gamma="dimensionless")
def equivalent_amplitude(criterion: str, sigma_a: Any, sigma_m: Any, Sut: Any = None, Sy: Any = None,
                         sigma_f: Any = None, gamma: Any = None) -> Any:
    """Fully reversed amplitude sigma_rev equivalent to (sigma_a, sigma_m) under ``criterion`` [Pa].

    The fully reversed stress that gives the same life, to be read against an S-N curve measured
    at R = -1 (Ref. 1, Example 6-12 and Eq. (6-59) for Goodman: ``sigma_rev = sigma_a/(1 - sigma_m/Sut)``;
    Gerber ``sigma_a/(1 - (sigma_m/Sut)^2)``; ASME ``sigma_a/sqrt(1 - (sigma_m/Sy)^2)``;
    Soderberg with Sy, Morrow with sigma_f'; Walker/SWT ``sigma_max^(1-gamma) sigma_a^gamma``).
    A tensile mean at or beyond the static strength gives ``inf``; compressive means count as zero.
    """
    need = _needs(criterion)
    given = {"Sut": Sut, "Sy": Sy, "sigma_f": sigma_f, "gamma": gamma}
    if need is not None and given[need] is None:
        raise InputError(f"{need}: the {criterion} criterion needs it")
    _check(sigma_a, "proportional", **({need: given[need]} if need and need != "gamma" else {}))
    sa, sm = _arr(sigma_a), np.maximum(_arr(sigma_m), 0.0)
    if criterion in ("walker", "smith_watson_topper"):
        g = _arr(0.5 if criterion == "smith_watson_topper" else gamma)
        if np.any((g <= 0) | (g > 1)):
            raise InputError(f"gamma: Walker exponent must lie in (0, 1], got {gamma!r}")
        return _out((sa + sm) ** (1.0 - g) * sa ** g)
    S = _arr(given[need])
    if criterion == "gerber":
        factor = 1.0 - (sm / S) ** 2
    elif criterion == "asme_elliptic":
        factor = np.sqrt(np.maximum(1.0 - (sm / S) ** 2, 0.0))
    else:
        factor = 1.0 - sm / S
    factor = np.maximum(factor, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(factor > 0, sa / np.where(factor > 0, factor, 1.0), np.inf)
    return _out(out)


__all__ = ["LOAD_LINES", "CRITERIA", "goodman", "gerber", "asme_elliptic", "soderberg", "morrow", "walker",
           "smith_watson_topper", "langer", "safety_factor", "equivalent_amplitude", "require_criterion",
           "require_load_line"]
