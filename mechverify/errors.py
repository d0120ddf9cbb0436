"""The exception hierarchy: every error mechverify raises on purpose is a :class:`MechverifyError`.

A user-facing error always says *what* was wrong, *where* (parameter or key path) and *what was
expected*; the CLI prints the message and exits with status 2 instead of showing a traceback.
"""

from __future__ import annotations

import difflib
import sys
import warnings
from collections.abc import Callable, Iterable, Mapping
from typing import Any


class MechverifyError(Exception):
    """Base class of every error that mechverify raises deliberately."""


class UnitError(MechverifyError, TypeError):
    """A value has no unit, the wrong dimension, or is not a finite number."""


class InputError(MechverifyError, ValueError):
    """A value has the right dimension but is impossible (negative length, reversed range, ...)."""


class UnknownNameError(MechverifyError, KeyError):
    """A name (material, thread, bearing, motor, ...) is not in its catalogue."""

    def __init__(self, kind: str, name: str, known: Iterable[str]):
        self.kind, self.name = kind, name
        self.suggestions = suggest(name, known)
        hint = f"; did you mean {', '.join(repr(s) for s in self.suggestions)}?" if self.suggestions else ""
        super().__init__(f"unknown {kind} {name!r}{hint}")

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return str(self.args[0])


class ValidityError(MechverifyError, ValueError):
    """An input lies outside the validity range of the formula asked to evaluate it."""


class ModelError(MechverifyError, ValueError):
    """A model cannot be solved as stated (e.g. an FEA model that is not fully supported)."""


def suggest(name: str, known: Iterable[str], n: int = 3) -> list[str]:
    """The closest names to ``name`` among ``known`` (case-insensitive), best first."""
    known = list(known)
    lower = {k.lower(): k for k in known}
    hits = difflib.get_close_matches(name.lower(), list(lower), n=n, cutoff=0.5)
    contains = [k for k in known if name.lower() in k.lower() or k.lower() in name.lower()]
    out: list[str] = []
    for k in [lower[h] for h in hits] + contains:
        if k not in out:
            out.append(k)
    return out[:n]


def renamed(module: str, old_to_new: Mapping[str, str], stacklevel: int = 2) -> Callable[[str], Any]:
    """A module ``__getattr__`` that keeps renamed public names working as deprecated aliases.

    ``__getattr__ = renamed(__name__, {"PointLoad": "FramePointLoad"})`` in a module makes
    ``module.PointLoad`` (and ``from module import PointLoad``) return ``FramePointLoad`` with a
    :class:`DeprecationWarning` naming the new name. Unknown names raise :class:`AttributeError` as usual.
    ``stacklevel``: 3 when the returned function is called from the module's own ``__getattr__``.
    """

    def __getattr__(name: str) -> Any:
        if name in old_to_new:
            new = old_to_new[name]
            warnings.warn(f"{module}.{name} is deprecated; use {module}.{new}", DeprecationWarning,
                          stacklevel=stacklevel)
            return getattr(sys.modules[module], new)
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__


def install_hint(extra: str, package: str = "") -> str:
    """How to add the optional extra ``extra`` (what README.md's "Optional extras" documents): mechverify is not
    published on PyPI, so pip finds no ``mechverify[extra]`` there; from a clone the extra is installed
    with ``scripts/install.sh`` (the venv ``make`` creates with uv has no pip), or with pip in a venv made by pip.
    ``package``: the third-party package the extra brings, named as the alternative when given; ``extra`` empty:
    the base installation (a base dependency that is missing or broken).
    ``install_hint("mesh", "gmsh")``: "in the mechverify clone: scripts/install.sh -e '.[mesh]' (or pip install
    -e '.[mesh]' in a venv made with pip; or just pip install gmsh)".
    """
    alone = f"; or just pip install {package}" if package else ""
    target = f"'.[{extra}]'" if extra else "."
    return (f"in the mechverify clone: scripts/install.sh -e {target} "
            f"(or pip install -e {target} in a venv made with pip{alone})")
