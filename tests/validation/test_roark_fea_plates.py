"""Plate-bending FEA (Morley triangles) against Roark's and Timoshenko's plate coefficients.

Sources:
- [Roark] Young & Budynas, Roark's Formulas for Stress and Strain, 7th ed., 2002.
  Table 11.4 case 1a (rectangle, all edges simply supported, uniform load), a/b = 1, nu = 0.3:
  y_max = -alpha q b^4 / (E t^3), alpha = 0.0444; sigma_max = beta q b^2 / t^2, beta = 0.2874 (centre).
  Table 11.4 case 8a (all edges fixed, uniform load), a/b = 1: alpha = 0.0138; beta = 0.3078 (centre of
  each edge).
  Table 11.2 case 10a (solid circular plate, simply supported edge, uniform load):
  y_max = -q a^4 (5 + nu) / (64 D (1 + nu)), sigma_max = 3 (3 + nu) q a^2 / (8 t^2) at the centre.
  Table 11.2 case 10b (fixed edge): y_max = -q a^4 / (64 D), sigma_max = 3 q a^2 / (4 t^2) at the edge.
- [TWK] Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., 1959, Table 8: simply
  supported square plate under a central point load P: w_max = 0.01160 P a^2 / D.
The Morley element converges in deflection as h^2 (checked below on the simply supported square).
"""

import numpy as np
import pytest

from mechverify.components import plates as P
from mechverify.fea.plate import solve_plate

E, NU = 200e9, 0.30  # "Structural Steel": nu = 0.3 as Roark's tables assume
A, T, Q = 0.2, 0.004, 10e3  # 200 mm square, 4 mm thick, 10 kPa


def square(condition, n, loads=None):
    loads = loads or (P.PressureLoad(f"-{Q} Pa"),)
    plate = P.Plate.rectangle(f"{A} m", f"{A} m", f"{T} m", "Structural Steel")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all", condition),), loads=loads)
    return solve_plate(model, mesh_size=f"{A / n} m")


@pytest.mark.parametrize(("condition", "alpha", "beta"), [("simply_supported", 0.0444, 0.2874),
                                                          ("clamped", 0.0138, 0.3078)])
def test_square_plate_uniform_load_roark_table_11_4(condition, alpha, beta):
    res = square(condition, 64)
    w = -res.u[:, 2].min()
    assert w * E * T**3 / (Q * A**4) == pytest.approx(alpha, rel=0.01)
    sigma = np.abs(res.sigma[:, 0, 0]).max()
    assert sigma * T**2 / (Q * A**2) == pytest.approx(beta, rel=0.03)
    assert res.reactions.m_as("N")[2] == pytest.approx(Q * A * A, rel=1e-9)


def test_deflection_converges_at_second_order():
    """Errors against the series solution w = 0.00406 q a^4 / D ([TWK] Table 8, nu = 0.3) fall by about
    4x per halving of the element size."""
    D = E * T**3 / (12 * (1 - NU**2))
    exact = 0.00406235 * Q * A**4 / D
    err = [abs(-square("simply_supported", n).u[:, 2].min() - exact) for n in (8, 16, 32)]
    rates = np.log2(np.array(err[:-1]) / np.array(err[1:]))
    assert np.all(rates > 1.7), rates


def test_central_point_load_twk():
    """[TWK] Table 8: simply supported square, central load P: w_max = 0.01160 P a^2 / D."""
    res = square("simply_supported", 64, loads=(P.PlatePointLoad(("100 mm", "100 mm"), "-100 N"),))
    D = E * T**3 / (12 * (1 - NU**2))
    assert -res.u[:, 2].min() == pytest.approx(0.01160 * 100 * A**2 / D, rel=0.01)


@pytest.mark.parametrize("condition", ["simply_supported", "clamped"])
def test_circular_plate_roark_table_11_2(condition):
    pytest.importorskip("gmsh")
    a = 0.1
    ang = np.linspace(0, 2 * np.pi, 129)[:-1]
    outline = [(f"{a * np.cos(s)} m", f"{a * np.sin(s)} m") for s in ang]
    plate = P.Plate(outline, f"{T} m", "Structural Steel")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all", condition),), loads=(P.PressureLoad(f"-{Q} Pa"),))
    res = solve_plate(model, mesh_size="8 mm")
    D = E * T**3 / (12 * (1 - NU**2))
    if condition == "simply_supported":
        y, s = Q * a**4 * (5 + NU) / (64 * D * (1 + NU)), 3 * (3 + NU) * Q * a**2 / (8 * T**2)
    else:
        y, s = Q * a**4 / (64 * D), 3 * Q * a**2 / (4 * T**2)
    assert -res.u[:, 2].min() == pytest.approx(y, rel=0.015)
    r = np.hypot(res.points[:, 0], res.points[:, 1])
    radial = np.abs(res.sigma[:, 0, 0] * (res.points[:, 0] / np.maximum(r, 1e-12)) ** 2
                    + res.sigma[:, 1, 1] * (res.points[:, 1] / np.maximum(r, 1e-12)) ** 2
                    + 2 * res.sigma[:, 0, 1] * res.points[:, 0] * res.points[:, 1] / np.maximum(r, 1e-12) ** 2)
    assert max(radial.max(), np.abs(res.sigma[:, 0, 0]).max()) == pytest.approx(s, rel=0.05)
