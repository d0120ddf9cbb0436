"""The direct solve reads the lower triangle of the permuted free-DOF stiffness straight from the BSR K (issue 23,
task thinperf: the thin plate at 37k-67k DOF, time and memory per DOF).

No published number is involved: the new path must give the factor of the old one bit for bit (the old path:
``free_submatrix``, the CSR read as CSC, ``permuted_matrix``, sorted by scikit-sparse; CHOLMOD reads the lower
triangle). The physics of the solid solve is validated elsewhere (tests/test_fea_solid.py, tests/validation/).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from mechverify.fea import assembly, factor, linsolve, mesh, solid
from mechverify.fea.loads import Fixed, Force, Restraint
from mechverify.fea.regions import Plane

pytestmark = pytest.mark.skipif(not factor.cholmod_available() or factor.symbolic_cost(sp.eye(2)) is None,
                                reason="scikit-sparse (mechverify[direct]) / CHOLMOD's library not installed")


@pytest.fixture(scope="module")
def system():
    """A P2 box (80 x 30 x 20 mm) clamped at x = 0, with the y component also held on the plane x = 40 mm (nodes
    that keep two of three DOFs), loaded at x = 80 mm: its BSR K, free mask, load vector, held DOFs and model."""
    model = solid.SolidModel(mesh.box(("80 mm", "30 mm", "20 mm"), (8, 3, 2)), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")), Restraint(Plane(x="40 mm"), y=True)),
                             loads=(Force(Plane(x="80 mm"), ("0 N", "0 N", "-100 N")),))
    m, b = model.mesh.mesh, model.mesh.basis
    lam, mu = assembly.lame(model.material.E.m_as("Pa"), model.material.nu.m_as(""))
    K = assembly.assemble_elasticity(m.p, m.t, lam, mu, assembly.block_pattern(b.element_dofs, b.N))
    held = model._held()
    free = np.ones(K.shape[0], bool)
    free[held] = False
    return K, free, model.load_vector(), held, model


def test_some_nodes_keep_two_dofs(system):
    """The fixture exercises partly held nodes (else the node groups would all have three DOFs)."""
    K, free, *_ = system
    per_node = free.reshape(-1, 3).sum(axis=1)
    assert np.any(per_node == 2) and np.any(per_node == 3) and np.any(per_node == 0)


def test_node_graph_is_the_free_pattern_at_the_nodes(system):
    """node_graph: the pattern of K[free][:, free] at each node's first free DOF, the node runs and nnz."""
    K, free, *_ = system
    Kff = assembly.free_submatrix(K, free)
    graph, groups, nnz = assembly.node_graph(K, free)
    fd = np.flatnonzero(free)
    assert np.array_equal(groups, np.r_[0, np.flatnonzero(np.diff(fd // 3)) + 1, fd.size])
    assert nnz == Kff.nnz
    C = Kff[groups[:-1]][:, groups[:-1]].sorted_indices()  # stored entries, zeros of K's blocks included
    assert np.array_equal(C.indptr, graph.indptr) and np.array_equal(C.indices, graph.indices)


@pytest.mark.parametrize("rows", [1, 7, 1 << 15])
def test_free_lower_permuted_is_the_old_paths_lower_triangle(system, rows):
    """free_lower_permuted = tril of permuted_matrix(K[free][:, free] read as CSC) with sorted rows: the same indices
    and values bit for bit, for any chunk of rows; the node-graph ordering equals the one found on Kff."""
    K, free, *_ = system
    Kff = assembly.free_submatrix(K, free)
    graph, groups, nnz = assembly.node_graph(K, free)
    cost = factor.symbolic_cost(None, "amd", groups, graph=graph)
    assert np.array_equal(cost.perm, factor.symbolic_cost(Kff, "amd", groups).perm)
    L = assembly.free_lower_permuted(K, free, cost.perm, rows=rows)
    B = factor.permuted_matrix(sp.csc_matrix((Kff.data, Kff.indices, Kff.indptr), shape=Kff.shape), cost.perm)
    ref = sp.tril(B, format="csc")
    ref.sort_indices()
    assert L.has_sorted_indices
    assert all(np.all(np.diff(L.indices[L.indptr[j]:L.indptr[j + 1]]) > 0) for j in range(L.shape[1]))
    assert np.array_equal(L.indptr, ref.indptr) and np.array_equal(L.indices, ref.indices)
    assert np.array_equal(L.data, ref.data)


def test_solve_takes_the_lower_path_with_the_same_bits(system, monkeypatch):
    """linsolve.solve (auto, the cost model choosing the factorisation) gives the old path's displacements bit for
    bit: factorize(Kff, symbolic=the same ordering)."""
    K, free, f, held, model = system
    monkeypatch.setattr(linsolve, "ITERATIVE_THRESHOLD_3D", 100)  # this small box is 'big' for the choice
    m = model.mesh.mesh
    P = linsolve.p1_prolongation(m.nvertices, m.edges, 3)
    u, info = linsolve.solve(K.copy(), f, held, model.nodes, prolongation=P)
    assert info.method.startswith("direct (cholmod; predicted")
    assert info.residual < 1e-10
    Kff = assembly.free_submatrix(K, free)
    graph, groups, nnz = assembly.node_graph(K, free)
    _, cost = linsolve.choose_solver(Kff, groups=groups)
    x = factor.factorize(Kff, "cholmod", symbolic=cost).solve(f[free])
    assert np.array_equal(u[free], x) and not np.any(u[~free])


def test_held_rows_are_ks_rows(system):
    """held_rows (read from the held rows' blocks): K's held rows bit for bit, the other rows empty, with whole nodes
    and single components held."""
    K, free, f, held, model = system
    Kc = K.tocsr()
    for rows in (held, held[held % 3 == 1], np.array([K.shape[0] - 1])):
        A = assembly.held_rows(K, rows)
        others = np.setdiff1d(np.arange(K.shape[0]), rows)
        assert A[others].nnz == 0
        assert (A[rows] != Kc[rows]).nnz == 0 and A[rows].nnz == Kc[rows].nnz
        u = np.random.default_rng(2).standard_normal(K.shape[0])
        assert np.array_equal((A @ u)[rows], (Kc @ u)[rows])


def test_metis_is_tried_for_memory(system, monkeypatch):
    """choose_solver tries METIS when AMD's factor is over METIS_BYTES_PER_DOF even where its ordering would not pay in
    time (the plate at 67k DOF: AMD's factor 2.9 kB/DOF put the solve's peak at 5.05 kB/DOF); not when under it."""
    K, free, *_ = system
    graph, groups, nnz = assembly.node_graph(K, free)
    calls = []
    original = factor.symbolic_cost

    def spy(M, ordering="amd", g=None, graph=None):
        calls.append(ordering)
        return original(M, ordering, g, graph=graph)

    monkeypatch.setattr(factor, "symbolic_cost", spy)
    monkeypatch.setattr(linsolve, "METIS_SECONDS_PER_NNZ", 1.0)  # never pays in time
    amd = original(None, "amd", groups, graph=graph)
    monkeypatch.setattr(linsolve, "METIS_BYTES_PER_DOF", 1.01 * amd.factor_bytes / groups[-1])
    linsolve.choose_solver(None, groups=groups, graph=graph, nnz=nnz)
    assert calls == ["amd"]
    calls.clear()
    monkeypatch.setattr(linsolve, "METIS_BYTES_PER_DOF", 0.99 * amd.factor_bytes / groups[-1])
    linsolve.choose_solver(None, groups=groups, graph=graph, nnz=nnz)
    assert calls == ["amd", "metis"]


@pytest.mark.parametrize("high", [1, 300, 1 << 20, 1 << 40, 1 << 50])
def test_stable_argsort_is_numpys(high):
    """assembly.stable_argsort (16-bit LSD radix) gives NumPy's stable argsort, ties in input order, for keys of 1 to
    50 bits (above 48 NumPy's own sort)."""
    key = np.random.default_rng(high).integers(0, high, 5000, dtype=np.int64)
    assert np.array_equal(assembly.stable_argsort(key), np.argsort(key, kind="stable"))
