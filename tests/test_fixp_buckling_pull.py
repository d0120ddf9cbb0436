"""Review finding 8 (frame and plate_fea parts): a load case without compression cannot buckle; it passes with a note
and an infinite capacity, the compressive case governs the envelope, and the design is no longer refused (frame: the
pull case was dropped without a word; plate_fea: a pull in_plane case made the whole design an error).

Hand values: the fixed-free steel column 10 x 10 mm, L = 300 mm: P_cr = π² E I / (4 L²) (Timoshenko & Gere, Theory
of Elastic Stability, Sec. 2.1) = π² 200 GPa 833.3 mm⁴ / (4 (300 mm)²) = 4569 N, so 1000 N gives 4.569 (hand
calculation; the reviewer's number, review finding 24). The panel: simply supported 400 x 200 x 2 mm steel,
nx = -50 N/mm, N_cr = 4 π² D / b² (Timoshenko & Gere eq. 9-9, k = 4 at a/b = 2) = 144.6 N/mm: factor 2.892 (hand).
"""

from __future__ import annotations

import math

import pytest

import mechverify

FRAME = """
[design]
name = "column"
[requirements.safety_factors]
buckling = 2.0
[components.col]
type = "frame"
material = "Structural Steel"
section = "rectangle"
width = "10 mm"
height = "10 mm"
theory = "euler"
nodes = { A = ["0 mm", "0 mm", "0 mm"], B = ["0 mm", "0 mm", "300 mm"] }
members = [{ name = "m", start = "A", end = "B" }]
supports = [{ at = "A", type = "fixed" }]
[components.col.checks]
buckling_load_factor = true
frame_stress = false
frame_deflection = false
CASES
"""
PUSH = '[load_cases.push.col]\npoint_loads = [{ at = "B", force = ["0 N", "0 N", "-1000 N"] }]\n'
PULL = '[load_cases.pull.col]\npoint_loads = [{ at = "B", force = ["0 N", "0 N", "1000 N"] }]\n'

PANEL = """
[design]
name = "panel"
[components.pl]
type = "plate_fea"
width = "400 mm"
height = "200 mm"
thickness = "2 mm"
material = "Structural Steel"
supports = [ { edges = "all", type = "pinned" } ]
mesh_size = "20 mm"
[load_cases.p.pl]
pressure = "1 kPa"
[load_cases.squeeze.pl]
in_plane = { nx = "-50 N/mm" }
[load_cases.stretch.pl]
in_plane = { nx = "50 N/mm" }
"""


def _buckling(tmp_path, text):
    f = tmp_path / "d.toml"
    f.write_text(text)
    return [r for r in mechverify.load(f).verify() if r.check == "buckling_load_factor"]


def test_frame_push_and_pull(tmp_path):
    p_cr = math.pi**2 * 200e9 * (0.01**4 / 12) / (4 * 0.3**2)
    assert p_cr == pytest.approx(4569, abs=1)
    (r,) = _buckling(tmp_path, FRAME.replace("CASES", PUSH + PULL))
    assert r.load_case == "push" and r.capacity.m == pytest.approx(p_cr / 1000, rel=1e-3)
    assert any("pull: u=0" in n for n in r.notes)  # the pull case was analysed, not dropped


def test_frame_pull_only_passes_with_a_note(tmp_path):
    (r,) = _buckling(tmp_path, FRAME.replace("CASES", PULL))  # before: no result at all
    assert r.passed and math.isinf(r.capacity.m)
    assert any("no compression" in n and "no member" in n for n in r.notes)


def test_plate_push_and_pull(tmp_path):
    D = 200e9 * 0.002**3 / (12 * (1 - 0.3**2))
    hand = 4 * math.pi**2 * D / 0.2**2 / 50e3
    assert hand == pytest.approx(2.892, abs=1e-3)
    (r,) = _buckling(tmp_path, PANEL)  # before: an error at load_cases.stretch.pl.in_plane
    assert r.load_case == "squeeze" and r.capacity.m == pytest.approx(hand, rel=0.03)
    assert any("stretch: u=0" in n for n in r.notes)


def test_frame_uls_combination_review_24(tmp_path):
    """Review finding 24's case: dead = live = 1000 N on the column, ULS = 1.35 dead + 1.5 live = 2850 N:
    factor 4569 / 2850 = 1.603 < 2 (buckling SF) -> FAIL, u·SF 1.25 (the reviewer's hand calculation); it was a
    PASS of 4.569 with the combination skipped."""
    cases = ('[load_cases.dead.col]\npoint_loads = [{ at = "B", force = ["0 N", "0 N", "-1000 N"] }]\n'
             '[load_cases.live.col]\npoint_loads = [{ at = "B", force = ["0 N", "0 N", "-1000 N"] }]\n'
             '[load_cases.ULS.col]\ncombination = { dead = 1.35, live = 1.5 }\n')
    (r,) = _buckling(tmp_path, FRAME.replace("CASES", cases))
    p_cr = math.pi**2 * 200e9 * (0.01**4 / 12) / (4 * 0.3**2)
    assert r.load_case == "ULS" and r.capacity.m == pytest.approx(p_cr / 2850, rel=1e-3)
    assert r.capacity.m == pytest.approx(1.603, abs=1e-3) and not r.passed
