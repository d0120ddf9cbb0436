"""Fatigue package: errors, units, vectorisation and properties (published values are in tests/validation)."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mechverify import Q, materials
from mechverify.checks.fatigue import check_fatigue, check_fatigue_field
from mechverify.errors import InputError, UnitError, UnknownNameError, ValidityError
from mechverify.fatigue import criteria, endurance, life, notch, stress
from mechverify.fatigue.rainflow import rainflow

pos = st.floats(1e6, 5e8)


def test_bare_number_and_wrong_dimension_name_the_parameter():
    with pytest.raises(UnitError, match="sigma_a"):
        criteria.goodman(100e6, "50 MPa", "200 MPa", "600 MPa")
    with pytest.raises(UnitError, match="Sut"):
        criteria.goodman("1 MPa", "1 MPa", "200 MPa", "600 mm")


def test_bad_names_and_values():
    with pytest.raises(UnknownNameError, match="goodman"):
        criteria.safety_factor("godman", "1 MPa", "1 MPa", "2 MPa", Sut="3 MPa")
    with pytest.raises(UnknownNameError, match="load line"):
        criteria.goodman("1 MPa", "1 MPa", "2 MPa", "3 MPa", load_line="constant_ratio")
    with pytest.raises(InputError, match="sigma_a"):
        criteria.goodman("-1 MPa", "1 MPa", "2 MPa", "3 MPa")
    with pytest.raises(InputError, match="Sy"):
        criteria.safety_factor("soderberg", "1 MPa", "1 MPa", "2 MPa", Sut="3 MPa")
    with pytest.raises(InputError, match="gamma"):
        criteria.walker("1 MPa", "1 MPa", "2 MPa", 1.5)
    with pytest.raises(UnknownNameError):
        endurance.surface_factor("500 MPa", "polished-ish")
    with pytest.raises(ValidityError):
        endurance.size_factor("1 mm")
    with pytest.raises(ValidityError):
        endurance.temperature_factor(Q(700, "degC"))
    with pytest.raises(ValidityError):
        notch.neuber_constant("200 MPa")
    with pytest.raises(InputError):
        notch.fatigue_notch_factor(0.9, 0.5)


def test_no_stress_no_failure_and_static_limit():
    assert criteria.goodman.si(0.0, 0.0, 1.0, 2.0) == np.inf
    assert criteria.goodman.si(0.0, 1.0, 1.0, 2.0) == pytest.approx(2.0)  # Sut / sigma_m
    assert criteria.gerber.si(0.0, 1.0, 1.0, 2.0) == pytest.approx(2.0)
    assert criteria.goodman.si(1.0, 3.0, 1.0, 2.0, load_line="constant_mean") == 0.0


@settings(max_examples=60, deadline=None)
@given(sa=pos, sm=st.floats(0, 5e8), se=pos, k=st.floats(1.05, 4))
def test_criteria_ordering(sa, sm, se, k):
    """Gerber >= Goodman >= Soderberg (Sy < Sut), all equal Se/sigma_a at zero mean (Shigley Fig. 6-27)."""
    sut, sy = k * se * 1.2, se * 1.1
    sy = min(sy, sut)
    g = criteria.goodman.si(sa, sm, se, sut)
    assert criteria.gerber.si(sa, sm, se, sut) >= g * (1 - 1e-12)
    assert criteria.soderberg.si(sa, sm, se, sy) <= g * (1 + 1e-12)
    assert criteria.goodman.si(sa, 0.0, se, sut) == pytest.approx(se / sa)
    # on the failure locus n = 1 after scaling the load by n
    assert criteria.goodman.si(sa * g, sm * g, se, sut) == pytest.approx(1.0)
    gm = criteria.gerber.si(sa, sm, se, sut)
    assert criteria.gerber.si(sa * gm, sm * gm, se, sut) == pytest.approx(1.0)


def test_vectorised_equals_scalar():
    sa, sm = np.array([50e6, 80e6, 0.0]), np.array([20e6, -10e6, 30e6])
    for name, kw in [("goodman", {"Sut": 600e6}), ("gerber", {"Sut": 600e6}), ("asme_elliptic", {"Sy": 400e6}),
                     ("walker", {"gamma": 0.6})]:
        for line in criteria.LOAD_LINES:
            v = criteria.safety_factor.si(name, sa, sm, 200e6, load_line=line, **kw)
            assert v.shape == (3,)
            for i in range(3):
                assert v[i] == pytest.approx(criteria.safety_factor.si(name, sa[i], sm[i], 200e6, load_line=line, **kw))
    q = criteria.goodman(Q(sa, "Pa"), Q(sm, "Pa"), "200 MPa", "600 MPa")
    assert q.m.shape == (3,)


def test_walker_half_is_swt_and_equivalent_amplitude_goodman():
    assert criteria.walker.si(1.0, 2.0, 3.0, 0.5) == pytest.approx(criteria.smith_watson_topper.si(1.0, 2.0, 3.0))
    srev = criteria.equivalent_amplitude("goodman", "40 ksi", "20 ksi", Sut="80 ksi")
    assert srev.m_as("ksi") == pytest.approx(40 / 0.75)  # Shigley Eq. (6-59) form


def test_endurance_estimates_by_class():
    assert endurance.estimate_fatigue_strength("2000 MPa").strength.m_as("MPa") == 700
    al = endurance.estimate_fatigue_strength("310 MPa", "aluminium")
    assert al.cycles == 5e8 and al.strength.m_as("MPa") == pytest.approx(124)
    with pytest.raises(InputError, match="S-N data"):
        endurance.estimate_fatigue_strength("50 MPa", "polymer")
    p = endurance.estimate_fatigue_strength("50 MPa", "PLA", polymer_fraction=0.2)
    assert p.strength.m_as("MPa") == pytest.approx(10) and "ASSUMED" in p.notes[0]
    with pytest.raises(UnknownNameError):
        endurance.estimate_fatigue_strength("50 MPa", "wood")


def test_basquin_curve_regions():
    c = life.BasquinCurve.from_ultimate("600 MPa", "250 MPa", f=0.9)
    assert c.stress_at(1e3).m_as("MPa") == pytest.approx(540)
    assert c.stress_at(1e7).m_as("MPa") == pytest.approx(250)
    assert c.life_at("240 MPa") == np.inf
    assert c.life_at("600 MPa") == 1.0
    assert c.life_at(c.stress_at(2e4)) == pytest.approx(2e4)
    assert c.life_at(c.stress_at(300)) == pytest.approx(300)
    with pytest.raises(InputError):
        life.BasquinCurve.from_ultimate("600 MPa", "700 MPa")
    with pytest.raises(InputError):
        life.miner_life([0.5, 0.4], ["300 MPa", "280 MPa"], c)


def test_miner_with_material_sn_table():
    sn = materials.get("Structural Steel").sn_curve
    res = life.miner_damage([("138 MPa", 5e4), ("114 MPa", 1e5), ("50 MPa", 1e9)], sn)
    assert res.damage == pytest.approx(0.5 + 0.5)
    assert res.blocks_to_failure == pytest.approx(1.0)


def test_von_mises_alternating_mean_uniaxial_and_shear():
    a, m = stress.von_mises_alternating_mean(Q([100, 0, 0, 0, 0, 0], "MPa"), Q([-100, 0, 0, 0, 0, 0], "MPa"))
    assert a.m_as("MPa") == pytest.approx(100) and m.m_as("MPa") == pytest.approx(0)
    a, m = stress.von_mises_alternating_mean(Q([0, 0, 0, 50, 0, 0], "MPa"), Q([0, 0, 0, 10, 0, 0], "MPa"), Kfs=1.5)
    assert a.m_as("MPa") == pytest.approx(np.sqrt(3) * 20 * 1.5)
    assert m.m_as("MPa") == pytest.approx(np.sqrt(3) * 30 * 1.5)
    sa, sm = stress.alternating_mean_of_history(Q([0, 80, -20, 40], "MPa"))
    assert (sa.m_as("MPa"), sm.m_as("MPa")) == (50, 30)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(-100, 100), min_size=2, max_size=40))
def test_rainflow_properties(h):
    """Every range is within the global range; the global range is always counted (ASTM E1049)."""
    assume(max(h) != min(h))
    cycles = rainflow(h)
    assert all(0 <= c.range <= max(h) - min(h) for c in cycles)
    assert any(c.range == max(h) - min(h) for c in cycles)
    assert all(c.count in (0.5, 1.0) for c in cycles)


def test_check_reproduces_fea_tool_default_ratio():
    """Fully reversed stress against the ANSYS Structural Steel S-N table: SF = 86.2 MPa / sigma_a."""
    r = check_fatigue("link", "70.2 MPa", "0 MPa", "Structural Steel")
    assert r.safety_factor == pytest.approx(86.2 / 70.2)
    assert r.details["governing_mode"] == "fatigue"
    assert any("S-N data used as given" in n for n in r.notes)


def test_check_polymer_warns_and_aluminium_needs_life():
    r = check_fatigue("pla link", "2 MPa", "2 MPa", "PLA (FDM, XY flat)", life=1e6)
    assert r.warnings and "ASSUMED" in r.warnings[0] and r.verdict.value in ("warn", "fail")
    with pytest.raises(InputError, match="no endurance limit"):
        check_fatigue("arm", "20 MPa", "0 MPa", "Aluminium 6061-T6")
    r = check_fatigue("arm", "20 MPa", "0 MPa", "Aluminium 6061-T6", life=1e7, marin={"finish": "machined"})
    assert r.safety_factor > 1


def test_check_steel_estimate_langer_governs_and_kf():
    r = check_fatigue("shaft", "30 MPa", "200 MPa", "AISI 1045 CD", marin={"finish": "machined", "d": "20 mm"})
    assert r.details["n_yield"] == pytest.approx(530 / 230)
    r2 = check_fatigue("shaft", "30 MPa", "20 MPa", "AISI 1045 CD", Kf=2.0, marin={"finish": "machined"})
    r1 = check_fatigue("shaft", "30 MPa", "20 MPa", "AISI 1045 CD", marin={"finish": "machined"})
    assert r2.details["n_fatigue"] == pytest.approx(r1.details["n_fatigue"] / 2)
    with pytest.raises(InputError, match="Kf"):
        check_fatigue("shaft", "30 MPa", "20 MPa", "AISI 1045 CD", Kf=0.5)


def test_field_check_governing_node_and_location():
    sa = Q(np.array([10.0, 60.0, 40.0]), "MPa")
    sm = Q(np.array([0.0, 10.0, 50.0]), "MPa")
    xyz = Q(np.array([[0, 0, 0], [1, 2, 3], [4, 5, 6]]), "mm")
    r = check_fatigue_field("link", sa, sm, "Structural Steel", coordinates=xyz)
    n = criteria.goodman.si(sa.m_as("Pa"), sm.m_as("Pa"), 86.2e6, 460e6)
    assert r.details["governing_node"] == int(np.argmin(n))
    assert r.safety_factor == pytest.approx(n.min())
    assert r.details["governing_location"].m_as("mm") == pytest.approx([1, 2, 3])
    with pytest.raises(InputError):
        check_fatigue_field("link", sa, sm[:2], "Structural Steel")
