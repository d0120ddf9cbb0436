"""Console output of the commands: rich consoles sized to the terminal, the results table.

Imported by a command's ``run`` only (rich is not needed for ``--help``). Width: ``COLUMNS`` when
set, else the terminal's width, else (output to a file or a CI log) 160 columns, wide enough for the
results table.

Output that is not a terminal and has no colour forced (a CI log, a pipe; :func:`plain_output`) gets the
results table and the verdict lines from :mod:`mechverify.cli._table`, which draws them character for
character as rich does without importing it: :func:`print_results` and :func:`print_line` (rich's import and
layout were ~45 ms of a cold ``mechverify check``; issue 27).
"""

from __future__ import annotations

import os
import re
import shutil
import sys
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rich.console import Console
    from rich.table import Table

COLOURS = {"pass": "green", "warn": "yellow", "fail": "red"}
_TAGS = re.compile(r"\[/?(?:green|yellow|red)\]")  # the colour tags of the verdict and bar cells


def width(stream: Any = None) -> int | None:
    """Columns for a console on ``stream``: ``COLUMNS``, the terminal's width, or 160 when not a terminal."""
    columns = os.environ.get("COLUMNS", "")
    if columns.isdigit() and int(columns) > 0:
        return int(columns)
    stream = stream or sys.stdout
    try:
        if stream.isatty():
            return shutil.get_terminal_size().columns
    except (AttributeError, ValueError, OSError):
        pass
    return 160


def console(stderr: bool = False) -> Console:
    """A console on the *current* sys.stdout/sys.stderr (so that tests capturing output see it)."""
    from rich.console import Console

    stream = sys.stderr if stderr else sys.stdout
    return Console(file=stream, highlight=False, width=width(stream), soft_wrap=False)


# Environment variables with which rich colours output that is not a terminal (rich.console.Console.__init__).
_COLOUR_ENV = ("FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE")


def plain_output(stream: Any = None) -> bool:
    """True when rich would write ``stream`` (default sys.stdout) without colour: not a terminal, no colour forced."""
    stream = stream or sys.stdout
    if any(os.environ.get(k) for k in _COLOUR_ENV):
        return False
    try:
        return not stream.isatty()
    except (AttributeError, ValueError, OSError):
        return False


def print_results(rs: Any, units: dict[Any, str] | None = None) -> None:
    """``out.print(results_table(rs, units))``, without rich when the output is plain (same characters)."""
    if plain_output():
        from mechverify.cli._table import render

        title, headers, justify, rows = results_rows(rs, units, width(sys.stdout))
        lines = render(title, headers, justify, [[_TAGS.sub("", c) for c in r] for r in rows], width(sys.stdout),
                       fixed_widths(headers, rows))
        if lines is not None:
            sys.stdout.write("\n".join(lines) + "\n")
            return
    out.print(results_table(rs, units, width(sys.stdout)))


def print_line(markup: str) -> None:
    """``out.print(markup)`` for a line in mechverify's colour tags, without rich when the output is plain."""
    if plain_output():
        from mechverify.cli._table import strip_tags

        text = strip_tags(markup)
        if text is not None and len(text) <= (width(sys.stdout) or 0):
            sys.stdout.write(text + "\n")
            return
    out.print(markup)


class _Lazy:
    """``out.print(...)``: a console on whatever sys.stdout is at the time of the call."""

    def __init__(self, stderr: bool):
        self.stderr = stderr

    def print(self, *objects: Any, **kwargs: Any) -> None:
        console(self.stderr).print(*objects, **kwargs)


out = _Lazy(False)
err = _Lazy(True)


def _bar(u: float, width: int = 10) -> str:
    filled = min(width, max(0, round(min(u, 1.0) * width)))
    return "█" * filled + "·" * (width - filled) + ("▶" if u > 1 else " ")


_COLUMNS = (("verdict", "left"), ("component", "left"), ("check", "left"), ("demand", "right"),
            ("capacity", "right"), ("u·SF", "right"), ("", "left"), ("SF req", "right"), ("governing case", "left"))


#: Below this many columns the table shows the check's name instead of its title and no u·SF bar; below
#: NARROWER also no required SF and no governing case (an 80-column terminal: one or two lines a row, not five).
NARROW, NARROWER = 120, 100


def results_rows(rs: Any, units: dict[Any, str] | None = None,
                 columns: int | None = None) -> tuple[str, list[str], list[str], list[list[str]]]:
    """Title, column headers, their justification and the rows (rich markup) of :func:`results_table`;
    ``columns``: the console's width (None: every column, the titles in full)."""
    title, headers, justify, rows = _all_rows(rs, units)
    if columns is None or columns >= NARROW:
        return title, headers, justify, rows
    checks = [r.check for r in rs.sorted()]
    rows = [[*row[:2], name, *row[3:]] for row, name in zip(rows, checks)]
    drop = {""} | ({"SF req", "governing case"} if columns < NARROWER else set())
    keep = [i for i, h in enumerate(headers) if h not in drop]
    headers, justify = [headers[i] for i in keep], [justify[i] for i in keep]
    rows = [[row[i] for i in keep] for row in rows]
    natural = [max(_cell_width(c) for c in col) for col in zip(headers, *rows)]
    if sum(natural) + 3 * len(natural) + 1 > columns:  # (padding 2 and a border per column)
        # the names are the keys users type (checks.<name>, --until <component>.<check>): rather than let the
        # console crop them, the component and the check share one column on two lines, "lift_screw." over
        # "nut_pv" (review 2 finding 8); demand and capacity wrap first
        headers = [headers[0], "component.check", *headers[3:]]
        justify = [justify[0], "left", *justify[3:]]
        rows = [[row[0], f"{row[1]}.\n{row[2]}", *row[3:]] for row in rows]
    return title, headers, justify, rows


def fixed_widths(headers: list[str], rows: list[list[str]]) -> list[int | None]:
    """Per column of :func:`results_rows`, the fixed content width (rich's ``Column(width=)``) or None: the
    merged name column keeps its width, so a narrow console narrows demand and capacity first."""
    return [max(_cell_width(c) for c in col) if col[0] == "component.check" else None for col in zip(headers, *rows)]


def _cell_width(markup: str) -> int:
    """The width of a cell's longest line, without mechverify's colour tags."""
    return max(len(line) for line in _TAGS.sub("", markup).split("\n"))


def _all_rows(rs: Any, units: dict[Any, str] | None = None) -> tuple[str, list[str], list[str], list[list[str]]]:
    from mechverify.reports.numbers import number, quantity_in

    rows = []
    for r in rs.sorted():
        c = COLOURS[r.verdict.value]
        fu = r.factored_utilisation
        if any(n.startswith("Not verifiable") for n in r.notes):  # beyond the method's validity: no numbers
            demand, capacity, shown = "-", "-", "n/a"
        else:
            demand, capacity, shown = quantity_in(r.demand, units), quantity_in(r.capacity, units), number(fu)
        rows.append([f"[{c}]{r.verdict.value.upper()}[/{c}]", r.component, r.title or r.check, demand, capacity,
                     shown, f"[{c}]{_bar(fu)}[/{c}]", f"{r.required_sf:g}", r.load_case])
    return rs.name, [c for c, _ in _COLUMNS], [j for _, j in _COLUMNS], rows


def results_table(rs: Any, units: dict[Any, str] | None = None, columns: int | None = None) -> Table:
    """The table of one :class:`~mechverify.checks.ResultSet`, worst first; ``units``: the design file's own units
    by kind (:func:`mechverify.reports.numbers.design_units`), shown beside the report's; ``columns``: the
    console's width (a narrow one gets fewer columns, :func:`results_rows`)."""
    from rich.table import Table

    title, headers, justify, rows = results_rows(rs, units, columns)
    t = Table(title=title, title_justify="left", show_lines=False)
    for col, just, fixed in zip(headers, justify, fixed_widths(headers, rows)):
        t.add_column(col, justify=just, width=fixed)
    for row in rows:
        t.add_row(*row)
    return t


def verdict_line(rs: Any) -> str:
    """``PASS name: 3 pass, 0 warn, 0 fail`` (rich markup)."""
    counts = {v: sum(r.verdict.value == v for r in rs) for v in ("pass", "warn", "fail")}
    c = COLOURS[rs.verdict.value]
    if not len(rs):
        return f"[{c}]{rs.verdict.value.upper()}[/{c}] {rs.name}: no check ran (nothing was verified)"
    return (f"[{c}]{rs.verdict.value.upper()}[/{c}] {rs.name}: {counts['pass']} pass, {counts['warn']} warn, "
            f"{counts['fail']} fail")


def combined_line(result_sets: list[Any]) -> str:
    """One verdict over several designs: ``FAIL overall: 2 designs, 30 pass, 1 warn, 3 fail``."""
    order = {"pass": 0, "warn": 1, "fail": 2}
    worst = max((rs.verdict.value for rs in result_sets), key=order.__getitem__, default="pass")
    n = {v: sum(r.verdict.value == v for rs in result_sets for r in rs) for v in order}
    c = COLOURS[worst]
    return (f"[{c}]{worst.upper()}[/{c}] overall: {len(result_sets)} design{'s' * (len(result_sets) != 1)}, "
            f"{n['pass']} pass, {n['warn']} warn, {n['fail']} fail")


def table(title: str, columns: list[str], rows: list[list[str]]) -> None:
    """Print a simple table: first column left-aligned, the others right-aligned."""
    from rich.table import Table

    t = Table(title=title, title_justify="left")
    for c in columns:
        t.add_column(c, justify="left" if c in columns[:1] else "right")
    for r in rows:
        t.add_row(*r)
    out.print(t)


def opt(q: Any, unit: str, digits: int = 4) -> str:
    """A quantity in ``unit``, or ``-`` when absent."""
    from mechverify.units import fmt

    return fmt(q, unit, digits) if q is not None else "-"
