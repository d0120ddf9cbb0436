"""Report generation time for a realistic review: about 20 checks and two FEA figures.

Two bundled example designs are verified together — the lead-screw lift (14 checks, with motor,
spring-free drive and bearing plots) and the five-bar links (frame FEA: two figures of deformed
shape and moment diagrams) — and written as one HTML and one PDF report. Printed: the time to
verify (the reference in the same process), the time to render each format, and their ratios.
Target (issue 9): a report in under a few seconds.
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = [ROOT / "examples" / "lead_screw_lift" / "design.toml", ROOT / "examples" / "five_bar" / "design.toml"]


def _best(f, repeat: int = 3) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main(argv: list[str] | None = None) -> dict:
    from mechverify.design import load
    from mechverify.reports import render_html, write_report

    load(DESIGNS[0]).verify()  # warm imports and caches once
    t_verify, runs = _best(lambda: [(d, d.verify()) for d in (load(p) for p in DESIGNS)])
    n_checks = sum(len(rs) for _, rs in runs)
    t_html, _ = _best(lambda: render_html(runs))
    with tempfile.TemporaryDirectory() as tmp:
        t_pdf, _ = _best(lambda: write_report(runs, Path(tmp) / "review.pdf"), repeat=2)
        size_pdf = (Path(tmp) / "review.pdf").stat().st_size
    size_html = len(render_html(runs).encode())
    out = {"checks": n_checks, "verify_s": round(t_verify, 3), "html_s": round(t_html, 3),
           "pdf_s": round(t_pdf, 3), "html_over_verify": round(t_html / t_verify, 2),
           "pdf_over_verify": round(t_pdf / t_verify, 2), "html_bytes": size_html, "pdf_bytes": size_pdf}
    print(f"report generation, {n_checks} checks, two frame-FEA figures (best of repeated runs):")
    print(f"  verify (reference) {t_verify:6.2f} s")
    print(f"  HTML               {t_html:6.2f} s   ratio to verify {t_html / t_verify:5.2f}   {size_html / 1e3:.0f} kB")
    print(f"  PDF (incl. HTML)   {t_pdf:6.2f} s   ratio to verify {t_pdf / t_verify:5.2f}   {size_pdf / 1e3:.0f} kB")
    results = ROOT / "benchmarks" / "results"
    results.mkdir(exist_ok=True)
    (results / "report_generation.json").write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main(sys.argv[1:])
