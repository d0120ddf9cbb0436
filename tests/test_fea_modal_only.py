"""A modal-only FEA design file (issue 23, known leftover of task fixsolid): a solid, frame or plate that no load case
loads is checked for its natural frequencies only. The checks that need loads (stress, deflection, ...), enabled by
default, are left out with a note on the component's results, not refused with one error each; a check the file
turns on explicitly (``checks.solid_stress = true``) without loads stays a named error.

Frequencies: Euler-Bernoulli beam, Blevins, *Formulas for Natural Frequency and Mode Shape* (1979), Table 8-1:
lambda_1 = 4.73004 (free-free), 1.87510 (clamped-free), f = lambda^2 / (2 pi L^2) sqrt(E I / (rho A)); the numbers
compared below are hand calculations from that formula, not printed frequencies.
"""

from __future__ import annotations

import math
import textwrap

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

pytest.importorskip("gmsh")

E, RHO = 200e9, 7850.0  # Structural Steel of the database (checked below through the result's inputs)
L, B = 0.3, 0.01


def _eb(lam: float) -> float:
    """Hand calculation of Blevins Table 8-1's formula for the 300 x 10 x 10 mm steel bar [Hz]."""
    return lam**2 / (2 * math.pi * L**2) * math.sqrt(E * B**4 / 12 / (RHO * B * B))


def _write(tmp_path, body: str):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(body))
    return p


SOLID = """
    [design]
    name = "modal only"

    [components.bar]
    type = "solid_fea"
    box = "300, 10, 10"
    mesh_size = "5 mm"
    material = "Structural Steel"
    supports = {supports}
    min_frequency = "20 Hz"
    """


def test_free_free_solid_without_checks_table_gives_frequency_and_a_note(tmp_path):
    """supports = [] and no load case: natural_frequency only (574 Hz against the hand EB 576.5 Hz, Blevins Table 8-1
    free-free lambda 4.73004), and the note names the two checks left out. Before: two errors asking to write
    checks.solid_stress = false and checks.solid_deflection = false."""
    rs = load(_write(tmp_path, SOLID.format(supports="[]"))).verify()
    assert [r.check for r in rs] == ["natural_frequency"]
    r = rs.get("bar", "natural_frequency")
    assert r.capacity.m_as("Hz") == pytest.approx(_eb(4.73004), rel=0.03)
    note = next(n for n in r.notes if "left out" in n)
    assert "solid_stress" in note and "solid_deflection" in note and "no load case loads bar" in note


def test_supported_solid_without_loads_gives_frequency_and_a_note(tmp_path):
    """A cantilever (xmin held) no load case loads: first frequency within 4 % of the hand EB 91.0 Hz (Blevins Table
    8-1, clamped-free lambda 1.87510; the solid's shear and root flexibility make it a little lower)."""
    rs = load(_write(tmp_path, SOLID.format(supports='[{ named = "xmin" }]'))).verify()
    assert [r.check for r in rs] == ["natural_frequency"]
    r = rs.get("bar", "natural_frequency")
    assert r.capacity.m_as("Hz") == pytest.approx(_eb(1.87510), rel=0.04)
    assert any("solid_stress" in n and "left out" in n for n in r.notes)


def test_a_check_turned_on_explicitly_without_loads_stays_an_error(tmp_path):
    text = SOLID.format(supports='[{ named = "xmin" }]') + "\n    [components.bar.checks]\n    solid_stress = true\n"
    with pytest.raises(DesignFileError, match=r"components.bar.checks.solid_stress: needs forces") as exc:
        load(_write(tmp_path, text))
    assert "solid_deflection" not in str(exc.value)  # the default-enabled one is still left out


def test_no_load_free_result_keeps_the_error(tmp_path):
    """Without min_frequency the solid would give no result at all: leaving the loaded checks out would print an empty
    report, so the named error stays (at verify, where it is known that no check gave a result)."""
    text = SOLID.format(supports='[{ named = "xmin" }]').replace('min_frequency = "20 Hz"', "")
    with pytest.raises(DesignFileError, match=r"components.bar.checks.solid_stress: needs forces"):
        load(_write(tmp_path, text)).verify()


def test_a_component_in_a_load_case_without_the_needed_loads_stays_an_error(tmp_path):
    """A load case that names the solid (an empty table) but gives none of the loads the stress check needs is a
    mistake, not a modal-only study: still the named error."""
    text = SOLID.format(supports='[{ named = "xmin" }]') + "\n    [load_cases.tip.bar]\n"
    with pytest.raises(DesignFileError, match=r"components.bar.checks.solid_stress: needs"):
        load(_write(tmp_path, text))


def test_modal_only_frame(tmp_path):
    """The same rule for a frame: a steel cantilever frame member no load case loads gives its natural frequency
    (hand EB, Blevins Table 8-1 clamped-free, within 2 %) and the note for frame_stress and frame_deflection."""
    text = """
    [design]
    name = "modal frame"

    [components.f]
    type = "frame"
    material = "Structural Steel"
    section = "rectangle"
    width = "10 mm"
    height = "10 mm"
    theory = "euler"
    nodes = { A = ["0 mm", "0 mm", "0 mm"], B = ["300 mm", "0 mm", "0 mm"] }
    members = [ { name = "m", start = "A", end = "B" } ]
    supports = [ { at = "A", type = "fixed" } ]
    min_frequency = "20 Hz"
    """
    try:
        d = load(_write(tmp_path, text))
    except DesignFileError as exc:  # the frame's own keys: shown if this sketch of a frame file is wrong
        raise AssertionError(str(exc)) from None
    rs = d.verify()
    assert [r.check for r in rs] == ["natural_frequency"]
    r = rs.get("f", "natural_frequency")
    assert r.capacity.m_as("Hz") == pytest.approx(_eb(1.87510), rel=0.02)
    note = next(n for n in r.notes if "left out" in n)
    assert "frame_stress" in note and "frame_deflection" in note


def test_a_load_case_with_no_load_solves_to_zero(tmp_path):
    """A load case whose only key is ``gravity = false`` gives the solid no load: zero stress, as a zero force does
    (it was an internal IndexError in fea.loads.held_load_names, which read the first load's vector)."""
    text = SOLID.format(supports='[{ named = "xmin" }]') + "\n    [load_cases.tip.bar]\n    gravity = false\n"
    rs = load(_write(tmp_path, text)).verify()
    assert rs.get("bar", "solid_stress").demand.m_as("MPa") == 0.0
