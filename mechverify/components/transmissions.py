"""Transmission elements between a motor and its load: direct drive, belt/gear reductions, drums
and pulleys (rotary to linear), and lead screws (wrapping :mod:`mechverify.components.power_screw`).

Every element converts between its *input* (motor side) and *output* (load side):

* kinematics with the ratio ``r`` = input displacement per unit output displacement
  (rad/rad, or rad/m for rotary-to-linear): ω_in = r·v_out, α_in = r·a_out;
* inertia reflected with the square of the ratio: J_in = m_out / r² (or J_out / r²);
* effort (torque or force) with the ratio and the efficiency, in the direction power flows [1, 2]:

  - motoring (the drive pushes the load along its motion, F·v > 0): T_in = F_out / (r·η);
  - back-driven (the load pushes the drive, F·v < 0): T_in = F_out·η' / r, with η' the
    back-drive efficiency (≤ 0 for a self-locking screw: the motor must then still drive);
  - holding at rest: T_in = F_out·max(η', 0) / r (a self-locking element holds by itself).

  At rest with an acceleration commanded, the element is taken as motoring in the direction of
  the acceleration (breakaway).

References
----------
1. Oriental Motor, *Technical Reference: Motor Sizing Calculations*, "load torque by drive
   mechanism": T_L = F·P_B/(2π·η·i) for a ball screw, T_L = F·D/(2·η·i) for pulley, wire/belt
   and rack-and-pinion drives; load inertia J = m·(P_B/2π)² and J = m·(D/2)².
2. Budynas, R. G. & Nisbett, J. K., *Shigley's Mechanical Engineering Design*, 10th ed., 2015,
   §8-2 (power screws: raising/lowering torque, efficiency, self-locking).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, Protocol

import numpy as np
import pint

from mechverify.errors import InputError
from mechverify.frozen import set_fields
from mechverify.units import Q, QuantityLike, from_si, to_si

MOTORING, HOLDING = 1, 0


def effort_to_input(effort_out: Any, direction: Any, ratio: float, efficiency: float,
                    backdrive_efficiency: float) -> np.ndarray:
    """Input effort [N·m] for an output effort [N or N·m] with power-flow dependent efficiency.

    ``direction`` is +1/-1 (sense of motion, or of the commanded acceleration at rest) or 0
    (holding). See the module docstring for the three cases [1].
    """
    F = np.asarray(effort_out, float)
    d = np.asarray(direction, float)
    if d.shape != F.shape:
        d = np.broadcast_to(d, F.shape)
    motoring = (d != 0) & (F * d >= 0)
    backdriven = (d != 0) & (F * d < 0)
    out = np.where(motoring, F / (ratio * efficiency), 0.0)
    out = np.where(backdriven, F * backdrive_efficiency / ratio, out)
    return np.where(d == 0, F * max(backdrive_efficiency, 0.0) / ratio, out)


def _eta(value: Any, name: str, *, allow_negative: bool = False) -> float:
    v = to_si(value, "dimensionless", name)
    if isinstance(value, pint.Quantity) and str(value.units) == "percent":
        v = float(value.to("").magnitude)
    if allow_negative:
        if not -1 < v <= 1:
            raise InputError(f"{name}: must lie in (-1, 1], got {v:g}")
    elif not 0 < v <= 1:
        raise InputError(f"{name}: must lie in (0, 1] (give 0.9 or '90 %'), got {v:g}")
    return v


class Stage(Protocol):
    """What a drive train needs from an element (SI floats)."""

    name: str
    input_kind: str  # "angle"
    output_kind: str  # "angle" or "length"

    @property
    def ratio_si(self) -> float: ...

    @property
    def inertia_at_input_si(self) -> float: ...

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray: ...


@dataclass(frozen=True)
class _Reduction:
    """Shared behaviour: a fixed ratio with forward and back-drive efficiencies."""

    @cached_property
    def inertia_at_input_si(self) -> float:
        """The stage's inertia at its input [kg·m²] (0 without one; the stage is immutable: read once)."""
        return 0.0 if self.inertia is None else float(self.inertia.m_as("kg*m**2"))

    def _normalise_inertia(self) -> None:
        """``inertia`` (None or any inertia unit) as a quantity in SI, checked."""
        if self.inertia is not None:
            set_fields(self, inertia=from_si(to_si(self.inertia, "inertia", f"{self.name}.inertia"), "inertia"))

    def _normalise_efficiencies(self, *, negative_backdrive: bool = False) -> None:
        """``efficiency`` in (0, 1]; ``backdrive_efficiency`` defaults to it (may be negative: self-locking)."""
        eta = _eta(self.efficiency, f"{self.name}.efficiency")
        set_fields(self, efficiency=eta,
                   backdrive_efficiency=eta if self.backdrive_efficiency is None else
                   _eta(self.backdrive_efficiency, f"{self.name}.backdrive_efficiency",
                        allow_negative=negative_backdrive))

    def input_speed(self, output_speed: QuantityLike) -> pint.Quantity:
        """ω_in = r·v_out."""
        v = to_si(output_speed, "velocity" if self.output_kind == "length" else "angular_velocity", "output_speed")
        return from_si(self.ratio_si * v, "angular_velocity")

    def output_speed(self, input_speed: QuantityLike) -> pint.Quantity:
        w = to_si(input_speed, "angular_velocity", "input_speed")
        return from_si(w / self.ratio_si, "velocity" if self.output_kind == "length" else "angular_velocity")

    def reflected_inertia(self, load: QuantityLike) -> pint.Quantity:
        """Load mass (linear output) or inertia (rotary output) seen at the input: J = m/r² [1]."""
        dim = "mass" if self.output_kind == "length" else "inertia"
        return from_si(to_si(load, dim, "load") / self.ratio_si**2, "inertia")

    def input_torque(self, output_effort: QuantityLike, *, backdriven: bool = False) -> pint.Quantity:
        """Input torque for an output force/torque, motoring (default) or back-driven [1]."""
        dim = "force" if self.output_kind == "length" else "torque"
        F = to_si(output_effort, dim, "output_effort")
        d = -1.0 if backdriven else 1.0
        return from_si(float(self.input_effort_si(np.array([F]), np.array([d * (1 if F >= 0 else -1)]))[0]), "torque")

    def output_effort(self, input_torque: QuantityLike) -> pint.Quantity:
        """Force/torque delivered at the output for a motoring input torque: F = T·r·η."""
        T = to_si(input_torque, "torque", "input_torque")
        return from_si(T * self.ratio_si * self.efficiency_forward,
                       "force" if self.output_kind == "length" else "torque")


@dataclass(frozen=True)
class DirectDrive(_Reduction):
    """Motor coupled straight to the load (ratio 1, optionally a coupling's inertia and efficiency)."""

    name: str = "direct drive"
    efficiency: Any = 1.0
    inertia: Any = None  # coupling inertia
    input_kind: str = field(default="angle", init=False)
    output_kind: str = field(default="angle", init=False)

    def __post_init__(self) -> None:
        set_fields(self, efficiency=_eta(self.efficiency, f"{self.name}.efficiency"))
        self._normalise_inertia()

    ratio_si = property(lambda self: 1.0)
    efficiency_forward = property(lambda self: self.efficiency)

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray:
        return effort_to_input(effort_out, direction, 1.0, self.efficiency, self.efficiency)


@dataclass(frozen=True)
class BeltDrive(_Reduction):
    """A two-pulley belt (or spur-gear pair) reduction, rotary to rotary: r = d_driven / d_driver.

    Give pitch diameters or tooth counts. ``inertia`` is the pulleys' inertia already referred to
    the input (driver) shaft. ``backdrive_efficiency`` defaults to the forward efficiency.
    """

    driver: Any
    driven: Any
    efficiency: Any = 1.0
    backdrive_efficiency: Any = None
    inertia: Any = None
    name: str = "belt drive"
    input_kind: str = field(default="angle", init=False)
    output_kind: str = field(default="angle", init=False)

    def __post_init__(self) -> None:
        self.ratio_si  # noqa: B018 - checks the pulleys at construction
        self._normalise_efficiencies()
        self._normalise_inertia()

    @cached_property
    def ratio_si(self) -> float:
        """r = d_driven / d_driver [-] (pitch diameters or tooth counts)."""

        def size(v: QuantityLike, what: str) -> float:
            if isinstance(v, int | float) and not isinstance(v, bool):
                if v <= 0:
                    raise InputError(f"{self.name}.{what}: tooth count must be positive")
                return float(v)
            x = to_si(v, "length", f"{self.name}.{what}")
            if x <= 0:
                raise InputError(f"{self.name}.{what}: diameter must be positive")
            return x

        a, b = size(self.driver, "driver"), size(self.driven, "driven")
        if isinstance(self.driver, int | float) != isinstance(self.driven, int | float):
            raise InputError(f"{self.name}: give both pulleys as diameters or both as tooth counts")
        return b / a

    efficiency_forward = property(lambda self: self.efficiency)

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray:
        return effort_to_input(effort_out, direction, self.ratio_si, self.efficiency, self.backdrive_efficiency)


@dataclass(frozen=True)
class Drum(_Reduction):
    """Rotary to linear through a drum, pulley + belt, cable or rack-and-pinion: r = 2/D [1].

    ``diameter`` is the effective (pitch or cable-centre) diameter. ``inertia`` is the drum's
    (or pulleys') own inertia at the input shaft.
    """

    diameter: QuantityLike
    efficiency: Any = 1.0
    backdrive_efficiency: Any = None
    inertia: Any = None
    name: str = "drum"
    input_kind: str = field(default="angle", init=False)
    output_kind: str = field(default="length", init=False)

    def __post_init__(self) -> None:
        d = to_si(self.diameter, "length", f"{self.name}.diameter")
        if d <= 0:
            raise InputError(f"{self.name}.diameter: must be positive")
        set_fields(self, diameter=from_si(d, "length"))
        self._normalise_efficiencies()
        self._normalise_inertia()

    ratio_si = property(lambda self: 2.0 / float(self.diameter.magnitude))
    efficiency_forward = property(lambda self: self.efficiency)

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray:
        return effort_to_input(effort_out, direction, self.ratio_si, self.efficiency, self.backdrive_efficiency)


@dataclass(frozen=True)
class ScrewDrive(_Reduction):
    """A lead screw (or ball screw) driven at the screw, the nut carrying the load: r = 2π/l.

    Wraps a :class:`mechverify.components.power_screw.LeadScrew`: its raising and lowering
    torques at the friction coefficient ``mu`` give the forward efficiency η = F·l/(2π·T_raise)
    and the back-drive efficiency η' = −2π·T_lower/(F·l) (negative when self-locking) [2]. Both
    torques are proportional to the axial force, so they are evaluated once for a unit force.
    ``inertia`` is the screw shaft's (and coupling's) inertia; ``collar_mu``/``collar_diameter``
    add thrust-collar friction (passed to the screw's torque methods).
    """

    screw: Any
    mu: QuantityLike
    inertia: Any = None
    collar_mu: Any = 0.0
    collar_diameter: Any = None
    name: str = "lead screw"
    input_kind: str = field(default="angle", init=False)
    output_kind: str = field(default="length", init=False)

    def __post_init__(self) -> None:
        mu = to_si(self.mu, "dimensionless", f"{self.name}.mu")
        if not 0 <= mu < 1:
            raise InputError(f"{self.name}.mu: friction coefficient must lie in [0, 1), got {mu:g}")
        set_fields(self, mu=mu)
        self.efficiency_forward, self.backdrive_efficiency  # noqa: B018 - the screw's torques (and errors) now
        self._normalise_inertia()

    @cached_property
    def lead_si(self) -> float:
        """Lead l of the screw [m]."""
        return to_si(self.screw.lead, "length", f"{self.name}.screw.lead")

    @cached_property
    def ratio_si(self) -> float:
        """r = 2π/l [rad/m]."""
        return 2 * math.pi / self.lead_si

    def _unit_torque(self, which: str) -> float:
        """Raising or lowering torque [N·m] for a unit axial force at ``mu`` (collar friction included)."""
        fn = self.screw.raise_torque if which == "raise" else self.screw.lower_torque
        return to_si(fn(Q(1.0, "N"), self.mu, self.collar_mu, self.collar_diameter), "torque", f"{which}_torque")

    @cached_property
    def efficiency_forward(self) -> float:
        """η = F·l/(2π·T_raise) [-]."""
        return self.lead_si / (2 * math.pi * self._unit_torque("raise"))

    @cached_property
    def backdrive_efficiency(self) -> float:
        """η' = −2π·T_lower/(F·l) [-]; negative when the screw is self-locking."""
        return -2 * math.pi * self._unit_torque("lower") / self.lead_si

    @property
    def self_locking(self) -> bool:
        return self.backdrive_efficiency <= 0

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray:
        return effort_to_input(effort_out, direction, self.ratio_si, self.efficiency_forward,
                               self.backdrive_efficiency)


__all__ = ["Stage", "DirectDrive", "BeltDrive", "Drum", "ScrewDrive", "effort_to_input", "MOTORING", "HOLDING"]
