"""Motor winding temperature over a duty cycle, efficiency and regeneration.

Sources: maxon motor ag, "maxon DC motor: Key information" (thermal data, R(T) with alpha_Cu = 0.0039/K,
eta_max = (1 - sqrt(I0/I_A))^2). No printed maxon duty-cycle temperature was found in the search corpora,
so the temperatures are tested against hand calculations (closed-form steady state) and an independent
numerical integration of the same network (scipy solve_ivp over repeated cycles), each stated as such.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from mechverify.checks.motors import check_drive_regeneration, check_motor_winding_temperature
from mechverify.components.motors import (
    StepperMotor,
    inertia_matching_ratio,
    microstep_incremental_torque,
    motor,
    operating_efficiency,
    optimal_ratio,
    steady_winding_temperature,
    stepper_datasheet_relations,
    stepper_datasheet_warnings,
    stepper_resolution,
    winding_temperature_cycle,
)
from mechverify.components.transmissions import DirectDrive
from mechverify.errors import InputError, ValidityError
from mechverify.motion.drive_train import DriveTrain, RotaryLoad
from mechverify.motion.profiles import trapezoidal

M6 = motor("maxon 6V 10.3 mNm")  # R_th1 = 6.5, R_th2 = 17.6 K/W, 100 degC, R = 1.47 ohm (catalogue data)
M6T = dataclasses.replace(M6, thermal_time_constant_winding="8 s", thermal_time_constant_motor="300 s")


def test_steady_state_closed_form_hand_calculation():
    """Hand calculation (maxon steady state with R(T)): I = 1.2 A, R_th = 24.1 K/W, R_25 = 1.47 ohm:
    k = 24.1*1.47*1.44 = 51.01 K; T_W = (25 + 51.01*(1 - 0.0975)) / (1 - 0.0039*51.01) = 88.7 degC."""
    k = 24.1 * 1.47 * 1.2**2
    assert (25 + k * (1 - 0.0039 * 25)) / (1 - 0.0039 * k) == pytest.approx(88.7, abs=0.05)
    assert steady_winding_temperature(1.47, 1.2, 6.5, 17.6) == pytest.approx(88.7, abs=0.05)
    # constant current through the transient model: the periodic state is the steady state
    r = winding_temperature_cycle(np.array([0.0, 10.0]), np.array([1.2, 1.2]), 1.47, 6.5, 17.6, 8.0, 300.0)
    assert r.peak_winding == pytest.approx(steady_winding_temperature(1.47, 1.2, 6.5, 17.6), rel=1e-9)
    assert r.housing[0] == pytest.approx(25 + 17.6 * (r.peak_winding - r.housing[0]) / 6.5, rel=1e-9)


def test_periodic_state_matches_repeated_cycles_integrated_independently():
    """On/off cycle (2 A for 3 s, 0 A for 7 s), tau_s = 60 s so that 60 cycles settle: solve_ivp over the
    repeated cycles (RK45, tight tolerances; 250 cycles, many times the network's slow time constant) against
    the exact periodic solution; peak within 0.01 K."""
    R25, R1, R2, tw, ts = 1.47, 6.5, 17.6, 8.0, 60.0
    t = np.array([0.0, 3.0, 3.0, 10.0])
    current = np.array([2.0, 2.0, 0.0, 0.0])
    r = winding_temperature_cycle(t, current, R25, R1, R2, tw, ts)
    Cw, Cs = tw / R1, ts / R2

    def rhs(tt, x):
        i = 2.0 if (tt % 10.0) < 3.0 else 0.0
        p = i * i * R25 * (1 + 0.0039 * (x[0] - 25))
        return [(p - (x[0] - x[1]) / R1) / Cw, ((x[0] - x[1]) / R1 - (x[1] - 25) / R2) / Cs]

    x = [25.0, 25.0]
    for _ in range(250):
        a = solve_ivp(rhs, (0, 3), x, rtol=1e-10, atol=1e-10, max_step=0.25)
        b = solve_ivp(rhs, (3, 10), a.y[:, -1], rtol=1e-10, atol=1e-10, max_step=0.25)
        peak, x = a.y[0, -1], b.y[:, -1]
    assert r.peak_winding == pytest.approx(peak, abs=0.01)
    assert r.winding[0] == pytest.approx(x[0], abs=0.01)


def test_fast_cycle_linear_model_averages_to_rms_current():
    """alpha = 0 (linear network), a cycle much shorter than tau_w: the mean winding temperature is the
    steady state of the RMS current, T = T_U + R_th R I_rms^2 (hand calculation: 25 + 24.1*1.47*2 = 95.85)."""
    t = np.array([0.0, 0.05, 0.05, 0.1])
    current = np.array([2.0, 2.0, 0.0, 0.0])  # I_rms^2 = 2 A^2
    r = winding_temperature_cycle(t, current, 1.47, 6.5, 17.6, 8.0, 300.0, alpha=0.0)
    assert float(np.mean(r.winding)) == pytest.approx(25 + 24.1 * 1.47 * 2, abs=0.01)


def test_runaway_and_bad_input():
    with pytest.raises(ValidityError, match="runaway"):
        steady_winding_temperature(1.47, 6.0, 6.5, 17.6)
    with pytest.raises(ValidityError, match="runaway"):
        winding_temperature_cycle(np.array([0.0, 1.0]), np.array([6.0, 6.0]), 1.47, 6.5, 17.6, 8.0, 300.0)
    with pytest.raises(InputError):
        winding_temperature_cycle(np.array([0.0, 1.0]), np.array([1.0]), 1.47, 6.5, 17.6, 8.0, 300.0)


def _hold_demand(m, force="2 N", cycle="20 s"):
    tr = DriveTrain(m, (DirectDrive(),), RotaryLoad("1e-6 kg*m**2", external_torque=force.replace("N", "mN*m")))
    prof = trapezoidal("10 rad", max_velocity="20 rad/s", acceleration="200 rad/s**2")
    return tr.demand(prof, cycle_time=cycle)


def test_check_winding_temperature_and_named_errors():
    d = _hold_demand(M6T, "8 N")
    r = check_motor_winding_temperature(d)
    assert r.check == "motor_winding_temperature" and r.capacity.m_as("") == 1.0
    I = M6T.current_si(d.motor_torque)
    th = winding_temperature_cycle(d.t, I, 1.47, 6.5, 17.6, 8.0, 300.0)
    assert r.demand.m_as("") == pytest.approx((th.peak_winding - 25) / 75, rel=1e-12)
    hot = check_motor_winding_temperature(d, ambient_temperature="60 degC")
    assert hot.utilisation > r.utilisation
    with pytest.raises(InputError, match="thermal_time_constant_winding"):
        check_motor_winding_temperature(_hold_demand(M6))
    with pytest.raises(InputError, match="not available for steppers"):
        check_motor_winding_temperature(_hold_demand(motor("stepper 004")))


def test_operating_efficiency_peaks_at_eta_max():
    """maxon: on the speed-torque line at nominal voltage the efficiency is highest at I = sqrt(I0 I_A) and
    equals (1 - sqrt(I0/I_A))^2 (hand derivation from eta = (I - I0)(U - R I)/(U I) with k_t k_n = 1)."""
    m = M6
    I0, IA = m.no_load_current.m_as("A"), m.stall_current.m_as("A")
    kt = m.torque_constant.m_as("N*m/A")
    M = np.linspace(0.0, m.stall_torque.m_as("N*m") * 0.99, 4001)
    w = m.speed_constant.m_as("rad/s/V") * (6.0 - 1.47 * m.current_si(M))
    eta = operating_efficiency(m, M, w)
    j = int(np.argmax(eta))
    assert eta[j] == pytest.approx((1 - math.sqrt(I0 / IA)) ** 2, rel=2e-3)
    assert m.current_si(M[j]) == pytest.approx(math.sqrt(I0 * IA), rel=0.02)
    assert kt > 0


def test_regeneration_hand_calculation():
    """Decelerating an inertia with the 6 V maxon motor (k_t = 8.91 mN m/A, R = 1.47 ohm, rotor 2.68 g cm^2)
    and a load J = 1e-5 kg m^2 from 600 rad/s at 600 rad/s^2: T = J a, I = T/k_t; the motor
    returns P = k_t I w - I^2 R while w > w_c = I R/k_t. Hand calculation:
    E = k_t I (w0^2 - w_c^2)/(2 a) - I^2 R (w0 - w_c)/a, U = sqrt(U0^2 + 2E/C)."""
    m = motor("maxon 6V 10.3 mNm")
    J = 1e-5 + 2.68e-7
    tr = DriveTrain(m, (DirectDrive(),), RotaryLoad("1e-5 kg*m**2"))
    d = tr.demand(trapezoidal("900 rad", max_velocity="600 rad/s", acceleration="600 rad/s**2"),
                  points_per_segment=401)
    kt, R, a, w0 = 8.91e-3, 1.47, 600.0, 600.0
    I = J * a / kt
    wc = I * R / kt
    E = kt * I * (w0**2 - wc**2) / (2 * a) - I**2 * R * (w0 - wc) / a
    assert E == pytest.approx(1.212, abs=0.001)  # 1.7814 - 0.5691 J
    r = check_drive_regeneration(d, "6 V", "1000 uF", "7 V")
    assert r.demand.m_as("V") == pytest.approx(math.sqrt(36 + 2 * E / 1e-3), rel=2e-3)
    assert r.verdict.value == "fail" and any("braking resistor" in n for n in r.notes)
    big = check_drive_regeneration(d, "6 V", "1 F", "7 V")
    assert big.demand.m_as("V") == pytest.approx(math.sqrt(36 + 2 * E), rel=1e-3)
    assert big.verdict.value == "pass"
    with pytest.raises(InputError):
        check_drive_regeneration(d, "6 V", "1000 uF", "5 V")
    with pytest.raises(InputError, match="DC motor"):
        check_drive_regeneration(_hold_demand(motor("stepper 004")), "24 V", "1000 uF", "30 V")


# ------------------------------------------------------------------------------ steppers
def test_stepper_datasheet_u_equals_i_r():
    """SureStep STP-42D3018 as transcribed in reference project 000: 8.8 V, 0.64 A, 11.6 ohm; hand calculation
    0.64*11.6 = 7.42 V, so the transcribed 8.8 V is +18.5 % off (reported, not raised: the catalogue row
    stays usable)."""
    m = motor("STP-42D3018")
    rel = stepper_datasheet_relations(m)["rated voltage = rated current * phase resistance"]
    assert rel[1] == pytest.approx(0.64 * 11.6)
    w = stepper_datasheet_warnings(m)
    assert len(w) == 1 and "+18.5 %" in w[0]
    ok = StepperMotor("x", step_angle="1.8 deg", holding_torque="0.5 N*m", rated_current="1 A",
                      phase_resistance="3 ohm", rated_voltage="3.05 V")
    assert stepper_datasheet_warnings(ok) == ()


def test_microstep_torque_and_resolution():
    """sin(90 deg/mu): 70.71 %, 38.27 %, 19.51 %, 9.80 %, 4.91 % for mu = 2..32 (the table of the Micromo /
    MachineDesign article, read here from a forum copy of it). Resolution: 1.8 deg / (16 * 5) = 0.0225 deg;
    through a 2 mm lead screw 0.0225/360 * 2 mm = 0.125 um (hand calculation)."""
    for mu, pct in ((1, 100.0), (2, 70.71), (4, 38.27), (8, 19.51), (16, 9.80), (32, 4.91)):
        assert microstep_incremental_torque("1 N*m", mu).m_as("N*m") * 100 == pytest.approx(pct, abs=0.006)
    assert stepper_resolution("1.8 deg", microsteps=16, ratio=5).m_as("deg") == pytest.approx(0.0225)
    assert stepper_resolution("1.8 deg", microsteps=16, ratio=5, lead="2 mm").m_as("um") == pytest.approx(0.125)
    with pytest.raises(InputError):
        microstep_incremental_torque("1 N*m", 0)
    with pytest.raises(InputError):
        stepper_resolution("1.8 deg", ratio=0)


def test_inertia_matching_and_optimal_ratio():
    """Pure inertia: T_m = (J_M i + J_L/i) alpha_out is least at i = sqrt(J_L/J_M) (hand derivation):
    J_L = 0.01, J_M = 1e-4 kg m^2 -> i = 10. With a constant output torque T_L added the RMS of the cycle
    (accelerate then hold, equal times) is minimised numerically and must beat the ratios next to it."""
    assert inertia_matching_ratio("0.01 kg*m**2", "1e-4 kg*m**2") == pytest.approx(10.0)
    JM, JL, a = 1e-4, 0.01, 50.0
    i, T = optimal_ratio(lambda r: (JM * r + JL / r) * a, 1.0, 100.0)
    assert i == pytest.approx(10.0, rel=1e-5) and T == pytest.approx(2 * math.sqrt(JM * JL) * a, rel=1e-9)

    def cycle_rms(r, TL=2.0):
        return math.sqrt(0.5 * ((JM * r + JL / r) * a + TL / r) ** 2 + 0.5 * (TL / r) ** 2)

    i2, T2 = optimal_ratio(cycle_rms, 1.0, 1000.0)
    assert T2 <= cycle_rms(i2 * 1.01) and T2 <= cycle_rms(i2 / 1.01) and i2 > 10
    with pytest.raises(InputError):
        inertia_matching_ratio("0 kg*m**2", "1e-4 kg*m**2")


# ------------------------------------------------------------------------------ design files
_DRIVE = """
[design]
name = "thermal"
[profiles.move]
type = "trapezoidal"
distance = "10 rad"
max_velocity = "20 rad/s"
acceleration = "200 rad/s^2"
[components.d]
type = "drive"
motor_data = {{ type = "dc", name = "m6", nominal_voltage = "6 V", no_load_current = "52.9 mA", nominal_torque = "10.3 mN*m", terminal_resistance = "1.47 ohm", torque_constant = "8.91 mN*m/A", rotor_inertia = "2.68 g*cm^2", thermal_resistance_housing_ambient = "17.6 K/W", thermal_resistance_winding_housing = "6.5 K/W", max_winding_temperature = "100 degC"{extra_motor} }}
inertia = "1e-6 kg*m^2"
external_torque = "8 mN*m"
profile = "move"
cycle_time = "20 s"
supply_voltage = "6 V"
{extra}
"""


def _drive_design(tmp_path, extra="", extra_motor=', thermal_time_constant_winding = "8 s", '
                  'thermal_time_constant_motor = "300 s"'):
    from mechverify.design import load
    p = tmp_path / "d.toml"
    p.write_text(_DRIVE.format(extra=extra, extra_motor=extra_motor))
    return load(p)


def test_design_drive_thermal_and_regeneration(tmp_path):
    """The design-file drive runs motor_winding_temperature when the motor has thermal data and
    drive_regeneration with bus_capacitance and overvoltage_limit; the numbers are the API's."""
    from mechverify.design import DesignFileError
    d = _drive_design(tmp_path, 'bus_capacitance = "1000 uF"\novervoltage_limit = "7 V"\nambient_temperature = "40 degC"')
    rs = d.verify()
    th = rs.get("d", "motor_winding_temperature")
    assert th.inputs["ambient"].m_as("degC") == 40
    assert rs.get("d", "drive_regeneration").capacity.m_as("V") == 7
    no_data = _drive_design(tmp_path, extra_motor="").verify()
    assert not [r for r in no_data if r.check in ("motor_winding_temperature", "drive_regeneration")]
    with pytest.raises(DesignFileError, match="thermal_time_constant_winding"):
        _drive_design(tmp_path, "checks = { motor_winding_temperature = true }", extra_motor="").verify()
    with pytest.raises(DesignFileError, match="bus_capacitance"):
        _drive_design(tmp_path, 'bus_capacitance = "7 V"\novervoltage_limit = "7 V"')


def test_stepper_driver_current_is_the_rated_phase_current():
    """A chopper driver holds the stepper's phase current at its setting whatever the torque (Oriental Motor):
    the 004 stepper's rated 1.7 A against a 1.5 A and a 2 A driver."""
    from mechverify.checks.motors import check_driver_current
    d = _hold_demand(motor("stepper 004"))
    assert check_driver_current(d, "1.5 A").verdict.value == "fail"
    r = check_driver_current(d, "2 A")
    assert r.verdict.value == "pass" and r.demand.m_as("A") == pytest.approx(1.7)
    with pytest.raises(InputError, match="rated_current"):
        check_driver_current(_hold_demand(StepperMotor("s", step_angle="1.8 deg", holding_torque="0.5 N*m",
                                                       pullout_speeds=["0 rpm", "600 rpm"],
                                                       pullout_torques=["0.4 N*m", "0.2 N*m"])), "2 A")
