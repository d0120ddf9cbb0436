"""The package does not use its own deprecated names (issue 16).

Former public names stay importable as deprecated aliases (``mechverify.errors.renamed``: a
``DeprecationWarning`` "mechverify.<module>.<name> is deprecated; use ..."), and former design-file check keys
are accepted with a "Deprecated check key" note. Neither may be used by mechverify itself or by its examples:
in a fresh interpreter (so module-level imports count too), every module of the package is imported and every
example design is loaded and verified while mechverify's own deprecation warnings are recorded; the test fails on
any of them, and on any result that carries a deprecated-key note. (Recorded rather than raised: a design's
loader turns exceptions in a component into a design error, which would hide the warning's origin.)
Tests of the aliases themselves are in tests/test_public_names.py.
"""

from __future__ import annotations

import json
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
OWN = r"mechverify\.\S+ is deprecated"  # the message of errors.renamed's warnings, and only those

_SCRIPT = r"""
import glob, importlib, json, pkgutil, re, sys, warnings

found = []
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    import mechverify

    for m in pkgutil.walk_packages(mechverify.__path__, "mechverify."):
        if m.name.endswith("__main__"):
            continue
        try:
            importlib.import_module(m.name)
        except ImportError as exc:  # an optional dependency (gmsh, ...) that is not installed
            print(f"skipped {m.name}: {exc}", file=sys.stderr)
    from mechverify.checks.registry import deprecation_note

    note = deprecation_note("X", "Y").split("'X'")[0]
    for path in sorted(glob.glob("examples/*/design*.toml")):
        start = len(caught)
        for r in mechverify.load(path).verify():
            found += [f"{path}: {r.component}/{r.check}: {n}" for n in r.notes if n.startswith(note)]
        found += [f"{path}: {w.filename}:{w.lineno}: {w.message}" for w in caught[start:]
                  if issubclass(w.category, DeprecationWarning) and re.match(sys.argv[1], str(w.message))]
        del caught[start:]
    found += [f"import: {w.filename}:{w.lineno}: {w.message}" for w in caught
              if issubclass(w.category, DeprecationWarning) and re.match(sys.argv[1], str(w.message))]
print(json.dumps(found))
"""


def test_the_filter_catches_mechverify_deprecations_only():
    """Not vacuous: a deprecated alias raises under the filter this module uses; another package's does not."""
    from mechverify.components import plates

    with warnings.catch_warnings(record=True) as other:
        warnings.simplefilter("always")
        warnings.filterwarnings("error", message=OWN, category=DeprecationWarning)
        with pytest.raises(DeprecationWarning, match="use mechverify.components.plates.PlatePointLoad"):
            _ = plates.PointLoad
        warnings.warn("somepackage.thing is old", DeprecationWarning, stacklevel=1)  # not ours: recorded only
    assert [str(w.message) for w in other] == ["somepackage.thing is old"]

@pytest.mark.slow
def test_package_and_examples_use_no_deprecated_name():
    """Every module imported and every example design verified in a fresh interpreter: no mechverify
    DeprecationWarning, no deprecated design-file check key."""
    out = subprocess.run([sys.executable, "-c", _SCRIPT, OWN], cwd=ROOT, capture_output=True, text=True,
                         timeout=600)
    assert out.returncode == 0, out.stderr[-3000:]
    found = json.loads(out.stdout.strip().splitlines()[-1])
    assert not found, "deprecated names used:\n" + "\n".join(found)
