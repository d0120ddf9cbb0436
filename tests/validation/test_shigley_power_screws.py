"""Power screws against Shigley's worked example.

Source: R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 9th ed., McGraw-Hill
2011, Example 8-1, pp. 419-420: a square-thread power screw, major diameter 32 mm, pitch 4 mm,
double threads, f = f_c = 0.08, d_c = 40 mm, F = 6.4 kN. The answers are quoted to the digits the
book prints; tolerances are half a unit of the last printed digit.
"""

import pytest

from mechverify.components.power_screw import (
    LeadScrew,
    collar_torque,
    flank_pressure,
    thread_bending_stress,
    thread_root_von_mises,
)
from mechverify.components.threads import square
from mechverify.units import Q

F = Q(6.4, "kN")
MU = 0.08
DC = Q(40, "mm")


@pytest.fixture(scope="module")
def screw():
    return LeadScrew(square("32 mm", "4 mm", starts=2), "500 mm", name="Shigley Example 8-1")


def test_a_geometry(screw):
    """(a) depth = width = p/2 = 2 mm; d_m = 30 mm; d_r = 28 mm; l = 8 mm."""
    t = screw.thread
    assert t.d2.m_as("mm") == pytest.approx(30.0)
    assert t.d3.m_as("mm") == pytest.approx(28.0)
    assert t.lead.m_as("mm") == pytest.approx(8.0)
    assert t.H1.m_as("mm") == pytest.approx(2.0)


def test_b_raise_torque(screw):
    """(b) T_R = 15.94 + 10.24 = 26.18 N m."""
    assert screw.raise_torque(F, MU).m_as("N*m") == pytest.approx(15.94, abs=0.005)
    assert collar_torque(F, MU, DC).m_as("N*m") == pytest.approx(10.24, abs=0.005)
    assert screw.raise_torque(F, MU, MU, DC).m_as("N*m") == pytest.approx(26.18, abs=0.005)


def test_b_lower_torque_and_not_self_locking(screw):
    """(b) T_L = -0.466 + 10.24 = 9.77 N m; "the minus sign ... the screw alone is not self-locking"."""
    assert screw.lower_torque(F, MU).m_as("N*m") == pytest.approx(-0.466, abs=0.0005)
    assert screw.lower_torque(F, MU, MU, DC).m_as("N*m") == pytest.approx(9.77, abs=0.005)
    assert screw.self_locking_mu().m_as("") > MU  # mu below mu*: back-drives
    assert screw.holding_torque(F, MU).m_as("N*m") == pytest.approx(0.466, abs=0.0005)


def test_c_efficiency(screw):
    """(c) e = F l / (2 pi T_R) = 0.311 (with collar friction)."""
    assert screw.efficiency(MU, MU, DC).m_as("") == pytest.approx(0.311, abs=0.0005)


def test_d_body_stresses(screw):
    """(d) tau = 16 T_R/(pi d_r^3) = 6.07 MPa; sigma = -4F/(pi d_r^2) = -10.39 MPa."""
    s = screw.stresses(F, Q(26.18, "N*m"))
    assert s.torsion.m_as("MPa") == pytest.approx(6.07, abs=0.005)
    assert s.axial.m_as("MPa") == pytest.approx(10.39, abs=0.005)


def test_e_bearing_stress():
    """(e) sigma_B = 2(0.38F)/(pi d_m (1) p) = 12.9 MPa: one thread carrying 0.38 F, H1 = p/2."""
    p = flank_pressure(0.38 * F, "30 mm", "2 mm", 1)
    assert p.m_as("MPa") == pytest.approx(12.9, abs=0.05)


def test_f_thread_root_bending():
    """(f) sigma_b = 6(0.38F)/(pi d_r (1) p) = 41.5 MPa (square thread: root width = height = p/2)."""
    sb = thread_bending_stress(0.38 * F, "28 mm", "2 mm", "2 mm", 1)
    assert sb.m_as("MPa") == pytest.approx(41.5, abs=0.05)


def test_g_von_mises_at_thread_root():
    """(g) sigma_x = 41.5, sigma_y = -10.39, tau_yz = 6.07 MPa -> sigma' = 48.7 MPa."""
    vm = thread_root_von_mises("41.5 MPa", "-10.39 MPa", "6.07 MPa")
    assert vm.m_as("MPa") == pytest.approx(48.7, abs=0.05)
