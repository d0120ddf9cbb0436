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
import re
from collections.abc import Mapping
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
    if isinstance(v, str):
        if v in known:
            out.add(v)
        if words:
            out.update(w for w in _WORD.findall(v) if w in known)
    elif isinstance(v, Mapping):
        for x in v.values():
            _names(x, known, out, words)
    elif isinstance(v, list | tuple):
        for x in v:
            _names(x, known, out, words)


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


def fingerprints(data: Any) -> dict[str, Any]:
    """Component name -> the fingerprint of everything its checks read (see the module docstring)."""
    raw_cases = data.raw.get("load_cases", {}) if isinstance(data.raw, Mapping) else {}
    own: dict[str, Any] = {}
    refs: dict[str, set[str]] = {}
    params = _parameters(data)
    for name, entry in data.components.items():
        cases = []
        tables = [entry.raw]
        for case, comps in data.load_cases.items():
            if name in comps:
                table = raw_cases.get(case, {}) if isinstance(raw_cases, Mapping) else {}
                written = table.get(name) if isinstance(table, Mapping) else None
                cases.append((case, _canon(written), _canon(comps[name])))
                tables.append(written)
        found: set[str] = set()  # the components it names, directly or through the profiles it names
        own[name] = (entry.type.name, _canon(entry.raw), _canon(entry.checks), _canon(entry.params), tuple(cases),
                     _profiles(tables, data, found))
        for t in tables:
            _names(t, data.components, found)
        for t in tables:  # a parameter read by an expression inside a table-kind field (a path's "r0 - ..."): its
            _names(t, params, found, words=True)  # value, not only the text (conservative: any word that is one)
        used = sorted(n for n in found if n in params)
        own[name] += (tuple((n, _canon(params[n])) for n in used),)
        found = {n for n in found if n in data.components}
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
