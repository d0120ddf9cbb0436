"""``python -m mechverify.demo`` (``make demo``), its error path (issue 27)."""

from __future__ import annotations

import mechverify.demo as demo
from mechverify.errors import ModelError


def test_an_error_is_shown_as_written_not_as_markup(monkeypatch, capsys):
    """A message naming ``pip install 'mechverify[mesh]'`` (the demo's plates need gmsh) kept its ``[mesh]``:
    rich took it for a markup tag and printed ``pip install 'mechverify'``."""
    def fail(*a, **k):
        raise ModelError("this needs the gmsh mesher: pip install 'mechverify[mesh]'  (or: pip install gmsh)")

    monkeypatch.setattr(demo, "load_example", fail)
    assert demo.main(["--no-pdf"]) == 2
    assert "pip install 'mechverify[mesh]'" in capsys.readouterr().err
