"""Markdown for pull requests and CI logs: GitHub-flavoured tables of the checks that need attention.

``check_markdown(runs)``: per design a one-line verdict and a table of the failing and warning checks
(all passing checks are only counted), for ``mechverify check --markdown FILE`` and
``--github-step-summary``. ``diff_markdown(...)``: the checks whose verdict or margin changed between two
revisions, for ``mechverify diff --markdown FILE``. Numbers come from :mod:`mechverify.reports.numbers`,
the same formatter as the HTML/PDF report and the console table.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from mechverify.checks import CheckResult, ResultSet
from mechverify.errors import InputError
from mechverify.reports.numbers import number, quantity

ICON = {"pass": "✅ PASS", "warn": "⚠️ WARN", "fail": "❌ FAIL"}
MAX_ROWS = 100  # rows per table; the rest are counted in a closing line (a PR comment stays readable)
CELL_LIMIT = 200  # characters per cell


def cell(text: Any) -> str:
    """Text safe inside a GitHub table cell: pipes escaped, line breaks as spaces, long text cut."""
    s = " ".join(str(text).split()).replace("\\", "\\\\").replace("|", "\\|")
    return s if len(s) <= CELL_LIMIT else s[:CELL_LIMIT - 1] + "…"


def table(header: list[str], rows: list[list[Any]], align: list[str] | None = None) -> str:
    """A GitHub-flavoured Markdown table (``align``: ``l`` or ``r`` per column)."""
    align = align or ["l"] * len(header)
    sep = ["---:" if a == "r" else "---" for a in align]
    lines = ["| " + " | ".join(cell(h) for h in header) + " |", "| " + " | ".join(sep) + " |"]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def _na(r: CheckResult) -> str:
    return next((n for n in r.notes if n.startswith("Not verifiable")), "")


def _row(r: CheckResult) -> list[str]:
    na = _na(r)
    if na:
        return [ICON[r.verdict.value], r.component, r.title or r.check, "n/a", "n/a", "n/a", f"{r.required_sf:g}",
                na]
    return [ICON[r.verdict.value], r.component, r.title or r.check, quantity(r.demand), quantity(r.capacity),
            number(r.factored_utilisation), f"{r.required_sf:g}", r.load_case]


def verdict_line(rs: ResultSet) -> str:
    counts = {v: sum(r.verdict.value == v for r in rs) for v in ("pass", "warn", "fail")}
    return (f"**{ICON[rs.verdict.value]}** {cell(rs.name)}: {counts['pass']} pass, {counts['warn']} warn, "
            f"{counts['fail']} fail")


def check_markdown(runs: list[tuple[Any, ResultSet]], *, rows: str = "problems") -> str:
    """Markdown of one or more verified designs: verdict line, then the failing and warning checks
    (``rows="all"``: every check), worst first."""
    if rows not in ("problems", "all"):
        raise InputError(f"markdown rows: expected 'problems' or 'all', got {rows!r}")
    out = ["## mechverify design check", ""]
    for _, rs in runs:
        out.append(verdict_line(rs))
        out.append("")
        shown = [r for r in rs.sorted() if rows == "all" or r.verdict.value != "pass"]
        if not shown:
            out += [f"All {len(rs)} checks pass.", ""]
            continue
        body = [_row(r) for r in shown[:MAX_ROWS]]
        out.append(table(["Verdict", "Component", "Check", "Demand", "Capacity", "u·SF", "SF req.", "Governing case"],
                         body, ["l", "l", "l", "r", "r", "r", "r", "l"]))
        if len(shown) > MAX_ROWS:
            out.append(f"\n… and {len(shown) - MAX_ROWS} more (see the full report).")
        out.append("")
    if len(runs) > 1:
        worst = max((rs.verdict for _, rs in runs), key=lambda v: v.rank)
        out.append(f"**Overall: {ICON[worst.value]}** ({len(runs)} designs)")
        out.append("")
    return "\n".join(out)


def diff_markdown(changes: list[Any], base: str, head: str) -> str:
    """Markdown of :func:`mechverify.design.outputs.diff`: the checks that changed, biggest margin loss first."""
    changed = [c for c in changes if c.status != "same"]
    lost = any(c.lost_requirement for c in changed)
    lines = ["## mechverify diff", "",
             f"`{cell(base)}` → `{cell(head)}`: {len(changed)} of {len(changes)} checks changed"
             + ("; **❌ a requirement is no longer met**" if lost else ""), ""]
    if not changed:
        return "\n".join(lines)
    rows = []
    for c in changed[:MAX_ROWS]:
        fb = number(c.base.factored_utilisation) if c.base else "–"
        fh = number(c.head.factored_utilisation) if c.head else "–"
        d = f"{c.delta:+.3g}" if c.base and c.head else ""
        vb = c.base.verdict.value if c.base else "–"
        vh = ICON[c.head.verdict.value] if c.head else "–"
        rows.append([c.component, c.check, c.status, fb, fh, d, f"{vb} → {vh}"
                     + (" (margin lost)" if c.lost_requirement else "")])
    lines.append(table(["Component", "Check", "Status", "base u·SF", "head u·SF", "Δ", "Verdict"], rows,
                       ["l", "l", "l", "r", "r", "r", "l"]))
    if len(changed) > MAX_ROWS:
        lines.append(f"\n… and {len(changed) - MAX_ROWS} more.")
    lines.append("")
    return "\n".join(lines)


def step_summary_path() -> Path:
    """``$GITHUB_STEP_SUMMARY`` (set by GitHub Actions), or a named error."""
    p = os.environ.get("GITHUB_STEP_SUMMARY", "")
    if not p:
        raise InputError("--github-step-summary: the environment variable GITHUB_STEP_SUMMARY is not set "
                         "(GitHub Actions sets it in every step); use --markdown FILE outside GitHub Actions")
    return Path(p)


def append_step_summary(text: str) -> Path:
    """Append ``text`` to the GitHub step summary file (GitHub collects what every step appends)."""
    path = step_summary_path()
    with open(path, "a", encoding="utf-8") as f:
        f.write(text if text.endswith("\n") else text + "\n")
    return path


__all__ = ["check_markdown", "diff_markdown", "table", "cell", "append_step_summary", "step_summary_path"]
