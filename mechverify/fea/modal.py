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
- :func:`modal` - the first ``n_modes`` eigenpairs, by one of two eigensolvers:

  - Lanczos in shift-invert mode on one sparse factorisation of ``K - σ M`` (CHOLMOD or SuperLU,
    :mod:`mechverify.fea.factor`; ARPACK through ``scipy.sparse.linalg.eigsh``, ref. 2): the faster path
    wherever its factor fits in memory (on the benchmark's lug: 3.8 s against 11 s of CPU at 48k DOF);
  - LOBPCG (ref. 4) preconditioned by the static solver's p-multigrid V-cycle
    (:func:`mechverify.fea.linsolve.pmg_preconditioner`), with the node mass ``m ⊗ I`` as an operator: no
    factor, so its memory grows as n where the factor's grows as n^(4/3) (:func:`memory_estimate`).

  ``method="auto"`` takes the factorisation when its memory fits *and* its predicted peak stays within a budget
  per unknown (:data:`MEMORY_PER_DOF`, issue 23's 5 kB; small models the budget of
  :data:`BUDGET_FLOOR_UNKNOWNS` unknowns, 0.5 GB; ``memory_per_dof=None`` for speed), else LOBPCG
  (:func:`auto_choice`; the results' ``solver_note`` says which ran and why): with CHOLMOD, the factor's size
  is counted by its symbolic analysis of the assembled K (:func:`mechverify.fea.factor.symbolic_cost`, METIS
  ordering, reused by the factorisation); without it, by the measured rule (:func:`memory_estimate`). A model
  too large for either path is refused before assembly with the estimate and the largest model that fits
  (:func:`require_memory`). A model with supports must be fully supported (the rigid motion
  left free is named, as in statics); a model with *no* supports is analysed free-free: its rigid-body
  modes (6 in 3D, 3 in 2D) are the exact rigid motions at zero frequency, set apart so that the eigensolver
  seeks the elastic modes M-orthogonal to them (shift-invert: a projection; LOBPCG: its constraints ``Y``;
  a six-fold zero eigenvalue is where Lanczos may miss a copy), and are counted in
  :attr:`ModalResults.rigid_body_modes`.
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
4. A. V. Knyazev, "Toward the optimal preconditioned eigensolver: Locally optimal block preconditioned
   conjugate gradient method", SIAM J. Sci. Comput. 23 (2001) 517-541 (LOBPCG; SciPy's ``lobpcg``).
"""

from __future__ import annotations

import warnings
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
from mechverify.fea.factor import cholmod_available, factorize, symbolic_cost
from mechverify.fea.linsolve import p1_prolongation, pmg_preconditioner, rigid_modes
from mechverify.fea.reproducible import one_blas_thread, reproducible
from mechverify.units import Q, to_si

#: ``method`` values of :func:`modal`.
METHODS = ("auto", "cholmod", "superlu", "lobpcg")
#: LOBPCG: extra block vectors beyond the wanted modes (at least; k/2 for k wanted), iterations of the first
#: chunk (its eigenvalues set the absolute tolerance), of each further chunk, and the iteration limit.
LOBPCG_GUARD = 4
LOBPCG_FIRST = 8
LOBPCG_CHUNK = 40
LOBPCG_MAXITER = 500
#: Memory model [bytes] of :func:`memory_estimate`, fitted to the peak RSS of benchmarks/fea_modal.py (the lug,
#: P2 tetrahedra, less the interpreter's 96 MB): the stiffness and mass of the free DOFs and the copy for K - σM
#: per unknown,
MATRIX_BYTES_PER_DOF = 2500.0
#: CHOLMOD's supernodal factor of a compact solid: ``FACTOR_BYTES_3D · n^(1/3)`` per unknown (nested dissection:
#: fill grows as n^(4/3); total peaks 8.1, 10.8 and 13.1 kB per DOF at 12.6k, 47.6k and 203k DOF, the estimate
#: 7.5, 10.3 and 15.0); SuperLU's is
#: :data:`SUPERLU_FILL` times larger (its fill on the 46k-DOF lug, :mod:`mechverify.fea.factor`). A thin part
#: fills less: the estimate is then conservative.
FACTOR_BYTES_3D = 210.0
SUPERLU_FILL = 4.0
#: and for LOBPCG the multigrid hierarchy and work vectors per unknown, plus 12 block vectors of 8 bytes per
#: block column (measured with 15 columns: 4.2 kB per DOF above the interpreter at 46k DOF, a total peak of 4.6 kB
#: per DOF at 203k; the estimate 4.9).
MULTIGRID_BYTES_PER_DOF = 1000.0
#: The memory budget per unknown of ``method="auto"`` [bytes]: issue 23's target "memory per DOF stays <= 5 kB"
#: (the whole process's peak over the model's unknowns, as benchmarks/fea_modal.py measures it). The factorisation
#: is taken only when its predicted peak (:func:`factorisation_peak`) stays within it, else LOBPCG; ``modal``'s
#: ``memory_per_dof`` argument changes it (None: no budget, the factorisation wherever it fits: the faster path).
MEMORY_PER_DOF = 5000.0
#: Small models get the budget of this many unknowns (0.5 GB at the default): below about 100k unknowns no
#: eigensolver meets 5 kB per DOF, because the interpreter is a fixed cost. Measured on the benchmark's lug, LOBPCG's
#: peak is 283 MB at 47 643 DOF (5.9 kB/DOF) and 936 MB at 202 539 (4.6 kB/DOF): the line through them,
#: 82 MB + 4.21 kB per DOF, crosses 5 kB per DOF at 104k DOF (docs/performance.md).
BUDGET_FLOOR_UNKNOWNS = 100_000
#: The interpreter with numpy, SciPy, pint and mechverify's FEA modules imported [bytes]: peak RSS of a fresh
#: process, 82.0 MB measured 2026-11-25 (the intercept of LOBPCG's line above: 82.4 MB).
INTERPRETER_BYTES = 82e6
#: What the factorisation path holds beside the factor itself, per unknown [bytes]: K and M of the free DOFs, the
#: copy K - σM, CHOLMOD's copy of it and ARPACK's Lanczos vectors. Measured on the lug (peak RSS less
#: :data:`INTERPRETER_BYTES` less CHOLMOD's symbolic count of the factor, ``method="auto"``): 5.27 kB at 46 356
#: unknowns (529 MB peak, factor 203 MB), 4.66 kB at 199 188 (2.75 GB, factor 1.74 GB); the larger is taken.
FACTOR_PATH_BYTES_PER_DOF = 5300.0


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


def _mass_elements(model: Any) -> np.ndarray:
    """Scalar element mass matrices ``me[a, b, e] = ∫ ρ t N_a N_b dV`` [kg] (degree-4 rule)."""
    dim, ed, t, _ = _parts(model)
    rho = density(model)
    _, W, N, dN = iso.reference(dim, 4)
    if model.is_curved:
        det, _ = iso.geometry(model.nodes, ed, dN)
    else:
        mesh = model.mesh if dim == 2 else model.mesh.mesh
        _, dj = asm.jacobians(mesh.p, mesh.t[: dim + 1])
        det = np.abs(dj)[:, None] * np.ones_like(W)[None, :]
    return np.einsum("aq,bq,eq->abe", N, N, det * W[None, :] * (rho * t), optimize=True)  # a, b, e


def mass_matrix(model: Any, pattern: asm.BlockPattern | None = None) -> sp.bsr_matrix:
    """The consistent mass matrix ``M_ab = ∫ ρ t N_a N_b dV · I`` [kg] (ref. 1, sec. 16.2)."""
    dim, ed, _, _ = _parts(model)
    me = _mass_elements(model)
    nb, ne = me.shape[0], me.shape[2]
    blocks = np.zeros((nb * nb, ne, dim * dim))
    for i in range(dim):
        blocks[:, :, i * dim + i] = me.reshape(nb * nb, ne)
    return asm.assemble_blocks(blocks, pattern if pattern is not None else _pattern(model, dim, ed), dim)


def node_mass_matrix(model: Any, pattern: asm.BlockPattern | None = None) -> sp.csr_matrix:
    """The scalar node-by-node consistent mass ``m_ab = ∫ ρ t N_a N_b dV`` [kg]: :func:`mass_matrix` is
    ``m ⊗ I`` (every block is ``m_ab`` times the identity), so ``m`` holds it in a ninth of the memory (3D)."""
    dim, ed, _, _ = _parts(model)
    me = _mass_elements(model)
    nb, ne = me.shape[0], me.shape[2]
    pattern = pattern if pattern is not None else _pattern(model, dim, ed)
    return asm.assemble_blocks(me.reshape(nb * nb, ne, 1), pattern, 1).tocsr()


class _NodeMass(spl.LinearOperator):
    """``M_ff`` of the free DOFs applied as the node mass ``m ⊗ I`` (scatter to all DOFs, one sparse product of
    ``m`` with the ``[nodes, dim·k]`` block, gather): no vector mass matrix is stored."""

    def __init__(self, m: sp.csr_matrix, free: np.ndarray, dim: int):
        self.m, self.free, self.dim = m, free, dim
        self.n_all = m.shape[0] * dim
        self.all_free = free.size == self.n_all
        super().__init__(float, (free.size, free.size))

    def _matmat(self, X: np.ndarray) -> np.ndarray:
        k = X.shape[1]
        full = X if self.all_free else np.zeros((self.n_all, k))
        if not self.all_free:
            full[self.free] = X
        Y = (self.m @ full.reshape(self.m.shape[0], self.dim * k)).reshape(self.n_all, k)
        return Y if self.all_free else Y[self.free]

    def _matvec(self, x: np.ndarray) -> np.ndarray:
        return self._matmat(x.reshape(-1, 1)).ravel()

    def _adjoint(self) -> _NodeMass:
        return self

    def diagonal(self) -> np.ndarray:
        return np.repeat(self.m.diagonal(), self.dim)[self.free]


def free_dofs(model: Any) -> np.ndarray:
    """DOFs left free by the supports (all of them for a model without supports); a model whose supports
    leave a rigid motion free is a :class:`ModelError` naming it."""
    dim = 2 if hasattr(model, "plane") else 3
    n = model.nodes.shape[1] * dim
    if not model.supports:
        return np.arange(n)
    from mechverify.fea.pins import checked_held  # (pin supports: the held DOFs in the pins' axes)

    held = checked_held(model)
    mask = np.ones(n, bool)
    mask[held] = False
    return np.flatnonzero(mask)


@dataclass(frozen=True, eq=False)
class ModalResults:
    """The first natural frequencies and mode shapes of a model.

    ``omega2[k]`` [rad²/s²] ascending; ``shapes[k, n, 3]`` mass-normalised (``φᵀ M φ = 1`` [kg]);
    ``effective_mass[k, 3]`` [kg] along x, y, z (Chopra, sec. 13.2: ``(φᵀ M r)²`` with ``r`` a unit
    translation); ``total_mass`` [kg] of the free DOFs along each axis (the sum of all modes'
    effective masses); ``method`` the eigensolver used ("cholmod", "superlu" or "lobpcg"), ``iterations``
    LOBPCG's iterations, ``residual`` the largest relative residual ``‖Kφ - λMφ‖ / (λ‖Mφ‖)`` of the
    elastic modes; ``solver_note`` which eigensolver ran and why ("LOBPCG: the CHOLMOD factorisation would need
    14.5 kB per unknown ..., above the budget ...", :func:`auto_choice`).
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
    method: str = ""
    iterations: int = 0
    residual: float = 0.0
    solver_note: str = ""

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


def memory_estimate(unknowns: int, dim: int = 3, n_modes: int = 10, method: str = "cholmod") -> float:
    """Estimated peak memory [bytes] of :func:`modal` for ``unknowns`` free DOFs (measured rule, module
    constants): the matrices (:data:`MATRIX_BYTES_PER_DOF`), plus for a factorisation the factor
    (3D: :data:`FACTOR_BYTES_3D` ``· n^(1/3)`` per unknown for CHOLMOD, :data:`SUPERLU_FILL` times that for
    SuperLU; 2D: a third of it, an unmeasured allowance: a plane model's fill grows as n log n) and ARPACK's 2k+1
    Lanczos vectors, or for LOBPCG the multigrid
    (:data:`MULTIGRID_BYTES_PER_DOF`) and 12 block vectors of ``k + max(LOBPCG_GUARD, k/2)`` columns."""
    n = float(unknowns)
    base = MATRIX_BYTES_PER_DOF * n
    if method == "lobpcg":
        m = n_modes + max(LOBPCG_GUARD, n_modes // 2)
        return base + MULTIGRID_BYTES_PER_DOF * n + 12 * 8 * m * n
    fill = FACTOR_BYTES_3D * n ** (1 / 3) * n * (1.0 if dim == 3 else 1 / 3)
    if method == "superlu":
        fill *= SUPERLU_FILL
    return base + fill + 8 * (2 * n_modes + 1) * n


def _available(memory: float | None) -> float:
    """:data:`~mechverify.fea.study.MEMORY_SHARE` of ``memory`` [bytes] or, when None, of the machine's."""
    from mechverify.fea.study import MEMORY_SHARE, available_memory

    if memory is None:
        return available_memory() * MEMORY_SHARE
    if isinstance(memory, bool) or not isinstance(memory, int | float) or not memory > 0:
        raise InputError(f"memory: a positive number of bytes (or None: the machine's), got {memory!r}")
    return float(memory) * MEMORY_SHARE


def memory_per_unknown(value: Any) -> float | None:
    """The ``memory_per_dof`` of :func:`modal` in bytes: a positive number of bytes, a quantity or string in bytes
    (``"5 kB"``), or None (no budget); else an :class:`InputError` naming ``memory_per_dof``."""
    if value is None:
        return None
    if isinstance(value, bool):
        raise InputError(f"memory_per_dof: bytes per unknown such as 5000 or '5 kB' (None: no budget), got {value!r}")
    try:
        b = float(value) if isinstance(value, int | float | np.integer | np.floating) else Q(value).m_as("byte")
    except Exception:
        raise InputError(f"memory_per_dof: bytes per unknown such as 5000 or '5 kB' (None: no budget), got {value!r}") \
            from None
    if not (np.isfinite(b) and b > 0):
        raise InputError(f"memory_per_dof: a positive number of bytes per unknown (None: no budget), got {value!r}")
    return float(b)


def memory_budget(unknowns: int, memory_per_dof: float | None = MEMORY_PER_DOF) -> float:
    """The peak memory [bytes] ``method="auto"`` allows the factorisation for ``unknowns`` free DOFs:
    ``memory_per_dof`` [bytes] per unknown, counted for at least :data:`BUDGET_FLOOR_UNKNOWNS` unknowns
    (infinite for None: no budget)."""
    if memory_per_dof is None:
        return float("inf")
    return float(memory_per_dof) * max(int(unknowns), BUDGET_FLOOR_UNKNOWNS)


def factorisation_peak(unknowns: int, n_modes: int, factor_bytes: float) -> float:
    """Predicted peak memory [bytes] of the whole process for :func:`modal` by a factorisation whose factor holds
    ``factor_bytes`` (CHOLMOD's symbolic count, or the fill of :func:`memory_estimate`): the interpreter
    (:data:`INTERPRETER_BYTES`), the factor, and :data:`FACTOR_PATH_BYTES_PER_DOF` per unknown (measured with 10
    modes; 16 bytes per unknown for each further mode's two Lanczos vectors)."""
    n = float(unknowns)
    return INTERPRETER_BYTES + factor_bytes + (FACTOR_PATH_BYTES_PER_DOF + 16.0 * max(0, n_modes - 10)) * n


def _fill(unknowns: int, dim: int, method: str) -> float:
    """The factor's bytes by the measured rule of :func:`memory_estimate` (without the matrices and vectors)."""
    n = float(unknowns)
    fill = FACTOR_BYTES_3D * n ** (1 / 3) * n * (1.0 if dim == 3 else 1 / 3)
    return fill * (SUPERLU_FILL if method == "superlu" else 1.0)


_NAMES = {"cholmod": "CHOLMOD", "superlu": "SuperLU", "lobpcg": "LOBPCG"}


def auto_choice(unknowns: int, dim: int = 3, n_modes: int = 10, memory: float | None = None,
                memory_per_dof: Any = MEMORY_PER_DOF, factor_bytes: float | None = None,
                direct: str | None = None) -> tuple[str, str]:
    """``(method, note)``: the eigensolver ``method="auto"`` takes for the lowest modes and why. The factorisation
    (``direct``: CHOLMOD when installed, else SuperLU) when

    1. it fits in :data:`~mechverify.fea.study.MEMORY_SHARE` of the available memory (``memory`` [bytes] instead
       of the machine's; the factor, the matrices and the Lanczos vectors), and
    2. its predicted peak (:func:`factorisation_peak`) stays within the budget (:func:`memory_budget`:
       ``memory_per_dof``, default :data:`MEMORY_PER_DOF`, issue 23's 5 kB per unknown; None: no budget),

    else LOBPCG. ``factor_bytes``: CHOLMOD's symbolic count of the factor when known, else the measured rule
    (:func:`memory_estimate`; SuperLU's fill :data:`SUPERLU_FILL` times CHOLMOD's, so on the default budget SuperLU
    is taken up to about 17k unknowns: above that LOBPCG, which is also the faster of the two there)."""
    direct = direct or ("cholmod" if cholmod_available() else "superlu")
    per = memory_per_unknown(memory_per_dof)
    n, name = int(unknowns), _NAMES[direct]
    counted = "counted by CHOLMOD's symbolic analysis" if factor_bytes is not None else "estimated"
    fb = _fill(n, dim, direct) if factor_bytes is None else float(factor_bytes)
    fits = fb + (MATRIX_BYTES_PER_DOF + 8 * (2 * n_modes + 1)) * n
    avail = _available(memory)
    if fits > avail:
        return "lobpcg", (f"LOBPCG: the {name} factorisation would need about {fits / 1e9:.3g} GB ({counted}), more "
                          f"than the {avail / 1e9:.3g} GB available")
    peak, budget = factorisation_peak(n, n_modes, fb), memory_budget(n, per)
    per_unknown = peak / max(n, 1) / 1e3
    if per is None:
        return direct, (f"{name}: no memory budget (memory_per_dof=None) and the factorisation fits "
                        f"(predicted peak {peak / 1e9:.3g} GB, {per_unknown:.3g} kB per unknown, {counted})")
    rule = f"{per / 1e3:.3g} kB per unknown" + ("" if n >= BUDGET_FLOOR_UNKNOWNS else
                                                f", counted for at least {BUDGET_FLOOR_UNKNOWNS:,} unknowns")
    if peak > budget:
        return "lobpcg", (f"LOBPCG: the {name} factorisation would need {per_unknown:.3g} kB per unknown (a peak of "
                          f"{peak / 1e9:.3g} GB, {counted}), above the budget of {budget / 1e9:.3g} GB ({rule}; "
                          "memory_per_dof=None takes the faster factorisation wherever it fits)")
    return direct, (f"{name}: the factorisation's predicted peak of {peak / 1e9:.3g} GB ({per_unknown:.3g} kB per "
                    f"unknown, {counted}) is within the budget of {budget / 1e9:.3g} GB ({rule})")


def choose_method(unknowns: int, dim: int = 3, n_modes: int = 10, shift: Any = None,
                  memory: float | None = None, memory_per_dof: Any = MEMORY_PER_DOF) -> str:
    """The eigensolver ``method="auto"`` takes by the measured rule (:func:`auto_choice` without CHOLMOD's
    symbolic count): a factorisation (CHOLMOD when installed, else SuperLU) when it fits in memory and within the
    budget per unknown, else LOBPCG; always a factorisation for a ``shift`` (LOBPCG finds the lowest modes only)."""
    direct = "cholmod" if cholmod_available() else "superlu"
    if shift is not None:
        return direct
    return auto_choice(unknowns, dim, n_modes, memory, memory_per_dof, direct=direct)[0]


def largest_fitting(dim: int, n_modes: int, method: str, memory: float | None = None) -> int:
    """The most unknowns whose :func:`memory_estimate` fits in the available memory (bisection)."""
    avail = _available(memory)
    lo, hi = 0, 1
    while memory_estimate(hi, dim, n_modes, method) <= avail:
        lo, hi = hi, hi * 2
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if memory_estimate(mid, dim, n_modes, method) <= avail else (lo, mid)
    return lo


def require_memory(unknowns: int, dim: int, n_modes: int, method: str, memory: float | None = None) -> None:
    """:class:`ModelError` with the estimate and the largest model that fits when :func:`modal` with ``method``
    would need more than the available memory (checked before assembling anything)."""
    need, avail = memory_estimate(unknowns, dim, n_modes, method), _available(memory)
    if need > avail:
        n_max = largest_fitting(dim, n_modes, method, memory)
        other = "" if method == "lobpcg" else " (method='lobpcg' needs less)"
        raise ModelError(f"modal analysis ({method}) of {unknowns:,} unknowns would need about {need / 1e9:.3g} GB, "
                         f"more than the {avail / 1e9:.3g} GB available; the largest model that fits has about "
                         f"{n_max:,} unknowns{other}: use a coarser mesh")


def mode_count(value: Any, name: str = "n_modes") -> int:
    """``value`` as a number of modes (a whole number; 3.0 is 3), else an :class:`InputError` naming ``name``."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise InputError(f"{name}: a whole number of modes, got {value!r}")
    return int(value)


def shift_frequency(shift: Any) -> float:
    """The ``shift`` of :func:`modal` in Hz: a frequency (``"1200 Hz"``, a quantity) or a bare number of Hz,
    not negative; else an :class:`InputError` / :class:`~mechverify.errors.UnitError` naming ``shift``."""
    if isinstance(shift, bool):
        raise InputError(f"shift: expected a frequency such as '1200 Hz', got {shift!r}")
    f0 = float(shift) if isinstance(shift, int | float | np.integer | np.floating) else to_si(shift, "frequency",
                                                                                              "shift")
    if not np.isfinite(f0) or f0 < 0:
        raise InputError(f"shift: a frequency of zero or more (the modes nearest above it are found), got {shift!r}")
    return f0


def _default_shift(K: sp.spmatrix, M: sp.spmatrix) -> float:
    """A shift below the lowest elastic eigenvalue: -1e-4 of the median diagonal ratio Kii/Mii (that ratio is
    an element-scale frequency², far above the first structural one); keeps ``K - σM`` regular for free bodies."""
    d = K.diagonal() / np.where(M.diagonal() > 0, M.diagonal(), 1.0)
    return -1e-4 * float(np.median(d[d > 0]))


def _prolongation(model: Any, dim: int) -> sp.csr_matrix:
    """Linear-to-quadratic interpolation of the model's mesh (the coarse level of the p-multigrid)."""
    if dim == 3:
        m = model.mesh.mesh
        basis = getattr(model, "dof_basis", None)  # pins: in the pins' axes, Tᵀ P T₁
        P = p1_prolongation(m.nvertices, m.edges, 3)
        return P if basis is None else basis.prolongation(P)
    return p1_prolongation(model.mesh.nvertices, model.mesh.facets, 2)


def _relative_residuals(K: sp.spmatrix, M: sp.spmatrix, w: np.ndarray, V: np.ndarray) -> np.ndarray:
    """``‖K φ - λ M φ‖ / (λ ‖M φ‖)`` per column (the backward error of an eigenpair; ref. 4, sec. 2)."""
    MV = M @ V
    R = K @ V - MV * w[None, :]
    return np.linalg.norm(R, axis=0) / np.maximum(np.abs(w) * np.linalg.norm(MV, axis=0), 1e-300)


def _lobpcg(model: Any, Kf: sp.csr_matrix, Mf: _NodeMass, free: np.ndarray, dim: int, k: int,
            Y: np.ndarray | None, sigma: float, rtol: float) -> tuple[np.ndarray, np.ndarray, int, float]:
    """The ``k`` lowest eigenpairs of ``Kf φ = λ Mf φ`` (M-orthogonal to the columns of ``Y``) by LOBPCG
    (ref. 4) preconditioned by the static solver's p-multigrid V-cycle of ``Kf - σ Mf``
    (:func:`mechverify.fea.linsolve.pmg_preconditioner`): ``(λ, φ, iterations, largest relative residual)``.

    The block carries :data:`LOBPCG_GUARD` extra vectors (the last wanted mode converges at the rate set by
    the first unwanted one). SciPy's LOBPCG stops on one absolute residual for the whole block, so it runs in
    chunks of :data:`LOBPCG_CHUNK` iterations, restarted from its best block, until the wanted pairs'
    relative residuals (:func:`_relative_residuals`) are below ``rtol``; an eigenvalue's relative error is
    then of order ``rtol²`` times λ over its gap to the rest of the spectrum."""
    if sigma == 0:
        A = Kf
    else:  # K - σM with the vector mass built for it (m ⊗ I on the free DOFs)
        Mv = sp.kron(Mf.m, sp.identity(dim, format="csr"), format="csr")[free][:, free]
        A = (Kf - sigma * Mv).tocsr()
        del Mv
    apply = pmg_preconditioner(A, model.nodes, free, dim, _prolongation(model, dim))

    def precondition(R: np.ndarray) -> np.ndarray:
        R = R.reshape(R.shape[0], -1)
        return np.column_stack([apply(np.ascontiguousarray(R[:, j])) for j in range(R.shape[1])])

    T = spl.LinearOperator(Kf.shape, matvec=precondition, matmat=precondition, dtype=float)
    m = min(k + max(LOBPCG_GUARD, k // 2), free.size - (0 if Y is None else Y.shape[1]) - 1)
    X = np.random.default_rng(0).standard_normal((free.size, m))
    iterations, tol, rel = 0, None, np.array([np.inf])
    while iterations < LOBPCG_MAXITER:
        with warnings.catch_warnings(), one_blas_thread():
            warnings.simplefilter("ignore")  # "did not reach the tolerance": judged below, per wanted pair
            w, X, hist = spl.lobpcg(Kf, X, B=Mf, M=T, Y=Y, tol=tol if tol is not None else 1e-300,
                                    maxiter=LOBPCG_CHUNK if tol is not None else LOBPCG_FIRST,
                                    largest=False, retLambdaHistory=True)
        iterations += max(len(hist) - 1, 1)
        order = np.argsort(w)
        w, X = w[order], X[:, order]
        rel = _relative_residuals(Kf, Mf, w[:k], X[:, :k])
        if np.all(rel <= rtol):
            return w[:k], X[:, :k], iterations, float(np.max(rel))
        # SciPy's absolute tolerance for the next chunk: the wanted pairs' residual scale ‖λ M φ‖
        tol = rtol * float(np.min(np.abs(w[:k]) * np.linalg.norm(Mf @ X[:, :k], axis=0)))
    raise ModelError(f"LOBPCG did not converge in {iterations} iterations (largest relative residual "
                     f"{float(np.max(rel)):.2e} > {rtol:g}); the model may be nearly a mechanism, or use "
                     "method='cholmod' (a factorisation) if it fits in memory")


@reproducible  # one BLAS thread: the same bits whatever the process's thread count (issue 19)
def modal(model: Any, n_modes: int = 6, shift: Any = None, method: str = "auto", rtol: float = 1e-5,
          memory: float | None = None, memory_per_dof: Any = MEMORY_PER_DOF) -> ModalResults:
    """The ``n_modes`` natural frequencies of ``model`` nearest above ``shift`` (a frequency; default: the
    lowest ones) with mass-normalised mode shapes.

    ``method``:

    - ``"cholmod"`` / ``"superlu"``: one sparse factorisation of ``K - σ M`` (σ = (2π shift)², or a small
      negative number that keeps a free body's matrix regular) drives ARPACK's Lanczos iteration in
      shift-invert mode (ref. 2; :mod:`mechverify.fea.factor`; SuperLU always for a positive shift, where
      ``K - σM`` is indefinite).
    - ``"lobpcg"``: LOBPCG (ref. 4) preconditioned by the static solver's multigrid (solids and plane
      models; the lowest modes only, no ``shift``), to relative residuals ``rtol``: no factor, so a few kB per
      unknown where the factor of a large solid takes 15 or more.
    - ``"auto"``: the factorisation (CHOLMOD when installed) when its memory fits in
      :data:`~mechverify.fea.study.MEMORY_SHARE` of the available memory (``memory`` [bytes]: instead of the
      machine's) *and* its predicted peak stays within ``memory_per_dof`` per unknown (default
      :data:`MEMORY_PER_DOF`, issue 23's 5 kB; small models the budget of :data:`BUDGET_FLOOR_UNKNOWNS`; a number
      of bytes, ``"8 kB"``, or None: no budget, the faster factorisation wherever it fits), the factor counted by
      CHOLMOD's symbolic analysis of K (else estimated), else LOBPCG (:func:`auto_choice`). The results'
      ``solver_note`` says which eigensolver ran and why.

    A model too large for either path is refused *before* assembly with the estimate and the largest
    model that fits (:class:`ModelError`). Asking for as many modes as the model has free DOFs, or more, is
    an :class:`InputError`.
    """
    n_modes = mode_count(n_modes)
    if method not in METHODS:
        raise InputError(f"method: one of {', '.join(METHODS)}, got {method!r}")
    if not (isinstance(rtol, int | float) and 0 < rtol < 1e-1):
        raise InputError(f"rtol: a relative residual between 0 and 0.1, got {rtol!r}")
    dim = 2 if hasattr(model, "plane") else 3
    free = free_dofs(model)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} modes asked, but the model has only {free.size} free degrees of "
                         f"freedom (at most {free.size - 1} modes can be computed); refine the mesh or ask fewer")
    if method == "lobpcg" and shift is not None:
        raise InputError("shift: LOBPCG finds the lowest modes; modes near a frequency need a factorisation "
                         "(method 'auto', 'cholmod' or 'superlu')")
    f0 = None if shift is None else shift_frequency(shift)
    # SciPy's lobpcg turns to a dense eigensolver (with another return signature) when its block exceeds a fifth
    # of the unknowns: so many modes are a factorisation's job
    block_fits = 5 * (n_modes + max(LOBPCG_GUARD, n_modes // 2) + 6) < free.size
    if method == "lobpcg" and not block_fits:
        raise InputError(f"n_modes: {n_modes} modes of a model with {free.size} free degrees of freedom are too many "
                         "for LOBPCG (its block must stay under a fifth of the unknowns): ask fewer modes or use "
                         "method 'auto', 'cholmod' or 'superlu'")
    per_dof = memory_per_unknown(memory_per_dof)
    direct = "cholmod" if cholmod_available() else "superlu"
    if method != "auto":
        used, note = method, f"{_NAMES[method]}: method={method!r} asked"
    elif shift is not None:
        used, note = direct, f"{_NAMES[direct]}: a shift needs a factorisation (LOBPCG finds the lowest modes only)"
    else:
        used, note = auto_choice(free.size, dim, n_modes, memory, per_dof, direct=direct)
    # before assembling anything: what the least demanding allowed path needs must fit (the measured rule)
    require_memory(free.size, dim, n_modes, "lobpcg" if method == "auto" and shift is None else used, memory)
    pattern = _pattern(model, dim, _parts(model)[1])
    basis = getattr(model, "dof_basis", None)  # pin supports: K and M in the pins' axes, K' = Tᵀ K T (fea.pins)

    def axes(A: sp.spmatrix) -> sp.spmatrix:
        return A if basis is None else basis.rotate(A)

    # one matrix at a time, each cut to the free DOFs before the next (peak memory); CSR: the faster product
    Kf = axes(stiffness_matrix(model, pattern)).tocsr()[free][:, free].tocsr()
    symbolic = None
    if method == "auto" and shift is None and cholmod_available() \
            and factorisation_peak(free.size, n_modes, 0.0) <= memory_budget(free.size, per_dof):
        # CHOLMOD's symbolic analysis (METIS ordering) counts the factor exactly: it decides instead of the rule,
        # and the factorisation reuses its ordering (K - σM has K's pattern). Not run when the factorisation path
        # without any factor is already over the budget (at the default budget: from 100k unknowns up; its memory
        # would count against LOBPCG's peak: 20 MB more at 46k unknowns)
        symbolic = symbolic_cost(Kf, "metis")
        if symbolic is not None:
            used, note = auto_choice(free.size, dim, n_modes, memory, per_dof, symbolic.factor_bytes, "cholmod")
    if used == "lobpcg" and not block_fits:
        used = direct
        note = (f"{_NAMES[direct]}: {n_modes} modes are too many for LOBPCG's block (a fifth of the unknowns at "
                f"most), whatever the memory budget ({note})")
    Mf: Any
    if used == "lobpcg" and basis is None:  # the node mass m (M = m ⊗ I): a ninth of M's memory, a cheaper product
        Mf = _NodeMass(node_mass_matrix(model, pattern), free, dim)
    else:  # (pins: Tᵀ M T is not m ⊗ I at the wall nodes)
        Mf = axes(mass_matrix(model, pattern)).tocsr()[free][:, free].tocsr()
    del pattern
    if shift is None:
        sigma = _default_shift(Kf, Mf) if not model.supports else 0.0
    else:
        sigma = (2 * np.pi * f0) ** 2
    n_rigid, B = 0, None
    if not model.supports:
        # free body: the rigid-body modes (a multiple eigenvalue at zero, which Lanczos may not resolve) are
        # set apart exactly and the elastic modes sought in their M-orthogonal complement
        B, _ = rigid_modes(model.nodes)
        B = B[free]
        C = np.linalg.cholesky(B.T @ (Mf @ B))
        B = np.linalg.solve(C, B.T).T  # M-orthonormal
        n_rigid = B.shape[1]
    k = n_modes - n_rigid
    iterations, residual = 0, 0.0
    if k > 0 and used == "lobpcg":
        w, V, iterations, residual = _lobpcg(model, Kf, Mf, free, dim, k, B, sigma, rtol)
    elif k > 0:
        if sigma > 0 and used != "superlu":
            used = "superlu"  # K - σM is indefinite above the first eigenvalue
            note = "SuperLU: a positive shift makes K - σM indefinite (CHOLMOD needs a positive definite matrix)"
        try:
            fac = factorize((Kf - sigma * Mf).tocsc(), used, what="K - σM",
                            symbolic=symbolic if used == "cholmod" else None)
        except ModelError as exc:
            raise ModelError(f"{exc} (σ = {sigma:.4g} rad²/s²; a shift on an eigenvalue: give another shift)") \
                from None
        if fac.method != used:
            note = f"{note}; {_NAMES.get(fac.method, fac.method)} factored"
        used = fac.method
        v0 = np.random.default_rng(0).standard_normal(free.size)
        if B is not None:
            def project(x: np.ndarray) -> np.ndarray:
                return x - B @ (B.T @ (Mf @ x))

            op = spl.LinearOperator(Kf.shape, matvec=lambda x: project(fac.solve(x)), dtype=float)
            v0 = project(v0)
        else:
            op = fac.operator()
        with one_blas_thread():  # ARPACK's reorthogonalisation: BLAS-2, slower with threads on a loaded machine
            w, V = spl.eigsh(Kf, k=k, M=Mf, sigma=sigma, which="LM", OPinv=op, v0=v0, tol=1e-10)
        order = np.argsort(w)
        w, V = w[order], V[:, order]
        residual = float(np.max(_relative_residuals(Kf, Mf, w, V)))
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
    if basis is not None:
        full = basis.outward(full)
    shapes[:, :, :dim] = full.T.reshape(n_modes, n, dim)
    # effective masses: r_i = unit translation along axis i restricted to the free DOFs
    R = np.zeros((n * dim, dim))
    for i in range(dim):
        R[i::dim, i] = 1.0
    if basis is not None:
        R = basis.inward(R)
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
    return ModalResults(kind, w, shapes, pts, cells, eff, tot, rigid, int(free.size), used, iterations,
                        residual, note)
