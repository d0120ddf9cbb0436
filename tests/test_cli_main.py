"""The command line itself: argparse help (full option names, the terminal's width), a light start,
warnings on one line (``-q`` keeps only mechverify's own), catalogue listings, and ``diff --base-ref``
run in a real temporary git repository.

The design is the rod of ``conftest.py`` (sigma = F/A, Shigley 10th ed. Eq. 3-22): 2 kN on 20 mm^2 is
100 MPa, u·SF = 100·2/250 = 0.8 (pass); on 10 mm^2, 200 MPa, u·SF = 1.6 (fail).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import pytest
from conftest import ROD_DESIGN

from mechverify.cli import main

ROOT = Path(__file__).resolve().parents[1]
DESIGN = ROD_DESIGN


@pytest.fixture(autouse=True)
def _rod(rod_type):
    yield


def cli(*args: str, columns: int | None = None) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    if columns:
        env["COLUMNS"] = str(columns)
    return subprocess.run([sys.executable, "-m", "mechverify.cli", *args], capture_output=True, text=True, env=env,
                          cwd=ROOT, timeout=120)


def test_help_lists_every_command_and_full_option_names():
    r = cli("--help", columns=80)
    assert r.returncode == 0
    for cmd in ("check", "diff", "materials", "threads", "bearings", "motors", "explain", "init", "schema"):
        assert f"\n    {cmd} " in r.stdout, cmd
    r = cli("check", "--help", columns=60)
    assert r.returncode == 0
    for opt in ("--json", "--junit", "--report", "--fail-on", "--quiet", "--allow-outside-includes",
                "--no-allow-outside-includes"):
        assert opt in r.stdout, opt
    body = r.stdout.split("\n\n", 1)[1]  # after the usage (an option name is never split there)
    assert max(len(line) for line in body.splitlines()) <= 60  # wrapped to COLUMNS, names whole
    wide = cli("check", "--help", columns=200).stdout
    assert max(len(line) for line in wide.splitlines()) > 80  # and wider when the terminal is


def test_help_starts_without_numpy_pint_rich_or_typer():
    """`mechverify --help` needs no scientific stack (issue 27: <= 0.6 x `import numpy, pint`)."""
    code = ("import sys\nfrom mechverify.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            "print(sorted(m for m in ('numpy', 'pint', 'rich', 'typer', 'scipy', 'matplotlib') if m in sys.modules))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.stdout.strip().splitlines()[-1] == "[]", r.stdout + r.stderr


def test_usage_errors_and_version(capsys):
    assert main([]) == 2
    assert main(["--version"]) == 0
    assert "mechverify" in capsys.readouterr().out
    assert main(["check", "--nonsense", "x.toml"]) == 2
    assert "unrecognized arguments" in capsys.readouterr().err


def test_table_width_follows_columns(tmp_path, monkeypatch, capsys):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(area=20, rev="A")))
    monkeypatch.setenv("COLUMNS", "70")
    assert main(["check", str(p)]) == 0
    assert max(len(line) for line in capsys.readouterr().out.splitlines()) <= 70
    monkeypatch.setenv("COLUMNS", "200")
    assert main(["check", str(p)]) == 0
    assert "governing case" in capsys.readouterr().out  # room for every column


def test_warnings_one_line_and_quiet_keeps_only_our_own(tmp_path, monkeypatch, capsys):
    """A library's warning during a run (matplotlib's "Glyph missing" in a report) is printed as one line,
    and not at all with -q; mechverify's own warnings (implausible values) always are."""
    from mechverify.design.design import Design

    real = Design.verify

    def noisy(self, *a, **k):
        warnings.warn_explicit("Glyph 8722 missing from font(s) DejaVu Serif.", UserWarning, "text.py", 1,
                               module="matplotlib.text")
        return real(self, *a, **k)

    monkeypatch.setattr(Design, "verify", noisy)
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(area=20, rev="A")).replace('"350 mm"', '"350 km"'))
    assert main(["check", str(p)]) == 0
    err = capsys.readouterr().err
    assert "warning: Glyph 8722 missing" in err and "warning: components.rod.length: 350 km is implausible" in err
    assert "text.py" not in err  # one line, no source location
    assert main(["check", str(p), "-q"]) == 0
    err = capsys.readouterr().err
    assert "Glyph" not in err and "350 km is implausible" in err


def test_bearings_listed_once(capsys):
    """61800..61805 are also known as 6800..6805 (aliases): each bearing appears in one row."""
    assert main(["bearings"]) == 0
    out = capsys.readouterr().out
    for d in ("61800", "61801", "61802", "61803", "61804", "61805", "608"):
        assert sum(line.split("│")[1].strip() == d for line in out.splitlines() if line.count("│") > 2) == 1, d


def test_explain_and_catalogues(capsys):
    assert main(["explain", "no_such_check"]) == 2
    assert "unknown check" in capsys.readouterr().err
    assert main(["threads"]) == 0 and main(["materials", "PLA"]) == 0 and main(["motors", "nope"]) == 2


# --- diff --base-ref in a temporary git repository ---------------------------------------------------

def git(repo: Path, *args: str) -> str:
    return subprocess.run(["git", "-C", str(repo), "-c", "user.name=t", "-c", "user.email=t@t",
                           "-c", "commit.gpgsign=false", *args], check=True, capture_output=True, text=True).stdout


@pytest.fixture()
def repo(tmp_path):
    r = tmp_path / "repo"
    (r / "designs").mkdir(parents=True)
    git(r, "init", "-q")
    (r / "designs" / "rig.toml").write_text(textwrap.dedent(DESIGN.format(area=20, rev="A")))
    git(r, "add", "-A")
    git(r, "commit", "-q", "-m", "A")
    git(r, "tag", "base")
    return r


def test_diff_base_ref_loses_a_margin(repo, capsys):
    design = repo / "designs" / "rig.toml"
    design.write_text(textwrap.dedent(DESIGN.format(area=10, rev="B")))  # 200 MPa: u·SF 1.6
    out = repo / "d.json"
    assert main(["diff", str(design), "--base-ref", "base", "--json", str(out)]) == 1
    assert "margin lost" in capsys.readouterr().out
    doc = json.loads(out.read_text())
    assert doc["lost_requirement"] and doc["changes"][0]["base"]["utilisation"] == pytest.approx(100 / 250)
    assert doc["changes"][0]["head"]["utilisation"] == pytest.approx(200 / 250)


def test_diff_base_ref_gains_a_margin(repo, capsys):
    design = repo / "designs" / "rig.toml"
    git(repo, "checkout", "-q", "-b", "weak")
    design.write_text(textwrap.dedent(DESIGN.format(area=10, rev="B")))
    git(repo, "commit", "-q", "-am", "B")
    design.write_text(textwrap.dedent(DESIGN.format(area=25, rev="C")))  # 80 MPa: better than the base
    assert main(["diff", str(design), "--base-ref", "weak"]) == 0
    assert "1 of 1 checks changed" in capsys.readouterr().out


def test_diff_bad_ref_names_the_ref_and_the_file(repo, capsys):
    design = repo / "designs" / "rig.toml"
    assert main(["diff", str(design), "--base-ref", "no-such-branch"]) == 2
    err = capsys.readouterr().err
    assert "no-such-branch" in err and "designs/rig.toml" in err and "Traceback" not in err
    new = repo / "designs" / "new.toml"  # a file that did not exist at the ref
    new.write_text(design.read_text())
    assert main(["diff", str(new), "--base-ref", "base"]) == 2
    err = capsys.readouterr().err
    assert "designs/new.toml does not exist at git ref 'base'" in err


def test_diff_outside_a_repository(tmp_path, capsys):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(area=20, rev="A")))
    env_ceiling = os.environ.get("GIT_CEILING_DIRECTORIES")
    os.environ["GIT_CEILING_DIRECTORIES"] = str(tmp_path)
    try:
        assert main(["diff", str(p), "--base-ref", "HEAD"]) == 2
    finally:
        if env_ceiling is None:
            os.environ.pop("GIT_CEILING_DIRECTORIES")
        else:
            os.environ["GIT_CEILING_DIRECTORIES"] = env_ceiling
    err = capsys.readouterr().err
    assert f"--base-ref: {p.resolve()} is not inside a git repository" in err
    assert "rev-parse" not in err and "Command" not in err and "Traceback" not in err  # no raw git command


def test_diff_base_ref_without_git(tmp_path, capsys, monkeypatch):
    """No git on the PATH: a named error that says what --base-ref needs, not a FileNotFoundError."""
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(area=20, rev="A")))
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    assert main(["diff", str(p), "--base-ref", "HEAD"]) == 2
    err = capsys.readouterr().err
    assert "no git command was found" in err and "Traceback" not in err


def test_demo_prints_every_design_of_its_report_and_one_verdict(tmp_path, capsys):
    """`make demo`: the report holds design.toml and design_plates.toml; the console shows both tables and
    one combined verdict (the design as specified fails: the finding, exit 0 once the report is written)."""
    from mechverify.demo import main as demo

    assert demo(["--no-pdf", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "design.toml" in out and "design_plates.toml" in out
    assert out.count(" overall: 2 designs,") == 1 and "FAIL overall" in out
    assert (tmp_path / "report.html").is_file()


def test_demo_details_the_problems_by_default_and_everything_on_request(tmp_path, capsys):
    """`make demo` writes what `mechverify check --report` writes (the failing and warning checks in detail,
    issue 25's default), `--detail all` every check: the committed example report is the latter."""
    from mechverify.demo import main as demo

    counts = {}
    for detail in ("problems", "all"):
        out = tmp_path / detail
        assert demo(["--no-pdf", "--out", str(out), "--detail", detail]) == 0
        counts[detail] = (out / "report.html").read_text(encoding="utf-8").count('class="formula"')
    capsys.readouterr()
    assert 0 < counts["problems"] < counts["all"]
