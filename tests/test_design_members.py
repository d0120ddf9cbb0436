"""Design files with links and plates: numbers against hand calculations from the published formulas
(Shigley's Mechanical Engineering Design, 10th ed., Budynas & Nisbett 2015: Secs. 3-10/3-12, Table A-9,
Eqs. (4-42)/(4-46), Table 4-2; ASME BTH-1-2008 Sec. 3-3.3.1; Roark's Formulas for Stress and Strain, 8th ed.,
Tables 11.2 and 11.4; Peterson's Stress Concentration Factors, 3rd ed., Eq. (4.1)), errors with key paths,
and the report of a link design (typeset formulas, figures)."""

import math
import textwrap

import pytest

from mechverify.components.links import beam_deflection_curve
from mechverify.design import DesignFileError, load
from mechverify.reports import render_html

# A steel with round numbers so the hand calculations below are easy to follow.
MATERIALS = """
[materials.steel]
base = "S235JR"
E = "200 GPa"
yield_strength = "300 MPa"
ultimate_strength = "400 MPa"
elongation = 0.2
"""


def design(tmp_path, body, materials=MATERIALS):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent('[design]\nname = "members"\n' + materials + body))
    return load(p)


# ----------------------------------------------------------------------------------------- link body
BAR = """
[components.bar]
type = "link"
length = "400 mm"
section = "rectangle"
width = "10 mm"
height = "20 mm"
material = "steel"
deflection_limit = "L/250"
{extra}
[load_cases.work.bar]
{loads}
"""


def test_simply_supported_centre_load_matches_shigley_table_a9_5(tmp_path):
    """Shigley Table A-9-5 (simple supports, centre load): M_max = F l/4, y_max = F l^3/(48 E I), V = F/2.
    Rectangle b = 10, h = 20 mm (h in the load plane): I = b h^3/12 = 6666.7 mm^4, W = b h^2/6 = 666.7 mm^3
    (Shigley Sec. 3-10: sigma = M c / I). F = 500 N, l = 400 mm, N = 1000 N tension:
    M = 50 N m, sigma_b = 75 MPa, sigma_a = N/A = 5 MPa, tau = V/(5/6 A) = 250/166.7 = 1.5 MPa,
    sigma_vM = sqrt(80^2 + 3 * 1.5^2) = 80.042 MPa; y = 500 * 0.4^3/(48 * 200e9 * 6.6667e-9) = 0.5 mm;
    limit L/250 = 1.6 mm."""
    rs = design(tmp_path, BAR.format(extra="", loads='axial_force = "1000 N"\ntransverse_load = "500 N"')).verify()
    body = rs.get("bar", "member_body_strength")
    assert body.demand.m_as("MPa") == pytest.approx(math.sqrt(80**2 + 3 * 1.5**2), rel=1e-6)
    assert body.capacity.m_as("MPa") == pytest.approx(300)
    assert body.required_sf == 2.0
    assert body.inputs["My"].m_as("N*m") == pytest.approx(50)
    defl = rs.get("bar", "link_deflection")
    assert defl.demand.m_as("mm") == pytest.approx(0.5, rel=1e-9)
    assert defl.capacity.m_as("mm") == pytest.approx(400 / 250)
    assert defl.details["beam_case"] == "simply_supported_center_load"


def test_cantilever_uniform_load_matches_shigley_table_a9_3(tmp_path):
    """Table A-9-3 (cantilever, uniform w): y = w l^4/(8 E I), M = w l^2/2 at the wall, V = w l.
    w = 1000 N/m, l = 0.4 m, E I = 200e9 * 6.6667e-9 = 1333.3 N m^2: y = 1000 * 0.0256/(8 * 1333.3) = 2.4 mm,
    M = 80 N m -> sigma = 80/666.7e-9 = 120 MPa, tau = 400/166.7 mm^2 = 2.4 MPa."""
    rs = design(tmp_path, BAR.format(extra='end = "fixed-free"', loads='distributed_load = "1 N/mm"')).verify()
    defl = rs.get("bar", "link_deflection")
    assert defl.demand.m_as("mm") == pytest.approx(1000 * 0.4**4 / (8 * 200e9 * 10 * 20**3 / 12 * 1e-12) * 1e3)
    assert defl.demand.m_as("mm") == pytest.approx(2.4, rel=1e-9)
    body = rs.get("bar", "member_body_strength")
    assert body.demand.m_as("MPa") == pytest.approx(math.sqrt(120**2 + 3 * 2.4**2), rel=1e-6)


def test_deflection_limit_forms(tmp_path):
    """A length, 'L/n', a fraction, and the design's requirements.deflection_limit (default 0.002 = L/500)."""
    loads = 'transverse_load = "500 N"'
    for extra, lim_mm in (('deflection_limit = "0.4 mm"', 0.4), ("deflection_limit_fraction = 0.01", 4.0)):
        rs = design(tmp_path, BAR.format(extra="", loads=loads).replace('deflection_limit = "L/250"', extra)).verify()
        r = rs.get("bar", "link_deflection")
        assert r.capacity.m_as("mm") == pytest.approx(lim_mm)
    rs = design(tmp_path, BAR.format(extra="", loads=loads).replace('deflection_limit = "L/250"', "")).verify()
    assert rs.get("bar", "link_deflection").capacity.m_as("mm") == pytest.approx(0.002 * 400)
    assert rs.get("bar", "link_deflection").utilisation == pytest.approx(0.5 / 0.8)

def test_torsion_of_a_tube_matches_shigley_sec_3_12(tmp_path):
    """tau = T r / J (Shigley Sec. 3-12), tube 20 x 2: J = pi (20^4 - 16^4)/32 = 9274.2 mm^4; T = 20 N m:
    tau = 20 * 0.010 / 9274.2e-12 = 21.566 MPa; von Mises sqrt(3) tau = 37.35 MPa."""
    body = """
    [components.shaft]
    type = "link"
    length = "300 mm"
    section = "tube"
    outer_diameter = "20 mm"
    thickness = "2 mm"
    material = "steel"
    [load_cases.twist.shaft]
    torque = "20 N*m"
    """
    r = design(tmp_path, body).verify().get("shaft", "member_body_strength")
    J = math.pi * (20**4 - 16**4) / 32
    assert r.demand.m_as("MPa") == pytest.approx(math.sqrt(3) * 20e3 * 10 / J, rel=1e-6)


# -------------------------------------------------------------------------------------------- buckling
STRUT = """
[components.strut]
type = "link"
length = "{length}"
section = "tube"
outer_diameter = "20 mm"
thickness = "2 mm"
material = "steel"
end = "{end}"
[load_cases.push.strut]
axial_force = "-2000 N"
"""
I_TUBE = math.pi * (20**4 - 16**4) / 64  # 4637.1 mm^4
A_TUBE = math.pi * (20**2 - 16**2) / 4  # 113.10 mm^2
K_TUBE = math.sqrt(I_TUBE / A_TUBE)  # 6.403 mm


def test_euler_column_matches_shigley_eq_4_42(tmp_path):
    """P_cr = C pi^2 E I / l^2 (Shigley Eq. 4-42), C = 1 pinned-pinned: l = 1000 mm, l/k = 156.2 >
    (l/k)_1 = sqrt(2 pi^2 C E / Sy) = sqrt(2 pi^2 200e3/300) = 114.7 (Eq. 4-45):
    P_cr = pi^2 * 200e9 * 4637.1e-12 / 1.0^2 = 9153 N. Fixed-free: C = 1/4 (Table 4-2) -> 2288 N."""
    r = design(tmp_path, STRUT.format(length="1000 mm", end="pinned-pinned")).verify().get("strut", "member_buckling")
    assert 1000 / K_TUBE > math.sqrt(2 * math.pi**2 * 200e3 / 300)
    assert r.capacity.m_as("N") == pytest.approx(math.pi**2 * 200e9 * I_TUBE * 1e-12, rel=1e-6)
    assert r.capacity.m_as("N") == pytest.approx(9153, rel=1e-3)
    assert r.demand.m_as("N") == pytest.approx(2000)
    assert r.required_sf == 3.0
    r = design(tmp_path, STRUT.format(length="1000 mm", end="fixed-free")).verify().get("strut", "member_buckling")
    assert r.capacity.m_as("N") == pytest.approx(0.25 * math.pi**2 * 200e9 * I_TUBE * 1e-12, rel=1e-6)


def test_johnson_column_matches_shigley_eq_4_46(tmp_path):
    """P_cr = A [Sy - (Sy l/(2 pi k))^2 / (C E)] (Eq. 4-46) for l/k = 500/6.403 = 78.1 < 114.7:
    113.10 mm^2 * [300 - (300 * 78.09/(2 pi))^2 / 200e3] MPa = 113.10 * 230.5 = 26069 N."""
    r = design(tmp_path, STRUT.format(length="500 mm", end="pinned-pinned")).verify().get("strut", "member_buckling")
    lk = 500 / K_TUBE
    expected = A_TUBE * (300 - (300 * lk / (2 * math.pi)) ** 2 / 200e3)
    assert r.capacity.m_as("N") == pytest.approx(expected, rel=1e-6)
    assert expected == pytest.approx(26069, rel=1e-3)


def test_tension_gives_no_buckling_demand(tmp_path):
    r = design(tmp_path, STRUT.format(length="500 mm", end="pinned-pinned").replace("-2000", "2000")).verify()
    assert r.get("strut", "member_buckling").demand.m_as("N") == 0


# ---------------------------------------------------------------------------------------- eye, lug, pin
EYE = """
[components.eye]
type = "link"
length = "200 mm"
section = "rectangle"
width = "30 mm"
height = "8 mm"
material = "{material}"
hole_diameter = "10 mm"
pin_material = "steel"
{extra}
[load_cases.pull.eye]
axial_force = "3000 N"
"""


def test_lug_matches_asme_bth1_equations(tmp_path):
    """ASME BTH-1-2008 Sec. 3-3.3.1 by hand: Dh = Dp = 10, w = 30 (default: the bar's larger side), t = 8 (its
    smaller side), R = w/2 = 15 mm, rounded; Fy = 300, Fu = 400 MPa; Cr = 1 (Eq. 3-46, no clearance).
    be = 10; b_eff = min(be, 4t, 0.6 Fu/Fy sqrt(Dh/be) be) = min(10, 32, 8) = 8 mm (Eqs. 3-47, 3-48).
    Pt = Cr Fu 2 t b_eff = 51 200 N (3-45); Pb = Cr Fu [1.13 (R - Dh/2) + 0.92 be/(1 + be/Dh)] t = 50 880 N (3-49);
    phi = 55 deg, Z' = R - sqrt(R^2 - (Dp/2 sin phi)^2), Av = 2 [a + Dp/2 (1 - cos phi) - Z'] t, Pv = 0.70 Fu Av
    (3-50..3-52, C3-2); Pp = 1.25 Fy Dp t = 30 000 N. Allowables: P/(1.20 Nd) and Pp/Nd with Nd = required SF."""
    rs = design(tmp_path, EYE.format(material="steel", extra="")).verify()
    phi = math.radians(55)
    z = 15 - math.sqrt(15**2 - (5 * math.sin(phi)) ** 2)
    Av = 2 * (10 + 5 * (1 - math.cos(phi)) - z) * 8
    expected = {"lug_tension": 400 * 2 * 8 * 8 / 1.2, "lug_fracture_beyond": 400 * (1.13 * 10 + 0.92 * 10 / 2) * 8 / 1.2,
                "lug_shear_out": 0.70 * 400 * Av / 1.2, "lug_bearing": 1.25 * 300 * 10 * 8}
    for check, cap in expected.items():
        r = rs.get("eye", check)
        assert r.capacity.m_as("N") == pytest.approx(cap, rel=1e-6), check
        assert r.demand.m_as("N") == pytest.approx(3000)
        assert r.required_sf == 2.0  # Nd = 2.0, BTH-1 Design Category A
    assert 400 * 2 * 8 * 8 == 51200 and 400 * (1.13 * 10 + 0.92 * 10 / 2) * 8 == pytest.approx(50880)


def test_eye_net_section_and_pin_shear(tmp_path):
    """Net section F/((w - D) t) = 3000/(20 * 8) = 18.75 MPa; ductile steel under static load: no Kt (Shigley
    Sec. 3-13). Pin in double shear: tau = F/(2 pi d^2/4) = 3000/157.08 = 19.099 MPa against 0.577 Sy = 173.1 MPa
    (Shigley Eq. 5-21)."""
    rs = design(tmp_path, EYE.format(material="steel", extra="")).verify()
    net = rs.get("eye", "eye_net_section")
    assert net.demand.m_as("MPa") == pytest.approx(18.75)
    assert net.details["kt_applied"] is False
    pin = rs.get("eye", "pin_shear")
    assert pin.demand.m_as("MPa") == pytest.approx(3000 / (2 * math.pi * 25), rel=1e-9)
    assert pin.capacity.m_as("MPa") == pytest.approx(0.577 * 300)


def test_brittle_printed_eye_gets_peterson_kt_and_knock_down(tmp_path):
    """PLA (elongation 1 %) is brittle: the open-hole net-section Kt of Peterson 3rd ed. Eq. (4.1),
    Ktn = 2 + 0.284 (1 - d/H) - 0.600 (1 - d/H)^2 + 1.32 (1 - d/H)^3 = 2.3138 at d/H = 1/3 (Heywood's older
    fit 3 - 3.14 x + 3.667 x^2 - 1.527 x^3 gives 2.304, 0.4 % lower), multiplies the net stress;
    strength_factor = 0.5 halves S_y = 26 MPa (the library's Stratasys XY value)."""
    extra = 'strength_factor = 0.5\nprint_orientation = "Z"'
    rs = design(tmp_path, EYE.format(material="PLA (FDM, XY flat)", extra=extra).replace("3000 N", "100 N")).verify()
    net = rs.get("eye", "eye_net_section")
    x = 1 - 1 / 3
    kt = 2 + 0.284 * x - 0.600 * x**2 + 1.32 * x**3
    assert kt == pytest.approx(2.3138, abs=1e-4)
    assert net.demand.m_as("MPa") == pytest.approx(kt * 100 / (20 * 8), rel=1e-6)
    assert net.capacity.m_as("MPa") == pytest.approx(13.0)
    assert any("Z" in n for n in net.notes)
    assert rs.get("eye", "lug_tension").warnings  # BTH-1 is steel-based


def test_pin_force_defaults_to_resultant_with_end_reaction(tmp_path):
    """Pinned link with N = 3000 N and a centre load F = 800 N: each pin carries sqrt(3000^2 + 400^2) N."""
    rs = design(tmp_path, EYE.format(material="steel", extra="") + 'transverse_load = "800 N"\n').verify()
    assert rs.get("eye", "pin_shear").inputs["F"].m_as("N") == pytest.approx(math.hypot(3000, 400))


def test_link_without_hole_has_no_eye_checks(tmp_path):
    rs = design(tmp_path, BAR.format(extra="", loads='axial_force = "100 N"')).verify()
    assert {r.check for r in rs} == {"member_body_strength", "member_buckling"}


# ------------------------------------------------------------------------------------ plot data
@pytest.mark.parametrize("case, coefficient, load_kind", [
    ("simply_supported_center_load", 1 / 48, "force"), ("simply_supported_uniform", 5 / 384, "line"),
    ("cantilever_end_load", 1 / 3, "force"), ("cantilever_uniform", 1 / 8, "line"),
    ("fixed_pinned_center_load", 1 / (48 * math.sqrt(5)), "force"), ("fixed_pinned_uniform", 1 / 185, "line"),
    ("fixed_fixed_center_load", 1 / 192, "force"), ("fixed_fixed_uniform", 1 / 384, "line"),
])
def test_plotted_deflection_curve_reaches_table_a9_maximum(case, coefficient, load_kind):
    """The report's curve (E I y'' = M integrated) peaks at Shigley Table A-9's y_max (w l^4/(185 E I) is the
    table's rounded coefficient for case 13) and vanishes at the supports."""
    x, y = beam_deflection_curve(case, 1.0, 1.0, 1.0, n=4001)
    assert abs(y).max() == pytest.approx(coefficient, rel=2e-3)
    assert y[0] == pytest.approx(0, abs=1e-12)
    if not case.startswith("cantilever"):
        assert y[-1] == pytest.approx(0, abs=1e-6)


# ---------------------------------------------------------------------------------------------- plates
PLATE = """
[materials.alu]
base = "Aluminium 6061-T6"
E = "70 GPa"
nu = 0.3
[components.p]
type = "plate"
{geometry}
thickness = "4 mm"
material = "alu"
{extra}
[load_cases.load.p]
{loads}
"""


def test_rectangular_plate_matches_roark_table_11_4_case_1a(tmp_path):
    """Roark 8th ed. Table 11.4 case 1a, a/b = 1.6 (tabulated): beta = 0.5172, alpha = 0.0906.
    a = 320, b = 200, t = 4 mm, q = 10 kPa: sigma = beta q b^2/t^2 = 0.5172 * 1e4 * 0.04/16e-6 = 12.93 MPa,
    y = alpha q b^4/(E t^3) = 0.0906 * 1e4 * 0.0016/(70e9 * 64e-9) = 0.3236 mm."""
    rs = design(tmp_path, PLATE.format(geometry='width = "320 mm"\nheight = "200 mm"', extra="",
                                       loads='pressure = "10 kPa"'), materials="").verify()
    s = rs.get("p", "plate_stress_roark")
    assert s.demand.m_as("MPa") == pytest.approx(0.5172 * 1e4 * 0.04 / 16e-6 / 1e6, rel=1e-6)
    assert s.capacity.m_as("MPa") == pytest.approx(276)
    assert any("FEA plate model" in n for n in s.notes)
    y = rs.get("p", "plate_deflection_roark")
    assert y.demand.m_as("mm") == pytest.approx(0.0906 * 1e4 * 0.2**4 / (70e9 * 0.004**3) * 1e3, rel=1e-6)
    assert y.capacity.m_as("mm") == pytest.approx(0.002 * 200)  # requirements default of the shorter side


def test_clamped_rectangle_and_self_weight_roark_case_8a(tmp_path):
    """Case 8a (clamped), a/b = 1.6: sigma_edge = beta_1 q b^2/t^2 with beta_1 = 0.4680, alpha = 0.0251;
    self-weight adds rho g t = 2700 * 9.80665 * 0.004 = 105.9 Pa to q."""
    rs = design(tmp_path, PLATE.format(geometry='width = "320 mm"\nheight = "200 mm"', extra='edges = "clamped"',
                                       loads='pressure = "10 kPa"\nself_weight = true'), materials="").verify()
    q = 1e4 + 2700 * 9.80665 * 0.004
    assert rs.get("p", "plate_stress_roark").demand.m_as("Pa") == pytest.approx(0.4680 * q * 0.04 / 16e-6, rel=1e-6)
    assert rs.get("p", "plate_deflection_roark").demand.m_as("m") == pytest.approx(0.0251 * q * 0.2**4 / (70e9 * 64e-9),
                                                                              rel=1e-6)


def test_circular_plate_matches_roark_table_11_2(tmp_path):
    """Table 11.2 case 10a (simply supported, uniform q): sigma_c = 3 (3 + nu) q a^2/(8 t^2),
    y = q a^4 (5 + nu)/(64 D (1 + nu)), D = E t^3/(12 (1 - nu^2)); a = 100 mm, t = 4 mm, q = 10 kPa, nu = 0.3:
    sigma = 3 * 3.3 * 1e4 * 0.01/(8 * 16e-6) = 7.734 MPa. Case 16 (central W, point: r0' = 1.6 t... for
    r0 = 0: r0' = sqrt(t^2) - 0.675 t = 0.325 t): sigma = 3W/(2 pi t^2) [(1 + nu) ln(a/r0') + 1]."""
    geo = 'shape = "circle"\ndiameter = "200 mm"'
    rs = design(tmp_path, PLATE.format(geometry=geo, extra="", loads='pressure = "10 kPa"'), materials="").verify()
    D = 70e9 * 0.004**3 / (12 * (1 - 0.09))
    assert rs.get("p", "plate_stress_roark").demand.m_as("MPa") == pytest.approx(3 * 3.3 * 1e4 * 0.01 / (8 * 16e-6) / 1e6)
    assert rs.get("p", "plate_deflection_roark").demand.m_as("m") == pytest.approx(1e4 * 0.1**4 * 5.3 / (64 * D * 1.3))
    rs = design(tmp_path, PLATE.format(geometry=geo, extra="", loads='central_force = "200 N"'), materials="").verify()
    r0e = 0.325 * 0.004
    sigma = 3 * 200 / (2 * math.pi * 0.004**2) * (1.3 * math.log(0.1 / r0e) + 1)
    assert rs.get("p", "plate_stress_roark").demand.m_as("Pa") == pytest.approx(sigma, rel=1e-6)


# ---------------------------------------------------------------------------------------------- errors
def errors_of(tmp_path, body, materials=MATERIALS):
    with pytest.raises(DesignFileError) as exc:
        design(tmp_path, body, materials)
    return str(exc.value)


def test_unknown_section_kind_suggests(tmp_path):
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('"rectangle"', '"tubee"'))
    assert 'components.bar.section: expected one of' in msg and "did you mean 'tube'?" in msg


def test_section_dimension_errors(tmp_path):
    msg = errors_of(tmp_path, BAR.format(extra='diameter = "5 mm"', loads='axial_force = "1 N"'))
    assert "components.bar.diameter: not a dimension of a rectangle section" in msg
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('height = "20 mm"', ""))
    assert "components.bar.height: missing; a rectangle section needs width, height" in msg
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('"20 mm"', '"20 N"'))
    assert 'components.bar.height: expected a length, got "20 N"' in msg


def test_hole_larger_than_the_lug(tmp_path):
    msg = errors_of(tmp_path, EYE.format(material="steel", extra="").replace('"10 mm"', '"35 mm"'))
    assert "components.eye.hole_diameter: hole diameter 35 mm must be smaller than the lug width 30 mm" in msg
    msg = errors_of(tmp_path, EYE.format(material="steel", extra='pin_diameter = "12 mm"'))
    assert "components.eye.pin_diameter:" in msg and "exceeds the hole" in msg
    msg = errors_of(tmp_path, BAR.format(extra='pin_material = "steel"', loads='axial_force = "1 N"'))
    assert "components.bar.pin_material: a pin eye needs hole_diameter" in msg
    tube_with_hole = STRUT.format(length="500 mm", end="pinned-pinned").replace('end = "pinned-pinned"',
                                                                                'hole_diameter = "8 mm"')
    msg = errors_of(tmp_path, tube_with_hole)
    assert "components.strut.lug_width: missing" in msg


def test_bad_deflection_limit_and_plate_geometry(tmp_path):
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('"L/250"', '"2 N"'))
    assert "components.bar.deflection_limit: expected a length" in msg
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('"L/250"', '"L/0"'))
    assert "components.bar.deflection_limit: expected a length" in msg and "got 'L/0'" in msg
    msg = errors_of(tmp_path, BAR.format(extra="", loads='axial_force = "1 N"').replace('"400 mm"', '"-4 mm"'))
    assert "components.bar.length: must be positive, got -4 mm" in msg
    msg = errors_of(tmp_path, PLATE.format(geometry='shape = "circle"\nwidth = "20 mm"\ndiameter = "20 mm"',
                                           extra="", loads='pressure = "1 kPa"'), materials="")
    assert "components.p.width: not a dimension of a circle plate" in msg
    msg = errors_of(tmp_path, PLATE.format(geometry='width = "20 mm"', extra="", loads='pressure = "1 kPa"'),
                    materials="")
    assert "components.p.height: missing; a rectangle plate needs width and height" in msg
    msg = errors_of(tmp_path, PLATE.format(geometry='shape = "circle"\ndiameter = "20 mm"', extra="",
                                           loads='pressure = "1 kPa"').replace('"alu"', '"PLA (FDM, XY flat)"'),
                    materials="")
    assert "components.p.material: 'PLA (FDM, XY flat)' has no Poisson's ratio" in msg


def test_check_needing_a_missing_load_names_the_key_path(tmp_path):
    body = PLATE.format(geometry='width = "320 mm"\nheight = "200 mm"', extra="", loads="self_weight = true")
    msg = errors_of(tmp_path, body, materials="")
    assert "components.p.checks.plate_stress_roark: needs pressure or central_force" in msg


# ---------------------------------------------------------------------------------------------- report
def test_report_typesets_formulas_and_draws_figures(tmp_path):
    body = (EYE.format(material="steel", extra="") + 'transverse_load = "200 N"\n'
            + STRUT.format(length="1000 mm", end="pinned-pinned")
            + PLATE.format(geometry='width = "320 mm"\nheight = "200 mm"', extra="", loads='pressure = "10 kPa"'))
    d = design(tmp_path, body)
    rs = d.verify()
    html = render_html([(d, rs)], date="2025-01-01")
    assert 'class="latex"' not in html
    assert html.count("data:image/svg+xml") >= 4  # utilisation chart, 2 beam diagrams, column curve
