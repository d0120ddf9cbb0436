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
