"""Mode figures of frames (review 3 finding 15; task fixstudy): a portal in the x-z plane stands upright (z up) and
its out-of-plane (y) sway, invisible in the x-z view, gets a second view that shows it.

No published numbers: the figure's geometry is checked (which axes each panel draws)."""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.checks.result import CheckResult
from mechverify.units import Q

pytest.importorskip("matplotlib")

# portal: columns A-B and D-C along z (1000 mm), beam B-C along x, points every 250 mm
_PTS = np.array([[0, 0, z] for z in range(0, 1001, 250)] + [[x, 0, 1000] for x in range(250, 751, 250)]
                + [[1000, 0, z] for z in range(1000, -1, -250)], dtype=float)
_LINES = np.array([[k, k + 1] for k in range(len(_PTS) - 1)])


def _result(direction: int) -> CheckResult:
    shape = np.zeros_like(_PTS)
    shape[:, direction] = _PTS[:, 2] / 1000  # sway grows with the height
    return CheckResult(check="buckling_load_factor", component="f", demand=Q(1.0, ""), capacity=Q(3.876, ""),
                       details={"mode_points": Q(_PTS, "mm"), "mode_shape": shape, "mode_lines": _LINES,
                                "mode_value": 3.876})


def _drawn(ax) -> tuple[str, str, float]:
    """(x label, y label, largest horizontal spread of the deformed blue lines in the panel)."""
    xs = np.concatenate([ln.get_xdata() for ln in ax.get_lines() if ln.get_color() == "#0969da" and len(ln.get_xdata())])
    return ax.get_xlabel(), ax.get_ylabel(), float(np.ptp(xs))


def test_a_portal_swaying_out_of_its_plane_is_upright_with_a_side_view():
    from mechverify.reports.plots.fea import buckling_shape_plot

    fig = buckling_shape_plot(_result(1))
    assert len(fig.axes) == 2
    front, side = fig.axes
    assert _drawn(front)[:2] == ("x [mm]", "z [mm]")  # upright: z up, not lying on its side
    assert "mode out of plane (y)" in front.get_title()
    xl, yl, spread = _drawn(side)
    assert (xl, yl) == ("y [mm]", "z [mm]") and spread == pytest.approx(0.12 * 1000)  # the sway is drawn


def test_a_portal_swaying_in_its_plane_has_one_upright_view():
    from mechverify.reports.plots.fea import buckling_shape_plot

    fig = buckling_shape_plot(_result(0))
    assert len(fig.axes) == 1
    xl, yl, spread = _drawn(fig.axes[0])
    assert (xl, yl) == ("x [mm]", "z [mm]") and spread == pytest.approx(1000 + 0.12 * 1000)
