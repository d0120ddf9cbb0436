"""Checks on solid FEA, modal and buckling results (mechverify.checks.fea): verdicts and orientation.

The numbers checked come from the analyses validated in tests/validation/test_blevins_cantilever_modes.py
(cantilever 203.8 Hz, Euler-Bernoulli hand calculation) and test_timoshenko_gere_euler_column.py
(Euler factor 10.28, hand calculation of Timoshenko & Gere sec. 2.1).
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.checks.fea import (
    check_buckling_load_factor,
    check_natural_frequency,
    check_solid_deflection,
    check_solid_stress,
    no_buckling_result,
)
from mechverify.checks.registry import CHECKS
from mechverify.errors import InputError
from mechverify.fea import buckling, mesh, modal, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane
from mechverify.units import Q


@pytest.fixture(scope="module")
def bar():
    return solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (10, 1, 1)), "Structural Steel",
                            supports=(Fixed(Plane(x="0 mm")),),
                            loads=(Force(Plane(x="200 mm"), ("-1 kN", "0 N", "0 N")),))


def test_registered():
    for name in ("solid_stress", "solid_deflection", "natural_frequency", "buckling_load_factor"):
        assert name in CHECKS


def test_natural_frequency_minimum_and_band(bar):
    res = modal.modal(bar, 4)  # f1 = f2 ~ 206 Hz, f3 = f4 ~ 1283 Hz
    assert check_natural_frequency(res, minimum="150 Hz").verdict == "pass"
    assert check_natural_frequency(res, minimum="250 Hz").verdict == "fail"
    # a band between the pairs with 15 % margin: 206*1.15 < 300 and 1283/1.15 > 1000
    assert check_natural_frequency(res, band=("300 Hz", "1000 Hz")).verdict == "pass"
    r = check_natural_frequency(res, band=("190 Hz", "220 Hz"))
    assert r.verdict == "fail" and "governing mode" in " ".join(r.notes)
    # the band above every mode computed: a warning that more modes are needed
    r = check_natural_frequency(res, band=("2000 Hz", "3000 Hz"))
    assert r.warnings
    with pytest.raises(InputError, match="either minimum or band"):
        check_natural_frequency(res)


def test_buckling_factor_against_required_sf(bar):
    res = buckling.buckling(bar, 1)  # 10.4
    assert check_buckling_load_factor(res, required_sf=3.0).verdict == "pass"
    assert check_buckling_load_factor(res, required_sf=12.0).verdict == "fail"


def test_solid_stress_and_deflection(bar):
    res = bar.solve()  # 1 kN on 100 mm² -> 10 MPa axial compression (plus clamp effects)
    r = check_solid_stress(res, component="bar")
    assert r.demand.m_as("MPa") == pytest.approx(10, rel=0.3) and r.verdict == "pass"
    d = check_solid_deflection(res, "0.01 mm")  # PL/EA = 1e3*0.2/(200e9*1e-4) = 0.01 mm
    assert d.demand.m_as("mm") == pytest.approx(0.01, rel=0.05)


def test_substituted_lines_evaluate_to_the_results(bar):
    """Each FEA check prints ``symbol = formula with numbers = result``; parsed back (tests/test_reports_substituted)
    the formula gives the printed result, and the result is the check's demand or capacity."""
    from tests.test_reports_substituted import evaluate

    static = bar.solve(progress=False)
    r = check_solid_stress(static)
    value, printed = evaluate(r.substituted)
    assert value.m_as("MPa") == pytest.approx(printed.m_as("MPa"), rel=2e-3)
    assert printed.m_as("MPa") == pytest.approx(r.demand.m_as("MPa"), rel=1e-3)
    r = check_solid_deflection(static, "1 mm")
    value, printed = evaluate(r.substituted)
    assert value.m_as("mm") == pytest.approx(printed.m_as("mm"), rel=2e-3)
    assert printed.m_as("mm") == pytest.approx(r.demand.m_as("mm"), rel=1e-3)
    r = check_natural_frequency(modal.modal(bar, 2), minimum="150 Hz")
    value, printed = evaluate(r.substituted)
    assert value.m_as("Hz") == pytest.approx(printed.m_as("Hz"), rel=1e-3)
    assert printed.m_as("Hz") == pytest.approx(r.capacity.m_as("Hz"), rel=1e-3)
    r = check_buckling_load_factor(buckling.buckling(bar, 1), required_sf=3.0)
    value, printed = evaluate(r.substituted)
    assert float(value) == pytest.approx(float(printed), rel=1e-3)
    assert float(printed) == pytest.approx(r.capacity.m, rel=1e-3)


def test_mode_shape_figures(bar):
    """natural_frequency and buckling_load_factor carry the mode's figure data; the figures draw (solid, frame)."""
    import math

    import mechverify.fea.frame as fp
    from mechverify.components import sections
    from mechverify.fea.frame import Frame, Member
    from mechverify.fea.frame.modal import frame_modes
    from mechverify.reports.plots import figure_for

    r = check_natural_frequency(modal.modal(bar, 2), minimum="150 Hz")
    assert r.details["mode_points"].shape == r.details["mode_shape"].shape
    assert math.isclose(float(abs(r.details["mode_shape"]).max()), 1.0)
    assert figure_for(r).startswith("data:image/svg")
    r = check_buckling_load_factor(buckling.buckling(bar, 1))
    assert figure_for(r).startswith("data:image/svg")
    support = fp.FrameSupport
    fr = Frame({"A": ["0 mm"] * 3, "B": ["500 mm", "0 mm", "0 mm"]},
               [Member("A", "B", sections.circle("20 mm"), "Structural Steel")], [support("A", "fixed")])
    r = check_natural_frequency(frame_modes(fr, 2), minimum="20 Hz")
    assert "mode_lines" in r.details and r.verdict == "pass"
    assert figure_for(r).startswith("data:image/svg")


# ------------------------------------------------ review (round 2 session 3) findings 14, 18: modal words, legend
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


def test_a_case_that_cannot_buckle_says_so_in_the_note_and_the_substituted_line():
    """Review 2 finding 7: a pull case printed the substituted line "\\lambda_{cr} > \\infty" (false as written) and
    the note "capacity: the factor every positive buckling factor would exceed" while the capacity is infinite (null
    in JSON). Both now say "no buckling under this load case"; a finite bound (solid_fea: the reversed load's
    factor bounds it) is still named as the capacity."""
    from mechverify.reports.mathtext import formula_svg

    r = no_buckling_result(float("inf"), "no member in compression")
    assert r.substituted == r"\text{no buckling under this load case}" and r.passed
    assert r.notes == ("no buckling under this load case: no compression that can buckle the model: "
                       "no member in compression",)
    b = no_buckling_result(43.2, "the reversed loads would buckle it at 41.1")
    assert b.substituted.startswith(r"\lambda_{cr} > 43.2") and "no buckling under this load case" in b.substituted
    assert any(n.startswith("capacity: 43.2,") for n in b.notes)
    assert formula_svg(r.substituted) is not None and formula_svg(b.substituted) is not None  # both typeset
