"""Constant parts of an expression are evaluated once, at parse time (expressions._fold, issue 19).

Oracle: the same expression evaluated by the unfolded program (the postfix code as parsed), which must give the same
value bit for bit (repr of the quantity or float) or the same error message.
"""

from __future__ import annotations

import dataclasses

import pytest

from mechverify.design.expressions import ExpressionError, parse
from mechverify.units import Q

ENV = {"lifted_load": Q(341.9079737335097, "N"), "x": 2.5, "m": Q(3.0, "kg"), "n": 3, "L": Q(0.45, "m")}

CASES = [
    "2 * (120 N * 400 mm + 30 N * 800 mm) / lifted_load",  # the lift's load_offset
    "-(3 N) * x", "sqrt(4 m^2) * x + 1 m", "m * 9.81 m/s^2 * cos(30 deg)", "x ** 2 ** 0.5", "-x",
    "max(1 N, 2 N) + 0 * lifted_load", "(1 + 2) * (3 + 4) * n", "L / (2 * pi) + 1 mm * 3 ^ 2",
    "atan2(1 m, 2 m) + 0 * x", "abs(-5 N) / lifted_load", "1 / 3 + x - 1 / 3",
    "x / (2 - 2)", "(1 N + 1 m) * x", "sqrt(-4) * x", "10 ** 400 * x",  # errors: left to evaluate
]


def _unfolded(e):
    return dataclasses.replace(e, _run=())


def _outcome(e):
    try:
        return repr(e.evaluate(ENV))
    except ExpressionError as exc:
        return f"error: {exc}"


@pytest.mark.parametrize("text", CASES)
def test_folded_equals_unfolded(text):
    e = parse(text)
    assert _outcome(e) == _outcome(_unfolded(e))


def test_the_lifts_load_offset_keeps_one_constant():
    """2 * (120 N * 400 mm + 30 N * 800 mm) / lifted_load: 11 instructions, 3 run (the constant 144 000 N·mm,
    the name, the division): 2 * (120 * 400 + 30 * 800) = 144 000 by hand."""
    e = parse("2 * (120 N * 400 mm + 30 N * 800 mm) / lifted_load")
    assert len(e._code) == 11
    assert [op for op, _ in e._run] == ["const", "name", "op"]
    assert e._run[0][1].to("N*mm").magnitude == pytest.approx(144_000.0, rel=1e-15)
    assert e == _unfolded(e)  # (equality and hash ignore the folded program)


@pytest.mark.parametrize("text", ["14.351286127411761 kg", "0.14968018499747365 m/s^2", "540 rpm", "5", "1e3 mm",
                                  ".5 N*m", "24 mN*m", "3 kg·m^2", "2 g", "7 N/mm^2", "1.5e-3 m**2", "5 foo"])
def test_a_single_literal_skips_pythons_parser_with_the_same_program(text, monkeypatch):
    """A number with its unit (a study's drawn value: a new string every sample) becomes the one-constant program
    the parser's walk makes, without ast.parse; the same Expression (or the same error) as the full path."""
    from mechverify.design import expressions as ex

    fast = ex._parse_or_error.__wrapped__(text)

    class _NoShortcut:
        def match(self, s):
            return None

        def __getattr__(self, name):
            return getattr(real, name)

    real = ex._LITERAL
    monkeypatch.setattr(ex, "_LITERAL", _NoShortcut())
    slow = ex._parse_or_error.__wrapped__(text)
    if isinstance(fast, Exception):
        assert str(fast) == str(slow)
    else:
        assert fast == slow and repr(fast._code) == repr(slow._code) and fast._run == slow._run == ()
