"""A frame its supports leave a rigid motion (a mechanism), in a design file (issue 23 bad input "a model with a free
rigid-body motion (name it)"; task fix23's audit): one error at ``components.f.supports`` naming the motions, as
solid_fea does, instead of the same text once per check and load case at the checks' keys (three errors for a
cantilever pinned instead of clamped, one of them at checks.natural_frequency)."""

from __future__ import annotations

import textwrap

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

FRAME = """
    [design]
    name = "mechanism"
    [components.f]
    type = "frame"
    material = "Structural Steel"
    section = "rectangle"
    width = "10 mm"
    height = "20 mm"
    nodes = {{ A = ["0 mm", "0 mm", "0 mm"], B = ["1000 mm", "0 mm", "0 mm"] }}
    members = [ {{ name = "m", start = "A", end = "B" }} ]
    supports = [ {{ at = "A", type = "{support}" }} ]
    min_frequency = "1 Hz"
    {extra}
    """
CASE = """
    deflection_limit = "10 mm"
    checks.buckling_load_factor = true
    [load_cases.q.f]
    point_loads = [ { at = "B", force = ["-10 N", "0 N", "-10 N"] } ]
    """


@pytest.mark.parametrize("extra", ["", CASE])
def test_a_mechanism_is_one_error_at_supports(tmp_path, extra):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(FRAME.format(support="pinned", extra=textwrap.dedent(extra))))
    with pytest.raises(DesignFileError) as exc:
        load(p).verify()
    (key, msg), = exc.value.errors
    assert key == "components.f.supports"
    assert "not fully supported" in msg and "rotation about an axis parallel to y through (0, 0, 0) mm" in msg


def test_the_clamped_cantilever_is_not_refused(tmp_path):
    """The same frame clamped: the checks run (f1 of the 1000 mm 10 x 20 mm cantilever bending along y, the weak
    axis: 1.87510² / (2π L²) · sqrt(E I / ρ A) = 8.15 Hz by hand (Blevins Table 8-1), within 1 %)."""
    import math

    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(FRAME.format(support="fixed", extra=textwrap.dedent(CASE))))
    r = load(p).verify().get("f", "natural_frequency")
    I, A = 0.02 * 0.01**3 / 12, 2e-4
    f1 = 1.87510**2 / (2 * math.pi) * math.sqrt(200e9 * I / (7850 * A))
    assert r.capacity.m_as("Hz") == pytest.approx(f1, rel=0.01)
