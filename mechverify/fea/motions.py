"""Words for the rigid motions a model's supports leave free, shared by the solid/frame (:func:`mechverify.fea.linsolve.
describe_mode`) and plate (:func:`mechverify.fea.plate.check_plate_supported`) messages: positions rounded to the
model's scale and directions snapped to the coordinate axes, so that numerical noise of the null space does not show
("rotation about the line through (150, -0.03794) mm along (0.000253, 1)" is "the line x = 150 mm (along y)";
review 3 finding 7).
"""

from __future__ import annotations

import numpy as np

#: Directions whose components are within this of an axis are that axis.
DIRECTION_TOL = 1e-3
#: Positions are rounded to a power of ten at or below this share of the model's size.
POSITION_SHARE = 1e-3


def resolution(scale: float) -> float:
    """The rounding step [m] of positions in a model of size ``scale`` [m]: the power of ten at or below
    :data:`POSITION_SHARE` of it (0.1 mm for a 300 mm part)."""
    return float(10 ** np.floor(np.log10(max(POSITION_SHARE * scale, 1e-300))))


def length_mm(x: float, scale: float) -> str:
    """A position [m] in mm rounded to the model's :func:`resolution` (``150``, ``4.9`` -> ``5``), no negative
    zero."""
    r = resolution(scale)
    v = round(float(x) / r) * r * 1e3
    digits = max(0, -int(np.floor(np.log10(r * 1e3))))
    return f"{round(v, digits) + 0.0:g}"


def point_mm(p: np.ndarray, scale: float) -> str:
    """``(150, 5, 5)`` (mm) of a point [m]."""
    return "(" + ", ".join(length_mm(c, scale) for c in p) + ")"


def snap_direction(d: np.ndarray) -> np.ndarray:
    """A unit direction with components below :data:`DIRECTION_TOL` set to zero (then normalised again)."""
    d = np.asarray(d, dtype=float) / np.linalg.norm(d)
    d = np.where(np.abs(d) < DIRECTION_TOL, 0.0, d)
    return d / np.linalg.norm(d)


def axis_name(d: np.ndarray) -> str | None:
    """``"x"``, ``"y"`` or ``"z"`` when the (snapped) direction is a coordinate axis, else None."""
    d = snap_direction(d)
    k = int(np.argmax(np.abs(d)))
    return "xyz"[k] if abs(abs(d[k]) - 1) < 1e-12 else None


def direction_words(d: np.ndarray) -> str:
    """``"(0.6, 0.8, 0)"`` of a snapped direction, its first non-zero component positive (a line has no sense)."""
    d = snap_direction(d)
    d = -d if d[np.flatnonzero(d)[0]] < 0 else d
    return "(" + ", ".join(f"{c + 0.0:.3g}" for c in d) + ")"


def rotation_words(axis: np.ndarray, point: np.ndarray, scale: float) -> str:
    """A rotation about the line through ``point`` [m] along ``axis``, in 2D (a plate's line in its plane) or 3D:
    "the line x = 150 mm (along y)" / "an axis parallel to x through (150, 5, 5) mm"."""
    d = snap_direction(axis)
    p = np.asarray(point, dtype=float)
    name = axis_name(d)
    if p.size == 2:
        if name is not None:
            other = 1 - "xy".index(name)
            return f"the line {'xy'[other]} = {length_mm(p[other], scale)} mm (along {name})"
        return f"the line through {point_mm(p, scale)} mm along {direction_words(d)}"
    if name is not None:
        return f"an axis parallel to {name} through {point_mm(p, scale)} mm"
    return f"the axis {direction_words(d)} through {point_mm(p, scale)} mm"
