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


# ---------------------------------------------------------------- findings 3, 4: a scheduler that is not one


class _FakePeer:
    """A TCP server on 127.0.0.1 that is not a Dask scheduler: it accepts and sends ``reply`` (or nothing)."""

    def __init__(self, reply: bytes):
        import socket
        import threading

        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.reply, self.conns = reply, []
        self.address = f"tcp://127.0.0.1:{self.sock.getsockname()[1]}"
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            self.conns.append(c)
            if self.reply:
                c.sendall(self.reply)

    def close(self) -> None:
        for c in self.conns:
            c.close()
        self.sock.close()


@pytest.mark.parametrize("reply", [b"", b"HTTP/1.0 400 Bad Request\r\n\r\n" + b"\xff" * 64],
                         ids=["silent", "garbage"])
def test_a_peer_that_is_not_a_dask_scheduler_is_a_named_error_within_the_timeout(reply, capsys):
    """Findings 3 and 4: a silent peer hung past --timeout; a peer sending bytes that are not Dask frames gave
    'internal error: MemoryError: Unable to allocate 3.07 EiB', exit 3. Now exit 2 within the deadline."""
    pytest.importorskip("distributed")
    import time

    peer = _FakePeer(reply)
    try:
        import distributed  # noqa: F401  (imported before the clock starts: its import takes seconds here)

        t = time.perf_counter()
        rc = main(["study", str(LIFT), "--vary", "parameters.lifted_load=normal:300 N:10 N", "--samples", "2",
                   "--scheduler", peer.address, "--timeout", "2", "--no-progress"])
        took = time.perf_counter() - t
    finally:
        peer.close()
    err = capsys.readouterr().err
    assert rc == 2 and f"cannot reach the Dask scheduler at {peer.address} within 2 s" in err
    assert "internal error" not in err
    assert took < 2 + 3  # the deadline plus loading the design


def test_a_half_made_client_is_closed_without_a_traceback():
    """Finding 4: 'nonsense' (no port) left a half-made Client whose __del__ waited 6 s at exit and printed
    'Exception ignored in: <function Client.__del__> ... TimeoutError'. Run in a fresh interpreter (the
    traceback comes at its exit)."""
    pytest.importorskip("distributed")
    import subprocess
    import sys
    import time

    code = ("import time\nfrom mechverify.studies import SchedulerError, dask_executor\n"
            "try:\n    with dask_executor('nonsense', timeout=3):\n        pass\n"
            "except SchedulerError as e:\n    print('named:', e)\n"
            "import atexit\nt = time.perf_counter()\natexit.register(lambda: print('exit', time.perf_counter() - t))\n")
    t = time.perf_counter()
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    took = time.perf_counter() - t
    assert "named: cannot reach the Dask scheduler at nonsense" in p.stdout, p.stdout + p.stderr
    assert "Exception ignored" not in p.stderr and "Traceback" not in p.stderr, p.stderr
    assert took < 15  # (the old half-made client alone waited 6 s at exit)


# ---------------------------------------------------------------- findings 5, 28, 29, 30: options and exit status

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


def test_memory_per_worker_says_what_it_chose(capsys, monkeypatch):
    """Finding 28: '--memory-per-worker 100 GB' on a smaller box ran silently; now a note with the workers chosen
    and a warning that one sample may not fit."""
    from mechverify.studies import execution

    monkeypatch.setattr(execution, "available_memory", lambda: 16e9)
    monkeypatch.setattr(execution, "process_pool", lambda workers=None: execution.SerialExecutor())
    rc = main(["study", str(LIFT), *MC, "--samples", "2", "--memory-per-worker", "100 GB", "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 0 and "note: 1 local worker(s) for 100 GB per sample (16 GB of memory available)" in err
    assert "one sample may not fit" in err


@pytest.mark.parametrize("local", [["--serial"], ["--workers", "1"]])
def test_an_explicit_local_run_beats_dask_scheduler_address(local, capsys, monkeypatch):
    """Finding 29: with DASK_SCHEDULER_ADDRESS set, --serial was refused ('--serial and --scheduler: choose one')
    and --workers went to the cluster. The variable is a default; an explicit local choice wins."""
    from mechverify.studies import execution

    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", "tcp://127.0.0.1:9")
    monkeypatch.setattr(execution, "process_pool", lambda workers=None: execution.SerialExecutor())
    rc = main(["study", str(LIFT), *MC, "--samples", "2", "--no-progress", *local])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    assert "Monte Carlo study" in captured.out and "Dask" not in captured.err


def test_a_study_with_no_valid_sample_exits_2_and_still_writes_its_outputs(tmp_path, capsys):
    """Finding 30: every sample invalid (a negative load) exited 0 with no statistics: a CI job passed."""
    j = tmp_path / "allinv.json"
    rc = main(["study", str(LIFT), "--vary", "parameters.lifted_load=normal:-300 N:10 N", "--samples", "3",
               "--serial", "--no-progress", "--json", str(j)])
    captured = capsys.readouterr()
    assert rc == 2 and "no valid sample: all 3 samples are invalid" in captured.err
    assert "3 invalid" in captured.out
    assert [s["status"] for s in json.loads(j.read_text())["samples"]] == ["error"] * 3


# ---------------------------------------------------------------- finding 23: --reproduce --out elsewhere

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
    from mechverify.studies.study import FILE_KEYS, rebase_files

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
    # every file-name key of the component types is rebased (a new one must join FILE_KEYS)
    import re

    from mechverify.design import adapters  # noqa: F401  (registers the types)
    from mechverify.design.spec import REGISTRY

    file_fields = {f.name for t in REGISTRY.types.values() for f in t.fields
                   if f.kind == "str" and re.search(r"\bfile\b", f.doc or "", re.I)}
    assert file_fields <= set(FILE_KEYS), file_fields


# ---------------------------------------------------------------- finding 1: a key the file does not write


def test_a_component_key_left_to_its_default_can_be_varied(tmp_path):
    """Finding 1: a key the component type defines but the file does not write was 'unknown parameter'. The
    screw bearing's reliability (ball_bearing default 0.9) is not in the lift's file; it can now be varied from
    that default. Expected ratio: ISO 281:2007 Table 12 a1 = 1 at 90 %, 0.25 at 99 % (the table of
    components/data/bearings_ball.toml), so the life check's u grows by 1/0.25 = 4 (hand calculation)."""
    s = Study(LIFT, vary=["components.screw_bearing.reliability=0.9:0.99:2"])
    assert s.axes[0].param.base == 0.9
    res = s.run("serial")
    u = [x["checks"]["screw_bearing.bearing_life"]["u"] for x in res.samples]
    assert u[1] / u[0] == pytest.approx(1 / 0.25, rel=1e-3)
    out = res.reproduce(1, tmp_path / "s1.toml")  # the key is written into the reproduced file
    assert "reliability = 0.99" in out.read_text()


def test_a_key_whose_default_is_not_one_number_is_a_clear_error(capsys):
    """Finding 1: the screw stage's mu (the issue's friction example) defaults to the nut material's friction
    range (both ends checked): not one base value. The message says to write the key into the file first."""
    with pytest.raises(InputError, match=r"does not write 'mu' in components\.lift\.transmission\[0\].*write the "
                                         r"key into the file"):
        Study(LIFT, vary=["components.lift.transmission[0].mu=0.1:0.3:3"])
    rc = main(["size", str(LIFT), "--vary", "components.lift.transmission[0].mu", "--until", "motor_peak_torque",
               "--bounds", "0.05:0.3"])
    assert rc == 2 and "write the key into the file" in capsys.readouterr().err


def test_a_friction_written_into_the_file_is_varied(tmp_path):
    """Finding 1, the documented way: with 'mu = 0.25' written into the screw stage, a sweep of mu runs and the
    motor's torque grows with the friction (raise torque, Hamrock Eq. 16.10: monotonic in mu)."""
    text = LIFT.read_text().replace('transmission = [{ type = "screw", screw = "lift_screw" }]',
                                    'transmission = [{ type = "screw", screw = "lift_screw", mu = 0.25 }]')
    assert "mu = 0.25 }]" in text
    design = tmp_path / "design.toml"  # (the lift has no includes or file names: it can move)
    design.write_text(text)
    res = Study(design, vary=["components.lift.transmission[0].mu=0.1:0.3:3"]).run("serial")
    fu = [x["checks"]["lift.motor_peak_torque"]["fu"] for x in res.samples]
    assert fu[0] < fu[1] < fu[2]


# ---------------------------------------------------------------- findings 16, 26: size's margin and options


def _sized(today: float, today_fu: float, limit: float):
    from mechverify.studies import SizingResult

    return SizingResult("p", "mm", "governing", today, today_fu, limit, "c", (limit,), (1.0, 10.0), 9)


def test_size_margin_is_spelt_out_by_direction_and_verdict():
    """Finding 16: 'margin -7.3% to the limit' meant 'room to thin by 7.3 %' for a plate that passes and
    'short by 58.3 %' for a lift that fails. The text now says which way and what it means (hand arithmetic:
    (3.708 - 4)/4 = -7.3 %, (145.8 - 350)/350 = -58.3 %)."""
    passes = _sized(4.0, 0.7968, 3.708).text()
    assert "the limit is 7.3 % below today's value: it may fall by 7.3 % before u·SF reaches 1" in passes
    fails = _sized(350.0, 2.38, 145.82).text()
    assert "the limit is 58.3 % below today's value: it must fall by 58.3 % for u·SF to come down to 1" in fails
    assert "rise by 25.0 %" in _sized(4.0, 0.8, 5.0).text()
    assert _sized(4.0, 0.8, 5.0).to_dict()["margin"] == pytest.approx(0.25)  # the JSON keeps the signed number


@pytest.mark.parametrize("argv, message", [
    (["--vary", "parameters.lifted_load", "--bounds", "500 N:50 N"], "--bounds: expected low < high"),
    (["--vary", "parameters.lifted_load", "--scan", "0"], "--scan: expected a positive integer"),
    (["--vary", "parameters.lifted_load", "--until", "lift_screw.nope"], "unknown check"),
])
def test_size_messages_name_the_options(argv, message, capsys):
    """Finding 26: 'bounds: give the range ...' named the Python argument; the option is --bounds."""
    assert main(["size", str(LIFT), *argv]) == 2
    assert message in capsys.readouterr().err


# ---------------------------------------------------------------- finding 6: --reproduce keeps the file's comments


def test_reproduce_rewrites_only_the_changed_values_and_keeps_the_comments(tmp_path):
    """Finding 6: --reproduce wrote the design from its data: every comment of the source (its sources and
    assumptions) was lost, and 'acceleration = "0.0618... m/s**2"' came in pint's spelling. Now only the
    varied values' lines change (their comments kept, in the file's unit spelling), and the file reads back
    as the sample's data."""
    import tomllib

    from mechverify.studies.params import apply_overrides

    s = Study(LIFT, vary=["parameters.lifted_load=normal:140 N:10 N",
                          "profiles.raise.acceleration=triangular:0.05 m/s^2:0.1 m/s^2:0.2 m/s^2"], samples=8, seed=1)
    out = s.reproduce(5, tmp_path / "s5.toml")
    src, new = LIFT.read_text().splitlines(), out.read_text().splitlines()
    head = [x for x in new if x.startswith("# Sample") or x.startswith("#   ")]
    body = new[len(head):]
    assert len(head) == 3 and len(body) == len(src)
    changed = [(a, b) for a, b in zip(src, body) if a != b]
    assert [a.split("=")[0].strip() for a, _ in changed] == ["lifted_load", "acceleration"]
    for a, b in changed:
        assert b.split("#", 1)[1] == a.split("#", 1)[1]  # the comment is kept
    assert " m/s^2\"" in changed[1][1] and "**" not in out.read_text()
    assert tomllib.loads(out.read_text()) == apply_overrides(s.doc, s.result_skeleton().overrides(5))


def test_reproduce_falls_back_to_the_whole_document_when_a_value_is_not_on_its_own_line(tmp_path):
    """A value the source does not write on its own line (a key left to its default) is written through
    the TOML writer; the result still reads back as the sample's data."""
    import tomllib

    s = Study(LIFT, vary=["components.screw_bearing.reliability=0.9:0.99:2"])
    out = s.reproduce(1, tmp_path / "s1.toml")
    data = tomllib.loads(out.read_text())
    assert data["components"]["screw_bearing"]["reliability"] == 0.99
    assert data["parameters"]["lifted_load"] == "350 N"


# ---------------------------------------------------------------- finding 31: the check table at 80 columns


def test_check_table_on_an_80_column_console_keeps_rows_short(capsys, monkeypatch):
    """Finding 31: at 80 columns the lift's table had headers 'verdi…', 'compo…' and rows wrapped over 5 lines.
    Below 120 columns the check's name replaces its title and the bar goes; below 100 also SF and case."""
    monkeypatch.setenv("COLUMNS", "80")
    assert main(["check", str(LIFT)]) == 1
    lines = capsys.readouterr().out.splitlines()
    table = [x for x in lines if x.startswith(("│", "┃"))]
    assert all(len(x) <= 80 for x in lines if x.strip()), max(len(x) for x in lines)
    header = next(x for x in table if "verdict" in x)
    assert "component" in header and "capacity" in header and "…" not in header
    rows = [x for x in table if x.startswith("│")]
    starts = [x for x in rows if x.split("│")[1].strip()]  # a verdict in the first cell: a new row
    assert len(starts) == 15 and len(rows) <= 2 * len(starts)


def test_narrow_results_tables_are_still_drawn_like_rich():
    """The narrow columns go through both renderers alike: cli/_table.py (output that is not a terminal) draws
    them character for character as rich does, or declines."""
    import io

    from rich.console import Console

    from mechverify.cli._console import results_rows, results_table
    from mechverify.cli._table import render
    from mechverify.design import load

    rs = load(LIFT).verify()
    drawn = 0
    for width in range(60, 120, 3):
        title, headers, justify, rows = results_rows(rs, None, width)
        assert "" not in headers and ("governing case" in headers) == (width >= 100)
        mine = render(title, headers, justify, [[c.replace("[red]", "").replace("[/red]", "")
                                                .replace("[green]", "").replace("[/green]", "")
                                                .replace("[yellow]", "").replace("[/yellow]", "") for c in r]
                                               for r in rows], width)
        if mine is None:
            continue
        buf = io.StringIO()
        Console(file=buf, width=width, color_system=None, highlight=False, soft_wrap=False).print(
            results_table(rs, None, width))
        assert mine == [x.rstrip("\n") for x in buf.getvalue().splitlines()], width
        drawn += 1
    assert drawn >= 1  # (a name cropped with "…" is left to rich: the renderer declines)


def test_size_margin_words_for_negative_values():
    """Review 2 finding 2 (session 3): a compressive in-plane load sized from -10 to its limit -53.46 N/mm read
    'the limit is 434.6 % above today's value: it may rise' (it must become more negative). For two negative values
    the words speak of the magnitude; a limit across zero says so."""
    from mechverify.studies.sizing import SizingResult

    def r(today: float, limit: float, fu: float = 0.5) -> SizingResult:
        return SizingResult("p", "N/mm", "governing", today, fu, limit, "x", (limit,), (-200.0, -1.0), 10)

    assert r(-10.0, -53.4638).margin_text() == ("the limit is 434.6 % above today's value in magnitude: it may grow "
                                                "by 434.6 % before u·SF reaches 1")
    assert r(-10.0, -5.0, 2.0).margin_text() == ("the limit is 50.0 % below today's value in magnitude: it must "
                                                 "shrink by 50.0 % for u·SF to come down to 1")
    assert r(10.0, 12.0).margin_text().startswith("the limit is 20.0 % above today's value: it may rise by 20.0 %")
    assert "other side of zero" in r(-10.0, 5.0).margin_text()
