"""Roark's plate formulas checked against the independent series solutions of Timoshenko & Woinowsky-Krieger.

Sources:
- Roark's Formulas for Stress and Strain, 8th ed., Table 11.4 cases 1a, 1b, 8a, 8b (coefficients in
  mechverify/components/data/roark_plates.toml) and Table 11.2 cases 10a, 10b, 16, 17.
- S. Timoshenko, S. Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed. (1959), nu = 0.3,
  D = E t^3 / (12 (1 - nu^2)) = E t^3 / 10.92:
  Table 8 (simply supported, uniform): w = alpha q a^4 / D, M = beta q a^2:
      b/a = 1: alpha 0.00406, beta_x 0.0479; 1.5: 0.00772, 0.0812; 2: 0.01013, 0.1017.
  Table 35 (clamped, uniform): b/a = 1: w 0.00126, M_centre 0.0231, M_edge -0.0513;
      b/a = 2: w 0.00254, M_edge -0.0829.
  Table 23 (simply supported, central point load): w = alpha P a^2 / D: b/a = 1: 0.01160; 2: 0.01651.
  Table 57/58 (clamped, central load): b/a = 1: w 0.00560 P a^2 / D, M_edge(mid-side) -0.1257 P.
  Sec. 15/16 (circular plates, uniform load): w = (5+nu) q a^4 / (64 (1+nu) D) simply supported,
      q a^4 / (64 D) clamped.
"""

import math

import pytest

from mechverify.components.plates import equivalent_contact_radius, roark_circular_plate, roark_rectangular_plate
from mechverify.errors import InputError, UnknownNameError

E, T, NU = 70e9, 0.005, 0.3
D = E * T**3 / (12 * (1 - NU**2))


def rect(a_mm, b_mm, load, edges, loading, r0="0 m"):
    return roark_rectangular_plate(f"{a_mm} mm", f"{b_mm} mm", f"{T} m", f"{E} Pa", load, edges, loading, r0)


@pytest.mark.parametrize(("ratio", "alpha", "beta"), [(1.0, 0.00406, 0.0479), (1.5, 0.00772, 0.0812),
                                                      (2.0, 0.01013, 0.1017)])
def test_simply_supported_uniform(ratio, alpha, beta):
    b, q = 0.2, 1e4
    r = rect(200 * ratio, 200, f"{q} Pa", "simply_supported", "uniform")
    assert r.max_deflection.m_as("m") == pytest.approx(alpha * q * b**4 / D, rel=0.005)
    assert r.max_stress.m_as("Pa") == pytest.approx(6 * beta * q * b**2 / T**2, rel=0.005)
    assert r.stress_location == "centre"
    assert "1a" in r.source


@pytest.mark.parametrize(("ratio", "alpha", "m_edge"), [(1.0, 0.00126, 0.0513), (2.0, 0.00254, 0.0829)])
def test_clamped_uniform(ratio, alpha, m_edge):
    b, q = 0.2, 1e4
    r = rect(200 * ratio, 200, f"{q} Pa", "clamped", "uniform")
    assert r.max_deflection.m_as("m") == pytest.approx(alpha * q * b**4 / D, rel=0.006)
    assert r.max_stress.m_as("Pa") == pytest.approx(6 * m_edge * q * b**2 / T**2, rel=0.005)
    assert r.stress_location == "centre of long edge"
    if ratio == 1.0:
        assert r.stresses["centre"].m_as("Pa") == pytest.approx(6 * 0.0231 * q * b**2 / T**2, rel=0.005)


@pytest.mark.parametrize(("ratio", "alpha"), [(1.0, 0.01160), (2.0, 0.01651)])
def test_simply_supported_central_load_deflection(ratio, alpha):
    b, P = 0.2, 100.0
    r = rect(200 * ratio, 200, f"{P} N", "simply_supported", "central", "10 mm")
    assert r.max_deflection.m_as("m") == pytest.approx(alpha * P * b**2 / D, rel=0.005)


def test_clamped_central_load():
    b, P = 0.2, 100.0
    r = rect(200, 200, f"{P} N", "clamped", "central", "20 mm")
    assert r.max_deflection.m_as("m") == pytest.approx(0.00560 * P * b**2 / D, rel=0.005)
    assert r.stresses["centre of long edge"].m_as("Pa") == pytest.approx(6 * 0.1257 * P / T**2, rel=0.005)


def test_equivalent_contact_radius():
    """Roark/Westergaard r0' = sqrt(1.6 r0^2 + t^2) - 0.675 t below r0 = t/2: 0.325 t for a point load."""
    assert equivalent_contact_radius(0.0, 0.01) == pytest.approx(0.00325)
    assert equivalent_contact_radius(0.006, 0.01) == 0.006
    # continuous at r0 = t/2 within the formula's rounding
    assert equivalent_contact_radius(0.005 - 1e-12, 0.01) == pytest.approx(0.005, rel=0.02)


def test_circular_uniform_against_timoshenko():
    a, q = 0.1, 2e4
    ss = roark_circular_plate(f"{a} m", f"{T} m", f"{E} Pa", NU, f"{q} Pa", "simply_supported")
    cl = roark_circular_plate(f"{a} m", f"{T} m", f"{E} Pa", NU, f"{q} Pa", "clamped")
    assert ss.max_deflection.m_as("m") == pytest.approx((5 + NU) * q * a**4 / (64 * (1 + NU) * D), rel=1e-12)
    assert cl.max_deflection.m_as("m") == pytest.approx(q * a**4 / (64 * D), rel=1e-12)
    assert cl.stress_location == "edge" and ss.stress_location == "centre"
    assert ss.max_stress.m_as("MPa") == pytest.approx(3 * 3.3 * q * a**2 / (8 * T**2) / 1e6)


def test_circle_brackets_square():
    """A simply supported square of side 2a deflects more than the inscribed circle of radius a and less
    than the circumscribed one of radius a*sqrt(2) (a support-inclusion argument: independent of both tables)."""
    a, q = 0.1, 1e4
    sq = rect(200, 200, f"{q} Pa", "simply_supported", "uniform").max_deflection
    inner = roark_circular_plate(f"{a} m", f"{T} m", f"{E} Pa", NU, f"{q} Pa").max_deflection
    outer = roark_circular_plate(f"{a * math.sqrt(2)} m", f"{T} m", f"{E} Pa", NU, f"{q} Pa").max_deflection
    assert inner < sq < outer


def test_validity_warnings_and_errors():
    r = rect(200, 200, "1 MPa", "simply_supported", "uniform")
    assert any("half the thickness" in w for w in r.warnings)
    with pytest.raises(UnknownNameError, match="clamped"):
        rect(200, 200, "1 kPa", "clampd", "uniform")
    with pytest.raises(UnknownNameError, match="uniform"):
        rect(200, 200, "1 kPa", "clamped", "unifrm")
    with pytest.raises(InputError):
        roark_rectangular_plate("0 mm", "100 mm", "1 mm", "70 GPa", "1 kPa")
