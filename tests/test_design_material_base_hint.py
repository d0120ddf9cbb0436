"""A material table written with the components' key ``extends`` (review 3, the materials hint; task fixstudy):
the error suggests ``base`` (the material key), not the nearest spelling ('notes'), and is the only error."""

from __future__ import annotations

import pytest

from mechverify.design.loader import DesignFileError, parse


def test_extends_in_a_material_suggests_base_and_nothing_cascades():
    doc = {"design": {"name": "m"},
           "materials": {"mysteel": {"extends": "Structural Steel", "yield_strength": "300 MPa"}},
           "components": {"s": {"type": "lead_screw", "thread": "Tr10x2", "length": "450 mm", "material": "mysteel",
                                "nut_material": "iglidur R", "nut_length": "10 mm"}}}
    with pytest.raises(DesignFileError) as e:
        parse(doc)
    assert e.value.errors == [("materials.mysteel.extends",
                               "unknown key; did you mean 'base'? (a material builds on another with base = \"...\"; "
                               "extends is the key of components and templates)")], e.value.errors
    doc["materials"]["mysteel"] = {"base": "Structural Steel", "yield_strength": "300 MPa"}
    parse(doc)  # the same table with 'base' loads
