"""Materials against manufacturers' and associations' data sheets.

Sources quoted:
* igus iglidur R (seed 004, Tabla 3): density 1.39 g/cm^3; dynamic friction against steel 0.09-0.25;
  pv max (dry) 0.27 MPa m/s; maximum recommended surface pressure 23 MPa (seed 004 section 2.2.1).
* igus iglide J material data (igus.com, US units): friction 0.06-0.18; p x v max 9,700 psi x fpm;
  modulus 348,100 psi; permissible static surface pressure 5,076 psi; long-term 194 F.
  Independently, seed 004 Tabla 7 (metric): pv 0.34 MPa m/s, modulus 2,400 MPa, density 1.49 g/cm^3.
* igus iglidur P210: 1.40 g/cm^3, friction 0.07-0.19, pv 0.4 MPa m/s, 50 MPa, +100 C.
* The Tribology Handbook, 2nd ed., A5: filled PTFE 1000 lbf/in^2 (7 MN/m^2), PV 10 000 lbf/in^2 ft/min
  (0.35 MN/m^2 m/s); PTFE bonded to steel backing 20 000 lbf/in^2 (140 MN/m^2), PV 1.75 MN/m^2 m/s.
* Mott, Table 16-1: porous bronze / oil impregnated pV = 50 000 psi-fpm = 1.750 MPa-m/s.
* MatWeb (Aluminum Association typical): 6061-T6 Sut 310, Sy 276 MPa, fatigue strength 96.5 MPa at
  5e8 cycles (completely reversed, R.R. Moore); 7075-T6 Sut 572, Sy 503, fatigue 159 MPa at 5e8.
* ASM/MatWeb AISI 4340: annealed 745 / 470 MPa, 22 %; oil quenched, 650 C temper 931 / 834 MPa, 20.5 %.
* Stratasys FDM PLA: XZ yield 45 MPa, ultimate 48 MPa, modulus 3,039 MPa; XY 26 / 26 / 2,539 MPa.
* ANSYS Engineering Data "Structural Steel" alternating stress (zero mean): 2e5 cycles 114 MPa,
  1e6 cycles 86.2 MPa; 20 cycles 2827 MPa.
"""

import math

import pytest

from mechverify import Q, materials


def test_iglidur_r_seed_004_datasheet():
    m = materials.get("iglidur R")
    assert m.density.m_as("g/cm^3") == pytest.approx(1.39)
    assert (m.mu_min.m_as(""), m.mu_max.m_as("")) == (0.09, 0.25)
    assert m.pv_max.m_as("MPa*m/s") == pytest.approx(0.27)
    assert m.p_max.m_as("MPa") == 23


def test_iglidur_j_us_datasheet_matches_metric_table_of_seed_004():
    m = materials.get("iglide J")
    assert m.pv_max.m_as("MPa*m/s") == pytest.approx(0.34, abs=0.005)  # 9,700 psi fpm
    assert m.E.m_as("MPa") == pytest.approx(2400, rel=2e-3)  # 348,100 psi
    assert m.p_max.m_as("MPa") == pytest.approx(35, rel=1e-3)  # 5,076 psi
    assert m.max_temperature.m_as("degC") == pytest.approx(90)
    assert (m.mu_min.m_as(""), m.mu_max.m_as("")) == (0.06, 0.18)


def test_iglidur_p210():
    m = materials.get("iglidur P210")
    assert (m.p_max.m_as("MPa"), m.pv_max.m_as("MPa*m/s"), m.mu_min.m_as(""), m.mu_max.m_as("")) == \
        pytest.approx((50, 0.4, 0.07, 0.19))


def test_tribology_handbook_ptfe_grades_in_both_unit_systems():
    ptfe, du = materials.get("filled PTFE"), materials.get("DU bearing")
    assert ptfe.p_max.m_as("psi") == pytest.approx(1000, rel=0.02)
    assert ptfe.pv_max.m_as("psi*ft/min") == pytest.approx(10_000, rel=0.01)
    assert du.p_max.m_as("psi") == pytest.approx(20_000, rel=0.02)
    assert du.pv_max.m_as("MPa*m/s") == pytest.approx(1.75)


def test_mott_porous_bronze_pv():
    assert materials.get("sintered bronze").pv_max.m_as("psi*ft/min") == pytest.approx(50_000, rel=1e-3)


@pytest.mark.parametrize(("name", "sut", "sy", "se"), [("6061-T6", 310, 276, 96.5), ("7075-T6", 572, 503, 159)])
def test_aluminum_association_typical_values(name, sut, sy, se):
    m = materials.get(name)
    assert (m.ultimate_strength.m_as("MPa"), m.yield_strength.m_as("MPa")) == (sut, sy)
    assert m.endurance_limit.m_as("MPa") == se
    assert any("5e8" in n for n in m.notes)


@pytest.mark.parametrize(("name", "sut", "sy", "elong"), [("4340 annealed", 745, 470, 0.22),
                                                          ("4340 Q&T", 931, 834, 0.205)])
def test_asm_4340(name, sut, sy, elong):
    m = materials.get(name)
    assert (m.ultimate_strength.m_as("MPa"), m.yield_strength.m_as("MPa")) == (sut, sy)
    assert m.elongation.m_as("") == pytest.approx(elong)


def test_stratasys_pla_orientation():
    xy, xz = materials.get("PLA"), materials.get("PLA XZ")
    assert (xy.yield_strength.m_as("MPa"), xy.ultimate_strength.m_as("MPa"), xy.E.m_as("MPa")) == (26, 26, 2539)
    assert (xz.yield_strength.m_as("MPa"), xz.ultimate_strength.m_as("MPa"), xz.E.m_as("MPa")) == (45, 48, 3039)
    assert "XY" in xy.source_of("yield_strength")


def test_ansys_structural_steel_sn_table():
    sn = materials.get("ANSYS Structural Steel").sn_curve
    assert sn.stress_at(2e5).m_as("MPa") == pytest.approx(114)
    assert sn.stress_at(20).m_as("MPa") == pytest.approx(2827)
    # log-log interpolation between the published points (2e5, 114) and (1e6, 86.2)
    expect = 114 * (86.2 / 114) ** (math.log10(5e5 / 2e5) / math.log10(1e6 / 2e5))
    assert sn.stress_at(5e5).m_as("MPa") == pytest.approx(expect)
    assert sn.life_at(Q(86.2, "MPa")) == pytest.approx(1e6)
    assert sn.stress_ratio == -1
