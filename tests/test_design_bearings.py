"""Design files with ball bearings and plain bushings: numbers against hand calculations from ISO 281:2007
(L10 = (C/P)^3, P = X Fr + Y Fa with Table 3), ISO 76 (P0, s0) and p = F/(dL), v, pv (Shigley 10th ed.
Sec. 12-15), with the SKF catalogue data of the 608 (C = 3.45 kN, C0 = 1.37 kN, f0 = 12, limiting speed
48 000 r/min; the same values as reference project 004, Tabla 9); errors with key paths."""

import textwrap

import pytest

from mechverify.design import DesignFileError, load
from mechverify.reports import render_html


def write(tmp_path, text):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(text))
    return p


LIFT = """
[design]
name = "lift bearing"
[requirements]
bearing_life = "10000 h"
[components.b]
type = "ball_bearing"
model = "608-2Z"
{extra}
[load_cases.raise.b]
axial_force = "350 N"
speed = "540 rpm"
[load_cases.side.b]
radial_force = "1 kN"
axial_force = "350 N"
speed = "100 rpm"
"""


def lift(tmp_path, extra=""):
    return load(write(tmp_path, LIFT.format(extra=extra)))


def test_axial_load_life_iso281_table3(tmp_path):
    """Fa = 350 N alone (seed 004's lift): f0 Fa/C0 = 12*350/1370 = 3.066; Table 3 between 2.07 (Y 1.31) and
    3.45 (Y 1.15): Y = 1.31 - 0.16 (3.066 - 2.07)/1.38 = 1.1946; Fa/Fr > e so P = 0.56*0 + Y*350 = 418.1 N;
    L10 = (3450/418.1)^3 = 562 Mrev; at 540 r/min L10h = L10/(60*540) = 17 300 h."""
    rs = lift(tmp_path).verify()
    Y = 1.31 - 0.16 * (12 * 350 / 1370 - 2.07) / (3.45 - 2.07)
    P = Y * 350
    L10h = (3450 / P) ** 3 * 1e6 / (60 * 540)
    assert L10h == pytest.approx(17300, rel=3e-3)
    assert rs.get("b", "bearing_life").load_case == "side"  # the shorter life governs (next test)
    raise_only = load(write(tmp_path, LIFT.format(extra="").split("[load_cases.side.b]")[0])).verify()
    r = raise_only.get("b", "bearing_life")
    assert r.details["P"].m_as("N") == pytest.approx(P, rel=1e-4)
    assert r.capacity.m_as("hour") == pytest.approx(L10h, rel=1e-4)
    assert r.demand.m_as("hour") == 10000 and r.required_sf == 1.0
    assert any("0.25 C0" in w for w in r.warnings)  # 350 N > 0.25*1370 = 342.5 N (SKF guideline)


def test_combined_load_uses_x_y_only_beyond_e(tmp_path):
    """Fr = 1 kN, Fa = 350 N: f0 Fa/C0 = 3.066 gives e = 0.34 + 0.04 (3.066 - 2.07)/1.38 = 0.3689;
    Fa/Fr = 0.35 <= e, so X = 1, Y = 0: P = Fr = 1000 N; L10 = 3.45^3 = 41.06 Mrev; at 100 r/min
    L10h = 41.06e6/6000 = 6843 h < 10 000 h: fails. ISO 76: P0 = max(0.6*1000 + 0.5*350, 1000) = 1000 N."""
    e = 0.34 + 0.04 * (12 * 350 / 1370 - 2.07) / 1.38
    assert 350 / 1000 <= e
    rs = lift(tmp_path).verify()
    r = rs.get("b", "bearing_life")
    assert r.load_case == "side"
    assert r.details["P"].m_as("N") == pytest.approx(1000)
    assert r.capacity.m_as("hour") == pytest.approx(3.45**3 * 1e6 / (60 * 100), rel=1e-6)
    assert r.verdict == "fail"
    s0 = rs.get("b", "bearing_static_safety")
    assert s0.demand.m_as("N") == pytest.approx(1000) and s0.capacity.m_as("N") == pytest.approx(1370)
    speed = rs.get("b", "bearing_speed")
    assert speed.demand.m_as("rpm") == pytest.approx(540) and speed.capacity.m_as("rpm") == pytest.approx(48000)
    assert speed.required_sf == 1.25


def test_component_required_life_and_reliability(tmp_path):
    """required_life overrides requirements.bearing_life; reliability 0.99 gives a1 = 0.25 (ISO 281 Table 12)."""
    text = LIFT.format(extra='required_life = "2000 h"\nreliability = 0.99').split("[load_cases.side.b]")[0]
    r = load(write(tmp_path, text)).verify().get("b", "bearing_life")
    Y = 1.31 - 0.16 * (12 * 350 / 1370 - 2.07) / 1.38
    assert r.demand.m_as("hour") == 2000
    assert r.capacity.m_as("hour") == pytest.approx(0.25 * (3450 / (Y * 350)) ** 3 * 1e6 / (60 * 540), rel=1e-4)
    assert any("component's required_life" in n for n in r.notes)


def test_catalogue_overrides(tmp_path):
    """dynamic_load_rating replaces the catalogue C: L10 = (C/P)^3 with C = 3 kN, P = Fr = 1 kN -> 27 Mrev."""
    text = LIFT.format(extra='dynamic_load_rating = "3 kN"\nlimiting_speed = "20000 rpm"')
    rs = load(write(tmp_path, text)).verify()
    assert rs.get("b", "bearing_life").capacity.m_as("hour") == pytest.approx(27e6 / 6000)
    assert rs.get("b", "bearing_speed").capacity.m_as("rpm") == pytest.approx(20000)


def test_plain_bushing_p_v_pv(tmp_path):
    """d = 10 mm, L = 10 mm, F = 100 N: p = F/(dL) = 1 MPa; shaft at 600 r/min: v = pi d n = 0.3142 m/s;
    pv = 0.3142 MPa m/s against 0.34 (Shigley 10th ed. Sec. 12-15)."""
    text = """
    [design]
    name = "bush"
    [components.g]
    type = "plain_bushing"
    bore = "10 mm"
    length = "10 mm"
    p_max = "60 MPa"
    v_max = "1 m/s"
    pv_max = "0.34 MPa*m/s"
    [load_cases.run.g]
    radial_force = "100 N"
    speed = "600 rpm"
    """
    rs = load(write(tmp_path, text)).verify()
    v = 3.141592653589793 * 0.010 * 600 / 60
    assert rs.get("g", "bushing_pressure").demand.m_as("MPa") == pytest.approx(1.0)
    assert rs.get("g", "bushing_pressure").capacity.m_as("MPa") == pytest.approx(60)
    assert rs.get("g", "bushing_velocity").demand.m_as("m/s") == pytest.approx(v)
    pv = rs.get("g", "bushing_pv")
    assert pv.demand.m_as("MPa*m/s") == pytest.approx(v)
    assert pv.capacity.m_as("MPa*m/s") == pytest.approx(0.34)
    assert pv.verdict == "warn"  # 0.314/0.34 = 0.92 > 0.9


def test_plain_bushing_limits_from_material(tmp_path):
    """iglidur J (igus data in the material library): p_max = 5076 psi = 35.0 MPa, pv_max =
    9700 psi*ft/min = 0.3397 MPa m/s; F = 40 N on 8 x 12 mm: p = 0.4167 MPa; v = 0.05 m/s."""
    text = """
    [design]
    name = "guide"
    [components.g]
    type = "plain_bushing"
    bore = "8 mm"
    length = "12 mm"
    material = "iglidur J"
    [components.g.checks]
    velocity = false
    [load_cases.run.g]
    radial_force = "40 N"
    sliding_speed = "0.05 m/s"
    """
    rs = load(write(tmp_path, text)).verify()
    p = rs.get("g", "bushing_pressure")
    assert p.capacity.m_as("MPa") == pytest.approx(5076 * 6894.757e-6, rel=1e-6)
    assert p.demand.m_as("MPa") == pytest.approx(40 / (8 * 12))
    pv = rs.get("g", "bushing_pv")
    assert pv.capacity.m_as("MPa*m/s") == pytest.approx(9700 * 6894.757e-6 * 0.3048 / 60, rel=1e-6)
    assert pv.demand.m_as("MPa*m/s") == pytest.approx(40 / 96 * 0.05)


def test_bearing_errors_name_their_key(tmp_path):
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, LIFT.format(extra="").replace('"608-2Z"', '"609-2Z"')))
    assert any(p == "components.b" and "609" in m and "608" in m for p, m in exc.value.errors), exc.value.errors
    with pytest.raises(DesignFileError) as exc:
        lift(tmp_path, extra="reliability = 0.5")
    assert any(p == "components.b.reliability" and "0.90 .. 0.9995" in m for p, m in exc.value.errors)
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, LIFT.format(extra="").replace('speed = "540 rpm"', 'speed = "540 N"')))
    assert any(p == "load_cases.raise.b.speed" for p, _ in exc.value.errors)
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, LIFT.format(extra="").replace('axial_force = "350 N"\nspeed = "540 rpm"',
                                                           'axial_force = "-350 N"\nspeed = "540 rpm"'))).verify()
    assert any(p.startswith("components.b.checks.") and "axial_force must be >= 0" in m
               for p, m in exc.value.errors), exc.value.errors
    text = """
    [design]
    name = "bush"
    [components.g]
    type = "plain_bushing"
    bore = "8 mm"
    length = "12 mm"
    material = "iglidur J"
    [load_cases.run.g]
    radial_force = "40 N"
    sliding_speed = "0.05 m/s"
    """
    with pytest.raises(DesignFileError) as exc:  # iglidur J has no v_max in the library
        load(write(tmp_path, text)).verify()
    assert any(p == "components.g.checks.bushing_velocity [run]" and "v_max" in m for p, m in exc.value.errors)


def test_catalogue_listing_has_each_bearing_once():
    """bearing_catalogue() (for `mechverify bearings`): each row once, aliases kept on the row; the 608 row is
    SKF's (8 x 22 x 7 mm, C = 3.45 kN, C0 = 1.37 kN, as quoted in seed 004, Tabla 9)."""
    from mechverify.components.bearings import bearing_catalogue, bearing_names

    rows = bearing_catalogue()
    names = [b.designation for b in rows]
    assert len(names) == len(set(names)) and set(names) <= set(bearing_names())
    assert set(bearing_names()) == set(names) | {a for b in rows for a in b.aliases}
    b608 = rows[names.index("608")]
    assert (b608.d.m_as("mm"), b608.D.m_as("mm"), b608.B.m_as("mm")) == (8, 22, 7)
    assert (b608.C.m_as("kN"), b608.C0.m_as("kN")) == (3.45, 1.37)


def test_report_draws_life_over_load(tmp_path):
    design = lift(tmp_path)
    html = render_html([(design, design.verify())], date="2025-01-01")
    assert 'class="latex"' not in html
    assert "Figure: Bearing rating life" in html
