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
    """No value in the allowed range brings the check to u·SF = 1 (or the design cannot be evaluated there).

    ``data``: what the scan found when there is no crossing (the scan points, their u·SF, or None where the
    design is invalid, and the first invalid point's reason), for ``--json``; empty otherwise."""

    def __init__(self, message: str, data: dict[str, Any] | None = None):
        super().__init__(message)
        self.data = dict(data or {})


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
        """(limit − today) / today: +0.25 means today's value may grow by 25 % before the limit. For a value in an
        offset unit (degC, degF) on its absolute scale (kelvin): a percentage of a Celsius reading means nothing."""
        if self._offset():
            from mechverify.units import ureg

            lim, now = (ureg.Quantity(x, self.unit).to("K").magnitude for x in (self.limit, self.today))
            return (lim - now) / now if now else math.inf
        return (self.limit - self.today) / self.today if self.today else math.inf

    def _offset(self) -> bool:
        """Whether the unit is an offset one (degC, degF): its readings are not proportional to the quantity."""
        if not self.unit:
            return False
        try:
            from mechverify.units import ureg

            return not ureg.Quantity(1.0, self.unit)._is_multiplicative
        except Exception:  # (not a pint unit: a plain label)
            return False

    def text(self) -> str:
        u = f" {self.unit}" if self.unit else ""
        side = "passes" if self.today_fu <= 1 else "fails"
        lines = [f"{self.parameter}: limit {self.limit:.6g}{u} ({self.until} u·SF = 1; "
                 f"governing there: {self.governing})",
                 f"today {self.today:.6g}{u}: u·SF = {self.today_fu:.4g} ({side}); {self.margin_text()}"]
        if len(self.limits) > 1:
            lines.append("other crossings in the range: " + ", ".join(f"{x:.6g}{u}" for x in self.limits
                                                                        if x != self.limit))
        return "\n".join(lines)

    def margin_text(self) -> str:
        """The margin in words, its sign spelt out: 'the limit is 7.3 % below today's value: it may fall by
        7.3 % before u·SF reaches 1' (passes today) or '... it must fall by 58.3 % for u·SF to reach 1' (fails)."""
        m = self.margin
        if self._offset():  # (a difference of temperatures, not a percentage of a reading: review 4 finding 18)
            diff = self.limit - self.today
            if diff == 0:
                return "today's value is the limit"
            delta = {"degC": "K", "degree_Celsius": "K", "celsius": "K"}.get(self.unit, f"{self.unit} (a difference)")
            way, verb = ("above", "rise") if diff > 0 else ("below", "fall")
            by = f"{abs(diff):.4g} {delta}"
            if self.today_fu <= 1:
                return f"the limit is {by} {way} today's value: it may {verb} by {by} before u·SF reaches 1"
            return f"the limit is {by} {way} today's value: it must {verb} by {by} for u·SF to come down to 1"
        if not math.isfinite(m):  # (no percentage of zero: the limit itself)
            u = f" {self.unit}" if self.unit else ""
            verb = "rise" if self.limit > 0 else "fall"
            if self.today_fu <= 1:
                return f"today's value is zero: it may {verb} to {self.limit:.6g}{u} before u·SF reaches 1"
            return f"today's value is zero: it must {verb} to {self.limit:.6g}{u} for u·SF to come down to 1"
        if m == 0:
            return "today's value is the limit"
        pct = f"{abs(m):.1%}".replace("%", " %")
        if self.today < 0 < self.limit or self.limit < 0 < self.today:
            way = "above" if self.limit > self.today else "below"
            goal = "reach 1" if self.today_fu <= 1 else "come down to 1"
            return (f"the limit lies {way} today's value, on the other side of zero: it changes sign before u·SF "
                    f"can {goal}")
        # m = (limit - today) / today: for two negative values its sign is that of the change in magnitude
        size = " in magnitude" if self.today < 0 else ""
        way, verb = ("above", "rise") if m > 0 else ("below", "fall")
        if self.today < 0:
            way, verb = ("above", "grow") if m > 0 else ("below", "shrink")
        if self.today_fu <= 1:
            return f"the limit is {pct} {way} today's value{size}: it may {verb} by {pct} before u·SF reaches 1"
        return f"the limit is {pct} {way} today's value{size}: it must {verb} by {pct} for u·SF to come down to 1"

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
    """Solve u·SF(x) = 1 for the parameter ``vary`` within ``bounds`` (default: today's value / 10 .. × 10; a
    temperature in degC or degF: today's value ± 100 degrees)."""
    doc, path, loaded = design_and_source(design)
    p = Parameter.of(doc, vary, None if loaded is None else resolver(loaded))
    if bounds is None and p.offset:  # (a tenth of 70 degC is not a temperature ten times lower)
        from mechverify.units import ureg

        zero = float(ureg.Quantity(1e-6, "K").to(p.unit).magnitude)  # (not below absolute zero)
        lo, hi = max(p.base - 100.0, zero), p.base + 100.0
    elif bounds is None:
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
    reasons: list[str] = []
    for x in xs:
        rec = run(float(x))
        vals.append(fu(rec) - 1.0 if rec["status"] == "ok" else None)
        reasons.append("" if rec["status"] == "ok" else _reason(rec["message"]))
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
        raise _no_crossing(vary, name, p, xs, vals, reasons, unit)
    limit = min(roots, key=lambda r: abs(r - p.base))
    at = run(limit)
    gov = max(at["checks"].items(), key=lambda kv: math.inf if kv[1]["fu"] is None else kv[1]["fu"])[0]
    return SizingResult(vary, p.unit, check, p.base, fu(base), limit, gov, tuple(roots), (lo, hi), calls[0])


def _reason(message: str) -> str:
    """An invalid scan point's error on one line: of a design file's error list the first (the cause, not the
    cascade that follows from it) and how many there are, as the study's console line
    (:func:`mechverify.studies.study._last_line`)."""
    from mechverify.studies.study import _last_line

    return _last_line(message) or message


def _span(xs: Sequence[float], unit: str) -> str:
    return f"{xs[0]:.6g}{unit}" if len(xs) == 1 else f"{xs[0]:.6g}..{xs[-1]:.6g}{unit}"


def _no_crossing(vary: str, name: str, p: Parameter, xs: np.ndarray, vals: Sequence[float | None],
                 reasons: Sequence[str], unit: str) -> SizingError:
    """The error for a scan without a crossing: u·SF at both ends, on which side of 1 the VALID points lie
    (all above: the design fails wherever it can be evaluated), and where and why the design is invalid."""
    lo, hi = float(xs[0]), float(xs[-1])
    ends = ", ".join(f"{'invalid' if v is None else f'{v + 1:.4g}'} at {x:.6g}{unit}"
                     for x, v in ((xs[0], vals[0]), (xs[-1], vals[-1])))
    good = [float(x) for x, v in zip(xs, vals) if v is not None]
    bad = [float(x) for x, v in zip(xs, vals) if v is None]
    data: dict[str, Any] = {"parameter": vary, "unit": p.unit, "limit": None, "today": p.base,
                            "bounds": [lo, hi], "scan": [{"value": float(x), "fu": None if v is None else v + 1,
                                                          "invalid": r or None}
                                                         for x, v, r in zip(xs, vals, reasons)]}
    if not good:
        first = next(r for r in reasons if r)
        return SizingError(f"no limit of {vary} in {lo:.6g}..{hi:.6g}{unit}: the design is invalid at every one of "
                           f"the {len(xs)} scan points ({first}); change the bounds", data)
    fin = [v for v in vals if v is not None]
    if all(v > 0 for v in fin):
        side = "above 1 (fails)"
    elif all(v < 0 for v in fin):
        side = "below 1 (passes)"
    else:
        side = "on both sides of 1 with invalid points between"
    where = "over the range" if not bad else f"over the valid part ({_span(good, unit)})"
    text = f"{ends}; {side} {where}"
    if bad:
        first = next(r for r in reasons if r)
        text += f"; invalid at {len(bad)} of {len(xs)} scan points ({_span(bad, unit)}): {first}"
    data["side"] = side.split(" (")[0]
    return SizingError(f"no limit of {vary} in {lo:.6g}..{hi:.6g}{unit}: {name} does not cross 1 ({text}); "
                       "widen the bounds or vary another parameter", data)
