"""Motors: brushed DC motors from datasheet constants, steppers from their pull-out curve, hobby
servos rated in kgf·cm and s/60°, and gear-motors sold as one unit.

Every motor offers the interface the motor-fit checks use:

* ``name``, ``kind`` ("dc", "stepper", "servo", "gearmotor");
* ``rotor_inertia`` (quantity or ``None``), ``max_speed`` (quantity or ``None``),
  ``continuous_torque`` (quantity or ``None`` when the datasheet gives no thermal rating);
* ``available_torque_si(speed, voltage=None)``: the torque the motor can deliver for a short time
  at that speed [N·m] (its intermittent limit), for speeds in rad/s (arrays accepted);
* ``torque_speed_curve()``: the limit as (speed, torque) quantity arrays, for plots.

Catalogue entries live in ``components/data/motors.toml``; :func:`motor` looks them up.

References
----------
1. maxon motor ag, *maxon DC motor and maxon EC motor: Key information* (catalogue section, 2009
   and later editions): n = k_n·U_ind, M = k_M·I, k_n·k_M = 30 000/π (rpm, mNm/A), stall
   torque M_H = k_M·I_A with I_A = U_N/R, speed-torque gradient Δn/ΔM = (30 000/π)·R/k_M²,
   no-load speed n_0 = k_n·(U_N − I_0·R), mechanical time constant τ_m = J_R·R/k_M².
2. maxon support article "Motor constants" (k_n and k_M inverse of each other in SI units).
3. Oriental Motor, *Technical Reference: Motor Sizing Calculations*: a stepper's required torque
   is compared with its pull-out torque at the operating speed with a safety factor of 1.5-2.
4. maxon motor ag, *maxon DC motor: Key information* (thermal data): thermal resistances
   winding-housing R_th1 and housing-ambient R_th2, thermal time constants of the winding τ_w and
   of the motor τ_s, max. winding temperature; winding resistance rises with temperature,
   R(T) = R_25·(1 + α_Cu·(T − 25 °C)), α_Cu = 0.0039 K⁻¹; steady state T_W − T_U = (R_th1 + R_th2)·R(T_W)·I².
   The two-node network (capacities C_w = τ_w/R_th1, C_s = τ_s/R_th2) is the lumped model those data
   describe; maxon's own duty-cycle formulas are not transcribed here.
5. Micromo / MachineDesign, "Microstepping myths and realities": the incremental torque of one
   microstep of a two-phase stepper, T_inc = T_H·sin(90°/μ) (μ microsteps per full step).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pint

from mechverify.components.catalogue import Catalogue, catalogue_entry
from mechverify.errors import InputError, UnitError
from mechverify.frozen import set_fields
from mechverify.units import Q, QuantityLike, as_quantity, fmt, from_si, to_si

_GRADIENT_UNIT = "rad/s/(N*m)"  # SI unit of the speed-torque gradient
_DATA = Path(__file__).parent / "data" / "motors.toml"


def _opt(value: Any, dim: str, name: str, *, positive: bool = True, allow_zero: bool = False) -> pint.Quantity | None:
    """None, or the value as a quantity in the SI unit of ``dim``, checked positive."""
    if value is None:
        return None
    v = to_si(value, dim, name)
    if positive and (v < 0 or (v == 0 and not allow_zero)):
        rel = "zero or positive" if allow_zero else "positive"
        raise InputError(f"{name}: must be {rel}, got {fmt(as_quantity(value, dim))}")
    return from_si(v, dim)


def _gradient(value: Any, name: str) -> pint.Quantity | None:
    if value is None:
        return None
    q = Q(value) if isinstance(value, str) else value
    if not isinstance(q, pint.Quantity) or q.dimensionality != Q(1, _GRADIENT_UNIT).dimensionality:
        raise UnitError(f"{name}: expected a speed per torque (e.g. 'rpm/mNm'), got {value!r}")
    v = float(q.to(_GRADIENT_UNIT).magnitude)
    if not v > 0:
        raise InputError(f"{name}: must be positive")
    return Q(v, _GRADIENT_UNIT)


def _si(q: pint.Quantity | None) -> float | None:
    return None if q is None else float(q.magnitude)


def _fraction_of(value: Any, name: str) -> float | None:
    if value is None:
        return None
    v = to_si(value, "dimensionless", name)
    if isinstance(value, pint.Quantity) and str(value.units) == "percent":
        v = float(value.to("").magnitude)
    if not 0 < v <= 1:
        raise InputError(f"{name}: must lie in (0, 1] (give 0.8 or '80 %'), got {v:g}")
    return v


# ============================================================================ brushed DC motor
@dataclass(frozen=True)
class DCMotor:
    """A brushed (or EC, block-commutated) DC motor described by its datasheet line.

    Give the nominal voltage and at least enough of the constants to fix the terminal resistance R
    and the torque constant k_t (R from ``terminal_resistance`` or U/I_stall; k_t from
    ``torque_constant``, ``speed_constant`` (k_t = 1/k_n in SI) or M_stall/I_stall). Missing values
    are derived [1] and listed in ``derived``. Redundant values are checked against each other
    (k_t·k_n = 1, M_H = k_t·U/R, I_A = U/R, Δn/ΔM = R/k_t², n_0 = k_n(U − R·I_0), τ_m = J·R/k_t²);
    a disagreement above ``datasheet_tolerance`` raises :class:`InputError` listing every relation
    that fails, because it means a value was mistyped or taken from another winding.
    """

    name: str
    nominal_voltage: Any
    no_load_speed: Any = None
    no_load_current: Any = None
    nominal_speed: Any = None
    nominal_torque: Any = None  # max. continuous torque
    nominal_current: Any = None  # max. continuous current
    stall_torque: Any = None
    stall_current: Any = None
    terminal_resistance: Any = None
    terminal_inductance: Any = None
    torque_constant: Any = None
    speed_constant: Any = None
    speed_torque_gradient: Any = None
    mechanical_time_constant: Any = None
    rotor_inertia: Any = None
    max_speed: Any = None  # limit speed (mechanical)
    max_efficiency: Any = None
    thermal_resistance_housing_ambient: Any = None
    thermal_resistance_winding_housing: Any = None
    max_winding_temperature: Any = None
    thermal_time_constant_winding: Any = None
    thermal_time_constant_motor: Any = None
    datasheet_tolerance: float = 0.05
    source: str = ""
    notes: tuple[str, ...] = ()
    derived: frozenset[str] = frozenset()
    kind: str = field(default="dc", init=False)

    def __post_init__(self) -> None:
        n = self.name
        dims = {"nominal_voltage": "voltage", "no_load_speed": "angular_velocity", "no_load_current": "current",
                "nominal_speed": "angular_velocity", "nominal_torque": "torque", "nominal_current": "current",
                "stall_torque": "torque", "stall_current": "current", "terminal_resistance": "resistance",
                "terminal_inductance": "inductance", "torque_constant": "torque_constant",
                "speed_constant": "speed_constant", "mechanical_time_constant": "time", "rotor_inertia": "inertia",
                "max_speed": "angular_velocity", "thermal_resistance_housing_ambient": "thermal_resistance",
                "thermal_resistance_winding_housing": "thermal_resistance", "max_winding_temperature": "temperature",
                "thermal_time_constant_winding": "time", "thermal_time_constant_motor": "time"}
        for f, d in dims.items():
            allow_zero = f in ("no_load_current",)
            positive = f != "max_winding_temperature"
            set_fields(self, **{f: _opt(getattr(self, f), d, f"{n}.{f}", positive=positive,
                                        allow_zero=allow_zero)})
        if self.nominal_voltage is None:
            raise InputError(f"{n}.nominal_voltage: required")
        set_fields(self, speed_torque_gradient=_gradient(self.speed_torque_gradient,
                                                         f"{n}.speed_torque_gradient"))
        set_fields(self, max_efficiency=_fraction_of(self.max_efficiency, f"{n}.max_efficiency"))
        if not 0 < self.datasheet_tolerance < 1:
            raise InputError(f"{n}.datasheet_tolerance: must lie in (0, 1)")
        set_fields(self, notes=tuple(self.notes))
        self._check_datasheet()
        self._normalise_derived()

    # ------------------------------------------------------------------ datasheet relations
    def datasheet_relations(self) -> dict[str, tuple[float, float]]:
        """Each redundant datasheet relation as (datasheet value, value implied by the others), SI [1]."""
        U = _si(self.nominal_voltage)
        R, kt, kn = _si(self.terminal_resistance), _si(self.torque_constant), _si(self.speed_constant)
        MH, IA, I0 = _si(self.stall_torque), _si(self.stall_current), _si(self.no_load_current) or 0.0
        n0, grad, J, tau = (_si(self.no_load_speed), _si(self.speed_torque_gradient), _si(self.rotor_inertia),
                            _si(self.mechanical_time_constant))
        out: dict[str, tuple[float, float]] = {}
        if kt and kn:
            out["kt*kn = 1"] = (kt * kn, 1.0)
        if MH and kt and R:
            out["stall torque = kt*U/R"] = (MH, kt * U / R)
        if IA and R:
            out["stall current = U/R"] = (IA, U / R)
        if MH and kt and IA and not R:
            out["stall torque = kt*I_stall"] = (MH, kt * IA)
        if grad and R and kt:
            out["gradient = R/kt^2"] = (grad, R / kt**2)
        if n0 and kn and R:
            out["no-load speed = kn*(U - R*I0)"] = (n0, kn * (U - R * I0))
        if tau and J and R and kt:
            out["mechanical time constant = J*R/kt^2"] = (tau, J * R / kt**2)
        return out

    def _check_datasheet(self) -> None:
        bad = []
        for rel, (given, implied) in self.datasheet_relations().items():
            if abs(given - implied) > self.datasheet_tolerance * abs(implied):
                bad.append(f"{rel}: datasheet {given:.5g}, implied {implied:.5g} (SI), off by "
                           f"{100 * (given / implied - 1):+.1f} %")
        if bad:
            raise InputError(f"motor {self.name!r}: inconsistent datasheet (tolerance "
                             f"{100 * self.datasheet_tolerance:g} %): " + "; ".join(bad))

    def _normalise_derived(self) -> None:
        """Fill the datasheet values that the others imply (named in ``derived``): construction only."""
        derived = set(self.derived)
        U = _si(self.nominal_voltage)

        def put(f: str, v: float, dim: str | None) -> None:
            set_fields(self, **{f: from_si(v, dim) if dim else Q(v, _GRADIENT_UNIT)})
            derived.add(f)

        if self.terminal_resistance is None and self.stall_current is not None:
            put("terminal_resistance", U / _si(self.stall_current), "resistance")
        if self.torque_constant is None:
            if self.speed_constant is not None:
                put("torque_constant", 1.0 / _si(self.speed_constant), "torque_constant")
            elif self.stall_torque is not None and self.stall_current is not None:
                put("torque_constant", _si(self.stall_torque) / _si(self.stall_current), "torque_constant")
        missing = [f for f in ("terminal_resistance", "torque_constant") if getattr(self, f) is None]
        if missing:
            raise InputError(f"motor {self.name!r}: cannot determine {' and '.join(missing)}; give them, or the stall "
                             "current (R = U/I_stall) and stall torque (k_t = M_stall/I_stall)")
        R, kt = _si(self.terminal_resistance), _si(self.torque_constant)
        if self.speed_constant is None:
            put("speed_constant", 1.0 / kt, "speed_constant")
        if self.stall_torque is None:
            put("stall_torque", kt * U / R, "torque")
        if self.stall_current is None:
            put("stall_current", U / R, "current")
        if self.speed_torque_gradient is None:
            put("speed_torque_gradient", R / kt**2, None)
        if self.no_load_speed is None:
            put("no_load_speed", _si(self.speed_constant) * (U - R * (_si(self.no_load_current) or 0.0)),
                "angular_velocity")
        set_fields(self, derived=frozenset(derived))

    # ------------------------------------------------------------------ physics (SI)
    @property
    def continuous_torque(self) -> pint.Quantity | None:
        """The nominal (max. continuous) torque."""
        return self.nominal_torque

    @property
    def friction_torque(self) -> pint.Quantity:
        """Friction torque M_R = k_t·I_0 (zero when no no-load current is given)."""
        return from_si(_si(self.torque_constant) * (_si(self.no_load_current) or 0.0), "torque")

    @property
    def speed_limit(self) -> pint.Quantity:
        """The limit speed if given, else the no-load speed."""
        return self.max_speed if self.max_speed is not None else self.no_load_speed

    def available_torque_si(self, speed: Any, voltage: float | None = None) -> np.ndarray:
        """Torque on the speed-torque line at ``speed`` [rad/s] for ``voltage`` [V] (default nominal).

        M = (k_n·(U − R·I_0) − ω) / (Δω/ΔM), clipped at zero [1]. The magnitude of the speed is
        used (motoring in either direction).
        """
        U = _si(self.nominal_voltage) if voltage is None else float(voltage)
        kn, R, I0 = _si(self.speed_constant), _si(self.terminal_resistance), _si(self.no_load_current) or 0.0
        w = np.abs(np.asarray(speed, float))
        return np.clip((kn * (U - R * I0) - w) / _si(self.speed_torque_gradient), 0.0, None)

    def current_si(self, torque: Any) -> np.ndarray:
        """Motor current [A] for a shaft torque [N·m]: I = |M|/k_t + I_0 [1]."""
        return np.abs(np.asarray(torque, float)) / _si(self.torque_constant) + (_si(self.no_load_current) or 0.0)

    def voltage_si(self, torque: Any, speed: Any) -> np.ndarray:
        """Terminal voltage [V] needed at a torque and speed: U = R·I + |ω|/k_n [1].

        Conservative in the generating quadrant (torque against speed), where the real voltage is lower.
        """
        return (_si(self.terminal_resistance) * self.current_si(torque)
                + np.abs(np.asarray(speed, float)) / _si(self.speed_constant))

    def torque_speed_curve(self, voltage: QuantityLike | None = None,
                           n: int = 2) -> tuple[pint.Quantity, pint.Quantity]:
        U = None if voltage is None else to_si(voltage, "voltage", "voltage")
        w0 = float(self.available_torque_si(0.0, U)) * _si(self.speed_torque_gradient)
        w = np.linspace(0.0, w0, max(n, 2))
        return from_si(w, "angular_velocity"), from_si(self.available_torque_si(w, U), "torque")

    def __repr__(self) -> str:
        return (f"<DCMotor {self.name!r} {fmt(self.nominal_voltage)} M_N={fmt(self.nominal_torque, 'mN*m')} "
                f"M_H={fmt(self.stall_torque, 'mN*m')}>" if self.nominal_torque is not None else
                f"<DCMotor {self.name!r} {fmt(self.nominal_voltage)} M_H={fmt(self.stall_torque, 'mN*m')}>")


# ============================================================================ stepper
def _quantity_list(values: Any, dim: str, name: str) -> np.ndarray:
    if values is None:
        return np.array([])
    if isinstance(values, pint.Quantity):
        return np.atleast_1d(np.asarray(to_si(values, dim, name), float))
    if isinstance(values, str):
        raise InputError(f"{name}: give a list of quantities, e.g. ['0 rpm', '300 rpm']")
    return np.array([to_si(v, dim, f"{name}[{i}]") for i, v in enumerate(values)], float)


@dataclass(frozen=True)
class StepperMotor:
    """A hybrid stepper described by its pull-out torque curve (points, any units).

    ``pullout_speeds``/``pullout_torques`` are the curve's points (a quantity array or a list of
    quantities/strings), measured with the driver and supply voltage named in ``drive``. Between
    points the curve is interpolated linearly; below the first point it keeps the first point's
    torque (never more, conservative); beyond the last point nothing is known and the available
    torque is zero. ``max_speed`` defaults to the last point's speed.
    """

    name: str
    step_angle: Any
    holding_torque: Any
    pullout_speeds: Any = None
    pullout_torques: Any = None
    rotor_inertia: Any = None
    detent_torque: Any = None
    rated_current: Any = None
    phase_resistance: Any = None
    phase_inductance: Any = None
    rated_voltage: Any = None
    max_speed: Any = None
    drive: str = ""  # driver and supply voltage of the pull-out curve
    source: str = ""
    notes: tuple[str, ...] = ()
    kind: str = field(default="stepper", init=False)

    def __post_init__(self) -> None:
        n = self.name
        dims = {"step_angle": "angle", "holding_torque": "torque", "rotor_inertia": "inertia",
                "detent_torque": "torque", "rated_current": "current", "phase_resistance": "resistance",
                "phase_inductance": "inductance", "rated_voltage": "voltage", "max_speed": "angular_velocity"}
        for f, d in dims.items():
            set_fields(self, **{f: _opt(getattr(self, f), d, f"{n}.{f}", allow_zero=f == "detent_torque")})
        if self.step_angle is None or self.holding_torque is None:
            raise InputError(f"stepper {n!r}: step_angle and holding_torque are required")
        w = _quantity_list(self.pullout_speeds, "angular_velocity", f"{n}.pullout_speeds")
        t = _quantity_list(self.pullout_torques, "torque", f"{n}.pullout_torques")
        if len(w) != len(t):
            raise InputError(f"stepper {n!r}: pullout_speeds and pullout_torques differ in length ({len(w)}, {len(t)})")
        if len(w) and (np.any(np.diff(w) <= 0) or w[0] < 0):
            raise InputError(f"stepper {n!r}: pull-out speeds must be >= 0 and strictly increasing")
        if len(t) and np.any(t < 0):
            raise InputError(f"stepper {n!r}: pull-out torques must be >= 0")
        if len(t) and np.any(t > _si(self.holding_torque) * 1.0001):
            raise InputError(f"stepper {n!r}: a pull-out torque exceeds the holding torque "
                             f"{fmt(self.holding_torque)}; check the units of the curve")
        set_fields(self, pullout_speeds=from_si(w, "angular_velocity") if len(w) else None,
                   pullout_torques=from_si(t, "torque") if len(t) else None)
        if self.max_speed is None and len(w):
            set_fields(self, max_speed=from_si(float(w[-1]), "angular_velocity"))
        set_fields(self, notes=tuple(self.notes))

    @property
    def steps_per_revolution(self) -> float:
        return 2 * math.pi / _si(self.step_angle)

    @property
    def continuous_torque(self) -> None:
        """Steppers run at rated current whatever the torque: no separate continuous rating."""
        return None

    @property
    def speed_limit(self) -> pint.Quantity | None:
        return self.max_speed

    @property
    def has_curve(self) -> bool:
        return self.pullout_speeds is not None

    def available_torque_si(self, speed: Any, voltage: float | None = None) -> np.ndarray:
        """Pull-out torque [N·m] at ``speed`` [rad/s] (see class notes for outside the points).

        Without a pull-out curve only standstill is known: the holding torque (energised, at rest).
        """
        w = np.abs(np.asarray(speed, float))
        if not self.has_curve:
            if np.all(w == 0):
                return np.full_like(w, _si(self.holding_torque))
            raise InputError(f"stepper {self.name!r} has no pull-out curve, so only holding at standstill can be "
                             "checked; give pullout_speeds and pullout_torques from the datasheet (holding torque "
                             "is not a running torque)")
        ws, ts = self.pullout_speeds.magnitude, self.pullout_torques.magnitude
        return np.interp(w, ws, ts, left=ts[0], right=0.0) * (w <= ws[-1] * (1 + 1e-12))

    def current_si(self, torque: Any) -> np.ndarray:
        """Phase current [A] the driver must supply: the rated phase current at every point, whatever the torque
        (a chopper driver regulates the phase current to its setting; [3]). Needs ``rated_current``."""
        if self.rated_current is None:
            raise InputError(f"stepper {self.name!r}: no rated_current, so the driver current cannot be checked")
        return np.full_like(np.asarray(torque, float), _si(self.rated_current))

    def torque_speed_curve(self, voltage: Any = None, n: int = 0) -> tuple[pint.Quantity, pint.Quantity]:
        if not self.has_curve:
            raise InputError(f"stepper {self.name!r} has no pull-out curve")
        return self.pullout_speeds, self.pullout_torques

    def __repr__(self) -> str:
        return f"<StepperMotor {self.name!r} {fmt(self.step_angle, 'deg')} holding {fmt(self.holding_torque)}>"


# ============================================================================ linear-line motors
@dataclass(frozen=True)
class HobbyServo:
    """An RC hobby servo rated by stall torque (usually kgf·cm) and speed (seconds per 60°).

    The rating is a stall torque, not a continuous one. Between no load and stall the servo is
    modelled by a straight speed-torque line: M(ω) = M_stall·(1 − ω/ω_0), ω_0 = 60°/t_60.
    Without a speed rating the full stall torque is assumed at all speeds (and no speed limit
    is known).
    """

    name: str
    stall_torque: Any
    time_per_60deg: Any = None
    voltage: Any = None
    rotation_range: Any = None
    source: str = ""
    notes: tuple[str, ...] = ()
    kind: str = field(default="servo", init=False)
    rotor_inertia: None = field(default=None, init=False)

    def __post_init__(self) -> None:
        n = self.name
        for f, d in {"stall_torque": "torque", "time_per_60deg": "time", "voltage": "voltage",
                     "rotation_range": "angle"}.items():
            set_fields(self, **{f: _opt(getattr(self, f), d, f"{n}.{f}")})
        if self.stall_torque is None:
            raise InputError(f"servo {n!r}: stall_torque is required")
        set_fields(self, notes=tuple(self.notes))

    @property
    def no_load_speed(self) -> pint.Quantity | None:
        """ω_0 = (π/3 rad) / t_60."""
        return None if self.time_per_60deg is None else from_si((math.pi / 3) / _si(self.time_per_60deg),
                                                                 "angular_velocity")

    max_speed = no_load_speed
    speed_limit = no_load_speed

    @property
    def continuous_torque(self) -> None:
        return None

    def available_torque_si(self, speed: Any, voltage: float | None = None) -> np.ndarray:
        w = np.abs(np.asarray(speed, float))
        Ms = _si(self.stall_torque)
        if self.time_per_60deg is None:
            return np.full_like(w, Ms)
        return np.clip(Ms * (1 - w / _si(self.no_load_speed)), 0.0, None)

    def torque_speed_curve(self, voltage: Any = None, n: int = 2) -> tuple[pint.Quantity, pint.Quantity]:
        if self.time_per_60deg is None:
            raise InputError(f"servo {self.name!r} has no speed rating (time_per_60deg)")
        w = np.array([0.0, _si(self.no_load_speed)])
        return from_si(w, "angular_velocity"), from_si(self.available_torque_si(w), "torque")


@dataclass(frozen=True)
class GearMotor:
    """A DC gear-motor sold as one unit and rated at its output shaft.

    Straight speed-torque line from ``no_load_speed`` to ``stall_torque`` (both at the output, at
    ``nominal_voltage``); current rises linearly from ``no_load_current`` to ``stall_current``.
    ``rated_torque`` is the maker's continuous (rated) torque if one is given; many hobby
    gear-motors quote only the stall torque.
    """

    name: str
    no_load_speed: Any
    stall_torque: Any
    rated_torque: Any = None
    nominal_voltage: Any = None
    stall_current: Any = None
    no_load_current: Any = None
    ratio: float | None = None
    rotor_inertia: Any = None  # referred to the output shaft
    source: str = ""
    notes: tuple[str, ...] = ()
    kind: str = field(default="gearmotor", init=False)

    def __post_init__(self) -> None:
        n = self.name
        for f, d in {"no_load_speed": "angular_velocity", "stall_torque": "torque", "rated_torque": "torque",
                     "nominal_voltage": "voltage", "stall_current": "current", "no_load_current": "current",
                     "rotor_inertia": "inertia"}.items():
            set_fields(self, **{f: _opt(getattr(self, f), d, f"{n}.{f}", allow_zero=f == "no_load_current")})
        if self.no_load_speed is None or self.stall_torque is None:
            raise InputError(f"gear-motor {n!r}: no_load_speed and stall_torque are required")
        if self.rated_torque is not None and self.rated_torque > self.stall_torque:
            raise InputError(f"gear-motor {n!r}: rated torque {fmt(self.rated_torque)} exceeds stall torque "
                             f"{fmt(self.stall_torque)}")
        if self.ratio is not None and not float(self.ratio) > 0:
            raise InputError(f"gear-motor {n!r}: ratio must be positive")
        set_fields(self, notes=tuple(self.notes))

    @property
    def continuous_torque(self) -> pint.Quantity | None:
        return self.rated_torque

    @property
    def max_speed(self) -> pint.Quantity:
        return self.no_load_speed

    speed_limit = max_speed

    def available_torque_si(self, speed: Any, voltage: float | None = None) -> np.ndarray:
        w = np.abs(np.asarray(speed, float))
        return np.clip(_si(self.stall_torque) * (1 - w / _si(self.no_load_speed)), 0.0, None)

    def current_si(self, torque: Any) -> np.ndarray:
        if self.stall_current is None:
            raise InputError(f"gear-motor {self.name!r} has no stall current; cannot estimate its current")
        I0 = _si(self.no_load_current) or 0.0
        return I0 + (_si(self.stall_current) - I0) * np.abs(np.asarray(torque, float)) / _si(self.stall_torque)

    def torque_speed_curve(self, voltage: Any = None, n: int = 2) -> tuple[pint.Quantity, pint.Quantity]:
        w = np.array([0.0, _si(self.no_load_speed)])
        return from_si(w, "angular_velocity"), from_si(self.available_torque_si(w), "torque")


Motor = DCMotor | StepperMotor | HobbyServo | GearMotor


# ============================================================================ thermal model
#: temperature coefficient of copper resistance [1/K] ([4])
ALPHA_CU = 0.0039
#: the temperature at which datasheet resistances are given [°C] ([4])
T_REF = 25.0
THERMAL_FIELDS = ("thermal_resistance_winding_housing", "thermal_resistance_housing_ambient",
                  "thermal_time_constant_winding", "thermal_time_constant_motor", "max_winding_temperature")


@dataclass(frozen=True)
class ThermalResult:
    """Thermally periodic winding and housing temperatures over one duty cycle [°C]."""

    t: np.ndarray
    winding: np.ndarray
    housing: np.ndarray
    peak_winding: float
    peak_index: int
    steady_mean_power: float  # mean Joule loss over the periodic cycle [W]


def thermal_data(m: Any) -> tuple[float, float, float, float, float]:
    """(R_th1 [K/W], R_th2 [K/W], τ_w [s], τ_s [s], T_max [°C]) of a DC motor, or :class:`InputError`
    naming the missing fields (and, for a stepper, saying the check is not available)."""
    if getattr(m, "kind", "") == "stepper":
        raise InputError(f"{m.name}: winding temperature not available for steppers without the maker's "
                         "temperature-rise data (a stepper draws its rated current whatever the torque)")
    if getattr(m, "kind", "") != "dc":
        raise InputError(f"{getattr(m, 'name', m)}: the winding-temperature model needs a DC motor's resistance and "
                         f"thermal data ({', '.join(THERMAL_FIELDS)})")
    missing = [f for f in THERMAL_FIELDS if getattr(m, f) is None]
    if missing:
        raise InputError(f"motor {m.name!r}: no thermal data for the winding-temperature check; give "
                         + ", ".join(missing) + " (maxon datasheet lines 'thermal resistance housing-ambient', "
                         "'winding-housing', 'thermal time constant winding', 'motor', 'max. winding temperature')")
    return (_si(m.thermal_resistance_winding_housing), _si(m.thermal_resistance_housing_ambient),
            _si(m.thermal_time_constant_winding), _si(m.thermal_time_constant_motor),
            _si(m.max_winding_temperature) - 273.15)


def steady_winding_temperature(R25: float, current: float, Rth1: float, Rth2: float, ambient: float = 25.0,
                               alpha: float = ALPHA_CU) -> float:
    """Steady winding temperature [°C] at constant current I [A] ([4]):
    T_W = (T_U + R_th·R_25·I²·(1 − α·25 °C)) / (1 − α·R_th·R_25·I²), R_th = R_th1 + R_th2.
    Thermal runaway (denominator <= 0) raises :class:`ValidityError`."""
    from mechverify.errors import ValidityError
    k = (Rth1 + Rth2) * R25 * current**2
    den = 1 - alpha * k
    if den <= 0:
        raise ValidityError(f"thermal runaway at {current:g} A: the winding's loss rises faster with temperature "
                            "than the motor can shed it")
    return (ambient + k * (1 - alpha * T_REF)) / den


def winding_temperature_cycle(t: Any, current: Any, R25: float, Rth1: float, Rth2: float, tau_w: float,
                              tau_s: float, ambient: float = 25.0, alpha: float = ALPHA_CU) -> ThermalResult:
    """Two-node thermal model over one duty cycle repeated until periodic ([4]); SI floats/arrays.

    C_w dT_w/dt = I²·R_25·(1 + α(T_w − 25)) − (T_w − T_h)/R_th1,
    C_s dT_h/dt = (T_w − T_h)/R_th1 − (T_h − T_U)/R_th2, with C_w = τ_w/R_th1, C_s = τ_s/R_th2.
    ``current`` at the times ``t`` (one cycle; I² is taken as the mean of its two ends on each interval).
    The system is linear in the temperatures, so each interval is stepped exactly with a matrix
    exponential and the periodic state x* = Φx* + ψ is solved directly (the limit of repeating the cycle,
    without the thousands of cycles a long motor time constant would take). Thermal runaway (no periodic
    state: spectral radius of Φ >= 1) raises :class:`ValidityError`.
    """
    from scipy.linalg import expm

    from mechverify.errors import ValidityError
    t = np.asarray(t, float)
    i2 = np.asarray(current, float) ** 2
    if t.ndim != 1 or t.shape != i2.shape or len(t) < 2 or np.any(np.diff(t) < 0):
        raise InputError("thermal model: times must increase and match the currents")
    if min(Rth1, Rth2, tau_w, tau_s, R25) <= 0:
        raise InputError("thermal model: resistances and time constants must be positive")
    Cw, Cs = tau_w / Rth1, tau_s / Rth2
    steps = []
    cache: dict[tuple[float, float], np.ndarray] = {}  # equal intervals at equal current share one exponential
    Phi, psi = np.eye(2), np.zeros(2)
    for j in range(len(t) - 1):
        dt = float(t[j + 1] - t[j])
        k = float(0.5 * (i2[j] + i2[j + 1]) * R25)
        E = cache.get((dt, k))
        if E is None:
            M = np.array([[(k * alpha - 1 / Rth1) / Cw, 1 / (Rth1 * Cw), k * (1 - alpha * T_REF) / Cw],
                          [1 / (Rth1 * Cs), -(1 / Rth1 + 1 / Rth2) / Cs, ambient / (Rth2 * Cs)],
                          [0.0, 0.0, 0.0]])
            E = cache[(dt, k)] = expm(M * dt) if dt > 0 else np.eye(3)
        steps.append(E)
        Phi, psi = E[:2, :2] @ Phi, E[:2, :2] @ psi + E[:2, 2]
    if np.max(np.abs(np.linalg.eigvals(Phi))) >= 1 - 1e-15:
        raise ValidityError("thermal runaway: no thermally periodic state for this duty cycle (the winding's loss "
                            "rises faster with temperature than the motor sheds it)")
    x = np.linalg.solve(np.eye(2) - Phi, psi)
    out = np.empty((len(t), 2))
    out[0] = x
    for j, E in enumerate(steps):
        x = E[:2, :2] @ x + E[:2, 2]
        out[j + 1] = x
    w = out[:, 0]
    i = int(np.argmax(w))
    span = t[-1] - t[0]
    p = i2 * R25 * (1 + alpha * (w - T_REF))
    mean_p = float(np.trapezoid(p, t) / span) if span > 0 else float(p[0])
    return ThermalResult(t=t, winding=w, housing=out[:, 1], peak_winding=float(w[i]), peak_index=i,
                         steady_mean_power=mean_p)


# ============================================================================ stepper datasheet and resolution
def stepper_datasheet_relations(m: StepperMotor) -> dict[str, tuple[float, float]]:
    """Redundant stepper datasheet values as (datasheet, implied) pairs, SI: U = I·R per phase (for a
    voltage-rated winding), and the pull-out curve's low-speed end not above the holding torque."""
    out: dict[str, tuple[float, float]] = {}
    U, I, R = _si(m.rated_voltage), _si(m.rated_current), _si(m.phase_resistance)
    if U and I and R:
        out["rated voltage = rated current * phase resistance"] = (U, I * R)
    if m.has_curve:
        out["holding torque >= pull-out torque at the lowest speed"] = (_si(m.holding_torque),
                                                                        float(m.pullout_torques.magnitude[0]))
    return out


def stepper_datasheet_warnings(m: StepperMotor, tolerance: float = 0.05) -> tuple[str, ...]:
    """The relations of :func:`stepper_datasheet_relations` that the datasheet breaks (beyond ``tolerance``)."""
    out = []
    for rel, (given, implied) in stepper_datasheet_relations(m).items():
        if rel.startswith("holding"):
            if given < implied * (1 - 1e-9):
                out.append(f"{m.name}: {rel}: holding {given:.4g} N*m < pull-out {implied:.4g} N*m")
        elif abs(given - implied) > tolerance * abs(implied):
            out.append(f"{m.name}: {rel}: datasheet {given:.4g}, implied {implied:.4g} (SI), off by "
                       f"{100 * (given / implied - 1):+.1f} % (a value from another winding or connection?)")
    return tuple(out)


def microstep_incremental_torque(holding_torque: QuantityLike, microsteps: int) -> pint.Quantity:
    """Torque that one microstep can move against: T_inc = T_H·sin(90°/μ) ([5]); μ >= 1 an integer."""
    if not isinstance(microsteps, int) or isinstance(microsteps, bool) or microsteps < 1:
        raise InputError(f"microsteps must be a whole number >= 1, got {microsteps!r}")
    return from_si(to_si(holding_torque, "torque", "holding_torque") * math.sin(math.pi / (2 * microsteps)),
                   "torque")


def stepper_resolution(step_angle: QuantityLike, *, microsteps: int = 1, ratio: float = 1.0,
                       lead: QuantityLike | None = None) -> pint.Quantity:
    """Output increment of one (micro)step: step angle / (μ·ratio), and × lead/(2π) through a screw of ``lead``
    (an angle without a screw, a length with one). ``ratio`` is the gear reduction (input turns per output turn)."""
    a = to_si(step_angle, "angle", "step_angle")
    if not a > 0 or not float(ratio) > 0:
        raise InputError("step angle and ratio must be positive")
    if not isinstance(microsteps, int) or microsteps < 1:
        raise InputError(f"microsteps must be a whole number >= 1, got {microsteps!r}")
    out = a / (microsteps * float(ratio))
    if lead is None:
        return from_si(out, "angle").to("deg")
    return from_si(out / (2 * math.pi) * to_si(lead, "length", "lead"), "length").to("mm")


def inertia_matching_ratio(load_inertia: QuantityLike, rotor_inertia: QuantityLike) -> float:
    """Gear ratio i = √(J_L/J_M) that minimises the motor torque J_M·i·α + J_L·α/i of accelerating a pure
    inertia J_L (at the output) with a rotor J_M: d/di = 0 (hand derivation; the inertia-matching rule)."""
    JL, JM = to_si(load_inertia, "inertia", "load_inertia"), to_si(rotor_inertia, "inertia", "rotor_inertia")
    if not (JL > 0 and JM > 0):
        raise InputError("inertia matching: both inertias must be positive")
    return math.sqrt(JL / JM)


def optimal_ratio(rms_torque_of_ratio: Any, low: float, high: float) -> tuple[float, float]:
    """(ratio, RMS motor torque) minimising ``rms_torque_of_ratio(i)`` [N·m] over low <= i <= high (bounded
    scalar search; the caller builds the drive train and profile demand for each ratio)."""
    from scipy.optimize import minimize_scalar
    if not 0 < low < high:
        raise InputError("optimal ratio: need 0 < low < high")
    res = minimize_scalar(lambda x: float(rms_torque_of_ratio(math.exp(x))), bounds=(math.log(low), math.log(high)),
                          method="bounded", options={"xatol": 1e-8})
    return math.exp(res.x), float(res.fun)


def max_efficiency(no_load_current: float, stall_current: float) -> float:
    """Maximum efficiency η_max = (1 − √(I_0/I_A))² of a DC motor ([1]; I_0 no-load, I_A stall current)."""
    if not 0 <= no_load_current < stall_current:
        raise InputError("max efficiency: need 0 <= I0 < I_A")
    return (1 - math.sqrt(no_load_current / stall_current)) ** 2


def operating_efficiency(m: DCMotor, torque: Any, speed: Any) -> np.ndarray:
    """Efficiency at operating points η = P_mech/P_el = |ω·M| / (U·I), motoring quadrant, with I = |M|/k_t + I_0
    and U = R·I + |ω|/k_n ([1]); 0 where no power is delivered. Arrays in SI."""
    M, w = np.abs(np.asarray(torque, float)), np.abs(np.asarray(speed, float))
    I = m.current_si(M)
    U = m.voltage_si(M, w)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(U * I > 0, M * w / (U * I), 0.0)

# ============================================================================ catalogue
_TYPES: dict[str, type] = {"dc": DCMotor, "stepper": StepperMotor, "servo": HobbyServo, "gearmotor": GearMotor}


def motor_from_dict(d: Mapping[str, Any], references: Mapping[str, str] | None = None) -> Motor:
    """Build a motor from a TOML-style mapping with a ``type`` key (dc, stepper, servo, gearmotor)."""
    d = dict(d)
    typ = d.pop("type", None)
    d.pop("aliases", None)
    if typ not in _TYPES:
        raise InputError(f"motor {d.get('name')!r}: type must be one of {sorted(_TYPES)}, got {typ!r}")
    cls = _TYPES[typ]
    return cls(**catalogue_entry(cls, d, f"motor {d.get('name')!r}", f"a {typ} motor", references))


_CATALOGUE: Catalogue[Motor] = Catalogue("motor", _DATA, "motor", motor_from_dict)


def motor(name: str | Motor) -> Motor:
    """A catalogue motor by name or alias (``components/data/motors.toml``); unknown names get suggestions."""
    if not isinstance(name, str):
        return name
    return _CATALOGUE.get(name)


def motor_names() -> list[str]:
    """Primary names of all catalogue motors."""
    return _CATALOGUE.names()


__all__ = ["DCMotor", "StepperMotor", "HobbyServo", "GearMotor", "Motor", "motor", "motor_names",
           "motor_from_dict", "ALPHA_CU", "THERMAL_FIELDS", "ThermalResult", "thermal_data",
           "steady_winding_temperature", "winding_temperature_cycle", "max_efficiency", "operating_efficiency",
           "stepper_datasheet_relations", "stepper_datasheet_warnings", "microstep_incremental_torque",
           "stepper_resolution", "inertia_matching_ratio", "optimal_ratio"]
