"""Substituted formulas (issue 25): the line ``symbol = formula with numbers and units = result`` that
a check fills in ``CheckResult.substituted`` must evaluate back to its printed result within rounding.

The LaTeX is parsed back into a pint expression here (``\\frac``, ``\\sqrt``, ``\\cdot``, ``^{n}``,
``\\pi``, ``a\\,\\mathrm{unit}``) and evaluated; that is a consistency check of the report line
against the check's own result (no published number is involved), so it would fail on a wrong
substitution, a wrong unit or a wrong exponent in the printed line.
"""

from __future__ import annotations

import math
import re

import pytest

from mechverify.checks.result import tex
from mechverify.units import Q


def _group(s: str, i: int) -> tuple[str, int]:
    """The brace group starting at s[i] == '{': (contents, index after the closing brace)."""
    assert s[i] == "{", s[i:]
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1:j], j + 1
    raise ValueError(f"unbalanced braces in {s!r}")


def latex_to_python(s: str) -> str:
    s = re.sub(r"(\d[\d.]*)\\times10\^\{(-?\d+)\}", r"\1e\2", s)
    out, i = [], 0
    while i < len(s):
        if s.startswith(r"\frac", i):
            a, i = _group(s, i + 5)
            b, i = _group(s, i)
            out.append(f"(({latex_to_python(a)})/({latex_to_python(b)}))")
        elif s.startswith(r"\sqrt", i):
            a, i = _group(s, i + 5)
            out.append(f"(({latex_to_python(a)})**0.5)")
        elif s.startswith(r"\,\mathrm", i):
            u, i = _group(s, i + 9)
            unit = re.sub(r"\^\{(-?\d+)\}", r"**\1", u).replace(r"\cdot ", "*")
            out.append(f"*Q(1, {unit!r})")
        elif s.startswith("^", i):
            a, i = _group(s, i + 1)
            out.append(f"**({latex_to_python(a)})")
        else:
            for latex, py in ((r"\left(", "("), (r"\right)", ")"), (r"\cdot", "*"), (r"\pi", "pi")):
                if s.startswith(latex, i):
                    out.append(py)
                    i += len(latex)
                    break
            else:
                out.append(s[i])
                i += 1
    return "".join(out)


def evaluate(line: str):
    """(value of the middle expression, printed result) of ``lhs = expression = result [= same in other units]``."""
    parts = line.split(" = ")
    assert len(parts) >= 3, line
    env = {"Q": Q, "pi": math.pi}
    return eval(latex_to_python(parts[1]), env), eval(latex_to_python(parts[2]), env)


def test_tex_reads_back_with_units():
    """tex() output parses back to the same quantity (4 significant digits)."""
    for q, unit in ((Q(350, "N"), None), (Q(1.5e5, "Pa"), "MPa"), (Q(2.07e11, "Pa"), None), (Q(3.25, "N*m"), None),
                    (Q(7850, "kg/m**3"), None)):
        back = eval(latex_to_python(tex(q, unit)), {"Q": Q})
        assert back.m_as(q.units) == pytest.approx(q.magnitude, rel=5e-4)


@pytest.fixture(scope="module")
def demo_results():
    from mechverify.demo import EXAMPLE
    from mechverify.design import load

    return list(load(EXAMPLE / "design.toml").verify())


SCREW_CHECKS = ("nut_flank_pressure", "nut_pv", "screw_strength", "screw_buckling", "screw_critical_speed")


def test_screw_checks_substituted_line_evaluates_to_result(demo_results):
    """Every lead-screw check of the demo design (reference project 004) prints a substituted line whose
    numbers, evaluated with their units, give the printed result and the check's demand or capacity
    (within the 4-significant-digit rounding of the printed inputs)."""
    seen = set()
    for r in demo_results:
        if r.check not in SCREW_CHECKS:
            continue
        assert r.substituted, f"{r.check} has no substituted formula"
        value, printed = evaluate(r.substituted)
        assert value.to(printed.units).magnitude == pytest.approx(printed.magnitude, rel=3e-3), r.substituted
        target = r.capacity if r.check in ("screw_buckling", "screw_critical_speed") else r.demand
        if r.check == "screw_critical_speed":  # printed in revolutions per second, then rpm
            assert printed.m_as("1/s") * 60 == pytest.approx(target.m_as("rpm"), rel=1e-3)
        else:
            assert printed.to(target.units).magnitude == pytest.approx(target.magnitude, rel=1e-3), r.check
        seen.add(r.check)
    assert seen == set(SCREW_CHECKS)


def test_wrong_substitution_is_detected():
    """The parser is not lenient: a squared term printed without its exponent does not evaluate back."""
    good = r"x = \frac{4\cdot 350\,\mathrm{N}}{\pi\cdot (2\,\mathrm{mm})^{2}} = 111.4\,\mathrm{MPa}"
    value, printed = evaluate(good)
    assert value.to("MPa").magnitude == pytest.approx(111.4, rel=1e-3)
    value, printed = evaluate(good.replace("^{2}", ""))
    assert value.dimensionality != printed.dimensionality


SPRING_CHECKS = ("spring_static_stress", "spring_solid_stress")


def test_spring_stress_substituted_line_evaluates_to_result(tmp_path):
    """Shigley 10th ed. Ex. 10-1's music-wire spring data (d = 0.037 in, OD = 0.4 in) as in
    tests/test_design_springs.py: the substituted tau line evaluates to the check's demand."""
    from mechverify.checks.springs import check_spring_solid_stress, check_spring_static_stress
    from mechverify.components.springs_compression import CompressionSpring

    s = CompressionSpring(name="s", d="0.037 in", OD="0.4 in", Nt=12.5, end="squared", L0="2.06 in",
                          G="11.85 Mpsi", Sut="324 ksi")
    for r in (check_spring_static_stress(s, "4 lbf"), check_spring_solid_stress(s)):
        value, printed = evaluate(r.substituted)
        assert value.to("MPa").magnitude == pytest.approx(printed.m_as("MPa"), rel=3e-3), r.substituted
        assert printed.m_as("MPa") == pytest.approx(r.demand.m_as("MPa"), rel=1e-3)
