"""The factorisation's ordering on the node graph (issue 23: the thin plate at 37k-67k DOF).

Sources: the fill of a symmetric matrix whose pattern is a node pattern with dense 3 x 3 blocks is that node
pattern's fill with each node expanded into a dense lower-triangular diagonal block and dense off-diagonal blocks
(George & Liu, Computer Solution of Large Sparse Positive Definite Systems, 1981, supervariables / indistinguishable
nodes), so a node factor column of c nodes gives the DOF columns 3c, 3c - 1, 3c - 2: nnz = sum(9c - 3) and flops
= sum(27c^2 - 18c + 5) - a hand derivation, checked here against the factor CHOLMOD computes, not a printed value."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from mechverify.fea import factor, linsolve, mesh, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane

pytestmark = pytest.mark.skipif(not factor.cholmod_available() or factor.symbolic_cost(sp.eye(2)) is None,
                                reason="scikit-sparse (mechverify[direct]) / CHOLMOD's library not installed")


def solid_system(cells: tuple[int, int, int] = (8, 3, 2)) -> tuple[sp.csr_matrix, np.ndarray]:
    """The free-DOF stiffness of a P2 box clamped at x = 0 (every free node keeps its three DOFs) and its node
    groups (starts of each node's DOFs)."""
    from mechverify.fea.modal import stiffness_matrix

    model = solid.SolidModel(mesh.box(("80 mm", "30 mm", "20 mm"), cells), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),),
                             loads=(Force(Plane(x="80 mm"), ("0 N", "0 N", "-100 N")),))
    K = stiffness_matrix(model).tocsr()
    free = np.setdiff1d(np.arange(K.shape[0]), model.held_dofs())
    groups = np.r_[0, np.flatnonzero(np.diff(free // 3)) + 1, free.size]
    return K[free][:, free].tocsr(), groups


@pytest.mark.parametrize("ordering", ["amd", "metis"])
def test_node_graph_counts_equal_the_computed_factor(ordering):
    """symbolic_cost analyses the node graph (a third of the columns) and expands the counts: with three DOFs on
    every node they are exact - nnz(L) of CHOLMOD's simplicial factor in that ordering, and flops = sum of the squared
    column counts. The returned ordering keeps each node's DOFs together."""
    from sksparse.cholmod import cholesky

    A, groups = solid_system()
    assert np.all(np.diff(groups) == 3)  # the premise of exactness
    c = factor.symbolic_cost(A, ordering, groups)
    L = cholesky(factor.permuted_matrix(A.tocsc(), c.perm), mode="simplicial", ordering_method="natural").L()
    counts = np.diff(L.tocsc().indptr).astype(float)
    assert c.factor_nnz == L.nnz
    assert c.flops == pytest.approx(counts @ counts, rel=1e-12)
    assert np.array_equal(c.perm.reshape(-1, 3) % 3, np.tile([0, 1, 2], (A.shape[0] // 3, 1)))


def test_ordering_is_a_postorder_of_the_elimination_tree():
    """In the returned ordering every column's parent in the elimination tree comes after it and each subtree is
    contiguous (a postorder): the supernodal factorisation then finds its supernodes whole (METIS's order without it
    factored 25-45 % slower). Checked on the etree of the permuted matrix computed from L's pattern."""
    from sksparse.cholmod import cholesky

    A, groups = solid_system((6, 2, 2))
    for ordering in ("amd", "metis"):
        c = factor.symbolic_cost(A, ordering, groups)
        L = cholesky(factor.permuted_matrix(A.tocsc(), c.perm), mode="simplicial", ordering_method="natural").L()
        L = L.tocsc()
        n = L.shape[0]
        parent = np.array([L.indices[L.indptr[j] + 1] if L.indptr[j + 1] - L.indptr[j] > 1 else -1 for j in range(n)])
        assert np.all((parent == -1) | (parent > np.arange(n)))
        size = np.ones(n, int)  # subtree sizes; a postorder puts subtree(j) at j - size + 1 ... j
        for j in range(n):
            if parent[j] >= 0:
                size[parent[j]] += size[j]
        first = np.arange(n) - size + 1
        for j in range(n):
            if parent[j] >= 0:
                assert first[parent[j]] <= first[j]


def test_permuted_matrix_is_the_symmetric_permutation():
    """factor.permuted_matrix(A, p) holds A[p][:, p] (its row indices unsorted within columns), and CHOLMOD factors
    it to the same bits as SciPy's sorted copy."""
    from sksparse.cholmod import cholesky

    A, groups = solid_system((5, 2, 2))
    A = A.tocsc()
    p = factor.symbolic_cost(A, "metis", groups).perm
    B = factor.permuted_matrix(A, p)
    ref = A[p][:, p].tocsc()
    assert abs(B - ref).max() == 0
    b = np.linspace(-1.0, 1.0, A.shape[0])
    x1 = cholesky(B, mode="supernodal", ordering_method="natural").solve_A(b)
    x2 = cholesky(ref, mode="supernodal", ordering_method="natural").solve_A(b)
    assert np.array_equal(x1, x2)


def test_metis_is_tried_only_when_it_may_pay(monkeypatch):
    """choose_solver orders with AMD (cheap) and tries METIS only when METIS_GAIN of AMD's predicted factor time
    exceeds METIS's predicted ordering time (METIS_SECONDS_PER_NNZ * nnz(A)); it keeps the faster of the two."""
    A, groups = solid_system()
    calls = []
    original = factor.symbolic_cost

    def spy(M, ordering="amd", g=None, graph=None):
        calls.append(ordering)
        return original(M, ordering, g, graph=graph)

    monkeypatch.setattr(factor, "symbolic_cost", spy)
    monkeypatch.setattr(linsolve, "METIS_SECONDS_PER_NNZ", 1.0)  # METIS never pays
    choice, cost = linsolve.choose_solver(A, groups=groups)
    assert calls == ["amd"] and choice.ordering == "amd"
    calls.clear()
    monkeypatch.setattr(linsolve, "METIS_SECONDS_PER_NNZ", 0.0)  # METIS always worth a try
    choice, cost = linsolve.choose_solver(A, groups=groups)
    assert calls == ["amd", "metis"]
    amd, metis = original(A, "amd", groups), original(A, "metis", groups)
    assert choice.ordering == ("metis" if metis.factor_seconds < amd.factor_seconds else "amd")
