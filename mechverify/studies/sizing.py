"""Sizing: the value of one parameter at which a check's factored utilisation u·SF reaches 1.

``size(design, vary="components.lift.mass", until="lift.motor_peak_torque", bounds=("1 kg", "100 kg"))``
scans the range at ``scan + 1`` evenly spaced values, and in every interval where u·SF − 1 changes
sign solves u·SF(x) = 1 with Brent's method (:func:`scipy.optimize.brentq`). ``until="governing"``
uses the largest u·SF of all checks (the governing check may change along the range). The limit
reported is the crossing nearest today's value (all crossings are kept); the margin of today's
value is (limit − today)/today. No crossing in the range is a :class:`SizingError` giving u·SF at
both ends.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError, UnknownNameError
from mechverify.studies.execution import evaluate
from mechverify.studies.params import Parameter, resolver
from mechverify.studies.study import design_and_source


class SizingError(InputError):
    """No value in the allowed range brings the check to u·SF = 1 (or the design cannot be evaluated there)."""


@dataclass(frozen=True)
class SizingResult:
    """The limit value of ``parameter`` (in ``unit``) and what governs there."""

    parameter: str
    unit: str
    until: str  # the check solved for, or "governing"
    today: float
    today_fu: float
    limit: float
    governing: str  # the check with the largest u·SF at the limit
    limits: tuple[float, ...]  # every crossing found in the range
    bounds: tuple[float, float]
    evaluations: int

    @property
    def margin(self) -> float:
        """(limit − today) / today: +0.25 means today's value may grow by 25 % before the limit."""
        return (self.limit - self.today) / self.today if self.today else math.inf

    def text(self) -> str:
        u = f" {self.unit}" if self.unit else ""
        side = "passes" if self.today_fu <= 1 else "fails"
        lines = [f"{self.parameter}: limit {self.limit:.6g}{u} ({self.until} u·SF = 1; "
                 f"governing there: {self.governing})",
                 f"today {self.today:.6g}{u}: u·SF = {self.today_fu:.4g} ({side}); "
                 f"margin {self.margin:+.1%} to the limit"]
        if len(self.limits) > 1:
            lines.append("other crossings in the range: " + ", ".join(f"{x:.6g}{u}" for x in self.limits
                                                                        if x != self.limit))
        return "\n".join(lines)

    def to_dict(self) -> dict[str, Any]:
        return {"parameter": self.parameter, "unit": self.unit, "until": self.until, "today": self.today,
                "today_fu": self.today_fu, "limit": self.limit, "governing": self.governing,
                "limits": list(self.limits), "bounds": list(self.bounds), "margin": self.margin,
                "evaluations": self.evaluations}


def _resolve_check(until: str, checks: Sequence[str]) -> str:
    if until == "governing" or until in checks:
        return until
    matches = [c for c in checks if c.split(".", 1)[-1] == until]
    if len(matches) == 1:
        return matches[0]
    if len(matches) > 1:
        raise InputError(f"until: {until!r} runs on several components ({', '.join(matches)}); name one")
    raise UnknownNameError("check (component.check, or 'governing')", until, list(checks))


def size(design: Any, vary: str, until: str = "governing", bounds: Sequence[Any] | None = None, *,
         scan: int = 8, xtol: float | None = None) -> SizingResult:
    """Solve u·SF(x) = 1 for the parameter ``vary`` within ``bounds`` (default: today's value / 10 .. × 10)."""
    doc, path, loaded = design_and_source(design)
    p = Parameter.of(doc, vary, None if loaded is None else resolver(loaded))
    if bounds is None:
        if not p.base > 0:
            raise InputError(f"bounds: give the range to search for {vary} (today's value is {p.base:g})")
        lo, hi = p.base / 10, p.base * 10
    else:
        if len(bounds) != 2:
            raise InputError(f"bounds: expected (low, high), got {bounds!r}")
        lo, hi = p.value(bounds[0]), p.value(bounds[1])
    if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
        raise InputError(f"bounds: expected low < high, got {lo:g} .. {hi:g}")
    if not (isinstance(scan, int) and scan >= 1):
        raise InputError(f"scan: expected a positive integer, got {scan!r}")
    calls = [0]

    def run(x: float) -> dict[str, Any]:
        calls[0] += 1
        return evaluate(doc, path, {vary: p.text(x)})

    base = run(p.base)
    if base["status"] != "ok":
        raise SizingError(f"the design cannot be evaluated at today's value: {base['message']}")
    check = _resolve_check(until, list(base["checks"]))

    def fu(rec: dict[str, Any]) -> float:
        if check == "governing":
            vals = [math.inf if c["fu"] is None else c["fu"] for c in rec["checks"].values()]
            return max(vals) if vals else 0.0
        c = rec["checks"].get(check)
        if c is None:
            raise SizingError(f"{check} did not run")
        return math.inf if c["fu"] is None else c["fu"]

    def g(x: float) -> float:
        rec = run(x)
        if rec["status"] != "ok":
            raise SizingError(f"{vary} = {p.text(x)}: the design cannot be evaluated: {rec['message']}")
        return fu(rec) - 1.0

    xs = np.linspace(lo, hi, scan + 1)
    vals: list[float | None] = []
    for x in xs:
        rec = run(float(x))
        vals.append(fu(rec) - 1.0 if rec["status"] == "ok" else None)
    roots: list[float] = []
    tol = xtol if xtol is not None else 1e-10 * max(abs(lo), abs(hi))
    from scipy.optimize import brentq

    for a, b, fa, fb in zip(xs[:-1], xs[1:], vals[:-1], vals[1:]):
        if fa is None or fb is None:
            continue
        if fa == 0:
            roots.append(float(a))
        elif fa * fb < 0 and math.isfinite(fa) and math.isfinite(fb):
            roots.append(float(brentq(g, float(a), float(b), xtol=tol, rtol=4 * np.finfo(float).eps)))
    if vals[-1] == 0:
        roots.append(float(xs[-1]))
    name = "the governing u·SF" if check == "governing" else f"u·SF of {check}"
    unit = f" {p.unit}" if p.unit else ""
    if not roots:
        ends = ", ".join(f"{'invalid' if v is None else f'{v + 1:.4g}'} at {x:.6g}{unit}"
                         for x, v in ((xs[0], vals[0]), (xs[-1], vals[-1])))
        bad = sum(v is None for v in vals)
        where = "above 1" if vals[0] is not None and vals[0] > 0 else "below 1"
        raise SizingError(f"no limit of {vary} in {lo:.6g}..{hi:.6g}{unit}: {name} does not cross 1 "
                          f"({ends}; {where} over the range" + (f", {bad} of {len(xs)} scan points invalid" if bad
                                                               else "") + "); widen the bounds or vary another "
                          "parameter")
    limit = min(roots, key=lambda r: abs(r - p.base))
    at = run(limit)
    gov = max(at["checks"].items(), key=lambda kv: math.inf if kv[1]["fu"] is None else kv[1]["fu"])[0]
    return SizingResult(vary, p.unit, check, p.base, fu(base), limit, gov, tuple(roots), (lo, hi), calls[0])
