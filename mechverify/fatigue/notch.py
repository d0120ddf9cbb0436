"""Notches: theoretical stress-concentration factors Kt from published fits, notch sensitivity, and Kf.

Public API::

    kt_plate_hole(W, d)                          # central hole in a plate in tension, net-section Kt
    kt_shoulder_fillet(D, d, r, loading)         # stepped round bar, loading bending/axial/torsion
    kt_groove(D, d, r, loading="bending")        # U-shaped circumferential groove, bending
    neuber_constant(Sut, loading="bending")      # sqrt(a) [m^0.5]
    notch_sensitivity(r, Sut, loading)           # q = 1 / (1 + sqrt(a/r))
    fatigue_notch_factor(Kt, q)                  # Kf = 1 + q (Kt - 1)
    neuber_kf(Kt, r, Sut, loading)               # Kf = 1 + (Kt - 1) / (1 + sqrt(a/r))

Kt refers to the nominal stress stated in each function (net section of the smaller diameter or the
net width). Each fit raises :class:`ValidityError` outside the range it was fitted on. The
coefficients live in ``fatigue/data/kt_fits.toml``.

References
----------
1. Pilkey, Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., Wiley, 2008: Eq. (4.1) and
   Chart 4.1 (plate with hole), Charts 3.4/3.10/3.12 (shoulder fillet), Ch. 2 (U-groove) fits.
2. Budynas, Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015, Sec. 6-10:
   Eq. (6-32) (Kf = 1 + q(Kt - 1)), Eqs. (6-33)..(6-35) (Neuber constant fits of Figs. 6-20, 6-21).
"""

from __future__ import annotations

import math
from typing import Any

import pint

from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.fatigue._data import load
from mechverify.units import Q, to_si

LOADINGS = ("bending", "axial", "torsion")
_INCH = 0.0254


def _positive(v: Any, name: str) -> float:
    x = to_si(v, "length", name)
    if x <= 0:
        raise InputError(f"{name}: must be positive, got {x!r} m")
    return x


def _poly_fit(kind: str, loading: str, D: float, d: float, r: float) -> float:
    fits = load("kt_fits")[kind]
    if loading not in fits:
        raise UnknownNameError(f"loading for a {kind.replace('_', ' ')} Kt fit", loading, list(fits))
    if not D > d:
        raise InputError(f"D = {D * 1e3:.4g} mm must exceed d = {d * 1e3:.4g} mm")
    t = (D - d) / 2.0
    x = t / r
    for branch in fits[loading]["branch"]:
        lo, hi = branch["t_over_r"]
        if lo <= x <= hi:
            s = math.sqrt(x)
            C = [c0 + c1 * s + c2 * x for c0, c1, c2 in branch["C"]]
            u = 2.0 * t / D
            return C[0] + C[1] * u + C[2] * u * u + C[3] * u ** 3
    ranges = ", ".join(f"{b['t_over_r'][0]}..{b['t_over_r'][1]}" for b in fits[loading]["branch"])
    raise ValidityError(f"{kind.replace('_', ' ')} ({loading}): t/r = {x:.4g} outside the fitted range {ranges} "
                        f"({fits[loading]['source']})")


def kt_shoulder_fillet(D: Any, d: Any, r: Any, loading: str = "bending") -> pint.Quantity:
    """Kt of a stepped round bar with a shoulder fillet [-], nominal stress on the small diameter d.

    ``Kt = C1 + C2 (2t/D) + C3 (2t/D)^2 + C4 (2t/D)^3``, t = (D - d)/2, Ci functions of t/r.
    Validity: 0.1 <= t/r <= 20 (bending, axial), 0.25 <= t/r <= 4 (torsion). Ref. 1, Charts 3.4, 3.10, 3.12.
    """
    return Q(_poly_fit("shoulder_fillet", loading, _positive(D, "D"), _positive(d, "d"), _positive(r, "r")), "")


def kt_groove(D: Any, d: Any, r: Any, loading: str = "bending") -> pint.Quantity:
    """Kt of a round bar with a U-shaped circumferential groove [-], nominal stress on the root diameter d.

    Same polynomial form as :func:`kt_shoulder_fillet`; bending, 0.25 <= t/r <= 2.0 (Ref. 1, Ch. 2 fit).
    """
    return Q(_poly_fit("groove", loading, _positive(D, "D"), _positive(d, "d"), _positive(r, "r")), "")


def kt_plate_hole(W: Any, d: Any) -> pint.Quantity:
    """Net-section Kt of a finite-width plate with a central circular hole in tension [-].

    ``Ktn = 2 + 0.284 (1 - d/W) - 0.600 (1 - d/W)^2 + 1.32 (1 - d/W)^3`` with the nominal stress
    ``F / ((W - d) t)``; 0 <= d/W < 1 (Ref. 1, Eq. (4.1), Chart 4.1; Ktn -> 3 for a small hole, Kirsch).
    """
    w, dd = _positive(W, "W"), _positive(d, "d")
    ratio = dd / w
    if ratio >= 1:
        raise ValidityError(f"d/W = {ratio:.4g}: the hole must be narrower than the plate")
    c = load("kt_fits")["plate_hole"]["axial"]["c"]
    x = 1.0 - ratio
    return Q(c[0] + c[1] * x + c[2] * x * x + c[3] * x ** 3, "")


def neuber_constant(Sut: Any, loading: str = "bending") -> pint.Quantity:
    """Neuber characteristic length sqrt(a) of steels [m^0.5], fits of Ref. 2 Figs. 6-20/6-21.

    Bending or axial (Eq. (6-35a)): ``sqrt(a) = 0.246 - 3.08e-3 S + 1.51e-5 S^2 - 2.67e-8 S^3``;
    torsion (Eq. (6-35b)): ``0.190 - 2.51e-3 S + 1.35e-5 S^2 - 2.67e-8 S^3``; S = Sut in kpsi,
    sqrt(a) in sqrt(in). Valid for steels with 50 <= Sut <= 250 kpsi (345..1724 MPa).
    """
    key = str(loading).strip().lower()
    if key not in LOADINGS:
        raise UnknownNameError("loading type", loading, LOADINGS)
    s = to_si(Sut, "pressure", "Sut") / 6.894757e6
    if not 50 - 1e-6 <= s <= 250 + 1e-6:
        raise ValidityError(f"Sut = {s:.4g} kpsi: the Neuber-constant fit holds for steels, 50..250 kpsi")
    if key == "torsion":
        root_a = 0.190 - 2.51e-3 * s + 1.35e-5 * s * s - 2.67e-8 * s ** 3
    else:
        root_a = 0.246 - 3.08e-3 * s + 1.51e-5 * s * s - 2.67e-8 * s ** 3
    return Q(root_a * math.sqrt(_INCH), "m**0.5")


def notch_sensitivity(r: Any, Sut: Any, loading: str = "bending") -> pint.Quantity:
    """Notch sensitivity ``q = 1 / (1 + sqrt(a)/sqrt(r))`` [-] of steels, Ref. 2 Eq. (6-34)."""
    rm = _positive(r, "r")
    root_a = neuber_constant(Sut, loading).m_as("m**0.5")
    return Q(1.0 / (1.0 + root_a / math.sqrt(rm)), "")


def fatigue_notch_factor(Kt: Any, q: Any) -> pint.Quantity:
    """``Kf = 1 + q (Kt - 1)`` [-], Ref. 2 Eq. (6-32). Kt >= 1, 0 <= q <= 1."""
    kt, qq = to_si(Kt, "dimensionless", "Kt"), to_si(q, "dimensionless", "q")
    if kt < 1:
        raise InputError(f"Kt: must be >= 1, got {kt!r}")
    if not 0 <= qq <= 1:
        raise InputError(f"q: notch sensitivity must lie in [0, 1], got {qq!r}")
    return Q(1.0 + qq * (kt - 1.0), "")


def neuber_kf(Kt: Any, r: Any, Sut: Any, loading: str = "bending") -> pint.Quantity:
    """``Kf = 1 + (Kt - 1) / (1 + sqrt(a)/sqrt(r))`` [-] (Neuber), Ref. 2 Eq. (6-33)."""
    return fatigue_notch_factor(Kt, notch_sensitivity(r, Sut, loading))


__all__ = ["kt_plate_hole", "kt_shoulder_fillet", "kt_groove", "neuber_constant", "notch_sensitivity",
           "fatigue_notch_factor", "neuber_kf"]
