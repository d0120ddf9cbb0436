"""Member end releases, fully restrained members and nodes inside members against the closed-form
beam formulas.

Sources: AISC *Steel Construction Manual*, Table 3-23 "Shears, moments and deflections" — case 1
(simple beam, uniform load: M = wl²/8), case 12 (beam fixed at one end, supported at the other,
uniform load: R = 3wl/8 and 5wl/8, M = wl²/8 at the fixed end, 9wl²/128 at x = 3l/8), case 15
(fixed at both ends, uniform load: R = wl/2, M = wl²/12 at the ends, wl²/24 at the centre,
Δ = wl⁴/(384EI)); the same closed forms as Roark's *Formulas for Stress and Strain*, 8th ed., Table
8.1 cases 2c, 2d, 2e. The values below are hand calculations from these formulas (not numbers
read from a printed page). The guided-end beam and the beam on a flexible column are hand
calculations by superposition (stated in each test).
"""

import pytest

from mechverify.components import sections
from mechverify.errors import InputError, ModelError
from mechverify.fea.frame import DistributedLoad, Frame, FramePointLoad, FrameSupport, Hinge, Member, Release
from mechverify.materials.database import get

STEEL = get("Structural Steel")  # E = 200 GPa
E = 200e9
SEC = sections.rectangle("20 mm", "40 mm")
I = 0.020 * 0.040**3 / 12  # about local y (height along z)
A = 0.020 * 0.040
L, W = 2.0, 1500.0  # m, N/m
UNIFORM = DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{W} N/m"])
NODES = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"]}


def beam(supports, hinges=(), **kw):
    return Frame(NODES, [Member("A", "B", SEC, STEEL, "beam", **kw)], supports, hinges, theory="euler")


def test_fixed_fixed_member_fully_restrained_case_15():
    """No free degree of freedom at all: reactions only. R = wl/2, M_end = wl²/12, M_centre = wl²/24,
    Δ_centre = wl⁴/(384 EI) (the exact field between the nodes)."""
    res = beam([FrameSupport("A"), FrameSupport("B")]).solve([UNIFORM])
    for n in ("A", "B"):
        f, m = res.reactions[n]
        assert f.m_as("N")[2] == pytest.approx(W * L / 2, rel=1e-12)
        assert abs(m.m_as("N*m")[1]) == pytest.approx(W * L**2 / 12, rel=1e-12)
    r = res.ranges("beam")
    # My > 0 is hogging (sigma = My z / Iy: tension at the top fibre, z > 0)
    assert r["My"].max.m_as("N*m") == pytest.approx(W * L**2 / 12, rel=1e-12)
    assert r["My"].min.m_as("N*m") == pytest.approx(-W * L**2 / 24, rel=1e-12)
    assert r["My"].s_min.m_as("m") == pytest.approx(L / 2, rel=1e-9)
    assert r["uz"].min.m_as("m") == pytest.approx(-W * L**4 / (384 * E * I), rel=1e-9)


@pytest.mark.parametrize("how", ["member", "release_object", "hinge"])
def test_propped_cantilever_by_a_release_at_a_one_member_node_case_12(how):
    """Both ends on fixed supports, the end moment at B released (member release, Release object, or a
    Hinge at a node with one member): the propped cantilever. R_B = 3wl/8, M_A = wl²/8, span moment
    9wl²/128 at 3l/8 from B."""
    if how == "member":
        fr = beam([FrameSupport("A"), FrameSupport("B")], releases_end="My")
    elif how == "release_object":
        fr = beam([FrameSupport("A"), FrameSupport("B")], releases_end=Release(My=True))
    else:
        fr = beam([FrameSupport("A"), FrameSupport("B")], hinges=[Hinge("B", "y")])
    res = fr.solve([UNIFORM])
    assert res.reactions["B"][0].m_as("N")[2] == pytest.approx(3 * W * L / 8, rel=1e-12)
    assert res.reactions["A"][0].m_as("N")[2] == pytest.approx(5 * W * L / 8, rel=1e-12)
    assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(W * L**2 / 8, rel=1e-12)
    assert res.reactions["B"][1].m_as("N*m")[1] == pytest.approx(0, abs=1e-9)
    r = res.ranges("beam")["My"]  # sagging is My < 0
    assert r.min.m_as("N*m") == pytest.approx(-9 * W * L**2 / 128, rel=1e-12)
    assert r.s_min.m_as("m") == pytest.approx(L - 3 * L / 8, rel=1e-9)


@pytest.mark.parametrize("how", ["member", "hinge"])
def test_pinned_ended_beam_between_fixed_supports_case_1(how):
    """The issue's silent wrong answer: a beam with pinned ends between two fixed supports. Midspan moment
    wl²/8 (simple beam), not wl²/24 (the fixed-fixed beam, a factor 3 low)."""
    if how == "member":
        fr = beam([FrameSupport("A"), FrameSupport("B")], releases_start="My", releases_end="My,Mz")
    else:
        fr = beam([FrameSupport("A"), FrameSupport("B")], hinges=[Hinge("A", "y"), Hinge("B", "y")])
    res = fr.solve([UNIFORM])
    r = res.ranges("beam")["My"]
    assert r.min.m_as("N*m") == pytest.approx(-W * L**2 / 8, rel=1e-12)  # sagging is My < 0
    assert r.max.m_as("N*m") == pytest.approx(0, abs=1e-9)
    assert res.ranges("beam")["uz"].min.m_as("m") == pytest.approx(-5 * W * L**4 / (384 * E * I), rel=1e-9)
    assert res.end_rotation("beam", "start").m_as("rad")[1] == pytest.approx(W * L**3 / (24 * E * I), rel=1e-9)


def test_shear_release_gives_a_guided_end():
    """Vz released at the end B of a beam fixed at both supports: B slides but does not turn (a guided
    end). Hand calculation by superposition (cantilever + tip moment restoring zero slope):
    M_B = wl²/6, M_A = wl²/3, Δ_B = wl⁴/(24 EI)."""
    res = beam([FrameSupport("A"), FrameSupport("B")], releases_end="Vz").solve([UNIFORM])
    assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(W * L**2 / 3, rel=1e-12)
    assert abs(res.reactions["B"][1].m_as("N*m")[1]) == pytest.approx(W * L**2 / 6, rel=1e-12)
    assert res.reactions["B"][0].m_as("N")[2] == pytest.approx(0, abs=1e-9)
    assert res.ranges("beam")["uz"].min.m_as("m") == pytest.approx(-W * L**4 / (24 * E * I), rel=1e-9)


def test_beam_continuous_over_a_pinned_column():
    """A two-span beam A-B-C (pinned at A, roller at C) continuous over a column D-B whose top is pinned
    to it (member releases of the column only; a Hinge would also free the beam). Hand calculation by
    superposition (simple beam 2l + the column's reaction R at mid-span, column axial spring k = EA/h):
    δ0 = 5w(2l)⁴/(384 EI), R = δ0 / ((2l)³/(48 EI) + 1/k), hogging M_B = R(2l)/4 - w(2l)²/8 (with a
    rigid column the two-span continuous beam's wl²/8)."""
    h = 1.5
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"], "C": [f"{2 * L} m", "0 m", "0 m"],
             "D": [f"{L} m", "0 m", f"{-h} m"]}
    ms = [Member("A", "B", SEC, STEEL, "AB"), Member("B", "C", SEC, STEEL, "BC"),
          Member("D", "B", SEC, STEEL, "column", releases_end="My,Mz")]
    sups = [FrameSupport("A", "pinned"), FrameSupport("C", "custom", hold=("y", "z", "rx")), FrameSupport("D")]
    loads = [DistributedLoad(m, ["0 N/m", "0 N/m", f"-{W} N/m"]) for m in ("AB", "BC")]
    res = Frame(nodes, ms, sups, theory="euler").solve(loads)
    k = E * A / h
    d0 = 5 * W * (2 * L) ** 4 / (384 * E * I)
    R = d0 / ((2 * L) ** 3 / (48 * E * I) + 1 / k)
    MB = R * 2 * L / 4 - W * (2 * L) ** 2 / 8
    assert MB == pytest.approx(W * L**2 / 8, rel=2e-3)  # nearly the rigid-support value
    assert res.diagram("AB").My.m_as("N*m")[-1] == pytest.approx(MB, rel=1e-9)
    assert res.diagram("BC").My.m_as("N*m")[0] == pytest.approx(MB, rel=1e-9)
    assert res.diagram("column").My.m_as("N*m")[-1] == pytest.approx(0, abs=1e-9)
    assert -res.diagram("column").N.m_as("N")[0] == pytest.approx(R, rel=1e-9)


def test_a_named_node_inside_a_member_is_joined_with_a_note():
    """A node C at mid-span of AB with a post C-D under it: AB is split at C and joined to the post (a note
    says so), the same answer as two members A-C, C-B — not the misleading 'mechanism' error."""
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"], "C": [f"{L / 2} m", "0 m", "0 m"],
             "D": [f"{L / 2} m", "0 m", "-1 m"]}
    sups = [FrameSupport("A", "pinned"), FrameSupport("B", "custom", hold=("y", "z", "rx")), FrameSupport("D")]
    one = Frame(nodes, [Member("A", "B", SEC, STEEL, "AB"), Member("C", "D", SEC, STEEL, "post")], sups)
    two = Frame(nodes, [Member("A", "C", SEC, STEEL, "AC"), Member("C", "B", SEC, STEEL, "CB"),
                        Member("C", "D", SEC, STEEL, "post")], sups)
    load = [FramePointLoad(["0.3 m", "0 m", "0 m"], force=["0 N", "0 N", "-1000 N"])]
    r1, r2 = one.solve(load), two.solve(load)
    assert any("passes through node C" in n for n in r1.notes)
    assert r1.displacement("C").m_as("mm") == pytest.approx(r2.displacement("C").m_as("mm"), rel=1e-12)
    assert r1.reactions["D"][0].m_as("N") == pytest.approx(r2.reactions["D"][0].m_as("N"), rel=1e-12, abs=1e-9)


def test_unstable_and_ineffective_releases_are_named():
    with pytest.raises(InputError, match=r"member beam: its end releases leave it unstable.*twist"):
        beam([FrameSupport("A"), FrameSupport("B")], releases_start="T", releases_end="T").solve([UNIFORM])
    with pytest.raises(InputError, match=r"member beam: its end releases leave it unstable.*translation along local z"):
        beam([FrameSupport("A"), FrameSupport("B")], releases_start="Vz", releases_end="Vz").solve([UNIFORM])
    # a release at a free end (cantilever tip) has no effect: named, not ignored
    with pytest.raises(ModelError, match=r"rotation about y at node B.*released \(member beam end \(My\)\)"):
        beam([FrameSupport("A")], releases_end="My").solve([UNIFORM])
    # a hinge at a pinned support with one member: the end turns freely anyway
    with pytest.raises(ModelError, match=r"node A.*hinge about y.*has no effect"):
        beam([FrameSupport("A", "pinned"), FrameSupport("B")], hinges=[Hinge("A", "y")]).solve([UNIFORM])
    with pytest.raises(InputError, match=r"releases_end.*did you mean 'Mz'"):
        Member("A", "B", SEC, STEEL, "beam", releases_end="Mzz")


def test_three_hinged_frame_with_a_hinge_at_the_apex():
    """Two inclined rafters A-C, C-B on pinned supports with a Hinge about global y at the apex C (a three-hinged
    frame, statically determinate): a load P at C gives V = P/2 at each support and the thrust H = P l / (4 h)
    (moments about C of one half; hand calculation from statics); the moment at C is zero."""
    P, span, h = 10e3, 6.0, 2.0
    nodes = {"A": ["0 m", "0 m", "0 m"], "C": [f"{span / 2} m", "0 m", f"{h} m"], "B": [f"{span} m", "0 m", "0 m"]}
    ms = [Member("A", "C", SEC, STEEL, "left"), Member("C", "B", SEC, STEEL, "right")]
    hold = ("x", "y", "z", "rx")
    fr = Frame(nodes, ms, [FrameSupport("A", "custom", hold=hold), FrameSupport("B", "custom", hold=hold)], [Hinge("C", "y")])
    res = fr.solve([FramePointLoad("C", force=["0 N", "0 N", f"-{P} N"])])
    H = P * span / (4 * h)
    assert res.reactions["A"][0].m_as("N") == pytest.approx([H, 0, P / 2], rel=1e-9, abs=1e-6)
    assert res.reactions["B"][0].m_as("N") == pytest.approx([-H, 0, P / 2], rel=1e-9, abs=1e-6)
    assert res.diagram("left").My.m_as("N*m")[-1] == pytest.approx(0, abs=1e-6)
    assert res.ranges("right")["My"].max.m_as("N*m") == pytest.approx(0, abs=1e-6)
