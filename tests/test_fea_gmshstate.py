"""gmsh's OpenCASCADE state left behind by mechverify's STEP readers (mechverify/fea/gmshstate.py, issue 19).

The STEP unit gmsh sets for OpenCASCADE (``Geometry.OCCTargetUnit = "M"`` in fea.mesh.from_step and
fea.study.step_volume) is process-wide and outlived ``gmsh.finalize``: a later gmsh session of the same process
wrote a 40 mm box as 40 m (and read one in metres), and meshing that box at 5 mm never ended (the test-order hang
of tests/test_fea_study.py then tests/test_fea_solid.py::test_bolt_holes_as_regions_and_step_import). These
tests write the box after each reader and look at the coordinates in the file (they fail, not hang, without
the fix). No published numbers: a 10 mm edge must be written as 10 mm.
"""

from __future__ import annotations

import re

import pytest

from mechverify.errors import ModelError
from mechverify.fea import mesh, study

gmsh = pytest.importorskip("gmsh")


def _written_box(path) -> float:
    """Write a 40 x 20 x 10 box (gmsh model units, meant as mm) as STEP in a fresh gmsh session, as a user's
    script does; the largest z coordinate in the file (mm, the STEP file's declared unit)."""
    mesh.initialize_gmsh(gmsh)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.occ.addBox(0, 0, 0, 40, 20, 10)
        gmsh.model.occ.synchronize()
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    text = path.read_text()
    assert "SI_UNIT(.MILLI.,.METRE.)" in text
    points = re.findall(r"CARTESIAN_POINT\('',\(([^)]*)\)\)", text)
    return max(float(p.split(",")[2]) for p in points if p.count(",") == 2)  # (2D points: curves on faces)


def test_step_volume_leaves_the_unit_as_it_found_it(tmp_path):
    """A good and a broken STEP file read by step_volume (metres), then the box: its 10 mm edge stays 10 mm
    (before the fix: 1.E+04, the box written 1000 times too large)."""
    box = tmp_path / "box.step"
    assert _written_box(box) == 10.0
    assert study.step_volume(box) == pytest.approx(40e-3 * 20e-3 * 10e-3)
    assert _written_box(tmp_path / "after_good.step") == 10.0
    broken = tmp_path / "broken.step"
    broken.write_text("ISO-10303-21;\nthis is not a step file\n")
    with pytest.raises(ModelError, match="could not read"):
        study.step_volume(broken)
    assert _written_box(tmp_path / "after_broken.step") == 10.0


def test_from_step_leaves_the_unit_as_it_found_it(tmp_path):
    """from_step reads in metres (the mesh is 40 x 20 x 10 mm); a box written afterwards keeps its size, and a
    second read of it gives the same mesh extent."""
    box = tmp_path / "box.step"
    assert _written_box(box) == 10.0  # (checked before meshing: a 40 m box at 10 mm would never finish)
    first = mesh.from_step(box, "10 mm")
    assert first.mesh.p.max(axis=1) == pytest.approx([0.04, 0.02, 0.01])
    assert _written_box(tmp_path / "again.step") == 10.0
    second = mesh.from_step(tmp_path / "again.step", "10 mm")
    assert second.mesh.p.max(axis=1) == pytest.approx([0.04, 0.02, 0.01])


def test_the_reset_prints_nothing(tmp_path, capfd):
    """The reset reads an empty file as STEP; OpenCASCADE's complaint about it (printed by native code, in red,
    on every successful read: found by another engineer) must not reach the terminal."""
    box = tmp_path / "box.step"
    _written_box(box)
    capfd.readouterr()
    study.step_volume(box)
    out, err = capfd.readouterr()
    assert "ERR" not in out + err and "StepFile" not in out + err
