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
    def _index(self) -> tuple[dict[str, T], tuple[str, ...]]:
        with open(self.path, "rb") as fh:
            data = tomllib.load(fh)
        refs = data.get("references", {})
        by_key: dict[str, T] = {}
        names: list[str] = []
        for entry in data.get(self.table, []):
            item = self.build(entry, refs)
            for key in [entry["name"], *entry.get("aliases", [])]:
                if normalise(key) in by_key:
                    raise InputError(f"{self.path.name}: name {key!r} used twice")
                by_key[normalise(key)] = item
                names.append(key)
        return by_key, tuple(names)

    def get(self, name: str) -> T:
        by_key, names = self._index
        hit = by_key.get(normalise(name))
        if hit is None:
            raise UnknownNameError(self.kind, name, names)
        return hit

    def names(self) -> list[str]:
        """Primary names, sorted."""
        by_key, _ = self._index
        return sorted({item.name for item in by_key.values()})
