"""CHOLMOD's factorisation runs without OpenMP threads and gives the same bits (issue 23, task thinperf).

CHOLMOD 3 (SuiteSparse 5) opens parallel regions of a fixed four threads in ``cholmod_super_numeric`` whatever
``OMP_NUM_THREADS`` says; on the 2-core box their busy-waiting cost 0.15-0.2 s CPU per factorisation of the 37k-DOF
plate. :func:`mechverify.fea.factor.one_openmp_thread` makes those regions run on the calling thread. Not a timed
test: it counts the process's threads and compares the solution's bits with the raw scikit-sparse factorisation.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import scipy.sparse as sp

from mechverify.fea.factor import cholmod_available, factorize, one_openmp_thread

pytestmark = pytest.mark.skipif(not cholmod_available(), reason="scikit-sparse (CHOLMOD) not installed")


def laplacian_3d(k: int) -> sp.csc_matrix:
    """The 7-point Laplacian of a k x k x k grid (SPD, Dirichlet)."""
    T = sp.diags([-np.ones(k - 1), 2 * np.ones(k), -np.ones(k - 1)], [-1, 0, 1])
    I = sp.identity(k)
    return (sp.kron(sp.kron(T, I), I) + sp.kron(sp.kron(I, T), I) + sp.kron(sp.kron(I, I), T)).tocsc()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="counts threads in /proc/self/task")
def test_factorize_starts_no_openmp_threads() -> None:
    """A fresh process with one OpenBLAS thread (so any new thread is OpenMP's): ``factorize`` leaves the thread count
    as it was; the raw ``sksparse.cholmod.cholesky`` afterwards starts CHOLMOD's OpenMP team (three more threads on
    SuiteSparse 5; skipped where this CHOLMOD opens none, as the test would prove nothing)."""
    code = textwrap.dedent("""
        import os, numpy as np, scipy.sparse as sp
        from tests.test_fea_factor_threads import laplacian_3d
        from mechverify.fea.factor import factorize
        from sksparse.cholmod import cholesky
        n = lambda: len(os.listdir("/proc/self/task"))
        A = laplacian_3d(24)
        start = n()
        factorize(A, "cholmod").solve(np.ones(A.shape[0]))
        ours = n()
        cholesky(A, mode="supernodal")
        print(start, ours, n())
    """)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="2")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                         cwd=os.path.dirname(os.path.dirname(os.path.abspath(__file__))), timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    start, ours, raw = map(int, out.stdout.split()[-3:])
    if raw == ours:
        pytest.skip("this CHOLMOD build starts no OpenMP threads")
    assert ours == start, f"factorize started {ours - start} threads"


def test_same_bits_as_the_threaded_factorisation() -> None:
    """The OpenMP regions only copy and clear supernodes: one thread gives the threaded factor's solution bit for
    bit (``factorize`` without a symbolic analysis calls ``cholesky(A, mode="supernodal")``, as here)."""
    from sksparse.cholmod import cholesky

    A = laplacian_3d(22)
    b = np.random.default_rng(1).standard_normal(A.shape[0])
    threaded = cholesky(A, mode="supernodal").solve_A(b)
    ours = factorize(A, "cholmod").solve(b)
    assert np.array_equal(ours, threaded)
    assert np.linalg.norm(A @ ours - b) <= 1e-10 * np.linalg.norm(b)


def test_one_openmp_thread_nests_and_restores() -> None:
    """Nested blocks: the setting is restored once, by the outermost block (the runtime is loaded with CHOLMOD)."""
    from mechverify.fea.factor import _openmp_runtime

    lib = _openmp_runtime()
    if lib is None:
        pytest.skip("no OpenMP runtime loaded")
    before = lib.omp_get_max_active_levels()
    with one_openmp_thread():
        assert lib.omp_get_max_active_levels() == 0
        with one_openmp_thread():
            assert lib.omp_get_max_active_levels() == 0
        assert lib.omp_get_max_active_levels() == 0
    assert lib.omp_get_max_active_levels() == before


def test_one_openmp_thread_is_per_thread() -> None:
    """The setting belongs to the calling thread: a block in one thread leaves another thread's setting alone, and
    blocks in two threads at once each restore their own."""
    import threading

    from mechverify.fea.factor import _openmp_runtime

    lib = _openmp_runtime()
    if lib is None:
        pytest.skip("no OpenMP runtime loaded")
    seen: dict[str, int] = {}
    inside, release = threading.Event(), threading.Event()

    def worker() -> None:
        with one_openmp_thread():
            seen["worker inside"] = lib.omp_get_max_active_levels()
            inside.set()
            release.wait(10)
        seen["worker after"] = lib.omp_get_max_active_levels()

    before = lib.omp_get_max_active_levels()
    t = threading.Thread(target=worker)
    t.start()
    inside.wait(10)
    seen["main while worker inside"] = lib.omp_get_max_active_levels()
    with one_openmp_thread():
        release.set()
        t.join(10)
        seen["main inside"] = lib.omp_get_max_active_levels()
    assert seen == {"worker inside": 0, "worker after": before, "main while worker inside": before, "main inside": 0}
    assert lib.omp_get_max_active_levels() == before
