"""One bibliography, one edition (issue 16): Shigley is cited in its 10th edition only (``ref("shigley10", ...)``
and the same edition in docstrings and data files).

A line may still name the 9th edition when it records a check made against that text (it contains "checked"
or "compared with"): that is provenance, not a citation. The ``ref()`` keys are checked against
``mechverify/references.toml`` in tests/test_architecture.py.
"""

from __future__ import annotations

import re
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "mechverify"
FILES = sorted(p for ext in ("py", "toml", "md", "j2") for p in PKG.rglob(f"*.{ext}"))
OTHER_EDITION = re.compile(r"\b(?:7th|8th|9th|11th)[ -]?(?:ed\b|ed\.|edition)", re.IGNORECASE)  # Shigley editions near 10
SHIGLEY = re.compile(r"Shigley|Nisbett|bud29281", re.IGNORECASE)
PROVENANCE = re.compile(r"checked|compared with", re.IGNORECASE)


def shigley_citations_of_another_edition(text: str) -> list[tuple[int, str]]:
    """(line number, line) of every Shigley edition other than the 10th (7th, 8th, 9th, 11th) cited in ``text``."""
    out = []
    for m in OTHER_EDITION.finditer(text):
        window = text[max(0, m.start() - 200):m.end() + 200]
        start = text.rfind("\n", 0, m.start()) + 1
        end = text.find("\n", m.end())
        line = text[start:end if end >= 0 else None]
        if SHIGLEY.search(window) and not PROVENANCE.search(line):
            # Shigley on the same line, or on the line before when the edition opens this one (a wrapped citation)
            prev = text[text.rfind("\n", 0, max(start - 1, 0)) + 1:max(start - 1, 0)]
            if SHIGLEY.search(line) or (SHIGLEY.search(prev) and not text[start:m.start()].strip()):
                out.append((text.count("\n", 0, m.start()) + 1, line.strip()))
    return out


def test_no_shigley_citation_of_another_edition_in_the_package():
    assert len(FILES) > 100  # the scan sees the package (not vacuous)
    bad = [f"{p.relative_to(PKG.parent)}:{n}: {line}" for p in FILES
           for n, line in shigley_citations_of_another_edition(p.read_text(encoding="utf-8"))]
    assert not bad, "cite Shigley's 10th edition (ref('shigley10', ...)):\n" + "\n".join(bad)


def test_the_scan_finds_a_9th_edition_citation_and_spares_provenance():
    found = shigley_citations_of_another_edition(
        "Lead angle (Shigley 9th ed., Sec. 8-2).\nBudynas & Nisbett, Shigley's Mechanical Engineering Design,\n"
        "    9th ed., 2011.\nRoark's Formulas, 9th ed. (Young, Budynas, Sadegh)\n")
    assert [n for n, _ in found] == [1, 3]
    assert not shigley_citations_of_another_edition("values checked in the Shigley 9th-ed. text\n")
    assert not shigley_citations_of_another_edition("Shigley 10th ed., Eq. 8-1\n")
