"""Design files: a ``planar_arm`` walking a path from an expression, and its joints handed to drives.

Expected values are hand calculations in this file from Lagrange's equations of the polar RP arm in closed form
(Spong, Hutchinson & Vidyasagar, Robot Modeling and Control, Sec. 7.3):
tau1 = (J + m q2^2) q1'' + 2 m q2 q2' q1' + (m_a r_a + m q2) g cos q1, with J = sum m L^2/3 of rods turning about
their end (Meriam & Kraige, Table D/4), on the path sampled here by an independent parametrisation; the torque
through a gearhead T_motor = T_out/(i eta) (maxon, Key information on gearheads). Not printed values.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

ARM = """
[design]
name = "arm"

[parameters]
r0 = "8 cm"

[profiles.q1]
type = "joint_motion"
mechanism = "arm"
joint = "q1"

[components.arm]
type = "planar_arm"
kind = "rp"
path = {{ curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"], speed = "1.4 cm/s" }}
reach_min = "22 cm"
reach_max = "{reach}"
carriage_mass = "98 g"
bodies = [{{ shape = "rod", mass = "99 g", length = "25 cm" }}, {{ shape = "rod", mass = "8.5 g", length = "25 cm" }}]
gravity = "9.8 m/s^2"

[components.revolute]
type = "drive"
motor = "maxon 6V 10.3 mNm"
gearhead = "GP 22 850:1"
inertia = "0 kg*m^2"
profile = "q1"

[components.constant]
type = "drive"
motor = "maxon 6V 10.3 mNm"
gearhead = "GP 22 850:1"
inertia = "arm.q1_inertia"
external_torque = "arm.q1_peak_torque"
profile = "still"

[profiles.still]
type = "dwell"
duration = "1 s"
axis = "rotary"
"""


def _write(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "d.toml"
    p.write_text(text, encoding="utf-8")
    return p


def _hand_tau1(n: int = 20000):
    """tau1 along the clover by the closed form, the path parametrised by phi (not by arc length) and the
    joint rates by finite differences of q(t) on a fine grid."""
    from scipy.integrate import cumulative_trapezoid

    phi = np.linspace(0, 2 * math.pi, n + 1)
    r = 0.08 - 0.015 * np.cos(4 * phi)
    x, y = 0.125 + r * np.cos(phi), 0.375 + r * np.sin(phi)
    ds = np.hypot(r, 0.06 * np.sin(4 * phi))
    t = cumulative_trapezoid(ds, phi, initial=0) / 0.014
    q1, q2 = np.arctan2(y, x), np.hypot(x, y)
    d1, d2 = np.gradient(q1, t, edge_order=2), np.gradient(q2, t, edge_order=2)
    dd1 = np.gradient(d1, t, edge_order=2)
    m, g = 0.098, 9.8
    J = 0.099 * 0.25**2 / 3 + 0.0085 * 0.25**2 / 3
    mr = (0.099 + 0.0085) * 0.125
    tau = (J + m * q2**2) * dd1 + 2 * m * q2 * d2 * d1 + (mr + m * q2) * g * np.cos(q1)
    return t, tau, J + m * q2**2


def test_joint_torque_reaches_the_drive(tmp_path):
    """The drive on the joint_motion profile: gearhead output torque = the arm's tau1 (peak within 0.1 % of the
    hand calculation); motor torque = tau1/(i eta) + rotor and gearhead inertia terms (< 1e-4 of it here)."""
    d = load(_write(tmp_path, ARM.format(reach="50 cm")))
    rs = d.verify()
    _, tau, J1 = _hand_tau1()
    peak = float(np.max(np.abs(tau)))
    g = rs.get("revolute", "gearhead_intermittent_torque")
    assert g.demand.m_as("N*m") == pytest.approx(peak, rel=1e-3)
    i, eta = 531441 / 625, 0.49
    m = rs.get("revolute", "motor_peak_torque")
    assert m.demand.m_as("N*m") == pytest.approx(peak / (i * eta), rel=2e-3)
    # the output connection: the constant drive gets the same peak and the largest inertia about q1
    c = rs.get("constant", "gearhead_intermittent_torque")
    assert c.demand.m_as("N*m") == pytest.approx(peak, rel=1e-3)
    arm = d.data.components["arm"].obj
    assert float(np.max(arm.q1_inertia)) == pytest.approx(float(np.max(J1)), rel=1e-4)


def test_path_outside_the_stroke_names_the_sample(tmp_path):
    """Reach 44 cm (seed 003's Eq. 27 domain) against the clover reaching 48.4 cm."""
    with pytest.raises(DesignFileError, match=r"components\.arm: arm: sample \d+ .*outside the stroke 220 to 440 mm"):
        load(_write(tmp_path, ARM.format(reach="44 cm")))


@pytest.mark.parametrize("old, new, message", [
    ('speed = "1.4 cm/s" }', 'speed = "1.4 cm/s", radius = "1 cm" }', "path.radius: unknown key"),
    ("r0 - 1.5 cm", "q0 - 1.5 cm", "unknown name 'q0'"),
    ('curve = "polar"', 'curve = "spiral"', "path.curve: expected 'polar', 'cartesian' or 'points'"),
    ('mechanism = "arm"', 'mechanism = "revolute"', "mechanism 'revolute' is not a planar_arm component"),
    # review item 1: a curve must be a length (a bare number was read as metres, a speed as a length)
    ("r0 - 1.5 cm * cos(4*phi)", "8 - 1.5 * cos(4*phi)", "components.arm.path.r: expected a length"),
    ("r0 - 1.5 cm * cos(4*phi)", "8 cm/s - 1.5 cm/s * cos(4*phi)", "components.arm.path.r: expected a length"),
    ('curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"]',
     'curve = "cartesian", x = "30 * cos(u)", y = "30 cm * sin(u)"', "components.arm.path.x: expected a length"),
    ('curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"]',
     'curve = "cartesian", x = "30 cm * cos(u)", y = "3 N * sin(u)"', "components.arm.path.y: expected a length"),
    ('curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"]',
     'curve = "points", points = [["1 cm", "2 cm"], ["3 cm/s", "4 cm"], ["5 cm", "1 cm"]]',
     "path.points[1][0]: expected a length"),
    # review item 9: a negative polar radius was accepted (the point on the other side of the centre)
    ("r0 - 1.5 cm * cos(4*phi)", "-8 cm", "components.arm.path.r: the radius must not be negative"),
    ("r0 - 1.5 cm * cos(4*phi)", "1 cm - 1.5 cm * cos(4*phi)", "is -0.5 cm at phi = 0 deg"),
])
def test_bad_paths_are_named(tmp_path, old, new, message):
    """Unknown path key, unknown name in the curve, unknown curve, a joint_motion on a drive: named errors."""
    text = ARM.format(reach="50 cm").replace(old, new)
    with pytest.raises(DesignFileError) as e:
        load(_write(tmp_path, text))
    assert message in str(e.value)


@pytest.mark.parametrize(("samples", "message"), [
    ("2.5", "path.samples: expected a whole number, got 2.5"),
    ("50000000", "path.samples: expected 2 to 100,000 (time and memory of the walk), got 50,000,000"),
    ("1", "path.samples: expected 2 to 100,000"),
])
def test_path_samples_are_whole_and_bounded(tmp_path, samples, message):
    """Review item 2: path.samples = 50000000 ran for minutes, 2.5 was accepted."""
    text = ARM.format(reach="50 cm").replace('speed = "1.4 cm/s" }', f'speed = "1.4 cm/s", samples = {samples} }}')
    with pytest.raises(DesignFileError) as e:
        load(_write(tmp_path, text))
    assert f"components.arm.{message}" in str(e.value)


def test_cartesian_circle_and_sampled_points(tmp_path):
    """A Cartesian circle about the axis (x = R cos u, y = R sin u, u in radians): q2' = 0, tau1 = gravity only
    (J q1'' = 0 at constant speed); the same circle as 72 sampled points (a periodic spline) within 0.2 %."""
    base = ARM.format(reach="50 cm")
    text = base.replace('curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"]',
                        'curve = "cartesian", x = "30 cm * cos(u)", y = "30 cm * sin(u)", u = [0.1, 3.0]')
    d = load(_write(tmp_path, text))
    arm = d.data.components["arm"].obj
    q1 = arm.motion.q1
    tau = (0.098 * 0.3 + (0.099 + 0.0085) * 0.125) * 9.8 * np.cos(q1)
    assert arm.efforts[0] == pytest.approx(tau, rel=1e-6, abs=1e-9)
    assert arm.path.length == pytest.approx(0.3 * 2.9, rel=1e-9)
    pts = ", ".join(f'["{30 * math.cos(a):.9f} cm", "{30 * math.sin(a):.9f} cm"]'
                    for a in np.linspace(0, 2 * math.pi, 72, endpoint=False))
    text = base.replace('curve = "polar", r = "r0 - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"]',
                        f'curve = "points", closed = true, points = [{pts}]')
    arm = load(_write(tmp_path, text)).data.components["arm"].obj
    assert arm.path.length == pytest.approx(2 * math.pi * 0.3, rel=1e-5)
    assert np.max(np.abs(arm.efforts[0])) == pytest.approx((0.098 * 0.3 + 0.107 * 0.125) * 9.8, rel=2e-3)


def test_trapezoidal_walk_starts_and_ends_at_rest(tmp_path):
    """speed and acceleration: the tool starts and stops at rest, so q1' = q2' = 0 at both ends."""
    text = ARM.format(reach="50 cm").replace('speed = "1.4 cm/s"', 'speed = "1.4 cm/s", acceleration = "1 cm/s^2"')
    arm = load(_write(tmp_path, text)).data.components["arm"].obj
    assert abs(arm.motion.dq1[0]) < 1e-12 and abs(arm.motion.dq1[-1]) < 1e-9
    L = arm.path.length
    assert arm.path.t[-1] == pytest.approx(L / 0.014 + 0.014 / 0.01, rel=1e-9)  # T = L/v + v/a


FIVE_BAR = """
[design]
name = "five-bar path"

[profiles.left]
type = "joint_motion"
mechanism = "fb"
joint = "q1"

[components.fb]
type = "planar_arm"
kind = "five_bar"
base = "100 mm"
proximal_left = "100 mm"
distal_left = "100 mm"
distal_right = "100 mm"
proximal_right = "100 mm"
payload = "0.5 kg"
path = { curve = "polar", r = "3 cm", centre = ["5 cm", "12 cm"], speed = "10 cm/s", samples = 200 }

[components.left_motor]
type = "drive"
motor = "maxon 6V 10.3 mNm"
gearhead = "GP 22 850:1"
inertia = "0 kg*m^2"
profile = "left"
"""


def test_five_bar_arm_feeds_its_drive(tmp_path):
    """kind = "five_bar" (seed 002's 100 mm links, a 0.5 kg payload on a 3 cm circle): the left drive's gearhead
    output torque is the payload's virtual-work torque on the left motor, checked at rest-equivalent samples by
    the five-bar's own holding_torques (massless links, gravity + d'Alembert); q2 limits name the first sample."""
    from mechverify.mechanisms.fivebar import FiveBar

    d = load(_write(tmp_path, FIVE_BAR))
    arm = d.data.components["fb"].obj
    fb = FiveBar("100 mm", "100 mm", "100 mm", "100 mm", "100 mm")
    i = 37
    pose = fb.inverse((f"{arm.path.x[i]} m", f"{arm.path.y[i]} m"))
    tl, _ = fb.holding_torques(pose, (f"{-0.5 * arm.path.ax[i]} N", f"{-0.5 * (arm.path.ay[i] + 9.80665)} N"))
    assert arm.efforts[0][i] == pytest.approx(tl.m_as("N*m"), rel=1e-9)
    g = d.verify().get("left_motor", "gearhead_intermittent_torque")
    assert g.demand.m_as("N*m") == pytest.approx(float(np.max(np.abs(arm.efforts[0]))), rel=1e-3)
    with pytest.raises(DesignFileError, match=r"sample \d+ .*theta_right"):
        load(_write(tmp_path, FIVE_BAR.replace('payload = "0.5 kg"', 'payload = "0.5 kg"\nq2_max = "60 deg"')))


def test_a_drive_on_a_joint_motion_needs_no_load_of_its_own(tmp_path):
    """A drive on a joint_motion profile without ``inertia`` (revolute joint) or ``mass`` (prismatic joint) has a
    zero load of its own: the joint's effort and inertia come with the profile. The RP robot example without its
    ``inertia = "0 kg*m^2"`` and ``mass = "0 kg"`` lines gives the same results, number for number."""
    example = Path(__file__).resolve().parents[1] / "examples" / "rp_robot" / "design.toml"
    text = example.read_text(encoding="utf-8")
    bare = text.replace('inertia = "0 kg*m^2"\n', "").replace('mass = "0 kg"  ', "# ")
    assert bare.count("inertia =") == text.count("inertia =") - 2 and 'mass = "0 kg"' not in bare
    rows = [[(r.component, r.check, r.verdict, r.demand, r.capacity, r.safety_factor) for r in load(p).verify()]
            for p in (example, _write(tmp_path, bare))]
    assert len(rows[0]) > 10 and rows[0] == rows[1]
    assert {c for c, *_ in rows[0]} >= {"revolute_maxon", "revolute_gearmotor", "prismatic_maxon", "prismatic_pololu"}


def test_a_drive_on_a_plain_profile_still_needs_its_load(tmp_path):
    """Only a joint_motion profile brings a load: a drive on a dwell without mass or inertia is still an error."""
    text = ARM.format(reach="50 cm").replace('inertia = "arm.q1_inertia"\n', "")
    with pytest.raises(DesignFileError) as info:
        load(_write(tmp_path, text))
    assert any(p == "components.constant.mass" and "missing" in m for p, m in info.value.errors), info.value.errors
