"""Natural frequencies and mode shapes of solids (:class:`~mechverify.fea.solid.SolidModel`) and plane
models (:class:`~mechverify.fea.plane.PlaneModel`): the generalized eigenproblem ``K φ = ω² M φ``.

    >>> from mechverify.fea import mesh, modal, solid
    >>> m = mesh.box(("100 mm", "10 mm", "10 mm"), (10, 1, 1))
    >>> res = modal.modal(solid.SolidModel(m, "Structural Steel"), n_modes=8)   # free-free: 6 zeros first
    >>> res.rigid_body_modes
    6

- :func:`stiffness_matrix`, :func:`mass_matrix` - the P2 stiffness and the *consistent* mass
  ``M = ∫ ρ Nᵀ N dV`` (ref. 1, sec. 16.2; degree-4 rule, exact for straight P2 elements; curved
  elements through the isoparametric map), density from the material (``density``).
- :func:`modal` - the first ``n_modes`` eigenpairs by Lanczos in shift-invert mode on one sparse
  factorisation of ``K - σ M`` (CHOLMOD or SuperLU, :mod:`mechverify.fea.factor`; ARPACK through
  ``scipy.sparse.linalg.eigsh``, ref. 2). A model with supports must be fully supported (the rigid motion
  left free is named, as in statics); a model with *no* supports is analysed free-free: its rigid-body
  modes (6 in 3D, 3 in 2D) are the exact rigid motions at zero frequency, set apart so that Lanczos seeks
  the elastic modes M-orthogonal to them (a six-fold zero eigenvalue is where Lanczos may miss a copy),
  and are counted in :attr:`ModalResults.rigid_body_modes`.
- :class:`ModalResults` - frequencies, mass-normalised mode shapes, effective modal masses along x,
  y, z (ref. 3, sec. 13.2), VTU export of every mode.

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   sec. 16.2 (consistent mass) and ch. 16 (eigenvalue problems).
2. Lehoucq, Sorensen & Yang, ARPACK Users' Guide, SIAM 1998, sec. 3.2 (shift-invert spectral
   transformation for the generalized problem).
3. Chopra, Dynamics of Structures, 4th ed., 2012, sec. 13.2 (modal participation factor, effective
   modal mass).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pint
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError
from mechverify.fea import assembly as asm
from mechverify.fea import isoparametric as iso
from mechverify.fea.factor import factorize, one_blas_thread
from mechverify.fea.linsolve import check_supported, rigid_modes
from mechverify.units import Q


def _parts(model: Any) -> tuple[int, np.ndarray, float, tuple[float, float]]:
    """``(dim, element_dofs, thickness, (λ, μ))`` of a solid or plane model."""
    mat = model.material
    E, nu = mat.E.m_as("Pa"), mat.nu.m_as("")
    lam, mu = asm.lame(E, nu)
    if hasattr(model, "plane"):  # PlaneModel
        if model.plane == "stress":
            lam = asm.lame(E, nu, "stress")[0]
        return 2, model.basis.element_dofs, model.thickness_si, (lam, mu)
    return 3, model.mesh.basis.element_dofs, 1.0, (lam, mu)


def _pattern(model: Any, dim: int, ed: np.ndarray) -> asm.BlockPattern:
    n = model.basis.N if dim == 2 else model.mesh.basis.N
    return asm.block_pattern(ed, n)


def stiffness_matrix(model: Any, pattern: asm.BlockPattern | None = None) -> sp.bsr_matrix:
    """The P2 stiffness matrix ``[dim*n, dim*n]`` [N/m] of a solid or plane model (node-interleaved DOFs);
    ``pattern`` the sparsity pattern when already built (it is shared with the mass matrix)."""
    dim, ed, t, (lam, mu) = _parts(model)
    pattern = pattern if pattern is not None else _pattern(model, dim, ed)
    if model.is_curved:
        blocks, _ = iso.stiffness_blocks(model.nodes, ed, lam, mu, t)
    else:
        mesh = model.mesh if dim == 2 else model.mesh.mesh
        blocks = asm.elasticity_blocks(mesh.p, mesh.t, lam, mu, t)
    return asm.assemble_blocks(blocks, pattern, dim)


def density(model: Any) -> float:
    """Mass density [kg/m³] of the model's material; :class:`InputError` when the material has none."""
    try:
        return float(model.material.require("density").m_as("kg/m**3"))
    except Exception as exc:  # the material's own named error says which property is missing
        raise InputError(f"modal analysis needs the material's density: {exc}") from None


def mass_matrix(model: Any, pattern: asm.BlockPattern | None = None) -> sp.bsr_matrix:
    """The consistent mass matrix ``M_ab = ∫ ρ t N_a N_b dV · I`` [kg] (ref. 1, sec. 16.2)."""
    dim, ed, t, _ = _parts(model)
    rho = density(model)
    _, W, N, dN = iso.reference(dim, 4)
    if model.is_curved:
        det, _ = iso.geometry(model.nodes, ed, dN)
    else:
        mesh = model.mesh if dim == 2 else model.mesh.mesh
        _, dj = asm.jacobians(mesh.p, mesh.t[: dim + 1])
        det = np.abs(dj)[:, None] * np.ones_like(W)[None, :]
    me = np.einsum("aq,bq,eq->abe", N, N, det * W[None, :] * (rho * t), optimize=True)  # a, b, e
    nb, ne = me.shape[0], me.shape[2]
    blocks = np.zeros((nb * nb, ne, dim * dim))
    for i in range(dim):
        blocks[:, :, i * dim + i] = me.reshape(nb * nb, ne)
    return asm.assemble_blocks(blocks, pattern if pattern is not None else _pattern(model, dim, ed), dim)


def free_dofs(model: Any) -> np.ndarray:
    """DOFs left free by the supports (all of them for a model without supports); a model whose supports
    leave a rigid motion free is a :class:`ModelError` naming it."""
    dim = 2 if hasattr(model, "plane") else 3
    n = model.nodes.shape[1] * dim
    if not model.supports:
        return np.arange(n)
    held = model.held_dofs()
    check_supported(model.nodes, held)
    mask = np.ones(n, bool)
    mask[held] = False
    return np.flatnonzero(mask)


@dataclass(frozen=True, eq=False)
class ModalResults:
    """The first natural frequencies and mode shapes of a model.

    ``omega2[k]`` [rad²/s²] ascending; ``shapes[k, n, 3]`` mass-normalised (``φᵀ M φ = 1`` [kg]);
    ``effective_mass[k, 3]`` [kg] along x, y, z (Chopra, sec. 13.2: ``(φᵀ M r)²`` with ``r`` a unit
    translation); ``total_mass`` [kg] of the free DOFs along each axis (the sum of all modes'
    effective masses).
    """

    kind: str
    omega2: np.ndarray
    shapes: np.ndarray
    points: np.ndarray  # [n, 3] m
    cells: list[tuple[str, np.ndarray]]
    effective_mass: np.ndarray
    total_mass: np.ndarray
    rigid_body_modes: int
    unknowns: int

    @property
    def frequencies(self) -> pint.Quantity:
        """Natural frequencies f = ω / 2π [Hz] (rigid-body modes: 0)."""
        return Q(np.sqrt(np.clip(self.omega2, 0.0, None)) / (2 * np.pi), "Hz")

    @property
    def first_frequency(self) -> pint.Quantity:
        """The lowest natural frequency of an elastic (not rigid-body) mode [Hz]."""
        if self.rigid_body_modes >= len(self.omega2):
            raise ModelError("all modes found are rigid-body modes; ask for more modes")
        return self.frequencies[self.rigid_body_modes]

    def effective_mass_fraction(self) -> np.ndarray:
        """Effective modal mass over total mass ``[k, 3]`` (their sums show how much mass the modes found cover)."""
        return self.effective_mass / np.where(self.total_mass > 0, self.total_mass, 1.0)[None, :]

    def to_vtu(self, path: str | Path) -> Path:
        """Write every mode shape as point data ``mode_<k>_<f>Hz`` (mass-normalised) to a VTU file."""
        from mechverify.fea.vtu import write_vtu

        f = self.frequencies.m
        data = {f"mode_{k + 1}_{f[k]:.6g}Hz": self.shapes[k] for k in range(len(f))}
        return write_vtu(Path(path), self.points, self.cells, data)

    def summary(self) -> dict[str, Any]:
        return {"kind": self.kind, "frequencies_Hz": [float(x) for x in self.frequencies.m],
                "rigid_body_modes": self.rigid_body_modes, "unknowns": self.unknowns,
                "effective_mass_fraction": self.effective_mass_fraction().sum(axis=0).tolist()}


def _default_shift(K: sp.spmatrix, M: sp.spmatrix) -> float:
    """A shift below the lowest elastic eigenvalue: -1e-4 of the median diagonal ratio Kii/Mii (that ratio is
    an element-scale frequency², far above the first structural one); keeps ``K - σM`` regular for free bodies."""
    d = K.diagonal() / np.where(M.diagonal() > 0, M.diagonal(), 1.0)
    return -1e-4 * float(np.median(d[d > 0]))


def modal(model: Any, n_modes: int = 6, shift: Any = None, method: str = "auto") -> ModalResults:
    """The ``n_modes`` natural frequencies of ``model`` nearest above ``shift`` (a frequency; default: the
    lowest ones) with mass-normalised mode shapes.

    One sparse factorisation of ``K - σ M`` (σ = (2π shift)², or a small negative number that keeps a
    free body's matrix regular) drives ARPACK's Lanczos iteration (ref. 2): CHOLMOD when scikit-sparse is
    installed (``method="auto"``/``"cholmod"``), else SuperLU (``"superlu"``; always for a positive shift,
    where ``K - σM`` is indefinite); :mod:`mechverify.fea.factor`. Asking for as many modes as
    the model has free DOFs, or more, is an :class:`InputError`.
    """
    n_modes = int(n_modes)
    dim = 2 if hasattr(model, "plane") else 3
    free = free_dofs(model)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} modes asked, but the model has only {free.size} free degrees of "
                         f"freedom (at most {free.size - 1} modes can be computed); refine the mesh or ask fewer")
    pattern = _pattern(model, dim, _parts(model)[1])
    K = stiffness_matrix(model, pattern).tocsr()
    M = mass_matrix(model, pattern).tocsr()
    Kf, Mf = K[free][:, free].tocsc(), M[free][:, free].tocsr()  # CSR: the faster product in ARPACK's loop
    if shift is None:
        sigma = _default_shift(Kf, Mf) if not model.supports else 0.0
    else:
        f0 = Q(shift).m_as("Hz") if not isinstance(shift, int | float) else float(shift)
        sigma = (2 * np.pi * f0) ** 2
    # K - σM is positive definite for σ <= 0 (CHOLMOD when installed); above the first eigenvalue it is indefinite
    try:
        fac = factorize((Kf - sigma * Mf).tocsc(), method if sigma <= 0 else "superlu", what="K - σM")
    except ModelError as exc:
        raise ModelError(f"{exc} (σ = {sigma:.4g} rad²/s²; a shift on an eigenvalue: give another shift)") from None
    rng = np.random.default_rng(0)
    v0 = rng.standard_normal(free.size)
    n_rigid = 0
    if not model.supports:
        # free body: the rigid-body modes (a multiple eigenvalue at zero, which Lanczos may not resolve) are
        # set apart exactly and the elastic modes sought in their M-orthogonal complement
        B, _ = rigid_modes(model.nodes)
        B = B[free]
        C = np.linalg.cholesky(B.T @ (Mf @ B))
        B = np.linalg.solve(C, B.T).T  # M-orthonormal
        n_rigid = B.shape[1]

        def project(x: np.ndarray) -> np.ndarray:
            return x - B @ (B.T @ (Mf @ x))

        op = spl.LinearOperator(Kf.shape, matvec=lambda x: project(fac.solve(x)), dtype=float)
        v0 = project(v0)
    else:
        op = fac.operator()
    k = n_modes - n_rigid
    if k > 0:
        with one_blas_thread():  # ARPACK's reorthogonalisation: BLAS-2, slower with threads on a loaded machine
            w, V = spl.eigsh(Kf, k=k, M=Mf, sigma=sigma, which="LM", OPinv=op, v0=v0, tol=1e-10)
        order = np.argsort(w)
        w, V = w[order], V[:, order]
    else:
        w, V = np.zeros(0), np.zeros((free.size, 0))
    if n_rigid:
        w = np.concatenate([np.zeros(n_rigid), w])[:n_modes]
        V = np.column_stack([B, V])[:, :n_modes]
    V = V / np.sqrt(np.einsum("ik,ik->k", V, Mf @ V))[None, :]  # mass-normalised
    n = model.nodes.shape[1]
    shapes = np.zeros((n_modes, n, 3))
    full = np.zeros((n * dim, n_modes))
    full[free] = V
    shapes[:, :, :dim] = full.T.reshape(n_modes, n, dim)
    # effective masses: r_i = unit translation along axis i restricted to the free DOFs
    R = np.zeros((n * dim, dim))
    for i in range(dim):
        R[i::dim, i] = 1.0
    MR = Mf @ R[free]
    gamma = V.T @ MR  # k, dim
    eff = np.zeros((n_modes, 3))
    eff[:, :dim] = gamma ** 2
    tot = np.zeros(3)
    tot[:dim] = np.einsum("ij,ij->j", R[free], MR)
    rigid = min(n_rigid, n_modes)
    if dim == 2:
        pts = np.column_stack([model.nodes.T, np.zeros(n)])
        cells = [("triangle6", model.basis.element_dofs.T.copy())]
        kind = f"plane {model.plane}"
    else:
        pts = model.nodes.T.copy()
        cells = [("tetra10", model.mesh.basis.element_dofs.T.copy())]
        kind = "solid"
    return ModalResults(kind, w, shapes, pts, cells, eff, tot, rigid, int(free.size))
