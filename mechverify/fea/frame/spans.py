"""Spans and support motion of a frame's deflection check (review 4 findings 15 and 19; the ``frame`` design-file
type's ``frame_deflection``).

- :func:`span_of` - the span of a fractional limit ("L/250"): on a straight beam the span that holds the point of
  largest deflection (between the two supports around it, or an overhang), else the given default.
- :func:`moving_supports` - a note (and a WARN when the governing point is one) when supports move in a load case
  (a settlement, a spring), with the deflection relative to the line through the supports' translations.
- :func:`straight_line` - the line all members and supports lie on, if any.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mechverify.errors import MechverifyError
from mechverify.units import Q


def span_of(frame: Any, res: Any, span: Any, given: bool) -> tuple[Any, str]:
    """(span, how it was found) for a fractional deflection limit in one load case's results ``res``: the
    ``span`` field; on a straight beam (members and supports on one line) the span that holds the point of
    largest deflection - between the two supports around it, or an overhang beyond the last one (review 4
    finding 15: a two-span continuous beam took its whole length); else the largest distance from a support to
    a member end."""
    if given:
        return span, "the 'span' field"
    line = straight_line(frame)
    if line is None:
        n = len(frame.supports)
        more = (f"; with {n} supports the span a limit means may be shorter: give span" if n > 2 else "")
        return span, f"the largest distance from a support to a member end ({span:.4g~P}){more}"
    o, d, ts, lo, hi = line
    t = float((res.max_displacement.location.m_as("m") - o) @ d)
    tol = 1e-9 * (hi - lo)
    left, right = [s for s in ts if s <= t + tol], [s for s in ts if s >= t - tol]
    if left and right and min(right) - max(left) > tol:
        a, b = max(left), min(right)
        how = "between the supports"
    elif left and right:  # the largest deflection at a support (it moves): the longer span next to it
        nxt = [(x, y) for x, y in zip(ts, ts[1:], strict=False) if x - tol <= t <= y + tol and y - x > tol]
        a, b = max(nxt or [(lo, hi)], key=lambda ab: ab[1] - ab[0])
        how = "between the supports"
    else:
        a, b = (hi, max(ts)) if left else (lo, min(ts))
        a, b = min(a, b), max(a, b)
        how = "of the overhang beyond the last support"
    span = Q((b - a) * 1e3, "mm")
    return span, f"span {span.m:.4g} mm {how} (the straight beam's span holding the largest deflection)"


def straight_line(frame: Any) -> tuple[Any, Any, list[float], float, float] | None:
    """(origin, unit direction, the supports' positions along it sorted, the members' extent lo, hi) [m] when every
    member end and support lies on one straight line (a beam, continuous or not); else None."""
    pts = np.array([p for e in frame.ends for p in e], float)
    if len(pts) < 2 or not frame.supports:
        return None
    o = pts[0]
    far = pts[int(np.argmax(np.linalg.norm(pts - o, axis=1)))]
    length = float(np.linalg.norm(far - o))
    if length == 0:
        return None
    d = (far - o) / length
    sup = np.array([frame.point(s.at) for s in frame.supports], float)
    every = np.vstack([pts, sup])
    rel = every - o
    if np.max(np.linalg.norm(rel - np.outer(rel @ d, d), axis=1)) > 1e-6 * length:
        return None
    t = pts @ d - o @ d
    return o, d, sorted(float(x) for x in (sup - o) @ d), float(t.min()), float(t.max())


def moving_supports(frame: Any, res: Any) -> tuple[str | None, str | None]:
    """(note, WARN) when supports move in this load case (a settlement, a spring's compression): the largest
    translation counts their motion (review 4 finding 19: a 6 mm settlement at B was 'deflection 6.00 mm', the
    beam's bending deflection relative to its supports 0.098 mm). On a straight beam the note gives the deflection
    relative to the chord through the supports around each point; a WARN when the governing point is a moving
    support itself."""
    mx = res.max_displacement
    top = float(mx.value.m_as("m"))
    moved = [(k, frame.point(s.at), res.displacement(s.at).m_as("m")) for k, s in enumerate(frame.supports)]
    moved = [(k, x, u) for k, x, u in moved if float(np.linalg.norm(u)) > 1e-9 * max(top, 1e-12) and
             float(np.linalg.norm(u)) > 1e-12]
    if not moved:
        return None, None
    said = ", ".join(f"supports[{k}] by {np.linalg.norm(u) * 1e3:.4g} mm" for k, _, u in moved)
    rel = ""
    line = straight_line(frame)
    if line is not None:
        o, d, _, _, _ = line
        ts = sorted((float((x - o) @ d), res.displacement(s.at).m_as("m")) for s, x in
                    ((s, frame.point(s.at)) for s in frame.supports))
        t_s = np.array([t for t, _ in ts])
        u_s = np.array([u for _, u in ts])
        worst = 0.0
        try:
            for dg in res.diagrams():
                t = (dg.points.m_as("m") - o) @ d
                chord = np.stack([np.interp(t, t_s, u_s[:, i]) for i in range(3)], axis=1)  # flat beyond the ends
                worst = max(worst, float(np.max(np.linalg.norm(dg.displacement.m_as("m") - chord, axis=1))))
            rel = f"; relative to the straight line through the supports' translations the largest deflection is " \
                  f"{worst * 1e3:.4g} mm"
        except MechverifyError:  # (a tabulated section without fibres has no diagrams: the note without the figure)
            rel = ""
    note = f"supports move in this load case ({said}): the largest translation counts their motion{rel}"
    at = [k for k, x, _ in moved if float(np.linalg.norm(mx.location.m_as("m") - x)) <= 1e-9 * max(_extent(frame), 1.0)]
    warn = (f"the largest translation, {top * 1e3:.4g} mm, is the motion of supports[{at[0]}] itself (a settlement or "
            f"a spring), not a deflection of the members{rel}; check the members against the relative deflection"
            if at else None)
    return note, warn


def _extent(frame: Any) -> float:
    """The largest distance between two member ends [m] (a length scale for tolerances)."""
    pts = np.array([p for e in frame.ends for p in e], float)
    return float(np.max(np.linalg.norm(pts - pts[0], axis=1))) if len(pts) else 0.0


__all__ = ["moving_supports", "span_of", "straight_line"]
