"""Design-review reports: one self-contained HTML file, and a PDF made from it by WeasyPrint.

``write_report(runs, "review.html")`` or ``"review.pdf"``, where ``runs`` is a list of
``(Design, ResultSet)`` pairs (what ``mechverify check`` verified). Writing is atomic: the file
appears complete or not at all.

The names are imported on first use (PEP 562): the console and Markdown outputs use
:mod:`mechverify.reports.numbers` alone, without the HTML renderer's Jinja2 and Markdown imports.
"""

from __future__ import annotations

from typing import Any

__all__ = ["render_html", "write_report"]


def __getattr__(name: str) -> Any:
    if name in __all__:
        from mechverify.reports import render

        return getattr(render, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
