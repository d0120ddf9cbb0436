"""Statics solver: rank check messages, input errors, equilibrium residuals, slider joints."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechverify import Q
from mechverify.errors import InputError, ModelError, UnitError, UnknownNameError
from mechverify.mechanisms import GROUND, AppliedForce, Body, Couple, Mechanism, Pin, Slider

O, A, B = (Q(0, "m"), Q(0, "m")), (Q(1, "m"), Q(0, "m")), (Q(2, "m"), Q(0, "m"))


def test_under_constrained_names_the_free_body():
    mech = Mechanism((Body("bar", {"O": O, "A": A}),), (Pin("p", GROUND, "bar", "O"),),
                     (AppliedForce("bar", "A", ("0 N", "-1 N")),), name="pendulum")
    with pytest.raises(ModelError, match=r"under-constrained.*body 'bar' rotates"):
        mech.solve()


def test_free_translation_is_named():
    mech = Mechanism((Body("block", {"A": A}, mass="1 kg", com=A),),
                     (Slider("s", GROUND, "block", "A", direction="0 deg"),))
    with pytest.raises(ModelError, match=r"body 'block' translates along 0.0 deg"):
        mech.solve()


def test_over_constrained_names_indeterminate_unknowns():
    mech = Mechanism((Body("beam", {"O": O, "B": B}),),
                     (Pin("left", GROUND, "beam", "O"), Pin("right", GROUND, "beam", "B")),
                     (AppliedForce("beam", A, ("0 N", "-10 N")),))
    with pytest.raises(ModelError, match=r"over-constrained.*pin 'left' Rx.*pin 'right' Rx"):
        mech.solve()


def test_singular_configuration_is_reported():
    """Three collinear pins (a toggle): counts balance, but the rank drops."""
    bodies = (Body("l1", {"O": O, "A": A}), Body("l2", {"A": A, "B": B}))
    joints = (Pin("o", GROUND, "l1", "O"), Pin("a", "l1", "l2", "A"), Pin("b", GROUND, "l2", "B"))
    mech = Mechanism(bodies, joints, (AppliedForce("l1", A, ("0 N", "-1 N")),))
    with pytest.raises(ModelError, match="singular configuration"):
        mech.solve()


def test_input_errors():
    with pytest.raises(UnitError, match=r"point 'A'\[x\]"):
        Body("b", {"A": (1, 0)})
    with pytest.raises(InputError, match="mass"):
        Body("b", {"A": A}, mass="-1 kg")
    with pytest.raises(InputError, match="give com"):
        Body("b", {"A": A}, mass="1 kg")
    with pytest.raises(InputError, match="tree"):
        Body("t", {"A": O, "B": A, "C": (Q(0, "m"), Q(1, "m"))}, segments=(("A", "B"), ("B", "C"), ("C", "A")))
    with pytest.raises(UnknownNameError, match="did you mean 'bar'"):
        Mechanism((Body("bar", {"O": O, "A": A}),), (Pin("p", GROUND, "baar", "O"),)).solve()
    with pytest.raises(UnknownNameError, match="unknown point"):
        Mechanism((Body("bar", {"O": O, "A": A}),), (Pin("p", GROUND, "bar", "Z"),)).solve()
    with pytest.raises(InputError, match="is at"):
        Mechanism((Body("u", {"A": A}, mass="1 kg", com=A), Body("v", {"A": B}, mass="1 kg", com=B)),
                  (Pin("p", "u", "v", "A"),)).solve()
    with pytest.raises(InputError, match="unique"):
        Mechanism((Body("u", {"A": A}), Body("u", {"A": A})), ())


def test_actuated_slider_and_couple():
    """A block on a slide driven by a force holds a horizontal load; a couple on a pinned crank is
    balanced by its motor."""
    mech = Mechanism((Body("block", {"A": A}),), (Slider("s", GROUND, "block", "A", "30 deg", actuated=True),),
                     (AppliedForce("block", "A", (Q(math.cos(math.radians(30)) * 5, "N"),
                                               Q(math.sin(math.radians(30)) * 5, "N"))),))
    assert mech.solve().actuator_efforts["s"].m_as("N") == pytest.approx(-5.0)
    crank = Mechanism((Body("c", {"O": O, "A": A}),), (Pin("m", GROUND, "c", "O", actuated=True),),
                      (Couple("c", "2 N*m"),))
    assert crank.solve().actuator_efforts["m"].m_as("N*m") == pytest.approx(-2.0)


def _slider_crank(theta, r=0.05, ell=0.2, P=100.0):
    """Crank OA (motor at O), rod AB, piston at B sliding along x; piston force P toward O."""
    Ap = np.array([r * math.cos(theta), r * math.sin(theta)])
    Bp = np.array([Ap[0] + math.sqrt(ell**2 - Ap[1] ** 2), 0.0])
    q = {k: (Q(v[0], "m"), Q(v[1], "m")) for k, v in {"O": np.zeros(2), "A": Ap, "B": Bp}.items()}
    bodies = (Body("crank", {"O": q["O"], "A": q["A"]}), Body("rod", {"A": q["A"], "B": q["B"]}),
              Body("piston", {"B": q["B"]}))
    joints = (Pin("motor", GROUND, "crank", "O", actuated=True), Pin("a", "crank", "rod", "A"),
              Pin("b", "rod", "piston", "B"), Slider("bore", GROUND, "piston", "B", "0 deg"))
    return Mechanism(bodies, joints, (AppliedForce("piston", "B", (Q(-P, "N"), "0 N")),)), Bp[0]


@settings(max_examples=30, deadline=None)
@given(st.floats(0.2, 2.9))
def test_slider_crank_virtual_work_and_residual(theta):
    """Virtual work: tau = P dx_B/dtheta (Meriam & Kraige 7th ed., Art. 7/3)."""
    mech, _ = _slider_crank(theta)
    sol = mech.solve()
    h = 1e-7
    dx = (_slider_crank(theta + h)[1] - _slider_crank(theta - h)[1]) / (2 * h)
    assert sol.actuator_efforts["motor"].m_as("N*m") == pytest.approx(100.0 * dx, rel=1e-6, abs=1e-9)
    assert sol.residual_force.m_as("N") < 1e-9 and sol.residual_moment.m_as("N*m") < 1e-10
    assert sol.axial_forces["rod"].m_as("N") < 0  # the rod pushes the piston against the load
