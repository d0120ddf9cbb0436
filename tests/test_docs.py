"""Every documented snippet runs: the ```python and ```sh blocks of README.md and docs/*.md.

A block that cannot run in a test (it runs ``make``, needs network access, ...) is preceded by an
explicit ``<!-- skip-test: reason -->`` comment; every other block runs:

- a ``python`` or ``sh`` block that reads ``design.toml`` finds there the nearest ```toml block above it in
  the same document that holds a ``[design]`` table (the document's own example);
- a ``python`` block in a fresh interpreter of this virtual environment, in a temporary folder holding
  a copy of ``examples/`` (blocks of one file run separately: each must stand on its own);
- a ``sh`` block line by line (comments stripped, ``\\`` continuations joined) with bash in a temporary
  copy of ``examples/`` made a git repository (``origin/main`` points at its only commit, for
  ``diff --base-ref``), ``mechverify`` resolved to this virtual environment's. A ``mechverify`` line may
  exit 0 or 1 (the documented verdicts: a check failing is a finding, not an error of the snippet);
  anything else, or a traceback, fails the test.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```(\w+)[^\n]*\n(.*?)^```\s*$", re.S | re.M)
SKIP = re.compile(r"<!--\s*skip-test:\s*(.+?)\s*-->\s*$")


def blocks(path: Path) -> list[tuple[str, int, str, str | None, str | None]]:
    """(language, line number, code, skip reason, the nearest design-file block above) of every fenced
    block of ``path``."""
    text = path.read_text(encoding="utf-8")
    out = []
    design = None
    for m in FENCE.finditer(text):
        before = text[:m.start()].rstrip("\n").splitlines()
        skip = SKIP.search(before[-1]) if before else None
        out.append((m.group(1), text.count("\n", 0, m.start()) + 1, m.group(2), skip.group(1) if skip else None,
                    design))
        if m.group(1) == "toml" and re.search(r"^\[design\]", m.group(2), re.M):
            design = m.group(2)
    return out


def cases(lang: str) -> list:
    params = []
    for doc in DOCS:
        for kind, line, code, skip, design in blocks(doc):
            if kind != lang:
                continue
            marks = [pytest.mark.skip(reason=f"skip-test: {skip}")] if skip else []
            params.append(pytest.param(code, design, id=f"{doc.relative_to(ROOT)}:{line}", marks=marks))
    return params


@pytest.fixture()
def workdir(tmp_path: Path) -> Path:
    """A copy of examples/ (without generated reports) in a git repository with origin/main (the tests
    commit after each command line and move origin/main along: a user's design is committed)."""
    work = tmp_path / "work"
    shutil.copytree(ROOT / "examples", work / "examples",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pdf", "*.html", "out"))
    git = ["git", "-C", str(work), "-c", "user.name=t", "-c", "user.email=t@t", "-c", "commit.gpgsign=false"]
    subprocess.run([*git, "init", "-q"], check=True)
    commit(work)
    return work


def commit(work: Path) -> None:
    git = ["git", "-C", str(work), "-c", "user.name=t", "-c", "user.email=t@t", "-c", "commit.gpgsign=false"]
    subprocess.run([*git, "add", "-A"], check=True)
    subprocess.run([*git, "commit", "-q", "--allow-empty", "-m", "state"], check=True)
    subprocess.run([*git, "update-ref", "refs/remotes/origin/main", "HEAD"], check=True)


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    env.setdefault("MPLBACKEND", "Agg")
    env["COLUMNS"] = "160"
    return env


def sh_commands(code: str) -> list[str]:
    """The command lines of a sh block: comments dropped, continuation lines joined."""
    out, pending = [], ""
    for raw in code.splitlines():
        line = re.sub(r"(^|\s)#.*$", "", raw).strip()
        if line.endswith("\\"):
            pending += line[:-1].strip() + " "
            continue
        line = (pending + line).strip()
        pending = ""
        if line:
            out.append(line)
    return out


def test_every_doc_has_been_scanned():
    """The extraction itself: README has python and sh blocks; a skip comment is found."""
    kinds = [b[0] for b in blocks(ROOT / "README.md")]
    assert "python" in kinds and "sh" in kinds
    assert any(b[3] for b in blocks(ROOT / "README.md"))  # `make demo` is marked skip-test
    assert sh_commands("a  # x\nb \\\n  c\n# only a comment\n") == ["a", "b c"]


@pytest.mark.parametrize(("code", "design"), cases("python"))
def test_python_block_runs(code: str, design: str | None, workdir: Path):
    if design and "design.toml" in code:
        (workdir / "design.toml").write_text(design, encoding="utf-8")
    script = workdir / "snippet.py"
    script.write_text(code, encoding="utf-8")
    r = subprocess.run([sys.executable, str(script)], cwd=workdir, env=_env(), capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, f"the block failed:\n{code}\n--- stderr ---\n{r.stderr[-3000:]}"


@pytest.mark.parametrize(("code", "design"), cases("sh"))
def test_sh_block_runs(code: str, design: str | None, workdir: Path):
    if design and "design.toml" in code and "init design.toml" not in code:
        (workdir / "design.toml").write_text(design, encoding="utf-8")
        commit(workdir)
    for cmd in sh_commands(code):
        r = subprocess.run(["bash", "-c", cmd], cwd=workdir, env=_env(), capture_output=True, text=True,
                           timeout=300)
        allowed = (0, 1) if cmd.startswith("mechverify ") else (0,)
        assert r.returncode in allowed, f"{cmd!r} exited {r.returncode}:\n{r.stderr[-3000:]}"
        assert "Traceback" not in r.stderr and "internal error" not in r.stderr, f"{cmd!r}:\n{r.stderr[-3000:]}"
        commit(workdir)


def test_every_design_file_key_is_documented():
    """Every key a user can write in a design file (the [design] and [requirements] keys, every field and
    load of every component type) is named in docs/design-files.md: in backticks, as a table header, or
    written in an example (`key = ...`). The check keys are kept current by the registry's own test (tests/test_registry.py)."""
    from mechverify.design import REGISTRY, adapters  # noqa: F401
    from mechverify.design.loader import DESIGN_KEYS, REQUIREMENT_FIELDS

    text = (ROOT / "docs" / "design-files.md").read_text(encoding="utf-8")

    def documented(key: str) -> bool:
        return (f"`{key}`" in text or f".{key}]" in text  # `key`, a [table.key] header, or key = in an example
                or re.search(rf"(^|[{{,`]\s*){re.escape(key)}\s*=", text, re.M) is not None)

    missing = [f"design.{k}" for k in DESIGN_KEYS if not documented(k)]
    missing += [f"requirements.{f.name}" for f in REQUIREMENT_FIELDS if not documented(f.name)]
    for ct in REGISTRY.types.values():
        if ct.name.startswith("test_"):  # conftest.py's test-only types
            continue
        missing += [f"{ct.name}.{f.name}" for f in (*ct.fields, *ct.loads) if not documented(f.name)]
    assert not missing, f"not in docs/design-files.md: {missing}"
