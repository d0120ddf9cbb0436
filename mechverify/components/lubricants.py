"""Lubricant viscosity from its ISO VG grade and viscosity index (for the ISO 281 viscosity ratio kappa).

``ISO VG 68, VI 95``: the grade is the mid-point kinematic viscosity at 40 degC (ISO 3448); the viscosity at
100 degC follows from the viscosity index by inverting ASTM D2270 [1]; between and around the two the
ASTM D341 line log log(nu + 0.7) = A − B log T gives nu(T)
(:func:`mechverify.components.bearings.viscosity_at_temperature`).

ASTM D2270 [1]: with U = nu40, Y = nu100 and the basic values L(Y), H(Y) (Table 1 for 2 <= Y <= 70 mm²/s,
linear interpolation between rows; above 70: L = 0.8353 Y² + 14.67 Y − 216, H = 0.1684 Y² + 11.85 Y − 97):
* Procedure A (VI <= 100): VI = 100 (L − U)/(L − H);
* Procedure B (VI > 100): N = (log H − log U)/log Y, VI = (10^N − 1)/0.00715 + 100.

References
----------
[1] ASTM D2270-10, Standard Practice for Calculating Viscosity Index from Kinematic Viscosity at 40 and
    100 degC, Procedures A and B, Table 1 (table transcription: components/data/astm_d2270.toml, unverified).
[2] ISO 3448:1992, Industrial liquid lubricants - ISO viscosity classification (VG = mid-point nu40).
"""

from __future__ import annotations

import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np

from mechverify.errors import InputError, ValidityError

_DATA = Path(__file__).parent / "data" / "astm_d2270.toml"
#: ASTM D2270 defines the VI for nu100 >= 2 mm²/s; the inversion searches up to this nu100 [mm²/s]
NU100_MIN, NU100_MAX = 2.0, 500.0


@cache
def _table() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    d = tomllib.loads(_DATA.read_text(encoding="utf-8"))
    return np.asarray(d["nu100"], float), np.asarray(d["L"], float), np.asarray(d["H"], float)


def vi_basic_values(nu100: float) -> tuple[float, float]:
    """(L, H) [mm²/s] of ASTM D2270 for the viscosity at 100 degC nu100 [mm²/s] ([1] Table 1, Eqs. above 70)."""
    Y = float(nu100)
    if not Y >= NU100_MIN:
        raise ValidityError(f"viscosity at 100 degC {Y:g} mm²/s: ASTM D2270 defines the VI for >= 2 mm²/s only")
    if Y > 70.0:
        return 0.8353 * Y**2 + 14.67 * Y - 216.0, 0.1684 * Y**2 + 11.85 * Y - 97.0
    y, L, H = _table()
    return float(np.interp(Y, y, L)), float(np.interp(Y, y, H))


def viscosity_index(nu40: float, nu100: float) -> float:
    """VI from the kinematic viscosities at 40 and 100 degC [mm²/s] ([1] Procedures A and B)."""
    U, Y = float(nu40), float(nu100)
    if not U > Y > 0:
        raise InputError(f"viscosity at 40 degC ({U:g}) must exceed that at 100 degC ({Y:g}) mm²/s")
    L, H = vi_basic_values(Y)
    vi = 100.0 * (L - U) / (L - H)
    if vi <= 100.0:
        return vi
    N = (math.log10(H) - math.log10(U)) / math.log10(Y)
    return (10.0**N - 1.0) / 0.00715 + 100.0


def viscosity_100_from_vi(nu40: float, vi: float) -> float:
    """nu100 [mm²/s] of an oil with nu40 [mm²/s] and viscosity index ``vi``: ASTM D2270 solved for nu100
    (VI(nu40, nu100) rises monotonically with nu100 at fixed nu40; bisection to 1e-9 relative)."""
    U, target = float(nu40), float(vi)
    if not U > NU100_MIN:
        raise InputError(f"viscosity at 40 degC must exceed {NU100_MIN:g} mm²/s, got {U:g}")
    if not -100.0 <= target <= 400.0:
        raise ValidityError(f"viscosity index {target:g} outside -100..400: give the viscosity at 100 degC instead")
    lo, hi = NU100_MIN, min(U * 0.999, NU100_MAX)
    f_lo, f_hi = viscosity_index(U, lo) - target, viscosity_index(U, hi) - target
    if f_lo > 0 or f_hi < 0:
        raise ValidityError(f"no ASTM D2270 viscosity at 100 degC gives VI {target:g} with {U:g} mm²/s at 40 degC "
                            f"(VI spans {f_lo + target:.0f}..{f_hi + target:.0f}): give viscosity_100")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if viscosity_index(U, mid) < target:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-9 * hi:
            break
    return 0.5 * (lo + hi)


__all__ = ["vi_basic_values", "viscosity_index", "viscosity_100_from_vi"]
