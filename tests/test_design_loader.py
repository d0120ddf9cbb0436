"""Design-file machinery: key-path errors, all errors at once, includes, overrides, governing case.

These tests register a minimal rod type (sigma = F/A against yield, Shigley 10th ed. Eq. 3-22) so
that the loader is tested independently of the component adapters.
"""

import textwrap

import pytest

from mechverify.design import DesignFileError, load


@pytest.fixture(autouse=True)
def _rod(rod_type):
    yield


def write(tmp_path, text, name="design.toml"):
    p = tmp_path / name
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(textwrap.dedent(text))
    return p


GOOD = """
[design]
name = "rig"
revision = "B"

[requirements.safety_factors]
static = 2.5

[materials.my_steel]
base = "Structural Steel"
yield_strength = "300 MPa"

[components.rod]
type = "test_rod"
length = "350 mm"
area = "20 mm^2"
material = "my_steel"

[load_cases.lift.rod]
force = "1.2 kN"

[load_cases.hold.rod]
force = "2.0 kN"
"""


def test_good_design_verifies_with_governing_case(tmp_path):
    rs = load(write(tmp_path, GOOD)).verify()
    r = rs.get("rod", "stress")
    assert r.demand.m_as("MPa") == pytest.approx(100.0)  # 2 kN / 20 mm^2
    assert r.load_case == "hold" and r.required_sf == 2.5
    assert r.capacity.m_as("MPa") == 300
    assert "Governing of 2 load cases" in r.notes[-1]
    assert rs.name == "rig rev B"


def test_governing_note_gives_the_other_cases_u_sf_like_the_table(tmp_path):
    """Review 2 finding 9: the note 'Governing of N load cases (others: lift: u=0.2)' gave u where the table's
    column and the verdict use u·SF: the other case looked better than it is. lift: 1.2 kN / 20 mm² = 60 MPa of
    300 MPa, u = 0.2, u·SF = 0.2 x 2.5 = 0.5 (hand calculation)."""
    r = load(write(tmp_path, GOOD)).verify().get("rod", "stress")
    assert r.notes[-1] == "Governing of 2 load cases (others: lift: u·SF=0.5)."


def test_all_errors_reported_with_key_paths(tmp_path):
    bad = GOOD.replace('length = "350 mm"', 'length = "350 N"').replace('area = "20 mm^2"', "area = 20") \
              .replace('material = "my_steel"', 'material = "structural stel"')
    bad = 'colour = "red"\n' + bad + '\nmass = "1 kg"\n'
    bad = bad.replace("[components.rod]", "[components.rod]\nlenght = \"1 m\"")
    with pytest.raises(DesignFileError) as info:
        load(write(tmp_path, bad))
    paths = dict(info.value.errors)
    assert paths["components.rod.length"] == 'expected a length, got "350 N"'
    assert "bare number 20" in paths["components.rod.area"]
    assert "did you mean 'Structural Steel'" in paths["components.rod.material"]
    assert "did you mean 'length'" in paths["components.rod.lenght"]
    assert "unknown key" in paths["colour"]
    assert "unknown key" in paths["load_cases.hold.rod.mass"]
    assert len(info.value.errors) == 6


def test_unknown_type_and_choice_and_load_case_component(tmp_path):
    text = GOOD.replace('type = "test_rod"', 'type = "test_rdo"')
    with pytest.raises(DesignFileError, match=r"components.rod.type: unknown type 'test_rdo'; did you mean 'test_rod'"):
        load(write(tmp_path, text))
    text = GOOD.replace('material = "my_steel"', 'material = "my_steel"\nfinish = "polished"')
    with pytest.raises(DesignFileError, match=r"components.rod.finish: expected one of 'ground', 'machined'"):
        load(write(tmp_path, text))
    text = GOOD.replace("[load_cases.hold.rod]", "[load_cases.hold.rdo]")
    with pytest.raises(DesignFileError, match=r"load_cases.hold.rdo: no such component; did you mean 'rod'"):
        load(write(tmp_path, text))


def test_check_override_disable_and_sf(tmp_path):
    text = GOOD + "\n[components.rod.checks]\nstress = { required_sf = 4.0 }\n"
    r = load(write(tmp_path, text)).verify().get("rod", "stress")
    assert r.required_sf == 4.0 and r.verdict.value == "fail"  # 100 MPa * 4 > 300 MPa
    text = GOOD + "\n[components.rod.checks]\nstress = false\n"
    assert len(load(write(tmp_path, text)).verify()) == 0


def test_check_without_loads_is_an_error(tmp_path):
    text = GOOD.split("[load_cases.lift.rod]")[0]
    with pytest.raises(DesignFileError, match=r"components.rod.checks.stress: needs force from a load case"):
        load(write(tmp_path, text))


def test_includes_inside_tree_and_refused_outside(tmp_path):
    write(tmp_path, '[materials.team_steel]\nbase = "Structural Steel"\n', "shared/materials.toml")
    text = GOOD.replace('revision = "B"', 'revision = "B"\ninclude = ["shared/materials.toml"]') \
               .replace('material = "my_steel"', 'material = "team_steel"')
    assert load(write(tmp_path, text)).verify().get("rod", "stress").capacity.m_as("MPa") == 250
    write(tmp_path.parent, '[materials.x]\nbase = "Structural Steel"\n', "outside.toml")
    text = GOOD.replace('revision = "B"', 'revision = "B"\ninclude = ["../outside.toml"]')
    with pytest.raises(DesignFileError, match="outside the design's folder"):
        load(write(tmp_path, text))
    load(write(tmp_path, text), allow_outside=True)


def test_file_level_errors(tmp_path):
    with pytest.raises(DesignFileError, match="file not found"):
        load(tmp_path / "missing.toml")
    with pytest.raises(DesignFileError, match="not valid TOML"):
        load(write(tmp_path, "[design\nname = 1"))
    with pytest.raises(DesignFileError, match="design.name: missing"):
        load(write(tmp_path, "[design]\n"))
