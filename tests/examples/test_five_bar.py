"""Worked example of reference project 002 (five-bar manipulator): examples/five_bar.

Every expected value is computed here from the method it names, never copied from mechverify's output:
- the critical pose: both legs straight, |A1 P| = 200 mm with P on the mid-line x = 50 mm (geometry);
- the out-of-plane grillage by compatibility (Timoshenko & Gere, Mechanics of Materials, 1972, Sec. 7.8 and the
  cantilever formulas of Roark 8th ed. Table 8.1 case 1a; torsion of a thin-walled box by Bredt's formula,
  Roark 8th ed. Table 10.7 case 16): by symmetry each leg carries F/2 and the joint at P passes only a moment
  about the y axis, fixed by zero rotation about y at P (see `grillage_hand`);
- the document's own FEA results scaled linearly with the load (Sec. 3 of the document);
- ANSYS's fully reversed fatigue factor S_N(1e6) / sigma (S-N table of 'Structural Steel': 86.2 MPa at 1e6);
- motor torques by virtual work with finite differences of the forward kinematics written out here
  (Meriam & Kraige, Engineering Mechanics: Statics, 7th ed., Art. 7/3).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechverify.cli import main
from mechverify.design import load
from tests.builders import run_module as run_file

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "five_bar"
L = 0.200  # leg A1-B1-P, two 100 mm links in line [m]
E_PLA, NU_PLA = 2539e6, 0.36  # Stratasys PLA XY; nu assumed in the design file
B, H, T = 0.020, 0.012, 0.0015  # assumed hollow rectangle: width (in plane), height (out of plane), wall [m]


def run_module():
    return run_file(EXAMPLE / "run.py", "five_bar_run")


def grillage_hand(F: float, E: float, G: float) -> tuple[float, float]:
    """(deflection at P [m], bending moment at the motor hub [N m]) for F down at P."""
    I = (B * H**3 - (B - 2 * T) * (H - 2 * T) ** 3) / 12  # bending out of plane
    Am = (B - T) * (H - T)  # area inside the wall's mid-line
    J = 4 * Am**2 * T / (2 * ((B - T) + (H - T)))  # Bredt, uniform wall
    As = 2 * H * T  # shear area of a box ~ its two webs
    ex, ey = 0.05 / L, math.sqrt(L**2 - 0.05**2) / L  # leg direction from A1 to P
    f = F / 2
    # zero rotation about y at P: m (ey^2 / GJ + ex^2 / EI) L = -f L^2 ex / (2 E I)
    m = -f * L * ex / (2 * E * I) / (ey**2 / (G * J) + ex**2 / (E * I))
    w = f * L**3 / (3 * E * I) + m * ex * L**2 / (2 * E * I) + f * L / (G * As)
    return w, f * L + m * ex


def test_cli_exit_codes():
    assert main(["check", str(EXAMPLE / "design.toml")]) == 0
    assert main(["check", str(EXAMPLE / "design_corrected.toml")]) == 0  # two warnings, no failure


def test_critical_pose():
    mod = run_module()
    pose = mod.critical_pose()
    assert pose.P * 1e3 == pytest.approx([50.0, math.sqrt(200**2 - 50**2)], abs=1e-9)
    assert pose.theta_left.m_as("deg") == pytest.approx(math.degrees(math.atan2(math.sqrt(200**2 - 50**2), 50)))
    assert pose.theta_right.m_as("deg") == pytest.approx(180 - math.degrees(math.atan2(193.6491673, 50)))
    # the design file's nodes are that pose (B1, B2 at the middle of each leg)
    comp = load(EXAMPLE / "design.toml").data.components["pla_links"].obj
    assert comp.frame.nodes["P"] * 1e3 == pytest.approx([50, 193.6492, 0], abs=1e-3)
    assert comp.frame.nodes["B1"] * 1e3 == pytest.approx([25, 96.8246, 0], abs=1e-3)


def test_pla_grillage_against_hand_compatibility():
    res = {r.check: r for r in load(EXAMPLE / "design.toml").verify() if r.component == "pla_links"}
    w, M = grillage_hand(1.5, E_PLA, E_PLA / (2 * (1 + NU_PLA)))
    assert res["frame_deflection"].demand.m_as("m") == pytest.approx(w, rel=0.02)  # Bredt J, web shear area
    comp = load(EXAMPLE / "design.toml").data.components["pla_links"].obj
    from mechverify.fea.frame import FramePointLoad

    d = comp.frame.solve([FramePointLoad("P", force=["0 N", "0 N", "-1.5 N"])]).diagram("link2")
    I = (B * H**3 - (B - 2 * T) * (H - 2 * T) ** 3) / 12
    assert np.max(np.abs(d.normal_stress.m_as("Pa"))) == pytest.approx(M * (H / 2) / I, rel=0.01)
    # the document's criterion (SF 4 against Sy = 26 MPa) holds with a wide margin in the beam model
    assert res["frame_stress"].safety_factor > 4 * 10


def test_document_numbers_scaled():
    """Sec. 3: 1.5 N gives SF 3.9 and 3.3 mm on the PLA links; 15 N gives SF 3.56 on steel (Sy 250 MPa)."""
    s = run_module().document_scaling()
    assert s["gripper_weight"] == pytest.approx(1.5 - 0.077 * 9.80665)
    assert s["F_static_sf4"] == pytest.approx(1.5 * 3.9 / 4)
    assert s["F_deflection 1 mm (1 % of the 100 mm links, Sec. 2.4.2)"] == pytest.approx(1.5 / 3.3)
    # within the document's own 1 mm limit the printed links cannot even carry the gripper
    assert 1.5 / 3.3 < s["gripper_weight"]
    assert s["sigma_steel_MPa"] == pytest.approx(250 / 3.56)
    assert s["pla_strength_implied_MPa"] == pytest.approx(250 / 3.56 / 10 * 3.9)


def test_steel_fatigue_as_ansys_and_the_document_value():
    res = {r.check: r for r in load(EXAMPLE / "design.toml").verify() if r.component == "steel_links"}
    # fully reversed, no mean stress: SF_fatigue / SF_static = S_N(1e6) / Sy = 86.2 / 250 (same von Mises stress)
    assert res["frame_fatigue"].safety_factor / res["frame_stress"].safety_factor == pytest.approx(86.2 / 250)
    # the document's stress (250 / 3.56 = 70.2 MPa) reproduces its fatigue factor 1.229 the same way
    from mechverify.checks.fatigue import check_fatigue

    r = check_fatigue("link", f"{250 / 3.56} MPa", "0 MPa", "Structural Steel", life=1e6)
    assert r.safety_factor == pytest.approx(86.2 * 3.56 / 250, rel=1e-6)
    assert r.safety_factor == pytest.approx(1.229, abs=0.002)


def test_corrected_payload_meets_the_criteria():
    res = {(r.component, r.check): r for r in load(EXAMPLE / "design_corrected.toml").verify()}
    assert res[("pla_links", "frame_deflection")].demand.m_as("mm") <= 1.0
    assert res[("pla_links", "frame_stress")].safety_factor >= 4.0
    # 3.4 N is the largest round load: by linearity 3.5 N would exceed 1 mm (self-weight part held fixed)
    mod = run_module()
    pn = mod.frame_per_newton()
    assert pn["delta_self"] + 3.5 * pn["delta_per_N"] > 1.0 >= pn["delta_self"] + 3.4 * pn["delta_per_N"]
    assert res[("steel_links", "frame_fatigue")].passed


def _forward(t1: float, t2: float) -> np.ndarray:
    """Tool point of the 100 mm five-bar ('+' assembly: the upper circle intersection)."""
    B1 = np.array([0.1 * math.cos(t1), 0.1 * math.sin(t1)])
    B2 = np.array([0.1 + 0.1 * math.cos(t2), 0.1 * math.sin(t2)])
    d = np.linalg.norm(B2 - B1)
    mid = (B1 + B2) / 2
    h = math.sqrt(0.1**2 - (d / 2) ** 2)
    n = np.array([-(B2 - B1)[1], (B2 - B1)[0]]) / d
    return mid + h * n


def test_gearhead_fit_by_virtual_work():
    g = run_module().gearhead_fit((50.0, 150.0))
    # the pose's motor angles from the run, then dP/dtheta by central differences of _forward
    t1, t2 = math.radians(g["theta_left_deg"]), math.radians(g["theta_right_deg"])
    assert _forward(t1, t2) * 1e3 == pytest.approx([50, 150], abs=1e-6)
    h = 1e-7
    Jc = np.column_stack([(_forward(t1 + h, t2) - _forward(t1 - h, t2)) / (2 * h),
                          (_forward(t1, t2 + h) - _forward(t1, t2 - h)) / (2 * h)])
    k = np.linalg.norm(Jc.T, 2)  # tau = -Jc^T F: largest torque per newton over force directions
    assert g["torque_per_N"] == pytest.approx(k, rel=1e-4)
    assert g["F_allow"] == pytest.approx(3.0 / k, rel=1e-4)  # PG100: 3 N m continuous at the output
    # the document's "40 N m" would need 40 / (100 x 0.73) = 0.548 N m at the motor, 8 x the 5 N m momentary limit
    assert 40 / 5 == 8 and g["motor_torque_for_40Nm"] == pytest.approx(40 / 73)
