"""The command line: exit codes, deterministic JSON, JUnit XML validity, the CI diff gate, messages.

Exit codes (documented in ``mechverify.cli``): 0 all pass, 1 a check fails, 2 invalid input.
The rod type of ``conftest.py`` (sigma = F/A, Shigley 10th ed. Eq. 3-22) keeps the numbers
checkable by hand: 2 kN on 20 mm^2 is 100 MPa against 250 MPa yield.
"""

import json
import textwrap
import xml.etree.ElementTree as ET

import pytest
from conftest import ROD_DESIGN

from mechverify.cli import main

DESIGN = ROD_DESIGN


@pytest.fixture(autouse=True)
def _rod(rod_type):
    yield


def design(tmp_path, area=20, rev="A", name="design.toml"):
    p = tmp_path / name
    p.write_text(textwrap.dedent(DESIGN.format(area=area, rev=rev)))
    return p


def test_check_passes_and_writes_outputs(tmp_path, capsys):
    p = design(tmp_path)
    code = main(["check", str(p), "--json", str(tmp_path / "r.json"), "--junit", str(tmp_path / "r.xml")])
    assert code == 0
    out = capsys.readouterr().out
    assert "PASS" in out and "rod" in out and "100 MPa" in out
    doc = json.loads((tmp_path / "r.json").read_text())
    r = doc["designs"][0]["results"][0]
    assert r["demand"]["unit"] == "MPa" and r["demand"]["value"] == pytest.approx(100.0) and r["verdict"] == "pass"
    assert doc["designs"][0]["files"]["design.toml"]  # sha-256 of the design file
    suite = ET.parse(tmp_path / "r.xml").getroot()
    assert suite.tag == "testsuites" and suite.get("tests") == "1" and suite.get("failures") == "0"


def test_json_is_deterministic(tmp_path):
    p = design(tmp_path)
    main(["check", str(p), "--json", str(tmp_path / "a.json"), "-q"])
    main(["check", str(p), "--json", str(tmp_path / "b.json"), "-q"])
    assert (tmp_path / "a.json").read_bytes() == (tmp_path / "b.json").read_bytes()


def test_failing_check_exit_1_and_junit_failure(tmp_path):
    p = design(tmp_path, area=5)  # 400 MPa > 250 MPa / 2
    assert main(["check", str(p), "--junit", str(tmp_path / "r.xml"), "-q"]) == 1
    root = ET.parse(tmp_path / "r.xml").getroot()
    assert root.get("failures") == "1"
    assert root.find("testsuite/testcase/failure").get("type") == "fail"


def test_fail_on_warn(tmp_path):
    p = design(tmp_path, area=10.8)  # 185.2 MPa * 2.0 / 250 MPa = 1.48 -> fail
    assert main(["check", str(p), "-q"]) == 1
    p = design(tmp_path, area=40 / 2.3)  # 115 MPa * 2 / 250 = 0.92 -> warn
    assert main(["check", str(p), "-q"]) == 0
    assert main(["check", str(p), "-q", "--fail-on", "warn"]) == 1


def test_invalid_design_exit_2_with_key_path(tmp_path, capsys):
    p = tmp_path / "bad.toml"
    p.write_text(DESIGN.format(area=20, rev="A").replace('length = "350 mm"', 'length = "350 N"'))
    assert main(["check", str(p)]) == 2
    err = capsys.readouterr().err
    assert 'components.rod.length: expected a length, got "350 N"' in err
    assert "Traceback" not in err


def test_missing_file_and_bad_option_exit_2(tmp_path, capsys):
    assert main(["check", str(tmp_path / "nope.toml")]) == 2
    assert main(["check", str(design(tmp_path)), "--fail-on", "sometimes"]) == 2
    assert main(["check", str(design(tmp_path)), "--report", str(tmp_path / "r.docx")]) == 2
    assert not (tmp_path / "r.docx").exists()


def test_diff_catches_lost_margin(tmp_path, capsys):
    base = design(tmp_path, area=20, rev="A", name="a.toml")
    head = design(tmp_path, area=10, rev="B", name="b.toml")  # 200 MPa * 2 > 250 MPa
    assert main(["diff", str(base), str(head), "--json", str(tmp_path / "d.json")]) == 1
    out = capsys.readouterr().out
    assert "margin lost" in out
    d = json.loads((tmp_path / "d.json").read_text())
    assert d["lost_requirement"] and d["changes"][0]["status"] == "changed"
    assert main(["diff", str(head), str(base)]) == 0  # improving is fine


def test_materials_and_schema_commands(tmp_path, capsys):
    assert main(["materials"]) == 0
    assert "Structural Steel" in capsys.readouterr().out
    assert main(["materials", "structural steel"]) == 0
    assert "250 MPa" in capsys.readouterr().out
    assert main(["materials", "unobtainium"]) == 2
    assert main(["schema", "-o", str(tmp_path / "s.json")]) == 0
    schema = json.loads((tmp_path / "s.json").read_text())
    import tomllib

    import jsonschema

    doc = tomllib.loads(DESIGN.format(area=20, rev="A"))
    jsonschema.validate(doc, schema)
    doc["components"]["rod"]["colour"] = "red"
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(doc, schema)


def test_browse_commands(capsys):
    """Catalogue browsing: ISO 2904 gives Tr10x2 d2 = 9 mm, d3 = 7.5 mm; SKF 608 has C = 3.45 kN."""
    assert main(["threads", "Tr10x2"]) == 0
    out = capsys.readouterr().out
    assert "9 mm" in out and "7.5 mm" in out
    assert main(["threads", "Tr10x4"]) == 2
    assert "did you mean" in capsys.readouterr().err
    assert main(["bearings", "608"]) == 0
    assert "3.45 kN" in capsys.readouterr().out
    assert main(["motors"]) == 0
    assert "N·m" in capsys.readouterr().out
    assert main(["explain"]) == 0
    assert main(["explain", "self_locking"]) == 0
    assert "friction angle" in capsys.readouterr().out


def test_init_writes_a_starter_that_verifies(tmp_path, capsys):
    p = tmp_path / "design.toml"
    assert main(["init", str(p)]) == 0
    assert main(["init", str(p)]) == 2  # refuses to overwrite
    assert main(["check", str(p), "-q"]) in (0, 1)
    assert "lift_screw" in p.read_text()


def test_published_schema_is_current(monkeypatch):
    """docs/design.schema.json is what `mechverify schema` prints (regenerate it when component types change:
    `mechverify schema -o docs/design.schema.json`)."""
    from pathlib import Path

    from mechverify.design import REGISTRY
    from mechverify.design.schema import design_schema

    monkeypatch.delitem(REGISTRY.types, "test_rod")  # the test-only type of conftest.py

    published = json.loads((Path(__file__).parents[1] / "docs" / "design.schema.json").read_text())
    assert published == json.loads(json.dumps(design_schema()))


def test_every_example_validates_against_the_schema():
    import tomllib
    from pathlib import Path

    import jsonschema

    schema = json.loads((Path(__file__).parents[1] / "docs" / "design.schema.json").read_text())
    files = sorted((Path(__file__).parents[1] / "examples").glob("*/design*.toml"))
    assert files
    for f in files:
        jsonschema.validate(tomllib.loads(f.read_text()), schema)


def test_usage_errors_exit_2(capsys):
    assert main(["check"]) == 2
    assert main(["chek", "x.toml"]) == 2
    assert "Traceback" not in capsys.readouterr().err
