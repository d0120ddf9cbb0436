"""Review finding 25: a bad material property is reported once, at its key (materials.<name>.<property>), not as
"materials.mystery: mystery.density: ...", and without a second error at every component using the material."""

from __future__ import annotations

import pytest

import mechverify
from mechverify.design.loader import DesignFileError

TEXT = """
[design]
name = "no density"
[materials.mystery]
base = "Structural Steel"
density = "0 kg/m^3"
[components.link]
type = "link"
material = "mystery"
length = "100 mm"
section = "rectangle"
width = "10 mm"
height = "10 mm"
[load_cases.a.link]
axial_force = "100 N"
"""


def test_material_error_at_its_key_once(tmp_path):
    f = tmp_path / "d.toml"
    f.write_text(TEXT)
    with pytest.raises(DesignFileError) as exc:
        mechverify.load(f).verify()
    text = str(exc.value)
    assert "materials.mystery.density: must be positive" in text
    assert "mystery.density: mystery" not in text and "materials.mystery: mystery." not in text
    assert "unknown material" not in text and "1 error" in text


def test_readme_lists_every_extra():
    """Review finding 25: the README's extras table lacked `explore` and `docs`; every optional dependency group of
    pyproject.toml has its row."""
    import re
    import tomllib
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    extras = tomllib.loads((root / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    rows = set(re.findall(r"^\| `([\w-]+)` \|", (root / "README.md").read_text(), flags=re.M))
    assert set(extras) <= rows, set(extras) - rows


def test_plate_negative_min_frequency_reads_as_a_quantity(tmp_path):
    """Review finding 26 (plate part): 'must be positive, got <Quantity(-5, 'hertz')>' (pint's repr)."""
    f = tmp_path / "d.toml"
    f.write_text('[design]\nname = "p"\n[components.p]\ntype = "plate_fea"\nwidth = "400 mm"\nheight = "200 mm"\n'
                 'thickness = "4 mm"\nmaterial = "Structural Steel"\nsupports = [{ edges = "all", type = "pinned" }]\n'
                 'min_frequency = "-5 Hz"\n[load_cases.a.p]\npressure = "1 kPa"\n')
    with pytest.raises(DesignFileError) as exc:
        mechverify.load(f).verify()
    assert "components.p.min_frequency: must be positive" in str(exc.value)
    assert "Quantity" not in str(exc.value) and "-5 Hz" in str(exc.value)
