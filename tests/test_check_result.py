"""The check-result model: utilisation, the documented verdict rule, and lossless JSON round trips."""

import json
import math

import pytest

from mechverify import Q
from mechverify.checks import WARN_LEVEL, CheckResult, ResultSet, Verdict
from mechverify.errors import InputError, UnitError


def make(demand, capacity, sf=1.0, **kw):
    return CheckResult("static", "bar", Q(demand, "MPa"), Q(capacity, "MPa"), required_sf=sf, **kw)


def test_utilisation_and_safety_factor_mixed_units():
    r = CheckResult("static", "bar", Q(50, "MPa"), Q("0.25 GPa"))
    assert r.utilisation == pytest.approx(0.2)
    assert r.safety_factor == pytest.approx(5.0)


@pytest.mark.parametrize(
    ("demand", "sf", "verdict"),
    [(100, 2.0, Verdict.PASS), (115, 2.0, Verdict.WARN), (125, 2.0, Verdict.WARN), (126, 2.0, Verdict.FAIL),
     (240, 1.0, Verdict.WARN), (260, 1.0, Verdict.FAIL)],
)
def test_verdict_rule(demand, sf, verdict):
    assert make(demand, 250, sf).verdict is verdict


def test_warn_level_boundary_is_exclusive():
    assert make(WARN_LEVEL * 250, 250).verdict is Verdict.PASS


def test_validity_warning_forces_warn():
    assert make(10, 250, warnings=("outside validity",)).verdict is Verdict.WARN


def test_zero_capacity_fails():
    r = make(1, 0)
    assert math.isinf(r.utilisation) and r.verdict is Verdict.FAIL


def test_bad_results_rejected():
    with pytest.raises(UnitError, match="different dimensions"):
        CheckResult("x", "c", Q(1, "N"), Q(1, "m"))
    with pytest.raises(InputError):
        make(-1, 10)
    with pytest.raises(InputError):
        make(1, 10, sf=0)


def test_json_round_trip_is_lossless():
    r = make(123.456, 250, 1.5, title="Axial", formula=r"\sigma=F/A", source="Shigley 10th ed., Eq. 3-22",
             inputs={"F": Q(2, "kN"), "A": Q(16.2, "mm**2"), "case": "lift"}, notes=("n1",), load_case="raise",
             details={"curve": Q([1.0, 2.0], "N*m")})
    back = CheckResult.from_dict(json.loads(json.dumps(r.to_dict())))
    assert back.to_dict() == r.to_dict()
    assert back.verdict is r.verdict and back.inputs["F"] == Q(2, "kN")


def test_result_set_overall_and_sort():
    rs = ResultSet([make(10, 250), make(300, 250), make(230, 250)], name="d")
    assert rs.verdict is Verdict.FAIL and not rs.passed
    assert [r.demand.m for r in rs.sorted()] == [300, 230, 10]
    assert ResultSet().verdict is Verdict.WARN  # no check ran: nothing verified (review item 8)
    assert rs.to_json() == ResultSet.from_dict(json.loads(rs.to_json())).to_json()
    assert "<table>" in rs._repr_html_() and "fail" in repr(rs)


def test_the_constructor_takes_the_fields_in_their_order():
    """CheckResult's own __init__ (issue 19: one dict update instead of an object.__setattr__ per field) takes the
    dataclass fields in order, positionally or by name, with the dataclass defaults; inputs are copied."""
    import dataclasses
    import inspect

    from mechverify.checks.result import CheckResult
    from mechverify.units import Q

    names = [f.name for f in dataclasses.fields(CheckResult)]
    assert list(inspect.signature(CheckResult).parameters) == names
    inputs = {"F": Q(1.0, "N")}
    args = ("c", "x", Q(1.0, "N"), Q(2.0, "kN"), 1.5, "T", "f", "s", inputs, ("n",), ("w",), "case",
            {"d": 1}, "a = 1")
    a, b = CheckResult(*args), CheckResult(**dict(zip(names, args, strict=True)))
    assert a == b and a.to_dict() == b.to_dict() and a.substituted == "a = 1" and a.verdict == "warn"
    inputs["G"] = 2
    assert "G" not in a.inputs
    d = CheckResult("c", "x", Q(1.0, "N"), Q(2.0, "N"))
    assert (d.required_sf, d.title, d.inputs, d.notes, d.warnings, d.details, d.substituted) == (
        1.0, "", {}, (), (), {}, "")
    assert dataclasses.replace(d, demand=Q(4.0, "N")).utilisation == 2.0
