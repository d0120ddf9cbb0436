"""The check registry: one decorator makes a check function the single identity of a check.

A check's **name** is the one string by which everything refers to it: the design-file key under
``[components.<name>.checks]``, the ``check`` field of its :class:`~mechverify.checks.CheckResult`,
``mechverify explain <name>``, the report figure key (:func:`mechverify.reports.plots.plotter`) and
the JUnit test name. :func:`check` registers it with its title, safety-factor class, source,
explanation and formula in :data:`CHECKS`; names and aliases are unique across the package.

.. code-block:: python

    @check("screw_buckling", title="Screw buckling (Euler/Johnson)", sf_kind="buckling",
           source=ref("shigley10", "Secs. 4-11 to 4-13"), aliases=("lead_screw.buckling",),
           explain="One paragraph: what is compared with what, and where the formula comes from.")
    def check_screw_buckling(screw, *, required_sf=1.0, load_case=""): ...

Aliases are former names: ``"<component_type>.<key>"`` aliases are the old design-file keys of that
component type (still accepted, with a deprecation note in the result); a bare alias is a former
result name. The decorated function is returned unchanged (a plain function) with ``.check_def``.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from mechverify.errors import UnknownNameError
from mechverify.references import keys_in

#: The safety-factor classes a check may name, with their defaults (a design file's
#: ``[requirements.safety_factors]`` may set them).
DEFAULT_SAFETY_FACTORS: dict[str, float] = {
    "static": 2.0,
    "spring": 1.2,  # Shigley 10th ed. Sec. 10-7: springs are designed for n_s >= 1.2 at solid
    "buckling": 3.0,
    "fatigue": 1.5,
    "self_locking": 1.0,
    "motor": 1.5,
    "bearing": 1.0,
    "deflection": 1.0,
    "speed": 1.25,
    "limit": 1.0,  # hard limits that already contain their margin (guidelines, ratings with margin)
    "pressure": 1.0,
}
#: The class names.
SF_KINDS = tuple(DEFAULT_SAFETY_FACTORS)

_NAME = re.compile(r"^[a-z][a-z0-9_]*$")
_ALIAS = re.compile(r"^[a-z][a-z0-9_]*(\.[a-z][a-z0-9_]*)?$")


@dataclass(frozen=True)
class CheckDef:
    """What the registry knows about one check (see :func:`check`)."""

    name: str
    function: Callable[..., Any]
    title: str
    sf_kind: str = "static"
    source: str = ""
    #: the :mod:`mechverify.references` keys cited in ``source`` (found by the registry)
    source_keys: tuple[str, ...] = ()
    explain: str = ""
    aliases: tuple[str, ...] = ()
    formula: str = ""  # LaTeX of the governing formula, when one formula states the check

    @property
    def module(self) -> str:
        """The module that defines the check function (``mechverify.checks.<domain>``)."""
        return self.function.__module__

    def local_aliases(self, component_type: str) -> tuple[str, ...]:
        """Former design-file keys of this check under ``component_type`` (``"lead_screw.buckling"`` ->
        ``"buckling"`` for ``"lead_screw"``)."""
        prefix = component_type + "."
        return tuple(a[len(prefix):] for a in self.aliases if a.startswith(prefix))


#: Every registered check by name.
CHECKS: dict[str, CheckDef] = {}
_ALIASES: dict[str, str] = {}  # alias -> name


def _owner(name: str) -> CheckDef | None:
    if name in CHECKS:
        return CHECKS[name]
    if name in _ALIASES:
        return CHECKS[_ALIASES[name]]
    return None


def _same_function(a: Callable[..., Any], b: Callable[..., Any]) -> bool:
    """True when ``b`` is ``a`` redefined (a module reloaded), which may re-register its names."""
    return (a.__module__, a.__qualname__) == (b.__module__, b.__qualname__)


def register(d: CheckDef) -> CheckDef:
    """Add a :class:`CheckDef` to :data:`CHECKS` (what :func:`check` does); names must be unique."""
    if not _NAME.match(d.name):
        raise ValueError(f"check name {d.name!r}: use lower_snake_case (letters, digits, underscores)")
    if not d.title:
        raise ValueError(f"check {d.name!r}: a title is required")
    if d.sf_kind not in SF_KINDS:
        raise ValueError(f"check {d.name!r}: sf_kind {d.sf_kind!r} is not one of {', '.join(SF_KINDS)}")
    for a in d.aliases:
        if not _ALIAS.match(a) or a == d.name:
            raise ValueError(f"check {d.name!r}: bad alias {a!r}")
    for n in (d.name, *d.aliases):
        other = _owner(n)
        if other is not None and not _same_function(other.function, d.function):
            raise ValueError(f"check name {n!r} of {d.module}.{d.function.__qualname__} is already used by "
                             f"{other.module}.{other.function.__qualname__} (names are unique package-wide)")
    old = CHECKS.pop(d.name, None)
    if old is not None:
        for a in old.aliases:
            _ALIASES.pop(a, None)
    CHECKS[d.name] = d
    for a in d.aliases:
        _ALIASES[a] = d.name
    return d


def check(name: str, *, title: str, sf_kind: str = "static", source: str = "", explain: str = "",
          aliases: tuple[str, ...] = (), formula: str = "") -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register the decorated function as the check ``name`` (see the module docstring).

    Args:
        name: the check's one name (lower_snake_case, unique package-wide).
        title: a short human title ("Screw buckling (Euler/Johnson)").
        sf_kind: the safety-factor class the check uses by default (:data:`SF_KINDS`).
        source: the citation(s), built with :func:`mechverify.references.ref`.
        explain: one paragraph for ``mechverify explain``: what is compared with what, and why.
        aliases: former names (``"<component_type>.<old key>"`` or a former result name).
        formula: LaTeX of the governing formula (optional).

    Returns:
        A decorator returning the function itself, with the :class:`CheckDef` as ``.check_def``.

    Raises:
        ValueError: a malformed, duplicate or alias-clashing name, or an unknown ``sf_kind``.
    """

    def deco(fn: Callable[..., Any]) -> Callable[..., Any]:
        d = CheckDef(name=name, function=fn, title=title, sf_kind=sf_kind, source=source,
                     source_keys=tuple(keys_in(source)), explain=explain, aliases=tuple(aliases), formula=formula)
        register(d)
        fn.check_def = d  # type: ignore[attr-defined]
        return fn

    return deco


def load_all() -> None:
    """Import every module of :mod:`mechverify.checks` so that all checks are registered."""
    import importlib
    import pkgutil

    import mechverify.checks as pkg

    for m in pkgutil.iter_modules(pkg.__path__):
        if not m.name.startswith("_"):
            importlib.import_module(f"{pkg.__name__}.{m.name}")


def get_check(name: str) -> CheckDef:
    """The :class:`CheckDef` registered as ``name`` or with ``name`` as an alias.

    Raises:
        UnknownNameError: no check has that name or alias (with the closest names as suggestions).
    """
    d = _owner(name)
    if d is None:
        load_all()
        d = _owner(name)
    if d is None:
        raise UnknownNameError("check", name, [*CHECKS, *_ALIASES])
    return d


def is_alias(name: str) -> bool:
    """True when ``name`` is a former name (an alias), not a check's current name."""
    return name in _ALIASES and name not in CHECKS


def all_checks() -> Iterator[CheckDef]:
    """Every registered check, sorted by name (after importing all check modules)."""
    load_all()
    yield from (CHECKS[k] for k in sorted(CHECKS))


def deprecation_note(alias: str, name: str) -> str:
    """The note a result carries when the design file named its check by a former key."""
    return f"Deprecated check key {alias!r}: the check is now named {name!r}; rename the key in the design file."


def explain_text(name: str) -> str:
    """The ``mechverify explain <name>`` text of a check (name or alias), plain text.

    Raises:
        UnknownNameError: no check has that name or alias.
    """
    d = get_check(name)
    lines = [f"{d.name}: {d.title}"]
    if name != d.name:
        lines.append(f"  ({name!r} is a former name of this check)")
    lines.append(f"  safety-factor class: {d.sf_kind}")
    if d.explain:
        import textwrap

        lines += ["", textwrap.fill(" ".join(d.explain.split()), 96)]
    if d.formula:
        lines += ["", f"Formula: {d.formula}"]
    if d.source:
        lines += ["", f"Source: {d.source}"]
    if d.aliases:
        lines += ["", "Former names (still accepted): " + ", ".join(d.aliases)]
    lines += ["", f"Python: {d.module}.{d.function.__name__}"]
    return "\n".join(lines)


def checks_markdown() -> str:
    """The index of all registered checks as a Markdown table (kept in ``docs/design-files.md`` between
    ``<!-- checks:begin -->`` and ``<!-- checks:end -->``; a test compares it with the registry)."""
    rows = ["| check | title | class | former names | function |", "|---|---|---|---|---|"]
    for d in all_checks():
        former = ", ".join(f"`{a}`" for a in d.aliases) or "-"
        rows.append(f"| `{d.name}` | {d.title} | `{d.sf_kind}` | {former} | `{d.module}.{d.function.__name__}` |")
    return "\n".join(rows)
