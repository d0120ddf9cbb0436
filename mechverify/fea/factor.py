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

CHOLMOD runs with one BLAS thread (``threadpoolctl``, when installed): triangular solves are memory-bound,
and on the shared 2-core box busy-waiting BLAS threads made a solve up to 9 times and a factorisation up to
3 times slower than one thread (measured with a load average of 10).

References
----------
1. Y. Chen, T. A. Davis, W. W. Hager, S. Rajamanickam, "Algorithm 887: CHOLMOD, supernodal sparse Cholesky
   factorization and update/downdate", ACM TOMS 35 (2008) 22.
2. X. S. Li, "An overview of SuperLU", ACM TOMS 31 (2005) 302-325.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError

METHODS = ("auto", "cholmod", "superlu")


def cholmod_available() -> bool:
    """Whether scikit-sparse's CHOLMOD can be imported."""
    try:
        import sksparse.cholmod  # noqa: F401
    except Exception:  # ImportError, or a broken build against another SuiteSparse
        return False
    return True


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """Limit BLAS to one thread inside the block (``threadpoolctl`` when installed, else no effect)."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:
        yield
        return
    with threadpool_limits(limits=1, user_api="blas"):
        yield


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
        with one_blas_thread():
            return self._solve(np.ascontiguousarray(b) if self.method == "superlu" else b)

    __call__ = solve

    def operator(self) -> spl.LinearOperator:
        """``A⁻¹`` as a SciPy LinearOperator (e.g. ``OPinv`` of ``eigsh``)."""
        return spl.LinearOperator((self.n, self.n), matvec=self.solve, matmat=self.solve, dtype=float)


def factorize(A: sp.spmatrix, method: str = "auto", what: str = "the stiffness matrix") -> Factorization:
    """Factor the symmetric positive definite ``A`` once (``method``: "auto" = CHOLMOD when installed, else SuperLU).

    A matrix that is not positive definite (a mechanism, or a shift above an eigenvalue) is a
    :class:`ModelError` naming ``what``."""
    if method not in METHODS:
        raise InputError(f"method: one of {', '.join(METHODS)}, got {method!r}")
    if method == "auto":
        method = "cholmod" if cholmod_available() else "superlu"
    A = sp.csc_matrix(A)
    t0 = time.perf_counter()
    if method == "cholmod":
        if not cholmod_available():
            raise InputError("method 'cholmod' needs scikit-sparse: pip install 'mechverify[direct]' (it builds "
                             "against SuiteSparse: apt-get install libsuitesparse-dev)")
        from sksparse.cholmod import CholmodError, cholesky

        try:
            with one_blas_thread():
                F = cholesky(A, mode="supernodal")  # LLᵀ: a matrix that is not positive definite fails
        except CholmodError as exc:
            raise ModelError(f"{what} is not positive definite ({exc}): the model has a mechanism, or the "
                             "shift lies above an eigenvalue") from None
        return Factorization("cholmod", A.shape[0], time.perf_counter() - t0, None, F.solve_A)
    try:
        lu = spl.splu(A, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    except RuntimeError as exc:
        raise ModelError(f"{what} is singular ({exc}): the model has a mechanism") from None
    return Factorization("superlu", A.shape[0], time.perf_counter() - t0, int(lu.L.nnz + lu.U.nnz), lu.solve)
