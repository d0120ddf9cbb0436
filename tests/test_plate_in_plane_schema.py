"""The design-file schema describes the load-case keys (review 2 finding 15: `in_plane` was missing, as were all load
keys: a load case names components, not types, so the schema lists the union of every type's load keys), with
in_plane's own keys nx, ny (one value or a pair), nxy and hole_loads."""

import functools

import pytest

from mechverify.design.schema import design_schema


@functools.cache
def _schema():
    return design_schema()


def _loads_schema():
    return _schema()["properties"]["load_cases"]["additionalProperties"]["additionalProperties"]


def test_in_plane_and_the_plate_load_keys_are_in_the_schema():
    props = _loads_schema()["properties"]
    assert {"in_plane", "pressure", "point_loads", "patch_loads", "self_weight"} <= set(props)
    assert set(props["in_plane"]["properties"]) == {"nx", "ny", "nxy", "hole_loads"}
    assert set(props["in_plane"]["properties"]["hole_loads"]["items"]["properties"]) == {"holes", "force_x", "force_y"}
    assert "membrane" in props["in_plane"]["description"]


def test_in_plane_values_validate():
    jsonschema = pytest.importorskip("jsonschema")
    schema = _loads_schema()  # one component's loads in one case (the whole file's schema validates in seconds)
    panel = {"pressure": "1 kPa", "in_plane": {"nx": ["-10 N/mm", "10 N/mm"], "nxy": "2 N/mm"}}
    jsonschema.validate(panel, schema)
    panel["in_plane"] = {"nz": "1 N/mm"}  # not a key of in_plane
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(panel, schema)
    panel["in_plane"] = {"nx": ["1 N/mm", "2 N/mm", "3 N/mm"]}  # a pair at most
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(panel, schema)
