"""Cold start-up of the command line, each a fresh process, against ``python -c "import numpy, pint"``.

Three commands are timed, each run ``repeat`` times (minimum of 5) as a new interpreter, and the
minimum wall time kept (the least disturbed run on a shared machine):

- ``python -c "import numpy, pint"`` - the reference: what any unit-aware numerical tool pays;
- ``mechverify --help`` - target ratio <= 0.6 (it needs neither numpy nor pint);
- ``mechverify check examples/lead_screw_lift/design.toml`` - target ratio <= 2.0.

Every run uses the same interpreter (``sys.executable``) and the warm caches a user has after the
first run (bytecode, pint's registry cache); one untimed run of each primes them. Bytecode is written
even where ``PYTHONDONTWRITEBYTECODE`` is set (as in some sandboxes: every process would then compile
mechverify's sources again, while numpy and pint come with compiled wheels), into a separate
``PYTHONPYCACHEPREFIX`` so that the source tree stays clean. Issue 27.

The command line ends its process with ``os._exit`` once its output is flushed (``mechverify.cli.entry``,
as mypy's fast exit): the interpreter's teardown, ~80 ms CPU after a check and ~50 ms after the reference's
imports, is skipped; the reference pays its own.

The output goes to /dev/null, not a terminal, as in a CI log: ``check`` then draws its table without rich
(``mechverify/cli/_table.py``); in a terminal rich draws it, in colour, which adds ~45 ms CPU (rich's import
and layout; docs/performance.md).
"""

from __future__ import annotations

import importlib.util
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DESIGN = ROOT / "examples" / "lead_screw_lift" / "design.toml"
TARGETS = {"help": 0.6, "check": 2.0}
_ENV = {**{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}, "COLUMNS": "200",
        "PYTHONPYCACHEPREFIX": str(Path.home() / ".cache" / "mechverify" / "pycache-startup-bench")}


# pint imports dask when it is installed (its dask support), which the test extras install and a base
# install does not: both the reference and ``check`` then pay ~0.15 s more. The base install's pair is
# timed too, with dask hidden from the interpreter (an import of it fails as if it were absent).
_NO_DASK = "import sys; sys.modules['dask'] = None; "


def commands() -> dict[str, list[str]]:
    py = sys.executable
    cli = [py, "-m", "mechverify.cli"] if not _script() else [_script()]
    cmds = {"reference": [py, "-c", "import numpy, pint"], "help": [*cli, "--help"],
            "check": [*cli, "check", str(DESIGN)]}
    if importlib.util.find_spec("dask") is not None:
        cmds["reference_base"] = [py, "-c", _NO_DASK + "import numpy, pint"]
        cmds["check_base"] = [py, "-c", _NO_DASK + "sys.argv = ['mechverify', 'check', sys.argv[1]]; "
                              "from mechverify.cli import entry; entry()", str(DESIGN)]  # what the script runs
    return cmds


def _script() -> str | None:
    exe = Path(sys.executable).with_name("mechverify")
    return str(exe) if exe.exists() else None


def _time(cmd: list[str]) -> tuple[float, float]:
    """Wall time and CPU time (user + system, of the child) of one run."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=_ENV)
    dt = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode not in (0, 1):  # check exits 1 when a check fails: still a complete run
        raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}: {proc.stderr.decode()[-500:]}")
    return dt, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def main(argv: list[str] | None = None, repeat: int = 7) -> dict:
    argv = argv or []
    if argv:
        repeat = max(5, int(argv[0]))
    cmds = commands()
    for cmd in cmds.values():  # prime bytecode and the pint cache
        _time(cmd)
    times: dict[str, list[tuple[float, float]]] = {k: [] for k in cmds}
    for _ in range(repeat):  # interleaved, so that a busy moment hits all three alike
        for name, cmd in cmds.items():
            times[name].append(_time(cmd))
    best = {k: min(w for w, _ in v) for k, v in times.items()}
    cpu = {k: min(c for _, c in v) for k, v in times.items()}  # less sensitive to a loaded machine
    ref, ref_cpu = best["reference"], cpu["reference"]
    out = {"repeat": repeat, "load_average": round(os.getloadavg()[0], 2),
           **{f"{k}_s": round(v, 3) for k, v in best.items()},
           **{f"{k}_ratio": round(best[k] / ref, 2) for k in TARGETS},
           **{f"{k}_cpu_s": round(v, 3) for k, v in cpu.items()},
           **{f"{k}_cpu_ratio": round(cpu[k] / ref_cpu, 2) for k in TARGETS},
           **{f"{k}_target": t for k, t in TARGETS.items()},
           "meets_targets": all(best[k] / ref <= t for k, t in TARGETS.items())}
    print(f"start-up, fresh processes, minimum of {repeat} (load average {os.getloadavg()[0]:.1f}):")
    print(f"  python -c 'import numpy, pint' {ref:6.3f} s   cpu {ref_cpu:6.3f} s   (reference)")
    for k, t in TARGETS.items():
        print(f"  mechverify {k:<22} {best[k]:6.3f} s   cpu {cpu[k]:6.3f} s   ratio {best[k] / ref:5.2f} "
              f"(cpu {cpu[k] / ref_cpu:4.2f})   target <= {t}")
    if "check_base" in best:
        rb, rbc, cb, cbc = best["reference_base"], cpu["reference_base"], best["check_base"], cpu["check_base"]
        out.update(base_check_ratio=round(cb / rb, 2), base_check_cpu_ratio=round(cbc / rbc, 2))
        print(f"  without dask (a base install): reference {rb:6.3f} s (cpu {rbc:6.3f}), check {cb:6.3f} s "
              f"(cpu {cbc:6.3f})   ratio {cb / rb:5.2f} (cpu {cbc / rbc:4.2f})   target <= {TARGETS['check']}")
    results = ROOT / "benchmarks" / "results"
    results.mkdir(exist_ok=True)
    (results / "startup.json").write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main(sys.argv[1:])
