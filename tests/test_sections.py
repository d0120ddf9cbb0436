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


# ------------------------------------------------------------------ closed forms without sectionproperties
def test_sharp_i_section_closed_forms():
    """Roark 8th ed. Table A.1 (I-section): A = b h - (b - tw)(h - 2 tf), Iy = [b h^3 - (b - tw)(h - 2 tf)^3] / 12,
    Wpl_y = b h^2/4 - (b - tw)(h - 2 tf)^2/4; hand calculations from these formulas, not printed values."""
    h, b, tw, tf = 100.0, 60.0, 4.0, 6.0
    s = sections.i_section(f"{h} mm", f"{b} mm", f"{tw} mm", f"{tf} mm")
    assert s.area.m_as("mm**2") == pytest.approx(b * h - (b - tw) * (h - 2 * tf), rel=1e-12)
    assert s.Iy.m_as("mm**4") == pytest.approx((b * h**3 - (b - tw) * (h - 2 * tf) ** 3) / 12, rel=1e-12)
    assert s.Iz.m_as("mm**4") == pytest.approx((2 * tf * b**3 + (h - 2 * tf) * tw**3) / 12, rel=1e-12)
    assert s.Wpl_y.m_as("mm**3") == pytest.approx(b * h**2 / 4 - (b - tw) * (h - 2 * tf) ** 2 / 4, rel=1e-9)
    assert s.Wpl_z.m_as("mm**3") == pytest.approx(2 * tf * b**2 / 4 + (h - 2 * tf) * tw**2 / 4, rel=1e-9)
    # Roark Table 10.7, I-section without fillets: J = 2 K1 + K2 + 2 alpha D^4 (hand calculation)
    K1 = b * tf**3 * (1 / 3 - 0.21 * tf / b * (1 - tf**4 / (12 * b**4)))
    K2 = (h - 2 * tf) * tw**3 / 3
    alpha, D = tw / tf * 0.15, (tf**2 + tw * tw / 4) / tf
    assert s.J.m_as("mm**4") == pytest.approx(2 * K1 + K2 + 2 * alpha * D**4, rel=1e-12)
    assert s.method.startswith("closed form")


def test_channel_shear_centre_hand_calculation():
    """Thin-walled channel: e = 3 b'^2 tf / (6 b' tf + h' tw) from the web mid-line (b' = b - tw/2, h' = h - tf);
    hand calculation for 100 x 50 x 5 x 5: b' = 47.5, h' = 95 -> e = 33843.75 / 1900 = 17.81 mm."""
    c = sections.c_section("100 mm", "50 mm", "5 mm", "5 mm")
    assert c.shear_center_y.m_as("mm") == pytest.approx(2.5 - 3 * 47.5**2 * 5 / (6 * 47.5 * 5 + 95 * 5), rel=1e-12)
    assert c.shear_center_z.m_as("mm") == pytest.approx(50.0)


def test_channel_shear_area_thin_walled_shear_flow():
    """Thin-walled channel, vertical shear: As = I'^2 / integral(Q^2 / t ds) (Pilkey Sec. 2.8) with the mid-line
    I' = tw h'^3/12 + 2 b' tf (h'/2)^2, flanges contributing tf h'^2 b'^3 / 6 and the web
    (Q0^2 h' + Q0 tw h'^3/6 + tw^2 h'^5/120) / tw, Q0 = tf b' h'/2 (hand calculation, not a printed value)."""
    h, b, tw, tf = 100.0, 50.0, 4.0, 6.0
    bp, hp = b - tw / 2, h - tf
    I = tw * hp**3 / 12 + 2 * bp * tf * (hp / 2) ** 2
    Q0 = tf * bp * hp / 2
    integral = tf * hp**2 * bp**3 / 6 + (Q0**2 * hp + Q0 * tw * hp**3 / 6 + tw**2 * hp**5 / 120) / tw
    c = sections.c_section(f"{h} mm", f"{b} mm", f"{tw} mm", f"{tf} mm")
    assert c.Asz.m_as("mm**2") == pytest.approx(I**2 / integral, rel=1e-12)


def test_hollow_rectangle_bredt():
    """EN 10219-2 Annex B with sharp corners: It = t^3 p/3 + 2 K Ah, K = 2 Ah t / p (hand calculation);
    for a thin wall it tends to Bredt's 4 Ah^2 t / p (Roark 8th ed. Table 10.7)."""
    s = sections.hollow_rectangle("40 mm", "60 mm", "3 mm")
    Ah, p, t = 37 * 57, 2 * (37 + 57), 3.0
    assert s.J.m_as("mm**4") == pytest.approx(t**3 * p / 3 + 4 * Ah**2 * t / p, rel=1e-12)
    assert s.area.m_as("mm**2") == pytest.approx(40 * 60 - 34 * 54, rel=1e-12)
    assert s.Iy.m_as("mm**4") == pytest.approx((40 * 60**3 - 34 * 54**3) / 12, rel=1e-12)


# Agreement with sectionproperties' warping analysis (fine mesh, 16-point fillets), measured 2026-11-24:
# geometric and plastic properties to 1e-5; J: IPE 200 +2.3 %, sharp I +0.8 %, sharp T +1.1 %, T with fillets +14 %,
# L 50x50x5 +4.3 %, sharp L -0.8 %, sharp C +0.9 %, UPE-like C -0.8 %, sharp RHS -2.5 %, rounded SHS -0.3 %.
# Shear areas: Cowper for I and box -2 ... -11 %; thin-walled shear flow for T and C -3 ... -6 % (sharp corners),
# -11 ... -16 % with fillets (not counted); Jourawski strips for L +4 ... +16 % (the strips gave +45 % for a
# channel's flange-direction shear before the shear flow replaced them). Wt with fillets -7 ... +19 %; at sharp
# re-entrant corners the exact stress is singular, so Wt is not compared there.
SP_CASES = [
    ("i_section", dict(height="200 mm", width="100 mm", web_thickness="5.6 mm", flange_thickness="8.5 mm",
                       root_radius="12 mm"), 0.03),
    ("i_section", dict(height="100 mm", width="60 mm", web_thickness="4 mm", flange_thickness="6 mm"), 0.02),
    ("t_section", dict(height="60 mm", width="60 mm", web_thickness="6 mm", flange_thickness="6 mm"), 0.02),
    ("t_section", dict(height="60 mm", width="60 mm", web_thickness="7 mm", flange_thickness="7 mm",
                       root_radius="7 mm"), 0.15),
    ("l_section", dict(height="50 mm", width="50 mm", thickness="5 mm", root_radius="7 mm", toe_radius="3.5 mm"), 0.05),
    ("l_section", dict(height="60 mm", width="40 mm", thickness="5 mm"), 0.02),
    ("c_section", dict(height="100 mm", width="50 mm", web_thickness="5 mm", flange_thickness="5 mm"), 0.02),
    ("c_section", dict(height="100 mm", width="55 mm", web_thickness="4.5 mm", flange_thickness="7.5 mm",
                       root_radius="10 mm"), 0.02),
    ("hollow_rectangle", dict(width="40 mm", height="60 mm", thickness="3 mm"), 0.03),
    ("hollow_rectangle", dict(width="100 mm", height="100 mm", thickness="5 mm", outer_radius="10 mm"), 0.01),
]


def _sp_reference(kind, kw):
    lib = pytest.importorskip("sectionproperties.pre.library")

    def f(k):
        return sections._dim(kw.get(k, "0 mm"), k, allow_zero=True) * 1e3

    make = {
        "i_section": lambda m: lib.i_section(d=f("height"), b=f("width"), t_f=f("flange_thickness"),
                                             t_w=f("web_thickness"), r=f("root_radius"), n_r=48, material=m),
        "t_section": lambda m: lib.tee_section(d=f("height"), b=f("width"), t_f=f("flange_thickness"),
                                               t_w=f("web_thickness"), r=f("root_radius"), n_r=48, material=m),
        "l_section": lambda m: lib.angle_section(d=f("height"), b=f("width"), t=f("thickness"), r_r=f("root_radius"),
                                                 r_t=f("toe_radius"), n_r=48, material=m),
        "c_section": lambda m: lib.channel_section(d=f("height"), b=f("width"), t_f=f("flange_thickness"),
                                                   t_w=f("web_thickness"), r=f("root_radius"), n_r=48, material=m),
        "hollow_rectangle": lambda m: lib.rectangular_hollow_section(d=f("height"), b=f("width"), t=f("thickness"),
                                                                     r_out=f("outer_radius"), n_r=48, material=m),
    }[kind]
    return sections._analyse(kind, {}, make, 300)


@pytest.mark.parametrize(("kind", "kw", "j_rel"), SP_CASES)
def test_closed_forms_against_sectionproperties(kind, kw, j_rel):
    """The closed forms against sectionproperties' finite-element warping analysis (test dependency only)."""
    s = sections.make_section(kind, **kw)
    r = _sp_reference(kind, kw)
    for attr in ("area", "Iy", "Iz", "I1", "I2", "Wel_y", "Wel_z", "Wpl_y", "Wpl_z"):
        assert getattr(s, attr).to_base_units().m == pytest.approx(getattr(r, attr).to_base_units().m, rel=1e-4), attr
    for attr in ("centroid_y", "centroid_z"):
        assert getattr(s, attr).m_as("mm") == pytest.approx(getattr(r, attr).m_as("mm"), abs=1e-3), attr
    assert s.Iyz.m_as("mm**4") == pytest.approx(r.Iyz.m_as("mm**4"), abs=1e-4 * s.I1.m_as("mm**4"))
    assert s.principal_angle.m_as("deg") % 180 == pytest.approx(r.principal_angle.m_as("deg") % 180, abs=0.05) \
        or abs(s.Iyz.m_as("mm**4")) < 1e-6 * s.I1.m_as("mm**4")
    assert s.J.m_as("mm**4") == pytest.approx(r.J.m_as("mm**4"), rel=j_rel)
    # thin-walled shear centre within 2 mm (a small fraction of the section) of the exact one
    assert s.shear_center_y.m_as("mm") == pytest.approx(r.shear_center_y.m_as("mm"), abs=2.0)
    assert s.shear_center_z.m_as("mm") == pytest.approx(r.shear_center_z.m_as("mm"), abs=2.0)
    assert 0.85 < s.Asz.m_as("mm**2") / r.Asz.m_as("mm**2") < 1.25


def test_polygon_without_sectionproperties_names_the_extra(monkeypatch):
    """A polygon section needs the optional extra; the error names the pip command."""
    import sys

    from mechverify.errors import ModelError

    monkeypatch.setitem(sys.modules, "sectionproperties", None)
    monkeypatch.setitem(sys.modules, "sectionproperties.pre.geometry", None)
    with pytest.raises(ModelError, match=r"scripts/install\.sh -e '\.\[sections\]'"):
        sections.polygon([[0, 0], [30, 0], [30, 10], [0, 10]], unit="mm")
    # the closed-form kinds do not need it
    assert sections.i_section("100 mm", "50 mm", "4 mm", "6 mm").area.m_as("mm**2") > 0


def test_fillet_outline_area():
    """A root fillet adds (1 - pi/4) r^2 per corner: IPE 200 area = h b - ... hand calculation
    A = 2 b tf + (h - 2 tf) tw + (4 - pi) r^2 = 2848.3 mm^2 (catalogue 28.48 cm^2)."""
    s = sections.i_section("200 mm", "100 mm", "5.6 mm", "8.5 mm", root_radius="12 mm")
    # rel 1e-4: each fillet arc is a polygon of 48 chords (area error ~ r^2 n theta^3 / 12 = 0.02 mm^2 each)
    assert s.area.m_as("mm**2") == pytest.approx(2 * 100 * 8.5 + 183 * 5.6 + (4 - math.pi) * 144, rel=1e-4)
    assert s.geometry.area == pytest.approx(s.area.m_as("m**2"), rel=1e-12)  # shapely built on demand
