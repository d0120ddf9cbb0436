"""Every check in every bundled example design says where its formula comes from and typesets.

The house rule is that every formula cites its source; this test holds the whole chain to it on
the real designs of the five reference projects: each result has a title, a LaTeX formula that
matplotlib's mathtext can render (so the HTML and PDF reports show mathematics, not code) and a
non-empty source.
"""

from pathlib import Path

import pytest

from mechverify.design import load
from mechverify.reports.mathtext import formula_svg

DESIGNS = sorted((Path(__file__).parents[1] / "examples").glob("*/design*.toml"))


@pytest.mark.parametrize("path", DESIGNS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_check_has_source_and_typeset_formula(path):
    results = load(path).verify()
    assert len(results) > 0
    for r in results:
        where = f"{r.component}/{r.check}"
        assert r.title, where
        assert r.source.strip(), f"{where}: no source"
        assert r.formula.strip(), f"{where}: no formula"
        assert formula_svg(r.formula) is not None, f"{where}: mathtext cannot typeset {r.formula!r}"
