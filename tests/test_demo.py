"""``python -m mechverify.demo`` (``make demo``), its error path (issue 27)."""

from __future__ import annotations

import mechverify.demo as demo
from mechverify.errors import ModelError


def test_an_error_is_shown_as_written_not_as_markup(monkeypatch, capsys):
    """A message naming ``scripts/install.sh -e '.[mesh]'`` (the demo's plates need gmsh) kept its ``[mesh]``:
    rich took it for a markup tag and printed ``pip install 'mechverify'`` (the message of the time)."""
    from mechverify.fea.mesh import GMSH_HINT

    def fail(*a, **k):
        raise ModelError(GMSH_HINT)

    monkeypatch.setattr(demo, "load_example", fail)
    assert demo.main(["--no-pdf"]) == 2
    assert "scripts/install.sh -e '.[mesh]'" in capsys.readouterr().err
