"""Meshes made by other tools (meshio readers) solve in mechverify as the direct model does, and VTU files open in
an independent reader (the ``vtk`` package).

Sources: a bar in tension, ``u = F L / (E A)`` (Hooke's law; Timoshenko & Gere, Mechanics of Materials, Sec. 2.2),
for the absolute check; otherwise the imported mesh must give the same solution as the same mesh built directly
(gmsh's Python API model; CalculiX deck written by mechverify.fea.calculix.write_inp). VTU: the VTK file-format
specification as implemented by vtk's vtkXMLUnstructuredGridReader.
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.errors import InputError, MechverifyError, ModelError, UnitError
from mechverify.fea import mesh as fmesh
from mechverify.fea import meshimport, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.plane import PlaneModel
from mechverify.fea.regions import Named, Plane
from mechverify.fea.vtu import write_vtu, write_vtu_own
from tests.builders import gmsh_bar

L, B = 0.1, 0.01  # bar 100 x 10 x 10 mm


def _bar_model(m):
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("fixed")),),
                            loads=(Force(Named("loaded"), ("1000 N", "0 N", "0 N")),))


def _by_position(points, values):
    order = np.lexsort(np.round(points, 12))
    return points[:, order], values[order]


@pytest.mark.parametrize(("order", "fmt"), [(2, "4.1"), (1, "2.2")])
def test_gmsh_msh_solves_like_the_direct_model(tmp_path, order, fmt):
    pytest.importorskip("gmsh")
    path, direct = gmsh_bar(tmp_path, order, fmt)
    imported = meshimport.read_solid_mesh(path)
    assert set(imported.named) == {"fixed", "loaded"}  # the volume group 'body' is not a boundary region
    assert imported.mesh.nelements == direct.mesh.nelements and imported.mesh.nvertices == direct.mesh.nvertices
    r_imp, r_dir = _bar_model(imported).solve(), _bar_model(direct).solve()
    p1, u1 = _by_position(imported.points, r_imp.u)
    p2, u2 = _by_position(direct.points, r_dir.u)
    np.testing.assert_allclose(p1, p2, atol=1e-12)
    np.testing.assert_allclose(u1, u2, atol=1e-9 * np.abs(u2).max())
    # Hooke: u = F L / (E A) at the loaded end (the clamped end's Poisson restraint stiffens by < 2 %)
    E = 200e9  # Structural Steel in the material library
    tip = r_imp.u[np.isclose(imported.points[0], L), 0].mean()
    assert tip == pytest.approx(1000 * L / (E * B * B), rel=0.02)


def test_calculix_inp_written_by_mechverify_solves_like_the_direct_model(tmp_path):
    """A CalculiX deck (C3D10, node set NFIX) from mechverify.fea.calculix.write_inp, read back with meshio."""
    from mechverify.fea.calculix import write_inp

    m = fmesh.box((f"{L} m", f"{B} m", f"{B} m"), (8, 2, 2))
    b = m.basis
    nodes, elements = m.points.T, b.element_dofs.T
    held = np.flatnonzero(np.isclose(m.points[0], 0.0))
    fixed = (3 * held[:, None] + np.arange(3)).ravel()
    path = tmp_path / "bar.inp"
    write_inp(path, nodes, elements, 200e9, 0.3, fixed, np.zeros(3 * len(nodes)))
    imported = meshimport.read_solid_mesh(path)
    assert "NFIX" in imported.named and imported.named_dimension("NFIX") == 2  # the set holds the whole face x = 0
    assert imported.mesh.nelements == m.mesh.nelements
    model_i = solid.SolidModel(imported, "Structural Steel", supports=(Fixed(Named("NFIX")),),
                               loads=(Force(Plane(x=f"{L} m"), ("1000 N", "0 N", "0 N")),))
    model_d = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                               loads=(Force(Plane(x=f"{L} m"), ("1000 N", "0 N", "0 N")),))
    r_i, r_d = model_i.solve(), model_d.solve()
    assert r_i.max_displacement.value.m_as("m") == pytest.approx(r_d.max_displacement.value.m_as("m"), rel=1e-9)


def test_plane_mesh_from_gmsh_msh(tmp_path):
    """A 2D gmsh mesh (quadratic triangles, physical curves) in a plane model: same tip displacement as the direct
    gmsh model, and u = F L / (E A t) for the bar in plane stress within 2 %."""
    pytest.importorskip("gmsh")
    gmsh = fmesh.import_gmsh()
    fmesh.gmsh_session(gmsh, 0.002)
    try:
        occ = gmsh.model.occ
        s = occ.addRectangle(0, 0, 0, L, B)
        occ.synchronize()
        curves = {round(occ.getCenterOfMass(1, t)[0], 9): t for _, t in gmsh.model.getEntities(1)}
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, [curves[0.0]]), "fixed")
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, [curves[L]]), "loaded")
        gmsh.model.addPhysicalGroup(2, [s])
        gmsh.model.mesh.generate(2)
        from mechverify.fea import mesh2d

        direct = mesh2d.from_gmsh_model(gmsh)
        gmsh.model.mesh.setOrder(2)
        path = tmp_path / "strip.msh"
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    imported = meshimport.read_mesh(path)
    assert set(imported.boundaries) == {"fixed", "loaded"}

    def tip(m):
        r = PlaneModel(m, "1 mm", "Structural Steel", supports=(Fixed(Named("fixed")),),
                       loads=(Force(Named("loaded"), ("100 N", "0 N")),)).solve()
        return r.u[np.isclose(r.points[:, 0], L), 0].mean()

    assert tip(imported) == pytest.approx(tip(direct), rel=1e-9)
    assert tip(imported) == pytest.approx(100 * L / (200e9 * B * 1e-3), rel=0.02)


def test_refused_and_bad_meshes(tmp_path):
    meshio = pytest.importorskip("meshio")
    hexa = meshio.Mesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1],
                                 [0, 1, 1]], float), [("hexahedron", np.arange(8)[None, :])])
    hexa.write(tmp_path / "hex.vtu")
    with pytest.raises(ModelError, match="hexahedron are not supported"):
        meshimport.read_solid_mesh(tmp_path / "hex.vtu")
    with pytest.raises(InputError, match="unknown mesh format"):
        meshimport.read_mesh(tmp_path / "part.stl")
    with pytest.raises(InputError, match="no such mesh file"):
        meshimport.read_mesh(tmp_path / "missing.msh")
    (tmp_path / "bad.msh").write_text("not a mesh\n")
    with pytest.raises(InputError, match="cannot read it as a Gmsh mesh"):
        meshimport.read_mesh(tmp_path / "bad.msh")
    tilted = meshio.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 1]], float), [("triangle", np.array([[0, 1, 2]]))])
    tilted.write(tmp_path / "tilted.vtu")
    with pytest.raises(ModelError, match="do not lie in a plane"):
        meshimport.read_plane_mesh(tmp_path / "tilted.vtu")


def test_meshio_missing_names_the_install(monkeypatch, tmp_path):
    import sys

    monkeypatch.setitem(sys.modules, "meshio", None)
    (tmp_path / "a.msh").write_text("")
    with pytest.raises(ModelError, match="pip install"):
        meshimport.read_mesh(tmp_path / "a.msh")


# ------------------------------------------------------------------------------------------ VTU export
def _read_vtk(path):
    vtk = pytest.importorskip("vtk")
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    types = np.array([grid.GetCellType(i) for i in range(grid.GetNumberOfCells())])
    first = grid.GetCell(0)
    ids = np.array([first.GetPointId(k) for k in range(first.GetNumberOfPoints())])
    pd = grid.GetPointData()
    data = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
    return pts, types, ids, data


@pytest.fixture(scope="module")
def solved_bar():
    m = fmesh.box((f"{L} m", f"{B} m", f"{B} m"), (6, 2, 2))
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                            loads=(Force(Plane(x=f"{L} m"), ("1000 N", "0 N", "0 N")),)).solve()


@pytest.mark.parametrize("writer", ["meshio", "own"])
def test_vtu_opens_in_vtk(tmp_path, solved_bar, writer):
    """Both writers produce a file vtk reads back: points, quadratic tetrahedra (VTK type 24) with the element's
    node order, and every field."""
    r = solved_bar
    data = {"displacement_m": r.u, "von_mises_Pa": r._vm}
    path = write_vtu(tmp_path / f"bar_{writer}.vtu", r.points, r.cells, data, writer=writer)
    pts, types, ids, got = _read_vtk(path)
    np.testing.assert_allclose(pts, r.points, rtol=0, atol=1e-15)
    assert set(types) == {24} and len(types) == len(r.cells[0][1])
    np.testing.assert_array_equal(ids, r.cells[0][1][0])
    np.testing.assert_allclose(got["displacement_m"], r.u, rtol=1e-15)
    np.testing.assert_allclose(got["von_mises_Pa"], r._vm, rtol=1e-15)


def test_results_to_vtu_and_fallback(tmp_path, solved_bar, monkeypatch):
    """FieldResults.to_vtu writes through write_vtu; with meshio broken the own writer takes over (a warning)."""
    import sys

    path = solved_bar.to_vtu(tmp_path / "r.vtu")
    _, types, _, data = _read_vtk(path)
    assert "displacement_m" in data and set(types) == {24}
    monkeypatch.setitem(sys.modules, "meshio", None)
    with pytest.warns(RuntimeWarning, match="own VTU writer"):
        path = write_vtu(tmp_path / "fallback.vtu", solved_bar.points, solved_bar.cells, {"u": solved_bar.u})
    _, types, _, data = _read_vtk(path)
    np.testing.assert_allclose(data["u"], solved_bar.u, rtol=1e-15)


def test_own_writer_2d_points(tmp_path):
    """Plane meshes: 2D points padded with z = 0, triangle6 (VTK type 22)."""
    p = np.array([[0, 0], [1, 0], [0, 1], [0.5, 0], [0.5, 0.5], [0, 0.5]], float)
    path = write_vtu_own(tmp_path / "t.vtu", p, [("triangle6", np.arange(6)[None, :])], {"s": np.arange(6.0)})
    pts, types, ids, data = _read_vtk(path)
    np.testing.assert_allclose(pts[:, :2], p) and np.testing.assert_allclose(pts[:, 2], 0)
    assert list(types) == [22] and list(ids) == list(range(6))
    np.testing.assert_allclose(data["s"], np.arange(6.0))


@pytest.mark.parametrize("suffix", [".bdf", ".vtu", ".vtk", ".inp", ".msh"])
def test_every_format_round_trip(tmp_path, suffix):
    """Each supported format: a linear tetrahedral mesh written by meshio reads back as the same mesh and solves
    to the same tip displacement as the direct model (promotion to P2 on the same vertices)."""
    meshio = pytest.importorskip("meshio")
    m = fmesh.box((f"{L} m", f"{B} m", f"{B} m"), (6, 2, 2))
    path = tmp_path / f"bar{suffix}"
    fmt = {".msh": "gmsh22", ".bdf": "nastran", ".inp": "abaqus", ".vtu": "vtu", ".vtk": "vtk"}[suffix]
    meshio.Mesh(m.mesh.p.T, [("tetra", m.mesh.t.T)]).write(path, file_format=fmt)
    imported = meshimport.read_solid_mesh(path)
    assert imported.mesh.nelements == m.mesh.nelements and imported.mesh.nvertices == m.mesh.nvertices

    def tip(mesh):
        r = solid.SolidModel(mesh, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                             loads=(Force(Plane(x=f"{L} m"), ("1000 N", "0 N", "0 N")),)).solve()
        return r.max_displacement.value.m_as("m")

    assert tip(imported) == pytest.approx(tip(m), rel=1e-9)


# ------------------------------------------------------------------ review findings 12, 35 (round 2 session 3)
def test_gmsh_second_order_inp_solves_and_a_volume_group_is_named(tmp_path):
    """gmsh's P2 Abaqus export (CPS6 triangles; meshio 5.3 alone refuses CPS6) is read; the bar in tension
    stretches u = F L / (E A) = 1000 · 0.1 / (200e9 · 1e-4) = 5.0e-6 m (Hooke's law, Timoshenko & Gere, Mechanics
    of Materials, sec. 2.2; hand calculation). The volume group 'body' used as a region is named as a volume group
    with the regions."""
    pytest.importorskip("gmsh")
    m = meshimport.read_solid_mesh(gmsh_bar(tmp_path, suffix=".inp", name="bar_p2.inp")[0])
    assert {"fixed", "loaded"} <= set(m.named) and "body" not in m.named and "body" in m.volumes
    res = _bar_model(m).solve()
    ux = res.u[np.argmax(res.points[:, 0]), 0]
    assert ux == pytest.approx(1000 * 0.1 / (200e9 * 1e-4), rel=0.02)
    with pytest.raises(MechverifyError, match=r"'body' is a volume group.*regions.*fixed.*loaded"):
        solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("body")),)).solve()


def test_mesh_import_messages(tmp_path):
    """meshio's reason instead of 'SystemExit: 1' and 'a abaqus'; a unit that is not a length is a UnitError; a mesh
    without named groups (VTU) says so and points to Box/Plane."""
    meshio = pytest.importorskip("meshio")
    (tmp_path / "bad.inp").write_text("*NODE\n1, 0, 0, 0\n*ELEMENT, type=XYZ99, ELSET=a\n1, 1\n")
    with pytest.raises(InputError) as e:
        meshimport.read_solid_mesh(tmp_path / "bad.inp")
    assert "SystemExit" not in str(e.value) and "an Abaqus/CalculiX mesh" in str(e.value) and "XYZ99" in str(e.value)
    (tmp_path / "bad.msh").write_text("not a mesh\n")
    with pytest.raises(InputError, match=r"a Gmsh mesh \(meshio found no valid data") as e:
        meshimport.read_solid_mesh(tmp_path / "bad.msh")
    tet = meshio.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float), [("tetra", np.array([[0, 1, 2, 3]]))])
    tet.write(tmp_path / "t.vtu")
    with pytest.raises(UnitError, match="length unit"):
        meshimport.read_solid_mesh(tmp_path / "t.vtu", unit="kg")
    m = meshimport.read_solid_mesh(tmp_path / "t.vtu")
    with pytest.raises(MechverifyError, match="no named regions.*Box or Plane"):
        solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("fixed")),)).solve()
