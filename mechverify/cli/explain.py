"""``mechverify explain``: formula, source and assumptions of a check."""

from __future__ import annotations

import argparse

ORDER = 40


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("explain", help="formula, source and assumptions of a check",
                       description="Formula, source and assumptions of a check (without CHECK: list all checks).")
    p.add_argument("check_name", nargs="?", metavar="CHECK", help="a check name, e.g. self_locking")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rich.table import Table

    from mechverify.cli._console import out
    from mechverify.design import REGISTRY, adapters  # noqa: F401

    specs = {f"{ct.name}.{c.name}": (ct, c) for ct in REGISTRY.types.values() for c in ct.checks}
    if args.check_name is None:
        t = Table(title="checks", title_justify="left")
        t.add_column("check")
        t.add_column("title")
        for k, (_, c) in sorted(specs.items()):
            t.add_row(k, c.title)
        out.print(t)
        return 0
    name = args.check_name
    hits = [v for k, v in specs.items() if k == name or k.split(".", 1)[1] == name]
    from mechverify.checks.registry import explain_text
    from mechverify.errors import UnknownNameError

    try:  # the registry's text: title, class, explanation, formula, source, former names, Python function
        text = explain_text(hits[0][1].name if hits else name)
    except UnknownNameError:
        if not hits:
            raise
        text = None
    if text is not None:
        out.print(text, markup=False, highlight=False)
    for ct, c in hits:
        if text is None:
            out.print(f"[bold]{ct.name}.{c.name}[/bold] — {c.title}")
            out.print(c.explain or "(no explanation)")
            out.print(f"default safety-factor class: {c.sf_kind}")
        needs = f"; needs from a load case: {', '.join(n.replace('|', ' or ') for n in c.needs)}" if c.needs else ""
        if c.reads:  # a check that runs once over every load case giving these keys
            needs += f"; reads from each load case that gives it: {' or '.join(c.reads)}"
        out.print(f"In design files: component type {ct.name}, key checks.{c.name}{needs}", markup=False)
    return 0
