"""Catalogues of named components read from a TOML data file (motors, gearheads).

Each entry is a table in an array (``[[motor]]``) with a ``name`` and optional ``aliases``; a
``[references]`` table maps short source keys to full references. Lookups ignore case, blanks,
underscores and dashes; an unknown name raises :class:`UnknownNameError` with the closest names.
"""

from __future__ import annotations

import functools
import tomllib
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any, Generic, TypeVar

from mechverify.errors import InputError, UnknownNameError

T = TypeVar("T")


def normalise(name: str) -> str:
    return " ".join(name.lower().replace("_", " ").replace("-", " ").split())


class Catalogue(Generic[T]):
    """Entries of ``table`` in ``path``, each built by ``build(entry, references)``, loaded on first use."""

    def __init__(self, kind: str, path: Path, table: str, build: Callable[[Mapping[str, Any], Mapping[str, str]], T]):
        self.kind, self.path, self.table, self.build = kind, path, table, build

    @functools.cached_property
    def _index(self) -> tuple[dict[str, int], tuple[str, ...], list[Mapping[str, Any]], dict[str, str]]:
        """Keys -> entry number, all names, the raw entries and the references; entries are built lazily.

        A catalogue holds dozens of rows and a design uses one or two: building a row parses its unit
        strings, so a lookup builds only the row it returns (a cold ``mechverify check``, issue 27).
        """
        with open(self.path, "rb") as fh:
            data = tomllib.load(fh)
        refs = data.get("references", {})
        entries = list(data.get(self.table, []))
        by_key: dict[str, int] = {}
        names: list[str] = []
        for i, entry in enumerate(entries):
            for key in [entry["name"], *entry.get("aliases", [])]:
                if normalise(key) in by_key:
                    raise InputError(f"{self.path.name}: name {key!r} used twice")
                by_key[normalise(key)] = i
                names.append(key)
        return by_key, tuple(names), entries, refs

    @functools.cached_property
    def _built(self) -> dict[int, T]:
        return {}

    def _item(self, i: int) -> T:
        built = self._built
        if i not in built:
            _, _, entries, refs = self._index
            built[i] = self.build(entries[i], refs)
        return built[i]

    def get(self, name: str) -> T:
        by_key, names, _, _ = self._index
        i = by_key.get(normalise(name))
        if i is None:
            raise UnknownNameError(self.kind, name, names)
        return self._item(i)

    def names(self) -> list[str]:
        """Primary names, sorted."""
        _, _, entries, _ = self._index
        return sorted({str(e["name"]) for e in entries})
