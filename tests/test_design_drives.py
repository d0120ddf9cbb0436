"""Design files with motion profiles and drives: numbers against hand calculations, errors, report.

Hand calculations use the published rules, written out here (not taken from the code):

* load torque through a reduction of ratio r (input per output displacement) and efficiency eta, motoring:
  T_in = F / (r·eta); a screw has r = 2*pi/l, a drum r = 2/D (Oriental Motor, Technical Reference:
  Motor Sizing Calculations, "load torque by drive mechanism": T_L = F·P_B/(2*pi·eta), T_L = F·D/(2·eta));
* acceleration torque J·alpha at each shaft, alpha_motor = r·a_load (same source, "acceleration torque");
* reflected inertia J/r² (m·(P_B/2*pi)², m·(D/2)²) (same source, "load inertia");
* RMS torque sqrt(sum T_i²·t_i / t_c) (THK, Ball Screw: Studying the Driving Motor, effective torque);
* DC motor: I = T/k_t + I_0, U = R·I + omega/k_n, available torque on the speed-torque line
  T(omega) = k_t·(U - omega/k_n)/R - k_t·I_0 (maxon, DC motor Key information);
* trapezoid profile time T = D/v + v/a (Biagiotti & Melchiorri 2008, Sec. 3.2); double-S with
  V·J >= A²: T = D/V + V/A + A/J (same, Sec. 3.4);
* screw raising torque with a flank angle in the normal plane, tan(alpha_n) = tan(alpha)·cos(lambda):
  T = F·d2/2 · (l + pi·mu·d2/cos(alpha_n)) / (pi·d2 - mu·l/cos(alpha_n))
  (Hamrock, Schmid & Jacobson, Fundamentals of Machine Elements, 3rd ed., Eqs. 16.8-16.10).
"""

import math
import textwrap

import pytest

from mechverify.design import DesignFileError, load

G = 9.80665


def write(tmp_path, text):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(text))
    return p


def errors_of(tmp_path, text):
    with pytest.raises(DesignFileError) as info:
        load(write(tmp_path, text))
    return dict(info.value.errors)


# --------------------------------------------------------------------------- rotary: DC motor + gearhead

ROTARY = """
[design]
name = "neck"

[profiles.nod]
type = "triangular"
distance = "90 deg"
duration = "1 s"

[components.neck]
type = "drive"
motor = "maxon RE 35 273762"
gearhead = "GP 32 166155"
inertia = "0.01 kg*m^2"
external_torque = "0.5 N*m"
profile = "nod"
supply_voltage = "48 V"
driver_current = "2 A"
"""

# maxon RE 35 273762 (001 Table 8) and GP 32 166155 (001 Table 9), catalogue values:
N, ETA, J_GH, J_ROT = 26 / 7, 0.80, 1.5e-7, 61.2e-7
KT, KN, R, I0 = 0.214, 44.7 * 2 * math.pi / 60, 40.2, 0.0172  # N·m/A, rad/s/V, ohm, A


def _rotary_hand():
    a = 4 * (math.pi / 2) / 1.0**2  # triangular: a = 4D/T² [rad/s²]
    w_peak = a * 0.5  # [rad/s] at the load
    am, wm = N * a, N * w_peak  # motor side
    t_out_acc = 0.01 * a + 0.5  # J_L·a + T_ext at the gearhead output
    t_out_dec = -0.01 * a + 0.5  # still positive: the gearhead keeps motoring
    t_acc = t_out_acc / (N * ETA) + (J_GH + J_ROT) * am
    t_dec = t_out_dec / (N * ETA) - (J_GH + J_ROT) * am
    return t_out_acc, t_out_dec, t_acc, t_dec, wm


def test_rotary_dc_drive_matches_hand_calculation(tmp_path):
    rs = load(write(tmp_path, ROTARY)).verify()
    t_out_acc, t_out_dec, t_acc, t_dec, wm = _rotary_hand()
    peak = rs.get("neck", "motor_peak_torque")
    # governing point: end of the acceleration (highest torque at the highest speed)
    assert peak.demand.m_as("N*m") == pytest.approx(t_acc, rel=1e-6)
    avail = KT * (48 - wm / KN) / R - KT * I0
    assert peak.capacity.m_as("N*m") == pytest.approx(avail, rel=1e-3)
    assert peak.required_sf == 1.5  # motor class default
    rms = rs.get("neck", "motor_rms_torque")
    assert rms.demand.m_as("N*m") == pytest.approx(math.sqrt((t_acc**2 + t_dec**2) / 2), rel=1e-4)
    assert rms.capacity.m_as("mN*m") == pytest.approx(105)  # nominal torque
    gc = rs.get("neck", "gearhead_continuous_torque")
    assert gc.demand.m_as("N*m") == pytest.approx(math.sqrt((t_out_acc**2 + t_out_dec**2) / 2), rel=1e-6)
    assert gc.capacity.m_as("N*m") == pytest.approx(0.75)
    gi = rs.get("neck", "gearhead_intermittent_torque")
    assert gi.demand.m_as("N*m") == pytest.approx(t_out_acc, rel=1e-6)
    speed = rs.get("neck", "motor_max_speed")
    assert speed.demand.m_as("rpm") == pytest.approx(wm * 60 / (2 * math.pi), rel=1e-9)  # 111.4 rpm
    assert speed.required_sf == 1.0  # limit class: a rating with the maker's margin
    ratio = rs.get("neck", "inertia_ratio")
    assert ratio.demand.m_as("") == pytest.approx((0.01 / N**2 + J_GH) / J_ROT, rel=1e-9)
    assert ratio.required_sf == 1.0
    volt = rs.get("neck", "motor_supply_voltage")
    assert volt.demand.m_as("V") == pytest.approx(R * (t_acc / KT + I0) + wm / KN, rel=1e-6)
    cur = rs.get("neck", "driver_current")
    assert cur.demand.m_as("A") == pytest.approx(t_acc / KT + I0, rel=1e-6)
    # the GP 32 entry has no input-speed rating: that check cannot run, and the peak-torque check says so
    assert len(rs.where(check="gearhead_input_speed")) == 0
    assert any("gearhead input speed (no max. input speed)" in n for n in peak.notes)


def test_rms_torque_exact(tmp_path):
    """THK effective torque of the two constant-torque halves: sqrt((T_acc² + T_dec²)/2), exact for this profile."""
    rs = load(write(tmp_path, ROTARY)).verify()
    _, _, t_acc, t_dec, _ = _rotary_hand()
    rms = rs.get("neck", "motor_rms_torque")
    assert rms.demand.m_as("N*m") == pytest.approx(math.sqrt((t_acc**2 + t_dec**2) / 2), rel=1e-6)


def test_rms_fails_like_001_when_torque_is_held(tmp_path):
    """001's neck: 0.71 N·m held at the GP 32 output -> 0.71/(3.714·0.80) = 0.239 N·m > 0.105 N·m nominal."""
    text = ROTARY.replace('external_torque = "0.5 N*m"', 'external_torque = "0.71 N*m"')
    rs = load(write(tmp_path, text)).verify()
    rms = rs.get("neck", "motor_rms_torque")
    assert rms.demand.m_as("N*m") > 0.71 / (N * ETA) * 0.99
    assert rms.verdict.value == "fail"


def test_load_cases_replace_and_add(tmp_path):
    text = ROTARY + """
[load_cases.light.neck]
external_torque = "0.2 N*m"

[load_cases.heavy.neck]
external_torque = "0.5 N*m"
load_factor = 1.2
"""
    rs = load(write(tmp_path, text)).verify()
    peak = rs.get("neck", "motor_peak_torque")
    a = 2 * math.pi
    t_acc = 1.2 * (0.01 * a + 0.5) / (N * ETA) + (J_GH + J_ROT) * N * a
    assert peak.demand.m_as("N*m") == pytest.approx(t_acc, rel=1e-6)
    assert peak.load_case.startswith("heavy (")
    assert any("Governing of 2 load cases" in n for n in peak.notes)


# --------------------------------------------------------------------------- linear: screw, drum, belt

SCREW = """
[design]
name = "lift"

[profiles.up]
type = "trapezoidal"
distance = "100 mm"
max_velocity = "20 mm/s"
acceleration = "0.5 m/s^2"

[components.lift_screw]
type = "lead_screw"
thread = "Tr10x2"
length = "300 mm"
mu_min = 0.08
mu_max = 0.12

[components.lift_screw.checks]
nut_flank_pressure = false
nut_pv = false
screw_strength = false
buckling = false
critical_speed = false

[components.lift]
type = "drive"
transmission = [{ type = "screw", screw = "lift_screw" }]
mass = "10 kg"
incline = "90 deg"
profile = "up"

[components.lift.motor_data]
type = "stepper"
name = "flat stepper"
step_angle = "1.8 deg"
holding_torque = "0.5 N*m"
rotor_inertia = "50 g*cm^2"
pullout_speeds = ["0 rpm", "1000 rpm"]
pullout_torques = ["0.4 N*m", "0.4 N*m"]
"""


def _screw_torque_per_newton(mu):
    d2, lead, alpha = 9e-3, 2e-3, math.radians(15)  # Tr10x2 (DIN 103: d2 = d - P/2)
    lam = math.atan(lead / (math.pi * d2))
    cos_an = math.cos(math.atan(math.tan(alpha) * math.cos(lam)))
    return d2 / 2 * (lead + math.pi * mu * d2 / cos_an) / (math.pi * d2 - mu * lead / cos_an)


def test_screw_lift_peak_torque_by_hand(tmp_path):
    rs = load(write(tmp_path, SCREW)).verify()
    peak = rs.get("lift", "motor_peak_torque")
    alpha_m = 0.5 * 2 * math.pi / 2e-3  # a·2*pi/l [rad/s²]
    # motoring upward while accelerating, at mu_max: T = m(g + a)·k(mu_max) + J_rotor·alpha
    t_acc = 10 * (G + 0.5) * _screw_torque_per_newton(0.12) + 50e-7 * alpha_m
    assert peak.demand.m_as("N*m") == pytest.approx(t_acc, rel=1e-6)
    assert peak.capacity.m_as("N*m") == pytest.approx(0.4)
    assert any("mu_max = 0.12 governs" in n for n in peak.notes)
    # cross-check the efficiency form: T = F·l/(2*pi·eta) with eta from the same formula
    eta = 2e-3 / (2 * math.pi * _screw_torque_per_newton(0.12))
    assert t_acc == pytest.approx(10 * (G + 0.5) * 2e-3 / (2 * math.pi * eta) + 50e-7 * alpha_m)
    ratio = rs.get("lift", "inertia_ratio")
    assert ratio.demand.m_as("") == pytest.approx(10 * (2e-3 / (2 * math.pi)) ** 2 / 50e-7, rel=1e-9)
    assert len(rs.where(component="lift", check="motor_rms_torque")) == 0  # steppers: no RMS rating


def test_drum_and_belt_linear_by_hand(tmp_path):
    """Horizontal axis: F = m·a + mu·m·g; T = F·(D/2)/(eta_drum·eta_belt·i) + J·alpha, i = 40/20."""
    text = """
    [design]
    name = "slide"

    [profiles.move]
    type = "trapezoidal"
    distance = "300 mm"
    max_velocity = "0.2 m/s"
    acceleration = "2 m/s^2"

    [components.slide]
    type = "drive"
    motor = "maxon 6V 10.3 mNm"
    transmission = [{ type = "belt", driver = 20, driven = 40, efficiency = 0.95 },
                    { type = "drum", diameter = "20 mm", efficiency = 0.9 }]
    mass = "0.5 kg"
    friction_coefficient = 0.1
    profile = "move"
    """
    rs = load(write(tmp_path, text)).verify()
    i, D = 2.0, 0.02
    r = i * 2 / D  # rad per m at the motor
    F = 0.5 * 2 + 0.1 * 0.5 * G
    t_acc = F * (D / 2) / (0.9 * 0.95 * i) + 2.68e-7 * 2 * r
    peak = rs.get("slide", "motor_peak_torque")
    assert peak.demand.m_as("N*m") == pytest.approx(t_acc, rel=1e-6)
    ratio = rs.get("slide", "inertia_ratio")
    assert ratio.demand.m_as("") == pytest.approx(0.5 * (D / 2) ** 2 / i**2 / 2.68e-7, rel=1e-9)


def test_profiles_against_closed_forms(tmp_path):
    text = """
    [design]
    name = "profiles"

    [profiles.trap]
    type = "trapezoidal"
    distance = "200 mm"
    max_velocity = "50 mm/s"
    acceleration = "0.25 m/s^2"

    [profiles.seq]
    type = "sequence"
    steps = ["trap", "rest", "back"]

    [profiles.rest]
    type = "dwell"
    duration = "0.5 s"

    [profiles.back]
    type = "s_curve"
    distance = "-200 mm"
    max_velocity = "100 mm/s"
    acceleration = "0.5 m/s^2"
    jerk = "5 m/s^3"

    [profiles.tri]
    type = "triangular"
    distance = "180 deg"
    acceleration = "2 rad/s^2"

    [profiles.meas]
    type = "sampled"
    t = ["0 s", "0.1 s", "0.2 s", "0.3 s"]
    x = ["0 mm", "1 mm", "2 mm", "3 mm"]
    """
    p = load(write(tmp_path, text)).profiles
    assert p["trap"].duration.m_as("s") == pytest.approx(0.2 / 0.05 + 0.05 / 0.25)  # D/v + v/a = 4.2 s
    # V·J = 0.5 >= A² = 0.25: T = D/V + V/A + A/J = 2 + 0.2 + 0.1
    assert p["back"].duration.m_as("s") == pytest.approx(2.3)
    assert p["seq"].duration.m_as("s") == pytest.approx(4.2 + 0.5 + 2.3)
    assert p["seq"].distance.m_as("mm") == pytest.approx(0.0, abs=1e-9)
    assert p["tri"].duration.m_as("s") == pytest.approx(2 * math.sqrt(math.pi / 2))  # T = 2·sqrt(D/a)
    assert p["meas"].peak_velocity.m_as("mm/s") == pytest.approx(10.0)


# --------------------------------------------------------------------------- errors


def test_unknown_motor_suggests(tmp_path):
    errs = errors_of(tmp_path, ROTARY.replace("maxon RE 35 273762", "maxon RE 35 273726"))
    assert "unknown motor 'maxon RE 35 273726'" in errs["components.neck.motor"]
    assert "did you mean" in errs["components.neck.motor"] and "273762" in errs["components.neck.motor"]


def test_unreachable_profile(tmp_path):
    text = ROTARY.replace('[profiles.nod]\ntype = "triangular"\ndistance = "90 deg"\nduration = "1 s"',
                          '[profiles.nod]\ntype = "trapezoidal"\ndistance = "90 deg"\nduration = "1 s"\n'
                          'acceleration = "1 rad/s^2"')
    errs = errors_of(tmp_path, text)
    assert "not reachable in 1 s" in errs["profiles.nod"]
    assert "needs acceleration >=" in errs["profiles.nod"]


def test_stage_and_load_errors(tmp_path):
    text = SCREW.replace('screw = "lift_screw"', 'screw = "lift_scew"')
    assert "expected the name of a lead_screw component" in \
        errors_of(tmp_path, text)["components.lift.transmission[0].screw"]
    assert "did you mean 'lift_screw'" in errors_of(tmp_path, text)["components.lift.transmission[0].screw"]
    text = SCREW.replace('transmission = [{ type = "screw", screw = "lift_screw" }]', "")
    assert "add a screw or drum" in errors_of(tmp_path, text)["components.lift"]
    text = SCREW.replace('{ type = "screw", screw = "lift_screw" }', '{ type = "drum", diametre = "20 mm" }')
    assert "unknown key for a drum stage; did you mean 'diameter'?" in \
        errors_of(tmp_path, text)["components.lift.transmission[0].diametre"]
    text = SCREW.replace('holding_torque = "0.5 N*m"', 'holding_torque = "0.5 N"')
    assert errors_of(tmp_path, text)["components.lift.motor_data.holding_torque"].startswith("expected a torque")
    text = SCREW.replace('distance = "100 mm"', 'distance = "90 deg"').replace('max_velocity = "20 mm/s"',
                                                                            'max_velocity = "20 rpm"') \
                .replace('acceleration = "0.5 m/s^2"', 'acceleration = "5 rad/s^2"')
    assert "'up' is a rotary move but the load is linear" in errors_of(tmp_path, text)["components.lift.profile"]
    text = SCREW.replace('mass = "10 kg"', 'mass = "10 kg"\ninertia = "1 kg*m^2"')
    assert "not both" in errors_of(tmp_path, text)["components.lift"]


def test_bad_load_case_reported_once_and_every_time(tmp_path):
    d = load(write(tmp_path, ROTARY + '\n[load_cases.a.neck]\nmass = "1 kg"\n'))
    for _ in range(2):  # a second verify() reports it again
        with pytest.raises(DesignFileError) as info:
            d.verify()
        assert info.value.errors == [("components.neck.checks.motor_peak_torque",
                                      "load case 'a': a linear-load key (mass, payload, external_force) in a load "
                                      "case of a rotary drive")]
    errs = errors_of(tmp_path, ROTARY + 'cycle_time = "0.5 s"\n')
    assert errs["components.neck.cycle_time"] == "0.5 s is shorter than the profile 'nod' (1.0 s)"


def test_sequence_cycle_is_an_error(tmp_path):
    text = SCREW.replace("[components.lift_screw]", '[profiles.a]\ntype = "sequence"\nsteps = ["b"]\n\n'
                                                    '[profiles.b]\ntype = "sequence"\nsteps = ["a"]\n\n'
                                                    "[components.lift_screw]")
    errs = errors_of(tmp_path, text)
    assert "refers to itself" in errs["profiles.a.steps"]


# --------------------------------------------------------------------------- report


def test_report_renders_formulas_and_plots(tmp_path):
    from mechverify.reports.render import render_html

    for text in (ROTARY, SCREW):
        d = load(write(tmp_path, text))
        html = render_html([(d, d.verify())])
        assert 'class="latex"' not in html
        # utilisation chart + torque-speed/profile figures of the motor checks
        assert html.count("data:image/svg+xml") >= 4
