"""The cable spine tilted in any direction: a pan between cables, solved as a 3D elastic rod.

:class:`~mechverify.mechanisms.cable_spine.CableSpine` solves the spine in the tilt plane with the one cable that
lies in it. For a pan between two cables both pull, their resultant is not in a plane of symmetry (except midway),
and the spring bends and twists in 3D. Here the spring column is a Kirchhoff rod (clamped at the base, the
platform rigid on its top) with Timoshenko & Gere's bending rigidity beta0 (Sec. 2.18), the helical spring's
twisting rigidity C0 = E I L0/(pi D Na) (the torsion-spring rate E d^4/(64 D Na) times L0; Shigley 10th ed.
Eq. 10-44 with the wire in bending) and its axial rate k (extension lam = 1 + F.d3/(k L0)); loads at the top only
(the cables and the weight W), so the internal force is constant and the moment m(s) = M_top + (r_top - r(s)) x F:

    r' = lam d3,  d_i' = omega x d_i,  omega = (m.d1/beta0) d1 + (m.d2/beta0) d2 + (m.d3/C0) d3

(Antman, Nonlinear Problems of Elasticity, Ch. 8; the planar case is ``integrate_elastica``). The two cables that
bracket the pan pull (the third is slack: the least-tension choice, as ``tension_distribution`` finds), and one
Newton solve finds the top position and orientation and the two tensions for which the rod closes on the platform
and the platform's normal has the asked tilt and pan; the twist the cables leave is reported. Shear is neglected
(it changes the planar results by < 0.1 %; the critical load keeps it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mechverify.errors import InputError
from mechverify.units import Q, QuantityLike, to_si


@dataclass(frozen=True)
class SpineState3D:
    """Equilibrium of the spine at a tilt and pan (SI: N, m, rad)."""

    tilt: float
    pan: float
    tensions: np.ndarray  # per cable [N] (slack cables 0)
    top: np.ndarray  # spring-top position (x, y, z) [m]
    twist: float  # rotation of the platform about its normal left by the cables [rad]
    axial_force: float  # vertical force on the spring top, P = W - sum T_i u_iz [N]


def _rotation(tilt: float, pan: float) -> np.ndarray:
    cp, sp, ct, st = math.cos(pan), math.sin(pan), math.cos(tilt), math.sin(tilt)
    Rz = np.array([[cp, -sp, 0], [sp, cp, 0], [0, 0, 1.0]])
    Ry = np.array([[ct, 0, st], [0, 1, 0], [-st, 0, ct]])
    return Rz @ Ry @ Rz.T


def _rotvec(v: np.ndarray) -> np.ndarray:
    """Rotation matrix of the rotation vector v (Rodrigues)."""
    th = float(np.linalg.norm(v))
    if th < 1e-15:
        return np.eye(3)
    k = v / th
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(th) * K + (1 - math.cos(th)) * K @ K


def _log(R: np.ndarray) -> np.ndarray:
    """Rotation vector of a rotation matrix near the identity."""
    c = max(-1.0, min(1.0, (np.trace(R) - 1) / 2))
    th = math.acos(c)
    w = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return w / 2 if th < 1e-8 else w * th / (2 * math.sin(th))


def spine_parameters(spine: object) -> dict[str, float | np.ndarray]:
    """SI inputs of a :class:`CableSpine` from its public fields: a, b, cable angles g, W, k, L0, beta0, C0."""
    sp = spine.spring  # type: ignore[attr-defined]
    r = sp.rigidities()
    beta0 = r.beta.m_as("N*m**2") if spine.beta0 is None else Q(spine.beta0).m_as("N*m**2")  # type: ignore[attr-defined]
    L0 = sp.free_length.m_as("m")
    R = sp.mean_diameter.m_as("m") / 2
    C0 = r.gamma.m_as("N") * R * R / 2  # E I L0/(pi n D) = gamma0 R^2/2 (gamma0 = E I L0/(pi n R^3))
    g = np.array([to_si(x, "angle", "cable_angles") for x in spine.cable_angles])  # type: ignore[attr-defined]
    return {"a": to_si(spine.platform_radius, "length", "platform_radius"),  # type: ignore[attr-defined]
            "b": to_si(spine.base_radius, "length", "base_radius"),  # type: ignore[attr-defined]
            "g": g, "W": to_si(spine.weight, "force", "weight"), "k": sp.rate.m_as("N/m"),  # type: ignore[attr-defined]
            "L0": L0, "beta0": beta0, "C0": C0}


def integrate_rod(F: np.ndarray, M_top: np.ndarray, r_top: np.ndarray, beta0: float, C0: float, L0: float,
                  alpha0: float = math.inf) -> tuple[np.ndarray, np.ndarray]:
    """Top position and director frame (columns d1 d2 d3) of the base-clamped rod under the top force F and the
    moment M_top about the (assumed) top point r_top."""
    from scipy.integrate import solve_ivp

    def rhs(_s: float, y: np.ndarray) -> np.ndarray:
        r, R = y[:3], y[3:].reshape(3, 3)
        m = M_top + np.cross(r_top - r, F)
        kb = R.T @ m  # body components
        omega = R @ np.array([kb[0] / beta0, kb[1] / beta0, kb[2] / C0])
        lam = 1.0 + float(F @ R[:, 2]) / alpha0
        dR = np.cross(omega[None, :], R.T).T  # d_i' = omega x d_i, column-wise
        return np.concatenate([lam * R[:, 2], dR.ravel()])

    y0 = np.concatenate([np.zeros(3), np.eye(3).ravel()])
    sol = solve_ivp(rhs, (0.0, L0), y0, rtol=1e-11, atol=1e-13, method="DOP853")
    y = sol.y[:, -1]
    return y[:3], y[3:].reshape(3, 3)


def _loads(p: dict, top: np.ndarray, R: np.ndarray, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Resultant force on the platform and its moment about the spring top."""
    a, b, g = p["a"], p["b"], p["g"]
    F = np.array([0.0, 0.0, -p["W"]])
    M = np.zeros(3)
    for gi, Ti in zip(g, T, strict=True):
        if Ti == 0:
            continue
        arm = R @ np.array([a * math.cos(gi), a * math.sin(gi), 0.0])
        u = np.array([b * math.cos(gi), b * math.sin(gi), 0.0]) - (top + arm)
        f = Ti * u / np.linalg.norm(u)
        F, M = F + f, M + np.cross(arm, f)
    return F, M


def bracketing_cables(g: np.ndarray, pan: float) -> tuple[int, int | None]:
    """The cable along the pan (second None), or the two whose angles bracket it."""
    rel = (np.asarray(g) - pan + math.pi) % (2 * math.pi) - math.pi
    i = int(np.argmin(np.abs(rel)))
    if abs(rel[i]) < 1e-9:
        return i, None
    neg = [k for k in range(len(g)) if rel[k] < 0]
    pos = [k for k in range(len(g)) if rel[k] > 0]
    if not neg or not pos:
        raise InputError("the cables do not surround the spine: no pair brackets the pan")
    return max(neg, key=lambda k: rel[k]), min(pos, key=lambda k: rel[k])


def state_3d(spine: object, tilt: QuantityLike, pan: QuantityLike, guess: SpineState3D | None = None
             ) -> SpineState3D:
    """Equilibrium of the spine with the platform's normal at ``tilt`` from the vertical towards ``pan``."""
    from scipy.optimize import fsolve

    from mechverify.mechanisms.cable_spine import SpineBucklingError, UnreachableTiltError

    p = spine_parameters(spine)
    th, ph = to_si(tilt, "angle", "tilt"), to_si(pan, "angle", "pan")
    if not 0 < th < math.pi / 2:
        raise InputError(f"tilt must lie between 0 and 90 deg, got {math.degrees(th):g} deg")
    i, j = bracketing_cables(p["g"], ph)
    pulling = [i] if j is None else [i, j]
    alpha0 = p["k"] * p["L0"]
    Rt = _rotation(th, ph)
    if guess is None:  # the planar solution along the pan direction, tension shared by the angular distance
        lin = spine.at_tilt(Q(th, "rad"), "linear")  # type: ignore[attr-defined]
        ep = np.array([math.cos(ph), math.sin(ph), 0.0])
        x0 = np.concatenate([lin.lateral * ep + np.array([0, 0, lin.height]), np.zeros(3),
                             [lin.tension] if j is None else
                             lin.tension * np.array([abs(math.cos(p["g"][k] - ph)) for k in pulling])])
    else:
        x0 = np.concatenate([guess.top, np.zeros(3), guess.tensions[pulling]])

    def unpack(x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        T = np.zeros(len(p["g"]))
        T[pulling] = x[6:]
        return x[:3], Rt @ _rotvec(x[3:6]), T

    def residual(x: np.ndarray) -> np.ndarray:
        top, R, T = unpack(x)
        F, M = _loads(p, top, R, T)
        r, D = integrate_rod(F, M, top, p["beta0"], p["C0"], p["L0"], alpha0)
        rot = _log(R.T @ D)  # rod end frame against the platform frame
        out = [*(r - top) / p["L0"], *rot]
        n = R[:, 2]
        if j is None:  # one cable: the tilt (the pan holds by symmetry)
            out.append(math.acos(max(-1.0, min(1.0, n[2]))) - th)
        else:  # the platform normal's direction: two components
            nt = Rt[:, 2]
            e1 = np.cross(np.array([0.0, 0.0, 1.0]), nt)
            e1 /= np.linalg.norm(e1)
            e2 = np.cross(nt, e1)
            out += [float(n @ e1), float(n @ e2)]
        return np.array(out)

    x, _info, ier, msg = fsolve(residual, x0, xtol=1e-12, full_output=True)
    res = residual(x)
    if float(np.max(np.abs(res))) > 1e-8:
        raise SpineBucklingError(f"no 3D equilibrium at tilt {math.degrees(th):.4g} deg, pan {math.degrees(ph):.4g} "
                                 f"deg ({msg})")
    top, R, T = unpack(x)
    if np.any(T < -1e-9):
        k = int(np.argmin(T))
        raise UnreachableTiltError(f"cable {k} would have to push ({T[k]:.4g} N) to hold tilt "
                                   f"{math.degrees(th):.4g} deg at pan {math.degrees(ph):.4g} deg")
    F, _ = _loads(p, top, R, T)
    twist = float(_log(Rt.T @ R) @ Rt[:, 2])
    return SpineState3D(th, ph, T, top, twist, float(-F[2]))


def as_spine_state(spine: object, st: SpineState3D) -> object:
    """The 3D state in the planar :class:`SpineState`'s terms for the checks: the most loaded cable's tension,
    the top's lateral displacement and lowering, the axial force and the rigidities at l = L0 - P/k."""
    from mechverify.mechanisms.cable_spine import SpineState

    p = spine_parameters(spine)
    P = st.axial_force
    l = p["L0"] - P / p["k"]
    gamma0 = spine.spring.rigidities().gamma.m_as("N")  # type: ignore[attr-defined]
    return SpineState(float(np.max(st.tensions)), st.tilt, float(np.hypot(st.top[0], st.top[1])), l - st.top[2], l,
                      math.nan, P, p["beta0"] * l / p["L0"], gamma0 * l / p["L0"], "elastica-3d")


__all__ = ["SpineState3D", "as_spine_state", "state_3d", "integrate_rod", "spine_parameters", "bracketing_cables"]
