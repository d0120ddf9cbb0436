"""The architecture, enforced: layer order of imports, no import cycles, one name per check, one bibliography.

Layer order (docs/architecture.md; imports only go to the same or a lower layer):
errors → units, references, fileio → materials, fatigue → components → mechanisms, motion → fea → checks
→ design → studies → reports → cli, demo. The package root ``mechverify/__init__.py`` re-exports the
public API and is exempt; no module may import it (``__version__`` excepted).
"""

from __future__ import annotations

import ast
import glob
import re
from pathlib import Path

import pytest

from mechverify.checks.registry import CHECKS, all_checks, explain_text, get_check
from mechverify.references import references

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "mechverify"

LAYERS: dict[str, int] = {
    "errors": 0, "frozen": 0, "pint_cache": 0,
    "units": 1, "references": 1, "fileio": 1,
    "materials": 2, "fatigue": 2,
    "components": 3,
    "mechanisms": 4, "motion": 4,
    "fea": 5,
    "checks": 6,
    "design": 7,
    "studies": 8,
    "reports": 9,
    "cli": 10, "demo": 10,
}


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports(path: Path, top_level_only: bool = False) -> list[tuple[int, str]]:
    """(line, module) of every ``mechverify`` import in a file; ``top_level_only`` skips imports inside
    functions, classes and ``if TYPE_CHECKING`` blocks (they do not run when the module loads)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    nodes: list[ast.AST]
    if top_level_only:
        nodes = []
        for n in tree.body:
            if isinstance(n, ast.If) and "TYPE_CHECKING" in ast.unparse(n.test):
                continue
            if isinstance(n, ast.Import | ast.ImportFrom | ast.If | ast.Try):
                nodes.extend(ast.walk(n))
    else:
        nodes = list(ast.walk(tree))
    out = []
    for n in nodes:
        if isinstance(n, ast.Import):
            out += [(n.lineno, a.name) for a in n.names if a.name.split(".")[0] == "mechverify"]
        elif isinstance(n, ast.ImportFrom) and n.level == 0 and n.module and n.module.split(".")[0] == "mechverify":
            if n.module == "mechverify":  # from mechverify import materials -> mechverify.materials
                out += [(n.lineno, "mechverify" if a.name.startswith("__") else f"mechverify.{a.name}")
                        for a in n.names if a.name != "__version__"]
            else:
                out.append((n.lineno, n.module))
    return out


def _layer(module: str) -> int | None:
    parts = module.split(".")
    return LAYERS.get(parts[1]) if len(parts) > 1 else None


FILES = sorted(p for p in PKG.rglob("*.py") if p != PKG / "__init__.py")


def test_every_package_has_a_layer():
    tops = {p.relative_to(PKG).parts[0].removesuffix(".py") for p in FILES}
    assert tops - set(LAYERS) <= {"__main__"}, f"add {sorted(tops - set(LAYERS))} to LAYERS (and the doc's map)"


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(ROOT)))
def test_imports_follow_the_layer_order(path: Path):
    """No module imports a higher layer, nor the package root (which re-exports everything)."""
    me = _module_name(path)
    mine = _layer(me)
    bad = []
    for line, target in _imports(path):
        if target == "mechverify":
            bad.append(f"line {line}: imports the package root")
            continue
        theirs = _layer(target)
        if mine is not None and theirs is not None and theirs > mine:
            bad.append(f"line {line}: {target} (layer {theirs}) from layer {mine}")
    assert not bad, f"{me}: " + "; ".join(bad)


def test_no_import_cycles():
    """Module-level imports between mechverify modules form no cycle (Tarjan's strongly connected components)."""
    modules = {_module_name(p): p for p in FILES}
    graph: dict[str, set[str]] = {}
    for m, p in modules.items():
        targets = set()
        for _, t in _imports(p, top_level_only=True):
            while t and t not in modules:  # `from mechverify.checks import members` names a module or a symbol
                t = t.rpartition(".")[0]
            if t and t != m and not m.startswith(t + "."):  # a package's own __init__ is loaded first anyway
                targets.add(t)
        graph[m] = targets
    assert sum(map(len, graph.values())) > 100  # the scan sees the imports (not vacuous)
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    cycles: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                cycles.append(sorted(comp))

    for v in graph:
        if v not in index:
            visit(v)
    assert not cycles, f"import cycles: {cycles}"


def test_the_checker_finds_an_upward_import(tmp_path):
    """The layer test is not vacuous: a components module importing design is reported."""
    f = tmp_path / "bad.py"
    f.write_text("from mechverify.design.spec import Field\nimport mechverify.checks.registry\n")
    found = [t for _, t in _imports(f)]
    assert found == ["mechverify.design.spec", "mechverify.checks.registry"]
    assert _layer(found[0]) > LAYERS["components"]


# ----------------------------------------------------------------------------------------- check registry
def test_every_check_has_a_working_explain_and_a_source():
    for d in all_checks():
        text = explain_text(d.name)
        assert d.title in text and d.explain and " ".join(d.explain.split())[:40] in " ".join(text.split()), d.name
        assert d.source and d.source_keys, f"{d.name}: cite its source with mechverify.references.ref()"
        assert d.function.__name__ == f"check_{d.name}", f"{d.name}: name the function check_{d.name}"


def test_every_check_appears_in_the_design_file_docs():
    doc = (ROOT / "docs" / "design-files.md").read_text(encoding="utf-8")
    missing = [d.name for d in all_checks() if not re.search(rf"`{re.escape(d.name)}`", doc)]
    assert not missing, (f"document {missing} in docs/design-files.md (the check index is "
                         "mechverify.checks.registry.checks_markdown())")


def test_every_figure_key_is_a_registered_check():
    from mechverify.reports import plots

    plots._load_domains()
    assert plots.PLOTTERS
    assert set(plots.PLOTTERS) <= set(CHECKS), set(plots.PLOTTERS) - set(CHECKS)


def test_every_component_type_check_is_registered_under_its_key():
    """A design file's check key is the registered name (former keys are aliases of it)."""
    from mechverify.design import REGISTRY, adapters  # noqa: F401

    for ct in REGISTRY.types.values():
        if ct.name == "test_rod":  # the test-only type of conftest.py
            continue
        for spec in ct.checks:
            d = get_check(spec.name)
            assert d.name == spec.name, f"{ct.name}: check key {spec.name!r} is not a registered name"
            assert (spec.title, spec.sf_kind) == (d.title, d.sf_kind), f"{ct.name}.{spec.name}: use CheckSpec.of"


@pytest.mark.slow
@pytest.mark.parametrize("path", sorted(glob.glob(str(ROOT / "examples" / "*" / "design*.toml"))),
                         ids=lambda p: str(Path(p).relative_to(ROOT)))
def test_example_result_names_are_registered_check_names(path: str):
    """Every result name of the examples is a registered check name with a working explain, and the key
    of its component type's check (design-file key = result name = explain name)."""
    from mechverify.design.design import load

    d = load(path)
    for r in d.verify():
        assert r.check in CHECKS, f"{r.component}: result {r.check!r} is not a registered check name"
        assert explain_text(r.check)
        ct = d.data.components[r.component].type
        assert r.check in {c.name for c in ct.checks}, f"{ct.name}: no check key {r.check!r}"


# ------------------------------------------------------------------------------------------- bibliography
def _ref_keys_in_source() -> list[tuple[str, int, str]]:
    out = []
    for p in FILES:
        for n in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if (isinstance(n, ast.Call) and isinstance(n.func, ast.Name | ast.Attribute)
                    and (n.func.id if isinstance(n.func, ast.Name) else n.func.attr) == "ref"
                    and n.args and isinstance(n.args[0], ast.Constant) and isinstance(n.args[0].value, str)):
                out.append((str(p.relative_to(ROOT)), n.lineno, n.args[0].value))
    return out


def test_every_cited_reference_key_is_in_the_bibliography():
    keys = _ref_keys_in_source()
    assert len(keys) > 20  # the scan finds the citations (not vacuous)
    known = references()
    missing = [f"{f}:{line} {k!r}" for f, line, k in keys if k not in known]
    assert not missing, "add these to mechverify/references.toml: " + ", ".join(missing)


def test_one_edition_per_book():
    seen: dict[tuple[str, str], str] = {}
    for k, r in references().items():
        key = (r.authors, r.title)
        assert key not in seen, f"{k} and {seen[key]} are the same source"
        seen[key] = k


#: Known exceptions, to be replaced by public accessors (none left).
PRIVATE_ACCESS_ALLOWED: set[tuple[str, str]] = set()


def test_checks_use_public_accessors_only():
    """A check reads what it needs through public attributes, never another object's private member."""
    bad = []
    for p in sorted((PKG / "checks").glob("*.py")):
        rel = str(p.relative_to(ROOT))
        for n in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if (isinstance(n, ast.Attribute) and n.attr.startswith("_") and not n.attr.endswith("_")
                    and not (isinstance(n.value, ast.Name) and n.value.id in ("self", "cls"))
                    and (rel, ast.unparse(n)) not in PRIVATE_ACCESS_ALLOWED):
                bad.append(f"{rel}:{n.lineno} {ast.unparse(n)}")
    assert not bad, bad
