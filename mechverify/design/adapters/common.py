"""Helpers shared by the adapters."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any


def pick(params: Mapping[str, Any], *names: str, **renames: str) -> dict[str, Any]:
    """Keyword arguments from validated params: ``names`` as they are, ``renames`` as kwarg=param."""
    out = {n: params[n] for n in names if n in params}
    out.update({k: params[v] for k, v in renames.items() if v in params})
    return out
