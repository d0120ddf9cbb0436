"""Alternating and mean stresses from a history or two load cases, and von Mises equivalents.

Public API (``.si`` versions are vectorised over numpy arrays of SI stresses)::

    alternating_mean(s_max, s_min) -> (sigma_a, sigma_m)              # Eq. (6-36)
    alternating_mean_of_history(history) -> (sigma_a, sigma_m)        # from the extremes of a history
    von_mises(s)                                                      # s: (..., 6) Voigt [sx sy sz txy tyz tzx]
    von_mises_alternating_mean(s_1, s_2, Kf=1, Kfs=1) -> (sigma_a', sigma_m')

For proportional multiaxial loading between two stress states s_1 and s_2 (two load cases, or the
extremes of a cycle), the alternating tensor is (s_1 - s_2)/2 and the mean tensor (s_1 + s_2)/2;
their von Mises equivalents are the alternating and mean stresses of the fatigue criteria
(Shigley 10th ed., Sec. 6-14, Eqs. (6-55), (6-56)). The von Mises mean carries no sign; a
compressive mean is therefore treated like a tensile one (conservative).

Reference: Budynas, Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015, Eq. (6-36)
and Sec. 6-14.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.units import from_si, si_function, to_si


@si_function(returns=("pressure", "pressure"), s_max="pressure", s_min="pressure")
def alternating_mean(s_max: Any, s_min: Any) -> tuple[Any, Any]:
    """``sigma_a = (s_max - s_min)/2``, ``sigma_m = (s_max + s_min)/2`` [Pa], Shigley Eq. (6-36)."""
    hi, lo = np.asarray(s_max, float), np.asarray(s_min, float)
    if np.any(hi < lo):
        raise InputError("s_max, s_min: the maximum stress is below the minimum")
    a, m = (hi - lo) / 2.0, (hi + lo) / 2.0
    return (float(a), float(m)) if a.ndim == 0 else (a, m)


def alternating_mean_of_history(history: Any) -> tuple[Any, Any]:
    """Alternating and mean stress [Pa] of one cycle spanning the extremes of a stress history.

    Conservative for a variable-amplitude history (every cycle counted at the largest range); use
    :func:`mechverify.fatigue.rainflow.rainflow` with Miner's rule for the real spectrum.
    """
    h = np.atleast_1d(to_si(history, "pressure", "history"))
    if h.size < 2:
        raise InputError("history: need at least two stress values")
    return alternating_mean(from_si(float(h.max()), "pressure"), from_si(float(h.min()), "pressure"))


def _vm(s: np.ndarray) -> np.ndarray:
    s = np.asarray(s, float)
    if s.shape[-1] != 6:
        raise InputError(f"stress tensor: expected Voigt components (..., 6) [sx sy sz txy tyz tzx], got {s.shape}")
    sx, sy, sz, txy, tyz, tzx = np.moveaxis(s, -1, 0)
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * (txy ** 2 + tyz ** 2 + tzx ** 2))


@si_function(returns="pressure", s="pressure")
def von_mises(s: Any) -> Any:
    """Von Mises equivalent stress [Pa] of stress tensors given as Voigt arrays ``(..., 6)``."""
    out = _vm(s)
    return float(out) if out.ndim == 0 else out


@si_function(returns=("pressure", "pressure"), s_1="pressure", s_2="pressure")
def von_mises_alternating_mean(s_1: Any, s_2: Any, Kf: float = 1.0, Kfs: float = 1.0) -> tuple[Any, Any]:
    """Von Mises alternating and mean stresses [Pa] of a proportional cycle between tensors s_1 and s_2.

    Normal components are multiplied by Kf and shear components by Kfs before combining (Shigley
    Eqs. (6-55), (6-56), generalised to all six components). s_1, s_2: Voigt arrays ``(..., 6)``.
    """
    if Kf < 1 or Kfs < 1:
        raise InputError(f"Kf, Kfs: fatigue notch factors must be >= 1, got {Kf!r}, {Kfs!r}")
    a = (np.asarray(s_1, float) - np.asarray(s_2, float)) / 2.0
    m = (np.asarray(s_1, float) + np.asarray(s_2, float)) / 2.0
    k = np.array([Kf, Kf, Kf, Kfs, Kfs, Kfs])
    va, vm = _vm(a * k), _vm(m * k)
    return (float(va), float(vm)) if va.ndim == 0 else (va, vm)


__all__ = ["alternating_mean", "alternating_mean_of_history", "von_mises", "von_mises_alternating_mean"]
