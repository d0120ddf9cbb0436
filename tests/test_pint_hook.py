"""``import pint`` through mechverify leaves out pint's dask and babel integrations (mechverify/__init__.py,
_PintWithoutExtras): 9 MB and ~90 ms of start-up that no mechverify code uses. Oracles: the modules present in a fresh
interpreter after importing mechverify's units (not a timing), dask importable afterwards, pint's own behaviour."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

CODE = """
import json, sys
import mechverify.units as u
before = {m: m in sys.modules for m in ("pint", "dask", "babel")}
q = u.Q("3 kN").to("N").magnitude
hooks = [type(f).__name__ for f in sys.meta_path if type(f).__name__ == "_PintWithoutExtras"]
try:
    import dask  # the studies' Dask executor imports it later
    later = True
except ImportError:
    later = None
print(json.dumps({"before": before, "q": q, "hooks": hooks, "later": later}))
"""


def test_pint_is_imported_without_dask_and_babel_and_dask_still_imports_later():
    out = json.loads(subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True, check=True).stdout)
    assert out["before"] == {"pint": True, "dask": False, "babel": False}
    assert out["q"] == 3000.0
    assert out["hooks"] == []  # one-shot: gone once pint is imported
    try:
        import dask  # noqa: F401
    except ImportError:
        pytest.skip("dask not installed: nothing to hide")
    assert out["later"] is True


def test_nothing_happens_when_pint_came_first():
    code = ("import sys, pint, mechverify.units; "
            "print(sum(type(f).__name__ == '_PintWithoutExtras' for f in sys.meta_path))")
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True).stdout.strip() == "0"
