"""A design whose components ran no check is not a PASS (review item 8): nothing was verified, so the overall
verdict is WARN with "no check ran" (exit 0 by default, 1 with --fail-on warn), in the console and the JSON."""

from __future__ import annotations

import json

from mechverify.checks import ResultSet, Verdict
from mechverify.cli import main

DESIGN = """
[design]
name = "RR points"
[components.pts]
type = "planar_arm"
kind = "rr"
l1 = "20 cm"
l2 = "15 cm"
path = { curve = "points", points = [["15 cm","5 cm"],["20 cm","10 cm"],["15 cm","15 cm"],["10 cm","10 cm"]], closed = true, speed = "5 cm/s" }
"""


def test_no_check_is_a_warning(tmp_path, capsys):
    f = tmp_path / "d.toml"
    f.write_text(DESIGN)
    out = tmp_path / "d.json"
    assert main(["check", str(f), "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "WARN RR points: no check ran" in text and "PASS" not in text
    doc = json.loads(out.read_text())
    assert doc["verdict"] == "warn" and doc["designs"][0]["results"] == []
    assert main(["check", str(f), "--fail-on", "warn"]) == 1
    assert ResultSet().verdict is Verdict.WARN
