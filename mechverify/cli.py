"""The ``mechverify`` command: check designs, diff revisions for CI, browse data, explain checks.

Exit codes: 0 all checks pass, 1 a check fails (or a margin was lost, for ``diff``), 2 invalid input.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from mechverify.checks import ResultSet, Verdict
from mechverify.errors import MechverifyError
from mechverify.units import fmt

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Verify the mechanical design of small machines and robots.")
_WIDTH = None if sys.stdout.isatty() else 160  # CI logs: wide enough for the results table
out = Console(highlight=False, width=_WIDTH)
err = Console(stderr=True, highlight=False, width=_WIDTH)

COLOURS = {"pass": "green", "warn": "yellow", "fail": "red"}


class Invalid(Exception):
    """Raised inside commands for exit status 2 with a message."""


def _bar(u: float, width: int = 10) -> str:
    filled = min(width, max(0, round(min(u, 1.0) * width)))
    return "█" * filled + "·" * (width - filled) + ("▶" if u > 1 else " ")


def results_table(rs: ResultSet) -> Table:
    t = Table(title=rs.name, title_justify="left", show_lines=False)
    for col, just in (("verdict", "left"), ("component", "left"), ("check", "left"), ("demand", "right"),
                      ("capacity", "right"), ("u·SF", "right"), ("", "left"), ("SF req", "right"),
                      ("governing case", "left")):
        t.add_column(col, justify=just)
    for r in rs.sorted():
        c = COLOURS[r.verdict.value]
        fu = r.factored_utilisation
        t.add_row(f"[{c}]{r.verdict.value.upper()}[/{c}]", r.component, r.title or r.check, fmt(r.demand),
                  fmt(r.capacity), f"{fu:.3g}", f"[{c}]{_bar(fu)}[/{c}]", f"{r.required_sf:g}", r.load_case)
    return t


def _write_atomic(path: Path, text: str) -> None:
    from mechverify.fileio import atomic_write

    atomic_write(path, text)


def _load_and_verify(paths: list[Path], allow_outside: bool, quiet: bool) -> list[tuple[Any, ResultSet]]:
    from mechverify.design import load

    done = []
    errors: list[str] = []
    for p in paths:
        try:
            d = load(p, allow_outside=allow_outside)
            done.append((d, d.verify()))
        except MechverifyError as exc:
            errors.append(str(exc))
    if errors:
        raise Invalid("\n".join(errors))
    return done


@app.command()
def check(
    designs: Annotated[list[Path], typer.Argument(help="design files (TOML)", show_default=False)],
    json_out: Annotated[Path | None, typer.Option("--json", help="write the results as JSON")] = None,
    junit: Annotated[Path | None, typer.Option("--junit", help="write JUnit XML for CI")] = None,
    report: Annotated[Path | None, typer.Option("--report", help="write an HTML or PDF report (.html/.pdf)")] = None,
    fail_on: Annotated[str, typer.Option("--fail-on", help="exit 1 on 'fail' (default) or also on 'warn'")] = "fail",
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="print only the overall verdict")] = False,
    allow_outside_includes: Annotated[bool, typer.Option(help="allow includes outside the design's folder")] = False,
) -> None:
    """Run every check of each DESIGN; exit 0 when all pass, 1 when a check fails, 2 on invalid input."""
    if fail_on not in ("fail", "warn"):
        raise Invalid(f"--fail-on: expected 'fail' or 'warn', got {fail_on!r}")
    if report is not None and report.suffix.lower() not in (".html", ".htm", ".pdf"):
        raise Invalid(f"--report: expected a .html or .pdf file name, got {str(report)!r}")
    runs = _load_and_verify(designs, allow_outside_includes, quiet)
    from mechverify.design.outputs import junit_xml, run_document, to_json

    if json_out:
        _write_atomic(json_out, to_json(run_document(runs)))
    if junit:
        _write_atomic(junit, junit_xml(runs, fail_on))
    if report:
        from mechverify.reports import write_report

        write_report(runs, report)
    worst = max((rs.verdict for _, rs in runs), key=lambda v: v.rank, default=Verdict.PASS)
    for _, rs in runs:
        if not quiet:
            out.print(results_table(rs))
        counts = {v: sum(r.verdict is v for r in rs) for v in Verdict}
        c = COLOURS[rs.verdict.value]
        out.print(f"[{c}]{rs.verdict.value.upper()}[/{c}] {rs.name}: {counts[Verdict.PASS]} pass, "
                  f"{counts[Verdict.WARN]} warn, {counts[Verdict.FAIL]} fail")
    failed = worst is Verdict.FAIL or (fail_on == "warn" and worst is Verdict.WARN)
    raise typer.Exit(1 if failed else 0)


def _design_at_ref(path: Path, ref: str, tmp: Path) -> Path:
    """Extract the design's folder as it was at git REF into ``tmp``; return the design's path there."""
    path = path.resolve()
    try:
        top = Path(subprocess.run(["git", "-C", str(path.parent), "rev-parse", "--show-toplevel"], check=True,
                                  capture_output=True, text=True).stdout.strip())
    except (subprocess.CalledProcessError, FileNotFoundError) as exc:
        raise Invalid(f"--base-ref: {path} is not inside a git repository ({exc})") from None
    rel_dir = path.parent.relative_to(top)
    archive = subprocess.run(["git", "-C", str(top), "archive", "--format=tar", ref, "--", str(rel_dir) or "."],
                             capture_output=True)
    if archive.returncode != 0:
        raise Invalid(f"--base-ref: cannot read {rel_dir} at {ref!r}: {archive.stderr.decode().strip()}")
    subprocess.run(["tar", "-x", "-C", str(tmp)], input=archive.stdout, check=True)
    base = tmp / rel_dir / path.name
    if not base.exists():
        raise Invalid(f"--base-ref: {path.name} does not exist at {ref!r}")
    return base


@app.command()
def diff(
    base: Annotated[Path, typer.Argument(help="the earlier design file (or the only file, with --base-ref)")],
    head: Annotated[Path | None, typer.Argument(help="the later design file")] = None,
    base_ref: Annotated[str | None, typer.Option(help="read BASE from this git ref (same path)")] = None,
    json_out: Annotated[Path | None, typer.Option("--json", help="write the changes as JSON")] = None,
    allow_outside_includes: Annotated[bool, typer.Option(help="allow includes outside the design's folder")] = False,
) -> None:
    """Which checks changed verdict or margin between two revisions; exit 1 when a margin dropped below
    its requirement (the CI gate for component changes)."""
    from mechverify.design import load
    from mechverify.design.outputs import diff as diff_results
    from mechverify.design.outputs import to_json

    with tempfile.TemporaryDirectory() as tmpdir:
        if base_ref:
            if head is not None:
                raise Invalid("diff: give one file with --base-ref, or two files without it")
            head = base
            base = _design_at_ref(base, base_ref, Path(tmpdir))
        elif head is None:
            raise Invalid("diff: give two design files, or one with --base-ref REF")
        try:
            rb = load(base, allow_outside_includes).verify()
            rh = load(head, allow_outside_includes).verify()
        except MechverifyError as exc:
            raise Invalid(str(exc)) from None
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
        t.add_row(ch.component, ch.check, ch.status, fb, fh, d, f"{vb} → [{COLOURS.get(vh, 'white')}]{vh}"
                  f"[/{COLOURS.get(vh, 'white')}]{mark}")
    n_changed = sum(c.status != "same" for c in changes)
    if n_changed:
        out.print(t)
    out.print(f"{n_changed} of {len(changes)} checks changed" + ("; a requirement is no longer met" if lost else ""))
    if json_out:
        doc = {"base": rb.name, "head": rh.name, "lost_requirement": lost, "changes": [
            {"component": c.component, "check": c.check, "status": c.status,
             "base": c.base.to_dict() if c.base else None, "head": c.head.to_dict() if c.head else None}
            for c in changes if c.status != "same"]}
        _write_atomic(json_out, to_json(doc))
    raise typer.Exit(1 if lost else 0)


@app.command()
def materials(name: Annotated[str | None, typer.Argument(help="show one material in full")] = None) -> None:
    """List the material database, or show one material with the source of every value."""
    from mechverify import materials as mats
    from mechverify.materials.material import PROPERTY_DIMENSIONS

    if name:
        m = mats.get(name)
        t = Table(title=f"{m.name} ({m.category})", title_justify="left")
        t.add_column("property")
        t.add_column("value", justify="right")
        t.add_column("source")
        for p in PROPERTY_DIMENSIONS:
            v = getattr(m, p)
            if v is not None:
                t.add_row(p, fmt(v), m.source_of(p))
        out.print(t)
        if m.aliases:
            out.print("aliases: " + ", ".join(m.aliases))
        if m.sn_curve:
            out.print(f"S-N curve: {len(m.sn_curve.cycles)} points, R = {m.sn_curve.stress_ratio:g} "
                      f"({m.sn_curve.source})")
        for n in m.notes:
            out.print(f"note: {n}")
        return
    t = Table(title="materials", title_justify="left")
    for col in ("name", "category", "E", "yield", "ultimate", "density"):
        t.add_column(col)
    for m in mats.default_library():
        t.add_row(m.name, m.category, *(fmt(getattr(m, p), u, 3) if getattr(m, p) is not None else "-" for p, u in
                                        (("E", "GPa"), ("yield_strength", "MPa"), ("ultimate_strength", "MPa"),
                                         ("density", "kg/m**3"))))
    out.print(t)


def _table(title: str, columns: list[str], rows: list[list[str]]) -> None:
    t = Table(title=title, title_justify="left")
    for c in columns:
        t.add_column(c, justify="left" if c in columns[:1] else "right")
    for r in rows:
        t.add_row(*r)
    out.print(t)


def _opt(q: Any, unit: str, digits: int = 4) -> str:
    return fmt(q, unit, digits) if q is not None else "-"


@app.command()
def threads(
    name: Annotated[str | None, typer.Argument(help="a designation, e.g. Tr10x2 or 1/2-10 ACME")] = None,
) -> None:
    """List the thread tables (ISO 2904 trapezoidal, ASME B1.5 Acme), or show one thread's geometry."""
    from mechverify.components.threads import known_designations, thread

    names = [name] if name else known_designations()
    rows = []
    for n in names:
        t = thread(n)
        rows.append([t.designation, _opt(t.d, "mm"), _opt(t.pitch, "mm"), _opt(t.lead, "mm"), str(t.starts),
                     _opt(t.d2, "mm"), _opt(t.d3, "mm"), _opt(t.H1, "mm"), _opt(t.lead_angle, "deg", 3)])
    _table("threads", ["designation", "d", "P", "lead", "starts", "d2", "d3", "H1", "lead angle"], rows)
    if name:
        t = thread(name)
        out.print(f"source: {t.source}")
        for n in t.notes:
            out.print(f"note: {n}")


@app.command()
def bearings(name: Annotated[str | None, typer.Argument(help="a designation, e.g. 608-2Z")] = None) -> None:
    """List the rolling-bearing catalogue, or show one bearing."""
    from mechverify.components.bearings import bearing, bearing_names

    rows = []
    for n in [name] if name else bearing_names():
        b = bearing(n)
        rows.append([b.designation, _opt(b.d, "mm"), _opt(b.D, "mm"), _opt(b.B, "mm"), _opt(b.C, "kN"),
                     _opt(b.C0, "kN"), _opt(b.Pu, "kN"), _opt(b.reference_speed, "rpm", 5),
                     _opt(b.limiting_speed, "rpm", 5), f"{b.f0:g}"])
    _table("ball bearings", ["designation", "d", "D", "B", "C", "C0", "Pu", "ref. speed", "limit speed", "f0"],
           rows)
    if name:
        out.print(f"source: {bearing(name).source}")


@app.command()
def motors(name: Annotated[str | None, typer.Argument(help="a catalogue name")] = None) -> None:
    """List the motor and gearhead catalogues, or show one entry with its source."""
    from mechverify.components.gearheads import gearhead, gearhead_names
    from mechverify.components.motors import motor, motor_names

    if name:
        from mechverify.errors import UnknownNameError

        try:
            item: Any = motor(name)
        except UnknownNameError:
            try:
                item = gearhead(name)
            except UnknownNameError:
                raise UnknownNameError("motor or gearhead", name, motor_names() + gearhead_names()) from None
        out.print(repr(item))
        out.print(f"source: {getattr(item, 'source', '')}")
        return
    rows = []
    for n in motor_names():
        m = motor(n)
        torque = getattr(m, "holding_torque", None) or getattr(m, "stall_torque", None)
        rows.append([n, type(m).__name__, _opt(getattr(m, "nominal_voltage", None), "V", 3),
                     _opt(torque, "N*m", 3), _opt(getattr(m, "nominal_torque", None), "N*m", 3),
                     _opt(getattr(m, "rotor_inertia", None), "g*cm**2", 3)])
    _table("motors", ["name", "kind", "voltage", "holding/stall torque", "nominal torque", "rotor inertia"], rows)
    rows = []
    for n in gearhead_names():
        g = gearhead(n)
        rows.append([n, f"{g.ratio:.5g}", f"{g.efficiency:.3g}", _opt(g.continuous_torque, "N*m", 3),
                     _opt(getattr(g, "intermittent_torque", None), "N*m", 3)])
    _table("gearheads", ["name", "ratio", "efficiency", "continuous torque", "intermittent torque"], rows)


@app.command()
def explain(check_name: Annotated[str | None, typer.Argument(metavar="CHECK", help="a check name")] = None) -> None:
    """Formula, source and assumptions of a check (without CHECK: list all checks)."""
    from mechverify.design import REGISTRY, adapters  # noqa: F401
    from mechverify.errors import UnknownNameError

    specs = {f"{ct.name}.{c.name}": (ct, c) for ct in REGISTRY.types.values() for c in ct.checks}
    if check_name is None:
        t = Table(title="checks", title_justify="left")
        t.add_column("check")
        t.add_column("title")
        for k, (_, c) in sorted(specs.items()):
            t.add_row(k, c.title)
        out.print(t)
        return
    hits = [v for k, v in specs.items() if k == check_name or k.split(".", 1)[1] == check_name]
    if not hits:
        raise UnknownNameError("check", check_name, list(specs) + [k.split(".", 1)[1] for k in specs])
    for ct, c in hits:
        out.print(f"[bold]{ct.name}.{c.name}[/bold] — {c.title}")
        out.print(c.explain or "(no explanation)")
        if c.needs:
            out.print(f"needs from a load case: {', '.join(c.needs)}")
        out.print(f"default safety-factor class: {c.sf_kind}\n")


@app.command()
def init(
    path: Annotated[Path, typer.Argument(help="where to write the starter design")] = Path("design.toml"),
    force: Annotated[bool, typer.Option("--force", help="overwrite an existing file")] = False,
) -> None:
    """Write a commented starter design file (a lead-screw lift) to PATH."""
    from importlib import resources

    if path.exists() and not force:
        raise Invalid(f"{path} exists; pass --force to overwrite it")
    _write_atomic(path, resources.files("mechverify.design").joinpath("starter.toml").read_text(encoding="utf-8"))
    out.print(f"wrote {path}; verify it with: mechverify check {path}")


@app.command()
def schema(output: Annotated[Path | None, typer.Option("--output", "-o", help="write to a file")] = None) -> None:
    """Print the JSON Schema of the design-file format."""
    import json

    from mechverify.design.schema import design_schema

    text = json.dumps(design_schema(), indent=2, sort_keys=True) + "\n"
    if output:
        _write_atomic(output, text)
    else:
        sys.stdout.write(text)


def main(argv: list[str] | None = None) -> int:
    """Entry point: runs the app and turns every error into a message and exit status 2."""
    try:
        code = app(args=argv, standalone_mode=False)
        return int(code or 0)
    except typer.Exit as exc:
        return exc.exit_code
    except (Invalid, MechverifyError) as exc:
        err.print(f"[red]error:[/red] {escape(str(exc))}", soft_wrap=True)
        return 2
    except (typer.BadParameter, typer.Abort) as exc:  # click errors
        err.print(f"error: {exc}")
        return 2
    except Exception as exc:  # click usage errors (typer vendors click) and anything unforeseen
        if hasattr(exc, "show") and hasattr(exc, "exit_code"):  # a click usage error
            exc.show()
            return 2
        err.print(f"[red]internal error:[/red] {type(exc).__name__}: {exc}\n"
                  "This is a bug in mechverify; please report it with the design file.")
        return 3


if __name__ == "__main__":
    sys.exit(main())
