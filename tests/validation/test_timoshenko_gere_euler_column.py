"""Linear buckling of a slender solid column against Euler's load (mechverify.fea.buckling).

Source: Timoshenko & Gere, Theory of Elastic Stability, 2nd ed., 1961, sec. 2.1: a column built in at
the base and free at the top buckles at P_cr = π² E I / (4 L²) (effective length 2L). The value below is
a hand calculation from that formula (10 x 10 mm steel bar, L = 200 mm, E = 200 GPa: 10 281 N), not a
printed value. A compressive load of 1 kN then has a buckling load factor of 10.28.
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.fea import buckling, mesh, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane


def euler_fixed_free(E: float, I: float, L: float) -> float:
    """Hand calculation of Timoshenko & Gere sec. 2.1: P_cr = π² E I / (2 L)² [N]."""
    return np.pi**2 * E * I / (2 * L) ** 2


def test_fixed_free_column_factor():
    """20x2x2 cells of P2 tets (L/h = 20): within 0.5 % of Euler (the solid's shear softening at L/h = 20 is
    about 0.1 %, the coarse section stiffens by about 0.4 %); the first two modes are the y and z bending
    pair of the square bar, equal to 1 %."""
    P = 1000.0
    col = solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (20, 2, 2)), "Structural Steel",
                           supports=(Fixed(Plane(x="0 mm")),), loads=(Force(Plane(x="200 mm"), (f"{-P} N", "0 N", "0 N")),))
    res = buckling.buckling(col, 2)
    pcr = euler_fixed_free(200e9, 0.01**4 / 12, 0.2)
    assert pcr == pytest.approx(10281, abs=1)
    assert res.factors[0] == pytest.approx(pcr / P, rel=5e-3)
    assert res.factors[1] == pytest.approx(res.factors[0], rel=1e-2)
    # the mode is lateral: the axial component of the shape is small against the tip's lateral motion
    tip = res.shapes[0][np.argmax(np.linalg.norm(res.shapes[0], axis=1))]
    assert np.hypot(tip[1], tip[2]) > 5 * abs(tip[0])
