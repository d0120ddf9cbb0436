"""Write a parsed design-file document (the dict ``tomllib`` returns) back as TOML text.

Only what design files hold: tables, arrays, strings, numbers, booleans (no dates). Tables become
``[a.b]`` sections; arrays and tables inside arrays are written inline. ``tomllib.loads(dumps(doc))
== doc`` for every such document (tested). :func:`rewrite_values` instead changes single values in a
file's own text, keeping its comments and layout (``study --reproduce``).
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


_HEADER = re.compile(r"^\s*\[(?!\[)\s*([^\]]+?)\s*\]\s*(#.*)?$")
_ASSIGN = re.compile(r"^(\s*)([A-Za-z0-9_-]+|\"[^\"]*\")(\s*=\s*)(.*)$")


def _split_comment(rest: str) -> tuple[str, str] | None:
    """``value  # comment`` -> (value, '  # comment'); None when the value does not end on this line."""
    quote = None
    i = 0
    while i < len(rest):
        ch = rest[i]
        if quote:
            if ch == "\\" and quote == '"':
                i += 2
                continue
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            j = i
            while j > 0 and rest[j - 1] in " \t":
                j -= 1
            return rest[:j], rest[j:]
        i += 1
    return (None if quote else (rest.rstrip(), rest[len(rest.rstrip()):]))


def _header_path(text: str) -> tuple[str, ...] | None:
    parts = []
    for p in text.split("."):
        p = p.strip()
        if _BARE.match(p):
            parts.append(p)
        elif len(p) >= 2 and p[0] == p[-1] == '"':
            parts.append(json.loads(p))
        else:
            return None
    return tuple(parts)


def rewrite_values(text: str, values: dict[tuple[str, ...], Any]) -> str | None:
    """``text`` (a design file) with the value of each key (a table path plus the key, e.g.
    ``("parameters", "lifted_load")``) replaced on its own line, everything else (comments, layout, the
    line's own trailing comment) kept. None when a key is not written as ``key = value`` on one line
    of its table (a template's value, a default, an inline table, a value over several lines): the
    caller then writes the whole document with :func:`dumps`."""
    lines = text.splitlines(keepends=True)
    table: tuple[str, ...] = ()
    todo = dict(values)
    for n, line in enumerate(lines):
        body = line.rstrip("\r\n")
        m = _HEADER.match(body)
        if m:
            path = _header_path(m.group(1))
            if path is None:
                return None
            table = path
            continue
        m = _ASSIGN.match(body)
        if not m:
            continue
        key = json.loads(m.group(2)) if m.group(2).startswith('"') else m.group(2)
        target = (*table, key)
        if target not in todo:
            continue
        split = _split_comment(m.group(4))
        if split is None or not split[0]:
            return None
        new = _value(todo.pop(target))
        comment = split[1]
        if comment.strip():  # keep the comment's column where the new value leaves room
            gap = len(comment) - len(comment.lstrip())
            comment = " " * max(1, gap + len(split[0]) - len(new)) + comment.lstrip()
        lines[n] = f"{m.group(1)}{m.group(2)}{m.group(3)}{new}{comment}" + line[len(body):]
    if todo:
        return None
    return "".join(lines)
