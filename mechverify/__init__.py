"""mechverify: verify the mechanical design of small machines and robots.

Quantities come from one pint registry (:data:`mechverify.ureg`, :func:`mechverify.Q`); every check
returns a :class:`mechverify.checks.CheckResult`.

The documented entry points are attributes of this package, imported when first used (so that
``import mechverify`` and the command line start without numpy, pint or scipy):

- ``mechverify.load(path)`` - a design file (:func:`mechverify.design.load`);
- ``Q``, ``Quantity``, ``QuantityLike``, ``ureg`` - units (:mod:`mechverify.units`);
- ``materials``, ``components``, ``checks``, ``fea`` - the sub-packages;
- ``SolidModel``, ``PlaneModel``, ``Frame``, ``PlateModel`` - the FEA models;
- the errors (:mod:`mechverify.errors`, standard library only, imported at once).
"""

from __future__ import annotations

import importlib
import importlib.util
from typing import TYPE_CHECKING, Any

from mechverify.errors import (
    InputError,
    MechverifyError,
    ModelError,
    UnitError,
    UnknownNameError,
    ValidityError,
)

if TYPE_CHECKING:  # for editors and type checkers; at run time these come from __getattr__
    from mechverify import checks, components, design, fea, materials, units
    from mechverify.components.plates import PlateModel
    from mechverify.design import load
    from mechverify.fea.frame import Frame
    from mechverify.fea.plane import PlaneModel
    from mechverify.fea.solid import SolidModel
    from mechverify.units import Q, Quantity, QuantityLike, ureg

#: attribute -> (module, name in it, or None for the module itself)
class _PintWithoutExtras:
    """A one-shot import hook: ``import pint`` (the first, wherever in mechverify it happens) without the optional
    integrations mechverify never uses. pint imports dask (with jinja2, toolz ...) and babel when they are installed
    - the ``cluster`` extra installs dask -: 9 MB of resident memory and ~90 ms of start-up (task solve2 measured the
    46k-DOF plate at 5.13 -> 4.93 kB per unknown). They are hidden while pint's module runs (``sys.modules[name] =
    None`` makes pint's ``try: import dask`` fail as if absent) and un-hidden after, so a later ``import dask`` (the
    studies' Dask executor) works as usual; pint then does not treat dask arrays specially, which mechverify never
    asks of it. Nothing happens when pint was imported before mechverify."""

    HIDE = ("dask", "babel")

    def find_spec(self, name: str, path: Any = None, target: Any = None) -> Any:
        import sys

        if name != "pint":
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec("pint")
        loader = getattr(spec, "loader", None)
        run = getattr(loader, "exec_module", None)
        if run is None:
            return spec

        def exec_module(module: Any) -> None:
            hidden = [m for m in self.HIDE if m not in sys.modules]
            for m in hidden:
                sys.modules[m] = None  # type: ignore[assignment]
            try:
                run(module)
            finally:
                for m in hidden:
                    if m in sys.modules and sys.modules[m] is None:
                        del sys.modules[m]

        loader.exec_module = exec_module  # type: ignore[union-attr]  (this spec's loader instance only)
        return spec


def _install_pint_hook() -> None:
    import sys

    if "pint" not in sys.modules and not any(isinstance(f, _PintWithoutExtras) for f in sys.meta_path):
        sys.meta_path.insert(0, _PintWithoutExtras())


_install_pint_hook()

_LAZY: dict[str, tuple[str, str | None]] = {
    "Q": ("mechverify.units", "Q"),
    "Quantity": ("mechverify.units", "Quantity"),
    "QuantityLike": ("mechverify.units", "QuantityLike"),
    "ureg": ("mechverify.units", "ureg"),
    "load": ("mechverify.design", "load"),
    "SolidModel": ("mechverify.fea.solid", "SolidModel"),
    "PlaneModel": ("mechverify.fea.plane", "PlaneModel"),
    "Frame": ("mechverify.fea.frame", "Frame"),
    "PlateModel": ("mechverify.components.plates", "PlateModel"),
    **{m: (f"mechverify.{m}", None) for m in ("units", "materials", "components", "checks", "design", "fea",
                                               "mechanisms", "motion", "fatigue", "reports", "studies")},
}


def __getattr__(name: str) -> Any:
    if name == "__version__":
        value: Any = _version()
    elif name in _LAZY:
        module, attr = _LAZY[name]
        mod = importlib.import_module(module)
        value = mod if attr is None else getattr(mod, attr)
    elif not name.startswith("_") and importlib.util.find_spec(f"{__name__}.{name}") is not None:
        value = importlib.import_module(f"{__name__}.{name}")  # any other sub-package or module
    else:
        raise AttributeError(f"module 'mechverify' has no attribute {name!r}")
    globals()[name] = value  # once imported, a plain attribute
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY, "__version__"})


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("mechverify")
    except PackageNotFoundError:  # running from a source tree that is not installed
        return "0.0.0+source"


__all__ = ["Q", "Quantity", "QuantityLike", "ureg", "load", "units", "design", "materials", "components", "checks",
           "fea", "SolidModel", "PlaneModel", "Frame", "PlateModel", "MechverifyError", "UnitError", "InputError",
           "UnknownNameError", "ValidityError", "ModelError", "__version__"]
