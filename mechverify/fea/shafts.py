"""Shaft analysis on the frame FEA: reactions, shear, bending in two planes, torque, slope and deflection,
and the first critical speed by Rayleigh and Dunkerley with deflections from the same model.

The shaft (:class:`mechverify.components.shafts.Shaft`) becomes a :class:`mechverify.fea.frame.Frame` along
global x: one member per interval between segment steps, features, loads, supports and lumped masses, each
a circle or tube section of its segment, Timoshenko elements (exact for prismatic members with point loads
at nodes), so stepped sections, overhangs and more than two bearings are exact. Bearings hold y and z (and
x at the locating one; rotations as well for a fixed support), or act as radial springs; the first
support holds the rotation about x (torques must balance, which the shaft checks). A shaft the bearings
cannot hold is the frame's named error (it names the free motion).

References: Shigley 10th ed. Secs. 7-5 (deflection), 7-6 (Eqs. 7-23, 7-24); the frame package's sources.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from mechverify.components import sections
from mechverify.components.shafts import (
    G_STANDARD,
    Shaft,
    dunkerley_critical_speed,
    rayleigh_critical_speed,
)
from mechverify.errors import InputError, ModelError
from mechverify.fea.frame import Member, PointLoad, Support
from mechverify.units import Q

MASS_PIECES = 4  # lumped masses per segment for the shaft's own mass in the critical speed


@dataclass(frozen=True)
class Reaction:
    """Force a bearing exerts on the shaft [N] (global components) and its radial and axial magnitudes."""

    name: str
    x: float
    force: tuple[float, float, float]
    moment: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def radial(self) -> float:
        return math.hypot(self.force[1], self.force[2])

    @property
    def axial(self) -> float:
        return abs(self.force[0])


@dataclass(frozen=True)
class ShaftAnalysis:
    """Fields along the shaft (SI arrays sorted by x; at a node both sides are kept) and the reactions."""

    shaft: Shaft
    x: np.ndarray
    N: np.ndarray
    Vy: np.ndarray
    Vz: np.ndarray
    My: np.ndarray
    Mz: np.ndarray
    T: np.ndarray
    uy: np.ndarray
    uz: np.ndarray
    reactions: dict[str, Reaction]
    slopes: dict[str, float]  # support name -> resultant slope [rad]
    node_slopes: dict[float, float] = field(default_factory=dict)  # x -> resultant slope [rad]

    @property
    def M(self) -> np.ndarray:
        """Resultant bending moment [N m]."""
        return np.hypot(self.My, self.Mz)

    @property
    def deflection(self) -> np.ndarray:
        """Resultant transverse deflection [m]."""
        return np.hypot(self.uy, self.uz)

    def at(self, x: float) -> dict[str, float]:
        """Largest |M|, |T|, N (the larger tension) and deflection at x over both sides of a node."""
        i = np.flatnonzero(np.abs(self.x - x) < 1e-9)
        if not len(i):
            j = int(np.searchsorted(self.x, x))
            i = np.array([max(j - 1, 0), min(j, len(self.x) - 1)])
        return {"M": float(self.M[i].max()), "T": float(np.abs(self.T[i]).max()), "N": float(self.N[i].max()),
                "deflection": float(self.deflection[i].max())}

    def max_moment(self) -> tuple[float, float]:
        """(x, M) of the largest resultant bending moment (exact: the frame includes stationary points); of a flat
        maximum, the point with the largest torque."""
        M = self.M
        near = np.flatnonzero(M >= M.max() * (1 - 1e-9))  # a flat maximum: the point with the most torque
        k = int(near[np.argmax(np.abs(self.T[near]))])
        return float(self.x[k]), float(M[k])

    def slope_at(self, x: float) -> float:
        """Resultant slope [rad] at a node position x."""
        for k, v in self.node_slopes.items():
            if abs(k - x) < 1e-9:
                return v
        raise InputError(f"shaft {self.shaft.name}: no node at x = {x * 1e3:g} mm")


def _stations(shaft: Shaft, extra: list[float] = ()) -> list[float]:  # type: ignore[assignment]
    xs = set(shaft.boundaries)
    xs.update(s.x for s in shaft.supports)
    xs.update(ld.x for ld in shaft.loads)
    xs.update(f.x for f in shaft.features)
    xs.update(extra)
    out: list[float] = []
    for v in sorted(xs):
        if not out or v - out[-1] > 1e-9:
            out.append(v)
    return out


def _frame(shaft: Shaft, stations: list[float], theory: str = "timoshenko") -> Any:
    from mechverify.fea.frame import Frame

    members = []
    for i in range(len(stations) - 1):
        a, b = stations[i], stations[i + 1]
        seg = shaft.segment_at(0.5 * (a + b))
        sec = sections.tube(Q(seg.diameter, "m"), inner_diameter=Q(seg.bore, "m")) if seg.bore else \
            sections.circle(Q(seg.diameter, "m"))
        members.append(Member(Q([a, 0, 0], "m"), Q([b, 0, 0], "m"), sec, shaft.material, name=f"s{i}"))
    locating = any(s.locating for s in shaft.supports)
    sups = []
    for k, s in enumerate(shaft.supports):
        hold = ["y", "z"] if s.kind != "spring" else []
        if s.kind == "fixed":
            hold += ["ry", "rz"]
        if s.locating or (not locating and k == 0):
            hold.append("x")
        if k == 0:
            hold.append("rx")
        springs = {"y": Q(s.stiffness, "N/m"), "z": Q(s.stiffness, "N/m")} if s.kind == "spring" else {}
        if hold:
            sups.append(Support(Q([s.x, 0, 0], "m"), kind="custom", hold=tuple(hold), springs=springs))
        else:
            sups.append(Support(Q([s.x, 0, 0], "m"), kind="spring", springs=springs))
    return Frame(None, members, sups, theory=theory, name=shaft.name)


def _point_loads(shaft: Shaft, loads: Any = None) -> list[PointLoad]:
    lds = shaft.loads if loads is None else loads
    return [PointLoad(Q([ld.x, 0, 0], "m"), force=Q(list(ld.force), "N"), moment=Q(list(ld.moment), "N*m"))
            for ld in lds]


def _wrap(shaft: Shaft, exc: Exception) -> Exception:
    return type(exc)(f"shaft {shaft.name}: {exc}")


def analyse(shaft: Shaft, theory: str = "timoshenko") -> ShaftAnalysis:
    """Static analysis of the shaft under its loads (weights of given masses included; the shaft's own weight
    is neglected, as in Shigley's examples). ``theory``: "timoshenko" (default) or "euler" (for comparisons
    with Euler-Bernoulli hand calculations).

    Raises:
        InputError: the bearings do not hold the shaft (the frame names the free motion).
    """
    st = _stations(shaft)
    try:
        fr = _frame(shaft, st, theory)
        res = fr.solve(_point_loads(shaft), name="shaft")
    except (InputError, ModelError) as exc:  # the frame names the free motion of an unsupported shaft
        raise _wrap(shaft, exc) from None
    parts: dict[str, list[np.ndarray]] = {k: [] for k in ("x", "N", "Vy", "Vz", "My", "Mz", "T", "uy", "uz")}
    for i in range(len(st) - 1):
        d = res.diagram(f"s{i}", points_per_element=21)
        parts["x"].append(st[i] + d.s.m_as("m"))
        for k in ("N", "Vy", "Vz", "My", "Mz"):
            parts[k].append(getattr(d, k).m_as("N" if k[0] in "NV" else "N*m"))
        parts["T"].append(d.T.m_as("N*m"))
        disp = d.displacement.m_as("m")
        parts["uy"].append(disp[:, 1])
        parts["uz"].append(disp[:, 2])
    arr = {k: np.concatenate(v) for k, v in parts.items()}
    reac_q = res.reactions
    reactions: dict[str, Reaction] = {}
    keys = list(reac_q)
    for k, s in enumerate(shaft.supports):
        f, m = reac_q[keys[k]]
        reactions[s.name] = Reaction(s.name, s.x, tuple(float(c) for c in f.m_as("N")),  # type: ignore[arg-type]
                                     tuple(float(c) for c in m.m_as("N*m")))  # type: ignore[arg-type]
    node_slopes = {}
    for x in st:
        r = res.rotation(Q([x, 0, 0], "m")).m_as("rad")
        node_slopes[x] = float(math.hypot(r[1], r[2]))
    slopes = {s.name: node_slopes[min(node_slopes, key=lambda v: abs(v - s.x))] for s in shaft.supports}
    return ShaftAnalysis(shaft, arr["x"], arr["N"], arr["Vy"], arr["Vz"], arr["My"], arr["Mz"], arr["T"], arr["uy"],
                         arr["uz"], reactions, slopes, node_slopes)


@dataclass(frozen=True)
class CriticalSpeed:
    """First critical speed [rad/s] by Rayleigh (Eq. 7-23) and Dunkerley (Eq. 7-24) on lumped masses."""

    rayleigh: float
    dunkerley: float
    masses: tuple[float, ...]
    positions: tuple[float, ...]
    deflections: tuple[float, ...]
    influence: tuple[float, ...]


def lumped_masses(shaft: Shaft) -> list[tuple[float, float]]:
    """(x, m) of the load masses and, when ``shaft.shaft_mass``, of the shaft split in MASS_PIECES per segment."""
    out = [(ld.x, ld.mass) for ld in shaft.loads if ld.mass > 0]
    if shaft.shaft_mass:
        rho = shaft.material.require("density").m_as("kg/m**3")
        b = shaft.boundaries
        for i, s in enumerate(shaft.segments):
            m = rho * math.pi / 4 * (s.diameter**2 - s.bore**2) * s.length / MASS_PIECES
            out += [(b[i] + (j + 0.5) * s.length / MASS_PIECES, m) for j in range(MASS_PIECES)]
    return out


def critical_speed(shaft: Shaft, theory: str = "timoshenko") -> CriticalSpeed:
    """First lateral critical speed from the lumped masses: Rayleigh with the static deflections under all
    the weights (taken along -z; an overhung mass deflecting upwards counts with |y|, as Shigley advises by
    reversing its weight), Dunkerley with the self-influence coefficients delta_ii (unit force at each mass),
    all from one factorisation of the frame model.

    Raises:
        InputError: no masses (no load masses and ``shaft_mass`` off).
    """
    lm = lumped_masses(shaft)
    if not lm:
        raise InputError(f"shaft {shaft.name}: no masses for the critical speed (give load masses or shaft_mass)")
    st = _stations(shaft, [x for x, _ in lm])
    from mechverify.components.shafts import ShaftLoad

    cases = {"weights": _point_loads(shaft, [ShaftLoad(f"m{i}", x, (0.0, 0.0, -m * G_STANDARD))
                                            for i, (x, m) in enumerate(lm)])}
    for i, (x, _) in enumerate(lm):
        cases[f"unit{i}"] = _point_loads(shaft, [ShaftLoad("u", x, (0.0, 0.0, -1.0))])
    try:
        fa = _frame(shaft, st, theory).analyse(cases)
    except (InputError, ModelError) as exc:
        raise _wrap(shaft, exc) from None
    y = [abs(float(fa["weights"].displacement(Q([x, 0, 0], "m")).m_as("m")[2])) for x, _ in lm]
    dii = [abs(float(fa[f"unit{i}"].displacement(Q([x, 0, 0], "m")).m_as("m")[2])) for i, (x, _) in enumerate(lm)]
    ms = [m for _, m in lm]
    return CriticalSpeed(rayleigh_critical_speed(ms, y), dunkerley_critical_speed(ms, dii), tuple(ms),
                         tuple(x for x, _ in lm), tuple(y), tuple(dii))


__all__ = ["Reaction", "ShaftAnalysis", "CriticalSpeed", "analyse", "critical_speed", "lumped_masses"]
