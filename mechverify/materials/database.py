"""The material database: TOML files under ``materials/data/``, looked up by name or alias.

File format (one file per family, any number of ``[[material]]`` entries)::

    [references]                      # short keys for the sources used below
    shigley10 = "Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015"

    [[material]]
    name = "AISI 1045 CD"             # unique, case-insensitive
    aliases = ["1045 CD", "C45 cold drawn"]
    category = "steel"
    source = "shigley10, Table A-20"  # default source of every value
    E = "207 GPa"                     # quantities as strings with units
    nu = 0.29
    yield_strength = "530 MPa"
    [material.sources]                # per-property source where it differs
    E = "shigley10, Table A-5"
    [material.sn_curve]               # optional: amplitude vs cycles, log-log interpolated
    unit = "MPa"
    cycles = [1e3, 1e6]
    stress = [500, 250]
    stress_ratio = -1
    [material.wire_strength]          # optional, spring wire: Sut = A/d^m, and a table by diameter
    A = "2211 MPa"
    m = 0.145
    d_unit = "mm"
    d_range = ["0.10 mm", "6.5 mm"]
    table_d_unit = "in"
    table_d = [0.004, 0.010]
    table_sut_unit = "ksi"
    table_sut = [439, 387]
    segments = [                      # optional: further laws where the law changes with d (A313)
      { A = "2065 MPa", m = 0.263, d_range = ["2.5 mm", "5 mm"] },
    ]

A reference key used in a ``source`` string is expanded to its full text.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterable, Iterator, Mapping
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

from mechverify.errors import InputError, UnknownNameError
from mechverify.materials.material import PROPERTY_DIMENSIONS, Material, SNCurve, WireStrength
from mechverify.units import Q, to_si

_KEYS = {"name", "aliases", "category", "source", "sources", "notes", "sn_curve", "wire_strength",
         *PROPERTY_DIMENSIONS}


def _norm(name: str) -> str:
    return re.sub(r"[\s_\-]+", " ", name.strip().lower())


class MaterialLibrary:
    """Materials by name and alias (case-insensitive, blanks/underscores/dashes alike).

    A library may have a ``parent`` (the built-in database): lookups fall back to it, so a design's
    own materials can extend or shadow the built-in ones.
    """

    def __init__(self, materials: Iterable[Material] = (), parent: MaterialLibrary | None = None):
        self.parent = parent
        self._by_key: dict[str, Material | _Pending] = {}
        self._own: list[Material | _Pending] = []
        for m in materials:
            self.add(m)

    def add(self, material: Material | _Pending) -> None:
        keys = [_norm(material.name), *(_norm(a) for a in material.aliases)]
        for k in keys:
            other = self._by_key.get(k)
            if other is not None and other is not material:
                raise InputError(f"material name {k!r} is used by both {other.name!r} and {material.name!r}")
        for k in keys:
            self._by_key[k] = material
        self._own.append(material)

    def get(self, name: str | Material) -> Material:
        """The material called ``name`` (or with that alias); unknown names list the closest ones."""
        if isinstance(name, Material):
            return name
        if not isinstance(name, str):
            raise InputError(f"material: expected a name, got {type(name).__name__}")
        hit = self._by_key.get(_norm(name))
        if isinstance(hit, _Pending):
            hit = self._resolve(hit)
        if hit is not None:
            return hit
        if self.parent is not None:
            try:
                return self.parent.get(name)
            except UnknownNameError:
                pass
        raise UnknownNameError("material", name, self.all_names())

    def _resolve(self, pending: _Pending) -> Material:
        """Build a material read lazily from the built-in data and put it in its entry's place."""
        material = pending.build()
        for k, v in list(self._by_key.items()):
            if v is pending:
                self._by_key[k] = material
        self._own = [material if m is pending else m for m in self._own]
        return material

    def __contains__(self, name: str) -> bool:
        try:
            self.get(name)
        except UnknownNameError:
            return False
        return True

    def names(self) -> list[str]:
        """Primary names of all materials, own first then inherited."""
        own = [m.name for m in self._own]
        inherited = [n for n in (self.parent.names() if self.parent else []) if _norm(n) not in self._by_key]
        return own + inherited

    def all_names(self) -> list[str]:
        """Names and aliases (for suggestions)."""
        out = [m.name for m in self._own] + [a for m in self._own for a in m.aliases]
        return out + (self.parent.all_names() if self.parent else [])

    def __iter__(self) -> Iterator[Material]:
        return (self.get(n) for n in self.names())

    def __len__(self) -> int:
        return len(self.names())


class _Pending:
    """A built-in material known by name and aliases, built from its TOML entry on first lookup.

    The database holds a few dozen materials and a design uses a few: building each one parses its
    unit strings, which made a cold ``mechverify check`` pay for every material (issue 27).
    """

    __slots__ = ("name", "aliases", "_entry", "_refs", "_where")

    def __init__(self, entry: Mapping[str, Any], refs: Mapping[str, str], where: str):
        self.name = entry.get("name")
        self.aliases = tuple(entry.get("aliases", ()))
        self._entry, self._refs, self._where = entry, refs, where
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError(f"{where}.name: expected a non-empty string")

    def build(self) -> Material:
        return material_from_dict(self._entry, self._refs, self._where)


def material_from_dict(d: Mapping[str, Any], references: Mapping[str, str] | None = None,
                       where: str = "material") -> Material:
    """Build a :class:`Material` from a TOML-style mapping (see the module docstring)."""
    refs = dict(references or {})
    unknown = set(d) - _KEYS
    if unknown:
        from mechverify.errors import suggest
        bad = sorted(unknown)[0]
        hint = suggest(bad, _KEYS)
        raise InputError(f"{where}.{bad}: unknown key" + (f"; did you mean {hint[0]!r}?" if hint else ""))
    for key in ("name", "category"):
        if not isinstance(d.get(key), str) or not d[key].strip():
            raise InputError(f"{where}.{key}: expected a non-empty string")

    def expand(src: str) -> str:
        return re.sub(r"\b([A-Za-z][\w-]*)\b", lambda m: refs.get(m.group(1), m.group(1)), src, count=1) if src else src

    name = d["name"]
    kwargs: dict[str, Any] = {}
    for prop in PROPERTY_DIMENSIONS:
        if prop in d:
            kwargs[prop] = d[prop]
    sn = d.get("sn_curve")
    if sn is not None:
        unit = sn.get("unit", "MPa")
        kwargs["sn_curve"] = SNCurve(
            cycles=tuple(float(c) for c in sn["cycles"]),
            stress=tuple(Q(float(s), unit).m_as("Pa") for s in sn["stress"]),
            stress_ratio=float(sn.get("stress_ratio", -1.0)),
            constant_beyond_last=bool(sn.get("constant_beyond_last", True)),
            source=expand(sn.get("source", d.get("source", ""))),
        )
    ws = d.get("wire_strength")
    if ws is not None:
        d_range = ws.get("d_range", ["0 mm", "1 m"])
        table_d = tuple(Q(float(x), ws.get("table_d_unit", "mm")).m_as("m") for x in ws.get("table_d", []))
        table_s = tuple(Q(float(x), ws.get("table_sut_unit", "MPa")).m_as("Pa") for x in ws.get("table_sut", []))
        if len(table_d) != len(table_s):
            raise InputError(f"{where}.wire_strength: table_d and table_sut differ in length")
        kwargs["wire_strength"] = WireStrength(
            A=to_si(ws["A"], "pressure", f"{where}.wire_strength.A"), m=float(ws["m"]),
            d_unit=ws.get("d_unit", "mm"),
            d_min=to_si(d_range[0], "length", "d_range"), d_max=to_si(d_range[1], "length", "d_range"),
            table_d=table_d, table_sut=table_s,
            source=expand(ws.get("source", d.get("source", ""))),
            table_source=expand(ws.get("table_source", "")),
            segments=tuple(_wire_segment(seg, f"{where}.wire_strength.segments[{i}]")
                           for i, seg in enumerate(ws.get("segments", []))),
        )
    return Material(
        name=name, category=d["category"], aliases=tuple(d.get("aliases", ())),
        source=expand(d.get("source", "")),
        sources={k: expand(v) for k, v in d.get("sources", {}).items()},
        notes=tuple(d.get("notes", ())) if not isinstance(d.get("notes"), str) else (d["notes"],),
        **kwargs,
    )


def _wire_segment(seg: Mapping[str, Any], where: str) -> tuple[float, float, float, float]:
    """One further power law of a wire: ``{A = "2065 MPa", m = 0.263, d_range = ["2.5 mm", "5 mm"]}``."""
    unknown = set(seg) - {"A", "m", "d_range"}
    if unknown or not {"A", "m", "d_range"} <= set(seg):
        raise InputError(f"{where}: expected keys A, m and d_range, got {sorted(seg)}")
    lo, hi = seg["d_range"]
    return (to_si(seg["A"], "pressure", f"{where}.A"), float(seg["m"]),
            to_si(lo, "length", f"{where}.d_range"), to_si(hi, "length", f"{where}.d_range"))


def load_toml(path: str | Path) -> list[Material]:
    """Read the materials of one TOML file (the built-in format, see the module docstring)."""
    path = Path(path)
    with path.open("rb") as fh:
        try:
            data = tomllib.load(fh)
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"{path.name}: not valid TOML ({exc})") from None
    return _materials_from_document(data, path.name)


def _materials_from_document(data: Mapping[str, Any], where: str) -> list[Material]:
    refs = data.get("references", {})
    return [material_from_dict(m, refs, f"{where}: material[{i}]") for i, m in enumerate(data.get("material", []))]


@cache
def default_library() -> MaterialLibrary:
    """The built-in database, loaded once on first use."""
    lib = MaterialLibrary()
    for entry in sorted(resources.files("mechverify.materials").joinpath("data").iterdir(), key=lambda p: p.name):
        if entry.name.endswith(".toml"):
            data = tomllib.loads(entry.read_text(encoding="utf-8"))
            refs = data.get("references", {})
            for i, m in enumerate(data.get("material", [])):
                lib.add(_Pending(m, refs, f"{entry.name}: material[{i}]"))
    return lib


def get(name: str | Material) -> Material:
    """A built-in material by name or alias: ``get("pla")``, ``get("Structural Steel")``."""
    return default_library().get(name)


def names() -> list[str]:
    """The names of all built-in materials."""
    return default_library().names()
