"""``mechverify size`` and ``mechverify study`` from the command line (exit codes, files, reproduce -> check).

Expected numbers: the hand-calculated lift-mass limit of tests/test_studies.py (14.86 kg, a hand
calculation from Hamrock Eq. 16.10 and the stepper's pull-out points, not a printed value).
"""

from __future__ import annotations

import json
import time

import pytest

from mechverify.cli import main
from tests.builders import EXAMPLES, LIFT


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


# ------------------------------------------------ review (round 2 session 3) findings 34, 6: units in the console
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


# ------------------------------------------------ review finding 33: the no-crossing message
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


# ------------------------------------------------ review findings 5, 26, 30: options and exit status
MC = ["--vary", "parameters.lifted_load=normal:300 N:10 N"]


@pytest.mark.parametrize("argv, message", [
    (["--samples", "2", "--batch-size", "0"], "--batch-size: expected a positive integer, got 0"),
    (["--samples", "2", "--workers", "0"], "--workers: expected a positive integer, got 0"),
    (["--samples", "2", "--memory-per-worker", "2 kg"], "--memory-per-worker: expected a memory size"),
    (["--samples", "-3"], "--samples: expected a positive integer, got -3"),
    ([], "--samples: a Monte Carlo study (distributions in vary) needs the number of samples"),
    (["--samples", "2", "--serial", "--memory-per-worker", "1 GB"], "--memory-per-worker would be ignored"),
    (["--samples", "2", "--workers", "2", "--scheduler", "tcp://127.0.0.1:9"], "--workers and --scheduler"),
])
def test_study_messages_name_the_options(argv, message, capsys):
    """Finding 5 (and 28): the messages named Python arguments (batch_size, memory_per_worker, 'got None');
    --memory-per-worker was ignored silently with --serial, --workers with --scheduler."""
    rc = main(["study", str(LIFT), *MC, "--no-progress", *argv])
    err = capsys.readouterr().err
    assert rc == 2 and message in err and "None" not in err, err


@pytest.mark.parametrize("argv, message", [
    (["--vary", "parameters.lifted_load", "--bounds", "500 N:50 N"], "--bounds: expected low < high"),
    (["--vary", "parameters.lifted_load", "--scan", "0"], "--scan: expected a positive integer"),
    (["--vary", "parameters.lifted_load", "--until", "lift_screw.nope"], "unknown check"),
])
def test_size_messages_name_the_options(argv, message, capsys):
    """Finding 26: 'bounds: give the range ...' named the Python argument; the option is --bounds."""
    assert main(["size", str(LIFT), *argv]) == 2
    assert message in capsys.readouterr().err


def test_a_study_with_no_valid_sample_exits_2_and_still_writes_its_outputs(tmp_path, capsys):
    """Finding 30: every sample invalid (a negative load) exited 0 with no statistics: a CI job passed."""
    j = tmp_path / "allinv.json"
    rc = main(["study", str(LIFT), "--vary", "parameters.lifted_load=normal:-300 N:10 N", "--samples", "3",
               "--serial", "--no-progress", "--json", str(j)])
    captured = capsys.readouterr()
    assert rc == 2 and "no valid sample: all 3 samples are invalid" in captured.err
    assert "3 invalid" in captured.out
    assert [s["status"] for s in json.loads(j.read_text())["samples"]] == ["error"] * 3


# ------------------------------------------------ review finding 23: --reproduce --out elsewhere
STEP_DESIGN = """[design]
name = "step beam p"
[parameters]
q = "1 MPa"
[components.beam]
type = "solid_fea"
step = "geometry/beam.step"
material = "structural steel"
mesh_size = "5 mm"
supports = [{ face = 1 }]
deflection_limit = "10 mm"
[load_cases.tip.beam]
pressures = [{ face = 6, pressure = "q" }]
"""


def test_reproduce_into_another_folder_rewrites_relative_file_names(tmp_path, capsys):
    """Finding 23: 'step = "beam.step"' was copied verbatim into other/s1.toml, which then could not be checked
    ('file .../other/beam.step does not exist'). The file name is rewritten relative to the output's folder."""
    from mechverify.design import load
    from mechverify.studies.study import file_keys, rebase_files

    (tmp_path / "geometry").mkdir()
    (tmp_path / "geometry" / "beam.step").write_text("ISO-10303-21;\n")  # only its existence is checked at load
    design = tmp_path / "step_p.toml"
    design.write_text(STEP_DESIGN)
    out = tmp_path / "runs" / "deep" / "s1.toml"
    out.parent.mkdir(parents=True)
    rc = main(["study", str(design), "--vary", "parameters.q=normal:1 MPa:0.1 MPa", "--samples", "4",
               "--reproduce", "1", "--out", str(out)])
    assert rc == 0, capsys.readouterr().err
    assert 'step = "../../geometry/beam.step"' in out.read_text()
    assert load(out).data.raw["components"]["beam"]["step"] == "../../geometry/beam.step"  # it loads
    # the same folder keeps the name; an absolute name is kept
    same = tmp_path / "s2.toml"
    assert main(["study", str(design), "--vary", "parameters.q=normal:1 MPa:0.1 MPa", "--samples", "4",
                 "--reproduce", "1", "--out", str(same)]) == 0
    assert 'step = "geometry/beam.step"' in same.read_text()
    doc = {"components": {"b": {"stl": "/abs/x.stl"}}, "templates": {"t": {"step": "a.step"}}}
    assert rebase_files(doc, tmp_path, tmp_path / "o") == {"components": {"b": {"stl": "/abs/x.stl"}},
                                                           "templates": {"t": {"step": "../a.step"}}}
    # every file-name key of the component types is rebased (declared Field(..., file=True))
    import re

    from mechverify.design.spec import REGISTRY

    file_fields = {f.name for t in REGISTRY.types.values() for f in t.fields
                   if f.kind == "str" and re.search(r"\bfile\b", f.doc or "", re.I)}
    outputs = {"vtu"}  # solid_fea's output folder (made if missing): a reproduced sample writes beside itself
    assert file_fields - outputs <= set(file_keys()), file_fields
    assert {"step", "stl", "mesh"} <= set(file_keys())


def test_file_keys_come_from_the_component_types(tmp_path, monkeypatch):
    """The keys rebased for another folder are the fields a component type declares as files (cleanup2: they were
    a hand list, FILE_KEYS = ("step", "stl", "mesh"), in studies/study.py that a new type's file key had to join):
    a type registered with Field("drawing", "str", ..., file=True) gets its file rebased, with no list to edit."""
    from mechverify.design.spec import REGISTRY, ComponentType, Field
    from mechverify.studies.study import file_keys, rebase_files

    REGISTRY.types  # noqa: B018  (every built-in type registered first)
    ct = ComponentType("drawing_test", "a test type", (Field("drawing", "str", "a DXF file", file=True),),
                       build=lambda p, ctx: None)
    monkeypatch.setitem(REGISTRY._types, ct.name, ct)
    assert "drawing" in file_keys()
    doc = {"components": {"d": {"type": "drawing_test", "drawing": "parts/d.dxf"}}}
    assert rebase_files(doc, tmp_path, tmp_path / "out")["components"]["d"]["drawing"] == "../parts/d.dxf"


def test_report_scatter_has_a_verdict_legend(monkeypatch):
    """Review 3 finding 8: the Monte Carlo report's scatter was coloured green/orange/red by verdict with no
    legend; now one entry per verdict with its sample count."""
    from mechverify.reports import study as rstudy
    from mechverify.studies import StudyResult

    figs = []
    monkeypatch.setattr(rstudy, "svg_data_uri", lambda fig: figs.append(fig) or "data:")
    verdicts = ["pass"] * 5 + ["warn"] * 2 + ["fail"] * 3
    samples = [{"index": i, "inputs": {"x": float(i)}, "status": "ok", "message": "", "verdict": v, "governing": "a.b",
                "max_fu": 0.5 + 0.1 * i, "checks": {"a.b": {"u": 0.5, "required_sf": 1.0, "fu": 0.5 + 0.1 * i,
                                                             "verdict": v}}}
               for i, v in enumerate(verdicts)]
    res = StudyResult("monte_carlo", "lhs", 0, [{"name": "x", "unit": "", "spec": "", "base": 0.0}], samples, "d")
    rstudy.scatter(res, "x")
    labels = [t.get_text() for t in figs[0].axes[0].get_legend().get_texts()]
    assert labels == ["pass (5)", "warn (2)", "fail (3)"]


# ------------------------------------------------ task fix19 (audit of issue 19): the parts of "done when" no test held
@pytest.mark.slow
def test_study_report_as_pdf_holds_the_tables_and_the_figures(tmp_path):
    """Issue 19: '--report study.html|pdf'. The PDF path (weasyprint) had no test. The report's tables and its
    figures (drawn as SVG: their text, e.g. the limit line's legend, is text in the PDF) must be in the PDF. A small
    Monte Carlo (two checks, six samples: weasyprint's time grows with the figures)."""
    import shutil
    import subprocess

    from mechverify.reports.study import write_study_report
    from mechverify.studies.study import StudyResult

    def sample(i: int, x: float) -> dict:
        fus = {"lift.motor_peak_torque": x / 10, "lift_screw.nut_pv": x / 12}
        checks = {c: {"u": v, "required_sf": 1.0, "fu": v, "verdict": "fail" if v > 1 else "pass"}
                  for c, v in fus.items()}
        return {"index": i, "inputs": {"components.lift.mass": x}, "status": "ok", "message": "",
                "verdict": "fail" if max(fus.values()) > 1 else "pass", "governing": "lift.motor_peak_torque",
                "max_fu": max(fus.values()), "checks": checks}

    axes = [{"name": "components.lift.mass", "spec": "normal:10 kg:2 kg", "unit": "kg", "integer": False,
             "base": 10.0}]
    res = StudyResult("monte_carlo", "lhs", 2, axes, [sample(i, x) for i, x in enumerate([7, 9, 10, 11, 12, 14])],
                      "lift", {}, None)
    pdf = write_study_report(res, tmp_path / "mc.pdf")
    assert pdf.read_bytes().startswith(b"%PDF-")
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext (poppler-utils) is not installed: the PDF's text is not read")
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    for part in ("Failure probability", "Sensitivity", "Most influential input", "u·SF per check",
                 "limit u·SF = 1", "lift.motor_peak_torque"):
        assert part in text, part


def test_study_draws_a_progress_bar_on_the_console(capsys):
    """Issue 19: 'Progress bar on the console'. No test asserted it is drawn (every CLI test passes
    --no-progress). The bar (rich, on stderr) counts the samples to the last one; --no-progress leaves it out."""
    args = ["study", str(LIFT), "--vary", "components.lift.mass=10 kg:20 kg:5", "--serial"]
    assert main(args) == 0
    err = capsys.readouterr().err
    assert "samples" in err and "5/5" in err, err
    assert main([*args, "--no-progress"]) == 0
    assert "5/5" not in capsys.readouterr().err


def test_size_names_the_cause_of_invalid_scan_points_not_its_cascade(capsys):
    """Task fix19 (audit; review 3 finding 14 was fixed for the study's console only): sizing the lift screw's
    length over -100..500 mm gave '... invalid at 2 of 9 scan points (-100..-25 mm): load_cases.raise.screw_bearing.
    axial_force: 'lift_screw.support_axial_force': lift_screw is invalid (see its own errors)', the LAST error of the
    cascade. Now the first, the cause, and how many there are."""
    rc = main(["size", str(LIFT), "--vary", "components.lift_screw.length", "--bounds", "-100 mm:500 mm"])
    err = capsys.readouterr().err
    assert rc == 2
    assert "invalid at 2 of 9 scan points (-100..-25 mm): components.lift_screw: lift_screw.length: must be " \
           "positive" in err and "errors)" in err, err
    assert "see its own errors" not in err, err


def test_reproduce_into_another_folder_rebases_only_the_types_file_keys(tmp_path):
    """Review 4 finding 12: the lever arm's reproduce into another folder wrote `step = "../ex/lever_arm/10 deg"`
    (the pose sweep's angle step rebased as a file name: `step` is a STEP file of solid_fea, a number of
    lever_arm_sweep) and `check` of it failed with 52 errors. Only the keys the table's own type (or its template's)
    declares as files are rebased; a table of unknown type keeps every type's file keys."""
    import tomllib

    from mechverify.studies.study import rebase_files

    doc = {"components": {"arm": {"type": "lever_arm_sweep", "step": "10 deg"},
                          "beam": {"type": "solid_fea", "step": "beam.step"},
                          "copy": {"extends": "t"}},
           "templates": {"t": {"type": "solid_fea", "step": "t.step"}, "u": {"step": "u.step"}}}
    out = rebase_files(doc, tmp_path, tmp_path / "repro")
    assert out["components"]["arm"]["step"] == "10 deg"
    assert out["components"]["beam"]["step"] == "../beam.step"
    assert out["templates"] == {"t": {"type": "solid_fea", "step": "../t.step"}, "u": {"step": "../u.step"}}
    # the lever arm example itself (its arm is the lever_arm_sweep of arm.toml, merged by the study)
    data = tomllib.loads((EXAMPLES / "lever_arm" / "arm.toml").read_text())
    arm = {"components": {k: dict(v) for k, v in data["components"].items()}}
    assert any(t.get("type") == "lever_arm_sweep" and "step" in t for t in arm["components"].values())
    assert rebase_files(arm, EXAMPLES / "lever_arm", tmp_path / "repro") == {
        "components": {k: dict(v) for k, v in data["components"].items()}}
