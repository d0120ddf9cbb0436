"""Warnings that mean something (issue 25): the contact-seal speed caveat of a 2RS bearing only near the
limit. Catalogue: the 608 of mechverify's ball-bearing table (open limiting speed, SKF data); the 0.25
threshold is a conservative choice of this project, not a catalogue value.
"""

from __future__ import annotations

from mechverify.checks.bearings import SEAL_SPEED_FRACTION, check_bearing_speed
from mechverify.components.bearings import bearing


def test_seal_caveat_only_near_the_open_limit():
    b = bearing("608-2RS1")
    assert b.variant == "sealed"
    n_lim = b.limiting_speed.m_as("rpm")
    slow = check_bearing_speed(b, "96 rpm")
    assert not slow.warnings and slow.verdict.value == "pass"
    assert any("contact seals" in n for n in slow.notes)  # still said, as a note
    fast = check_bearing_speed(b, f"{(SEAL_SPEED_FRACTION + 0.05) * n_lim} rpm")
    assert any("contact seals" in w for w in fast.warnings) and fast.verdict.value == "warn"
