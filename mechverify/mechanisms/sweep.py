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


@dataclass(frozen=True, eq=False)
class LinearSweep:
    """A sweep whose loads are ``L0 + s L1`` for a scalar ``s`` (a payload weight): two sweeps combined.

    The planar statics are linear in the loads, so at every pose each actuator effort and each member's
    diagrams (``N``, ``V``, ``M`` at the same stations) under ``L0 + s L1`` are ``X0 + s X1``, ``X0`` from the
    sweep under ``L0`` (the self-weight) and ``X1`` from the sweep under ``L1`` alone (a unit payload,
    massless). :meth:`member_demands` and :meth:`actuator_demands` take the governing values at any ``s`` from
    these arrays (maxima over stations, then poses, as :class:`SweepResult` does): the numbers a sweep solved
    at ``s`` gives, to round-off (``tests/test_lever_arm_sweep.py``), without solving again. Arrays are SI.
    """

    labels: tuple[str, ...]
    lengths: dict[str, float]  # member -> length [m]
    N: dict[str, tuple[np.ndarray, np.ndarray]]  # member -> (X0, X1), each (poses, stations)
    V: dict[str, tuple[np.ndarray, np.ndarray]]
    M: dict[str, tuple[np.ndarray, np.ndarray]]
    efforts: dict[str, tuple[np.ndarray, np.ndarray, str]]  # actuator -> (X0, X1, "torque" | "force"), (poses,)
    # (a governing pose is the first of the poses within 1e-9 of the peak: mirrored poses tie)

    def member_demands(self, s: float) -> dict[str, MemberDemand]:
        """Governing tension, compression, |moment| and |shear| of every member at ``s``, with their poses."""
        out: dict[str, MemberDemand] = {}
        for key in self.N:
            N = self.N[key][0] + s * self.N[key][1]
            per = {"t": np.maximum(N.max(axis=1), 0.0), "c": np.maximum(-N.min(axis=1), 0.0),
                   "m": np.abs(self.M[key][0] + s * self.M[key][1]).max(axis=1),
                   "v": np.abs(self.V[key][0] + s * self.V[key][1]).max(axis=1)}
            k = {n: _first_peak(v) for n, v in per.items()}
            out[key] = MemberDemand(
                member=key, length=Quantity(self.lengths[key], "m"),
                tension=Quantity(float(per["t"][k["t"]]), "N"), tension_pose=self.labels[k["t"]],
                compression=Quantity(float(per["c"][k["c"]]), "N"), compression_pose=self.labels[k["c"]],
                moment=Quantity(float(per["m"][k["m"]]), "N*m"), moment_pose=self.labels[k["m"]],
                shear=Quantity(float(per["v"][k["v"]]), "N"), shear_pose=self.labels[k["v"]])
        return out

    def actuator_demands(self, s: float) -> dict[str, ActuatorDemand]:
        """Peak |effort| of every actuator at ``s``, with its pose, its signed extremes and the series."""
        out: dict[str, ActuatorDemand] = {}
        for name, (x0, x1, dim) in self.efforts.items():
            unit = "N*m" if dim == "torque" else "N"
            vals = x0 + s * x1
            k = _first_peak(np.abs(vals))
            out[name] = ActuatorDemand(
                actuator=name, peak=Quantity(float(abs(vals[k])), unit), peak_pose=self.labels[k],
                maximum=Quantity(float(vals.max()), unit), minimum=Quantity(float(vals.min()), unit),
                series=Quantity(vals, unit), poses=self.labels)
        return out


def _first_peak(values: np.ndarray) -> int:
    """The first pose within 1e-9 (relative) of the largest value: poses that tie (the same peak at a mirrored
    pose) are told apart by round-off otherwise, so the governing pose's name would depend on it."""
    top = float(values.max())
    return int(np.argmax(values >= top - 1e-9 * abs(top)))


def linear_sweep(poses: Iterable[Any], build_base: Callable[[Any], Mechanism],
                 build_unit: Callable[[Any], Mechanism], label: Callable[[Any], str] | None = None) -> LinearSweep:
    """Solve the base loads (``build_base(pose)``: ``s = 0``) and the scaled loads alone (``build_unit(pose)``:
    the loads multiplied by ``s``, at ``s = 1``, nothing else) at every pose; see :class:`LinearSweep`.

    Raises:
        ModelError: a pose cannot be solved (named), or the two sweeps' members or stations differ.
    """
    poses = list(poses)
    base = sweep_statics(poses, build_base, label)
    unit = sweep_statics(poses, build_unit, label)
    first = base.solutions[0]
    N: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    V: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    M: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    lengths: dict[str, float] = {}
    for key, ml in first.member_loads.items():
        lengths[key] = float(ml.length.m_as("m"))
        for store, attr, unit_name in ((N, "N", "N"), (V, "V", "N"), (M, "M", "N*m")):
            arrays = []
            for res in (base, unit):
                rows = []
                for s in res.solutions:
                    if key not in s.member_loads:
                        raise ModelError(f"linear_sweep: member {key!r} is missing from {s.mechanism}")
                    rows.append(np.asarray(getattr(s.member_loads[key], attr).m_as(unit_name), dtype=float))
                if len({r.shape for r in rows}) != 1:
                    raise ModelError(f"linear_sweep: member {key!r} has different stations at different poses")
                arrays.append(np.vstack(rows))
            if arrays[0].shape != arrays[1].shape:
                raise ModelError(f"linear_sweep: member {key!r} has different stations in the two sweeps")
            store[key] = (arrays[0], arrays[1])
    efforts: dict[str, tuple[np.ndarray, np.ndarray, str]] = {}
    for name, q in first.actuator_efforts.items():
        dim = "torque" if q.check("[length] * [force]") else "force"
        unit_name = "N*m" if dim == "torque" else "N"
        efforts[name] = (np.array([float(s.actuator_efforts[name].m_as(unit_name)) for s in base.solutions]),
                         np.array([float(s.actuator_efforts[name].m_as(unit_name)) for s in unit.solutions]), dim)
    return LinearSweep(base.labels, lengths, N, V, M, efforts)
