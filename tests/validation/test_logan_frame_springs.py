"""Two-node springs, support springs and one-way (compression-only) support springs.

Sources: D. L. Logan, *A First Course in the Finite Element Method*, 4th ed., Example 2.1 (a
spring assemblage: k1 = 1000, k2 = 2000, k3 = 3000 lb/in, P = 5000 lb at node 4; nodes 1 and 2
fixed). Logan's printed results are quoted in PyNite's test suite (test_spring.py): u3 = 0.9091 in,
u4 = 1.3636 in, f1x = -909.1 lb, f2x = -4090.9 lb; the hand calculation from the assembled equations
gives u3 = 10/11 in, u4 = 15/11 in. Springs in series and the lever on one-way springs are hand
calculations from statics (stated in each test).
"""

import pytest

from mechverify.components import sections
from mechverify.errors import InputError, ModelError
from mechverify.fea.frame import Frame, FramePointLoad, FrameSupport, Member, Spring
from mechverify.materials.database import get

STEEL = get("Structural Steel")
E = 200e9
SEC = sections.rectangle("10 mm", "20 mm")
I = 0.010 * 0.020**3 / 12
LBF_IN = 4.4482216152605 / 0.0254  # N/m per lbf/in


def test_logan_example_2_1_spring_assemblage():
    nodes = {"1": ["0 in", "0 in", "0 in"], "2": ["30 in", "0 in", "0 in"], "3": ["10 in", "0 in", "0 in"],
             "4": ["20 in", "0 in", "0 in"]}
    springs = [Spring("1", "3", axial="1000 lbf/in", name="k1"), Spring("3", "4", axial="2000 lbf/in", name="k2"),
               Spring("4", "2", axial="3000 lbf/in", name="k3")]
    line = ("y", "z", "rx", "ry", "rz")
    sups = [FrameSupport("1"), FrameSupport("2"), FrameSupport("3", "custom", hold=line), FrameSupport("4", "custom", hold=line)]
    res = Frame(nodes, [], sups, springs=springs).solve([FramePointLoad("4", force=["5000 lbf", "0 lbf", "0 lbf"])])
    book = {"u3": 0.9091, "u4": 1.3636, "f1": -909.1, "f2": -4090.9}  # Logan's printed values (4 significant)
    hand = {"u3": 10 / 11, "u4": 15 / 11}
    u3, u4 = res.displacement("3").m_as("in")[0], res.displacement("4").m_as("in")[0]
    assert u3 == pytest.approx(hand["u3"], rel=1e-12)
    assert u4 == pytest.approx(hand["u4"], rel=1e-12)
    assert u3 == pytest.approx(book["u3"], abs=1e-4)
    assert u4 == pytest.approx(book["u4"], abs=1e-4)
    assert res.reactions["1"][0].m_as("lbf")[0] == pytest.approx(book["f1"], abs=0.05)
    assert res.reactions["2"][0].m_as("lbf")[0] == pytest.approx(book["f2"], abs=0.05)
    # spring k2 is stretched by u4 - u3 = 5/11 in: tension 2000 * 5/11 lb
    assert res.spring_force("k2")["axial"].m_as("lbf") == pytest.approx(2000 * 5 / 11, rel=1e-12)
    assert res.spring_force("k3")["axial"].m_as("lbf") == pytest.approx(-3000 * 15 / 11, rel=1e-12)


def test_six_component_spring_between_coincident_nodes():
    """A cantilever A-B (fixed at A) carries, through a six-component spring to a coincident node B2, a load
    at B2: springs in series, δ(B2) = P/k_z + P a³/(3 EI); the rotation at B2 adds P a²/(2EI) + 0 (no moment
    in the spring). Coincident named nodes stay separate nodes."""
    a, P, kz = 0.4, 100.0, 5e5
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{a} m", "0 m", "0 m"], "B2": [f"{a} m", "0 m", "0 m"]}
    k = {"x": "1e9 N/m", "y": "1e9 N/m", "z": f"{kz} N/m", "rx": "1e6 N*m/rad", "ry": "1e6 N*m/rad",
         "rz": "1e6 N*m/rad"}
    fr = Frame(nodes, [Member("A", "B", SEC, STEEL, "arm")], [FrameSupport("A")], theory="euler",
               springs=[Spring("B", "B2", stiffness=k, name="joint")])
    res = fr.solve([FramePointLoad("B2", force=["0 N", "0 N", f"-{P} N"])])
    assert -res.displacement("B2").m_as("m")[2] == pytest.approx(P / kz + P * a**3 / (3 * E * I), rel=1e-12)
    assert -res.displacement("B").m_as("m")[2] == pytest.approx(P * a**3 / (3 * E * I), rel=1e-12)
    assert res.spring_force("joint")["force"].m_as("N")[2] == pytest.approx(P, rel=1e-12)  # holds B2 up
    with pytest.raises(InputError, match="across the offset"):
        Frame(nodes | {"C": ["1 m", "0 m", "0 m"]}, [Member("A", "B", SEC, STEEL)], [FrameSupport("A")],
              springs=[Spring("B", "C", stiffness={"z": "1 N/m"})]).solve([])


def test_one_way_spring_under_a_cantilever_tip():
    """A cantilever whose tip rests on a one-way spring (it can push up, +z, never pull). Load down: in
    contact, δ = P/(k + 3EI/L³) (springs in parallel); load up: the tip lifts off, δ = P L³/(3EI), no
    reaction, and the note says so."""
    k, P, L = 2e5, 100.0, 0.4
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"]}
    fr = Frame(nodes, [Member("A", "B", SEC, STEEL, "beam")],
               [FrameSupport("A"), FrameSupport("B", "spring", springs={"z": f"{k} N/m"}, one_way={"z": "+"})], theory="euler")
    down = fr.solve([FramePointLoad("B", force=["0 N", "0 N", f"-{P} N"])])
    assert -down.displacement("B").m_as("m")[2] == pytest.approx(P / (k + 3 * E * I / L**3), rel=1e-12)
    assert any("all in contact" in n for n in down.notes)
    up = fr.solve([FramePointLoad("B", force=["0 N", "0 N", f"{P} N"])])
    assert up.displacement("B").m_as("m")[2] == pytest.approx(P * L**3 / (3 * E * I), rel=1e-12)
    assert up.reactions["B"][0].m_as("N")[2] == 0.0
    assert any("lifted (no reaction): z at node B" in n for n in up.notes)


def test_lever_on_one_way_springs_needs_the_active_set():
    """A beam A-C pinned at its middle B (a seesaw) rests on one-way springs at A and C. A downward load P at
    a = L/2 right of B tips it: the spring at A would have to pull, so it lifts (second iteration); statics
    then gives R_C = P a / L, R_A = 0, R_B = P - R_C."""
    L, P = 1.0, 1000.0
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"], "C": [f"{2 * L} m", "0 m", "0 m"]}
    sp = {"z": "1e6 N/m"}
    fr = Frame(nodes, [Member("A", "C", SEC, STEEL, "lever")],
               [FrameSupport("B", "custom", hold=("x", "y", "z", "rx", "rz")),
                FrameSupport("A", "spring", springs=sp, one_way={"z": "+"}),
                FrameSupport("C", "spring", springs=sp, one_way={"z": "+"})], theory="euler")
    res = fr.solve([FramePointLoad([f"{1.5 * L} m", "0 m", "0 m"], force=["0 N", "0 N", f"-{P} N"])])
    assert res.reactions["A"][0].m_as("N")[2] == 0.0
    assert res.reactions["C"][0].m_as("N")[2] == pytest.approx(P * 0.5, rel=1e-12)
    assert res.reactions["B"][0].m_as("N")[2] == pytest.approx(P * 0.5, rel=1e-12)
    assert any("converged in 2 iteration(s); lifted (no reaction): z at node A" in n for n in res.notes)
    # with the A spring the only support in z besides the pin... lifted everywhere: named, not a singular matrix
    fr2 = Frame(nodes, [Member("A", "C", SEC, STEEL, "lever")],
                [FrameSupport("B", "custom", hold=("x", "y", "rx", "rz")),
                 FrameSupport("A", "spring", springs=sp, one_way={"z": "+"}),
                 FrameSupport("C", "spring", springs=sp, one_way={"z": "+"})], theory="euler")
    with pytest.raises(ModelError, match="one-way springs at z at node A, z at node C lifted"):
        fr2.solve([FramePointLoad("B", force=["0 N", "0 N", f"{P} N"])])
