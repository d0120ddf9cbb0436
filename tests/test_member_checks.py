"""Member checks: orientation of demand/capacity, Kt policy, BTH-1 factors, buckling, deflection limits, plates.

Hand values: a 33 x 6 mm eye with a 22 mm hole carries F on (33 - 22) x 6 = 66 mm^2;
Kt = 2.077 (Peterson Eq. (4.1) at d/w = 2/3). A 6 mm thick 200 x 200 mm simply supported square under 10 kPa gives
sigma = 0.2874 q b^2 / t^2 = 31.9 MPa (Roark 8th ed., Table 11.4 case 1a).
"""

import pytest

from mechverify import Q
from mechverify.checks.members import (
    check_eye_net_section,
    check_link_deflection,
    check_member_body_strength,
    check_member_buckling,
    check_pin_shear,
    deflection_check,
    deflection_limit,
    lug_checks,
)
from mechverify.checks.plates import check_plate_stress_roark
from mechverify.checks.result import Verdict
from mechverify.components import sections
from mechverify.components.links import Link
from mechverify.components.plates import Plate, corner_holes, roark_rectangular_plate
from mechverify.errors import InputError

EYE = dict(hole_diameter="22 mm", width="33 mm", thickness="6 mm", edge_distance="16.5 mm")


def link(material="PLA", **kw):
    return Link("100 mm", sections.rectangle("33 mm", "6 mm"), material, lug=EYE, name="link 3", **kw)


def test_body_strength_verdicts():
    r = check_member_body_strength(link(), axial="15 N", moment_y="0.5 N*m", required_sf=4)
    assert r.demand.m_as("MPa") == pytest.approx(15 / 198 + 500 / 198)
    assert r.capacity.m_as("MPa") == pytest.approx(26.0)
    assert r.verdict is Verdict.PASS
    assert check_member_body_strength(link(), moment_y="2 N*m", required_sf=4).verdict is Verdict.FAIL


def test_eye_kt_policy():
    brittle = check_eye_net_section(link(), "100 N")
    assert brittle.demand.m_as("MPa") == pytest.approx(100 / 66 * (2.0 + 0.284 / 3 - 0.600 / 9 + 1.32 / 27))
    assert brittle.warnings  # pin-loaded hole in a brittle material
    ductile = check_eye_net_section(link("AISI 1045 HR"), "100 N")  # 16 % elongation
    assert ductile.demand.m_as("MPa") == pytest.approx(100 / 66)
    assert "not applied" in " ".join(ductile.notes)
    forced = check_eye_net_section(link("AISI 1045 HR"), "100 N", apply_kt=True)
    assert forced.demand > ductile.demand
    unknown = check_eye_net_section(link("S235JR"), "100 N")  # no elongation in the record: Kt applied
    assert "unknown" in " ".join(unknown.notes)


def test_lug_checks_required_factors_and_material_warning():
    rs = lug_checks(link("S235JR"), "1 kN", design_factor=2.0)
    assert [r.check for r in rs] == ["lug_tension", "lug_fracture_beyond", "lug_shear_out", "lug_bearing"]
    assert [r.required_sf for r in rs] == [2.4, 2.4, 2.4, 2.0]
    assert all(not r.warnings for r in rs)
    assert all(r.warnings for r in lug_checks(link(), "10 N"))  # PLA: outside BTH-1's steel basis


def test_pin_shear_uses_0577_sy_without_shear_yield():
    r = check_pin_shear(link(), "1 kN", "S235JR", planes=2)
    assert r.demand.m_as("MPa") == pytest.approx(1000 / (2 * 3.14159265 * 11**2), rel=1e-6)
    assert r.capacity.m_as("MPa") == pytest.approx(0.577 * 235, rel=0.03)


def test_buckling_check():
    r = check_member_buckling(link(), "100 N", required_sf=4)
    assert r.capacity.m_as("N") == pytest.approx(link().buckling().critical_load.m_as("N"))
    assert r.verdict is Verdict.PASS
    t = check_member_buckling(link(), "-100 N")
    assert t.demand.m_as("N") == 0 and "tension" in " ".join(t.notes)


def test_deflection_limits():
    assert deflection_limit("1 mm").m_as("mm") == pytest.approx(1.0)
    assert deflection_limit(0.01, span="200 mm").m_as("mm") == pytest.approx(2.0)
    assert deflection_limit("L/250", span="500 mm").m_as("mm") == pytest.approx(2.0)
    with pytest.raises(InputError, match="give span"):
        deflection_limit("L/250")
    with pytest.raises(InputError, match=r"\(0, 1\)"):
        deflection_limit(2.0, span="1 m")
    r = deflection_check("3.3 mm", 0.01, span="268 mm", component="PLA arm")
    assert r.verdict is Verdict.FAIL and r.capacity.m_as("mm") == pytest.approx(2.68)
    d = check_link_deflection(link(), "cantilever_end_load", "1.5 N", "1 mm", axis="z")
    assert d.demand.m_as("mm") == pytest.approx(1.5 * 100**3 / (3 * 2539 * 33 * 6**3 / 12), rel=1e-9)


def test_plate_stress_check_warns_for_holes():
    p = Plate.rectangle("200 mm", "200 mm", "6 mm", "Inventor Aluminum 6061",
                        holes=corner_holes("200 mm", "200 mm", "10 mm", "5 mm"))
    est = roark_rectangular_plate("200 mm", "200 mm", "6 mm", p.material.E, "10 kPa")
    r = check_plate_stress_roark(p, est, required_sf=2)
    assert r.demand.m_as("MPa") == pytest.approx(0.2874 * 1e4 * 0.2**2 / 0.006**2 / 1e6, rel=1e-9)
    assert any("holes" in w for w in r.warnings)
    assert r.verdict is Verdict.WARN
    assert Q(0, "MPa") < r.capacity
