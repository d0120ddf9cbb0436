"""Report figures and titles the review found wanting (review items 11-12, /tmp/notes/review.md): the shaft layout's
labels overlapped each other and the title, the plain section at the largest moment was titled "max moment@300",
and workspace_payload / solid_fea checks had no figure. These are layout and presence tests (no published number
is involved)."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import FIVE_BAR_LINKS

ROOT = Path(__file__).resolve().parents[1]


def _text_boxes(fig, ax):
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    from matplotlib.text import Text

    # the text alone (an Annotation's own extent includes its arrow)
    return [Text.get_window_extent(t, r) for t in ax.texts if t.get_text()], ax.title.get_window_extent(r)


def _assert_no_overlap(fig, ax):
    boxes, title = _text_boxes(fig, ax)
    assert boxes
    frame = ax.get_window_extent()
    for i, a in enumerate(boxes):
        assert not a.overlaps(title), "a label overlaps the title"
        assert frame.x0 - 1 <= a.x0 and a.x1 <= frame.x1 + 1, "a label sticks out of the axes"
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), f"labels overlap: {a} {b}"


def test_conveyor_shaft_layout_labels_do_not_overlap():
    """examples/conveyor_drum: features, loads (two at the same x as a feature) and bearings keep clear of each
    other and of the title."""
    from mechverify.design import load
    from mechverify.reports.plots.shafts import shaft_figure

    r = next(r for r in load(ROOT / "examples" / "conveyor_drum" / "design.toml").verify()
             if r.check == "shaft_fatigue")
    fig = shaft_figure(r)
    _assert_no_overlap(fig, fig.axes[0])


def test_crowded_shaft_labels_and_max_moment_section_title():
    """Five features within 40 mm and a load among them: rows keep the labels apart. The largest moment sits at
    the load (x = 400 mm, no feature there): its section is named in words, not "max moment@400"."""
    from mechverify.checks import shafts as cs
    from mechverify.components.shafts import Feature, Segment, Shaft, Support, force_load
    from mechverify.fea.shafts import analyse
    from mechverify.materials.database import get
    from mechverify.reports.plots.shafts import label_levels, shaft_figure

    assert label_levels([(0, 10), (5, 10), (20, 10), (6, 2)]) == [0, 1, 0, 2]
    feats = tuple(Feature("shoulder", 0.3, radius=0.002, name=f"shoulder {i}") if i == 0 else
                  Feature("groove", 0.3 + 0.01 * i, radius=0.0005, depth=0.0005, name=f"retaining groove {i}")
                  for i in range(4))
    sh = Shaft("f", (Segment(0.3, 0.03), Segment(0.4, 0.04)), get("AISI 1045 CD"),
               (Support("A", 0.05), Support("B", 0.65)), (force_load("P", 0.4, (0, 0, -2000.0)),), feats)
    a = analyse(sh)
    r = cs.check_shaft_fatigue(sh, a)
    names = [s["name"] for s in r.details["sections"]]
    assert "the section of maximum moment (x = 400 mm)" in names
    assert not any("@" in n for n in names)
    y = cs.check_shaft_static_yield(sh, a)
    assert "max moment@" not in y.title
    fig = shaft_figure(r)
    _assert_no_overlap(fig, fig.axes[0])
    assert "max. M (x = 400 mm)" in [t.get_text() for t in fig.axes[3].get_xticklabels()]


def _figure_svgs(html: str) -> list[str]:
    import base64
    import re

    uris = re.findall(r'<img src="data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)"', html)
    return [base64.b64decode(u).decode() for u in uris]


FIVE_BAR = """
[design]
name = "five-bar payload"

[parameters]
W = "1 N"

[requirements.safety_factors]
motor = 1.5

[components.fb]
""" + FIVE_BAR_LINKS + """x_range = ["-50 mm", "150 mm"]
y_range = ["0 mm", "200 mm"]
samples = 15
motor_torque = "3 N*m"
theta_left_min = "0 deg"
theta_left_max = "150 deg"
payload = "W"
"""


def test_five_bar_report_has_the_workspace_map(tmp_path):
    """The five-bar design of tests/test_mechanisms_workspace.py: the report (detail all) carries the workspace
    map; its data are the points inside the limited workspace with W_max(x, y), whose smallest value is the check's
    capacity, at the marked governing point."""
    import numpy as np

    from mechverify.design import load
    from mechverify.reports import render_html

    p = tmp_path / "fb.toml"
    p.write_text(FIVE_BAR, encoding="utf-8")
    d = load(p)
    res = d.verify()
    r = res.get("fb", "workspace_payload")
    W = r.details["map_wmax"].m_as("N")
    P = r.details["map_points"].m_as("mm")
    i = int(np.argmin(W))
    assert W[i] == r.capacity.m_as("N")
    assert np.array_equal(P[i], r.details["map_governing"].m_as("mm"))
    assert len(W) + len(r.details["map_outside"].magnitude) <= 15 * 15
    assert len(r.details["map_outside"].magnitude) > 0  # the grid's corners are out of reach
    svgs = [s for s in _figure_svgs(render_html([(d, res)], detail="all")) if "workspace map" in s]
    assert len(svgs) == 1
    assert "governs: theta_" in svgs[0]


SOLID = """
[design]
name = "solid cantilever"

[components.bar]
type = "solid_fea"
box = "200, 10, 10"
material = "Structural Steel"
mesh_size = "5 mm"
supports = [{ named = "xmin" }]
deflection_limit = "2 mm"

[load_cases.tip.bar]
forces = [{ named = "xmax", force = "0, 0, -100" }]
"""


def test_solid_fea_report_has_the_field_figures(tmp_path):
    """A 200 x 10 x 10 mm steel cantilever (the box of tests/test_design_solid_fea.py): solid_stress and
    solid_deflection each get a figure of the surface nodes coloured by their field with the governing node; the
    deflection governs at the free end (x = 200 mm) and the stress at the clamped end (x near 0)."""
    from mechverify.design import load
    from mechverify.reports import render_html

    p = tmp_path / "solid.toml"
    p.write_text(SOLID, encoding="utf-8")
    d = load(p)
    res = d.verify()
    s, u = res.get("bar", "solid_stress"), res.get("bar", "solid_deflection")
    assert u.details["field_point"].m_as("mm")[0] == pytest.approx(200.0)
    assert s.details["field_point"].m_as("mm")[0] < 20.0
    assert u.details["field_value"].m_as("mm") == pytest.approx(u.demand.m_as("mm"))
    assert s.details["field_value"].m_as("MPa") == pytest.approx(s.demand.m_as("MPa"))
    svgs = _figure_svgs(render_html([(d, res)], detail="all"))
    assert sum("von Mises stress, view on the" in x for x in svgs) == 1
    assert sum("displacement |u|, view on the" in x for x in svgs) == 1
