"""``mechverify size``: the value of one parameter at which a check's u·SF reaches 1 (Brent's method)."""

from __future__ import annotations

import argparse
from pathlib import Path

from mechverify.cli._common import write

ORDER = 40


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("size", help="solve for the limit value of one parameter (u·SF = 1)",
                       description="Find the value of a numeric parameter or field (a key path of the design "
                                   "file) at which the governing check, or a named one, reaches u·SF = 1: the "
                                   "range is scanned, then Brent's method solves each crossing. Prints the limit, "
                                   "the governing check there and the margin of today's value. Exit 0 with a "
                                   "limit, 2 when none lies in the range (u·SF at both ends is printed; --json then "
                                   "holds the scan with limit null).")
    p.add_argument("design", type=Path, metavar="DESIGN", help="design file (TOML)")
    p.add_argument("--vary", required=True, metavar="KEY.PATH",
                   help="the parameter, e.g. components.lift.mass or parameters.payload")
    p.add_argument("--until", default="governing", metavar="CHECK",
                   help="'governing' (default: the largest u·SF of all checks) or a check, e.g. "
                        "motor_peak_torque or lift.motor_peak_torque")
    p.add_argument("--bounds", metavar="LO:HI", help="range to search, e.g. '1 kg:100 kg' (default: today/10 .. "
                                                     "today*10); bare numbers take the file's unit")
    p.add_argument("--scan", type=int, default=8, metavar="N", help="intervals scanned for crossings (default 8)")
    p.add_argument("--json", dest="json_out", type=Path, metavar="PATH", help="write the answer as JSON")
    p.add_argument("--allow-outside-includes", action=argparse.BooleanOptionalAction, default=False,
                   help="allow includes outside the design's folder (default: refused)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from mechverify.cli import Invalid
    from mechverify.fileio import check_output_paths

    check_output_paths({"--json": args.json_out}, [args.design])
    bounds = None
    if args.bounds is not None:
        bounds = [b.strip() for b in args.bounds.split(":")]
        if len(bounds) != 2:
            raise Invalid(f"--bounds: expected LO:HI, e.g. '1 kg:100 kg', got {args.bounds!r}")
    from mechverify.cli._common import load_designs
    from mechverify.cli._console import console
    from mechverify.errors import InputError
    from mechverify.fileio import json_text
    from mechverify.studies import SizingError, size

    (design,) = load_designs([args.design], args.allow_outside_includes)
    try:
        r = size(design, args.vary, until=args.until, bounds=bounds, scan=args.scan)
    except SizingError as exc:  # no limit: a CI script still gets the scan (u·SF per point) to read
        if args.json_out and exc.data:
            write(args.json_out, json_text({**exc.data, "error": str(exc)}, indent=1) + "\n")
        raise
    except InputError as exc:  # name the option, not the Python argument
        head, sep, rest = str(exc).partition(": ")
        if sep and head in ("bounds", "scan", "until"):
            raise type(exc)(f"--{head}: {rest}") from None
        raise
    console().print(r.text(), markup=False, highlight=False, soft_wrap=True)
    if args.json_out:
        write(args.json_out, json_text(r.to_dict(), indent=1) + "\n")
    return 0
