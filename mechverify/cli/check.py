"""``mechverify check``: run every check of each design; exit 0 all pass, 1 a check fails, 2 invalid input."""

from __future__ import annotations

import argparse
from pathlib import Path

from mechverify.cli._common import add_allow_outside, input_files, load_designs, write

ORDER = 10


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check", help="run every check of each design file",
                       description="Run every check of each DESIGN; exit 0 when all pass, 1 when a check fails, "
                                   "2 on invalid input. Output paths are checked before any check runs.")
    p.add_argument("designs", nargs="+", type=Path, metavar="DESIGN", help="design files (TOML)")
    p.add_argument("--json", dest="json_out", type=Path, metavar="PATH", help="write the results as JSON")
    p.add_argument("--junit", type=Path, metavar="PATH", help="write JUnit XML for CI")
    p.add_argument("--report", type=Path, metavar="PATH", help="write an HTML or PDF report (.html/.pdf)")
    p.add_argument("--detail", choices=("problems", "all"), default="problems",
                   help="report detail (formulas, inputs, figures) for failing and warning checks (default) or all")
    p.add_argument("--markdown", type=Path, metavar="PATH",
                   help="write a Markdown summary (verdict, table of failing and warning checks) for a pull request")
    p.add_argument("--github-step-summary", action="store_true",
                   help="append the Markdown summary to $GITHUB_STEP_SUMMARY (GitHub Actions)")
    p.add_argument("--fail-on", default="fail", metavar="{fail,warn}",
                   help="exit 1 on 'fail' (default) or also on 'warn'")
    p.add_argument("--quiet", "-q", action="store_true", help="print only the verdicts")
    add_allow_outside(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from mechverify.cli import Invalid
    from mechverify.fileio import check_output_paths

    if args.fail_on not in ("fail", "warn"):
        raise Invalid(f"--fail-on: expected 'fail' or 'warn', got {args.fail_on!r}")
    if args.report is not None and args.report.suffix.lower() not in (".html", ".htm", ".pdf"):
        raise Invalid(f"--report: expected a .html or .pdf file name, got {str(args.report)!r}")
    outputs = {"--json": args.json_out, "--junit": args.junit, "--report": args.report, "--markdown": args.markdown}
    if args.github_step_summary:
        from mechverify.errors import InputError
        from mechverify.reports.markdown import step_summary_path

        try:
            step_summary_path()
        except InputError as exc:
            raise Invalid(str(exc)) from None
    check_output_paths(outputs, args.designs)  # before loading: nothing is read or written yet
    designs = load_designs(args.designs, args.allow_outside_includes)
    check_output_paths(outputs, input_files(designs, args.designs))  # the includes too

    from mechverify.checks import Verdict
    from mechverify.cli._console import combined_line, out, print_line, print_results, verdict_line
    from mechverify.errors import MechverifyError

    runs, errors = [], []
    for d in designs:
        try:
            runs.append((d, d.verify()))
        except MechverifyError as exc:
            errors.append(str(exc))
    if errors:
        raise Invalid("\n".join(errors))
    if args.json_out or args.junit:  # design.outputs imports xml.etree: only when a file is asked for
        from mechverify.design.outputs import junit_xml, run_document, to_json

        if args.json_out:
            write(args.json_out, to_json(run_document(runs)))
        if args.junit:
            write(args.junit, junit_xml(runs, args.fail_on))
    if args.report:
        from mechverify.reports import write_report

        write_report(runs, args.report, detail=args.detail)
    if args.markdown or args.github_step_summary:
        from mechverify.reports.markdown import append_step_summary, check_markdown

        md = check_markdown(runs)
        if args.markdown:
            write(args.markdown, md)
        if args.github_step_summary:
            append_step_summary(md)
    worst = max((rs.verdict for _, rs in runs), key=lambda v: v.rank, default=Verdict.PASS)
    for design, rs in runs:
        if not args.quiet and len(rs):  # no check ran: the verdict line says so, no empty table
            from mechverify.reports.numbers import design_units

            print_results(rs, design_units(getattr(getattr(design, "data", None), "raw", None) or {}))
            for r in rs:  # a check that could not be evaluated fails: say why
                for n in r.notes:
                    if n.startswith("Not verifiable"):
                        from rich.markup import escape

                        out.print(f"[red]{r.component} / {r.check}:[/red] {escape(n)}")
        print_line(verdict_line(rs))
    if len(runs) > 1:
        print_line(combined_line([rs for _, rs in runs]))
    failed = worst is Verdict.FAIL or (args.fail_on == "warn" and worst is Verdict.WARN)
    return 1 if failed else 0
