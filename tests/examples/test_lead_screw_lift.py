"""Reference project 004 (lead-screw lift, the ``make demo`` example) end to end: examples/lead_screw_lift/.

Every expected number is worked out here from the published formula it names, with the document's inputs:
Tr10x2 (ISO 2904: d2 = d - P/2 = 9 mm, d3 = d - 2 h3 = 7.5 mm, H1 = P/2 = 1 mm, flank 15°), 450 mm, 350 N,
iglidur R nut (Tabla 3: mu 0.09..0.25, pv 0.27 MPa·m/s, 23 MPa), 18 mm/s = 540 rpm, SKF 608 (Tabla 9:
C 3.45 kN, C0 1.37 kN, f0 12), the Tabla 8 stepper (82 g·cm², two curve points 0.35 N·m @ 500 rpm,
0.25 N·m @ 850 rpm), Inventor's default steel (E 210 GPa, Sy 207 MPa, 7850 kg/m³).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import mechverify.design
from mechverify.cli import main
from tests.builders import run_module

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lead_screw_lift"
DESIGN = EXAMPLE / "design.toml"

F, L, D2, D3, LEAD, H1 = 350.0, 0.450, 9e-3, 7.5e-3, 2e-3, 1e-3
E, SY, RHO = 210e9, 207e6, 7850.0
MU_MIN, MU_MAX = 0.09, 0.25
N_RPM = 0.018 / LEAD * 60  # 540 rpm


def _run_module():
    return run_module(EXAMPLE / "run.py", "lead_screw_lift_run_test")


@pytest.fixture(scope="module")
def results():
    return mechverify.design.load(DESIGN).verify()


def _one(results, component, check):
    found = list(results.where(component=component, check=check))
    assert len(found) == 1, [(r.component, r.check) for r in results]
    return found[0]


def _angles(lead, d2):
    """Lead angle tan(lam) = l/(pi d2) and the normal-plane flank angle tan(an) = tan(15°) cos(lam)
    (Hamrock, Schmid & Jacobson, Fundamentals of Machine Elements, 3rd ed., Sec. 16.3, Eq. 16.8)."""
    lam = math.atan(lead / (math.pi * d2))
    return lam, math.atan(math.tan(math.radians(15)) * math.cos(lam))


def _torque_per_newton(mu, lead=LEAD, d2=D2):
    """Raising torque / F = d2/2 (cos an tan lam + mu)/(cos an - mu tan lam) (Hamrock 3rd ed. Eqs. 16.8-16.10)."""
    lam, an = _angles(lead, d2)
    return d2 / 2 * (math.cos(an) * math.tan(lam) + mu) / (math.cos(an) - mu * math.tan(lam))


def test_cli_check_exits_1_because_the_design_fails(capsys):
    assert main(["check", str(DESIGN)]) == 1
    assert "4 fail" in capsys.readouterr().out


def test_failing_checks_are_the_three_the_example_documents(results):
    failed = sorted((r.component, r.check) for r in results if r.verdict.value == "fail")
    assert failed == [("carriage", "carriage_binding"), ("lift", "motor_peak_torque"), ("lift_screw", "nut_pv"),
                      ("screw_horizontal", "member_body_strength")]


def test_carriage_binding_on_the_rod_bushings(results):
    """The arms hang in front of the rods: 2 x (120 N x 400 mm + 30 N x 800 mm) = 144 N·m over 350 N is a 411 mm
    offset. Carried by the bushing ends (L = 30 mm, assumed), N = 144/0.03 = 4800 N; their friction at mu 0.18
    (Tabla 7) adds 2 mu M/L = 1728 N: the drive must push F = 350 (1 + 2 x 0.18 x 0.4114/0.03) = 2078 N, not the
    350 N it was sized for (edge-force equilibrium; hand calculation, the document has no guide check)."""
    r = _one(results, "carriage", "carriage_binding")
    a = 2 * (120 * 0.4 + 30 * 0.8) / F
    assert r.demand.m_as("N") == pytest.approx(F * (1 + 2 * 0.18 * a / 0.03), rel=1e-9)
    assert r.capacity.m_as("N") == pytest.approx(F)
    assert r.details["edge_force"].m_as("N") == pytest.approx(144 / 0.03, rel=1e-9)
    assert not r.passed


def test_self_locking_angles(results):
    """lam = atan(2/(9 pi)) = 4.046°, rho' = atan(0.09/cos an) = 5.322° (Hamrock Eq. 16.8; Shigley 9th ed. Sec. 8-2)."""
    lam, an = _angles(LEAD, D2)
    r = _one(results, "lift_screw", "self_locking")
    assert r.demand.m_as("deg") == pytest.approx(math.degrees(lam), rel=1e-9)
    assert r.capacity.m_as("deg") == pytest.approx(math.degrees(math.atan(MU_MIN / math.cos(an))), rel=1e-9)
    assert r.passed


def test_motor_torque_at_540_rpm_with_the_highest_friction(results):
    """Peak at the end of the 0.1 m/s² ramp: T = m (g + a) T/F(mu_max) + (J_rotor + J_screw) a 2 pi/l, with
    J_screw = pi rho L d2^4/32 (solid cylinder); limit by linear interpolation of the two curve points."""
    m, g, a = F / 9.81, 9.80665, 0.1  # the design's mass = lifted_load / g with the document's g = 9.81 m/s²
    j = 82e-7 + math.pi * RHO * L * D2**4 / 32
    t = m * (g + a) * _torque_per_newton(MU_MAX) + j * a * 2 * math.pi / LEAD
    limit = 0.35 + (N_RPM - 500) / (850 - 500) * (0.25 - 0.35)
    r = _one(results, "lift", "motor_peak_torque")
    assert r.demand.m_as("N*m") == pytest.approx(t, rel=1e-6)
    assert r.capacity.m_as("N*m") == pytest.approx(limit, rel=1e-9)
    assert F * _torque_per_newton(MU_MAX) > limit  # fails even without the 1.5 margin and without acceleration


def test_nut_pressure_and_pv(results):
    """p = F/(pi d2 H1 n), n = 10 mm / 2 mm (DIN 103 mean flank pressure); v = pi d2 n_rot / cos(lam)."""
    lam, _ = _angles(LEAD, D2)
    p = F / (math.pi * D2 * H1 * 5)
    v = math.pi * D2 * N_RPM / 60 / math.cos(lam)
    assert _one(results, "lift_screw", "nut_flank_pressure").demand.m_as("Pa") == pytest.approx(p, rel=1e-9)
    assert _one(results, "lift_screw", "nut_pv").demand.m_as("Pa*m/s") == pytest.approx(p * v, rel=1e-9)
    assert p * v > 0.27e6
    # the nut length pv needs at 540 rpm: p v L = const -> L = 10 mm x pv / 0.27
    assert 10 * p * v / 0.27e6 == pytest.approx(23.4, abs=0.05)


def test_buckling_and_critical_speed(results):
    """Euler, pinned ends: P = pi² E I/L², I = pi d3^4/64 (Shigley 10th ed. Eq. 4-42, C = 1); first whirl of a
    pinned-pinned shaft n = (pi/(2 L²)) sqrt(E I/(rho A)) [rev/s] (Blevins 1979, Table 8-1, lambda = pi)."""
    i = math.pi * D3**4 / 64
    a = math.pi * D3**2 / 4
    pcr = math.pi**2 * E * i / L**2
    nc = math.pi / (2 * L**2) * math.sqrt(E * i / (RHO * a)) * 60
    assert _one(results, "lift_screw", "screw_buckling").capacity.m_as("N") == pytest.approx(pcr, rel=1e-6)
    assert _one(results, "lift_screw", "screw_critical_speed").capacity.m_as("rpm") == pytest.approx(nc, rel=1e-5)  # lambda_1 tabulated
    assert pcr == pytest.approx(1590, rel=1e-3) and nc == pytest.approx(4514, rel=1e-3)


def test_bearing_608_life(results):
    """ISO 281: f0 Fa/C0 = 12·350/1370 = 3.066 -> Y by linear interpolation of Table 3 between 2.07 (1.31) and
    3.45 (1.15); Fr = 0 so X = 0.56; L10h = (C/P)^3 10^6/(60 n)."""
    y = 1.31 + (12 * F / 1370 - 2.07) / (3.45 - 2.07) * (1.15 - 1.31)
    p = 0.56 * 0 + y * F
    l10h = (3450 / p) ** 3 * 1e6 / (60 * N_RPM)
    r = _one(results, "screw_bearing", "bearing_life")
    assert r.capacity.m_as("h") == pytest.approx(l10h, rel=1e-4)
    assert r.verdict.value == "warn"  # passes 10 000 h, but Fa > 0.25 C0 = 342.5 N (SKF guideline)


def test_screw_bending_horizontal_posture(results):
    """120 N at mid-span, pinned ends: M = F L/4 (Shigley 10th ed. Table A-9 case 5), sigma = 32 M/(pi d3³)."""
    sigma = 120 * L / 4 * 32 / (math.pi * D3**3)
    r = _one(results, "screw_horizontal", "member_body_strength")
    assert r.demand.m_as("Pa") == pytest.approx(sigma, rel=1e-3)  # + a negligible transverse-shear term
    assert SY / sigma < 1  # yields even without a safety factor


def test_clamped_ends_reproduce_the_documents_inventor_figures():
    """Table A-9 case 14 (fixed-fixed, centre load): M = F L/8, y = F L³/(192 E I). The document's Tr10x2 figures
    (SF 1.2, 0.8 mm) match clamped ends: SF at d3 = 1.27, y with the d2 cylinder = 0.84 mm."""
    run = _run_module()
    row = run.screw_bending("Tr10x2", "clamped")
    sf = SY / (120 * L / 8 * 32 / (math.pi * D3**3))
    y = 120 * L**3 / (192 * E * math.pi * D2**4 / 64)
    assert row.safety_factor == pytest.approx(sf, rel=1e-9)
    assert row.deflection["d2"] == pytest.approx(y * 1e3, rel=1e-9)
    assert sf == pytest.approx(1.27, abs=0.01) and y * 1e3 == pytest.approx(0.84, abs=0.01)


def test_document_thread_table_formulas_and_the_corrected_table():
    """The document's Tabla 2/4 values follow its Formulas 2-4 as printed (alpha = tan(l/(pi D2)) instead of the
    arctangent, tan(beta_n) = tan(beta) tan(alpha)); with the correct angles Tr12x3 and Tr16x4 ARE self-locking."""
    run = _run_module()
    rows = {r.designation: r for r in run.thread_table()}
    for r in rows.values():
        doc = r.doc
        lead = {"Tr6x2P1": 2.0}.get(r.designation) or float(r.designation.split("x")[1].split("P")[0])
        alpha_doc = math.tan(lead / (math.pi * float(doc["D2_mm"])))
        assert float(doc["alpha_rad"]) == pytest.approx(alpha_doc, rel=1e-6)
        beta_n = math.atan(math.tan(math.radians(15)) * math.tan(alpha_doc))
        assert float(doc["delta_rad"]) == pytest.approx(math.atan(MU_MIN / math.cos(beta_n)), rel=1e-6)
        lam, an = _angles(lead * 1e-3, float(doc["D2_mm"]) * 1e-3)
        assert r.lead_angle == pytest.approx(lam, rel=1e-9)
        assert r.self_locking == (lam <= math.atan(MU_MIN / math.cos(an)))
    assert [d for d, r in rows.items() if r.self_locking != (r.doc["self_locking"] == "yes")] == ["Tr12x3", "Tr16x4"]
    assert rows["Tr10x2"].torque_max == pytest.approx(F * _torque_per_newton(MU_MAX), rel=1e-9)
    assert rows["Tr10x2"].torque_max == pytest.approx(0.529, abs=5e-4)


def test_demo_writes_the_report_outside_the_example(tmp_path, capsys):
    from mechverify import demo

    assert demo.main(["--no-pdf", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "report.html").stat().st_size > 10_000
    assert "4 fail" in capsys.readouterr().out


# ------------------------------------------------------------------ plates: plate-bending FEA (design_plates.toml)
PLATES = EXAMPLE / "design_plates.toml"
AL_E, AL_NU, AL_SY = 68.9e9, 0.33, 275e6  # Inventor's default Aluminum 6061


@pytest.fixture(scope="module")
def plates():
    d = mechverify.design.load(PLATES)
    return d, d.verify()


def test_plates_cli_exits_1_because_the_4_mm_arm_plate_fails(capsys):
    assert main(["check", str(PLATES)]) == 1
    assert "2 fail" in capsys.readouterr().out


def test_plate_results_scale_as_kirchhoff_theory_and_exceed_the_nominal_bounds(plates):
    """Kirchhoff plate theory (Timoshenko & Woinowsky-Krieger 2nd ed., ch. 4): with loads independent of t,
    M does not depend on t, sigma = 6 M / t^2 and w ~ 1/D ~ 1/t^3; so the arm plate at 4 and 6 mm (same mesh,
    moment couples only) must give sigma ratio (6/4)^2 = 2.25 and deflection ratio (6/4)^3 = 3.375.
    Nominal lower bounds on the peak: the arm's 48 N m twisting the 160 mm plate strip, tau = T/Wt with
    Wt = k2 b t^2 (Timoshenko & Goodier Sec. 109; b/t = 26.7: k2 = (1 - 0.630 t/b)/3 to 0.1 %),
    sigma_vM = sqrt(3) tau; the base plate's mean stress across the mid-section 6 (P a / 4) / (b t^2) with
    P = 380 N on four corner supports (statics)."""
    _, rs = plates
    s4, s6 = (rs.get(f"arm_plate_{t}", "plate_stress_fea").demand.m_as("Pa") for t in (4, 6))
    w4, w6 = (rs.get(f"arm_plate_{t}", "plate_deflection_fea").demand.m_as("m") for t in (4, 6))
    assert s4 / s6 == pytest.approx(2.25, rel=1e-3)
    assert w4 / w6 == pytest.approx(3.375, rel=1e-3)
    for t, s in ((4e-3, s4), (6e-3, s6)):
        b = 0.160
        wt = (1 - 0.630 * t / b) / 3 * b * t**2
        assert s > math.sqrt(3) * 48.0 / wt
    for t in (8e-3, 6e-3):
        sb = rs.get(f"base_plate_{round(t * 1e3)}", "plate_stress_fea").demand.m_as("Pa")
        assert sb > 6 * (380 * 0.450 / 4) / (0.400 * t**2)
    # the document's 6 mm arm-plate SF 2.75 and base-plate deflections 0.17 / 0.39 mm (Figs. 28, 31, 33)
    assert AL_SY / s6 == pytest.approx(2.75, rel=0.05)
    assert rs.get("base_plate_8", "plate_deflection_fea").demand.m_as("mm") == pytest.approx(0.17, rel=0.05)
    assert rs.get("base_plate_6", "plate_deflection_fea").demand.m_as("mm") == pytest.approx(0.39, rel=0.06)


def test_arm_plate_as_a_cantilever_lies_between_beam_and_plate_strip_theory(tmp_path):
    """The arm plate (335 x 160 x 4 mm) clamped along its long bottom edge, 50 N along its top edge (a 5 mm
    strip, lever L = 157.5 mm). Its tip deflection must lie between the beam (E I, free anticlastic bending)
    and the plate-strip value (cylindrical bending, D = E t^3 / 12 (1 - nu^2)): Shigley 10th ed. Table A-9-1
    y = F L^3 / (3 E I), I = b t^3 / 12, times (1 - nu^2) for the strip (Timoshenko & Woinowsky-Krieger ch. 1).
    At the clamped root the edge cannot curve along itself, so sigma_x = nu sigma_y there with the mean
    sigma_y = 6 F L / (b t^2): von Mises (Shigley Eq. 5-13) sigma_y sqrt(1 - nu + nu^2) is a lower bound on the
    peak."""
    body = (PLATES.read_text().split("[components.arm_plate_4]")[0]
            + '[components.c]\ntype = "plate_fea"\nwidth = "335 mm"\nheight = "160 mm"\nthickness = "4 mm"\n'
              'material = "Inventor Aluminum 6061"\nsupports = [{ edges = ["bottom"], type = "fixed" }]\n'
              'mesh_size = "10 mm"\n[load_cases.tip.c]\n'
              'patch_loads = [{ center = "167.5, 157.5", size = "335, 5", force = "-50 N" }]\n')
    p = tmp_path / "c.toml"
    p.write_text(body)
    rs = mechverify.design.load(p).verify()
    b, t, lever, force = 0.335, 4e-3, 0.1575, 50.0
    y_beam = force * lever**3 / (3 * AL_E * b * t**3 / 12)
    y = rs.get("c", "plate_deflection_fea").demand.m_as("m")
    assert y_beam * (1 - AL_NU**2) < y < y_beam
    sigma_root = 6 * force * lever / (b * t**2)
    assert rs.get("c", "plate_stress_fea").demand.m_as("Pa") > sigma_root * math.sqrt(1 - AL_NU + AL_NU**2)
