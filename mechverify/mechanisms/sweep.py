"""Pose sweeps: solve the statics over many poses and find the governing pose of every member and motor.

:func:`sweep_statics` takes poses and a function that builds the :class:`Mechanism` at a pose (the
presets' ``statics`` methods do this) and returns a :class:`SweepResult`. Its
:meth:`~SweepResult.member_demands` and :meth:`~SweepResult.actuator_demands` hand the governing
values out as plain data (quantities) for the link checks and the motor-fit checks:

* :class:`MemberDemand`: per member (body segment) the largest tension, compression, bending
  moment and shear over the sweep, each with the pose that governs it;
* :class:`ActuatorDemand`: per actuator the peak |torque| (or |force|) and its pose, with the
  signed extremes and the whole series.

A pose where the statics cannot be solved (a singular configuration) raises the solver's
:class:`~mechverify.errors.ModelError`, naming the pose, unless ``skip_singular=True``, which
records it in ``SweepResult.skipped`` instead.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, ModelError
from mechverify.mechanisms.statics import Mechanism, StaticsSolution
from mechverify.units import Quantity


@dataclass(frozen=True)
class MemberDemand:
    """Governing internal loads of one member over a sweep (magnitudes >= 0; tension-positive axial)."""

    member: str
    length: pint.Quantity
    tension: pint.Quantity
    tension_pose: str
    compression: pint.Quantity
    compression_pose: str
    moment: pint.Quantity
    moment_pose: str
    shear: pint.Quantity
    shear_pose: str

    @property
    def axial(self) -> pint.Quantity:
        """The axial force of largest magnitude, signed (tension +)."""
        return self.tension if self.tension >= self.compression else -self.compression


@dataclass(frozen=True)
class ActuatorDemand:
    """Torque (or force) demand of one actuator over a sweep."""

    actuator: str
    peak: pint.Quantity  # max |effort|
    peak_pose: str
    maximum: pint.Quantity  # signed extremes
    minimum: pint.Quantity
    series: pint.Quantity  # effort at every pose, in sweep order
    poses: tuple[str, ...]


@dataclass(frozen=True)
class SweepResult:
    """Solutions at every pose of a sweep (``labels[i]`` names pose ``i``)."""

    labels: tuple[str, ...]
    solutions: tuple[StaticsSolution, ...]
    skipped: tuple[tuple[str, str], ...] = field(default=())  # (pose label, reason)

    def member_demands(self) -> dict[str, MemberDemand]:
        """Governing tension, compression, moment and shear of every member, with their poses."""
        if not self.solutions:
            return {}
        out: dict[str, MemberDemand] = {}
        for key in self.solutions[0].member_loads:
            rows = [s.member_loads[key] for s in self.solutions]

            def arg(values: list[float]) -> int:
                return int(np.argmax(values))

            t = arg([r.tension.m_as("N") for r in rows])
            c = arg([r.compression.m_as("N") for r in rows])
            m = arg([r.moment.m_as("N*m") for r in rows])
            v = arg([r.shear.m_as("N") for r in rows])
            out[key] = MemberDemand(
                member=key, length=rows[0].length,
                tension=rows[t].tension, tension_pose=self.labels[t],
                compression=rows[c].compression, compression_pose=self.labels[c],
                moment=rows[m].moment, moment_pose=self.labels[m],
                shear=rows[v].shear, shear_pose=self.labels[v],
            )
        return out

    def actuator_demands(self) -> dict[str, ActuatorDemand]:
        """Peak |torque| (or |force|) of every actuator, with its pose and the whole series."""
        if not self.solutions:
            return {}
        out: dict[str, ActuatorDemand] = {}
        for name, first in self.solutions[0].actuator_efforts.items():
            unit = first.units
            vals = np.array([float(s.actuator_efforts[name].m_as(unit)) for s in self.solutions])
            k = int(np.argmax(np.abs(vals)))
            out[name] = ActuatorDemand(
                actuator=name, peak=Quantity(abs(vals[k]), unit), peak_pose=self.labels[k],
                maximum=Quantity(vals.max(), unit), minimum=Quantity(vals.min(), unit),
                series=Quantity(vals, unit), poses=self.labels,
            )
        return out


def sweep_statics(poses: Iterable[Any], build: Callable[[Any], Mechanism],
                  label: Callable[[Any], str] | None = None, skip_singular: bool = False) -> SweepResult:
    """Solve ``build(pose)`` at every pose. ``label(pose)`` names poses (default: the pose's
    ``label()`` method or ``str``)."""
    labels: list[str] = []
    sols: list[StaticsSolution] = []
    skipped: list[tuple[str, str]] = []
    for pose in poses:
        name = label(pose) if label else (pose.label() if hasattr(pose, "label") else str(pose))
        try:
            sol = build(pose).solve()
        except ModelError as exc:
            if not skip_singular:
                raise ModelError(f"pose {name}: {exc}") from None
            skipped.append((name, str(exc)))
            continue
        labels.append(name)
        sols.append(sol)
    if not sols:
        raise InputError("sweep_statics: no pose could be solved" + (f" ({len(skipped)} skipped as singular)"
                                                                     if skipped else " (no poses given)"))
    return SweepResult(tuple(labels), tuple(sols), tuple(skipped))
