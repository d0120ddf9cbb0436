"""Partial, trapezoidal and triangular distributed loads, point loads and moments along members, and
the exact extremes of the fields, against the closed-form beam formulas.

Sources: AISC *Steel Construction Manual*, Table 3-23 (beam diagrams and formulas): simple beam with a
uniform load partially distributed (R1 = wb(2c + b)/(2l), M_max = R1 (a + R1/(2w)) at x = a + R1/w),
simple beam with a concentrated load at any point (M = Pab/l), beam fixed at both ends with a load
increasing uniformly to one end (R = 3wl/20 and 7wl/20, M = wl²/30 and wl²/20); Roark's *Formulas for
Stress and Strain*, 8th ed., Table 8.1 cases 2d (the same triangular-load fixed-end moments) and 3e
(simple beam, concentrated moment M0: reactions M0/l). The expected values are hand calculations from
these formulas, not numbers read from a printed example.
"""

import numpy as np
import pytest

from mechverify.components import sections
from mechverify.fea.frame import DistributedLoad, Frame, FrameSupport, Member, MemberPointLoad, fixed_end_forces_linear
from mechverify.materials.database import get

STEEL = get("Structural Steel")
E = 200e9
SEC = sections.rectangle("20 mm", "40 mm")
I = 0.020 * 0.040**3 / 12
L = 3.0
NODES = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"]}
SIMPLE = [FrameSupport("A", "pinned"), FrameSupport("B", "custom", hold=("y", "z", "rx"))]


def frame(supports, theory="euler", **kw):
    return Frame(NODES, [Member("A", "B", SEC, STEEL, "beam", **kw)], supports, theory=theory)


def test_partial_uniform_load_simple_beam_exact_maximum():
    """w = 2 kN/m from a = 0.7 m over b = 1.1 m (c = 1.2 m): the maximum moment lies between any sample
    points; the exact extreme (stationary point of the closed-form field) matches the formula to 1e-12."""
    w, a, b = 2000.0, 0.7, 1.1
    c = L - a - b
    res = frame(SIMPLE).solve([DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{w} N/m"], start=f"{a} m",
                                               end=f"{a + b} m")])
    R1 = w * b * (2 * c + b) / (2 * L)
    Mmax = R1 * (a + R1 / (2 * w))
    assert res.reactions["A"][0].m_as("N")[2] == pytest.approx(R1, rel=1e-12)
    r = res.ranges("beam")["My"]
    assert -r.min.m_as("N*m") == pytest.approx(Mmax, rel=1e-12)
    assert r.s_min.m_as("m") == pytest.approx(a + R1 / w, rel=1e-9)
    # the diagram includes the stationary points, so its sampled extreme is the exact one too
    assert -np.min(res.diagram("beam").My.m_as("N*m")) == pytest.approx(Mmax, rel=1e-12)
    assert res.max_bending_moment.value.m_as("N*m") == pytest.approx(Mmax, rel=1e-12)


@pytest.mark.parametrize("theory", ["euler", "timoshenko"])
def test_triangular_load_fixed_both_ends(theory):
    """Load rising from 0 at A to w at B on a fixed-fixed beam: R_A = 3wl/20, R_B = 7wl/20, M_A = wl²/30,
    M_B = wl²/20 (Euler-Bernoulli). With shear deformation the statically indeterminate end moments shift
    (the fixed-end forces come from the exact Timoshenko fields); statics still holds: R_A + R_B = wl/2 and
    R_B l - w l²/3 = M_A + M_B (global y components of the support moments)."""
    w = 3000.0
    res = frame([FrameSupport("A"), FrameSupport("B")], theory).solve(
        [DistributedLoad("beam", ["0 N/m", "0 N/m", "0 N/m"], load_end=["0 N/m", "0 N/m", f"-{w} N/m"])])
    RA, RB = res.reactions["A"][0].m_as("N")[2], res.reactions["B"][0].m_as("N")[2]
    MA, MB = res.reactions["A"][1].m_as("N*m")[1], res.reactions["B"][1].m_as("N*m")[1]
    assert RA + RB == pytest.approx(w * L / 2, rel=1e-12)
    if theory == "euler":
        assert RA == pytest.approx(3 * w * L / 20, rel=1e-12)
        assert RB == pytest.approx(7 * w * L / 20, rel=1e-12)
        assert abs(MA) == pytest.approx(w * L**2 / 30, rel=1e-12)
        assert abs(MB) == pytest.approx(w * L**2 / 20, rel=1e-12)
    # moment equilibrium about A (global y components; checks the Timoshenko end forces)
    assert RB * L - w * L / 2 * (2 * L / 3) == pytest.approx(MA + MB, rel=1e-9)


def test_trapezoidal_load_is_uniform_plus_triangle_and_element_independent():
    """A trapezoid (w1 at A, w2 at B) is the sum of a uniform w1 and a triangle w2 - w1 (superposition of
    the Table 3-23 cases): the end moments of a fixed-fixed beam are w1 l²/12 + (w2-w1) l²/30 and
    w1 l²/12 + (w2-w1) l²/20; one element or five give the same answer (exact fixed-end forces)."""
    w1, w2 = 1000.0, 4000.0
    load = DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{w1} N/m"], load_end=["0 N/m", "0 N/m", f"-{w2} N/m"])
    for div in (1, 5):
        res = frame([FrameSupport("A"), FrameSupport("B")], divisions=div).solve([load])
        assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(w1 * L**2 / 12 + (w2 - w1) * L**2 / 30,
                                                                          rel=1e-12)
        assert abs(res.reactions["B"][1].m_as("N*m")[1]) == pytest.approx(w1 * L**2 / 12 + (w2 - w1) * L**2 / 20,
                                                                          rel=1e-12)


def test_fixed_end_forces_of_a_uniform_load_match_the_classical_values():
    """qL/2 and qL²/12 for both theories (the load is symmetric) - Przemieniecki Sec. 5.7."""
    q = np.array([[100.0, 200.0, -300.0]])
    for s in (0.0, 1e-6):
        f = fixed_end_forces_linear(np.array([2.0]), q, q, np.array([1e4]), np.array([2e4]), np.array([s]),
                                    np.array([s]))[0]
        assert f[[0, 1, 2]] == pytest.approx([100.0, 200.0, -300.0])
        assert f[5] == pytest.approx(200 * 4 / 12) and f[11] == pytest.approx(-200 * 4 / 12)
        assert f[4] == pytest.approx(300 * 4 / 12) and f[10] == pytest.approx(-300 * 4 / 12)


def test_point_load_and_moment_along_a_member_in_local_axes():
    """P at a = 1.2 m on a simple beam: M = P a b / l under the load; a concentrated moment M0 at 1 m:
    reactions ±M0/l (Roark Table 8.1 case 3e). The inclined copy of the beam with the load in its local
    axes gives the same moments."""
    P, a = 900.0, 1.2
    res = frame(SIMPLE).solve([MemberPointLoad("beam", f"{a} m", force=["0 N", "0 N", f"-{P} N"])])
    assert -res.ranges("beam")["My"].min.m_as("N*m") == pytest.approx(P * a * (L - a) / L, rel=1e-12)
    M0 = 500.0
    res = frame(SIMPLE).solve([MemberPointLoad("beam", "1 m", moment=["0 N*m", f"{M0} N*m", "0 N*m"])])
    assert abs(res.reactions["A"][0].m_as("N")[2]) == pytest.approx(M0 / L, rel=1e-12)
    assert res.reactions["A"][0].m_as("N")[2] == pytest.approx(-res.reactions["B"][0].m_as("N")[2], rel=1e-12)
    # inclined beam (30 degrees in the x-z plane), load across it in local z
    c, s = np.cos(np.pi / 6), np.sin(np.pi / 6)
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L * c} m", "0 m", f"{L * s} m"]}
    inc = Frame(nodes, [Member("A", "B", SEC, STEEL, "beam")],
                [FrameSupport("A", "pinned"), FrameSupport("B", "custom", hold=("x", "y", "z", "rx"))], theory="euler")
    r2 = inc.solve([MemberPointLoad("beam", f"{a} m", force=["0 N", "0 N", f"-{P} N"])])
    assert -r2.ranges("beam")["My"].min.m_as("N*m") == pytest.approx(P * a * (L - a) / L, rel=1e-9)
