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
from mechverify.checks.result import CheckResult, ResultSet, tex, tex_minus
from mechverify.components.gearheads import Gearhead
from mechverify.components.motors import ALPHA_CU, thermal_data, winding_temperature_cycle
from mechverify.errors import InputError
from mechverify.motion.drive_train import TorqueDemand, rms
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, from_si, si_to, to_si

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


def _sf_line(capacity: Any, demand: Any, unit: str | None = None) -> str:
    """S = capacity/demand with both numbers and units (the check's safety factor); "" when demand is 0."""
    d = float(Q(demand).to(unit).magnitude if unit else Q(demand).magnitude)
    c = float(Q(capacity).to(unit).magnitude if unit else Q(capacity).magnitude)
    if not d > 0:
        return ""
    return rf"S = \frac{{{tex(Q(capacity), unit)}}}{{{tex(Q(demand), unit)}}} = {tex(c / d)}"


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
    # T/avail where the motor has torque, else inf (T > 0) or 0: divided only where avail > 0 (no warnings)
    u = np.divide(T, avail, out=np.where(T > 0, np.inf, 0.0), where=avail > 0)
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
        notes=tuple(notes), warnings=tuple(warnings), load_case=_case(demand, i), details=lambda: _plot(demand, m, U),
        substituted=lambda: _sf_line(from_si(float(avail[i]), "torque"), from_si(float(T[i]), "torque"), "N*m"))


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
        warnings=tuple(warnings), load_case=f"whole cycle (peak at {_case(demand, i)})",
        details=lambda: _plot(demand, m),
        substituted=lambda: _sf_line(cap, Trms, "N*m"))


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
        demand=si_to(float(w[i]), "angular_velocity", "rpm"),
        capacity=cap.to("rpm"), title="Motor speed within its limit", formula=r"\max|\omega| \le \omega_{max}",
        source=_SRC_MAXON, notes=("capacity: " + ("limit speed" if m.kind == "dc" and m.max_speed is not None
                                                  else "no-load speed / last curve point"),),
        load_case=_case(demand, i), details=lambda: _plot(demand, m),
        substituted=lambda: _sf_line(cap, from_si(float(w[i]), "angular_velocity"), "rpm"))


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
        details=lambda: {"time": Q(demand.t, "s"), "output_torque": Q(sd.output_effort, "N*m")},
        substituted=lambda: _sf_line(g.continuous_torque, from_si(Trms, "torque"), "N*m"))


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
        details=lambda: {"time": Q(demand.t, "s"), "output_torque": Q(sd.output_effort, "N*m")},
        substituted=lambda: _sf_line(g.intermittent_torque, from_si(float(T[i]), "torque"), "N*m"))


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
        source=_SRC_MAXON, notes=tuple(notes), load_case=_case(demand, i),
        substituted=lambda: _sf_line(cap, from_si(float(w[i]), "angular_velocity"), "rpm"))


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
        load_case="whole cycle",
        substituted=lambda: (rf"\frac{{J_L}}{{J_M}} = \frac{{{tex(demand.load_inertia, 'g*cm**2')}}}"
                     rf"{{{tex(m.rotor_inertia, 'g*cm**2')}}} = {tex(ratio)}"))


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
        load_case=_case(demand, i),
        details=lambda: _plot(demand, m, to_si(supply_voltage, "voltage", "supply_voltage")),
        substituted=lambda: _voltage_line(m, float(demand.motor_torque[i]), float(demand.motor_speed[i]), float(U[i])))


def _voltage_line(m: Any, T: float, w: float, U: float) -> str:
    """U = R (|T|/k_t + I_0) + |omega|/k_n with the motor's constants (maxon)."""
    R = from_si(to_si(m.terminal_resistance, "resistance"), "resistance")
    kt = from_si(to_si(m.torque_constant, "torque_constant"), "torque_constant")
    kn = from_si(to_si(m.speed_constant, "speed_constant"), "speed_constant")
    I0 = Q(to_si(m.no_load_current, "current") if m.no_load_current is not None else 0.0, "A")
    return (rf"U = {tex(R, 'ohm')}\cdot \left(\frac{{{tex(Q(abs(T), 'N*m'), 'mN*m')}}}{{{tex(kt, 'mN*m/A')}}} + "
            rf"{tex(I0, 'A')}\right) + \frac{{{tex(Q(abs(w), 'rad/s'), 'rpm')}}}{{{tex(kn, 'rpm/V')}}} = "
            rf"{tex(Q(U, 'V'), 'V')}")


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
        formula={"dc": r"I = |T|/k_t + I_0 \le I_{driver}", "stepper": r"I = I_{rated,phase} \le I_{driver}"}.get(
            m.kind, r"I = I_0 + (I_H - I_0)\,|T|/T_H"),
        source=_SRC_MAXON, load_case=_case(demand, i),
        substituted=lambda: _sf_line(from_si(to_si(max_current, "current", "max_current"), "current"),
                             from_si(float(current[i]), "current"), "A"))


def _celsius(value: QuantityLike, name: str) -> float:
    q = Q(value) if isinstance(value, str) else value
    try:
        return float(q.to("degC").magnitude)
    except Exception as exc:  # pint raises several types for a wrong or unitless value
        raise InputError(f"{name}: expected a temperature such as '25 degC', got {value!r}") from exc


@check("motor_winding_temperature", title="Motor winding temperature over the duty cycle", sf_kind="limit",
       source=ref("maxon", "'maxon DC motor: Key information', thermal data and R(T) with alpha_Cu = 0.0039/K"),
       explain=("Peak winding temperature over the thermally periodic duty cycle against the motor's max. winding "
                "temperature: a two-node network (winding-housing R_th1, tau_w; housing-ambient R_th2, tau_s) "
                "heated by I^2 R(T), I = |T|/k_t + I_0, R(T) = R_25 (1 + 0.0039 (T - 25 degC)), the cycle repeated "
                "until periodic (solved exactly). Class limit: the maker's limit already is the rating. DC motors "
                "with thermal data only; steppers need the maker's temperature-rise data."))
def check_motor_winding_temperature(demand: TorqueDemand, motor: Any = None, *,
                                    ambient_temperature: QuantityLike = "25 degC",
                                    component: str | None = None) -> CheckResult:
    """Peak winding temperature of the periodic duty cycle against the max. winding temperature [1].

    The demand is the winding's rise above ambient as a share of the allowed rise (T_peak − T_U)/(T_max − T_U),
    the capacity 1, so that a required SF applies to the rise, not to a temperature on an arbitrary scale;
    the temperatures themselves are in the notes and details. (Reported as a ratio because the report's
    number formatter shows every temperature as an absolute °C value.)
    """
    m = _motor(demand, motor)
    Rth1, Rth2, tw, ts, Tmax = thermal_data(m)
    Ta = _celsius(ambient_temperature, "ambient_temperature")
    if not Tmax > Ta:
        raise InputError(f"{m.name}: ambient {Ta:g} degC is not below the max. winding temperature {Tmax:g} degC")
    current = m.current_si(demand.motor_torque)
    R25 = float(m.terminal_resistance.m_as("ohm"))
    th = winding_temperature_cycle(demand.t, current, R25, Rth1, Rth2, tw, ts, ambient=Ta)
    Irms = rms(demand.t, current, demand.cycle_time)
    return CheckResult(
        check="motor_winding_temperature", component=component or m.name,
        demand=Q((th.peak_winding - Ta) / (Tmax - Ta)), capacity=Q(1.0),
        title="Motor winding temperature over the duty cycle",
        formula=r"C_w \dot T_w = I^2 R_{25}(1+\alpha(T_w-25)) - \frac{T_w-T_h}{R_{th1}},\ "
                r"C_s \dot T_h = \frac{T_w-T_h}{R_{th1}} - \frac{T_h-T_U}{R_{th2}}",
        source=_SRC_MAXON,
        inputs={"R_th1": m.thermal_resistance_winding_housing, "R_th2": m.thermal_resistance_housing_ambient,
                "tau_w": m.thermal_time_constant_winding, "tau_s": m.thermal_time_constant_motor,
                "ambient": Q(Ta, "degC"), "R_25": m.terminal_resistance},
        notes=(f"rise {th.peak_winding - Ta:.1f} K of the allowed {Tmax - Ta:.1f} K: peak winding temperature "
               f"{th.peak_winding:.1f} degC (max. {Tmax:g} degC) at ambient {Ta:g} degC; "
               f"housing {float(np.max(th.housing)):.1f} degC", f"RMS current {Irms:.3g} A, mean Joule loss "
               f"{th.steady_mean_power:.3g} W over the periodic cycle (alpha_Cu = {ALPHA_CU}/K)",
               "the duty cycle repeats without pause beyond the given cycle time; iron and friction losses "
               "are not in the model (I_0 heats the winding as current)"),
        load_case=f"whole cycle (peak at {_case(demand, th.peak_index)})",
        substituted=lambda: (rf"\frac{{T_w - T_U}}{{T_{{max}} - T_U}} = \frac{{{tex_minus(th.peak_winding, Ta)}}}"
                     rf"{{{tex_minus(Tmax, Ta)}}} = {tex((th.peak_winding - Ta) / (Tmax - Ta))}"),
        details=lambda: {"time": Q(th.t, "s"), "winding_temperature": Q(th.winding, "degC"),
                 "housing_temperature": Q(th.housing, "degC")})


@check("drive_regeneration", title="Bus voltage rise from regeneration", sf_kind="limit",
       source=f"{_SRC_MAXON}; capacitor energy E = C (U^2 - U0^2)/2",
       explain=("Energy a DC motor returns while braking or lowering (generating: T·omega < 0), P = -T·omega - I^2 R, "
                "integrated over each braking interval; the supply's capacitance C absorbs it, U = sqrt(U0^2 + 2E/C), "
                "against the driver's overvoltage limit. The braking-resistor energy and mean power needed when it "
                "does not fit are in the notes. Conservative: friction and driver losses are not subtracted."))
def check_drive_regeneration(demand: TorqueDemand, supply_voltage: QuantityLike, capacitance: QuantityLike,
                             overvoltage_limit: QuantityLike, motor: Any = None, *,
                             component: str | None = None) -> CheckResult:
    """Bus voltage after the largest braking interval against the driver's overvoltage limit."""
    m = _motor(demand, motor)
    if m.kind != "dc":
        raise InputError(f"{m.name}: the regeneration check needs a DC motor's k_t and R")
    U0 = to_si(supply_voltage, "voltage", "supply_voltage")
    Ulim = to_si(overvoltage_limit, "voltage", "overvoltage_limit")
    Cq = Q(capacitance) if isinstance(capacitance, str) else capacitance
    try:
        C = float(Cq.to("F").magnitude)
    except Exception as exc:
        raise InputError(f"capacitance: expected a capacitance such as '1000 uF', got {capacitance!r}") from exc
    if not (C > 0 and U0 > 0 and Ulim > U0):
        raise InputError("regeneration: capacitance and supply voltage must be positive and the overvoltage limit "
                         "above the supply voltage")
    T, w, t = demand.motor_torque, demand.motor_speed, demand.t
    kt, R = float(m.torque_constant.m_as("N*m/A")), float(m.terminal_resistance.m_as("ohm"))
    P = np.clip(-T * w - (T / kt) ** 2 * R, 0.0, None)  # power back to the bus [W]
    # energy of each contiguous generating interval (trapezoids between samples)
    seg = 0.5 * (P[1:] + P[:-1]) * np.diff(t)
    events, cur, worst_end = [], 0.0, 0
    for j, e in enumerate(seg):
        if e > 0:
            cur += e
        elif cur > 0:
            events.append((cur, j))
            cur = 0.0
    if cur > 0:
        events.append((cur, len(seg)))
    E, worst_end = max(events, default=(0.0, 0))
    U = float(np.sqrt(U0**2 + 2 * E / C))
    absorb = 0.5 * C * (Ulim**2 - U0**2)
    excess = sum(max(0.0, e - absorb) for e, _ in events)
    notes = [f"largest braking interval returns {E:.4g} J; the capacitance absorbs {absorb:.4g} J up to the limit",
             f"peak regenerated power {float(np.max(P)):.4g} W"]
    if excess > 0:
        notes.append(f"braking resistor (or shunt) needed: {excess:.4g} J per cycle above what C absorbs, mean "
                     f"{excess / demand.cycle_time:.4g} W, peak {float(np.max(P)):.4g} W")
    return CheckResult(
        check="drive_regeneration", component=component or m.name, demand=Q(U, "V"), capacity=Q(Ulim, "V"),
        title="Bus voltage rise from regeneration", formula=r"U = \sqrt{U_0^2 + 2E/C} \le U_{max}",
        source=f"{_SRC_MAXON}; capacitor energy E = C (U^2 - U0^2)/2",
        inputs={"U0": Q(U0, "V"), "C": Q(C * 1e6, "uF"), "U_max": Q(Ulim, "V")}, notes=tuple(notes),
        load_case=_case(demand, min(worst_end, len(t) - 1)) if events else "no braking in the cycle",
        details=lambda: {"time": Q(t, "s"), "regenerated_power": Q(P, "W")},
        substituted=lambda: (rf"U = \sqrt{{({tex(Q(U0, 'V'), 'V')})^{{2}} + \frac{{2\cdot {tex(Q(E, 'J'), 'J')}}}"
                     rf"{{{tex(Q(C, 'F'), 'F')}}}}} = {tex(Q(U, 'V'), 'V')}"))


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
           "check_inertia_ratio", "check_motor_winding_temperature", "check_drive_regeneration",
           "check_motor_supply_voltage", "check_driver_current", "motor_fit_checks", "STEPPER_MARGIN",
           "INERTIA_RATIO_LIMIT"]
