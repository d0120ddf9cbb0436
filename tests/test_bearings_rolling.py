"""Angular contact (single and matched pairs), thrust ball, cylindrical and needle roller bearings: the maker's
equivalent-load rules, bad input, checks with substituted lines, and the design-file types."""

from __future__ import annotations

import pytest
from test_reports_substituted import assert_substituted

from mechverify.checks import bearings as bc
from mechverify.components.bearings import Lubrication
from mechverify.components.bearings_rolling import rolling_bearing, rolling_bearing_names
from mechverify.errors import InputError, UnknownNameError, ValidityError


def test_angular_contact_single_factors_fgfa_row():
    """Row 7206 B verified against the fgfa.com.cn product page (C 22.5, C0 14.3 kN; e 1.14, X 0.35, Y2 0.57,
    Y0 0.26). Hand: Fr 2, Fa 3 kN: Fa/Fr = 1.5 > 1.14 -> P = 0.35(2) + 0.57(3) = 2.41 kN; P0 = max(0.5(2) +
    0.26(3), 2) = 2 kN; Fa/Fr = 0.5 -> P = Fr."""
    b = rolling_bearing("7206 B")
    assert not b.unverified
    assert b.equivalent_load("2 kN", "3 kN").P.m_as("kN") == pytest.approx(2.41)
    assert b.equivalent_load("2 kN", "1 kN").P.m_as("kN") == pytest.approx(2.0)
    assert b.static_load("2 kN", "3 kN").m_as("kN") == pytest.approx(2.0)
    assert b.induced_axial_force("2 kN").m_as("kN") == pytest.approx(2.28)


def test_matched_pair_ratings_and_factors():
    """SKF 17000 (load carrying capacity of bearing pairs): C = 1.62 C, C0 = 2 C0; back-to-back P = Fr + Y1 Fa
    below e (hand: 2 + 0.55 x 1 = 2.55 kN), X2 Fr + Y2 Fa above (0.57 x 2 + 0.93 x 3 = 3.93 kN). The pair factors
    are not verified: the pair carries the warning text."""
    p = rolling_bearing("7206 B", "back_to_back")
    assert p.C.m_as("kN") == pytest.approx(1.62 * 22.5) and p.C0.m_as("kN") == pytest.approx(28.6)
    assert p.equivalent_load("2 kN", "1 kN").P.m_as("kN") == pytest.approx(2.55)
    assert p.equivalent_load("2 kN", "3 kN").P.m_as("kN") == pytest.approx(3.93)
    assert "pair factors" in p.unverified
    t = rolling_bearing("7206 B", "tandem")
    assert t.equivalent_load("2 kN", "3 kN").P.m_as("kN") == pytest.approx(2.41)  # single-bearing factors
    with pytest.raises(InputError):
        rolling_bearing("30205", "back_to_back")
    with pytest.raises(UnknownNameError):
        rolling_bearing("7206 B", "sideways")


def test_thrust_cylindrical_needle_rules():
    """Thrust ball: P = Fa, no radial load; NU and needle: P = Fr, no axial load; NJ locating: P = 0.92 Fr + 0.6 Fa
    above e = 0.2 (SKF; honghui188 table). Life exponent 10/3 for rollers."""
    th = rolling_bearing("51105")
    assert th.equivalent_load("0 N", "3 kN").P.m_as("kN") == pytest.approx(3.0)
    with pytest.raises(ValidityError, match="no radial load"):
        th.equivalent_load("1 kN", "3 kN")
    nu = rolling_bearing("NU205")
    with pytest.raises(ValidityError, match="no axial load"):
        nu.equivalent_load("1 kN", "0.1 kN")
    assert nu.life_exponent == pytest.approx(10 / 3)
    nj = rolling_bearing("NJ 205")
    assert nj.equivalent_load("10 kN", "3 kN").P.m_as("kN") == pytest.approx(0.92 * 10 + 0.6 * 3)
    assert nj.equivalent_load("10 kN", "1 kN").P.m_as("kN") == pytest.approx(10)
    with pytest.raises(UnknownNameError):
        rolling_bearing("99999")
    assert "30205" in rolling_bearing_names()


def test_checks_on_new_types_with_substituted_lines():
    """bearing_life (exponent 10/3 for the roller), static safety and speed on the new types; each substituted
    line evaluates back to the result; unverified rows warn."""
    nu = rolling_bearing("NU 205 ECP")
    r = bc.check_bearing_life(nu, "5 kN", "0 N", "1000 rpm", "10000 h")
    L = (28.6 / 5) ** (10 / 3) * 1e6 / 1000 / 60
    assert r.capacity.m_as("hour") == pytest.approx(L, rel=1e-9)
    rs = [r, bc.check_bearing_static_safety(nu, "5 kN"), bc.check_bearing_speed(nu, "1000 rpm"),
          bc.check_bearing_life(rolling_bearing("51105"), "0 N", "2 kN", "500 rpm", "1000 h"),
          bc.check_bearing_static_safety(rolling_bearing("7206 B", "face_to_face"), "2 kN", "3 kN")]
    for x in rs:
        assert_substituted(x)
    assert any("not verified" in w for w in bc.check_bearing_speed(nu, "1000 rpm").warnings)


def test_modified_life_angular_contact_and_thrust_refused():
    """The ISO 281 radial-ball a_ISO applies to angular contact ball bearings (roller types: the radial-roller a_ISO,
    tests/test_bearings_iso281_roller.py); for thrust types it is refused (ValidityError naming the alternative)."""
    lub = Lubrication(iso_vg=68, viscosity_index=95, operating_temperature="60 degC")
    r = bc.check_bearing_modified_life(rolling_bearing("7206 B"), "2 kN", "1 kN", "1500 rpm", "10000 h", lub)
    assert r.details["a_iso"] > 0
    assert any("radial ball" in n for n in r.notes)
    assert_substituted(r)
    with pytest.raises(ValidityError, match="thrust ball.*bearing_life"):
        bc.check_bearing_modified_life(rolling_bearing("51105"), "0 N", "2 kN", "500 rpm", "10000 h", lub)


DESIGN = """
[design]
name = "rolling types"
[requirements]
bearing_life = "20000 h"
[components.spindle]
type = "rolling_bearing"
model = "7206 B"
arrangement = "back_to_back"
[components.roller]
type = "rolling_bearing"
model = "NU 205 ECP"
[components.pinion_shaft]
type = "adjusted_bearing_pair"
model = "30205"
rule = "timken"
K = 1.5
[load_cases.run.spindle]
radial_force = "2 kN"
axial_force = "1 kN"
speed = "1500 rpm"
[load_cases.run.roller]
radial_force = "5 kN"
speed = "1500 rpm"
[load_cases.run.pinion_shaft]
radial_force_A = "2.492 kN"
radial_force_B = "4.873 kN"
speed = "300 rpm"
"""


def test_design_file_types(tmp_path):
    """The two design-file types run bearing_life, static safety and speed; the pair's life is the worse bearing
    (B, P = 4.873 kN) with the induced forces in the notes."""
    from mechverify.design import load

    p = tmp_path / "d.toml"
    p.write_text(DESIGN)
    rs = {(r.component, r.check): r for r in load(p).verify()}
    life = rs[("pinion_shaft", "bearing_life")]
    assert any("bearing B governs" in n for n in life.notes)
    L = (38.0 / 4.873) ** (10 / 3) * 1e6 / 300 / 60
    assert life.capacity.m_as("hour") == pytest.approx(L, rel=1e-9)
    assert rs[("spindle", "bearing_life")].details["P"].m_as("kN") == pytest.approx(2.55)
    assert ("roller", "bearing_static_safety") in rs


def test_design_file_bad_input(tmp_path):
    """A thrust bearing in an adjusted pair and a pair arrangement on a roller bearing are named errors."""
    from mechverify.design import load
    from mechverify.design.loader import DesignFileError

    bad = DESIGN.replace('model = "30205"', 'model = "51105"')
    p = tmp_path / "bad.toml"
    p.write_text(bad)
    with pytest.raises((DesignFileError, InputError), match="adjusted pairs"):
        load(p).verify()
    bad2 = DESIGN.replace('model = "NU 205 ECP"', 'model = "NU 205 ECP"\narrangement = "tandem"')
    p.write_text(bad2)
    with pytest.raises((DesignFileError, InputError), match="matched-pair"):
        load(p).verify()


def test_select_rolling_bearing_by_life():
    """Smallest tapered roller bearing for Fr = 5 kN at 1000 rpm: 30205 (C 38 kN) gives (38/5)^(10/3) 10^6/60000
    = 14 384 h (hand calculation), so it is chosen for 10 000 h, and 30206 (C 49.5 kN) alone for 30 000 h; none of a
    thrust bearing under a radial load; none beyond the catalogue."""
    from mechverify.components.bearings_rolling import select_rolling_bearing

    assert (38 / 5) ** (10 / 3) * 1e6 / 60000 == pytest.approx(14384, rel=1e-3)
    sel = select_rolling_bearing("tapered_roller", "5 kN", "0 N", "1000 rpm", "10000 h")
    assert [b.designation for b in sel] == ["30205", "30206"]
    sel = select_rolling_bearing("tapered_roller", "5 kN", "0 N", "1000 rpm", "30000 h")
    assert [b.designation for b in sel] == ["30206"]
    assert select_rolling_bearing("thrust_ball", "1 kN", "1 kN", "100 rpm", "1000 h") == []
    assert select_rolling_bearing("cylindrical_roller", "50 kN", "0 N", "1000 rpm", "10000 h") == []
    with pytest.raises(UnknownNameError):
        select_rolling_bearing("spherical_roller", "5 kN", "0 N", "1000 rpm", "10000 h")


def test_life_plot_uses_the_roller_exponent():
    """The bearing_life figure's curve L(P) passes through the check's operating point for a roller bearing
    (exponent 10/3), i.e. it is not drawn with the ball exponent."""
    import numpy as np

    from mechverify.reports.plots.bearings import life_load_plot

    r = bc.check_bearing_life(rolling_bearing("NU 205"), "5 kN", "0 N", "1000 rpm", "10000 h")
    x, y = life_load_plot(r).axes[0].lines[0].get_data()
    L = float(np.exp(np.interp(np.log(5000.0), np.log(x), np.log(y))))
    assert L == pytest.approx(r.capacity.m_as("hour"), rel=1e-6)


def test_cli_lists_the_other_types(capsys):
    """`mechverify bearings` lists the other types with their verification status; a name of either catalogue
    shows that bearing; an unknown one is exit 2 with suggestions from both."""
    from mechverify.cli import main

    assert main(["bearings"]) == 0
    out = capsys.readouterr().out
    assert "other rolling bearings" in out and "7206 B" in out and "608" in out
    assert main(["bearings", "NU 205 ECP"]) == 0
    assert "cylindrical roller" in capsys.readouterr().out
    assert main(["bearings", "3020"]) == 2
    assert "30205" in capsys.readouterr().err


def test_duty_cycle_uses_the_roller_exponent(tmp_path):
    """A duty cycle on a roller bearing averages with p = 10/3 (Mott Eq. 14-11 with the roller exponent; hand
    calculation): 8 kN for 30 % and 2 kN for 70 % of the time at one speed -> P = (0.3 x 8^(10/3) + 0.7 x
    2^(10/3))^(3/10) kN."""
    from mechverify.design import load

    d = """
[design]
name = "dc"
[requirements]
bearing_life = "1000 h"
[components.roller]
type = "rolling_bearing"
model = "NU 205 ECP"
duty_cycle = { heavy = 0.3, light = 0.7 }
[load_cases.heavy.roller]
radial_force = "8 kN"
speed = "1000 rpm"
[load_cases.light.roller]
radial_force = "2 kN"
speed = "1000 rpm"
"""
    p = tmp_path / "d.toml"
    p.write_text(d)
    [r] = [x for x in load(p).verify() if x.check == "bearing_life"]
    P = (0.3 * 8 ** (10 / 3) + 0.7 * 2 ** (10 / 3)) ** 0.3
    assert r.details["P"].m_as("kN") == pytest.approx(P, rel=1e-9)
    assert r.capacity.m_as("hour") == pytest.approx((28.6 / P) ** (10 / 3) * 1e6 / 60000, rel=1e-9)
