"""Build the report's content from designs and results, render it with Jinja2, write HTML or PDF."""

from __future__ import annotations

import datetime as _dt
import math
import platform
import re
import subprocess
from importlib import metadata, resources
from pathlib import Path
from typing import Any

import jinja2
import pint
from markupsafe import Markup

from mechverify.checks import CheckResult, ResultSet
from mechverify.errors import InputError
from mechverify.fileio import atomic_write
from mechverify.materials import Material
from mechverify.materials.material import PROPERTY_DIMENSIONS
from mechverify.references import bibliography, keys_in
from mechverify.reports.mathtext import formula_html
from mechverify.reports.numbers import design_units, number, quantity, quantity_in
from mechverify.reports.plots import figure_for, svg_data_uri, utilisation_chart
from mechverify.reports.symbols import describe, symbol_html

_PACKAGES = ("numpy", "scipy", "scikit-fem", "pint", "matplotlib", "jinja2", "weasyprint", "meshio", "trimesh")


def _anchor(*parts: str) -> str:
    return "-".join(re.sub(r"[^a-z0-9]+", "-", p.lower()).strip("-") for p in parts)


def _value(v: Any, units: dict[Any, str] | None = None) -> str:
    """A value for a table; a quantity also in the design file's own unit of its kind (``units``)."""
    if isinstance(v, pint.Quantity):
        return quantity_in(v, units)
    if isinstance(v, Material):
        return v.name
    if isinstance(v, dict):  # an inline table (e.g. motor_data): one "key = value" per line
        return "\n".join(f"{k} = {_value(x)}" for k, x in v.items())
    if isinstance(v, list | tuple):
        if any(isinstance(x, dict) for x in v):  # a list of tables (members, supports): one table per line
            return "\n".join("; ".join(f"{k} = {_value(y)}" for k, y in x.items()) if isinstance(x, dict)
                             else _value(x) for x in v)
        return ", ".join(_value(x) for x in v)
    if isinstance(v, float):
        return number(v, 4)
    return _truncate(str(v))


TEXT_LIMIT = 4000  # characters of a free text (description, note, value) shown before it is cut
FILE_LIMIT = 200_000  # characters of an input file shown in the appendix


def _truncate(text: str, limit: int = TEXT_LIMIT) -> str:
    """``text``, or its first ``limit`` characters and a note saying how much was left out."""
    if len(text) <= limit:
        return text
    return f"{text[:limit]} … [truncated: {len(text) - limit:,} more characters not shown]"


def not_verifiable(r: CheckResult) -> str:
    """The reason when the check could not be evaluated (beyond its method's validity), else ``""``."""
    return next((n for n in r.notes if n.startswith("Not verifiable")), "")


def _git_commit(path: Path | None) -> str:
    if path is None:
        return ""
    try:
        head = subprocess.run(["git", "-C", str(path.parent), "rev-parse", "HEAD"], capture_output=True, text=True,
                              timeout=5)
        if head.returncode != 0:
            return ""
        dirty = subprocess.run(["git", "-C", str(path.parent), "status", "--porcelain", "--", str(path.parent)],
                               capture_output=True, text=True, timeout=5).stdout.strip()
        return head.stdout.strip() + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.SubprocessError):
        return ""


BAR_MAX = 2.0  # the summary bars' shared scale ends at u·SF = 2 (larger values: a full bar and "▶")


def bar_scale(results: list[CheckResult]) -> float:
    """One scale for every bar of a summary: up to the largest finite u·SF, at least 1.25, at most 2."""
    finite = [r.factored_utilisation for r in results if math.isfinite(r.factored_utilisation)]
    return min(BAR_MAX, max([1.25, *finite]))


DETAIL_LIMIT = 150  # failing and warning checks shown in detail by default (worst first); all with detail="all"
SUMMARY_ROWS = 300  # a design with more checks lists only its failing and warning ones in the summary table
PROBLEM_ROWS = 1000  # ... and at most this many of those (the worst); all are in the JSON, JUnit and Markdown
FIGURE_LIMIT = 40  # figures per design (worst checks first); a big design's report stays fast and printable


class _Budget:
    """How many figures a report may still draw."""

    def __init__(self, n: int):
        self.left, self.skipped = n, 0

    def take(self) -> bool:
        if self.left > 0:
            self.left -= 1
            return True
        self.skipped += 1
        return False


class _Context:
    """What a design gives every check view: the design file's own units and its derived values."""

    def __init__(self, data: Any = None):
        self.units = design_units(getattr(data, "raw", None) or {}) if data is not None else {}
        trace = getattr(data, "trace", None)
        self.entries: dict[str, tuple[str, Any]] = dict(trace.entries) if trace is not None else {}
        self.cases = list(getattr(data, "load_cases", {}) or {})

    def derived(self, component: str, load_case: str) -> list[tuple[str, str, Any]]:
        """(key, expression, value) of the component's derived fields and its derived loads in ``load_case``."""
        if not self.entries:
            return []
        out = []
        prefixes = [f"components.{component}."]
        prefixes += [f"load_cases.{c}.{component}." for c in self.cases
                     if load_case == c or load_case.startswith(c + " (")]
        for p, (src, v) in self.entries.items():
            for pre in prefixes:
                if p.startswith(pre) and "." not in p[len(pre):]:
                    out.append((p[len(pre):], src, v))
        return out


def _same(a: Any, b: Any) -> bool:
    if not (isinstance(a, pint.Quantity) and isinstance(b, pint.Quantity)) or a.dimensionality != b.dimensionality:
        return False
    try:
        x, y = float(a.m_as(b.units)), float(b.magnitude)
    except (TypeError, ValueError):
        return False
    return abs(x - y) <= 1e-9 * max(abs(x), abs(y)) and y != 0


def _check_view(r: CheckResult, scale: float = 1.25, detail: bool = True,
                budget: _Budget | None = None, ctx: _Context | None = None) -> dict[str, Any]:
    fu = r.factored_utilisation
    na = not_verifiable(r)
    view = {
        "anchor": _anchor(r.component, r.check), "component": r.component, "title": r.title or r.check,
        "verdict": r.verdict.value, "na": _truncate(na),
        "demand": "n/a" if na else quantity_in(r.demand, ctx.units if ctx else None),
        "capacity": "n/a" if na else quantity_in(r.capacity, ctx.units if ctx else None),
        "u": "n/a" if na else number(r.utilisation), "fu": "n/a" if na else number(fu),
        "sf": f"{r.required_sf:g}", "achieved_sf": "n/a" if na else number(r.safety_factor),
        "bar": f"{0 if na else min(fu, scale) / scale * 100:.1f}", "over": fu > scale and not na,
        "limit": f"{100 / scale:.1f}", "load_case": r.load_case, "detail": detail,
    }
    if detail:  # the expensive parts (typeset formulas, figures) only for checks shown in detail
        inputs = _inputs_view(r, ctx)
        traced = {i["derived_key"] for i in inputs if i["origin"]}
        view.update({
            "formula": Markup(formula_html(r.formula)),
            "substituted": Markup(formula_html(substituted_latex(r))) if substituted_latex(r) else "",
            "inputs": inputs,
            "notes": [_truncate(n) for n in r.notes if n != na and not _note_traced(n, traced)],
            "warnings": [_truncate(w) for w in r.warnings],
            "source": r.source,
            "figure": None if na or (budget is not None and not budget.take()) else figure_for(r),
        })
    return view


def substituted_latex(r: CheckResult) -> str:
    """The check's formula with its inputs substituted (LaTeX), when the check function gave one."""
    return getattr(r, "substituted", "") or ""


def _inputs_view(r: CheckResult, ctx: _Context | None = None) -> list[dict[str, Any]]:
    """One row per input: the formula's symbol, the value (also in the design file's unit), a description and,
    for a value derived from parameters or another component's output, the expression it came from."""
    derived = ctx.derived(r.component, r.load_case) if ctx else []
    rows = []
    for k, v in r.inputs.items():
        sym, desc = describe(r.check, k)
        hit = next(((key, src) for key, src, val in derived if key == k or _same(v, val)), None)
        rows.append({"key": k, "symbol": symbol_html(sym) if sym else "",
                     "value": _value(v, ctx.units if ctx else None), "description": desc,
                     "origin": f"← {hit[1]} ({hit[0]})" if hit else "", "derived_key": hit[0] if hit else ""})
    return rows


_DERIVED_NOTE = re.compile(r"^derived input(?: \([^)]*\))?: (\S+) = ")


def _note_traced(note: str, keys: set[str]) -> bool:
    """A "derived input: key = value ← expression" note whose key the inputs table already traces."""
    m = _DERIVED_NOTE.match(note)
    return bool(m and m.group(1) in keys)


def _material_view(m: Material) -> dict[str, Any]:
    props = [{"name": p, "value": quantity(getattr(m, p)), "source": m.source_of(p)}
             for p in PROPERTY_DIMENSIONS if getattr(m, p) is not None]
    if m.sn_curve is not None:
        props.append({"name": "S-N curve", "value": f"{len(m.sn_curve.cycles)} points, R = {m.sn_curve.stress_ratio:g}",
                      "source": m.sn_curve.source})
    return {"name": m.name, "props": props}


def _design_view(design: Any, rs: ResultSet, detail: str = "problems") -> dict[str, Any]:
    from mechverify.design.outputs import file_hashes

    ordered = rs.sorted()
    scale = bar_scale(list(ordered))
    problems = [r for r in ordered if r.verdict.value != "pass"]
    detailed = list(ordered) if detail == "all" else problems[:DETAIL_LIMIT]
    shown = {id(r) for r in detailed}
    # the summary lists every check of a design up to SUMMARY_ROWS checks, else the failing and warning ones
    listed = list(ordered) if detail == "all" or len(ordered) <= SUMMARY_ROWS else problems[:PROBLEM_ROWS]
    short = len(listed) < len(ordered)
    passing_unlisted = [r for r in ordered if r.verdict.value == "pass"] if short else []
    budget = _Budget(FIGURE_LIMIT)  # worst first: the figures go to the checks that matter most
    ctx = _Context(getattr(design, "data", None))
    views = {id(r): _check_view(r, scale, id(r) in shown, budget, ctx) for r in ordered}  # each figure rendered once
    by_comp: dict[str, list[CheckResult]] = {}
    for r in ordered:
        by_comp.setdefault(r.component, []).append(r)
    comps, mats = [], {}
    entries = getattr(design, "data", None)
    for name, entry in (entries.components.items() if entries else []):
        if detail != "all" and not any(id(r) in shown for r in by_comp.get(name, [])):
            continue  # a component whose checks all pass: in the summary only
        params = []
        written = entry.raw if isinstance(getattr(entry, "raw", None), dict) else entry.params
        for k, v in entry.params.items():
            # a key the file (or its template) does not write is the type's default, not "design file"
            src = v.source if isinstance(v, Material) and v.source else "design file" if k in written else "default"
            derived = entries.trace.entries.get(f"components.{name}.{k}") if hasattr(entries, "trace") else None
            if derived:
                src = f"design file: ← {derived[0]}"
            if isinstance(v, Material):
                mats[v.name] = v
            params.append({"name": k, "value": _value(v, ctx.units), "source": src})
        figures = []
        if entry.type.figures is not None and entry.obj is not None and budget.take():
            for caption, fig in entry.type.figures(entry.obj, by_comp.get(name, [])):
                figures.append({"caption": caption, "uri": svg_data_uri(fig)})
        comps.append({"name": name, "anchor": _anchor(name), "type": entry.type.name, "doc": entry.type.doc,
                      "params": params, "figures": figures, "checks": [views[id(r)] for r in by_comp.get(name, [])]})
    for name in by_comp:  # results for components not declared in a design file (Python API)
        if not any(c["name"] == name for c in comps):
            if detail != "all" and not any(id(r) in shown for r in by_comp[name]):
                continue
            comps.append({"name": name, "anchor": _anchor(name), "type": "", "doc": "", "params": [], "figures": [],
                          "checks": [views[id(r)] for r in by_comp[name]]})
    for c in comps:  # in a component's detail, only the checks shown in detail
        c["checks"] = [v for v in c["checks"] if v["detail"]]
    files = list(getattr(design, "files", []) or [])
    inputs = []
    for f in files:
        try:
            inputs.append({"name": f.name, "text": _truncate(f.read_text(encoding="utf-8"), FILE_LIMIT)})
        except OSError:
            pass
    counts = {v: sum(r.verdict.value == v for r in rs) for v in ("pass", "warn", "fail")}
    return {
        "name": getattr(design, "name", rs.name) or rs.name, "revision": getattr(design, "revision", ""),
        "description": _truncate(getattr(getattr(design, "data", None), "description", "") or ""),
        "detail": detail, "n_detailed": len(shown), "bar_scale": f"{scale:g}",
        "figures_skipped": budget.skipped, "figure_limit": FIGURE_LIMIT,
        "verdict": rs.verdict.value, "counts": counts, "hashes": file_hashes(files),
        "commit": _git_commit(getattr(design, "path", None)),
        "results": [views[id(r)] for r in listed],
        "unlisted": len(passing_unlisted), "unlisted_max": (
            f"{number(passing_unlisted[0].factored_utilisation)} ({passing_unlisted[0].component}: "
            f"{passing_unlisted[0].title or passing_unlisted[0].check})" if passing_unlisted else ""),
        "problems_unlisted": len(problems) - len(listed) if short else 0,
        "problems_not_detailed": max(0, len(problems) - DETAIL_LIMIT) if detail != "all" else 0,
        "detail_limit": DETAIL_LIMIT,
        "chart": utilisation_chart(list(rs)) if len(rs) else None,
        "components": comps, "materials": [_material_view(m) for m in mats.values()], "inputs": inputs,
        "references": [c for _, c in bibliography(keys_in("\n".join(r.source for r in rs)))],
        **_parameters_view(entries),
        "overrides": [{"key": k, "value": str(v)} for k, v in (getattr(design, "overrides", None) or {}).items()],
    }


def _parameters_view(data: Any) -> dict[str, Any]:
    """The design's [parameters] and every derived value with its expression and what it reads (the load path)."""
    from mechverify.design.parameters import show

    trace = getattr(data, "trace", None)
    params = getattr(data, "parameters", None) or {}
    entries = trace.entries if trace is not None else {}
    edges = trace.edges if trace is not None else {}
    return {
        "parameters": [{"name": k, "value": show(v), "expression": entries.get(f"parameters.{k}", ("",))[0]}
                       for k, v in params.items()],
        "derived": [{"path": p, "value": show(v), "expression": src, "reads": ", ".join(edges.get(p, ()))}
                    for p, (src, v) in entries.items() if not p.startswith("parameters.")],
    }


def _software() -> list[tuple[str, str]]:
    out = [("python", platform.python_version()), ("platform", platform.platform())]
    for p in _PACKAGES:
        try:
            out.append((p, metadata.version(p)))
        except metadata.PackageNotFoundError:
            out.append((p, "not installed"))
    return out


DETAIL = ("problems", "all")


def render_html(runs: list[tuple[Any, ResultSet]], date: str | None = None, detail: str = "all") -> str:
    """The complete self-contained HTML report of one or more verified designs.

    ``detail="problems"`` (the CLI's default): the per-component detail (formulas, inputs, figures)
    covers the failing and warning checks (the 150 worst); the summary lists every check (in a design of
    more than 300 checks the failing and warning ones). ``detail="all"`` (the API's default): every check.
    """
    if detail not in DETAIL:
        raise InputError(f"report detail: expected one of {', '.join(DETAIL)}, got {detail!r}")
    from mechverify import __version__

    tpl_dir = resources.files("mechverify.reports").joinpath("templates")
    env = jinja2.Environment(autoescape=jinja2.select_autoescape(["html", "j2"]), trim_blocks=True,
                             lstrip_blocks=True, undefined=jinja2.StrictUndefined)
    template = env.from_string(tpl_dir.joinpath("report.html.j2").read_text(encoding="utf-8"))
    designs = [_design_view(d, rs, detail) for d, rs in runs]
    return template.render(
        title=" / ".join(d["name"] for d in designs) or "design review", designs=designs, version=__version__,
        date=date or _dt.date.today().isoformat(), software=_software(),
        css=Markup(tpl_dir.joinpath("report.css").read_text(encoding="utf-8")),
    )


def write_report(runs: list[tuple[Any, ResultSet]], path: str | Path, detail: str = "all",
                 html: str | None = None) -> Path:
    """Write ``path`` (.html or .pdf) atomically; return it. ``detail``: see :func:`render_html`.

    ``html``: the report already rendered by :func:`render_html` for these runs (writing the HTML and
    the PDF of one review renders its formulas and figures once).
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".html", ".htm", ".pdf"):
        raise InputError(f"report: expected a .html or .pdf file name, got {str(path)!r}")
    text = render_html(runs, detail=detail) if html is None else html
    if suffix != ".pdf":
        return atomic_write(path, text)

    def pdf(tmp: Path) -> None:
        import logging

        from weasyprint import HTML

        logging.getLogger("weasyprint").setLevel(logging.ERROR)
        logging.getLogger("fontTools").setLevel(logging.ERROR)
        HTML(string=text, base_url=str(path.parent)).write_pdf(tmp)

    return atomic_write(path, pdf)


__all__ = ["render_html", "write_report"]
