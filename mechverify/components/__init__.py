"""Components: unit-aware dataclasses and the closed-form formulas of each domain.

Import from the domain modules: ``components.threads``, ``power_screw``, ``springs``, ``bearings``,
``motors``, ``gearheads``, ``transmissions``, ``columns``, ``sections``, ``links``, ``plates``.
The most used names are re-exported here.
"""

from mechverify.components.bearings import BallBearing, PlainBushing, bearing
from mechverify.components.gearheads import Gearhead, gearhead
from mechverify.components.links import Link, Lug
from mechverify.components.motors import DCMotor, GearMotor, HobbyServo, StepperMotor, motor
from mechverify.components.plates import Plate
from mechverify.components.power_screw import LeadScrew, Nut
from mechverify.components.sections import make_section
from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring
from mechverify.components.threads import thread

__all__ = ["BallBearing", "PlainBushing", "bearing", "Gearhead", "gearhead", "Link", "Lug", "DCMotor", "GearMotor",
           "HobbyServo", "StepperMotor", "motor", "Plate", "LeadScrew", "Nut", "make_section", "CompressionSpring",
           "ExtensionSpring", "TorsionSpring", "thread"]
