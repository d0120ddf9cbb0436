"""Material records and lookup: names, aliases, suggestions, derived materials, S-N and wire strength.

Values checked against: ANSYS Engineering Data 'Structural Steel' S-N table (alternating stress,
zero mean); Shigley 10th ed. Table 10-4 (music wire A = 2211 MPa*mm^m, m = 0.145).
"""

import pytest

from mechverify import Q, materials
from mechverify.errors import InputError, UnknownNameError, ValidityError


def test_lookup_is_case_and_alias_insensitive():
    assert materials.get("structural steel") is materials.get("ANSYS Structural Steel")
    assert materials.get("MUSIC_WIRE") is materials.get("ASTM A228 music wire")


def test_unknown_material_suggests_near_names():
    with pytest.raises(UnknownNameError, match="did you mean 'Structural Steel'"):
        materials.get("structural stel")


def test_g_derived_from_e_and_nu():
    s = materials.get("Structural Steel")
    assert s.G.m_as("GPa") == pytest.approx(200 / 2.6)
    assert s.source_of("G").startswith("derived")


def test_with_derives_again_and_marks_user_source():
    s = materials.get("Structural Steel").with_(E="210 GPa", yield_strength="355 MPa")
    assert s.G.m_as("GPa") == pytest.approx(210 / 2.6)
    assert s.source_of("yield_strength") == "user"
    with pytest.raises(InputError, match="did you mean 'yield_strength'"):
        materials.get("Structural Steel").with_(yield_strenght="1 MPa")
    with pytest.raises(InputError, match="exceeds ultimate"):
        materials.get("Structural Steel").with_(yield_strength="500 MPa")


def test_ansys_sn_table_points_and_interpolation():
    sn = materials.get("Structural Steel").sn_curve
    assert sn.stress_at(1e6).m_as("MPa") == pytest.approx(86.2)
    assert sn.stress_at(1e4).m_as("MPa") == pytest.approx(262)
    # log-log midpoint between (1e5, 138) and (2e5, 114): 138 * (114/138)**(log(1.5)/log(2))
    import math
    expect = 138 * (114 / 138) ** (math.log10(1.5e5 / 1e5) / math.log10(2))
    assert sn.stress_at(1.5e5).m_as("MPa") == pytest.approx(expect)
    assert sn.life_at("114 MPa") == pytest.approx(2e5)
    assert sn.stress_at(1e8).m_as("MPa") == pytest.approx(86.2)  # held beyond the last point
    with pytest.raises(ValidityError):
        sn.stress_at(5)


def test_music_wire_power_law_shigley_table_10_4():
    ws = materials.get("A228").wire_strength
    # the Table 10-4 law itself (min_tensile_strength prefers the ASTM A228 table inside its range)
    assert ws.power_law("1 mm").m_as("MPa") == pytest.approx(2211)
    assert ws.min_tensile_strength(Q(2, "mm"), method="power_law").m_as("MPa") == pytest.approx(2211 / 2**0.145)
    with pytest.raises(ValidityError, match="outside"):
        ws.min_tensile_strength("8 mm")
