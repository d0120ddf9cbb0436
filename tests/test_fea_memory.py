"""What ``SolidModel.solve`` keeps alive while it solves (issue 23: memory per DOF stays <= 5 kB).

Peak memory itself is measured by ``benchmarks/fea_vs_calculix.py`` (a byte count at test size is fragile), so
these tests assert what is alive instead: the element stiffness blocks ``[(a,b), e, 9]`` (100 * 9 floats per
quadratic tetrahedron, 1.4 times the assembled K's data) must be freed as soon as K is assembled, before the
linear solve and the stress recovery. Commit a02e5c2 (curved elements) held them in a local of ``solve``:
the 47k-DOF lug's peak went from 288 MB to 357 MB (4.2 -> 5.7 kB/DOF above the process's start), measured
with ``SolidModel.solve`` in a fresh process, before and after.
"""

from __future__ import annotations

import dataclasses
import weakref

import pytest

from mechverify.fea import assembly, isoparametric, mesh, solid
from mechverify.fea import recovery as rc
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Named, Plane


def _model(curved: bool) -> solid.SolidModel:
    m = mesh.box(("60 mm", "10 mm", "10 mm"), (6, 2, 2))
    if curved:  # the isoparametric path, on straight mid-side nodes given as "curved" ones
        m = dataclasses.replace(m, curved=m.basis.doflocs.copy())
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("xmin")),),
                            loads=(Force(Plane(x="60 mm"), ("0 N", "0 N", "-100 N")),))


@pytest.mark.parametrize("curved", [False, True], ids=["straight", "curved"])
def test_element_blocks_are_freed_before_the_solve(monkeypatch, curved):
    refs: list[weakref.ref] = []
    # straight elements: the per-element table the blocks are made from (the blocks themselves exist a tenth at a
    # time inside assembly.assemble_elasticity)
    module, name = (isoparametric, "stiffness_blocks") if curved else (assembly, "_lame_table")
    make_blocks = getattr(module, name)

    def watched(*a, **k):
        out = make_blocks(*a, **k)
        refs.append(weakref.ref(out[0] if isinstance(out, tuple) else out))
        return out

    alive: dict[str, bool] = {}

    def during(label, fn):
        def wrapped(*a, **k):
            alive[label] = any(r() is not None for r in refs)
            return fn(*a, **k)
        return wrapped

    monkeypatch.setattr(module, name, watched)
    monkeypatch.setattr(solid, "solve", during("linear solve", solid.solve))
    monkeypatch.setattr(rc, "recover", during("recovery", rc.recover))
    monkeypatch.setattr(rc, "recover_curved", during("recovery", rc.recover_curved))
    model = _model(curved)
    assert model.is_curved is curved
    res = model.solve(method="direct", progress=False)
    assert refs, "the stiffness blocks were not built through the watched function"
    assert set(alive) == {"linear solve", "recovery"}
    assert not any(alive.values()), f"element blocks still alive during: {[k for k, v in alive.items() if v]}"
    assert res.u[:, 2].min() < 0  # the load bends the bar down: the solve ran on the assembled K


def test_plane_element_blocks_are_freed_before_the_solve(monkeypatch):
    """``PlaneModel.solve`` held its element blocks in a local through the solve and the recovery (the defect
    1de1158 removed from ``SolidModel.solve``); they die right after the assembly now."""
    from mechverify.fea import mesh2d, plane

    refs: list[weakref.ref] = []
    make_blocks = assembly.elasticity_blocks

    def watched(*a, **k):
        out = make_blocks(*a, **k)
        refs.append(weakref.ref(out))
        return out

    alive: dict[str, bool] = {}

    def during(label, fn):
        def wrapped(*a, **k):
            alive[label] = any(r() is not None for r in refs)
            return fn(*a, **k)
        return wrapped

    monkeypatch.setattr(assembly, "elasticity_blocks", watched)
    monkeypatch.setattr(plane, "solve", during("linear solve", plane.solve))
    monkeypatch.setattr(rc, "recover", during("recovery", rc.recover))
    model = plane.PlaneModel(mesh2d.rectangle(0.1, 0.02, 10, 2), "5 mm", "Structural Steel",
                             supports=(Fixed(Plane(x="0 m")),), loads=(Force(Plane(x="0.1 m"), ("0 N", "-100 N")),))
    res = model.solve()
    assert len(refs) == 1, "the stiffness blocks were not built through the watched function"
    assert set(alive) == {"linear solve", "recovery"}
    assert not any(alive.values()), f"element blocks still alive during: {[k for k, v in alive.items() if v]}"
    assert res.u[:, 1].min() < 0


@pytest.mark.parametrize("share", [1.0, 0.9, 0.5, 0.02, 0.0])
@pytest.mark.parametrize("chunk", [1, 7, 1 << 16])
def test_free_submatrix_is_scipys_slice(share, chunk):
    """``assembly.free_submatrix`` reads K[free][:, free] straight from the BSR matrix: the same CSR (indptr,
    indices, data: bit for bit, so CG and the factorisation see the same matrix) as SciPy's
    ``K.tocsr()[free][:, free]``, for any mask (whole nodes or single components held) and chunk size, and from a
    CSR input too."""
    import numpy as np

    model = _model(False)
    m = model.mesh
    K, _ = model._stiffness(assembly.block_pattern(m.basis.element_dofs, m.basis.N), *assembly.lame(200e9, 0.3))
    free = np.random.default_rng(7).random(K.shape[0]) < share
    idx = np.flatnonzero(free)
    ref = K.tocsr()[idx][:, idx]
    for A in (assembly.free_submatrix(K, free, chunk=chunk), assembly.free_submatrix(K.tocsr(), free, chunk=chunk)):
        assert A.shape == ref.shape
        assert np.array_equal(A.indptr, ref.indptr)
        assert np.array_equal(A.indices, ref.indices)
        assert np.array_equal(A.data, ref.data)


def test_linear_solve_keeps_one_copy_of_the_free_stiffness(monkeypatch):
    """``linsolve.solve`` kept a full CSR copy of K (``Kc``) beside its free part ``Kff`` until it returned, and
    built ``Kff`` with both alive (K + Kc + Kc[free] + Kff): at the factorisation (or CG) 2.05 x Kff's bytes were
    alive beyond the caller's K, the peak was 3.08 x; then 1.03 x and 2.06 x (tracemalloc, a 12k-DOF bar of
    24 x 4 x 4 cells; this test's 6 x 2 x 2 bar: 2.15 x alive before). The lug's peak at 47k DOF: 288 -> 234 MB.
    Since ``assembly.free_submatrix`` reads Kff from K without a CSR copy the peak on the 12k bar is 1.3 x (its
    work arrays are bounded by a chunk of blocks; on this small bar one chunk holds all: 2.1 x)."""
    import tracemalloc

    import numpy as np

    from mechverify.fea import factor, linsolve

    model = _model(False)
    m = model.mesh
    lam, mu = assembly.lame(200e9, 0.3)
    K, _ = model._stiffness(assembly.block_pattern(m.basis.element_dofs, m.basis.N), lam, mu)
    f = np.zeros(K.shape[0])
    f[-1] = 1.0
    seen: dict[str, tuple[int, int] | int] = {}
    factorize = factor.factorize

    def spy(A, *a, **k):
        seen["memory"] = tracemalloc.get_traced_memory()
        seen["Kff"] = A.data.nbytes + A.indices.nbytes + A.indptr.nbytes
        return factorize(A, *a, **k)

    monkeypatch.setattr(factor, "factorize", spy)
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        u, _ = linsolve.solve(K, f, model._held(), model.nodes, method="direct")
    finally:
        tracemalloc.stop()
    (current, peak), kff = seen["memory"], seen["Kff"]
    assert (current - base) / kff < 1.5, f"{(current - base) / kff:.2f} x Kff alive at the factorisation"
    assert (peak - base) / kff < 2.5, f"peak {(peak - base) / kff:.2f} x Kff while Kff was built"
    assert u[-1] > 0  # the unit force along +z at the last node moves it along +z


def test_assembly_without_all_element_blocks():
    """``assembly.assemble_elasticity`` sums the element blocks a tenth at a time (:data:`PAIRS_PER_CHUNK` local
    node pairs): the same K as ``assemble_blocks(elasticity_blocks(...))`` (the same terms summed in the same order
    per block; the chunked matrix product may round differently in the last bit) at about half the peak memory.
    Measured with tracemalloc, peak beyond the inputs over K's data: 3.35 -> 1.85 on this 24 x 4 x 4 bar, 3.48 ->
    1.89 at 84k DOF; the 203k-DOF lug's solve 716 -> ... MB peak RSS (benchmarks/fea_memory.py)."""
    import tracemalloc

    import numpy as np

    m = mesh.box(("60 mm", "10 mm", "10 mm"), (24, 4, 4))
    p, t = m.mesh.p, m.mesh.t
    pattern = assembly.block_pattern(m.basis.element_dofs, m.basis.N)
    lam, mu = assembly.lame(200e9, 0.3)
    tracemalloc.start()
    try:
        K0 = assembly.assemble_blocks(assembly.elasticity_blocks(p, t, lam, mu), pattern, 3)
        whole = tracemalloc.get_traced_memory()[1]
        tracemalloc.reset_peak()
        base = tracemalloc.get_traced_memory()[0]
        K1 = assembly.assemble_elasticity(p, t, lam, mu, pattern)
        chunked = tracemalloc.get_traced_memory()[1] - base
    finally:
        tracemalloc.stop()
    assert np.array_equal(K0.indptr, K1.indptr) and np.array_equal(K0.indices, K1.indices)
    assert np.abs(K1.data - K0.data).max() <= 1e-14 * np.abs(K0.data).max()
    assert whole / K0.data.nbytes > 3.0, "the reference (all blocks at once) should need over 3 x K's data"
    assert chunked / K1.data.nbytes < 2.2, f"{chunked / K1.data.nbytes:.2f} x K's data at the peak"


@pytest.mark.parametrize("method", ["amg", "direct"])
def test_stiffness_is_freed_during_the_linear_solve(monkeypatch, method):
    """``SolidModel.solve`` hands K over to ``linsolve.solve``, which drops it once K's free part exists; the
    reactions use K's held rows only (``assembly.held_rows``). K (0.7 kB/DOF) was alive through the multigrid setup
    and CG, the peak of the 203k-DOF lug's solve. The reactions and displacements are those of the full K."""
    import numpy as np

    from mechverify.fea import factor, linsolve

    refs: list[weakref.ref] = []
    assemble = assembly.assemble_elasticity

    def watched(*a, **k):
        out = assemble(*a, **k)
        refs.append(weakref.ref(out))
        return out

    alive: dict[str, bool] = {}

    def during(label, fn):
        def wrapped(*a, **k):
            alive[label] = any(r() is not None for r in refs)
            return fn(*a, **k)
        return wrapped

    monkeypatch.setattr(assembly, "assemble_elasticity", watched)
    monkeypatch.setattr(linsolve, "pmg_preconditioner", during("multigrid setup", linsolve.pmg_preconditioner))
    monkeypatch.setattr(factor, "factorize", during("factorisation", factor.factorize))
    model = _model(False)
    res = model.solve(method=method, progress=False)
    assert len(refs) == 1 and alive, "K was not assembled or the solve was not watched"
    assert not any(alive.values()), f"K still alive during: {[k for k, v in alive.items() if v]}"
    # the reactions from K's held rows balance the load and equal those of the whole K
    m = model.mesh
    K, measure = model._stiffness(assembly.block_pattern(m.basis.element_dofs, m.basis.N),
                                  *assembly.lame(model.material.E.m_as("Pa"), model.material.nu.m_as("")))
    u = res.u.ravel()
    f = model._load_vector(measure)
    held = model._held()
    assert np.allclose(res.reaction.m_as("N") if hasattr(res.reaction, "m_as") else res.reaction,
                       -f.reshape(-1, 3).sum(axis=0), rtol=1e-9, atol=1e-9 * np.abs(f).sum())
    r_full = solid.nodal_reactions(K, u, f, held)
    r_rows = solid.nodal_reactions(assembly.held_rows(K, held), u, f, held)
    assert np.array_equal(r_full, r_rows)


def test_memory_refusal_knows_the_analyses():
    """``study.require_memory`` (solid_fea's check before meshing) takes the most demanding of the study's analyses:
    a block that fits the static solve (3.5 kB per unknown) is refused for buckling (a factorisation, whose factor
    grows as n^(1/3) per unknown) with the analysis named, and the size it offers fits (hand check against the
    module's own rules: ``modal.memory_estimate``; not a published value)."""
    from mechverify.errors import ModelError
    from mechverify.fea import modal, study

    memory = 16e9
    volume, h = 0.1 * 0.1 * 0.1, 0.75e-3  # ~95 million unknowns at 40 V/h^3
    n = study.estimate_dofs(volume, h)
    avail = memory * study.MEMORY_SHARE
    assert n * study.BYTES_PER_DOF > avail  # the static solve alone is too big: refused, named "static"
    with pytest.raises(ModelError, match=r"\(static analysis\)"):
        study.require_memory(volume, h, "components.block", memory=memory)
    h = 2.8e-3  # 1.8 million unknowns: static 6.4 GB and modal (LOBPCG) 9.0 GB fit 12.8 GB, buckling's 52 GB does not
    n = study.require_memory(volume, h, "components.block", memory=memory)
    assert n * study.BYTES_PER_DOF <= avail
    with pytest.raises(ModelError, match=r"\(buckling analysis\).*largest mesh that fits has about ([\d,]+) unknowns"
                       ) as err:
        study.require_memory(volume, h, "components.block", memory=memory, analyses=("static", "buckling"))
    n_max = int(err.value.args[0].split("largest mesh that fits has about ")[1].split(" ")[0].replace(",", ""))
    need, worst = study.analysis_bytes(n_max, ("static", "buckling"))
    assert worst == "buckling" and need <= avail < study.analysis_bytes(n_max + 1, ("static", "buckling"))[0]
    direct = "cholmod" if modal.cholmod_available() else "superlu"
    assert need == modal.memory_estimate(n_max, 3, 10, direct)
    # modal falls back to LOBPCG (no factor): it needs more than the static solve but fits here
    need_modal, worst = study.analysis_bytes(n, ("static", "modal"))
    assert worst == "modal" and need_modal == modal.memory_estimate(n, 3, 10, "lobpcg") > n * study.BYTES_PER_DOF
    assert study.require_memory(volume, h, "components.block", memory=memory, analyses=("modal",)) == n
    with pytest.raises(Exception, match="analyses"):
        study.analysis_bytes(10, ("thermal",))


def test_curved_assembly_by_element_chunks(monkeypatch):
    """Curved elements' blocks are formed a chunk of elements at a time (``assembly.assemble_element_chunks``;
    all at once the assembly peaked at 5.8 kB per DOF on a 473k-DOF cylinder, now 0.8, tracemalloc): the same K as
    one ``assemble_blocks`` of all blocks up to the order of the additions, whatever the chunk size."""
    import numpy as np

    model = _model(True)
    m, b = model.mesh.mesh, model.mesh.basis
    pattern = assembly.block_pattern(b.element_dofs, b.N)
    lam, mu = assembly.lame(200e9, 0.3)
    blocks, measure = isoparametric.stiffness_blocks(model.nodes, b.element_dofs, lam, mu)
    K0 = assembly.assemble_blocks(blocks, pattern, 3)
    calls = []

    def count(*a, **k):
        calls.append(a[1].shape[1])
        return stiffness(*a, **k)

    stiffness = isoparametric.stiffness_blocks
    monkeypatch.setattr(isoparametric, "stiffness_blocks", count)
    for chunk in (1, 7, 10_000):
        calls.clear()
        K1 = assembly.assemble_element_chunks(
            lambda e0, e1: isoparametric.stiffness_blocks(model.nodes, b.element_dofs[:, e0:e1], lam, mu)[0],
            pattern, 3, m.nelements, elements=chunk)
        assert calls == [min(chunk, m.nelements - e0) for e0 in range(0, m.nelements, chunk)]
        assert np.array_equal(K0.indices, K1.indices)
        assert np.abs(K1.data - K0.data).max() <= 1e-14 * np.abs(K0.data).max()
    K2, measure2 = model._stiffness(pattern, lam, mu)
    assert np.abs(K2.data - K0.data).max() <= 1e-14 * np.abs(K0.data).max()
    assert np.allclose(measure2, measure, rtol=1e-14)


def test_shared_solve_keeps_only_the_held_rows():
    """``study.SharedSolve`` keeps K's held rows (the reactions), not the whole K, beside Kff and the factorisation;
    the load cases solved on it give the reactions and displacements of a plain solve."""
    import numpy as np

    from mechverify.fea import study

    model = _model(False)
    shared = study.SharedSolve.of(model, "direct")
    held = model._held()
    assert shared.K.shape == (model.mesh.n_dofs,) * 2
    assert np.array_equal(np.unique(shared.K.tocoo().row), held)  # rows at the held DOFs only
    a = model.solve(method="direct", progress=False)
    b = model.solve(factorization=shared, progress=False)
    assert np.allclose(b.u, a.u, rtol=0, atol=1e-12 * np.abs(a.u).max())
    ra, rb = (np.asarray(getattr(r.reaction, "magnitude", r.reaction)) for r in (a, b))
    assert np.allclose(rb, ra, rtol=1e-9, atol=1e-9 * np.abs(ra).max())
