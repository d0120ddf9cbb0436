"""``mechverify size`` and ``mechverify study`` from the command line (exit codes, files, reproduce -> check).

Expected numbers: the hand-calculated lift-mass limit of tests/test_studies.py (14.86 kg, a hand
calculation from Hamrock Eq. 16.10 and the stepper's pull-out points, not a printed value).
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from mechverify.cli import main

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


def test_size_prints_the_limit_and_writes_json(tmp_path, capsys):
    out = tmp_path / "size.json"
    rc = main(["size", str(LIFT), "--vary", "components.lift.mass", "--until", "motor_peak_torque",
               "--bounds", "1 kg:100 kg", "--json", str(out)])
    assert rc == 0
    assert "limit 14.8" in capsys.readouterr().out
    assert json.loads(out.read_text())["limit"] == pytest.approx(14.86, abs=0.01)


def test_size_without_a_crossing_is_exit_2_with_both_ends(capsys):
    rc = main(["size", str(LIFT), "--vary", "components.lift.mass", "--until", "lift.motor_peak_torque",
               "--bounds", "1 kg:5 kg"])
    err = capsys.readouterr().err
    assert rc == 2 and "does not cross 1" in err and "at 1 kg" in err and "at 5 kg" in err


def test_study_sweep_json_csv_report(tmp_path, capsys):
    j, c, r = tmp_path / "s.json", tmp_path / "s.csv", tmp_path / "s.html"
    rc = main(["study", str(LIFT), "--vary", "components.lift.mass=10 kg:20 kg:3", "--serial", "--no-progress",
               "--json", str(j), "--csv", str(c), "--report", str(r)])
    assert rc == 0
    text = capsys.readouterr().out
    assert "sweep of" in text and "3 samples" in text
    data = json.loads(j.read_text())
    assert [s["inputs"]["components.lift.mass"] for s in data["samples"]] == [10.0, 15.0, 20.0]
    assert len(c.read_text().splitlines()) == 4
    html = r.read_text()
    assert html.startswith("<!DOCTYPE html>") and "Sweep curves" in html and "data:image/svg+xml" in html


def test_study_monte_carlo_report_and_reproduce_goes_through_check(tmp_path, capsys):
    r = tmp_path / "mc.html"
    args = ["study", str(LIFT), "--vary", "components.lift.mass=normal:15 kg:1 kg", "-n", "16", "--seed", "2",
            "--serial", "--no-progress"]
    assert main([*args, "--report", str(r)]) == 0
    out = capsys.readouterr().out
    assert "P_fail" in out and "lift.motor_peak_torque" in out and "Wilson" in out
    html = r.read_text()
    for part in ("Failure probability", "Sensitivity", "Most influential input", "u·SF per check",
                 "the check the tolerances decide"):
        assert part in html
    sample = tmp_path / "sample3.toml"
    assert main([*args, "--reproduce", "3", "--out", str(sample)]) == 0
    assert "mechverify check" in capsys.readouterr().out
    rc = main(["check", str(sample), "--json", str(tmp_path / "c.json")])
    assert rc in (0, 1)  # it verifies (the screw in bending fails in every sample)
    from mechverify.studies import Study

    s = Study(LIFT, vary={"components.lift.mass": "normal:15 kg:1 kg"}, samples=16, seed=2)
    mass = s.inputs()[3]["components.lift.mass"]
    assert f'mass = "{mass!r} kg"' in sample.read_text()


@pytest.mark.parametrize("argv, message", [
    (["--vary", "components.lift.nope=1:2:2"], "unknown parameter"),
    (["--vary", "components.lift.mass=normal:15 kg:-1 kg", "-n", "4"], "standard deviation"),
    (["--vary", "components.lift.mass=normal:15 kg:1 kg", "-n", "0"], "zero samples"),
    (["--vary", "components.lift.mass=1 m:2 m:3"], "dimension"),
    (["--vary", "components.lift.mass=normal:15 kg:1 kg", "-n", "4", "--reproduce", "9", "--out", "x.toml"],
     "does not exist"),
])
def test_study_bad_input_exit_2(argv, message, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["study", str(LIFT), "--serial", "--no-progress", *argv]) == 2
    assert message in capsys.readouterr().err


def test_study_unreachable_scheduler_exit_2_within_timeout(capsys, monkeypatch):
    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", "tcp://127.0.0.1:9")
    t = time.perf_counter()
    rc = main(["study", str(LIFT), "--vary", "components.lift.mass=10 kg:20 kg:2", "--timeout", "2", "--no-progress"])
    assert rc == 2 and "cannot reach the Dask scheduler at tcp://127.0.0.1:9" in capsys.readouterr().err
    assert time.perf_counter() - t < 15


def test_report_histogram_of_a_nearly_constant_check():
    """u·SF equal up to rounding in every sample (3.149, one sample one ulp higher: matplotlib cannot make
    8 bins of that range) still gives one bar, not an error."""
    from mechverify.reports.study import histogram
    from mechverify.studies import StudyResult

    samples = [{"index": i, "inputs": {"x": float(i)}, "status": "ok", "message": "", "verdict": "fail",
                "governing": "a.b", "max_fu": 3.149 + (i == 5) * 4.5e-16,
                "checks": {"a.b": {"u": 1.0, "required_sf": 1.0, "fu": 3.149 + (i == 5) * 4.5e-16, "verdict": "fail"}}}
               for i in range(64)]
    res = StudyResult("monte_carlo", "lhs", 0, [{"name": "x", "unit": "", "spec": "", "base": 0.0}], samples, "d")
    assert histogram(res, "a.b").startswith("data:image/svg+xml;base64,")
