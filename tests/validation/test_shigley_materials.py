"""Materials against Shigley's Mechanical Engineering Design, 10th ed. (Budynas & Nisbett, 2015).

Tables quoted:
* Table 10-4 (constants for Sut = A/d^m): music wire A228 m = 0.145, A = 201 kpsi in^m / 2211 MPa mm^m;
  OQ&T wire A229 m = 0.187, A = 147 / 1855; 302 stainless A313: 0.013-0.10 in (0.3-2.5 mm) m = 0.146,
  A = 169 / 1867; 0.10-0.20 in (2.5-5 mm) m = 0.263, A = 128 / 2065; 0.20-0.40 in (5-10 mm) m = 0.478,
  A = 90 / 2911.
* Example 10-1: no. 16 music wire, d = 0.037 in: Sut = 201/0.037^0.145 = 324 kpsi.
* Table 10-5: music wire 0.064-0.125 in E = 196.5 GPa, G = 81.0 GPa; oil-tempered E = 196.5,
  G = 77.2 GPa; stainless A313 E = 193, G = 69.0 GPa.
* Table A-20: 1045 HR Sut = 570 MPa (82 kpsi), Sy = 310 MPa (45 kpsi), 16 %; 1045 CD 630 (91), 530 (77), 12 %.
* Table A-5: carbon steel E = 207.0 GPa, G = 79.3 GPa, nu = 0.292, 76.5 kN/m^3; stainless steel
  E = 190.0, G = 73.1, nu = 0.305, 76.0 kN/m^3.
"""

import pytest

from mechverify import Q, materials

G0 = 9.80665


def test_example_10_1_music_wire_strength():
    ws = materials.get("music wire").wire_strength
    assert ws.min_tensile_strength(Q(0.037, "in"), method="power_law").m_as("ksi") == pytest.approx(324, rel=2e-3)


@pytest.mark.parametrize(("name", "d_in", "a_kpsi", "m"), [
    ("A228", 0.05, 201, 0.145),
    ("A229", 0.1, 147, 0.187),
    ("A229", 0.45, 147, 0.187),
    ("A313", 0.05, 169, 0.146),
    ("A313", 0.15, 128, 0.263),
    ("A313", 0.30, 90, 0.478),
])
def test_table_10_4_metric_constants_agree_with_inch_constants(name, d_in, a_kpsi, m):
    """The stored MPa-mm constants give the same Sut as Table 10-4's kpsi-in constants (0.5 %)."""
    ws = materials.get(name).wire_strength
    assert ws.power_law(Q(d_in, "in")).m_as("ksi") == pytest.approx(a_kpsi / d_in ** m, rel=5e-3)


def test_a313_segments_chosen_by_diameter_and_meet_at_the_boundaries():
    ws = materials.get("A313").wire_strength
    assert ws.power_law("1 mm").m_as("MPa") == pytest.approx(1867)
    assert ws.power_law("4 mm").m_as("MPa") == pytest.approx(2065 / 4 ** 0.263)
    assert ws.power_law("8 mm").m_as("MPa") == pytest.approx(2911 / 8 ** 0.478)
    for d in ("2.5 mm", "5 mm"):  # the published laws join within 1 %
        lo = ws.power_law(Q(d).to("mm") - Q(1e-9, "mm")).m_as("MPa")
        hi = ws.power_law(Q(d).to("mm") + Q(1e-9, "mm")).m_as("MPa")
        assert hi == pytest.approx(lo, rel=0.01)


@pytest.mark.parametrize(("name", "E", "G"), [("A228", 196.5, 81.0), ("A229", 196.5, 77.2), ("A313", 193, 69.0)])
def test_table_10_5_elastic_constants(name, E, G):
    m = materials.get(name)
    assert m.E.m_as("GPa") == pytest.approx(E)
    assert m.G.m_as("GPa") == pytest.approx(G)
    assert "Table 10-5" in m.source_of("E")


@pytest.mark.parametrize(("name", "sut", "sy", "elong"), [("AISI 1045 HR", 570, 310, 0.16),
                                                          ("AISI 1045 CD", 630, 530, 0.12)])
def test_table_a20_1045(name, sut, sy, elong):
    m = materials.get(name)
    assert m.ultimate_strength.m_as("MPa") == sut
    assert m.yield_strength.m_as("MPa") == sy
    assert m.elongation.m_as("") == pytest.approx(elong)
    # the kpsi column of the same table
    assert m.ultimate_strength.m_as("ksi") == pytest.approx({570: 82, 630: 91}[sut], abs=0.7)
    assert "Table A-20" in m.source_of("yield_strength")


@pytest.mark.parametrize(("name", "E", "G", "nu", "w_kn"), [("1045 CD", 207.0, 79.3, 0.292, 76.5),
                                                            ("304", 190.0, 73.1, 0.305, 76.0)])
def test_table_a5_physical_constants(name, E, G, nu, w_kn):
    m = materials.get(name)
    assert (m.E.m_as("GPa"), m.G.m_as("GPa"), m.nu.m_as("")) == pytest.approx((E, G, nu))
    assert m.density.m_as("kg/m^3") * G0 / 1000 == pytest.approx(w_kn, rel=2e-3)
