"""The API reference builds from the docstrings without a warning (``make docs``: Sphinx, autodoc, napoleon)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.slow
def test_api_reference_builds_without_warnings(tmp_path):
    pytest.importorskip("sphinx", reason="install the docs extra: pip install -e '.[docs]'")
    r = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-q", "-W", "--keep-going",
                        str(ROOT / "docs" / "api"), str(tmp_path / "html")], capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stderr[-4000:]
    page = (tmp_path / "html" / "checks.html").read_text(encoding="utf-8")
    assert "check_screw_buckling" in page and "Raises" in page  # autodoc + napoleon sections are there
