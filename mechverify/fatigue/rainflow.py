"""Rainflow counting of a sampled load (or stress) history, ASTM E1049-85 (reapproved 2017), Sec. 5.4.4.

Public API::

    reversals(history) -> ndarray                 # peaks and valleys, plateaus and non-reversals removed
    rainflow(history) -> list[Cycle]              # each Cycle(range, mean, count), count 1.0 or 0.5
    rainflow_table(history) -> dict[range, count] # counts summed by range

Works on plain numbers (any unit, the caller's) or on a pint quantity array (ranges and means come
back as quantities of the same unit). The three-point method: with X the range under
consideration and Y the previous range, when X >= Y a range Y containing the starting point is a
half cycle (the start point is dropped), otherwise a full cycle (both its points are dropped);
the ranges left at the end are half cycles.

Reference: ASTM E1049-85 (Reapproved 2017), *Standard Practices for Cycle Counting in Fatigue
Analysis*, Sec. 5.4.4 and Fig. 6 (example history and its count).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.units import Quantity


@dataclass(frozen=True)
class Cycle:
    """One counted cycle: its range (max - min), mean ((max + min)/2), and count (1.0 or 0.5)."""

    range: Any
    mean: Any
    count: float

    @property
    def amplitude(self) -> Any:
        return self.range / 2


def _values(history: Any) -> tuple[np.ndarray, Any]:
    unit = None
    if isinstance(history, Quantity):
        unit, history = history.units, history.magnitude
    h = np.asarray(history, dtype=float).ravel()
    if h.size < 2:
        raise InputError("history: need at least two samples")
    if not np.all(np.isfinite(h)):
        raise InputError("history: contains NaN or infinite samples")
    return h, unit


def reversals(history: Any) -> np.ndarray:
    """The peaks and valleys of ``history`` (first and last samples kept), in the history's unit."""
    h, unit = _values(history)
    h = h[np.concatenate(([True], np.diff(h) != 0))]  # plateaus -> one point
    if h.size < 3:
        out = h
    else:
        d = np.diff(h)
        turn = np.sign(d[1:]) != np.sign(d[:-1])
        out = np.concatenate(([h[0]], h[1:-1][turn], [h[-1]]))
    return Quantity(out, unit) if unit is not None else out


def _count(points: np.ndarray) -> list[tuple[float, float, float]]:
    stack: list[float] = []
    cycles: list[tuple[float, float, float]] = []
    for p in points:
        stack.append(float(p))
        while len(stack) >= 3:
            x = abs(stack[-1] - stack[-2])
            y = abs(stack[-2] - stack[-3])
            if x < y:
                break
            a, b = stack[-3], stack[-2]
            if len(stack) == 3:  # Y contains the starting point S = stack[0]: half cycle, drop S
                cycles.append((y, (a + b) / 2.0, 0.5))
                stack.pop(0)
            else:  # full cycle, drop both points of Y
                cycles.append((y, (a + b) / 2.0, 1.0))
                del stack[-3:-1]
    for a, b in zip(stack[:-1], stack[1:], strict=False):
        cycles.append((abs(b - a), (a + b) / 2.0, 0.5))
    return cycles


def rainflow(history: Any) -> list[Cycle]:
    """Rainflow cycles of ``history`` in the order ASTM E1049 counts them (Sec. 5.4.4)."""
    _, unit = _values(history)
    pts = reversals(history)
    pts = pts.magnitude if isinstance(pts, Quantity) else pts
    out = []
    for rng, mean, count in _count(pts):
        if unit is not None:
            out.append(Cycle(Quantity(rng, unit), Quantity(mean, unit), count))
        else:
            out.append(Cycle(rng, mean, count))
    return out


def rainflow_table(history: Any, decimals: int = 9) -> dict[float, float]:
    """Counts summed by range (ranges rounded to ``decimals``; magnitudes in the history's unit)."""
    table: dict[float, float] = defaultdict(float)
    for c in rainflow(history):
        r = c.range.magnitude if isinstance(c.range, Quantity) else c.range
        table[round(float(r), decimals)] += c.count
    return dict(sorted(table.items()))


__all__ = ["Cycle", "reversals", "rainflow", "rainflow_table"]
