"""Helpers shared by the adapters."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from mechverify.errors import InputError, MechverifyError, suggest
from mechverify.units import Q, as_quantity


def pick(params: Mapping[str, Any], *names: str, **renames: str) -> dict[str, Any]:
    """Keyword arguments from validated params: ``names`` as they are, ``renames`` as kwarg=param."""
    out = {n: params[n] for n in names if n in params}
    out.update({k: params[v] for k, v in renames.items() if v in params})
    return out


def inline_table(v: Any, path: str, keys: tuple[str, ...], required: tuple[str, ...] = ()) -> dict[str, Any]:
    """Check an inline table of a design file (unknown keys with a suggestion, missing required keys)."""
    if not isinstance(v, dict):
        raise InputError(f"{path}: expected a table, got {v!r}")
    for k in v:
        if k not in keys:
            hint = suggest(k, keys, 1)
            raise InputError(f"{path}.{k}: unknown key" + (f"; did you mean {hint[0]!r}?" if hint else
                                                           f" (allowed: {', '.join(keys)})"))
    for k in required:
        if k not in v:
            raise InputError(f"{path}.{k}: missing")
    return v


def _number_or_length(s: str, unit: str, path: str) -> Any:
    s = s.strip()
    try:
        return Q(float(s), unit)
    except ValueError:
        return as_quantity(s, "length", path)


def parse_point(v: Any, unit: str, path: str) -> tuple[Any, Any]:
    """``"x, y"`` (numbers in ``unit``, or lengths with units) -> two length quantities."""
    if not isinstance(v, str):
        raise InputError(f"{path}: expected a point as a string \"x, y\" (in {unit}), got {v!r}")
    parts = v.split(",")
    if len(parts) != 2 or not all(p.strip() for p in parts):
        raise InputError(f"{path}: expected a point \"x, y\" (two numbers in {unit}, or two lengths), got {v!r}")
    try:
        return (_number_or_length(parts[0], unit, f"{path}.x"), _number_or_length(parts[1], unit, f"{path}.y"))
    except MechverifyError as exc:
        raise InputError(f"{path}: {str(exc).split(': ', 1)[-1]} in {v!r}") from None
