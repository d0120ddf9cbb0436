"""Regions report what they caught and warn when it is not what was meant (issue 26, finding 4);
gmsh physical groups of every dimension as named regions in 2D and 3D; arcs and general curves.

Expected values are geometry by hand (edge lengths of a structured mesh, arc and ellipse lengths,
face areas), not printed values. The partial-catch case is the one of the issue: a load region
that catches only part of the intended edge was accepted silently.
"""

import numpy as np
import pytest
from shapely.geometry import Point
from shapely.geometry import box as shapely_box

from mechverify.errors import InputError
from mechverify.fea import mesh, mesh2d, solid
from mechverify.fea.loads import Fixed, Force, Pressure, Restraint
from mechverify.fea.plane import PlaneModel, mesh_region
from mechverify.fea.regions import Arc, Box, Named, Plane, Polyline
from mechverify.units import Q


def strip_model(nx, **kw):
    m = mesh2d.rectangle(0.1, 0.02, nx, 4)
    return PlaneModel(m, "1 mm", "Structural Steel", supports=(Fixed(Plane(x="0 m"), expect_length="20 mm"),),
                      loads=(Pressure(Box(("30 mm", "20 mm"), ("70 mm", "20 mm")), "1 MPa", **kw),))


def test_partial_edge_is_reported_and_warned():
    # 12 cells of 8.33 mm: the edges with both ends in 30..70 mm span 33.3..66.7 mm, 83 % of 40 mm
    res = strip_model(12, expect_length="40 mm").solve()
    load, support = res.regions
    assert load.count == 4 and load.measure == pytest.approx(0.1 / 3)
    assert load.resultant[1] == pytest.approx(-1e6 * 0.1 / 3 * 1e-3)  # p * caught length * t
    assert support.count == 9 and support.measure == pytest.approx(0.02) and support.warning is None
    assert support.resultant[1] == pytest.approx(-load.resultant[1])
    assert len(res.warnings) == 1 and "83.3 % of the expected 40 mm" in res.warnings[0]
    assert res.summary()["warnings"] == list(res.warnings)


def test_whole_edge_gives_no_warning():
    res = strip_model(10, expect_length="40 mm").solve()
    assert res.warnings == () and res.regions[0].measure == pytest.approx(0.04)
    with pytest.raises(InputError, match="expect_length"):
        Pressure(Plane(x="0 m"), "1 MPa", expect_length="-1 mm")


def quarter_plate():
    """A 40 x 20 mm quarter of a plate with a 10 mm radius hole at the origin (the rim is an arc)."""
    shape = shapely_box(0, 0, 0.04, 0.02).difference(Point(0, 0).buffer(0.01, 256))
    return mesh_region(shape, "3 mm", "1 mm")


def test_arc_catches_the_hole_rim_and_knows_its_length():
    m = quarter_plate()
    arc = Arc(("0 mm", "0 mm"), "10 mm", 0, 90)
    assert arc.measure(2) == pytest.approx(0.01 * np.pi / 2)
    model = PlaneModel(m, "1 mm", "Structural Steel",
                       supports=(Restraint(Plane(x="0 m"), x=True), Restraint(Plane(y="0 m"), y=True)),
                       loads=(Pressure(arc, "10 MPa"),))
    rep = model.region_reports()[0]
    assert rep.warning is None and rep.measure == pytest.approx(0.01 * np.pi / 2, rel=0.005)
    # internal pressure on the quarter rim: resultant p r t (1, 1) pushing into the body (x, y < 0 walls)
    assert rep.resultant == pytest.approx((1e7 * 0.01 * 1e-3, 1e7 * 0.01 * 1e-3), rel=1e-3)
    half = Arc(("0 mm", "0 mm"), "10 mm", 0, 180)  # the other half is not in the model: warned
    rep = PlaneModel(m, "1 mm", "Structural Steel", supports=model.supports,
                     loads=(Pressure(half, "10 MPa"),)).region_reports()[0]
    assert "50.0 % of the expected" in rep.warning


def test_polyline_follows_an_ellipse():
    """An elliptic edge (the outer boundary of NAFEMS LE1's quarter membrane, a = 3.25 m, b = 2.75 m)
    sampled as a polyline: the region catches the whole curve and its length is the ellipse's
    (Ramanujan's approximation of the quarter perimeter, hand calculation)."""
    a, b = 3.25, 2.75
    th = np.linspace(0, np.pi / 2, 400)
    curve = Polyline(Q(np.column_stack([a * np.cos(th), b * np.sin(th)]), "m"), tol="1 mm")
    h = ((a - b) / (a + b)) ** 2
    quarter = np.pi * (a + b) * (1 + 3 * h / (10 + np.sqrt(4 - 3 * h))) / 4
    assert curve.measure(2) == pytest.approx(quarter, rel=1e-5)
    pts = np.array([[a, 0.0, 2.0, 0.0], [0.0, b, 2.0, 1.0]])
    assert curve.contains(pts, 0.0).tolist() == [True, True, False, False]


def gmsh_plate_2d():
    """A 2D gmsh model: 100 x 50 mm plate with physical curves 'left', 'right' and a point 'origin'."""
    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, 0.01)
    try:
        occ = gmsh.model.occ
        occ.addRectangle(0, 0, 0, 0.1, 0.05)
        occ.synchronize()
        left, right, origin = [], [], []
        for _, tag in gmsh.model.getEntities(1):
            x = occ.getCenterOfMass(1, tag)[0]
            (left if abs(x) < 1e-9 else right if abs(x - 0.1) < 1e-9 else []).append(tag)
        for _, tag in gmsh.model.getEntities(0):
            if np.allclose(gmsh.model.getValue(0, tag, []), 0):
                origin.append(tag)
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, left), "left")
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, right), "right")
        gmsh.model.setPhysicalName(0, gmsh.model.addPhysicalGroup(0, origin), "origin")
        gmsh.model.addPhysicalGroup(2, [e[1] for e in gmsh.model.getEntities(2)])
        gmsh.model.mesh.generate(2)
        return mesh2d.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def test_named_curves_and_points_in_2d():
    pytest.importorskip("gmsh")
    m = gmsh_plate_2d()
    assert m.measures == pytest.approx({"left": 0.05, "right": 0.05})
    model = PlaneModel(m, "2 mm", "Structural Steel",
                       supports=(Restraint(Named("left"), x=True), Restraint(Named("origin"), y=True)),
                       loads=(Force(Named("right"), ("1000 N", "0 N")),))
    res = model.solve()
    assert res.warnings == ()
    right, left, origin = res.regions
    assert right.measure == pytest.approx(0.05) and right.resultant == pytest.approx((1000, 0))
    assert left.resultant[0] == pytest.approx(-1000) and origin.count == 1
    # uniform tension: u_x = F L / (E A) at the loaded edge (hand calculation)
    E = 200e9
    assert res.u[:, 0].max() == pytest.approx(1000 * 0.1 / (E * 0.05 * 0.002), rel=0.01)
    with pytest.raises(InputError, match="set of points"):
        PlaneModel(m, "2 mm", "Structural Steel", supports=model.supports,
                   loads=(Force(Named("origin"), ("1 N", "0 N")),)).solve()


def gmsh_block_3d():
    """A 100 x 20 x 20 mm block with a physical surface 'end', a physical curve 'edge' (the bottom edge
    at x = 0 along y) and a physical point 'corner' at the origin."""
    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, 0.01)
    try:
        occ = gmsh.model.occ
        vol = occ.addBox(0, 0, 0, 0.1, 0.02, 0.02)
        occ.synchronize()
        end = [t for _, t in gmsh.model.getEntities(2) if abs(occ.getCenterOfMass(2, t)[0] - 0.1) < 1e-9]
        edge = [t for _, t in gmsh.model.getEntities(1)
                if np.allclose(np.array(occ.getCenterOfMass(1, t)), [0, 0.01, 0])]
        corner = [t for _, t in gmsh.model.getEntities(0) if np.allclose(gmsh.model.getValue(0, t, []), 0)]
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, end), "end")
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, edge), "edge")
        gmsh.model.setPhysicalName(0, gmsh.model.addPhysicalGroup(0, corner), "corner")
        gmsh.model.addPhysicalGroup(3, [vol])
        gmsh.model.mesh.generate(3)
        return mesh.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def test_named_groups_of_every_dimension_in_3d():
    pytest.importorskip("gmsh")
    m = gmsh_block_3d()
    assert {k: m.named_dimension(k) for k in m.named} == {"end": 2, "edge": 1, "corner": 0}
    assert m.measures == pytest.approx({"end": 4e-4, "edge": 0.02})
    nseg = m.named["edge"].shape[0]
    assert m.named_nodes("edge").size == 2 * nseg + 1  # the edge's vertices and its mid-edge nodes
    assert m.named_nodes("corner").size == 1
    model = solid.SolidModel(m, "Structural Steel",
                             supports=(Fixed(Plane(x="0 m")), Restraint(Named("edge"), z=True)),
                             loads=(Force(Named("end"), ("0 N", "0 N", "-100 N")),))
    reps = model.region_reports()
    assert reps[0].measure == pytest.approx(4e-4) and reps[0].warning is None
    assert reps[2].count == 2 * nseg + 1
    with pytest.raises(InputError, match="a curve of the mesh"):
        solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                         loads=(Force(Named("edge"), ("0 N", "0 N", "-1 N")),)).solve()


def test_solid_load_partial_area_warns():
    m = mesh.box(("100 mm", "20 mm", "20 mm"), (10, 3, 3))
    model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                             loads=(Pressure(Box(("40 mm", "0 mm", "20 mm"), ("60 mm", "10 mm", "20 mm")), "1 MPa",
                                             expect_area="200 mm**2"),))
    res = model.solve()
    rep = res.regions[0]
    # y nodes at 0, 6.67, 13.3 mm: the box up to 10 mm catches 6.67 of 10 mm in width, 20 mm in length
    assert rep.measure == pytest.approx(0.02 * 0.02 / 3) and "66.7 % of the expected 200 mm²" in rep.warning
    assert rep.resultant[2] == pytest.approx(-1e6 * 0.02 * 0.02 / 3)
    assert res.regions[1].resultant[2] == pytest.approx(1e6 * 0.02 * 0.02 / 3)


def test_traction_field_resultant_and_moment():
    """A linearly varying traction t_x = 1 MPa (y - c)/c plus a uniform t_z (t_y in 2D) on the end face:
    resultant and bending moment of the consistent nodal loads equal the integrals by hand
    (∫ t dA = t_z A; ∫ t_x (y - c) dA = 1 MPa / c · b h³/12)."""
    from mechverify.fea.loads import Traction

    m = mesh.box(("100 mm", "20 mm", "10 mm"), (5, 2, 2))
    f3 = lambda x: np.vstack([1e6 * (x[1] - 0.01) / 0.01, 0 * x[0], 0 * x[0] + 2e5])  # noqa: E731
    model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                             loads=(Traction(Plane(x="100 mm"), f3),))
    F, P = model.load_vector().reshape(-1, 3), model.mesh.points.T
    assert F.sum(axis=0) == pytest.approx([0, 0, 2e5 * 2e-4], abs=1e-9)
    assert (F[:, 0] * (P[:, 1] - 0.01)).sum() == pytest.approx(1e6 / 0.01 * 0.01 * 0.02**3 / 12)
    f2 = lambda x: np.vstack([1e6 * (x[1] - 0.01) / 0.01, 0 * x[0] + 2e5])  # noqa: E731
    p = PlaneModel(mesh2d.rectangle(0.1, 0.02, 5, 3), "1 mm", "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                   loads=(Traction(Plane(x="100 mm"), f2),))
    F, P = p.load_vector().reshape(-1, 2), p.basis.doflocs.T
    assert F.sum(axis=0) == pytest.approx([0, 2e5 * 0.02 * 1e-3], abs=1e-9)
    assert (F[:, 0] * (P[:, 1] - 0.01)).sum() == pytest.approx(1e6 / 0.01 * 1e-3 * 0.02**3 / 12)
    with pytest.raises(InputError, match="callable"):
        Traction(Plane(x="0 m"), "1 MPa")
    bad = PlaneModel(p.mesh, "1 mm", "Structural Steel", supports=p.supports,
                     loads=(Traction(Plane(x="100 mm"), lambda x: np.zeros(3)),))
    with pytest.raises(InputError, match="returned shape"):
        bad.load_vector()


def test_solid_stress_at_and_integration_points():
    """Uniform tension of a bar: σxx = F/A everywhere (hand calculation), at any point and integration point."""
    m = mesh.box(("100 mm", "20 mm", "10 mm"), (5, 2, 2))
    model = solid.SolidModel(m, "Structural Steel",
                             supports=(Restraint(Plane(x="0 m"), x=True), Restraint(Box(("0 m",) * 3, ("0 m",) * 3),
                                                                                 y=True, z=True),
                                       Restraint(Box(("0 m", "20 mm", "0 m"), ("0 m", "20 mm", "0 m")), z=True)),
                             loads=(Force(Plane(x="100 mm"), ("2000 N", "0 N", "0 N")),))
    res = model.solve()
    s = res.stress_at([("50 mm", "10 mm", "5 mm"), (0.0999, 0.0001, 0.0099)]).m_as("MPa")
    assert s[:, 0, 0] == pytest.approx([10.0, 10.0], rel=1e-6)
    assert res.integration_point_stress.m_as("MPa")[..., 0, 0] == pytest.approx(10.0, rel=1e-6)
    assert res.error_estimate < 1e-6  # the exact solution is in the P2 space: nothing to recover
    with pytest.raises(InputError, match="outside the mesh"):
        res.stress_at([("150 mm", "0 mm", "0 mm")])


def test_region_cutting_through_facets_warns_without_an_expectation():
    """The issue's silent partial catch, with nothing stated: a box edge at x = 30 mm falls inside an element
    edge (nodes at 25 and 33.3 mm), so the box catches whole edges only - warned; with nodes at 30 and
    70 mm (10 cells) nothing is cut and nothing is warned. The end-face plane and a pressure pad aligned
    with element edges in 3D give no warning; a pad edge at y = 10 mm between nodes at 6.7 and 13.3 mm does."""
    cut = strip_model(12).region_reports()[0]
    assert "cuts through 2 boundary facet(s)" in cut.warning
    assert strip_model(10).region_reports()[0].warning is None
    m = mesh.box(("100 mm", "20 mm", "20 mm"), (10, 3, 3))
    for hi, warned in (("10 mm", True), ("13.3333333333 mm", False)):
        model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                                 loads=(Pressure(Box(("40 mm", "0 mm", "20 mm"), ("60 mm", hi, "20 mm")), "1 MPa"),
                                        Force(Plane(x="100 mm"), ("1 N", "0 N", "0 N"))))
        reps = model.region_reports()
        assert (reps[0].warning is not None) is warned and reps[1].warning is None
