"""Enforced, not documented (issue 16): every registered check answers ``mechverify explain`` on the command line
under its name and under every former name. That every design-file check key is a registered name, every check is
in docs/design-files.md and every figure key is a registered check: tests/test_architecture.py."""

from __future__ import annotations

import pytest

from mechverify.checks.registry import all_checks
from mechverify.cli import main


@pytest.fixture(scope="module")
def checks():
    from mechverify.design import REGISTRY, adapters

    if hasattr(adapters, "load_all"):  # the adapters are imported lazily per design; load every one
        adapters.load_all()
    assert len(REGISTRY.types) > 20
    return list(all_checks())


def test_explain_answers_every_registered_check_on_the_command_line(checks, capsys):
    assert len(checks) > 60
    for d in checks:
        assert main(["explain", d.name]) == 0, d.name
        out = " ".join(capsys.readouterr().out.split())
        assert d.title.split()[0] in out and d.name in out, d.name


def test_explain_answers_every_former_name_with_the_current_one(checks, capsys):
    former = [(a, d) for d in checks for a in d.aliases]
    assert former  # the renamed checks keep their former names
    for alias, d in former:
        assert main(["explain", alias]) == 0, alias
        assert d.name in capsys.readouterr().out, alias



def test_explain_lists_what_a_check_without_needs_reads(capsys, monkeypatch):
    """Review 2 finding 6: explain's 'needs from a load case' line listed nothing for plate_fea's buckling, which runs
    once over every load case that gives in_plane. A CheckSpec declares such keys in ``reads``; explain prints them."""
    import dataclasses

    from mechverify.checks.fea import check_buckling_load_factor
    from mechverify.design import REGISTRY
    from mechverify.design.spec import CheckSpec

    spec = CheckSpec.of(check_buckling_load_factor, lambda c, loads, ctx: None, reads=("in_plane",))
    assert spec.reads == ("in_plane",)
    plate = REGISTRY.types["plate_fea"]
    checks = tuple(spec if c.name == spec.name else c for c in plate.checks)
    monkeypatch.setitem(REGISTRY._types, "plate_fea", dataclasses.replace(plate, checks=checks))
    assert main(["explain", "buckling_load_factor"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if "component type plate_fea" in x)
    assert line.endswith("key checks.buckling_load_factor; reads from each load case that gives it: in_plane"), line


def test_plate_buckling_explain_names_in_plane(capsys):
    """Review 2 finding 6: explain gave plate_fea's buckling_load_factor no load key; it reads in_plane."""
    assert main(["explain", "buckling_load_factor"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if "component type plate_fea" in x)
    assert line.endswith("reads from each load case that gives it: in_plane"), line
