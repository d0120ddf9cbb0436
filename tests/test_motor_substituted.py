"""Every motor and gearhead check prints a substituted line (symbol = formula with the numbers and units =
result) that evaluates back to its result (the parser of tests/test_reports_substituted.py; a consistency check
of the printed line against the check's own result, no published number involved)."""

from __future__ import annotations

import dataclasses

from test_reports_substituted import assert_substituted

from mechverify.checks import motors as mc
from mechverify.components.gearheads import gearhead
from mechverify.components.motors import motor
from mechverify.components.transmissions import DirectDrive
from mechverify.motion.drive_train import DriveTrain, RotaryLoad
from mechverify.motion.profiles import trapezoidal

M6T = dataclasses.replace(motor("maxon 6V 10.3 mNm"), thermal_time_constant_winding="8 s",
                          thermal_time_constant_motor="300 s")


def _demand(m, stage=None, torque="2 mN*m"):
    tr = DriveTrain(m, (stage or DirectDrive(),), RotaryLoad("1e-5 kg*m**2", external_torque=torque))
    return tr.demand(trapezoidal("900 rad", max_velocity="600 rad/s", acceleration="600 rad/s**2"), cycle_time="4 s")


def test_dc_motor_checks_substituted():
    d = _demand(M6T)
    rs = [mc.check_motor_peak_torque(d), mc.check_motor_rms_torque(d), mc.check_motor_max_speed(d),
          mc.check_inertia_ratio(d), mc.check_motor_supply_voltage(d, "6 V"), mc.check_driver_current(d, "2 A"),
          mc.check_motor_winding_temperature(d), mc.check_drive_regeneration(d, "6 V", "1000 uF", "7 V")]
    for r in rs:
        assert_substituted(r)


def test_stepper_and_gearhead_checks_substituted():
    g = dataclasses.replace(gearhead("maxon GP 13 A 17:1"), max_input_speed="8000 rpm")  # rating absent in the row
    d = _demand(M6T, g, torque="20 mN*m")
    rs = [fn(d) for fn in (mc.check_gearhead_continuous_torque, mc.check_gearhead_intermittent_torque,
                           mc.check_gearhead_input_speed)]
    for r in rs:
        assert_substituted(r)
    s = _demand(motor("stepper 004"))
    for r in (mc.check_motor_peak_torque(s), mc.check_driver_current(s, "2 A")):
        assert_substituted(r)

