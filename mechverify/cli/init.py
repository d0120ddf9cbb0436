"""``mechverify init``: write a commented starter design file."""

from __future__ import annotations

import argparse
from pathlib import Path

from mechverify.cli._common import write

ORDER = 50


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("init", help="write a commented starter design file",
                       description="Write a commented starter design file (a lead-screw lift) to PATH.")
    p.add_argument("path", nargs="?", type=Path, default=Path("design.toml"), metavar="PATH",
                   help="where to write the starter design (default: design.toml)")
    p.add_argument("--force", action="store_true", help="overwrite an existing file")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from importlib import resources

    from mechverify.cli import Invalid
    from mechverify.cli._console import out
    from mechverify.fileio import check_output_path

    path = args.path
    if (path.exists() or path.is_symlink()) and not args.force:
        raise Invalid(f"{path} exists; pass --force to overwrite it")
    check_output_path(path, "PATH")
    write(path, resources.files("mechverify.design").joinpath("starter.toml").read_text(encoding="utf-8"))
    out.print(f"wrote {path}; verify it with: mechverify check {path}")
    return 0
