"""Worked example of reference project 000 (4-DOF lever arm, motors at the base): examples/lever_arm.

Every expected value is computed here from the method it names, never copied from mechverify's output:
- motor holding torques with self-weight: principle of virtual work with potential energy,
  tau_i = dV/dq_i (Meriam & Kraige, Engineering Mechanics: Statics, 7th ed., Art. 7/3). The three
  parallelograms decouple the motors: turning one crank with the other two held moves each body by a
  pure translation on a circle (radius = the crank length) or a rotation about a fixed pin, so each
  torque is g cos(angle) times a sum of masses times lever arms (written out below);
- member forces with massless links (the document's load case): equilibrium of IBC about B, GAH about A
  and EAB about A (Meriam & Kraige, 7th ed., Art. 4/6, frames and machines);
- link body stress: sigma = |N|/A + M/(t h^2/6) (Shigley, 10th ed., Eq. 3-24 and Sec. 5-5);
- the stepper's capacity: 66 oz-in holding torque (document Annex 3) = 66 x 0.0070615518 N m;
- a belt reduction holding a load that back-drives it: T_motor = T_crank eta / i (lower bound) and
  T_crank / (i eta) to start lifting it (upper bound).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from mechverify.cli import main
from mechverify.design import load
from mechverify.units import Q
from tests.builders import run_module

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lever_arm"

G = 9.80665  # standard gravity, the statics solver's default [m/s^2]
b, c, d, p, q, r = 0.200, 0.150, 0.050, 0.030, 0.030, 0.030  # document Sec. 2.2 [m]
W = 2.0  # design payload at C [N] (assumption stated in design.toml)
RHO = 2700.0  # 6061-T6 density [kg/m^3]
A_MAIN, A_LINK = 20e-3 * 4e-3, 12e-3 * 3e-3  # 20 x 4 and 12 x 3 mm flats [m^2]
HOLDING = 66 * 0.0070615518  # 66 oz-in in N m (1 ozf in = 0.278013851 N x 0.0254 m)

# body masses: area x pin-centre length x density [kg]
m_OA, m_EA, m_AB = (A_MAIN * RHO * L for L in (b, p, c))
m_BI, m_BC = A_MAIN * RHO * r, A_MAIN * RHO * d
m_OD, m_OF, m_AG, m_AH = (A_LINK * RHO * L for L in (p, q, q, r))
m_DE, m_FG, m_HI = A_LINK * RHO * b, A_LINK * RHO * b, A_LINK * RHO * c

# Virtual work, each at its crank's horizontal position (cos = 1), which the sweep reaches:
# shoulder (OA turns; OD, OF held): EAB, GAH, IBC, HI and the payload translate on a circle of radius b;
# OA, DE, FG turn about O, D, F with their centres of mass at b/2.
TAU_SHOULDER = G * b * (W / G + m_EA + m_AB + m_AG + m_AH + m_BI + m_BC + m_HI + (m_OA + m_DE + m_FG) / 2)
# elbow (OD turns; OA, OF held): EAB turns about A (AB forward, EA behind), IBC and W translate with B
# (radius c), HI turns about H (centre at c/2), DE translates with D and E (radius p), OD turns about O.
TAU_ELBOW = G * (c * (W / G + m_BI + m_BC + m_HI / 2) + m_AB * c / 2 - m_EA * p / 2 - m_DE * p - m_OD * p / 2)
# wrist (OF turns; OA, OD held) at psi = 0: BC, W, AG, OF along the crank direction, FG translates with F
# (radius q); BI, AH, HI are vertical at psi = 0 and contribute no torque there.
TAU_WRIST = G * (d * W / G + m_BC * d / 2 + m_OF * q / 2 + m_FG * q + m_AG * q / 2)


@pytest.fixture(scope="module")
def run():
    return run_module(EXAMPLE / "run.py", "lever_arm_run")


@pytest.fixture(scope="module")
def results():
    return {r.component + "/" + r.check: r for r in load(EXAMPLE / "design.toml").verify()}


@pytest.fixture(scope="module")
def corrected():
    return {r.component: r for r in load(EXAMPLE / "design_corrected.toml").verify()}


@pytest.fixture(scope="module")
def arm_outputs():
    """The pose sweep's outputs (component "arm" of arm.toml) at design.toml's W."""
    return load(EXAMPLE / "design.toml").components["arm"]


# ---------------------------------------------------------------- end to end
def test_cli_document_design_fails_and_corrected_passes():
    """The document's direct-drive steppers fail the holding check (exit 1); the 4:1 belts pass (exit 0)."""
    assert main(["check", str(EXAMPLE / "design.toml")]) == 1
    assert main(["check", str(EXAMPLE / "design_corrected.toml")]) == 0


# ---------------------------------------------------------------- motors
@pytest.mark.parametrize("motor, expected", [("shoulder", TAU_SHOULDER), ("elbow", TAU_ELBOW), ("wrist", TAU_WRIST)])
def test_peak_holding_torque_by_virtual_work(results, motor, expected):
    """Sweep's peak torque on each crank = the virtual-work torque at the crank's horizontal pose.
    Shoulder: 0.2 x (2 + 9.80665 x 0.117612) = 0.6307 N m; elbow 0.3529 N m; wrist 0.1092 N m."""
    res = results[f"{motor}_motor/motor_peak_torque"]
    assert res.demand.m_as("N*m") == pytest.approx(expected, rel=1e-5)
    assert res.capacity.m_as("N*m") == pytest.approx(HOLDING, rel=1e-6)


def test_document_motors_fail_with_the_stepper_margin(results):
    """0.6307 x 1.5 = 0.946 > 0.466 N m (shoulder, fails even without a margin); 0.3529 x 1.5 = 0.529 >
    0.466 (elbow); 0.1092 x 1.5 = 0.164 < 0.466 (wrist)."""
    assert results["shoulder_motor/motor_peak_torque"].verdict.name == "FAIL"
    assert results["elbow_motor/motor_peak_torque"].verdict.name == "FAIL"
    assert results["wrist_motor/motor_peak_torque"].verdict.name == "PASS"
    assert TAU_SHOULDER > HOLDING  # the shoulder stepper cannot even hold the arm at full reach


def test_largest_payload_the_annex_stepper_holds():
    """W_max = (T_hold/1.5 - tau_self) / b at the shoulder = (0.31071 - 0.23068)/0.2 = 0.400 N (41 g), by
    ``mechverify size`` over parameters.W (the sweep's outputs drive the motor checks; more in
    tests/test_lever_arm_sweep.py)."""
    from mechverify.studies.sizing import size

    tau_self = TAU_SHOULDER - W * b
    expected = (HOLDING / 1.5 - tau_self) / b
    res = size(EXAMPLE / "design.toml", "parameters.W", "governing", ("0.1 N", "50 N"))
    assert res.limit == pytest.approx(expected, rel=1e-6)
    assert res.governing == "shoulder_motor.motor_peak_torque"
    assert expected == pytest.approx(0.400, abs=0.002)


def test_corrected_design_belts(corrected):
    """4:1 belt, eta 0.95: the shoulder motor's holding torque lies between T eta/i = 0.1498 and
    T/(i eta) = 0.1660 N m, well inside 0.466/1.5 = 0.311 N m; the wrist is unchanged (direct)."""
    sh = corrected["shoulder_motor"].demand.m_as("N*m")
    assert TAU_SHOULDER * 0.95 / 4 * (1 - 1e-5) <= sh <= TAU_SHOULDER / (4 * 0.95) * (1 + 1e-5)
    assert corrected["wrist_motor"].demand.m_as("N*m") == pytest.approx(TAU_WRIST, rel=1e-5)


# ---------------------------------------------------------------- members
def test_oa_bending_equals_shoulder_torque_and_its_stress(arm_outputs, results):
    """OA is a cantilever from the motor: its largest moment (at O) is the shoulder torque. Body stress
    |N|/A + M/(t h^2/6) with h = 20 mm in the plane, t = 4 mm (Shigley 10th ed. Sec. 5-5, no shear/torsion)."""
    M = arm_outputs.members["OA"].moment.m_as("N*m")
    N = -arm_outputs.members["OA"].compression.m_as("N")
    assert M == pytest.approx(TAU_SHOULDER, rel=1e-5)
    sigma = abs(N) / A_MAIN + M / (4e-3 * 20e-3**2 / 6)
    assert results["OA/member_body_strength"].demand.m_as("Pa") == pytest.approx(sigma, rel=1e-4)


def test_coupler_buckling_capacity(results):
    """DE (200 mm, 12 x 3 flat, pinned-pinned): P_cr = pi^2 E I / l^2 with I = 12 x 3^3/12 = 27 mm^4,
    E = 68.9 GPa: 459.0 N (Shigley 10th ed. Eq. 4-42, C = 1)."""
    pcr = math.pi**2 * 68.9e9 * (12e-3 * 3e-3**3 / 12) / 0.2**2
    assert results["DE/member_buckling"].capacity.m_as("N") == pytest.approx(pcr, rel=1e-4)


# ---------------------------------------------------------------- the document's load case (massless, W at C)
def test_statics_at_reference_pose_against_equilibrium(run):
    """varphi 70, phi 20, psi 10 deg, W = 10 N: N_HI = W d cos psi/(r cos(phi+psi)) = 18.95 N,
    N_FG = -W d cos psi/(q sin(varphi+psi)) = -16.67 N, N_DE = W c cos phi/(p sin(varphi-phi)) = 61.33 N;
    |M_OA| = W b cos varphi = 0.684 N m, |M_OD| = W c cos phi = 1.410, |M_OF| = W d cos psi = 0.4924."""
    vp, ph, ps, w = math.radians(70), math.radians(20), math.radians(10), 10.0
    s = run.solver_statics(run.reference_pose(), Q(w, "N"))
    assert s["N_HI"][0] == pytest.approx(w * d * math.cos(ps) / (r * math.cos(ph + ps)), rel=1e-9)
    assert s["N_FG"][0] == pytest.approx(-w * d * math.cos(ps) / (q * math.sin(vp + ps)), rel=1e-9)
    assert s["N_DE"][0] == pytest.approx(w * c * math.cos(ph) / (p * math.sin(vp - ph)), rel=1e-9)
    assert abs(s["M_OA (36a)"][0]) == pytest.approx(w * b * math.cos(vp), rel=1e-9)
    assert abs(s["M_OD (40a)"][0]) == pytest.approx(w * c * math.cos(ph), rel=1e-9)
    assert abs(s["M_OF (38a)"][0]) == pytest.approx(w * d * math.cos(ps), rel=1e-9)


def test_document_formulas_as_printed(run):
    """The document's Eqs. evaluated by hand at the same pose: (36a) M_OA = [cos 70 + 50 sin(-50) cos 10 /
    (30 cos 30)] x 10 x 0.05 = -0.5549 N m; (30b) F_A = (-2 x 50 cos 20 cos 10/(30 cos 30), ...) x 10 =
    (-35.62, 12.96) N; (38b) |F'_O| = 50 cos 10/(30 cos 80) x 10 = 94.52 N; (28a) divides by cos 90 = 0."""
    doc = run.document_statics(run.reference_pose(), Q(10, "N"))
    r70, r20, r10 = math.radians(70), math.radians(20), math.radians(10)
    m_oa = (math.cos(r70) + 50 * math.sin(r20 - r70) * math.cos(r10) / (30 * math.cos(r20 + r10))) * 10 * 0.05
    assert doc["M_OA (36a)"][0] == pytest.approx(m_oa, rel=1e-9)
    assert m_oa == pytest.approx(-0.5549, abs=1e-4)
    k = 2 * 50 * math.cos(r10) / (30 * math.cos(r20 + r10)) * 10
    assert doc["F_A (30b)"] == pytest.approx([-k * math.cos(r20), k * math.sin(r20)], rel=1e-9)
    assert math.hypot(*doc["F'_O (38b)"]) == pytest.approx(50 * math.cos(r10) / (30 * math.cos(r70 + r10)) * 10)
    assert math.isinf(doc["F_I (28a)"][0])


# ---------------------------------------------------------------- kinematics
def test_forward_kinematics_and_the_printed_equation(run):
    """theta 30 deg: u_C = -b cos varphi + c cos phi + d cos psi = -68.40 + 140.95 + 49.24 = 121.79 mm,
    C = (u cos 30, u sin 30, b sin varphi - c sin phi + d sin psi) = (105.47, 60.90, 145.32) mm (Eqs. 9, 14
    with varphi in the A terms). The printed Eq. (14) (phi in the A terms) gives (1.95, 1.13, 25.78) mm."""
    vp, ph, ps, th = (math.radians(a) for a in (70, 20, 10, 30))
    u = -200 * math.cos(vp) + 150 * math.cos(ph) + 50 * math.cos(ps)
    z = 200 * math.sin(vp) - 150 * math.sin(ph) + 50 * math.sin(ps)
    pose = run.reference_pose()
    assert pose.tool.m_as("mm") == pytest.approx([u * math.cos(th), u * math.sin(th), z], rel=1e-9)
    u_doc = (-200 + 150) * math.cos(ph) + 50 * math.cos(ps)
    assert run.document_kinematics(pose)["C"] == pytest.approx(
        [u_doc * math.cos(th), u_doc * math.sin(th), 50 * math.sin(ph) + 50 * math.sin(ps)], rel=1e-9)


def test_inverse_quadrant(run):
    """Tool at theta = 135 deg: the printed Eq. (21) tan^-1(y0/x0) returns -45 deg (quadrant lost);
    atan2 and the elbow-up branch recover theta 135, varphi 70, phi 20 deg."""
    arm = run.arm()
    pose = arm.forward("70 deg", "20 deg", "10 deg", "135 deg")
    assert run.document_inverse(pose.tool.m_as("mm"), 10.0)["theta"] == pytest.approx(-45.0)
    back = arm.inverse(pose.tool, "10 deg", elbow_branch="up")
    assert [back.base.m_as("deg"), back.shoulder.m_as("deg"), back.elbow.m_as("deg")] == pytest.approx(
        [135.0, 70.0, 20.0], abs=1e-9)


def test_sweep_keeps_parallelograms_off_flat(run):
    """Reference pose: OAED |varphi - phi| = 50, OFGA 180 - (varphi + psi) = 100 -> 80, ABIH 90 - (phi + psi)
    = 60 deg; a pose with phi = varphi (OAED flat: the coupler DE cannot drive EAB) is not in the sweep."""
    from mechverify.mechanisms.lever_arm import pose_grid

    ang = run.transmission_angles(run.reference_pose())
    assert ang == pytest.approx({"OAED": 50.0, "OFGA": 80.0, "ABIH": 60.0})
    poses = pose_grid(run.arm(), (0, 180), (0, 90), (0, 90), 30.0, 40.0)
    assert poses and all(min(run.transmission_angles(x).values()) >= 40 - 1e-9 for x in poses)
    assert not any(abs(x.shoulder.m_as("deg") - x.elbow.m_as("deg")) < 1 for x in poses)
