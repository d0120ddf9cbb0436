"""The plate-FEA figure shows where the loads act (issue 25): a point force as a red triangle pointing along its
sign, a patch load as a hatched red outline, a uniform pressure named in the caption. Geometry only: the markers
sit at the points and patches the design file gives (a 200 x 100 mm plate, coarse mesh)."""

from __future__ import annotations

import textwrap

import numpy as np

from mechverify.design import load

DESIGN = """
[design]
name = "plate figure"
[components.p]
type = "plate_fea"
width = "200 mm"
height = "100 mm"
thickness = "4 mm"
material = "Inventor Aluminum 6061"
supports = [{ edges = "all", type = "pinned" }]
mesh_size = "25 mm"
[load_cases.q.p]
point_loads = [{ at = "60, 50", force = "-100 N" }]
patch_loads = [{ center = "150, 50", size = "20, 30", force = "-50 N" }]
pressure = "1 kPa"
"""


def test_plate_figure_marks_the_loads(tmp_path):
    path = tmp_path / "design.toml"
    path.write_text(textwrap.dedent(DESIGN))
    d = load(path)
    rs = d.verify()
    entry = d.data.components["p"]
    [(caption, fig)] = entry.type.figures(entry.obj, [r for r in rs if r.component == "p"])
    assert "loads in red" in caption and "uniform pressure" in caption
    for ax in fig.axes[:2]:  # stress and deflection panels (the others are colour bars)
        points = [ln for ln in ax.lines if ln.get_marker() == "v" and ln.get_color() == "red"]
        assert len(points) == 1
        assert np.allclose([points[0].get_xdata()[0], points[0].get_ydata()[0]], [60, 50])
        patches = [p for p in ax.patches if p.get_hatch() == "////"]
        assert len(patches) == 1
        xy = patches[0].get_xy()
        assert np.allclose(xy[:, 0].min(), 140) and np.allclose(xy[:, 0].max(), 160)
        assert np.allclose(xy[:, 1].min(), 35) and np.allclose(xy[:, 1].max(), 65)
