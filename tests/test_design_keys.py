"""Review item 6 (and the rest of 9): a bad value in a design file is reported once, at its key path
(``components.arm.path.r: ...``), with the value as written: never at the component or at every check
that happens to read it, never as an SI number or a repr.

The designs are the reviewer's files (/tmp/review/*.toml of the review pass), one value edited.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import FIVE_BAR_LINKS

from mechverify.design import load
from mechverify.design.loader import DesignFileError, key_path

ARM = """
[design]
name = "RP arm review"

[components.arm]
type = "planar_arm"
kind = "rp"
path = { curve = "polar", r = "8 cm - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"], speed = "1.4 cm/s" }
carriage_mass = "98 g"
bodies = [{ name = "screw", shape = "rod", mass = "99 g", length = "25 cm" }]
"""

FIVE_BAR = """
[design]
name = "Five-bar workspace"

[components.fb]
""" + FIVE_BAR_LINKS + """working_mode = "+-"
x_range = ["0 mm", "100 mm"]
y_range = ["100 mm", "180 mm"]
samples = 21
payload = "5 N"
motor_torque = "1.5 N*m"
"""


def errors(tmp_path: Path, text: str, old: str = "", new: str = "") -> list[tuple[str, str]]:
    """The (key path, message) pairs of loading and verifying ``text`` with ``old`` replaced by ``new``."""
    assert old in text, old
    p = tmp_path / "d.toml"
    p.write_text(text.replace(old, new, 1))
    with pytest.raises(DesignFileError) as info:
        load(p).verify()
    return info.value.errors


def test_key_path_joins_only_keys_of_the_table():
    keys = {"path", "distal_left", "supports"}
    assert key_path("components.arm", "path.r: expected a length", keys) == ("components.arm.path.r",
                                                                            "expected a length")
    assert key_path("components.s", "supports[0].named: unknown", keys) == ("components.s.supports[0].named",
                                                                           "unknown")
    assert key_path("components.s", "components.s.supports[0].named: unknown", set()) == (
        "components.s.supports[0].named", "unknown")
    # not a key of the table: left alone (a sentence, a profile's name, another component's key)
    assert key_path("components.arm", "Not verifiable: x", keys) == ("components.arm", "Not verifiable: x")
    assert key_path("components.arm", "profile 'q1': path.r: x", keys) == ("components.arm",
                                                                          "profile 'q1': path.r: x")
    assert key_path("components.arm", "speed: x", keys) == ("components.arm", "speed: x")


def test_adapter_message_is_joined_into_the_key_path(tmp_path):
    """Review item 6: ``components.arm: path.r: ...`` read as if the component were the key."""
    errs = errors(tmp_path, ARM, 'r = "8 cm - 1.5 cm * cos(4*phi)"', 'r = "8"')
    assert errs == [("components.arm.path.r",
                     "expected a length (e.g. \"8 cm - 1.5 cm * cos(4*phi)\"), '8' is a bare number")]
    errs = errors(tmp_path, ARM, 'curve = "polar"', 'curve = "polr"')
    assert errs == [("components.arm.path.curve", "expected 'polar', 'cartesian' or 'points', got 'polr'")]


GUIDES = """
[design]
name = "Guides review"

[components.carriage]
type = "sliding_carriage"
friction = 0.18
contact_length = "30 mm"
load_offset = "411 mm"
available_force = "2500 N"

[components.rail]
type = "linear_guide"
dynamic_load_rating = "14.7 kN"
static_load_rating = "23.5 kN"
rails = 2
blocks_per_rail = 2
rail_spacing = "200 mm"
block_spacing = "150 mm"
required_travel = "5000 km"

[load_cases.raise.carriage]
resisting_force = "350 N"
[load_cases.raise.rail]
force = "4 kN"
offset_x = "50 mm"
offset_y = "30 mm"
"""


@pytest.mark.parametrize(("old", "new", "expected"), [
    # was at components.rail.checks.linear_guide_life [raise] and again at ...static_safety [raise]
    ("rails = 2", "rails = 3", ("components.rail.rails", "expected 1 or 2, got 3")),
    ("blocks_per_rail = 2", "blocks_per_rail = 0", ("components.rail.blocks_per_rail", "expected 1 or 2, got 0")),
    ('rail_spacing = "200 mm"', 'rail_spacing = "-200 mm"', ("components.rail.rail_spacing",
                                                               "must be positive, got -200 mm")),
    # was at components.carriage
    ("friction = 0.18", "friction = -0.18", ("components.carriage.friction",
                                              "expected a coefficient in 0..5, got -0.18")),
    # was accepted as 4 kN (the block loads take |F|)
    ('force = "4 kN"', 'force = "-4 kN"', ("load_cases.raise.rail.force",
                                           "expected a magnitude >= 0 (the sign is not a direction here: the "
                                           "block loads use |F|), got -4 kN")),
])
def test_linear_guide_errors_once_at_the_key(tmp_path, old, new, expected):
    """Review items 6 and 9: linear_guide and sliding_carriage values, each reported once at its key."""
    assert errors(tmp_path, GUIDES, old, new) == [expected]


BEARINGS = """
[design]
name = "Bearing review"

[components.pinion_shaft]
type = "adjusted_bearing_pair"
model = "30205"
rule = "timken"
K = 1.5

[components.ac]
type = "rolling_bearing"
model = "7206 B"
iso_vg = 68
viscosity_index = 95
operating_temperature = "70 degC"
[components.ac.checks]
bearing_modified_life = true

[load_cases.run.pinion_shaft]
radial_force_A = "2.492 kN"
radial_force_B = "4.873 kN"
axial_force = "0 N"
speed = "300 rpm"
[load_cases.run.ac]
radial_force = "2 kN"
axial_force = "1 kN"
speed = "1500 rpm"
"""


@pytest.mark.parametrize(("old", "new", "expected"), [
    # was "induced forces ... >= 0" at both checks of the pair
    ("K = 1.5", "K = -1.5", ("components.pinion_shaft.K", "expected a positive Timken thrust factor, got -1.5")),
    # were at components.ac
    ("iso_vg = 68", "iso_vg = 67", ("components.ac.iso_vg", "ISO VG 67 is not an ISO 3448 grade")),
    ('operating_temperature = "70 degC"', 'operating_temperature = "500 degC"',
     ("components.ac.operating_temperature", "operating temperature 500 degC outside -20..150 degC")),
    ("viscosity_index = 95", "viscosity_index = 500",
     ("components.ac.viscosity_index", "viscosity index 500 outside -100..400")),
    # review item 9: viscosity won silently over iso_vg + viscosity_index + operating_temperature (kappa 11.7)
    ("iso_vg = 68", 'iso_vg = 68\nviscosity = "20 mm^2/s"',
     ("components.ac.viscosity", "give viscosity or iso_vg + operating_temperature + viscosity_index, not both")),
    ("iso_vg = 68", 'iso_vg = 68\nviscosity_40 = "68 mm^2/s"',
     ("components.ac.iso_vg", "give iso_vg or viscosity_40, not both")),
])
def test_bearing_errors_once_at_the_key(tmp_path, old, new, expected):
    """Review items 6 and 9: bearing values reported at build time, once, at their key."""
    errs = errors(tmp_path, BEARINGS, old, new)
    assert len(errs) == 1 and errs[0][0] == expected[0] and errs[0][1].startswith(expected[1]), errs


SOLID = """
[design]
name = "Solid cantilever"
[components.beam]
type = "solid_fea"
box = "200, 20, 20"
material = "Structural Steel"
mesh_size = "5 mm"
supports = [{ named = "xmin" }]
deflection_limit = "1 mm"
[load_cases.tip.beam]
forces = [{ named = "xmax", force = "0, 0, -100" }]
"""


@pytest.mark.parametrize(("old", "new", "expected"), [
    # was "unknown mesh region 'xmn'" at components.beam.checks.solid_stress [tip] and again at solid_deflection
    ('named = "xmin"', 'named = "xmn"', ("components.beam.supports[0].named",
                                         "unknown mesh region 'xmn'; did you mean 'xmin'? valid regions: xmax, "
                                         "xmin, ymax, ymin, zmax, zmin")),
    ('named = "xmax"', 'named = "xmx"', ("load_cases.tip.beam.forces[0].named",
                                         "unknown mesh region 'xmx'; did you mean 'xmax'? valid regions: xmax, "
                                         "xmin, ymax, ymin, zmax, zmin")),
])
def test_solid_region_names_once_at_the_key(tmp_path, old, new, expected):
    """Review item 6: a misspelt region of a solid_fea is reported at its key, once (not per check)."""
    assert errors(tmp_path, SOLID, old, new) == [expected]


@pytest.mark.parametrize(("text", "old", "new", "expected"), [
    # was "components.fb: distal_left: must be positive, got -0.1 (SI)"
    (FIVE_BAR, 'distal_left = "100 mm"', 'distal_left = "-100 mm"',
     [("components.fb.distal_left", 'must be positive, got "-100 mm"')]),
    # was "(<Quantity(200, 'degree')>, <Quantity(100, 'degree')>)"
    (FIVE_BAR, "samples = 21", 'samples = 21\ntheta_left_min = "200 deg"\ntheta_left_max = "100 deg"',
     [("components.fb.theta_left_max", "must be above theta_left_min (200 deg), got 100 deg")]),
    (ARM, 'carriage_mass = "98 g"', 'carriage_mass = "98 g"\nq1_min = "200 deg"\nq1_max = "100 deg"',
     [("components.arm.q1_max", "must be above q1_min (200 deg), got 100 deg")]),
    # was "components.arm: path: acceleration: must be positive, got -1.0 (SI)"
    (ARM, 'speed = "1.4 cm/s"', 'speed = "1.4 cm/s", acceleration = "-1 m/s^2"',
     [("components.arm.path.acceleration", "must be > 0, got '-1 m/s^2'")]),
])
def test_values_as_written_not_si_or_repr(tmp_path, text, old, new, expected):
    """Review item 6: a design-file value is shown as written, not as an SI number or a pint repr."""
    assert errors(tmp_path, text, old, new) == expected


def test_profile_of_a_bad_arm_does_not_repeat_its_error(tmp_path):
    """The drive that follows a bad arm points at it; the arm's message is given once, at its key."""
    text = ARM + ('\n[profiles.q1]\ntype = "joint_motion"\nmechanism = "arm"\njoint = "q1"\n\n[components.revolute]\n'
                  'type = "drive"\nmotor = "maxon 6V 10.3 mNm"\ngearhead = "GP 22 850:1"\ninertia = "0 kg*m^2"\n'
                  'profile = "q1"\n')
    errs = errors(tmp_path, text, 'r = "8 cm - 1.5 cm * cos(4*phi)"', 'r = "8"')
    assert errs[0][0] == "components.arm.path.r"
    assert errs[1:] == [("components.revolute", "profile 'q1': the arm 'arm' is invalid (see its errors)")]


def test_joint_limits_from_python_show_angles_not_reprs():
    """Review item 6: ``(<Quantity(200, 'degree')>, ...)`` in the Python API's message."""
    from mechverify import Q
    from mechverify.errors import InputError
    from mechverify.mechanisms.workspace import joint_limits

    with pytest.raises(InputError, match=r"^joint limits\.theta_left: low must be below high, got \(200 deg, 100 deg\)$"):
        joint_limits({"theta_left": (Q(200, "deg"), Q(100, "deg"))}, ("theta_left",))


def test_as_written_replaces_an_si_value_only():
    """require_positive's SI value (bare '(SI)' or, with its dim, 'got -0.1 m') becomes the value as written at the
    key; a value already in the user's unit ('-4 mm') and a key not in the table are left alone."""
    from mechverify.design.loader import as_written

    table = {"distal_left": "-100 mm", "n": -3.0}
    for msg in ("must be positive, got -0.1 m", "must be positive, got -0.1 (SI)"):
        assert as_written("c.fb.distal_left", msg, table, "c.fb") == 'must be positive, got "-100 mm"'
    assert as_written("c.fb.n", "must be zero or positive, got -3", table, "c.fb") == "must be zero or positive, got -3.0"
    assert as_written("c.fb.distal_left", "must be positive, got -4 mm", table, "c.fb") == "must be positive, got -4 mm"
    assert as_written("c.fb.other", "must be positive, got -0.1 m", table, "c.fb") == "must be positive, got -0.1 m"


# ------------------------------------------------ review (round 2 session 3) finding 25: a material's bad value
MATERIAL_TEXT = """
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
    from tests.builders import refusal

    text = refusal(tmp_path, MATERIAL_TEXT)
    assert "materials.mystery.density: must be positive" in text
    assert "mystery.density: mystery" not in text and "materials.mystery: mystery." not in text
    assert "unknown material" not in text and "1 error" in text
