"""Studies: key-path parameters, sizing against a hand calculation, sweeps, Monte Carlo statistics.

Sources: the lead-screw lift of reference project 004 (examples/lead_screw_lift/design.toml);
raise torque of a trapezoidal thread, Hamrock, Fundamentals of Machine Elements 3rd ed., Eq. 16.10
(Shigley 10th ed. Eq. 8-5 form with the flank angle); Wilson (1927) score interval; Spearman (1904).
Every expected number below is a HAND CALCULATION from those formulas with the design file's data,
not a printed value.
"""

from __future__ import annotations

import json
import math
import tomllib

import numpy as np
import pytest

from mechverify.cli import main
from mechverify.design import load
from mechverify.errors import InputError, UnitError, UnknownNameError
from mechverify.studies import SizingError, Study, get_path, parse_vary, size, wilson_interval
from mechverify.studies.params import apply_overrides, resolver, split_path
from mechverify.studies.tomlout import dumps
from tests.builders import LIFT


def _doc() -> dict:
    with LIFT.open("rb") as fh:
        return tomllib.load(fh)


# ----------------------------------------------------------------------------- hand calculation
G = 9.80665
D2, LEAD, HALF_ANGLE = 9.0e-3, 2.0e-3, math.radians(15.0)  # Tr10x2 (ISO 2904): d2 = d - P/2 = 9 mm, 30° thread
MU = 0.25  # iglidur R, upper end of the nut's friction range (004 Tabla 3): the motoring case
ACC = 0.1  # m/s², profile 'raise'
J_SCREW = 7850 * math.pi * D2**4 * 0.45 / 32  # steel screw as a cylinder of d2, 450 mm (rho 7850 kg/m³)
J_ROTOR = 82e-7  # 82 g·cm² (004 Tabla 8)
ALPHA = ACC * 2 * math.pi / LEAD  # motor angular acceleration [rad/s²]
T_PULLOUT = 0.35 + (0.25 - 0.35) * (540 - 500) / (850 - 500)  # pull-out torque at 540 rpm, linear between points
SF = 1.5  # [requirements.safety_factors] motor


def _k_raise() -> float:
    """Raise torque per newton, Hamrock Eq. 16.10: d2/2 (cos an tan l + mu)/(cos an - mu tan l)."""
    tan_l = LEAD / (math.pi * D2)
    an = math.atan(math.tan(HALF_ANGLE) * math.cos(math.atan(tan_l)))
    return D2 / 2 * (math.cos(an) * tan_l + MU) / (math.cos(an) - MU * tan_l)


def _motor_fu(mass: float) -> float:
    """u·SF of the motor peak torque at the end of the acceleration (540 rpm, the lowest pull-out torque
    while accelerating): T = m (g + a) k_raise + (J_screw + J_rotor) alpha."""
    torque = mass * (G + ACC) * _k_raise() + (J_SCREW + J_ROTOR) * ALPHA
    return SF * torque / T_PULLOUT


def _today_mass() -> float:
    """The lift's mass in the file: 350 N / g (35.68 kg), written as a value or as an expression."""
    return float(load(LIFT).data.components["lift"].params["mass"].to("kg").magnitude)


def test_hand_calculation_reproduces_the_design_file_result():
    """At 35.68 kg the hand formula gives the u·SF the design verifies (guards the hand model itself)."""
    r = next(r for r in load(LIFT).verify() if r.check == "motor_peak_torque")
    assert _today_mass() == pytest.approx(35.68, abs=0.01)
    assert _motor_fu(_today_mass()) == pytest.approx(r.factored_utilisation, rel=2e-3)


def test_size_largest_lift_mass_for_the_stepper_pullout_torque():
    """Largest lift mass before the stepper's pull-out torque (with SF 1.5) is exceeded.

    Hand calculation: m = (T_po/SF - J alpha) / (k_raise (g + a)) = 14.86 kg (not a printed value).
    """
    m_hand = (T_PULLOUT / SF - (J_SCREW + J_ROTOR) * ALPHA) / (_k_raise() * (G + ACC))
    assert m_hand == pytest.approx(14.86, abs=0.01)
    r = size(LIFT, "components.lift.mass", until="motor_peak_torque", bounds=("1 kg", "100 kg"))
    assert r.limit == pytest.approx(m_hand, rel=2e-3)
    m0 = _today_mass()
    assert r.unit == "kg" and r.today == pytest.approx(m0, rel=1e-12) and r.until == "lift.motor_peak_torque"
    assert r.today_fu == pytest.approx(_motor_fu(m0), rel=2e-3)
    assert r.margin == pytest.approx((m_hand - m0) / m0, rel=5e-3)
    assert r.governing  # the check with the largest u·SF at the limit is named
    assert "limit 14.8" in r.text()


def test_size_no_bracket_names_both_ends():
    with pytest.raises(SizingError, match=r"does not cross 1 .*at 1 kg.*at 5 kg.*below 1"):
        size(LIFT, "components.lift.mass", until="lift.motor_peak_torque", bounds=("1 kg", "5 kg"))


def test_size_unknown_check():
    with pytest.raises(UnknownNameError, match="motor_peek_torque"):
        size(LIFT, "components.lift.mass", until="motor_peek_torque", bounds=("1 kg", "5 kg"))


# ----------------------------------------------------------------------------- parameters
def test_key_paths_and_overrides_leave_the_source_alone():
    doc = _doc()
    assert split_path("components.lift.transmission[0].screw") == ["components", "lift", "transmission", 0, "screw"]
    assert get_path(doc, "components.lift.transmission[0].screw") == "lift_screw"
    before = doc["components"]["lift"]["mass"]
    new = apply_overrides(doc, {"components.lift.mass": "20.0 kg", "load_cases.raise.lift_screw.axial_force": "1 kN"})
    assert new["components"]["lift"]["mass"] == "20.0 kg" and doc["components"]["lift"]["mass"] == before
    assert new["load_cases"]["raise"]["lift_screw"]["axial_force"] == "1 kN"


@pytest.mark.parametrize("vary, error, match", [
    ({"components.lift.mas": "1 kg:2 kg:2"}, UnknownNameError, "did you mean"),
    ({"components.lift_screw.thread": "1:2:2"}, InputError, "is a text field"),
    ({"components.lift.mass": "normal:30 kg:0 kg"}, InputError, "standard deviation must be > 0"),
    ({"components.lift.mass": "uniform:30 kg:20 kg"}, InputError, "LO must be below HI"),
    ({"components.lift.mass": "triangular:30 kg:10 kg:40 kg"}, InputError, "LO <= MODE <= HI"),
    ({"components.lift.mass": "10 mm:20 mm:3"}, UnitError, "cannot change a quantity's dimension"),
    ({"components.lift.mass": "10 kg:20 kg:0"}, InputError, "zero samples"),
    ({"components.lift.mass": "10 kg:20 kg:x"}, InputError, "must be an integer"),
    ({}, InputError, "nothing to vary"),
])
def test_bad_axes_are_named_errors(vary, error, match):
    with pytest.raises(error, match=match):
        parse_vary(_doc(), vary, resolver(load(LIFT)))


def test_zero_monte_carlo_samples():
    with pytest.raises(InputError, match="zero samples"):
        Study(LIFT, vary={"components.lift.mass": "normal:30 kg:1 kg"}, samples=0)
    with pytest.raises(InputError, match="needs the number of samples"):
        Study(LIFT, vary={"components.lift.mass": "normal:30 kg:1 kg"})


def test_sweeps_and_distributions_do_not_mix_and_a_sweep_takes_no_sample_count():
    with pytest.raises(InputError, match="not both"):
        Study(LIFT, vary={"components.lift.mass": "normal:30 kg:1 kg", "parameters.g": "9 m/s^2:10 m/s^2:2"},
              samples=4)
    with pytest.raises(InputError, match=r"grid \(3 x 2\)"):
        Study(LIFT, vary={"components.lift.mass": "1 kg:3 kg:3", "parameters.g": "9 m/s^2:10 m/s^2:2"}, samples=4)


def test_bare_numbers_take_the_files_unit():
    (ax,) = parse_vary({"components": {"c": {"mass": "35 kg"}}}, ["components.c.mass=20:30000 g:3"])
    assert ax.args == (20.0, 30.0, 3.0) and ax.param.unit == "kg"


def test_a_value_written_as_an_expression_is_varied_from_its_resolved_value():
    """[parameters] (issue 18): 'mass = "load / g"' resolves to 350 N / 9.81 m/s² = 35.678 kg; a sweep
    replaces the expression by values in kg, a parameter sweep changes every value that uses it."""
    doc = {"design": {"name": "p"}, "parameters": {"load": "350 N", "g": "9.81 m/s^2"},
           "profiles": {"up": {"type": "trapezoidal", "distance": "450 mm", "max_velocity": "18 mm/s",
                               "acceleration": "0.1 m/s^2"}},
           "components": {"s": {"type": "lead_screw", "thread": "Tr10x2", "length": "450 mm",
                                "material": "Inventor Steel", "nut_material": "iglidur R", "nut_length": "10 mm"},
                          "lift": {"type": "drive", "motor": "NEMA 17 stepper 0.56 N·m (004 Table 8)",
                                   "transmission": [{"type": "screw", "screw": "s"}], "mass": "load / g",
                                   "incline": "90 deg", "profile": "up"}},
           "load_cases": {"up": {"s": {"axial_force": "load", "rotational_speed": "540 rpm"}}}}
    s = Study(doc, vary={"components.lift.mass": "30 kg:40 kg:2"})
    assert s.axes[0].param.base == pytest.approx(35.678, abs=1e-3) and s.axes[0].param.unit == "kg"
    res = s.run("serial")
    assert [x["status"] for x in res.samples] == ["ok", "ok"], res.samples[0]["message"]
    fu = [x["checks"]["lift.motor_peak_torque"]["fu"] for x in res.samples]
    assert fu == [pytest.approx(_motor_fu(30.0), rel=3e-3), pytest.approx(_motor_fu(40.0), rel=3e-3)]
    p = Study(doc, vary={"parameters.load": "300 N:400 N:2"}).run("serial")
    pv = [x["checks"]["s.nut_pv"]["fu"] for x in p.samples]
    assert pv[1] / pv[0] == pytest.approx(400 / 300, rel=1e-9)  # pv is proportional to the axial force
    assert p.samples[1]["checks"]["lift.motor_peak_torque"]["fu"] > fu[1]  # 400 N / g = 40.8 kg > 40 kg


def test_toml_writer_round_trips_the_design():
    doc = _doc()
    assert tomllib.loads(dumps(doc)) == doc


# ----------------------------------------------------------------------------- sweeps
def test_sweep_full_factorial_and_motor_utilisation_matches_hand_calculation():
    s = Study(LIFT, vary={"components.lift.mass": "10 kg:30 kg:3", "profiles.raise.max_velocity": "12 mm/s:18 mm/s:2"})
    res = s.run("serial")
    assert res.kind == "sweep" and len(res.samples) == 6
    assert [(x["inputs"]["components.lift.mass"], x["inputs"]["profiles.raise.max_velocity"]) for x in res.samples] \
        == [(10.0, 12.0), (10.0, 18.0), (20.0, 12.0), (20.0, 18.0), (30.0, 12.0), (30.0, 18.0)]
    for x in res.samples:
        if x["inputs"]["profiles.raise.max_velocity"] == 18.0:  # 540 rpm: the hand model's operating point
            assert x["checks"]["lift.motor_peak_torque"]["fu"] == pytest.approx(
                _motor_fu(x["inputs"]["components.lift.mass"]), rel=2e-3)
    csv = res.to_csv().splitlines()
    assert len(csv) == 7 and "lift.motor_peak_torque fu" in csv[0]


def test_invalid_sample_is_recorded_and_the_study_goes_on():
    res = Study(LIFT, vary={"components.lift.mass": "-10 kg:10 kg:2"}).run("serial")
    bad, good = res.samples
    assert bad["status"] == "error" and "mass" in bad["message"] and bad["verdict"] == "error"
    assert bad["max_fu"] is None and bad["governing"] == "" and json.loads(res.to_json())["samples"][0]["checks"] == {}
    assert res.to_csv().splitlines()[1].split(",")[5] == ""  # no u·SF for the invalid sample
    assert good["status"] == "ok" and good["checks"]


# ----------------------------------------------------------------------------- Monte Carlo
def test_wilson_interval_hand_calculations():
    """Wilson (1927): the bounds are the proportions pi with (p - pi)^2 = z^2 pi (1 - pi)/n (score test)."""
    z = 1.959963984540054
    for k, n in ((81, 263), (15, 148), (1, 29), (7, 10)):
        lo, hi = wilson_interval(k, n)
        for pi in (lo, hi):
            assert (k / n - pi) ** 2 == pytest.approx(z * z * pi * (1 - pi) / n, rel=1e-9)
    # k = 0: the upper bound is z^2/(n + z^2) in closed form (hand calculation: 0.16113 for n = 20)
    assert wilson_interval(0, 20) == (0.0, pytest.approx(z * z / (20 + z * z), rel=1e-12))
    assert wilson_interval(0, 20)[1] == pytest.approx(0.16113, abs=1e-5)
    # an independent implementation: SciPy's binomtest(...).proportion_ci(method="wilson") (no published table
    # value was found with the search tool; Newcombe 1998 Table II could not be read)
    from scipy.stats import binomtest

    for k, n in ((81, 263), (15, 148), (0, 20), (1, 29), (29, 29)):
        ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="wilson")
        assert wilson_interval(k, n) == (pytest.approx(ci.low, abs=1e-12), pytest.approx(ci.high, abs=1e-12))
    with pytest.raises(InputError):
        wilson_interval(3, 0)


def test_spearman_ignores_rounding_noise():
    """A u·SF constant up to one ulp has no rank correlation with anything (None), a monotonic one has +-1."""
    from mechverify.studies import spearman

    x = [1.0, 2.0, 3.0, 4.0, 5.0]
    assert spearman(x, [0.6353, 0.6353000000000001, 0.6353, 0.6353000000000001, 0.6353]) is None
    assert spearman(x, [v**3 for v in x]) == pytest.approx(1.0)
    assert spearman(x, [-math.exp(v) for v in x]) == pytest.approx(-1.0)


def test_monte_carlo_statistics_sensitivity_and_reproduce(tmp_path):
    vary = {"components.lift.mass": "normal:14.5 kg:0.5 kg",
            "load_cases.raise.lift_screw.axial_force": "uniform:300 N:400 N"}
    s = Study(LIFT, vary=vary, samples=40, method="lhs", seed=3)
    res = s.run("serial")
    again = Study(LIFT, vary=vary, samples=40, method="lhs", seed=3).run("serial")
    assert res.to_json() == again.to_json()  # same seed, same study
    masses = res.values("components.lift.mass")
    # failure of the motor check: exactly the samples above the hand-calculated limit mass
    m_lim = (T_PULLOUT / SF - (J_SCREW + J_ROTOR) * ALPHA) / (_k_raise() * (G + ACC))
    k = int(np.sum(masses > m_lim * (1 + 2e-3)))
    fp = res.failure_probability()["lift.motor_peak_torque"]
    assert k <= fp["failures"] <= int(np.sum(masses > m_lim * (1 - 2e-3)))
    assert (fp["lo"], fp["hi"]) == pytest.approx(wilson_interval(fp["failures"], 40))
    assert res.failure_probability()["overall"]["p"] == 1.0  # the screw in bending fails whatever the mass
    sens = res.sensitivity()
    # the motor torque is monotonic in the mass only; the nut pressure in the axial force only
    assert sens["lift.motor_peak_torque"][0] == ("components.lift.mass", pytest.approx(1.0))
    assert sens["lift_screw.nut_pv"][0] == ("load_cases.raise.lift_screw.axial_force", pytest.approx(1.0))
    worst = res.worst()
    assert worst["max_fu"] == max(x["max_fu"] for x in res.samples)
    # sample i as a design file, checked again: the same utilisations
    i = int(np.argmax(masses))
    out = res.reproduce(i, tmp_path / "sample.toml")
    rs = load(out).verify()
    got = {f"{r.component}.{r.check}": r.factored_utilisation for r in rs}
    for key, c in res.samples[i]["checks"].items():
        assert got[key] == pytest.approx(c["fu"], rel=1e-12)


@pytest.mark.parametrize("method", ["sobol", "random"])
def test_other_sampling_methods_follow_the_distribution_bounds(method):
    s = Study(LIFT, vary={"components.lift.mass": "triangular:10 kg:12 kg:20 kg"}, samples=16, method=method, seed=1)
    xs = [x["components.lift.mass"] for x in s.inputs()]
    assert len(xs) == 16 and all(10 < x < 20 for x in xs) and len(set(xs)) == 16


def test_drive_demand_computed_once_per_verify(monkeypatch):
    """The motor checks of one drive share one torque demand per verify (memo on the drive)."""
    from mechverify.design.adapters import drives

    calls = []
    real = drives._demands
    monkeypatch.setattr(drives, "_demands", lambda drive, ctx: calls.append(1) or real(drive, ctx))
    d = load(LIFT)
    rs = d.verify()
    assert sum(r.component == "lift" for r in rs) >= 3 and len(calls) == 1
    d2 = d.with_overrides({"components.lift.mass": "20 kg"})
    r2 = next(r for r in d2.verify() if r.check == "motor_peak_torque")
    assert len(calls) == 2 and r2.factored_utilisation == pytest.approx(_motor_fu(20.0), rel=2e-3)


def test_latin_hypercube_inputs_are_not_correlated_by_chance():
    """Plain LHS pairs columns at random (rank correlation ~1/sqrt(n)); the optimised design keeps it small,
    so a sensitivity ranking does not credit an input with another one's effect."""
    from mechverify.studies import spearman

    s = Study(LIFT, vary={"components.lift.mass": "uniform:10 kg:20 kg",
                          "load_cases.raise.lift_screw.axial_force": "uniform:300 N:400 N",
                          "profiles.raise.acceleration": "uniform:0.05 m/s^2:0.2 m/s^2"}, samples=100, seed=0)
    xs = s.inputs()
    cols = [[x[n] for x in xs] for n in xs[0]]
    for i, (lo, hi) in enumerate(((10, 20), (300, 400), (0.05, 0.2))):
        strata = np.floor((np.array(cols[i]) - lo) / (hi - lo) * 100).astype(int)
        assert sorted(strata.tolist()) == list(range(100))  # one point in each of the 100 strata
        for j in range(i + 1, 3):
            assert abs(spearman(cols[i], cols[j])) < 0.05


def test_explore_sliders_reverify_the_design():
    """explore(design): one slider per numeric parameter; a change re-verifies. At the sized limit of the
    lifted load (the hand-calculated 14.86 kg x 9.81 m/s² = 145.8 N, the file's g) the motor check reads 1."""
    pytest.importorskip("ipywidgets")
    import re

    d = load(LIFT)
    if "lifted_load" not in d.parameters:
        pytest.skip("the example has no lifted_load parameter")
    from mechverify.reports.explore import explore

    e = explore(d, {"parameters.lifted_load": ("100 N", "400 N")})
    slider = e.sliders["parameters.lifted_load"]
    assert (slider.min, slider.max, slider.value) == (100.0, 400.0, 350.0)
    m_lim = (T_PULLOUT / SF - (J_SCREW + J_ROTOR) * ALPHA) / (_k_raise() * (G + ACC))
    slider.value = m_lim * 9.81
    row = re.search(r"<tr><td>lift</td><td>[^<]*</td><td[^>]*>([^<]*)</td>", e.html)
    assert row and float(row.group(1)) == pytest.approx(1.0, abs=0.005)
    from mechverify.reports.plots import figure_for

    rs = d.with_overrides({"parameters.lifted_load": f"{m_lim * 9.81} N"}).verify()
    governing = max(rs, key=lambda r: r.factored_utilisation)
    if figure_for(governing) is not None:  # the governing check's figure under the table
        assert "Governing:" in e.html and "data:image/svg+xml" in e.html
    else:  # (the example's carriage check, issue 24, governs and has no figure): the table alone
        assert "Governing:" not in e.html and "data:image/svg+xml" not in e.html
    assert len(explore(d).sliders) == sum(1 for v in d.parameters.values() if hasattr(v, "magnitude"))
    e.update({"parameters.lifted_load": -5.0})  # invalid: the message instead of the table
    assert "<pre" in e.html


PLATE = {
    "design": {"name": "plate"},
    "materials": {"al": {"base": "Inventor Aluminum 6061", "E": "70 GPa", "nu": 0.3}},
    "components": {"p": {"type": "plate_fea", "width": "400 mm", "height": "200 mm", "thickness": "4 mm",
                         "material": "al", "supports": [{"edges": "all", "type": "pinned"}], "mesh_size": "10 mm",
                         "deflection_limit": "0.5 mm"}},
    "load_cases": {"q": {"p": {"pressure": "10 kPa"}}},
}


def test_size_thinnest_plate_against_roark_table_11_4_case_1a():
    """Thinnest simply supported 400 x 200 mm plate under 10 kPa whose deflection stays within 0.5 mm.

    Book value: Roark's Formulas for Stress and Strain, 7th ed., Table 11.4 case 1a, a/b = 2.0: alpha = 0.1110
    (printed), y_max = alpha q b^4 / (E t^3). Hand calculation from it (not printed): with u·SF = SF y/y_lim = 1,
    t = (SF alpha q b^4 / (E y_lim))^(1/3) = 3.70 mm for SF = 1. The FEA reproduces Roark's deflection within 1 %
    at this mesh (tests/test_design_plate_fea.py), so the limit agrees within 1/3 % (t ~ y^(1/3)) plus the mesh's
    change with the thickness."""
    from mechverify.design import adapters  # noqa: F401  (registers plate_fea)
    from mechverify.design.design import Design
    from mechverify.design.loader import parse

    base = Design(parse(json.loads(json.dumps(PLATE))))
    sf = next(r for r in base.verify() if r.check == "plate_deflection_fea").required_sf
    t_hand = (sf * 0.1110 * 1e4 * 0.2**4 / (70e9 * 0.5e-3)) ** (1 / 3) * 1e3
    assert t_hand == pytest.approx(3.70 * sf ** (1 / 3), abs=0.01)
    r = size(PLATE, "components.p.thickness", until="plate_deflection_fea", bounds=("2 mm", "8 mm"), scan=3)
    assert r.unit == "mm" and r.limit == pytest.approx(t_hand, rel=0.01)
    assert r.today_fu < 1 and r.margin < 0  # 4 mm passes; the limit lies below it


def test_explore_derived_parameter_follows_its_input(tmp_path):
    """Review finding (session 3): a slider per expression parameter froze it at its old value, so moving the
    input's slider changed nothing. The axial force of a link is `twice = "2 * load"`; at load = 180 N the
    member's u·SF must be 1.8x that at 100 N (stress linear in the axial force: sigma = N/A, hand calculation)."""
    pytest.importorskip("ipywidgets")
    import re

    from mechverify.errors import UnknownNameError
    from mechverify.reports.explore import explore

    path = tmp_path / "ex.toml"
    path.write_text(
        '[design]\nname = "ex"\n[parameters]\nload = "100 N"\ntwice = "2 * load"\n'
        '[components.rod]\ntype = "link"\nlength = "200 mm"\nsection = "rectangle"\nwidth = "10 mm"\n'
        'height = "10 mm"\nmaterial = "AISI 1045 CD"\nchecks = { member_buckling = false, link_deflection = false }\n'
        '[load_cases.a]\nrod = { axial_force = "twice" }\n')
    d = load(path)
    e = explore(d)
    assert list(e.sliders) == ["parameters.load"]  # no slider of its own for the derived parameter

    def u(html: str) -> float:
        return max(float(x) for x in re.findall(r"<td style='text-align:right'>([^<]*)</td>", html))

    def exact(load_text: str) -> float:
        return max(r.factored_utilisation for r in d.with_parameters(load=load_text).verify())

    assert exact("180 N") == pytest.approx(1.8 * exact("100 N"), rel=1e-9)  # linear in the axial force
    assert u(e.html) == float(f"{exact('100 N'):.3g}")  # the table prints 3 significant digits
    e.sliders["parameters.load"].value = 180.0
    assert u(e.html) == float(f"{exact('180 N'):.3g}") != float(f"{exact('100 N'):.3g}")
    named = explore(d, ["parameters.load", "parameters.twice"])  # named explicitly: both sliders
    named.sliders["parameters.load"].value = 180.0  # the unmoved `twice` slider must not freeze the expression
    assert u(named.html) == float(f"{exact('180 N'):.3g}")
    with pytest.raises(UnknownNameError, match="parameters.nope"):
        e.update({"parameters.nope": 1.0})


# ------------------------------------------------ review (round 2 session 3) finding 34: bare numbers for an expression
def test_bare_numbers_are_refused_for_a_value_written_as_an_expression(capsys):
    """Finding 34: the carriage's load_offset is written as '2 * (120 N * 400 mm + 30 N * 800 mm) / lifted_load'
    (411 mm); '300:500:2' used to sweep 300..500 METRES (u·SF 3601) without a word. Now refused, naming a unit."""
    with pytest.raises(InputError, match=r"bare number 300 has no unit.*expression.*0\.411 m"):
        Study(LIFT, vary=["components.carriage.load_offset=300:500:2"])
    with pytest.raises(InputError, match="has no unit"):
        Study(LIFT, vary=["components.carriage.load_offset=normal:400:10"], samples=4)
    with pytest.raises(InputError, match="has no unit"):
        size(LIFT, "components.carriage.load_offset", bounds=(300, 500))
    rc = main(["study", str(LIFT), "--vary", "components.carriage.load_offset=300:500:2", "--serial",
               "--no-progress"])
    assert rc == 2 and "give the unit" in capsys.readouterr().err
    # with a unit it is read as written; bare numbers of a value written with a unit keep the file's unit
    s = Study(LIFT, vary=["components.carriage.load_offset=300 mm:500 mm:2"])
    assert s.axes[0].args[:2] == pytest.approx((0.3, 0.5))
    assert Study(LIFT, vary=["components.lift_screw.length=400:500:2"]).axes[0].param.unit == "mm"


# ------------------------------------------------ review finding 1: a key the file does not write
def test_a_component_key_left_to_its_default_can_be_varied(tmp_path):
    """Finding 1: a key the component type defines but the file does not write was 'unknown parameter'. The
    screw bearing's reliability (ball_bearing default 0.9) is not in the lift's file; it can now be varied from
    that default. Expected ratio: ISO 281:2007 Table 12 a1 = 1 at 90 %, 0.25 at 99 % (the table of
    components/data/bearings_ball.toml), so the life check's u grows by 1/0.25 = 4 (hand calculation)."""
    s = Study(LIFT, vary=["components.screw_bearing.reliability=0.9:0.99:2"])
    assert s.axes[0].param.base == 0.9
    res = s.run("serial")
    u = [x["checks"]["screw_bearing.bearing_life"]["u"] for x in res.samples]
    assert u[1] / u[0] == pytest.approx(1 / 0.25, rel=1e-3)
    out = res.reproduce(1, tmp_path / "s1.toml")  # the key is written into the reproduced file
    assert "reliability = 0.99" in out.read_text()


def test_a_screw_stage_mu_left_to_the_nut_is_varied(capsys):
    """Finding 1, then task 19f: the screw stage's mu (the issue's friction example) defaults to the nut material's
    friction range (both ends checked). It used to be an error ("write the key into the file first"); it is varied
    now, from the range's upper end, with a warning where the values leave the range (0.3 > 0.25 of iglidur R;
    tests/test_studies_screw_mu.py has the hand calculation). size finds the friction at which the motor's peak
    torque reaches its limit."""
    from mechverify.studies.params import OutsideRangeWarning

    with pytest.warns(OutsideRangeWarning, match="0.09..0.25"):
        study = Study(LIFT, vary=["components.lift.transmission[0].mu=0.1:0.3:3"])
    assert study.axes[0].param.base == 0.25
    rc = main(["size", str(LIFT), "--vary", "components.lift.transmission[0].mu", "--until", "motor_peak_torque",
               "--bounds", "0.05:0.3"])
    assert rc == 0, capsys.readouterr().err


def test_a_friction_written_into_the_file_is_varied(tmp_path):
    """Finding 1, the documented way: with 'mu = 0.25' written into the screw stage, a sweep of mu runs and the
    motor's torque grows with the friction (raise torque, Hamrock Eq. 16.10: monotonic in mu)."""
    text = LIFT.read_text().replace('transmission = [{ type = "screw", screw = "lift_screw" }]',
                                    'transmission = [{ type = "screw", screw = "lift_screw", mu = 0.25 }]')
    assert "mu = 0.25 }]" in text
    design = tmp_path / "design.toml"  # (the lift has no includes or file names: it can move)
    design.write_text(text)
    res = Study(design, vary=["components.lift.transmission[0].mu=0.1:0.3:3"]).run("serial")
    fu = [x["checks"]["lift.motor_peak_torque"]["fu"] for x in res.samples]
    assert fu[0] < fu[1] < fu[2]


# ------------------------------------------------ review findings 16, 26: size's margin
def _sized(today: float, today_fu: float, limit: float):
    from mechverify.studies import SizingResult

    return SizingResult("p", "mm", "governing", today, today_fu, limit, "c", (limit,), (1.0, 10.0), 9)


def test_size_margin_is_spelt_out_by_direction_and_verdict():
    """Finding 16: 'margin -7.3% to the limit' meant 'room to thin by 7.3 %' for a plate that passes and
    'short by 58.3 %' for a lift that fails. The text now says which way and what it means (hand arithmetic:
    (3.708 - 4)/4 = -7.3 %, (145.8 - 350)/350 = -58.3 %)."""
    passes = _sized(4.0, 0.7968, 3.708).text()
    assert "the limit is 7.3 % below today's value: it may fall by 7.3 % before u·SF reaches 1" in passes
    fails = _sized(350.0, 2.38, 145.82).text()
    assert "the limit is 58.3 % below today's value: it must fall by 58.3 % for u·SF to come down to 1" in fails
    assert "rise by 25.0 %" in _sized(4.0, 0.8, 5.0).text()
    assert _sized(4.0, 0.8, 5.0).to_dict()["margin"] == pytest.approx(0.25)  # the JSON keeps the signed number


def test_size_margin_words_for_negative_values():
    """Review 2 finding 2 (session 3): a compressive in-plane load sized from -10 to its limit -53.46 N/mm read
    'the limit is 434.6 % above today's value: it may rise' (it must become more negative). For two negative values
    the words speak of the magnitude; a limit across zero says so."""
    from mechverify.studies.sizing import SizingResult

    def r(today: float, limit: float, fu: float = 0.5) -> SizingResult:
        return SizingResult("p", "N/mm", "governing", today, fu, limit, "x", (limit,), (-200.0, -1.0), 10)

    assert r(-10.0, -53.4638).margin_text() == ("the limit is 434.6 % above today's value in magnitude: it may grow "
                                                "by 434.6 % before u·SF reaches 1")
    assert r(-10.0, -5.0, 2.0).margin_text() == ("the limit is 50.0 % below today's value in magnitude: it must "
                                                 "shrink by 50.0 % for u·SF to come down to 1")
    assert r(10.0, 12.0).margin_text().startswith("the limit is 20.0 % above today's value: it may rise by 20.0 %")
    assert "other side of zero" in r(-10.0, 5.0).margin_text()


# ------------------------------------------------ review finding 6: --reproduce keeps the file's comments
def test_reproduce_rewrites_only_the_changed_values_and_keeps_the_comments(tmp_path):
    """Finding 6: --reproduce wrote the design from its data: every comment of the source (its sources and
    assumptions) was lost, and 'acceleration = "0.0618... m/s**2"' came in pint's spelling. Now only the
    varied values' lines change (their comments kept, in the file's unit spelling), and the file reads back
    as the sample's data."""
    import tomllib

    from mechverify.studies.params import apply_overrides

    s = Study(LIFT, vary=["parameters.lifted_load=normal:140 N:10 N",
                          "profiles.raise.acceleration=triangular:0.05 m/s^2:0.1 m/s^2:0.2 m/s^2"], samples=8, seed=1)
    out = s.reproduce(5, tmp_path / "s5.toml")
    src, new = LIFT.read_text().splitlines(), out.read_text().splitlines()
    head = [x for x in new if x.startswith("# Sample") or x.startswith("#   ")]
    body = new[len(head):]
    assert len(head) == 3 and len(body) == len(src)
    changed = [(a, b) for a, b in zip(src, body) if a != b]
    assert [a.split("=")[0].strip() for a, _ in changed] == ["lifted_load", "acceleration"]
    for a, b in changed:
        assert b.split("#", 1)[1] == a.split("#", 1)[1]  # the comment is kept
    assert " m/s^2\"" in changed[1][1] and "**" not in out.read_text()
    assert tomllib.loads(out.read_text()) == apply_overrides(s.doc, s.result_skeleton().overrides(5))


def test_reproduce_falls_back_to_the_whole_document_when_a_value_is_not_on_its_own_line(tmp_path):
    """A value the source does not write on its own line (a key left to its default) is written through
    the TOML writer; the result still reads back as the sample's data."""
    import tomllib

    s = Study(LIFT, vary=["components.screw_bearing.reliability=0.9:0.99:2"])
    out = s.reproduce(1, tmp_path / "s1.toml")
    data = tomllib.loads(out.read_text())
    assert data["components"]["screw_bearing"]["reliability"] == 0.99
    assert data["parameters"]["lifted_load"] == "350 N"


def test_size_margin_words_when_todays_value_is_zero():
    """Task fix19: a parameter that is zero today (an extra load "0 N") printed 'the limit is -0.373861 (today's value
    is zero)': no unit, no direction. Now the limit's value with its unit and what it means (no percentage of zero)."""
    from mechverify.studies.sizing import SizingResult

    def r(limit: float, fu: float) -> SizingResult:
        return SizingResult("parameters.extra", "N", "governing", 0.0, fu, limit, "x", (limit,), (-100.0, 500.0), 9)

    assert r(-0.373861, 1.0025).margin_text() == ("today's value is zero: it must fall to -0.373861 N for u·SF to "
                                                   "come down to 1")
    assert r(12.5, 0.8).margin_text() == "today's value is zero: it may rise to 12.5 N before u·SF reaches 1"


def test_size_margin_of_a_temperature_is_a_difference():
    """Review 4 finding 18: sizing a bearing's operating_temperature (limit 42.3628 degC, today 70 degC) said 'the
    limit is 39.5 % below today's value': a percentage of a Celsius reading means nothing. Now the difference,
    27.64 K (hand: 70 - 42.3628), and the JSON margin on the absolute scale: (315.5128 - 343.15)/343.15 = -8.05 %."""
    from mechverify.studies.sizing import SizingResult

    r = SizingResult("components.b.operating_temperature", "degC", "b.bearing_modified_life", 70.0, 1.2, 42.3628,
                     "b.bearing_modified_life", (42.3628,), (20.0, 150.0), 12)
    assert r.margin_text() == ("the limit is 27.64 K below today's value: it must fall by 27.64 K for u·SF to come "
                               "down to 1")
    assert "%" not in r.text()
    assert r.margin == pytest.approx((315.5128 - 343.15) / 343.15, rel=1e-9)
    f = SizingResult("t", "degF", "x", 100.0, 0.5, 150.0, "x", (150.0,), (0.0, 200.0), 9)
    assert f.margin_text() == ("the limit is 50 degF (a difference) above today's value: it may rise by 50 degF (a "
                               "difference) before u·SF reaches 1")
    assert SizingResult("t", "K", "x", 343.15, 1.2, 315.5128, "x", (1.0,), (1.0, 2.0), 9).margin_text().startswith(
        "the limit is 8.1 % below")  # (kelvin: a percentage is fine)
