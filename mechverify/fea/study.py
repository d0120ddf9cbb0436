"""Solid studies at any size: many load cases on one factorisation, a memory estimate before meshing,
and a two-mesh convergence check of the governing result.

- :class:`SharedSolve` / :func:`solve_cases` - the load cases of one mesh, material and supports solved on
  one sparse factorisation (CHOLMOD or SuperLU, :mod:`mechverify.fea.factor`; small and mid-size models;
  :meth:`SharedSolve.solve_many` solves a block of load vectors at once) or one multigrid hierarchy reused by CG for
  every case (large 3D models): the marginal cost of a case is a pair of triangular solves (or one CG run),
  not a new factorisation (``benchmarks/fea_load_cases.py`` measures it).
- :func:`estimate_dofs`, :func:`require_memory` - the unknowns of a P2 tetrahedral mesh of a volume at an
  element size (measured on gmsh meshes: about 40 V/h³, a structured box 29 V/h³) and the memory the static
  solver needs (about :data:`BYTES_PER_DOF` per unknown, measured in the FEA benchmark); a mesh that would not
  fit is refused *before* meshing, with the estimate and the smallest element size that fits.
- :func:`step_volume` - the volume of the solids of a STEP file (gmsh/OpenCASCADE), to estimate first.
- :func:`two_mesh_check` - the change of a peak result between a mesh and a refined one, and the refinement
  needed for a tolerance assuming the observed change shrinks as h^p (Richardson; ref. 1).
- :func:`two_mesh_stress`, :func:`convergence_warning` - that check for a solid's peak von Mises stress on a mesh
  :data:`REFINE` times finer: the governing (larger) peak, its note, and a warning with the ``mesh_size`` needed
  or, for a peak at a rigid support, its singularity named (the ``solid_fea`` design-file type's
  ``convergence_check``).

References
----------
1. Roache, Verification and Validation in Computational Science and Engineering, Hermosa 1998, ch. 5
   (Richardson extrapolation, grid convergence).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
import scipy.sparse as sp

from mechverify.errors import InputError, ModelError
from mechverify.fea.factor import cholmod_available, factorize
from mechverify.fea.linsolve import (
    ITERATIVE_THRESHOLD_3D,
    SolveInfo,
    choose_solver,
    p1_prolongation,
    pcg,
    pmg_preconditioner,
)
from mechverify.fea.reproducible import one_blas_thread, reproducible

#: Memory of the static solver per unknown [bytes]: peak RSS of ``SolidModel.solve`` with multigrid CG in a fresh
#: process, interpreter included, 2.8-2.9 kB per DOF at 181k-203k DOF and 4.4 at 47.6k (benchmarks/fea_memory.py,
#: issue 23; 4.3 kB before). A factorisation is taken only up to 300k unknowns and a factor of 3 kB per unknown
#: (:mod:`mechverify.fea.linsolve`), so a model large enough to be refused is solved by CG; the margin covers a
#: mesh with more surface (a thin plate) and a new process's libraries.
BYTES_PER_DOF = 3500.0
#: P2 unknowns per V/h³ of a gmsh tetrahedral mesh (measured: 39 on a 100x60x20 mm block with a hole at h = 5 mm).
DOFS_PER_VOLUME = 40.0
#: With the surface area known, unknowns = max(a V/h³ + b A/h², c A/h²): a two-point fit on gmsh blocks at h = 5 mm
#: (a 50 mm cube 24 705 DOF, a 300x10x10 mm bar 8 127: a = 20.9, b = 6.4) rounded up, and c for thin parts (a
#: 200x200x4 mm plate at h = 4 mm: 114 978 DOF = 22.1 A/h²). Measured (task fixsolid): estimate / real 1.04-1.38 on five
#: blocks without holes; with holes (gmsh refines them to h/2) 0.58-0.73 (the bracket at 6 mm: 14 583 DOF, 40 V/h³ said
#: 8 679), so the count after meshing is checked again before assembling (:func:`require_unknowns`).
DOFS_VOLUME_TERM, DOFS_SURFACE_TERM, DOFS_THIN_TERM = 24.0, 7.5, 23.0
#: Share of the available memory a solve may take.
MEMORY_SHARE = 0.8


@dataclass(eq=False)
class SharedSolve:
    """One factorisation (or one multigrid hierarchy) of ``K`` with the supports' held DOFs, reused for every
    load vector given to :meth:`solve`. ``K`` keeps the stiffness's held rows only (``assembly.held_rows``: the
    reactions ``(K @ u)[held]`` need no more; the full K, 0.7 kB per DOF, is freed once its free part exists). With
    pin supports (``SolidModel.dof_basis``, :mod:`mechverify.fea.pins`) ``K``, ``held``, the load vectors and the
    solutions are in the pins' axes (``K' = Tᵀ K T``): ``SolidModel.solve`` rotates ``f`` in and ``u`` out."""

    K: sp.spmatrix
    held: np.ndarray
    method: str
    _apply: Callable[[np.ndarray], np.ndarray]
    _Kff: sp.csr_matrix | None  # CG's matrix, and a factorisation's when it was made from the full K[free][:, free]
    _free: np.ndarray
    setup_seconds: float
    rtol: float = 1e-10
    _lower: sp.csc_matrix | None = None  # else the factorisation's lower triangle of K[free][:, free][perm][:, perm]
    _perm: np.ndarray | None = None

    @classmethod
    @reproducible  # one BLAS thread: the same bits whatever the process's thread count (issue 19)
    def of(cls, model: Any, method: str = "auto", cases: int = 1) -> SharedSolve:
        """Assemble and factor the stiffness of ``model`` (a SolidModel or PlaneModel) once. ``method="auto"``: a
        factorisation up to :data:`ITERATIVE_THRESHOLD_3D` unknowns (and in 2D); above, with CHOLMOD installed, the
        cheaper of a factorisation and multigrid CG for ``cases`` load cases by the cost model of
        :func:`mechverify.fea.linsolve.choose_solver` (the more cases, the more a factorisation pays).

        As :func:`mechverify.fea.linsolve.solve` (task solve2, issue 23): a solid's stiffness is summed a chunk of
        elements at a time (``SolidModel._stiffness``: at 121k curved DOF 0.55 s against 1.13 s for all element blocks
        at once), the choice is made on the node graph (:func:`mechverify.fea.assembly.node_graph`) and a factorisation
        chosen there reads only the lower triangle of the permuted ``K[free][:, free]`` from ``K``
        (:func:`~mechverify.fea.assembly.free_lower_permuted`, :func:`~mechverify.fea.factor.factorize_lower`: the
        same factor bit for bit, without the full free matrix and its permuted copy). CG and the small systems below
        the threshold keep ``K[free][:, free]``."""
        from mechverify.fea.assembly import free_lower_permuted, free_submatrix, held_rows, node_graph
        from mechverify.fea.factor import factorize_lower
        from mechverify.fea.pins import checked_held

        if method not in ("auto", "direct", "amg"):
            raise InputError(f"method: 'auto', 'direct' or 'amg', got {method!r}")
        t0 = time.perf_counter()
        K = _stiffness(model)
        held = checked_held(model)
        basis = getattr(model, "dof_basis", None)  # pin supports: K and the held DOFs in the pins' axes (fea.pins)
        if basis is not None:
            K = basis.rotate(K)
        mask = np.ones(K.shape[0], bool)
        mask[held] = False
        free = np.flatnonzero(mask)
        dim = model.nodes.shape[0]
        cost = None
        if method == "auto":
            method = "amg" if dim == 3 and free.size > ITERATIVE_THRESHOLD_3D else "direct"
            if method == "amg" and cholmod_available():
                graph, groups, nnz = node_graph(K, mask)  # the choice before any scalar matrix (as linsolve.solve)
                choice, cost = choose_solver(None, cases=max(int(cases), 1), groups=groups, graph=graph, nnz=nnz)
                method = choice.method
                del graph
        Kr = held_rows(K, held)  # all the reactions need
        if method == "direct" and cost is not None:
            lower = free_lower_permuted(K, mask, cost.perm)
            del K  # the full K (0.7 kB/DOF) goes before the factorisation, the peak of a direct solve
            apply = factorize_lower(lower, cost).solve
            return cls(Kr, held, method, apply, None, free, time.perf_counter() - t0, _lower=lower, _perm=cost.perm)
        Kff = free_submatrix(K, mask)  # no CSR copy of K on the way (issue 23)
        del K
        if method == "direct":
            apply = factorize(Kff, "auto", symbolic=cost).solve  # CHOLMOD when installed, else SuperLU
        else:
            m = model.mesh.mesh
            P = p1_prolongation(m.nvertices, m.edges, 3)
            apply = pmg_preconditioner(Kff, model.nodes, free, 3, P if basis is None else basis.prolongation(P))
        return cls(Kr, held, method, apply, Kff, free, time.perf_counter() - t0)

    def _residual(self, X: np.ndarray, R: np.ndarray) -> float:
        """``|K_ff X - R| / |R|`` (Frobenius norms); from the lower triangle L of the permuted matrix when that is what
        was factored: ``A x = L x + Lᵀ x - diag(A) x`` in the permuted order."""
        if self._Kff is not None:
            r = self._Kff @ X - R
        else:
            L, p = self._lower, self._perm
            Xp = X[p]
            d = L.diagonal()
            r = L @ Xp + L.T @ Xp - (d[:, None] if Xp.ndim == 2 else d) * Xp - R[p]
        return float(np.linalg.norm(r) / max(np.linalg.norm(R), 1e-300))

    @reproducible
    def solve_many(self, F: np.ndarray) -> tuple[np.ndarray, SolveInfo]:
        """``U[n, k]`` with ``K U = F`` for the ``k`` load vectors ``F[n, k]`` (zero at the held DOFs): one block
        solve on the factorisation (BLAS-3: a fraction of ``k`` single solves), or one CG run per column on the
        shared multigrid hierarchy. The studies of many samples that change only loads call this once."""
        F = np.asarray(F, dtype=float)
        if F.ndim != 2 or F.shape[0] != self.K.shape[0]:
            raise InputError(f"F: expected [{self.K.shape[0]}, k] load vectors, got shape {F.shape}")
        t0 = time.perf_counter()
        R = F[self._free]
        iters = 0
        if self.method == "direct":
            X = self._apply(R)
        else:
            X = np.empty_like(R)
            with one_blas_thread():  # CG's vector operations: a second BLAS thread only waits
                for j in range(R.shape[1]):
                    X[:, j], it = pcg(self._Kff, R[:, j], self._apply, self.rtol)
                    iters = max(iters, it)
        U = np.zeros_like(F)
        U[self._free] = X
        res = self._residual(X, R)
        return U, SolveInfo(f"{self.method} (shared, block of {F.shape[1]})", int(self._free.size), iters, res,
                            time.perf_counter() - t0)

    @reproducible
    def solve(self, f: np.ndarray, held: np.ndarray | None = None) -> tuple[np.ndarray, SolveInfo]:
        """``u`` with ``K u = f`` at the free DOFs, zero at the held ones, and how it was solved."""
        if held is not None and not np.array_equal(np.unique(held), self.held):
            raise ModelError("this load case holds other DOFs than the shared factorisation: the supports differ")
        t0 = time.perf_counter()
        rhs = f[self._free]
        if self.method == "direct":
            x, iters = self._apply(rhs), 0
        else:
            with one_blas_thread():
                x, iters = pcg(self._Kff, rhs, self._apply, self.rtol)
        u = np.zeros(self.K.shape[0])
        u[self._free] = x
        res = self._residual(x, rhs)
        return u, SolveInfo(f"{self.method} (shared)", int(self._free.size), iters, res, time.perf_counter() - t0)


def _stiffness(model: Any) -> sp.bsr_matrix:
    """The stiffness of a SolidModel as its own solve assembles it (``SolidModel._stiffness``: straight elements a few
    node pairs at a time, curved ones a chunk of elements at a time), of a PlaneModel by
    :func:`mechverify.fea.modal.stiffness_matrix`."""
    from mechverify.fea.solid import SolidModel

    if isinstance(model, SolidModel):
        from mechverify.fea import assembly as asm

        lam, mu = asm.lame(model.material.E.m_as("Pa"), model.material.nu.m_as(""))
        b = model.mesh.basis
        return model._stiffness(asm.block_pattern(b.element_dofs, b.N), lam, mu)[0]
    from mechverify.fea.modal import stiffness_matrix

    return stiffness_matrix(model)


def solve_cases(model: Any, load_cases: Sequence[Sequence[Any]], method: str = "auto", **kw: Any) -> list[Any]:
    """``FieldResults`` of ``model`` (a SolidModel) under each tuple of loads in ``load_cases``, all solved on one
    factorisation of the stiffness (:class:`SharedSolve`); the supports, mesh and material are the model's."""
    if not load_cases:
        raise InputError("load_cases: give at least one tuple of loads")
    shared = SharedSolve.of(model, method, cases=len(load_cases))
    return [replace(model, loads=tuple(loads)).solve(factorization=shared, **kw) for loads in load_cases]


# ----------------------------------------------------------------------------------------------- memory
def available_memory() -> float:
    """Memory available to a new computation [bytes] (``MemAvailable`` of /proc/meminfo, else physical memory)."""
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemAvailable:"):
                return float(line.split()[1]) * 1024.0
    except OSError:
        pass
    import os

    return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def estimate_dofs(volume: float, mesh_size: float, area: float | None = None) -> int:
    """Estimated P2 unknowns of a tetrahedral mesh of ``volume`` [m³] at element size ``mesh_size`` [m]; with the
    surface ``area`` [m²] by :data:`DOFS_VOLUME_TERM` V/h³ + :data:`DOFS_SURFACE_TERM` A/h² (at least
    :data:`DOFS_THIN_TERM` A/h², thin parts), else :data:`DOFS_PER_VOLUME` V/h³."""
    if area is None:
        return int(DOFS_PER_VOLUME * volume / mesh_size**3)
    return int(max(DOFS_VOLUME_TERM * volume / mesh_size**3 + DOFS_SURFACE_TERM * area / mesh_size**2,
                   DOFS_THIN_TERM * area / mesh_size**2))


def analysis_bytes(unknowns: int, analyses: Sequence[str] = ("static",), n_modes: int = 10) -> tuple[float, str]:
    """The peak memory [bytes] of the most demanding of ``analyses`` on ``unknowns`` and its name: ``"static"``
    (:data:`BYTES_PER_DOF` per unknown), ``"modal"`` (the eigensolver ``method="auto"`` falls back to when a factor does
    not fit, LOBPCG: :func:`mechverify.fea.modal.memory_estimate`, measured 4.6 kB per DOF at 203k) and
    ``"buckling"`` (a factorisation: CHOLMOD when installed, else SuperLU; its factor grows as n^(1/3) per unknown,
    13 kB per DOF at 203k)."""
    from mechverify.fea.factor import cholmod_available
    from mechverify.fea.modal import memory_estimate

    needs = {"static": unknowns * BYTES_PER_DOF}
    for a in analyses:
        if a == "modal":
            needs[a] = memory_estimate(unknowns, 3, n_modes, "lobpcg")
        elif a == "buckling":
            needs[a] = memory_estimate(unknowns, 3, n_modes, "cholmod" if cholmod_available() else "superlu")
        elif a != "static":
            raise InputError(f"analyses: 'static', 'modal' or 'buckling', got {a!r}")
    worst = max(needs, key=needs.__getitem__)
    return needs[worst], worst


def _need(n: int, analyses: Sequence[str], n_modes: int, refine: float | None) -> tuple[float, str]:
    """:func:`analysis_bytes` of ``n`` unknowns, plus, with a two-mesh check refining by ``refine``, the finer mesh's
    static solve (``refine``³ times the unknowns) while the first mesh's solve is kept."""
    need, worst = analysis_bytes(n, analyses, n_modes)
    if refine:
        two = (1 + refine**3) * n * BYTES_PER_DOF
        if two > need:
            return two, f"static, with the convergence check's mesh {refine:g}x finer"
    return need, worst


def _refuse(n: int, mesh_size: float, what: str, memory: float | None, analyses: Sequence[str], n_modes: int,
            refine: float | None, dofs_at: Callable[[float], float], measured: bool) -> int:
    avail = (available_memory() if memory is None else memory) * MEMORY_SHARE
    need, worst = _need(n, analyses, n_modes, refine)
    if need <= avail:
        return n
    lo, hi = 0, max(n, 1)  # the most unknowns that fit (the need grows with n)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if _need(mid, analyses, n_modes, refine)[0] <= avail else (lo, mid)
    n_max = max(lo, 1)
    h_lo, h_hi = mesh_size, mesh_size * 1e3  # the smallest element size whose unknowns fit (bisection in log h)
    for _ in range(60):
        h_mid = (h_lo * h_hi) ** 0.5
        h_lo, h_hi = (h_lo, h_mid) if dofs_at(h_mid) <= n_max else (h_mid, h_hi)
    has = "has" if measured else "would have about"
    raise ModelError(f"{what}: a mesh of {mesh_size * 1e3:.4g} mm elements {has} {n:,} unknowns and "
                     f"need{'s' if measured else ''} about {need / 1e9:.3g} GB ({worst} analysis), more than the "
                     f"{avail / 1e9:.3g} GB available; the largest mesh that fits has about {int(n_max):,} unknowns "
                     f"(mesh_size >= {h_hi * 1e3:.3g} mm)")


def require_memory(volume: float, mesh_size: float, what: str, memory: float | None = None,
                   analyses: Sequence[str] = ("static",), n_modes: int = 10, area: float | None = None,
                   refine: float | None = None) -> int:
    """The estimated unknowns (:func:`estimate_dofs`, with the surface ``area`` when known); a :class:`ModelError`
    with the estimate and the smallest element size that fits when the most demanding of ``analyses``
    (:func:`analysis_bytes`: ``"static"``, ``"modal"``, ``"buckling"`` with ``n_modes``) would need more than
    :data:`MEMORY_SHARE` of the available memory. ``refine``: a two-mesh convergence check will also solve a mesh
    ``refine`` times finer while this one's solve is kept (review 3 finding 10: not counted before)."""
    n = estimate_dofs(volume, mesh_size, area)
    return _refuse(n, mesh_size, what, memory, analyses, n_modes, refine,
                   lambda h: estimate_dofs(volume, h, area), measured=False)


def require_unknowns(unknowns: int, mesh_size: float, what: str, memory: float | None = None,
                     analyses: Sequence[str] = ("static",), n_modes: int = 10, refine: float | None = None) -> int:
    """:func:`require_memory` with the unknowns of the mesh made (after meshing, before assembling): the estimate
    before meshing can be low where gmsh refines (holes at half the size, curved faces: the solid bracket has 1.68x
    the 40 V/h³ of the volume). The element size offered assumes the unknowns scale as h⁻³."""
    return _refuse(int(unknowns), mesh_size, what, memory, analyses, n_modes, refine,
                   lambda h: unknowns * (mesh_size / h) ** 3, measured=True)


def step_volume(path: str | Path) -> float:
    """Total volume [m³] of the solids in a STEP file, read by gmsh/OpenCASCADE without meshing; a
    :class:`ModelError` naming the file and gmsh's reason when gmsh cannot read it."""
    return step_size(path)[0]


def step_size(path: str | Path) -> tuple[float, float]:
    """Total volume [m³] and surface area [m²] of the solids in a STEP file (:func:`step_volume`)."""
    from mechverify.fea.mesh import step_model

    with step_model(path) as (gmsh, vols):
        faces = {t for v in vols for _, t in gmsh.model.getBoundary([(3, v)], oriented=False)}
        return (float(sum(gmsh.model.occ.getMass(3, t) for t in vols)),
                float(sum(gmsh.model.occ.getMass(2, t) for t in faces)))


# ----------------------------------------------------------------------------------------------- convergence
@dataclass(frozen=True)
class ConvergenceCheck:
    """The peak of a result on a mesh (``coarse``, element size ``h``) and on a refined one (``fine``, ``h/r``)."""

    coarse: float
    fine: float
    ratio: float  # refinement ratio r = h_coarse / h_fine
    order: float  # assumed convergence order p of the peak
    tolerance: float

    @property
    def change(self) -> float:
        """Relative change of the peak between the meshes, |fine - coarse| / |fine|."""
        return abs(self.fine - self.coarse) / max(abs(self.fine), 1e-300)

    @property
    def estimated_error(self) -> float:
        """Richardson estimate of the fine mesh's relative error: change / (r^p - 1) (Roache ch. 5)."""
        return self.change / (self.ratio**self.order - 1)

    @property
    def refinement_needed(self) -> float:
        """Factor by which the element size must shrink so that the change between successive meshes falls
        under the tolerance, the change scaling as h^p (1 when it already is)."""
        return float(max(1.0, (self.change / self.tolerance) ** (1 / self.order)))

    @property
    def warning(self) -> str | None:
        if self.change <= self.tolerance:
            return None
        return (f"mesh convergence: the peak changed by {100 * self.change:.3g} % between element sizes h and "
                f"h/{self.ratio:.3g} (tolerance {100 * self.tolerance:.3g} %); estimated error of the finer mesh "
                f"{100 * self.estimated_error:.3g} %: refine the elements at the peak by about "
                f"{self.refinement_needed:.2g}x more")


def two_mesh_check(coarse: float, fine: float, ratio: float = 2.0, order: float = 2.0,
                   tolerance: float = 0.05) -> ConvergenceCheck:
    """Compare a peak result on two meshes (element sizes h and h/``ratio``); ``order`` 2 suits P2 stresses."""
    if not ratio > 1:
        raise InputError(f"ratio: the refined mesh must be finer (ratio > 1), got {ratio}")
    return ConvergenceCheck(float(coarse), float(fine), float(ratio), float(order), float(tolerance))


#: The two-mesh check's second mesh has elements this many times smaller (about 3.4x the unknowns of P2 tetrahedra).
REFINE = 1.5


def two_mesh_stress(result: Any, fine_model: Any, mesh_size: Any, supports: Sequence[Any] | None = None,
                    tolerance: float = 0.05, refine: float = REFINE) -> tuple[Any, list[str], list[str]]:
    """The two-mesh check of a solid's peak von Mises stress: ``result`` is the design mesh's solution (element
    size ``mesh_size``), ``fine_model`` the same model on a mesh ``refine`` times finer, solved here, so the change
    measures the error of the design's own mesh. Returns the governing result (the larger peak: the coarse mesh's
    is not conservative), the notes (both peaks, the change, the Richardson estimate, which peak governs) and the
    warnings (:func:`convergence_warning`; ``supports`` are the design file's support tables, to name a peak at a
    support)."""
    with one_blas_thread():
        fine_res = fine_model.solve()
    fine = fine_res.max_von_mises.value.m_as("MPa")
    chk = two_mesh_check(result.max_von_mises.value.m_as("MPa"), fine, refine, 2.0, float(tolerance))
    governing = fine_res if fine > chk.coarse else result
    notes = [f"two-mesh check: peak von Mises {chk.coarse:.4g} MPa at mesh_size, {fine:.4g} MPa at "
             f"mesh_size / {refine:g} (change {100 * chk.change:.3g} %, Richardson error estimate of the "
             f"finer mesh {100 * chk.estimated_error:.3g} %); the demand is the "
             + ("finer mesh's peak" if governing is fine_res else "design mesh's peak (the larger)")]
    near = fine_model.support_near(int(fine_res.max_von_mises.node))
    w = convergence_warning(chk, mesh_size, supports, near)
    return governing, notes, [w] if w else []


def support_peak_warning(model: Any, node: int, supports: Sequence[Any] | None) -> str | None:
    """A WARN when the peak von Mises stress at ``node`` of ``model`` (a SolidModel) is at or next to a support that
    holds all three directions (a clamp: :class:`~mechverify.fea.loads.Fixed`), whose edge is singular - the peak
    grows as the mesh is refined and does not converge (review 4 finding 20: without convergence_check the result
    said nothing); None otherwise (a symmetry plane or a roller holding some directions, a pin). ``supports`` are the
    design file's support tables, to name the support as written."""
    from mechverify.fea.loads import Fixed

    near = model.support_near(int(node))
    if near is None or not isinstance(model.supports[near], Fixed):
        return None
    t = supports[near] if supports and near < len(supports) else {}
    what = next((f"{k} = {t[k]!r}" for k in ("named", "face", "plane", "box") if isinstance(t, Mapping) and k in t), "")
    return (f"the peak von Mises stress is at support supports[{near}] ({what}), held in x, y and z: the stress at the "
            "edge of a rigid support is singular, it grows as the mesh is refined and does not converge, so this peak "
            "depends on mesh_size; judge the stress away from the support (convergence_check = true shows the "
            "change), or model the support as it is (a bolt's clamp area, a pin, a restraint of fewer directions)")


def convergence_warning(chk: ConvergenceCheck, mesh_size: Any, supports: Sequence[Any] | None,
                        near: int | None) -> str | None:
    """The two-mesh check's warning (None within the tolerance): the element size needed, as a ``mesh_size``
    (the change between h and h/r scales as h^p, so h / refinement_needed brings it under the tolerance), or,
    when the peak is at or next to support ``near`` (index into the design file's ``supports``), that the peak
    is the singularity of a rigid support, which refinement does not converge."""
    if chk.change <= chk.tolerance:
        return None
    head = (f"mesh convergence: the peak von Mises stress changed by {100 * chk.change:.3g} % between mesh_size "
            f"and mesh_size / {chk.ratio:.3g} (tolerance {100 * chk.tolerance:.3g} %)")
    if near is not None:
        t = supports[near] if supports and near < len(supports) else {}
        what = next((f"{k} = {t[k]!r}" for k in ("named", "face", "plane", "box") if isinstance(t, Mapping) and k in t),
                    "")
        return (f"{head}; the peak is at support supports[{near}] ({what}): the stress at the edge of a rigid support "
                "is singular, it grows as the mesh is refined and will not converge, so a smaller mesh_size does not "
                "help; judge the stress away from the support, or model the support as it is (a bolt's clamp "
                "area or a restraint of fewer directions)")
    h = mesh_size.to("mm")
    return (f"{head}; estimated error of the finer mesh {100 * chk.estimated_error:.3g} %: a mesh_size of about "
            f"{(h / chk.refinement_needed).m:.3g} mm (now {h.m:.3g} mm) is needed to bring the change under the "
            "tolerance")
