"""Torsion, shear deflection and a grillage of mechverify.fea.frame against Timoshenko's closed forms.

Sources:
1. J. M. Gere, S. P. Timoshenko, *Mechanics of Materials*, 4th ed., PWS 1997: Eq. 3-15 (angle of twist
   phi = T L / (G I_P)), Eq. 3-11 (tau_max = T r / I_P); Sec. 9.8-9.9 (Castigliano's theorem with the
   strain energies of bending M^2/(2EI) and torsion T^2/(2GJ)).
2. S. P. Timoshenko, J. N. Goodier, *Theory of Elasticity*, 3rd ed., McGraw-Hill 1970, Sec. 109, table of
   the rectangle coefficients: b/c = 2 gives k1 = 0.229 (J = k1 b c^3), k2 = 0.246 (tau_max = T / (k2 b c^2)).
3. S. P. Timoshenko, J. M. Gere, *Mechanics of Materials*, Van Nostrand 1972, Sec. 7.8: shear deflection of a
   cantilever, delta_s = alpha_s P L / (G A) (alpha_s = 1.2 for a rectangle).
"""

import math

import numpy as np
import pytest

from mechverify.components import sections
from mechverify.fea.frame import Frame, FramePointLoad, FrameSupport, Member
from mechverify.materials.database import get

STEEL = get("Structural Steel")
E, G = 200e9, 200e9 / 2.6


def bar(section, length_mm, load):
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": [f"{length_mm} mm", "0 mm", "0 mm"]}
    fr = Frame(nodes, [Member("A", "B", section, STEEL, "bar")], [FrameSupport("A", "fixed")])
    return fr.solve([load])


def test_twist_of_a_round_shaft():
    """phi = T L / (G I_P) (ref. 1 Eq. 3-15), tau_max = 16 T / (pi d^3) (Eq. 3-11); von Mises = sqrt(3) tau."""
    T, L, d = 100.0, 0.5, 0.020
    res = bar(sections.circle("20 mm"), 500, FramePointLoad("B", moment=[f"{T} N*m", "0 N*m", "0 N*m"]))
    Ip = math.pi * d**4 / 32
    assert res.rotation("B").m_as("rad")[0] == pytest.approx(T * L / (G * Ip), rel=1e-9)
    tau = 16 * T / (math.pi * d**3)
    dg = res.diagram("bar")
    assert np.max(dg.shear_stress.m_as("Pa")) == pytest.approx(tau, rel=1e-9)
    assert res.max_von_mises.value.m_as("Pa") == pytest.approx(math.sqrt(3) * tau, rel=1e-9)
    assert dg.T.m_as("N*m") == pytest.approx(np.full(dg.T.shape, T))
    assert res.reactions["A"][1].m_as("N*m") == pytest.approx([-T, 0, 0], abs=1e-9)


def test_twist_of_a_rectangular_bar():
    """Rectangle 20 x 10 mm (b/c = 2): J = 0.229 b c^3, tau_max = T / (0.246 b c^2) (ref. 2, Sec. 109 table;
    three significant figures, hence the 0.3 % tolerance)."""
    T, L, b, c = 20.0, 0.3, 0.020, 0.010
    res = bar(sections.rectangle("10 mm", "20 mm"), 300, FramePointLoad("B", moment=[f"{T} N*m", "0 N*m", "0 N*m"]))
    assert res.rotation("B").m_as("rad")[0] == pytest.approx(T * L / (G * 0.229 * b * c**3), rel=3e-3)
    assert np.max(res.diagram("bar").shear_stress.m_as("Pa")) == pytest.approx(T / (0.246 * b * c**2), rel=3e-3)


def test_shear_deflection_of_a_deep_cantilever():
    """A deep cantilever (L/h = 2.5): delta = P L^3 / (3 E I) + 1.2 P L / (G A) (ref. 3, Sec. 7.8); the shear
    part is 11 % of the total here, so the Timoshenko element must carry it."""
    P, L, b, h = 10_000.0, 0.050, 0.010, 0.020
    res = bar(sections.rectangle("10 mm", "20 mm"), 50, FramePointLoad("B", force=["0 N", "0 N", f"-{P} N"]))
    I, A = b * h**3 / 12, b * h
    bend, shear = P * L**3 / (3 * E * I), 1.2 * P * L / (G * A)
    assert shear / (bend + shear) > 0.1
    assert -res.displacement("B").m_as("m")[2] == pytest.approx(bend + shear, rel=1e-9)


def test_right_angle_grillage_castigliano():
    """An L-shaped horizontal rod: arm 1 (length a along x) clamped at A, arm 2 (length b along y) to the tip C,
    a vertical load P at C. Castigliano (ref. 1 Sec. 9.9): U = int M^2/(2EI) + int T^2/(2GJ) with arm 1 in
    bending P (a - x) and torsion P b, arm 2 in bending P (b - y):
    delta_C = P a^3 / (3 E I) + P b^3 / (3 E I) + P b^2 a / (G J)  (shear deformation neglected: Euler)."""
    P, a, b, d = 50.0, 0.300, 0.200, 0.012
    sec = sections.circle("12 mm")
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": ["300 mm", "0 mm", "0 mm"], "C": ["300 mm", "200 mm", "0 mm"]}
    fr = Frame(nodes, [Member("A", "B", sec, STEEL, "arm1"), Member("B", "C", sec, STEEL, "arm2")],
               [FrameSupport("A", "fixed")], theory="euler")
    res = fr.solve([FramePointLoad("C", force=["0 N", "0 N", f"-{P} N"])])
    I, J = math.pi * d**4 / 64, math.pi * d**4 / 32
    delta = P * a**3 / (3 * E * I) + P * b**3 / (3 * E * I) + P * b**2 * a / (G * J)
    assert -res.displacement("C").m_as("m")[2] == pytest.approx(delta, rel=1e-9)
    assert res.max_displacement.value.m_as("m") == pytest.approx(delta, rel=1e-9)
    # arm 1 carries the torque P b and the root moment P a: von Mises at the root sqrt(sigma^2 + 3 tau^2)
    sigma, tau = 32 * P * a / (math.pi * d**3), 16 * P * b / (math.pi * d**3)
    vm = res.max_von_mises
    assert vm.member == "arm1" and vm.position.m_as("mm") == pytest.approx(0)
    tau_v = P / (6 / 7 * math.pi * d**2 / 4)  # plus the nominal shear V / A_s (A_s = 6/7 A, Cowper at nu = 0)
    assert vm.value.m_as("Pa") == pytest.approx(math.sqrt(sigma**2 + 3 * (tau + tau_v) ** 2), rel=1e-3)
    force, moment = res.reactions["A"]
    assert force.m_as("N") == pytest.approx([0, 0, P], abs=1e-9)
    # the reaction moment balances r_C x F = (a, b, 0) x (0, 0, -P) = (-P b, P a, 0)
    assert moment.m_as("N*m") == pytest.approx([P * b, -P * a, 0], abs=1e-9)
