"""Acme power screw with the normal-plane flank angle, against Hamrock's solved problem.

Source: B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Machine Elements, 3rd ed., CRC
Press 2014, Problem 16.1 and its published solution: single-thread Acme screw, crest diameter
1.125 in, 5 threads per inch, W = 25 000 lb, collar mean diameter 1.5 in, mu = mu_c = 0.12.
Solution values: d_p = 1.015 in (Hamrock's Eq. 16.4 with its 0.01 in allowance, used here as input),
alpha = 3.589 deg, theta_n = 14.47 deg, T_r = 4637 in-lb, mu for self-locking limit = 0.0607.
"""

import pytest

from mechverify.components.power_screw import lead_angle, normal_flank_angle, raise_torque, self_locking_mu

DP, L = "1.015 in", "0.2 in"


def test_lead_angle():
    assert lead_angle(L, DP).m_as("deg") == pytest.approx(3.589, abs=0.0005)


def test_normal_flank_angle():
    assert normal_flank_angle("14.5 deg", lead_angle(L, DP)).m_as("deg") == pytest.approx(14.47, abs=0.005)


def test_raise_torque_with_collar():
    T = raise_torque("25000 lbf", DP, L, 0.12, "14.5 deg", 0.12, "1.5 in")
    assert T.m_as("lbf*in") == pytest.approx(4637, abs=0.5)


def test_self_locking_limit():
    assert self_locking_mu(DP, L, "14.5 deg").m_as("") == pytest.approx(0.0607, abs=0.00005)
