"""Tetrahedron quality and sliver removal (issue 23: the thin plate's sliver held multigrid CG at 203 iterations).

Sources: the radius ratio of the regular tetrahedron is 1 by construction (Shewchuk 2002, "What is a good linear
finite element?"); for the corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) it is a hand calculation from
r_in = 3V/S = 1/(3 + sqrt 3) and R = sqrt(3)/2 (the circumsphere of the unit cube's corner): 3 r_in / R = sqrt(3) - 1
(not a printed value). The plate's deflection is bounded by two closed forms (hand calculation, not printed values):
the Euler-Bernoulli cantilever, u = F a^3 / (3 E I) + (L - a) F a^2 / (2 E I) at the free end for a load at a = 150 mm,
with E (a beam: free to contract sideways) and with E / (1 - nu^2) (a plate strip in cylindrical bending); a 3D model
of a 100 mm wide, 6 mm thick plate lies between them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechverify.fea import mesh, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.meshquality import SLIVER_QUALITY, remove_slivers, tet_quality
from mechverify.fea.regions import Named


def test_radius_ratio_closed_forms():
    """Regular tetrahedron 1; the unit corner tetrahedron sqrt(3) - 1 (hand calculation above); a flat one 0; the
    measure does not change with scale, rotation or vertex order."""
    regular = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], float).T
    corner = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float).T
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], float).T
    t = np.arange(4)[:, None]
    assert tet_quality(regular, t)[0] == pytest.approx(1.0, rel=1e-12)
    assert tet_quality(corner, t)[0] == pytest.approx(math.sqrt(3) - 1, rel=1e-12)  # 0.7320508
    assert tet_quality(flat, t)[0] == 0.0
    c, s = math.cos(0.3), math.sin(0.3)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    assert tet_quality(7.5e-3 * R @ corner, np.array([[2], [0], [3], [1]]))[0] == pytest.approx(math.sqrt(3) - 1)


def octahedron_with_sliver(eps: float = 1e-3) -> tuple[np.ndarray, np.ndarray]:
    """A nearly flat square A B C D (A and C raised by eps, B and D lowered) between apexes N (above) and S (below):
    the sliver ABCD, N on its upper faces ABC and ACD, S on its lower faces ABD and BCD (5 tetrahedra)."""
    p = np.array([[1, 0, eps], [0, 1, -eps], [-1, 0, eps], [0, -1, -eps], [0, 0, 1], [0, 0, -1]], float).T
    A, B, C, D, N, S = range(6)
    t = np.array([[A, B, C, D], [A, B, C, N], [A, C, D, N], [A, B, D, S], [B, C, D, S]]).T
    return p, t


def boundary(t: np.ndarray) -> set[tuple[int, ...]]:
    """The faces that belong to one tetrahedron only (sorted vertex triples)."""
    count: dict[tuple[int, ...], int] = {}
    for tet in t.T.tolist():
        for o in range(4):
            f = tuple(sorted(tet[:o] + tet[o + 1:]))
            count[f] = count.get(f, 0) + 1
    return {f for f, k in count.items() if k == 1}


def volume(p: np.ndarray, t: np.ndarray) -> float:
    a, b, c, d = (p[:, t[k]] for k in range(4))
    return float(np.abs(np.einsum("ie,ie->e", np.cross(b - a, c - a, axis=0), d - a)).sum() / 6)


def test_edge_removal_takes_out_a_sliver_and_keeps_the_boundary():
    """The sliver's raised diagonal AC has three tetrahedra around it (the sliver and N's two): the 3-2 flip leaves
    ABDN and CBDN, so the octahedron is split along BD on both sides (4 tetrahedra, no new vertex)."""
    p, t = octahedron_with_sliver()
    assert tet_quality(p, t).min() < 1e-2  # the premise: a sliver
    fixed = remove_slivers(p, t)
    assert (fixed.removed, fixed.left, fixed.t.shape[1], fixed.p.shape[1]) == (1, 0, 4, 6)
    assert fixed.worst_after > 0.5 and fixed.worst_before == pytest.approx(tet_quality(p, t).min())
    assert boundary(fixed.t) == boundary(t)
    assert volume(fixed.p, fixed.t) == pytest.approx(volume(p, t), rel=1e-12)
    assert not any({0, 2} <= set(tet) for tet in fixed.t.T.tolist())  # the edge AC is gone


def test_protected_edges_are_kept():
    """An edge in ``protect`` (an edge of a named surface) is never removed: with AC and BD protected the sliver
    stays and is counted as left."""
    p, t = octahedron_with_sliver()
    fixed = remove_slivers(p, t, protect=[(2, 0), (1, 3)])
    assert (fixed.removed, fixed.left) == (0, 1)
    assert np.array_equal(fixed.t, t)


def thin_plate(h: float, order: int) -> tuple[mesh.SolidMesh, mesh.SolidMesh]:
    """The benchmark's thin plate (benchmarks/ccx_common.PLATE: 200 x 100 x 6 mm, 20 mm hole at (150, 50) mm) meshed
    by gmsh with element size ``h``; the mesh read without and with the sliver repair."""
    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        block = occ.addBox(0, 0, 0, 0.2, 0.1, 0.006)
        occ.cut([(3, block)], [(3, occ.addCylinder(0.15, 0.05, -0.01, 0, 0, 0.026, 0.01))])
        occ.synchronize()
        clamp, wall = [], []
        for _, tag in gmsh.model.getEntities(2):
            com = occ.getCenterOfMass(2, tag)
            if abs(com[0]) < 1e-9:
                clamp.append(tag)
            elif abs(com[0] - 0.15) < 1e-6 and abs(com[1] - 0.05) < 1e-6:
                wall.append(tag)
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, clamp), "clamp")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, wall), "hole")
        gmsh.model.addPhysicalGroup(3, [e[1] for e in gmsh.model.getEntities(3)])
        gmsh.model.mesh.generate(3)
        if order == 2:
            mesh.second_order(gmsh)
        return mesh.from_gmsh_model(gmsh, repair=False), mesh.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


@pytest.mark.parametrize("order", [1, 2])
def test_thin_plate_sliver_is_repaired(order):
    """The 67k-DOF benchmark plate's geometry at h = 10 mm (11k DOF): gmsh leaves two slivers (quality 1.4e-3,
    each spanning the thickness across a vertical quadrilateral); read with the repair the worst is above
    SLIVER_QUALITY, the boundary facets, named regions and volume are gmsh's, and the repaired plate solves the same
    (to 1e-4) in far fewer CG iterations (134 -> 72 measured). order 2: gmsh's curved second-order mesh, the new
    interior edges straight."""
    pytest.importorskip("gmsh")
    raw, fixed = thin_plate(0.01, order)
    assert raw.worst_quality < 0.01  # the premise: gmsh's mesh has a sliver
    assert fixed.worst_quality >= SLIVER_QUALITY and fixed.slivers_removed >= 1
    assert raw.sliver_warning() and "sliver" in raw.sliver_warning() and fixed.sliver_warning() is None
    nv = raw.mesh.nvertices
    assert np.array_equal(fixed.mesh.p[:, :nv], raw.mesh.p)  # gmsh's vertices kept, new ones appended
    bf = lambda m: {tuple(sorted(f)) for f in m.mesh.facets[:, m.mesh.boundary_facets()].T.tolist()}  # noqa: E731
    assert bf(fixed) == bf(raw)
    assert {k: v.tolist() for k, v in fixed.named.items()} == {k: v.tolist() for k, v in raw.named.items()}
    assert volume(fixed.mesh.p, fixed.mesh.t) == pytest.approx(volume(raw.mesh.p, raw.mesh.t), rel=1e-12)
    if order == 2:  # gmsh's mid-side node on every edge gmsh made; the midpoint on the repair's new edges
        def mids(m: mesh.SolidMesh) -> dict[tuple[int, int], tuple[float, ...]]:
            e = np.sort(m.mesh.edges, axis=0)
            return {(int(i), int(j)): tuple(m.curved[:, m.mesh.nvertices + k]) for k, (i, j) in enumerate(e.T)}

        old, new = mids(raw), mids(fixed)
        made = [e for e in new if e not in old]
        assert made and all(new[e] == old[e] for e in new if e in old)
        P = fixed.mesh.p
        assert all(np.allclose(new[e], (P[:, e[0]] + P[:, e[1]]) / 2, rtol=0, atol=1e-15) for e in made)
    results = []
    for m in (raw, fixed) if order == 1 else (fixed,):  # the curved raw solve adds nothing but time
        model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("clamp")),),
                                 loads=(Force(Named("hole"), ("0 N", "0 N", "-500 N")),))
        results.append(model.solve(method="amg", progress=False))
    r_fix = results[-1]
    assert r_fix.info.worst_quality == pytest.approx(fixed.worst_quality)
    assert not any("sliver" in w for w in r_fix.warnings)
    u_fix = float(np.abs(r_fix.u).max())
    if order == 1:
        r_raw = results[0]
        assert r_fix.info.iterations < 0.7 * r_raw.info.iterations
        assert any("sliver" in w for w in r_raw.warnings)
        assert u_fix == pytest.approx(float(np.abs(r_raw.u).max()), rel=1e-4)
    E, nu, F, a, L, b, th = 200e9, 0.3, 500.0, 0.15, 0.2, 0.1, 0.006
    I = b * th**3 / 12
    beam = F * a**3 / (3 * E * I) + (L - a) * F * a**2 / (2 * E * I)  # 2.344 mm
    assert beam * (1 - nu**2) < u_fix < beam  # 2.133 mm < 2.2435 mm (measured) < 2.344 mm
