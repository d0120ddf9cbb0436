"""Nothing of the user's is overwritten: output paths are refused before any check runs (exit 2 with a
named error), writes are atomic, and no temporary file survives an error, SIGINT or SIGTERM.

The design is the rod of ``conftest.py`` (sigma = F/A, Shigley 10th ed. Eq. 3-22): 2 kN on 20 mm^2.
"""

from __future__ import annotations

import hashlib
import os
import signal
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from mechverify.cli import main
from mechverify.design.design import Design
from mechverify.fileio import OutputPathError, atomic_write, check_output_paths

DESIGN = """
[design]
name = "rig"
include = ["parts.toml"]

[components.rod]
type = "test_rod"
length = "350 mm"
area = "20 mm^2"
material = "Structural Steel"

[load_cases.hold.rod]
force = "2 kN"
"""
PARTS = """
[materials.steel2]
base = "Structural Steel"
"""


@pytest.fixture(autouse=True)
def _rod(rod_type):
    yield


@pytest.fixture()
def design(tmp_path: Path) -> Path:
    (tmp_path / "parts.toml").write_text(textwrap.dedent(PARTS))
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(DESIGN))
    return p


@pytest.fixture()
def no_verify(monkeypatch):
    """Fail the test if any check runs: outputs must be refused before."""
    def boom(self, *a, **k):
        raise AssertionError("a check ran before the output paths were validated")
    monkeypatch.setattr(Design, "verify", boom)


def digest(folder: Path) -> dict[str, str]:
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file() and not p.is_symlink()}


def refused(capsys, argv: list[str], *words: str) -> str:
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and "internal error" not in err
    for w in words:
        assert w in err, err
    return err


def test_output_equal_to_the_design_or_an_include_is_refused(design, capsys, no_verify):
    before = digest(design.parent)
    refused(capsys, ["check", str(design), "--json", str(design)], "--json", "is an input")
    refused(capsys, ["check", str(design), "--junit", str(design.parent / "parts.toml")], "--junit", "is an input")
    refused(capsys, ["check", str(design), "--junit", f"{design.parent}/x/../design.toml"], "is an input")
    os.link(design, design.parent / "hard.json")  # a hard link is the same file under another name
    refused(capsys, ["check", str(design), "--json", str(design.parent / "hard.json")], "is an input")
    after = digest(design.parent)
    assert after.pop("hard.json") == before["design.toml"] and after == before


def test_two_outputs_naming_one_file_are_refused(design, capsys, no_verify):
    out = design.parent / "r.json"
    refused(capsys, ["check", str(design), "--json", str(out), "--junit", str(out)], "same file")
    assert not out.exists()


def test_links_fifos_devices_folders_are_refused(design, tmp_path, capsys, no_verify):
    target = tmp_path / "target.txt"
    target.write_text("keep me")
    (tmp_path / "link.json").symlink_to(target)
    refused(capsys, ["check", str(design), "--json", str(tmp_path / "link.json")], "symbolic link")
    assert (tmp_path / "link.json").is_symlink() and target.read_text() == "keep me"
    os.mkfifo(tmp_path / "fifo.json")
    refused(capsys, ["check", str(design), "--json", str(tmp_path / "fifo.json")], "FIFO")
    try:  # a device node of our own: a regression in the guard replaces it, never the system's /dev/null
        os.mknod(tmp_path / "null", stat.S_IFCHR | 0o666, os.makedev(1, 3))
    except (PermissionError, OSError):
        pass
    else:
        refused(capsys, ["check", str(design), "--junit", str(tmp_path / "null")], "device")
        assert (tmp_path / "null").is_char_device()
    refused(capsys, ["check", str(design), "--json", str(tmp_path)], "folder")


def test_missing_or_unwritable_folder_is_refused_before_any_check(design, tmp_path, capsys, no_verify):
    refused(capsys, ["check", str(design), "--report", str(tmp_path / "nope" / "r.html")], "does not exist")
    refused(capsys, ["check", str(design), "--report", "/proc/nope/r.html"], "does not exist")
    refused(capsys, ["check", str(design), "--json", "/proc/r.json"], "cannot write")
    assert not (tmp_path / "nope").exists()


def test_diff_and_schema_and_init_outputs_are_checked(design, tmp_path, capsys):
    refused(capsys, ["diff", str(design), str(design), "--json", str(design)], "is an input")
    (tmp_path / "s.json").symlink_to(tmp_path / "elsewhere.json")
    refused(capsys, ["schema", "-o", str(tmp_path / "s.json")], "symbolic link")
    assert not (tmp_path / "elsewhere.json").exists()
    refused(capsys, ["init", str(tmp_path / "s.json")], "exists")
    refused(capsys, ["init", str(tmp_path / "s.json"), "--force"], "symbolic link")
    refused(capsys, ["init", str(tmp_path), "--force"], "folder")


def test_valid_outputs_are_written(design, tmp_path, capsys):
    before = digest(tmp_path)
    assert main(["check", str(design), "-q", "--json", str(tmp_path / "r.json"), "--junit",
                 str(tmp_path / "r.xml")]) == 0
    after = digest(tmp_path)
    assert {k: v for k, v in after.items() if k in before} == before  # inputs untouched
    assert set(after) - set(before) == {"r.json", "r.xml"}  # and no temporary file left


def test_check_output_paths_api():
    with pytest.raises(OutputPathError, match="--json: the folder"):
        check_output_paths({"--json": "/nonexistent-folder/x.json"})
    check_output_paths({"--json": None})  # absent options are skipped


def test_atomic_write_refuses_links_and_keeps_the_target(tmp_path):
    target = tmp_path / "t.txt"
    target.write_text("old")
    (tmp_path / "l.txt").symlink_to(target)
    with pytest.raises(OutputPathError):
        atomic_write(tmp_path / "l.txt", "new")
    assert target.read_text() == "old"

    def fails(tmp: Path) -> None:
        tmp.write_text("half")
        raise RuntimeError("renderer crashed")

    with pytest.raises(RuntimeError):
        atomic_write(target, fails)
    assert target.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == ["l.txt", "t.txt"]


def test_stale_temp_files_of_dead_processes_are_removed(tmp_path):
    """A process killed with SIGKILL cannot clean up; the next write of the same target does, but only
    for processes that no longer run."""
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = tmp_path / f".r.json.{dead.pid}.abcd.tmp"
    live = tmp_path / f".r.json.{os.getppid()}.efgh.tmp"  # the pytest runner's parent: alive
    stale.write_text("x")
    live.write_text("y")
    atomic_write(tmp_path / "r.json", "{}")
    assert not stale.exists() and live.exists()


WRITER = """
import os, signal, sys, time
from pathlib import Path
from mechverify.fileio import atomic_write

def slow(tmp):
    tmp.write_text("half")
    Path(sys.argv[2]).write_text("started")
    time.sleep(30)

atomic_write(sys.argv[1], slow)
"""


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_signal_during_a_write_leaves_no_temp_file(tmp_path, sig):
    target = tmp_path / "out" / "r.html"
    target.parent.mkdir()
    target.write_text("previous report")
    flag = tmp_path / "started"
    p = subprocess.Popen([sys.executable, "-c", WRITER, str(target), str(flag)], stderr=subprocess.PIPE)
    for _ in range(300):
        if flag.exists():
            break
        p.poll()
        assert p.returncode is None, p.stderr.read()
        import time

        time.sleep(0.05)
    assert flag.exists()
    p.send_signal(sig)
    p.wait(timeout=20)
    assert p.returncode != 0
    assert sorted(x.name for x in target.parent.iterdir()) == ["r.html"]
    assert target.read_text() == "previous report"


CLI_RUN = """
import sys, time
from pathlib import Path
import mechverify.fileio as fio
real = fio.atomic_write
def slow_write(path, content):
    def writer(tmp):
        tmp.write_text("half")
        Path(sys.argv[1]).write_text("started")
        time.sleep(30)
    return real(path, writer)
import mechverify.cli._common as common
common.write = lambda path, text: slow_write(path, text)
import mechverify.cli.schema as sch
sch.write = common.write
from mechverify.cli import main
sys.exit(main(["schema", "-o", sys.argv[2]]))
"""


def test_sigterm_to_the_cli_during_a_write(tmp_path):
    """The command installs its own SIGTERM handler (a clean exit, status 143): the temporary file goes."""
    flag, out = tmp_path / "started", tmp_path / "schema.json"
    p = subprocess.Popen([sys.executable, "-c", CLI_RUN, str(flag), str(out)], stderr=subprocess.PIPE)
    import time

    for _ in range(300):
        if flag.exists() or p.poll() is not None:
            break
        time.sleep(0.05)
    assert flag.exists(), p.stderr.read() if p.poll() is not None else "not started"
    p.send_signal(signal.SIGTERM)
    p.wait(timeout=20)
    assert p.returncode == 128 + signal.SIGTERM
    assert sorted(x.name for x in tmp_path.iterdir()) == ["started"]
