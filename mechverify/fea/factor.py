"""One sparse factorisation of a symmetric positive definite matrix, reused for any number of right-hand sides.

    >>> import numpy as np, scipy.sparse as sp
    >>> from mechverify.fea.factor import factorize
    >>> A = sp.diags([-np.ones(4), 2 * np.ones(5), -np.ones(4)], [-1, 0, 1]).tocsc()
    >>> F = factorize(A)
    >>> bool(np.allclose(A @ F.solve(np.ones(5)), 1.0))
    True

- CHOLMOD (supernodal Cholesky, METIS/AMD ordering, BLAS-3 kernels; ref. 1) through the optional
  ``scikit-sparse`` package (extra ``mechverify[direct]``; it builds against the system's SuiteSparse,
  ``scripts/system-deps.sh`` installs ``libsuitesparse-dev`` and an optimised BLAS) when it is installed,
- else SciPy's SuperLU (LU in symmetric mode, minimum-degree ordering of AᵀA; ref. 2).

On the FEA benchmark's lug (P2 tetrahedra, 46k unknowns) CHOLMOD factors in about a third of SuperLU's time
with a quarter of its fill; solves of many right-hand sides at once (``solve(B)`` with ``B[n, k]``) use
BLAS-3 and cost a fraction of k single solves. The factorisation object is what a study caches to solve
many load cases (:class:`mechverify.fea.study.SharedSolve`) and what shift-invert eigensolvers apply.

:func:`symbolic_cost` predicts a factorisation's cost before it is paid: a fill-reducing ordering (AMD, or METIS
nested dissection) and CHOLMOD's symbolic analysis (``cholmod_analyze_ordering``, through ``ctypes``) give the
non-zeros of L and the flop count in a fraction of the factorisation's time (0.2 s against 1.2 s on a 66k-DOF
plate); :meth:`SymbolicCost.factor_seconds` turns them into seconds and :func:`factorize` reuses the ordering
(``symbolic=``). :mod:`mechverify.fea.linsolve` weighs that against conjugate gradients.

CHOLMOD runs with one BLAS thread (``threadpoolctl``, when installed): triangular solves are memory-bound,
and on the shared 2-core box busy-waiting BLAS threads made a solve up to 9 times and a factorisation up to
3 times slower than one thread (measured with a load average of 10). It also runs without OpenMP threads
(:func:`one_openmp_thread`): CHOLMOD 3 (SuiteSparse 5, Debian 12) opens parallel regions of a fixed four threads in
its supernodal factorisation (``cholmod_super_numeric``, whatever ``OMP_NUM_THREADS`` says), which only copy and
clear supernodes; on the 2-core box the three extra threads spun for 0.15-0.2 s CPU per factorisation of the
37k-DOF plate (1.00 against 0.80 s CPU for the whole solve) and gave the same bits.

References
----------
1. Y. Chen, T. A. Davis, W. W. Hager, S. Rajamanickam, "Algorithm 887: CHOLMOD, supernodal sparse Cholesky
   factorization and update/downdate", ACM TOMS 35 (2008) 22.
2. X. S. Li, "An overview of SuperLU", ACM TOMS 31 (2005) 302-325.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import functools
import os
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError, install_hint
from mechverify.fea.reproducible import one_blas_thread

METHODS = ("auto", "cholmod", "superlu")
ORDERINGS = ("amd", "metis")
#: Seconds per non-zero of L and flops per second of CHOLMOD's supernodal factorisation with one BLAS thread and no
#: OpenMP threads (:func:`one_openmp_thread`), CHOLMOD's own analysis included, fitted on the benchmark's plate with a
#: hole (37k, 67k and 188k DOF, AMD and METIS orderings; CPU time, the least of three runs, load average 6-7 on the
#: 2-core box; task thinperf): t = nnz(L) * FACTOR_SECONDS_PER_NNZ + flops / FACTOR_FLOP_RATE is within 4 % of the
#: measured time on all six (0.20 s at 7.9M non-zeros, 0.61 s at 19M, 5.2 s at 104M). The constants before (5e-8 s,
#: 50e9/s, fitted while CHOLMOD's three OpenMP threads spun beside it) over-predicted by 60-130 %.
FACTOR_SECONDS_PER_NNZ = 1.77e-8
FACTOR_FLOP_RATE = 46e9
#: Bytes of the supernodal factor per non-zero of L (8-byte values, supernode padding and indices).
FACTOR_BYTES_PER_NNZ = 10.0
#: Seconds per non-zero of L of one solve (the two triangular solves; memory-bound): 0.028 s at 16.2M and 0.099 s
#: at 71.9M non-zeros measured (the plate with a hole at 66k and 179k DOF, CPU time, one BLAS thread).
SOLVE_SECONDS_PER_NNZ = 1.75e-9


_omp_state = threading.local()  # per thread: the nesting depth and the saved setting


_omp_runtime: list[Any] = []


def _openmp_runtime() -> Any:
    """The OpenMP runtime already loaded into this process (GNU, LLVM or Intel; None while there is none: nothing
    is loaded here, and it is looked for again next time)."""
    if _omp_runtime:
        return _omp_runtime[0]
    for name in ("libgomp.so.1", "libomp.so", "libomp.so.5", "libiomp5.so"):
        try:
            lib = ctypes.CDLL(name, mode=os.RTLD_NOLOAD | os.RTLD_LAZY)
            lib.omp_get_max_active_levels.restype = ctypes.c_int
            lib.omp_set_max_active_levels.argtypes = [ctypes.c_int]
        except (OSError, AttributeError):
            continue
        _omp_runtime.append(lib)
        return lib
    return None


@contextlib.contextmanager
def one_openmp_thread() -> Iterator[None]:
    """Run the block with OpenMP parallel regions inactive (``omp_set_max_active_levels(0)``: a region then runs on
    the calling thread alone, even one that asks for a number of threads), then restore the setting. The setting is
    an OpenMP ICV of the calling thread (GNU libgomp 12 and LLVM's runtime: another thread keeps its own, measured),
    so each thread sets and restores its own; nested blocks restore once, at the outermost."""
    depth = getattr(_omp_state, "depth", 0)
    if depth == 0:
        lib = _openmp_runtime()
        _omp_state.saved = None if lib is None else lib.omp_get_max_active_levels()
        if lib is not None:
            lib.omp_set_max_active_levels(0)
    _omp_state.depth = depth + 1
    try:
        yield
    finally:
        _omp_state.depth -= 1
        if _omp_state.depth == 0 and _omp_state.saved is not None:
            _openmp_runtime().omp_set_max_active_levels(_omp_state.saved)
            _omp_state.saved = None


def cholmod_available() -> bool:
    """Whether scikit-sparse's CHOLMOD can be imported."""
    try:
        import sksparse.cholmod  # noqa: F401
    except Exception:  # ImportError, or a broken build against another SuiteSparse
        return False
    return True


@dataclass(frozen=True, eq=False)
class SymbolicCost:
    """What a Cholesky factorisation of ``A`` would cost, from the symbolic analysis of one fill-reducing
    ordering: ``perm`` (``A[perm][:, perm]`` is factored), ``factor_nnz`` non-zeros of L, ``flops`` = Σ c_j²
    over the column counts c_j of L (the multiply-adds of a left-looking Cholesky), ``seconds`` spent on the
    ordering and the analysis."""

    ordering: str
    perm: np.ndarray
    factor_nnz: int
    flops: float
    seconds: float

    @property
    def factor_seconds(self) -> float:
        """Predicted CHOLMOD factorisation time [s] (:data:`FACTOR_SECONDS_PER_NNZ`, :data:`FACTOR_FLOP_RATE`)."""
        return self.factor_nnz * FACTOR_SECONDS_PER_NNZ + self.flops / FACTOR_FLOP_RATE

    @property
    def solve_seconds(self) -> float:
        """Predicted seconds of one solve with the factor (:data:`SOLVE_SECONDS_PER_NNZ`)."""
        return self.factor_nnz * SOLVE_SECONDS_PER_NNZ

    @property
    def factor_bytes(self) -> float:
        """Predicted memory of the factor [bytes]."""
        return self.factor_nnz * FACTOR_BYTES_PER_NNZ


class _CholmodSparse(ctypes.Structure):
    """``cholmod_sparse`` (cholmod_core.h; the same layout in SuiteSparse 4 to 7)."""

    _fields_ = [("nrow", ctypes.c_size_t), ("ncol", ctypes.c_size_t), ("nzmax", ctypes.c_size_t),
                ("p", ctypes.c_void_p), ("i", ctypes.c_void_p), ("nz", ctypes.c_void_p), ("x", ctypes.c_void_p),
                ("z", ctypes.c_void_p), ("stype", ctypes.c_int), ("itype", ctypes.c_int), ("xtype", ctypes.c_int),
                ("dtype", ctypes.c_int), ("sorted", ctypes.c_int), ("packed", ctypes.c_int)]


@functools.lru_cache(maxsize=1)
def _libcholmod() -> Any:
    """The CHOLMOD shared library scikit-sparse is built against (None when it cannot be loaded)."""
    if not cholmod_available():
        return None
    name = ctypes.util.find_library("cholmod")
    try:
        lib = ctypes.CDLL(name or "libcholmod.so")
        for f in ("cholmod_start", "cholmod_finish", "cholmod_amd", "cholmod_metis", "cholmod_analyze_ordering"):
            getattr(lib, f).restype = ctypes.c_int
    except (OSError, AttributeError):
        return None
    return lib


def _cholmod_sparse(A: sp.csc_matrix) -> tuple[_CholmodSparse, tuple[np.ndarray, np.ndarray]]:
    """A pattern-only, symmetric ``cholmod_sparse`` view of ``A`` (CHOLMOD reads its upper triangle), and the arrays
    it points into (keep them alive while it is used)."""
    colptr, rows = A.indptr.astype(np.int32, copy=False), A.indices.astype(np.int32, copy=False)
    n = A.shape[0]
    return _CholmodSparse(n, n, A.nnz, colptr.ctypes.data, rows.ctypes.data, None, None, None,
                          1, 0, 0, 0, int(A.has_sorted_indices), 1), (colptr, rows)  # upper, int, pattern


def supervariables(A: sp.csc_matrix) -> np.ndarray:
    """Starts of the runs of consecutive columns of the symmetric ``A`` with the same pattern (the 2 or 3 DOFs of
    a finite-element node), plus ``n`` at the end. Columns are compared by their length and the sums of their row
    indices and of their squares (a grouping that is off only costs ordering quality, never correctness)."""
    n = A.shape[0]
    lens = np.diff(A.indptr)
    if A.nnz == 0 or np.any(lens == 0):
        return np.arange(n + 1)
    idx = A.indices.astype(np.float64)
    s1 = np.add.reduceat(idx, A.indptr[:-1])
    s2 = np.add.reduceat(idx * idx, A.indptr[:-1])
    same = (lens[1:] == lens[:-1]) & (s1[1:] == s1[:-1]) & (s2[1:] == s2[:-1])
    return np.r_[0, np.flatnonzero(~same) + 1, n]


def symbolic_cost(A: sp.spmatrix | None, ordering: str = "amd", groups: np.ndarray | None = None,
                  graph: sp.spmatrix | None = None) -> SymbolicCost | None:
    """Order the symmetric ``A`` (``ordering``: "amd" or "metis") and count the non-zeros and flops of its Cholesky
    factor without computing it (CHOLMOD's ``cholmod_amd``/``cholmod_metis`` and ``cholmod_analyze_ordering``,
    ref. 1); ``None`` when CHOLMOD's library is not available. Only the pattern is read (a CSR matrix is read as
    its transpose, the same for a symmetric one).

    Both orderings and the analysis work on the graph of the supervariables ``groups`` (starts of runs of columns
    with one pattern, e.g. a node's DOFs; found by :func:`supervariables` when not given): at 66k DOF (22k nodes)
    AMD took 0.014 s there against 0.068 s on the DOFs, the analysis 0.008 s against 0.046 s. A supervariable j of
    s_j columns whose factor column holds c_j supervariables gives the DOF columns S_j, S_j - 1, ..., S_j - s_j + 1
    with S_j = s c_j (s the mean size: exact when all have one size, as a solid's nodes with three free DOFs; else
    an estimate). The ordering returned is the elimination tree's postorder of it (the same fill): without it
    METIS's nested dissection factored 25-45 % slower in CHOLMOD's natural order (its supernodes broken up).

    ``graph``: the supervariables' graph itself (symmetric pattern, ``groups`` given; ``A`` is then not read), e.g. the
    block pattern of a BSR stiffness restricted to the nodes with a free DOF (:func:`mechverify.fea.linsolve.solve`
    orders before it extracts any scalar matrix)."""
    if ordering not in ORDERINGS:
        raise InputError(f"ordering: one of {', '.join(ORDERINGS)}, got {ordering!r}")
    lib = _libcholmod()
    if graph is not None and groups is None:
        raise InputError("symbolic_cost: a graph needs its groups (the supervariables' first columns)")
    n = int(groups[-1]) if graph is not None else A.shape[0]
    if lib is None or n == 0:
        return None
    t0 = time.perf_counter()
    if graph is not None:
        A = graph
    if sp.issparse(A) and A.format == "csr":
        A = sp.csc_matrix((A.data, A.indices, A.indptr), shape=A.shape)  # Aᵀ = A: no conversion
    A = sp.csc_matrix(A)
    starts = supervariables(A) if groups is None else np.asarray(groups)
    sizes = np.diff(starts)
    nc = sizes.size
    C = A if graph is not None or nc == n else A[starts[:-1]][:, starts[:-1]].tocsc()
    Sc, keep = _cholmod_sparse(C)
    perm_c, parent, post, count, first, level = (np.empty(nc, np.int32) for _ in range(6))
    ptr = ctypes.c_void_p
    common = ctypes.create_string_buffer(1 << 16)  # cholmod_common (2.7 kB in SuiteSparse 5)
    if lib.cholmod_start(common) != 1:
        return None
    try:
        if ordering == "amd":
            ok = lib.cholmod_amd(ctypes.byref(Sc), None, ctypes.c_size_t(0), perm_c.ctypes.data_as(ptr), common)
        else:
            ok = lib.cholmod_metis(ctypes.byref(Sc), None, ctypes.c_size_t(0), 0, perm_c.ctypes.data_as(ptr),
                                   common)
        ok = ok == 1 and lib.cholmod_analyze_ordering(
            ctypes.byref(Sc), 1, perm_c.ctypes.data_as(ptr), None, ctypes.c_size_t(0),  # 1 = CHOLMOD_GIVEN
            parent.ctypes.data_as(ptr), post.ctypes.data_as(ptr), count.ctypes.data_as(ptr),
            first.ctypes.data_as(ptr), level.ctypes.data_as(ptr), common) == 1
    finally:
        lib.cholmod_finish(common)
    del keep
    c = count.astype(np.float64)
    if not ok or c.min() < 1 or c.max() > nc or np.unique(perm_c).size != nc:
        return None
    order = perm_c[post]  # supervariables in the postorder of the elimination tree
    size_p = sizes[order]  # each supervariable's columns in order
    perm = np.repeat(starts[order], size_p) + np.arange(n) - np.repeat(np.cumsum(size_p) - size_p, size_p)
    s = size_p.astype(np.float64)
    S = c[post] * (n / nc)  # the first DOF column's count of each supervariable
    nnz = float(np.sum(s * S - s * (s - 1) / 2))
    flops = float(np.sum(s * S * S - S * s * (s - 1) + (s - 1) * s * (2 * s - 1) / 6))  # sum of (S - k)^2, k < s
    return SymbolicCost(ordering, perm.astype(np.int64), int(round(nnz)), flops, time.perf_counter() - t0)


@dataclass(eq=False)
class Factorization:
    """A factorisation of ``A[n, n]``: :meth:`solve` takes ``b[n]`` or ``B[n, k]``; ``method`` is "cholmod" or
    "superlu"; ``seconds`` the time to factor; ``factor_nnz`` the non-zeros of SuperLU's factors (None for
    CHOLMOD: counting them would copy the supernodal factor)."""

    method: str
    n: int
    seconds: float
    factor_nnz: int | None
    _solve: Any

    def solve(self, b: np.ndarray) -> np.ndarray:
        """``A⁻¹ b`` for one vector or the columns of a matrix."""
        b = np.asarray(b, dtype=float)
        if b.shape[0] != self.n:
            raise InputError(f"right-hand side of length {b.shape[0]} for a factorisation of size {self.n}")
        with one_blas_thread(), one_openmp_thread():
            return self._solve(np.ascontiguousarray(b) if self.method == "superlu" else b)

    __call__ = solve

    def operator(self) -> spl.LinearOperator:
        """``A⁻¹`` as a SciPy LinearOperator (e.g. ``OPinv`` of ``eigsh``)."""
        return spl.LinearOperator((self.n, self.n), matvec=self.solve, matmat=self.solve, dtype=float)


def permuted_matrix(A: sp.csc_matrix, p: np.ndarray) -> sp.csc_matrix:
    """``A[p][:, p]`` of a symmetric CSC ``A``: its columns gathered, their row indices renamed (left unsorted within
    a column, which CHOLMOD accepts: the same factor bit for bit). 0.03-0.04 s against SciPy's 0.14-0.15 s at 66k
    DOF."""
    inverse = np.empty_like(p)
    inverse[p] = np.arange(p.size)
    B = A[:, p]
    B.indices = inverse[B.indices].astype(B.indices.dtype, copy=False)
    B.has_sorted_indices = False
    return B


def release_free_memory() -> None:
    """Hand the C heap's free pages back to the operating system (glibc's ``malloc_trim(0)``; nothing elsewhere).

    Memory that NumPy and SciPy freed (K's blocks, work arrays) stays in the heap and counts in the resident set;
    the factor (mapped afresh, tens of MB) then comes on top of it. One trim before the factorisation took 2.6 ms
    and lowered the 45.9k-DOF plate's peak from 259 to 232 MB (the RSS before factoring 159 -> 121 MB; task
    thinperf). Not after every free: ``MALLOC_TRIM_THRESHOLD_=0`` cost 30 % CPU (issue 23)."""
    try:
        trim = ctypes.CDLL(None).malloc_trim
    except (OSError, AttributeError):
        return
    trim.argtypes = [ctypes.c_size_t]
    trim(0)


def factorize_lower(L: sp.csc_matrix, symbolic: SymbolicCost, what: str = "the stiffness matrix") -> Factorization:
    """CHOLMOD's factorisation of ``A`` from ``L``, the lower triangle of ``A[p][:, p]`` (CSC, sorted row indices; ``p``
    = ``symbolic.perm``, e.g. :func:`mechverify.fea.assembly.free_lower_permuted`): CHOLMOD reads only the lower
    triangle of a symmetric matrix, so the factor is bit for bit that of :func:`factorize` with ``symbolic``, without
    the full matrix, its permuted copy and the sort of that copy (the 37k-DOF plate: 0.11 s CPU and 1.2 kB/DOF less;
    task thinperf). :meth:`Factorization.solve` takes and returns vectors in ``A``'s order."""
    if not cholmod_available():
        raise InputError(f"factorize_lower needs scikit-sparse: {install_hint('direct')}")
    from sksparse.cholmod import CholmodError, analyze

    t0 = time.perf_counter()
    release_free_memory()  # the peak of a direct solve is at the end of the factorisation
    L.has_sorted_indices = True  # sksparse would sort otherwise (the caller's promise, checked by the tests)
    try:
        with one_blas_thread(), one_openmp_thread():
            F = analyze(L, mode="supernodal", ordering_method="natural")  # what cholesky() does, in two steps:
            release_free_memory()  # the analysis's freed work arrays (7 MB of 11 at 45.9k DOF) go first
            F.cholesky_inplace(L)
    except CholmodError as exc:
        raise ModelError(f"{what} is not positive definite ({exc}): the model has a mechanism") from None
    p = symbolic.perm

    def permuted(b: np.ndarray) -> np.ndarray:
        x = np.empty_like(b)
        x[p] = F.solve_A(b[p])
        return x

    return Factorization("cholmod", L.shape[0], time.perf_counter() - t0, None, permuted)


def factorize(A: sp.spmatrix, method: str = "auto", what: str = "the stiffness matrix",
              symbolic: SymbolicCost | None = None) -> Factorization:
    """Factor the symmetric positive definite ``A`` once (``method``: "auto" = CHOLMOD when installed, else SuperLU).

    ``symbolic``: the :func:`symbolic_cost` of ``A``, whose ordering CHOLMOD then uses (it is not computed again);
    without it CHOLMOD chooses (AMD, and METIS too when AMD's fill is high). A matrix that is not positive definite
    (a mechanism, or a shift above an eigenvalue) is a :class:`ModelError` naming ``what``."""
    if method not in METHODS:
        raise InputError(f"method: one of {', '.join(METHODS)}, got {method!r}")
    if method == "auto":
        method = "cholmod" if cholmod_available() else "superlu"
    if sp.issparse(A) and A.format == "csr" and method == "cholmod":
        A = sp.csc_matrix((A.data, A.indices, A.indptr), shape=A.shape)  # symmetric: Aᵀ = A, no conversion
    A = sp.csc_matrix(A)
    t0 = time.perf_counter()
    if method == "cholmod":
        if not cholmod_available():
            raise InputError(f"method 'cholmod' needs scikit-sparse: {install_hint('direct')} (it builds "
                             "against SuiteSparse: apt-get install libsuitesparse-dev)")
        from sksparse.cholmod import CholmodError, cholesky

        p = None if symbolic is None or method != "cholmod" else symbolic.perm
        try:
            with one_blas_thread(), one_openmp_thread():  # LLᵀ: a matrix that is not positive definite fails
                F = cholesky(A, mode="supernodal") if p is None else \
                    cholesky(permuted_matrix(A, p), mode="supernodal", ordering_method="natural")
        except CholmodError as exc:
            raise ModelError(f"{what} is not positive definite ({exc}): the model has a mechanism, or the "
                             "shift lies above an eigenvalue") from None
        if p is None:
            return Factorization("cholmod", A.shape[0], time.perf_counter() - t0, None, F.solve_A)

        def permuted(b: np.ndarray) -> np.ndarray:
            x = np.empty_like(b)
            x[p] = F.solve_A(b[p])
            return x

        return Factorization("cholmod", A.shape[0], time.perf_counter() - t0, None, permuted)
    try:
        lu = spl.splu(A, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    except RuntimeError as exc:
        raise ModelError(f"{what} is singular ({exc}): the model has a mechanism") from None
    return Factorization("superlu", A.shape[0], time.perf_counter() - t0, int(lu.L.nnz + lu.U.nnz), lu.solve)
