"""Plane and plate models: unsupported models name the free motion, bolt-hole supports, self-weight,
equilibrium, export."""

import meshio
import numpy as np
import pytest
from shapely.geometry import box as shapely_box

from mechverify.components import plates as P
from mechverify.errors import InputError, ModelError
from mechverify.fea import mesh2d
from mechverify.fea.loads import Fixed, Force, Gravity, Restraint
from mechverify.fea.plane import PlaneModel
from mechverify.fea.plate import check_plate_supported, solve_plate
from mechverify.fea.regions import Box, Plane


def strip():
    return mesh2d.rectangle(0.1, 0.02, 10, 2)


def test_plane_unsupported_names_free_motion():
    model = PlaneModel(strip(), "5 mm", "Structural Steel", supports=(Restraint(Plane(x="0 m"), x=True),),
                       loads=(Force(Plane(x="100 mm"), ("100 N", "0 N")),))
    with pytest.raises(ModelError, match="translation along y"):
        model.solve()
    pin = Box(("0 m", "0 m"), ("0 m", "0 m"))
    model = PlaneModel(strip(), "5 mm", "Structural Steel", supports=(Fixed(pin),),
                       loads=(Force(Plane(x="100 mm"), ("100 N", "0 N")),))
    with pytest.raises(ModelError, match=r"rotation about z through \(0, 0\) mm"):
        model.solve()


def test_plane_cantilever_equilibrium_gravity_and_vtu(tmp_path):
    model = PlaneModel(strip(), "5 mm", "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                       loads=(Force(Plane(x="100 mm"), ("0 N", "-50 N")), Gravity()))
    res = model.solve()
    weight = 7850 * 9.80665 * 0.1 * 0.02 * 0.005
    assert res.reactions.m_as("N")[:2] == pytest.approx([0, 50 + weight], rel=1e-9, abs=1e-9)
    back = meshio.read(res.to_vtu(tmp_path / "p.vtu"))
    assert back.cells[0].type == "triangle6"
    res.plot(tmp_path / "p.png")
    with pytest.raises(InputError, match="no boundary edge"):
        PlaneModel(strip(), "5 mm", "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                   loads=(Force(Plane(x="50 mm"), ("1 N", "0 N")),)).solve()


def test_plate_rigid_motions_named():
    pts = np.array([[0.0, 0.1], [0.0, 0.0]])  # two points on y = 0
    with pytest.raises(ModelError, match=r"rotation about the line y = 0 mm \(along x\)\."):  # rounded: fea.motions
        check_plate_supported(pts, np.zeros((2, 0)))
    with pytest.raises(ModelError, match="translation along z"):
        check_plate_supported(np.zeros((2, 0)), np.array([[1.0], [0.0]]))
    check_plate_supported(np.array([[0.0, 0.1, 0.0], [0.0, 0.0, 0.1]]), np.zeros((2, 0)))


def test_plate_on_two_corner_points_fails_clearly():
    plate = P.Plate.rectangle("200 mm", "100 mm", "4 mm", "Inventor Aluminum 6061")
    model = P.PlateModel(plate, supports=(P.PointSupport(("0 mm", "0 mm")), P.PointSupport(("200 mm", "0 mm"))),
                         loads=(P.PressureLoad("-1 kPa"),))
    with pytest.raises(ModelError, match="rotation about the line"):
        solve_plate(model, mesh_size="20 mm")


def test_bolted_plate_with_cutout_self_weight_and_point_loads(tmp_path):
    """An arm-support plate like the one of seed 004 (335 x 160 mm, 6 mm aluminium, four corner bolts,
    a lightening cut-out): reactions balance 2 x 120 N plus the plate's weight."""
    pytest.importorskip("gmsh")
    holes = P.corner_holes("335 mm", "160 mm", "15 mm", "6.5 mm")
    plate = P.Plate.rectangle("335 mm", "160 mm", "6 mm", "Inventor Aluminum 6061", holes=holes,
                              cutouts=[[("120 mm", "50 mm"), ("215 mm", "50 mm"), ("215 mm", "110 mm"),
                                        ("120 mm", "110 mm")]])
    loads = (P.PlatePointLoad(("60 mm", "80 mm"), "-120 N"), P.PlatePointLoad(("275 mm", "80 mm"), "-120 N"), P.PlateSelfWeight())
    model = P.PlateModel(plate, supports=(P.HoleSupport("all", "clamped", washer_diameter="12 mm"),), loads=loads)
    res = solve_plate(model, mesh_size="10 mm")
    weight = plate.weight.m_as("N")
    assert res.reactions.m_as("N")[2] == pytest.approx(240 + weight, rel=1e-6)
    assert res.max_displacement.value.m_as("mm") > 0
    assert res.min_safety_factor().value.m > 1
    res.plot(tmp_path / "plate.png")
    assert shapely_box(0, 0, 0.335, 0.16).contains(plate.region)


def test_pin_load_bears_on_the_near_half_only():
    """A 2D link, pin hole A held, pin B pulled along +x by 1 kN: the load is exactly 1 kN, all of it on
    the half of hole B's wall towards +x, and the reactions balance it."""
    pytest.importorskip("gmsh")
    from shapely.geometry import Point

    from mechverify.fea.loads import PinLoad
    from mechverify.fea.plane import mesh_region
    from mechverify.fea.regions import Cylinder

    region = shapely_box(0, 0, 0.1, 0.03).difference(Point(0.015, 0.015).buffer(0.004, 32)).difference(
        Point(0.085, 0.015).buffer(0.004, 32))
    model = PlaneModel(mesh_region(region, "4 mm", "1 mm"), "5 mm", "Structural Steel",
                       supports=(Fixed(Cylinder(("15 mm", "15 mm"), "4 mm")),),
                       loads=(PinLoad(Cylinder(("85 mm", "15 mm"), "4 mm"), ("1 kN", "0 N")),))
    _, area = __import__("mechverify.fea.assembly", fromlist=["x"]).barycentric_gradients(model.mesh.p, model.mesh.t)
    f = model.load_vector(area).reshape(-1, 2)
    assert f.sum(axis=0) == pytest.approx([1000, 0], abs=1e-9)
    x = model.basis.doflocs
    loaded = np.abs(f).sum(axis=1) > 0
    assert np.all(x[0, loaded] >= 0.085 - 1e-9)
    res = model.solve()
    assert res.reactions.m_as("N")[:2] == pytest.approx([-1000, 0], abs=1e-6)
    with pytest.raises(InputError):
        PinLoad(Cylinder(("85 mm", "15 mm"), "4 mm"), ("0 N", "0 N"))


def _clockwise(m):
    a, b, c = (m.p[:, m.t[k]] for k in range(3))
    return int(np.sum((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0))


def test_2d_meshes_stay_counter_clockwise():
    """Issue 26: scikit-fem's MeshTri sorts each triangle's vertices by default, which left 4 of the 8
    triangles of rectangle(1, 1, 2, 2) clockwise (CalculiX rejects them: "nonpositive jacobian")."""
    from skfem import MeshTri

    assert _clockwise(mesh2d.rectangle(1, 1, 2, 2)) == 0
    sorted_mesh = MeshTri(mesh2d.rectangle(1, 1, 2, 2).p, mesh2d.rectangle(1, 1, 2, 2).t)
    assert _clockwise(sorted_mesh) == 4  # what scikit-fem does by default: the defect this guards
    model = PlaneModel(sorted_mesh.with_boundaries({"left": lambda x: x[0] == 0}), "1 mm", "Structural Steel")
    assert _clockwise(model.mesh) == 0
    assert model.mesh.boundaries["left"].size == 2
