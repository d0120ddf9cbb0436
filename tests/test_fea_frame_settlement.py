"""frame_deflection when supports move (review 4 finding 19): a 6 mm settlement at a support was reported as the beam's
deflection, 6.00 mm at the support itself, with nothing said. The check still compares the largest translation
(conservative), and now says that it is a support's motion: a WARN when the governing point is a moving support, and
the deflection relative to the line through the supports' translations.

Reference: simply supported beam under a uniform load, 5 w L^4 / (384 E I) (AISC Steel Construction Manual, Beam
Diagrams and Formulas, case 1; Shigley 10th ed. Table A-9 case 7): 1 m, 10 x 20 mm steel, 10 N/m -> 0.09766 mm (hand).
A settlement moves the beam rigidly (a statically determinate beam): the relative deflection is the same."""

from __future__ import annotations

import re
import textwrap

import pytest

from mechverify.design import load

BEAM = """
    [design]
    name = "settlement"
    [components.beam]
    type = "frame"
    material = "Structural Steel"
    section = "rectangle"
    width = "10 mm"
    height = "20 mm"
    theory = "euler"
    nodes = { A = ["0 mm", "0 mm", "0 mm"], B = ["1000 mm", "0 mm", "0 mm"] }
    members = [ { name = "m", start = "A", end = "B" } ]
    supports = [ { at = "A", type = "pinned" }, { at = "B", type = "custom", hold = ["y", "z", "rx"] } ]
    deflection_limit = "L/250"
    [load_cases.s.beam]
    distributed_loads = [ { member = "m", load = ["0 N/m", "0 N/m", "-10 N/m"], axes = "global" } ]
    """


def _deflection(tmp_path, settlement: str):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(BEAM) + settlement)
    return load(p).verify().get("beam", "frame_deflection")


def test_a_settled_support_is_named_with_the_relative_deflection(tmp_path):
    r = _deflection(tmp_path, 'settlements = [ { at = "B", values = { z = "-6 mm" } } ]\n')
    hand = 5 * 10 * 1.0**4 / (384 * 200e9 * 0.01 * 0.02**3 / 12) * 1e3  # mm
    assert r.demand.m_as("mm") == pytest.approx(6.0, rel=1e-6)  # the largest translation, as before (conservative)
    (w,) = [x for x in r.warnings if "supports[1] itself" in x]
    rel = float(re.search(r"largest deflection is ([\d.]+) mm", w).group(1))
    assert rel == pytest.approx(hand, rel=1e-3)
    assert any("supports move in this load case (supports[1] by 6 mm)" in n for n in r.notes)


def test_no_settlement_no_note(tmp_path):
    r = _deflection(tmp_path, "")
    assert r.demand.m_as("mm") == pytest.approx(0.09766, rel=1e-3)
    assert not [n for n in r.notes if "supports move" in n] and not r.warnings
