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

from mechverify.errors import InputError, renamed
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.units import Q, QuantityLike, fmt, to_si

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


def _derivatives(f: Callable[[np.ndarray], np.ndarray], u: np.ndarray, h: float):
    """f, f', f'' by central differences of step h (error O(h^4 f^(5)) and O(h^4 f^(6)), 5-point stencils)."""
    f0 = np.asarray(f(u), float)
    fp1, fm1, fp2, fm2 = (np.asarray(f(u + k), float) for k in (h, -h, 2 * h, -2 * h))
    d1 = (-fp2 + 8 * fp1 - 8 * fm1 + fm2) / (12 * h)
    d2 = (-fp2 + 16 * fp1 - 30 * f0 + 16 * fm1 - fm2) / (12 * h * h)
    return f0, d1, d2


Curve = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


def _xy_derivatives(curve: Curve, u: np.ndarray, h: float):
    x = _derivatives(lambda w: np.asarray(curve(w)[0], float), u, h)
    y = _derivatives(lambda w: np.asarray(curve(w)[1], float), u, h)
    return (*x, *y)


def _arc_table(curve: Curve, u_range: tuple[float, float], dense: int, h: float) -> tuple[np.ndarray, np.ndarray]:
    u = np.linspace(u_range[0], u_range[1], dense)
    x, xu, _, y, yu, _ = _xy_derivatives(curve, u, h)
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y)) and np.all(np.isfinite(xu)) and np.all(np.isfinite(yu))):
        raise InputError("the path is not finite everywhere on its range")
    ds = np.hypot(xu, yu)
    s = np.concatenate([[0.0], np.cumsum(0.5 * (ds[1:] + ds[:-1]) * np.diff(u))])
    if s[-1] <= 0:
        raise InputError("the path has zero length")
    return u, s


def _check_range(u_range: tuple[float, float], what: str) -> tuple[float, float, float]:
    u0, u1 = float(u_range[0]), float(u_range[1])
    if not (math.isfinite(u0) and math.isfinite(u1) and u1 > u0):
        raise InputError(f"{what} range must increase, got {u_range}")
    return u0, u1, 1e-5 * (u1 - u0)  # stencil step relative to the parameter range


def curve_length(curve: Curve, u_range: tuple[float, float], dense: int = 200_001) -> float:
    """Length [m] of the curve (x(u), y(u)), u in ``u_range`` (trapezoidal integral of |dp/du| on a dense grid)."""
    u0, u1, h = _check_range(u_range, "curve parameter")
    return float(_arc_table(curve, (u0, u1), dense, h)[1][-1])


@dataclass(frozen=True)
class Timing:
    """How a path is walked: arc length s(t) [m] with its rates s' [m/s] and s'' [m/s^2] at the sample times."""

    t: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    dds: np.ndarray


def walk_curve(curve: Curve, u_range: tuple[float, float], speed: QuantityLike | None = None, *,
               timing: Timing | Callable[[float], Timing] | None = None, samples: int = 400,
               dense: int = 200_001) -> PathSamples:
    """The planar curve p(u) = (x(u), y(u)) [m] walked in time: at constant tangential ``speed`` (``samples``
    equal arc-length steps, both ends included), or along ``timing`` (arc length over time, e.g. a trapezoidal
    move over the curve's length; a callable gets the length and returns the :class:`Timing`).

    Chain rule with s' = |p_u| u': u' = s'/|p_u|, u'' = s''/|p_u| - s'^2 (p_u . p_uu)/|p_u|^4,
    v = p_u u', a = p_uu u'^2 + p_u u'' (exact in the curve's derivatives, here 5-point differences)."""
    u0, u1, h = _check_range(u_range, "curve parameter")
    if (speed is None) == (timing is None):
        raise InputError("give either a constant path speed or a timing (a motion profile along the path)")
    u, s = _arc_table(curve, (u0, u1), dense, h)
    length = float(s[-1])
    if timing is None:
        v = to_si(speed, "velocity", "speed")
        if not v > 0:
            raise InputError(f"path speed must be > 0, got {speed!r}")
        if samples < 2:
            raise InputError(f"samples must be >= 2, got {samples}")
        s_k = np.linspace(0.0, length, samples + 1)
        tm = Timing(s_k / v, s_k, np.full_like(s_k, v), np.zeros_like(s_k))
    else:
        tm = timing(length) if callable(timing) else timing
        if np.any(tm.s < -1e-9 * length) or np.any(tm.s > length * (1 + 1e-6)):
            raise InputError(f"the timing walks s = {float(np.min(tm.s)):.6g} to {float(np.max(tm.s)):.6g} m, "
                             f"outside the path's length 0 to {length:.6g} m")
    uk = np.interp(np.clip(tm.s, 0.0, length), s, u)
    x, xu, xuu, y, yu, yuu = _xy_derivatives(curve, uk, h)
    sp = np.hypot(xu, yu)
    if np.any(sp <= 1e-12 * max(float(np.max(sp)), 1e-300)):
        i = int(np.argmin(sp))
        raise InputError(f"the path stops (dp/du = 0) at sample {i} (x = {x[i] * 1e3:.4g} mm, y = {y[i] * 1e3:.4g} mm)")
    du = tm.ds / sp
    ddu = tm.dds / sp - tm.ds**2 * (xu * xuu + yu * yuu) / sp**4
    return PathSamples(t=tm.t, x=x, y=y, vx=xu * du, vy=yu * du, ax=xuu * du**2 + xu * ddu,
                       ay=yuu * du**2 + yu * ddu, length=length)


def walk_polar(r: Callable[[np.ndarray], np.ndarray], speed: QuantityLike | None = None,
               centre: tuple[float, float] = (0.0, 0.0), phi_range: tuple[float, float] = (0.0, 2 * math.pi),
               samples: int = 400, dense: int = 200_001, *, timing: Timing | Callable[[float], Timing] | None = None,
               ) -> PathSamples:
    """The polar curve x = x_c + r cos(phi), y = y_c + r sin(phi) [m], walked as :func:`walk_curve` says
    (constant tangential ``speed``: ``samples`` equal arc-length steps, ``samples + 1`` points)."""
    xc, yc = float(centre[0]), float(centre[1])

    def curve(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        rr = np.asarray(r(phi), float)
        return xc + rr * np.cos(phi), yc + rr * np.sin(phi)

    return walk_curve(curve, phi_range, speed, timing=timing, samples=samples, dense=dense)


def spline_through(points: np.ndarray, closed: bool = False) -> tuple[Curve, tuple[float, float]]:
    """A C2 cubic spline through sampled points (N x 2, metres), parametrised by chord length (a periodic spline
    when ``closed``: the first point is repeated at the end); returns (curve, u_range) for :func:`walk_curve`."""
    from scipy.interpolate import CubicSpline

    pts = np.asarray(points, float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 3:
        raise InputError(f"a sampled path needs at least 3 points (x, y), got an array of shape {pts.shape}")
    if closed and np.hypot(*(pts[-1] - pts[0])) > 0:
        pts = np.vstack([pts, pts[:1]])
    chord = np.hypot(*np.diff(pts, axis=0).T)
    if np.any(chord <= 0):
        raise InputError(f"sampled path: point {int(np.argmin(chord)) + 1} repeats the point before it")
    u = np.concatenate([[0.0], np.cumsum(chord)])
    sp = CubicSpline(u, pts, bc_type="periodic" if closed else "natural")
    pad = u[-1]  # the stencils look past the ends: a periodic spline wraps, a natural one extrapolates its cubic

    def curve(w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ww = np.mod(w, pad) if closed else w
        p = sp(ww)
        return p[..., 0], p[..., 1]

    return curve, (0.0, float(u[-1]))


@dataclass(frozen=True)
class JointMotion:
    """Positions, rates and accelerations of a two-joint arm's joints along a path (SI: rad for a revolute
    joint, m for a prismatic one, s), one value per path sample.

    The RP arm (q1 the revolute angle, q2 the extension), the RR arm (q1, q2 the joint angles) and the
    five-bar (q1 the left motor angle, q2 the right one) all return this. Former names, deprecated aliases of
    this class: ``RPJointMotion``, ``RRJointMotion``, ``FiveBarJointMotion``."""

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
    reach_max: QuantityLike | None = "1 m"  # None: no limit
    carriage_mass: QuantityLike = "0 kg"
    arm_inertia: QuantityLike = "0 kg*m^2"
    arm_mass: QuantityLike = "0 kg"
    arm_com: QuantityLike = "0 m"
    gravity: QuantityLike = "9.80665 m/s^2"
    name: str = "RP arm"
    q1_min: QuantityLike | None = None
    q1_max: QuantityLike | None = None

    def _si(self) -> tuple[float, ...]:
        hi = math.inf if self.reach_max is None else to_si(self.reach_max, "length", "reach_max")
        return (to_si(self.reach_min, "length", "reach_min"), hi,
                to_si(self.carriage_mass, "mass", "carriage_mass"), to_si(self.arm_inertia, "inertia", "arm_inertia"),
                to_si(self.arm_mass, "mass", "arm_mass"), to_si(self.arm_com, "length", "arm_com"),
                to_si(self.gravity, "acceleration", "gravity"))

    def inverse(self, path: PathSamples) -> JointMotion:
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
        q1 = _within_limits(np.unwrap(np.arctan2(y, x)), _angle_limits(self.q1_min, self.q1_max, "q1"),
                            "q1", self.name, path)
        dq2 = (x * vx + y * vy) / q2
        dq1 = (x * vy - y * vx) / q2**2
        ddq2 = (vx**2 + vy**2 + x * ax + y * ay) / q2 - dq2**2 / q2
        ddq1 = (x * ay - y * ax) / q2**2 - 2 * dq2 * dq1 / q2
        return JointMotion(path.t, q1, q2, dq1, dq2, ddq1, ddq2)

    def joint_loads(self, m: JointMotion) -> tuple[np.ndarray, np.ndarray]:
        """(tau1 [N m], F2 [N]) from Lagrange's equations (module docstring), inertial, Coriolis and gravity."""
        _lo, _hi, mc, J, ma, ra, g = self._si()
        tau1 = (J + mc * m.q2**2) * m.ddq1 + 2 * mc * m.q2 * m.dq2 * m.dq1 + (ma * ra + mc * m.q2) * g * np.cos(m.q1)
        F2 = mc * m.ddq2 - mc * m.q2 * m.dq1**2 + mc * g * np.sin(m.q1)
        return tau1, F2

    def energy(self, m: JointMotion) -> np.ndarray:
        """T + V [J] (module docstring)."""
        _lo, _hi, mc, J, ma, ra, g = self._si()
        T = 0.5 * (J + mc * m.q2**2) * m.dq1**2 + 0.5 * mc * m.dq2**2
        return T + (ma * ra + mc * m.q2) * g * np.sin(m.q1)


def _angle_limits(lo: QuantityLike | None, hi: QuantityLike | None, joint: str) -> tuple[float, float] | None:
    """(lo, hi) [rad] of a revolute joint, or None without limits."""
    if lo is None and hi is None:
        return None
    a = -math.inf if lo is None else to_si(lo, "angle", f"{joint}_min")
    b = math.inf if hi is None else to_si(hi, "angle", f"{joint}_max")
    if not b > a:
        shown = [v if isinstance(v, str) else fmt(Q(v)) for v in (lo, hi)]
        raise InputError(f"{joint}_max: must be above {joint}_min ({shown[0]}), got {shown[1]}")
    return a, b


def _within_limits(q: np.ndarray, limits: tuple[float, float] | None, joint: str, name: str,
                   path: PathSamples) -> np.ndarray:
    """The unwrapped joint angles shifted by whole turns into the limits (the first sample decides the turn);
    the first sample outside them is named in an :class:`UnreachablePoseError`."""
    if limits is None:
        return q
    lo, hi = limits
    if math.isfinite(lo):
        q = q - 2 * math.pi * math.floor((q[0] - lo) / (2 * math.pi))  # q[0] in [lo, lo + 2 pi)
    elif math.isfinite(hi):
        q = q - 2 * math.pi * math.ceil((q[0] - hi) / (2 * math.pi))  # q[0] in (hi - 2 pi, hi]
    tol = 1e-9 * max(1.0, abs(lo) if math.isfinite(lo) else 0.0, abs(hi) if math.isfinite(hi) else 0.0)
    bad = (q < lo - tol) | (q > hi + tol)
    if np.any(bad):
        i = int(np.argmax(bad))
        raise UnreachablePoseError(f"{name}: sample {i} (t = {path.t[i]:.4g} s, x = {path.x[i] * 1e3:.4g} mm, "
                                   f"y = {path.y[i] * 1e3:.4g} mm) needs {joint} = {math.degrees(q[i]):.4g} deg, "
                                   f"outside its limits {math.degrees(lo):.4g} to {math.degrees(hi):.4g} deg")
    return q


@dataclass(frozen=True)
class RRArm:
    """Planar RR (elbow) arm, shoulder at the origin: links l1, l2; q1 from +x, q2 of link 2 relative to link 1;
    ``elbow`` picks the branch: "down" q2 > 0 (link 2 turned counter-clockwise from link 1, so the elbow lies
    clockwise of the shoulder-tip line), "up" q2 < 0.

    Dynamics data: link masses m1, m2 with centres of mass at lc1, lc2 from their proximal joints and centroidal
    inertias I1, I2; ``payload`` a point mass at the tip. Lagrange's equations of the planar elbow manipulator
    (Spong, Hutchinson & Vidyasagar, Robot Modeling and Control, Sec. 7.4.2):

        d11 = m1 lc1^2 + m2 (l1^2 + lc2^2 + 2 l1 lc2 cos q2) + I1 + I2,  d12 = m2 (lc2^2 + l1 lc2 cos q2) + I2,
        d22 = m2 lc2^2 + I2,  h = -m2 l1 lc2 sin q2,
        tau1 = d11 q1'' + d12 q2'' + 2 h q1' q2' + h q2'^2 + (m1 lc1 + m2 l1) g cos q1 + m2 lc2 g cos(q1 + q2),
        tau2 = d12 q1'' + d22 q2'' - h q1'^2 + m2 lc2 g cos(q1 + q2),

    with the payload merged into link 2 (mass, centre of mass and inertia by the parallel-axis theorem)."""

    l1: QuantityLike
    l2: QuantityLike
    elbow: str = "down"
    link1_mass: QuantityLike = "0 kg"
    link2_mass: QuantityLike = "0 kg"
    link1_com: QuantityLike | None = None  # default l1/2
    link2_com: QuantityLike | None = None  # default l2/2
    link1_inertia: QuantityLike = "0 kg*m^2"  # about the link's centre of mass
    link2_inertia: QuantityLike = "0 kg*m^2"
    payload: QuantityLike = "0 kg"
    gravity: QuantityLike = "9.80665 m/s^2"
    q1_min: QuantityLike | None = None
    q1_max: QuantityLike | None = None
    q2_min: QuantityLike | None = None
    q2_max: QuantityLike | None = None
    name: str = "RR arm"

    def _si(self) -> tuple[float, ...]:
        l1, l2 = to_si(self.l1, "length", "l1"), to_si(self.l2, "length", "l2")
        if not (l1 > 0 and l2 > 0):
            raise InputError(f"{self.name}: link lengths must be > 0, got l1 = {self.l1!r}, l2 = {self.l2!r}")
        if self.elbow not in ("up", "down"):
            raise InputError(f"{self.name}: elbow must be 'up' or 'down', got {self.elbow!r}")
        m1, m2 = to_si(self.link1_mass, "mass", "link1_mass"), to_si(self.link2_mass, "mass", "link2_mass")
        lc1 = l1 / 2 if self.link1_com is None else to_si(self.link1_com, "length", "link1_com")
        lc2 = l2 / 2 if self.link2_com is None else to_si(self.link2_com, "length", "link2_com")
        I1, I2 = to_si(self.link1_inertia, "inertia", "link1_inertia"), to_si(self.link2_inertia, "inertia",
                                                                                "link2_inertia")
        mp, g = to_si(self.payload, "mass", "payload"), to_si(self.gravity, "acceleration", "gravity")
        M2 = m2 + mp  # link 2 with the payload
        lcm = (m2 * lc2 + mp * l2) / M2 if M2 > 0 else lc2
        IM = I2 + m2 * (lc2 - lcm) ** 2 + mp * (l2 - lcm) ** 2
        return l1, l2, m1, lc1, I1, M2, lcm, IM, g

    def forward(self, q1: np.ndarray, q2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Tip position (x, y) [m]."""
        l1, l2 = self._si()[:2]
        return l1 * np.cos(q1) + l2 * np.cos(q1 + q2), l1 * np.sin(q1) + l2 * np.sin(q1 + q2)

    def inverse(self, path: PathSamples) -> JointMotion:
        """Joint angles by the law of cosines, rates q' = J^-1 v and accelerations q'' = J^-1 (a - J' q').

        Raises UnreachablePoseError (the first sample out of the annulus |l1 - l2| <= r <= l1 + l2, or outside a
        joint limit) or SingularPoseError (the first sample with sin q2 = 0: arm stretched or folded)."""
        l1, l2 = self._si()[:2]
        x, y = path.x, path.y
        c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2)
        tol = 1e-9
        bad = np.abs(c2) > 1 + tol
        c2c = np.clip(c2, -1.0, 1.0)
        sing = np.sqrt(1 - c2c * c2c) < 1e-4  # within 0.006 deg of stretched or folded: rates 1e4 x the tool speed
        if np.any(bad) and not (np.any(sing) and np.argmax(sing) < np.argmax(bad)):
            i = int(np.argmax(bad))
            r = math.hypot(x[i], y[i])
            raise UnreachablePoseError(f"{self.name}: sample {i} (t = {path.t[i]:.4g} s, x = {x[i] * 1e3:.4g} mm, "
                                       f"y = {y[i] * 1e3:.4g} mm) is {r * 1e3:.4g} mm from the shoulder, outside the "
                                       f"reach {abs(l1 - l2) * 1e3:.4g} to {(l1 + l2) * 1e3:.4g} mm")
        c2 = c2c
        s2 = np.sqrt(1 - c2 * c2) * (1.0 if self.elbow == "down" else -1.0)
        if np.any(sing):
            i = int(np.argmax(sing))
            raise SingularPoseError(f"{self.name}: sample {i} (t = {path.t[i]:.4g} s, x = {x[i] * 1e3:.4g} mm, "
                                    f"y = {y[i] * 1e3:.4g} mm) has the arm {'stretched' if c2[i] > 0 else 'folded'} "
                                    f"(q2 = {math.degrees(math.atan2(s2[i], c2[i])):.4g} deg, sin q2 = {s2[i]:.2g}): "
                                    "the joint rates are undefined")
        q2 = np.arctan2(s2, c2)
        q1 = np.unwrap(np.arctan2(y, x) - np.arctan2(l2 * s2, l1 + l2 * c2))
        q1 = _within_limits(q1, _angle_limits(self.q1_min, self.q1_max, "q1"), "q1", self.name, path)
        q2 = _within_limits(q2, _angle_limits(self.q2_min, self.q2_max, "q2"), "q2", self.name, path)
        s1, c1, s12, c12 = np.sin(q1), np.cos(q1), np.sin(q1 + q2), np.cos(q1 + q2)
        j11, j12, j21, j22 = -l1 * s1 - l2 * s12, -l2 * s12, l1 * c1 + l2 * c12, l2 * c12
        det = j11 * j22 - j12 * j21  # = l1 l2 sin q2
        dq1 = (j22 * path.vx - j12 * path.vy) / det
        dq2 = (-j21 * path.vx + j11 * path.vy) / det
        w12 = dq1 + dq2
        bx = path.ax + l1 * c1 * dq1**2 + l2 * c12 * w12**2  # a - J' q'
        by = path.ay + l1 * s1 * dq1**2 + l2 * s12 * w12**2
        ddq1 = (j22 * bx - j12 * by) / det
        ddq2 = (-j21 * bx + j11 * by) / det
        return JointMotion(path.t, q1, q2, dq1, dq2, ddq1, ddq2)

    def joint_loads(self, m: JointMotion) -> tuple[np.ndarray, np.ndarray]:
        """(tau1, tau2) [N m] from Lagrange's equations (class docstring)."""
        l1, _l2, m1, lc1, I1, M2, lc2, I2, g = self._si()
        c2 = np.cos(m.q2)
        d11 = m1 * lc1**2 + M2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * c2) + I1 + I2
        d12 = M2 * (lc2**2 + l1 * lc2 * c2) + I2
        d22 = M2 * lc2**2 + I2
        h = -M2 * l1 * lc2 * np.sin(m.q2)
        g2 = M2 * lc2 * g * np.cos(m.q1 + m.q2)
        tau1 = d11 * m.ddq1 + d12 * m.ddq2 + 2 * h * m.dq1 * m.dq2 + h * m.dq2**2 + (m1 * lc1 + M2 * l1) * g * np.cos(
            m.q1) + g2
        tau2 = d12 * m.ddq1 + d22 * m.ddq2 - h * m.dq1**2 + g2
        return tau1, tau2

    def energy(self, m: JointMotion) -> np.ndarray:
        """T + V [J] of the two links and the payload (from the centres of mass' velocities, not from d_ij)."""
        l1, _l2, m1, lc1, I1, M2, lc2, I2, g = self._si()
        w1, w12 = m.dq1, m.dq1 + m.dq2
        v1 = lc1 * w1
        vx2 = -l1 * np.sin(m.q1) * w1 - lc2 * np.sin(m.q1 + m.q2) * w12
        vy2 = l1 * np.cos(m.q1) * w1 + lc2 * np.cos(m.q1 + m.q2) * w12
        T = 0.5 * (m1 * v1**2 + I1 * w1**2 + M2 * (vx2**2 + vy2**2) + I2 * w12**2)
        V = g * (m1 * lc1 * np.sin(m.q1) + M2 * (l1 * np.sin(m.q1) + lc2 * np.sin(m.q1 + m.q2)))
        return T + V

    def joint_inertias(self, q2: np.ndarray) -> tuple[np.ndarray, float]:
        """(d11 at each q2, d22) [kg m^2]: the inertia about q1 (links and payload) and about q2 (class docstring)."""
        l1, _l2, m1, lc1, I1, M2, lc2, I2, _g = self._si()
        return m1 * lc1**2 + M2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * np.cos(q2)) + I1 + I2, M2 * lc2**2 + I2

    def reach(self) -> tuple[float, float]:
        """(inner, outer) radius [m] of the annulus the tip reaches without joint limits."""
        l1, l2 = self._si()[:2]
        return abs(l1 - l2), l1 + l2


@dataclass(frozen=True)
class LinkBody:
    """A homogeneous body fixed to an arm's link, for the link's mass, first moment and inertia about its joint.

    ``shape``: "rod" (slender, along the link, ``length``), "cylinder" (solid, along the link, ``length`` and
    ``radius``), "tube" (hollow: ``radius`` outer, ``inner_radius``), "point" (a lumped mass). It starts at
    ``start`` from the joint axis (rod, cylinder, tube) or sits there (point). Inertia about the joint axis
    (normal to the plane): the centroidal transverse inertia of the shape (mechverify.components.mass_properties)
    plus m c^2 with c the centre's distance (parallel-axis theorem)."""

    shape: str
    mass: QuantityLike
    length: QuantityLike | None = None
    radius: QuantityLike | None = None
    inner_radius: QuantityLike | None = None
    start: QuantityLike = "0 m"
    name: str = ""

    def properties(self) -> tuple[float, float, float]:
        """(m [kg], m c [kg m], I about the joint [kg m^2])."""
        from mechverify.components import mass_properties as mp

        what = self.name or self.shape
        m = to_si(self.mass, "mass", f"{what}.mass")
        s0 = to_si(self.start, "length", f"{what}.start")
        if self.shape == "point":
            return m, m * s0, m * s0 * s0
        if self.shape not in ("rod", "cylinder", "tube"):
            raise InputError(f"{what}.shape: expected rod, cylinder, tube or point, got {self.shape!r}")
        if self.length is None:
            raise InputError(f"{what}.length: a {self.shape} needs its length")
        L = to_si(self.length, "length", f"{what}.length")
        if self.shape == "rod":
            Ic = mp.rod_about_centre(self.mass, self.length)
        elif self.radius is None:
            raise InputError(f"{what}.radius: a {self.shape} needs its radius")
        elif self.shape == "cylinder":
            Ic = mp.solid_cylinder_transverse(self.mass, self.radius, self.length)
        else:
            Ic = mp.hollow_cylinder_transverse(self.mass, self.radius, self.inner_radius or "0 m", self.length)
        c = s0 + L / 2
        return m, m * c, float(Ic.m_as("kg*m**2")) + m * c * c


def compose_bodies(bodies: tuple[LinkBody, ...] | list[LinkBody]) -> tuple[float, float, float]:
    """(total mass [kg], centre of mass from the joint [m], inertia about the joint [kg m^2]) of bodies on a link."""
    m = mr = J = 0.0
    for b in bodies:
        bm, bmr, bJ = b.properties()
        m, mr, J = m + bm, mr + bmr, J + bJ
    return m, (mr / m if m > 0 else 0.0), J


def _perp(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def _cross2(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def five_bar_inverse(fb: object, path: PathSamples, working_mode: str = "-+",
                     limits: dict[str, tuple[QuantityLike, QuantityLike]] | None = None,
                     singular_tol: float = 1e-3) -> JointMotion:
    """Inverse kinematics of a :class:`~mechverify.mechanisms.fivebar.FiveBar` along a path: the motor angles at
    every sample, their rates from A P' = B theta' (the five-bar's velocity equation, ``jacobian_parts``) and
    accelerations from its time derivative A' P' + A P'' = B' theta' + B theta'' (exact in the path's derivatives).
    ``limits`` {"theta_left": (lo, hi), "theta_right": ...}; the first unreachable, out-of-limit or singular sample
    (a measure at or below ``singular_tol``) is named."""
    name = getattr(fb, "name", "five-bar")
    lim = {k: _angle_limits(v[0], v[1], k) for k, v in (limits or {}).items()}
    n = len(path.t)
    q = np.zeros((n, 2))
    dq = np.zeros((n, 2))
    ddq = np.zeros((n, 2))
    for i in range(n):
        where = f"sample {i} (t = {path.t[i]:.4g} s, x = {path.x[i] * 1e3:.4g} mm, y = {path.y[i] * 1e3:.4g} mm)"
        try:
            pose = fb.inverse((Q(path.x[i], "m"), Q(path.y[i], "m")), working_mode)  # type: ignore[attr-defined]
        except UnreachablePoseError as exc:
            raise UnreachablePoseError(f"{name}: {where} is out of reach ({exc})") from None
        m = fb.singularity_measures(pose)  # type: ignore[attr-defined]
        worst = min(m, key=lambda k: m[k])
        if m[worst] <= singular_tol:
            raise SingularPoseError(f"{name}: {where} is at a {worst.replace('_', ' ')} singularity "
                                    f"(sin = {m[worst]:.3g} <= {singular_tol:g})")
        A1, B1, P, B2, A2 = pose.A1, pose.B1, pose.P, pose.B2, pose.A2
        t = np.array([pose.theta_left.m_as("rad"), pose.theta_right.m_as("rad")])
        v, a = np.array([path.vx[i], path.vy[i]]), np.array([path.ax[i], path.ay[i]])
        A = np.vstack([P - B1, P - B2])
        b = np.array([_cross2(B1 - A1, P - B1), _cross2(B2 - A2, P - B2)])
        w = (A @ v) / b
        dB1, dB2 = w[0] * _perp(B1 - A1), w[1] * _perp(B2 - A2)
        dA = np.vstack([v - dB1, v - dB2])
        db = np.array([_cross2(dB1, P - B1) + _cross2(B1 - A1, v - dB1),
                       _cross2(dB2, P - B2) + _cross2(B2 - A2, v - dB2)])
        q[i], dq[i], ddq[i] = t, w, (dA @ v + A @ a - db * w) / b
    for k, key in enumerate(("theta_left", "theta_right")):
        q[:, k] = np.unwrap(q[:, k])
        if key in lim:
            q[:, k] = _within_limits(q[:, k], lim[key], key, name, path)
    unknown = set(lim) - {"theta_left", "theta_right"}
    if unknown:
        raise InputError(f"{name}: unknown joint {sorted(unknown)[0]!r} in limits (theta_left, theta_right)")
    return JointMotion(path.t, q[:, 0], q[:, 1], dq[:, 0], dq[:, 1], ddq[:, 0], ddq[:, 1])


def five_bar_payload_torques(fb: object, path: PathSamples, motion: JointMotion, payload: QuantityLike,
                             gravity: QuantityLike = "9.80665 m/s^2", working_mode: str = "-+"
                             ) -> tuple[np.ndarray, np.ndarray]:
    """Motor torques (left, right) [N m] that move a point ``payload`` at the tool along the path against gravity
    (-y), massless links: the d'Alembert force on the tool F = m (g - a) held by virtual work, tau = -J^T F
    (:meth:`FiveBar.holding_torques`)."""
    m, g = to_si(payload, "mass", "payload"), to_si(gravity, "acceleration", "gravity")
    out = np.zeros((len(path.t), 2))
    for i in range(len(path.t)):
        pose = fb.inverse((Q(path.x[i], "m"), Q(path.y[i], "m")), working_mode)  # type: ignore[attr-defined]
        F = (Q(-m * path.ax[i], "N"), Q(-m * (path.ay[i] + g), "N"))
        tl, tr = fb.holding_torques(pose, F)  # type: ignore[attr-defined]
        out[i] = tl.m_as("N*m"), tr.m_as("N*m")
    return out[:, 0], out[:, 1]


# Former names (one JointMotion for the RP, RR and five-bar arms; they were three identical classes), deprecated.
__getattr__ = renamed(__name__, {"RPJointMotion": "JointMotion", "RRJointMotion": "JointMotion",
                                 "FiveBarJointMotion": "JointMotion"})
