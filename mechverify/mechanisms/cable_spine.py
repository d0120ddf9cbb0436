"""Cable-driven spring spine: a compression spring column, a top platform and N cables (seed 001's neck).

Geometry (the document's Ch. 4, Eqs. (4.1)-(4.7), a standard cable-driven parallel mechanism): base frame
OXYZ at the spring's bottom centre, cable i anchored on the base at A_i = b (cos g_i, sin g_i, 0) and on
the platform at B_i = a (cos g_i, sin g_i, 0) in the platform frame; platform orientation
R = R_z(pan) R_y(tilt) R_z(-pan) (tilt about the horizontal axis normal to the pan direction, no torsion),
top centre P; cable vector l_i = P + R B_i - A_i, length |l_i| (Eq. (4.7)).

Statics of the spine in the tilt plane, the cable in that plane pulling (the document's simplification
T3 = 0, Sec. 3.2.2): the spring is a column clamped at the base with the platform at its free top,
carrying the platform weight W at the top centre and the cable tension T at the platform edge.
Timoshenko & Gere, *Theory of Elastic Stability*, 2nd ed. (1961), Sec. 2.18: a helical spring acts as a
column of bending rigidity beta = beta0 l/L0, shear rigidity gamma = gamma0 l/L0 and axial rate k, its
length reduced to l = L0 - P/k under the axial load P. Two solutions:

* :meth:`CableSpine.linear_state` -- the small-deflection beam-column (Timoshenko & Gere Sec. 1.2-1.3,
  cantilever with axial load, end moment and lateral force; the document's Eqs. (3.9)-(3.19)), with
  the top lowered by z = 1/2 Int y'^2 dz. Valid for small slopes (the document: about 15 deg).
* :meth:`CableSpine.elastica_state` -- the large-deflection (inextensible-in-bending) elastica of the
  same column, solved by shooting: dtheta/ds0 = M(s)/beta0 along the unstrained arc length s0 (the
  curvature per deformed length is M/beta with beta = beta0 lambda, and ds = lambda ds0), with the
  local axial stretch lambda = 1 - N/(k L0) from the local axial force N. In the small-slope limit
  it reduces to the linear model (tests).

Buckling: fixed-free column with the shear correction of Timoshenko & Gere Eq. (2-46)
(Engesser): P_cr = P_e / (1 + P_e/gamma), P_e = pi^2 beta / (4 l^2), beta, gamma and l at the load.

Cable tensions over N >= 3 cables for a required moment (any pan): :func:`tension_distribution`,
the least total tension with every tension >= a minimum (linear programme); infeasible -> a named error.

References: [1] Timoshenko & Gere 1961, Secs. 1.2, 2.18; [2] seed 001 (Eqs. 3.9-3.19, 4.1-4.9) for
the problem statement only (its Tabla 5 beta0 is wrong by a factor 10).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from mechverify.components.springs import CompressionSpring
from mechverify.errors import InputError, ModelError, ValidityError
from mechverify.units import Q, Quantity, to_si


# scipy's integrate/optimize cost ~0.3 s to import: loaded on first use, not when a design file is checked.
def solve_ivp(*args, **kwargs):
    from scipy.integrate import solve_ivp as f

    return f(*args, **kwargs)


def brentq(*args, **kwargs):
    from scipy.optimize import brentq as f

    return f(*args, **kwargs)


def fsolve(*args, **kwargs):
    from scipy.optimize import fsolve as f

    return f(*args, **kwargs)


def linprog(*args, **kwargs):
    from scipy.optimize import linprog as f

    return f(*args, **kwargs)

QuantityLike = Quantity | str | float  # local alias (see COMMON: until mechverify.units exports one)


class SpineBucklingError(ModelError):
    """The cable tension asked for drives the spine past its buckling load (no equilibrium)."""


class UnreachableTiltError(ValidityError):
    """The cables cannot hold the requested tilt (with the reachable range in the message)."""


@dataclass(frozen=True)
class SpineState:
    """Equilibrium of the spine for one pulling-cable tension (SI: N, m, rad)."""

    tension: float  # T of the pulling cable [N]
    tilt: float  # platform tilt = slope of the spring top [rad]
    lateral: float  # lateral displacement of the spring top y_b [m]
    lowering: float  # lowering of the top by bending z_y (height = l - z_y) [m]
    length: float  # axially compressed spring length l [m]
    cable_angle: float  # cable angle from the vertical alpha [rad]
    axial_force: float  # P = W + T cos(alpha) [N] (vertical force on the top)
    beta: float  # bending rigidity at l [N m^2]
    gamma: float  # shear rigidity at l [N]
    method: str = "linear"

    @property
    def critical_load(self) -> float:
        """Fixed-free critical load with shear, P_e/(1 + P_e/gamma), P_e = pi^2 beta/(4 l^2) [1] Eq. 2-46."""
        Pe = math.pi**2 * self.beta / (4 * self.length**2)
        return Pe / (1 + Pe / self.gamma)

    @property
    def buckling_ratio(self) -> float:
        """P / P_cr (fixed-free, with shear); >= 1 is past buckling."""
        return self.axial_force / self.critical_load

    @property
    def euler_ratio(self) -> float:
        """P / (pi^2 beta / (4 l^2)), the bending-only ratio the document's model uses."""
        return self.axial_force / (math.pi**2 * self.beta / (4 * self.length**2))

    @property
    def height(self) -> float:
        """Height of the spring top above the base [m]."""
        return self.length - self.lowering


@dataclass(frozen=True)
class CableGeometry:
    """Cable lengths and unit directions (platform anchor -> base anchor) at one pose (SI)."""

    lengths: np.ndarray  # [m], one per cable
    directions: np.ndarray  # (N, 3) unit vectors from B_i to A_i (the pull on the platform)
    platform_points: np.ndarray  # (N, 3) B_i in the base frame [m]
    base_points: np.ndarray  # (N, 3) A_i [m]
    angles_from_vertical: np.ndarray  # [rad] cable angle to the -Z axis (pulley entry angle)


def rotation(tilt: float, pan: float) -> np.ndarray:
    """R = R_z(pan) R_y(tilt) R_z(-pan): tilt about the horizontal axis normal to the pan direction (Eq. 4.2
    with psi = -phi, no torsion about the spine)."""
    c, s = math.cos(pan), math.sin(pan)
    Rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    ct, st = math.cos(tilt), math.sin(tilt)
    Ry = np.array([[ct, 0.0, st], [0.0, 1.0, 0.0], [-st, 0.0, ct]])
    return Rz @ Ry @ Rz.T


@dataclass(frozen=True)
class CableSpine:
    """Spring spine + platform + cables. ``cable_angles``: anchor angles g_i about Z (same on base and
    platform); ``weight``: platform + payload at the top centre."""

    spring: CompressionSpring
    platform_radius: QuantityLike = "50 mm"
    base_radius: QuantityLike = "50 mm"
    cable_angles: Sequence[QuantityLike] = ("0 deg", "120 deg", "240 deg")
    weight: QuantityLike = "0 N"
    beta0: QuantityLike | None = None  # override of Timoshenko's beta0 (e.g. the document's wrong 0.554)
    name: str = "spine"

    def __post_init__(self) -> None:
        self.si  # noqa: B018 - the inputs are checked at construction

    @cached_property
    def si(self) -> dict[str, Any]:
        """The inputs in SI [m, rad, N] and the spring's values used by the model: ``a``, ``b`` (anchor radii),
        ``g`` (cable angles), ``W``, ``k``, ``L0``, ``Ls``, ``beta0``, ``gamma0``; read it, do not change it."""
        if not isinstance(self.spring, CompressionSpring):
            raise InputError(f"{self.name}: spring must be a CompressionSpring")
        a = to_si(self.platform_radius, "length", "platform_radius")
        b = to_si(self.base_radius, "length", "base_radius")
        if a <= 0 or b <= 0:
            raise InputError(f"{self.name}: anchor radii must be > 0 (a = {a:g} m, b = {b:g} m)")
        g = [to_si(x, "angle", "cable_angles") for x in self.cable_angles]
        if len(g) < 3:
            raise InputError(f"{self.name}: a 2-DOF tilt needs at least 3 cables, got {len(g)}")
        for i in range(len(g)):
            for j in range(i):
                gap = abs(math.remainder(g[i] - g[j], 2 * math.pi))
                if gap < 1e-6:  # the same anchor twice: two cables on one line (a 3-cable tilt loses a direction)
                    raise InputError(f"cable_angles: cables {j} and {i} have the same anchor angle "
                                     f"({math.degrees(g[i]):g} deg, modulo 360 deg); give distinct angles")
        W = to_si(self.weight, "force", "weight")
        if W < 0:
            raise InputError(f"{self.name}: weight must be >= 0, got {W:g} N")
        r = self.spring.rigidities()
        beta0 = r.beta.m_as("N*m**2") if self.beta0 is None else Q(self.beta0).m_as("N*m**2")
        if beta0 <= 0:
            raise InputError(f"{self.name}: beta0 must be > 0")
        return dict(
            a=a, b=b, g=np.array(g), W=W, k=self.spring.rate.m_as("N/m"), L0=self.spring.free_length.m_as("m"),
            Ls=self.spring.solid_length.m_as("m"), beta0=beta0, gamma0=r.gamma.m_as("N"))

    # ----------------------------------------------------------------------------------- kinematics
    def cable_geometry(self, tilt: QuantityLike, pan: QuantityLike = "0 deg", lateral: QuantityLike = "0 m",
                       height: QuantityLike | None = None) -> CableGeometry:
        """Inverse kinematics (Eqs. 4.1-4.7): platform at ``tilt``/``pan`` with its centre moved ``lateral``
        along the pan direction at ``height`` (default: the free length) -> cable lengths and directions."""
        s = self.si
        th, ph = to_si(tilt, "angle", "tilt"), to_si(pan, "angle", "pan")
        yb = to_si(lateral, "length", "lateral")
        h = s["L0"] if height is None else to_si(height, "length", "height")
        R = rotation(th, ph)
        P = np.array([yb * math.cos(ph), yb * math.sin(ph), h])
        plat = np.column_stack([s["a"] * np.cos(s["g"]), s["a"] * np.sin(s["g"]), np.zeros_like(s["g"])])
        base = np.column_stack([s["b"] * np.cos(s["g"]), s["b"] * np.sin(s["g"]), np.zeros_like(s["g"])])
        B = P + plat @ R.T
        vec = base - B
        lengths = np.linalg.norm(vec, axis=1)
        if np.any(B[:, 2] <= 0):
            i = int(np.argmin(B[:, 2]))
            raise UnreachableTiltError(f"{self.name}: at tilt {math.degrees(th):.4g} deg the anchor of cable {i + 1} "
                                       f"would be at or below the base plate")
        u = vec / lengths[:, None]
        return CableGeometry(lengths, u, B, base, np.arccos(np.clip(-u[:, 2], -1.0, 1.0)))

    def pulling_cable(self, pan: QuantityLike) -> int:
        """Index of the cable in the tilt plane on the side the platform tilts to (the planar model's T1)."""
        ph = to_si(pan, "angle", "pan")
        diff = np.abs((self.si["g"] - ph + math.pi) % (2 * math.pi) - math.pi)
        i = int(np.argmin(diff))
        if diff[i] > 1e-9:
            raise InputError(f"{self.name}: the planar spine model needs the pan along a cable "
                             f"(cable angles {', '.join(f'{math.degrees(x):g}' for x in self.si['g'])} deg); "
                             f"got {math.degrees(ph):g} deg")
        return i

    # ---------------------------------------------------------------------------- linear beam-column
    def _lin_residual(self, x: Sequence[float], T: float) -> tuple[list[float], SpineState]:
        s = self.si
        l, al, zy = x
        P = s["W"] + T * math.cos(al)
        if P <= 0 or l <= 0:
            raise SpineBucklingError(f"{self.name}: no compressive equilibrium (P = {P:.3g} N)")
        beta = s["beta0"] * l / s["L0"]
        w = math.sqrt(P / beta)
        wl = w * l
        if wl >= math.pi / 2:
            raise SpineBucklingError(f"{self.name}: axial force {P:.4g} N reaches the spine's fixed-free buckling load")
        a, b = s["a"], s["b"]
        th = 0.0
        for _ in range(300):  # the end moment depends on the tilt through the cable's lever arm
            a0 = (T * math.cos(al) * a * math.cos(th) + T * math.sin(al) * a * math.sin(th) - T * math.sin(al) * l) / P
            a1 = T * math.sin(al) / P
            th_new = math.atan(a0 * w * math.tan(wl) + a1 * (1 - 1 / math.cos(wl) + wl * math.tan(wl)))
            if abs(th_new - th) < 1e-15:
                break
            th = 0.5 * (th + th_new)
        yb = (1 - math.cos(wl)) / math.cos(wl) * a0 - a1 / w * math.tan(wl) + a1 * l / math.cos(wl)
        z = np.linspace(0.0, l, 401)
        slope = (yb + a0) * w * np.sin(w * z) - a1 * np.cos(w * z) + a1
        zy_new = 0.5 * float(np.trapezoid(slope**2, z))
        al_new = math.atan2(yb + a * math.cos(th) - b, l - zy - a * math.sin(th))
        st = SpineState(T, th, yb, zy, l, al, P, beta, s["gamma0"] * l / s["L0"], "linear")
        return [s["L0"] - P / s["k"] - l, al_new - al, zy_new - zy], st

    def linear_state(self, tension: QuantityLike, guess: Sequence[float] | None = None) -> SpineState:
        """Small-deflection beam-column equilibrium for a pulling-cable tension T ([1] Sec. 1.2-1.3; the
        document's Eqs. (3.9)-(3.19) with beta(l) = beta0 l/L0, l = L0 - P/k, z_y = 1/2 Int y'^2)."""
        T = tension if isinstance(tension, float) else to_si(tension, "force", "tension")
        s = self.si
        starts = [[s["L0"] - s["W"] / s["k"], 0.0, 0.0]]
        if guess is not None:  # continuation from a neighbouring equilibrium first
            starts.insert(0, list(guess))
        for x0 in starts:
            try:
                x, _info, ier, msg = fsolve(lambda x: self._lin_residual(x, T)[0], x0, xtol=1e-13, full_output=True)
                res, st = self._lin_residual(x, T)
            except SpineBucklingError as exc:
                ier, msg, res = 0, str(exc), [1.0]
            if ier == 1 and max(abs(r) for r in res) <= 1e-9:
                break
        else:
            raise SpineBucklingError(f"{self.name}: no small-deflection equilibrium for T = {T:.4g} N ({msg})")
        return st

    # ------------------------------------------------------------------------------------- elastica
    def _shoot(self, T: float, guess: Sequence[float]) -> tuple[np.ndarray, SpineState]:
        """Residual of the elastica for top state guess (x_t, z_t, theta_t)."""
        s = self.si
        xt, zt, tht = guess
        a = s["a"]
        Bx, Bz = xt + a * math.cos(tht), zt - a * math.sin(tht)
        dx, dz = s["b"] - Bx, -Bz
        L = math.hypot(dx, dz)
        ux, uz = dx / L, dz / L
        Fx, Fz = T * ux, T * uz - s["W"]
        # M0: moment about the top of the cable force at B (the weight acts at the top centre: no moment)
        M0 = (-a * math.sin(tht)) * T * ux - (a * math.cos(tht)) * T * uz
        x, z, th = integrate_elastica(Fx, Fz, M0, xt, zt, s["beta0"], s["L0"], s["k"] * s["L0"])
        P = -Fz
        l_axial = s["L0"] - P / s["k"]
        st = SpineState(T, th, x, l_axial - z, l_axial, math.atan2(-ux, -uz), P,
                        s["beta0"] * l_axial / s["L0"], s["gamma0"] * l_axial / s["L0"], "elastica")
        return np.array([x - xt, z - zt, th - tht]), st

    def elastica_state(self, tension: QuantityLike, guess: Sequence[float] | None = None) -> SpineState:
        """Large-deflection equilibrium for a pulling-cable tension T (shooting on the elastica)."""
        T = tension if isinstance(tension, float) else to_si(tension, "force", "tension")
        if guess is None:
            lin = self.linear_state(T)
            guess = [lin.lateral, lin.height, lin.tilt]
        x, _info, ier, msg = fsolve(lambda g: self._shoot(T, g)[0], list(guess), xtol=1e-12, full_output=True)
        res, st = self._shoot(T, x)
        if float(np.max(np.abs(res))) > 1e-10:
            raise SpineBucklingError(f"{self.name}: no large-deflection equilibrium found for T = {T:.4g} N ({msg})")
        return st

    # ------------------------------------------------------------------------------------ along tilt
    def at_tilt(self, tilt: QuantityLike, method: str = "linear") -> SpineState:
        """Tension of the pulling cable and the shape that hold the platform at ``tilt``."""
        target = to_si(tilt, "angle", "tilt")
        if method not in ("linear", "elastica"):
            raise InputError(f"{self.name}: method must be 'linear' or 'elastica', got {method!r}")
        if target < 0:
            raise InputError(f"{self.name}: tilt must be >= 0 (the pan gives the direction)")
        if target == 0 or self.si["W"] >= self.critical_load():
            try:
                return self.linear_state(0.0)
            except SpineBucklingError as exc:
                raise UnreachableTiltError(f"{self.name}: the weight {self.si['W']:.4g} N alone buckles the spine "
                                           f"(P_cr = {self.critical_load():.4g} N); reachable: no tilt") from exc
        guess: list[float] | None = None

        def state(T: float) -> SpineState:
            nonlocal guess
            if method == "linear":
                st = self.linear_state(T, guess)
                guess = [st.length, st.cable_angle, st.lowering]
                return st
            st = self.elastica_state(T, guess)
            guess = [st.lateral, st.height, st.tilt]
            return st

        T_lo, step, last = 0.0, 0.05, None
        while True:  # march up in tension (continuation), halving the step where no equilibrium is found
            T_hi = T_lo + step
            try:
                st = state(T_hi)
            except SpineBucklingError as exc:
                if step > 1e-7 * max(1.0, T_lo):
                    step *= 0.5
                    if last is not None:
                        guess = ([last.length, last.cable_angle, last.lowering] if method == "linear"
                                 else [last.lateral, last.height, last.tilt])
                    continue
                raise UnreachableTiltError(
                    f"{self.name}: tilt {math.degrees(target):.4g} deg is not reached before the spine buckles "
                    f"(reachable: 0 to {math.degrees(last.tilt) if last else 0:.4g} deg, at T = "
                    f"{last.tension if last else 0:.4g} N)") from exc
            if st.tilt >= target:
                break
            if last is not None and st.tilt <= last.tilt:
                raise UnreachableTiltError(f"{self.name}: the tilt stops growing at {math.degrees(last.tilt):.4g} "
                                           f"deg (T = {last.tension:.4g} N); {math.degrees(target):.4g} deg is "
                                           f"out of reach")
            last, T_lo, step = st, T_hi, min(step * 1.5, 0.25 * T_hi + 0.05)
        if last is not None:
            guess = ([last.length, last.cable_angle, last.lowering] if method == "linear"
                     else [last.lateral, last.height, last.tilt])
        T = brentq(lambda t: state(t).tilt - target, T_lo, T_hi, xtol=1e-12, rtol=1e-12)
        return state(T)

    def critical_load(self) -> float:
        """Axial load at which the spine buckles as a fixed-free column (SI, N): P = P_e(l)/(1 + P_e(l)/gamma(l)),
        P_e = pi^2 beta(l)/(4 l^2), l = L0 - P/k ([1] Sec. 2.18 with Eq. 2-46), solved for P."""
        s = self.si

        def f(P: float) -> float:
            l = s["L0"] - P / s["k"]
            beta, gamma = s["beta0"] * l / s["L0"], s["gamma0"] * l / s["L0"]
            Pe = math.pi**2 * beta / (4 * l * l)
            return Pe / (1 + Pe / gamma) - P

        P_solid = s["k"] * (s["L0"] - s["Ls"])
        if f(P_solid) > 0:
            return P_solid  # stable down to solid
        return brentq(f, 0.0, P_solid, xtol=1e-12)


def integrate_elastica(Fx: float, Fz: float, M0: float, xt: float, zt: float, beta0: float, L0: float,
                       alpha0: float = math.inf) -> tuple[float, float, float]:
    """Integrate a base-clamped elastica (SI) loaded at its top (xt, zt) by the force (Fx, Fz) and the moment M0:
    dtheta/ds0 = M/beta0, M = M0 + (zt - z) Fx - (xt - x) Fz, dx/ds0 = lam sin(theta), dz/ds0 = lam cos(theta),
    lam = 1 - N/alpha0 with the axial force N = -(Fx sin(theta) + Fz cos(theta)) (alpha0 = k L0; inf:
    inextensible). Returns the top (x, z, theta) of the integration; equilibrium is where it meets (xt, zt)."""

    def rhs(_s0: float, y: np.ndarray) -> list[float]:
        x, z, th = y
        M = M0 + (zt - z) * Fx - (xt - x) * Fz
        lam = 1.0 + (Fx * math.sin(th) + Fz * math.cos(th)) / alpha0
        return [lam * math.sin(th), lam * math.cos(th), M / beta0]

    sol = solve_ivp(rhs, (0.0, L0), [0.0, 0.0, 0.0], rtol=1e-11, atol=1e-13, method="DOP853")
    x, z, th = sol.y[:, -1]
    return float(x), float(z), float(th)


def tension_distribution(directions: np.ndarray, arms: np.ndarray, moment: np.ndarray,
                         minimum: float = 0.0) -> np.ndarray:
    """Cable tensions T_i >= ``minimum`` giving the moment ``moment`` about the top (its two components
    normal to Z; the spine takes the axial part): sum_i (r_i x u_i) T_i = M, least sum of T (linprog).

    ``directions`` (N, 3) unit pulls, ``arms`` (N, 3) anchor points relative to the moment centre [m].
    No solution -> :class:`UnreachableTiltError` (the cables cannot produce that moment while all pull)."""
    A = np.cross(arms, directions)[:, :2].T
    n = A.shape[1]
    res = linprog(np.ones(n), A_eq=A, b_eq=np.asarray(moment, float)[:2], bounds=[(minimum, None)] * n,
                  method="highs")
    if res.status != 0:
        raise UnreachableTiltError(f"the cables cannot produce the moment ({moment[0]:.4g}, {moment[1]:.4g}) N m "
                                   f"with every tension >= {minimum:g} N ({res.message})")
    return res.x


def free_spring_length(spring: CompressionSpring, weight: QuantityLike) -> Quantity:
    """Zero-tension limit: the upright spring under the top weight, l = L0 - W/k (Shigley Eq. 10-9 rate)."""
    W = to_si(weight, "force", "weight")
    return Q(spring.free_length.m_as("m") - W / spring.rate.m_as("N/m"), "m").to("mm")
