"""Helpers shared by the command modules (standard library only at import time)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any


def add_allow_outside(p: argparse.ArgumentParser) -> None:
    p.add_argument("--allow-outside-includes", action=argparse.BooleanOptionalAction, default=False,
                   help="allow includes outside the design's folder (default: refused)")


def load_designs(paths: list[Path], allow_outside: bool) -> list[Any]:
    """Load (parse and validate, no checks yet) every design; all errors together as one exit-2 message."""
    from mechverify.cli import Invalid
    from mechverify.design import load
    from mechverify.errors import MechverifyError

    designs, errors = [], []
    for p in paths:
        try:
            designs.append(load(p, allow_outside=allow_outside))
        except MechverifyError as exc:
            errors.append(str(exc))
    for p, d in zip(paths, designs):
        if not d.data.components:  # loadable from Python (a library of profiles), but nothing to check
            errors.append(f"{p}: the design has no components, so there is nothing to verify; add a "
                          "[components.NAME] table (docs/design-files.md)")
    if errors:
        raise Invalid("\n".join(errors))
    return designs


def input_files(designs: list[Any], paths: list[Path]) -> list[Path]:
    """Every file a run reads: the design files given and their includes."""
    files = list(paths)
    for d in designs:
        files += list(getattr(d, "files", []) or [])
    return files


def write(path: Path, text: str) -> None:
    from mechverify.fileio import atomic_write

    atomic_write(path, text)
