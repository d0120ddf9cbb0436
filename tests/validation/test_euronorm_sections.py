"""Section properties of rolled European profiles against the standard tables.

Sources:
- IPE 200 (dimensions EN 10365 / Euronorm 19-57: h = 200, b = 100, tw = 5.6, tf = 8.5, r = 12 mm);
  tabulated properties from the ArcelorMittal "Sections and Merchant Bars" catalogue (2022),
  IPE table: A = 28.48 cm^2, Iy = 1943 cm^4, Wel,y = 194.3 cm^3, Wpl,y = 220.6 cm^3,
  Iz = 142.4 cm^4, Wel,z = 28.47 cm^3, Wpl,z = 44.61 cm^3, It = 6.98 cm^4.
- Equal angle L 50x50x5 (EN 10056-1: r1 = 7, r2 = 3.5 mm): A = 4.80 cm^2, c = 1.40 cm,
  Iy = Iz = 10.96 cm^4, Iu = 17.4 cm^4, Iv = 4.54 cm^4 (same catalogue, angle table).
Table values use the rounded dimensions with fillets; tolerances state the tables' rounding
(0.5 %), and 2 % for It, which catalogues compute with an approximate fillet formula.
"""

import math

import pytest

from mechverify.components import sections


@pytest.fixture(scope="module")
def ipe200():
    return sections.i_section("200 mm", "100 mm", "5.6 mm", "8.5 mm", root_radius="12 mm")


@pytest.mark.parametrize(("attr", "unit", "table", "rel"), [
    ("area", "cm**2", 28.48, 0.005),
    ("Iy", "cm**4", 1943, 0.005),
    ("Wel_y", "cm**3", 194.3, 0.005),
    ("Wpl_y", "cm**3", 220.6, 0.005),
    ("Iz", "cm**4", 142.4, 0.005),
    ("Wel_z", "cm**3", 28.47, 0.005),
    ("Wpl_z", "cm**3", 44.61, 0.005),
    ("J", "cm**4", 6.98, 0.02),
])
def test_ipe200(ipe200, attr, unit, table, rel):
    assert getattr(ipe200, attr).m_as(unit) == pytest.approx(table, rel=rel)


def test_ipe200_symmetry_and_fibres(ipe200):
    assert ipe200.Iyz.m_as("cm**4") == pytest.approx(0.0, abs=1e-6)
    assert ipe200.c_z_pos.m_as("mm") == pytest.approx(100.0)
    assert ipe200.c_y.m_as("mm") == pytest.approx(50.0)
    assert ipe200.ry.m_as("cm") == pytest.approx(8.26, rel=0.005)  # table iy = 8.26 cm
    assert ipe200.rz.m_as("cm") == pytest.approx(2.24, rel=0.005)  # table iz = 2.24 cm
    # the web carries the vertical shear: Asz lies between the clear web area and h*tw
    assert (200 - 2 * 8.5) * 5.6 < ipe200.Asz.m_as("mm**2") < 200 * 5.6 * 1.1


def test_equal_angle_50x50x5():
    L = sections.l_section("50 mm", "50 mm", "5 mm", root_radius="7 mm", toe_radius="3.5 mm")
    assert L.area.m_as("cm**2") == pytest.approx(4.80, rel=0.005)
    assert L.centroid_y.m_as("cm") == pytest.approx(1.40, abs=0.005)
    assert L.Iy.m_as("cm**4") == pytest.approx(10.96, rel=0.005)
    assert L.I1.m_as("cm**4") == pytest.approx(17.4, rel=0.005)
    assert L.I2.m_as("cm**4") == pytest.approx(4.54, rel=0.005)
    # the major axis u-u of an equal angle is its axis of symmetry, at 45 degrees
    assert L.principal_angle.m_as("deg") == pytest.approx(45.0, abs=1e-6)
    assert math.isclose(L.r_min.m_as("cm"), 0.973, rel_tol=0.01)  # table iv = 0.97 cm
