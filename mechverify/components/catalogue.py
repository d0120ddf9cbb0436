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

from mechverify.errors import InputError, MechverifyError, UnknownNameError

T = TypeVar("T")


def normalise(name: str) -> str:
    return " ".join(name.lower().replace("_", " ").replace("-", " ").split())


def catalogue_entry(cls: type, d: Mapping[str, Any], where: str, needs: str,
                    references: Mapping[str, str] | None = None,
                    tuples: tuple[str, ...] = ("notes",)) -> dict[str, Any]:
    """The keyword arguments of dataclass ``cls`` from a catalogue entry ``d``: ``aliases`` dropped, ``source``
    looked up in ``references``, the ``tuples`` keys made tuples. An unknown key (with a did-you-mean) or a missing
    required field is an :class:`InputError` at ``where.key`` (``where`` = ``"motor 'RE 13'"``; ``needs`` =
    ``"a dc motor"`` in the message)."""
    from dataclasses import MISSING, fields

    d = dict(d)
    d.pop("aliases", None)
    allowed = {f.name for f in fields(cls) if f.init}
    unknown = set(d) - allowed
    if unknown:
        from mechverify.errors import suggest
        bad = sorted(unknown)[0]
        hint = suggest(bad, allowed)
        raise InputError(f"{where}.{bad}: unknown key" + (f"; did you mean {hint[0]!r}?" if hint else ""))
    missing = sorted(f.name for f in fields(cls) if f.init and f.name not in d
                     and f.default is MISSING and f.default_factory is MISSING)
    if missing:
        raise InputError(f"{where}.{missing[0]}: missing ({needs} needs {', '.join(missing)})")
    refs = dict(references or {})
    if "source" in d:
        d["source"] = refs.get(d["source"], d["source"])
    for k in tuples:
        if k in d:
            d[k] = tuple(d[k])
    return d


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


# ------------------------------------------------------------------------------ a user's catalogue file
def read_catalogue_file(path: str | Path, builders: Mapping[str, Callable[[Mapping[str, Any], Mapping[str, str]], Any]]
                        ) -> dict[str, list[tuple[str, dict[str, Any], Any]]]:
    """A user's catalogue file (TOML, the layout of ``components/data/motors.toml``: ``[[motor]]`` and
    ``[[gearhead]]`` entries with a ``name``, optional ``[references]``), validated entry by entry.

    ``builders`` maps each allowed table name to the function that builds an entry (``motor_from_dict``).
    Returns table -> [(name, raw entry, built item)]. Every problem is an :class:`InputError` naming the file
    and the key path (``my_motors.toml: motor[2].torque_konstant: unknown key; did you mean
    'torque_constant'?``): a missing file, TOML syntax, an unknown table, an entry without ``name``, a name
    used twice, an entry its builder rejects, a file without entries.
    """
    p = Path(path)
    label = p.name
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"catalogue file {str(p)!r} not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"catalogue file {str(p)!r} cannot be read: {exc}") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{label}: not valid TOML: {exc}") from None
    allowed = (*builders, "references")
    for key in data:
        if key not in allowed:
            from mechverify.errors import suggest
            hint = suggest(key, allowed, 1)
            raise InputError(f"{label}: {key}: unknown table" + (f"; did you mean {hint[0]!r}?" if hint else
                                                                  f" (allowed: {', '.join(allowed)})"))
    refs = data.get("references", {})
    if not isinstance(refs, dict) or not all(isinstance(v, str) for v in refs.values()):
        raise InputError(f"{label}: references: give a table of key = \"full reference\" strings")
    out: dict[str, list[tuple[str, dict[str, Any], Any]]] = {}
    seen: dict[str, str] = {}
    for table, build in builders.items():
        entries = data.get(table, [])
        if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
            raise InputError(f"{label}: {table}: give [[{table}]] entries (an array of tables)")
        rows = []
        for i, entry in enumerate(entries):
            where = f"{label}: {table}[{i}]"
            name = entry.get("name")
            if not isinstance(name, str) or not name.strip():
                raise InputError(f"{where}.name: missing (every entry needs a name)")
            for key in [name, *entry.get("aliases", [])]:
                k = normalise(str(key))
                if k in seen:
                    raise InputError(f"{where}.name: {key!r} is used twice (also {seen[k]})")
                seen[k] = f"{table}[{i}]"
            try:
                item = build(entry, refs)
            except MechverifyError as exc:
                msg = str(exc)
                for prefix in (f"{table} {name!r}.", f"{name}."):
                    if msg.startswith(prefix):
                        raise InputError(f"{where}.{msg[len(prefix):]}") from None
                raise InputError(f"{where} ({name}): {msg}") from None
            rows.append((name, dict(entry), item))
        out[table] = rows
    if not any(out.values()):
        raise InputError(f"{label}: no entries (give {' or '.join(f'[[{t}]]' for t in builders)} tables)")
    return out
