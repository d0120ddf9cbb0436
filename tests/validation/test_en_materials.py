"""Materials against European standards.

Tables quoted:
* EN 10025-2:2019 Table 7 (minimum values): S235JR ReH 235 MPa (t <= 16 mm), 225 (16-40 mm),
  Rm 360-510 MPa (3-100 mm); S355JR ReH 355 (t <= 16 mm), 345 (16-40 mm), Rm 470-630 MPa.
* EN 1993-1-1:2005 3.2.6: E = 210 000 N/mm^2, G = E/(2(1 + nu)) ~ 81 000 N/mm^2, nu = 0.3.
* EN 1991-1-1 Table A.4: steel 77.0-78.5 kN/m^3.
* EN 1999-1-1:2007 3.2.5: E = 70 000 N/mm^2, G = 27 000 N/mm^2, nu = 0.3, rho = 2700 kg/m^3;
  Table 3.2b: EN AW-5083 O/H111 extrusions, t <= 200 mm: f0 = 110, fu = 270 N/mm^2, A = 12 %.
* EN 754-2:2008: EN AW-6082 T6 drawn bar: Rm >= 310, Rp0.2 >= 255 N/mm^2.
"""

import pytest

from mechverify import materials


@pytest.mark.parametrize(("name", "reh", "rm"), [("S235JR", 235, 360), ("S355JR", 355, 470)])
def test_en10025_2_table_7(name, reh, rm):
    m = materials.get(name)
    assert m.yield_strength.m_as("MPa") == reh
    assert m.ultimate_strength.m_as("MPa") == rm
    assert "EN 10025-2" in m.source_of("yield_strength")


@pytest.mark.parametrize("name", ["S235", "S355"])
def test_en1993_elastic_constants(name):
    m = materials.get(name)
    assert m.E.m_as("MPa") == 210_000
    assert m.nu.m_as("") == 0.3
    assert m.G.m_as("MPa") == pytest.approx(81_000, rel=5e-3)  # "G ~ 81 000 N/mm^2"
    # EN 1991-1-1 Table A.4: 77.0-78.5 kN/m^3; the conventional 7850 kg/m^3 is 76.98 kN/m^3
    assert 77.0 - 0.05 <= m.density.m_as("kg/m^3") * 9.80665 / 1000 <= 78.5


@pytest.mark.parametrize("name", ["6082-T6", "5083-H111"])
def test_en1999_material_constants(name):
    m = materials.get(name)
    assert (m.E.m_as("MPa"), m.G.m_as("MPa"), m.nu.m_as(""), m.density.m_as("kg/m^3")) == (70_000, 27_000, 0.3, 2700)
    # EN 1999-1-1 gives E, G and nu independently; they agree with G = E/(2(1+nu)) to 0.3 %
    assert m.E.m_as("MPa") / (2 * 1.3) == pytest.approx(27_000, rel=3e-3)


def test_en1999_table_3_2b_5083():
    m = materials.get("EN AW-5083-H111")
    assert (m.yield_strength.m_as("MPa"), m.ultimate_strength.m_as("MPa"), m.elongation.m_as("")) == (110, 270, 0.12)


def test_en754_2_6082_t6():
    m = materials.get("EN AW-6082-T6")
    assert (m.yield_strength.m_as("MPa"), m.ultimate_strength.m_as("MPa")) == (255, 310)
