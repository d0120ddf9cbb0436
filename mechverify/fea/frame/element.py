"""The 3D beam element: local axes, exact prismatic stiffness (Euler-Bernoulli or Timoshenko),
fixed-end forces of linearly varying loads, end releases by static condensation, and the exact
fields (polynomials in the position s) between the nodes.

References
----------
1. J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968 (Dover 1985),
   Sec. 5.6 (beam element with shear deformation), Sec. 5.7 (fixed-end forces).
2. W. McGuire, R. H. Gallagher, R. D. Ziemian, *Matrix Structural Analysis*, 2nd ed., Wiley 2000,
   Sec. 4.3-4.5 (3D frame element, transformation), Sec. 7.3 (member end releases by condensation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError

#: Words for the 12 local end DOFs.
LOCAL_WORDS = ("axial translation", "translation along local y", "translation along local z", "twist about the axis",
               "rotation about local y", "rotation about local z")


def local_axes(p1: np.ndarray, p2: np.ndarray, orientation: Any = None, roll: float = 0.0) -> np.ndarray:
    """Rows e_x, e_y, e_z of a member's local frame (global components); ``roll`` turns y, z about x."""
    ex = p2 - p1
    ex = ex / np.linalg.norm(ex)
    if orientation is None:
        ref = np.array([0.0, 0.0, 1.0]) if abs(ex[2]) < 1.0 - 1e-9 else np.array([1.0, 0.0, 0.0])
    else:
        ref = np.asarray(orientation, dtype=float)
    ez = ref - np.dot(ref, ex) * ex
    if np.linalg.norm(ez) < 1e-9 * np.linalg.norm(ref):
        raise InputError("member orientation is parallel to the member; give a vector across it")
    ez /= np.linalg.norm(ez)
    ey = np.cross(ez, ex)
    if roll:
        c, s = math.cos(roll), math.sin(roll)
        ey, ez = c * ey + s * ez, -s * ey + c * ez
    return np.vstack((ex, ey, ez))


def local_axes_batch(a: np.ndarray, b: np.ndarray, orientations: list[Any], rolls: np.ndarray | None = None
                     ) -> np.ndarray:
    """:func:`local_axes` of many members ``[n, 3, 3]``; ``orientations[i]`` None for the default."""
    ex = b - a
    ex = ex / np.linalg.norm(ex, axis=1)[:, None]
    ref = np.where((np.abs(ex[:, 2]) < 1.0 - 1e-9)[:, None], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    given = [i for i, o in enumerate(orientations) if o is not None]
    if given:
        ref[given] = np.array([orientations[i] for i in given], dtype=float)
    ez = ref - np.einsum("ij,ij->i", ref, ex)[:, None] * ex
    nz = np.linalg.norm(ez, axis=1)
    bad = np.flatnonzero(nz < 1e-9 * np.linalg.norm(ref, axis=1))
    if len(bad):
        raise InputError(f"member {int(bad[0])}: orientation is parallel to the member; give a vector across it")
    ez /= nz[:, None]
    ey = np.cross(ez, ex)
    if rolls is not None and np.any(rolls):
        c, s = np.cos(rolls)[:, None], np.sin(rolls)[:, None]
        ey, ez = c * ey + s * ez, -s * ey + c * ez
    return np.stack((ex, ey, ez), axis=1)


def local_stiffness_batch(L: np.ndarray, E: np.ndarray, G: np.ndarray, A: np.ndarray, Iy: np.ndarray,
                          Iz: np.ndarray, J: np.ndarray, sy: np.ndarray, sz: np.ndarray) -> np.ndarray:
    """``[n, 12, 12]`` local stiffnesses; ``sy = 1/(G Asy)``, ``sz = 1/(G Asz)`` (0: Euler-Bernoulli)."""
    n = len(L)
    k = np.zeros((n, 12, 12))
    ea, gj = E * A / L, G * J / L
    k[:, 0, 0] = k[:, 6, 6] = ea
    k[:, 0, 6] = k[:, 6, 0] = -ea
    k[:, 3, 3] = k[:, 9, 9] = gj
    k[:, 3, 9] = k[:, 9, 3] = -gj
    for (iv, ir, jv, jr), EI, s, sgn in (((1, 5, 7, 11), E * Iz, sy, 1.0), ((2, 4, 8, 10), E * Iy, sz, -1.0)):
        phi = 12 * EI * s / L**2
        c = EI / ((1 + phi) * L**3)
        blk = np.array([[12 + 0 * L, 6 * L * sgn, -12 + 0 * L, 6 * L * sgn],
                        [6 * L * sgn, (4 + phi) * L**2, -6 * L * sgn, (2 - phi) * L**2],
                        [-12 + 0 * L, -6 * L * sgn, 12 + 0 * L, -6 * L * sgn],
                        [6 * L * sgn, (2 - phi) * L**2, -6 * L * sgn, (4 + phi) * L**2]])  # [4, 4, n]
        idx = (iv, ir, jv, jr)
        for a in range(4):
            for b in range(4):
                k[:, idx[a], idx[b]] = c * blk[a, b]
    return k


def local_stiffness(L: float, E: float, G: float, A: float, Iy: float, Iz: float, J: float,
                    Asy: float | None, Asz: float | None) -> np.ndarray:
    """12x12 stiffness of a prismatic 3D beam in local axes (DOFs u, v, w, θx, θy, θz at each end).

    Timoshenko with shear areas ``Asy``, ``Asz`` (``None``: Euler-Bernoulli); ref. 1 Sec. 5.6:
    bending in x-y: ``E Iz/((1+Φy) L³) [12, 6L, -12, 6L; 6L, (4+Φy)L², -6L, (2-Φy)L²; ...]``,
    ``Φy = 12 E Iz / (G Asy L²)``; x-z likewise with ``Iy``, ``Φz`` and the signs of θy = -dw/dx.
    """
    sy = 1 / (G * Asy) if Asy else 0.0
    sz = 1 / (G * Asz) if Asz else 0.0
    a = [np.array([x], dtype=float) for x in (L, E, G, A, Iy, Iz, J, sy, sz)]
    return local_stiffness_batch(*a)[0]


def fixed_end_forces(L: float, q: np.ndarray) -> np.ndarray:
    """Nodal loads equivalent to a uniform local load ``q = (qx, qy, qz)`` [N/m]: the reactions of the
    clamped member reversed (ref. 1 Sec. 5.7): ``qL/2`` at each end, ``±q L²/12`` end moments (both
    theories: the load is symmetric)."""
    qx, qy, qz = q
    f = np.zeros(12)
    f[[0, 6]] = qx * L / 2
    f[[1, 7]] = qy * L / 2
    f[[2, 8]] = qz * L / 2
    f[5], f[11] = qy * L**2 / 12, -qy * L**2 / 12
    f[4], f[10] = -qz * L**2 / 12, qz * L**2 / 12
    return f


def load_integrals(a: np.ndarray, b: np.ndarray, s: Any) -> tuple[Any, Any, Any, Any]:
    """Repeated integrals from 0 to s of a linear load ``q = a + b s``: I1 = ∫q, I2 = ∫I1, I3, I4."""
    return (a * s + b * s**2 / 2, a * s**2 / 2 + b * s**3 / 6, a * s**3 / 6 + b * s**4 / 24,
            a * s**4 / 24 + b * s**5 / 120)


def fixed_end_forces_linear(L: np.ndarray, q0: np.ndarray, q1: np.ndarray, EIy: np.ndarray, EIz: np.ndarray,
                            sy: np.ndarray, sz: np.ndarray) -> np.ndarray:
    """``[n, 12]`` nodal loads equivalent to local loads varying linearly from ``q0`` to ``q1`` ``[n, 3]``.

    The clamped-clamped member's end forces (reversed) from compatibility of the exact fields:
    axial ``u(L) = 0``; bending ``θ(L) = 0`` and ``v(L) = 0`` with ``v' = θ + V/(G As)``:
    ``F1 = ((I4 - I3 L/2)/EI - s I2) / (L³/(12 EI) + s L)``, ``M1 = F1 L/2 + I3/L`` (x-y plane).
    Euler-Bernoulli uniform load: ``qL/2``, ``qL²/12``; triangular (0 → q): ``3qL/20``, ``qL²/30``,
    ``7qL/20``, ``qL²/20`` (AISC Manual Table 3-23 case 1/2 limits, Roark Table 8.1 case 2c/2d).
    """
    b = (q1 - q0) / L[:, None]
    I1, I2, I3, I4 = load_integrals(q0, b, L[:, None])  # each [n, 3] at s = L
    f = np.zeros((len(L), 12))
    # axial: N = -F1x - I1x; u(L) = 0 -> F1x = -I2x / L
    F1x = -I2[:, 0] / L
    F2x = -F1x - I1[:, 0]
    f[:, 0], f[:, 6] = -F1x, -F2x
    # x-y
    F1y = ((I4[:, 1] - I3[:, 1] * L / 2) / EIz - sy * I2[:, 1]) / (L**3 / (12 * EIz) + sy * L)
    M1z = F1y * L / 2 + I3[:, 1] / L
    F2y = -F1y - I1[:, 1]
    M2z = -M1z + F1y * L + I2[:, 1]
    f[:, 1], f[:, 5], f[:, 7], f[:, 11] = -F1y, -M1z, -F2y, -M2z
    # x-z
    F1z = ((I4[:, 2] - I3[:, 2] * L / 2) / EIy - sz * I2[:, 2]) / (L**3 / (12 * EIy) + sz * L)
    M1y = -F1z * L / 2 - I3[:, 2] / L
    F2z = -F1z - I1[:, 2]
    M2y = -M1y - F1z * L - I2[:, 2]
    f[:, 2], f[:, 4], f[:, 8], f[:, 10] = -F1z, -M1y, -F2z, -M2y
    return f


# ----------------------------------------------------------------------------------------- releases
@dataclass(frozen=True)
class Condensed:
    """Static condensation of released end forces (ref. 2 Sec. 7.3): released local motions ``C``
    ``[12, m]`` (orthonormal columns). ``P = I - k C (Cᵀ k C)⁻¹ Cᵀ`` gives the condensed stiffness
    ``P k`` and loads ``P f``; ``W = C (Cᵀ k C)⁻¹ Cᵀ`` recovers the member's own end motions
    ``u_el = u - W (k u - f)``, at which the released end forces vanish."""

    P: np.ndarray
    W: np.ndarray


def condense(k: np.ndarray, C: np.ndarray, member: str) -> Condensed:
    """The condensation of ``k`` for released directions ``C``; a member left unstable is named."""
    kcc = C.T @ k @ C
    d = np.sqrt(np.abs(np.diag(kcc)))
    if np.any(d <= 1e-12 * np.max(np.abs(np.diag(k)))):
        i = int(np.argmin(d))
        _unstable(C[:, i], member)
    w, V = np.linalg.eigh(kcc / d[:, None] / d[None, :])
    if w[0] <= 1e-9 * max(float(w[-1]), 1.0):
        _unstable(C @ (V[:, 0] / d), member)
    X = np.linalg.solve(kcc, C.T)
    return Condensed(np.eye(12) - k @ C @ X, C @ X)


def _unstable(motion: np.ndarray, member: str) -> None:
    m = np.abs(motion)
    big = np.flatnonzero(m >= 0.3 * m.max())
    words = [f"{LOCAL_WORDS[i % 6]} at its {'start' if i < 6 else 'end'}" for i in big]
    raise InputError(f"member {member}: its end releases leave it unstable: nothing resists the "
                     + " with the ".join(words) + " (e.g. the same force released at both ends). "
                     "Keep that end force at one end at least.")


# ------------------------------------------------------------------------------------------ fields
def _pad(c: list[Any] | np.ndarray, n: int = 6) -> np.ndarray:
    out = np.zeros(n)
    c = np.asarray(c, dtype=float)
    out[:len(c)] = c
    return out


def element_polynomials(L: float, F: np.ndarray, ul: np.ndarray, q0: np.ndarray, q1: np.ndarray, E: float,
                        G: float, A: float, Iy: float, Iz: float, sy: float, sz: float) -> dict[str, np.ndarray]:
    """Coefficients (ascending powers of s, degree <= 5) of the exact fields along an element.

    ``F`` local end forces on the element, ``ul`` the element's own local end motions, loads varying
    linearly from ``q0`` to ``q1``. Resultants on the cut face with outward normal +x: ``N = -F1x - ∫qx``,
    ``Vy = -F1y - ∫qy``, ``Mz = -M1z + F1y s + ∫∫qy``, ``My = -M1y - F1z s - ∫∫qz``; displacements
    from ``θz' = Mz/EIz``, ``v' = θz + Vy/(G Asy)``, ``θy' = My/EIy``, ``w' = -θy + Vz/(G Asz)``.
    """
    a = q0
    b = (q1 - q0) / L
    I1 = [_pad([0, a[i], b[i] / 2]) for i in range(3)]
    I2 = [_pad([0, 0, a[i] / 2, b[i] / 6]) for i in range(3)]
    I4 = [_pad([0, 0, 0, 0, a[i] / 24, b[i] / 120]) for i in range(3)]
    N = _pad([-F[0]]) - I1[0]
    Vy = _pad([-F[1]]) - I1[1]
    Vz = _pad([-F[2]]) - I1[2]
    T = _pad([-F[3]])
    My = _pad([-F[4], -F[2]]) - I2[2]
    Mz = _pad([-F[5], F[1]]) + I2[1]
    u = _pad([ul[0], -F[0] / (E * A)]) - I2[0] / (E * A)
    v = _pad([ul[1], ul[5]]) + (_pad([0, 0, -F[5] / 2, F[1] / 6]) + I4[1]) / (E * Iz) + sy * (_pad([0, -F[1]]) - I2[1])
    w = _pad([ul[2], -ul[4]]) - (_pad([0, 0, -F[4] / 2, -F[2] / 6]) - I4[2]) / (E * Iy) \
        + sz * (_pad([0, -F[2]]) - I2[2])
    return {"N": N, "Vy": Vy, "Vz": Vz, "T": T, "My": My, "Mz": Mz, "u": u, "v": v, "w": w}


def stationary_points(c: np.ndarray, L: float) -> np.ndarray:
    """Positions in (0, L) where the polynomial ``c`` (ascending) is stationary."""
    d = np.polynomial.polynomial.polyder(c)
    nz = np.flatnonzero(np.abs(d) > 0)
    if not len(nz):
        return np.zeros(0)
    d = d[:nz[-1] + 1]
    if len(d) < 2:
        return np.zeros(0)
    r = np.polynomial.polynomial.polyroots(d)
    r = r.real[np.abs(r.imag) <= 1e-9 * max(L, 1.0)]
    return np.sort(r[(r > 1e-12 * L) & (r < L * (1 - 1e-12))])


def poly_extremes(c: np.ndarray, L: float) -> tuple[float, float, float, float]:
    """(max, s at max, min, s at min) of the polynomial ``c`` over [0, L] (ends and stationary points)."""
    s = np.concatenate(([0.0, L], stationary_points(c, L)))
    v = np.polynomial.polynomial.polyval(s, c)
    i, j = int(np.argmax(v)), int(np.argmin(v))
    return float(v[i]), float(s[i]), float(v[j]), float(s[j])
