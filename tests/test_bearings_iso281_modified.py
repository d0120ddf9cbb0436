"""ISO 281:2007 modified rating life (a_ISO), lubricant viscosity, contamination and duty cycles.

Sources: ISO 281:2007 Sec. 9 and Table 13 (constants cross-read from two public transcriptions and the
MESYS manual's copy of Table 13; the standard itself was not available); ASTM D341 (Walther). The
numbers below marked "hand calculation" are worked from those formulas by hand, not printed values.
"""

from __future__ import annotations

import math

import pytest

from mechverify.checks.bearings import check_bearing_modified_life
from mechverify.components.bearings import (
    Lubrication,
    a_iso_ball,
    bearing,
    contamination_factor,
    duty_cycle_load,
    modified_rating_life,
    rated_viscosity,
    viscosity_at_temperature,
)
from mechverify.errors import InputError, UnitError, UnknownNameError, ValidityError
from mechverify.units import Q


def test_rated_viscosity_both_branches_hand_calculation():
    """nu1 = 4500 n^-0.5 dm^-0.5 (n >= 1000) and 45000 n^-0.83 dm^-0.5 (n < 1000), ISO 281 Sec. 9.3.3.

    Hand calculation: 4500/sqrt(3000*72.5) = 9.649 mm²/s; 45000 * 500^-0.83 / sqrt(20) = 57.9 mm²/s.
    """
    assert rated_viscosity("3000 rpm", "72.5 mm").m_as("mm**2/s") == pytest.approx(9.649, rel=1e-3)
    assert rated_viscosity("500 rpm", "20 mm").m_as("mm**2/s") == pytest.approx(
        45000 * 500**-0.83 / math.sqrt(20), rel=1e-12)
    assert 45000 * 500**-0.83 / math.sqrt(20) == pytest.approx(57.9, rel=2e-3)


def test_a_iso_hand_calculation_and_continuity_at_the_branch_points():
    """a_ISO at kappa = 2.45, e_C Cu/P = 0.1072 (hand calculation: 5.52); the three ISO 281 branches
    meet at kappa = 0.4 and 1 to 0.1 % (a check of the transcribed constants, not of the code)."""
    a, w = a_iso_ball(2.45, 0.8 * 0.134)
    assert a == pytest.approx(5.52, rel=3e-3) and w == ()
    for k in (0.4, 1.0):
        lo, _ = a_iso_ball(k * (1 - 1e-9), 0.3)
        hi, _ = a_iso_ball(k, 0.3)
        assert hi == pytest.approx(lo, rel=1e-3)
    # e_C Cu/P -> 0: a_ISO -> 0.1 for every kappa (ISO 281; SKF's diagram note says the same for a_SKF)
    for k in (0.1, 0.5, 2.0, 4.0):
        assert a_iso_ball(k, 0.0)[0] == pytest.approx(0.1)


def test_a_iso_clipping_and_cap_warn():
    a4, _ = a_iso_ball(4.0, 0.2)
    a8, w = a_iso_ball(8.0, 0.2)
    assert a8 == a4 and "taken as 4" in w[0]
    a_low, w = a_iso_ball(0.05, 0.2)
    assert a_low == a_iso_ball(0.1, 0.2)[0] and "outside ISO 281" in w[0]
    a, w = a_iso_ball(4.0, 5.0)
    assert a == 50.0 and any("cap of 50" in x for x in w)
    with pytest.raises(InputError):
        a_iso_ball(0.0, 0.1)


def test_contamination_table_13_lower_ends():
    """ISO 281 Table 13 (as in the MESYS manual): normal cleanliness 0.6..0.5 (dm < 100), 0.8..0.6 (>= 100)."""
    assert contamination_factor("normal cleanliness", "50 mm") == 0.5
    assert contamination_factor("normal_cleanliness", "120 mm") == 0.6
    assert contamination_factor("typical_contamination", "50 mm") == 0.1
    assert contamination_factor("extreme_cleanliness", "50 mm") == 1.0
    assert contamination_factor(0.7, "50 mm") == 0.7
    with pytest.raises(UnknownNameError):
        contamination_factor("spotless", "50 mm")
    with pytest.raises(InputError):
        contamination_factor(1.5, "50 mm")


def test_walther_reproduces_both_points_and_a_hand_value():
    """ASTM D341 through (40 degC, 68) and (100 degC, 8.6): both points back; at 70 degC hand calculation
    log log(nu+0.7) interpolated linearly in log T gives 20.0 mm²/s."""
    nu = lambda t: viscosity_at_temperature("68 mm**2/s", "8.6 mm**2/s", t).m_as("mm**2/s")  # noqa: E731
    assert nu("40 degC") == pytest.approx(68, rel=1e-9)
    assert nu("100 degC") == pytest.approx(8.6, rel=1e-9)
    y1, y2 = math.log10(math.log10(68.7)), math.log10(math.log10(9.3))
    x1, x2, x = math.log10(313.15), math.log10(373.15), math.log10(343.15)
    hand = 10 ** 10 ** (y1 + (y2 - y1) * (x - x1) / (x2 - x1)) - 0.7
    assert nu("70 degC") == pytest.approx(hand, rel=1e-12)
    assert hand == pytest.approx(20.0, abs=0.1)
    assert nu("60 degC") > nu("70 degC") > nu("80 degC")


def test_bad_lubricant_input_is_named():
    with pytest.raises(ValidityError, match="outside"):
        viscosity_at_temperature("68 mm**2/s", "8.6 mm**2/s", "180 degC")
    with pytest.raises(InputError, match="viscosity_100"):
        Lubrication(iso_vg=68, operating_temperature="70 degC").operating_viscosity()
    with pytest.raises(InputError, match="ISO 3448"):
        Lubrication(iso_vg=70, viscosity_100="8 mm**2/s", operating_temperature="70 degC").operating_viscosity()
    with pytest.raises(UnitError):
        Lubrication(viscosity="20 mm").operating_viscosity()
    with pytest.raises(InputError, match="must exceed"):
        viscosity_at_temperature("8 mm**2/s", "68 mm**2/s", "70 degC")


def test_modified_life_composes_a1_aiso_l10():
    """L_nm = a1 a_ISO L10 (ISO 281 Eq. for L_nm): the product of the separately computed factors."""
    b = bearing("6204")
    lub = Lubrication(viscosity="30 mm**2/s", contamination="normal_cleanliness")
    m = modified_rating_life(b, "1.2 kN", "1500 rpm", lub, reliability=0.95)
    kappa = 30 / rated_viscosity("1500 rpm", (b.d + b.D) / 2).m_as("mm**2/s")
    a, _ = a_iso_ball(kappa, 0.5 * b.Pu.m_as("N") / 1200)
    L10 = (b.C.m_as("N") / 1200) ** 3 * 1e6
    assert m.kappa == pytest.approx(kappa, rel=1e-12)
    assert m.L_rev.m_as("revolution") == pytest.approx(0.64 * a * L10, rel=1e-3)


def test_check_bearing_modified_life_verdict_and_duty_cycle():
    b = bearing("6204")
    lub = Lubrication(iso_vg=68, viscosity_100="8.6 mm**2/s", operating_temperature="70 degC")
    r = check_bearing_modified_life(b, "1 kN", "0 N", "1500 rpm", "10000 h", lub)
    m = modified_rating_life(b, "1 kN", "1500 rpm", lub)
    assert r.capacity.m_as("h") == pytest.approx(m.L_rev.m_as("revolution") / (1500 * 60), rel=1e-9)
    assert r.check == "bearing_modified_life"
    dc = duty_cycle_load(["1 kN", "2 kN"], [3, 1], speeds=["1000 rpm", "1000 rpm"])
    r2 = check_bearing_modified_life(b, "2 kN", "0 N", "1000 rpm", "10000 h", lub, duty_cycle=dc)
    assert r2.inputs["P"].m_as("N") == pytest.approx(((3 * 1e9 + 8e9) / 4) ** (1 / 3), rel=1e-9)


def test_duty_cycle_weights_and_bad_shares():
    """Time shares with speeds weight by n_i t_i (NSK 'Average of fluctuating load'); hand calculation:
    1 kN for 1 h at 2000 rpm and 3 kN for 1 h at 500 rpm -> P = ((2000 + 500*27)/2500)^(1/3) kN = 1.837 kN,
    n_m = 1250 rpm."""
    d = duty_cycle_load(["1 kN", "3 kN"], [1, 1], speeds=["2000 rpm", "500 rpm"])
    assert d.P.m_as("kN") == pytest.approx(((2000 + 500 * 27) / 2500) ** (1 / 3), rel=1e-12)
    assert d.P.m_as("kN") == pytest.approx(1.837, rel=1e-3)
    assert d.mean_speed.m_as("rpm") == pytest.approx(1250)
    for shares in ([0, 0], [-1, 2], [float("nan"), 1]):
        with pytest.raises(InputError, match="positive total"):
            duty_cycle_load(["1 kN", "2 kN"], shares)
    with pytest.raises(InputError, match="one share per"):
        duty_cycle_load(["1 kN", "2 kN"], [1])


# ------------------------------------------------------------------------------------ design files
_DESIGN = """
[design]
name = "duty cycle"
[requirements]
bearing_life = "5000 h"
[components.b]
type = "ball_bearing"
model = "6204"
{extra}
[load_cases.run.b]
radial_force = "1 kN"
speed = "1500 rpm"
[load_cases.start.b]
radial_force = "2 kN"
speed = "500 rpm"
"""


def _load(tmp_path, extra):
    import textwrap

    from mechverify.design import load
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(_DESIGN.format(extra=extra)))
    return load(p)


def test_design_duty_cycle_and_modified_life(tmp_path):
    """duty_cycle = { run = 0.75, start = 0.25 } (time shares): hand calculation P = ((0.75*1500*1^3 +
    0.25*500*2^3)/(0.75*1500 + 0.25*500))^(1/3) kN = (2125/1250)^(1/3) = 1.1935 kN, n_m = 1250 rpm."""
    extra = ('duty_cycle = { run = 0.75, start = 0.25 }\niso_vg = 68\nviscosity_100 = "8.6 mm^2/s"\n'
             'operating_temperature = "70 degC"\ncontamination = "high_cleanliness"')
    rs = _load(tmp_path, extra).verify()
    life = rs.get("b", "bearing_life")
    assert life.details["P"].m_as("kN") == pytest.approx((2125 / 1250) ** (1 / 3), rel=1e-9)
    b = bearing("6204")
    L10h = (b.C.m_as("kN") / (2125 / 1250) ** (1 / 3)) ** 3 * 1e6 / (60 * 1250)
    assert life.capacity.m_as("h") == pytest.approx(L10h, rel=1e-9)
    mod = rs.get("b", "bearing_modified_life")
    lub = Lubrication(iso_vg=68, viscosity_100="8.6 mm**2/s", operating_temperature="70 degC",
                      contamination="high_cleanliness")
    m = modified_rating_life(b, Q(1.19348, "kN"), "1250 rpm", lub)
    assert mod.capacity.m_as("h") == pytest.approx(m.L_rev.m_as("revolution") / (1250 * 60), rel=1e-4)
    assert any(n.startswith("duty cycle") for n in mod.notes) and m.eC == 0.6


def test_design_modified_life_skipped_without_lubricant_and_errors(tmp_path):
    from mechverify.design import DesignFileError
    rs = _load(tmp_path, "").verify()
    assert not [r for r in rs if r.check == "bearing_modified_life"]
    with pytest.raises(DesignFileError, match="needs the lubricant"):
        _load(tmp_path, "[components.b.checks]\nbearing_modified_life = true").verify()
    with pytest.raises(DesignFileError, match="positive total"):
        _load(tmp_path, "duty_cycle = { run = 0, start = 0 }")
    with pytest.raises(DesignFileError, match="no loads"):
        _load(tmp_path, "duty_cycle = { run = 1, stop = 1 }").verify()
    with pytest.raises(DesignFileError, match="viscosity_100"):
        _load(tmp_path, 'iso_vg = 68\noperating_temperature = "70 degC"')


def test_select_bearing_smallest_meeting_life():
    """Fr = 1 kN, 1000 r/min, 5000 h, d >= 20 mm: required C = 1 kN * (5000*60*1000/1e6)^(1/3) = 6.69 kN (hand
    calculation); of the d >= 20 mm rows only 61804/61805 fall short (4.03, 4.36 kN), and the 6004
    (D = 42 mm, C = 9.95 kN, catalogue row not verified) is the smallest that passes."""
    from mechverify.components.bearings import select_bearing
    found = select_bearing("1 kN", "0 N", "1000 rpm", "5000 h", min_bore="20 mm")
    assert found[0].designation == "6004"
    assert {b.designation for b in found} == {"6004", "6005", "6204", "6205"}
    assert select_bearing("1 kN", "0 N", "1000 rpm", "5000 h", series="62", min_bore="20 mm")[0].designation == "6204"
    assert select_bearing("50 kN", "0 N", "1000 rpm", "5000 h") == []
