"""A load a bearing type cannot take is refused by the static check as by the life check (review item 5).

A thrust ball bearing takes no radial load, a non-locating cylindrical roller bearing (NU) no axial load
(SKF 17000 EN, product descriptions): the equivalent dynamic load already raised ValidityError (bearing_life
FAILs as not verifiable) but the static P0 ignored the load (bearing_static_safety passed). No published
numbers: the refusal itself is tested.
"""

from __future__ import annotations

import pytest

from mechverify.checks import bearings as bc
from mechverify.components.bearings_rolling import rolling_bearing
from mechverify.errors import ValidityError

DESIGN = """
[design]
name = "unsupported loads"
[components.tb]
type = "rolling_bearing"
model = "51105"
[components.nu]
type = "rolling_bearing"
model = "NU 205 ECP"
[load_cases.run.tb]
axial_force = "3 kN"
radial_force = "1 kN"
speed = "1000 rpm"
[load_cases.run.nu]
radial_force = "5 kN"
axial_force = "100 N"
speed = "1500 rpm"
"""


@pytest.mark.parametrize(("name", "Fr", "Fa", "words"), [("51105", "1 kN", "3 kN", "takes no radial load"),
                                                          ("NU 205 ECP", "5 kN", "100 N", "takes no axial load")])
def test_static_load_refuses_what_the_bearing_cannot_take(name, Fr, Fa, words):
    b = rolling_bearing(name)
    with pytest.raises(ValidityError, match=words):
        b.static_load(Fr, Fa)
    with pytest.raises(ValidityError, match=words):
        bc.check_bearing_static_safety(b, Fr, Fa)
    with pytest.raises(ValidityError, match=words):  # same refusal as the life check
        b.equivalent_load(Fr, Fa)


def test_loads_the_bearing_takes_still_check():
    assert rolling_bearing("51105").static_load("0 N", "3 kN").m_as("N") == pytest.approx(3000)
    assert rolling_bearing("NU 205 ECP").static_load("5 kN", "0 N").m_as("N") == pytest.approx(5000)


def test_design_static_safety_fails_as_not_verifiable(tmp_path):
    from mechverify.design import load

    f = tmp_path / "b.toml"
    f.write_text(DESIGN)
    rs = load(f).verify()
    for comp in ("tb", "nu"):
        life, static = rs.get(comp, "bearing_life"), rs.get(comp, "bearing_static_safety")
        assert life.verdict.value == "fail" and static.verdict.value == "fail"
        assert static.notes[0].startswith("Not verifiable:")
        assert static.notes[0].split(":")[1] == life.notes[0].split(":")[1]
