"""Column buckling of centrally loaded straight members: Euler, J. B. Johnson, end conditions.

Formulas (Shigley 10th ed., Sec. 4-11 to 4-13; equation numbers as in that edition):

* Euler (long columns), Eq. (4-42)/(4-43): ``P_cr = C pi^2 E I / l^2``
* transition slenderness, Eq. (4-45): ``(l/k)_1 = sqrt(2 pi^2 C E / S_y)`` where the Euler stress is ``S_y/2``
* J. B. Johnson parabola (intermediate columns, ``l/k <= (l/k)_1``), Eq. (4-46):
  ``P_cr / A = S_y - (S_y l / (2 pi k))^2 / (C E)``

``k = sqrt(I/A)`` is the radius of gyration about the buckling axis (the weak axis unless the ends
restrain it differently) and ``C`` the end-condition constant of Table 4-2 (data file
``components/data/column_end_conditions.toml``); the effective-length factor is ``K = 1/sqrt(C)``.

``end`` is a name (``"pinned-pinned"``, ``"fixed-free"``, ``"fixed-pinned"``, ``"fixed-fixed"`` and
aliases such as ``"rounded-rounded"``) or a number, taken as ``C`` itself. ``basis`` picks the column
of Table 4-2: ``"recommended"`` (default, Shigley's design values), ``"theoretical"`` or ``"conservative"``.

References
----------
1. R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill,
   2015, Sec. 4-11 to 4-13, Eqs. (4-42) to (4-46), Table 4-2.
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import pint

from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.units import QuantityLike, from_si, require_positive, to_si

_DATA = Path(__file__).parent / "data" / "column_end_conditions.toml"
BASES = ("recommended", "theoretical", "conservative")
SOURCE = "Shigley's Mechanical Engineering Design, 10th ed., Sec. 4-11 to 4-13, Eqs. (4-43), (4-45), (4-46), Table 4-2"


@dataclass(frozen=True)
class EndCondition:
    """One row of Shigley Table 4-2."""

    name: str
    theoretical: float
    conservative: float
    recommended: float
    aliases: tuple[str, ...] = ()

    def C(self, basis: str = "recommended") -> float:
        if basis not in BASES:
            raise UnknownNameError("end-condition basis", basis, BASES)
        return float(getattr(self, basis))


def _norm(name: str) -> str:
    return re.sub(r"[\s_]+", "-", name.strip().lower())


@cache
def _table() -> tuple[dict[str, EndCondition], dict[str, str]]:
    with _DATA.open("rb") as fh:
        data = tomllib.load(fh)
    rows, keys = {}, {}
    for name, row in data["end_condition"].items():
        ec = EndCondition(name=name, theoretical=float(row["theoretical"]), conservative=float(row["conservative"]),
                          recommended=float(row["recommended"]), aliases=tuple(row.get("aliases", ())))
        rows[name] = ec
        for k in (name, *ec.aliases):
            keys[_norm(k)] = name
    return rows, keys


def end_conditions() -> dict[str, EndCondition]:
    """All end cases of Shigley Table 4-2 by primary name."""
    return dict(_table()[0])


def end_condition(end: str) -> EndCondition:
    """The row of Table 4-2 for an end-case name or alias (``UnknownNameError`` with suggestions)."""
    rows, keys = _table()
    if not isinstance(end, str):
        raise InputError(f"end: expected an end-case name or a number C, got {type(end).__name__}")
    key = keys.get(_norm(end))
    if key is None:
        raise UnknownNameError("column end condition", end, list(keys))
    return rows[key]


def end_condition_constant(end: str | float, basis: str = "recommended") -> float:
    """End-condition constant ``C`` [-] (Shigley 10th ed., Table 4-2); a number passes through as C."""
    if isinstance(end, int | float) and not isinstance(end, bool):
        C = float(end)
        if not (C > 0 and math.isfinite(C)):
            raise InputError(f"end: an end-condition constant C must be positive, got {end!r}")
        return C
    return end_condition(end).C(basis)


def effective_length_factor(end: str | float, basis: str = "recommended") -> float:
    """Effective-length factor ``K = 1/sqrt(C)`` [-]: ``l_eff = K l`` (Shigley 10th ed., Sec. 4-12)."""
    return 1.0 / math.sqrt(end_condition_constant(end, basis))


def _check(E: float, I: float, length: float, A: float | None = None, Sy: float | None = None) -> None:
    require_positive(E, "E", dim="pressure")
    require_positive(I, "I", dim="second_moment")
    require_positive(length, "length", dim="length")
    if A is not None:
        require_positive(A, "A", dim="area")
    if Sy is not None:
        require_positive(Sy, "Sy", dim="pressure")


def radius_of_gyration(A: QuantityLike, I: QuantityLike) -> pint.Quantity:
    """``k = sqrt(I/A)`` [m]."""
    a, i = to_si(A, "area", "A"), to_si(I, "second_moment", "I")
    require_positive(a, "A", dim="area")
    require_positive(i, "I", dim="second_moment")
    return from_si(math.sqrt(i / a), "length")


def slenderness_ratio(length: QuantityLike, A: Any, I: Any) -> pint.Quantity:
    """``l/k`` [-] with the actual (not effective) length, as Shigley uses it with ``C``."""
    L = to_si(length, "length", "length")
    require_positive(L, "length", dim="length")
    return from_si(L / radius_of_gyration(A, I).m_as("m"), "dimensionless")


def euler_critical_load(E: QuantityLike, I: QuantityLike, length: QuantityLike, end: str | float = "pinned-pinned",
                        basis: str = "recommended") -> pint.Quantity:
    """Euler critical load ``P_cr = C pi^2 E I / l^2`` [N] (Shigley 10th ed., Eq. (4-42)).

    Valid for long columns, ``l/k >= (l/k)_1`` (see :func:`transition_slenderness`); for shorter
    columns it overestimates the load: use :func:`critical_load`.
    """
    e, i, L = to_si(E, "pressure", "E"), to_si(I, "second_moment", "I"), to_si(length, "length", "length")
    _check(e, i, L)
    C = end_condition_constant(end, basis)
    return from_si(C * math.pi**2 * e * i / L**2, "force")


def transition_slenderness(E: QuantityLike, Sy: QuantityLike, end: str | float = "pinned-pinned",
                           basis: str = "recommended") -> pint.Quantity:
    """``(l/k)_1 = sqrt(2 pi^2 C E / S_y)`` [-] (Shigley 10th ed., Eq. (4-45)).

    Below it the J. B. Johnson parabola applies, above it Euler's formula.
    """
    e, sy = to_si(E, "pressure", "E"), to_si(Sy, "pressure", "Sy")
    require_positive(e, "E", dim="pressure")
    require_positive(sy, "Sy", dim="pressure")
    C = end_condition_constant(end, basis)
    return from_si(math.sqrt(2 * math.pi**2 * C * e / sy), "dimensionless")


def johnson_critical_load(E: QuantityLike, Sy: QuantityLike, A: QuantityLike, I: QuantityLike, length: QuantityLike,
                          end: str | float = "pinned-pinned",
                          basis: str = "recommended") -> pint.Quantity:
    """J. B. Johnson critical load ``P_cr = A [S_y - (S_y l/(2 pi k))^2 / (C E)]`` [N] (Shigley 10th ed., Eq. (4-46)).

    Valid for ``l/k <= (l/k)_1``; beyond it the parabola is not defined (:class:`ValidityError`).
    """
    e, sy = to_si(E, "pressure", "E"), to_si(Sy, "pressure", "Sy")
    a, i, L = to_si(A, "area", "A"), to_si(I, "second_moment", "I"), to_si(length, "length", "length")
    _check(e, i, L, a, sy)
    C = end_condition_constant(end, basis)
    lk = L / math.sqrt(i / a)
    lk1 = math.sqrt(2 * math.pi**2 * C * e / sy)
    if lk > lk1 * (1 + 1e-12):
        raise ValidityError(f"Johnson parabola valid for l/k <= (l/k)_1 = {lk1:.4g}; this column has "
                            f"l/k = {lk:.4g} (a long column: use euler_critical_load or critical_load)")
    return from_si(a * (sy - (sy * lk / (2 * math.pi)) ** 2 / (C * e)), "force")


@dataclass(frozen=True)
class ColumnBuckling:
    """Result of :func:`column_buckling`: the critical load and how it was obtained."""

    critical_load: pint.Quantity  # [N]
    regime: str  # "euler" or "johnson"
    slenderness: float  # l/k
    transition_slenderness: float  # (l/k)_1
    C: float  # end-condition constant used
    end: str  # end-case name (or "C = x")
    basis: str
    effective_length: pint.Quantity  # l / sqrt(C)
    radius_of_gyration: pint.Quantity
    critical_stress: pint.Quantity  # P_cr / A
    source: str = SOURCE


def column_buckling(E: QuantityLike, Sy: QuantityLike, A: QuantityLike, I: QuantityLike, length: QuantityLike,
                    end: str | float = "pinned-pinned",
                    basis: str = "recommended") -> ColumnBuckling:
    """Critical load choosing Euler (``l/k > (l/k)_1``) or Johnson (``l/k <= (l/k)_1``), with the details.

    ``I`` is the second moment about the buckling axis (normally the least one). Shigley 10th ed.,
    Sec. 4-12/4-13.
    """
    e, sy = to_si(E, "pressure", "E"), to_si(Sy, "pressure", "Sy")
    a, i, L = to_si(A, "area", "A"), to_si(I, "second_moment", "I"), to_si(length, "length", "length")
    _check(e, i, L, a, sy)
    C = end_condition_constant(end, basis)
    k = math.sqrt(i / a)
    lk = L / k
    lk1 = math.sqrt(2 * math.pi**2 * C * e / sy)
    if lk > lk1:
        regime, P = "euler", C * math.pi**2 * e * i / L**2
    else:
        regime, P = "johnson", a * (sy - (sy * lk / (2 * math.pi)) ** 2 / (C * e))
    name = f"C = {C:g}" if isinstance(end, int | float) else end_condition(end).name
    return ColumnBuckling(critical_load=from_si(P, "force"), regime=regime, slenderness=lk,
                          transition_slenderness=lk1, C=C, end=name, basis=basis,
                          effective_length=from_si(L / math.sqrt(C), "length"),
                          radius_of_gyration=from_si(k, "length"), critical_stress=from_si(P / a, "pressure"))


def critical_load(E: Any, Sy: Any, A: Any, I: Any, length: Any, end: str | float = "pinned-pinned",
                  basis: str = "recommended") -> pint.Quantity:
    """Critical load [N]: Euler or Johnson by slenderness (see :func:`column_buckling`)."""
    return column_buckling(E, Sy, A, I, length, end, basis).critical_load


__all__ = ["EndCondition", "ColumnBuckling", "end_conditions", "end_condition", "end_condition_constant",
           "effective_length_factor", "radius_of_gyration", "slenderness_ratio", "euler_critical_load",
           "transition_slenderness", "johnson_critical_load", "column_buckling", "critical_load"]
