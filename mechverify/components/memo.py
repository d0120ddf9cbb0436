"""Values a check or a formula derives from immutable inputs alone, computed once per set of input objects (issue 19).

A study sample re-runs every check with a few inputs changed; most of a check's work depends on the component
only (a screw's buckling load, a nut's engaged turns, the notes that name them), and a design variant takes over
unchanged immutable components (``mechverify/design/reuse.py``), so the same objects come back sample after
sample. :func:`once` keeps such values per (name, objects), holding the objects (their ids stay theirs while
the entry lives). Only for objects that never change after construction (frozen dataclasses of values); a value
computed from anything else (a load, a speed) must not go through it. The table is bounded (cleared when full).
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Any, TypeVar

T = TypeVar("T")

#: (name, id of each object) -> (the objects, the value)
_MEMO: dict[tuple[Any, ...], tuple[tuple[Any, ...], Any]] = {}
LIMIT = 2048


def once(name: Hashable, objs: tuple[Any, ...], make: Callable[[], T]) -> T:
    """``make()`` for the immutable ``objs``, computed on the first call and remembered (an error is not: the
    next call raises it again). ``name`` (a string, or a tuple of a string and the plain values, such as a speed,
    the value also depends on) tells apart the values of one set of objects."""
    if len(objs) == 1:  # the common case, without the generic comparison
        key: tuple[Any, ...] = (name, id(objs[0]))
        hit = _MEMO.get(key)
        if hit is not None and hit[0][0] is objs[0]:
            return hit[1]
    else:
        key = (name, *map(id, objs))
        hit = _MEMO.get(key)
        if hit is not None and all(a is b for a, b in zip(hit[0], objs, strict=True)):
            return hit[1]
    value = make()
    if len(_MEMO) >= LIMIT:
        _MEMO.clear()
    _MEMO[key] = (objs, value)
    return value


def clear() -> None:
    """Forget every value (tests)."""
    _MEMO.clear()


__all__ = ["once", "clear"]
