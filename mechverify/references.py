"""The one bibliography: ``ref("shigley10", "Eq. 8-1")`` formats a citation from :file:`references.toml`.

Every source the code cites has one key in ``mechverify/references.toml`` (one edition per book); a
check's ``source`` is built with :func:`ref`, the report's reference list with :func:`bibliography`,
and ``tests/test_architecture.py`` fails on a ``ref()`` key that is not in the file.
"""

from __future__ import annotations

import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from mechverify.errors import UnknownNameError

PATH = Path(__file__).with_name("references.toml")


@dataclass(frozen=True)
class Reference:
    """One source of :file:`references.toml`."""

    key: str
    title: str
    authors: str = ""
    edition: str = ""
    year: int = 0
    publisher: str = ""
    number: str = ""  # standard number, e.g. "ISO 281:2007"
    url: str = ""
    note: str = ""

    @property
    def citation(self) -> str:
        """The formatted citation without a location: authors, title, edition, publisher and year."""
        head = f"{self.number}, {self.title}" if self.number else self.title
        parts = [p for p in (self.authors, head) if p]
        if self.edition:
            parts.append(f"{self.edition} ed.")
        if self.publisher and not self.number and self.publisher != self.authors:
            parts.append(self.publisher)
        if self.year and str(self.year) not in self.number:
            parts.append(str(self.year))
        return ", ".join(parts)


@cache
def references() -> dict[str, Reference]:
    """Every reference of :file:`references.toml` by key."""
    with PATH.open("rb") as f:
        raw = tomllib.load(f)
    out = {}
    for key, entry in raw.items():
        if not isinstance(entry, dict) or "title" not in entry:
            raise ValueError(f"{PATH.name}: [{key}] needs at least a title")
        out[key] = Reference(key=key, **entry)
    return out


def get(key: str) -> Reference:
    """The :class:`Reference` with ``key``.

    Raises:
        UnknownNameError: ``key`` is not in :file:`references.toml` (with suggestions).
    """
    refs = references()
    if key not in refs:
        raise UnknownNameError("reference", key, refs)
    return refs[key]


def ref(key: str, where: str = "") -> str:
    """The citation of source ``key`` at ``where`` (``"Sec. 8-2, Eq. 8-1"``), as one string.

    >>> ref("shigley10", "Eq. 8-1")
    "R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill Education, \
    2015, Eq. 8-1"

    Raises:
        UnknownNameError: ``key`` is not in :file:`references.toml`.
    """
    c = get(key).citation
    return f"{c}, {where}" if where else c


def keys_in(text: str) -> list[str]:
    """The reference keys whose formatted citation occurs in ``text`` (a source built with :func:`ref`)."""
    return [k for k, r in references().items() if r.citation in text] if text else []


def bibliography(keys: Iterable[str] | None = None) -> list[tuple[str, str]]:
    """``(key, citation)`` pairs for ``keys`` (all references when ``None``), sorted by citation."""
    refs = references()
    ks = list(refs) if keys is None else list(dict.fromkeys(keys))
    return sorted(((k, get(k).citation) for k in ks), key=lambda kc: kc[1].lower())
