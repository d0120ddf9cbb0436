"""Regressions of the newcomer review of the studies (review round 2 session 3, /tmp/notes/review.md).

Each test names its finding. Numbers checked against a source are marked so; most of these tests are
about the command line's behaviour (what is refused, what is printed), not about formula values.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mechverify.cli import main
from mechverify.errors import InputError
from mechverify.studies import Study, size

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
LIFT = EXAMPLES / "lead_screw_lift" / "design.toml"


# ---------------------------------------------------------------- finding 34: bare numbers for an expression


def test_bare_numbers_are_refused_for_a_value_written_as_an_expression(capsys):
    """Finding 34: the carriage's load_offset is written as '2 * (120 N * 400 mm + 30 N * 800 mm) / lifted_load'
    (411 mm); '300:500:2' used to sweep 300..500 METRES (u·SF 3601) without a word. Now refused, naming a unit."""
    with pytest.raises(InputError, match=r"bare number 300 has no unit.*expression.*0\.411 m"):
        Study(LIFT, vary=["components.carriage.load_offset=300:500:2"])
    with pytest.raises(InputError, match="has no unit"):
        Study(LIFT, vary=["components.carriage.load_offset=normal:400:10"], samples=4)
    with pytest.raises(InputError, match="has no unit"):
        size(LIFT, "components.carriage.load_offset", bounds=(300, 500))
    rc = main(["study", str(LIFT), "--vary", "components.carriage.load_offset=300:500:2", "--serial",
               "--no-progress"])
    assert rc == 2 and "give the unit" in capsys.readouterr().err
    # with a unit it is read as written; bare numbers of a value written with a unit keep the file's unit
    s = Study(LIFT, vary=["components.carriage.load_offset=300 mm:500 mm:2"])
    assert s.axes[0].args[:2] == pytest.approx((0.3, 0.5))
    assert Study(LIFT, vary=["components.lift_screw.length=400:500:2"]).axes[0].param.unit == "mm"


def test_the_sweep_table_and_worst_sample_print_units(capsys):
    """Findings 34 and 6: the console's sweep header and the worst-sample line carry the unit."""
    rc = main(["study", str(LIFT), "--vary", "components.carriage.load_offset=300 mm:500 mm:2", "--serial",
               "--no-progress"])
    out = capsys.readouterr().out
    assert rc == 0 and "components.carriage.load_offset [m]" in out
    rc = main(["study", str(LIFT), "--vary", "components.lift.mass=normal:15 kg:1 kg", "-n", "4", "--serial",
               "--no-progress"])
    out = capsys.readouterr().out
    worst = next(line for line in out.splitlines() if line.startswith("worst sample"))
    assert rc == 0 and worst.rstrip().endswith(" kg"), worst


# ---------------------------------------------------------------- finding 33: the no-crossing message


def test_size_without_a_crossing_says_which_side_the_valid_points_lie(tmp_path, capsys):
    """Finding 33: cable neck wire_d 2..4 mm: 2..2.75 mm invalid (the weight alone buckles the spine), 3..4 mm
    all fail (spine_buckling_ratio u·SF 2.76..1.92). The message said 'below 1 over the range'; now 'above 1'
    over the valid part, with the invalid part and its reason; --json holds the scan (limit null)."""
    out = tmp_path / "nolimit.json"
    rc = main(["size", str(EXAMPLES / "cable_neck" / "design.toml"), "--vary", "parameters.wire_d",
               "--bounds", "2 mm:4 mm", "--json", str(out)])
    err = capsys.readouterr().err
    assert rc == 2
    assert "above 1 (fails) over the valid part (3..4 mm)" in err and "below 1" not in err
    assert "invalid at 4 of 9 scan points (2..2.75 mm)" in err and "alone buckles the spine" in err
    data = json.loads(out.read_text())
    assert data["limit"] is None and len(data["scan"]) == 9
    assert [p["fu"] is None for p in data["scan"]] == [True] * 4 + [False] * 5
    assert all(p["fu"] > 1 for p in data["scan"][4:]) and "buckles" in data["scan"][0]["invalid"]


def test_sweep_lists_the_whole_reason_of_an_invalid_sample(capsys):
    """Finding 33: the invalid reason was cut at 100 characters ('neck: the w')."""
    rc = main(["study", str(EXAMPLES / "cable_neck" / "design.toml"), "--vary", "parameters.wire_d=2 mm:3 mm:2",
               "--serial", "--no-progress"])
    out = capsys.readouterr().out
    assert rc == 0 and "sample 0 invalid:" in out and "reachable: no tilt" in out
