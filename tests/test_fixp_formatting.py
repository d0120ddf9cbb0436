"""Review findings 13, 14, 18 (formatting of FEA results): structural frequencies in Hz (rpm stays for speeds),
a micrometre deflection in µm, the effective masses as words not a numpy array, the frequency margin listed only
where it applies (an excitation band), the mode-shape legend outside the model's points."""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.checks.fea import check_natural_frequency
from mechverify.reports.numbers import design_units, quantity, quantity_in
from mechverify.units import Q


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


class _Modes:
    """Modal results of a 1-DOF-per-axis toy: two modes at 50 and 80 Hz."""

    rigid_body_modes = 0
    frequencies = Q(np.array([50.0, 80.0]), "Hz")
    omega2 = (2 * np.pi * np.array([50.0, 80.0])) ** 2

    def effective_mass_fraction(self):
        return np.array([[0.613, 0.0, 0.0], [0.0, 0.799, 0.717]])


def test_effective_mass_words_and_margin_only_for_a_band():
    r = check_natural_frequency(_Modes(), minimum="40 Hz", margin=0.15)
    note = next(n for n in r.notes if n.startswith("effective mass"))
    assert note == "effective mass of the modes computed: 61.3 % along x, 79.9 % along y, 71.7 % along z of the total"
    assert "margin" not in r.inputs and r.inputs["f_req"].m_as("Hz") == pytest.approx(40)
    assert r.capacity.m_as("Hz") == pytest.approx(50) and r.demand.m_as("Hz") == pytest.approx(40)  # no margin
    band = check_natural_frequency(_Modes(), band=("55 Hz", "60 Hz"), margin=0.15)
    assert band.inputs["margin"] == 0.15


def test_mode_legend_outside_the_axes():
    pytest.importorskip("matplotlib")
    from mechverify.checks.result import CheckResult
    from mechverify.reports.plots.fea import mode_shape_plot

    pts = np.array([[x, y, z] for x in range(5) for y in range(3) for z in range(3)], dtype=float)
    shape = np.zeros_like(pts)
    shape[:, 1] = pts[:, 0] / 4
    r = CheckResult(check="natural_frequency", component="c", demand=Q(1.0, "Hz"), capacity=Q(2.0, "Hz"),
                    details={"mode_points": Q(pts, "mm"), "mode_shape": shape, "mode_number": 1,
                             "mode_value": Q(2.0, "Hz")})
    fig = mode_shape_plot(r)
    fig.canvas.draw()
    ax = fig.axes[0]
    leg = ax.get_legend().get_window_extent()
    assert leg.y0 >= ax.get_window_extent().y1 - 1  # above the axes, not on the points
