"""Helpers shared by the adapters."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from mechverify.errors import InputError, suggest


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
