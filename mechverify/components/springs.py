"""Helical springs: compression, extension and torsion springs and their formulas, in one namespace.

``from mechverify.components.springs import CompressionSpring, wahl_factor`` and so on; the code
lives in ``spring_formulas`` (shared formulas and data), ``springs_compression``,
``springs_extension`` and ``springs_torsion``.
"""

from mechverify.components.spring_formulas import *  # noqa: F403
from mechverify.components.spring_formulas import __all__ as _formulas
from mechverify.components.springs_compression import (
    CompressionSpring,
    EndType,
    SpringFatigue,
    SpringRigidities,
    en13906_min_gap_sum,
)
from mechverify.components.springs_extension import ExtensionSpring, hook_bending_factor, hook_torsion_factor
from mechverify.components.springs_torsion import TorsionSpring

__all__ = [*_formulas, "CompressionSpring", "EndType", "SpringFatigue", "SpringRigidities", "en13906_min_gap_sum",
           "ExtensionSpring", "hook_bending_factor", "hook_torsion_factor", "TorsionSpring"]
