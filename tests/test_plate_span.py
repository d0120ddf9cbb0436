"""plate_fea's span from its supports (review 4 finding 30; mechverify.fea.plate_span): the "L" of a fractional
deflection limit ("L/250") and of the thin-plate test (span / thickness < 10) was the bounding box's shorter side
whatever the supports.

Hand values (no book needed: the spans are geometry, the deflection is the beam formula):
- a 400 x 40 x 5 mm steel strip (E 200 GPa) held on its two SHORT edges under 10 kPa is a simply supported beam:
  w = 10 kPa x 40 mm = 400 N/m, I = 40 x 5^3 / 12 = 416.7 mm^4, delta = 5 w L^4 / (384 E I) = 1.600 mm
  (Shigley 10th ed. Table A-9 case 7, the same formula); span 400 mm, limit L/250 = 1.600 mm, span/t = 80 (thin).
  Before: limit 0.16 mm (span 40 mm, u 10, FAIL) and a false THICK PLATE warning (span/t 8).
- a 400 x 400 plate pinned all round with a row of point supports at x = 200 mm (pitch 50 mm): the largest
  deflection is in one 200 x 400 half; span 200 mm, limit 0.8 mm (before 400 mm: 1.6 mm, utilisation halved).
- a cantilever strip clamped at x = 0: span = its length, 400 mm.
- four bolts at (15, 15) ... (285, 185) mm with 11 mm washers: 285 - 15 - 11 = 259 mm between washers; four corner
  posts of a 400 mm square: the side, 400 mm.
"""

from __future__ import annotations

import textwrap

import pytest

from mechverify.components import plates as P
from mechverify.design import load
from mechverify.fea.plate_span import plate_span

STRIP = """
[design]
name = "strip"
[components.p]
type = "plate_fea"
width = "400 mm"
height = "40 mm"
thickness = "5 mm"
material = "Structural Steel"
supports = [{{ edges = [{edges}], type = "{kind}" }}]
deflection_limit = "L/250"
{extra}
[load_cases.q.p]
pressure = "-10 kPa"
"""


def _check(tmp_path, edges='"left", "right"', kind="pinned", extra=""):
    f = tmp_path / "d.toml"
    f.write_text(textwrap.dedent(STRIP.format(edges=edges, kind=kind, extra=extra)))
    return load(f).verify().get("p", "plate_deflection_fea")


def test_strip_on_its_short_edges_spans_its_length(tmp_path):
    r = _check(tmp_path)
    hand = 5 * 400 * 0.4**4 / (384 * 200e9 * 40 * 5**3 / 12 * 1e-12) * 1e3  # 5wL^4/384EI [mm]
    assert hand == pytest.approx(1.600, abs=1e-9)
    assert r.demand.m_as("mm") == pytest.approx(hand, rel=0.01)  # the FEA: 1.602 mm
    assert r.capacity.m_as("mm") == pytest.approx(400 / 250)  # was 40 / 250
    assert r.utilisation == pytest.approx(1.0, abs=0.01)  # was 10
    assert any("span 400 mm: the shortest clear distance between supports" in n for n in r.notes)
    assert not any("THICK PLATE" in w for w in r.warnings)  # span/t = 80 (was 40/5 = 8: a false warning)


def test_strip_on_its_long_edges_keeps_the_short_span_and_the_thick_warning(tmp_path):
    r = _check(tmp_path, edges='"bottom", "top"')
    assert r.capacity.m_as("mm") == pytest.approx(40 / 250)
    assert any("THICK PLATE: span/thickness = 8" in w for w in r.warnings)  # 40 / 5


def test_cantilever_strip_spans_its_length(tmp_path):
    r = _check(tmp_path, edges='"left"', kind="fixed")
    assert r.capacity.m_as("mm") == pytest.approx(400 / 250)
    assert any("span 400 mm: a cantilever" in n for n in r.notes)


def test_span_field_overrides_the_limit_and_the_thin_plate_test(tmp_path):
    r = _check(tmp_path, extra='span = "40 mm"')
    assert r.capacity.m_as("mm") == pytest.approx(40 / 250)
    assert any("span 40 mm: the 'span' field" in n for n in r.notes)
    assert any("THICK PLATE: span/thickness = 8" in w for w in r.warnings)


def test_middle_row_of_point_supports_halves_the_span(tmp_path):
    pts = ", ".join(f'{{ point = "200, {y}", type = "pinned" }}' for y in range(50, 400, 50))
    f = tmp_path / "d.toml"
    f.write_text(textwrap.dedent(f"""
        [design]
        name = "two spans"
        [components.p]
        type = "plate_fea"
        width = "400 mm"
        height = "400 mm"
        thickness = "3 mm"
        material = "Structural Steel"
        supports = [{{ edges = "all", type = "pinned" }}, {pts}]
        deflection_limit = "L/250"
        [components.p.checks]
        plate_stress_fea = false
        [load_cases.q.p]
        pressure = "-14 kPa"
        """))
    r = load(f).verify().get("p", "plate_deflection_fea")
    assert r.capacity.m_as("mm") == pytest.approx(200 / 250)  # was 400 / 250
    assert r.details["location"].m_as("mm")[0] < 200  # the largest deflection in one half


def _model(w, h, supports):
    return P.PlateModel(P.Plate.rectangle(f"{w} mm", f"{h} mm", "5 mm", "Structural Steel"), supports)


def test_plate_held_all_round_spans_its_shorter_side():
    assert plate_span(_model(400, 200, [P.EdgeSupport()]), (0.2, 0.1))[0] == pytest.approx(0.2)
    assert plate_span(_model(400, 200, [P.EdgeSupport()]), (0.1, 0.05))[0] == pytest.approx(0.2)


def test_corner_posts_and_bolts():
    posts = [P.PointSupport((x, y), unit="mm") for x in (0, 400) for y in (0, 400)]
    assert plate_span(_model(400, 400, posts), (0.2, 0.2))[0] == pytest.approx(0.4)
    centers = [(15, 15), (285, 15), (285, 185), (15, 185)]
    plate = P.Plate.rectangle("300 mm", "200 mm", "6 mm", "Structural Steel",
                              holes=[P.Hole(c, 6.6, name=f"b{i}", unit="mm") for i, c in enumerate(centers)])
    model = P.PlateModel(plate, [P.HoleSupport("all", washer_diameter="11 mm")])
    span, how = plate_span(model, (0.148, 0.130))
    assert span == pytest.approx(0.259)
    assert "between supports" in how


def test_no_support_on_any_line_keeps_the_shorter_side():
    # one point support far off every line through the point cannot be met (its reach is its radius, 0)
    span, how = plate_span(_model(400, 200, [P.PointSupport((0, 0), unit="mm")]), (0.3, 0.1))
    assert span == pytest.approx(0.2) and "bounding box" in how
