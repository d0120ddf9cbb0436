"""Natural frequencies, mode shapes and linear buckling of frames (:class:`~mechverify.fea.frame.Frame`).

    >>> from mechverify.components import sections
    >>> from mechverify.fea.frame import Frame, Member, FrameSupport as Support
    >>> from mechverify.fea.frame.modal import frame_modes
    >>> fr = Frame({"A": ["0 mm"] * 3, "B": ["500 mm", "0 mm", "0 mm"]},
    ...            [Member("A", "B", sections.circle("20 mm"), "Structural Steel")], [Support("A", "fixed")],
    ...            theory="euler")
    >>> round(float(frame_modes(fr, 2).frequencies.m[0]), 1)   # Euler-Bernoulli: 1.8751² √(EI/(ρA)) / (2π L²)
    56.5

- :func:`element_mass` - the *consistent* mass of the two-node 3D beam: axial and torsion (linear
  shape functions, polar inertia ``ρ (Iy + Iz)``), bending from the element's own interdependent
  (Timoshenko) shape functions, the exact homogeneous solutions of the shear-flexible beam (ref. 1,
  Sec. 11.?; ref. 2): translational inertia ``ρA ∫ N_vᵀ N_v ds`` and, for Timoshenko members, rotary
  inertia ``ρI ∫ N_θᵀ N_θ ds``. With ``Φ = 0`` the translational part is the classical
  ``ρAL/420 [156, 22L, 54, -13L; ...]`` (ref. 1, Eq. 11.41). Euler-Bernoulli members carry no rotary
  inertia (the classical theory).
- :func:`element_geometric_stiffness` - ``N ∫ N_v'ᵀ N_v' ds`` in both bending planes plus the torsional
  term ``N Ip/(A L)`` (ref. 3, Sec. 9.3): with ``Φ = 0`` the classical ``N/(30L) [36, 3L, -36, 3L; ...]``.
- :func:`frame_modes` - the first ``n_modes`` natural frequencies and mass-normalised mode shapes
  (members divided into ``elements_per_member`` elements, :class:`PointMass` es at nodes or points
  (discs on a shaft), support springs as in statics). Dense ``eigh`` up to :data:`DENSE_LIMIT`
  unknowns, else ARPACK shift-invert Lanczos on one sparse factorisation.
- :func:`frame_buckling` - linear buckling load factors of a load case: the static solution's axial forces
  give ``K_G``; ``(K + μ K_G) φ = 0``.

End releases condense the element mass the same way as the stiffness (``u_el = Pᵀ u``, so
``m_c = P m Pᵀ``: the released motion follows the element statically; Guyan's reduction, exact in
the limit of fine division). Gyroscopic (speed-dependent) effects of spinning shafts are not modelled:
the frequencies are those of the non-rotating structure (the critical speeds of a shaft whose discs
have small polar inertia).

References
----------
1. J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968 (Dover 1985), Ch. 11
   (consistent mass matrices; Eq. 11.41 the beam element).
2. Z. Friedman, J. B. Kosmatka, "An improved two-node Timoshenko beam finite element", *Computers &
   Structures* 47 (1993) 473-481 (interdependent interpolation: cubic v, quadratic θ).
3. W. McGuire, R. H. Gallagher, R. D. Ziemian, *Matrix Structural Analysis*, 2nd ed., Wiley 2000,
   Sec. 9.3 (geometric stiffness of the 3D frame element).
"""

from __future__ import annotations

import copy
import dataclasses
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import pint
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError
from mechverify.fea.frame import model as _model
from mechverify.fea.frame.model import DOF_NAMES, Load, Where
from mechverify.fea.reproducible import reproducible
from mechverify.units import Q, QuantityLike, to_si

if TYPE_CHECKING:
    from mechverify.fea.frame.analysis import Frame
    from mechverify.fea.frame.mesh import _Mesh

# the nodal point load
_POINT_LOAD: Any = _model.FramePointLoad
#: Largest number of free unknowns solved by the dense symmetric eigensolver.
DENSE_LIMIT = 2500
#: Default elements per member for modal and buckling analyses.
ELEMENTS_PER_MEMBER = 10

_GX, _GW = np.polynomial.legendre.leggauss(5)
_GX, _GW = (_GX + 1) / 2, _GW / 2  # on [0, 1]


def bending_shapes(L: float, phi: float, xi: np.ndarray = _GX) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Interdependent shape functions of one bending plane at ``xi = s/L`` (ref. 2), DOFs ``(v1, θ1, v2, θ2)``
    with ``θ = dv/ds`` for ``Φ = 0``: ``(N_v[4, q], dN_v/ds[4, q], N_θ[4, q])``.

    ``N_v1 = (2ξ³ - 3ξ² - Φξ + 1 + Φ)/(1+Φ)``, ``N_v2 = L(ξ³ - (2+Φ/2)ξ² + (1+Φ/2)ξ)/(1+Φ)``,
    ``N_v3 = (-2ξ³ + 3ξ² + Φξ)/(1+Φ)``, ``N_v4 = L(ξ³ - (1-Φ/2)ξ² - Φξ/2)/(1+Φ)``;
    ``N_θ1 = 6(ξ² - ξ)/((1+Φ)L)``, ``N_θ2 = (3ξ² - (4+Φ)ξ + 1 + Φ)/(1+Φ)``, ``N_θ3 = -N_θ1``,
    ``N_θ4 = (3ξ² - (2-Φ)ξ)/(1+Φ)``. They solve the homogeneous Timoshenko equations exactly
    (``θ'' `` constant, ``v' - θ = -(ΦL²/12) θ''``), so they reproduce the element's exact stiffness.
    """
    x = np.asarray(xi, dtype=float)
    c = 1.0 / (1.0 + phi)
    Nv = c * np.array([2 * x**3 - 3 * x**2 - phi * x + 1 + phi,
                       L * (x**3 - (2 + phi / 2) * x**2 + (1 + phi / 2) * x),
                       -2 * x**3 + 3 * x**2 + phi * x,
                       L * (x**3 - (1 - phi / 2) * x**2 - phi / 2 * x)])
    dNv = c * np.array([6 * x**2 - 6 * x - phi,
                        L * (3 * x**2 - (4 + phi) * x + 1 + phi / 2),
                        -6 * x**2 + 6 * x + phi,
                        L * (3 * x**2 - (2 - phi) * x - phi / 2)]) / L
    Nt = c * np.array([6 * (x**2 - x) / L, 3 * x**2 - (4 + phi) * x + 1 + phi,
                       -6 * (x**2 - x) / L, 3 * x**2 - (2 - phi) * x])
    return Nv, dNv, Nt


# the two bending planes: local DOFs (v1, θ1, v2, θ2) and the sign of the rotation (θy = -dw/dx)
_PLANES = (((1, 5, 7, 11), 1.0), ((2, 4, 8, 10), -1.0))


def element_mass(L: float, rho: float, A: float, Iy: float, Iz: float, sy: float = 0.0, sz: float = 0.0,
                 E: float = 1.0, rotary: bool = True) -> np.ndarray:
    """12x12 consistent mass [kg, kg·m, kg·m²] of a prismatic 3D beam in local axes (DOFs as the stiffness).

    ``sy = 1/(G Asy)``, ``sz = 1/(G Asz)`` (0: no shear deformation); ``rotary``: include the rotary
    inertia of the bending rotations (Timoshenko/Rayleigh beams)."""
    m = np.zeros((12, 12))
    for (a, b), val in (((0, 6), rho * A * L), ((3, 9), rho * (Iy + Iz) * L)):
        m[a, a] = m[b, b] = val / 3
        m[a, b] = m[b, a] = val / 6
    for (idx, sgn), I, s in zip(_PLANES, (Iz, Iy), (sy, sz), strict=True):
        phi = 12 * E * I * s / L**2
        Nv, _, Nt = bending_shapes(L, phi)
        blk = rho * A * L * np.einsum("aq,bq,q->ab", Nv, Nv, _GW)
        if rotary:
            blk += rho * I * L * np.einsum("aq,bq,q->ab", Nt, Nt, _GW)
        D = np.array([1.0, sgn, 1.0, sgn])
        m[np.ix_(idx, idx)] = blk * D[:, None] * D[None, :]
    return m


def element_geometric_stiffness(L: float, N: float, A: float, Iy: float, Iz: float, sy: float = 0.0,
                                sz: float = 0.0, E: float = 1.0) -> np.ndarray:
    """12x12 geometric (initial-stress) stiffness [N/m] of a beam carrying the axial force ``N`` [N]
    (tension positive): ``N ∫ N_v'ᵀ N_v' ds`` in each bending plane and ``N (Iy + Iz)/(A L)`` in torsion
    (ref. 3, Sec. 9.3)."""
    k = np.zeros((12, 12))
    t = N * (Iy + Iz) / (A * L)
    k[3, 3] = k[9, 9] = t
    k[3, 9] = k[9, 3] = -t
    for (idx, sgn), I, s in zip(_PLANES, (Iz, Iy), (sy, sz), strict=True):
        phi = 12 * E * I * s / L**2
        _, dNv, _ = bending_shapes(L, phi)
        blk = N * L * np.einsum("aq,bq,q->ab", dNv, dNv, _GW)
        D = np.array([1.0, sgn, 1.0, sgn])
        k[np.ix_(idx, idx)] = blk * D[:, None] * D[None, :]
    return k


@dataclass(frozen=True)
class PointMass:
    """A rigid mass at a node or a point on a member: ``mass`` (kg) and optionally its mass moments of
    inertia ``inertia`` (kg·m²) about global x, y, z through the point (one value: the same about all
    three; a disc of mass m and radius r on a shaft along x: ``(m r²/2, m r²/4, m r²/4)``)."""

    at: Where
    mass: QuantityLike
    inertia: QuantityLike | Sequence[QuantityLike] | None = None

    def values(self) -> tuple[float, np.ndarray]:
        m = to_si(self.mass, "mass", "point mass")
        if m < 0:
            raise InputError(f"point mass at {self.at!r}: mass must not be negative, got {self.mass!r}")
        if self.inertia is None:
            J = np.zeros(3)
        elif isinstance(self.inertia, str | pint.Quantity) and np.ndim(getattr(self.inertia, "m", 0)) == 0:
            J = np.full(3, to_si(self.inertia, "inertia", "point mass inertia"))
        else:
            items = list(self.inertia)  # type: ignore[arg-type]
            if len(items) != 3:
                raise InputError(f"point mass at {self.at!r}: inertia needs three values (about x, y, z), "
                                 f"got {len(items)}")
            J = np.array([to_si(v, "inertia", "point mass inertia") for v in items])
        if np.any(J < 0):
            raise InputError(f"point mass at {self.at!r}: inertia must not be negative")
        return m, J


@dataclass(frozen=True, eq=False)
class FrameModes:
    """Natural frequencies and mode shapes of a frame.

    ``omega2[k]`` [rad²/s²] ascending; ``shapes[k, n, 6]`` node translations [m] and rotations [rad],
    mass-normalised (``φᵀ M φ = 1`` kg); ``effective_mass[k, 3]`` [kg] along global x, y, z
    (``(φᵀ M r)²``, Chopra Sec. 13.2); ``total_mass[3]`` the frame's whole mass along each axis (the
    share the consistent mass gives the supported nodes included, so the fractions sum to less than 1).
    ``points[n, 3]`` [m] and ``elements[ne, 2]`` the analysis nodes and beam elements.
    """

    omega2: np.ndarray
    shapes: np.ndarray
    points: np.ndarray
    elements: np.ndarray
    effective_mass: np.ndarray
    total_mass: np.ndarray
    rigid_body_modes: int
    unknowns: int
    names: dict[str, int]
    notes: tuple[str, ...] = ()

    @property
    def frequencies(self) -> pint.Quantity:
        """Natural frequencies f = ω/2π [Hz] (rigid-body modes: 0)."""
        return Q(np.sqrt(np.clip(self.omega2, 0.0, None)) / (2 * np.pi), "Hz")

    @property
    def first_frequency(self) -> pint.Quantity:
        """The lowest frequency of an elastic (not rigid-body) mode [Hz]."""
        if self.rigid_body_modes >= len(self.omega2):
            raise ModelError("all modes found are rigid-body modes; ask for more modes")
        return self.frequencies[self.rigid_body_modes]

    @property
    def critical_speeds(self) -> pint.Quantity:
        """The frequencies as shaft speeds [rpm] (60 f; non-rotating modes, no gyroscopic effect)."""
        return Q(self.frequencies.m * 60.0, "rpm")

    def effective_mass_fraction(self) -> np.ndarray:
        """Effective modal mass over total mass ``[k, 3]``."""
        return self.effective_mass / np.where(self.total_mass > 0, self.total_mass, 1.0)[None, :]

    def shape_at(self, where: str, mode: int = 0) -> np.ndarray:
        """Mode ``mode``'s six components (x, y, z [m], rx, ry, rz [rad]) at the named node ``where``."""
        if where not in self.names:
            from mechverify.errors import UnknownNameError

            raise UnknownNameError("node", where, self.names)
        return self.shapes[mode, self.names[where]].copy()

    def to_vtu(self, path: str | Path) -> Path:
        """Write every mode (translations ``mode_<k>_<f>Hz``, rotations ``rot_<k>``) on line cells to VTU."""
        from mechverify.fea.vtu import write_vtu

        f = self.frequencies.m
        data: dict[str, np.ndarray] = {}
        for k in range(len(f)):
            data[f"mode_{k + 1}_{f[k]:.6g}Hz"] = self.shapes[k, :, :3]
            data[f"rot_{k + 1}"] = self.shapes[k, :, 3:]
        return write_vtu(Path(path), self.points, [("line", self.elements.copy())], data)

    def summary(self) -> dict[str, Any]:
        return {"kind": "frame", "frequencies_Hz": [float(x) for x in self.frequencies.m],
                "rigid_body_modes": self.rigid_body_modes, "unknowns": self.unknowns,
                "effective_mass_fraction": self.effective_mass_fraction().sum(axis=0).tolist()}


class NoCompressionError(ModelError):
    """No member of the frame is in compression under the loads, so nothing can buckle."""


@dataclass(frozen=True, eq=False)
class FrameBuckling:
    """Buckling load factors ``factors[k]`` (ascending, positive, multiplying every load of the case) and
    mode shapes ``shapes[k, n, 6]`` (largest translation 1)."""

    factors: np.ndarray
    shapes: np.ndarray
    points: np.ndarray
    elements: np.ndarray
    axial_force: np.ndarray  # [ne] N, tension positive, of the loads as given
    unknowns: int

    @property
    def first_factor(self) -> float:
        """The lowest positive buckling load factor."""
        return float(self.factors[0])


# ---------------------------------------------------------------------------------------------- helpers
def _refined(frame: Frame, elements_per_member: int) -> Frame:
    n = int(elements_per_member)
    if n < 1:
        raise InputError(f"elements_per_member: at least 1, got {elements_per_member!r}")
    fr = copy.copy(frame)
    fr.members = [dataclasses.replace(m, divisions=max(m.divisions, n)) for m in frame.members]
    return fr


def _transform(R: np.ndarray) -> np.ndarray:
    T = np.zeros((12, 12))
    for b in range(4):
        T[3 * b:3 * b + 3, 3 * b:3 * b + 3] = R
    return T


def _assemble(mesh: _Mesh, local: Iterable[np.ndarray]) -> sp.csr_matrix:
    """Global matrix of element matrices in local axes (condensed with the release projections ``P m Pᵀ``)."""
    rows, cols, vals = [], [], []
    for e, me in enumerate(local):
        if e in mesh.cond:
            P = mesh.cond[e].P
            me = P @ me @ P.T
            me = (me + me.T) / 2
        T = _transform(mesh.R[e])
        rows.append(np.repeat(mesh.dofs[e], 12))
        cols.append(np.tile(mesh.dofs[e], 12))
        vals.append((T.T @ me @ T).ravel())
    if not vals:
        return sp.csr_matrix((mesh.ndof, mesh.ndof))
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(mesh.ndof, mesh.ndof))


def _densities(frame: Frame, mesh: _Mesh) -> None:
    for e, pr in enumerate(mesh.props):
        if not math.isfinite(pr.rho):
            m = frame.members[mesh.elem_member[e]]
            raise InputError(f"member {m.name}: material {m.material.name!r} has no density (needed for the mass "
                             "of a modal analysis)")


def mass_matrix(frame: Frame, mesh: _Mesh, masses: Sequence[PointMass] = ()) -> sp.csr_matrix:
    """The consistent global mass matrix [kg] of the analysis model ``mesh`` of ``frame`` with point masses."""
    _densities(frame, mesh)
    M = _assemble(mesh, (element_mass(mesh.L[e], p.rho, p.A, p.Iy, p.Iz, p.sy, p.sz, p.E, rotary=p.Asy is not None)
                         for e, p in enumerate(mesh.props)))
    diag = np.zeros(mesh.ndof)
    for pm in masses:
        m, J = pm.values()
        k = frame._node(mesh, pm.at)
        diag[6 * k:6 * k + 3] += m
        diag[6 * k + 3:6 * k + 6] += J
    return (M + sp.diags(diag)).tocsr()


def _restrained_stiffness(frame: Frame, mesh: _Mesh) -> tuple[sp.csr_matrix, np.ndarray, list[str]]:
    """Stiffness with support springs (one-way springs taken as in contact), and the free DOFs; checks
    that the supports hold every rigid motion and that no mechanism is left (as in statics)."""
    K = frame._stiffness(mesh)
    held, springs, one_way, _ = frame._restraints(mesh)
    notes = []
    diag = np.zeros(mesh.ndof)
    for dof, kv in springs.items():
        diag[dof] += kv
    for dof, (kv, _) in one_way.items():
        diag[dof] += kv
    if one_way:
        notes.append("one-way springs are linearised as in contact (acting both ways) for the natural frequencies: "
                     "a support that lifts off while vibrating gives a lower frequency than this")
    Ks = (K + sp.diags(diag)).tocsr()
    free = np.setdiff1d(np.arange(mesh.ndof), held)
    if frame.supports:
        frame._check_supported(mesh, np.union1d(held, np.array(list(springs) + list(one_way), dtype=np.int64)))
        frame._check_releases(mesh, Ks, held)
        frame._mechanism(mesh, Ks[free][:, free], free)
    return Ks, free, notes


def _mass_points(masses: Sequence[PointMass]) -> list[Load]:
    out: list[Load] = []
    for i, pm in enumerate(masses):
        if not isinstance(pm, PointMass):
            raise InputError(f"masses[{i}]: expected a PointMass, got {type(pm).__name__}")
        out.append(_POINT_LOAD(pm.at))  # splits a member at the mass (no force)
    return out


def _count_below(A: np.ndarray) -> int:
    """The number of negative eigenvalues of the symmetric ``A`` (Sylvester's law of inertia on its LDLᵀ
    factorisation: the negative eigenvalues of the 1x1 and 2x2 blocks of D); for ``A = K - σM`` the number of
    modes with ω² < σ."""
    _, D, _ = sla.ldl(A)
    n, count, i = len(D), 0, 0
    while i < n:
        if i + 1 < n and D[i, i + 1] != 0:
            count += int(np.sum(np.linalg.eigvalsh(D[i:i + 2, i:i + 2]) < 0))
            i += 2
        else:
            count += int(D[i, i] < 0)
            i += 1
    return count


# ---------------------------------------------------------------------------------------------- analyses
@reproducible  # ARPACK's shift-invert on OpenBLAS: last digits differed with 1 and 2 BLAS threads
def frame_modes(frame: Frame, n_modes: int = 6, *, masses: Sequence[PointMass] = (),
                elements_per_member: int = ELEMENTS_PER_MEMBER, shift: QuantityLike | float | None = None
                ) -> FrameModes:
    """The first ``n_modes`` natural frequencies (nearest above ``shift``, a frequency) and mass-normalised
    mode shapes of ``frame`` with the point ``masses``.

    Members are divided into at least ``elements_per_member`` elements (the consistent mass makes the
    frequencies converge from above, with the fourth power of the element length for Euler beams).
    A frame without supports is analysed free-free (six rigid-body modes at zero frequency, counted in
    ``rigid_body_modes``); supports that leave a rigid motion free or a mechanism are a :class:`ModelError`
    naming it, as in statics. Asking for as many modes as there are free unknowns is an :class:`InputError`.
    """
    n_modes = int(n_modes)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    fr = _refined(frame, elements_per_member)
    mesh = fr._mesh(_mass_points(masses))
    Ks, free, notes = _restrained_stiffness(fr, mesh)
    M = mass_matrix(fr, mesh, masses)
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} modes asked, but the frame has only {free.size} free unknowns (at "
                         f"most {free.size - 1} modes); raise elements_per_member or ask fewer")
    Kf, Mf = Ks[free][:, free], M[free][:, free]
    md = Mf.diagonal()
    massless = np.flatnonzero(md <= 1e-30 * max(float(md.max()), 1e-300))  # short Euler members: ρAL³/105
    if len(massless):
        node, c = divmod(int(free[massless[0]]), 6)
        raise ModelError(f"frame {frame.name!r}: the {DOF_NAMES[c]} motion at node {mesh.node_words(node)} has no "
                         "mass (a node carried only by springs?); add a PointMass there or hold it")
    kd = Kf.diagonal()
    scale = float(np.median(kd[kd > 0] / md[kd > 0])) if np.any(kd > 0) else 1.0
    if shift is None:
        sigma = -1e-6 * scale if not frame.supports else 0.0
    else:
        f0 = float(shift) if isinstance(shift, int | float) else to_si(shift, "frequency", "shift")
        sigma = (2 * math.pi * f0) ** 2
    if free.size <= DENSE_LIMIT:
        # θ = 1/(ω² - σ0) of M φ = θ (K - σ0 M) φ: the Cholesky factor is of K - σ0 M (positive definite: σ0 = 0
        # on supports, slightly negative for a free body), not of M, whose conditioning grows with the fourth power
        # of 1/element length for short Euler members (no rotary inertia) and made eigh(K, M)'s lowest ω² err by
        # 3e-5, non-monotonically under refinement (the stepped drum shaft, issue 23), and a user shift by 8e-5
        n = free.size
        s0 = sigma if shift is None else (0.0 if frame.supports else -1e-6 * scale)
        Md, Ks0 = Mf.toarray(), Kf.toarray() - s0 * Mf.toarray()
        below = 0 if shift is None else _count_below(Kf.toarray() - sigma * Md)  # modes under the shift
        if n_modes > n - below:
            raise InputError(f"n_modes: only {n - below} modes lie above the shift {f0:g} Hz; ask fewer or lower "
                             "the shift")
        # the n_modes largest θ after the `below` largest ones: the lowest frequencies at or above the shift
        th, V = sla.eigh(Md, Ks0, subset_by_index=[n - below - n_modes, n - below - 1])
        w, V = 1.0 / th[::-1] + s0, V[:, ::-1]
    else:
        from mechverify.fea.frame.analysis import _node_order

        p = _node_order(Kf, free)
        try:
            lu = spl.splu((Kf - sigma * Mf).tocsr()[p][:, p].tocsc(), permc_spec="NATURAL", diag_pivot_thresh=0.0,
                          options={"SymmetricMode": True})
        except RuntimeError as exc:
            raise ModelError(f"frame {frame.name!r}: K - σM is singular at σ = {sigma:.4g} ({exc})") from None

        def solve(b: np.ndarray) -> np.ndarray:
            x = np.empty_like(b, dtype=float)
            x[p] = lu.solve(np.ascontiguousarray(b[p]))
            return x

        op = spl.LinearOperator(Kf.shape, matvec=solve, dtype=float)
        v0 = np.random.default_rng(0).standard_normal(free.size)
        w, V = spl.eigsh(Kf.tocsc(), k=n_modes, M=Mf.tocsc(), sigma=sigma, which="LM", OPinv=op, v0=v0, tol=1e-10)
        order = np.argsort(w)
        w, V = w[order], V[:, order]
    V = V / np.sqrt(np.einsum("ik,ik->k", V, Mf @ V))[None, :]
    full = np.zeros((mesh.ndof, n_modes))
    full[free] = V
    shapes = full.T.reshape(n_modes, -1, 6)
    R = np.zeros((mesh.ndof, 3))
    for i in range(3):
        R[i::6, i] = 1.0
    MR = Mf @ R[free]
    eff = (V.T @ MR) ** 2
    tot = np.einsum("ij,ij->j", R, M @ R)  # the whole mass (supported nodes' share included, as ANSYS reports)
    rigid = int(np.sum(np.abs(w) < 1e-8 * scale)) if not frame.supports else 0
    return FrameModes(w, shapes, mesh.points.copy(), mesh.elem_nodes.copy(), eff, tot, rigid, int(free.size),
                      dict(mesh.named), tuple(mesh.notes) + tuple(notes))


@reproducible  # ARPACK's shift-invert on OpenBLAS: last digits differed with 1 and 2 BLAS threads
def frame_buckling(frame: Frame, loads: Iterable[Load] | Mapping[str, Iterable[Load]], n_modes: int = 1, *,
                   elements_per_member: int = ELEMENTS_PER_MEMBER,
                   combination: Mapping[str, float] | None = None) -> FrameBuckling:
    """Linear buckling load factors of ``frame`` under ``loads``: ``(K + μ K_G) φ = 0`` with ``K_G`` from the
    axial forces of the static solution (ref. 3, Sec. 9.3). Factors multiply all the loads; only positive
    factors are returned (the loads as given, not reversed). A load case without compression anywhere is a
    :class:`NoCompressionError` (a :class:`ModelError`).

    With ``combination = {case: factor}``, ``loads`` maps load-case names to their loads and the factored sum of
    those cases is analysed: the axial forces are ``Σ factor · N_case`` (superposition, on one mesh of all the
    cases' loads; with one-way springs the combined loads are solved together, as ``Frame.analyse`` does)."""
    n_modes = int(n_modes)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    fr = _refined(frame, elements_per_member)
    if combination is None:
        res = fr.solve(tuple(loads))  # type: ignore[arg-type]
    else:
        if not isinstance(loads, Mapping):
            raise InputError("frame_buckling: with a combination, loads maps load-case names to their loads")
        cases = {str(k): tuple(loads[k]) for k in combination if k in loads}
        missing = [k for k in combination if k not in loads]
        if missing:
            from mechverify.errors import UnknownNameError

            raise UnknownNameError("load case (in the combination)", missing[0], list(loads))
        name = "+".join(cases) + " (combination)"
        res = fr.analyse(cases, [_model.LoadCombination(name, dict(combination))]).results[name]
    mesh = res.mesh
    Ks, free, _ = _restrained_stiffness(fr, mesh)
    # axial force of each element: N = -F1x (start) and F2x (end) of its local end forces (mean over the element)
    N = (-res.end_forces[:, 0] + res.end_forces[:, 6]) / 2 if len(mesh.L) else np.zeros(0)
    if not np.any(N < 0):
        raise NoCompressionError(f"frame {frame.name!r}: no member is in compression under these loads, so it "
                                 "cannot buckle (reverse the loads to study the other direction)")
    KG = _assemble(mesh, (element_geometric_stiffness(mesh.L[e], N[e], p.A, p.Iy, p.Iz, p.sy, p.sz, p.E)
                          for e, p in enumerate(mesh.props)))
    Kf, Gf = Ks[free][:, free], KG[free][:, free]
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} asked, the frame has only {free.size} free unknowns")
    if free.size <= DENSE_LIMIT:
        th, V = sla.eigh(-Gf.toarray(), Kf.toarray())
        order = np.argsort(-th)
    else:
        from mechverify.fea.frame.analysis import _node_order

        p = _node_order(Kf, free)
        lu = spl.splu(Kf.tocsr()[p][:, p].tocsc(), permc_spec="NATURAL", diag_pivot_thresh=0.0,
                      options={"SymmetricMode": True})

        def solve(b: np.ndarray) -> np.ndarray:
            x = np.empty_like(b, dtype=float)
            x[p] = lu.solve(np.ascontiguousarray(b[p]))
            return x

        op = spl.LinearOperator(Kf.shape, matvec=solve, dtype=float)
        k = min(n_modes + 4, free.size - 1)
        th, V = spl.eigsh(-Gf.tocsc(), k=k, M=Kf.tocsc(), Minv=op, which="LA", tol=1e-10,
                          v0=np.random.default_rng(0).standard_normal(free.size))
        order = np.argsort(-th)
    th, V = th[order], V[:, order]
    pos = th > 1e-12 * max(float(np.max(np.abs(th))), 1e-300)
    th, V = th[pos][:n_modes], V[:, pos][:, :n_modes]
    if not len(th):
        raise ModelError(f"frame {frame.name!r}: no positive buckling factor found under these loads")
    full = np.zeros((mesh.ndof, len(th)))
    full[free] = V
    shapes = full.T.reshape(len(th), -1, 6)
    for k in range(len(th)):
        t = shapes[k, :, :3]
        shapes[k] /= t.flat[np.argmax(np.abs(t))] if np.max(np.abs(t)) > 0 else 1.0
    return FrameBuckling(1.0 / th, shapes, mesh.points.copy(), mesh.elem_nodes.copy(), N, int(free.size))
