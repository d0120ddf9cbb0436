"""The planar five-bar (DexTAR-type, RR-RR) parallel manipulator: kinematics, singularities, statics.

Geometry: motor axes ``A1 = (0, 0)`` and ``A2 = (base, 0)``; proximal links (cranks) ``A1B1`` and
``A2B2`` driven at ``theta_left``/``theta_right`` (absolute angles from +x); distal links ``B1P``
and ``B2P`` meet at the tool point ``P``.

* **Assembly mode** (forward kinematics has two solutions): ``"+"`` when ``P`` lies to the left of
  the directed line ``B1 -> B2`` (the upper solution in the usual layout), i.e.
  ``sign((B2 - B1) x (P - B1))``; changing it passes a type-2 singularity.
* **Working mode** (inverse kinematics has two solutions per leg): one sign per leg,
  ``w_i = sign((B_i - A_i) x (P - B_i)) = sign(sin(theta_distal - theta_proximal))``; written as
  a two-character string, left leg first. The mode ``"-+"`` is the one of seed 002 (theta2 > theta3,
  theta5 < theta4); changing it passes a type-1 singularity.
* **Jacobian**: differentiating ``|P - B_i|^2 = l_distal^2`` gives ``A Pdot = B thetadot`` with
  rows ``A_i = (P - B_i)^T`` and ``B = diag((B_i - A_i) x (P - B_i))``; ``J = A^-1 B``.
  Type-1 (serial) singularity: ``det B = 0`` (a leg fully extended or folded); type-2 (parallel):
  ``det A = 0`` (distal links aligned). The measures reported are the sines of those angles.
* **Statics by virtual work**: the torques the motors must apply to hold a force ``F`` acting on
  the tool are ``tau = -J^T F``.

All angles are computed with ``atan2``.

References
----------
1. J.-P. Merlet, *Parallel Robots*, 2nd ed., Springer, 2006, Sec. 3.1 (five-bar), 6.1-6.2
   (Jacobian, singularity types).
2. C. Gosselin, J. Angeles, "Singularity analysis of closed-loop kinematic chains", IEEE Trans.
   Robotics and Automation 6(3), 1990, 281-290 (type-1/type-2 classification).
3. L. Campos, F. Bourbonnais, I. Bonev, P. Bigras, "Development of a five-bar parallel robot with
   large workspace", ASME IDETC 2010 (DexTAR; working and assembly modes).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError
from mechverify.frozen import set_fields
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.statics import GROUND, AppliedForce, Body, Mechanism, Pin, point_si, vector_si
from mechverify.units import from_si, require_positive, to_si

_MODES = ("++", "+-", "-+", "--")


def _perp(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def _cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _sign(ch: str, what: str) -> float:
    if ch not in "+-" or len(ch) != 1:
        raise InputError(f"{what}: expected '+' or '-', got {ch!r}")
    return 1.0 if ch == "+" else -1.0


_CLOSE_TOL = 1e-9  # relative tolerance of a closure on the workspace boundary (acos/sqrt argument clamped)


def _circle_intersection(c1: np.ndarray, r1: float, c2: np.ndarray, r2: float, side: float, what: str) -> np.ndarray:
    """The intersection of two circles on the left (side=+1) or right (-1) of the line c1 -> c2."""
    dvec = c2 - c1
    d = float(np.hypot(*dvec))
    tol = _CLOSE_TOL * (r1 + r2)  # a point on the workspace boundary closes (round-off, not a reach error)
    if d == 0 or d > r1 + r2 + tol or d < abs(r1 - r2) - tol:
        raise UnreachablePoseError(
            f"{what}: cannot close, the centres are {d * 1e3:.4g} mm apart but the links reach only "
            f"{abs(r1 - r2) * 1e3:.4g} to {(r1 + r2) * 1e3:.4g} mm")
    e = dvec / d
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    return c1 + a * e + side * h * _perp(e)


@dataclass(frozen=True)
class FiveBarPose:
    """One assembled pose: actuated and distal angles, joint positions, modes and Jacobian data."""

    theta_left: pint.Quantity
    theta_right: pint.Quantity
    theta_distal_left: pint.Quantity
    theta_distal_right: pint.Quantity
    A1: np.ndarray  # SI positions [m]
    B1: np.ndarray
    P: np.ndarray
    B2: np.ndarray
    A2: np.ndarray
    assembly_mode: str
    working_mode: str

    @property
    def tool(self) -> pint.Quantity:
        """The tool point P as a length quantity (x, y)."""
        return from_si(self.P.copy(), "length")

    def label(self) -> str:
        return (f"theta_left={self.theta_left.m_as('deg'):.2f} deg, theta_right={self.theta_right.m_as('deg'):.2f} deg"
                f" (P = {self.P[0] * 1e3:.2f}, {self.P[1] * 1e3:.2f} mm)")


@dataclass(frozen=True)
class WorkspaceSample:
    """Cartesian workspace samples: positions, reachability and singularity measures per point."""

    x: pint.Quantity  # (n,) lengths
    y: pint.Quantity
    reachable: np.ndarray  # bool (n,)
    type1: np.ndarray  # min of the two leg measures (nan where unreachable)
    type2: np.ndarray  # |sin| of the angle between the distal links (nan where unreachable)


@dataclass(frozen=True)
class FiveBar:
    """A five-bar linkage. Lengths as quantities or strings; seed 002 uses 100 mm for all five.

    Optional ``masses`` (left crank, left distal, right distal, right crank) and ``com_fractions``
    (centre of mass as a fraction of each link's length from its base-side joint: A1, B1, B2, A2)
    give self-weight for :meth:`statics` when the mechanism works in a vertical plane.
    """

    base: Any
    proximal_left: Any
    distal_left: Any
    distal_right: Any
    proximal_right: Any
    masses: Sequence[Any] = ("0 kg", "0 kg", "0 kg", "0 kg")
    com_fractions: Sequence[float] = (0.5, 0.5, 0.5, 0.5)
    name: str = "five-bar"

    def __post_init__(self) -> None:
        for f in ("base", "proximal_left", "distal_left", "distal_right", "proximal_right"):
            v = to_si(getattr(self, f), "length", f)
            require_positive(v, f, dim="length")
            set_fields(self, **{f: from_si(v, "length")})
        if len(self.masses) != 4 or len(self.com_fractions) != 4:
            raise InputError("masses and com_fractions: give four values (left crank, left distal, right distal, "
                             "right crank)")
        ms = tuple(from_si(require_positive(to_si(m, "mass", "masses"), "masses", allow_zero=True, dim="mass"), "mass")
                   for m in self.masses)
        set_fields(self, masses=ms)
        fr = tuple(float(f) for f in self.com_fractions)
        if any(not 0 <= f <= 1 for f in fr):
            raise InputError(f"com_fractions: each must lie in [0, 1], got {fr}")
        set_fields(self, com_fractions=fr)

    # ---------------------------------------------------------------- SI geometry
    @property
    def _L(self) -> tuple[float, float, float, float, float]:
        return tuple(float(getattr(self, f).m_as("m")) for f in
                     ("base", "proximal_left", "distal_left", "distal_right", "proximal_right"))  # type: ignore[return-value]

    def _pose(self, t1: float, t2: float, B1: np.ndarray, P: np.ndarray, B2: np.ndarray) -> FiveBarPose:
        d, l1, l2, l3, l4 = self._L
        A1, A2 = np.zeros(2), np.array([d, 0.0])
        w1 = "+" if _cross(B1 - A1, P - B1) >= 0 else "-"
        w2 = "+" if _cross(B2 - A2, P - B2) >= 0 else "-"
        asm = "+" if _cross(B2 - B1, P - B1) >= 0 else "-"
        return FiveBarPose(
            theta_left=from_si(t1, "angle").to("deg"), theta_right=from_si(t2, "angle").to("deg"),
            theta_distal_left=from_si(math.atan2(P[1] - B1[1], P[0] - B1[0]), "angle").to("deg"),
            theta_distal_right=from_si(math.atan2(P[1] - B2[1], P[0] - B2[0]), "angle").to("deg"),
            A1=A1, B1=B1, P=P, B2=B2, A2=A2, assembly_mode=asm, working_mode=w1 + w2)

    # ---------------------------------------------------------------- kinematics
    def forward(self, theta_left: Any, theta_right: Any, assembly_mode: str = "+") -> FiveBarPose:
        """Tool point from the two motor angles; ``assembly_mode`` picks one of the two solutions."""
        t1, t2 = to_si(theta_left, "angle", "theta_left"), to_si(theta_right, "angle", "theta_right")
        side = _sign(assembly_mode, "assembly_mode")
        d, l1, l2, l3, l4 = self._L
        B1 = np.array([l1 * math.cos(t1), l1 * math.sin(t1)])
        B2 = np.array([d + l4 * math.cos(t2), l4 * math.sin(t2)])
        P = _circle_intersection(B1, l2, B2, l3, side, f"{self.name} forward kinematics (distal links)")
        return self._pose(t1, t2, B1, P, B2)

    def inverse(self, point: Any, working_mode: str = "-+") -> FiveBarPose:
        """Motor angles that put the tool at ``point`` (x, y) in ``working_mode`` (see module doc)."""
        if working_mode not in _MODES:
            raise InputError(f"working_mode: expected one of {_MODES}, got {working_mode!r}")
        P = point_si(point, "point")
        d, l1, l2, l3, l4 = self._L
        A1, A2 = np.zeros(2), np.array([d, 0.0])
        # B = M - w h n with n the left normal of A -> P gives sign((B - A) x (P - B)) = w
        B1 = _circle_intersection(A1, l1, P, l2, -_sign(working_mode[0], "working_mode"),
                                  f"{self.name} inverse kinematics, left leg")
        B2 = _circle_intersection(A2, l4, P, l3, -_sign(working_mode[1], "working_mode"),
                                  f"{self.name} inverse kinematics, right leg")
        t1 = math.atan2(B1[1] - A1[1], B1[0] - A1[0])
        t2 = math.atan2(B2[1] - A2[1], B2[0] - A2[0])
        return self._pose(t1, t2, B1, P, B2)

    def jacobian_parts(self, pose: FiveBarPose) -> tuple[np.ndarray, np.ndarray]:
        """``(A, B)`` of ``A Pdot = B thetadot`` in SI (A in m, B in m^2/rad)."""
        A = np.vstack([pose.P - pose.B1, pose.P - pose.B2])
        B = np.diag([_cross(pose.B1 - pose.A1, pose.P - pose.B1), _cross(pose.B2 - pose.A2, pose.P - pose.B2)])
        return A, B

    def jacobian(self, pose: FiveBarPose) -> pint.Quantity:
        """``J = A^-1 B`` (m/rad): tool velocity per motor speed. Raises at a type-2 singularity."""
        self.check_singularity(pose, type1_tol=0.0)
        A, B = self.jacobian_parts(pose)
        return from_si(np.linalg.solve(A, B), "length")

    def singularity_measures(self, pose: FiveBarPose) -> dict[str, float]:
        """Sines of the singular angles: ``type1_left``/``type1_right`` (crank vs distal), ``type2``
        (between the distal links). 0 at the singularity, 1 at right angles."""
        d, l1, l2, l3, l4 = self._L
        return {
            "type1_left": abs(_cross(pose.B1 - pose.A1, pose.P - pose.B1)) / (l1 * l2),
            "type1_right": abs(_cross(pose.B2 - pose.A2, pose.P - pose.B2)) / (l4 * l3),
            "type2": abs(_cross(pose.P - pose.B1, pose.P - pose.B2)) / (l2 * l3),
        }

    def check_singularity(self, pose: FiveBarPose, type1_tol: float = 1e-3, type2_tol: float = 1e-3) -> None:
        """Raise :class:`SingularPoseError` if a measure is at or below its tolerance."""
        m = self.singularity_measures(pose)
        if m["type2"] <= type2_tol:
            raise SingularPoseError(
                f"{self.name}: type-2 (parallel) singularity at {pose.label()}: the distal links are aligned "
                f"(sin = {m['type2']:.3g} <= {type2_tol:g}); the motors cannot resist a force across them")
        for leg in ("left", "right"):
            if m[f"type1_{leg}"] <= type1_tol:
                raise SingularPoseError(
                    f"{self.name}: type-1 (serial) singularity of the {leg} leg at {pose.label()}: crank and "
                    f"distal link aligned (sin = {m[f'type1_{leg}']:.3g} <= {type1_tol:g}); the tool loses a "
                    "direction of motion")

    def holding_torques(self, pose: FiveBarPose, force: Any) -> tuple[pint.Quantity, pint.Quantity]:
        """Motor torques (left, right; counter-clockwise on the cranks) that hold ``force`` acting on the
        tool, by virtual work: ``tau = -J^T F`` (massless links). Raises at a type-2 singularity."""
        F = vector_si(force, "force", "force")
        self.check_singularity(pose, type1_tol=0.0)
        A, B = self.jacobian_parts(pose)
        y = np.linalg.solve(A.T, F)
        tau = -B.T @ y
        return from_si(float(tau[0]), "torque"), from_si(float(tau[1]), "torque")

    def workspace(self, x_range: Any, y_range: Any, n: int = 41, working_mode: str = "-+") -> WorkspaceSample:
        """Sample an ``n x n`` grid over ``x_range``/``y_range`` (pairs of lengths) by inverse kinematics."""
        if n < 2:
            raise InputError(f"n: need at least 2 samples per axis, got {n}")
        x0, x1 = (to_si(v, "length", "x_range") for v in x_range)
        y0, y1 = (to_si(v, "length", "y_range") for v in y_range)
        if x1 <= x0 or y1 <= y0:
            raise InputError(f"x_range/y_range: give (low, high) with low < high, got ({x0}, {x1}), ({y0}, {y1}) m")
        X, Y = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
        xs, ys = X.ravel(), Y.ravel()
        ok = np.zeros(xs.size, dtype=bool)
        t1m, t2m = np.full(xs.size, np.nan), np.full(xs.size, np.nan)
        for k, (x, y) in enumerate(zip(xs, ys, strict=True)):
            try:
                pose = self.inverse((from_si(x, "length"), from_si(y, "length")), working_mode)
            except UnreachablePoseError:
                continue
            m = self.singularity_measures(pose)
            ok[k] = True
            t1m[k] = min(m["type1_left"], m["type1_right"])
            t2m[k] = m["type2"]
        return WorkspaceSample(from_si(xs, "length"), from_si(ys, "length"), ok, t1m, t2m)

    # ---------------------------------------------------------------- statics
    def statics(self, pose: FiveBarPose, force: Any = ("0 N", "0 N"), gravity: Any = ("0 m/s**2", "0 m/s**2"),
                ) -> Mechanism:
        """The statics model at ``pose``: four links, five pins (motors actuated), ``force`` on the tool.

        The default ``gravity`` is zero in the plane (a five-bar working in a horizontal plane, as in
        seed 002, carries its payload's weight out of plane); pass ``("0 m/s**2", "-9.80665 m/s**2")``
        for a mechanism in a vertical plane so that link self-weight counts.
        """
        pts = {"A1": pose.A1, "B1": pose.B1, "P": pose.P, "B2": pose.B2, "A2": pose.A2}
        q = {k: from_si(v.copy(), "length") for k, v in pts.items()}
        links = (("crank_left", "A1", "B1"), ("distal_left", "B1", "P"), ("distal_right", "B2", "P"),
                 ("crank_right", "A2", "B2"))
        bodies = []
        for (name, a, b), m, f in zip(links, self.masses, self.com_fractions, strict=True):
            com = from_si(pts[a] + f * (pts[b] - pts[a]), "length") if m.magnitude > 0 else None
            bodies.append(Body(name, {a: q[a], b: q[b]}, mass=m, com=com))
        joints = (
            Pin("motor_left", GROUND, "crank_left", "A1", actuated=True),
            Pin("elbow_left", "crank_left", "distal_left", "B1"),
            Pin("tool", "distal_left", "distal_right", "P"),
            Pin("elbow_right", "crank_right", "distal_right", "B2"),
            Pin("motor_right", GROUND, "crank_right", "A2", actuated=True),
        )
        loads = (AppliedForce("distal_left", "P", force, name="tool force"),)
        return Mechanism(tuple(bodies), joints, loads, gravity=gravity, name=f"{self.name} at {pose.label()}")
