"""Sections: the FE path agrees with the closed forms, principal axes by Mohr's circle, and input errors.

Closed forms: rectangle b h^3/12, b h^2/4 (plastic); Mohr's circle for a rotated rectangle
(I1, I2 = the unrotated values; angle = rotation).
"""

import math

import numpy as np
import pytest

from mechverify import Q
from mechverify.components import sections
from mechverify.errors import InputError, UnitError, UnknownNameError


def test_polygon_rectangle_matches_closed_form():
    p = sections.polygon([[0, 0], [30, 0], [30, 10], [0, 10]], unit="mm")
    r = sections.rectangle("30 mm", "10 mm")
    for attr in ("area", "Iy", "Iz", "Wel_y", "Wel_z", "Wpl_y", "Wpl_z"):
        assert getattr(p, attr).m_as("mm**4" if attr[0] == "I" else getattr(r, attr).units) == pytest.approx(
            getattr(r, attr).m_as("mm**4" if attr[0] == "I" else getattr(r, attr).units), rel=1e-9)
    assert p.J.m_as("mm**4") == pytest.approx(r.J.m_as("mm**4"), rel=0.01)
    assert p.Wt.m_as("mm**3") == pytest.approx(r.Wt.m_as("mm**3"), rel=0.03)
    # shear areas: sectionproperties (nu = 0) against Cowper/Timoshenko 5/6 A
    assert p.Asz.m_as("mm**2") == pytest.approx(5 / 6 * 300, rel=0.01)
    assert p.Asy.m_as("mm**2") == pytest.approx(5 / 6 * 300, rel=0.01)
    assert r.Asz.m_as("mm**2") == pytest.approx(5 / 6 * 300, rel=1e-12)


def test_rotated_rectangle_principal_axes():
    th = math.radians(30)
    R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    pts = (np.array([[-20, -5], [20, -5], [20, 5], [-20, 5]]) @ R.T).tolist()
    p = sections.polygon(pts, unit="mm")
    assert p.I1.m_as("mm**4") == pytest.approx(10 * 40**3 / 12, rel=1e-9)
    assert p.I2.m_as("mm**4") == pytest.approx(40 * 10**3 / 12, rel=1e-9)
    # I1 is about the long axis' normal... the axis of I1 is perpendicular to the 40 mm side
    assert math.degrees(p.principal_angle.m_as("rad")) % 180 == pytest.approx(120.0, abs=1e-6)
    assert p.Iyz.m_as("mm**4") != pytest.approx(0.0, abs=1.0)


def test_polygon_with_hole_and_make_section():
    s = sections.make_section("polygon", outline=[[0, 0], [40, 0], [40, 40], [0, 40]],
                              holes=[[[10, 10], [30, 10], [30, 30], [10, 30]]], unit="mm")
    assert s.area.m_as("mm**2") == pytest.approx(1600 - 400)
    assert s.Iy.m_as("mm**4") == pytest.approx((40**4 - 20**4) / 12)
    t = sections.make_section("CHS", outer_diameter="20 mm", thickness="2 mm")
    assert t.kind == "tube" and t is sections.make_section("pipe", outer_diameter="20 mm", thickness="2 mm")


def test_c_and_t_sections_shear_centre_and_centroid():
    c = sections.c_section("100 mm", "50 mm", "5 mm", "5 mm")
    # the shear centre of a channel lies outside the web, on the side away from the flanges
    assert c.shear_center_y.m_as("mm") < 0
    t = sections.t_section("60 mm", "60 mm", "6 mm", "6 mm")
    # centroid of the tee (flange on top): (60*6*57 + 54*6*27) / (360 + 324)
    assert t.centroid_z.m_as("mm") == pytest.approx((360 * 57 + 324 * 27) / 684, rel=1e-9)


def test_si_dict_for_fea():
    d = sections.rectangle("10 mm", "20 mm").si()
    assert d["Iy"] == pytest.approx(10e-3 * 20e-3**3 / 12)
    assert set(d) >= {"area", "Iy", "Iz", "Iyz", "J", "Asy", "Asz", "Wel_y", "Wpl_y", "c_z_pos"}


@pytest.mark.parametrize(("call", "exc", "match"), [
    (lambda: sections.rectangle("0 mm", "5 mm"), InputError, "width"),
    (lambda: sections.rectangle("-1 mm", "5 mm"), InputError, "width"),
    (lambda: sections.rectangle(10, "5 mm"), UnitError, "width"),
    (lambda: sections.tube("10 mm", "6 mm"), InputError, "thinner"),
    (lambda: sections.tube("10 mm"), InputError, "exactly one"),
    (lambda: sections.hollow_rectangle("10 mm", "20 mm", "5 mm"), InputError, "no hollow"),
    (lambda: sections.i_section("10 mm", "20 mm", "2 mm", "5 mm"), InputError, "do not fit"),
    (lambda: sections.l_section("10 mm", "20 mm", "12 mm"), InputError, "thickness"),
    (lambda: sections.polygon([[0, 0], [1, 1], [1, 0], [0, 1]], unit="mm"), InputError, "crosses itself"),
    (lambda: sections.polygon([[0, 0], [1, 0], [2, 0]], unit="mm"), InputError, "no area"),
    (lambda: sections.polygon([[0, 0], [10, 0], [10, 10], [0, 10]], holes=[[[8, 8], [12, 8], [12, 12], [8, 12]]],
                              unit="mm"), InputError, "not inside"),
    (lambda: sections.make_section("hollow_rectangel", width="1 mm"), UnknownNameError, "hollow_rectangle"),
    (lambda: sections.make_section("rectangle", widht="1 mm", height="1 mm"), InputError, "width"),
])
def test_errors(call, exc, match):
    with pytest.raises(exc, match=match):
        call()


def test_quantity_array_outline():
    s = sections.polygon(Q(np.array([[0, 0], [2, 0], [2, 1], [0, 1]]), "cm"))
    assert s.area.m_as("cm**2") == pytest.approx(2.0)
