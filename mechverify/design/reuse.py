"""Check results a variant of a design takes over from the design it was made from (issue 19).

``Design.with_overrides`` builds a variant (a study sample, a sizing step); usually one or a few values
change and most components see exactly the inputs they saw before. A component's checks depend on: its
type, its table as written (after templates) and its check settings, its validated field values (after
expressions and connections are resolved), its loads in every load case as written and as resolved, the
components it names (a drive's screw, transitively), the profiles it or its load cases name (as written and
resolved) and the components those profiles name (a ``joint_motion`` profile's ``mechanism``: a drive fed by an
arm depends on the arm; any identifier in a profile's strings that is a component's name counts, since profiles
are built when checked), the values of the parameters any of these tables names by a word of a string (an
adapter may evaluate an expression inside a table-kind field itself: a path's ``r = "r0 - ..."``), and the
design-wide tables (requirements and safety factors as resolved, the design's materials as built, templates and
any other table as written). :func:`fingerprints` reduces these to comparable
values; a component whose fingerprint equals the base design's reuses the base's results (the same objects: results
are frozen). A value that cannot be compared exactly (NaN, an object that is not a dataclass) compares
unequal, so its checks run again.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Mapping, MutableMapping
from typing import Any

import numpy as np

from mechverify.units import Quantity

#: Top-level tables compared per component (components, load cases, the profiles a component names), by their
#: resolved values (parameters, materials) or not read by checks (design); every other table is compared whole.
_PER_COMPONENT = ("components", "load_cases", "parameters", "design", "profiles", "materials")


def _canon(v: Any) -> Any:
    """A value reduced to plain, exactly comparable data (types kept: 1, 1.0 and True differ)."""
    t = type(v)
    if t is str or t is bool or t is int or t is float or v is None:
        return (t.__name__, v)
    if t is dict:  # (exact types first: the abstract isinstance checks below cost more than the reduction)
        return ("D", tuple((k, _canon(x)) for k, x in v.items()))
    if t is list or t is tuple:
        return ("L", tuple(_canon(x) for x in v))
    if isinstance(v, Quantity):
        return ("Q", _canon(v._magnitude), v._units)
    if isinstance(v, np.ndarray):
        return ("A", v.dtype.str, v.shape, v.tobytes())
    if isinstance(v, Mapping):
        return ("D", tuple((k, _canon(x)) for k, x in v.items()))
    if isinstance(v, list | tuple):
        return ("L", tuple(_canon(x) for x in v))
    if isinstance(v, frozenset | set):
        return ("S", frozenset(_canon(x) for x in v))
    if isinstance(v, np.generic):
        return ("G", v.dtype.str, v.tobytes())
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        frozen = v.__dataclass_params__.frozen  # type: ignore[attr-defined]
        hit = _FROZEN.get(id(v)) if frozen else None
        if hit is not None and hit[0] is v:
            return hit[1]
        out = ("C", t.__qualname__, tuple((f.name, _canon(getattr(v, f.name))) for f in dataclasses.fields(v)))
        if frozen:  # library materials are shared by every design of the process: reduced once
            if len(_FROZEN) >= 512:
                _FROZEN.clear()
            _FROZEN[id(v)] = (v, out)
        return out
    return ("?", object())  # equal to nothing: the checks run again


_FROZEN: dict[int, tuple[Any, Any]] = {}  # id -> (the frozen dataclass, its reduced value); holds the object


_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def _names(v: Any, known: Mapping[str, Any], out: set[str], words: bool = False) -> None:
    """The names of ``known`` that ``v`` holds as a whole string (a drive's ``screw = "lift_screw"``); with
    ``words``, also any identifier inside a string (``"arm.path_length"`` names ``arm``: conservative, a word that
    merely looks like a name makes a dependency, so its checks run again). Component tables need no ``words``:
    what an expression there reads is resolved into the values compared (``entry.params``, the resolved loads)."""
    t = type(v)
    if t is str:
        if v in known:
            out.add(v)
        if words:
            out.update(w for w in _words(v) if w in known)
    elif t is dict or t is list or t is tuple:
        for x in v.values() if t is dict else v:
            if type(x) in _SCALARS:
                if words and type(x) is str:
                    out.update(w for w in _words(x) if w in known)
                if type(x) is str and x in known:
                    out.add(x)
            else:
                _names(x, known, out, words)
    elif isinstance(v, str):
        _names(str(v), known, out, words)
    elif isinstance(v, Mapping):
        for x in v.values():
            _names(x, known, out, words)
    elif isinstance(v, list | tuple):
        for x in v:
            _names(x, known, out, words)


_SCALARS = frozenset({str, int, float, bool, type(None)})


@functools.lru_cache(maxsize=4096)
def _words(text: str) -> tuple[str, ...]:
    """The identifiers in ``text`` (found once per distinct string)."""
    return tuple(_WORD.findall(text))


def design_wide(data: Any) -> Any:
    """The design-wide part every component depends on: requirements and safety factors as resolved, the
    design's own materials as built (their values may be expressions over parameters), the other tables."""
    raw = data.raw if isinstance(data.raw, Mapping) else {}
    mats = raw.get("materials")
    own = []
    for name in mats if isinstance(mats, Mapping) else ():
        try:
            own.append((name, _canon(data.materials.get(name))))
        except Exception:  # (an invalid material never reaches a verify)
            own.append((name, ("?", object())))
    return (_canon({k: v for k, v in raw.items() if k not in _PER_COMPONENT}), _canon(mats), tuple(own),
            _canon(data.requirements), _canon(data.safety_factors))


def _profiles(tables: list[Any], data: Any, components: set[str] | None = None) -> tuple[Any, ...]:
    """The profiles named in ``tables`` (and in those profiles, transitively): as written and as resolved. The
    components those profiles name (a ``joint_motion`` profile's ``mechanism``) are added to ``components``."""
    found: set[str] = set()
    for t in tables:
        _names(t, data.profiles, found)
    out, seen = [], set()
    todo = sorted(found)
    while todo:
        n = todo.pop()
        if n in seen:
            continue
        seen.add(n)
        e = data.profiles[n]
        out.append((n, _canon(e.raw), _canon(e.params)))
        if components is not None:
            _names(e.raw, data.components, components, words=True)
            _names(e.raw, _parameters(data), components, words=True)  # (split off by fingerprints)
        more: set[str] = set()
        _names(e.raw, data.profiles, more)
        todo.extend(sorted(more - seen))
    return tuple(sorted(out, key=lambda x: x[0]))


def _parameters(data: Any) -> Mapping[str, Any]:
    p = getattr(data, "parameters", None)
    return p if isinstance(p, Mapping) else {}


def _cases_part(name: str, data: Any, raw_cases: Any) -> tuple[tuple[Any, ...], list[Any]]:
    """A component's loads in every load case that names it, as written and as resolved (part 4 of its own
    fingerprint), and the tables its dependencies are read from (its own table first)."""
    cases = []
    tables = [data.components[name].raw]
    for case, comps in data.load_cases.items():
        if name in comps:
            table = raw_cases.get(case, {}) if isinstance(raw_cases, Mapping) else {}
            written = table.get(name) if isinstance(table, Mapping) else None
            cases.append((case, _canon(written), _canon(comps[name])))
            tables.append(written)
    return tuple(cases), tables


def _refs_part(tables: list[Any], data: Any, params: Mapping[str, Any]) -> tuple[Any, Any, set[str]]:
    """Parts 5 and 6 of a component's own fingerprint (the profiles it names, the parameters its strings name, by
    value) and the components it names, directly or through those profiles (itself included)."""
    found: set[str] = set()
    profiles = _profiles(tables, data, found)
    for t in tables:
        _names(t, data.components, found)
    for t in tables:  # a parameter read by an expression inside a table-kind field (a path's "r0 - ..."): its
        _names(t, params, found, words=True)  # value, not only the text (conservative: any word that is one)
    used = tuple((n, _canon(params[n])) for n in sorted(n for n in found if n in params))
    return profiles, used, {n for n in found if n in data.components}


def _raw_cases(data: Any) -> Any:
    return data.raw.get("load_cases", {}) if isinstance(data.raw, Mapping) else {}


def fingerprints(data: Any) -> dict[str, Any]:
    """Component name -> the fingerprint of everything its checks read (see the module docstring): ``(own, closure)``,
    ``own`` = (type, table, check settings, validated fields, loads per case, profiles, named parameters), ``closure``
    = the own fingerprints of the components it names, transitively, by name."""
    raw_cases = _raw_cases(data)
    own: dict[str, Any] = {}
    refs: dict[str, set[str]] = {}
    params = _parameters(data)
    for name, entry in data.components.items():
        cases, tables = _cases_part(name, data, raw_cases)
        profiles, used, found = _refs_part(tables, data, params)
        own[name] = (entry.type.name, _canon(entry.raw), _canon(entry.checks), _canon(entry.params), cases, profiles,
                     used)
        found.discard(name)
        refs[name] = found
    out: dict[str, Any] = {}
    for name in data.components:
        seen = {name}
        todo = sorted(refs[name])
        closure = []
        while todo:
            n = todo.pop()
            if n in seen:
                continue
            seen.add(n)
            closure.append((n, own[n]))
            todo.extend(sorted(refs[n] - seen))
        out[name] = (own[name], tuple(sorted(closure, key=lambda x: x[0])))
    return out


def reusable(data: Any, theirs: Mapping[str, Any]) -> set[str]:
    """The components of ``data`` whose :func:`fingerprints` entry equals ``theirs[name]`` (a base design's), found
    without computing every fingerprint in full (a study sample changes most components: their loads or fields
    differ, and comparing those first decides them). The same equality, part by part: the type, the loads per case
    and the validated fields first (what a variant usually changes), then the table and check settings, then the
    profiles and parameters it names; for a component whose own parts all match, the components it names
    (transitively) must match too, and be the same set of names."""
    raw_cases = _raw_cases(data)
    params = _parameters(data)
    same: dict[str, bool] = {}
    refs: dict[str, set[str]] = {}

    def own_equal(name: str) -> bool:
        hit = same.get(name)
        if hit is not None:
            return hit
        entry, t = data.components.get(name), theirs.get(name)
        ok = entry is not None and t is not None
        if ok:
            was = t[0]
            cases, tables = _cases_part(name, data, raw_cases)
            ok = (was[0] == entry.type.name and was[4] == cases and was[3] == _canon(entry.params)
                  and was[1] == _canon(entry.raw) and was[2] == _canon(entry.checks))
            if ok:
                profiles, used, found = _refs_part(tables, data, params)
                ok = was[5] == profiles and was[6] == used
                found.discard(name)
                refs[name] = found
        same[name] = ok
        return ok

    out = set()
    for name in data.components:
        if name not in theirs or not own_equal(name):
            continue
        seen, todo, closure, ok = {name}, sorted(refs[name]), [], True
        while todo and ok:
            n = todo.pop()
            if n in seen:
                continue
            seen.add(n)
            closure.append(n)
            ok = own_equal(n)
            if ok:
                todo.extend(sorted(refs[n] - seen))
        if ok and sorted(closure) == [n for n, _ in theirs[name][1]]:
            out.add(name)
    return out


# ------------------------------------------------------------------------------------------ built objects
#
# A variant (``Design.with_overrides``) is parsed again, but an entry (component or profile) whose build inputs are
# unchanged takes the object the base design built, when that object is immutable: building a lead screw, a link or
# a profile repeats pint arithmetic a study sample does not need. Build inputs: the type, the table as written
# (after templates), the validated fields after expressions and connections are resolved (what the adapter gets),
# the values of the parameters its strings name (an adapter may evaluate a table's expression itself), the
# design-wide values an adapter reads from its context (requirements, the design's file path, its own materials as
# built) and the other entries it names (the same object in both designs, so a drive keeps a screw it was built
# with). Mutable objects are never shared: a frame or plate-FEA component caches solutions per load case, a drive
# memoises its demands; they are rebuilt (their check results are still reused by :func:`fingerprints`).


def shareable(obj: Any) -> bool:
    """True when ``obj`` is immutable all the way down, so two designs may hold the same object: a frozen dataclass
    whose fields (and derived values already cached on it) are numbers, strings, quantities with a scalar or
    read-only array magnitude, tuples or frozensets of such values, or frozen dataclasses of them. Materials are
    values (the library's are shared by every design of the process already). A dict, list, set, writeable array
    or any other object anywhere inside makes it not shareable (a memo, a cache per load case)."""
    hit = _SHAREABLE.get(id(obj))
    if hit is not None and hit[0] is obj:
        return hit[1]
    out = _immutable(obj, set())
    if len(_SHAREABLE) >= 512:
        _SHAREABLE.clear()
    _SHAREABLE[id(obj)] = (obj, out)
    return out


_SHAREABLE: dict[int, tuple[Any, bool]] = {}  # id -> (the object, shareable); holds the object


def _immutable(v: Any, seen: set[int]) -> bool:
    import enum

    from mechverify.materials import Material

    t = type(v)
    if v is None or t in (bool, int, float, complex, str, bytes) or isinstance(v, enum.Enum | Material):
        return True
    if id(v) in seen:
        return True
    seen.add(id(v))
    if isinstance(v, Quantity):
        return _immutable(v._magnitude, seen)
    if isinstance(v, np.ndarray):
        return not v.flags.writeable and v.dtype != object
    if isinstance(v, np.generic):
        return True
    if t is tuple or t is frozenset:
        return all(_immutable(x, seen) for x in v)
    if isinstance(v, Mapping) and not isinstance(v, MutableMapping) and t.__module__.startswith("mechverify."):
        return all(_immutable(k, seen) and _immutable(x, seen) for k, x in v.items())  # (a section's Dimensions)
    if t.__module__.startswith("shapely.") and _is_geometry(v):  # (immutable since shapely 2: a cached outline)
        return True
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        if not v.__dataclass_params__.frozen:  # type: ignore[attr-defined]
            return False
        fields = [getattr(v, f.name) for f in dataclasses.fields(v)]
        return all(_immutable(x, seen) for x in (*fields, *getattr(v, "__dict__", {}).values()))
    return False


def _is_geometry(v: Any) -> bool:
    from shapely.geometry.base import BaseGeometry

    return isinstance(v, BaseGeometry)


def _wide_key(raw: Any, requirements: Any, materials: Any, path: Any) -> Any:
    mats = raw.get("materials") if isinstance(raw, Mapping) else None
    own = []
    for name in mats if isinstance(mats, Mapping) else ():
        try:
            own.append((name, _canon(materials.get(name))))
        except Exception:  # an invalid material: its error is reported; nothing is reused
            own.append((name, ("?", object())))
    return (str(path), _canon(requirements), tuple(own))


def build_key(entry: Any, parameters: Mapping[str, Any]) -> Any:
    """What an entry's build reads besides the design-wide values and the entries it names (see above)."""
    words: set[str] = set()
    _names(entry.raw, parameters, words, words=True)
    return (entry.type.name, _canon(entry.raw), _canon(entry.params),
            tuple((n, _canon(parameters[n])) for n in sorted(words)))


def _named(entry: Any, names: Mapping[str, Any]) -> set[str]:
    out: set[str] = set()
    _names(entry.raw, names, out, words=True)
    out.discard(entry.name)
    return out


def reuse_context(base: Any, doc: Any, requirements: Any, materials: Any, path: Any, parameters: Any = None,
                  changed: Any = None) -> dict[str, Any]:
    """The parse context entries :func:`reused_object` and :func:`validated_before` read: the base design's data, the
    design-wide key, and (``changed``: the override key paths that made this variant from the base) the tables whose
    text the base shares (:func:`unchanged_table_key`)."""
    keys = base.__dict__.setdefault("_build_keys", {})
    if "" not in keys:
        keys[""] = _wide_key(base.raw, base.requirements, base.materials, base.path)
    same_names = parameters is not None and set(parameters) == set(_parameters(base))
    return {"reuse_base": base, "reuse_wide": _wide_key(doc, requirements, materials, path),
            "reuse_touched": None if changed is None else touched_tables(changed),
            "reuse_same_parameter_names": same_names}


def reused_object(entry: Any, section: str, ctx: Mapping[str, Any]) -> Any:
    """The object the base design built for ``entry`` (``ctx["reuse_base"]``, a ``DesignData``) when it may be
    shared (see above), else ``None`` (then the entry is built). Called after the entry's fields are resolved."""
    base = ctx.get("reuse_base")
    if base is None:
        return None
    old = getattr(base, section, {}).get(entry.name)
    if old is None or old.obj is None or old.type is not entry.type or not shareable(old.obj):
        return None
    keys = base.__dict__["_build_keys"]
    if ctx["reuse_wide"] != keys[""]:
        return None
    taken = f"{section}.{entry.name}" in ctx.get("_taken_tables", ())  # its text is the base's (validate_reusing)
    for kind, was in (("components", base.components), ("profiles", base.profiles)):
        now = ctx.get(kind) or {}
        if taken:  # (the names in the base's text, found once)
            named = keys.get(("named", kind, section, entry.name))
            if named is None:
                named = keys[("named", kind, section, entry.name)] = _named(old, was)
        else:
            named = _named(entry, was)
        for n in named:
            if getattr(now.get(n), "obj", None) is None or now[n].obj is not was[n].obj:
                return None  # (a component not built yet, as when a profile names one: built again)
    k = (section, entry.name)
    if k not in keys:
        keys[k] = build_key(old, _parameters(base))
    was = keys[k]
    params = ctx.get("parameters") or {}
    if taken:  # its text and validated values are the base's
        now = (*was[:3], tuple((n, _canon(params[n])) for n, _ in was[3]))  # (see validate_reusing)
    else:
        now = build_key(entry, params)
    return old.obj if now == was else None


# ------------------------------------------------------------------------------------------ validated tables
#
# Validating a table (reading its unit strings and expressions) repeats for every variant. A table's validated values
# depend on: the table (after templates), its type's fields, the values of the parameters its strings name, the
# names of the components and profiles (a name read as a connection or a reference), and the design-wide values
# (the design's own materials by name). When all are unchanged, a variant takes the base's values (containers copied,
# so a variant's connections resolved in place never reach the base) and records the derived values they traced.


def validation_key(table: Any, ctx: Mapping[str, Any]) -> Any:
    """What validating ``table`` reads from the design (see above)."""
    params = ctx.get("parameters") or {}
    words: set[str] = set()
    _names(table, params, words, words=True)
    names = (frozenset(ctx.get("component_names") or ()), tuple(ctx.get("profiles") or ()),
             tuple(ctx.get("components") or ()))
    return (_canon(table), tuple((n, _canon(params[n])) for n in sorted(words)), names)


def touched_tables(keys: Any) -> frozenset[str] | None:
    """The tables whose text a variant's override key paths change: ``components.NAME``, ``profiles.NAME``,
    ``load_cases.CASE.COMPONENT``; ``parameters.*`` change none (their values are compared where they are read).
    None when an override may change any table: templates, the design-wide tables, a whole section or load case."""
    out = set()
    for key in keys:
        parts = _KEY_PARTS.findall(key)
        head = parts[0] if parts else ""
        if head == "parameters" and len(parts) >= 2:
            continue
        depth = {"components": 2, "profiles": 2, "load_cases": 3}.get(head)
        if depth is None or len(parts) < depth:
            return None
        out.add(".".join(parts[:depth]))
    return frozenset(out)


_KEY_PARTS = re.compile(r"[^.\[\]]+")


def unchanged_table_key(path: str, ctx: Mapping[str, Any]) -> Any:
    """:func:`validation_key` of the table at ``path`` when its text is the base design's (no override touched it:
    :func:`touched_tables`, and the parameters have the same names): the base's key with the values of its parameters
    and the names as they are now, without reducing the table again; None otherwise."""
    touched = ctx.get("reuse_touched")
    base = ctx.get("reuse_base")
    if base is None or touched is None or path in touched or not ctx.get("reuse_same_parameter_names"):
        return None
    hit = base.__dict__.get("_validated", {}).get(path)
    if hit is None:
        return None
    params = ctx.get("parameters") or {}
    names = (frozenset(ctx.get("component_names") or ()), tuple(ctx.get("profiles") or ()),
             tuple(ctx.get("components") or ()))
    return (hit[1][0], tuple((n, _canon(params[n])) for n, _ in hit[1][1]), names)


def remember_validated(path: str, fields: Any, key: Any, ctx: dict[str, Any], values: Mapping[str, Any],
                       traced: tuple[Any, ...]) -> None:
    """Keep the validated ``values`` of the table at ``path`` for this design's variants."""
    ctx.setdefault("_validated", {})[path] = (fields, key, _detach(values), traced)


def validated_before(path: str, fields: Any, key: Any, ctx: dict[str, Any]) -> tuple[dict[str, Any], Any] | None:
    """``(values, traced)`` the base design validated for the table at ``path`` with the same fields and
    :func:`validation_key`, else ``None``. ``traced``: the ``Trace.add`` arguments of its derived values."""
    base = ctx.get("reuse_base")
    if base is None or ctx.get("reuse_wide") != base.__dict__.get("_build_keys", {}).get(""):
        return None
    hit = base.__dict__.get("_validated", {}).get(path)
    if hit is None or hit[0] is not fields or hit[1] != key:
        return None
    ctx.setdefault("_validated", {})[path] = hit  # (for this variant's own variants)
    return _detach(hit[2]), hit[3]


def field_reuse(path: str, fields: Any, key: Any, ctx: dict[str, Any]) -> Any:
    """For a table the base design validated with other inputs (:func:`validated_before` found no match): a function
    ``(field name, value) -> (validated value, traced) | None`` giving the base's validated value of one field whose
    text is the base's and whose named parameters have the base's values (the rest of the validation inputs - the
    fields, the names, the design-wide values - being the same), so only the fields that changed are read again;
    None when the base has nothing to offer."""
    base = ctx.get("reuse_base")
    if base is None or not ctx.get("reuse_same_parameter_names") or \
            ctx.get("reuse_wide") != base.__dict__.get("_build_keys", {}).get(""):
        return None
    hit = base.__dict__.get("_validated", {}).get(path)
    if hit is None or hit[0] is not fields or hit[1][2] != key[2] or hit[1][0][0] != "D" or key[0][0] != "D":
        return None
    per_field = base.__dict__.setdefault("_field_reuse", {})
    if per_field.get(path, (None,))[0] is not hit:  # field -> (its text reduced, the parameters it names, its traces)
        params_then = _parameters(base)
        info = {}
        for name, text in hit[1][0][1]:
            at = f"{path}.{name}"
            words: set[str] = set()
            _names(_plain(text), params_then, words, words=True)
            info[name] = (text, frozenset(words),
                          tuple(t for t in hit[3] if t[0] == at or t[0].startswith((at + ".", at + "["))))
        per_field[path] = (hit, info)
    info = per_field[path][1]
    changed = ctx.get("_changed_parameters")
    if changed is None:
        params, before = ctx.get("parameters") or {}, _parameters(base)
        changed = ctx["_changed_parameters"] = frozenset(n for n in params if _canon(params[n]) != _canon(before[n]))
    now = dict(key[0][1])
    values = hit[2]

    def same(name: str, value: Any) -> tuple[Any, tuple[Any, ...]] | None:
        was = info.get(name)
        if was is None or name not in values or was[0] != now.get(name) or was[1] & changed:
            return None
        return _detach(values[name]), was[2]

    return same


def _plain(c: Any) -> Any:
    """The value a :func:`_canon` reduction stands for, as far as :func:`_names` reads it (strings, tables, arrays)."""
    tag = c[0]
    if tag == "str":
        return c[1]
    if tag == "D":
        return {k: _plain(x) for k, x in c[1]}
    if tag == "L":
        return [_plain(x) for x in c[1]]
    return None


def _detach(v: Any) -> Any:
    """``v`` with its dicts and lists copied (the leaves, immutable values, shared)."""
    t = type(v)
    if t is dict:
        return {k: _detach(x) for k, x in v.items()}
    if t is list:
        return [_detach(x) for x in v]
    return v
