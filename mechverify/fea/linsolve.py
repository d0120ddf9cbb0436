"""Solving K u = f with supports: a rigid-body check first, then the right solver for the size.

- :func:`rigid_modes` - the rigid-body motions (translations, rotations) of a node set.
- :func:`check_supported` - which rigid motions the supports leave free; a :class:`ModelError`
  naming the free direction instead of a singular matrix.
- :func:`solve` - eliminates the held DOFs, then a sparse direct solve (CHOLMOD when installed, else SuperLU;
  :mod:`mechverify.fea.factor`) for small systems, or for large 3D systems whichever a cost model predicts cheaper
  (:func:`choose_solver`): the factorisation (its flops and memory from CHOLMOD's symbolic analysis) or conjugate
  gradients preconditioned by multigrid: Gauss-Seidel on the quadratic elements, then the linear-element
  system by smoothed-aggregation algebraic multigrid (pyamg, rigid-body modes as near-null space). CG that then
  converges slowly gives way to the factorisation when its measured rate predicts more time than factoring.

Why CG was slow on some thin parts: on the benchmark's 6 mm plate with a hole at 66k DOF CG needed 203
iterations where the 37k and 181k meshes of the same plate needed 43 and 30. That mesh held a near-degenerate
sliver tetrahedron (radius ratio 2.3e-4; the others' worst are 0.17 and 0.25), and the coarse space is not
the cause: an exact solve of the P1 coarse level still took 172 iterations, and a coarse space of smoothed
rigid-body modes per vertex aggregate (which represents bending) solved exactly still 88. gmsh meshes are now read
with their slivers repaired (:func:`mechverify.fea.meshquality.remove_slivers`: 42 iterations on that mesh); a mesh
from elsewhere may still have one (the solve WARNs), and the factorisation does not care, hence the measured switch.

References
----------
1. Vaněk, Mandel & Brezina, "Algebraic multigrid by smoothed aggregation for second and fourth
   order elliptic problems", Computing 56 (1996) 179-196.
2. Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., SIAM 2003, Alg. 9.1 (PCG).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp

from mechverify.errors import ModelError

#: CG's convergence is judged from this iteration on (see :func:`pcg`).
PREDICT_AFTER = 20
#: CG's cost per iteration and non-zero of the P2 matrix (one p-multigrid V-cycle: two Gauss-Seidel sweeps, three
#: products with A, the coarse cycle; one BLAS thread): 6.3 ns measured (CPU time) on the 6 mm plate with a hole
#: at 37k and 66k DOF. Used only before CG has run; then its measured time per iteration counts.
CG_SECONDS_PER_NNZ = 6.3e-9
#: The multigrid setup costs about this many iterations (0.15-0.2 s at 37k-66k DOF).
CG_SETUP_ITERATIONS = 7
#: Iterations CG is expected to need before it has run: compact solids need 26-37 (FEA benchmark, 47k-830k DOF).
CG_EXPECTED_ITERATIONS = 30
#: "auto" considers a factorisation only up to this many unknowns, and only when the factor's predicted memory
#: stays under :data:`DIRECT_BYTES_PER_DOF` per unknown (the static solver's budget is 5 kB per DOF in all).
DIRECT_SWITCH_MAX = 300_000
DIRECT_BYTES_PER_DOF = 3000.0
#: Up to this many unknowns the factorisation is analysed before CG starts (AMD on the node graph and CHOLMOD's
#: column counts there: 0.02 s CPU at 66k DOF, under one CG iteration; METIS too when it may pay); above,
#: only when CG's measured rate predicts more than 1.5 :data:`CG_EXPECTED_ITERATIONS` (45; 30 were measured at 179k
#: DOF, 203 at 66k). The plate with a hole's factorisation beat a 30-iteration CG up to ~70k DOF and lost from
#: ~100k (predicted 0.46 s against 0.58 s at 37k, 5.0 s against 3.0 s at 179k), so a larger system is factored only
#: for a slow CG.
ANALYSE_FIRST_MAX = 100_000
#: METIS's nested dissection (postordered) factored about 20 % faster than AMD's ordering on the benchmark's plate at
#: 67k DOF and its lug at 47k, about 5 % at 37k (predicted 0.95 / 1.21 s, 1.39 / 1.95 s, 0.46 / 0.53 s), and ordering
#: the node graph costs METIS_SECONDS_PER_NNZ per non-zero of A (0.095 s at 37k, 0.19 s at 67k, 0.15 s for the lug;
#: AMD 0.02-0.035 s). METIS is tried after AMD only when a factorisation may be chosen and METIS_GAIN of AMD's
#: predicted factor time would pay for the ordering (it would not at 37k). Since the factorisation runs without
#: CHOLMOD's OpenMP threads (task thinperf), measured CPU with METIS / AMD: factor 0.20 / 0.25 s and whole solve 0.69 /
#: 0.67 s at 37k, factor 0.45 / 0.62 s and whole solve 1.39 / 1.33 s at 67k (METIS's ordering cost more than it
#: saved); with the re-fitted factor constants METIS is no longer tried at either.
METIS_GAIN = 0.17
METIS_SECONDS_PER_NNZ = 4.2e-8
#: METIS is also tried when AMD's factor would take more than this many bytes per unknown: a direct solve's peak is
#: the factor plus about 2.3 kB/DOF (the interpreter and its libraries, 84 MB, the mesh, the matrix) at 37k-67k DOF,
#: and the budget is 5 kB/DOF in all (issue 23). The plate at 67k DOF: AMD's factor 193 MB (2.9 kB/DOF), peak 339 MB
#: (5.05 kB/DOF); METIS's 160 MB, peak 302 MB (4.5 kB/DOF), the whole solve 1.39 against 1.33 s CPU (task thinperf).
#: At 37k (2.4 kB/DOF) and 46k (2.4) AMD stays: METIS cost more CPU than its 10 and 6 MB were worth there.
METIS_BYTES_PER_DOF = 2500.0


@dataclass(frozen=True)
class SolverChoice:
    """Why "auto" solved as it did: the predicted seconds and bytes of a factorisation (None: not analysed) and the
    seconds of CG at :data:`CG_EXPECTED_ITERATIONS`, the ordering analysed, the seconds spent predicting, and
    whether the factor fits the memory budget."""

    method: str
    direct_seconds: float | None
    direct_bytes: float | None
    cg_seconds: float
    ordering: str | None
    analysis_seconds: float
    fits: bool

    def describe(self) -> str:
        """One line for the solve's method: what was predicted."""
        if self.direct_seconds is None:
            return f"predicted CG {self.cg_seconds:.2g} s"
        over = "" if self.fits else ", over the memory budget"
        return (f"predicted: direct {self.direct_seconds:.2g} s, factor {self.direct_bytes / 1e6:.0f} MB "
                f"({self.ordering}{over}), CG {self.cg_seconds:.2g} s")


def cg_seconds(A: sp.spmatrix, iterations: float) -> float:
    """Predicted seconds of multigrid CG on ``A`` for ``iterations`` (setup included), before it has run."""
    return A.nnz * CG_SECONDS_PER_NNZ * (iterations + CG_SETUP_ITERATIONS)


def choose_solver(A: sp.spmatrix | None, analyse: bool = True, cases: int = 1,
                  groups: np.ndarray | None = None, graph: sp.spmatrix | None = None,
                  nnz: int | None = None) -> tuple[SolverChoice, Any]:
    """Direct or iterative for the SPD system ``A`` with ``cases`` right-hand sides, from a cost model: CHOLMOD's
    symbolic analysis predicts the factorisation's seconds and memory and the seconds per solve
    (:func:`mechverify.fea.factor.symbolic_cost` with AMD on the node graph ``groups``, then METIS when
    :data:`METIS_GAIN` of the factor time would pay for its ordering or AMD's factor is over
    :data:`METIS_BYTES_PER_DOF`; METIS's factor took 0.6-0.9 of AMD's flops on
    the benchmark's plates and lug, its ordering 5-10x AMD's),
    CG is predicted at :data:`CG_EXPECTED_ITERATIONS` per case on one multigrid setup. Returns the
    :class:`SolverChoice` ("direct" or "amg"; its seconds are the totals over the cases) and the
    :class:`~mechverify.fea.factor.SymbolicCost` to factor with (None when CHOLMOD is absent, the system is above
    :data:`DIRECT_SWITCH_MAX` or its factor would take more than :data:`DIRECT_BYTES_PER_DOF` per unknown).
    ``analyse=False`` predicts CG only (the analysis is left for later). ``graph`` and ``nnz``: the node graph of
    ``A``, its ``groups`` and ``A.nnz`` instead of ``A`` (:func:`mechverify.fea.assembly.node_graph`: the choice is made
    before ``A`` is extracted, so a factorisation never needs the full ``A``)."""
    from mechverify.fea.factor import symbolic_cost

    n = A.shape[0] if graph is None else int(groups[-1])
    nnz = A.nnz if nnz is None else int(nnz)
    t_cg = nnz * CG_SECONDS_PER_NNZ * (CG_EXPECTED_ITERATIONS * cases + CG_SETUP_ITERATIONS)

    def direct(c: Any) -> float:
        return c.factor_seconds + cases * c.solve_seconds

    cost, spent = None, 0.0
    if analyse and n <= DIRECT_SWITCH_MAX:
        cost = symbolic_cost(A, "amd", groups, graph=graph)
        spent = 0.0 if cost is None else cost.seconds
        if cost is not None and direct(cost) <= 2 * t_cg and (
                METIS_GAIN * cost.factor_seconds > METIS_SECONDS_PER_NNZ * nnz
                or cost.factor_bytes > METIS_BYTES_PER_DOF * n):
            nested = symbolic_cost(A, "metis", groups, graph=graph)
            if nested is not None:
                spent += nested.seconds
                cost = nested if nested.factor_seconds < cost.factor_seconds else cost
    if cost is None:
        return SolverChoice("amg", None, None, t_cg, None, spent, False), None
    fits = cost.factor_bytes <= DIRECT_BYTES_PER_DOF * n
    method = "direct" if fits and direct(cost) <= t_cg else "amg"
    choice = SolverChoice(method, direct(cost), cost.factor_bytes, t_cg, cost.ordering, spent, fits)
    return choice, cost if fits else None


#: Above this many unknowns a 3D solid is solved by AMG-preconditioned CG rather than SuperLU.
ITERATIVE_THRESHOLD_3D = 12_000


def rigid_modes(points: np.ndarray) -> tuple[np.ndarray, list[str]]:
    """Rigid-body motions ``[n*dim, k]`` of nodes ``points[dim, n]`` (node-interleaved DOFs) and their names.

    3D: translations x, y, z and rotations about x, y, z through the centroid (k = 6); 2D: x, y and
    the in-plane rotation (k = 3). Rotations are scaled by the model size so all columns are O(1).
    """
    dim, n = points.shape
    c = points.mean(axis=1, keepdims=True)
    scale = max(float(np.max(np.ptp(points, axis=1))), 1e-300)
    X = (points - c) / scale
    if dim == 2:
        B = np.zeros((n, 2, 3))
        B[:, 0, 0] = B[:, 1, 1] = 1.0
        B[:, 0, 2], B[:, 1, 2] = -X[1], X[0]
        return B.reshape(-1, 3), ["translation along x", "translation along y", "rotation about z"]
    B = np.zeros((n, 3, 6))
    B[:, 0, 0] = B[:, 1, 1] = B[:, 2, 2] = 1.0
    B[:, 1, 3], B[:, 2, 3] = -X[2], X[1]  # about x
    B[:, 0, 4], B[:, 2, 4] = X[2], -X[0]  # about y
    B[:, 0, 5], B[:, 1, 5] = -X[1], X[0]  # about z
    names = ["translation along x", "translation along y", "translation along z",
             "rotation about x", "rotation about y", "rotation about z"]
    return B.reshape(-1, 6), names


def describe_mode(v: np.ndarray, names: list[str], centroid: np.ndarray, scale: float) -> str:
    """Words for a rigid motion given by coefficients ``v`` of :func:`rigid_modes`."""
    v = v / np.max(np.abs(v))
    dim = 2 if len(v) == 3 else 3
    t, w = (v[:2], v[2:]) if dim == 2 else (v[:3], v[3:])
    if np.linalg.norm(w) < 1e-6:
        parts = [f"{names[i]}" for i in range(dim) if abs(t[i]) > 1e-6]
        return "translation along " + " + ".join(p.split()[-1] for p in parts)
    from mechverify.fea.motions import point_mm, rotation_words

    if dim == 2:
        # u = t + w ez x (x - c) / scale is zero at x = c + scale * (-t_y, t_x) / w
        pole = centroid + scale * np.array([-t[1], t[0]]) / w[0]
        return f"rotation about z through {point_mm(pole, scale)} mm"  # rounded to the model's size (fea.motions)
    axis = w / np.linalg.norm(w)
    along = float(np.dot(t, axis))
    # the axis of a rigid motion passes through c + scale * (w x t)/|w|^2
    pt = centroid + scale * np.cross(w, t) / np.dot(w, w)
    words = "rotation about " + rotation_words(axis, pt, scale)
    if abs(along) > 1e-6:
        words += " (with a slide along it)"
    return words


def plain_basis(free: np.ndarray, tol: float = 1e-6) -> np.ndarray:
    """An orthonormal basis ``[m, k]`` of the span of ``free`` (orthonormal columns) that uses the coordinate
    motions (translation along x, ..., rotation about z through the centroid) lying in it, the rest completed
    orthogonally: eigh mixes them into rotations about far-away axes (review finding 9: a bar held in x only
    was 'free to rotate about an axis parallel to x through (50, -1.733e+04, 8166) mm', which is mostly a
    translation)."""
    m, k = free.shape
    P = free @ free.T
    picked = [np.eye(m)[:, i] for i in range(m) if np.linalg.norm(P[:, i]) > 1 - tol]
    picked = picked[:k]
    if len(picked) == k:
        return np.column_stack(picked) if picked else free
    rest = free - (np.column_stack(picked) @ (np.column_stack(picked).T @ free) if picked else 0.0)
    u, sv, _ = np.linalg.svd(rest, full_matrices=False)
    return np.column_stack([*picked, *u[:, :k - len(picked)].T])


def check_supported(points: np.ndarray, held: np.ndarray, spring_dofs: np.ndarray | None = None,
                    axes: np.ndarray | None = None, hint: str = "") -> None:
    """Raise :class:`ModelError` naming every rigid motion the held DOFs do not prevent.

    ``held`` are node-interleaved DOF indices held at prescribed values; a rigid motion is free
    when it moves none of them (the restricted mode matrix has a null vector). ``axes[n, 3, 3]``: each node's
    DOF axes when they are not x, y, z (pin supports, :mod:`mechverify.fea.pins`); ``hint`` ends the message.
    """
    B, names = rigid_modes(points)
    if axes is not None:
        n = points.shape[1]
        B = np.einsum("nji,njc->nic", axes, B.reshape(n, 3, -1)).reshape(B.shape)
    dofs = held if spring_dofs is None else np.union1d(held, spring_dofs)
    Bc = B[np.asarray(dofs, dtype=np.int64)]
    G = Bc.T @ Bc
    w, V = np.linalg.eigh(G)
    tol = 1e-10 * max(float(np.trace(B.T @ B)) / B.shape[1], 1.0)
    free = V[:, w <= tol]
    if free.shape[1]:
        c = points.mean(axis=1)
        scale = max(float(np.max(np.ptp(points, axis=1))), 1e-300)
        # present the free space in the plainest basis: snap to coordinate modes where possible
        free = plain_basis(free)
        motions = [describe_mode(free[:, k], names, c, scale) for k in range(free.shape[1])]
        raise ModelError("the model is not fully supported: the supports leave free "
                         + "; ".join(motions) + f". Add a support that prevents this motion{hint}.")


@dataclass(frozen=True)
class SolveInfo:
    """How a system was solved (for reports and the benchmark)."""

    method: str
    unknowns: int
    iterations: int
    residual: float
    seconds: float
    worst_quality: float | None = None  # the mesh's worst element (radius ratio, fea.meshquality), when known


def solve(K: sp.spmatrix, f: np.ndarray, held: np.ndarray, points: np.ndarray, prescribed: np.ndarray | None = None,
          method: str = "auto", rtol: float = 1e-10, progress: Callable[[str], None] | None = None,
          prolongation: sp.csr_matrix | None = None) -> tuple[np.ndarray, SolveInfo]:
    """Solve ``K u = f`` with ``u[held] = prescribed`` (zero by default) after the rigid-body check.

    ``points[dim, n]`` are the node coordinates (node-interleaved DOFs ``dim*node + i``). ``method``:
    ``"direct"`` (CHOLMOD when installed, else SuperLU), ``"amg"`` (multigrid-CG; needs ``prolongation``,
    :func:`p1_prolongation`) or ``"auto"``: a direct solve up to :data:`ITERATIVE_THRESHOLD_3D` unknowns (and for
    2D); above, for 3D, the cheaper of the two by the cost model of :func:`choose_solver` (with CHOLMOD installed;
    without it, CG). A CG that then converges slowly (a thin part, a sliver element) leaves for the factorisation
    as soon as its measured rate and time per iteration predict more seconds than the factorisation's.
    """
    t0 = time.perf_counter()
    dim = points.shape[0]
    n = K.shape[0]
    held = np.unique(np.asarray(held, dtype=np.int64))
    check_supported(points, held)
    u = np.zeros(n)
    if prescribed is not None:
        u[held] = prescribed
    free_mask = np.ones(n, dtype=bool)
    free_mask[held] = False
    free = np.flatnonzero(free_mask)
    # K's free part read straight from K (which stays with the caller for the reactions), no CSR copy of K: a full
    # copy kept beside Kff cost 1.5 kB/DOF of peak memory, slicing one 0.9 kB/DOF more (issue 23)
    from mechverify.fea.assembly import free_submatrix

    rhs = f[free] - ((K @ u)[free] if prescribed is not None and np.any(u[held]) else 0.0)
    from mechverify.fea.assembly import free_lower_permuted, node_graph
    from mechverify.fea.factor import cholmod_available, factorize, factorize_lower
    from mechverify.fea.reproducible import one_blas_thread

    cost, label, analysis, Kff = None, "", None, None
    if method == "auto":
        big = dim == 3 and free.size > ITERATIVE_THRESHOLD_3D and prolongation is not None
        method = "amg" if big else "direct"
        if big and cholmod_available():
            # the choice on the node graph, before any scalar matrix: a factorisation then reads the lower triangle
            # of the permuted K[free][:, free] straight from K (free_lower_permuted), never the full one (task thinperf)
            bsr = sp.issparse(K) and K.format == "bsr" and K.blocksize == (dim, dim)
            if bsr:
                graph, groups, nnz = node_graph(K, free_mask)
                choice, cost = choose_solver(None, analyse=free.size <= ANALYSE_FIRST_MAX, groups=groups,
                                             graph=graph, nnz=nnz)
            else:
                Kff = free_submatrix(K, free_mask)
                groups = np.r_[0, np.flatnonzero(np.diff(free // dim)) + 1, free.size]  # each node's free DOFs
                graph, nnz = None, Kff.nnz
                choice, cost = choose_solver(Kff, analyse=free.size <= ANALYSE_FIRST_MAX, groups=groups)
            method, label = choice.method, choice.describe()
            if choice.direct_seconds is None and free.size <= DIRECT_SWITCH_MAX:
                def analysis() -> float | None:  # run when CG turns out slower than expected
                    nonlocal cost, label
                    later, cost = choose_solver(Kff, groups=groups, graph=graph, nnz=nnz)
                    label = later.describe() + " (analysed when CG was slow)"
                    return None if cost is None else cost.factor_seconds
            if method == "direct" and cost is not None and bsr:
                graph = None  # not needed any more (1.7 MB at 46k DOF)
                lower = free_lower_permuted(K, free_mask, cost.perm)
                del K  # a caller that handed K over (SolidModel.solve keeps only its held rows) frees it here
                if progress:
                    progress(f"solving {free.size} unknowns (direct)")
                x = factorize_lower(lower, cost).solve(rhs)
                if not np.all(np.isfinite(x)):
                    raise ModelError("the solve produced non-finite displacements; the model has a mechanism")
                xp = x[cost.perm]  # the residual with the lower triangle: A x = L x + Lᵀ x - diag(A) x
                r = lower @ xp + lower.T @ xp - lower.diagonal() * xp - rhs[cost.perm]
                u[free] = x
                return u, SolveInfo(f"direct (cholmod; {label})", int(free.size), 0,
                                    float(np.linalg.norm(r) / max(np.linalg.norm(rhs), 1e-300)),
                                    time.perf_counter() - t0)
    if Kff is None:
        Kff = free_submatrix(K, free_mask)
    del K  # a caller that handed K over (SolidModel.solve keeps only its held rows) frees it before the solve
    if progress:
        progress(f"solving {free.size} unknowns ({method})")
    iters = 0
    if method == "amg":
        if prolongation is None:
            raise ValueError("method 'amg' needs the P1 -> P2 prolongation")
        try:
            with one_blas_thread():  # vector operations: a second, busy-waiting BLAS thread only slows CG
                x, iters = pcg(Kff, rhs, pmg_preconditioner(Kff, points, free, dim, prolongation), rtol,
                               direct_seconds=analysis if analysis is not None else
                               None if cost is None else cost.factor_seconds)
            if label:
                method = f"amg ({label})"
        except SlowConvergence as slow:
            if progress:
                progress(f"{slow}: direct solve instead")
            method = f"direct (cholmod, {cost.ordering}; CG left after {slow.iterations} iterations)"
            iters = slow.iterations
            x = factorize(Kff, "cholmod", symbolic=cost).solve(rhs)
    elif method == "direct":
        fac = factorize(Kff, "auto", symbolic=cost)
        method = "direct" if fac.method == "superlu" else f"direct (cholmod; {label})" if label \
            else "direct (cholmod)"
        x = fac.solve(rhs)
    else:
        raise ValueError(f"unknown method {method!r}")
    if not np.all(np.isfinite(x)):
        raise ModelError("the solve produced non-finite displacements; the model has a mechanism")
    res = float(np.linalg.norm(Kff @ x - rhs) / max(np.linalg.norm(rhs), 1e-300))
    u[free] = x
    return u, SolveInfo(method, int(free.size), iters, res, time.perf_counter() - t0)


def p1_prolongation(nverts: int, edges: np.ndarray, dim: int) -> sp.csr_matrix:
    """Interpolation of linear (vertex) fields into the P2 space: ``[dim*N, dim*nverts]``.

    A vertex keeps its value; a mid-edge node takes the mean of its edge's two vertices. Since
    P1 is a subspace of P2 on the same mesh, ``Pᵀ K P`` is exactly the linear-element stiffness.
    """
    ne = edges.shape[1]
    rows = np.r_[np.arange(nverts), nverts + np.arange(ne), nverts + np.arange(ne)]
    cols = np.r_[np.arange(nverts), edges[0], edges[1]]
    vals = np.r_[np.ones(nverts), np.full(2 * ne, 0.5)]
    Ps = sp.csr_matrix((vals, (rows, cols)), shape=(nverts + ne, nverts))
    return sp.kron(Ps, sp.identity(dim, format="csr"), format="csr")


def _pmg_cg(A: sp.csr_matrix, b: np.ndarray, points: np.ndarray, free: np.ndarray, dim: int, rtol: float,
            prolongation: sp.csr_matrix) -> tuple[np.ndarray, int]:
    """CG preconditioned by a two-stage multigrid: symmetric Gauss-Seidel on the quadratic system,
    coarse correction on the linear-element system ``Pᵀ A P`` by one smoothed-aggregation AMG V-cycle.

    Smoothed aggregation on the P2 matrix itself coarsens far too fast (each node couples to ~60
    others), so the P2 -> P1 step comes first (p-multigrid, ref. 1 and Saad ch. 13).
    """
    return pcg(A, b, pmg_preconditioner(A, points, free, dim, prolongation), rtol)


def pmg_preconditioner(A: sp.csr_matrix, points: np.ndarray, free: np.ndarray, dim: int,
                       prolongation: sp.csr_matrix) -> Callable[[np.ndarray], np.ndarray]:
    """The p-multigrid V-cycle of :func:`_pmg_cg` as a function ``r -> z`` (built once, reusable for many
    right-hand sides)."""
    import pyamg
    from pyamg.relaxation.relaxation import gauss_seidel

    n_dofs = points.shape[1] * dim
    held_mask = np.ones(n_dofs, dtype=bool)
    held_mask[free] = False
    ncoarse = prolongation.shape[1]
    coarse_free = np.flatnonzero(~held_mask[:ncoarse])  # vertex DOFs come first in the numbering
    P = prolongation[free][:, coarse_free].tocsr()
    PT = P.T.tocsr()
    A1 = (PT @ A @ P).tocsr()
    B, _ = rigid_modes(points[:, : ncoarse // dim])
    ml = pyamg.smoothed_aggregation_solver(
        A1, B=B[coarse_free], max_coarse=1500, coarse_solver="splu",
        presmoother=("gauss_seidel", {"sweep": "symmetric"}), postsmoother=("gauss_seidel", {"sweep": "symmetric"}))
    coarse = ml.aspreconditioner(cycle="V")

    def apply(r: np.ndarray) -> np.ndarray:
        x = np.zeros_like(r)
        gauss_seidel(A, x, r, iterations=1, sweep="forward")
        x += P @ coarse(PT @ (r - A @ x))
        gauss_seidel(A, x, r, iterations=1, sweep="backward")
        return x

    return apply


class SlowConvergence(ModelError):
    """CG's measured convergence rate predicts more iterations than the caller allows (``predicted``)."""

    def __init__(self, message: str, iterations: int, predicted: float):
        super().__init__(message)
        self.iterations, self.predicted = iterations, predicted


def pcg(A: sp.csr_matrix, b: np.ndarray, precondition: Callable[[np.ndarray], np.ndarray], rtol: float,
        maxiter: int = 2000, predict_limit: int | None = None,
        direct_seconds: float | Callable[[], float | None] | None = None) -> tuple[np.ndarray, int]:
    """Preconditioned conjugate gradients (ref. 2, Alg. 9.1), stopping on the true residual
    ``‖b - A x‖ ≤ rtol ‖b‖``; :class:`ModelError` when it does not get there. From iteration
    :data:`PREDICT_AFTER` on (every 10) the mean convergence factor so far predicts the iterations needed; it
    raises :class:`SlowConvergence` (the caller switches to a direct solve) when they exceed ``predict_limit``, or
    when the remaining iterations at the model's seconds per iteration (``A.nnz`` ·
    :data:`CG_SECONDS_PER_NNZ`, not the measured time: the choice, and so the result's last digits, must not
    depend on the machine's load or the executor) exceed ``direct_seconds`` (the predicted cost of a
    factorisation; a function giving it - or None, no factorisation - is called once, the first time more than
    1.5 :data:`CG_EXPECTED_ITERATIONS` are predicted)."""
    per_iteration = A.nnz * CG_SECONDS_PER_NNZ
    bnorm = float(np.linalg.norm(b))
    x = np.zeros_like(b)
    if bnorm == 0:
        return x, 0
    r = b.copy()
    z = precondition(r)
    p = z.copy()
    rz = float(r @ z)
    for k in range(1, maxiter + 1):
        Ap = A @ p
        alpha = rz / float(p @ Ap)
        x += alpha * p
        r -= alpha * Ap
        rnorm = float(np.linalg.norm(r))
        if rnorm <= rtol * bnorm:
            return x, k
        if (predict_limit is not None or direct_seconds is not None) and k >= PREDICT_AFTER and k % 10 == 0:
            rate = (rnorm / bnorm) ** (1.0 / k)
            predicted = np.log(rtol) / np.log(rate) if rate < 1 else np.inf
            if predict_limit is not None and predicted > predict_limit:
                raise SlowConvergence(f"CG would need about {predicted:.0f} iterations (convergence factor "
                                      f"{rate:.3f} over {k})", k, float(predicted))
            if callable(direct_seconds) and predicted > 1.5 * CG_EXPECTED_ITERATIONS:
                direct_seconds = direct_seconds()
            if isinstance(direct_seconds, (int, float)) and (predicted - k) * per_iteration > direct_seconds:
                raise SlowConvergence(f"CG would need about {predicted:.0f} iterations (convergence factor "
                                      f"{rate:.3f} over {k}), {(predicted - k) * per_iteration:.2g} s more against "
                                      f"{direct_seconds:.2g} s to factor", k, float(predicted))
        z = precondition(r)
        rz_new = float(r @ z)
        p *= rz_new / rz
        p += z
        rz = rz_new
    raise ModelError(f"multigrid-preconditioned CG did not converge in {maxiter} iterations (relative residual "
                     f"{np.linalg.norm(r) / bnorm:.2e}); the model may be nearly a mechanism")
