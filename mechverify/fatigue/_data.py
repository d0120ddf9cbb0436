"""Loading of the fatigue data files (``fatigue/data/*.toml``), once per process."""

from __future__ import annotations

import tomllib
from functools import cache
from importlib import resources
from typing import Any


@cache
def load(name: str) -> dict[str, Any]:
    """The parsed TOML file ``fatigue/data/<name>.toml``."""
    text = resources.files("mechverify.fatigue").joinpath("data", f"{name}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)
