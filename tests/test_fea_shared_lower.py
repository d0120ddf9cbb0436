"""SharedSolve (every design-file solid_fea solve, pinned models) assembles and factors as the plain solve does (task
solve2, issue 23): the chunked stiffness of ``SolidModel._stiffness``, the choice on the node graph and, for a
factorisation, only the lower triangle of the permuted free matrix (``assembly.free_lower_permuted`` ->
``factor.factorize_lower``). No published numbers are involved: these are equalities between two code paths (bit for
bit), plus the cantilever's tip deflection against the hand calculation PL³/3EI."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from mechverify.fea import assembly as asm
from mechverify.fea import mesh, solid, study
from mechverify.fea.factor import cholmod_available, factorize
from mechverify.fea.loads import Fixed, Force, PinSupport
from mechverify.fea.regions import Named, Plane
from mechverify.units import Q

pytestmark = pytest.mark.skipif(not cholmod_available(), reason="the lower-triangle path needs CHOLMOD")


def _beam(curved: bool = False) -> solid.SolidModel:
    m = mesh.box(("200 mm", "10 mm", "10 mm"), (20, 2, 2))
    if curved:  # the isoparametric path, on straight mid-side nodes given as "curved" ones
        m = dataclasses.replace(m, curved=m.basis.doflocs.copy())
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                            loads=(Force(Plane(x="200 mm"), ("0 N", "0 N", "-100 N")),))


@pytest.fixture
def low_threshold(monkeypatch):
    """Both solvers' "auto" weighs a factorisation against CG above 12k unknowns; at 100 these small models take
    that branch (and choose the factorisation), so the tests stay fast."""
    from mechverify.fea import linsolve

    monkeypatch.setattr(study, "ITERATIVE_THRESHOLD_3D", 100)
    monkeypatch.setattr(linsolve, "ITERATIVE_THRESHOLD_3D", 100)


def _old_path(model: solid.SolidModel, K, held: np.ndarray) -> np.ndarray:
    """What SharedSolve.of did before: the full K[free][:, free] factored with the node graph's ordering."""
    from mechverify.fea.linsolve import choose_solver

    mask = np.ones(K.shape[0], bool)
    mask[held] = False
    graph, groups, nnz = asm.node_graph(K, mask)
    _, cost = choose_solver(None, groups=groups, graph=graph, nnz=nnz)
    return mask, factorize(asm.free_submatrix(K, mask), "cholmod", symbolic=cost)


@pytest.mark.parametrize("curved", [False, True], ids=["straight", "curved"])
def test_shared_direct_is_the_plain_solve_bit_for_bit(low_threshold, curved):
    """The factorisation keeps no full free matrix, only the lower triangle; u and sigma equal the plain solve's
    (linsolve.solve's lower path and the same chunked stiffness: before, a curved mesh's K was summed in another
    order and differed in the last bits) and the old path's factor of K[free][:, free]; tip deflection within 2 % of
    PL³/3EI = 100·0.2³/(3·200e9·0.01⁴/12) = 1.6 mm (hand calculation)."""
    model = _beam(curved)
    shared = study.SharedSolve.of(model)
    assert shared.method == "direct"
    assert shared._Kff is None and shared._lower is not None  # fails before: the full Kff was kept
    a = model.solve(factorization=shared, progress=False)
    b = model.solve(progress=False)
    assert "cholmod" in b.info.method
    assert np.array_equal(a.u, b.u) and np.array_equal(a.sigma, b.sigma)
    assert a.info.residual < 1e-8
    held = np.unique(model.held_dofs())
    mask, old = _old_path(model, study._stiffness(model), held)
    f = np.zeros(model.mesh.n_dofs)
    f[-1] = 1.0
    u, _ = shared.solve(f, held)
    assert np.array_equal(u[mask], old.solve(f[mask]))
    assert abs(a.u[:, 2]).max() == pytest.approx(1.6e-3, rel=0.02)


def test_shared_stiffness_is_the_solids_own():
    """study._stiffness of a SolidModel is SolidModel._stiffness's K (what the plain solve assembles), bit for bit; for
    straight elements also modal.stiffness_matrix's (the same sums in the same order)."""
    from mechverify.fea.modal import stiffness_matrix

    for curved in (False, True):
        model = _beam(curved)
        b = model.mesh.basis
        lam, mu = asm.lame(model.material.E.m_as("Pa"), model.material.nu.m_as(""))
        own = model._stiffness(asm.block_pattern(b.element_dofs, b.N), lam, mu)[0]
        K = study._stiffness(model)
        assert np.array_equal(K.data, own.data) and np.array_equal(K.indices, own.indices)
        if not curved:
            assert np.array_equal(K.data, stiffness_matrix(model).data)


def test_block_solve_on_the_lower_triangle(low_threshold):
    """solve_many on the lower-triangle factorisation: each column equals its single solve bit for bit (one
    factor) to round-off, held DOFs zero, residual from the lower triangle small."""
    model = _beam()
    shared = study.SharedSolve.of(model)
    assert shared._lower is not None
    F = np.random.default_rng(5).standard_normal((model.mesh.n_dofs, 4))
    F[shared.held] = 0.0
    U, info = shared.solve_many(F)
    assert info.residual < 1e-8
    for j in (0, 3):
        u, one = shared.solve(F[:, j])
        assert np.max(np.abs(U[:, j] - u)) <= 1e-10 * np.max(np.abs(u))
        assert one.residual < 1e-8
    assert np.all(U[shared.held] == 0)


def test_pinned_model_on_the_lower_triangle(low_threshold):
    """A beam on two pins (K' = Tᵀ K T in the pins' axes) factored through the lower triangle: u equals the old
    path's factor of K'[free][:, free] bit for bit at the free DOFs."""
    pytest.importorskip("gmsh")
    m = mesh.block_with_holes((Q(300, "mm"), Q(20, "mm"), Q(10, "mm")),
                              [((Q(10, "mm"), Q(10, "mm")), "6 mm"), ((Q(290, "mm"), Q(10, "mm")), "6 mm")], "12 mm")
    model = solid.SolidModel(m, "Structural Steel", supports=(PinSupport(Named("hole0"), axial=True),
                                                              PinSupport(Named("hole1"))),
                             loads=(Force(Named("ymax"), ("0 N", "-1000 N", "0 N")),))
    shared = study.SharedSolve.of(model)
    assert shared.method == "direct" and shared._lower is not None
    basis = model.dof_basis
    held = np.unique(model.held_in_axes()[0])
    mask, old = _old_path(model, basis.rotate(study._stiffness(model)), held)
    f = np.random.default_rng(2).standard_normal(model.mesh.n_dofs)
    u, info = shared.solve(f)
    assert np.array_equal(u[mask], old.solve(f[mask]))
    assert info.residual < 1e-8
    res = model.solve(progress=False)
    assert res.info.method == "direct (shared)"
