"""Inputs tables (issue 25): the formula's symbols with a description, derived inputs with the expression they
came from, and the design file's own units beside the report's (a user who writes ``lbf`` or ``kgf*cm`` sees
it). The design is ``mechverify init``'s starter with its payload as a parameter and the bearing load in lbf;
the numbers are unit conversions (1 lbf = 4.4482216 N, 1 kgf·cm = 0.0980665 N·m), not published values."""

from __future__ import annotations

import re
from importlib import resources

import pytest

from mechverify.design import load
from mechverify.reports.numbers import design_units, quantity, quantity_in
from mechverify.reports.render import render_html
from mechverify.reports.symbols import describe, symbol_html
from mechverify.units import Q

STARTER = resources.files("mechverify.design").joinpath("starter.toml").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    text = STARTER.replace("[components.lift_screw]", '[parameters]\npayload = "300 N"\n\n[components.lift_screw]', 1)
    text = text.replace('[load_cases.raise.lift_screw]\naxial_force = "300 N"',
                        '[load_cases.raise.lift_screw]\naxial_force = "payload"', 1)
    text = text.replace('[load_cases.raise.top_bearing]\naxial_force = "300 N"',
                        '[load_cases.raise.top_bearing]\naxial_force = "67.443 lbf"', 1)
    assert text.count("axial_force = \"payload\"") == 1 and "lbf" in text
    path = tmp_path_factory.mktemp("inputs") / "design.toml"
    path.write_text(text, encoding="utf-8")
    d = load(path)
    return render_html([(d, d.verify())], detail="all")


def _row(html: str, symbol: str) -> str:
    rows = re.findall(r"<tr><td>(.*?)</td><td class=\"value\">(.*?)</td><td>(.*?)</td></tr>", html)
    hit = [r for r in rows if r[0] == symbol]
    assert hit, symbol
    return " | ".join(hit[0])


def test_inputs_show_symbols_and_descriptions(html):
    row = _row(html, str(symbol_html("d_3")))
    assert "minor (root) diameter" in row and "mm" in row
    assert "<i>d</i><sub>3</sub>" in html and "<i>S</i><sub>y</sub>" in html
    assert "<th>Symbol</th>" in html and "<th>Description</th>" in html


def test_derived_input_names_its_expression(html):
    """The screw's axial force comes from the parameter ``payload``: its row says so."""
    assert "← payload" in html
    rows = [r for r in re.findall(r"<tr><td>(.*?)</td><td class=\"value\">(.*?)</td><td>(.*?)</td></tr>", html)
            if "← payload" in r[2]]
    assert rows and all("300 N" in r[1] for r in rows)


def test_design_file_units_are_carried(html):
    """The bearing's load was written in lbf: every force is also shown in lbf (300 N = 67.4 lbf)."""
    assert "300 N (67.4 lbf)" in html


def test_user_units_helpers():
    units = design_units({"a": {"t": "30 kgf*cm", "l": "450 mm", "f": "2 kN", "s": "fixed-pinned", "T": "20 degC"}})
    assert list(units.values()) == ["kgf*cm"]  # mm, kN: the report's own units (any SI prefix); degC: offset
    assert quantity_in(Q(30, "kgf*cm"), units) == "2.94 N·m (30.0 kgf·cm)"
    assert quantity_in(Q(1, "m"), units) == "1000 mm"
    assert describe("bearing_life", "C")[1] == "basic dynamic load rating"
    assert describe("spring_buckling", "C")[1] == "spring index D/d"
    assert describe("any", "unknown_key") == ("unknown_key", "")


def test_temperature_differences_in_kelvin():
    """A rise (pint's delta_degC/delta_degF) is shown in K, not converted as an absolute temperature (40 Δ°C used
    to print as -233 °C or fail); absolute temperatures stay in °C. 72 Δ°F = 40 K (5/9)."""
    from mechverify.checks.result import CheckResult
    from mechverify.reports.numbers import quantity

    assert quantity(Q(40, "delta_degC")) == "40.0 K"
    assert quantity(Q(72, "delta_degF")) == "40.0 K"
    assert quantity(Q(40, "degC")) == "40.0 °C" and quantity(Q(313.15, "K")) == "40.0 °C"
    r = CheckResult(check="rise", component="m", demand=Q(40, "delta_degC"), capacity=Q(50, "delta_degC"))
    assert r.utilisation == pytest.approx(0.8)


def test_angles_in_degrees():
    """An angle is shown in degrees (the self-locking lead angle 4.05° used to print as 0.0706, its radians)."""
    from mechverify.reports.numbers import quantity

    assert quantity(Q(4.046, "deg")) == "4.05°"
    assert quantity(Q(0.2618, "rad")) == "15.0°"
    assert quantity(Q(0.5, "")) == "0.500"


def test_traced_inputs_are_not_repeated_in_the_notes(html):
    """Per check: the derived-input note of a value its inputs table already traces ("← payload") is not repeated
    below it; a check without that input (the critical speed) keeps the note."""
    note = "derived input (raise): axial_force = 300 N ← payload"
    checks = html.split('<div class="check ')[1:]
    traced = [c for c in checks if "← payload (axial_force)" in c]
    assert len(traced) >= 3
    assert all(note not in c for c in traced)
    assert any(note in c for c in checks if c not in traced)


def test_console_table_carries_design_units(tmp_path, capsys, monkeypatch):
    """`mechverify check` prints forces of a design written in lbf in N and lbf (300 N = 67.4 lbf); a wide
    terminal, so that rich does not wrap the cell."""
    from mechverify.cli import main

    monkeypatch.setenv("COLUMNS", "200")
    text = STARTER.replace('[load_cases.raise.top_bearing]\naxial_force = "300 N"',
                           '[load_cases.raise.top_bearing]\naxial_force = "67.443 lbf"', 1)
    path = tmp_path / "design.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "300 N (67.4 lbf)" in out


# ------------------------------------------------ review (round 2 session 3) findings 13, 14: FEA results' units
def test_frequency_in_hz_speed_in_rpm():
    assert quantity(Q(50, "Hz")) == "50.0 Hz"  # was "477 rpm" (and "(50.0 Hz)" after it)
    assert quantity(Q(90.7, "Hz")) == "90.7 Hz"
    assert quantity(Q(2500, "Hz")) == "2.50 kHz"
    assert quantity(Q(1500, "rpm")) == "1500 rpm"
    assert quantity(Q(100, "rad/s")) == "955 rpm"  # 100 x 60 / 2π = 954.9
    assert quantity_in(Q(50, "Hz"), design_units({"f": "40 Hz"})) == "50.0 Hz"  # not "50.0 Hz (50.0 Hz)"


def test_micrometre_deflection():
    assert quantity(Q(0.00074, "mm")) == "0.740 µm"  # was "740×10⁻⁶ mm"
    assert quantity(Q(0.012, "mm")) == "0.0120 mm"
    assert quantity(Q(0.0, "mm")) == "0 mm"


def test_nanometres_and_kilopascals():
    """Review 4 #28: a stiff solid under a small load printed "0.00198 µm" and "55900 Pa" beside "250 MPa"."""
    assert quantity(Q(1.98e-9, "m")) == "1.98 nm"
    assert quantity(Q(0.0099, "mm")) == "9.90 µm"
    assert quantity(Q(55900, "Pa")) == "55.9 kPa"
    assert quantity(Q(105.9, "Pa")) == "106 Pa"
    assert quantity(Q(0.25, "MPa")) == "0.250 MPa"


def test_data_table_says_default_for_keys_the_file_does_not_write(tmp_path):
    """Review 2 finding 13: the report's Data table gave "design file" as the source of defaults the file never
    wrote (plate_fea's frequency_margin 0.15, modes 6, convergence_tolerance 0.05); they read "default" now, a key
    written in the file (or its template) still "design file"."""
    from mechverify.reports.render import _design_view
    from tests.builders import load as load_text

    text = ('[design]\nname = "l"\n[templates.bar]\nsection = "rectangle"\nwidth = "10 mm"\nheight = "10 mm"\n'
            '[components.link]\ntype = "link"\nextends = "bar"\nmaterial = "Structural Steel"\nlength = "100 mm"\n'
            'end = "pinned-pinned"\n[load_cases.a.link]\naxial_force = "100 N"\n')
    d = load_text(tmp_path, text)
    (comp,) = _design_view(d, d.verify(), "all")["components"]
    src = {p["name"]: p["source"] for p in comp["params"]}
    assert src["length"] == src["end"] == src["width"] == "design file"  # (width from the template)
    assert src["pin_shear_planes"] == src["strength_factor"] == "default"


def test_explore_names_the_figure_that_is_not_the_governing_checks(tmp_path):
    """Review 3 finding 23: explore's summary said 'Governing: l / Link body stress' and showed the buckling
    figure under 'Figure: l / Link buckling', read as the governing check's figure; a tension link's body stress
    governs (u·SF > 0) and draws no figure. The caption now says so."""
    pytest.importorskip("matplotlib")
    from mechverify.reports.explore import summary_html
    from tests.builders import load as load_text

    text = ('[design]\nname = "explore"\n[components.l]\ntype = "link"\nlength = "200 mm"\nsection = "circle"\n'
            'diameter = "10 mm"\nmaterial = "Structural Steel"\n[load_cases.a.l]\naxial_force = "200 N"\n')
    out = summary_html(load_text(tmp_path, text).verify())
    assert "<p>Governing: l / Link body stress" in out and "<img" in out
    assert ("<p class='small'>l / Link body stress (von Mises) draws no figure; the figure of the next check that "
            "has one: l / Link buckling</p>") in out
