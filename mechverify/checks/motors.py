"""Motor-fit checks: a :class:`~mechverify.motion.drive_train.TorqueDemand` against the motor,
gearhead and driver ratings, one check per limit, each naming the profile point that governs.

* :func:`check_motor_peak_torque` — ``|T|`` at every point against the motor's intermittent limit at that
  speed (DC: the speed-torque line at the supply voltage; stepper: the pull-out curve, with a
  margin, default 1.5; servo / gear-motor: their straight line);
* :func:`check_motor_rms_torque` — RMS torque over the cycle against the continuous (nominal) torque;
* :func:`check_motor_max_speed` — peak motor speed against the limit speed;
* :func:`check_gearhead_continuous_torque` / :func:`check_gearhead_intermittent_torque` — RMS and
  peak output torque of each gearhead against its ratings;
* :func:`check_gearhead_input_speed` — peak input speed against the gearhead's limit;
* :func:`check_inertia_ratio` — load inertia at the motor / rotor inertia against a limit;
* :func:`check_motor_supply_voltage`, :func:`check_driver_current` — DC motors: voltage and current
  needed at the worst point against the supply and the driver;
* :func:`motor_fit_checks` — all of those that apply, as a :class:`ResultSet`.

References
----------
1. maxon motor ag, *maxon DC motor: Key information* and *maxon gear: Key information*
   (catalogue): operating points must lie below the speed-torque line at the supply voltage;
   RMS torque ≤ nominal (max. continuous) torque; gearhead RMS/peak output torque ≤ max.
   continuous/intermittent torque; input speed ≤ max. input speed.
2. Oriental Motor, *Technical Reference: Motor Sizing Calculations*: stepper required torque ×
   safety factor 1.5-2 within the pull-out torque at the operating speed; load-to-rotor inertia
   ratio limits (about 10 for steppers).
3. THK, *Ball Screw: Studying the Driving Motor*: T_max ≤ peak torque, T_rms ≤ rated torque,
   inertia ratio normally 3-10.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, ResultSet
from mechverify.components.gearheads import Gearhead
from mechverify.errors import InputError
from mechverify.motion.drive_train import TorqueDemand, rms
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, from_si, to_si

_SRC_MAXON = ref("maxon", "'maxon DC motor: Key information' and 'maxon gear: Key information'")
_SRC_ORIENTAL = ref("oriental_motor")

#: Default margin on a stepper's pull-out torque (Oriental Motor recommends 1.5 to 2).
STEPPER_MARGIN = 1.5
#: Default load-to-rotor inertia ratio limit (Oriental Motor: about 10 for steppers; THK: 3 to 10).
INERTIA_RATIO_LIMIT = 10.0


def _motor(demand: TorqueDemand, motor: Any) -> Any:
    m = motor if motor is not None else demand.train.motor
    if m is None:
        raise InputError("no motor: give one to the drive train or to the check")
    return m


def _plot(demand: TorqueDemand, motor: Any, voltage: float | None = None) -> dict[str, Any]:
    details: dict[str, Any] = {"motor_speed": Q(np.abs(demand.motor_speed), "rad/s").to("rpm"),
                               "motor_torque": Q(np.abs(demand.motor_torque), "N*m"), "time": Q(demand.t, "s")}
    try:
        w, T = motor.torque_speed_curve(None if voltage is None else Q(voltage, "V"), n=50)
        details["limit_speed"], details["limit_torque"] = w.to("rpm"), T
    except InputError:
        pass
    return details


def _case(demand: TorqueDemand, i: int) -> str:
    return demand.describe(i)


@check("motor_peak_torque", title="Motor peak torque", sf_kind="motor",
       source=f"{_SRC_ORIENTAL}; {_SRC_MAXON}",
       explain=("|T(t)| at every profile point against the motor's intermittent limit at that speed (DC: speed-torque"
                ' line at the supply voltage; stepper: pull-out curve), T = F/(r·eta) + J·alpha (Oriental Motor, '
                'Motor Sizing Calculations; maxon Key information). Margin (motor class, default 1.5): the torque '
                'comes from estimated friction, efficiency and load, so it carries their uncertainty (Oriental Motor:'
                " 1.5-2 on a stepper's pull-out torque)."))
def check_motor_peak_torque(demand: TorqueDemand, motor: Any = None, *, margin: float | None = None,
                      supply_voltage: QuantityLike | None = None, component: str | None = None) -> CheckResult:
    """``|T(t)|`` against the motor's intermittent limit at the speed of the same point [1, 2].

    The governing point is the one of highest utilisation ``|T|/T_avail(ω)``, not necessarily the
    peak torque. ``margin`` (required safety factor) defaults to 1.5 for steppers and 1 otherwise.
    """
    m = _motor(demand, motor)
    U = None if supply_voltage is None else to_si(supply_voltage, "voltage", "supply_voltage")
    if margin is None:
        margin = STEPPER_MARGIN if m.kind == "stepper" else 1.0
    avail = m.available_torque_si(demand.motor_speed, U)
    T = np.abs(demand.motor_torque)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(avail > 0, T / np.where(avail > 0, avail, 1.0), np.where(T > 0, np.inf, 0.0))
    i = int(np.argmax(u))
    warnings, notes = [], []
    limit = {"dc": "speed-torque line at " + (f"{U:g} V supply" if U is not None else "nominal voltage"),
             "stepper": "pull-out torque curve", "servo": "straight speed-torque line (stall rating)",
             "gearmotor": "straight speed-torque line (stall rating)"}[m.kind]
    notes.append(f"capacity: the motor's {limit} at the governing point's speed")
    if m.kind == "stepper":
        notes.append(f"required margin {margin:g} on pull-out torque ({_SRC_ORIENTAL}: 1.5-2); "
                     f"curve measured with: {m.drive or 'driver not stated'}")
    if m.kind == "stepper" and not m.has_curve:
        notes.append("no pull-out curve: at standstill only, against the holding torque (energised, at rest)")
    elif m.kind == "stepper":
        ws = m.pullout_speeds.magnitude
        if np.max(np.abs(demand.motor_speed)) > ws[-1]:
            warnings.append(f"speed beyond the pull-out curve's last point ({fmt(Q(ws[-1], 'rad/s'), 'rpm')}): "
                            "no torque is known there")
        if np.min(np.abs(demand.motor_speed)[T > 0], initial=np.inf) < ws[0]:
            notes.append("below the curve's first speed its first torque is used")
    if m.kind in ("servo", "gearmotor"):
        notes.append("the rating is a stall torque; a motor cannot run near stall for long")
    if m.kind == "dc" and U is None:
        notes.append("voltage: the motor's nominal voltage (give supply_voltage to use the supply's)")
    return CheckResult(
        check="motor_peak_torque", component=component or m.name, demand=from_si(float(T[i]), "torque"),
        capacity=from_si(float(avail[i]), "torque"), required_sf=margin,
        title="Motor torque within the intermittent limit at each speed",
        formula=r"|T(t)| \le T_{avail}(\omega(t)) / S_f",
        source=_SRC_MAXON if m.kind == "dc" else _SRC_ORIENTAL,
        inputs={"peak torque": demand.peak_torque, "peak speed": demand.peak_speed.to("rpm")},
        notes=tuple(notes), warnings=tuple(warnings), load_case=_case(demand, i), details=_plot(demand, m, U))


@check("motor_rms_torque", title="Motor RMS torque", sf_kind="motor",
       source=f"{_SRC_MAXON}; {ref('thk')}",
       explain=('T_rms = sqrt(1/t_c ∫T² dt) over the duty cycle against the continuous (nominal) torque (maxon Key '
                'information; THK). Not for steppers (they run at rated current). Margin (motor class, default 1.5): '
                'the torque comes from estimated friction, efficiency and load, so it carries their uncertainty '
                "(Oriental Motor: 1.5-2 on a stepper's pull-out torque)."))
def check_motor_rms_torque(demand: TorqueDemand, motor: Any = None, *, component: str | None = None) -> CheckResult:
    """RMS torque over the duty cycle against the motor's continuous (nominal) torque [1, 3].

    For a servo or gear-motor rated only by stall torque, the stall torque is the capacity and a
    warning says so. Steppers have no torque-based thermal rating: :class:`InputError`.
    """
    m = _motor(demand, motor)
    if m.kind == "stepper":
        raise InputError(f"{m.name}: a stepper runs at rated current whatever the torque; its thermal limit is not "
                         "an RMS torque (check the pull-out margin instead)")
    warnings, notes = [], [f"duty cycle {demand.cycle_time:.4g} s, standstill included"]
    cap = m.continuous_torque
    if cap is None:
        if m.kind == "dc":
            raise InputError(f"{m.name}: no nominal (continuous) torque given")
        cap = from_si(float(m.available_torque_si(0.0)), "torque")
        warnings.append("no continuous rating: compared with the stall torque, which no motor can deliver "
                        "continuously; get the rated torque from the maker")
    Trms = demand.rms_torque
    i = int(np.argmax(np.abs(demand.motor_torque)))
    return CheckResult(
        check="motor_rms_torque", component=component or m.name, demand=Trms, capacity=cap,
        title="RMS torque within the continuous torque", formula=r"T_{rms} = \sqrt{\frac{1}{t_c}\int T^2\,dt} \le T_N",
        source=_SRC_MAXON, inputs={"cycle time": Q(demand.cycle_time, "s")}, notes=tuple(notes),
        warnings=tuple(warnings), load_case=f"whole cycle (peak at {_case(demand, i)})", details=_plot(demand, m))


@check("motor_max_speed", title="Motor speed", sf_kind="limit",
       source=_SRC_MAXON,
       explain=('Peak motor speed against its limit speed (maxon Key information). A rating that already carries the '
                "maker's margin: class limit (default 1.0; raise [requirements.safety_factors] limit for more)."))
def check_motor_max_speed(demand: TorqueDemand, motor: Any = None, *, component: str | None = None) -> CheckResult:
    """Peak motor speed against the limit speed (DC: limit speed, else no-load speed) [1]."""
    m = _motor(demand, motor)
    cap = m.speed_limit
    if cap is None:
        raise InputError(f"{m.name}: no maximum speed known (give max_speed, a pull-out curve or a speed rating)")
    w = np.abs(demand.motor_speed)
    i = int(np.argmax(w))
    return CheckResult(
        check="motor_max_speed", component=component or m.name,
        demand=from_si(float(w[i]), "angular_velocity").to("rpm"),
        capacity=cap.to("rpm"), title="Motor speed within its limit", formula=r"\max|\omega| \le \omega_{max}",
        source=_SRC_MAXON, notes=("capacity: " + ("limit speed" if m.kind == "dc" and m.max_speed is not None
                                                  else "no-load speed / last curve point"),),
        load_case=_case(demand, i), details=_plot(demand, m))


def _gearheads(demand: TorqueDemand, gearhead: Any) -> list[Any]:
    if gearhead is not None:
        return [demand.stage(gearhead)]
    found = [s for s in demand.stages if isinstance(s.stage, Gearhead)]
    if not found:
        raise InputError(f"drive train {demand.train.name!r} has no gearhead")
    return found


@check("gearhead_continuous_torque", title="Gearhead continuous torque", sf_kind="motor",
       source=_SRC_MAXON,
       explain=('RMS output torque of the gearhead against its max. continuous torque (maxon gear Key information). '
                'Margin (motor class, default 1.5): the torque comes from estimated friction, efficiency and load, so'
                " it carries their uncertainty (Oriental Motor: 1.5-2 on a stepper's pull-out torque)."))
def check_gearhead_continuous_torque(demand: TorqueDemand, gearhead: Any = None, *,
                                     component: str | None = None) -> CheckResult:
    """RMS output torque of the gearhead against its max. continuous torque [1]."""
    sd = _gearheads(demand, gearhead)[0]
    g = sd.stage
    if g.continuous_torque is None:
        raise InputError(f"gearhead {g.name!r}: no continuous torque rating")
    Trms = rms(demand.t, sd.output_effort, demand.cycle_time)
    i = int(np.argmax(np.abs(sd.output_effort)))
    return CheckResult(
        check="gearhead_continuous_torque", component=component or g.name, demand=from_si(Trms, "torque"),
        capacity=g.continuous_torque, title="Gearhead RMS output torque within its continuous torque",
        formula=r"T_{out,rms} \le T_{cont}", source=_SRC_MAXON,
        inputs={"ratio": Q(g.ratio), "efficiency": Q(g.efficiency)},
        notes=("output torque includes the load's inertia, gravity and friction, reflected through the stages "
               "beyond the gearhead",), load_case=f"whole cycle (peak at {_case(demand, i)})",
        details={"time": Q(demand.t, "s"), "output_torque": Q(sd.output_effort, "N*m")})


@check("gearhead_intermittent_torque", title="Gearhead intermittent torque", sf_kind="motor",
       source=_SRC_MAXON,
       explain=('Peak output torque of the gearhead against its max. intermittent torque. Margin (motor class, '
                'default 1.5): the torque comes from estimated friction, efficiency and load, so it carries their '
                "uncertainty (Oriental Motor: 1.5-2 on a stepper's pull-out torque)."))
def check_gearhead_intermittent_torque(demand: TorqueDemand, gearhead: Any = None, *,
                                       component: str | None = None) -> CheckResult:
    """Peak output torque of the gearhead against its max. intermittent torque [1]."""
    sd = _gearheads(demand, gearhead)[0]
    g = sd.stage
    if g.intermittent_torque is None:
        raise InputError(f"gearhead {g.name!r}: no intermittent torque rating")
    T = np.abs(sd.output_effort)
    i = int(np.argmax(T))
    return CheckResult(
        check="gearhead_intermittent_torque", component=component or g.name, demand=from_si(float(T[i]), "torque"),
        capacity=g.intermittent_torque, title="Gearhead peak output torque within its intermittent torque",
        formula=r"\max|T_{out}| \le T_{int}", source=_SRC_MAXON, load_case=_case(demand, i),
        details={"time": Q(demand.t, "s"), "output_torque": Q(sd.output_effort, "N*m")})


@check("gearhead_input_speed", title="Gearhead input speed", sf_kind="limit",
       source=_SRC_MAXON,
       explain=("Peak input speed against the gearhead's max. input speed. A rating that already carries the maker's "
                'margin: class limit (default 1.0; raise [requirements.safety_factors] limit for more).'))
def check_gearhead_input_speed(demand: TorqueDemand, gearhead: Any = None, *,
                               component: str | None = None) -> CheckResult:
    """Peak input speed against the gearhead's max. (intermittent if given) input speed [1]."""
    sd = _gearheads(demand, gearhead)[0]
    g = sd.stage
    cap = g.max_input_speed_intermittent or g.max_input_speed
    if cap is None:
        raise InputError(f"gearhead {g.name!r}: no max. input speed rating")
    w = np.abs(sd.input_speed)
    i = int(np.argmax(w))
    notes = ["capacity: max. intermittent input speed" if g.max_input_speed_intermittent is not None
             else "capacity: max. continuous input speed (conservative for short peaks)"]
    return CheckResult(
        check="gearhead_input_speed", component=component or g.name,
        demand=from_si(float(w[i]), "angular_velocity").to("rpm"), capacity=cap.to("rpm"),
        title="Gearhead input speed within its limit", formula=r"\max|\omega_{in}| \le \omega_{in,max}",
        source=_SRC_MAXON, notes=tuple(notes), load_case=_case(demand, i))


@check("inertia_ratio", title="Inertia ratio", sf_kind="limit",
       source=f"{_SRC_ORIENTAL}; {ref('thk')}",
       explain=('Load inertia reflected to the motor, sum J_i/r_i², over the rotor inertia against the limit (default'
                ' 10; Oriental Motor, THK). A serviceability guideline like a deflection limit (class limit, default '
                '1.0): the limit already is the margin. Not for hobby servos.'))
def check_inertia_ratio(demand: TorqueDemand, motor: Any = None, *, max_ratio: float | None = None,
                        component: str | None = None) -> CheckResult:
    """Load inertia reflected to the motor (stages included) over the rotor inertia [2, 3].

    The limit depends on the motor and its control: about 10 for steppers (Oriental Motor), 3-10
    for servo motors (THK); ``max_ratio`` overrides the default 10.
    """
    m = _motor(demand, motor)
    if m.rotor_inertia is None:
        raise InputError(f"{m.name}: no rotor inertia given")
    limit = INERTIA_RATIO_LIMIT if max_ratio is None else float(max_ratio)
    if not limit > 0:
        raise InputError("max_ratio must be positive")
    ratio = demand.load_inertia_at_motor / float(m.rotor_inertia.magnitude)
    return CheckResult(
        check="inertia_ratio", component=component or m.name, demand=Q(ratio), capacity=Q(limit),
        title="Load-to-rotor inertia ratio", formula=r"J_{L}/J_{M} = \frac{\sum J_i/r_i^2}{J_M} \le k",
        source=f"{_SRC_ORIENTAL}; THK, Ball Screw: Studying the Driving Motor",
        inputs={"load inertia at motor": demand.load_inertia.to("g*cm**2"),
                "rotor inertia": m.rotor_inertia.to("g*cm**2")},
        notes=(f"limit {limit:g} ({'default for steppers and servos' if max_ratio is None else 'given'}); "
               "inertia reflected with the square of each ratio, no efficiency",),
        load_case="whole cycle")


@check("motor_supply_voltage", title="Supply voltage", sf_kind="limit",
       source=_SRC_MAXON,
       explain=('DC motors with supply_voltage: U = R(|T|/k_t + I_0) + |omega|/k_n at the worst point against the '
                'supply (maxon): a hard limit (class limit, default 1.0).'))
def check_motor_supply_voltage(demand: TorqueDemand, supply_voltage: QuantityLike, motor: Any = None, *,
                         component: str | None = None) -> CheckResult:
    """DC motor: terminal voltage ``U = R·(|T|/k_t + I_0) + |ω|/k_n`` needed at the worst point
    against the supply (less the driver's drop, if any, given by the caller) [1]."""
    m = _motor(demand, motor)
    if m.kind != "dc":
        raise InputError(f"{m.name}: the voltage check needs a DC motor's constants")
    U = m.voltage_si(demand.motor_torque, demand.motor_speed)
    i = int(np.argmax(U))
    return CheckResult(
        check="motor_supply_voltage", component=component or m.name, demand=from_si(float(U[i]), "voltage"),
        capacity=from_si(to_si(supply_voltage, "voltage", "supply_voltage"), "voltage"),
        title="Supply voltage covers the worst operating point", formula=r"U = R\,(|T|/k_t + I_0) + |\omega|/k_n",
        source=_SRC_MAXON, notes=("conservative when braking (generating), where the needed voltage is lower",),
        load_case=_case(demand, i), details=_plot(demand, m, to_si(supply_voltage, "voltage", "supply_voltage")))


@check("driver_current", title="Driver current", sf_kind="motor",
       source=_SRC_MAXON,
       explain=("With driver_current: I = |T|/k_t + I_0 at the worst point against the driver's current (maxon). "
                'Scales with the torque, so the torque margin applies. Margin (motor class, default 1.5): the torque '
                'comes from estimated friction, efficiency and load, so it carries their uncertainty (Oriental Motor:'
                " 1.5-2 on a stepper's pull-out torque)."))
def check_driver_current(demand: TorqueDemand, max_current: QuantityLike, motor: Any = None, *,
                         component: str | None = None) -> CheckResult:
    """Motor current ``I = |T|/k_t + I_0`` at the worst point against the driver's max. current [1]."""
    m = _motor(demand, motor)
    if not hasattr(m, "current_si"):
        raise InputError(f"{m.name}: no current model for a {m.kind} motor")
    current = m.current_si(demand.motor_torque)
    i = int(np.argmax(current))
    return CheckResult(
        check="driver_current", component=component or m.name, demand=from_si(float(current[i]), "current"),
        capacity=from_si(to_si(max_current, "current", "max_current"), "current"),
        title="Driver current covers the worst operating point",
        formula=r"I = |T|/k_t + I_0 \le I_{driver}" if m.kind == "dc" else r"I = I_0 + (I_H - I_0)\,|T|/T_H",
        source=_SRC_MAXON, load_case=_case(demand, i))


def motor_fit_checks(demand: TorqueDemand, *, supply_voltage: Any = None, driver_current: Any = None,
                     margin: float | None = None, max_inertia_ratio: float | None = None) -> ResultSet:
    """Every motor-fit check that the data allow, as a :class:`ResultSet`.

    A check whose rating is missing (no rotor inertia, no gearhead speed limit, ...) is left out;
    the peak-torque check is always run.
    """
    m = _motor(demand, None)
    results = [check_motor_peak_torque(demand, margin=margin, supply_voltage=supply_voltage)]

    def maybe(fn: Any, *args: Any, **kw: Any) -> None:
        try:
            results.append(fn(demand, *args, **kw))
        except InputError:
            pass

    if m.kind != "stepper":
        maybe(check_motor_rms_torque)
    maybe(check_motor_max_speed)
    maybe(check_inertia_ratio, max_ratio=max_inertia_ratio)
    for sd in demand.stages:
        if isinstance(sd.stage, Gearhead):
            maybe(check_gearhead_continuous_torque, sd.stage)
            maybe(check_gearhead_intermittent_torque, sd.stage)
            maybe(check_gearhead_input_speed, sd.stage)
    if supply_voltage is not None and m.kind == "dc":
        results.append(check_motor_supply_voltage(demand, supply_voltage))
    if driver_current is not None:
        maybe(check_driver_current, driver_current)
    return ResultSet(results, name=demand.train.name)


__all__ = ["check_motor_peak_torque", "check_motor_rms_torque", "check_motor_max_speed",
           "check_gearhead_continuous_torque", "check_gearhead_intermittent_torque", "check_gearhead_input_speed",
           "check_inertia_ratio",
           "check_motor_supply_voltage", "check_driver_current", "motor_fit_checks", "STEPPER_MARGIN",
           "INERTIA_RATIO_LIMIT"]
