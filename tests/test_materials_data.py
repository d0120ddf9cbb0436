"""The built-in material data files: they load, every record is sane and sourced, lookup and errors work.

Sanity rules (not against a table; the validation tests under tests/validation/ check values against
their published sources): positive moduli, yield <= ultimate, G = E/(2(1+nu)) within 5 % where a source
gives all three, density in the plausible band of its category, coherent bearing limits, every value
with an expanded source.
"""

import re
import tomllib
from importlib import resources

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mechverify import Q, materials
from mechverify.errors import InputError, UnknownNameError, ValidityError
from mechverify.materials import load_toml, material_from_dict
from mechverify.materials.material import PROPERTY_DIMENSIONS, WireStrength

DATA = resources.files("mechverify.materials").joinpath("data")
FILES = sorted(p.name for p in DATA.iterdir() if p.name.endswith(".toml"))
ALL = list(materials.default_library())

DENSITY_BANDS = {  # [kg/m^3]
    "steel": (7700, 8100), "stainless steel": (7700, 8100), "spring wire": (7700, 8100),
    "aluminium": (2600, 2900), "copper alloy": (8200, 9000),
    "polymer": (900, 1600), "polymer (3D printed)": (900, 1600), "plain bearing": (900, 9000),
}


def test_every_data_file_loads_and_has_materials():
    assert {"steels.toml", "aluminium.toml", "copper_alloys.toml", "polymers.toml", "plain_bearings.toml",
            "spring_wire.toml", "fea_tool_defaults.toml"} <= set(FILES)
    for name in FILES:
        with resources.as_file(DATA.joinpath(name)) as path:
            loaded = load_toml(path)
        assert loaded, name


def test_library_holds_every_file_entry_once():
    total = 0
    for name in FILES:
        doc = tomllib.loads(DATA.joinpath(name).read_text(encoding="utf-8"))
        total += len(doc.get("material", []))
    assert len(ALL) == total
    assert len({m.name for m in ALL}) == total


@pytest.mark.parametrize("m", ALL, ids=lambda m: m.name)
def test_material_is_sane(m):
    assert m.category in DENSITY_BANDS, m.category
    for prop in ("E", "G", "yield_strength", "ultimate_strength", "density", "p_max", "pv_max", "v_max"):
        v = getattr(m, prop)
        assert v is None or v.magnitude > 0, prop
    if m.yield_strength is not None and m.ultimate_strength is not None:
        assert m.yield_strength <= m.ultimate_strength
    if m.E is not None and m.G is not None and m.nu is not None and not m.derived:
        assert m.G.m_as("Pa") == pytest.approx(m.E.m_as("Pa") / (2 * (1 + m.nu.m_as(""))), rel=0.05)
    if m.density is not None:
        lo, hi = DENSITY_BANDS[m.category]
        assert lo <= m.density.m_as("kg/m^3") <= hi
    if m.elongation is not None:
        assert 0 < m.elongation.m_as("") < 1
    if m.mu_min is not None or m.mu_max is not None:
        assert 0 < m.mu_min.m_as("") <= m.mu_max.m_as("") < 1
    if m.category == "plain bearing":
        assert m.p_max is not None and m.pv_max is not None and m.mu_min is not None
    if m.category in ("steel", "stainless steel", "aluminium"):
        assert m.E is not None and m.yield_strength is not None and m.density is not None


@pytest.mark.parametrize("m", ALL, ids=lambda m: m.name)
def test_every_value_has_an_expanded_source(m):
    keys = set()
    for name in FILES:
        keys |= set(tomllib.loads(DATA.joinpath(name).read_text(encoding="utf-8")).get("references", {}))
    assert m.source
    for prop in PROPERTY_DIMENSIONS:
        if getattr(m, prop) is not None:
            src = m.source_of(prop)
            assert src, prop
            first = re.match(r"[A-Za-z][\w-]*", src)
            assert first is None or first.group(0) not in keys, f"{prop}: unexpanded reference {src!r}"
    if m.wire_strength is not None:
        assert m.wire_strength.source


@pytest.mark.parametrize("m", ALL, ids=lambda m: m.name)
def test_every_alias_finds_its_material(m):
    for alias in (m.name, *m.aliases):
        assert materials.get(alias) is m
        assert materials.get(alias.upper().replace(" ", "_")) is m


@pytest.mark.parametrize(("typo", "expected"), [("iglidr R", "iglidur R"), ("S335JR", "S355JR"),
                                                ("AISI 1054 CD", "AISI 1045 CD"), ("music wir", "music wire")])
def test_unknown_names_suggest_the_closest(typo, expected):
    with pytest.raises(UnknownNameError) as err:
        materials.get(typo)
    assert expected in err.value.suggestions
    assert "did you mean" in str(err.value)


def test_wire_strength_segments_and_errors():
    ws = WireStrength(A=1867e6, m=0.146, d_min=0.3e-3, d_max=2.5e-3, segments=[(2065e6, 0.263, 2.5e-3, 5e-3)])
    assert ws.power_law("4 mm").m_as("MPa") == pytest.approx(2065 / 4 ** 0.263)
    with pytest.raises(ValidityError, match="0.3 mm..2.5 mm, 2.5 mm..5 mm"):
        ws.power_law("6 mm")
    with pytest.raises(ValidityError, match="no tensile-strength table"):
        ws.min_tensile_strength("1 mm", method="table")
    with pytest.raises(InputError, match="method"):
        ws.min_tensile_strength("1 mm", method="fit")
    with pytest.raises(InputError, match="d_min < d_max"):
        WireStrength(A=1e9, m=0.1, d_min=2e-3, d_max=1e-3)
    with pytest.raises(InputError, match="increasing"):
        WireStrength(A=1e9, m=0.1, table_d=(2e-3, 1e-3), table_sut=(1e9, 1.1e9))


def test_toml_segments_are_validated_with_their_path():
    entry = {"name": "x", "category": "spring wire",
             "wire_strength": {"A": "1 GPa", "m": 0.1, "segments": [{"A": "1 GPa", "m": 0.1}]}}
    with pytest.raises(InputError, match=r"wire_strength.segments\[0\]"):
        material_from_dict(entry)


@given(st.floats(min_value=0.1016e-3, max_value=6.35e-3))
def test_a228_table_is_bracketed_by_its_rows(d):
    ws = materials.get("A228").wire_strength
    value = ws.min_tensile_strength(Q(d, "m")).m_as("Pa")
    below = [s for x, s in zip(ws.table_d, ws.table_sut) if x <= d]
    above = [s for x, s in zip(ws.table_d, ws.table_sut) if x >= d]
    assert min(above) - 1e-6 <= value <= max(below) + 1e-6
