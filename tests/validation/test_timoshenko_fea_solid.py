"""Solid P2-tetrahedron models against closed-form elasticity solutions.

Sources:
- [TG] Timoshenko & Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill 1970: simple tension (Hooke's
  law, sec. 3-4) and the prismatical bar stretched by its own weight (art. 97): sigma_x = rho g (L - x),
  end displacement rho g L^2 / (2E).
- [TG-M] Timoshenko & Gere, Mechanics of Materials, 4th ed., 1997: cantilever tip deflection
  P L^3 / (3 E I) (Table G-1, case 4) plus the shear deflection P L / (kappa G A), kappa = 5/6 for a
  rectangle (sec. 10.8? "shear deformations", eq. 10-33 with f_s = 6/5).
P2 tetrahedra represent a linear stress field exactly, so the first two cases must agree to solver
precision; the cantilever (cubic displacement, clamped end) to about 1 %.
"""

import numpy as np
import pytest

from mechverify.fea import mesh, solid
from mechverify.fea.loads import Fixed, Force, Gravity, Restraint
from mechverify.fea.regions import Plane
from mechverify.materials import get

STEEL = get("Structural Steel")  # E = 200 GPa, nu = 0.30, rho = 7850 kg/m^3


def rollers_at_x0():
    """Symmetry supports at x = 0 that leave lateral contraction free: x held on the face,
    y held on the y = 0 face, z held on the z = 0 face."""
    return (Restraint(Plane(x="0 mm"), x=True), Restraint(Plane(y="0 mm"), y=True), Restraint(Plane(z="0 mm"), z=True))


def test_bar_in_tension_is_exact():
    """[TG] sec. 3-4: sigma = F/A, elongation F L / (E A), lateral strain -nu sigma / E."""
    m = mesh.box(("100 mm", "10 mm", "20 mm"), (4, 1, 2))
    F = 20e3
    model = solid.SolidModel(m, STEEL, supports=rollers_at_x0(),
                             loads=(Force(Plane(x="100 mm"), (f"{F} N", "0 N", "0 N")),))
    res = model.solve()
    A = 10e-3 * 20e-3
    sigma = F / A
    assert res.stress.m_as("Pa")[:, 0, 0] == pytest.approx(np.full(m.n_nodes, sigma), rel=1e-7)
    assert res.max_displacement.value.m_as("m") == pytest.approx(
        np.hypot(np.hypot(F * 0.1 / (200e9 * A), 0.3 * sigma / 200e9 * 10e-3), 0.3 * sigma / 200e9 * 20e-3), rel=1e-7)
    assert res.reactions.m_as("N") == pytest.approx([-F, 0, 0], abs=1e-6 * F)
    assert res.min_safety_factor().value.m == pytest.approx(250e6 / sigma, rel=1e-7)


def test_bar_hanging_under_its_own_weight():
    """[TG] art. 97: sigma_x(x) = rho g (L - x) for a bar hung from x = 0 with gravity along +x;
    free-end displacement rho g L^2 / (2E). Reaction = weight. With nu = 0 the exact cross-sections
    stay plane, so the roller support at x = 0 is exact and so is the P2 solution; otherwise
    the exact solution warps the support face (terms nu rho g (y^2 + z^2) / 2E)."""
    L = 0.5
    m = mesh.box((f"{L} m", "20 mm", "20 mm"), (5, 1, 1))
    model = solid.SolidModel(m, STEEL.with_(nu=0.0), supports=rollers_at_x0(), loads=(Gravity(("9.80665 m/s**2", "0 m/s**2", "0 m/s**2")),))
    res = model.solve()
    rg = 7850 * 9.80665
    x = res.points[:, 0]
    assert res.stress.m_as("Pa")[:, 0, 0] == pytest.approx(rg * (L - x), abs=1e-6 * rg * L)
    tip = np.isclose(x, L)
    assert res.u[tip, 0] == pytest.approx(rg * L**2 / (2 * 200e9), rel=1e-6)
    weight = rg * L * 4e-4
    assert res.reactions.m_as("N")[0] == pytest.approx(-weight, rel=1e-9)


def test_cantilever_tip_deflection_timoshenko_beam():
    """[TG-M]: 200 x 20 x 20 mm steel cantilever, 1 kN tip load: P L^3/(3EI) + P L/(kappa G A)
    = 1.000 + 0.0078 mm. Clamped-end warping restraint makes the solid slightly stiffer; 1.5 %."""
    m = mesh.box(("200 mm", "20 mm", "20 mm"), (20, 2, 2))
    model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                             loads=(Force(Plane(x="200 mm"), ("0 N", "0 N", "-1 kN")),))
    res = model.solve()
    E, G, L, b, P = 200e9, 200e9 / 2.6, 0.2, 0.02, 1000.0
    I, A = b**4 / 12, b * b
    expect = P * L**3 / (3 * E * I) + P * L / (5 / 6 * G * A)
    tip = np.isclose(res.points[:, 0], L)
    assert -res.u[tip, 2].mean() == pytest.approx(expect, rel=0.015)
    # bending stress at mid-span, top fibre: M c / I = P (L/2) (b/2) / I = 75 MPa
    top = np.isclose(res.points[:, 0], L / 2) & np.isclose(res.points[:, 2], b)
    assert res.stress.m_as("MPa")[top, 0, 0].mean() == pytest.approx(75.0, rel=0.015)
    assert res.reactions.m_as("N") == pytest.approx([0, 0, P], abs=1e-6 * P)
