"""A table drawn exactly as rich draws it on a console without colour, without importing rich (issue 27).

``mechverify check`` in a CI log or a pipe (not a terminal) prints its results table through :func:`render`:
rich's import and layout were ~45 ms of the ~290 ms a cold check spends above ``import numpy, pint``
(docs/performance.md). The output is character for character what ``rich.table.Table(title=...,
title_justify="left")`` prints with rich's defaults (box ``HEAVY_HEAD``, padding (0, 1), columns that wrap
words, header cells aligned to the bottom, row cells to the top) on a console ``width`` columns wide;
``tests/test_cli_table.py`` compares the two over many widths and designs. The column widths follow rich's
``Table._calculate_column_widths``/``_collapse_widths`` and ``rich._ratio.ratio_reduce``, the word wrap
``rich._wrap.divide_line`` (rich is MIT-licensed, (c) Will McGugan).

:func:`render` returns None for what it does not reproduce - a character outside rich's single-cell ranges, a
control character, rich markup or an emoji code in a cell, a word longer than its column after the columns
are narrowed, a title wider than the table - and the caller then prints through rich.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

# Characters rich measures as one cell: its _SINGLE_CELL_UNICODE_RANGES (Latin, Greek, Cyrillic, box drawing) and
# what engineering text adds - dashes and quotes, super- and subscripts (10⁻⁶), letterlike symbols, arrows, and
# mathematical operators (≤ ×); tests/test_cli_table.py checks every one against rich.cells.cell_len.
_SINGLE_CELL = frozenset(chr(c) for lo, hi in ((0x20, 0x7E), (0xA0, 0xAC), (0xAE, 0x2FF), (0x370, 0x482),
                                               (0x2010, 0x2027), (0x2030, 0x205E), (0x2070, 0x2071),
                                               (0x2074, 0x208E), (0x2090, 0x209C), (0x2100, 0x214F),
                                               (0x2190, 0x21FF), (0x2200, 0x22FF), (0x2500, 0x25FC),
                                               (0x2800, 0x28FF)) for c in range(lo, hi + 1))
_MARKUP = re.compile(r"\[|:\S*?:")  # a markup tag or an escape, or an emoji code such as :warning:
_WORD = re.compile(r"\s*\S+\s*")
_TAG = re.compile(r"\[/?(?:red|green|yellow|bold|italic|dim)\]")  # the markup mechverify's own lines use


def plain(text: str) -> bool:
    """True when rich would print ``text`` (as markup) unchanged and measure every character as one cell."""
    return _SINGLE_CELL.issuperset(text) and not _MARKUP.search(text)


def strip_tags(markup: str) -> str | None:
    """The text of a line written with mechverify's own colour tags (``[red]FAIL[/red] ...``), or None when
    anything else in it would be markup to rich."""
    text = _TAG.sub("", markup)
    return text if plain(text) else None


def _ratio_reduce(total: int, ratios: list[int], maximums: list[int], values: list[int]) -> list[int]:
    """rich._ratio.ratio_reduce."""
    ratios = [r if m else 0 for r, m in zip(ratios, maximums)]
    total_ratio = sum(ratios)
    if not total_ratio:
        return values[:]
    remaining, out = total, []
    for ratio, maximum, value in zip(ratios, maximums, values):
        if ratio and total_ratio > 0:
            distributed = min(maximum, round(ratio * remaining / total_ratio))
            out.append(value - distributed)
            remaining -= distributed
            total_ratio -= ratio
        else:
            out.append(value)
    return out


def _collapse(widths: list[int], max_width: int, wrapable: list[bool]) -> list[int]:
    """rich.table.Table._collapse_widths: narrow the widest wrapable columns first (a fixed width is not)."""
    total = sum(widths)
    excess = total - max_width
    if not any(wrapable):
        return widths
    while total and excess > 0:
        widest = max(w for w, a in zip(widths, wrapable) if a)
        second = max((w if a and w != widest else 0) for w, a in zip(widths, wrapable))
        ratios = [1 if (w == widest and a) else 0 for w, a in zip(widths, wrapable)]
        if not any(ratios) or not widest - second:
            break
        widths = _ratio_reduce(excess, ratios, [min(excess, widest - second)] * len(widths), widths)
        total = sum(widths)
        excess = total - max_width
    return widths


def _measure(texts: Sequence[str], width: int) -> int:
    """The width rich gives a column of ``texts`` (padding included) on ``width`` cells: Table._measure_column."""
    if width < 1:
        return 0
    maxima = []
    for t in texts:
        if width - 2 < 1:  # Padding.__rich_measure__
            maxima.append(width)
            continue
        inner = min(max(len(line) for line in t.split("\n")), width - 2)  # Text: (longest word, longest line)
        maxima.append(0 + 2 if inner < 1 else inner + 2)
    return min(max(maxima) if maxima else width, width)


def _wrap(text: str, width: int) -> list[str] | None:
    """rich's word wrap of a cell (``divide_line`` without folding, each of its lines), or None when a word does
    not fit."""
    if "\n" in text:
        out: list[str] = []
        for line in text.split("\n"):
            part = _wrap(line, width)
            if part is None:
                return None
            out += part or [""]
        return out
    breaks, offset = [], 0
    for m in _WORD.finditer(text):
        start, word = m.start(), m.group(0)
        n = len(word.rstrip())
        if width - offset >= n:
            offset += len(word)
        elif n > width:
            return None  # rich would crop the word with an ellipsis
        elif offset and start:
            breaks.append(start)
            offset = len(word)
    cuts = [0, *breaks, len(text)]
    return [text[a:b] for a, b in zip(cuts, cuts[1:])]


def render(title: str, headers: Sequence[str], justify: Sequence[str], rows: Sequence[Sequence[str]],
           width: int, fixed: Sequence[int | None] | None = None) -> list[str] | None:
    """The lines rich prints for this table on a console ``width`` columns wide, or None (see the module);
    ``fixed``: per column a fixed content width (rich's ``Column(width=)``: not narrowed before the others) or
    None."""
    cells = [list(headers), *(list(r) for r in rows)]  # a cell may hold lines ("\n"), the title not
    if not all(plain(c.replace("\n", "")) for row in cells for c in row) or not plain(title) or width < 1:
        return None
    columns = list(zip(*cells))
    extra = len(headers) + 1  # the vertical borders
    max_width = width - extra
    fix = list(fixed) if fixed is not None else [None] * len(columns)
    widths = [min(f + 2, max_width) if f is not None else _measure(col, max_width) or 1 for col, f in zip(columns, fix)]
    if sum(widths) > max_width:
        widths = _collapse(widths, max_width, [f is None for f in fix])
        if sum(widths) > max_width:
            widths = _ratio_reduce(sum(widths) - max_width, [1] * len(widths), widths, widths)
        widths = [min(f + 2, w) if f is not None else _measure(col, w) for col, w, f in zip(columns, widths, fix)]
    if min(widths) < 3:
        return None
    table_width = sum(widths) + extra
    wrapped: list[list[list[str]]] = []
    for row in cells:
        out_row = []
        for text, w, just in zip(row, widths, justify):
            lines = _wrap(text, w - 2)
            if lines is None:
                return None
            fit = [(ln.rstrip().rjust(w - 2) if just == "right" else ln.rstrip().ljust(w - 2)) for ln in lines]
            out_row.append(fit)
        wrapped.append(out_row)
    lines = []
    if title:
        if len(title) > table_width:
            return None
        lines.append(title.ljust(table_width))
    lines.append("┏" + "┳".join("━" * w for w in widths) + "┓")
    for i, row in enumerate(wrapped):
        height = max(len(c) for c in row)
        for k in range(height):
            parts = []
            for c, w in zip(row, widths):
                pad = height - len(c)
                j = k - pad if i == 0 else k  # the header row is aligned to the bottom, the others to the top
                parts.append(" " + c[j] + " " if 0 <= j < len(c) else " " * w)
            edge = "┃" if i == 0 else "│"
            lines.append(edge + edge.join(parts) + edge)
        if i == 0:
            lines.append("┡" + "╇".join("━" * w for w in widths) + "┩")
    lines.append("└" + "┴".join("─" * w for w in widths) + "┘")
    return lines
