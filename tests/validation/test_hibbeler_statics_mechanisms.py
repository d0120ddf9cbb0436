"""Planar statics solver against textbook frames and beams with published answers.

* R. C. Hibbeler, *Engineering Mechanics: Statics*, 13th ed., Pearson, 2013, Sec. 6.6,
  Example 6.14 (Fig. 6-21): member AB at 60 deg, 3 m long, pinned at A; horizontal member BC,
  4 m, pinned at C; 2000 N at the middle of BC. Published answer: the pin at C exerts
  C_x = 577 N and C_y = 1000 N on BC; AB is a two-force member with F_AB = 1154.7 N.
* Simply supported beam (pin + roller) of span L: central point load P gives M_max = P L / 4,
  uniform load w gives M_max = w L^2 / 8 (W. C. Young, R. G. Budynas, *Roark's Formulas for Stress
  and Strain*, 7th ed., Table 8.1, cases 1e and 2e with a = L/2 and the full span loaded).
"""

import math

import pytest

from mechverify import Q
from mechverify.mechanisms import GROUND, AppliedForce, Body, Mechanism, Pin, Slider


def hibbeler_6_14() -> Mechanism:
    s60, c60 = math.sin(math.radians(60)), math.cos(math.radians(60))
    A = (Q(0, "m"), Q(0, "m"))
    B = (Q(3 * c60, "m"), Q(3 * s60, "m"))
    C = (Q(3 * c60 + 4, "m"), Q(3 * s60, "m"))
    mid = (Q(3 * c60 + 2, "m"), Q(3 * s60, "m"))
    return Mechanism(
        bodies=(Body("AB", {"A": A, "B": B}), Body("BC", {"B": B, "C": C})),
        joints=(Pin("A", GROUND, "AB", "A"), Pin("B", "AB", "BC", "B"), Pin("C", GROUND, "BC", "C")),
        loads=(AppliedForce("BC", mid, ("0 N", "-2000 N")),),
        name="Hibbeler Example 6.14",
    )


def test_hibbeler_example_6_14_pin_c():
    sol = hibbeler_6_14().solve()
    Cx, Cy = sol.force_on("C", "BC").m_as("N")
    assert abs(Cx) == pytest.approx(577.35, abs=0.5)  # published: 577 N
    assert Cy == pytest.approx(1000.0, rel=1e-9)  # published: 1000 N, upward
    assert sol.residual_force.m_as("N") < 1e-9


def test_hibbeler_example_6_14_two_force_member():
    sol = hibbeler_6_14().solve()
    assert sol.axial_forces["AB"].m_as("N") == pytest.approx(-1154.7, abs=0.1)  # compression
    assert sol.member_loads["AB"].moment.m_as("N*m") < 1e-9  # a two-force member carries no moment


def simply_supported(L=2.0, load=None, mass=None) -> Mechanism:
    P0, P1 = (Q(0, "m"), Q(0, "m")), (Q(L, "m"), Q(0, "m"))
    beam = Body("beam", {"L": P0, "R": P1}, mass=mass or "0 kg")
    roller = Body("roller", {"R": P1})
    joints = (Pin("pin", GROUND, "beam", "L"), Slider("slide", GROUND, "roller", "R", direction="0 deg"),
              Pin("roller_pin", "roller", "beam", "R"))
    loads = (AppliedForce("beam", (Q(L / 2, "m"), Q(0, "m")), ("0 N", f"-{load} N")),) if load else ()
    return Mechanism((beam, roller), joints, loads)


def test_roark_central_point_load():
    sol = simply_supported(L=2.0, load=1000).solve()
    ml = sol.member_loads["beam"]
    assert ml.moment.m_as("N*m") == pytest.approx(1000 * 2.0 / 4, rel=1e-12)
    assert ml.moment_at.m_as("m") == pytest.approx(1.0)
    assert ml.shear.m_as("N") == pytest.approx(500.0)


def test_roark_uniform_self_weight():
    m, g, L = 10.0, 9.80665, 2.0
    sol = simply_supported(L=L, mass=f"{m} kg").solve()
    assert sol.member_loads["beam"].moment.m_as("N*m") == pytest.approx(m * g * L / 8, rel=1e-9)
    assert sol.force_on("pin", "beam").m_as("N")[1] == pytest.approx(m * g / 2, rel=1e-12)
