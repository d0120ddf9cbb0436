"""Frames: errors for unsupported models and mechanisms, inputs in physical terms, springs, hinges,
self-weight equilibrium, principal axes, invariance under a rigid rotation of the model, the figure."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechverify.components import sections
from mechverify.errors import InputError, ModelError, UnitError, UnknownNameError
from mechverify.fea.frame import DistributedLoad, Frame, FramePointLoad, FrameSelfWeight, FrameSupport, Hinge, Member
from mechverify.materials.database import get

STEEL = get("Structural Steel")
E, G = 200e9, 200e9 / 2.6
SEC = sections.rectangle("10 mm", "20 mm")
I = 0.010 * 0.020**3 / 12
NODES = {"A": ["0 mm", "0 mm", "0 mm"], "B": ["400 mm", "0 mm", "0 mm"]}


def cantilever(supports=None, **kw):
    return Frame(NODES, [Member("A", "B", SEC, STEEL, "beam")], supports if supports is not None else
                 [FrameSupport("A")], **kw)


DOWN = FramePointLoad("B", force=["0 N", "0 N", "-100 N"])


def test_unsupported_frames_name_the_free_motion():
    with pytest.raises(ModelError, match="no supports"):
        cantilever([]).solve([DOWN])
    with pytest.raises(ModelError, match="rotation about an axis parallel to x through"):
        cantilever([FrameSupport("A", "pinned"), FrameSupport("B", "pinned")]).solve([DOWN])
    with pytest.raises(ModelError, match="translation along x"):
        cantilever([FrameSupport("A", "roller"), FrameSupport("B", "roller")]).solve([DOWN])


def test_mechanism_names_node_and_direction():
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": ["0 m", "0 m", "1 m"], "C": ["1 m", "0 m", "1 m"], "D": ["1 m", "0 m", "0 m"]}
    ms = [Member("A", "B", SEC, STEEL, "AB"), Member("B", "C", SEC, STEEL, "BC"), Member("C", "D", SEC, STEEL, "CD")]
    fr = Frame(nodes, ms, [FrameSupport("A"), FrameSupport("D")], [Hinge("B", "x"), Hinge("C", "x")])
    with pytest.raises(ModelError, match=r"mechanism.*rotation about x at node [BC]"):
        fr.solve([FramePointLoad("B", force=["10 N", "0 N", "0 N"])])


def test_inputs_in_physical_terms_and_clear_errors():
    with pytest.raises(UnitError, match="nodes.A"):
        Frame({"A": [0, 0, 0], "B": ["1 m", "0 m", "0 m"]}, [Member("A", "B", SEC, STEEL)], [FrameSupport("A")])
    with pytest.raises(UnknownNameError, match="did you mean 'B'"):
        Frame(NODES, [Member("A", "b2", SEC, STEEL)], [FrameSupport("A")])
    with pytest.raises(InputError, match="not on any member"):
        cantilever([FrameSupport(["0 mm", "5 mm", "0 mm"])])
    with pytest.raises(InputError, match="zero length"):
        Frame(NODES, [Member("A", "A", SEC, STEEL)], [FrameSupport("A")])
    with pytest.raises(InputError, match="did you mean 'pinned'"):
        FrameSupport("A", "pined")
    with pytest.raises(InputError, match="needs springs"):
        FrameSupport("A", "spring")
    with pytest.raises(UnitError, match="springs.z"):
        FrameSupport("A", "spring", springs={"z": "5 N"})
    with pytest.raises(UnitError, match="force"):
        cantilever().solve([FramePointLoad("B", force=["1 N*m", "0 N", "0 N"])])
    with pytest.raises(UnknownNameError, match="member"):
        cantilever().solve([DistributedLoad("bean", ["0 N/m", "0 N/m", "1 N/m"])])
    with pytest.raises(InputError, match="Section"):
        Member("A", "B", "rect", STEEL)
    with pytest.raises(InputError, match="theory"):
        cantilever(theory="bernoulli")


def test_spring_support_closed_form():
    """A cantilever whose tip rests on a spring k: delta = P / (k + 3 E I / L^3) (springs in parallel)."""
    k, P, L = 2e5, 100.0, 0.4
    fr = cantilever([FrameSupport("A"), FrameSupport("B", "spring", springs={"z": f"{k} N/m"})], theory="euler")
    res = fr.solve([DOWN])
    delta = P / (k + 3 * E * I / L**3)
    assert -res.displacement("B").m_as("m")[2] == pytest.approx(delta, rel=1e-9)
    assert res.reactions["B"][0].m_as("N")[2] == pytest.approx(k * delta, rel=1e-9)
    assert res.reactions["A"][0].m_as("N")[2] + res.reactions["B"][0].m_as("N")[2] == pytest.approx(P)


def test_hinge_releases_the_moment():
    """Two cantilevers joined by a hinge about y at mid-length (a load at the hinge): the moment there is zero and
    each arm takes the load in proportion to its stiffness; with equal arms, P/2 each: delta = (P/2) a^3 / (3EI)."""
    P, a = 100.0, 0.2
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "H": ["200 mm", "0 mm", "0 mm"], "B": ["400 mm", "0 mm", "0 mm"]}
    fr = Frame(nodes, [Member("A", "H", SEC, STEEL, "left"), Member("H", "B", SEC, STEEL, "right")],
               [FrameSupport("A"), FrameSupport("B")], [Hinge("H", "y")], theory="euler")
    res = fr.solve([FramePointLoad("H", force=["0 N", "0 N", f"-{P} N"])])
    assert -res.displacement("H").m_as("m")[2] == pytest.approx(P / 2 * a**3 / (3 * E * I), rel=1e-9)
    assert res.diagram("left").My.m_as("N*m")[-1] == pytest.approx(0, abs=1e-9)
    assert res.diagram("right").My.m_as("N*m")[0] == pytest.approx(0, abs=1e-9)


def test_self_weight_balances_and_matches_the_uniform_load():
    """Self-weight rho A g per length: the reactions carry the whole weight; the tip deflection equals that of a
    uniform load w = rho A g, w L^4 / (8 E I) + shear (Roark Table 8.1 case 2a)."""
    res = cantilever(theory="euler").solve([FrameSelfWeight()])
    rho = STEEL.density.m_as("kg/m**3")
    w = rho * 0.010 * 0.020 * 9.80665
    assert res.reactions["A"][0].m_as("N")[2] == pytest.approx(w * 0.4, rel=1e-12)
    assert -res.displacement("B").m_as("m")[2] == pytest.approx(w * 0.4**4 / (8 * E * I), rel=1e-9)


def test_principal_axes_of_an_angle():
    """An equal angle has Iy = Iz and a product of inertia: it bends about its principal axes, so a load along z
    also deflects it along y (unsymmetrical bending); the stresses agree with sigma = M v / I about the axes."""
    ang = sections.l_section("30 mm", "30 mm", "4 mm")
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": ["300 mm", "0 mm", "0 mm"]}
    res = Frame(nodes, [Member("A", "B", ang, STEEL, "angle")], [FrameSupport("A")], theory="euler").solve(
        [FramePointLoad("B", force=["0 N", "0 N", "-50 N"])])
    u = res.displacement("B").m_as("m")
    s = ang.si()
    # deflection from the principal-axis decomposition: the load splits along the two axes at 45 degrees
    Iu, Iv = s["I1"], s["I2"]
    L, P = 0.3, 50.0
    dz = P * L**3 / 3 / E * (0.5 / Iu + 0.5 / Iv)
    dy = P * L**3 / 3 / E * 0.5 * abs(1 / Iu - 1 / Iv)
    assert abs(u[2]) == pytest.approx(dz, rel=1e-6)
    assert abs(u[1]) == pytest.approx(dy, rel=1e-6)


@settings(max_examples=15, deadline=None)
@given(st.floats(0, 2 * math.pi), st.floats(-1, 1), st.floats(0, 2 * math.pi))
def test_invariant_under_rotation_of_the_whole_model(a, b, c):
    """Rotating the model and its loads rigidly rotates the displacements and keeps stresses and moments."""
    axis = np.array([math.cos(a) * math.sqrt(1 - b * b), math.sin(a) * math.sqrt(1 - b * b), b])
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    R = np.eye(3) + math.sin(c) * K + (1 - math.cos(c)) * K @ K
    pts = {"A": np.zeros(3), "B": np.array([0.3, 0, 0]), "C": np.array([0.3, 0.2, 0])}
    out = []
    for rot in (np.eye(3), R):
        nodes = {k: [f"{x if abs(x) > 1e-12 else 0.0} m" for x in rot @ v] for k, v in pts.items()}
        fr = Frame(nodes, [Member("A", "B", SEC, STEEL, "m1", orientation=tuple(rot @ [0, 0, 1])),
                           Member("B", "C", SEC, STEEL, "m2", orientation=tuple(rot @ [0, 0, 1]))], [FrameSupport("A")])
        res = fr.solve([FramePointLoad("C", force=[f"{x if abs(x) > 1e-9 else 0.0} N" for x in rot @ [0, 0, -40.0]])])
        out.append((np.linalg.norm(res.displacement("C").m_as("m")), res.max_von_mises.value.m_as("MPa")))
    assert out[1][0] == pytest.approx(out[0][0], rel=1e-7)
    assert out[1][1] == pytest.approx(out[0][1], rel=1e-7)


def test_figure(tmp_path):
    res = cantilever().solve([DOWN, FrameSelfWeight()])
    p = tmp_path / "frame.png"
    res.figure(p)
    assert p.stat().st_size > 10_000
    fig = res.figure()
    assert "max" in fig.axes[0].get_title()
