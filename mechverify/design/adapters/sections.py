"""Cross-sections of a design file: the flat keys ``section`` (kind) and its dimensions, for ``link`` and ``frame``."""

from __future__ import annotations

import inspect
from typing import Any

from mechverify.components import sections
from mechverify.errors import InputError, MechverifyError

#: Section kinds a design file may name, with the constructor of :mod:`~mechverify.components.sections`.
SECTION_KINDS = tuple(k for k in sections.section_kinds() if k != "polygon")
SECTION_ALIASES = {"rect": "rectangle", "bar": "rectangle", "flat": "rectangle", "round": "circle", "rod": "circle",
                   "pipe": "tube", "chs": "tube", "rhs": "hollow_rectangle", "shs": "hollow_rectangle",
                   "box": "hollow_rectangle", "ipe": "i_section", "tee": "t_section", "angle": "l_section",
                   "channel": "c_section"}
SECTION_DIMENSIONS = ("width", "height", "diameter", "outer_diameter", "inner_diameter", "thickness",
                      "web_thickness", "flange_thickness", "root_radius", "outer_radius", "toe_radius")


def _section_parameters(kind: str) -> tuple[list[str], list[str]]:
    """(required, optional) dimension keys of a section constructor."""
    sig = inspect.signature(getattr(sections, kind))
    req = [n for n, p in sig.parameters.items() if p.default is inspect.Parameter.empty]
    opt = [n for n, p in sig.parameters.items() if p.default is not inspect.Parameter.empty]
    return req, opt


def build_section(p: dict[str, Any]) -> sections.Section:
    """The body section from the flat keys ``section`` (kind) and its dimensions."""
    kind = SECTION_ALIASES.get(p["section"], p["section"])
    req, opt = _section_parameters(kind)
    given = {k: p[k] for k in SECTION_DIMENSIONS if k in p}
    extra = [k for k in given if k not in req + opt]
    if extra:
        raise InputError(f"{extra[0]}: not a dimension of a {kind} section (it takes {', '.join(req + opt)})")
    if kind == "tube" and "thickness" not in given and "inner_diameter" not in given:
        raise InputError("thickness: missing; a tube needs outer_diameter and thickness (or inner_diameter)")
    missing = [k for k in req if k not in given]
    if missing:
        raise InputError(f"{missing[0]}: missing; a {kind} section needs {', '.join(req)}")
    return sections.make_section(kind, **given)


def why(exc: Exception, limit: Any) -> str:
    return str(exc).split(": ", 1)[-1] if isinstance(exc, MechverifyError) else f"got {limit!r}"
