"""Hypothesis fuzzing of design-file expressions (issue 18): whatever is written, the only outcomes are a value
or an :class:`ExpressionError`; nothing outside the grammar is ever evaluated.

"Nothing outside the grammar" is tested by construction: strings that contain a call of a name outside the
whitelist, an attribute chain, a subscript, a lambda, a comparison or a string literal must be refused, and
a sentinel function placed in the evaluation environment must never run.
"""

from __future__ import annotations

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

import mechverify.design.adapters  # noqa: F401  (registers the real component types)
from mechverify.design import Design, DesignFileError
from mechverify.design.expressions import FUNCTIONS, ExpressionError, parse
from mechverify.design.loader import parse as parse_design
from mechverify.units import Q, Quantity

TOKENS = ["1", "2.5", "0", "1e3", "350 N", "9.81 m/s^2", "3 kg", "45 deg", "a", "b", "c.force", "pi", "+", "-",
          "*", "/", "**", "^", "(", ")", ",", " ", "sqrt(", "sin(", "cos(", "atan2(", "min(", "max(", "abs(",
          "tan(", ".", "[", "]", "'", "lambda", ":", "<", "__import__", "os", "_x", "x.y.z", "#", ";", "=",
          "N", "mm", "kN*m", "1/0", "e"]
ENV = {"a": Q(2, "m"), "b": 3.0, "c.force": Q(10, "N")}


def outcome(text: str) -> tuple[str, object]:
    """("value", v) or ("error", message); any other exception propagates and fails the test."""
    try:
        return "value", parse(text).evaluate(ENV)
    except ExpressionError as exc:
        return "error", str(exc)


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(TOKENS), min_size=1, max_size=14).map("".join))
def test_token_soup_gives_a_finite_value_or_a_named_error(text):
    kind, v = outcome(text)
    if kind == "value":
        m = v.magnitude if isinstance(v, Quantity) else v
        assert isinstance(m, int | float) and math.isfinite(m)
    else:
        assert isinstance(v, str) and v


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=60))
def test_arbitrary_text_gives_a_value_or_a_named_error(text):
    kind, v = outcome(text)
    assert kind in ("value", "error") and v is not None


CALLED: list[str] = []


class Sentinel:
    """Anything that would run it (a call, an attribute access) records it."""

    def __call__(self, *a, **k):
        CALLED.append("call")
        return 1.0

    def __getattr__(self, name):
        CALLED.append(name)
        return 1.0


FORBIDDEN = st.sampled_from([
    "evil({x})", "a.b.c", "{x}[0]", "lambda: {x}", "{x} < 1", "'s' * {x}", "{x}.__class__", "evil.attr({x})",
    "(lambda q: q)({x})", "[{x}]", "{{{x}: 1}}", "{x} if {x} else 1", "__import__('os')", "getattr({x}, 'y')",
    "{x} and 1", "not {x}", "{x} == 1", "f'{{x}}'", "{x} @ {x}", "{x} // 2", "{x} % 2", "~{x}", "{x} << 1",
])


@settings(max_examples=300, deadline=None)
@given(FORBIDDEN, st.sampled_from(["1", "a", "b", "2 N", "sqrt(4)", "evil", "(a + b)"]))
def test_syntax_outside_the_grammar_is_refused_and_never_evaluated(template, x):
    text = template.format(x=x)
    env = {**ENV, "evil": Sentinel(), "evil.attr": Sentinel()}
    CALLED.clear()
    try:
        parse(text).evaluate(env)
        raised = False
    except ExpressionError:
        raised = True
    assert raised, text
    assert CALLED == [], text


@given(st.sampled_from(["exec", "eval", "open", "getattr", "print", "input", "compile", "globals", "vars", "log"]))
def test_only_whitelisted_functions(name):
    assume(name not in FUNCTIONS)
    try:
        parse(f"{name}(1)")
    except ExpressionError as exc:
        assert "not allowed" in str(exc)
    else:
        raise AssertionError(f"{name}(1) was accepted")


# ------------------------------------------------------------------------------- whole design files
NAMES = ["a", "b", "c", "g", "payload"]
VALUES = ["3 kg", "9.81 m/s^2", "a * g", "b + 1 N", "a", "c.force", "screw.axial_force", "2", "payload * g",
          "sqrt(a)", "1/0", "a.b.c", "__import__('os')", "b * 1000", "max(a, 1 kg)", "nan"]


@settings(max_examples=150, deadline=None)
@given(params=st.dictionaries(st.sampled_from(NAMES), st.one_of(st.sampled_from(VALUES), st.integers(-3, 3),
                                                                  st.booleans()), max_size=5),
       force=st.sampled_from(VALUES + ["350 N", "payload * g", "screw", "bearing.axial_force"]),
       speed=st.sampled_from(["540 rpm", "screw.rotational_speed", "screw.speed", "a", "10 N"]))
def test_designs_with_parameters_give_a_design_or_a_design_file_error(params, force, speed):
    """A lead screw carried by a 608 whose loads read parameters and the screw: the outcome is a verified
    design or a DesignFileError (with key paths), never another exception."""
    doc = {"design": {"name": "fuzz"}, "parameters": params,
           "components": {"screw": {"type": "lead_screw", "thread": "Tr10x2", "length": "450 mm",
                                    "material": "Structural Steel", "nut_material": "iglidur R",
                                    "nut_length": "10 mm"},
                          "bearing": {"type": "ball_bearing", "model": "608"}},
           "load_cases": {"run": {"screw": {"axial_force": force, "rotational_speed": "540 rpm"},
                                  "bearing": {"axial_force": "screw.support_axial_force", "speed": speed}}}}
    try:
        outcome = ("design", Design(parse_design(doc)).verify())
    except DesignFileError as exc:
        outcome = ("error", exc.errors)
    kind, v = outcome
    assert (kind == "design" and len(v) > 0) or (kind == "error" and all(path or msg for path, msg in v))
