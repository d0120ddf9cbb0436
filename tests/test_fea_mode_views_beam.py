"""Mode figures of a straight beam (review 4 finding 8): a cantilever along x whose first mode bends along y was drawn
in the x-z view (the mode a straight line on the undeformed beam) plus a y-z END view (the beam collapsed to a
segment); no panel showed the deflection along the beam. A model with one extent (members on a line) gets one view:
its axis against the mode's largest translation (z up when the mode is along z; an axial mode against z).

No published numbers: the figure's geometry is checked (which axes the panel draws and the drawn deflection)."""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.checks.result import CheckResult
from mechverify.units import Q

pytest.importorskip("matplotlib")


def _beam(axis: int, direction: int) -> CheckResult:
    """A 1000 mm beam along ``axis`` (points every 100 mm), its mode along ``direction`` growing as (s/L)^2."""
    s = np.linspace(0, 1000, 11)
    P = np.zeros((11, 3))
    P[:, axis] = s
    S = np.zeros_like(P)
    S[:, direction] = (s / 1000) ** 2
    lines = np.array([[k, k + 1] for k in range(10)])
    return CheckResult(check="natural_frequency", component="f", demand=Q(1.0, "Hz"), capacity=Q(8.153, "Hz"),
                       details={"mode_points": Q(P, "mm"), "mode_shape": S, "mode_lines": lines,
                                "mode_value": Q(8.153, "Hz"), "mode_number": 1})


def _panels(fig) -> list[tuple[str, str, float, float]]:
    """Per panel: (x label, y label, spread of the deformed line along the panel's x and y)."""
    out = []
    for ax in fig.axes:
        blue = [ln for ln in ax.get_lines() if ln.get_color() == "#0969da" and len(ln.get_xdata())]
        if not blue:
            continue
        xs = np.concatenate([ln.get_xdata() for ln in blue])
        ys = np.concatenate([ln.get_ydata() for ln in blue])
        out.append((ax.get_xlabel(), ax.get_ylabel(), float(np.ptp(xs)), float(np.ptp(ys))))
    return out


@pytest.mark.parametrize(("axis", "direction", "labels"), [
    (0, 1, ("x [mm]", "y [mm]")),  # review 4's cantilever: bending along y, seen along the beam
    (0, 2, ("x [mm]", "z [mm]")),
    (2, 0, ("x [mm]", "z [mm]")),  # a column along z swaying along x: upright
    (1, 0, ("x [mm]", "y [mm]")),
])
def test_a_straight_beam_is_drawn_along_its_axis_against_the_mode(axis, direction, labels):
    from mechverify.reports.plots.fea import mode_shape_plot

    panels = _panels(mode_shape_plot(_beam(axis, direction)))
    assert len(panels) == 1
    xl, yl, sx, sy = panels[0]
    assert (xl, yl) == labels
    along, across = (sx, sy) if labels.index(f"{'xyz'[axis]} [mm]") == 0 else (sy, sx)
    assert along == pytest.approx(1000) and across == pytest.approx(0.12 * 1000)  # the deflection is drawn


def test_an_axial_mode_of_a_beam_is_one_view_along_it():
    from mechverify.reports.plots.fea import mode_shape_plot

    panels = _panels(mode_shape_plot(_beam(0, 0)))
    assert len(panels) == 1 and panels[0][:2] == ("x [mm]", "z [mm]")
    assert panels[0][2] == pytest.approx(1000 + 0.12 * 1000)


def test_the_undeformed_beam_stays_visible_on_a_grid_line():
    """Review 4 finding 21: the undeformed beam lies on y = 0, a grid line; drawn light grey and solid like the grid it
    could not be seen although the legend listed it. It is dashed and darker than the grid."""
    from matplotlib.colors import to_rgb

    from mechverify.reports.plots.fea import mode_shape_plot

    ax = mode_shape_plot(_beam(0, 1)).axes[0]
    grid = ax.get_ygridlines()[0]
    under = [ln for ln in ax.get_lines() if ln.get_color() not in ("#0969da",) and ln not in ax.get_ygridlines()
             and ln not in ax.get_xgridlines() and len(ln.get_xdata())]
    assert under and all(ln.get_linestyle() == "--" for ln in under)
    assert all(sum(to_rgb(ln.get_color())) < sum(to_rgb(grid.get_color())) for ln in under)
