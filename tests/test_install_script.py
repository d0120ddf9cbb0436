"""scripts/install.sh, what ``make`` installs with (issue 27): uv when it can be had, pip otherwise.

The interpreter, the venv's python and uv are replaced by small shell scripts that log their arguments, so the
tests check the script's decisions (which installer, which arguments, the fallbacks) in milliseconds, without a
network or a real installation. Measured times of the real thing: docs/performance.md, "Start-up and install".
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / "scripts" / "install.sh"

pytestmark = pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")

# The fake venv interpreter: `-m pip --version` fails until `-m ensurepip` has run; `-m pip install ... uv...`
# puts a fake uv into the venv.
VENV_PYTHON = """#!/bin/bash
echo "venv-python $*" >> "$LOG"
here=$(dirname "$0")
if [ "$1 $2" = "-m ensurepip" ]; then touch "$here/.has-pip"; exit 0; fi
if [ "$1 $2 $3" = "-m pip --version" ]; then [ -e "$here/.has-pip" ]; exit; fi
if [ "$1 $2" = "-m pip" ]; then [ -e "$here/.has-pip" ] || exit 1; fi
case "$*" in *"install -q uv>="*) cp "$FAKES/uv" "$here/uv" ;; esac
exit 0
"""
# The fake base interpreter: `-m venv [--without-pip] DIR` makes DIR/bin/python; `-m pip --python PY install uv`
# puts uv beside PY unless BOOTSTRAP_FAILS is set (no network, no pip).
BASE_PYTHON = """#!/bin/bash
echo "python $*" >> "$LOG"
if [ "$1 $2" = "-m venv" ]; then
  dir=${@: -1}; mkdir -p "$dir/bin"; cp "$FAKES/venv-python" "$dir/bin/python"; exit 0
fi
if [ "$1 $2 $3" = "-m pip --python" ]; then
  [ -n "${BOOTSTRAP_FAILS:-}" ] && exit 1
  cp "$FAKES/uv" "$(dirname "$4")/uv"; exit 0
fi
exit 1
"""
UV = """#!/bin/bash
echo "uv $*" >> "$LOG"
if [ "$1" = venv ]; then dir=${@: -1}; mkdir -p "$dir/bin"; cp "$FAKES/venv-python" "$dir/bin/python"; fi
exit 0
"""


@pytest.fixture
def fakes(tmp_path):
    d = tmp_path / "fakes"
    d.mkdir()
    for name, text in (("venv-python", VENV_PYTHON), ("python3", BASE_PYTHON), ("uv", UV)):
        (d / name).write_text(text)
        (d / name).chmod(0o755)
    return d


def run(tmp_path: Path, fakes: Path, *, uv_on_path: bool, **env: str) -> tuple[list[str], str]:
    """Run the script in ``tmp_path`` with the fakes; the logged calls (paths shortened) and stderr."""
    log = tmp_path / "calls.log"
    log.unlink(missing_ok=True)
    path = os.pathsep.join(([str(tmp_path / "onpath")] if uv_on_path else []) + ["/usr/bin", "/bin"])
    if uv_on_path:
        (tmp_path / "onpath").mkdir(exist_ok=True)
        shutil.copy(fakes / "uv", tmp_path / "onpath" / "uv")
    full = {"PATH": path, "LOG": str(log), "FAKES": str(fakes), "PYTHON": str(fakes / "python3"), "HOME": str(tmp_path),
            **env}
    proc = subprocess.run(["bash", str(SCRIPT), "-e", ".[mesh]"], cwd=tmp_path, env=full, capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    calls = log.read_text().replace(str(fakes) + "/", "").replace(str(tmp_path) + "/", "").splitlines()
    return calls, proc.stderr


def test_uv_on_path_makes_the_venv_and_installs(tmp_path, fakes):
    calls, _ = run(tmp_path, fakes, uv_on_path=True)
    assert calls == ["uv venv -q --python python3 .venv",
                     "uv pip install -q --python .venv/bin/python -e .[mesh]"]


def test_without_bytecode_writes_uv_compiles_at_install(tmp_path, fakes):
    """With PYTHONDONTWRITEBYTECODE set, Python never writes the bytecode of what it imports: uv compiles it."""
    calls, _ = run(tmp_path, fakes, uv_on_path=True, PYTHONDONTWRITEBYTECODE="1")
    assert calls[-1] == "uv pip install -q --compile-bytecode --python .venv/bin/python -e .[mesh]"


def test_uv_is_bootstrapped_into_the_venv_when_not_on_path(tmp_path, fakes):
    calls, _ = run(tmp_path, fakes, uv_on_path=False)
    assert calls == ["python -m venv --without-pip .venv",
                     "python -m pip --python .venv/bin/python install -q uv>=0.5,<1",
                     "uv pip install -q --python .venv/bin/python -e .[mesh]"]
    assert (tmp_path / ".venv" / "bin" / "uv").exists()
    calls, _ = run(tmp_path, fakes, uv_on_path=False)  # the next install finds it in the venv
    assert calls == ["uv pip install -q --python .venv/bin/python -e .[mesh]"]


def test_pip_when_uv_cannot_be_had(tmp_path, fakes):
    calls, stderr = run(tmp_path, fakes, uv_on_path=False, BOOTSTRAP_FAILS="1")
    assert "installing with pip" in stderr
    assert calls[0] == "python -m venv --without-pip .venv"
    assert calls[-3:] == ["venv-python -m ensurepip", "venv-python -m pip install -q --upgrade pip",
                          "venv-python -m pip install -q -e .[mesh]"]
    assert not any(c.startswith("uv ") for c in calls)


def test_pip_when_asked_even_with_uv_on_path(tmp_path, fakes):
    calls, _ = run(tmp_path, fakes, uv_on_path=True, MECHVERIFY_INSTALLER="pip")
    assert not any(c.startswith("uv ") for c in calls)
    assert calls[-1] == "venv-python -m pip install -q -e .[mesh]"


def test_the_makefile_installs_through_the_script():
    """Every install of the Makefile goes through scripts/install.sh (one place that picks the installer)."""
    text = (ROOT / "Makefile").read_text()
    assert "pip install" not in text.replace("# ", "")
    assert text.count("$(INSTALL) ") >= 3


def test_install_messages_work_from_a_clone():
    """mechverify is not published on PyPI (README.md): an error asking for an optional extra said
    ``pip install 'mechverify[mesh]'``, which finds nothing. Every message is made by ``errors.install_hint``
    (one place) and names the clone's ``scripts/install.sh -e '.[extra]'``, the way README documents."""
    import re

    from mechverify.components.sections import SECTIONS_HINT
    from mechverify.errors import install_hint
    from mechverify.fea.mesh import GMSH_HINT

    for text in (GMSH_HINT, SECTIONS_HINT, install_hint("cluster")):
        assert re.search(r"scripts/install\.sh -e '\.\[(mesh|sections|cluster)\]'", text), text
        assert "pip install 'mechverify[" not in text
    from mechverify.fea.meshimport import MESHIO_HINT  # a base dependency: the base installation again

    assert "scripts/install.sh -e . " in MESHIO_HINT and "pip install 'meshio>=5.3,<5.4'" in MESHIO_HINT
    readme = (ROOT / "README.md").read_text()
    assert "scripts/install.sh -e '.[" in readme and "not published on PyPI" in readme
    for path in (ROOT / "mechverify").rglob("*.py"):
        src = path.read_text()
        assert not re.search(r"pip install '?mechverify\[", src), path  # the PyPI form, written by hand


def test_readme_lists_every_extra():
    """Review finding 25: the README's extras table lacked `explore` and `docs`; every optional dependency group of
    pyproject.toml has its row."""
    import re
    import tomllib

    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    rows = set(re.findall(r"^\| `([\w-]+)` \|", (ROOT / "README.md").read_text(), flags=re.M))
    assert set(extras) <= rows, set(extras) - rows
