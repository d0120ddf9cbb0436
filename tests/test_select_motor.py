"""``mechverify select-motor``: each combination's verdict and margin are those of ``mechverify check`` on the
design with that motor and gearhead written in (a consistency test: the checks themselves are validated in
tests/test_motor_fit.py and tests/validation/); exit codes and named errors."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechverify.cli import main
from mechverify.cli.select_motor import combinations
from mechverify.design import load

EXAMPLE = Path(__file__).parents[1] / "examples" / "rp_robot" / "design.toml"


def _drive_name() -> str:
    text = EXAMPLE.read_text(encoding="utf-8")
    return re.search(r"\[components\.([\w-]+)\]\s*\ntype = \"drive\"", text).group(1)


def test_combination_equals_check_with_the_motor_written_in(tmp_path):
    design, drive = load(EXAMPLE), _drive_name()
    [c] = combinations(design, drive, motors=["maxon 6V 10.3 mNm"], gearheads=["GP 22 850:1"])
    rs = [r for r in design.verify() if r.component == drive]  # the example uses exactly this combination
    worst = max(rs, key=lambda r: r.factored_utilisation)
    assert c.governing == worst.check and c.margin == pytest.approx(1 / worst.factored_utilisation)
    assert c.passed == all(r.verdict.value != "fail" for r in rs)


def test_cli_exit_codes(capsys):
    drive = _drive_name()
    code = main(["select-motor", str(EXAMPLE), "--drive", drive, "--motor", "maxon 6V 10.3 mNm",
                 "--gearhead", "GP 22 850:1", "--gearhead", "none"])
    out = capsys.readouterr().out
    assert code in (0, 1) and "maxon 6 V DC motor" in out
    assert main(["select-motor", str(EXAMPLE), "--drive", "nope"]) == 2
    assert "nope" in capsys.readouterr().err
    # a motor alone (no gearhead) cannot drive the arm: none passes, the nearest are shown with the failing check
    code = main(["select-motor", str(EXAMPLE), "--drive", drive, "--motor", "maxon RE13", "--gearhead", "none"])
    out = capsys.readouterr().out
    assert code == 1 and "no combination" in out and "failing check" in out


# ------------------------------------------------------------------ a user's catalogue file (--catalogue)
USER = """
[references]
mine = "my datasheet, rev. A"

[[motor]]
type = "dc"
name = "my 6 V motor"
source = "mine"
nominal_voltage = "6 V"
no_load_speed = "6350 rpm"
no_load_current = "52.9 mA"
nominal_speed = "4540 rpm"
nominal_torque = "10.3 mN*m"
nominal_current = "1.2 A"
stall_torque = "36.3 mN*m"
stall_current = "4.07 A"
terminal_resistance = "1.47 ohm"
torque_constant = "8.91 mN*m/A"
speed_constant = "1070 rpm/V"
rotor_inertia = "2.68 g*cm**2"
"""


def _copy_of(motor_name: str) -> str:
    """The built-in row of ``motor_name`` as a user entry under another name (every key kept)."""
    import tomllib

    from mechverify.components.motors import motor as get

    rows = tomllib.loads((Path(__file__).parents[1] / "mechverify" / "components" / "data" / "motors.toml")
                         .read_text(encoding="utf-8"))["motor"]
    name = get(motor_name).name
    row = next(r for r in rows if r["name"] == name)
    lines = ["[[motor]]", 'name = "my copy"'] + [f"{k} = {v!r}".replace("'", '"') for k, v in row.items()
                                                 if k not in ("name", "aliases", "source", "notes")]
    return "\n".join(lines) + "\n"


def test_user_catalogue_motor_equals_the_builtin_it_copies(tmp_path):
    """A user's copy of a catalogue motor under another name gives the same verdict and margin as the original
    (the user entry runs as an inline motor_data table)."""
    from mechverify.cli.select_motor import read_user_catalogues

    f = tmp_path / "my_motors.toml"
    f.write_text(_copy_of("maxon 6V 10.3 mNm"))
    user = read_user_catalogues([f])
    design, drive = load(EXAMPLE), _drive_name()
    [orig] = combinations(design, drive, motors=["maxon 6V 10.3 mNm"], gearheads=["GP 22 850:1"])
    [mine] = combinations(design, drive, motors=["my copy"], gearheads=["GP 22 850:1"], user=user)
    assert (mine.passed, mine.governing) == (orig.passed, orig.governing)
    assert mine.margin == pytest.approx(orig.margin, rel=1e-12)


def test_user_catalogue_on_the_command_line(tmp_path, capsys):
    f = tmp_path / "my_motors.toml"
    f.write_text(USER)
    code = main(["select-motor", str(EXAMPLE), "--drive", _drive_name(), "--catalogue", str(f), "--motor",
                 "my 6 V motor", "--gearhead", "GP 22 850:1"])
    assert code in (0, 1) and "my 6 V motor" in capsys.readouterr().out


@pytest.mark.parametrize("text, message", [
    (USER.replace("torque_constant", "torque_konstant"), "motor[0].torque_konstant: unknown key; did you mean "
                                                          "'torque_constant'"),
    (USER.replace('name = "my 6 V motor"', ""), "motor[0].name: missing"),
    (USER.replace('type = "dc"', 'type = "dc"\n').replace("[[motor]]", "[[motors]]"), "motors: unknown table; "
                                                                                      "did you mean 'motor'"),
    (USER + USER.split("[[motor]]")[1].join(["[[motor]]", ""]), "used twice"),
    (USER.replace('name = "my 6 V motor"', 'name = "maxon 6V 10.3 mNm"'), "already a catalogue name"),
    ("[[motor]]\nname = 'x'\ntype = 'dc'\nnominal_voltage = \n", "not valid TOML"),
    ("[references]\n", "no entries"),
])
def test_user_catalogue_named_errors(tmp_path, capsys, text, message):
    """Every bad file is exit 2 with the file name and the key path, never a traceback."""
    f = tmp_path / "my_motors.toml"
    f.write_text(text)
    code = main(["select-motor", str(EXAMPLE), "--drive", _drive_name(), "--catalogue", str(f)])
    err = capsys.readouterr().err
    assert code == 2 and message in err and "my_motors.toml" in err, err


def test_user_catalogue_missing_file(tmp_path, capsys):
    code = main(["select-motor", str(EXAMPLE), "--drive", _drive_name(), "--catalogue", str(tmp_path / "no.toml")])
    assert code == 2 and "not found" in capsys.readouterr().err
