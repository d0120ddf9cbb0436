"""Bad input of a solid_fea design file found by review 4 (issue 23), each a named error at its key instead of an
internal error or a silent acceptance:

- #1 ``vtu`` where no folder can be made: was "internal error: FileNotFoundError" after the whole solve;
- #2 ``stl`` naming a file that is not STL (``base.toml``): was "internal error: NotImplementedError";
- #3 ``convergence_tolerance = -1`` was accepted (every result WARNed "tolerance -100 %"); 5 (a percent typed as a
  number) likewise;
- #5 an STL file with no triangles (text "solid garbage", an empty file): a bare numpy "invalid value encountered in
  divide" warning and "not watertight" instead of saying that no triangles were read.
"""

from __future__ import annotations

import textwrap
import warnings
from pathlib import Path

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

BASE = """
    [design]
    name = "bad files"
    [components.beam]
    type = "solid_fea"
    {geometry}
    material = "Structural Steel"
    mesh_size = "5 mm"
    supports = [{{ named = "xmin" }}]
    deflection_limit = "10 mm"
    {extra}
    [load_cases.p.beam]
    forces = [{{ named = "xmax", force = "0, 0, -10" }}]
    """


def _errors(tmp_path: Path, geometry: str = 'box = "100, 10, 10"', extra: str = "") -> list[tuple[str, str]]:
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(BASE.format(geometry=geometry, extra=extra)))
    with pytest.raises(DesignFileError) as exc:
        load(p).verify()
    return exc.value.errors


@pytest.mark.parametrize("where", ["file", "under_file"])
def test_vtu_folder_that_cannot_be_made_is_named_before_solving(tmp_path, where):
    """A ``vtu`` folder that is an existing file, or lies under one: no folder can be made there; the error is at
    components.beam.vtu when the file is read (before meshing and solving)."""
    (tmp_path / "taken").write_text("a file, not a folder")
    folder = "taken" if where == "file" else "taken/x"
    errs = _errors(tmp_path, extra=f'vtu = "{folder}"')
    assert [e[0] for e in errs] == ["components.beam.vtu"]
    assert "cannot" in errs[0][1] and "taken" in errs[0][1]


def test_vtu_write_failure_after_the_solve_is_named(tmp_path, monkeypatch):
    """A folder that passes the check but cannot be written when the results are exported (review 4's /proc path
    as root: os.access says yes, mkdir fails) is still a named error at vtu, not an internal one."""
    from mechverify.fea import results

    def refuse(self, path):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(results.FieldResults, "to_vtu", refuse)
    errs = _errors(tmp_path, extra='vtu = "out"')
    assert {e[0] for e in errs} == {"components.beam.vtu"}
    assert "cannot write" in errs[0][1] and "Permission denied" in errs[0][1]


@pytest.mark.parametrize(("name", "text", "match"), [
    ("base.toml", "[design]\n", "not an STL file"),
    ("g.stl", "solid garbage\n", "no triangles"),
    ("empty.stl", "", "no triangles"),
])
def test_stl_that_is_not_a_part_is_named(tmp_path, name, text, match):
    (tmp_path / name).write_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no bare numpy warning on the way
        errs = _errors(tmp_path, geometry=f'stl = "{name}"')
    assert [e[0] for e in errs] == ["components.beam.stl"]
    assert match in errs[0][1] and name in errs[0][1]


@pytest.mark.parametrize(("tol", "match"), [("-1", "between 0 and 1"), ("0", "between 0 and 1"),
                                            ("5", "did you mean 0.05")])
def test_convergence_tolerance_out_of_range_is_named(tmp_path, tol, match):
    errs = _errors(tmp_path, extra=f"convergence_check = true\nconvergence_tolerance = {tol}")
    assert [e[0] for e in errs] == ["components.beam.convergence_tolerance"]
    assert match in errs[0][1]


def test_free_free_mode_request_names_the_elastic_modes(tmp_path):
    """A free-free solid asked for more modes than it has: the message counts the user's modes and the elastic modes
    the model has (task fix23's audit: 'modes = 5000' was reported as '5006 modes asked ... at most 1646', the six
    rigid-body modes the adapter adds counted in both)."""
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent("""
        [design]
        name = "free-free"
        [components.bar]
        type = "solid_fea"
        box = "300, 10, 10"
        mesh_size = "10 mm"
        material = "Structural Steel"
        supports = []
        min_frequency = "100 Hz"
        modes = 5000
        """))
    with pytest.raises(DesignFileError) as exc:
        load(p).verify()
    (key, msg), = exc.value.errors
    assert key == "components.bar.modes" and msg.startswith("5000 elastic modes asked")
    import re

    n = int(re.search(r"of (\d+) degrees of freedom", msg).group(1))
    assert f"at most {n - 7} " in msg and "rigid-body" in msg
