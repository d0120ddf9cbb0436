"""The static solver's choice between a factorisation and multigrid CG (issue 23): CHOLMOD's symbolic analysis
(:func:`mechverify.fea.factor.symbolic_cost`), the cost model (:func:`mechverify.fea.linsolve.choose_solver`) and
CG's measured switch to the factorisation.

Sources: the fill of a tree-structured matrix is a closed form (a path or a star graph eliminated leaves first has
no fill: nnz(L) = 2n - 1, column counts 2 ... 2, 1; George & Liu, Computer Solution of Large Sparse Positive
Definite Systems, Prentice-Hall 1981, ch. 4 - a hand count, not a printed table). The counts of a general matrix
are checked against the factor CHOLMOD actually computes (simplicial, same ordering)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from mechverify.errors import InputError
from mechverify.fea import factor, linsolve, mesh, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane

pytestmark = pytest.mark.skipif(not factor.cholmod_available() or factor.symbolic_cost(sp.eye(2)) is None,
                                reason="scikit-sparse (mechverify[direct]) / CHOLMOD's library not installed")


def laplacian_2d(k: int) -> sp.csc_matrix:
    """5-point Laplacian on a k x k grid (SPD)."""
    T = sp.diags([-np.ones(k - 1), 2 * np.ones(k), -np.ones(k - 1)], [-1, 0, 1])
    return (sp.kron(T, sp.eye(k)) + sp.kron(sp.eye(k), T)).tocsc()


def test_tree_matrices_have_no_fill():
    """A tridiagonal (path graph) and an arrow matrix (star graph): AMD (minimum degree) eliminates leaves first,
    so L has the pattern of A's lower triangle. Hand count: nnz(L) = 2n - 1 and Σc² = 4(n - 1) + 1. (METIS's nested
    dissection of the path orders separators last and fills: 582 for n = 200; its counts are checked against the
    computed factor below.)"""
    n = 200
    path = sp.diags([-np.ones(n - 1), 4 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1]).tocsc()
    star = sp.lil_matrix((n, n))
    star.setdiag(float(n))
    star[0, 1:] = 1.0
    star[1:, 0] = 1.0
    for A in (path, star.tocsc()):
        c = factor.symbolic_cost(A, "amd")
        assert c.factor_nnz == 2 * n - 1
        assert c.flops == 4 * (n - 1) + 1
        assert sorted(c.perm.tolist()) == list(range(n))


@pytest.mark.parametrize("ordering", ["amd", "metis"])
def test_counts_equal_the_computed_factor(ordering):
    """On a 2D Laplacian (fill-in) the predicted non-zeros of L equal those of the simplicial factor CHOLMOD
    computes in the same ordering (the permuted matrix factored in natural order)."""
    from sksparse.cholmod import cholesky

    A = laplacian_2d(30)
    c = factor.symbolic_cost(A, ordering)
    p = c.perm
    L = cholesky(A[p][:, p].tocsc(), mode="simplicial", ordering_method="natural").L()
    assert c.factor_nnz == L.nnz
    counts = np.diff(L.tocsc().indptr).astype(float)
    assert c.flops == pytest.approx(counts @ counts)
    assert c.factor_nnz > 2 * A.nnz // 2  # real fill: more than A's lower triangle


@pytest.mark.parametrize("ordering", ["amd", "metis"])
def test_factorize_with_the_analysed_ordering(ordering):
    """factorize(symbolic=) factors A[p][:, p] and solves A x = b for one vector and a block of vectors."""
    A = laplacian_2d(25)
    c = factor.symbolic_cost(A, ordering)
    F = factor.factorize(A, symbolic=c)
    b = np.linspace(1.0, 2.0, A.shape[0])
    x = F.solve(b)
    assert np.linalg.norm(A @ x - b) <= 1e-12 * np.linalg.norm(b)
    X = F.solve(np.c_[b, -3 * b])
    assert np.allclose(X[:, 1], -3 * x, rtol=0, atol=1e-12 * np.abs(x).max())


def test_bad_ordering_is_named():
    with pytest.raises(InputError, match="ordering: one of amd, metis"):
        factor.symbolic_cost(sp.eye(3).tocsc(), "nested")


def plate(thickness: str, cells: tuple[int, int, int]):
    m = mesh.box(("200 mm", "100 mm", thickness), cells)
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                            loads=(Force(Plane(x="200 mm"), ("0 N", "0 N", "-100 N")),))


def test_thin_plate_factored_compact_block_iterated():
    """A 3 mm plate (12.9k unknowns: multigrid CG needs 157 iterations on it at 17k) is factored; a compact
    100 x 100 x 100 mm block at a similar size is solved by CG (its factor's fill grows as a 3D mesh's). The choice
    follows the predictions it reports, and both answers equal the direct solve."""
    thin = plate("3 mm", (26, 13, 1))
    block = solid.SolidModel(mesh.box(("100 mm", "100 mm", "100 mm"), (8, 8, 8)), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),),
                             loads=(Force(Plane(x="100 mm"), ("0 N", "0 N", "-100 N")),))
    for model, expect in ((thin, "direct"), (block, "amg")):
        res = model.solve(progress=False)
        assert res.info.unknowns > linsolve.ITERATIVE_THRESHOLD_3D
        assert res.info.method.startswith("direct (cholmod" if expect == "direct" else "amg (predicted")
        assert "predicted" in res.info.method
        ref = model.solve(method="direct", progress=False)
        assert np.max(np.abs(res.u - ref.u)) <= 1e-7 * np.max(np.abs(ref.u))


def test_choice_follows_the_predictions():
    """choose_solver: 'direct' exactly when the factor fits the memory budget and its predicted seconds (factor and
    one solve) are at most CG's at the expected iterations; CG's prediction is nnz(A) * CG_SECONDS_PER_NNZ * (30 + 7)."""
    model = plate("3 mm", (26, 13, 1))
    from mechverify.fea.modal import stiffness_matrix

    K = stiffness_matrix(model).tocsr()
    held = np.unique(model.held_dofs())
    free = np.setdiff1d(np.arange(K.shape[0]), held)
    A = K[free][:, free]
    choice, cost = linsolve.choose_solver(A)
    assert choice.cg_seconds == pytest.approx(A.nnz * linsolve.CG_SECONDS_PER_NNZ * (30 + 7))
    assert choice.direct_seconds == pytest.approx(cost.factor_seconds + cost.solve_seconds)
    assert choice.direct_bytes == pytest.approx(cost.factor_nnz * factor.FACTOR_BYTES_PER_NNZ)
    assert (choice.method == "direct") == (choice.fits and choice.direct_seconds <= choice.cg_seconds)
    assert choice.method == "direct"


def test_memory_budget_keeps_cg(monkeypatch):
    """A factor predicted above DIRECT_BYTES_PER_DOF per unknown is not used: CG solves, and says why."""
    monkeypatch.setattr(linsolve, "DIRECT_BYTES_PER_DOF", 1.0)
    res = plate("3 mm", (26, 13, 1)).solve(progress=False)
    assert res.info.method.startswith("amg") and "over the memory budget" in res.info.method


def test_slow_cg_switches_to_the_factorisation(monkeypatch):
    """CG chosen (its prediction made nearly free) on the thin plate, where it converges slowly: at iteration 20
    the measured rate and time per iteration predict more seconds than the (predicted) factorisation, so the solve
    leaves CG for CHOLMOD; the answer equals the direct solve."""
    monkeypatch.setattr(linsolve, "CG_SECONDS_PER_NNZ", 1e-18)
    monkeypatch.setattr(factor, "FACTOR_SECONDS_PER_NNZ", 1e-15)
    model = plate("3 mm", (26, 13, 1))
    res = model.solve(progress=False)
    assert res.info.method.startswith("direct (cholmod") and "CG left after 20 iterations" in res.info.method
    assert res.info.iterations == 20
    ref = model.solve(method="direct", progress=False)
    assert np.max(np.abs(res.u - ref.u)) <= 1e-8 * np.max(np.abs(ref.u))


def test_pcg_direct_seconds():
    """pcg(direct_seconds=): a 2D Laplacian (30 x 30) without preconditioning needs about 100 iterations; with a
    factorisation predicted at (nearly) no cost CG raises SlowConvergence at iteration 20, with a generous one it
    converges."""
    A = laplacian_2d(30).tocsr()
    b = np.ones(A.shape[0])
    with pytest.raises(linsolve.SlowConvergence, match="s more against") as exc:
        linsolve.pcg(A, b, lambda r: r, 1e-10, direct_seconds=1e-12)
    assert exc.value.iterations == 20 and exc.value.predicted > 20
    x, it = linsolve.pcg(A, b, lambda r: r, 1e-10, direct_seconds=1e6)
    assert it > 20 and np.linalg.norm(A @ x - b) < 1e-9 * np.linalg.norm(b)


def test_large_system_analysed_only_when_cg_is_slow(monkeypatch):
    """Above ANALYSE_FIRST_MAX unknowns CG starts without the symbolic analysis; the thin plate's slow convergence
    (157 iterations at 17k) makes it analyse at iteration 20 and leave CG for the factorisation, and says so."""
    monkeypatch.setattr(linsolve, "ANALYSE_FIRST_MAX", 0)
    monkeypatch.setattr(factor, "FACTOR_SECONDS_PER_NNZ", 1e-15)
    calls = []
    real = factor.symbolic_cost
    monkeypatch.setattr(factor, "symbolic_cost", lambda A, *a, **k: calls.append(a) or real(A, *a, **k))
    res = plate("3 mm", (26, 13, 1)).solve(progress=False)
    assert calls and res.info.iterations == 20
    assert res.info.method.startswith("direct (cholmod") and "CG left after 20 iterations" in res.info.method
