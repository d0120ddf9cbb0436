"""carriage_binding states the jam rule with its condition (review item 10).

With mu = 0.18, L = 30 mm, a drive offset e = 100 mm gives 2 mu e/L = 1.2, yet a load R = 350 N at a = 411 mm on
the same side keeps the carriage moving (F e < R a): F = R (1 + 2 mu a/L)/(1 + 2 mu e/L) = 350 (1 + 4.932)/2.2
= 943.7 N (hand calculation from the module's equilibrium, not a printed value). The note said "jam number ...
= 1.2 (jams at 1)" beside that finite force; it must say why it does not jam.
"""

from __future__ import annotations

import pytest

from mechverify.checks import linear_guides as lc
from mechverify.checks.registry import explain_text
from mechverify.errors import ValidityError
from mechverify.units import Q


def test_note_states_the_condition_beside_a_finite_force():
    c = lc.SlidingGuide(mu=0.18, length=Q(30, "mm"), load_offset=Q(411, "mm"), drive_offset=Q(100, "mm"),
                        available_force=Q(2, "kN"))
    r = lc.check_carriage_binding(c, "350 N")
    assert r.demand.m_as("N") == pytest.approx(350 * (1 + 2 * 0.18 * 411 / 30) / (1 + 2 * 0.18 * 100 / 30))
    note = next(n for n in r.notes if "2 mu e/L" in n)
    assert "jams at 1" not in note
    assert "1.2 >= 1" in note and "does not jam" in note and "F e - R a > 0" in note


def test_small_offset_note_and_jam_message():
    ok = lc.check_carriage_binding(lc.SlidingGuide(mu=0.18, length=Q(30, "mm"), drive_offset=Q(10, "mm"),
                                                   available_force=Q(2, "kN")), "350 N")
    assert any("0.12 < 1: the carriage does not jam" in n for n in ok.notes)
    with pytest.raises(ValidityError, match="F e - R a > 0"):
        lc.check_carriage_binding(lc.SlidingGuide(mu=0.18, length=Q(30, "mm"), drive_offset=Q(100, "mm"),
                                                  available_force=Q(2, "kN")), "350 N")


def test_explain_gives_the_condition():
    text = explain_text("carriage_binding")
    assert "2 mu e/L >= 1 AND the drive's own moment governs, F e - R a > 0" in " ".join(text.split())
