"""Solid models: supports and loads by region, clear errors for unsupported models and bad regions,
results export (VTU, figure) and the lazy, optional gmsh import."""

import builtins
from pathlib import Path

import meshio
import numpy as np
import pytest

from mechverify.errors import InputError, ModelError, UnitError
from mechverify.fea import mesh, solid
from mechverify.fea.loads import Fixed, Force, Gravity, Restraint
from mechverify.fea.regions import Box, Cylinder, Named, Plane


def cantilever(**kw):
    m = mesh.box(("60 mm", "10 mm", "10 mm"), (6, 1, 1))
    loads = kw.pop("loads", (Force(Plane(x="60 mm"), ("0 N", "0 N", "-100 N")),))
    return solid.SolidModel(m, "Structural Steel", loads=loads, **kw)


def test_unsupported_model_names_the_free_motion():
    with pytest.raises(ModelError, match="no supports"):
        cantilever().solve()
    # a roller in z on one face leaves x, y and the rotation about z free
    with pytest.raises(ModelError, match=r"translation along x.*translation along y|translation along x \+ y"):
        cantilever(supports=(Restraint(Plane(x="0 mm"), z=True),)).solve()
    # clamping only one edge (x = 0, z = 0, along y) leaves the beam free to swing about that edge
    edge = Box(("0 mm", "0 mm", "0 mm"), ("0 mm", "10 mm", "0 mm"))
    with pytest.raises(ModelError, match=r"rotation about an axis parallel to y through \(0, [-\d.e]+, 0\) mm"):
        cantilever(supports=(Fixed(edge),)).solve()


def test_named_faces_and_regions():
    model = cantilever(supports=(Fixed(Named("xmin")),))
    res = model.solve()
    assert res.reactions.m_as("N") == pytest.approx([0, 0, 100], abs=1e-6)
    assert res.max_displacement.location.m_as("mm")[0] == pytest.approx(60)
    with pytest.raises(InputError, match="contains no boundary node"):
        cantilever(supports=(Fixed(Plane(x="70 mm")),)).solve()
    with pytest.raises(InputError, match="contains no boundary facet"):
        cantilever(supports=(Fixed(Plane(x="0 mm")),), loads=(Force(Plane(x="30 mm"), ("1 N", "0 N", "0 N")),)).solve()
    with pytest.raises(Exception, match="did you mean 'xmin'"):
        cantilever(supports=(Fixed(Named("xmn")),)).solve()


def test_inputs_checked():
    with pytest.raises(UnitError):
        Force(Plane(x="0 mm"), (1, 0, 0))
    with pytest.raises(InputError):
        Box(("1 mm", "0 mm", "0 mm"), ("0 mm", "1 mm", "1 mm"))
    with pytest.raises(InputError):
        Plane(x="0 mm", y="1 mm")
    with pytest.raises(InputError):
        Cylinder(("0 mm", "0 mm"), "-1 mm")
    with pytest.raises(InputError):
        Restraint(Plane(x="0 mm"))
    with pytest.raises(InputError, match="Material or its name"):
        solid.SolidModel(mesh.box(("1 m",) * 3, (1, 1, 1)), 3.0)


def test_gravity_needs_density():
    m = cantilever(supports=(Fixed(Plane(x="0 mm")),), loads=(Gravity(),))
    res = m.solve()
    weight = 7850 * 9.80665 * 60e-3 * 1e-4
    assert res.reactions.m_as("N") == pytest.approx([0, 0, weight], rel=1e-9)


def test_vtu_and_figure(tmp_path):
    res = cantilever(supports=(Fixed(Plane(x="0 mm")),)).solve()
    path = res.to_vtu(tmp_path / "c.vtu")
    back = meshio.read(path)
    assert back.cells[0].type == "tetra10"
    assert np.allclose(back.point_data["von_mises_Pa"], res.von_mises.m_as("Pa"))
    res.plot(tmp_path / "c.png")
    assert (tmp_path / "c.png").stat().st_size > 10_000
    s = res.summary()
    assert s["min_safety_factor"].value.m == pytest.approx(250e6 / res.max_von_mises.value.m_as("Pa"))


def test_missing_gmsh_gives_install_command(monkeypatch):
    real = builtins.__import__

    def fake(name, *a, **k):
        if name == "gmsh":
            raise ImportError("No module named 'gmsh'")
        return real(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", fake)
    with pytest.raises(ModelError, match=r"scripts/install\.sh -e '\.\[mesh\]'"):
        mesh.cylinder("5 mm", "50 mm", "2 mm")


def test_stl_properties_and_meshing(tmp_path):
    """Mass properties of a 40 x 20 x 10 mm block: V = 8000 mm^3, m = rho V, I_zz = m (a^2 + b^2)/12."""
    trimesh = pytest.importorskip("trimesh")
    path = tmp_path / "block.stl"
    trimesh.creation.box(extents=(40, 20, 10)).export(path)
    p = mesh.stl_properties(path, unit="mm", density="2700 kg/m^3")
    assert p.watertight
    assert p.volume.m_as("mm**3") == pytest.approx(8000)
    assert p.mass.m_as("g") == pytest.approx(21.6)
    assert p.inertia.m_as("kg*m**2")[2, 2] == pytest.approx(21.6e-3 * (0.04**2 + 0.02**2) / 12)
    open_path = tmp_path / "open.stl"
    tm = trimesh.creation.box(extents=(40, 20, 10))
    tm.update_faces(np.arange(len(tm.faces)) != 0)
    tm.export(open_path)
    assert not mesh.stl_properties(open_path).watertight
    with pytest.raises(ModelError, match="not watertight"):
        mesh.from_stl(open_path, "5 mm")
    pytest.importorskip("gmsh")
    m = mesh.from_stl(path, "5 mm")
    vol = np.abs(np.linalg.det(np.stack([m.mesh.p[:, m.mesh.t[k]] - m.mesh.p[:, m.mesh.t[0]] for k in (1, 2, 3)], 1).transpose(2, 0, 1))).sum() / 6
    assert vol == pytest.approx(8e-6, rel=1e-9)
    # a block from the STL, clamped at one end, pulled at the other: sigma = F/A far from the ends
    model = solid.SolidModel(m, "Inventor Aluminum 6061", supports=(Fixed(Plane(x="-20 mm")),),
                             loads=(Force(Plane(x="20 mm"), ("2000 N", "0 N", "0 N")),))
    res = model.solve()
    assert res.reactions.m_as("N")[0] == pytest.approx(-2000, rel=1e-9)


def test_cylinder_primitive_named_regions():
    """Round steel bar d = 10 mm, L = 40 mm cantilever, 100 N tip load: Timoshenko beam tip deflection
    P L^3 / (3 E I) + P L / (kappa G A), kappa = 6(1 + nu)/(7 + 6 nu) for a circle (Timoshenko & Gere,
    Mechanics of Materials, 4th ed., Table G-1 case 4; Cowper, J. Appl. Mech. 33 (1966) 335, Table 1).
    The straight-sided mesh cuts the circle into a polygon of ~25 sides (I about 1.5 % low: measured
    +1.7 % deflection); gmsh's second-order mesh (curved elements, the default) follows the circle:
    measured +0.20 %, asserted within 0.5 %."""
    pytest.importorskip("gmsh")
    m = mesh.cylinder("5 mm", "40 mm", "1.25 mm", axis="x")
    assert set(m.named) == {"start", "end", "side"}
    res = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("start")),),
                           loads=(Force(Named("end"), ("0 N", "0 N", "-100 N")),)).solve()
    E, nu, P, L, d = 200e9, 0.3, 100.0, 0.04, 0.01
    I, A, G = np.pi * d**4 / 64, np.pi * d**2 / 4, E / (2 * (1 + nu))
    kappa = 6 * (1 + nu) / (7 + 6 * nu)
    expect = P * L**3 / (3 * E * I) + P * L / (kappa * G * A)
    assert res.max_displacement.value.m_as("m") == pytest.approx(expect, rel=0.005)


def test_bolt_holes_as_regions_and_step_import(tmp_path):
    """A link with two pin holes: one pin held (hole wall fixed), 800 N pulling on the other pin,
    selected by a Cylinder region; the same as the named hole; a STEP file is read in metres."""
    gmsh = pytest.importorskip("gmsh")
    link = mesh.block_with_holes(("100 mm", "30 mm", "6 mm"), [(("15 mm", "15 mm"), "8 mm"), (("85 mm", "15 mm"), "8 mm")],
                                 "6 mm")
    pin_a = Cylinder(("15 mm", "15 mm", "0 mm"), "4 mm", axis=(0, 0, 1))
    pin_b = Cylinder(("85 mm", "15 mm", "0 mm"), "4 mm", axis=(0, 0, 1))
    res = solid.SolidModel(link, "Structural Steel", supports=(Fixed(pin_a),),
                           loads=(Force(pin_b, ("800 N", "0 N", "0 N")),)).solve()
    assert res.reactions.m_as("N") == pytest.approx([-800, 0, 0], abs=1e-6)
    named = solid.SolidModel(link, "Structural Steel", supports=(Fixed(Named("hole0")),),
                             loads=(Force(Named("hole1"), ("800 N", "0 N", "0 N")),)).solve()
    assert named.max_displacement.value.m == pytest.approx(res.max_displacement.value.m, rel=1e-9)
    mesh.initialize_gmsh(gmsh)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.occ.addBox(0, 0, 0, 40, 20, 10)
    gmsh.model.occ.synchronize()
    gmsh.write(str(tmp_path / "block.step"))
    gmsh.finalize()
    step = mesh.from_step(tmp_path / "block.step", "5 mm")
    assert step.mesh.p.max(axis=1) == pytest.approx([0.04, 0.02, 0.01])
    with pytest.raises(InputError, match="does not fit"):
        mesh.block_with_holes(("10 mm", "10 mm", "5 mm"), [(("5 mm", "5 mm"), "12 mm")])


def test_coarse_curved_mesh_is_untangled():
    """A 3 mm hole in a 10 mm mesh (5 mm at the hole): raising it to second order on the CAD folds 3
    tetrahedra over (measured); gmsh's high-order optimiser moves them back, so the curved mesh every
    builder makes by default has positive Jacobians at all integration points (checked independently)."""
    pytest.importorskip("gmsh")
    from mechverify.fea import isoparametric as iso

    m = mesh.block_with_holes(("60 mm", "30 mm", "10 mm"), [(("20 mm", "15 mm"), "3 mm")], "10 mm", "5 mm")
    assert m.curved is not None
    det, _ = iso.geometry(m.curved, m.basis.element_dofs, iso.reference(3, 4)[3])
    assert det.min() > 0
    # the hole's nodes lie on the 1.5 mm radius (mid-side nodes too: on the CAD, not on chords)
    hole = m.named_nodes("hole0")
    r = np.hypot(m.points[0, hole] - 0.02, m.points[1, hole] - 0.015)
    assert r == pytest.approx(0.0015, rel=1e-6)


def _sigpipe_ignored_by_the_os() -> bool:
    with open("/proc/self/status") as f:
        mask = next(line for line in f if line.startswith("SigIgn:")).split()[1]
    return bool(int(mask, 16) >> (13 - 1) & 1)


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads the signal mask from Linux /proc")
def test_gmsh_leaves_python_ignoring_sigpipe():
    """gmsh's initialize() sets SIGPIPE back to the default action behind Python's back; mechverify restores
    Python's disposition, else a later write to a closed pipe kills the process (seen: the whole test run
    died with 'Broken pipe' when a study worker died after an earlier gmsh mesh)."""
    pytest.importorskip("gmsh")
    mesh.cylinder("5 mm", "20 mm", "5 mm")
    assert _sigpipe_ignored_by_the_os()


def test_support_box_cutting_through_facets_warns_with_the_held_area():
    """Review 3 finding 22: a support box that cuts boundary facets holds only the whole facets inside it (a
    mesh-dependent area) - the same WARN as a load's box, with the held area. End face x = 0 of a 20 x 20 mm
    section, nodes at y = 0, 6.67, 13.3, 20 mm: a box up to y = 10 mm holds the strip y <= 6.67 mm, 6.667 x 20 =
    133.3 mm² (hand calculation), warned; a box up to y = 13.333 mm cuts nothing and is not warned."""
    m = mesh.box(("100 mm", "20 mm", "20 mm"), (10, 3, 3))
    load = (Force(Plane(x="100 mm"), ("1 N", "0 N", "0 N")),)
    for hi, warned in (("10 mm", True), ("13.3333333333 mm", False)):
        sup = Fixed(Box(("-1 mm", "-1 mm", "-1 mm"), ("0.5 mm", hi, "21 mm")))
        rep = solid.SolidModel(m, "Structural Steel", supports=(sup,), loads=load).region_reports()[1]
        assert rep.item.startswith("Fixed 1")
        assert (rep.warning is not None) is warned
        if warned:
            assert "cuts through" in rep.warning
            assert "holds 133.333 mm² of boundary" in rep.warning
            assert rep.measure * 1e6 == pytest.approx(20 * 20 / 3)
