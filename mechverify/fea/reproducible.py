"""Same bits on every run: FE results that depend neither on the BLAS thread count nor on numpy's global random state.

A study's output must be identical whatever runs it (issue 19: serial, a process pool, Dask). Two causes made the
solid FEA differ in the last digits (measured on ``examples/solid_bracket``, 13.5k unknowns, and the same model
solved by multigrid CG):

1. **The BLAS thread count.** OpenBLAS's ``dgemm`` gives results that differ in the last bits with the number of
   threads it runs on; numpy calls it from the element integrals (``einsum(..., optimize=True)`` in
   :mod:`mechverify.fea.isoparametric`, ``R @ P`` in :mod:`mechverify.fea.assembly`). Already the Jacobians of the
   curved tetrahedra differed, hence the stiffness matrix, the displacements and the stresses: the bracket's
   peak von Mises stress was 81.37694512174657 MPa with two threads (``mechverify check`` on the 2-core box: one
   thread per core) and 81.37694512172219 MPa with one (a study's pool worker, the test suite, a Dask worker).
   :func:`one_blas_thread` runs a computation on one BLAS thread whatever the process's setting, and the FE entry
   points use it (:func:`reproducible`: ``SolidModel.solve``, ``SharedSolve``, ``modal``, ``buckling``, and the
   frame's ``frame_modes``/``frame_buckling``, whose ARPACK shift-invert gave the conveyor's shaft critical speed as
   9653.451577149817 rad/s on one thread and 9653.45157715028 on two; the plate and plane solvers, modes and
   buckling gave the same bits either way, measured: not wrapped). The
   factorisation already ran on one thread (:mod:`mechverify.fea.factor`: faster on the shared box).
2. **pyamg's random start vector.** Smoothed aggregation estimates the spectral radius of ``D⁻¹A`` for its
   prolongation smoother by Arnoldi from ``np.random.rand`` (numpy's global, unseeded generator,
   ``pyamg.util.linalg.approximate_spectral_radius``), so the multigrid hierarchy and CG's iterates differed on
   every run (three fresh processes, three displacement hashes). :func:`seeded_global_rng` gives that setup a
   fixed seed and puts the caller's random state back afterwards; :func:`reproducible` applies it around the same
   entry points (so around every multigrid setup they make).

Without ``threadpoolctl`` (extras ``direct``, ``cluster``, ``test``) :func:`one_blas_thread` has no effect: the
result then depends on the BLAS thread count the process starts with (``OPENBLAS_NUM_THREADS``).
Bits are the same on one machine and library build; another CPU (another OpenBLAS kernel) may differ in the last
digits.
"""

from __future__ import annotations

import contextlib
import functools
import threading
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

import numpy as np

F = TypeVar("F", bound=Callable[..., Any])

_lock = threading.Lock()
_depth = 0
_limiter: Any = None


@functools.cache
def _controller() -> Any:
    """A ``threadpoolctl.ThreadpoolController`` of the BLAS libraries this process uses: numpy's, scipy's (ARPACK,
    LAPACK) and CHOLMOD's are loaded first, since a controller lists only the libraries loaded when it is made (scipy's
    own OpenBLAS was missing when the first solve came before any scipy.linalg import, and buckling's ARPACK then ran
    on two threads); None without threadpoolctl."""
    try:
        from threadpoolctl import ThreadpoolController
    except ImportError:
        return None
    import scipy.linalg  # scipy's BLAS/LAPACK library
    import scipy.sparse.linalg  # noqa: F401  (ARPACK)
    with contextlib.suppress(Exception):  # optional; a broken build is the factor module's business
        import sksparse.cholmod  # noqa: F401
    return ThreadpoolController()


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """Run the block with every BLAS library on one thread, then restore the process's setting.

    Re-entrant and safe across threads: the limit is process-wide, so it is set by the first block to enter and
    restored by the last to leave (a thread leaving its block never lifts the limit under another's computation).
    """
    global _depth, _limiter
    with _lock:
        if _depth == 0:
            controller = _controller()
            _release_openblas()
            _limiter = None if controller is None else controller.limit(limits=1, user_api="blas")
        _depth += 1
    try:
        yield
    finally:
        with _lock:
            _depth -= 1
            if _depth == 0 and _limiter is not None:
                _release_openblas()
                _limiter.restore_original_limits()
                _limiter = None
                _release_openblas()


def _release_openblas() -> None:
    """threadpoolctl (3.6 on) lets only the thread that last set OpenBLAS's shared pool size set it again; the others
    are silently ignored. The first block to enter and the last to leave may be different threads, so each takes
    over (our lock orders them) and hands it back."""
    try:
        from threadpoolctl import OpenBLASController
    except ImportError:
        return
    clear = getattr(OpenBLASController, "clear_controlling_thread", None)
    if clear is not None:
        clear(force=True)


def reproducible(fn: F) -> F:
    """Decorator: ``fn`` runs inside :func:`one_blas_thread` and :func:`seeded_global_rng` (its result then has the
    same bits however many BLAS threads the caller's process uses, and whatever numpy's global random state is: the
    multigrid setup inside, :func:`mechverify.fea.linsolve.pmg_preconditioner`, draws from it). Calls from different
    threads run one after the other (the seeded global state is shared)."""

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        with one_blas_thread(), seeded_global_rng():
            return fn(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


_rng_lock = threading.RLock()


@contextlib.contextmanager
def seeded_global_rng(seed: int = 0) -> Iterator[None]:
    """numpy's global random generator (``np.random.rand``) seeded with ``seed`` inside the block, for a library
    that draws from it without a seed (pyamg); the caller's random state is put back afterwards. Blocks of
    different threads run one after the other (the global state is shared)."""
    with _rng_lock:
        state = np.random.get_state()
        np.random.seed(seed)
        try:
            yield
        finally:
            np.random.set_state(state)
