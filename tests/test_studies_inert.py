"""Varied inputs that reach no check are named before the study runs (issue 19, task 19f; mechverify/studies/inert.py).

No published numbers: the question is only whether an input changes any check's result. The rod of
tests/conftest.py (sigma = F/A against yield) reads its force and area, never its length: a hand argument, so
its length is inert and its area is not.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import pytest

from mechverify.studies import Study
from mechverify.studies.inert import InertInputWarning, inert_inputs, unread_parameters
from tests.conftest import ROD_DESIGN

ROOT = Path(__file__).resolve().parents[1]
LIFT = ROOT / "examples" / "lead_screw_lift" / "design.toml"


@pytest.fixture
def lift_with_spare_parameters(tmp_path):
    """The reference lift with three more parameters: ``spare`` read by nothing, ``twice`` read only by ``aux``,
    which nothing reads (both unread), and ``load_alias`` read by nothing but itself reading ``lifted_load``."""
    text = LIFT.read_text(encoding="utf-8")
    text = text.replace('screw_speed = "540 rpm"', 'screw_speed = "540 rpm"\nspare = "3 m"\ntwice = "2 * lifted_load"\n'
                        'aux = "twice / 2"\nload_alias = "lifted_load"', 1)
    p = tmp_path / "lift.toml"
    p.write_text(text, encoding="utf-8")
    return p


def _run(study: Study, **kw):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = study.run("serial", **kw)
    return result, [str(w.message) for w in caught if issubclass(w.category, InertInputWarning)]


def test_unread_parameters_from_the_dependency_graph(lift_with_spare_parameters):
    from mechverify.design.design import load

    design = load(lift_with_spare_parameters)
    assert unread_parameters(design) == {"spare", "twice", "aux", "load_alias"}
    assert unread_parameters(load(LIFT)) == set()  # g is read: the lift's mass is lifted_load / g


def test_an_unread_parameter_is_named_before_the_run(lift_with_spare_parameters):
    """The warning comes from the graph (no probe evaluation) and names the parameter; the results are constant in
    it, as the warning says; a parameter that is read gets no warning."""
    study = Study(lift_with_spare_parameters, vary={"parameters.spare": "1 m:2 m:3"})
    result, said = _run(study)
    assert len(said) == 1 and said[0].startswith("parameters.spare: no value of the design reads this parameter")
    assert len({s["max_fu"] for s in result.samples}) == 1
    assert json.loads(result.to_json())["warnings"] == said
    used = Study(lift_with_spare_parameters, vary={"parameters.lifted_load": "300 N:400 N:3"})
    result, said = _run(used)
    assert said == [] and "warnings" not in json.loads(result.to_json())
    assert len({s["max_fu"] for s in result.samples}) == 3


def test_a_field_no_check_reads_is_found_by_the_probe(tmp_path, rod_type):
    """The rod's length reaches no check (sigma = F/A): the probe verifies the rod at the file's 350 mm and at the
    study's farthest value (600 mm) and finds every check equal; its area changes the stress."""
    p = tmp_path / "rod.toml"
    p.write_text(ROD_DESIGN.format(rev="A", area=100))
    study = Study(p, vary={"components.rod.length": "200 mm:600 mm:5"})
    assert inert_inputs(study) == [
        "components.rod.length: no check's result changes when it goes from 350 mm (the file's value) to 600 mm "
        "(probe: the design verified at both values), so the study's results will be constant in it; is it the "
        "input you meant to vary?"]
    result, said = _run(study)
    assert len(said) == 1 and len({s["max_fu"] for s in result.samples}) == 1
    area = Study(p, vary={"components.rod.area": "80 mm^2:120 mm^2:7"})
    assert inert_inputs(area) == []
    mc = Study(p, vary={"components.rod.length": "uniform:300 mm:400 mm", "components.rod.area": "normal:100 mm^2:5 mm^2"},
               samples=20)
    said = inert_inputs(mc)
    assert len(said) == 1 and said[0].startswith("components.rod.length: no check's result changes")


def test_no_probe_when_it_would_cost_as_much_as_the_study(tmp_path, rod_type):
    """Two samples of one input: the probe (one evaluation) is left out; check_inputs=False skips the graph too."""
    p = tmp_path / "rod.toml"
    p.write_text(ROD_DESIGN.format(rev="A", area=100))
    assert inert_inputs(Study(p, vary={"components.rod.length": "200 mm:500 mm:2"})) == []
    result, said = _run(Study(p, vary={"components.rod.length": "200 mm:500 mm:7"}), check_inputs=False)
    assert said == [] and result.warnings == []
