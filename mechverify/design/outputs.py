"""Machine-readable outputs of a verification run: deterministic JSON, JUnit XML, and revision diffs."""

from __future__ import annotations

import hashlib
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mechverify.checks import CheckResult, ResultSet, Verdict
from mechverify.units import fmt


def file_hashes(files: list[Path]) -> dict[str, str]:
    """SHA-256 of each design file (names relative to the first file's folder)."""
    if not files:
        return {}
    root = files[0].parent
    out = {}
    for f in files:
        try:
            name = str(f.relative_to(root))
        except ValueError:
            name = str(f)
        out[name] = hashlib.sha256(f.read_bytes()).hexdigest()
    return out


def run_document(designs: list[tuple[Any, ResultSet]]) -> dict[str, Any]:
    """The JSON document of a ``check`` run: one entry per design, with file hashes."""
    from mechverify import __version__

    worst = max((rs.verdict for _, rs in designs), key=lambda v: v.rank, default=Verdict.PASS)
    return {
        "mechverify": __version__,
        "verdict": worst.value,
        "designs": [{"name": d.name, "revision": d.revision, "files": file_hashes(d.files), **_load_path(d),
                     **rs.to_dict()} for d, rs in designs],
    }


def _load_path(design: Any) -> dict[str, Any]:
    """Parameters, derived values (key path -> value and expression) and overrides, when the design has any."""
    from mechverify.design.expressions import format_value

    data = getattr(design, "data", None)
    trace = getattr(data, "trace", None)
    out: dict[str, Any] = {}
    if getattr(data, "parameters", None):
        out["parameters"] = {k: format_value(v) for k, v in data.parameters.items()}
    if trace is not None and trace.entries:
        out["derived"] = {p: {"value": format_value(v), "expression": src, "reads": list(trace.edges.get(p, ()))}
                          for p, (src, v) in trace.entries.items()}
    if getattr(design, "overrides", None):
        out["overrides"] = {k: str(v) for k, v in design.overrides.items()}
    return out


def to_json(doc: dict[str, Any]) -> str:
    """Deterministic JSON text (sorted keys, fixed indentation, trailing newline)."""
    from mechverify.fileio import json_text

    return json_text(doc, sort_keys=True, indent=2, ensure_ascii=False) + "\n"


def junit_xml(designs: list[tuple[Any, ResultSet]], fail_on: str = "fail") -> str:
    """JUnit XML: a ``testsuite`` per design, a ``testcase`` per check; failing checks are failures."""
    suites = ET.Element("testsuites", name="mechverify")
    total = failures = 0
    for d, rs in designs:
        suite = ET.SubElement(suites, "testsuite", name=rs.name or d.name)
        n_fail = 0
        for r in rs:
            case = ET.SubElement(suite, "testcase", classname=f"{d.name}.{r.component}", name=r.check, time="0")
            text = _case_text(r)
            failed = r.verdict is Verdict.FAIL or (fail_on == "warn" and r.verdict is Verdict.WARN)
            if failed:
                n_fail += 1
                f = ET.SubElement(case, "failure", message=f"{r.verdict.value}: utilisation {r.utilisation:.3g} "
                                                           f"with required SF {r.required_sf:g}", type=r.verdict.value)
                f.text = text
            else:
                ET.SubElement(case, "system-out").text = text
        suite.set("tests", str(len(rs)))
        suite.set("failures", str(n_fail))
        suite.set("errors", "0")
        total += len(rs)
        failures += n_fail
    suites.set("tests", str(total))
    suites.set("failures", str(failures))
    ET.indent(suites)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(suites, encoding="unicode") + "\n"


def _case_text(r: CheckResult) -> str:
    lines = [f"{r.title or r.check}: demand {fmt(r.demand)}, capacity {fmt(r.capacity)}, "
             f"utilisation {r.utilisation:.4g}, required SF {r.required_sf:g}, verdict {r.verdict.value}"]
    if r.load_case:
        lines.append(f"load case: {r.load_case}")
    if r.source:
        lines.append(f"source: {r.source}")
    lines += [f"note: {n}" for n in r.notes] + [f"warning: {w}" for w in r.warnings]
    return "\n".join(lines)


@dataclass(frozen=True)
class Change:
    component: str
    check: str
    status: str  # "added", "removed", "changed", "same"
    base: CheckResult | None
    head: CheckResult | None

    @property
    def delta(self) -> float:
        """Change of factored utilisation (head - base); NaN when either side is missing."""
        if self.base is None or self.head is None:
            return math.nan
        return self.head.factored_utilisation - self.base.factored_utilisation

    @property
    def lost_requirement(self) -> bool:
        """The head fails its requirement and is new or worse than the base."""
        if self.head is None or self.head.verdict is not Verdict.FAIL:
            return False
        return self.base is None or self.base.verdict is not Verdict.FAIL or self.delta > 1e-12


def diff(base: ResultSet, head: ResultSet, tol: float = 1e-9) -> list[Change]:
    """Pair checks by (component, check) and say what changed, biggest margin loss first."""
    b = {(r.component, r.check): r for r in base}
    h = {(r.component, r.check): r for r in head}
    out = []
    for key in sorted(set(b) | set(h)):
        rb, rh = b.get(key), h.get(key)
        if rb is None:
            status = "added"
        elif rh is None:
            status = "removed"
        elif rb.verdict is not rh.verdict or abs(rh.factored_utilisation - rb.factored_utilisation) > tol:
            status = "changed"
        else:
            status = "same"
        out.append(Change(key[0], key[1], status, rb, rh))
    out.sort(key=lambda c: (c.status == "same", -(c.delta if not math.isnan(c.delta) else math.inf)))
    return out
