"""``mechverify study``: a sweep or a Monte Carlo study of a design, locally or on a Dask cluster."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from mechverify.cli._common import write

ORDER = 41


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("study", help="sweep or Monte Carlo study of a design (local cores or a Dask cluster)",
                       description="Vary parameters of DESIGN (key paths of the file) and verify every sample. "
                                   "A sweep: every --vary NAME=START:STOP:N (full factorial). Monte Carlo: every "
                                   "--vary NAME=normal:MEAN:SD | uniform:LO:HI | triangular:LO:MODE:HI with "
                                   "--samples N. Bare numbers take the unit of the file's value. A sample that is "
                                   "invalid is recorded with its message. Exit 0 when the study ran, 2 on invalid "
                                   "input, an unreachable scheduler, or when no sample is valid (the outputs "
                                   "are still written).")
    p.add_argument("design", type=Path, metavar="DESIGN", help="design file (TOML)")
    p.add_argument("--vary", action="append", required=True, metavar="NAME=SPEC",
                   help="a parameter and its range or distribution (repeat for several)")
    p.add_argument("--samples", "-n", type=int, metavar="N", help="Monte Carlo samples")
    p.add_argument("--method", default="lhs", choices=("lhs", "sobol", "random"),
                   help="Monte Carlo sampling: Latin hypercube (default), scrambled Sobol, pseudo-random")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--workers", type=int, metavar="N", help="local worker processes (default: one per core)")
    p.add_argument("--memory-per-worker", metavar="SIZE",
                   help="peak memory of one sample, e.g. '2 GB' for an FEA model: fewer local workers when the "
                        "available memory would not hold one per core")
    p.add_argument("--serial", action="store_true", help="run in this process (no worker processes)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on the Dask cluster at tcp://host:8786 (default: $DASK_SCHEDULER_ADDRESS if set and "
                        "neither --serial, --workers nor --memory-per-worker is given)")
    p.add_argument("--timeout", type=float, default=10.0, metavar="S",
                   help="seconds to wait for the scheduler (default 10)")
    p.add_argument("--batch-size", type=int, metavar="N", help="samples per task (default: about 4 tasks a worker)")
    p.add_argument("--json", dest="json_out", type=Path, metavar="PATH", help="write every sample as JSON")
    p.add_argument("--csv", type=Path, metavar="PATH", help="write every sample as CSV")
    p.add_argument("--report", type=Path, metavar="PATH", help="write the study report (.html or .pdf)")
    p.add_argument("--reproduce", type=int, metavar="I",
                   help="write sample I as a design file (--out) instead of running the study")
    p.add_argument("--out", type=Path, metavar="PATH", help="the design file --reproduce writes")
    p.add_argument("--force", action="store_true", help="with --reproduce: overwrite an existing --out file")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--quiet", "-q", action="store_true", help="print only the summary line")
    p.add_argument("--allow-outside-includes", action=argparse.BooleanOptionalAction, default=False,
                   help="allow includes outside the design's folder (default: refused)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from mechverify.cli import Invalid
    from mechverify.errors import InputError
    from mechverify.fileio import check_output_paths

    if args.report is not None and args.report.suffix.lower() not in (".html", ".htm", ".pdf"):
        raise Invalid(f"--report: expected a .html or .pdf file name, got {str(args.report)!r}")
    for opt, path, ext in (("--json", args.json_out, ".json"), ("--csv", args.csv, ".csv")):
        if path is not None and path.suffix.lower() != ext:
            raise Invalid(f"{opt}: expected a {ext} file name, got {str(path)!r}")
    if args.reproduce is not None and args.out is None:
        raise Invalid("--reproduce: give the design file to write with --out PATH")
    if args.out is not None and args.reproduce is None:
        raise Invalid("--out: only with --reproduce I")
    if args.force and args.out is None:
        raise Invalid("--force: only with --reproduce I --out PATH")
    if args.out is not None and (args.out.exists() or args.out.is_symlink()) and not args.force:
        raise Invalid(f"--out: {args.out} exists; pass --force to overwrite it")
    for opt, n in (("--workers", args.workers), ("--batch-size", args.batch_size), ("--samples", args.samples)):
        if n is not None and n < 1:
            raise Invalid(f"{opt}: zero samples; give at least 1" if opt == "--samples" and n == 0 else
                          f"{opt}: expected a positive integer, got {n}")
    if args.timeout is not None and not args.timeout > 0:
        raise Invalid(f"--timeout: expected a positive number of seconds, got {args.timeout:g}")
    local = [o for o, given in (("--serial", args.serial), ("--workers", args.workers is not None),
                                ("--memory-per-worker", args.memory_per_worker is not None)) if given]
    if args.scheduler and local:
        raise Invalid(f"{' and '.join(local)} and --scheduler: choose the local run or the cluster")
    if args.serial and len(local) > 1:
        raise Invalid(f"--serial runs in this process: {' and '.join(local[1:])} would be ignored; drop it")
    # $DASK_SCHEDULER_ADDRESS is a default: an explicit local choice (--serial, --workers) beats it
    env = os.environ.get("DASK_SCHEDULER_ADDRESS") or None
    scheduler = args.scheduler or (None if local else env)
    outputs = {"--json": args.json_out, "--csv": args.csv, "--report": args.report, "--out": args.out}
    check_output_paths(outputs, [args.design])

    from mechverify.cli._common import load_designs
    from mechverify.cli._console import console
    from mechverify.studies import Study

    (design,) = load_designs([args.design], args.allow_outside_includes)
    try:
        study = Study(design, vary=args.vary, samples=args.samples, method=args.method, seed=args.seed,
                      batch_size=args.batch_size)
    except InputError as exc:  # name the option, not the Python argument
        raise _as_option(exc) from None
    out = console()
    if args.reproduce is not None:
        if not 0 <= args.reproduce < study.n_samples:
            raise Invalid(f"--reproduce: sample {args.reproduce} does not exist (0..{study.n_samples - 1})")
        path = study.reproduce(args.reproduce, args.out)
        out.print(f"sample {args.reproduce} written to {path}; check it with: mechverify check {path}",
                  markup=False, highlight=False, soft_wrap=True)
        return 0
    progress = not args.no_progress
    if scheduler:
        from mechverify.studies import dask_executor

        if not args.scheduler and not args.quiet:
            _note(f"running on the Dask cluster at {scheduler} ($DASK_SCHEDULER_ADDRESS; --serial or --workers N "
                  "run locally)")
        with dask_executor(scheduler, timeout=args.timeout) as executor:
            result = study.run(executor, progress=progress)
    else:
        from mechverify.studies import execution

        try:
            memory = args.memory_per_worker
            if memory is None and not args.serial and not args.workers:  # an FE study: measured (issue 19)
                memory = execution.fe_memory_per_worker(study.doc, study.path)
                if memory is not None and not args.quiet:
                    _note("a sample's memory measured on the base design in a fresh process (a worker may hold "
                          "two FE models: the last one's factorisation and the next)")
            if memory is not None:
                n = args.workers or execution.default_workers(memory)
                if not args.quiet:
                    _note(execution.memory_note(memory, n))
            result = study.run("serial" if args.serial else None, workers=args.workers,
                               memory_per_worker=memory, progress=progress)
        except InputError as exc:
            raise _as_option(exc) from None
    text = result.summary()
    out.print(text.splitlines()[0] if args.quiet else text, markup=False, highlight=False, soft_wrap=True)
    if args.json_out:
        write(args.json_out, result.to_json() + "\n")
    if args.csv:
        write(args.csv, result.to_csv())
    if args.report:
        from mechverify.reports.study import write_study_report

        write_study_report(result, args.report)
    if result.samples and not result.ok:  # nothing was verified: a CI job must not pass (outputs are written)
        from mechverify.studies.study import _last_line

        raise Invalid(f"no valid sample: all {len(result.samples)} samples are invalid, so the study verified "
                      f"nothing (sample 0: {_last_line(result.samples[0]['message'])})")
    return 0


_OPTIONS = {"samples": "--samples", "batch_size": "--batch-size", "workers": "--workers",
            "memory_per_worker": "--memory-per-worker", "method": "--method", "vary": "--vary"}


def _as_option(exc: Exception) -> Exception:
    """The same error with its leading Python argument name (``batch_size: ...``) as the option (``--batch-size``)."""
    text = str(exc)
    head, sep, rest = text.partition(": ")
    if sep and head in _OPTIONS:
        return type(exc)(f"{_OPTIONS[head]}: {rest}")
    return exc


def _note(text: str) -> None:
    import sys

    sys.stderr.write(f"note: {text}\n")
