"""Study report: one self-contained HTML (or PDF) page for a sweep or a Monte Carlo study.

Monte Carlo: the failure-probability table (Wilson 95 % intervals), the worst sample, the
sensitivity ranking, a histogram of u·SF per check with the limit line at 1, and a scatter of the
most influential input against the governing u·SF. Sweep: u·SF of each check against the first
axis (one curve per combination of the other axes) and the sample table. Figures are vector SVG
(:func:`mechverify.reports.plots.svg_data_uri`); the style is the design report's ``report.css``.
"""

from __future__ import annotations

import html
import itertools
import math
from pathlib import Path
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.reports.plots import new_figure, svg_data_uri
from mechverify.studies.study import StudyResult, pretty_unit

MAX_CHECK_FIGURES = 12  # histograms or curves for the checks with the highest u·SF
MAX_TABLE_ROWS = 300


def _e(x: Any) -> str:
    return html.escape(str(x))


def _num(v: float | None, digits: int = 4) -> str:
    return "inf" if v is None or (isinstance(v, float) and math.isinf(v)) else f"{v:.{digits}g}"


def _label(result: StudyResult, name: str) -> str:
    return result.label(name)


def _ylabel(check: str) -> str:
    """``u·SF`` with the check's name on a second line when it would not fit beside the axis (a figure
    2.6-3.2 in high holds about 30 characters of 8 pt text)."""
    text = f"u·SF of {check}"
    if len(text) <= 30:
        return text
    comp, _, name = check.rpartition(".")
    return f"u·SF of {comp}.\n{name}" if comp and len(name) <= 30 else f"u·SF of\n{check}"


def _ranked_checks(result: StudyResult) -> list[str]:
    """Checks by their highest u·SF over the study, highest first."""
    def peak(c: str) -> float:
        v = result.fu(c)
        v = v[np.isfinite(v)]
        return float(np.max(v)) if v.size else math.inf
    return sorted(result.checks, key=lambda c: -peak(c))[:MAX_CHECK_FIGURES]


def histogram(result: StudyResult, check: str) -> str:
    """Histogram of a check's u·SF over the valid samples, with the limit line at 1."""
    v = result.fu(check)
    v = v[np.isfinite(v)]
    fig, ax = new_figure(4.6, 2.6)
    if v.size:
        lo, hi = float(np.min(v)), float(np.max(v))
        if hi - lo <= 1e-9 * max(1.0, abs(hi)):  # (nearly) constant: one bar, not bins narrower than rounding
            pad = max(0.01 * abs(hi), 1e-3)
            ax.hist(v, bins=1, range=(lo - pad, hi + pad), color="#4c72b0", alpha=0.85)
        else:
            ax.hist(v, bins=min(40, max(5, int(math.sqrt(v.size)))), color="#4c72b0", alpha=0.85)
    ax.axvline(1.0, color="#cf222e", lw=1.5, label="limit u·SF = 1")
    ax.set_xlabel(f"u·SF of {check}")
    ax.set_ylabel("samples")
    ax.legend(fontsize=7)
    return svg_data_uri(fig)


def scatter(result: StudyResult, name: str, check: str | None = None) -> str:
    """The input ``name`` against the governing u·SF (or ``check``'s) of each valid sample, coloured by verdict."""
    colours = {"pass": "#2da44e", "warn": "#bf8700", "fail": "#cf222e"}
    ok = result.ok
    fig, ax = new_figure(5.5, 3.2)
    x = [s["inputs"][name] for s in ok]
    y = result.fu(check)
    if check is None:
        verdicts = [s["verdict"] for s in ok]
    else:
        verdicts = [s["checks"].get(check, {}).get("verdict", "") for s in ok]
    for v in [*colours, *sorted({v for v in verdicts if v not in colours})]:  # one legend entry per verdict
        idx = [i for i, w in enumerate(verdicts) if w == v]
        if idx:
            ax.scatter([x[i] for i in idx], [y[i] for i in idx], s=8, c=colours.get(v, "#777"),
                       label=f"{v or 'no verdict'} ({len(idx)})")
    ax.axhline(1.0, color="k", lw=1)
    if ok:
        ax.legend(fontsize=7, title="verdict (samples)", title_fontsize=7)
    ax.set_xlabel(_label(result, name))
    ax.set_ylabel("governing u·SF" if check is None else _ylabel(check), fontsize=8)
    return svg_data_uri(fig)


def deciding_check(result: StudyResult) -> str | None:
    """The check whose failure probability is closest to 1/2 (the one the tolerances decide), if any is
    neither 0 nor 1."""
    fp = {c: v["p"] for c, v in result.failure_probability().items() if c != "overall" and 0 < v["p"] < 1}
    return min(fp, key=lambda c: abs(fp[c] - 0.5)) if fp else None


def sweep_curves(result: StudyResult, check: str) -> str:
    """u·SF of ``check`` against the first axis; one curve per combination of the other axes."""
    names = result.names
    first, others = names[0], names[1:]
    fig, ax = new_figure(5.0, 2.9)
    groups: dict[tuple[float, ...], list[tuple[float, float]]] = {}
    for s in result.samples:
        key = tuple(s["inputs"][n] for n in others)
        c = s["checks"].get(check)
        y = math.nan if c is None else (math.inf if c["fu"] is None else c["fu"])
        groups.setdefault(key, []).append((s["inputs"][first], y))
    for key, pts in itertools.islice(groups.items(), 8):
        pts.sort()
        label = ", ".join(f"{n.rsplit('.', 1)[-1]} = {v:.4g}" for n, v in zip(others, key)) or None
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=label)
    ax.axhline(1.0, color="#cf222e", lw=1.2)
    ax.set_xlabel(_label(result, first))
    ax.set_ylabel(_ylabel(check), fontsize=8)
    if others:
        ax.legend(fontsize=6)
    return svg_data_uri(fig)


def render_study_html(result: StudyResult, title: str | None = None) -> str:
    css = (Path(__file__).parent / "templates" / "report.css").read_text(encoding="utf-8")
    kind = {"monte_carlo": "Monte Carlo study", "sweep": "Sweep"}.get(result.kind, result.kind)
    title = title or f"{kind} of {result.design_name}"
    parts = [f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{_e(title)}</title>"
             f"<style>{css}</style></head><body>", f"<h1>{_e(title)}</h1>"]
    n, bad = len(result.samples), len(result.errors)
    head = f"{n} samples" + (f", method {result.method}, seed {result.seed}" if result.kind == "monte_carlo" else "")
    parts.append(f"<p>{_e(head)}; {bad} invalid (recorded with their message, left out of the statistics).</p>")
    parts.append("<h2>Varied inputs</h2><table><tr><th>key path</th><th>values</th><th>unit</th>"
                 "<th>value in the file</th></tr>")
    for a in result.axes:
        parts.append(f"<tr><td><code>{_e(a['name'])}</code></td><td>{_e(a['spec'])}</td><td>{_e(pretty_unit(a['unit']))}</td>"
                     f"<td>{_num(a['base'], 6)}</td></tr>")
    parts.append("</table>")
    checks = _ranked_checks(result)
    if result.kind == "monte_carlo":
        fp = result.failure_probability()
        parts.append("<h2>Failure probability</h2><p>A sample fails a check when u·SF &gt; 1; interval: Wilson score, "
                     "95 %.</p><table><tr><th>check</th><th>failures</th><th>valid samples</th><th>P(fail)</th>"
                     "<th>95 % interval</th></tr>")
        for c, v in fp.items():
            parts.append(f"<tr><td>{_e(c)}</td><td>{v['failures']}</td><td>{v['n']}</td><td>{v['p']:.4f}</td>"
                         f"<td>{v['lo']:.4f} – {v['hi']:.4f}</td></tr>")
        inv = result.invalid_as_failures()
        if inv is not None:
            parts.append(f"<tr><td>overall, invalid counted as failures</td><td>{inv['failures']}</td><td>{inv['n']}"
                         f"</td><td>{inv['p']:.4f}</td><td>{inv['lo']:.4f} – {inv['hi']:.4f}</td></tr>")
        parts.append("</table>")
        if inv is not None:
            parts.append(f"<p>{_e(result.invalid_note())}.</p>")
        w = result.worst()
        if w is not None:
            ins = ", ".join(f"{k} = {result.value_text(k, v)}" for k, v in w["inputs"].items())
            parts.append(f"<p><b>Worst sample</b> {w['index']}: {_e(w['governing'])} u·SF = {_num(w['max_fu'])} "
                         f"({_e(ins)}); <code>mechverify study ... --reproduce {w['index']}</code> writes it as a "
                         "design file.</p>")
        sens = result.sensitivity()
        parts.append("<h2>Sensitivity</h2><p>Spearman rank correlation of each input with each check's u·SF "
                     "(strongest first).</p><table><tr><th>check</th><th>inputs</th></tr>")
        for c in ["governing", *checks]:
            row = ", ".join(f"{n} {r:+.3f}" for n, r in sens.get(c, [])) or "–"
            parts.append(f"<tr><td>{_e(c)}</td><td>{_e(row)}</td></tr>")
        parts.append("</table>")
        top = result.most_influential()
        if top is not None and result.ok:
            parts.append(f"<h2>Most influential input</h2><figure><img alt='scatter' src='{scatter(result, top)}'>"
                         f"<figcaption>{_e(top)} against the governing u·SF</figcaption></figure>")
            dec = deciding_check(result)
            ranks = sens.get(dec or "", [])
            if dec is not None and ranks:
                parts.append(f"<figure><img alt='scatter' src='{scatter(result, ranks[0][0], dec)}'><figcaption>"
                             f"{_e(ranks[0][0])} against the u·SF of {_e(dec)}, the check the tolerances decide "
                             f"(P(fail) = {fp[dec]['p']:.3f})</figcaption></figure>")
        if result.ok:
            parts.append("<h2>u·SF per check</h2>")
            for c in checks:
                parts.append(f"<figure><img alt='{_e(c)}' src='{histogram(result, c)}'><figcaption>{_e(c)}"
                             "</figcaption></figure>")
    else:
        parts.append("<h2>Sweep curves</h2>")
        for c in checks:
            parts.append(f"<figure><img alt='{_e(c)}' src='{sweep_curves(result, c)}'><figcaption>{_e(c)}"
                         "</figcaption></figure>")
        parts.append("<h2>Samples</h2><table><tr><th>#</th>"
                     + "".join(f"<th>{_e(_label(result, n))}</th>" for n in result.names)
                     + "<th>governing</th><th>u·SF</th><th>verdict</th></tr>")
        for s in result.samples[:MAX_TABLE_ROWS]:
            cells = "".join(f"<td>{s['inputs'][n]:.6g}</td>" for n in result.names)
            tail = (f"<td>{_e(s['governing'])}</td><td>{_num(s['max_fu'])}</td><td>{_e(s['verdict'])}</td>"
                    if s["status"] == "ok" else f"<td colspan='3'>invalid: {_e(s['message'][:200])}</td>")
            parts.append(f"<tr><td>{s['index']}</td>{cells}{tail}</tr>")
        parts.append("</table>")
    if result.errors:
        parts.append("<h2>Invalid samples</h2><ul>")
        for s in result.errors[:50]:
            parts.append(f"<li>{s['index']}: {_e(s['message'][:300])}</li>")
        parts.append("</ul>")
    parts.append("</body></html>")
    return "\n".join(parts)


def write_study_report(result: StudyResult, path: str | Path) -> Path:
    """Write ``path`` (.html or .pdf) atomically; return it."""
    from mechverify.fileio import atomic_write

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".html", ".htm", ".pdf"):
        raise InputError(f"report: expected a .html or .pdf file name, got {str(path)!r}")
    text = render_study_html(result)
    if suffix != ".pdf":
        return atomic_write(path, text)

    def pdf(tmp: Path) -> None:
        import logging

        from weasyprint import HTML

        logging.getLogger("weasyprint").setLevel(logging.ERROR)
        HTML(string=text, base_url=str(path.parent)).write_pdf(tmp)

    return atomic_write(path, pdf)
