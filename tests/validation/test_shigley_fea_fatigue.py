"""Fatigue safety field of FEA results against Shigley's mean-stress relations.

Source: Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, sec. 6-12:
fully reversed stress n = Se / sigma_a; modified Goodman eq. (6-46) n = 1 / (sigma_a/Se + sigma_m/Sut).
Material: ANSYS Structural Steel, S-N table held at 86.2 MPa beyond 1e6 cycles (ANSYS Engineering
Data), Sut = 460 MPa. A bar in uniform tension has sigma = F/A everywhere, so the field is checked
against the hand calculation at every node.
"""

import numpy as np
import pytest

from mechverify.errors import InputError
from mechverify.fea import mesh, solid
from mechverify.fea.loads import Force, Restraint
from mechverify.fea.regions import Plane


@pytest.fixture(scope="module")
def bar():
    m = mesh.box(("50 mm", "10 mm", "10 mm"), (2, 1, 1))
    model = solid.SolidModel(m, "Structural Steel",
                             supports=(Restraint(Plane(x="0 mm"), x=True), Restraint(Plane(y="0 mm"), y=True),
                                       Restraint(Plane(z="0 mm"), z=True)),
                             loads=(Force(Plane(x="50 mm"), ("5 kN", "0 N", "0 N")),))
    return model.solve()


def test_fully_reversed(bar):
    n = bar.fatigue_safety_factor(stress_ratio=-1).m
    assert n == pytest.approx(np.full(n.shape, 86.2 / 50.0), rel=1e-6)


def test_repeated_goodman(bar):
    sa = sm = 25.0
    expect = 1 / (sa / 86.2 + sm / 460.0)
    assert bar.min_fatigue_safety_factor(stress_ratio=0).value.m == pytest.approx(expect, rel=1e-6)
    # at 1e4 cycles the S-N table gives 262 MPa
    assert bar.min_fatigue_safety_factor(stress_ratio=0, cycles=1e4).value.m == pytest.approx(
        1 / (sa / 262 + sm / 460.0), rel=1e-6)
    with pytest.raises(InputError):
        bar.fatigue_safety_factor(stress_ratio=1.0)
