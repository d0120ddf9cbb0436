"""Regressions of the newcomer review of the studies (review round 2 session 3, /tmp/notes/review.md).

Each test names its finding. Numbers checked against a source are marked so; most of these tests are
about the command line's behaviour (what is refused, what is printed), not about formula values.
"""

from __future__ import annotations

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
