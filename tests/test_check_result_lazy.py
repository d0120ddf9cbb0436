"""Lazy figure data and substituted text of a CheckResult (issue 19: a study sample never reads them).

No published number is involved: these tests guard that a result whose ``details`` / ``substituted`` are
computed when first read gives exactly what computing them at once gives (JSON byte for byte), for the
example designs and for every registered check that passes a function for either, and the mechanics of the
lazy values (computed once, only when read; pickling, copying, ``replace``; profile samples memoised).
"""

from __future__ import annotations

import copy
import dataclasses
import inspect
import pickle
import re
from pathlib import Path

import numpy as np
import pytest

from mechverify.checks import result as res
from mechverify.checks.registry import CHECKS
from mechverify.checks.result import CheckResult, LazyDetails, ResultSet
from mechverify.errors import InputError
from mechverify.units import Q

ROOT = Path(__file__).resolve().parents[1]
#: Example designs that run the checks passing functions (drives: DC, stepper, gearheads; screw; bearing; carriage).
DESIGNS = ["lead_screw_lift/design.toml", "lever_arm/design.toml", "rp_robot/design.toml", "cable_neck/design.toml"]


class Counter:
    def __init__(self, value):
        self.value, self.calls = value, 0

    def __call__(self):
        self.calls += 1
        return self.value


def _result(**kw):
    return CheckResult(check="c", component="x", demand=Q(1.0, "N"), capacity=Q(2.0, "N"), **kw)


def test_details_function_runs_once_and_only_when_read():
    fn = Counter({"a": Q(1.0, "mm"), "b": np.arange(3)})
    r = _result(details=fn)
    assert fn.calls == 0 and isinstance(r.details, LazyDetails) and not r.details.resolved
    assert r.verdict == "pass" and r.utilisation == 0.5 and fn.calls == 0  # the verdict does not read them
    assert r.details["a"] == Q(1.0, "mm") and list(r.details) == ["a", "b"] and len(r.details) == 2
    assert {**r.details}.keys() == {"a", "b"} and r.details.get("c", 7) == 7 and "b" in r.details
    assert fn.calls == 1
    assert r.to_dict()["details"] == _result(details=fn.value).to_dict()["details"]
    assert fn.calls == 1


def test_substituted_function_runs_once_and_is_bracketed_on_read():
    fn = Counter(r"a - -6.2\,\mathrm{MPa}")
    r = _result(substituted=fn)
    assert fn.calls == 0 and r.verdict == "pass"
    assert r.substituted == r"a - (-6.2\,\mathrm{MPa})" == _result(substituted=fn.value).substituted
    assert r.substituted is r.substituted and fn.calls == 1
    assert _result().substituted == "" and _result(substituted="").substituted == ""
    with pytest.raises(TypeError, match="substituted must be a str"):
        _ = _result(substituted=lambda: 3).substituted


def test_replace_keeps_lazy_values_unread_and_validates_what_changed():
    sub, det = Counter("S = 2"), Counter({"k": 1})
    r = _result(substituted=sub, details=det)
    r2 = r.replace(component="y", notes=["n"], load_case="lc")
    assert (r2.component, r2.notes, r2.load_case) == ("y", ("n",), "lc") and sub.calls == det.calls == 0
    r3 = r2.replace(required_sf=3.0)  # checked (> 0), demand and capacity not re-validated
    assert r3.factored_utilisation == 1.5 and sub.calls == det.calls == 0
    with pytest.raises(InputError, match="safety factor"):
        r.replace(required_sf=0.0)
    r4 = r.replace(details=lambda: {"z": 2}, substituted="T")
    assert dict(r4.details) == {"z": 2} and r4.substituted == "T" and det.calls == 0
    assert r3.substituted == "S = 2" and r3.details == {"k": 1} and sub.calls == det.calls == 1
    assert r.substituted == "S = 2" and r2.substituted == "S = 2" and sub.calls == 1  # copies share the text
    r5 = r.replace(demand=Q(3.0, "N"))  # a validated field: through the constructor
    assert r5.utilisation == 1.5 and r5.verdict == "fail" and sub.calls == 1
    with pytest.raises(InputError, match="demand and capacity must be >= 0"):
        r.replace(demand=Q(-1.0, "N"))
    assert _result().replace(capacity=Q(4000.0, "mN")).utilisation == 0.25  # units converted when they differ
    # dataclasses.replace reads every field: correct, not lazy
    assert dataclasses.replace(r, component="z") == r.replace(component="z")


def test_pickle_copy_and_equality_carry_computed_values():
    r = _result(substituted=lambda: "S = 2", details=lambda: {"t": np.arange(3.0)})
    back = pickle.loads(pickle.dumps(r))
    assert back.substituted == "S = 2" and type(back.details) is dict and list(back.details["t"]) == [0.0, 1.0, 2.0]
    deep = copy.deepcopy(_result(substituted=lambda: "x", details=lambda: {"k": 1}))
    assert deep.substituted == "x" and deep.details == {"k": 1}
    assert _result(substituted=lambda: "x", details=lambda: {"k": 1}) == _result(substituted="x", details={"k": 1})
    assert _result(details=lambda: {"k": 1}) != _result(details={"k": 2})
    assert CheckResult.from_dict(r.to_dict()).to_dict() == r.to_dict()


def test_eager_switch_computes_at_construction(monkeypatch):
    monkeypatch.setattr(res, "EAGER", True)
    sub, det = Counter("S"), Counter({"k": 1})
    r = _result(substituted=sub, details=det)
    assert sub.calls == det.calls == 1 and r.details.resolved
    r.replace(details=Counter({"j": 2}))
    assert det.calls == 1


def test_profile_samples_are_computed_once_and_read_only():
    from mechverify.motion.profiles import trapezoidal

    p = trapezoidal("450 mm", max_velocity="18 mm/s", acceleration="0.1 m/s^2")
    s = p.sample()
    assert p.sample() is s and p.sample(41) is s and p.sample(5) is not s
    fresh = p._sample(41)
    for name in "txvaj":
        assert np.array_equal(getattr(s, name), getattr(fresh, name))
        with pytest.raises(ValueError, match="read-only"):
            getattr(s, name)[0] = 1.0
    assert pickle.loads(pickle.dumps(p)) == p and p.peak_velocity.m_as("mm/s") == pytest.approx(18.0)
    with pytest.raises(InputError):
        p.sample(1)


# ----------------------------------------------------------------- lazy == eager, every check that is lazy
def _lazy_given(r: CheckResult) -> bool:
    raw = r.__dict__.get("substituted")
    return (type(raw) is res._Pending and callable(raw.raw)) or callable(r.__dict__.get("details")) \
        or isinstance(r.__dict__.get("details"), LazyDetails)


@pytest.fixture
def lazy_recorder(monkeypatch):
    """The names of the checks that built a result with a function for details or substituted."""
    seen: set[str] = set()
    post = CheckResult.__post_init__

    def recording(self):
        if _lazy_given(self):
            seen.add(self.check)
        post(self)

    monkeypatch.setattr(CheckResult, "__post_init__", recording)
    return seen


def _direct_results() -> list[CheckResult]:
    """The lazy checks the example designs do not run (DC motor currents, heat, regeneration; ISO 281 modified
    life; plain bushings; linear guides), called as in their own tests."""
    from mechverify.checks import bearings as bc
    from mechverify.checks import linear_guides as lc
    from mechverify.checks import motors as mc
    from mechverify.components.bearings import Lubrication, PlainBushing, bearing, sliding_speed
    from mechverify.components.gearheads import gearhead
    from mechverify.components.motors import motor
    from mechverify.components.transmissions import DirectDrive
    from mechverify.motion.drive_train import DriveTrain, RotaryLoad
    from mechverify.motion.profiles import trapezoidal

    m6 = dataclasses.replace(motor("maxon 6V 10.3 mNm"), thermal_time_constant_winding="8 s",
                             thermal_time_constant_motor="300 s")

    def demand(m, stage=None, torque="2 mN*m"):
        tr = DriveTrain(m, (stage or DirectDrive(),), RotaryLoad("1e-5 kg*m**2", external_torque=torque))
        return tr.demand(trapezoidal("900 rad", max_velocity="600 rad/s", acceleration="600 rad/s**2"),
                         cycle_time="4 s")

    d = demand(m6)
    g = dataclasses.replace(gearhead("maxon GP 13 A 17:1"), max_input_speed="8000 rpm")
    dg = demand(m6, g, torque="20 mN*m")
    bush = PlainBushing(d="10 mm", length="10 mm", p_max="60 MPa", v_max="1 m/s", pv_max="0.34 MPa*m/s", name="b")
    v = sliding_speed("10 mm", "600 rpm")
    guide = lc.LinearGuide(C=Q(10, "kN"), C0=Q(20, "kN"), name="g")
    lub = Lubrication(iso_vg=68, viscosity_100="8.6 mm**2/s", operating_temperature="70 degC")
    return [mc.check_motor_peak_torque(d), mc.check_motor_rms_torque(d), mc.check_motor_max_speed(d),
            mc.check_inertia_ratio(d), mc.check_motor_supply_voltage(d, "6 V"), mc.check_driver_current(d, "2 A"),
            mc.check_motor_winding_temperature(d), mc.check_drive_regeneration(d, "6 V", "1000 uF", "7 V"),
            mc.check_gearhead_continuous_torque(dg), mc.check_gearhead_intermittent_torque(dg),
            mc.check_gearhead_input_speed(dg),
            bc.check_bushing_pressure(bush, "100 N"), bc.check_bushing_velocity(bush, v),
            bc.check_bushing_pv(bush, "100 N", v),
            bc.check_bearing_modified_life(bearing("6204"), "1 kN", "0 N", "1500 rpm", "10000 h", lub),
            lc.check_linear_guide_life(guide, "2 kN", "5000 km", km_per_hour=1.2),
            lc.check_linear_guide_static_safety(guide, "2 kN", required_fs=2)]


def _json(eager: bool, monkeypatch) -> list[str]:
    from mechverify.design import load

    monkeypatch.setattr(res, "EAGER", eager)
    out = [load(ROOT / "examples" / p).verify().to_json() for p in DESIGNS]
    return [*out, ResultSet(_direct_results()).to_json()]


def _lazy_checks() -> set[str]:
    """Registered checks whose function passes a function for details or substituted (read from the source)."""
    pat = re.compile(r"\b(details|substituted)=(lambda\b|sub\))")
    return {name for name, d in CHECKS.items() if pat.search(inspect.getsource(d.function))}


def test_lazy_values_equal_eager_ones_for_every_lazy_check(monkeypatch, lazy_recorder):
    """Examples and direct calls: the JSON (details and substituted included) with the values computed when read
    equals, byte for byte, the JSON with them computed at construction; every registered check that passes a
    function for either is among those run lazily here."""
    lazy = _json(False, monkeypatch)
    ran_lazily = set(lazy_recorder)
    eager = _json(True, monkeypatch)
    assert lazy == eager
    expected = _lazy_checks()
    assert {"motor_peak_torque", "screw_buckling", "bearing_life", "carriage_binding"} <= expected
    assert expected <= ran_lazily, f"lazy checks not compared: {sorted(expected - ran_lazily)}"


def test_drive_figure_data_are_lazy_and_complete():
    """The lift's drive results leave their figure data (profile samples, RMS torque, ...) uncomputed until read."""
    from mechverify.design import load

    rs = load(ROOT / "examples" / DESIGNS[0]).verify()
    peak = rs.get("lift", "motor_peak_torque")
    assert isinstance(peak.details, LazyDetails) and not peak.details.resolved
    assert {"rms_torque", "profile_time", "profile_velocity", "governing_speed", "motor_torque",
            "limit_torque", "margin"} <= set(peak.details)
    assert peak.details["profile_velocity"].units == Q(1, "mm/s").units


def test_a_verify_leaves_every_substituted_line_of_the_lift_uncomputed():
    """design.verify and the adapters copy results with CheckResult.replace: no substituted text of the lift is
    formatted (nor bracketed) until read, and reading gives the text."""
    from mechverify.design import load

    rs = load(ROOT / "examples" / DESIGNS[0]).verify()
    raw = {(r.component, r.check): r.__dict__["substituted"] for r in rs}
    assert len(raw) == len(rs) >= 10
    assert all(type(v) is res._Pending and v.text is None for v in raw.values()), \
        [k for k, v in raw.items() if type(v) is not res._Pending or v.text is not None]
    assert all(r.substituted.count("=") >= 1 for r in rs)


@pytest.mark.parametrize("v", [0.0, 0.1, 1, 0.25, 1e30, 2e30, float("nan"), float("inf"), True, -0.3, np.float64(0.2),
                               "0.2", Q(0.2, "")])
def test_power_screw_dimensionless_fast_path_equals_to_si(v):
    """The plain-number shortcut of the screw formulas' friction coefficients gives what to_si gives (value and
    type), or the same error."""
    from mechverify.components.power_screw import _dimensionless
    from mechverify.units import to_si

    def run(f):
        try:
            out = f(v, "dimensionless", "mu") if f is to_si else f(v, "mu")
            return repr(out), type(out)
        except Exception as exc:  # the same error type and message
            return type(exc), str(exc)

    assert run(_dimensionless) == run(to_si)
