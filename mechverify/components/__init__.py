"""Components: unit-aware dataclasses and the closed-form formulas of each domain.

Import from the domain modules: ``components.threads``, ``power_screw``, ``springs``, ``bearings``,
``motors``, ``gearheads``, ``transmissions``, ``columns``, ``sections``, ``links``, ``plates``.
The most used names are re-exported here, each imported when first used (``components.Plate``
imports shapely only then).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from mechverify.components.bearings import BallBearing, PlainBushing, bearing
    from mechverify.components.gearheads import Gearhead, gearhead
    from mechverify.components.links import Link, Lug
    from mechverify.components.motors import DCMotor, GearMotor, HobbyServo, StepperMotor, motor
    from mechverify.components.plates import Plate
    from mechverify.components.power_screw import LeadScrew, Nut
    from mechverify.components.sections import make_section
    from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring
    from mechverify.components.threads import thread

_EXPORTS = {
    "bearings": ("BallBearing", "PlainBushing", "bearing"),
    "gearheads": ("Gearhead", "gearhead"),
    "links": ("Link", "Lug"),
    "motors": ("DCMotor", "GearMotor", "HobbyServo", "StepperMotor", "motor"),
    "plates": ("Plate",),
    "power_screw": ("LeadScrew", "Nut"),
    "sections": ("make_section",),
    "springs": ("CompressionSpring", "ExtensionSpring", "TorsionSpring"),
    "threads": ("thread",),
}
_WHERE = {name: module for module, names in _EXPORTS.items() for name in names}


def __getattr__(name: str) -> Any:
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_WHERE})


__all__ = ["BallBearing", "PlainBushing", "bearing", "Gearhead", "gearhead", "Link", "Lug", "DCMotor", "GearMotor",
           "HobbyServo", "StepperMotor", "motor", "Plate", "LeadScrew", "Nut", "make_section", "CompressionSpring",
           "ExtensionSpring", "TorsionSpring", "thread"]
