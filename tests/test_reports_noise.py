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


def test_init_starter_passes_cleanly(tmp_path, capsys):
    """The design `mechverify init` writes verifies with every check PASS and no warning (issue 25: the starter
    used to WARN, its 608 bearing taking 350 N axial > 0.25 C0 = 342.5 N; it now lifts 300 N)."""
    from mechverify.cli import main
    from mechverify.design import load

    p = tmp_path / "design.toml"
    assert main(["init", str(p)]) == 0
    results = list(load(p).verify())
    assert len(results) >= 9
    assert [(r.check, r.verdict.value, r.warnings) for r in results if r.verdict.value != "pass"] == []
    assert main(["check", str(p), "-q"]) == 0
    capsys.readouterr()
