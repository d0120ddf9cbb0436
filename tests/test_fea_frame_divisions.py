"""A frame member's ``divisions`` has a ceiling (review 4 finding 14): 1 000 000 ran a minute into "internal error:
MemoryError" (5.7 GB), 100 000 000 ran on; measured here 20 000 divisions 87 s / 0.55 GB, 80 000 347 s / 1.7 GB
(about 20 kB and 4 ms per element on the 2-core box). The frame element is exact between its nodes for end loads, so
1000 divisions per member is far beyond what any load or mode needs: more is a named error at the key."""

from __future__ import annotations

import textwrap

import pytest

from mechverify.design import load
from mechverify.design.adapters.frame_parsing import MAX_DIVISIONS
from mechverify.design.loader import DesignFileError

FRAME = """
    [design]
    name = "divisions"
    [components.f]
    type = "frame"
    material = "Structural Steel"
    section = "rectangle"
    width = "10 mm"
    height = "20 mm"
    nodes = {{ A = ["0 mm", "0 mm", "0 mm"], B = ["1000 mm", "0 mm", "0 mm"] }}
    members = [ {{ name = "m", start = "A", end = "B", divisions = {n} }} ]
    supports = [ {{ at = "A", type = "fixed" }} ]
    min_frequency = "1 Hz"
    """


@pytest.mark.parametrize("n", [MAX_DIVISIONS + 1, 1_000_000, 100_000_000])
def test_too_many_divisions_are_named_at_once(tmp_path, n):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(FRAME.format(n=n)))
    with pytest.raises(DesignFileError) as exc:
        load(p)
    (key, msg), = exc.value.errors
    assert key == "components.f.members[0].divisions" and f"at most {MAX_DIVISIONS}" in msg


def test_a_usual_count_runs(tmp_path):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(FRAME.format(n=40)))
    assert load(p).verify().get("f", "natural_frequency").capacity.m_as("Hz") > 1
    assert MAX_DIVISIONS == 1000
