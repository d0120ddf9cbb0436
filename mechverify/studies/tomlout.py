"""Write a parsed design-file document (the dict ``tomllib`` returns) back as TOML text.

Only what design files hold: tables, arrays, strings, numbers, booleans (no dates). Tables become
``[a.b]`` sections; arrays and tables inside arrays are written inline. ``tomllib.loads(dumps(doc))
== doc`` for every such document (tested).
"""

from __future__ import annotations

import json
import math
import re
from typing import Any

from mechverify.errors import InputError

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: str) -> str:
    return k if _BARE.match(k) else json.dumps(k, ensure_ascii=False)


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }" if v else "{}"
    raise InputError(f"cannot write {type(v).__name__} {v!r} to TOML")


def dumps(doc: dict[str, Any]) -> str:
    """TOML text of ``doc``."""
    lines: list[str] = []

    def table(t: dict[str, Any], prefix: tuple[str, ...]) -> None:
        plain = [(k, v) for k, v in t.items() if not isinstance(v, dict)]
        subs = [(k, v) for k, v in t.items() if isinstance(v, dict)]
        if prefix and (plain or not subs):
            if lines:
                lines.append("")
            lines.append("[" + ".".join(_key(p) for p in prefix) + "]")
        for k, v in plain:
            lines.append(f"{_key(k)} = {_value(v)}")
        for k, v in subs:
            table(v, (*prefix, k))

    table(doc, ())
    return "\n".join(lines) + "\n"
