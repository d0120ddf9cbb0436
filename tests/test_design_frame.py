"""Design-file type ``frame``: numbers against hand calculations from the published formulas, key-path errors,
the report figure."""

import math

import pytest

import mechverify.design as mvd
from mechverify.design.loader import DesignFileError

CANTILEVER = """
[design]
name = "bracket"

[components.arm]
type = "frame"
material = "Structural Steel"
section = "rectangle"
width = "10 mm"
height = "20 mm"
nodes = {{ A = ["0 mm", "0 mm", "0 mm"], B = ["400 mm", "0 mm", "0 mm"] }}
members = [ {{ name = "beam", start = "A", end = "B" }} ]
supports = [ {{ at = "A", type = "fixed" }} ]
deflection_limit_fraction = 0.01
fatigue_life = 1e6
fatigue_loading = "{loading}"
[components.arm.checks]
fatigue = true

[load_cases.tip.arm]
point_loads = [ {{ at = "B", force = ["0 N", "0 N", "-200 N"] }} ]
"""


def verify(tmp_path, text):
    p = tmp_path / "d.toml"
    p.write_text(text)
    return {r.check: r for r in mvd.load(p).verify()}


def test_cantilever_checks_against_hand_calculation(tmp_path):
    """P = 200 N at L = 400 mm on a 10 x 20 mm steel bar (E = 200 GPa, nu = 0.3, Sy = 250 MPa):
    sigma = P L / (b h^2 / 6) = 200 * 0.4 / (0.01 * 0.02^2 / 6) = 120 MPa; tau = V / A_s = 200 / (5/6 * 200 mm^2)
    = 1.2 MPa at the root (Shigley 10th ed. Eq. 5-15: vM = sqrt(sigma^2 + 3 tau^2));
    delta = P L^3 / (3 E I) + 1.2 P L / (G A) (Roark 8th ed. Table 8.1 case 1a, Sec. 8.10), limit 1 % of 400 mm."""
    r = verify(tmp_path, CANTILEVER.format(loading="fully_reversed"))
    sigma, tau = 200 * 0.4 / (0.01 * 0.02**2 / 6), 200 / (5 / 6 * 200e-6)
    vm = math.sqrt(sigma**2 + 3 * tau**2)
    assert r["frame_stress"].demand.m_as("Pa") == pytest.approx(vm, rel=1e-9)
    assert r["frame_stress"].safety_factor == pytest.approx(250e6 / vm, rel=1e-9)
    E, G, I = 200e9, 200e9 / 2.6, 0.01 * 0.02**3 / 12
    delta = 200 * 0.4**3 / (3 * E * I) + 1.2 * 200 * 0.4 / (G * 200e-6)
    assert r["frame_deflection"].demand.m_as("m") == pytest.approx(delta, rel=1e-9)
    assert r["frame_deflection"].capacity.m_as("mm") == pytest.approx(4.0)
    # fully reversed, no mean stress: S-N value at 1e6 cycles of the ANSYS table, 86.2 MPa (ANSYS Engineering Data)
    assert r["frame_fatigue"].safety_factor == pytest.approx(86.2e6 / vm, rel=1e-6)


def test_zero_to_max_goodman(tmp_path):
    """Zero-to-max: sigma_a = sigma_m = vM / 2; Goodman 1/n = sigma_a / S_e + sigma_m / S_ut (Shigley 10th ed.
    Eq. 6-41) with S_e = 86.2 MPa (S-N at 1e6) and S_ut = 460 MPa."""
    r = verify(tmp_path, CANTILEVER.format(loading="zero_to_max"))
    sigma, tau = 120e6, 200 / (5 / 6 * 200e-6)
    half = math.sqrt(sigma**2 + 3 * tau**2) / 2
    n = 1 / (half / 86.2e6 + half / 460e6)
    assert r["frame_fatigue"].safety_factor == pytest.approx(n, rel=1e-6)


def test_errors_have_key_paths(tmp_path):
    bad = CANTILEVER.format(loading="zero_to_max").replace('start = "A"', 'start = "Q"')
    with pytest.raises(DesignFileError, match=r"components.arm.*unknown node 'Q'"):
        verify(tmp_path, bad)
    bad = CANTILEVER.format(loading="zero_to_max").replace('{ at = "A", type = "fixed" }', '{ at = "A", typ = "fixed" }')
    with pytest.raises(DesignFileError, match=r"supports\[0\].typ: unknown key; did you mean 'type'"):
        verify(tmp_path, bad)
    bad = CANTILEVER.format(loading="zero_to_max").replace('"-200 N"]', '"-200 mm"]')
    with pytest.raises(DesignFileError, match=r"load_cases.tip.arm.point_loads\[0\].force\[2\]: expected a force"):
        verify(tmp_path, bad)
    bad = CANTILEVER.format(loading="zero_to_max").replace('{ at = "A", type = "fixed" }', '{ at = "A", type = "pinned" }')
    with pytest.raises(DesignFileError, match=r"not fully supported.*rotation"):
        verify(tmp_path, bad)


def test_report_has_the_frame_figure(tmp_path):
    from mechverify.reports.render import render_html

    p = tmp_path / "d.toml"
    p.write_text(CANTILEVER.format(loading="zero_to_max"))
    d = mvd.load(p)
    html = render_html([(d, d.verify())])
    assert "deformed shape" in html and "data:image/svg+xml" in html


RELEASED = """
[design]
name = "floor beam"

[components.beam]
type = "frame"
material = "Structural Steel"
section = "rectangle"
width = "10 mm"
height = "20 mm"
theory = "euler"
nodes = { A = ["0 mm", "0 mm", "0 mm"], B = ["400 mm", "0 mm", "0 mm"] }
members = [ { name = "b", start = "A", end = "B", releases_start = "My", releases_end = "My" } ]
supports = [ { at = "A", type = "fixed" }, { at = "B", type = "fixed" } ]
deflection_limit = "L/100"

[load_cases.dead.beam]
distributed_loads = [ { member = "b", load = ["0 N/m", "0 N/m", "-1000 N/m"] } ]

[load_cases.live.beam]
distributed_loads = [ { member = "b", load = ["0 N/m", "0 N/m", "-2000 N/m"], start = "0 mm", end = "400 mm" } ]

[load_cases.ULS.beam]
combination = { dead = 1.35, live = 1.5 }
"""


def test_releases_and_a_combination_case(tmp_path):
    """Pinned-ended beam between fixed supports (releases): a simple beam, M = w l² / 8 (AISC Table 3-23 case 1);
    ULS = 1.35 dead + 1.5 live governs: w = 4350 N/m, M = 87 N·m, sigma = M / (b h²/6) = 130.5 MPa at mid-span
    (V = 0 there: von Mises = sigma); deflection 5 w l⁴ / (384 E I) (Euler)."""
    r = verify(tmp_path, RELEASED)
    w = 1.35 * 1000 + 1.5 * 2000
    M = w * 0.4**2 / 8
    assert r["frame_stress"].load_case == "ULS"
    assert r["frame_stress"].demand.m_as("Pa") == pytest.approx(M / (0.01 * 0.02**2 / 6), rel=1e-9)
    E, I = 200e9, 0.01 * 0.02**3 / 12
    assert r["frame_deflection"].demand.m_as("m") == pytest.approx(5 * w * 0.4**4 / (384 * E * I), rel=1e-9)
    bad = RELEASED.replace("dead = 1.35", "deadd = 1.35")
    with pytest.raises(DesignFileError, match=r"load_cases.ULS.beam.combination.deadd: not a load case of beam"):
        verify(tmp_path, bad)
    bad = RELEASED.replace('releases_end = "My"', 'releases_end = "Mq"')
    with pytest.raises(DesignFileError, match=r"members\[0\].*releases_end.*'Mq'"):
        verify(tmp_path, bad)


def test_settlement_spring_and_tabulated_section_keys(tmp_path):
    """A fixed-fixed member (tabulated section, Iy = b h³/12 of the 10 x 20 bar) whose end B settles 1 mm:
    M = 6 E I Δ / l² at the ends (slope-deflection, hand calculation); sigma = M c / I."""
    text = RELEASED.replace('members = [ { name = "b", start = "A", end = "B", releases_start = "My", '
                            'releases_end = "My" } ]',
                            'members = [ { name = "b", start = "A", end = "B", section = { kind = "properties", '
                            'area = "200 mm**2", Iy = "6666.666666666667 mm**4", Iz = "1666.6666666666667 mm**4", '
                            'J = "4577 mm**4", c_y = "5 mm", c_z = "10 mm" } } ]')
    text = text.split("[load_cases.dead.beam]")[0] + """
[load_cases.settle.beam]
settlements = [ { at = "B", values = { z = "-1 mm" } } ]
"""
    r = verify(tmp_path, text)
    E, I, L = 200e9, 0.01 * 0.02**3 / 12, 0.4
    M = 6 * E * I * 1e-3 / L**2
    sigma = M * 0.010 / I
    tau = 12 * E * I * 1e-3 / L**3 / 200e-6  # V / A (no shear areas given)
    assert r["frame_stress"].demand.m_as("Pa") == pytest.approx((sigma**2 + 3 * tau**2) ** 0.5, rel=1e-9)


def test_the_documented_example_verifies(tmp_path):
    """docs/design-files.md, 'Component type frame': the TOML example loads and verifies (ULS governs)."""
    from pathlib import Path

    doc = (Path(__file__).resolve().parents[1] / "docs" / "design-files.md").read_text(encoding="utf-8")
    block = doc[doc.index("## Component type `frame`"):].split("```toml\n", 1)[1].split("```", 1)[0]
    r = verify(tmp_path, '[design]\nname = "doc"\n\n' + block)
    assert r["frame_stress"].load_case == "ULS" and r["frame_stress"].passed
