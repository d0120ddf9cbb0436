"""No exception other than mechverify's own reaches the user: every case of issue 17 gives a named error
with its key path (exit 2) or the documented behaviour, never an internal error (exit 3).

The design is the starter of ``mechverify init`` (a Tr10x2 lead-screw lift with a 608 bearing), edited
one value at a time.
"""

from __future__ import annotations

import warnings
from importlib import resources
from pathlib import Path

import pytest

from mechverify import Q
from mechverify.cli import main
from mechverify.errors import InputError
from mechverify.units import BOUNDS, PlausibilityWarning, as_quantity

STARTER = resources.files("mechverify.design").joinpath("starter.toml").read_text(encoding="utf-8")


def edited(tmp_path: Path, old: str, new: str, name: str = "design.toml") -> Path:
    assert old in STARTER, old
    p = tmp_path / name
    p.write_text(STARTER.replace(old, new, 1))
    return p


def run(capsys, path: Path, *extra: str) -> tuple[int, str, str]:
    code = main(["check", str(path), *extra])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err and "internal error" not in cap.err, cap.err
    return code, cap.out, cap.err


@pytest.mark.parametrize(("old", "new", "key"), [
    ('length = "450 mm"', 'length = "1e300 mm"', "components.lift_screw.length"),
    ('length = "450 mm"', 'length = "1e-300 mm"', "components.lift_screw.length"),
    ('axial_force = "300 N"', 'axial_force = "1e300 N"', "load_cases.raise.lift_screw.axial_force"),
    ('axial_force = "300 N"\nradial_force', 'axial_force = "1e-300 N"\nradial_force',
     "load_cases.raise.top_bearing.axial_force"),
])
def test_magnitudes_outside_physical_bounds_are_named_errors(tmp_path, capsys, old, new, key):
    code, _, err = run(capsys, edited(tmp_path, old, new))
    assert code == 2
    assert f"{key}: " in err and "outside the physically meaningful range" in err


def test_bounds_table_and_api():
    """Zero passes (a free end, no load); the lower bound applies to text only (computed values may be tiny)."""
    assert set(BOUNDS) >= {"length", "force", "pressure", "time"}
    assert as_quantity("0 N", "force").magnitude == 0
    assert as_quantity(Q(1e-20, "N"), "force").magnitude == 1e-20
    with pytest.raises(InputError, match="F: .*outside"):
        as_quantity(Q(1e300, "N"), "force", "F")
    with pytest.raises(InputError, match="outside"):
        as_quantity("1e-300 mm", "length")


def test_plausibility_warning_for_an_implausible_unit(tmp_path, capsys):
    with pytest.warns(PlausibilityWarning, match="300 km"):
        as_quantity("300 km", "length", "length")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        as_quantity("450 mm", "length")  # no warning for a plausible value
    code, _, err = run(capsys, edited(tmp_path, 'length = "450 mm"', 'length = "300 km"'), "-q")
    assert code in (0, 1)
    assert "warning: components.lift_screw.length: 300 km is implausible" in err


def test_motor_data_without_step_angle(tmp_path, capsys):
    p = tmp_path / "d.toml"
    p.write_text("""
[design]
name = "m"
[profiles.p]
type = "trapezoidal"
distance = "100 mm"
max_velocity = "50 mm/s"
acceleration = "0.5 m/s^2"
[components.d]
type = "drive"
profile = "p"
mass = "2 kg"
motor_data = { type = "stepper", holding_torque = "0.4 N*m", rotor_inertia = "50 g*cm^2", pullout_speeds = ["0 rpm", "600 rpm"], pullout_torques = ["0.4 N*m", "0.2 N*m"] }
transmission = [{ type = "drum", diameter = "20 mm" }]
""")
    code, _, err = run(capsys, p)
    assert code == 2 and "components.d.motor_data.step_angle: missing" in err


@pytest.mark.parametrize("value", ["inf", "nan", "0", "-2", '"2"'])
def test_safety_factor_must_be_positive_and_finite(tmp_path, capsys, value):
    code, _, err = run(capsys, edited(tmp_path, "static = 2.0", f"static = {value}"))
    assert code == 2 and "requirements.safety_factors.static: expected a positive finite number" in err


def test_design_name_not_a_string(tmp_path, capsys):
    code, _, err = run(capsys, edited(tmp_path, 'name = "My lift"', "name = 42"))
    assert code == 2 and "design.name: expected a string, got 42" in err


def test_extends_cycle_is_named(tmp_path, capsys):
    p = edited(tmp_path, '[components.top_bearing]         # the bearing that carries the screw\'s axial load\n'
                         'type = "ball_bearing"',
               '[templates.a]\nextends = "b"\n[templates.b]\nextends = "a"\n'
               '[components.top_bearing]\nextends = "a"')
    code, _, err = run(capsys, p)
    assert code == 2 and "components.top_bearing.extends: templates extend each other in a cycle: a -> b -> a" in err


def test_extends_chain_is_followed(tmp_path, capsys):
    p = edited(tmp_path, '[components.top_bearing]         # the bearing that carries the screw\'s axial load\n'
                         'type = "ball_bearing"\nmodel = "608"',
               '[templates.bearing]\ntype = "ball_bearing"\n[templates.b608]\nextends = "bearing"\nmodel = "608"\n'
               '[components.top_bearing]\nextends = "b608"')
    code, out, _ = run(capsys, p)
    assert code in (0, 1) and "top_bearing" in out


def test_bearing_beyond_iso281_table_is_a_fail_with_reason(tmp_path, capsys):
    """6202 (SKF: C0 = 3.75 kN, f0 = 13) at Fa = 2 kN: f0·Fa/C0 = 6.93 > 6.89, the last row of ISO 281
    Table 3. The life cannot be computed by the standard's method: the check FAILS and says why."""
    p = tmp_path / "b.toml"
    p.write_text('[design]\nname = "b"\n[components.b]\ntype = "ball_bearing"\nmodel = "6202"\n'
                 '[load_cases.c.b]\naxial_force = "2 kN"\nradial_force = "100 N"\nspeed = "100 rpm"\n')
    code, out, err = run(capsys, p)
    assert code == 1, err
    assert "FAIL" in out and "bearing_life" in out and "6.93" in out and "ISO 281" in out


def test_design_without_components(tmp_path, capsys):
    p = tmp_path / "e.toml"
    p.write_text('[design]\nname = "empty"\n')
    code, _, err = run(capsys, p)
    assert code == 2 and "no components" in err
    assert main(["diff", str(p), str(p)]) == 2
    assert "no components" in capsys.readouterr().err


def test_negative_bearing_life_at_its_key(tmp_path, capsys):
    code, _, err = run(capsys, edited(tmp_path, 'bearing_life = "10000 h"', 'bearing_life = "-5000 h"'))
    assert code == 2 and 'requirements.bearing_life: must be positive, got "-5000 h"' in err


def test_life_in_revolutions(tmp_path, capsys):
    code, _, err = run(capsys, edited(tmp_path, 'bearing_life = "10000 h"', 'bearing_life = "5000 rev"'))
    assert code == 2
    assert 'requirements.bearing_life: expected a time, got "5000 rev"; a number of revolutions' in err


def test_check_settings_without_enabled_turn_the_check_on(tmp_path, capsys):
    """holding_torque is off by default; a table of settings switches it on (docs/design-files.md), so
    it now asks for its load; `enabled = false` with settings keeps it off."""
    on = edited(tmp_path, "# [components.lift_screw.checks]",
                "[components.lift_screw.checks]\nholding_torque = { required_sf = 3 }")
    code, _, err = run(capsys, on)
    assert code == 2 and "components.lift_screw.checks.holding_torque: needs" in err
    off = edited(tmp_path, "# [components.lift_screw.checks]",
                 "[components.lift_screw.checks]\nholding_torque = { required_sf = 3, enabled = false }")
    code, out, _ = run(capsys, off)
    assert code in (0, 1) and "holding" not in out.lower()
    bad = edited(tmp_path, "# [components.lift_screw.checks]",
                 "[components.lift_screw.checks]\nbuckling = { enabled = \"yes\" }")
    code, _, err = run(capsys, bad)
    assert code == 2 and "checks.buckling.enabled: expected true or false" in err


def test_schema_describes_motor_data_and_gearhead_data():
    """Every key a user can write is in the schema: the motor_data variants (by `type`) and gearhead_data
    come from the component dataclasses, so a missing step_angle is caught by an editor too."""
    import jsonschema

    from mechverify.design.schema import design_schema

    text = str(design_schema())
    assert "step_angle" in text and "max_input_speed" in text
    motor = {"type": "stepper", "step_angle": "1.8 deg", "holding_torque": "0.4 N*m"}
    schema = _find(design_schema(), "motor_data")
    jsonschema.validate(motor, schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({k: v for k, v in motor.items() if k != "step_angle"}, schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({**motor, "colour": "red"}, schema)
    jsonschema.validate({"ratio": "26/7", "efficiency": 0.8}, _find(design_schema(), "gearhead_data"))


def _find(node, key):
    """The first sub-schema under ``properties[key]`` anywhere in ``node``."""
    if isinstance(node, dict):
        if key in node.get("properties", {}):
            return node["properties"][key]
        for v in node.values():
            hit = _find(v, key)
            if hit is not None:
                return hit
    elif isinstance(node, list):
        for v in node:
            hit = _find(v, key)
            if hit is not None:
                return hit
    return None


def test_docs_list_every_motor_data_and_gearhead_data_key():
    """docs/design-files.md names every key of the inline datasheet tables (from the component classes)."""
    from dataclasses import fields

    from mechverify.components.gearheads import Gearhead
    from mechverify.components.motors import _TYPES

    text = (Path(__file__).resolve().parents[1] / "docs" / "design-files.md").read_text(encoding="utf-8")
    for cls in [*_TYPES.values(), Gearhead]:
        for f in fields(cls):
            if f.init and f.name != "derived":
                assert f"`{f.name}`" in text, (cls.__name__, f.name)
