"""Face ids in a solid_fea design file (issue 23, bad input: "a face id that does not exist (list the ids)"), found in
task fix23's audit: ``face = "abc"`` was an internal ValueError, ``face = 1.5`` held face1 while the name check read
'face1.5', and a modal-only study (no load case) named an unknown face at ``checks.natural_frequency`` without the
STEP file's face list (a second error beside the one at ``supports[0].face`` when a load case exists)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

gmsh = pytest.importorskip("gmsh")


def _bar_step(tmp_path: Path) -> Path:
    """A 300 x 10 x 10 mm box written by gmsh/OpenCASCADE as STEP (faces 1 .. 6: x = 0 is face1, x = 300 face2)."""
    from mechverify.fea.mesh import initialize_gmsh

    path = tmp_path / "bar.step"
    initialize_gmsh(gmsh)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("bar")
        gmsh.model.occ.addBox(0, 0, 0, 300, 10, 10)
        gmsh.model.occ.synchronize()
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path


def _design(tmp_path: Path, face: str, load_case: str = "") -> Path:
    _bar_step(tmp_path)
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(f"""
        [design]
        name = "faces"
        [components.bar]
        type = "solid_fea"
        step = "bar.step"
        mesh_size = "10 mm"
        material = "Structural Steel"
        min_frequency = "10 Hz"
        supports = [{{ face = {face} }}]
        """) + load_case)
    return p


def _errors(path: Path) -> list[tuple[str, str]]:
    with pytest.raises(DesignFileError) as exc:
        load(path).verify()
    return exc.value.errors


@pytest.mark.parametrize("face", ['"abc"', "1.5", "0", "true", "-2"])
def test_a_face_that_is_not_a_face_number_is_named(tmp_path, face):
    errs = _errors(_design(tmp_path, face))
    assert len(errs) == 1
    assert errs[0][0] == "components.bar.supports[0].face"
    assert "a face number" in errs[0][1] and "mechverify faces" in errs[0][1]


def test_unknown_face_in_a_modal_only_study_lists_the_step_faces(tmp_path):
    """No load case: the unknown face is named at supports[0].face with the file's faces (plane x = 0 ...)."""
    errs = _errors(_design(tmp_path, "99"))
    assert len(errs) == 1 and errs[0][0] == "components.bar.supports[0].face"
    assert "unknown mesh region" in errs[0][1] and "face1: plane x = 0 mm" in errs[0][1]


def test_unknown_face_with_a_load_case_is_one_error(tmp_path):
    case = '\n[load_cases.tip.bar]\nforces = [{ face = 2, force = "0, 0, -100" }]\n'
    errs = _errors(_design(tmp_path, "99", case))
    assert [e[0] for e in errs] == ["components.bar.supports[0].face"]
    assert "face6: plane z = 10 mm" in errs[0][1]
