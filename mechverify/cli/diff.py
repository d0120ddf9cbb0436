"""``mechverify diff``: which checks changed verdict or margin between two revisions (the CI gate)."""

from __future__ import annotations

import argparse
import subprocess
import tempfile
from pathlib import Path

from mechverify.cli._common import add_allow_outside, write

ORDER = 20


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("diff", help="compare two revisions of a design; exit 1 when a margin is lost",
                       description="Which checks changed verdict or margin between two revisions; exit 1 when a "
                                   "margin dropped below its requirement (the CI gate for component changes).")
    p.add_argument("base", type=Path, metavar="BASE",
                   help="the earlier design file (or the only file, with --base-ref)")
    p.add_argument("head", type=Path, nargs="?", metavar="HEAD", help="the later design file")
    p.add_argument("--base-ref", metavar="REF", help="read BASE from this git ref (same path)")
    p.add_argument("--json", dest="json_out", type=Path, metavar="PATH", help="write the changes as JSON")
    p.add_argument("--markdown", type=Path, metavar="PATH", help="write the changes as a Markdown table")
    p.add_argument("--github-step-summary", action="store_true",
                   help="append the Markdown table of changes to $GITHUB_STEP_SUMMARY (GitHub Actions)")
    add_allow_outside(p)
    p.set_defaults(run=run)


def design_at_ref(path: Path, ref: str, tmp: Path) -> Path:
    """Extract the design's folder as it was at git REF into ``tmp``; return the design's path there."""
    from mechverify.cli import Invalid

    path = path.resolve()
    if not path.parent.is_dir():
        raise Invalid(f"--base-ref: the folder of {path} does not exist")
    try:
        top = Path(subprocess.run(["git", "-C", str(path.parent), "rev-parse", "--show-toplevel"], check=True,
                                  capture_output=True, text=True).stdout.strip()).resolve()
    except FileNotFoundError:
        raise Invalid("--base-ref: reads the earlier design from git, and no git command was found "
                      "(install git, or compare two files: mechverify diff BASE HEAD)") from None
    except subprocess.CalledProcessError:
        raise Invalid(f"--base-ref: {path} is not inside a git repository (compare two files instead: "
                      f"mechverify diff BASE HEAD)") from None
    rel_dir = path.parent.relative_to(top)
    archive = subprocess.run(["git", "-C", str(top), "archive", "--format=tar", ref, "--", str(rel_dir) or "."],
                             capture_output=True)
    if archive.returncode != 0:
        raise Invalid(f"--base-ref: cannot read {rel_dir / path.name} at git ref {ref!r}: "
                      f"{archive.stderr.decode(errors='replace').strip()}")
    subprocess.run(["tar", "-x", "-C", str(tmp)], input=archive.stdout, check=True)
    base = tmp / rel_dir / path.name
    if not base.exists():
        raise Invalid(f"--base-ref: {rel_dir / path.name} does not exist at git ref {ref!r}")
    return base


def run(args: argparse.Namespace) -> int:
    from mechverify.cli import Invalid
    from mechverify.fileio import check_output_paths

    base, head = args.base, args.head
    if args.base_ref:
        if head is not None:
            raise Invalid("diff: give one file with --base-ref, or two files without it")
        head = base
    elif head is None:
        raise Invalid("diff: give two design files, or one with --base-ref REF")
    outputs = {"--json": args.json_out, "--markdown": args.markdown}
    check_output_paths(outputs, [args.base, head])
    if args.github_step_summary:
        from mechverify.errors import InputError
        from mechverify.reports.markdown import step_summary_path

        try:
            step_summary_path()
        except InputError as exc:
            raise Invalid(str(exc)) from None

    from mechverify.design import load
    from mechverify.errors import MechverifyError

    with tempfile.TemporaryDirectory() as tmpdir:
        if args.base_ref:
            base = design_at_ref(args.base, args.base_ref, Path(tmpdir))
        try:
            db = load(base, args.allow_outside_includes)
            dh = load(head, args.allow_outside_includes)
            check_output_paths(outputs, list(dh.files) + [head])
            if not dh.data.components:
                raise Invalid(f"{head}: the design has no components, so there is nothing to compare")
            rb, rh = db.verify(), dh.verify()
        except MechverifyError as exc:
            raise Invalid(str(exc)) from None

    from rich.table import Table

    from mechverify.cli._console import COLOURS, out
    from mechverify.design.outputs import diff as diff_results
    from mechverify.design.outputs import to_json

    changes = diff_results(rb, rh)
    t = Table(title=f"{rb.name} → {rh.name}", title_justify="left")
    for col in ("component", "check", "status", "base u·SF", "head u·SF", "Δ", "verdict"):
        t.add_column(col)
    lost = False
    for ch in changes:
        if ch.status == "same":
            continue
        fb = f"{ch.base.factored_utilisation:.3g}" if ch.base else "-"
        fh = f"{ch.head.factored_utilisation:.3g}" if ch.head else "-"
        d = f"{ch.delta:+.3g}" if ch.base and ch.head else ""
        vb = ch.base.verdict.value if ch.base else "-"
        vh = ch.head.verdict.value if ch.head else "-"
        mark = " [red]margin lost[/red]" if ch.lost_requirement else ""
        lost |= ch.lost_requirement
        c = COLOURS.get(vh, "white")
        t.add_row(ch.component, ch.check, ch.status, fb, fh, d, f"{vb} → [{c}]{vh}[/{c}]{mark}")
    n_changed = sum(c.status != "same" for c in changes)
    if n_changed:
        out.print(t)
    out.print(f"{n_changed} of {len(changes)} checks changed" + ("; a requirement is no longer met" if lost else ""))
    if args.json_out:
        doc = {"base": rb.name, "head": rh.name, "lost_requirement": lost, "changes": [
            {"component": c.component, "check": c.check, "status": c.status,
             "base": c.base.to_dict() if c.base else None, "head": c.head.to_dict() if c.head else None}
            for c in changes if c.status != "same"]}
        write(args.json_out, to_json(doc))
    if args.markdown or args.github_step_summary:
        from mechverify.reports.markdown import append_step_summary, diff_markdown

        md = diff_markdown(changes, rb.name, rh.name)
        if args.markdown:
            write(args.markdown, md)
        if args.github_step_summary:
            append_step_summary(md)
    return 1 if lost else 0
