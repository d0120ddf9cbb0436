"""Links: stresses by hand for a 33 x 6 mm bar, buckling through columns.py, input errors.

Hand values (elementary beam theory): A = 198 mm^2, Wel_y = 33*6^2/6 = 198 mm^3, so 15 N axial gives
0.0758 MPa and 0.5 N m about y gives 2.525 MPa; Wt of a 33 x 6 rectangle = k2 h b^2 with k2(5.5) ~ 0.294.
"""

import math

import pytest

from mechverify import Q
from mechverify.components import sections
from mechverify.components.links import Link, Lug, bearing_stress, pin_shear_stress
from mechverify.errors import InputError, UnitError, UnknownNameError

EYE = dict(hole_diameter="22 mm", width="33 mm", thickness="6 mm", edge_distance="16.5 mm")


def pla_link(**kw):
    return Link("100 mm", sections.rectangle("33 mm", "6 mm"), "PLA", lug=EYE, **kw)


def test_body_stresses():
    s = pla_link().stresses(axial="15 N", moment_y="0.5 N*m", torque="0.1 N*m")
    assert s.axial.m_as("MPa") == pytest.approx(15 / 198)
    assert s.bending.m_as("MPa") == pytest.approx(500 / 198)
    tau = 100 / sections.rectangle("33 mm", "6 mm").Wt.m_as("mm**3")
    assert s.torsion.m_as("MPa") == pytest.approx(tau)
    assert s.von_mises.m_as("MPa") == pytest.approx(math.sqrt((15 / 198 + 500 / 198) ** 2 + 3 * tau**2))


def test_eye_and_pin():
    link = pla_link()
    assert link.pin_diameter == Q(22, "mm")
    assert link.eye_net_stress("110 N").m_as("MPa") == pytest.approx(110 / (11 * 6))
    assert link.eye_kt().m_as("") == pytest.approx(2.0 + 0.284 / 3 - 0.600 / 9 + 1.32 / 27)  # Peterson Eq. (4.1)
    assert pin_shear_stress("100 N", "5 mm", planes=2).m_as("MPa") == pytest.approx(100 / (2 * math.pi * 6.25))
    assert bearing_stress("100 N", "5 mm", "4 mm").m_as("MPa") == pytest.approx(5.0)
    assert link.is_brittle is True  # printed PLA, 1 % elongation


def test_buckling_uses_least_axis_and_strength_factor():
    link = pla_link(strength_factor=0.5, print_orientation="upright (Z)")
    b = link.buckling()
    sec = link.section
    assert b.radius_of_gyration.m_as("mm") == pytest.approx(6 / math.sqrt(12))
    assert link.yield_strength.m_as("MPa") == pytest.approx(13.0)
    # knocked-down Sy = 13 MPa: (l/k)_1 = sqrt(2 pi^2 E / Sy) = 62.1 > l/k = 57.7, a Johnson column
    assert b.regime == "johnson"
    lk = 100 / (6 / math.sqrt(12))
    assert b.critical_load.m_as("N") == pytest.approx(198 * (13 - (13 * lk / (2 * math.pi)) ** 2 / 2539))
    assert pla_link().buckling().regime == "euler"  # full 26 MPa: (l/k)_1 = 43.9 < 57.7
    assert pla_link().buckling().critical_load.m_as("N") == pytest.approx(
        math.pi**2 * 2539e6 * sec.I2.m_as("m**4") / 0.1**2)


def test_section_and_lug_from_tables():
    link = Link("80 mm", {"kind": "tube", "outer_diameter": "10 mm", "thickness": "1 mm"}, "S235JR",
                lug={"hole_diameter": "4 mm", "width": "10 mm", "thickness": "2 mm", "edge_distance": "6 mm"},
                pin_diameter="3.9 mm")
    assert link.section.kind == "tube"
    assert link.lug_strength().Cr < 1


@pytest.mark.parametrize(("call", "exc", "match"), [
    (lambda: Lug("22 mm", "20 mm", "6 mm", "16 mm"), InputError, "smaller than the lug width"),
    (lambda: Lug("22 mm", "33 mm", "6 mm", "10 mm"), InputError, "break through"),
    (lambda: Lug("22 mm", "33 mm", "0 mm", "16 mm"), InputError, "thickness"),
    (lambda: pla_link(strength_factor=1.5), InputError, "strength_factor"),
    (lambda: pla_link(pin_diameter="23 mm"), InputError, "exceeds the hole"),
    (lambda: pla_link(end="fixed-fre"), UnknownNameError, "fixed-free"),
    (lambda: Link("30 mm", sections.rectangle("33 mm", "6 mm"), "PLA", lug=EYE), InputError, "overlap"),
    (lambda: Link(100, sections.rectangle("33 mm", "6 mm"), "PLA"), UnitError, "length"),
    (lambda: Link("100 mm", sections.rectangle("33 mm", "6 mm"), "PLAA"), UnknownNameError, "PLA"),
    (lambda: pla_link().deflection("cantilever_end_lod", "1 N"), UnknownNameError, "cantilever_end_load"),
])
def test_errors(call, exc, match):
    with pytest.raises(exc, match=match):
        call()
