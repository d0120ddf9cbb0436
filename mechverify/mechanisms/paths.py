"""Planar tool paths walked at constant tangential speed, and the RP arm's kinematics and dynamics on them.

Path: a polar curve r(phi) about a centre (x_c, y_c), phi in [phi0, phi1], given as a vectorised SI
callable (a design file builds it from an expression such as ``"8 cm - 1.5 cm * cos(4*phi)"``).
:func:`walk_polar` samples it at equal arc-length steps for a constant tangential speed v, with the exact
velocity and acceleration from the curve's derivatives (chain rule: phi' = v/s_phi,
phi'' = -v^2 (x_phi x_phiphi + y_phi y_phiphi)/s_phi^4, s_phi = |dp/dphi|).

RP arm (revolute joint at the origin, prismatic joint along the arm; y up, gravity -y):
q1 = atan2(y, x), q2 = sqrt(x^2 + y^2) and their rates by differentiating those relations. Dynamics
from Lagrange's equations with T = 1/2 (J + m q2^2) q1'^2 + 1/2 m q2'^2 and
V = (m_a r_a + m q2) g sin q1 (J: rotating parts about the revolute axis, independent of q2; m_a at r_a
their mass and centre of mass; m the carriage as a point mass):

    tau1 = (J + m q2^2) q1'' + 2 m q2 q2' q1' + (m_a r_a + m q2) g cos q1
    F2   = m q2'' - m q2 q1'^2 + m g sin q1

(the 2 m q2 q2' q1' Coriolis and m q2 q1'^2 centripetal terms; e.g. Spong, Hutchinson & Vidyasagar,
Robot Modeling and Control, Sec. 7.3 (Euler-Lagrange equations), Craig, Introduction to Robotics, Ch. 6
for the polar RP arm.) Tests check them against a d'Alembert (Newton) solution and the power balance
tau1 q1' + F2 q2' = d(T + V)/dt by finite differences.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from mechverify.errors import InputError
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.units import QuantityLike, to_si

G_STANDARD = 9.80665  # [m/s^2]


@dataclass(frozen=True)
class PathSamples:
    """A path walked in time (SI): positions, velocities, accelerations per sample."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    ax: np.ndarray
    ay: np.ndarray
    length: float  # path length [m]


def _derivatives(r: Callable[[np.ndarray], np.ndarray], phi: np.ndarray, h: float = 1e-4):
    """r, r', r'' by central differences of step h (error O(h^4 r'''') with the 5-point stencil)."""
    r0 = np.asarray(r(phi), float)
    rp1, rm1, rp2, rm2 = (np.asarray(r(phi + k), float) for k in (h, -h, 2 * h, -2 * h))
    d1 = (-rp2 + 8 * rp1 - 8 * rm1 + rm2) / (12 * h)
    d2 = (-rp2 + 16 * rp1 - 30 * r0 + 16 * rm1 - rm2) / (12 * h * h)
    return r0, d1, d2


def walk_polar(r: Callable[[np.ndarray], np.ndarray], speed: QuantityLike, centre: tuple[float, float] = (0.0, 0.0),
               phi_range: tuple[float, float] = (0.0, 2 * math.pi), samples: int = 400,
               dense: int = 200_001) -> PathSamples:
    """The polar curve x = x_c + r cos(phi), y = y_c + r sin(phi), walked at constant tangential ``speed``;
    ``samples`` equal arc-length steps (``samples + 1`` points, both ends included)."""
    v = to_si(speed, "velocity", "speed")
    if v <= 0:
        raise InputError(f"path speed must be > 0, got {speed!r}")
    if samples < 2:
        raise InputError(f"samples must be >= 2, got {samples}")
    p0, p1 = phi_range
    if not p1 > p0:
        raise InputError(f"phi range must increase, got {phi_range}")
    phi = np.linspace(p0, p1, dense)
    rr, d1, _ = _derivatives(r, phi)
    if not np.all(np.isfinite(rr)):
        raise InputError("the path r(phi) is not finite everywhere on its range")
    ds = np.sqrt(rr**2 + d1**2)
    s = np.concatenate([[0.0], np.cumsum(0.5 * (ds[1:] + ds[:-1]) * np.diff(phi))])
    if s[-1] <= 0:
        raise InputError("the path has zero length")
    s_k = np.linspace(0.0, s[-1], samples + 1)
    ph = np.interp(s_k, s, phi)
    r0, r1, r2 = _derivatives(r, ph)
    c, sn = np.cos(ph), np.sin(ph)
    x_p, y_p = r1 * c - r0 * sn, r1 * sn + r0 * c
    x_pp, y_pp = r2 * c - 2 * r1 * sn - r0 * c, r2 * sn + 2 * r1 * c - r0 * sn
    sp = np.hypot(x_p, y_p)
    if np.any(sp <= 0):
        raise InputError(f"the path stops (ds/dphi = 0) at sample {int(np.argmin(sp))}")
    dphi = v / sp
    ddphi = -v * v * (x_p * x_pp + y_p * y_pp) / sp**4
    return PathSamples(t=s_k / v, x=centre[0] + r0 * c, y=centre[1] + r0 * sn, vx=x_p * dphi, vy=y_p * dphi,
                       ax=x_pp * dphi**2 + x_p * ddphi, ay=y_pp * dphi**2 + y_p * ddphi, length=float(s[-1]))


@dataclass(frozen=True)
class RPJointMotion:
    """Joint positions, rates and accelerations of an RP arm along a path (SI: rad, m, s)."""

    t: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    dq1: np.ndarray
    dq2: np.ndarray
    ddq1: np.ndarray
    ddq2: np.ndarray


@dataclass(frozen=True)
class RPArm:
    """RP arm: revolute joint at the origin, prismatic extension q2 within [reach_min, reach_max].

    Dynamics data: ``carriage_mass`` m (point mass at q2), ``arm_inertia`` J of the rotating parts about
    the revolute axis, ``arm_mass`` m_a with its centre of mass at ``arm_com`` r_a."""

    reach_min: QuantityLike = "0 m"
    reach_max: QuantityLike = "1 m"
    carriage_mass: QuantityLike = "0 kg"
    arm_inertia: QuantityLike = "0 kg*m^2"
    arm_mass: QuantityLike = "0 kg"
    arm_com: QuantityLike = "0 m"
    gravity: QuantityLike = "9.80665 m/s^2"
    name: str = "RP arm"

    def _si(self) -> tuple[float, ...]:
        return (to_si(self.reach_min, "length", "reach_min"), to_si(self.reach_max, "length", "reach_max"),
                to_si(self.carriage_mass, "mass", "carriage_mass"), to_si(self.arm_inertia, "inertia", "arm_inertia"),
                to_si(self.arm_mass, "mass", "arm_mass"), to_si(self.arm_com, "length", "arm_com"),
                to_si(self.gravity, "acceleration", "gravity"))

    def inverse(self, path: PathSamples) -> RPJointMotion:
        """q1 = atan2(y, x), q2 = sqrt(x^2 + y^2) and their first and second time derivatives."""
        lo, hi = self._si()[:2]
        x, y, vx, vy, ax, ay = path.x, path.y, path.vx, path.vy, path.ax, path.ay
        q2 = np.hypot(x, y)
        if np.any(q2 < 1e-9):
            i = int(np.argmax(q2 < 1e-9))
            raise SingularPoseError(f"{self.name}: sample {i} (t = {path.t[i]:.4g} s) passes through the revolute "
                                    f"axis (q2 = 0): the joint rate is undefined")
        bad = (q2 < lo - 1e-12) | (q2 > hi + 1e-12)
        if np.any(bad):
            i = int(np.argmax(bad))
            raise UnreachablePoseError(f"{self.name}: sample {i} (t = {path.t[i]:.4g} s, x = {x[i] * 1e3:.4g} mm, "
                                       f"y = {y[i] * 1e3:.4g} mm) needs q2 = {q2[i] * 1e3:.4g} mm, outside the "
                                       f"stroke {lo * 1e3:.4g} to {hi * 1e3:.4g} mm")
        q1 = np.unwrap(np.arctan2(y, x))
        dq2 = (x * vx + y * vy) / q2
        dq1 = (x * vy - y * vx) / q2**2
        ddq2 = (vx**2 + vy**2 + x * ax + y * ay) / q2 - dq2**2 / q2
        ddq1 = (x * ay - y * ax) / q2**2 - 2 * dq2 * dq1 / q2
        return RPJointMotion(path.t, q1, q2, dq1, dq2, ddq1, ddq2)

    def joint_loads(self, m: RPJointMotion) -> tuple[np.ndarray, np.ndarray]:
        """(tau1 [N m], F2 [N]) from Lagrange's equations (module docstring), inertial, Coriolis and gravity."""
        _lo, _hi, mc, J, ma, ra, g = self._si()
        tau1 = (J + mc * m.q2**2) * m.ddq1 + 2 * mc * m.q2 * m.dq2 * m.dq1 + (ma * ra + mc * m.q2) * g * np.cos(m.q1)
        F2 = mc * m.ddq2 - mc * m.q2 * m.dq1**2 + mc * g * np.sin(m.q1)
        return tau1, F2

    def energy(self, m: RPJointMotion) -> np.ndarray:
        """T + V [J] (module docstring)."""
        _lo, _hi, mc, J, ma, ra, g = self._si()
        T = 0.5 * (J + mc * m.q2**2) * m.dq1**2 + 0.5 * mc * m.dq2**2
        return T + (ma * ra + mc * m.q2) * g * np.sin(m.q1)
