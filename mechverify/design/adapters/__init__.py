"""Component types a design file can declare, each adapting a component class and its checks.

Each adapter module declares its fields (what the TOML table holds), the loads it reads from load
cases, how to build the component, and the checks it runs (functions of :mod:`mechverify.checks`),
and registers its types in :data:`mechverify.design.spec.REGISTRY`. The modules of this package are
discovered (found with :mod:`pkgutil`; a new adapter module needs no entry anywhere); ``common`` and
the ``*_parsing`` helpers declare no type.

Importing every adapter imports every component, check and mechanism module of the package, which a
design that uses three types does not need (a third of a cold ``mechverify check``, issue 27). So the
registry imports an adapter when a design names one of its types, through :func:`index`: type name ->
(adapter module, section). The index is made by importing all adapters once and kept in
mechverify's cache folder under a key of the adapter files' names, sizes and modification times, so
an edited or added adapter makes a new index; without a cache folder every adapter is imported.
"""

from __future__ import annotations

import hashlib
import importlib
import json
import pkgutil
from pathlib import Path

_INDEX: dict[str, tuple[str, str]] | None = None


def modules() -> list[str]:
    """The adapter modules' full names, in name order."""
    return [f"{__name__}.{m}" for m in sorted(m.name for m in pkgutil.iter_modules(__path__))]


def load_all() -> None:
    """Import every adapter module (registering every built-in component type)."""
    for m in modules():
        importlib.import_module(m)


def _key() -> str:
    h = hashlib.sha1()
    for f in sorted(Path(__path__[0]).glob("*.py")):
        st = f.stat()
        h.update(f"{f.name}:{st.st_size}:{st.st_mtime_ns};".encode())
    return h.hexdigest()[:20]


def _build_index() -> dict[str, tuple[str, str]]:
    from mechverify.design.spec import REGISTRY

    load_all()
    return {name: (REGISTRY._module[name], ct.section) for name, ct in REGISTRY._types.items()
            if REGISTRY._module.get(name, "").startswith(f"{__name__}.")}


def index() -> dict[str, tuple[str, str]]:
    """Built-in component type name -> (adapter module, section), from the cache or by importing all."""
    global _INDEX
    if _INDEX is not None:
        return _INDEX
    from mechverify.units import cache_folder

    folder = cache_folder("adapters")
    path = folder / f"index-{_key()}.json" if folder is not None else None
    if path is not None and path.is_file():
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            _INDEX = {k: (str(v[0]), str(v[1])) for k, v in data.items()}
            return _INDEX
        except (OSError, ValueError, TypeError, IndexError):
            pass  # a damaged cache file: make it again
    _INDEX = _build_index()
    if path is not None:
        try:
            tmp = path.with_suffix(f".tmp{id(_INDEX)}")
            tmp.write_text(json.dumps(_INDEX, sort_keys=True), encoding="utf-8")
            tmp.replace(path)
        except OSError:
            pass
    return _INDEX


def forget_index() -> None:
    """Drop the in-process index (the cached file stays; tests use this)."""
    global _INDEX
    _INDEX = None
