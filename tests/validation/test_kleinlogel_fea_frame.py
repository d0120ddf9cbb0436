"""Single-bay portal frames of mechverify.fea.frame against Kleinlogel's rigid-frame formulas.

Source: A. Kleinlogel, *Rigid Frame Formulas* (translation of *Rahmenformeln*, 12th German ed.), Ungar,
New York 1958: the two-hinged rectangular frame (Frame 1) under a uniform load on the girder,
H = w L^2 / (4 h N) with N = 2k + 3, corner moments M_B = M_C = -H h; the fixed-base rectangular frame
(Frame 2) under a horizontal load P at the girder, M_A = P h (3k + 1) / (2 (6k + 1)),
M_B = P h 3k / (2 (6k + 1)); both with k = (I_2 / I_1)(h / L) (girder I_2, columns I_1). The formulas
neglect axial and shear deformation: the model uses Euler elements and stocky members, so the axial
shortening changes the answers by less than 0.1 %.
"""

import pytest

from mechverify.components import sections
from mechverify.fea.frame import DistributedLoad, Frame, FramePointLoad, FrameSupport, Member
from mechverify.materials.database import get

STEEL = get("Structural Steel")
L, h = 3.0, 2.0  # girder span and column height [m]


def portal(supports):
    col = sections.rectangle("30 mm", "60 mm")  # I_1 = 30*60^3/12 mm^4 about the in-plane axis
    gir = sections.rectangle("30 mm", "75 mm")  # I_2 = 30*75^3/12
    nodes = {"A": ["0 m", "0 m", "0 m"], "B": ["0 m", "0 m", f"{h} m"], "C": [f"{L} m", "0 m", f"{h} m"],
             "D": [f"{L} m", "0 m", "0 m"]}
    members = [Member("A", "B", col, STEEL, "left"), Member("B", "C", gir, STEEL, "girder"),
               Member("D", "C", col, STEEL, "right")]
    return Frame(nodes, members, [FrameSupport(n, **supports) for n in ("A", "D")], theory="euler")


def k_ratio():
    I1, I2 = 0.030 * 0.060**3 / 12, 0.030 * 0.075**3 / 12
    return I2 / I1 * h / L


def test_two_hinged_portal_uniform_girder_load():
    w = 10_000.0
    # plane-frame pins: free to turn about y (the in-plane rotation) only; 3D pins would let the frame
    # swing about the line A-D
    fr = portal({"kind": "custom", "hold": ("x", "y", "z", "rx", "rz")})
    res = fr.solve([DistributedLoad("girder", ["0 N/m", "0 N/m", f"-{w} N/m"])])
    N = 2 * k_ratio() + 3
    H = w * L**2 / (4 * h * N)
    fa = res.reactions["A"][0].m_as("N")
    assert abs(fa[0]) == pytest.approx(H, rel=1e-3)
    assert fa[2] == pytest.approx(w * L / 2, rel=1e-9)
    g = res.diagram("girder")
    My = g.My.m_as("N*m")
    assert abs(My[0]) == pytest.approx(H * h, rel=1e-3)  # corner moment
    assert abs(My[len(My) // 2]) == pytest.approx(w * L**2 / 8 - H * h, rel=1e-3)  # midspan
    assert res.max_bending_moment.value.m_as("N*m") == pytest.approx(w * L**2 / 8 - H * h, rel=1e-3)


def test_fixed_base_portal_horizontal_load():
    P = 5_000.0
    res = portal({"kind": "fixed"}).solve([FramePointLoad("B", force=[f"{P} N", "0 N", "0 N"])])
    k = k_ratio()
    MA = P * h * (3 * k + 1) / (2 * (6 * k + 1))
    MB = P * h * 3 * k / (2 * (6 * k + 1))
    left = res.diagram("left").My.m_as("N*m")
    assert abs(left[0]) == pytest.approx(MA, rel=1e-3)
    assert abs(left[-1]) == pytest.approx(MB, rel=1e-3)
    right = res.diagram("right").My.m_as("N*m")
    assert abs(right[0]) == pytest.approx(MA, rel=1e-3)
    assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(MA, rel=1e-3)
    # the base shears sum to P
    assert sum(f.m_as("N")[0] for f, _ in res.reactions.values()) == pytest.approx(-P, rel=1e-9)
