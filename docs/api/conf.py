"""Sphinx configuration of the mechverify API reference (``make docs``; warnings are errors).

Every public module of components, checks, fea, design, materials, fatigue, mechanisms, motion and studies
is listed in the ``*.rst`` files of this folder (tests/test_api_docs.py fails on a module left out).
"""

from __future__ import annotations

import re
from typing import Any

project = "mechverify"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon"]
# ignore-module-all: a module documents what it defines, not what it re-exports (components.springs), so
# every object is described once
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False,
                           "ignore-module-all": True}
autodoc_typehints = "description"
autodoc_member_order = "bysource"
autodoc_inherit_docstrings = False  # our docstrings only (not the standard library's, e.g. Executor.submit)
napoleon_google_docstring = True
napoleon_numpy_docstring = True
nitpicky = False
suppress_warnings = ["ref.python"]  # an unresolved cross-reference is not a build error
html_theme = "alabaster"
exclude_patterns = ["_build"]

# The docstrings are plain text first: |x| is an absolute value, never an RST substitution (the package
# defines none), and "[1] ..." lines are the entries of a reference list. Escape the bars outside ``literals``
# and table rows, and separate the references, before docutils reads them.
_LITERAL = re.compile(r"(``.+?``)")


_GRID_ROW = re.compile(r"^\s*(\+[-=+]+\+|\|.*\|)\s*$")  # a grid table's border or row


def _escape_bars(line: str) -> str:
    if "|" not in line or _GRID_ROW.match(line):
        return line
    return "".join(part if part.startswith("``") else part.replace("|", r"\|") for part in _LITERAL.split(line))


_REFERENCE = re.compile(r"^\s*\[\d+\] ")  # "[1] Author, Title, ..." entries of a reference list


def _plain_bars(app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    out: list[str] = []
    for line in lines:
        if _REFERENCE.match(line) and out and out[-1].strip():
            out.append("")  # each reference its own paragraph (its wrapped lines indented under it)
        out.append(_escape_bars(line))
    lines[:] = out


def setup(app: Any) -> dict[str, Any]:
    app.connect("autodoc-process-docstring", _plain_bars, priority=1000)  # after napoleon (priority 500)
    return {"parallel_read_safe": True}
