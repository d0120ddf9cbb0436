"""Every JSON file mechverify writes is strict JSON (RFC 8259: no NaN/Infinity), so jq and JavaScript read it.

Review finding 3: ``check --json`` wrote ``"e": NaN`` for an adjusted bearing pair under Timken's rule (which
has no limit ratio e) and the note read "(e = nan)". No published value involved: a format property.
"""

from __future__ import annotations

import json
import math

import pytest

from mechverify.cli import main
from mechverify.fileio import json_safe, json_text

DESIGN = """
[design]
name = "Bearing review"

[components.pinion_shaft]
type = "adjusted_bearing_pair"
model = "30205"
rule = "timken"
K = 1.5

[components.nu]
type = "rolling_bearing"
model = "NU 205 ECP"

[load_cases.run.pinion_shaft]
radial_force_A = "2.492 kN"
radial_force_B = "4.873 kN"
axial_force = "0 N"
speed = "300 rpm"
[load_cases.run.nu]
radial_force = "5 kN"
speed = "1500 rpm"
"""


def _strict(text: str) -> object:
    def bad(token: str) -> None:
        raise ValueError(f"non-standard JSON token {token}")
    return json.loads(text, parse_constant=bad)


def test_check_json_is_strict_and_notes_say_what_e_means(tmp_path):
    design = tmp_path / "bearings.toml"
    design.write_text(DESIGN)
    out = tmp_path / "b.json"
    main(["check", str(design), "--json", str(out)])
    doc = _strict(out.read_text())
    results = {(r["component"], r["check"]): r for d in doc["designs"] for r in d["results"]}
    pair = results[("pinion_shaft", "bearing_life")]
    assert pair["details"]["e"] is None
    text = " ".join(n for r in results.values() for n in r["notes"])
    assert "nan" not in text and "e = inf" not in text
    assert "adjusted pair's rule" in " ".join(pair["notes"])


def test_json_text_turns_non_finite_floats_into_null():
    import numpy as np

    obj = {"a": math.nan, "b": [1.0, math.inf, np.float64("-inf"), np.float32("nan")], "c": (2, "x")}
    assert json_safe(obj) == {"a": None, "b": [1.0, None, None, None], "c": [2, "x"]}
    assert _strict(json_text(obj)) == {"a": None, "b": [1.0, None, None, None], "c": [2, "x"]}
    with pytest.raises(ValueError):
        _strict('{"a": NaN}')
