"""Torsion of solid rectangular and thin-walled sections against published tables.

Sources:
- Timoshenko & Goodier, Theory of Elasticity, 3rd ed. (1970), Sec. 109, table of k1, k2 for a
  rectangle h x b (h >= b): J = k1 h b^3, tau_max = T / (k2 h b^2). The same coefficients are
  tabulated in Roark's Formulas for Stress and Strain, 8th ed., Table 10.7 case 4 (as K and the
  approximate polynomial); Roark's K = a b^3 [16/3 - 3.36 b/a (1 - b^4/(12 a^4))] (2a x 2b) is
  checked too, to its stated accuracy.
- Thin-walled closed section: Roark 8th ed., Table 10.7, hollow rectangle (Bredt):
  K = 2 t t1 (a - t)^2 (b - t1)^2 / (a t + b t1 - t^2 - t1^2).
"""

import math

import pytest

from mechverify.components import sections

# h/b: (k1, k2), Timoshenko & Goodier Sec. 109
TABLE = {1.0: (0.141, 0.208), 1.5: (0.196, 0.231), 2.0: (0.229, 0.246), 2.5: (0.249, 0.258),
         3.0: (0.263, 0.267), 4.0: (0.281, 0.282), 5.0: (0.291, 0.291), 10.0: (0.312, 0.312)}


@pytest.mark.parametrize("ratio", sorted(TABLE))
def test_rectangle_torsion_coefficients(ratio):
    k1, k2 = TABLE[ratio]
    b = 10.0
    s = sections.rectangle(f"{b * ratio} mm", f"{b} mm")
    h = b * ratio
    assert s.J.m_as("mm**4") / (h * b**3) == pytest.approx(k1, abs=0.0006)
    assert s.Wt.m_as("mm**3") / (h * b**2) == pytest.approx(k2, abs=0.0006)


@pytest.mark.parametrize("ratio", [1.0, 2.0, 4.0, 10.0])
def test_rectangle_against_roark_formula(ratio):
    """Roark's K formula for a 2a x 2b rectangle agrees with the exact series within 0.5 %."""
    a, b = 5.0 * ratio, 5.0
    K = a * b**3 * (16 / 3 - 3.36 * b / a * (1 - b**4 / (12 * a**4)))
    J = sections.rectangle(f"{2 * a} mm", f"{2 * b} mm").J.m_as("mm**4")
    assert J == pytest.approx(K, rel=0.005)


def test_thin_hollow_rectangle_bredt():
    """A 100 x 60 x 2 mm box: FE warping analysis within 1.5 % of Roark's thin-walled K (t/b = 1/30)."""
    a, b, t = 100.0, 60.0, 2.0
    K = 2 * t * t * (a - t) ** 2 * (b - t) ** 2 / (a * t + b * t - 2 * t * t)
    s = sections.hollow_rectangle("100 mm", "60 mm", "2 mm")
    assert s.J.m_as("mm**4") == pytest.approx(K, rel=0.015)
    # its second moment is exact for the polygon: (b h^3 - (b-2t)(h-2t)^3)/12, width 100 along y
    Iy = (100 * 60**3 - 96 * 56**3) / 12
    assert s.Iy.m_as("mm**4") == pytest.approx(Iy, rel=1e-9)


def test_round_sections_j_is_polar_moment():
    """For a circle and a tube, J = pi (D^4 - d^4)/32 and tau_max = T D / (2J) (elementary torsion)."""
    c = sections.circle("20 mm")
    assert c.J.m_as("mm**4") == pytest.approx(math.pi * 20**4 / 32)
    assert c.Wt.m_as("mm**3") == pytest.approx(math.pi * 20**3 / 16)
    t = sections.tube("20 mm", "2 mm")
    assert t.J.m_as("mm**4") == pytest.approx(math.pi * (20**4 - 16**4) / 32)
    assert t.J == t.polar_moment
    r = sections.rectangle("30 mm", "10 mm")
    assert r.J < 0.5 * r.polar_moment  # the polar moment would overstate torsional stiffness
