"""Beam elements of mechverify.fea.frame against Roark's closed forms.

Source: W. C. Young, R. G. Budynas, A. M. Sadegh, *Roark's Formulas for Stress and Strain*, 8th ed.,
McGraw-Hill 2012: Table 8.1 (bending of straight beams: case 1a cantilever with an end load, case 1e
simply supported with a central load, case 2e simply supported with a uniform load, and its elastic
curve), Sec. 8.10 (shear deflection with the form factor F = 1.2 of a rectangle), Sec. 8.1
(unsymmetrical bending: sigma = My z/Iy + Mz y/Iz at the corner of a rectangle).
"""

import numpy as np
import pytest

from mechverify.components import sections
from mechverify.fea.frame import DistributedLoad, Frame, FramePointLoad, FrameSupport, Member
from mechverify.materials.database import get

STEEL = get("Structural Steel")  # E = 200 GPa, nu = 0.3 (ANSYS default)
E, G = 200e9, 200e9 / 2.6
B, H = 0.010, 0.020  # rectangle 10 mm wide (y) x 20 mm high (z)
A, I = B * H, B * H**3 / 12
F_SHEAR = 1.2  # Roark Sec. 8.10, rectangle


def beam(length_mm, supports, theory, divisions=1):
    sec = sections.rectangle(f"{B * 1e3} mm", f"{H * 1e3} mm")
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": [f"{length_mm} mm", "0 mm", "0 mm"]}
    return Frame(nodes, [Member("A", "B", sec, STEEL, "beam", divisions=divisions)], supports, theory=theory)


def simply_supported(length_mm, theory, divisions=1):
    # pinned at A; at B a roller in z that also holds y and the twist about the axis (a 3D simple support)
    return beam(length_mm, [FrameSupport("A", "pinned"), FrameSupport("B", "custom", hold=("y", "z", "rx"))], theory, divisions)


@pytest.mark.parametrize("theory", ["euler", "timoshenko"])
def test_cantilever_end_load_table_8_1_case_1a(theory):
    """Tip deflection W l^3 / (3 E I) (+ F W l / (A G), Sec. 8.10); root moment W l; root stress W l c / I."""
    W, L = 500.0, 0.150  # short beam: the shear term is 0.8 % of the bending term
    res = beam(150, [FrameSupport("A", "fixed")], theory).solve([FramePointLoad("B", force=["0 N", "0 N", f"-{W} N"])])
    y = W * L**3 / (3 * E * I) + (F_SHEAR * W * L / (A * G) if theory == "timoshenko" else 0.0)
    assert res.displacement("B").m_as("m")[2] == pytest.approx(-y, rel=1e-9)
    assert res.max_displacement.value.m_as("m") == pytest.approx(y, rel=1e-9)
    assert res.max_bending_moment.value.m_as("N*m") == pytest.approx(W * L, rel=1e-9)
    sigma = W * L * (H / 2) / I
    d = res.diagram("beam")
    assert np.max(np.abs(d.normal_stress.m_as("Pa"))) == pytest.approx(sigma, rel=1e-9)
    force, moment = res.reactions["A"]
    assert force.m_as("N") == pytest.approx([0, 0, W], abs=1e-9)
    assert moment.m_as("N*m") == pytest.approx([0, -W * L, 0], abs=1e-9)


@pytest.mark.parametrize("theory", ["euler", "timoshenko"])
def test_simply_supported_central_load_table_8_1_case_1e(theory):
    """Midspan deflection W l^3 / (48 E I) (+ F W l / (4 A G)); the load point splits the member."""
    W, L = 1000.0, 0.400
    res = simply_supported(400, theory).solve([FramePointLoad(["200 mm", "0 mm", "0 mm"], force=["0 N", "0 N", f"-{W} N"])])
    y = W * L**3 / (48 * E * I) + (F_SHEAR * W * L / (4 * A * G) if theory == "timoshenko" else 0.0)
    assert res.max_displacement.value.m_as("m") == pytest.approx(y, rel=1e-9)
    assert res.max_displacement.position.m_as("mm") == pytest.approx(200)
    assert res.max_bending_moment.value.m_as("N*m") == pytest.approx(W * L / 4, rel=1e-9)


@pytest.mark.parametrize("theory", ["euler", "timoshenko"])
def test_simply_supported_uniform_load_table_8_1_case_2e(theory):
    """Midspan 5 w l^4 / (384 E I) (+ F w l^2 / (8 A G)), M_max = w l^2 / 8, end slope w l^3 / (24 E I)."""
    w, L = 2000.0, 0.500
    res = simply_supported(500, theory).solve([DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{w} N/m"])])
    y = 5 * w * L**4 / (384 * E * I) + (F_SHEAR * w * L**2 / (8 * A * G) if theory == "timoshenko" else 0.0)
    assert res.max_displacement.value.m_as("m") == pytest.approx(y, rel=1e-9)
    assert res.max_bending_moment.value.m_as("N*m") == pytest.approx(w * L**2 / 8, rel=1e-9)
    # Table 8.1 case 2e end slope (the Timoshenko section rotation is the bending part only)
    assert abs(res.rotation("A").m_as("rad")[1]) == pytest.approx(w * L**3 / (24 * E * I), rel=1e-9)
    assert sum(f.m_as("N")[2] for f, _ in res.reactions.values()) == pytest.approx(w * L, rel=1e-12)


@pytest.mark.parametrize("theory", ["euler", "timoshenko"])
@pytest.mark.parametrize("divisions", [1, 2, 3, 5, 8])
def test_mesh_convergence_exact_elastic_curve(theory, divisions):
    """Mesh study, uniform load on a simple span (Table 8.1 case 2e elastic curve
    y = w x (l^3 - 2 l x^2 + x^3) / (24 E I), plus the shear part F w x (l - x) / (2 A G)).

    The element stiffness is the exact one of a prismatic member and the uniform load enters through
    its fixed-end forces, so the nodal deflections are exact at every mesh (convergence order
    infinite): the error at the nodes and along the members stays at rounding level for 1..8 elements.
    """
    w, L = 2000.0, 0.500
    res = simply_supported(500, theory, divisions).solve([DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{w} N/m"])])
    d = res.diagram("beam", points_per_element=9)
    x = d.s.m_as("m")
    exact = w * x * (L**3 - 2 * L * x**2 + x**3) / (24 * E * I)
    if theory == "timoshenko":
        exact += F_SHEAR * w * x * (L - x) / (2 * A * G)
    num = -d.displacement.m_as("m")[:, 2]
    assert np.max(np.abs(num - exact)) <= 1e-9 * np.max(exact)
    nodes = [k / divisions * L for k in range(divisions + 1)]
    for xn in nodes:
        ye = w * xn * (L**3 - 2 * L * xn**2 + xn**3) / (24 * E * I)
        ye += F_SHEAR * w * xn * (L - xn) / (2 * A * G) if theory == "timoshenko" else 0.0
        node = [f"{xn * 1e3} mm", "0 mm", "0 mm"]
        assert -res.displacement(node).m_as("m")[2] == pytest.approx(ye, rel=1e-9, abs=1e-15)


def test_unsymmetrical_bending_corner_stress():
    """Cantilever with an end load along y and z: the corner stress is M_z c_y / I_z + M_y c_z / I_y (Roark
    Sec. 8.1, bending about both principal axes), and the deflections are independent in y and z."""
    Py, Pz, L = 200.0, 300.0, 0.200
    res = beam(200, [FrameSupport("A", "fixed")], "euler").solve([FramePointLoad("B", force=["0 N", f"{Py} N", f"{Pz} N"])])
    Iz = H * B**3 / 12
    sigma = Pz * L * (H / 2) / I + Py * L * (B / 2) / Iz
    d = res.diagram("beam")
    assert np.max(d.normal_stress.m_as("Pa")) == pytest.approx(sigma, rel=1e-9)
    # von Mises adds the nominal transverse shear V/A_s (A_s = 5/6 A) as if it acted at that corner (conservative)
    tau = np.hypot(Py, Pz) / (5 / 6 * A)
    assert res.max_von_mises.value.m_as("Pa") == pytest.approx(np.sqrt(sigma**2 + 3 * tau**2), rel=1e-9)
    assert abs(res.max_von_mises.fibre.m_as("mm")[0]) == pytest.approx(5) and abs(
        res.max_von_mises.fibre.m_as("mm")[1]) == pytest.approx(10)
    u = res.displacement("B").m_as("m")
    assert u[1] == pytest.approx(Py * L**3 / (3 * E * Iz), rel=1e-9)
    assert u[2] == pytest.approx(Pz * L**3 / (3 * E * I), rel=1e-9)
