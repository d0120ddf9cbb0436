"""``make demo``: verify the bundled lead-screw lift example and write its report.

``python -m mechverify.demo`` (what ``make demo`` runs) verifies ``examples/lead_screw_lift/design.toml``
(reference project 004: a Tr10x2 lead-screw lift for two wearable robotic arms: screw, nut, bearings, stepper
drive, the screw bent in the horizontal posture) and ``design_plates.toml`` (its arm and base plates, plate
FEA) with the example's ``run.py``, prints the results table of each and one combined verdict, and writes
``out/lead_screw_lift/report.html`` and ``report.pdf`` (both designs) in the repository (``--out DIR``
elsewhere, ``--no-pdf`` for the HTML only). As ``mechverify check --report`` does, the reports give the
formulas, inputs and figures of the failing and warning checks and summarise the passing ones
(``--detail all`` details every check: 58 PDF pages instead of 22, twice the time).

The demo writes into ``out/`` (ignored by git) and never over the committed ``examples/lead_screw_lift/report.*``:
a report records the date and the git commit it was made from, so regenerating the committed copy on every
demo would leave the working tree modified. The committed report is regenerated on purpose with
``python examples/lead_screw_lift/run.py``.

The design as the document specifies it FAILS three checks (stepper torque at 540 rpm with the nut's highest
friction, nut pv, screw bending in the horizontal posture) and its 4 mm arm plate two more (stress and
deflection, plate FEA): that is the finding, not an error of the demo,
which exits 0 once the report is written (2 if the example cannot be found or is invalid). The comparison
with every number of the document is in ``docs/examples/lead_screw_lift.md``.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
from pathlib import Path
from types import ModuleType

REPO = Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "lead_screw_lift"


def load_example(folder: Path = EXAMPLE) -> ModuleType:
    """Import the example's ``run.py`` (examples/ is not a package)."""
    path = folder / "run.py"
    if not path.is_file():
        raise FileNotFoundError(f"the demo needs a source checkout: {path} not found")
    spec = importlib.util.spec_from_file_location("lead_screw_lift_run", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m mechverify.demo", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=REPO / "out" / "lead_screw_lift", help="folder for the reports")
    ap.add_argument("--no-pdf", action="store_true", help="write the HTML report only")
    ap.add_argument("--detail", choices=("problems", "all"), default="problems",
                    help="per-check detail (formulas, inputs, figures) for the failing and warning checks "
                         "(default, as `mechverify check --report`) or for all")
    args = ap.parse_args(argv)
    os.environ.setdefault("MPLBACKEND", "Agg")

    from rich.markup import escape

    from mechverify.cli._console import combined_line, err, out, results_table, verdict_line
    from mechverify.errors import MechverifyError

    try:
        example = load_example()
        runs = [example.verify(), example.verify(example.PLATES)]
    except (FileNotFoundError, MechverifyError) as exc:
        err.print(f"[red]demo:[/red] {escape(str(exc))}")  # a message naming 'mechverify[mesh]' is not markup
        return 2
    for design, rs in runs:
        shown = design.path.relative_to(REPO) if design.path and design.path.is_relative_to(REPO) else design.path
        out.print(f"Verifying {shown or 'the example'} (reference project 004, lead-screw lift)\n")
        out.print(results_table(rs))
        out.print(verdict_line(rs) + "\n")
    out.print(combined_line([rs for _, rs in runs]) + " (the report holds both designs)")
    paths = example.write_reports(args.out, pdf=not args.no_pdf, run=runs[0], plates_run=runs[1], detail=args.detail)
    for p in paths:
        shown = p.relative_to(REPO) if p.is_relative_to(REPO) else p
        out.print(f"report: {shown}")
    out.print("the document's numbers next to mechverify's, with every difference explained: "
              "docs/examples/lead_screw_lift.md")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
