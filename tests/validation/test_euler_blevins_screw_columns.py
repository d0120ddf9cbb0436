"""Screw buckling and whirling against closed-form solutions.

* Euler column, P_cr = C pi^2 E I / l^2 with I = pi d3^4 / 64 (Shigley's Mechanical Engineering
  Design, 10th ed., Eq. 4-42 and Table 4-2: C = 1 pinned-pinned, 1/4 fixed-free).
* Whirling = first bending mode of a uniform Euler-Bernoulli shaft,
  w = lambda^2 / L^2 sqrt(E I / (rho A)) with lambda = pi exactly for pinned-pinned, and the
  eigenvalues 1.87510, 3.92660, 4.73004 of Blevins, Formulas for Natural Frequency and Mode Shape
  (1979), Table 8-1, which THK's ball-screw catalogue rounds to 1.875, 3.927, 4.730.
"""

import math

import pytest

from mechverify.components.power_screw import LeadScrew, critical_speed, whirl_factor
from mechverify.materials.material import Material

STEEL = Material("test steel", "steel", E="200 GPa", nu=0.3, density="7800 kg/m^3", yield_strength="300 MPa",
                 ultimate_strength="500 MPa")
E, RHO = 200e9, 7800.0


@pytest.mark.parametrize(("end", "C"), [("pinned-pinned", 1.0), ("fixed-free", 0.25)])
def test_euler_closed_form(end, C):
    s = LeadScrew("Tr10x2", "800 mm", STEEL, end)
    d3, L = 7.5e-3, 0.8
    I = math.pi * d3**4 / 64
    b = s.buckling()
    assert b.regime == "euler"
    assert b.critical_load.m_as("N") == pytest.approx(C * math.pi**2 * E * I / L**2, rel=1e-12)


def test_pinned_pinned_whirl_is_pi_squared():
    d3, L = 7.5e-3, 0.45
    w = critical_speed("200 GPa", "7800 kg/m^3", "7.5 mm", "450 mm", "pinned-pinned").m_as("rad/s")
    assert w == pytest.approx(math.pi**2 / L**2 * math.sqrt(E * (math.pi * d3**4 / 64) / (RHO * math.pi * d3**2 / 4)),
                              rel=1e-5)


@pytest.mark.parametrize(("end", "lam"), [("fixed-free", 1.87510), ("pinned-pinned", 3.14159),
                                          ("fixed-pinned", 3.92660), ("fixed-fixed", 4.73004),
                                          ("fixed-supported", 3.92660), ("supported-supported", 3.14159)])
def test_blevins_eigenvalues(end, lam):
    assert whirl_factor(end) == pytest.approx(lam, abs=1e-5)


def test_whirl_scales_with_lambda_squared():
    a = critical_speed("200 GPa", "7800 kg/m^3", "10 mm", "1 m", "fixed-fixed")
    b = critical_speed("200 GPa", "7800 kg/m^3", "10 mm", "1 m", "pinned-pinned")
    assert (a / b).m_as("") == pytest.approx((4.73004 / math.pi) ** 2, rel=1e-5)
