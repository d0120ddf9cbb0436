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
from mechverify.fea.frame.model import FramePointLoad, FrameSupport, Member
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
    slope_components: dict[str, tuple[float, float]] = field(default_factory=dict)  # support -> (about y, about z)

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
        k = int(i[np.argmax(self.deflection[i])])
        return {"M": float(self.M[i].max()), "T": float(np.abs(self.T[i]).max()), "N": float(self.N[i].max()),
                "deflection": float(self.deflection[k]), "uy": float(self.uy[k]), "uz": float(self.uz[k])}

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
    from mechverify.fea.frame.analysis import Frame

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
            sups.append(FrameSupport(Q([s.x, 0, 0], "m"), kind="custom", hold=tuple(hold), springs=springs))
        else:
            sups.append(FrameSupport(Q([s.x, 0, 0], "m"), kind="spring", springs=springs))
    return Frame(None, members, sups, theory=theory, name=shaft.name)


def _point_loads(shaft: Shaft, loads: Any = None) -> list[FramePointLoad]:
    lds = shaft.loads if loads is None else loads
    return [FramePointLoad(Q([ld.x, 0, 0], "m"), force=Q(list(ld.force), "N"), moment=Q(list(ld.moment), "N*m"))
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
    if all(not any(ld.force) and not ld.moment[1] and not ld.moment[2] for ld in shaft.loads):
        return _pure_torsion(shaft, st)
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
    node_slopes, node_rot = {}, {}
    for x in st:
        r = res.rotation(Q([x, 0, 0], "m")).m_as("rad")
        node_slopes[x] = float(math.hypot(r[1], r[2]))
        node_rot[x] = (float(r[1]), float(r[2]))
    near = {s.name: min(node_slopes, key=lambda v: abs(v - s.x)) for s in shaft.supports}
    slopes = {k: node_slopes[x] for k, x in near.items()}
    return ShaftAnalysis(shaft, arr["x"], arr["N"], arr["Vy"], arr["Vz"], arr["My"], arr["Mz"], arr["T"], arr["uy"],
                         arr["uz"], reactions, slopes, node_slopes, {k: node_rot[x] for k, x in near.items()})


def _pure_torsion(shaft: Shaft, st: list[float]) -> ShaftAnalysis:
    """A shaft loaded by balanced torques only (no force, no bending moment): no bending, no reactions, the torque
    diagram T(x) = -(sum of the torques applied at or left of x) in the frame's sign convention. Exact statics;
    solved directly because the frame's equilibrium check has no scale for self-equilibrated moments.

    Raises:
        ModelError: one pinned or spring bearing only (the shaft could tilt; the frame would name that too).
    """
    if len(shaft.supports) < 2 and shaft.supports[0].kind != "fixed":
        raise ModelError(f"shaft {shaft.name}: one {shaft.supports[0].kind} bearing ({shaft.supports[0].name}) leaves "
                         "the shaft free to tilt about it; give two bearings or a fixed one")
    xs, Ts = [], []
    for a, b in zip(st[:-1], st[1:], strict=True):
        T = -sum(ld.torque for ld in shaft.loads if ld.x <= a + 1e-12)
        xs.append(np.linspace(a, b, 21))
        Ts.append(np.full(21, T))
    x, T = np.concatenate(xs), np.concatenate(Ts)
    z = np.zeros_like(x)
    reactions = {sp.name: Reaction(sp.name, sp.x, (0.0, 0.0, 0.0)) for sp in shaft.supports}
    return ShaftAnalysis(shaft, x, z.copy(), z.copy(), z.copy(), z.copy(), z.copy(), T, z.copy(), z.copy(), reactions,
                         {sp.name: 0.0 for sp in shaft.supports}, dict.fromkeys(st, 0.0),
                         {sp.name: (0.0, 0.0) for sp in shaft.supports})


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


# ------------------------------------------------------------------------------------------ modal solution
ELEMENTS_PER_SPAN = 80  # beam elements over the shaft length (more at short intervals: at least 2 per interval)


@dataclass(frozen=True)
class ModalCriticalSpeeds:
    """Lateral natural frequencies of the shaft on its bearings [rad/s] (each a pair of equal whirl modes of the
    round shaft) from the consistent-mass eigenproblem, with the mode shapes (transverse displacement at ``x``)."""

    omegas: tuple[float, ...]
    x: np.ndarray
    shapes: np.ndarray  # (n_modes, len(x)), each normalised to a largest |w| of 1
    elements: int
    theory: str

    @property
    def first(self) -> float:
        return self.omegas[0]


def _beam_matrices(L: float, EI: float, mass_per_length: float, phi: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Stiffness and consistent mass of a planar beam element (dofs w1, theta1, w2, theta2).

    Stiffness: Euler-Bernoulli (phi = 0) or Timoshenko with phi = 12 E I / (G A_s L^2) (Przemieniecki, Theory of
    Matrix Structural Analysis, 1968, Sec. 5.6); mass: the cubic-Hermite consistent translational mass
    m' L / 420 [[156, 22L, 54, -13L], ...] (Przemieniecki Sec. 11.3; Zienkiewicz, Taylor & Zhu Sec. 16.2)."""
    c = EI / ((1 + phi) * L**3)
    K = c * np.array([[12, 6 * L, -12, 6 * L],
                      [6 * L, (4 + phi) * L**2, -6 * L, (2 - phi) * L**2],
                      [-12, -6 * L, 12, -6 * L],
                      [6 * L, (2 - phi) * L**2, -6 * L, (4 + phi) * L**2]])
    M = mass_per_length * L / 420 * np.array([[156, 22 * L, 54, -13 * L],
                                              [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                                              [54, 13 * L, 156, -22 * L],
                                              [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    return K, M


def modal_critical_speeds(shaft: Shaft, n_modes: int = 3, theory: str = "euler",
                          elements: int = ELEMENTS_PER_SPAN) -> ModalCriticalSpeeds:
    """Lateral critical speeds of the shaft as the natural frequencies of the generalized eigenproblem
    ``K phi = omega^2 M phi`` (scipy.linalg.eigh, dense: a shaft has a few hundred dofs).

    The shaft is meshed in planar beam elements (about ``elements`` over its length, at least two per interval
    between segment steps, supports, loads and features) with the consistent mass of each segment's own section
    (when ``shaft.shaft_mass``) plus the load masses lumped at their nodes. A round shaft on bearings that act alike
    in y and z whirls in either plane, so one plane gives every lateral frequency. Supports: pinned holds w, fixed
    holds w and theta, spring adds its radial stiffness to w. The frame's modal solution (FEA issue) did not exist
    when this was written; this is the shaft's own eigenproblem on the same model (Shigley 10th ed. Sec. 7-6 calls
    the first of these frequencies the first critical speed).

    Raises:
        InputError: no mass at all; the supports leave a free rigid motion (named); ``theory`` not euler/timoshenko.
    """
    import scipy.linalg as sla

    if theory not in ("euler", "timoshenko"):
        raise InputError(f"shaft {shaft.name}: theory must be 'euler' or 'timoshenko', got {theory!r}")
    lm = [(ld.x, ld.mass) for ld in shaft.loads if ld.mass > 0]
    if not lm and not shaft.shaft_mass:
        raise InputError(f"shaft {shaft.name}: no masses for the critical speed (give load masses or shaft_mass)")
    mat = shaft.material
    E = mat.require("E").m_as("Pa")
    G = mat.require("G").m_as("Pa") if theory == "timoshenko" else 0.0
    rho = mat.require("density").m_as("kg/m**3") if shaft.shaft_mass else 0.0
    st = _stations(shaft, [x for x, _ in lm])
    L = shaft.length
    nodes = [st[0]]
    for a, b in zip(st[:-1], st[1:], strict=True):
        n = max(2, math.ceil(elements * (b - a) / L))
        nodes += [a + (b - a) * (j + 1) / n for j in range(n)]
    x = np.array(nodes)
    ndof = 2 * len(x)
    K, M = np.zeros((ndof, ndof)), np.zeros((ndof, ndof))
    for e in range(len(x) - 1):
        le = x[e + 1] - x[e]
        seg = shaft.segment_at(0.5 * (x[e] + x[e + 1]))
        A = math.pi / 4 * (seg.diameter**2 - seg.bore**2)
        I = math.pi / 64 * (seg.diameter**4 - seg.bore**4)
        phi = 0.0
        if theory == "timoshenko":
            sec = sections.tube(Q(seg.diameter, "m"), inner_diameter=Q(seg.bore, "m")) if seg.bore else \
                sections.circle(Q(seg.diameter, "m"))
            phi = 12 * E * I / (G * sec.Asy.m_as("m**2") * le**2)
        ke, me = _beam_matrices(le, E * I, rho * A, phi)
        dofs = slice(2 * e, 2 * e + 4)
        K[dofs, dofs] += ke
        M[dofs, dofs] += me

    def node(xv: float) -> int:
        return int(np.argmin(np.abs(x - xv)))

    for xv, m in lm:
        M[2 * node(xv), 2 * node(xv)] += m
    fixed: list[int] = []
    for sup in shaft.supports:
        i = node(sup.x)
        if sup.kind == "spring":
            K[2 * i, 2 * i] += sup.stiffness
        else:
            fixed.append(2 * i)
            if sup.kind == "fixed":
                fixed.append(2 * i + 1)
    free = np.setdiff1d(np.arange(ndof), fixed)
    Kf, Mf = K[np.ix_(free, free)], M[np.ix_(free, free)]
    k = min(n_modes, len(free))
    # M phi = mu K phi with mu = 1/omega^2: K is positive definite for a supported shaft, M may be singular (a
    # massless shaft with point masses); the largest mu are the lowest frequencies.
    try:
        mu, vec = sla.eigh(Mf, Kf, subset_by_index=[len(free) - k, len(free) - 1])
    except np.linalg.LinAlgError:
        what = (f"free to tilt about bearing {shaft.supports[0].name}" if len(shaft.supports) == 1
                else "free to move as a rigid body")
        raise ModelError(f"shaft {shaft.name}: the supports leave the shaft {what} (the stiffness matrix is "
                         "singular); give two bearings or a fixed one") from None
    mu, vec = mu[::-1], vec[:, ::-1]
    if not mu[0] > 0:
        raise InputError(f"shaft {shaft.name}: no mass that moves laterally (load masses sit on the bearings)")
    k = int(np.count_nonzero(mu > mu[0] * 1e-12))
    mu, vec = mu[:k], vec[:, :k]
    w2 = 1.0 / mu
    full = np.zeros((k, ndof))
    full[:, free] = vec.T
    w = full[:, 0::2]
    w /= np.abs(w).max(axis=1, keepdims=True)
    return ModalCriticalSpeeds(tuple(float(v) for v in np.sqrt(w2)), x, w, len(x) - 1, theory)


def frame_critical_speeds(shaft: Shaft, n_modes: int = 3, theory: str = "timoshenko",
                          elements_per_member: int = 10) -> ModalCriticalSpeeds:
    """Lateral critical speeds from the frame's modal solution (:func:`mechverify.fea.frame.modal.frame_modes`):
    the shaft's frame model (the same members, supports and theory as the static analysis, the members' consistent
    mass from the material's density, Timoshenko members with rotary inertia) with the load masses as point
    masses. The 3D frame also has torsional and axial modes; the lateral ones are those whose largest motion is a
    transverse translation, and each appears twice (y and z whirl of the round shaft), counted once here.

    A shaft whose own mass is switched off (``shaft_mass = false``) has massless frame nodes, which the frame
    solver rejects; :func:`modal_critical_speeds` (the shaft's own planar eigenproblem) handles that case.

    Raises:
        InputError: ``shaft_mass`` off (use :func:`modal_critical_speeds`); the frame's named errors.
    """
    from mechverify.fea.frame.modal import PointMass, frame_modes

    if not shaft.shaft_mass:
        raise InputError(f"shaft {shaft.name}: the frame's modal solution needs the shaft's own mass "
                         "(shaft_mass = true); modal_critical_speeds handles a massless shaft")
    lm = [(ld.x, ld.mass) for ld in shaft.loads if ld.mass > 0]
    st = _stations(shaft, [x for x, _ in lm])
    masses = [PointMass(Q([x, 0, 0], "m"), Q(m, "kg")) for x, m in lm]
    rmax = max(seg.diameter for seg in shaft.segments) / 2
    fr = _frame(shaft, st, theory)
    ask = 4 * n_modes + 4
    while True:
        try:
            fm = frame_modes(fr, min(ask, 6 * (len(st) - 1) * elements_per_member), masses=masses,
                             elements_per_member=elements_per_member)
        except (InputError, ModelError) as exc:
            raise _wrap(shaft, exc) from None
        lateral: list[tuple[float, np.ndarray]] = []
        for k, w2 in enumerate(fm.omega2):
            sh = fm.shapes[k]
            lat = np.hypot(sh[:, 1], sh[:, 2])
            other = max(float(np.abs(sh[:, 0]).max()), float(np.abs(sh[:, 3]).max()) * rmax)
            if lat.max() > other:
                w = math.sqrt(max(float(w2), 0.0))
                if not lateral or w > lateral[-1][0] * (1 + 1e-6):
                    lateral.append((w, sh[:, 1] if np.abs(sh[:, 1]).max() >= np.abs(sh[:, 2]).max() else sh[:, 2]))
        if len(lateral) >= n_modes or ask >= 6 * (len(st) - 1) * elements_per_member:
            break
        ask *= 2
    if not lateral:
        raise ModelError(f"shaft {shaft.name}: no lateral mode among the {len(fm.omega2)} lowest frame modes")
    lateral = lateral[:n_modes]
    order = np.argsort(fm.points[:, 0])
    x = fm.points[order, 0]
    shapes = np.array([v[order] / np.abs(v).max() for _, v in lateral])
    return ModalCriticalSpeeds(tuple(w for w, _ in lateral), x, shapes, len(fm.elements), f"frame, {theory}")


__all__ = ["Reaction", "ShaftAnalysis", "CriticalSpeed", "ModalCriticalSpeeds", "analyse", "critical_speed",
           "frame_critical_speeds", "lumped_masses", "modal_critical_speeds"]
