"""Bearings: properties (life scales with (C/P)³), catalogue lookup errors, checks and bushings."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechverify.checks.bearings import (
    check_bearing_life,
    check_bearing_speed,
    check_bearing_static_safety,
    check_bushing_pressure,
    check_bushing_pv,
    check_bushing_velocity,
)
from mechverify.components.bearings import PlainBushing, basic_rating_life, bearing, bearing_names, sliding_speed
from mechverify.errors import InputError, UnitError, UnknownNameError, ValidityError
from mechverify.units import Q


@settings(max_examples=50, deadline=None)
@given(C=st.floats(100, 1e5), P=st.floats(10, 1e4), k=st.floats(0.2, 5))
def test_ball_life_scales_with_cube_of_load_ratio(C, P, k):
    """ISO 281 Eq. (1): L10 = (C/P)^3 -> scaling P by k scales life by k^-3."""
    L1 = basic_rating_life(Q(C, "N"), Q(P, "N")).m_as("revolution")
    L2 = basic_rating_life(Q(C, "N"), Q(P * k, "N")).m_as("revolution")
    assert L2 == pytest.approx(L1 / k**3, rel=1e-9)


def test_required_catalogue_covers_issue_list():
    for name in ["608", "625", "626", *(f"600{i}" for i in range(6)), *(f"620{i}" for i in range(6)),
                 *(f"680{i}" for i in range(6))]:
        assert name in bearing_names()


def test_unknown_bearing_suggests():
    with pytest.raises(UnknownNameError, match="did you mean '608'"):
        bearing("609")
    with pytest.raises(UnknownNameError):
        bearing("not a bearing")


def test_suffixes_give_variants():
    assert bearing("608-2Z").variant == "shielded"
    assert bearing("608LU").variant == "sealed"
    assert bearing("6200-Z").C == bearing("6200").C
    assert bearing("KML 625RS").designation == "625-RS"
    assert bearing("6800").designation == "61800"


def test_life_check_and_axial_warning():
    b = bearing("608")
    r = check_bearing_life(b, "0 N", "300 N", "540 rpm", "10000 h")
    assert r.capacity.m_as("hour") == pytest.approx((3450 / r.details["P"].m_as("N")) ** 3 * 1e6 / (60 * 540))
    assert r.verdict == "pass"
    # project 004's 350 N screw load on one 608 exceeds SKF's 0.25 C0 = 342.5 N for small bearings
    r2 = check_bearing_life(b, "0 N", "350 N", "540 rpm", "100 h")
    assert r2.warnings and r2.verdict == "warn"


def test_static_and_speed_checks():
    b = bearing("6200")
    s = check_bearing_static_safety(b, "3000 N", required_s0=1.0)
    assert s.safety_factor == pytest.approx(2360 / 3000) and s.verdict == "fail"
    # 6200's ratings and speeds are not verified against SKF's table: a warning, so at least WARN
    r = check_bearing_speed(b, "20000 rpm")
    assert r.verdict == "warn" and r.warnings == (next(w for w in r.warnings if "data not verified" in w),)
    assert check_bearing_speed(b, "40000 rpm").verdict == "fail"
    assert check_bearing_speed(bearing("608"), "20000 rpm").verdict == "pass"  # the verified row
    assert check_bearing_speed(bearing("6200-2RS1"), "1000 rpm").warnings


def test_bearing_errors():
    with pytest.raises(UnitError):
        bearing("608").equivalent_load(100, "0 N")
    with pytest.raises(InputError):
        bearing("608").equivalent_load("-1 N", "0 N")
    with pytest.raises(ValidityError):
        bearing("608").equivalent_load("0 N", "1000 N")  # f0 Fa/C0 = 8.8 beyond ISO 281 Table 3
    with pytest.raises(ValidityError):
        bearing("608").rating_life("100 N", "0 N", reliability=0.8)


def test_bushing_pressure_velocity_pv():
    """p = F/(dL) = 100/(10·10) = 1 MPa; v = π d n = π·0.01·(600/60) = 0.314 m/s; pv = 0.314 MPa·m/s."""
    bush = PlainBushing(d="10 mm", length="10 mm", p_max="60 MPa", v_max="1 m/s", pv_max="0.34 MPa*m/s",
                        name="slide bush")
    v = sliding_speed("10 mm", "600 rpm")
    assert v.m_as("m/s") == pytest.approx(3.14159265 * 0.01 * 10)
    assert bush.pressure("100 N").m_as("MPa") == pytest.approx(1.0)
    assert check_bushing_pv(bush, "100 N", v).demand.m_as("MPa*m/s") == pytest.approx(0.1 * 3.14159265)
    assert check_bushing_pv(bush, "100 N", v).capacity.m_as("MPa*m/s") == pytest.approx(0.34)
    assert check_bushing_pv(bush, "100 N", v).verdict == "warn"  # 0.314 / 0.34 = 0.92 > 0.9
    assert check_bushing_pressure(bush, "100 N").capacity.m_as("MPa") == pytest.approx(60.0)
    assert check_bushing_pressure(bush, "100 N").verdict == "pass"
    assert check_bushing_velocity(bush, "2 m/s").verdict == "fail"
    with pytest.raises(InputError, match="pv_max"):
        check_bushing_pv(PlainBushing(d="10 mm", length="10 mm"), "1 N", "1 m/s")
    with pytest.raises(InputError):
        PlainBushing(d="0 mm", length="10 mm")


def test_unverified_catalogue_rows_carry_a_warning():
    """Provenance acts: 20 of the 21 rows are not verified against the SKF table (their `verified = false`);
    every check of such a bearing warns, naming the row and what is unverified."""
    from mechverify.components.bearings import bearing_catalogue

    rows = bearing_catalogue()
    unverified = [b for b in rows if b.unverified]
    assert (len(rows), len(unverified)) == (21, 20)
    b = bearing("6001")
    for r in (check_bearing_life(b, "100 N", "0 N", "1000 rpm", "1000 h"), check_bearing_static_safety(b, "100 N"),
              check_bearing_speed(b, "1000 rpm")):
        assert r.verdict == "warn" and any(w.startswith("data not verified against source: bearing 6001")
                                           for w in r.warnings), r
    assert not check_bearing_life(bearing("608"), "100 N", "0 N", "1000 rpm", "1000 h").warnings
