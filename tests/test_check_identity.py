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

