"""select-motor messages are whole (review item 13): a skipped combination's reason is never cut mid-word
("... can be checke)"), and the empty-catalogue message names the tables correctly ("[[motor]] or [[gearhead]]",
not "[[motor], [[gearhead]]"). Text properties; no published numbers."""

from __future__ import annotations

import pytest

from mechverify.cli.select_motor import short_reason
from mechverify.components.catalogue import read_catalogue_file
from mechverify.errors import InputError

STEPPER = ("stepper 'my stepper' has no pull-out curve, so only holding at standstill can be checked; give "
           "pullout_speeds and pullout_torques from the datasheet (holding torque is not a running torque)")


def test_reason_is_whole_or_shortened_at_a_word():
    assert short_reason(InputError("components.drive: " + STEPPER)) == "components.drive: " + STEPPER
    long = short_reason(InputError(" ".join([STEPPER] * 3)))
    assert len(long) <= 240 and long.endswith(" …")
    assert all(w in STEPPER.split() for w in long[:-2].split())  # every word whole


def test_empty_catalogue_message(tmp_path):
    f = tmp_path / "mine.toml"
    f.write_text("[references]\n")
    with pytest.raises(InputError, match=r"give \[\[motor\]\] or \[\[gearhead\]\] tables"):
        read_catalogue_file(f, {"motor": dict, "gearhead": dict})
