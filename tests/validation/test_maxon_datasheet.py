"""maxon's datasheet relations on real catalogue entries, and exact datasheet unit conversions.

Sources
-------
* maxon motor ag, "maxon DC motor and maxon EC motor: Key information" (catalogue section):
  k_n·k_M = 30 000/π (k_n in rpm/V, k_M in mNm/A); M_H = k_M·I_A; I_A = U_N/R;
  Δn/ΔM = (30 000/π)·R/k_M² [rpm/mNm]; n_0 = k_n·(U_N − I_0·R); τ_m = J_R·R/k_M².
* maxon support article "Motor constants": k_n and k_M are inverse of each other in SI units.
* Catalogue data: RE 35 Ø35 mm graphite brushes 90 W, order no. 273762 (48 V), as printed in
  reference project 001, Table 8; the 6 V maxon motor of reference project 003, Fig. 12.
* Exact unit definitions: kgf = 9.80665 N (3rd CGPM 1901), ozf·in = 0.45359237/16 kg · g_n ·
  0.0254 m, rpm = 2π/60 rad/s (NIST SP 811, Appendix B.8).
"""

import math

import pytest

from mechverify.components.motors import DCMotor, motor
from mechverify.errors import InputError
from mechverify.units import Q

RPM = 2 * math.pi / 60
G0 = 9.80665
OZF_IN = 0.45359237 / 16 * G0 * 0.0254


@pytest.fixture
def re35():
    return motor("maxon RE 35 273762")


def test_re35_kn_times_kM_is_30000_over_pi(re35):
    # maxon units: 44.7 rpm/V * 214 mNm/A = 9565.8 vs 30000/pi = 9549.3 (0.17 %)
    kn_rpm_per_V = re35.speed_constant.m_as("rpm/V")
    kM_mNm_per_A = re35.torque_constant.m_as("mN*m/A")
    assert kn_rpm_per_V * kM_mNm_per_A == pytest.approx(30000 / math.pi, rel=2e-3)
    # SI: k_n [rad/s/V] = 1 / k_M [N m/A]
    assert re35.speed_constant.m_as("rad/s/V") * re35.torque_constant.m_as("N*m/A") == pytest.approx(1, rel=2e-3)


def test_re35_stall_torque_and_current(re35):
    # I_A = U/R = 48/40.2 = 1.194 A (datasheet 1.19 A); M_H = k_M I_A = 255.5 mNm (datasheet 255 mNm)
    assert 48 / 40.2 == pytest.approx(re35.stall_current.m_as("A"), rel=5e-3)
    assert 214 * 48 / 40.2 == pytest.approx(re35.stall_torque.m_as("mN*m"), rel=5e-3)


def test_re35_speed_torque_gradient(re35):
    # (30000/pi) R / k_M^2 = 9549.3 * 40.2 / 214^2 = 8.38 rpm/mNm (datasheet 8.4)
    grad = 30000 / math.pi * 40.2 / 214**2
    assert grad == pytest.approx(8.4, abs=0.03)
    assert re35.speed_torque_gradient.m_as("rpm/(mN*m)") == pytest.approx(8.4, rel=1e-12)


def test_re35_no_load_speed_and_time_constant(re35):
    # n0 = k_n (U - I0 R) = 44.7 (48 - 0.0172*40.2) = 2114.7 rpm (datasheet 2110)
    assert 44.7 * (48 - 0.0172 * 40.2) == pytest.approx(2110, rel=3e-3)
    # tau_m = J R / kM^2 = 61.2e-7 * 40.2 / 0.214^2 = 5.37 ms (datasheet 5.39 ms)
    assert 61.2e-7 * 40.2 / 0.214**2 == pytest.approx(re35.mechanical_time_constant.m_as("s"), rel=5e-3)
    rel = re35.datasheet_relations()
    assert set(rel) >= {"kt*kn = 1", "stall torque = kt*U/R", "gradient = R/kt^2", "no-load speed = kn*(U - R*I0)",
                        "mechanical time constant = J*R/kt^2"}
    for given, implied in rel.values():
        assert given == pytest.approx(implied, rel=5e-3)


def test_speed_torque_line_reproduces_datasheet_points(re35):
    # on the line at nominal voltage: n(M_N) = n0 - grad*M_N = 2110 - 8.4*105 = 1228 rpm (datasheet nominal speed 1230)
    w = 1230 * RPM
    M = float(re35.available_torque_si(w))
    assert M * 1e3 == pytest.approx(105, rel=0.02)
    # at standstill the shaft delivers the stall torque less friction: M_H - k_M I_0 = 255 - 214*0.0172 = 251.3 mNm
    assert float(re35.available_torque_si(0.0)) * 1e3 == pytest.approx(255 - 214 * 0.0172, rel=3e-3)


def test_003_fig12_motor_relations():
    # 6 V maxon motor of 003 Fig. 12: 8.91 mNm/A * 1070 rpm/V = 9533.7 ~ 30000/pi; M_H = 8.91*6/1.47 = 36.37 (36.3)
    m = motor("maxon 003 fig12")
    assert 8.91 * 1070 == pytest.approx(30000 / math.pi, rel=3e-3)
    assert m.torque_constant.m_as("N*m/A") * 6 / 1.47 * 1e3 == pytest.approx(36.3, rel=3e-3)
    assert 30000 / math.pi * 1.47 / 8.91**2 == pytest.approx(177, rel=3e-3)
    assert 2.68e-7 * 1.47 / 8.91e-3**2 == pytest.approx(4.98e-3, rel=5e-3)


def test_missing_constants_are_derived_from_stall_point():
    # maxon RE 13 1.8 V (003 Fig. 19) lists no R, k_M, k_n: R = U/I_A = 1.111 ohm, k_M = M_H/I_A = 1.512 mNm/A;
    # then n0 = k_n (U - I0 R) = 10988 rpm against the datasheet's 11000 rpm (0.1 %)
    m = motor("maxon RE 13 1.8 V")
    assert m.terminal_resistance.m_as("ohm") == pytest.approx(1.8 / 1.62, rel=1e-12)
    assert m.torque_constant.m_as("mN*m/A") == pytest.approx(2.45 / 1.62, rel=1e-12)
    n0 = m.speed_constant.m_as("rpm/V") * (1.8 - 0.0538 * 1.8 / 1.62)
    assert n0 == pytest.approx(11000, rel=2e-3)
    assert {"terminal_resistance", "torque_constant", "speed_constant"} <= m.derived


def test_inconsistent_datasheet_is_rejected():
    # the 003 Fig. 12 speed constant (1070 rpm/V) pasted onto the RE 35 data: k_t k_n = 24 instead of 1
    with pytest.raises(InputError, match=r"inconsistent datasheet.*kt\*kn = 1"):
        DCMotor("mixed", nominal_voltage="48 V", terminal_resistance="40.2 ohm", torque_constant="214 mN*m/A",
                speed_constant="1070 rpm/V")
    # stall torque typed in N m instead of mN m
    with pytest.raises(InputError, match="stall torque"):
        DCMotor("typo", nominal_voltage="48 V", terminal_resistance="40.2 ohm", torque_constant="214 mN*m/A",
                stall_torque="255 N*m")


def test_not_enough_constants():
    with pytest.raises(InputError, match="cannot determine"):
        DCMotor("bare", nominal_voltage="12 V", no_load_speed="3000 rpm")


# ---------------------------------------------------------------------- exact datasheet unit conversions
def test_ozf_in_to_mNm_pololu():
    # 003 §5.6: "40 oz·in, equivalent to 282.4 mN·m or 2.9 kg·cm": exact 282.46 mN·m, 2.880 kgf·cm
    m = motor("Pololu 150:1")
    assert m.stall_torque.m_as("mN*m") == pytest.approx(40 * OZF_IN * 1e3, rel=1e-12)
    assert 40 * OZF_IN * 1e3 == pytest.approx(282.4, abs=0.1)
    assert m.stall_torque.m_as("kgf*cm") == pytest.approx(40 * OZF_IN / G0 * 100, rel=1e-12)


def test_kgf_cm_servo_and_oz_in_stepper():
    assert motor("MG90S").stall_torque.m_as("N*m") == pytest.approx(2.2 * G0 / 100, rel=1e-15)
    # 000 Annex 3: 66 oz-in printed as 46 N·cm (exact 46.61 N·cm)
    assert motor("STP-42D3018").holding_torque.m_as("N*cm") == pytest.approx(66 * OZF_IN * 100, rel=1e-12)


def test_rpm_per_V_gcm2_and_gradient_units():
    assert Q("1070 rpm/V").m_as("rad/s/V") == pytest.approx(1070 * RPM, rel=1e-15)
    assert Q("2.68 g*cm**2").m_as("kg*m**2") == pytest.approx(2.68e-7, rel=1e-12)
    assert Q("177 rpm/(mN*m)").m_as("rad/s/(N*m)") == pytest.approx(177 * RPM * 1000, rel=1e-12)
