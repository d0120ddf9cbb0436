"""Review fixes of the solid_fea design-file type (round 2 session 3 review, /tmp/notes/review.md findings 7, 8, 9,
10, 11, 12, 15, 22, 26, 35): each test fails on the code before its fix."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mechverify
from mechverify.design.adapters.solid_fea import convergence_warning
from mechverify.errors import MechverifyError
from mechverify.fea.study import two_mesh_check
from mechverify.units import Q

BLOCK = """
[design]
name = "t"
[components.bar]
type = "solid_fea"
box = "{box}"
material = "Structural Steel"
mesh_size = "5 mm"
supports = [{{ named = "xmin" }}]
{extra}
[load_cases.tip.bar]
forces = [{{ named = "xmax", force = "{force}" }}]
"""


def _design(tmp_path: Path, box: str = "20, 10, 10", extra: str = "", force: str = "0, 0, -1000", tail: str = ""):
    f = tmp_path / "d.toml"
    f.write_text(BLOCK.format(box=box, extra=extra, force=force) + tail)
    return mechverify.load(f)


def _by(results):
    return {(r.check, r.load_case): r for r in results}


# ------------------------------------------------------------------------------------------- finding 7
def test_convergence_demand_is_the_larger_peak_and_a_support_peak_is_named_singular(tmp_path):
    """A stubby block 20 x 10 x 10 mm clamped at x = 0: the peak sits on the clamped face's edge (a singularity of
    the rigid support), 101.7 MPa at mesh_size 5 mm and 111.4 MPa at 5/1.5 mm (the code's numbers, not a printed
    value). The demand is the larger (finer) peak, not the coarse one, and the warning says the peak is at the
    support and will not converge instead of advising refinement."""
    r = _by(_design(tmp_path, extra="convergence_check = true").verify())[("solid_stress", "tip")]
    note = next(n for n in r.notes if n.startswith("two-mesh check"))
    coarse, fine = (float(s.split(" MPa")[0].split()[-1]) for s in note.split(" at mesh_size")[:2])
    assert fine > coarse
    assert r.demand.m_as("MPa") == pytest.approx(fine, rel=1e-3)
    (w,) = [w for w in r.warnings if "mesh convergence" in w]
    assert "supports[0]" in w and "singular" in w and "xmin" in w
    assert "refine the elements" not in w


def test_convergence_warning_names_the_mesh_size_needed():
    """Away from a support the advice is a mesh_size: peaks 100 and 110 MPa at h and h/1.5 (change 1/11 = 9.09 %),
    the change scaling as h^2 falls to 5 % at h·(0.05/0.0909)^(1/2) = 0.7416 h: 6 mm -> 4.45 mm (hand calculation
    of Richardson's h^p scaling, Roache ch. 5)."""
    chk = two_mesh_check(100.0, 110.0, 1.5, 2.0, 0.05)
    w = convergence_warning(chk, Q(6, "mm"), [{"named": "xmin"}], None)
    assert "a mesh_size of about 4.45 mm (now 6 mm)" in w
    assert convergence_warning(two_mesh_check(100.0, 101.0, 1.5, 2.0, 0.05), Q(6, "mm"), [], None) is None


# ------------------------------------------------------------------------------------------- finding 8
def test_a_pull_case_passes_buckling_and_the_push_case_governs(tmp_path):
    """A steel bar 100 x 10 x 10 mm fixed at x = 0 with a push case (-1000 N x) and a pull case (+1000 N x): the
    design used to be an error ('the loads cause no buckling') with no results at all. Now the pull case passes
    with a note and the push case governs: Euler fixed-free P_cr = π²EI/(4L²) = π²·200e9·(1e-2)^4/12/(4·0.1²) =
    41.1 kN, a factor of 41.1 (hand calculation, Timoshenko & Gere sec. 2.1; the FEA gives 41.09)."""
    tail = '[load_cases.pull.bar]\nforces = [{ named = "xmax", force = "1000, 0, 0" }]\n'
    d = _design(tmp_path, box="100, 10, 10", force="-1000, 0, 0", tail=tail,
                extra="checks.solid_stress = false\nchecks.solid_deflection = false\nchecks.buckling_load_factor = true")
    res = d.verify()
    rows = [r for r in res if r.check == "buckling_load_factor"]
    gov = min(rows, key=lambda r: r.capacity.m)
    euler = 3.141592653589793**2 * 200e9 * (1e-2) ** 4 / 12 / (4 * 0.1**2) / 1000
    assert gov.load_case == "tip" and gov.capacity.m == pytest.approx(euler, rel=0.02)
    assert gov.verdict.name == "PASS" and any("others: pull" in n for n in gov.notes)


def test_tension_only_buckling_is_fast_and_bounded():
    """The pull alone: a NoBucklingFactorError with a finite bound above the reversed load's factor (41.1), found
    by the largest-magnitude iteration (it took 4 s CPU on this 20 x 2 x 2 mesh through the 'LA' iteration)."""
    import time

    from mechverify.fea import buckling, mesh, solid
    from mechverify.fea.loads import Fixed, Force
    from mechverify.fea.regions import Named

    m = mesh.box(("100 mm", "10 mm", "10 mm"), (20, 2, 2))
    col = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("xmin")),),
                           loads=(Force(Named("xmax"), ("1000 N", "0 N", "0 N")),))
    t = time.process_time()
    with pytest.raises(buckling.NoBucklingFactorError, match=r"reversed loads would buckle it at 41\.\d") as e:
        buckling.buckling(col, 1)
    assert e.value.bound > 41.1
    assert time.process_time() - t < 2.0


# ------------------------------------------------------------------------------------------ finding 15
CANT = """
[design]
name = "solid cantilever"
[parameters]
P = "50 N"
[components.beam]
type = "solid_fea"
box = "300, 10, 10"
material = "Structural Steel"
mesh_size = "5 mm"
supports = [{{ named = "xmin" }}]
deflection_limit = "4 mm"
checks.solid_stress = false
[load_cases.tip.beam]
forces = [{{ named = "xmax", force = {force} }}]
"""


@pytest.mark.parametrize("force", ['"0, 0, -P"', '["0 N", "0 N", "-P"]', '"0, 0 N, -(P + 0 N)"'])
def test_solid_force_with_parameters_can_be_sized(tmp_path, force):
    """A solid's force written with a parameter (string or list form) is resolved like any quantity, so
    `mechverify size` finds the tip load of a 300 x 10 x 10 mm steel cantilever that deflects 4 mm:
    P = 3 E I δ / L³ = 3 · 200e9 · (0.01⁴/12) · 0.004 / 0.3³ = 74.07 N (hand calculation, Euler-Bernoulli,
    Shigley 10th ed. Table A-9 case 1; not a printed value). Both forms were refused ("expected a force, got -P";
    "got ['0 N', '0 N', '-50 newton']")."""
    from mechverify.studies.sizing import size

    f = tmp_path / "c.toml"
    f.write_text(CANT.format(force=force))
    r = size(mechverify.load(f), "parameters.P", until="solid_deflection", bounds=("10 N", "200 N"))
    assert r.limit == pytest.approx(3 * 200e9 * (0.01**4 / 12) * 0.004 / 0.3**3, rel=0.01)


def test_solid_force_list_of_wrong_length_is_named(tmp_path):
    f = tmp_path / "c.toml"
    f.write_text(CANT.format(force='["0 N", "-P"]'))
    with pytest.raises(MechverifyError, match=r"forces\[0\]\.force: expected three components.*got '0 N, -50 N'"):
        mechverify.load(f).verify()


# ------------------------------------------------------------------------------------- findings 12, 35
def _gmsh_p2_inp(tmp_path):
    """A bar 100 x 10 x 10 mm meshed by gmsh, second order, written by gmsh as Abaqus .inp (C3D10 with CPS6
    boundary triangles: meshio 5.3 alone refuses CPS6), physical surfaces 'fixed' / 'loaded', volume 'body'."""
    from mechverify.fea import mesh as fmesh

    gmsh = fmesh.import_gmsh()
    fmesh.gmsh_session(gmsh, 0.004)
    try:
        occ = gmsh.model.occ
        vol = occ.addBox(0, 0, 0, 0.1, 0.01, 0.01)
        occ.synchronize()
        faces = {round(occ.getCenterOfMass(2, t)[0], 9): t for _, t in gmsh.model.getEntities(2)}
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [faces[0.0]]), "fixed")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [faces[0.1]]), "loaded")
        gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [vol]), "body")
        gmsh.model.mesh.generate(3)
        gmsh.model.mesh.setOrder(2)
        gmsh.option.setNumber("Mesh.SaveGroupsOfNodes", 1)
        path = tmp_path / "bar_p2.inp"
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path


def test_gmsh_second_order_inp_solves_and_a_volume_group_is_named(tmp_path):
    """gmsh's P2 Abaqus export (CPS6 triangles) is read; the bar in tension stretches u = F L / (E A) =
    1000 · 0.1 / (200e9 · 1e-4) = 5.0e-6 m (Hooke's law, Timoshenko & Gere, Mechanics of Materials, sec. 2.2;
    hand calculation). The volume group 'body' used as a region is named as a volume group with the regions."""
    pytest.importorskip("gmsh")
    from mechverify.fea import meshimport, solid
    from mechverify.fea.loads import Fixed, Force
    from mechverify.fea.regions import Named

    m = meshimport.read_solid_mesh(_gmsh_p2_inp(tmp_path))
    assert {"fixed", "loaded"} <= set(m.named) and "body" not in m.named and "body" in m.volumes
    res = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("fixed")),),
                           loads=(Force(Named("loaded"), ("1000 N", "0 N", "0 N")),)).solve()
    ux = res.u[np.argmax(res.points[:, 0]), 0]
    assert ux == pytest.approx(1000 * 0.1 / (200e9 * 1e-4), rel=0.02)
    with pytest.raises(MechverifyError, match=r"'body' is a volume group.*regions.*fixed.*loaded"):
        solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("body")),)).solve()


def test_mesh_import_messages(tmp_path):
    """meshio's reason instead of 'SystemExit: 1' and 'a abaqus'; a unit that is not a length is a UnitError; a mesh
    without named groups (VTU) says so and points to Box/Plane."""
    meshio = pytest.importorskip("meshio")
    from mechverify.errors import InputError, UnitError
    from mechverify.fea import meshimport, solid
    from mechverify.fea.loads import Fixed
    from mechverify.fea.regions import Named

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


MESHED = """
[design]
name = "imported"
[components.bar]
type = "solid_fea"
mesh = "{mesh}"
unit = "m"
material = "Structural Steel"
supports = [{{ named = "{support}" }}]
deflection_limit = "1 mm"
[load_cases.pull.bar]
forces = [{{ named = "loaded", force = "1000 N, 0 N, 0 N" }}]
"""


def test_design_file_solid_from_another_tools_mesh(tmp_path):
    """solid_fea `mesh = "bar_p2.inp"` (issue 27: bring the mesh of an existing study): gmsh's physical groups are
    the regions; the bar in tension stretches F L / (E A) = 5.0e-6 m (Hooke's law, hand calculation). A wrong
    region name is reported at supports[0].named with the file's regions; an unreadable file at the key `mesh`."""
    pytest.importorskip("gmsh")
    _gmsh_p2_inp(tmp_path)
    f = tmp_path / "d.toml"
    f.write_text(MESHED.format(mesh="bar_p2.inp", support="fixed"))
    by = _by(mechverify.load(f).verify())
    assert by[("solid_deflection", "pull")].demand.m_as("m") == pytest.approx(1000 * 0.1 / (200e9 * 1e-4), rel=0.02)
    f.write_text(MESHED.format(mesh="bar_p2.inp", support="fixd"))
    with pytest.raises(MechverifyError, match=r"components\.bar\.supports\[0\]\.named: unknown mesh region 'fixd'; "
                                              r"did you mean 'fixed'\?.*valid regions: .*fixed, loaded"):
        mechverify.load(f)
    (tmp_path / "junk.msh").write_text("junk\n")
    f.write_text(MESHED.format(mesh="junk.msh", support="fixed"))
    with pytest.raises(MechverifyError, match=r"components\.bar\.mesh: junk\.msh: cannot read it as a Gmsh mesh"):
        mechverify.load(f)


def test_reproduce_rebases_an_imported_mesh(tmp_path):
    """study --reproduce --out into another folder rewrites solid_fea's `mesh` file name like `step`/`stl`."""
    from mechverify.studies.study import rebase_files

    doc = {"components": {"bar": {"type": "solid_fea", "mesh": "bar.inp"}}}
    (tmp_path / "other").mkdir()
    rebase_files(doc, tmp_path, tmp_path / "other")
    assert doc["components"]["bar"]["mesh"] == "../bar.inp"


# ------------------------------------------------------------------------------------------- finding 9
def test_free_motions_are_named_as_translations_and_rotations(tmp_path):
    """A bar 100 x 10 x 10 mm held only in x on its end face is free to translate along y and z and to rotate
    about its own axis (the line y = z = 5 mm, parallel to x): it was described as three rotations about axes far
    away ('through (50, -1.733e+04, 8166) mm')."""
    _design(tmp_path, box="100, 10, 10")  # writes d.toml
    f = tmp_path / "d.toml"
    f.write_text(f.read_text().replace('supports = [{ named = "xmin" }]', 'supports = [{ named = "xmin", hold = "x" }]'))
    with pytest.raises(MechverifyError, match=r"components\.bar\.supports: the model is not fully supported: the "
                                              r"supports leave free translation along y; translation along z; rotation about "
                                              r"an axis parallel to x through \(50, 5, 5\) mm\."):
        mechverify.load(f).verify()


# ------------------------------------------------------------------------------------ findings 10, 26, 22
@pytest.mark.parametrize(("extra", "key", "text"), [
    ("min_frequency = \"10 Hz\"\nmodes = 100000", "modes", r"100000 modes asked.*use a smaller mesh_size"),
    ("min_frequency = \"10 Hz\"\nmodes = 0", "modes", "a whole number >= 1, got 0"),
    ("excitation_band = [\"900 Hz\", \"800 Hz\"]", "excitation_band", r"0 <= lo <= hi"),
])
def test_modal_input_errors_are_at_their_keys(tmp_path, extra, key, text):
    """Too many modes, zero modes and a reversed band are reported at components.bar.<key> (they were at
    checks.natural_frequency with Python argument names, 'refine the mesh' and the band's list repr)."""
    with pytest.raises(MechverifyError) as e:
        _design(tmp_path, extra=extra).verify()
    msg = str(e.value)
    assert f"components.bar.{key}: " in msg and "checks.natural_frequency" not in msg and "n_modes" not in msg
    import re

    assert re.search(text, msg)


def test_gmsh_missing_is_one_error_at_the_geometry_key(tmp_path, monkeypatch):
    """Without gmsh a block with holes is one error at components.bar.holes with the install hint, not one per
    check and load case at components.bar.checks.<check> [case]."""
    from mechverify.errors import ModelError
    from mechverify.fea import mesh as fmesh

    def missing():
        raise ModelError("meshing needs gmsh: pip install mechverify[mesh] [no module named gmsh]")

    monkeypatch.setattr(fmesh, "import_gmsh", missing)
    tail = '[load_cases.two.bar]\nforces = [{ named = "xmax", force = "0, 0, -10" }]\n'
    with pytest.raises(MechverifyError) as e:
        _design(tmp_path, box="100, 40, 10", extra='holes = [{ center = "15, 20", diameter = "8 mm" }]\n'
                'deflection_limit = "1 mm"', tail=tail).verify()
    msg = str(e.value)
    assert msg.count("pip install") == 1 and "components.bar.holes: " in msg and "checks." not in msg


# ------------------------------------------------------------------------------------------ finding 11
def test_unreadable_step_keeps_opencascade_reason_at_the_key(tmp_path, capfd):
    """A STEP file that is text: OpenCASCADE's syntax error (printed by native code straight to the terminal, in
    red) is in the error at components.bar.step, and the terminal gets nothing raw; gmsh's own exception only says
    'Could not read file'."""
    pytest.importorskip("gmsh")
    (tmp_path / "junk.step").write_text("garbage\n")
    f = tmp_path / "d.toml"
    f.write_text(BLOCK.format(box="1, 1, 1", extra="", force="0, 0, -1").replace('box = "1, 1, 1"', 'step = "junk.step"')
                 .replace('named = "xmin"', "face = 1").replace('named = "xmax"', "face = 2"))
    with pytest.raises(MechverifyError) as e:
        mechverify.load(f).verify()
    msg = str(e.value)
    assert "components.bar.step: junk.step" in msg and "OpenCASCADE said:" in msg and "Incorrect syntax" in msg
    assert msg.count("junk.step: gmsh could not read") == 1
    out, err = capfd.readouterr()
    assert "StepFile" not in out + err


def test_loads_on_held_nodes_are_one_error_at_the_load_key(tmp_path):
    """Every load on a supported face: one error at load_cases.tip.bar.forces (it was one per check, at
    checks.<check> [tip])."""
    f = tmp_path / "d.toml"
    _design(tmp_path, extra='deflection_limit = "1 mm"')
    f.write_text(f.read_text().replace('supports = [{ named = "xmin" }]', 'supports = [{ named = "xmin" }, { named = "xmax" }]'))
    with pytest.raises(MechverifyError) as e:
        mechverify.load(f).verify()
    msg = str(e.value)
    assert msg.count("load_cases.tip.bar.forces: every load acts only on held nodes") == 1 and "checks." not in msg
