"""Study inputs a user can trust (review 3 findings 3, 3b, 4, 14; task fixstudy).

No published numbers here: these tests check which inputs a study refuses before running and what its messages
say. The lift is reference project 004 (examples/lead_screw_lift/design.toml).
"""

from __future__ import annotations

import math
import tomllib

import pytest

from mechverify.design import load
from mechverify.errors import InputError, UnitError
from mechverify.studies import parse_vary, size
from mechverify.studies.params import resolver
from tests.builders import LIFT


def _doc() -> dict:
    with LIFT.open("rb") as fh:
        return tomllib.load(fh)


# ----------------------------------------------------------------------------- review 3 finding 3 / 3b
@pytest.mark.parametrize("path, text", [
    ("components.screw_horizontal.section", "'circle'"),  # pint reads "circle" as 1 turn
    ("components.screw_bearing.model", "'608'"),  # a catalogue designation that looks like a number
    ("components.lift_screw.material", None),
])
def test_a_text_field_is_refused_before_running(path, text):
    """A key whose component type declares text (Field kind str/choice/material) is refused up front, not sampled
    as a number whose every sample is then invalid."""
    doc = _doc()
    with pytest.raises(InputError, match=r"is a text field .*a study varies numbers only") as e:
        parse_vary(doc, {path: "1:2:2"}, resolver(load(LIFT)))
    assert str(e.value).startswith(path)
    if text:
        assert text in str(e.value)


def test_size_refuses_a_text_field_before_evaluating():
    with pytest.raises(InputError, match="components.screw_horizontal.section is a text field"):
        size(LIFT, "components.screw_horizontal.section", until="motor_peak_torque", bounds=("0.5 turn", "2 turn"))


def test_a_vector_is_refused_and_names_the_way_to_vary_it():
    """force = "10000, 0, 0" (pint reads it as 0) is a vector: vary a parameter used in it."""
    doc = {"design": {"name": "plate"},
           "components": {"bar": {"type": "solid_fea", "box": "100, 50, 5", "material": "Structural Steel",
                                  "supports": [{"named": "xmin"}]}},
           "load_cases": {"pull": {"bar": {"forces": [{"named": "xmax", "force": "10000, 0, 0"}]}}}}
    with pytest.raises(InputError, match=r"forces\[0\]\.force is a vector \('10000, 0, 0'\).*parameter"):
        parse_vary(doc, {"load_cases.pull.bar.forces[0].force": "1:2:2"})
    with pytest.raises(InputError, match=r"components.bar.box is a vector"):
        parse_vary(doc, {"components.bar.box": "1:2:2"})


def test_a_text_parameter_is_refused_and_numbers_still_pass():
    doc = {"parameters": {"finish": "circle", "t": ".5 mm", "n": "-3 N"}}
    with pytest.raises(InputError, match=r"parameters.finish: its value 'circle' is text"):
        parse_vary(doc, {"parameters.finish": "1:2:2"})
    (t, n) = parse_vary(doc, {"parameters.t": "1 mm:2 mm:2", "parameters.n": "normal:-3 N:1 N"})
    assert t.args == (1.0, 2.0, 2.0) and t.param.unit == "mm" and n.args == (-3.0, 1.0)


# ----------------------------------------------------------------------------- review 3 finding 4
def test_an_unknown_distribution_is_named_not_read_as_a_sweep():
    doc = {"parameters": {"load": "350 N"}}
    with pytest.raises(InputError, match=r"unknown distribution 'lognormal' \(normal, uniform, triangular\)"):
        parse_vary(doc, {"parameters.load": "lognormal:140 N:10 N"})
    with pytest.raises(InputError, match=r"unknown distribution 'gauss'"):
        parse_vary(doc, {"parameters.load": "gauss:140 N:10 N"})


@pytest.mark.parametrize("spec, have, want", [
    ("140 kg:150 kg:2", "a mass", "a force"),
    ("1 N*m:2 N*m:2", "a torque, energy or torsional stiffness", "a force"),
    ("0.1 m/m:0.2 m/m:2", "dimensionless", "a force"),
])
def test_a_dimension_error_names_the_dimensions(spec, have, want):
    with pytest.raises(UnitError) as e:
        parse_vary({"parameters": {"load": "350 N"}}, {"parameters.load": spec})
    msg = str(e.value)
    assert f"is {have} but" in msg and f"is {want};" in msg and "[" not in msg, msg


# ----------------------------------------------------------------------------- review 3 finding 14
def test_an_invalid_sample_shows_its_first_error_and_the_count():
    """A negative screw length makes the screw invalid, and everything that reads it ('lift_screw is invalid (see
    its own errors)'): the console line shows the cause, the first error of the list, and how many there are."""
    from mechverify.studies import Study

    res = Study(LIFT, vary={"components.lift_screw.length": "-100 mm:200 mm:2"}).run("serial")
    bad = res.samples[0]
    assert bad["status"] == "error"
    n = bad["message"].count("\n")  # one line per error after the header line
    assert n >= 2, bad["message"]
    line = next(x for x in res.summary().splitlines() if x.startswith("sample 0 invalid:"))
    assert "length: must be positive, got -100 mm" in line and f"(first of {n} errors)" in line, line
    assert "see its own errors" not in line


# ----------------------------------------------------------------------------- review 3 finding 8 (first part)
def test_the_sweep_table_says_how_many_changing_checks_it_leaves_out():
    from mechverify.studies import Study

    res = Study(LIFT, vary={"parameters.lifted_load": "100 N:400 N:2"}).run("serial")
    changing = res.changing_checks()
    assert len(changing) > 3
    text = res.summary()
    assert f"u·SF of the 3 highest of the {len(changing)} checks that change over the sweep" in text, text
    assert "all of them in the --json and --csv outputs" in text


def test_a_parameter_written_as_an_expression_of_names_is_still_varied(tmp_path):
    """The text rule (no digit: text) leaves expressions alone: [parameters] arms = "lifted_load" resolves to
    350 N and is varied from that value."""
    from mechverify.studies.tomlout import dumps

    doc = _doc()
    doc["parameters"]["arms"] = "lifted_load"
    doc["load_cases"]["raise"]["lift_screw"]["axial_force"] = "arms"
    path = tmp_path / "lift.toml"
    path.write_text(dumps(doc))
    (ax,) = parse_vary(doc, {"parameters.arms": "300 N:400 N:2"}, resolver(load(path)))
    assert ax.param.base == pytest.approx(350.0) and ax.param.expression == "lifted_load"


# ----------------------------------------------------------------------------- review 4 finding 4
def test_a_check_constant_up_to_rounding_does_not_change_over_the_sweep():
    """Review 4 finding 4: the plates' thickness sweep of design_plates.toml listed arm_screws.bolt_working_stress
    (u·SF 0.8692159734470266 / 0.8692159734470295: the bolt loads scale exactly with a uniform thickness change,
    constant in theory) among 'the 3 highest of the 14 checks that change over the sweep'; 10 of the 14 were such
    round-off. A check changes when its u·SF spread exceeds 1e-9 of its size, the tolerance the rank correlation
    already uses (studies.stats.spearman)."""
    from mechverify.studies.study import StudyResult

    def sample(i: int, x: float, fus: dict[str, float]) -> dict:
        checks = {c: {"u": v, "required_sf": 1.0, "fu": v, "verdict": "pass"} for c, v in fus.items()}
        return {"index": i, "inputs": {"parameters.t": x}, "status": "ok", "message": "", "verdict": "pass",
                "governing": max(fus, key=fus.get), "max_fu": max(fus.values()), "checks": checks}

    samples = [sample(0, 4.0, {"a.bolt": 0.8692159734470266, "a.plate": 0.5, "a.zero": 0.0, "a.tiny": 1e-12}),
               sample(1, 6.0, {"a.bolt": 0.8692159734470295, "a.plate": 0.25, "a.zero": 0.0, "a.tiny": 2e-12}),
               sample(2, 8.0, {"a.bolt": 0.8692159734470266, "a.plate": 0.125, "a.zero": 0.0, "a.tiny": 3e-12})]
    axes = [{"name": "parameters.t", "spec": "4:8:3", "unit": "mm", "integer": False}]
    res = StudyResult("sweep", "grid", None, axes, samples, "plates", {}, None)
    assert res.changing_checks() == ["a.plate", "a.tiny"]  # (a small u·SF that doubles does change)
    header = res.summary().splitlines()[1]
    assert "a.plate" in header and "a.bolt" not in header, header  # (it still governs: the last column names it)


# ----------------------------------------------------------------------------- review 4 finding 6
def _rate_lift(tmp_path):
    """The lift with a frequency parameter besides its screw speed (540 rpm): ``f = "50 Hz"`` (read by no check) and
    ``f2 = "f / 2"`` (an expression: a frequency the file never writes a unit for)."""
    text = LIFT.read_text().replace('screw_speed = "540 rpm"',
                                    'screw_speed = "540 rpm"\nf = "50 Hz"\nf2 = "f / 2"', 1)
    assert 'f = "50 Hz"' in text
    p = tmp_path / "lift.toml"
    p.write_text(text)
    return p


def test_a_speed_in_hertz_for_a_value_the_file_writes_in_rpm_is_a_revolution_per_second(tmp_path):
    """Review 4 finding 6 (a)-(c): spec values were converted with pint's own factor, for which 1 Hz = 1/s = 1 rad/s:
    '6 Hz:9 Hz:2' for screw_speed = "540 rpm" became 57.2958 / 85.9437 rpm (nut_pv u·SF 0.2482 / 0.3723, PASS) where
    6 and 9 rev/s are 360 and 540 rpm (1.559 / 2.339, FAIL: the same study written in rpm). Hand: 1 Hz = 60 rpm."""
    from mechverify.studies import Study

    hz = Study(LIFT, vary={"parameters.screw_speed": "6 Hz:9 Hz:2"}).run("serial", check_inputs=False)
    rpm = Study(LIFT, vary={"parameters.screw_speed": "360 rpm:540 rpm:2"}).run("serial", check_inputs=False)
    assert [s["inputs"]["parameters.screw_speed"] for s in hz.samples] == pytest.approx([360.0, 540.0], rel=1e-12)
    assert [s["checks"]["lift_screw.nut_pv"]["fu"] for s in hz.samples] == pytest.approx(
        [s["checks"]["lift_screw.nut_pv"]["fu"] for s in rpm.samples], rel=1e-12)
    # (b) sizing bounds in Hz: the same limit as the same range in rpm (review: 'no limit ... in 9.5493..190.986 rpm')
    lift = load(LIFT)
    a = size(lift, vary="parameters.screw_speed", until="nut_pv", bounds=("1 Hz", "20 Hz"))
    b = size(lift, vary="parameters.screw_speed", until="nut_pv", bounds=("60 rpm", "1200 rpm"))
    assert a.limit == pytest.approx(b.limit, rel=1e-9) and 200 < b.limit < 260
    # (c) a normal distribution in Hz: mean and standard deviation both times 60
    mc = Study(LIFT, vary={"parameters.screw_speed": "normal:9 Hz:0.5 Hz"}, samples=8, seed=1)
    ref = Study(LIFT, vary={"parameters.screw_speed": "normal:540 rpm:30 rpm"}, samples=8, seed=1)
    assert [x["parameters.screw_speed"] for x in mc.inputs()] == pytest.approx(
        [x["parameters.screw_speed"] for x in ref.inputs()], rel=1e-12)


def test_a_frequency_given_in_rpm_is_a_revolution_per_minute(tmp_path):
    """Review 4 finding 6 (d), the other way: rpm for a value the file writes in Hz was 2 pi too high (3000 rpm read
    as 314.159 Hz; a revolution per minute is 1/60 Hz: 3000 rpm = 50 Hz). Also a frequency written as an expression
    ("f / 2"): its value is 25 Hz, not 25 rad/s (pint's 1 Hz = 1 rad/s gave today's value 2 pi too low)."""
    from mechverify.studies import Study

    p = _rate_lift(tmp_path)
    s = Study(p, vary={"parameters.f": "3000 rpm:6000 rpm:2"})
    assert [x["parameters.f"] for x in s.inputs()] == pytest.approx([50.0, 100.0], rel=1e-12)
    e = Study(p, vary={"parameters.f2": "3000 rpm:6000 rpm:2"})
    ax = e.axes[0].param
    assert ax.base * {"Hz": 1.0, "rad/s": 1 / (2 * math.pi)}[ax.unit] == pytest.approx(25.0, rel=1e-12), ax
    assert [float(str(e.overrides(x)["parameters.f2"]).split()[0]) for x in e.inputs()] == pytest.approx(
        [50.0, 100.0] if ax.unit == "Hz" else [100 * math.pi, 200 * math.pi], rel=1e-12)


# ----------------------------------------------------------------------------- task fix19: a spread in an offset unit
_BEARING = """
[design]
name = "bearing temperature"
[requirements]
bearing_life = "5000 h"
[components.b]
type = "ball_bearing"
model = "6204"
iso_vg = 68
viscosity_100 = "8.6 mm^2/s"
operating_temperature = "{t}"
contamination = "normal_cleanliness"
[components.b.checks]
bearing_modified_life = true
[load_cases.run.b]
radial_force = "1 kN"
speed = "1500 rpm"
"""


@pytest.mark.parametrize("written, spec, mean, sd", [
    ("70 degC", "normal:70 degC:5 K", 70.0, 5.0),          # was 'the standard deviation must be > 0' (5 K = -268.15 degC)
    ("343.15 K", "normal:70 degC:5 degC", 343.15, 5.0),   # was an SD of 278.15 K, silently
    ("70 degC", "normal:70 degC:9 degF", 70.0, 5.0),       # 9 degF of spread = 5 K (hand: 9 x 5/9)
    ("70 degC", "normal:70 degC:5 degC", 70.0, 5.0),
])
def test_a_standard_deviation_is_a_difference_not_a_temperature(tmp_path, written, spec, mean, sd):
    """Task fix19 (audit): a normal's SD was converted to the file's unit as a temperature, not as a difference of
    two: for a bearing's operating_temperature = "70 degC", 'normal:70 degC:5 K' was refused ('the standard
    deviation must be > 0': 5 K is -268.15 degC) and for "343.15 K", '5 degC' became an SD of 278.15 K. A spread of
    5 K is one of 5 degC (hand: the scales differ by an offset only; degF by 5/9)."""
    from mechverify.studies import Study

    p = tmp_path / "b.toml"
    p.write_text(_BEARING.format(t=written))
    axis = Study(p, vary={"components.b.operating_temperature": spec}, samples=4).axes[0]
    assert axis.args[0] == pytest.approx(mean, rel=1e-12)
    assert axis.args[1] == pytest.approx(sd, rel=1e-9)


# ----------------------------------------------------------------------------- review 4 finding 7
_SS_BEAM = """
[design]
name = "ss beam"
[components.beam]
type = "frame"
material = "Structural Steel"
section = "rectangle"
width = "10 mm"
height = "20 mm"
theory = "euler"
nodes = {{ A = ["0 mm", "0 mm", "0 mm"], B = ["1000 mm", "0 mm", "0 mm"] }}
members = [ {{ name = "m", start = "A", end = "B" }} ]
supports = [ {{ at = "A", type = "pinned" }}, {{ at = "B", type = "custom", hold = ["y", "z", "rx"] }} ]
{limit}
[load_cases.udl.beam]
distributed_loads = [ {{ member = "m", load = ["0 N/m", "0 N/m", "-200 N/m"], axes = "global" }} ]
"""


@pytest.mark.parametrize("spec", ["5 mm:10 mm:2", "0.002:0.004:2"])
def test_a_deflection_limit_written_as_a_span_fraction_is_refused_with_the_way_to_vary_it(tmp_path, spec):
    """Review 4 finding 7: deflection_limit = "L/250" (a fraction of the span) is read by pint as a litre / 250:
    '5 mm:10 mm:2' was refused as 'the design file's value (0.004 l) is a volume', and bare numbers ran every sample
    invalid ('expected a length, got 0.002 l'), exit 2. Refused up front, naming the span fraction and the way to
    vary it: the frame's numeric deflection_limit_fraction (0.004 = L/250), which then varies (the midspan
    deflection check's limit 1000 mm x 0.002 = 2 mm, hand)."""
    from mechverify.studies import Study

    p = tmp_path / "ss.toml"
    p.write_text(_SS_BEAM.format(limit='deflection_limit = "L/250"'))
    with pytest.raises(InputError) as info:
        Study(p, vary={"components.beam.deflection_limit": spec})
    text = str(info.value)
    assert "'L/250'" in text and "fraction of the span" in text and "volume" not in text, text
    assert "deflection_limit_fraction = 0.004" in text, text
    q = tmp_path / "ssf.toml"
    q.write_text(_SS_BEAM.format(limit="deflection_limit_fraction = 0.004"))
    res = Study(q, vary={"components.beam.deflection_limit_fraction": "0.002:0.004:2"}).run("serial",
                                                                                          check_inputs=False)
    assert [s["status"] for s in res.samples] == ["ok", "ok"]
    fus = [s["checks"]["beam.frame_deflection"]["fu"] for s in res.samples]
    assert fus[0] == pytest.approx(2 * fus[1], rel=1e-9)  # half the limit, twice the utilisation


# ----------------------------------------------------------------------------- review 4 finding 11
def test_monte_carlo_says_p_fail_is_over_the_valid_samples_and_counts_the_invalid_as_failures():
    """Review 4 finding 11: the cable neck's Monte Carlo of wire_d left out its 21 invalid samples (every draw below
    2.78 mm: 'the weight 9.81 N alone buckles the spine', a failure the design cannot express) with no hint, so
    P_fail and the worst sample read low. The summary, the JSON and the report now say that P_fail is over the valid
    samples, which inputs the invalid ones had, and give the overall P_fail with them counted as failures (hand:
    5 samples, 1 fail + 2 invalid -> 3/5 = 0.6, Wilson 95 % (3, 5) = [0.2307, 0.8824], Newcombe 1998 method 3)."""
    import json

    from mechverify.reports.study import render_study_html
    from mechverify.studies.study import StudyResult

    def ok(i: int, x: float, fu: float) -> dict:
        v = "fail" if fu > 1 else "pass"
        return {"index": i, "inputs": {"parameters.d": x}, "status": "ok", "message": "", "verdict": v,
                "governing": "s.buckling", "max_fu": fu,
                "checks": {"s.buckling": {"u": fu, "required_sf": 1.0, "fu": fu, "verdict": v}}}

    def bad(i: int, x: float) -> dict:
        return {"index": i, "inputs": {"parameters.d": x}, "status": "error", "verdict": "error", "governing": "",
                "max_fu": None, "checks": {}, "message": "d.toml: 1 error in the design file:\n  neck: buckles"}

    samples = [ok(0, 2.9, 0.5), bad(1, 2.6), ok(2, 3.0, 0.4), bad(3, 2.7), ok(4, 2.8, 1.3)]
    axes = [{"name": "parameters.d", "spec": "normal:2.9 mm:0.15 mm", "unit": "mm", "integer": False, "base": 3.07}]
    res = StudyResult("monte_carlo", "lhs", 1, axes, samples, "neck", {}, None)
    assert res.failure_probability()["overall"]["failures"] == 1 and res.failure_probability()["overall"]["n"] == 3
    inv = res.invalid_as_failures()
    assert (inv["failures"], inv["n"], inv["invalid"]) == (3, 5, 2)
    assert inv["p"] == pytest.approx(0.6) and (inv["lo"], inv["hi"]) == (pytest.approx(0.2307, abs=5e-5),
                                                                        pytest.approx(0.8824, abs=5e-5))
    assert inv["inputs"] == {"parameters.d": [2.6, 2.7]}
    text = res.summary()
    assert "overall, invalid counted as failures" in text and "0.6000  [0.2307, 0.8824]" in text, text
    assert "P_fail is over the 3 valid samples" in text and "parameters.d 2.6..2.7 mm" in text, text
    assert json.loads(res.to_json())["invalid_as_failures"]["failures"] == 3
    html = render_study_html(res)
    assert "overall, invalid counted as failures" in html and "over the 3 valid samples" in html
    # no invalid sample: nothing added
    clean = StudyResult("monte_carlo", "lhs", 1, axes, [ok(0, 2.9, 0.5), ok(1, 3.0, 0.4)], "neck", {}, None)
    assert clean.invalid_as_failures() is None and "invalid counted" not in clean.summary()
    assert "invalid_as_failures" not in json.loads(clean.to_json())


def test_default_ranges_of_a_temperature_are_degrees_around_it(tmp_path):
    """Task fix19 (with review 4 finding 18): without --bounds, size searched today / 10 .. x 10 (7..700 degC for a
    70 degC bearing), and explore's slider ran from half to twice (35..140 degC): proportions of a Celsius reading.
    Now today ± 100 degrees for sizing and ± 50 for the slider (not below absolute zero)."""
    from mechverify.reports.explore import _default_range
    from mechverify.studies import size
    from mechverify.studies.params import Parameter

    p = tmp_path / "b.toml"
    p.write_text(_BEARING.format(t="70 degC"))
    with pytest.raises(InputError, match=r"in -30\.\.170 degC"):  # (the bearing's -20..150 degC: no crossing)
        size(load(p), vary="components.b.operating_temperature", until="bearing_modified_life", scan=2)
    param = Parameter("components.b.operating_temperature", 70.0, "degC")
    assert param.offset and _default_range(param) == (20.0, 120.0)
    assert not Parameter("x", 70.0, "K").offset and _default_range(Parameter("x", 70.0, "K")) == (35.0, 140.0)
    cold = tmp_path / "c.toml"  # a parameter no check reads: only the range is looked at (not below absolute zero)
    cold.write_text(LIFT.read_text().replace('screw_speed = "540 rpm"', 'screw_speed = "540 rpm"\nt = "-250 degC"'))
    with pytest.raises(InputError, match=r"in -273\.15\.\.-150 degC"):
        size(load(cold), vary="parameters.t", until="nut_pv", scan=2)
