"""Load models and drive trains: the torque and speed a motion profile asks of the motor shaft.

A load (linear: mass, incline, Coulomb and viscous friction, external force; rotary: inertia,
gravity unbalance, friction, external torque) is moved along a :mod:`~mechverify.motion.profiles`
profile through a chain of transmission stages (gearheads, belts, drums, screws). Walking the
chain from the load to the motor, each stage converts speed and acceleration with its ratio,
adds its own inertia, and converts effort with its efficiency in the direction power flows
(see :mod:`mechverify.components.transmissions`). The result, :class:`TorqueDemand`, holds the
motor torque and speed over time, their peak and RMS over the duty cycle, the torque at every
stage output, and the load inertia reflected to the motor.

Equations (per sample): F_load = m·a + m·g·sin θ + s·(F_c + μ·m·g·cos θ) + c·v + F_ext, with
s = sign of motion; T_in = f(F_out) + J_stage·α_in through each stage; T_motor = T_in + J_rotor·α_m.
RMS over the cycle t_c: T_rms = sqrt((1/t_c)·∫T² dt) [1, 2].

References
----------
1. Oriental Motor, *Technical Reference: Motor Sizing Calculations* (load torque, acceleration
   torque T_a = J·α, required torque T_M = (T_a + T_L)·S_f, effective (RMS) torque).
2. THK, *Ball Screw: Studying the Driving Motor* (effective torque
   T_rms = sqrt((T1²·t1 + T2²·t2 + T3²·t3)/t), inertia ratio J_L/J_M).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnitError
from mechverify.frozen import set_fields
from mechverify.motion.profiles import Profile, ProfileSamples, SampledProfile
from mechverify.units import Q, fmt, from_si, si_to, to_si

G0 = 9.80665  # standard gravity [m/s²]


def _q_opt(value: Any, dim: str, name: str, *, default: float = 0.0, signed: bool = False) -> float:
    if value is None:
        return default
    v = to_si(value, dim, name)
    if not signed and v < 0:
        raise InputError(f"{name}: must be zero or positive")
    return v


def _viscous(value: Any, unit: str, name: str) -> float:
    if value is None:
        return 0.0
    q = Q(value) if isinstance(value, str) else value
    if not isinstance(q, pint.Quantity) or q.dimensionality != Q(1, unit).dimensionality:
        raise UnitError(f"{name}: expected a viscous friction coefficient in units like {unit}, got {value!r}")
    v = float(q.to(unit).magnitude)
    if v < 0:
        raise InputError(f"{name}: must be zero or positive")
    return v


@dataclass(frozen=True)
class LinearLoad:
    """A translating load. ``incline`` is the angle of the axis above horizontal (90° = vertical,
    positive motion upward). Friction: ``friction_coefficient``·m·g·cos θ plus ``coulomb_friction``
    (always against the motion) and ``viscous_friction``·v [N·s/m]. ``external_force`` is a
    constant force against positive motion (cutting force, spring preload, cable tension)."""

    mass: Any
    incline: Any = "0 deg"
    friction_coefficient: float = 0.0
    coulomb_friction: Any = None
    viscous_friction: Any = None
    external_force: Any = None
    name: str = "load"
    kind: str = field(default="length", init=False)

    def __post_init__(self) -> None:
        self.si  # noqa: B018 - the inputs are checked at construction

    @cached_property
    def si(self) -> dict[str, float]:
        """The inputs in SI [kg, rad, N, N·s/m]: ``m``, ``theta``, ``mu``, ``Fc``, ``c``, ``Fe``; read it, do not
        change it."""
        m = to_si(self.mass, "mass", f"{self.name}.mass")
        if m < 0:
            raise InputError(f"{self.name}.mass: must be zero or positive")
        mu = to_si(self.friction_coefficient, "dimensionless", f"{self.name}.friction_coefficient")
        if mu < 0:
            raise InputError(f"{self.name}.friction_coefficient: must be zero or positive")
        return {
            "m": m, "theta": to_si(self.incline, "angle", f"{self.name}.incline"), "mu": mu,
            "Fc": _q_opt(self.coulomb_friction, "force", f"{self.name}.coulomb_friction"),
            "c": _viscous(self.viscous_friction, "N*s/m", f"{self.name}.viscous_friction"),
            "Fe": _q_opt(self.external_force, "force", f"{self.name}.external_force", signed=True)}

    @property
    def mass_or_inertia_si(self) -> float:
        return self.si["m"]

    def effort_si(self, x: np.ndarray, v: np.ndarray, a: np.ndarray, direction: np.ndarray) -> np.ndarray:
        """Force [N] the drive must apply to the load along +x."""
        p = self.si
        friction = p["Fc"] + p["mu"] * p["m"] * G0 * math.cos(p["theta"])
        return (p["m"] * a + p["m"] * G0 * math.sin(p["theta"]) + direction * friction + p["c"] * v + p["Fe"])


@dataclass(frozen=True)
class RotaryLoad:
    """A rotating load: ``inertia`` about its axis; gravity torque ``gravity_torque``·cos(x + ``gravity_phase``)
    (``gravity_torque`` = m·g·r of the unbalance, x the profile angle, phase 0 = arm horizontal at x = 0);
    ``coulomb_friction`` (torque against the motion), ``viscous_friction`` [N·m·s/rad], constant
    ``external_torque`` against positive motion."""

    inertia: Any
    gravity_torque: Any = None
    gravity_phase: Any = "0 deg"
    coulomb_friction: Any = None
    viscous_friction: Any = None
    external_torque: Any = None
    name: str = "load"
    kind: str = field(default="angle", init=False)

    def __post_init__(self) -> None:
        self.si  # noqa: B018 - the inputs are checked at construction

    @cached_property
    def si(self) -> dict[str, float]:
        """The inputs in SI [kg·m², N·m, rad, N·m·s/rad]: ``J``, ``Tg``, ``phase``, ``Tc``, ``c``, ``Te``; read it,
        do not change it."""
        J = to_si(self.inertia, "inertia", f"{self.name}.inertia")
        if J < 0:
            raise InputError(f"{self.name}.inertia: must be zero or positive")
        return {
            "J": J, "Tg": _q_opt(self.gravity_torque, "torque", f"{self.name}.gravity_torque"),
            "phase": to_si(self.gravity_phase, "angle", f"{self.name}.gravity_phase"),
            "Tc": _q_opt(self.coulomb_friction, "torque", f"{self.name}.coulomb_friction"),
            "c": _viscous(self.viscous_friction, "N*m*s/rad", f"{self.name}.viscous_friction"),
            "Te": _q_opt(self.external_torque, "torque", f"{self.name}.external_torque", signed=True)}

    @property
    def mass_or_inertia_si(self) -> float:
        return self.si["J"]

    def effort_si(self, x: np.ndarray, v: np.ndarray, a: np.ndarray, direction: np.ndarray) -> np.ndarray:
        """Torque [N·m] the drive must apply to the load along +x."""
        p = self.si
        return (p["J"] * a + p["Tg"] * np.cos(x + p["phase"]) + direction * p["Tc"] + p["c"] * v + p["Te"])


Load = LinearLoad | RotaryLoad


@dataclass(frozen=True)
class StageDemand:
    """What one stage sees over time: output effort [N or N·m] and input speed [rad/s] (SI arrays)."""

    name: str
    stage: Any
    output_effort: np.ndarray
    input_speed: np.ndarray
    output_kind: str


@dataclass(frozen=True)
class TorqueDemand:
    """Torque and speed at the motor shaft over a duty cycle (SI arrays inside, quantities outside)."""

    train: DriveTrain
    t: np.ndarray
    motor_speed: np.ndarray  # rad/s
    motor_acceleration: np.ndarray  # rad/s²
    motor_torque: np.ndarray  # N·m
    labels: tuple[str, ...]
    stages: tuple[StageDemand, ...]
    cycle_time: float
    load_inertia_at_motor: float  # kg·m², everything beyond the rotor

    # -------------------------------------------------------------- summaries
    @property
    def peak_torque(self) -> pint.Quantity:
        return from_si(float(np.max(np.abs(self.motor_torque))), "torque")

    @property
    def rms_torque(self) -> pint.Quantity:
        """sqrt((1/t_c)·∫T² dt) over the cycle (rest at the end of a longer cycle included) [1, 2]."""
        return from_si(rms(self.t, self.motor_torque, self.cycle_time), "torque")

    @property
    def peak_speed(self) -> pint.Quantity:
        return from_si(float(np.max(np.abs(self.motor_speed))), "angular_velocity")

    @property
    def rotor_inertia(self) -> pint.Quantity | None:
        m = self.train.motor
        return None if m is None or m.rotor_inertia is None else m.rotor_inertia

    @property
    def load_inertia(self) -> pint.Quantity:
        """Load, stages and transmission inertia reflected to the motor shaft (rotor excluded)."""
        return from_si(self.load_inertia_at_motor, "inertia")

    def stage(self, which: Any) -> StageDemand:
        """The :class:`StageDemand` of a stage given by object, name or index."""
        for i, s in enumerate(self.stages):
            if which is s.stage or which == s.name or which == i:
                return s
        raise InputError(f"no stage {which!r} in drive train {self.train.name!r} "
                         f"(stages: {', '.join(s.name for s in self.stages) or 'none'})")

    def describe(self, i: int) -> str:
        """'t = 0.2 s, accelerating: 1200 rpm, 35.2 mN·m' for sample ``i`` (made once per sample: the checks of a
        drive name the same governing points)."""
        text = self._descriptions.get(i)
        if text is None:
            text = self._descriptions[i] = (  # (floats: si_to converts them as pint converts the array items)
                f"t = {self.t[i]:.4g} s, {self.labels[i]}: "
                f"{fmt(si_to(abs(float(self.motor_speed[i])), 'angular_velocity', 'rpm'))}, "
                f"{fmt(si_to(float(self.motor_torque[i]), 'torque', 'mN*m'))}")
        return text

    @cached_property
    def _descriptions(self) -> dict[int, str]:
        return {}

    def operating_points(self) -> list[dict[str, Any]]:
        """Per phase (accelerating, constant speed, ...), the sample of largest |torque|."""
        out: list[dict[str, Any]] = []
        labels = np.array(self.labels)
        for lab in dict.fromkeys(self.labels):
            idx = np.flatnonzero(labels == lab)
            i = int(idx[np.argmax(np.abs(self.motor_torque[idx]))])
            out.append({"phase": lab, "t": Q(self.t[i], "s"), "speed": Q(self.motor_speed[i], "rad/s").to("rpm"),
                        "torque": Q(self.motor_torque[i], "N*m")})
        return out

    def quantities(self) -> dict[str, pint.Quantity]:
        return {"t": Q(self.t, "s"), "motor_speed": Q(self.motor_speed, "rad/s"),
                "motor_torque": Q(self.motor_torque, "N*m")}


def rms(t: np.ndarray, y: np.ndarray, cycle_time: float | None = None) -> float:
    """sqrt(∫y² dt / t_c) by the trapezoidal rule (exact for piecewise-constant y sampled at both
    sides of each jump); t_c defaults to the span of ``t``."""
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    tc = float(t[-1] - t[0]) if cycle_time is None else float(cycle_time)
    if not tc > 0:
        raise InputError("rms: the cycle time must be positive")
    return math.sqrt(float(np.trapezoid(y * y, t)) / tc)


def _direction(v: np.ndarray, a: np.ndarray, vscale: float, ascale: float) -> np.ndarray:
    """Sense of motion per sample (+1/-1/0), which decides the efficiency and friction directions.

    Where the load is at rest the sample belongs to the adjacent motion: the move it ends (the
    previous sample's sense) or, after a dwell, the move it starts (the next sample's sense); a sample
    with no moving neighbour takes the sense of its acceleration.
    """
    moving = np.abs(v) > 1e-9 * vscale
    d = np.where(moving, np.sign(v), 0.0)
    prev = np.concatenate(([0.0], d[:-1]))
    nxt = np.concatenate((d[1:], [0.0]))
    acc = np.sign(np.where(np.abs(a) > 1e-9 * ascale, a, 0.0))
    at_rest = np.where(prev != 0, prev, np.where(nxt != 0, nxt, acc))
    return np.where(moving, d, at_rest)


@dataclass(frozen=True)
class DriveTrain:
    """Motor → stages (motor side first) → load.

    ``motor`` may be ``None`` to compute the demand only. Each stage must take rotation at its
    input; all but the last must deliver rotation; the last delivers what the load needs (length
    for a :class:`LinearLoad`, angle for a :class:`RotaryLoad`).
    """

    motor: Any
    stages: tuple[Any, ...]
    load: Load
    name: str = ""

    def __post_init__(self) -> None:
        set_fields(self, stages=tuple(self.stages))
        if not self.name:
            set_fields(self, name=getattr(self.motor, "name", "") or "drive train")
        expected = "angle"
        for i, s in enumerate(self.stages):
            if getattr(s, "input_kind", None) != expected:
                raise InputError(f"drive train {self.name!r}: stage {i} ({getattr(s, 'name', s)!r}) cannot follow a "
                                 f"stage that delivers {'linear' if expected == 'length' else 'rotary'} motion")
            expected = s.output_kind
        if expected != self.load.kind:
            raise InputError(f"drive train {self.name!r}: the last stage delivers "
                             f"{'linear' if expected == 'length' else 'rotary'} motion but the load is "
                             f"{'linear' if self.load.kind == 'length' else 'rotary'}; add a screw or drum")

    @property
    def ratio_si(self) -> float:
        """Motor displacement per unit load displacement (product of the stage ratios)."""
        return float(np.prod([s.ratio_si for s in self.stages])) if self.stages else 1.0

    def load_inertia_at_motor_si(self, extra: float = 0.0) -> float:
        """Load (plus ``extra``, a mechanism's inertia or mass at the load side) reflected to the motor shaft."""
        J = self.load.mass_or_inertia_si + extra
        for s in reversed(self.stages):
            J = J / s.ratio_si**2 + s.inertia_at_input_si
        return J

    def demand(self, profile: Profile | SampledProfile, *, cycle_time: Any = None,
               points_per_segment: int = 41) -> TorqueDemand:
        """Torque and speed at the motor over ``profile`` (the load's motion).

        ``cycle_time`` longer than the profile adds standstill at the final position (holding
        torque only) to the RMS; shorter is an error.
        """
        if profile.kind != self.load.kind:
            words = {"length": "linear", "angle": "rotary"}
            raise InputError(f"drive train {self.name!r}: the profile is {words[profile.kind]} "
                             f"but the load is {words[self.load.kind]}")
        s: ProfileSamples = profile.sample(points_per_segment) if isinstance(profile, Profile) else profile.sample()
        t, x, v, a = s.t, s.x, s.v, s.a
        labels = list(s.labels)
        duration = float(t[-1] - t[0])
        tc = duration if cycle_time is None else to_si(cycle_time, "time", "cycle_time")
        if tc < duration * (1 - 1e-9):
            raise InputError(f"cycle_time {tc:g} s is shorter than the profile ({duration:g} s)")
        if tc > duration * (1 + 1e-9):  # standstill at the end position
            t = np.concatenate([t, [t[-1], t[0] + tc]])
            x = np.concatenate([x, [x[-1], x[-1]]])
            v = np.concatenate([v, [0.0, 0.0]])
            a = np.concatenate([a, [0.0, 0.0]])
            labels += ["standstill", "standstill"]
        vs, as_ = max(float(np.abs(v).max()), 1e-300), max(float(np.abs(a).max()), 1e-300)
        d = _direction(v, a, vs, as_)
        effort = self.load.effort_si(x, v, a, d)
        joint = getattr(profile, "joint_effort", None)  # a mechanism's joint motion brings the joint's own effort
        if joint is not None:  # (its dynamics along a path), added to the load's; held at the end in standstill
            effort = effort + np.interp(t - t[0], joint[0], joint[1])
        stage_data = []
        for st in reversed(self.stages):
            r = st.ratio_si
            v, a = v * r, a * r
            stage_data.append(StageDemand(getattr(st, "name", type(st).__name__), st, effort, v, st.output_kind))
            effort = st.input_effort_si(effort, d) + st.inertia_at_input_si * a
        J_rotor = 0.0
        if self.motor is not None and getattr(self.motor, "rotor_inertia", None) is not None:
            J_rotor = float(self.motor.rotor_inertia.m_as("kg*m**2"))
        torque = effort + J_rotor * a
        return TorqueDemand(self, t - t[0], v, a, torque, tuple(labels), tuple(reversed(stage_data)), tc,
                            self.load_inertia_at_motor_si(float(getattr(profile, "joint_inertia", 0.0) or 0.0)))


__all__ = ["LinearLoad", "RotaryLoad", "DriveTrain", "TorqueDemand", "StageDemand", "rms", "G0"]
