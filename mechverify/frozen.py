"""One construction path for the package's frozen dataclasses (issue 16).

A component, load or result is a frozen dataclass, built the same way everywhere:

1. **Inputs are normalised once, at construction**, in ``__post_init__`` (or a custom ``__init__``):
   quantities and strings to SI floats or canonical quantities, names to objects (materials,
   threads), sequences to tuples. Invalid input raises its named error there, never later.
   :func:`set_fields` stores the normalised values. It accepts only the dataclass's own fields, so it
   cannot hang caches or hidden state on an instance; it is the only place in the package where a
   frozen instance is written (``tests/test_construction.py`` enforces both).
2. **Values derived from the fields** (a spring's SI values, a plate's region, a screw's material)
   are :func:`functools.cached_property`: computed on first use and kept in the instance
   ``__dict__`` (frozen, non-slots dataclasses allow it). They are not fields, so ``==``, ``hash`` and
   ``repr`` ignore them, ``pickle`` carries them with the instance (process pools, Dask) and
   ``dataclasses.replace`` computes them afresh for the new instance. When computing one also
   validates input, ``__post_init__`` reads it once so that the error is still raised at
   construction.
"""

from __future__ import annotations

from typing import Any


def set_fields(obj: Any, **values: Any) -> None:
    """Store normalised input values on the frozen dataclass ``obj`` under construction.

    Call it from ``__post_init__`` (or a custom ``__init__``) only, with field names only; a name
    that is not a field of ``obj`` raises :class:`TypeError` (a derived value is a
    ``functools.cached_property``, not a hidden attribute).
    """
    if not values.keys() <= obj.__dataclass_fields__.keys():
        name = next(iter(values.keys() - obj.__dataclass_fields__.keys()))
        raise TypeError(f"{type(obj).__name__}.{name} is not a dataclass field; derived values are "
                        "functools.cached_property (mechverify.frozen)")
    if hasattr(obj, "__dict__"):  # what the dataclass __init__ does, in one step
        obj.__dict__.update(values)
    else:  # a slots dataclass
        for name, value in values.items():
            object.__setattr__(obj, name, value)


__all__ = ["set_fields"]
