"""Reports that scale (issue 25): a generated design of N compression springs (Shigley 10th ed. Ex. 10-4's
spring, the load varied per spring so that some warn and some fail) rendered to HTML and PDF.

Measured: verify time, HTML time and size, PDF time and size, and the peak resident memory of a child
process doing each (``resource.getrusage(RUSAGE_CHILDREN).ru_maxrss``). Targets for N = 2000 on the
2-core reference box: HTML < 60 s, PDF < 5 min, peak memory < 2 GB. Not part of the test suite.

    .venv/bin/python benchmarks/report_scale.py [N] [--detail problems|all]
"""

from __future__ import annotations

import json
import multiprocessing as mp
import resource
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

SPRING = """
[components.s{i}]
type = "compression_spring"
wire_diameter = "0.092 in"
outside_diameter = "0.5625 in"
free_length = "4.375 in"
active_coils = 21
ends = "squared-ground"
shear_modulus = "11.75 Mpsi"
elastic_modulus = "28.5 Mpsi"
tensile_strength = "284.1 ksi"

[load_cases.run.s{i}]
force = "{force} lbf"
"""


def design_text(n: int) -> str:
    parts = [f'[design]\nname = "spring bank"\nrevision = "bench"\ndescription = "Generated: {n} springs."\n']
    for i in range(n):
        force = 20 + (i * 7919) % 41  # 20..60 lbf: mostly pass, some warn/fail
        parts.append(SPRING.format(i=i, force=force))
    return "".join(parts)


def _job(kind: str, path: str, out: str, detail: str, q: mp.Queue) -> None:
    from mechverify.design import load
    from mechverify.reports import write_report

    t0 = time.perf_counter()
    d = load(path)
    rs = d.verify()
    t1 = time.perf_counter()
    write_report([(d, rs)], out, detail=detail)
    t2 = time.perf_counter()
    q.put({"checks": len(rs), "verdict": rs.verdict.value, "verify_s": t1 - t0, "render_s": t2 - t1})


def measure(kind: str, path: Path, out: Path, detail: str) -> dict:
    ctx = mp.get_context("spawn")
    q = ctx.Queue()
    p = ctx.Process(target=_job, args=(kind, str(path), str(out), detail, q))
    p.start()
    res = q.get()
    p.join()
    res["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024  # max over children so far
    res["bytes"] = out.stat().st_size
    return res


def main(argv: list[str] | None = None) -> dict:
    argv = list(argv or [])
    detail = "problems"  # the CLI's default
    if "--detail" in argv:
        i = argv.index("--detail")
        detail = argv[i + 1]
        del argv[i:i + 2]
    n = int(argv[0]) if argv else 2000
    with tempfile.TemporaryDirectory() as tmp:
        design = Path(tmp) / "bank.toml"
        design.write_text(design_text(n))
        html = measure("html", design, Path(tmp) / "bank.html", detail)
        pdf = measure("pdf", design, Path(tmp) / "bank.pdf", detail)
    out = {"components": n, "detail": detail, "checks": html["checks"], "verdict": html["verdict"],
           "verify_s": round(html["verify_s"], 1), "html_s": round(html["render_s"], 1),
           "html_mb": round(html["bytes"] / 1e6, 2), "html_peak_rss_mb": round(html["peak_rss_mb"]),
           "pdf_s": round(pdf["render_s"], 1), "pdf_mb": round(pdf["bytes"] / 1e6, 2),
           "peak_rss_mb": round(pdf["peak_rss_mb"]),
           "targets": {"html_s": 60, "pdf_s": 300, "peak_rss_mb": 2048}}
    print(json.dumps(out, indent=2))
    results = ROOT / "benchmarks" / "results"
    results.mkdir(exist_ok=True)
    (results / f"report_scale_{n}.json").write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main(sys.argv[1:])
