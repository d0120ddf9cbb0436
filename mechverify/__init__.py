"""mechverify: verify the mechanical design of small machines and robots.

Quantities come from one pint registry (:data:`mechverify.ureg`, :func:`mechverify.Q`); every check
returns a :class:`mechverify.checks.CheckResult`.
"""

from importlib.metadata import PackageNotFoundError, version

from mechverify.errors import (
    InputError,
    MechverifyError,
    ModelError,
    UnitError,
    UnknownNameError,
    ValidityError,
)
from mechverify.units import Q, Quantity, ureg

try:
    __version__ = version("mechverify")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.0.0+source"

__all__ = ["Q", "Quantity", "ureg", "MechverifyError", "UnitError", "InputError", "UnknownNameError",
           "ValidityError", "ModelError", "__version__"]
