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
