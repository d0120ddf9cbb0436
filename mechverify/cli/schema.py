"""``mechverify schema``: the JSON Schema of the design-file format."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from mechverify.cli._common import write

ORDER = 60


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("schema", help="print the JSON Schema of the design-file format",
                       description="Print the JSON Schema of the design-file format (for editors and CI).")
    p.add_argument("--output", "-o", type=Path, metavar="PATH", help="write to a file instead of standard output")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    import json

    from mechverify.design.schema import design_schema
    from mechverify.fileio import check_output_path

    if args.output:
        check_output_path(args.output, "--output")
    text = json.dumps(design_schema(), indent=2, sort_keys=True) + "\n"
    if args.output:
        write(args.output, text)
    else:
        sys.stdout.write(text)
    return 0
