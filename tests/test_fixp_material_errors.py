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
