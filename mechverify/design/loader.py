"""Read and validate a design file (TOML), reporting every error at once with its key path.

Top-level tables: ``design`` (name, revision, description, include), ``requirements``,
``materials``, ``templates``, ``profiles``, ``components``, ``load_cases``. The format is
documented in ``docs/design-files.md``; its JSON Schema comes from :mod:`mechverify.design.schema`.
No code is executed: values are strings with units, numbers, booleans and names.
"""

from __future__ import annotations

import functools
import math
import re
import tomllib
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from mechverify.design.expressions import ExpressionError, format_value
from mechverify.design.expressions import parse as parse_expression
from mechverify.design.parameters import (
    Deferred,
    Trace,
    resolve_fields,
    resolve_load_cases,
    resolve_parameters,
    substitute,
    value_or_deferred,
)
from mechverify.design.reuse import (
    field_reuse,
    remember_validated,
    reuse_context,
    reused_object,
    unchanged_table_key,
    validated_before,
    validation_key,
)
from mechverify.design.spec import DEFAULT_SAFETY_FACTORS, REGISTRY, ComponentType, Field
from mechverify.errors import MechverifyError, suggest
from mechverify.materials import MaterialLibrary, default_library, material_from_dict
from mechverify.materials.material import PROPERTY_DIMENSIONS
from mechverify.units import DIMENSIONS, as_quantity, fmt, from_si

TOP_KEYS = ("design", "parameters", "requirements", "materials", "templates", "profiles", "components", "load_cases")
DESIGN_KEYS = ("name", "revision", "description", "include", "author")
REQUIREMENT_FIELDS = (
    Field("g", "acceleration", "standard gravity used for self-weight", default="9.80665 m/s^2"),
    Field("bearing_life", "time", "required L10 life of rolling bearings", default="10000 h"),
    Field("deflection_limit", "float", "allowed deflection as a fraction of the span (e.g. 0.002 = L/500)",
          default=0.002),
    Field("safety_factors", "table", "required safety factor per check class: " + ", ".join(DEFAULT_SAFETY_FACTORS)),
)


class DesignFileError(MechverifyError):
    """A design file is invalid. ``errors`` lists ``(key path, message)`` pairs, all of them."""

    def __init__(self, errors: list[tuple[str, str]], file: str = ""):
        self.errors = list(errors)
        self.file = file
        head = f"{file}: " if file else ""
        n = len(self.errors)
        lines = [f"{head}{n} error{'s' if n != 1 else ''} in the design file:"]
        lines += [f"  {path}: {msg}" if path else f"  {msg}" for path, msg in self.errors]
        super().__init__("\n".join(lines))


@dataclass
class Entry:
    """One validated entry of a typed section (a component or a profile)."""

    name: str
    type: ComponentType
    params: dict[str, Any]  # validated values: quantities, materials, strings ...
    raw: dict[str, Any]  # as written in the file
    checks: dict[str, dict[str, Any]] = field(default_factory=dict)  # overrides per check
    obj: Any = None  # the built component


@dataclass
class DesignData:
    path: Path | None
    files: list[Path]
    name: str
    revision: str
    description: str
    requirements: dict[str, Any]
    safety_factors: dict[str, float]
    materials: MaterialLibrary
    profiles: dict[str, Entry]
    components: dict[str, Entry]
    load_cases: dict[str, dict[str, dict[str, Any]]]  # case -> component -> load name -> value
    load_case_docs: dict[str, str]
    raw: dict[str, Any]
    parameters: dict[str, Any] = field(default_factory=dict)  # name -> value ([parameters], resolved)
    trace: Trace = field(default_factory=Trace)  # derived values: key path -> (expression, value)


class _Collector:
    def __init__(self) -> None:
        self.errors: list[tuple[str, str]] = []

    def add(self, path: str, msg: str) -> None:
        self.errors.append((path, msg))

    def unknown_keys(self, table: Mapping[str, Any], allowed: Any, path: str) -> None:
        allowed = list(allowed)
        for k in table:
            if k not in allowed:
                hint = suggest(str(k), allowed, 1)
                self.add(f"{path}.{k}" if path else str(k),
                         "unknown key" + (f"; did you mean {hint[0]!r}?" if hint else
                                          f" (allowed: {', '.join(allowed)})"))


def _describe(v: Any) -> str:
    return f'"{v}"' if isinstance(v, str) else repr(v)


def _a(kind: str) -> str:
    word = kind.replace("_", " ")
    return ("an " if word[0] in "aeiou" else "a ") + word


def validate_value(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    """Check one value against its field; record an error and return ``None`` when it is bad.

    An expression (over ``[parameters]`` or component values) is read first; otherwise the validator of
    the field's kind (:data:`_VALIDATORS`; a dimension name reads a quantity) checks the value.
    """
    if isinstance(v, str) and (ctx.get("parameters") or ctx.get("component_names")):
        done, out = _expression_value(f, v, path, col, ctx)
        if done:
            return out
    validator = _quantity if f.kind in DIMENSIONS else _VALIDATORS.get(f.kind)
    if validator is None:
        raise AssertionError(f.kind)
    return validator(f, v, path, col, ctx)


def _bad(col: _Collector, path: str, msg: str) -> None:
    """Record an error; the validators return this (``None``) for a bad value."""
    col.add(path, msg)


def _quantity(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    kind = f.kind
    if isinstance(v, bool) or not isinstance(v, str | int | float):
        return _bad(col, path, f"expected {_a(kind)} as a string with units, got {_describe(v)}")
    if isinstance(v, int | float) and kind != "dimensionless":
        unit = {"length": "mm", "force": "N", "pressure": "MPa", "torque": "N*m"}.get(kind, "...")
        return _bad(col, path, f'expected {_a(kind)}, got the bare number {v!r}; write it with units, '
                               f'e.g. "{v} {unit}"')
    try:
        return as_quantity(v, kind, path)
    except MechverifyError as exc:
        msg = str(exc).split(": ", 1)[-1]
        msg = msg.replace(f"got {v}", f"got {_describe(v)}") if isinstance(v, str) else msg
        return _bad(col, path, msg)


def _str(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    return v if isinstance(v, str) else _bad(col, path, f"expected a string, got {_describe(v)}")


def _bool(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    return v if isinstance(v, bool) else _bad(col, path, f"expected true or false, got {_describe(v)}")


def _number(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    ok = isinstance(v, int) if f.kind == "int" else isinstance(v, int | float)
    if isinstance(v, bool) or not ok:
        return _bad(col, path, f"expected {'an integer' if f.kind == 'int' else 'a number'}, got {_describe(v)}")
    return v


def _choice(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    if v in f.choices:
        return v
    hint = suggest(str(v), f.choices, 1)
    return _bad(col, path, f"expected one of {', '.join(repr(c) for c in f.choices)}, got {_describe(v)}"
                           + (f"; did you mean {hint[0]!r}?" if hint else ""))


def _material(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    if not isinstance(v, str):
        return _bad(col, path, f"expected a material name, got {_describe(v)}")
    try:
        return ctx["materials"].get(v)
    except MechverifyError as exc:
        return _bad(col, path, str(exc))


def _ref(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    names = ctx.get(f.ref, {})
    if isinstance(v, str) and v in names:
        return v
    hint = suggest(str(v), names, 1)
    return _bad(col, path, f"expected the name of an entry of [{f.ref}], got {_describe(v)}"
                           + (f"; did you mean {hint[0]!r}?" if hint else f" (defined: {', '.join(names) or 'none'})"))


def _list(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    if not isinstance(v, list):
        return _bad(col, path, f"expected a list, got {_describe(v)}")
    item = Field(f.name, f.item or "str", choices=f.choices, ref=f.ref)
    out = [validate_value(item, x, f"{path}[{i}]", col, ctx) for i, x in enumerate(v)]
    return None if any(x is None for x in out) else out


def _table(f: Field, v: Any, path: str, col: _Collector, ctx: dict[str, Any]) -> Any:
    if not isinstance(v, dict):
        return _bad(col, path, f"expected a table, got {_describe(v)}")
    try:
        return substitute(v, path, ctx, skip=_NAME_KEYS)
    except ExpressionError as exc:
        return _bad(col, path, str(exc))


#: The validator of each plain field kind (:data:`~mechverify.design.spec.PLAIN_KINDS`); dimension names
#: use :func:`_quantity`.
_VALIDATORS: dict[str, Any] = {"str": _str, "bool": _bool, "int": _number, "float": _number, "choice": _choice,
                               "material": _material, "ref": _ref, "list": _list, "table": _table}


#: Keys of inline tables that hold names, never expressions.
_NAME_KEYS = ("type", "name", "at", "start", "end", "screw", "axis", "drive", "base")


def _expression_value(f: Field, v: str, path: str, col: _Collector, ctx: dict[str, Any]) -> tuple[bool, Any]:
    """``(True, value)`` when ``v`` is an expression reading parameters or component values (``value`` is
    ``None`` after an error, a :class:`~mechverify.design.parameters.Deferred` for component values);
    ``(False, None)`` when the value is to be read as before (a plain quantity, a name, free text)."""
    if f.kind not in DIMENSIONS and f.kind not in ("int", "float", "str"):
        return False, None
    try:
        e = parse_expression(v)
    except ExpressionError as exc:
        if f.kind != "str" and (any(c in v for c in "()[]<>=;'\"") or "lambda" in v):
            col.add(path, str(exc))  # meant as an expression: say what is wrong with it
            return True, None
        return False, None  # not an expression: the plain reading reports what is wrong
    if not e.names:
        return False, None
    if f.kind == "str":  # free text or a quantity read by the adapter: only expressions over parameters
        params = ctx.get("parameters") or {}
        if not params or not e.names <= set(params):
            return False, None
        try:
            val = e.evaluate(params)
        except ExpressionError as exc:
            col.add(path, str(exc))
            return True, None
        ctx["trace"].add(path, e.source, val, tuple(sorted(e.names)))
        return True, format_value(val)
    try:
        return True, value_or_deferred(v, f.kind, path, f.name, ctx)
    except ExpressionError as exc:
        col.add(path, str(exc))
        return True, None


def _validate_fields(fields: tuple[Field, ...], table: Mapping[str, Any], path: str, col: _Collector,
                     ctx: dict[str, Any], extra_keys: tuple[str, ...] = (), reuse: Any = None) -> dict[str, Any]:
    """The validated values of ``table``'s fields. ``reuse``: :func:`mechverify.design.reuse.field_reuse` (a variant:
    fields whose inputs are the base's take its values, their derived values traced again, in field order)."""
    col.unknown_keys(table, [f.name for f in fields] + list(extra_keys), path)
    out: dict[str, Any] = {}
    for f in fields:
        if f.name in table:
            taken = reuse(f.name, table[f.name]) if reuse is not None else None
            if taken is not None:
                out[f.name] = taken[0]
                for args in taken[1]:
                    ctx["trace"].add(*args)
                continue
            val = validate_value(f, table[f.name], f"{path}.{f.name}", col, ctx)
            if val is not None:
                out[f.name] = val
        elif f.required:
            what = _a(f.kind) if f.kind in DIMENSIONS else f.kind
            col.add(f"{path}.{f.name}", f"missing: {f.doc or 'required'} ({what})")
        elif f.default is not None:
            out[f.name] = validate_value(f, f.default, f"{path}.{f.name}", col, ctx)
    return out


def validate_reusing(fields: tuple[Field, ...], table: Mapping[str, Any], path: str, col: _Collector,
                     ctx: dict[str, Any]) -> dict[str, Any]:
    """:func:`_validate_fields` of a component's, profile's or load case's table, or, in a variant
    (``Design.with_overrides``), the values the base design validated for the same table when everything the
    validation reads is unchanged (:func:`mechverify.design.reuse.validated_before`): the derived values it traced
    are recorded again. Every parse keeps its validated tables for its own variants."""
    key = unchanged_table_key(path, ctx)  # (a table no override touched: the base's reduction of its text)
    untouched = key is not None
    if key is None:
        key = validation_key(table, ctx)
    hit = validated_before(path, fields, key, ctx)
    if hit is not None:
        params, traced = hit
        if untouched and not any(isinstance(v, Deferred) for v in params.values()):
            # the same text and the same values as in the base (reuse.reused_object compares the rest of the build key)
            ctx.setdefault("_taken_tables", set()).add(path)
        for args in traced:
            ctx["trace"].add(*args)
        return params
    trace, n_err = ctx["trace"], len(col.errors)
    before = set(trace.entries)
    out = _validate_fields(fields, table, path, col, ctx, reuse=field_reuse(path, fields, key, ctx))
    if len(col.errors) == n_err:
        traced = tuple((p, *trace.entries[p], trace.edges.get(p, ())) for p in trace.entries if p not in before)
        remember_validated(path, fields, key, ctx, out, traced)
    return out


def _read_toml(path: Path, col: _Collector, where: str) -> dict[str, Any]:
    try:
        if path.exists() and not path.is_file() and not path.is_dir():  # a FIFO would block, a device never end
            col.add(where, f"not a regular file: {path}")
            return {}
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        col.add(where, f"file not found: {path}")
    except IsADirectoryError:
        col.add(where, f"is a directory, not a design file: {path}")
    except tomllib.TOMLDecodeError as exc:
        col.add(where, f"not valid TOML: {exc}")
    except (OSError, UnicodeDecodeError) as exc:
        col.add(where, f"cannot read {path}: {exc}")
    return {}


def _merge_includes(doc: dict[str, Any], base: Path | None, col: _Collector, allow_outside: bool,
                    files: list[Path]) -> dict[str, Any]:
    design = doc.get("design", {})
    includes = design.get("include", []) if isinstance(design, dict) else []
    if not includes:
        return doc
    if not isinstance(includes, list) or not all(isinstance(i, str) for i in includes):
        col.add("design.include", "expected a list of relative file paths")
        return doc
    root = base.parent.resolve() if base else Path.cwd().resolve()
    merged = {k: (dict(v) if isinstance(v, dict) else v) for k, v in doc.items()}
    for i, rel in enumerate(includes):
        where = f"design.include[{i}]"
        target = (root / rel).resolve()
        if not allow_outside and not target.is_relative_to(root):
            col.add(where, f"{rel!r} is outside the design's folder ({root}); pass --allow-outside-includes "
                           "to allow it")
            continue
        inc = _read_toml(target, col, where)
        files.append(target)
        for key, table in inc.items():
            if key not in ("materials", "templates", "profiles", "components"):
                col.add(f"{where}: {key}", "an included file may only hold [materials], [templates], "
                                           "[profiles] and [components]")
                continue
            if not isinstance(table, dict):
                continue
            dest = merged.setdefault(key, {})
            for name, entry in table.items():
                if name in dest:
                    col.add(f"{key}.{name}", f"defined both in the design and in {rel!r}")
                else:
                    dest[name] = entry
    return merged


def _materials(doc: dict[str, Any], col: _Collector, pctx: dict[str, Any]) -> MaterialLibrary:
    lib = MaterialLibrary(parent=default_library())
    table = doc.get("materials", {})
    if not isinstance(table, dict):
        col.add("materials", "expected a table of materials")
        return lib
    for name, entry in table.items():
        path = f"materials.{name}"
        if not isinstance(entry, dict):
            col.add(path, "expected a table")
            continue
        if "extends" in entry and "base" not in entry:  # the components' key; a material's is 'base' (review 3)
            col.add(f"{path}.extends", "unknown key; did you mean 'base'? (a material builds on another with "
                    "base = \"...\"; extends is the key of components and templates)")
            entry = {("base" if k == "extends" else k): v for k, v in entry.items()}  # no cascade of errors
        try:
            if "base" in entry:
                base = lib.get(entry["base"])
                changes = {k: v for k, v in entry.items() if k != "base"}
                col.unknown_keys(changes, list(PROPERTY_DIMENSIONS), path)
                ok = {}
                for k, v in changes.items():
                    if k in PROPERTY_DIMENSIONS:
                        q = validate_value(Field(k, PROPERTY_DIMENSIONS[k]), v, f"{path}.{k}", col, pctx)
                        if q is not None:
                            ok[k] = q
                lib.add(base.with_(name=name, **ok))
            else:
                lib.add(material_from_dict({"name": name, **entry}, where=path))
        except MechverifyError as exc:  # "mystery.density: must be positive" -> at materials.mystery.density
            msg = str(exc)
            for prefix in (f"{path}.", f"{name}."):
                key, sep, rest = msg[len(prefix):].partition(": ")
                if msg.startswith(prefix) and sep and key.isidentifier():
                    col.add(f"{path}.{key}", rest)
                    break
            else:
                col.add(path, msg)
            if "base" in entry and name not in lib:  # the design is refused already: no second error at every
                try:  # component that uses the material ("unknown material")
                    lib.add(lib.get(entry["base"]).with_(name=name))
                except MechverifyError:
                    pass
    return lib


def _extend(raw: dict[str, Any], templates: dict[str, Any], path: str, col: _Collector) -> dict[str, Any] | None:
    """``raw`` with its template (and the template's templates) filled in; ``None`` after an error
    (an unknown template, a cycle of ``extends``)."""
    chain: list[str] = []
    out = {k: v for k, v in raw.items() if k != "extends"}
    name = raw["extends"]
    while True:
        if not isinstance(name, str) or not isinstance(templates.get(name), dict):
            hint = suggest(str(name), templates, 1)
            where = f"{path}.extends" if not chain else f"templates.{chain[-1]}.extends"
            col.add(where, f"no template {name!r}" + (f"; did you mean {hint[0]!r}?" if hint else ""))
            return None
        if name in chain:
            col.add(f"{path}.extends", "templates extend each other in a cycle: " + " -> ".join([*chain, name]))
            return None
        chain.append(name)
        base = templates[name]
        out = {**{k: v for k, v in base.items() if k != "extends"}, **out}
        if "extends" not in base:
            return out
        name = base["extends"]


def _typed_section(doc: dict[str, Any], section: str, col: _Collector, ctx: dict[str, Any],
                   templates: dict[str, Any]) -> dict[str, Entry]:
    types = REGISTRY.section(section)  # imports only the adapters of the types the design names
    out: dict[str, Entry] = {}
    table = doc.get(section, {})
    if not isinstance(table, dict):
        col.add(section, "expected a table")
        return out
    for name, raw in table.items():
        path = f"{section}.{name}"
        if not isinstance(raw, dict):
            col.add(path, "expected a table")
            continue
        if "extends" in raw:
            raw = _extend(raw, templates, path, col)
            if raw is None:
                continue
        tname = raw.get("type")
        if tname not in types:
            hint = suggest(str(tname), types, 1)
            col.add(f"{path}.type", (f"unknown type {tname!r}" if tname is not None else "missing") +
                    (f"; did you mean {hint[0]!r}?" if hint else f" (known: {', '.join(sorted(types))})"))
            continue
        ct = types[tname]
        body = {k: v for k, v in raw.items() if k not in ("type", "checks")}
        params = validate_reusing(ct.fields, body, path, col, ctx)
        checks: dict[str, dict[str, Any]] = {}
        overrides = raw.get("checks", {})
        if not isinstance(overrides, dict):
            col.add(f"{path}.checks", "expected a table of check settings")
            overrides = {}
        known = [c.name for c in ct.checks] + [a for c in ct.checks for a in c.aliases]
        col.unknown_keys(overrides, known, f"{path}.checks")
        for key, setting in overrides.items():
            if key not in known:
                continue
            cpath = f"{path}.checks.{key}"
            if isinstance(setting, bool):
                value = {"enabled": setting}
            elif isinstance(setting, dict):
                col.unknown_keys(setting, ("enabled", "required_sf"), cpath)
                sf = setting.get("required_sf")
                if sf is not None and (isinstance(sf, bool) or not isinstance(sf, int | float)
                                       or not 0 < sf < math.inf):
                    col.add(f"{cpath}.required_sf", f"expected a positive finite number, got {_describe(sf)}")
                enabled = setting.get("enabled", True)  # settings without `enabled` turn the check on
                if not isinstance(enabled, bool):
                    col.add(f"{cpath}.enabled", f"expected true or false, got {_describe(enabled)}")
                value = {"enabled": enabled is not False, **{k: v for k, v in setting.items() if k == "required_sf"}}
            else:
                col.add(cpath, "expected true, false or a table such as { required_sf = 2.0 }, "
                               f"got {_describe(setting)}")
                continue
            for spec in ct.checks_named(key):  # a former key (alias) sets the renamed check(s), noted in the result
                checks[spec.name] = value | ({"alias": key} if key != spec.name else {})
        out[name] = Entry(name, ct, params, raw, checks)
    return out


_KEY_PREFIX = re.compile(r"([A-Za-z_]\w*)((?:\.\w+|\[\d+\])*): ")


def key_path(path: str, msg: str, keys: Collection[str]) -> tuple[str, str]:
    """``(path, msg)`` with a leading key path of the table at ``path`` joined into the path.

    An adapter's message ``"path.r: expected a length"`` about ``components.arm`` becomes
    ``("components.arm.path.r", "expected a length")`` when ``path`` is one of ``keys`` (the table's keys
    as written and its type's field names), as does one that starts with the full path
    (``"components.arm.path.r: ..."``); any other message is left as it is.
    """
    full = msg.startswith(f"{path}.")
    if full:
        msg = msg[len(path) + 1:]
    m = _KEY_PREFIX.match(msg)
    if m is None or not (full or m.group(1) in keys):
        return path, (f"{path}.{msg}" if full else msg)
    return f"{path}.{m.group(1)}{m.group(2)}", msg[m.end():]


@functools.cache
def _si_value() -> re.Pattern[str]:
    """An SI value in a message of :func:`mechverify.units.require_positive`: ``got -0.1 (SI)``, or with ``dim``
    ``must be positive, got -0.1 m`` (a number in the SI unit of a :data:`DIMENSIONS` entry, or none)."""
    units = sorted({fmt(from_si(1.0, d)).partition(" ")[2] for d in DIMENSIONS} - {""}, key=len, reverse=True)
    number = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?"
    return re.compile(rf"got (.+) \(SI\)|(?<=positive, )got {number}(?: (?:{'|'.join(map(re.escape, units))}))?$")


def as_written(path: str, msg: str, table: Mapping[str, Any], table_path: str) -> str:
    """``msg`` with an SI value (``"got -0.1 (SI)"`` or ``"got -0.1 m"``, :func:`mechverify.units.require_positive`)
    replaced by the value as written at ``path`` (a key path inside ``table``, the table at ``table_path``), when
    there is one."""
    if not path.startswith(f"{table_path}.") or _si_value().search(msg) is None:
        return msg
    v: Any = table
    for part in re.findall(r"[^.\[\]]+", path[len(table_path) + 1:]):
        try:
            v = v[int(part)] if isinstance(v, list) else v[part]
        except (KeyError, IndexError, ValueError, TypeError):
            return msg
    return msg if isinstance(v, Mapping | list) else _si_value().sub(lambda _: f"got {_describe(v)}", msg, count=1)


def _build(entries: dict[str, Entry], section: str, col: _Collector, ctx: dict[str, Any]) -> None:
    """Build every entry; one whose fields read other components' outputs after those (dependency order)."""
    bad = {e.name for e in entries.values()
           if any(p == f"{section}.{e.name}" or p.startswith(f"{section}.{e.name}.") for p, _ in col.errors)}
    building: list[str] = []  # being built, in order (a second visit is a cycle)
    done: set[str] = set()

    def build(e: Entry) -> bool:
        if e.name in done:
            return True
        if e.name in building:
            cycle = " -> ".join([*building[building.index(e.name):], e.name])
            if not any(m == f"cycle {cycle}" for _, m in col.errors):
                col.add(section, f"cycle {cycle}")
            return False
        if e.name in bad:
            return False
        building.append(e.name)
        try:
            if not resolve_fields(e, entries, ctx.get("parameters", {}), build, col.add, ctx["trace"]):
                bad.add(e.name)
                return False
            e.obj = reused_object(e, section, ctx)  # a variant's unchanged immutable entry: the base's object
            if e.obj is None:
                e.obj = e.type.build({**e.params, "_name": e.name}, ctx)
            done.add(e.name)
            return True
        except MechverifyError as exc:
            at, msg = key_path(f"{section}.{e.name}", str(exc), {*e.raw, *(f.name for f in e.type.fields)})
            col.add(at, as_written(at, msg, e.raw, f"{section}.{e.name}"))
            bad.add(e.name)
            return False
        finally:
            building.remove(e.name)

    for e in entries.values():
        build(e)
    build = None  # type: ignore[assignment]  # (the recursive closure's cycle holds the parse context: freed now)


def parse(doc: dict[str, Any], path: Path | None = None, allow_outside: bool = False,
          base: DesignData | None = None, changed: Collection[str] | None = None) -> DesignData:
    """Validate a parsed TOML document; raise :class:`DesignFileError` listing every problem.

    ``base``: the data of a design this one is a variant of (``Design.with_overrides``); entries whose build inputs
    are unchanged take its immutable built objects (:func:`mechverify.design.reuse.reused_object`). ``changed``: the
    key paths whose values differ from ``base``'s data (the variant's overrides; every other value is the base's),
    or None when unknown.
    """
    col = _Collector()
    if base is not None and path and base.path == path and base.files:  # (a variant: resolved once, by its base)
        files = [base.files[0]]
    else:
        files = [path.resolve()] if path else []
    doc = _merge_includes(doc, path, col, allow_outside, files)
    col.unknown_keys(doc, TOP_KEYS, "")
    design = doc.get("design", {})
    if not isinstance(design, dict):
        col.add("design", "expected a table")
        design = {}
    col.unknown_keys(design, DESIGN_KEYS, "design")
    trace = Trace()
    params = resolve_parameters(doc.get("parameters"), col.add, trace)
    pctx: dict[str, Any] = {"parameters": params, "trace": trace}
    name = design.get("name")
    if name is None or (isinstance(name, str) and not name.strip()):
        col.add("design.name", "missing: the design's name (a string)")
    elif not isinstance(name, str):
        col.add("design.name", f"expected a string, got {_describe(name)}; write it in quotes")
    revision = design.get("revision", "")
    if not isinstance(revision, str | int):
        col.add("design.revision", f"expected a string, got {_describe(revision)}")
    req_raw = doc.get("requirements", {})
    if not isinstance(req_raw, dict):
        col.add("requirements", "expected a table")
        req_raw = {}
    requirements = _validate_fields(REQUIREMENT_FIELDS, req_raw, "requirements", col, pctx)
    for k in ("g", "bearing_life", "deflection_limit"):
        m = getattr(requirements.get(k), "magnitude", requirements.get(k))
        if isinstance(m, int | float) and not m > 0:
            col.add(f"requirements.{k}", f"must be positive, got {_describe(req_raw.get(k, m))}")
            requirements.pop(k)
    sfs = dict(DEFAULT_SAFETY_FACTORS)
    for k, v in (requirements.pop("safety_factors", None) or {}).items():
        p = f"requirements.safety_factors.{k}"
        if k not in DEFAULT_SAFETY_FACTORS:
            hint = suggest(k, DEFAULT_SAFETY_FACTORS, 1)
            col.add(p, "unknown check class" + (f"; did you mean {hint[0]!r}?" if hint else ""))
        elif isinstance(v, bool) or not isinstance(v, int | float) or not 0 < v < math.inf:
            col.add(p, f"expected a positive finite number, got {_describe(v)}")
        else:
            sfs[k] = float(v)
    materials = _materials(doc, col, pctx)
    templates = doc.get("templates", {}) if isinstance(doc.get("templates", {}), dict) else {}
    ctx: dict[str, Any] = {"materials": materials, "requirements": requirements, **pctx,
                           "profiles": doc.get("profiles", {}) if isinstance(doc.get("profiles"), dict) else {},
                           "path": path}  # the design file (adapters resolve relative file names against it)
    if base is not None:
        ctx.update(reuse_context(base, doc, requirements, materials, path, params, changed))
    profiles = _typed_section(doc, "profiles", col, ctx, templates)
    ctx["profiles"] = profiles
    _build(profiles, "profiles", col, ctx)
    ctx["profile_objects"] = {k: e.obj for k, e in profiles.items()}
    comp_table = doc.get("components", {})
    ctx["component_names"] = set(comp_table) if isinstance(comp_table, dict) else set()
    components = _typed_section(doc, "components", col, ctx, templates)
    ctx["components"] = components
    load_cases, docs = _load_cases(doc, components, col, ctx)
    _build(components, "components", col, ctx)
    resolve_load_cases(load_cases, components, params, col.add, trace)
    if col.errors:
        raise DesignFileError(col.errors, str(path) if path else "")
    data = DesignData(path, files, name, str(revision), str(design.get("description", "")), requirements, sfs,
                      materials, profiles, components, load_cases, docs, doc, params, trace)
    data.__dict__["_validated"] = ctx.get("_validated", {})  # for the variants of this design (design/reuse.py)
    return data


def _load_cases(doc: dict[str, Any], components: dict[str, Entry], col: _Collector,
                ctx: dict[str, Any]) -> tuple[dict[str, dict[str, dict[str, Any]]], dict[str, str]]:
    out: dict[str, dict[str, dict[str, Any]]] = {}
    docs: dict[str, str] = {}
    table = doc.get("load_cases", {})
    if not isinstance(table, dict):
        col.add("load_cases", "expected a table of load cases")
        return out, docs
    for case, body in table.items():
        path = f"load_cases.{case}"
        if not isinstance(body, dict):
            col.add(path, "expected a table")
            continue
        docs[case] = str(body.get("description", ""))
        out[case] = {}
        for comp, loads in body.items():
            if comp == "description":
                continue
            if comp not in components:
                hint = suggest(comp, components, 1)
                col.add(f"{path}.{comp}", "no such component" + (f"; did you mean {hint[0]!r}?" if hint else ""))
                continue
            if not isinstance(loads, dict):
                col.add(f"{path}.{comp}", "expected a table of loads")
                continue
            out[case][comp] = validate_reusing(components[comp].type.loads, loads, f"{path}.{comp}", col, ctx)
    return out, docs


def load_file(path: str | Path, allow_outside: bool = False) -> DesignData:
    """Read and validate one design file."""
    p = Path(path)
    col = _Collector()
    doc = _read_toml(p, col, str(p))
    if col.errors:
        raise DesignFileError(col.errors)
    return parse(doc, p, allow_outside)
