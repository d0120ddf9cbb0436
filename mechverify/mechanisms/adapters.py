"""Hand-offs from a pose sweep to the motor-fit checks (the link checks take MemberDemand fields directly).

:func:`rotary_load` turns an actuator's governing static torque into a
:class:`~mechverify.motion.drive_train.RotaryLoad` (constant external torque) so that a
:class:`~mechverify.motion.drive_train.DriveTrain` and a motion profile give the
:class:`~mechverify.motion.drive_train.TorqueDemand` that :mod:`mechverify.checks.motors` checks.
"""

from __future__ import annotations

from typing import Any

from mechverify.mechanisms.sweep import ActuatorDemand
from mechverify.motion.drive_train import RotaryLoad


def rotary_load(demand: ActuatorDemand, inertia: Any = "0 kg*m**2", name: str | None = None) -> RotaryLoad:
    """A rotary load whose constant external torque is the actuator's signed peak holding torque.

    The mechanism torque is the torque the motor must apply to its crank (counter-clockwise
    positive); ``RotaryLoad.external_torque`` is the torque the drive must supply along +x, so the
    sign carries over for a profile that turns the crank counter-clockwise. ``inertia`` is the
    mechanism inertia reflected to the crank (not computed here: the statics are quasi-static).
    """
    if demand.peak.dimensionality != demand.peak.to("N*m").dimensionality:
        raise TypeError(f"actuator {demand.actuator!r} is a force actuator; use a linear load")
    signed = demand.maximum if abs(demand.maximum) >= abs(demand.minimum) else demand.minimum
    return RotaryLoad(inertia=inertia, external_torque=signed.to("N*m"), name=name or demand.actuator)
