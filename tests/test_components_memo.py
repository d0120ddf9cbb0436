"""components.memo.once: values derived from immutable objects, remembered per object set (issue 19, a study sample).

No published number is involved: the tests guard the mechanics (computed once per object set, per name; the
objects held so that their ids are never reused for another object while remembered; errors not remembered;
bounded) and that a screw check answers the same after its constants were remembered.
"""

from __future__ import annotations

import gc

import pytest

from mechverify.checks.screws import check_nut_flank_pressure, check_screw_buckling
from mechverify.components import memo
from mechverify.components.power_screw import LeadScrew, Nut
from mechverify.errors import InputError
from mechverify.units import Q


class Box:
    pass


def test_once_per_name_and_object_set():
    memo.clear()
    a, b, calls = Box(), Box(), []

    def make(tag):
        calls.append(tag)
        return tag

    assert memo.once("x", (a,), lambda: make(1)) == 1 and memo.once("x", (a,), lambda: make(2)) == 1
    assert memo.once("y", (a,), lambda: make(3)) == 3 and memo.once("x", (b,), lambda: make(4)) == 4
    assert memo.once("x", (a, b), lambda: make(5)) == 5 and memo.once("x", (b, a), lambda: make(6)) == 6
    assert calls == [1, 3, 4, 5, 6]


def test_an_object_is_held_so_its_id_is_not_taken_by_another():
    memo.clear()
    a = Box()
    memo.once("x", (a,), lambda: "first")
    ident = id(a)
    del a
    gc.collect()
    others = [Box() for _ in range(1000)]  # none can take the id: the memo holds the first object
    assert all(id(o) != ident for o in others)
    assert all(memo.once("x", (o,), lambda: "new") == "new" for o in others[:10])


def test_errors_are_not_remembered_and_the_table_is_bounded(monkeypatch):
    memo.clear()
    a, calls = Box(), []

    def bad():
        calls.append(1)
        raise InputError("no")

    for _ in range(2):
        with pytest.raises(InputError):
            memo.once("x", (a,), bad)
    assert len(calls) == 2
    monkeypatch.setattr(memo, "LIMIT", 5)
    keep = [Box() for _ in range(12)]
    for o in keep:
        memo.once("x", (o,), lambda: 1)
    assert len(memo._MEMO) <= 5


def test_screw_checks_answer_the_same_with_their_constants_remembered():
    """A remembered screw/nut: the results equal those of fresh objects, for several forces (JSON)."""
    def fresh():
        return (LeadScrew("Tr10x2", "450 mm", material="Inventor Steel", end_supports="supported-supported"),
                Nut(material="iglidur R", length="10 mm"))

    screw, nut = fresh()
    for F in ("350 N", "1.2 kN", Q(35.0, "N")):
        s2, n2 = fresh()
        assert (check_nut_flank_pressure(screw, nut, F).to_dict() == check_nut_flank_pressure(s2, n2, F).to_dict())
        assert check_screw_buckling(screw, F).to_dict() == check_screw_buckling(s2, F).to_dict()
    with pytest.raises(InputError, match="no allowable flank pressure"):  # not remembered as an answer
        check_nut_flank_pressure(screw, Nut(mu=0.1, length="10 mm"), "350 N")
