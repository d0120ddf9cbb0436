"""Parameters, expressions and connections of design files (issue 18).

Expected values are hand calculations from the expression itself (arithmetic, not printed values), the
lift's numbers from the document's inputs (reference project 004: F = 350 N, g = 9.81 m/s², 540 rpm) and
proportionality of published linear formulas: DIN 103 mean flank pressure p = F/(pi d2 H1 n) and ISO 76
P0 = max(0.6 Fr + 0.5 Fa, Fr) (here Fr = 0: P0 = 0.5 Fa) both scale with F exactly.
"""

from __future__ import annotations

import math
import pickle
import re
import textwrap
from pathlib import Path

import pytest

import mechverify.design
from mechverify import Q
from mechverify.checks import CheckResult
from mechverify.cli import main
from mechverify.design import REGISTRY, CheckSpec, ComponentType, DesignFileError, Field, Output, load
from mechverify.design.expressions import ExpressionError, evaluate, parse
from mechverify.design.parameters import dependency_graph, parameters_report
from mechverify.units import to_si

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


# ------------------------------------------------------------------------------------------- expressions
def test_numbers_with_units_names_and_functions():
    """Hand arithmetic: 8 cm - 1.5 cm cos(4·0) = 6.5 cm; at phi = 45°: cos(180°) = -1 -> 9.5 cm."""
    e = parse("8 cm - 1.5 cm * cos(4*phi)")
    assert e.names == {"phi"}
    assert e.evaluate({"phi": Q(0, "deg")}).m_as("cm") == pytest.approx(6.5)
    assert e.evaluate({"phi": Q(45, "deg")}).m_as("cm") == pytest.approx(9.5)
    assert evaluate("(payload + carriage_mass) * g", {"payload": Q(3, "kg"), "carriage_mass": Q(32.68, "kg"),
                                                       "g": Q(9.81, "m/s^2")}, "force").m_as("N") == \
        pytest.approx(35.68 * 9.81)
    assert evaluate("2 kN").m_as("N") == 2000
    assert evaluate("-2^2") == -4.0 and evaluate("2**3**2") == 512.0  # Python precedence: -(2^2), right-assoc
    assert evaluate("sqrt(9 m^2)").m_as("m") == pytest.approx(3.0)
    assert evaluate("atan2(1 N, 1 N)").m_as("deg") == pytest.approx(45.0)
    assert evaluate("max(1 N, 200 g*m/s^2)").m_as("N") == 1  # 200 g·m/s² = 0.2 N
    assert evaluate("min(3, 2, 5)") == 2.0 and evaluate("abs(-2 N)").m_as("N") == 2
    assert evaluate("2 * pi") == pytest.approx(2 * math.pi)
    assert evaluate("lift.axial_force / 2", {"lift.axial_force": Q(350, "N")}).m_as("N") == 175
    assert evaluate("350 N / g", {"g": Q(9.81, "m/s^2")}, "mass").m_as("kg") == pytest.approx(350 / 9.81)


def test_plain_quantities_read_exactly_as_before():
    """A literal without names is the same quantity as the quantity parser gives (same magnitude type too)."""
    for text in ("350 N", "0.56 N·m", "9.80665 m/s^2", "66 ozf*in", "82 g*cm^2", "1e-3 m", "540 rpm"):
        a, b = evaluate(text), Q(text)
        assert a == b and type(a.magnitude) is type(b.magnitude)


@pytest.mark.parametrize("text, word", [
    ("__import__('os')", "function '__import__' not allowed"),
    ("open('f')", "function 'open' not allowed"),
    ("a.b.c", "only <component>.<value>"),
    ("x.__class__", "private names"),
    ("x[0]", "subscripts not allowed"),
    ("lambda: 1", "lambda not allowed"),
    ("1 < 2", "comparisons not allowed"),
    ("'text'", "not allowed"),
    ("1 if x else 2", "unknown unit 'if'"),
    ("sqrt(x=1)", "plain arguments only"),
    ("sqrt(1, 2)", "takes 1 argument"),
    ("x; y", "not allowed"),
    ("_secret", "names starting with '_'"),
    ("2 n_arms", "unknown unit 'n_arms'"),
    ("sqrt", "is a function"),
    ("1 +", "not a valid expression"),
    ("x" * 1001, "longer than 1000 characters"),
])
def test_anything_outside_the_grammar_is_a_named_error(text, word):
    with pytest.raises(ExpressionError, match=word.replace("(", r"\(").replace("[", r"\[")):
        parse(text).evaluate({"x": 1.0, "y": 1.0})


@pytest.mark.parametrize("text, word", [
    ("1 N / (2 m - 2 m)", "division by zero"),
    ("10**400", "overflows"),
    ("(-8)**0.5", "not a real number"),
    ("sqrt(-1)", "sqrt of a negative"),
    ("1 m + 1 s", "units do not match"),
    ("sin(2 m)", "needs an angle"),
    ("nan_value * 2", "not finite"),
])
def test_evaluation_errors_are_named(text, word):
    with pytest.raises(ExpressionError, match=word):
        evaluate(text, {"nan_value": float("nan")})


def test_wrong_dimension_names_the_expression_and_the_expected_dimension():
    with pytest.raises(ExpressionError, match=r"'payload \* g' gives .* \(a force\), expected a mass"):
        evaluate("payload * g", {"payload": Q(3, "kg"), "g": Q(9.81, "m/s^2")}, "mass")


def test_parse_once_evaluate_many():
    assert parse("a * 2 N") is parse("a * 2 N")
    e = parse("a * 2 N")
    assert [e.evaluate({"a": float(i)}).m_as("N") for i in range(3)] == [0, 2, 4]


# ------------------------------------------------------------------------------------ design files
def _rod_stress(rod, loads, ctx):
    sigma = Q(to_si(loads["force"], "force") / to_si(rod["area"], "area"), "Pa").to("MPa")
    return CheckResult("stress", "", sigma, rod["material"].yield_strength, title="Axial stress")


ROD = ComponentType(
    "param_test_rod", "a rod in tension whose end reaction other components can read",
    fields=(Field("area", "area", required=True), Field("material", "material", required=True),
            Field("count", "int"), Field("note", "str")),
    build=lambda p, ctx: p,
    loads=(Field("force", "force"), Field("extra", "force")),
    checks=(CheckSpec("stress", _rod_stress, "Axial stress", needs=("force",)),),
    outputs=(Output("reaction", "force", "support reaction (= force)", lambda c, loads: loads["force"],
                    needs=("force",)),
             Output("area_out", "area", "the section", lambda c, loads: c["area"])),
)


@pytest.fixture(autouse=True)
def _rod():
    REGISTRY.types[ROD.name] = ROD
    yield
    REGISTRY.types.pop(ROD.name, None)


def write(tmp_path, text):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent(text))
    return p


BASE = """
[design]
name = "rig"

[parameters]
weight = "mass * g"          # before its inputs: resolved in dependency order
mass = "(payload + carriage) * 1"
payload = "3 kg"
carriage = "2 kg"
g = "9.81 m/s^2"
n = 2

[components.a]
type = "param_test_rod"
area = "20 mm^2 * n / 2"
material = "Structural Steel"
count = "n * 2"

[components.b]
type = "param_test_rod"
area = "a.area_out"
material = "Structural Steel"

[load_cases.lift.a]
force = "weight * n"
[load_cases.lift.b]
force = "a.reaction / 2"
"""


def test_parameters_and_connections_resolve_in_dependency_order(tmp_path):
    """weight = (3 + 2) kg x 9.81 = 49.05 N; a: F = 2 x 49.05 = 98.1 N on 20 mm² -> 4.905 MPa; b reads half."""
    d = load(write(tmp_path, BASE))
    assert d.parameters["weight"].m_as("N") == pytest.approx(49.05)
    assert d["a"]["count"] == 4 and d["b"]["area"].m_as("mm^2") == pytest.approx(20)
    rs = d.verify()
    assert rs.get("a", "stress").demand.m_as("MPa") == pytest.approx(98.1 / 20)
    assert rs.get("b", "stress").demand.m_as("MPa") == pytest.approx(49.05 / 20)
    notes = " ".join(rs.get("b", "stress").notes)
    assert "force = 49.05 N ← a.reaction / 2" in notes
    graph = dependency_graph(d)
    assert graph["load_cases.lift.b.force"] == ("a.reaction",)
    assert graph["parameters.weight"] == ("g", "mass")
    text = parameters_report(d)
    assert re.search(r"weight +\= 49.05 N  ← mass \* g", text) and "load_cases.lift.a.force <- n, weight" in text


def _errors(tmp_path, text):
    with pytest.raises(DesignFileError) as exc:
        load(write(tmp_path, text))
    return dict(exc.value.errors)


def test_parameter_cycle_is_named(tmp_path):
    errs = _errors(tmp_path, BASE.replace('payload = "3 kg"', 'payload = "mass - carriage"'))
    assert any(v.startswith("cycle ") and "mass -> payload -> mass" in v for k, v in errs.items()
               if k == "parameters"), errs


def test_unknown_names_suggest(tmp_path):
    errs = _errors(tmp_path, BASE.replace('force = "weight * n"', 'force = "wieght * n"')
                   .replace('g = "9.81 m/s^2"', 'g = "9.81 m/s^2"\nbad = "paylod * 2"'))
    assert "did you mean 'weight'" in errs["load_cases.lift.a.force"]
    assert "did you mean 'payload'" in errs["parameters.bad"]


def test_wrong_dimension_in_a_field_names_expression_and_kind(tmp_path):
    errs = _errors(tmp_path, BASE.replace('force = "weight * n"', 'force = "mass * n"'))
    assert "'mass * n' gives kg (a mass), expected a force" in errs["load_cases.lift.a.force"]


def test_connection_cycle_is_named(tmp_path):
    text = BASE.replace('force = "weight * n"', 'force = "b.force"')
    errs = _errors(tmp_path, text)
    assert "cycle a.force -> b.force -> a.force" in errs["load_cases.lift"] or \
        "cycle b.force -> a.force -> b.force" in errs["load_cases.lift"]


@pytest.mark.parametrize("value, path, word", [
    ('"c.reaction"', "load_cases.lift.b.force", "no component 'c'"),
    ('"a.reactoin"', "load_cases.lift.b.force", "did you mean 'reaction'"),
    ('"a.extra"', "load_cases.lift.b.force", "a is given no extra in load case 'lift'"),
    ('"__import__(1)"', "load_cases.lift.b.force", "not allowed"),
    ('"weight / (n - 2)"', "load_cases.lift.b.force", "division by zero"),
])
def test_bad_connections_have_key_paths(tmp_path, value, path, word):
    errs = _errors(tmp_path, BASE.replace('force = "a.reaction / 2"', f"force = {value}"))
    assert word in errs[path], errs


def test_an_output_of_a_load_case_is_refused_in_a_component_field(tmp_path):
    errs = _errors(tmp_path, BASE.replace('area = "a.area_out"', 'area = "a.reaction / 1 MPa"'))
    assert "use it in a load case" in errs["components.b.area"]


def test_cli_exit_2_without_traceback(tmp_path, capsys):
    p = write(tmp_path, BASE.replace('payload = "3 kg"', 'payload = "lambda: 3"'))
    assert main(["check", str(p)]) == 2
    err = capsys.readouterr()
    assert "parameters.payload" in err.out + err.err and "Traceback" not in err.out + err.err


# ----------------------------------------------------------------------------------------- the lift
def _by_key(rs):
    return {(r.component, r.check): r for r in rs}


def test_lift_payload_appears_once_and_loads_every_part():
    """lifted_load 350 N -> 420 N (+20 %): flank pressure p = F/(pi d2 H1 n) (DIN 103) and the 608's static
    load P0 = 0.5 Fa (ISO 76, Fr = 0) grow by exactly 20 %; the screw stress, the bearing life and the motor torque
    all change; the drive's mass is 420/9.81 kg."""
    base = load(LIFT)
    heavy = base.with_parameters(lifted_load="420 N")
    assert base.data.path == heavy.data.path and heavy.overrides == {"parameters.lifted_load": "420 N"}
    assert heavy["lift"].load["mass"].m_as("kg") == pytest.approx(420 / 9.81)
    a, b = _by_key(base.verify()), _by_key(heavy.verify())
    ratio = {k: b[k].utilisation / a[k].utilisation for k in a if a[k].utilisation > 0}
    assert a[("screw_bearing", "bearing_static_safety")].demand.m_as("N") == pytest.approx(0.5 * 350)
    for key in (("lift_screw", "nut_flank_pressure"), ("lift_screw", "nut_pv"), ("lift_screw", "screw_buckling"),
                ("screw_bearing", "bearing_static_safety")):
        assert ratio[key] == pytest.approx(1.2, rel=1e-12), key
    # L10 = (C/P)^3 with P = Y Fa, Y falling as f0 Fa/C0 grows (ISO 281 Table 3): between 1.2 and 1.2^3
    assert 1.2 < ratio[("screw_bearing", "bearing_life")] < 1.2**3
    for key in (("lift_screw", "screw_strength"), ("lift", "motor_peak_torque")):
        assert ratio[key] > 1.15, key
    # the checks that do not read the load stay the same
    assert ratio[("lift_screw", "self_locking")] == 1.0 and ratio[("screw_bearing", "bearing_speed")] == 1.0


def test_with_overrides_by_key_path_and_errors():
    d = load(LIFT)
    d2 = d.with_overrides({"components.lift.mass": Q(40, "kg"),
                           "load_cases.raise.lift_screw.axial_force": "400 N"})
    assert d2["lift"].load["mass"].m_as("kg") == 40
    assert d2.data.load_cases["raise"]["screw_bearing"]["axial_force"].m_as("N") == 400  # follows the screw
    assert d.data.load_cases["raise"]["lift_screw"]["axial_force"].m_as("N") == 350  # the original unchanged
    with pytest.raises(DesignFileError, match="did you mean 'lift'"):
        d.with_overrides({"components.lfit.mass": "1 kg"})
    with pytest.raises(DesignFileError, match="parameters.payload: no such parameter"):
        d.with_parameters(payload="5 kg")
    with pytest.raises(DesignFileError, match=r"components.lift.mass: 'lifted_load \* g' gives"):
        d.with_overrides({"components.lift.mass": "lifted_load * g"})


def test_design_pickles_by_its_data():
    d = load(LIFT).with_parameters(lifted_load="400 N")
    d2 = pickle.loads(pickle.dumps(d))
    assert d2.overrides == d.overrides and d2.files == d.files
    a, b = d.verify(), d2.verify()
    assert [(r.component, r.check, r.utilisation) for r in a] == [(r.component, r.check, r.utilisation) for r in b]


def test_library_function_is_the_same_as_load():
    assert mechverify.design.load(LIFT).parameters["lifted_load"].m_as("N") == 350


def test_report_appendix_and_json_show_the_load_path():
    from mechverify.design.outputs import run_document
    from mechverify.reports.render import render_html

    d = load(LIFT)
    rs = d.verify()
    html = render_html([(d, rs)])
    assert "<h3>Parameters</h3>" in html and "Derived values and connections" in html
    assert "<code>lifted_load / g</code>" in html and "load_cases.raise.screw_bearing.axial_force" in html
    variant = d.with_parameters(lifted_load="420 N")
    html2 = render_html([(variant, variant.verify())])
    assert "Overrides of the design file" in html2 and "<code>parameters.lifted_load</code>" in html2
    assert "Overrides of the design file" not in html
    doc = run_document([(d, rs)])
    notes = [n for r in doc["designs"][0]["results"] for n in r["notes"]]
    assert doc["designs"][0]["parameters"]["lifted_load"] == "350 newton"
    assert doc["designs"][0]["derived"]["components.lift.mass"]["expression"] == "lifted_load / g"
    assert "derived input (raise): axial_force = 350 N ← lift_screw.support_axial_force" in notes


def test_the_documented_example_runs(tmp_path):
    """docs/design-files.md, 'Parameters, expressions and connections': the TOML example verifies, and
    weight = (5 + 2.5) kg x 9.81 m/s² = 73.575 N reaches the screw and, through the connection, the bearing;
    540 rpm = 18 mm/s / 2 mm lead."""
    doc = (Path(__file__).resolve().parents[1] / "docs" / "design-files.md").read_text(encoding="utf-8")
    section = doc.split("## Parameters, expressions and connections", 1)[1]
    text = re.search(r"```toml\n(.*?)```", section, re.S).group(1)
    d = load(write(tmp_path, text))
    rs = d.verify()
    case = d.data.load_cases["raise"]
    assert case["screw_bearing"]["axial_force"].m_as("N") == pytest.approx(73.575)
    assert case["screw_bearing"]["speed"].m_as("rpm") == pytest.approx(540)
    assert rs.get("screw_bearing", "bearing_static_safety").demand.m_as("N") == pytest.approx(0.5 * 73.575)
    heavier = d.with_parameters(payload="6 kg")
    assert heavier.data.load_cases["raise"]["lift_screw"]["axial_force"].m_as("N") == pytest.approx(8.5 * 9.81)
    v = d.with_overrides({"components.lift.mass": "210 kg", "parameters.payload": "5 kg",
                          "components.lift.transmission[0].mu": 0.2})
    assert v["lift"].load["mass"].m_as("kg") == 210


def test_bare_component_name_is_the_same_value_of_that_component(tmp_path):
    text = BASE.replace('force = "a.reaction / 2"', 'force = "a"')
    d = load(write(tmp_path, text))
    assert d.data.load_cases["lift"]["b"]["force"].m_as("N") == pytest.approx(2 * 49.05)


@pytest.mark.parametrize("end, factor", [("pinned-pinned", 0.5), ("fixed-free", 1.0), ("fixed-pinned", 11 / 16)])
def test_a_bearing_takes_its_radial_load_from_the_link_it_carries(tmp_path, end, factor):
    """Shigley 10th ed. Table A-9 (beam cases by name): largest end reaction R = F/2 for simple supports with a
    centre load, R = F for a cantilever with an end load, R1 = 11F/16 at the fixed end of a fixed/simply
    supported beam with a centre load. F = 120 N."""
    text = f"""
    [design]
    name = "beam on bearings"
    [parameters]
    F = "120 N"
    [components.beam]
    type = "link"
    length = "450 mm"
    section = "circle"
    diameter = "7.5 mm"
    material = "Inventor Steel"
    end = "{end}"
    [components.brg]
    type = "ball_bearing"
    model = "608"
    [load_cases.side.beam]
    transverse_load = "F"
    [load_cases.side.brg]
    radial_force = "beam.end_reaction"
    speed = "100 rpm"
    """
    d = load(write(tmp_path, text))
    assert d.data.load_cases["side"]["brg"]["radial_force"].m_as("N") == pytest.approx(factor * 120)


def test_a_drive_takes_its_external_force_from_the_screw_it_turns(tmp_path):
    """docs example + a load case of the drive: external_force = "lift_screw.axial_force" (73.575 N) replaces
    the drive's own external force in that case (Drive.make_load)."""
    doc = (Path(__file__).resolve().parents[1] / "docs" / "design-files.md").read_text(encoding="utf-8")
    text = re.search(r"```toml\n(.*?)```", doc.split("## Parameters, expressions and connections", 1)[1],
                     re.S).group(1)
    text += '[load_cases.raise.lift]\nexternal_force = "lift_screw.axial_force"\nmass = "0.5 kg"\n'
    d = load(write(tmp_path, text))
    case = d.data.load_cases["raise"]["lift"]
    assert case["external_force"].m_as("N") == pytest.approx(7.5 * 9.81)
    load_ = d["lift"].make_load(case)
    assert load_.external_force.m_as("N") == pytest.approx(73.575) and load_.mass.m_as("kg") == 0.5


def test_a_cycle_of_component_fields_is_named(tmp_path):
    text = BASE.replace('area = "20 mm^2 * n / 2"', 'area = "b.area_out"')
    errs = _errors(tmp_path, text)
    assert errs["components"] in ("cycle a -> b -> a", "cycle b -> a -> b")


def test_quantities_the_unit_parser_read_before_still_read_the_same(tmp_path):
    """'450 * mm' and '5 N * m' were quantities before parameters existed; without a parameter of that name they
    still are. With a parameter g, 'lifted * g' is the parameter (names resolve to parameters first)."""
    text = BASE.replace('area = "20 mm^2 * n / 2"', 'area = "20 * mm^2"')
    d = load(write(tmp_path, text))
    assert d["a"]["area"].m_as("mm^2") == 20
    errs = _errors(tmp_path, BASE.replace('area = "20 mm^2 * n / 2"', 'area = "20 * mmm^2"'))
    assert "unknown name 'mmm'" in errs["components.a.area"]


@pytest.mark.parametrize("path", sorted((Path(__file__).resolve().parents[1] / "examples").glob("*/design*.toml")),
                         ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_example_design_pickles(path):
    """Designs go to worker processes (studies): each example round-trips through pickle (rebuilt from its data,
    includes already merged: the rp_robot's clover profiles come along)."""
    d = load(path)
    d2 = pickle.loads(pickle.dumps(d))
    assert list(d2.components) == list(d.components) and d2.files == d.files
    assert list(d2.data.load_cases) == list(d.data.load_cases) and d2.parameters == d.parameters


def test_expression_results_show_simplified_units():
    """Review item 12: the conveyor's drum speed belt_speed / (drum_diameter / 2) = 1 m/s / 80 mm printed
    "0.0125 m/s/mm". Hand arithmetic: 1 / 0.08 = 12.5 rad/s (= 119.4 rpm); the value (SI) is unchanged, only the
    unit is reduced; units already reduced stay as written."""
    from mechverify.design.parameters import show, simplify_units

    q = simplify_units(Q("0.0125 m/s/mm"), "angular_velocity")
    assert f"{q.units:~P}" == "rad/s" and q.m_as("rad/s") == pytest.approx(12.5)
    assert simplify_units(Q("0.0125 m/min/mm"), "angular_velocity").m_as("rpm") == pytest.approx(12.5 / (2 * math.pi))
    assert simplify_units(Q("2 mm/m * rad"), "angle").m_as("rad") == pytest.approx(0.002)
    assert f"{simplify_units(Q('2 mm/m * rad'), 'angle').units:~P}" == "rad"
    assert simplify_units(Q("10 mm/m"), "dimensionless").magnitude == pytest.approx(0.01)
    assert str(simplify_units(Q("100 rpm"), "angular_velocity").units) == str(Q("100 rpm").units)
    assert show(Q("0.0125 m/s/mm")) == "12.5 1/s"
    design = load(Path(__file__).resolve().parents[1] / "examples" / "conveyor_drum" / "design.toml")
    lines = [n for r in design.verify() for n in r.notes if "← drum_speed" in n]
    assert lines and all(re.search(r"= 12\.5 rad/s ← drum_speed", n) for n in lines), lines
    assert all("/mm" not in n for n in lines)


@pytest.mark.parametrize("text, names", [
    ("350 N + 2 m", "a force and a length"),
    ("1 m + 1 s", "a length and a time"),
    ("2 N*m + 1 kg", "a torque, energy or torsional stiffness and a mass"),
])
def test_a_unit_mismatch_names_mechverify_dimensions(text, names):
    """Task fix19: '350 N + 2 m' said 'units do not match ([mass] * [length] / [time] ** 2 and [length])' (pint's
    dimensions); the studies' messages already name mechverify's ('a force', studies.params.dimension_name)."""
    with pytest.raises(ExpressionError, match=r"units do not match \(") as info:
        evaluate(text, {})
    assert f"({names})" in str(info.value), str(info.value)


def test_a_number_added_to_a_length_names_both():
    """Task fix19: pint gives no dimensions for '1 m + 1' (units only): the message named nothing, 'units do not
    match ()'."""
    with pytest.raises(ExpressionError) as info:
        evaluate("1 m + 1", {})
    assert "(a length and dimensionless)" in str(info.value), str(info.value)
