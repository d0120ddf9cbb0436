"""Finite life: the S-N line from the ultimate strength (Basquin fit), and Palmgren-Miner damage.

Public API::

    fatigue_strength_fraction(Sut) -> f                     # Shigley Fig. 6-18 fit
    BasquinCurve.from_ultimate(Sut, Se, f=None)             # S = a N^b between 1e3 and 1e6 cycles
        .stress_at(cycles) -> Q ; .life_at(stress) -> float  # same interface as materials.SNCurve
        .stress_si(N) ; .life_si(S)                         # vectorised SI versions
    miner_damage(blocks, curve) -> MinerResult               # blocks: [(amplitude, cycles), ...]
    miner_life(fractions, amplitudes, curve) -> float        # cycles to failure of a mixed spectrum

``curve`` is anything with ``life_at(stress) -> cycles``: a :class:`BasquinCurve` or the
``sn_curve`` of a material from the database (table with log-log interpolation). Amplitudes are
fully reversed; convert a cycle with a mean stress first with
:func:`mechverify.fatigue.criteria.equivalent_amplitude`.

References
----------
1. Budynas, Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed. 2015 (``shigley10``), Sec. 6-8:
   Eqs. (6-13)..(6-17) (S = a N^b with a = (f Sut)^2/Se, b = -(1/3) log(f Sut/Se); low-cycle line),
   Fig. 6-18 (f); 10th ed. Eq. (6-10) fit of f; Sec. 6-16, Eq. (6-58) (Palmgren-Miner).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
import pint

from mechverify.errors import InputError, ValidityError
from mechverify.units import Q, fmt, from_si, to_si

SOURCE = "Shigley's Mechanical Engineering Design, 10th ed."
_KPSI = 6.894757e6


class LifeCurve(Protocol):
    def life_at(self, stress: Any) -> float: ...


def fatigue_strength_fraction(Sut: Any) -> pint.Quantity:
    """Fraction f of Sut reached at 1e3 cycles [-] (Ref. 1, Fig. 6-18).

    ``f = 1.06 - 2.8e-3 Sut + 6.9e-6 Sut^2`` (Sut in kpsi, 70 <= Sut <= 200 kpsi; 10th ed. Eq. (6-10));
    below 70 kpsi (483 MPa) f = 0.9 (Ref. 1, text of Sec. 6-8). Above 200 kpsi: :class:`ValidityError`.
    """
    s = to_si(Sut, "pressure", "Sut") / _KPSI
    if s <= 0:
        raise InputError("Sut: must be positive")
    if s < 70:
        return Q(0.9, "")
    if s > 200:
        raise ValidityError(f"Sut = {s:.4g} kpsi: Fig. 6-18 ends at 200 kpsi (1379 MPa); give f explicitly")
    return Q(1.06 - 2.8e-3 * s + 6.9e-6 * s * s, "")


@dataclass(frozen=True)
class BasquinCurve:
    """The S-N line ``S = a N^b`` through (1e3, f Sut) and (N_e, Se), with the low-cycle line below 1e3.

    a [Pa], b [-], Se [Pa] at ``N_e`` cycles, Sut [Pa], f [-]. Beyond N_e the strength stays Se when
    ``endurance_limit`` (steels); otherwise lives beyond N_e are outside the curve.
    """

    a: float
    b: float
    Se: float
    Sut: float
    f: float
    N_e: float = 1e6
    endurance_limit: bool = True
    source: str = f"{SOURCE}, Eqs. (6-13)..(6-17)"

    def __post_init__(self) -> None:
        if not (self.Se > 0 and self.Sut > 0 and self.a > 0 and self.b < 0):
            raise InputError("S-N line: need a > 0, b < 0, Se > 0, Sut > 0")
        if not 0 < self.f <= 1:
            raise InputError(f"f: must lie in (0, 1], got {self.f!r}")

    @classmethod
    def from_ultimate(cls, Sut: Any, Se: Any, f: float | None = None, N_e: float = 1e6,
                      endurance_limit: bool = True) -> BasquinCurve:
        """``a = (f Sut)^2 / Se``, ``b = -(1/3) log10(f Sut / Se)`` (Ref. 1, Eqs. (6-14), (6-15)) for N_e = 1e6.

        Se: the Marin-corrected endurance limit (or fatigue strength at N_e). For another N_e,
        the line through (1e3, f Sut) and (N_e, Se) is used.
        """
        sut, se = to_si(Sut, "pressure", "Sut"), to_si(Se, "pressure", "Se")
        ff = float(fatigue_strength_fraction(Sut).m) if f is None else float(f)
        if not 0 < se < ff * sut:
            raise InputError(f"Se = {fmt(Q(se, 'Pa'), 'MPa')} must lie below f Sut = {fmt(Q(ff * sut, 'Pa'), 'MPa')}")
        if not N_e > 1e3:
            raise InputError("N_e: must exceed 1e3 cycles")
        b = -math.log10(ff * sut / se) / math.log10(N_e / 1e3)
        a = ff * sut / 1e3 ** b
        return cls(a, b, se, sut, ff, float(N_e), endurance_limit)

    # ------------------------------------------------------------------ SI, vectorised
    def stress_si(self, N: Any) -> Any:
        """Fatigue strength [Pa] at N cycles (1 <= N; N > N_e only with an endurance limit)."""
        n = np.asarray(N, float)
        if np.any(n < 1):
            raise ValidityError("cycles: the S-N curve starts at 1 cycle")
        if not self.endurance_limit and np.any(n > self.N_e):
            raise ValidityError(f"cycles beyond {self.N_e:g}: no endurance limit, the curve ends there")
        low = self.Sut * n ** (math.log10(self.f) / 3.0)           # Eq. (6-17), 1 <= N <= 1e3
        mid = self.a * n ** self.b                                  # Eq. (6-13)
        out = np.where(n < 1e3, low, np.where(n <= self.N_e, mid, self.Se))
        return float(out) if out.ndim == 0 else out

    def life_si(self, S: Any) -> Any:
        """Cycles to failure at a fully reversed amplitude S [Pa]; ``inf`` below Se (endurance limit), 1 at Sut."""
        s = np.asarray(S, float)
        if np.any(s < 0):
            raise InputError("stress amplitude: must be >= 0")
        if not self.endurance_limit and np.any(s < self.Se):
            raise ValidityError(f"amplitude below the curve's last point ({fmt(Q(self.Se, 'Pa'), 'MPa')} at "
                                f"{self.N_e:g} cycles) and no endurance limit")
        with np.errstate(divide="ignore", invalid="ignore"):
            mid = (s / self.a) ** (1.0 / self.b)
            low = (np.minimum(s, self.Sut) / self.Sut) ** (3.0 / math.log10(self.f))
        out = np.where(s < self.Se, np.inf, np.where(s <= self.f * self.Sut, mid, np.where(s < self.Sut, low, 1.0)))
        return float(out) if out.ndim == 0 else out

    # ------------------------------------------------------------------ quantities (SNCurve interface)
    def stress_at(self, cycles: float) -> pint.Quantity:
        return from_si(self.stress_si(float(cycles)), "pressure")

    def life_at(self, stress: Any) -> float:
        return float(self.life_si(to_si(stress, "pressure", "stress")))


@dataclass(frozen=True)
class MinerResult:
    """Palmgren-Miner damage of one pass of a block spectrum."""

    damage: float
    lives: tuple[float, ...]
    cycles: tuple[float, ...]
    amplitudes: pint.Quantity

    @property
    def blocks_to_failure(self) -> float:
        """How many passes of the spectrum until D = 1 (``inf`` for no damage)."""
        return math.inf if self.damage == 0 else 1.0 / self.damage


def _amplitudes(amplitudes: Any) -> np.ndarray:
    if isinstance(amplitudes, list | tuple) and amplitudes and not isinstance(amplitudes[0], int | float):
        return np.array([to_si(a, "pressure", f"amplitude[{i}]") for i, a in enumerate(amplitudes)], float)
    return np.atleast_1d(np.asarray(to_si(amplitudes, "pressure", "amplitudes"), float))


def miner_damage(blocks: Iterable[tuple[Any, float]], curve: LifeCurve) -> MinerResult:
    """``D = sum n_i / N_i`` [-] for blocks of (fully reversed amplitude, cycles n_i) (Ref. 1, Eq. (6-58))."""
    blocks = list(blocks)
    if not blocks:
        raise InputError("blocks: need at least one (amplitude, cycles) pair")
    amps = _amplitudes([b[0] for b in blocks])
    n = np.array([float(b[1]) for b in blocks])
    if np.any(n < 0):
        raise InputError("blocks: cycle counts must be >= 0")
    lives = np.array([curve.life_at(Q(s, "Pa")) for s in amps], float)
    with np.errstate(divide="ignore"):
        d = float(np.sum(np.where(np.isinf(lives), 0.0, n / lives)))
    return MinerResult(d, tuple(lives.tolist()), tuple(n.tolist()), from_si(amps, "pressure"))


def miner_life(fractions: Sequence[float], amplitudes: Any, curve: LifeCurve) -> float:
    """Cycles to failure of a spectrum spending ``fractions[i]`` of its cycles at ``amplitudes[i]``.

    ``N = 1 / sum(alpha_i / N_i)`` (Ref. 1, Eq. (6-58) with n_i = alpha_i N); ``inf`` if no level damages.
    """
    alpha = np.asarray(fractions, float)
    if np.any(alpha < 0) or not math.isclose(float(alpha.sum()), 1.0, rel_tol=1e-6):
        raise InputError(f"fractions: must be >= 0 and sum to 1, got {list(alpha)}")
    amps = _amplitudes(amplitudes)
    if amps.shape != alpha.shape:
        raise InputError("fractions and amplitudes differ in length")
    res = miner_damage(zip(from_si(amps, "pressure"), alpha, strict=True), curve)
    return res.blocks_to_failure


__all__ = ["fatigue_strength_fraction", "BasquinCurve", "MinerResult", "miner_damage", "miner_life", "LifeCurve"]
