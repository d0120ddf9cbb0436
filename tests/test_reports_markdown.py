"""Markdown output for pull requests (issue 25): ``check --markdown``, ``--github-step-summary`` and
``diff --markdown`` write GitHub-flavoured tables, verified by parsing them with markdown-it-py's GFM
table rule (the CommonMark parser GitHub's renderer follows) and comparing cell by cell.

The design is the rod of ``conftest.py`` (sigma = F/A, Shigley 10th ed. Eq. 3-22): 2 kN on 20 mm^2
(100 MPa, passes) and on 5 mm^2 (400 MPa, fails against the 250 MPa yield of Structural Steel with the
required safety factor 2 of the test rod).
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from markdown_it import MarkdownIt

from mechverify.cli import main
from mechverify.reports.markdown import table
from tests.builders import two_rods

DESIGN = two_rods("rig", "A", "{thin}")  # (a template: DESIGN.format(thin=...))


@pytest.fixture(autouse=True)
def _rod(rod_type):
    yield


def write_design(folder: Path, name: str = "design.toml", thin: str = "5 mm^2") -> Path:
    p = folder / name
    p.write_text(textwrap.dedent(DESIGN).replace("{thin}", thin))
    return p


def tables(md: str) -> list[list[list[str]]]:
    """Every GFM table of ``md`` as rows of cell texts (header row first)."""
    tokens = MarkdownIt("commonmark").enable("table").parse(md)
    out, rows, row = [], None, None
    for t in tokens:
        if t.type == "table_open":
            rows = []
        elif t.type == "tr_open":
            row = []
        elif t.type == "inline" and row is not None:
            row.append(t.content)
        elif t.type == "tr_close":
            rows.append(row)
            row = None
        elif t.type == "table_close":
            out.append(rows)
    return out


def test_check_markdown_lists_the_failing_check(tmp_path, capsys):
    d = write_design(tmp_path)
    md_path = tmp_path / "summary.md"
    assert main(["check", str(d), "--markdown", str(md_path), "-q"]) == 1
    md = md_path.read_text()
    assert "FAIL" in md.splitlines()[2]  # the one-line verdict after the heading
    (t,) = tables(md)
    assert t[0] == ["Verdict", "Component", "Check", "Demand", "Capacity", "u·SF", "SF req.", "Governing case"]
    assert len(t) == 2  # the passing rod is counted, not listed
    row = t[1]
    assert row[1] == "thin_rod" and "FAIL" in row[0]
    assert row[3] == "400 MPa"  # 2 kN / 5 mm² (hand calculation)
    assert all(len(r) == len(t[0]) for r in t)


def test_all_pass_is_one_line(tmp_path, capsys):
    d = write_design(tmp_path, thin="20 mm^2")
    md_path = tmp_path / "summary.md"
    assert main(["check", str(d), "--markdown", str(md_path), "-q"]) == 0
    md = md_path.read_text()
    assert tables(md) == [] and "All 2 checks pass." in md


def test_github_step_summary_appends(tmp_path, capsys, monkeypatch):
    d = write_design(tmp_path)
    summary = tmp_path / "step_summary.md"
    summary.write_text("earlier step\n")
    monkeypatch.setenv("GITHUB_STEP_SUMMARY", str(summary))
    assert main(["check", str(d), "--github-step-summary", "-q"]) == 1
    text = summary.read_text()
    assert text.startswith("earlier step\n") and len(tables(text)) == 1


def test_github_step_summary_without_the_variable_is_a_named_error(tmp_path, capsys, monkeypatch):
    d = write_design(tmp_path)
    monkeypatch.delenv("GITHUB_STEP_SUMMARY", raising=False)
    assert main(["check", str(d), "--github-step-summary", "-q"]) == 2
    assert "GITHUB_STEP_SUMMARY" in capsys.readouterr().err


def test_markdown_output_over_the_design_is_refused(tmp_path, capsys):
    d = write_design(tmp_path)
    before = d.read_text()
    assert main(["check", str(d), "--markdown", str(d)]) == 2
    assert d.read_text() == before


def test_diff_markdown_shows_the_margin_change(tmp_path, capsys):
    base = write_design(tmp_path, "a.toml", thin="20 mm^2")  # 100 MPa / 250 MPa x SF 2: u·SF = 0.8
    head = write_design(tmp_path, "b.toml", thin="10 mm^2")  # 200 MPa: u·SF = 1.6
    md_path = tmp_path / "diff.md"
    assert main(["diff", str(base), str(head), "--markdown", str(md_path)]) == 1
    md = md_path.read_text()
    assert "requirement is no longer met" in md
    (t,) = tables(md)
    assert len(t) == 2 and t[1][0] == "thin_rod" and t[1][2] == "changed"
    assert t[1][3] == "0.800" and t[1][4] == "1.60" and t[1][5] == "+0.8"


def test_cells_with_pipes_and_newlines_stay_one_cell():
    md = table(["a", "b"], [["x | y", "line\nbreak"]])
    (t,) = tables(md)
    assert t[1] == ["x | y", "line break"]
