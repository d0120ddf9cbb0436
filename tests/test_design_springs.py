"""Design files with compression, extension and torsion springs: numbers against hand calculations from
Shigley's Mechanical Engineering Design, 10th ed. (Budynas & Nisbett, 2015), Ch. 10, errors with key
paths, and the report of a spring design (typeset formulas, figures)."""

import math
import textwrap

import pytest

from mechverify.design import DesignFileError, load
from mechverify.reports import render_html

# Shigley Ex. 10-4: music wire d = 0.092 in, OD = 9/16 in, L0 = 4 3/8 in, Na = 21, squared and ground,
# unpeened, cycling between 5 and 35 lbf; G = 11.75 Mpsi, E = 28.5 Mpsi (Table 10-5);
# Sut = 201/0.092^0.145 = 284.1 kpsi (Table 10-4).
EX10_4 = """
[design]
name = "Shigley Ex. 10-4 spring"

[components.s]
type = "compression_spring"
wire_diameter = "0.092 in"
outside_diameter = "0.5625 in"
free_length = "4.375 in"
active_coils = 21
ends = "squared-ground"
shear_modulus = "11.75 Mpsi"
elastic_modulus = "28.5 Mpsi"
tensile_strength = "284.1 ksi"
{extra}

[components.s.checks]
fatigue = true

[load_cases.run.s]
force = "35 lbf"
force_min = "5 lbf"
{loads}
"""


def write(tmp_path, text):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(text))
    return p


def ex10_4(tmp_path, extra="", loads=""):
    return load(write(tmp_path, EX10_4.format(extra=extra, loads=loads)))


# Hand calculation (Shigley Ex. 10-4): D = OD - d, C = D/d, K_B = (4C + 2)/(4C - 3) (Eq. 10-6).
D, d = 0.5625 - 0.092, 0.092  # in
C = D / d  # 5.114
KB = (4 * C + 2) / (4 * C - 3)  # 1.2864


def tau(F_lbf):
    """Eq. (10-7): tau = K_B 8 F D / (pi d^3) [kpsi]."""
    return KB * 8 * F_lbf * D / (math.pi * d**3) / 1000


def test_static_stress_and_clash_match_shigley_ex10_4(tmp_path):
    """tau_max = tau(35 lbf) = 69.3 kpsi (tau_a + tau_m = 29.7 + 39.6 of Ex. 10-4) against S_sy = 0.45 S_ut =
    127.8 kpsi (Table 10-6); k = d^4 G/(8 D^3 Na) = 48.1 lbf/in (Ex. 10-4), Ls = d Nt = 0.092 * 23 in."""
    rs = ex10_4(tmp_path).verify()
    r = rs.get("s", "spring_static_stress")
    assert tau(35) == pytest.approx(29.7 + 39.6, rel=3e-3)  # the hand calculation reproduces the book
    assert r.demand.m_as("ksi") == pytest.approx(tau(35), rel=1e-4)
    assert r.capacity.m_as("ksi") == pytest.approx(0.45 * 284.1, rel=1e-4)
    assert r.required_sf == 1.2  # the design's "spring" class (Shigley 10th ed. Sec. 10-7: n_s >= 1.2)
    k = d**4 * 11.75e6 / (8 * D**3 * 21)
    assert k == pytest.approx(48.1, rel=2e-3)
    clash = rs.get("s", "spring_clash")
    assert clash.demand.m_as("in") == pytest.approx(1.15 * 35 / k, rel=1e-4)
    assert clash.capacity.m_as("in") == pytest.approx(4.375 - 0.092 * 23, rel=1e-6)


def test_fatigue_gerber_matches_shigley_ex10_4(tmp_path):
    """Ex. 10-4: tau_a = 29.7 kpsi, Gerber n_f = 1.21 (Zimmerli unpeened S_sa = 35, S_sm = 55 kpsi)."""
    r = ex10_4(tmp_path).verify().get("s", "spring_fatigue")
    assert r.demand.m_as("ksi") == pytest.approx(tau(15), rel=1e-4)
    assert r.demand.m_as("ksi") == pytest.approx(29.7, rel=3e-3)
    assert r.safety_factor == pytest.approx(1.21, abs=0.01)
    assert r.required_sf == 1.5 and r.load_case == "run"


def test_fatigue_goodman_matches_shigley_ex10_4(tmp_path):
    """Ex. 10-4 (Goodman): S_se = S_sa/(1 - S_sm/S_su) = 49.2 kpsi, n_f = 1.23."""
    r = ex10_4(tmp_path, extra='fatigue_criterion = "goodman"').verify().get("s", "spring_fatigue")
    assert r.details["Sse"].m_as("ksi") == pytest.approx(49.2, rel=3e-3)
    assert r.safety_factor == pytest.approx(1.23, abs=0.01)


def test_buckling_fixed_free_from_eq_10_10(tmp_path):
    """Eq. (10-10): y_cr = L0 C1'[1 - sqrt(1 - C2'/lambda^2)], lambda = alpha L0/D, alpha = 2 (fixed-free,
    Table 10-2), C1' = E/(2(E - G)), C2' = 2 pi^2 (E - G)/(2G + E); E = 28.5, G = 11.75 Mpsi."""
    E, G, L0 = 28.5, 11.75, 4.375
    lam = 2 * L0 / D
    y_cr = L0 * E / (2 * (E - G)) * (1 - math.sqrt(1 - 2 * math.pi**2 * (E - G) / (2 * G + E) / lam**2))
    assert y_cr == pytest.approx(0.0344, abs=2e-4)
    r = ex10_4(tmp_path, loads='end_condition = "fixed-free"').verify().get("s", "spring_buckling")
    assert r.capacity.m_as("in") == pytest.approx(y_cr, rel=1e-4)
    assert r.demand.m_as("in") == pytest.approx(35 / (d**4 * 11.75e6 / (8 * D**3 * 21)), rel=1e-4)
    assert r.verdict == "fail" and r.details["end_condition"] == "fixed-free"
    # the component's default, between flat parallel plates (alpha = 0.5)
    r = ex10_4(tmp_path).verify().get("s", "spring_buckling")
    lam = 0.5 * L0 / D
    y_cr = L0 * E / (2 * (E - G)) * (1 - math.sqrt(1 - 2 * math.pi**2 * (E - G) / (2 * G + E) / lam**2))
    assert r.capacity.m_as("in") == pytest.approx(y_cr, rel=1e-4)


def test_deflection_load_gives_force_k_y(tmp_path):
    """A load case may give the deflection instead of the force: F = k y (Eq. 10-9)."""
    text = EX10_4.format(extra="", loads="").replace('force = "35 lbf"\nforce_min = "5 lbf"', 'deflection = "0.5 in"')
    text = text.replace("fatigue = true", "fatigue = false")
    r = load(write(tmp_path, text)).verify().get("s", "spring_static_stress")
    k = d**4 * 11.75e6 / (8 * D**3 * 21)
    assert r.demand.m_as("ksi") == pytest.approx(tau(k * 0.5), rel=1e-4)


def test_total_coils_and_inside_diameter(tmp_path):
    """Shigley Ex. 10-1: d = 0.037 in, OD = 7/16 in, squared ends, Nt = 12.5 (Na = 10.5), G = 11.85 Mpsi:
    k = 4.12 lbf/in; solid length (Nt + 1) d = 0.4995 in; the same spring given by its ID."""
    for dia in ('outside_diameter = "0.4375 in"', 'inside_diameter = "0.3635 in"'):
        text = f"""
        [design]
        name = "ex 10-1"
        [components.s]
        type = "compression_spring"
        wire_diameter = "0.037 in"
        {dia}
        total_coils = 12.5
        ends = "squared"
        free_length = "2.06 in"
        shear_modulus = "11.85 Mpsi"
        tensile_strength = "324 ksi"
        [load_cases.a.s]
        force = "4 lbf"
        """
        rs = load(write(tmp_path, text)).verify()
        clash = rs.get("s", "spring_clash")
        assert clash.capacity.m_as("in") == pytest.approx(2.06 - 13.5 * 0.037, rel=1e-6)
        assert clash.demand.m_as("in") == pytest.approx(1.15 * 4 / 4.12, rel=3e-3)


def test_extension_spring_static_checks_shigley_sec_10_11(tmp_path):
    """d = 1 mm, OD = 8 mm (D = 7, C = 7), F = 20 N, Sut = 2000 MPa (music wire, Table 10-7: body 45 %,
    end torsion 40 %, end bending 75 %). K_B = (4C + 2)/(4C - 3) = 30/25; hook A with r1 = D/2: C1 = 7,
    (K)_A = (4C1^2 - C1 - 1)/(4C1(C1 - 1)); hook B with r2 = 2 mm: C2 = 4, (K)_B = (4C2 - 1)/(4C2 - 4)."""
    text = """
    [design]
    name = "ext"
    [components.e]
    type = "extension_spring"
    wire_diameter = "1 mm"
    outside_diameter = "8 mm"
    body_coils = 20
    initial_tension = "5 N"
    hook_side_radius = "2 mm"
    tensile_strength = "2000 MPa"
    [load_cases.pull.e]
    force = "20 N"
    """
    rs = load(write(tmp_path, text)).verify()
    F, Dm, dm = 20.0, 7.0, 1.0  # N, mm
    body = rs.get("e", "extension_body_stress")
    assert body.demand.m_as("MPa") == pytest.approx(30 / 25 * 8 * F * Dm / (math.pi * dm**3), rel=1e-6)
    assert body.capacity.m_as("MPa") == pytest.approx(900)
    KA = (4 * 49 - 7 - 1) / (4 * 7 * 6)
    hookA = rs.get("e", "extension_hook_bending")
    assert hookA.demand.m_as("MPa") == pytest.approx(F * (KA * 16 * Dm / math.pi + 4 / math.pi), rel=1e-6)
    assert hookA.capacity.m_as("MPa") == pytest.approx(1500)
    hookB = rs.get("e", "extension_hook_torsion")
    assert hookB.demand.m_as("MPa") == pytest.approx(15 / 12 * 8 * F * Dm / math.pi, rel=1e-6)
    assert hookB.capacity.m_as("MPa") == pytest.approx(800)
    # without r2 the hook torsion is not checked, and the hook-bending result says so
    rs = load(write(tmp_path, text.replace('hook_side_radius = "2 mm"', ""))).verify()
    assert not rs.where(check="extension_hook_torsion").results
    assert any("hook_side_radius" in n for n in rs.get("e", "extension_hook_bending").notes)


def test_torsion_spring_stress_and_angle_load_shigley_sec_10_12(tmp_path):
    """d = 1.5 mm, OD = 12 mm (D = 10.5, C = 7), Nb = 6, legs 20 mm, E = 200 GPa, Sut = 2000 MPa.
    K_i = (4C^2 - C - 1)/(4C(C - 1)) (Eq. 10-43); sigma = K_i 32 M/(pi d^3); S_y = 0.78 S_ut (Eq. 10-57).
    Na = Nb + (l1 + l2)/(3 pi D); k' = d^4 E/(10.8 D Na) per turn (Eq. 10-51); 60 deg -> M = k'/6."""
    text = """
    [design]
    name = "tor"
    [components.t]
    type = "torsion_spring"
    wire_diameter = "1.5 mm"
    outside_diameter = "12 mm"
    body_turns = 6
    leg1_length = "20 mm"
    leg2_length = "20 mm"
    elastic_modulus = "200 GPa"
    tensile_strength = "2000 MPa"
    [load_cases.wind.t]
    angle = "60 deg"
    [load_cases.hold.t]
    moment = "0.2 N*m"
    """
    rs = load(write(tmp_path, text)).verify()
    Ki = (4 * 49 - 7 - 1) / (4 * 7 * 6)
    Na = 6 + 40 / (3 * math.pi * 10.5)
    k_turn = 1.5e-3**4 * 200e9 / (10.8 * 10.5e-3 * Na)  # N*m per turn
    M = k_turn / 6
    r = rs.get("t", "torsion_spring_stress")
    assert r.load_case == "wind"  # the 60 deg case (M = 0.232 N*m) governs over 0.2 N*m
    assert r.demand.m_as("MPa") == pytest.approx(Ki * 32 * M / (math.pi * 1.5e-3**3) / 1e6, rel=1e-6)
    assert r.capacity.m_as("MPa") == pytest.approx(0.78 * 2000)


@pytest.mark.parametrize("body, path, words", [
    ('outside_diameter = "12 mm"\nactive_coils = 10\nfree_length = "50 mm"', "components.s.wire_diameter",
     "missing"),
    ('wire_diameter = "1 mm"\noutside_diameter = "12 mm"\nactive_coils = 10\ntotal_coils = 12\nfree_length = "50 mm"',
     "components.s", "exactly one of active_coils or total_coils"),
    ('wire_diameter = "1 mm"\nactive_coils = 10\nfree_length = "50 mm"', "components.s",
     "exactly one of mean_diameter, outside_diameter or inside_diameter"),
    ('wire_diameter = "1 mm"\noutside_diameter = "12 mm"\nactive_coils = 10\nfree_length = "50 mm"\n'
     'ends = "squared-and-ground"', "components.s.ends", "did you mean 'squared-ground'"),
    ('wire_diameter = "1 N"\noutside_diameter = "12 mm"\nactive_coils = 10\nfree_length = "50 mm"',
     "components.s.wire_diameter", "length"),
    ('wire_diameter = "1 mm"\noutside_diameter = "12 mm"\nactive_coils = 10\nfree_length = "5 mm"',
     "components.s", "solid length"),
])
def test_bad_spring_fields_name_their_key(tmp_path, body, path, words):
    text = '[design]\nname = "x"\n[components.s]\ntype = "compression_spring"\n' + body
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, text))
    assert any(p == path and words in m for p, m in exc.value.errors), exc.value.errors


def test_bad_loads_name_their_key(tmp_path):
    with pytest.raises(DesignFileError) as exc:
        ex10_4(tmp_path, loads='end_condition = "fixed-loose"').verify()
    assert any(p == "load_cases.run.s.end_condition" for p, _ in exc.value.errors)
    # a deflection beyond solid is reported at the check with its load case
    text = EX10_4.format(extra="", loads="").replace('force = "35 lbf"\nforce_min = "5 lbf"', 'deflection = "3 in"')
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, text.replace("fatigue = true", "fatigue = false"))).verify()
    assert any(p == "components.s.checks.spring_static_stress [run]" and "travel to solid" in m
               for p, m in exc.value.errors), exc.value.errors
    # fatigue enabled, and no load case gives the bottom of the cycle
    text = EX10_4.format(extra="", loads="").replace('force_min = "5 lbf"', "")
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, text))
    assert any(p == "components.s.checks.spring_fatigue" and "force_min or deflection_min" in m
               for p, m in exc.value.errors)


def test_report_of_spring_design_typesets_every_formula_and_draws_figures(tmp_path):
    """The HTML report of a spring design: no formula falls back to raw LaTeX; the force-deflection and
    Haigh diagrams are embedded."""
    design = ex10_4(tmp_path)
    rs = design.verify()
    html = render_html([(design, rs)], date="2025-01-01")
    assert 'class="latex"' not in html
    assert html.count('class="formula"') >= 5
    assert "Figure: Spring buckling (critical deflection)" in html
    assert "Figure: Spring fatigue (infinite life)" in html
    fd = rs.get("s", "spring_buckling").details
    assert list(fd["operating_cases"]) == ["run", "run (min)"]
    assert fd["operating_forces"].m_as("lbf").tolist() == pytest.approx([35, 5])
