"""``mechverify select-motor DESIGN --drive NAME``: rank catalogue motor × gearhead combinations for a drive.

Every combination of a catalogue motor (``components/data/motors.toml``) with no gearhead or a catalogue
gearhead replaces the drive's ``motor``/``gearhead`` and runs every check of the drive over its profile and
load cases. Those that pass all of them are ranked by margin (the smallest capacity/(demand·SF) of the
drive's checks, highest first); when none passes, the three nearest are shown with the check that fails.
Servos and gear-motors are tried without a gearhead (they are sold as one unit). ``--catalogue FILE`` adds a
user's motors and gearheads (``[[motor]]``/``[[gearhead]]`` entries as in the built-in data files), validated
entry by entry with the key path of any error.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ORDER = 15


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("select-motor", help="rank catalogue motor and gearhead combinations for a drive",
                       description="Try every catalogue motor with no gearhead and with every catalogue gearhead "
                                   "on the drive NAME of DESIGN; list the combinations that pass every drive check, "
                                   "by margin (exit 0), or the three nearest with the failing check (exit 1).")
    p.add_argument("design", type=Path, metavar="DESIGN", help="design file (TOML)")
    p.add_argument("--drive", required=True, metavar="NAME", help="the drive component to size")
    p.add_argument("--top", type=int, default=10, metavar="N", help="show the N best passing combinations")
    p.add_argument("--motor", action="append", default=None, metavar="NAME",
                   help="only these catalogue motors (repeatable; default: all)")
    p.add_argument("--gearhead", action="append", default=None, metavar="NAME",
                   help="only these catalogue gearheads (repeatable; 'none' for none; default: none and all)")
    p.add_argument("--catalogue", action="append", default=None, metavar="FILE", type=Path,
                   help="a catalogue file of your own ([[motor]] and [[gearhead]] entries, the layout of "
                        "components/data/motors.toml and gearheads.toml), tried with the built-in ones (repeatable)")
    from mechverify.cli._common import add_allow_outside
    add_allow_outside(p)
    p.set_defaults(run=run)


def short_reason(exc: BaseException, width: int = 240) -> str:
    """The last line of an error message for the table of skipped combinations, shortened at a word boundary
    (with "…") when longer than ``width``, never cut mid-word."""
    import textwrap

    lines = str(exc).strip().splitlines() or [""]
    return textwrap.shorten(lines[-1].strip(), width, placeholder=" …")


@dataclass(frozen=True)
class Combination:
    """One motor × gearhead tried on the drive."""

    motor: str
    gearhead: str | None
    passed: bool
    margin: float  # min over the drive's checks of capacity / (demand * SF); inf when nothing loads it
    governing: str  # the check with the least margin
    error: str = ""  # why the combination could not be evaluated


@dataclass(frozen=True)
class UserEntries:
    """Motors and gearheads of users' catalogue files: name -> the raw entry (an inline datasheet table)."""

    motors: dict[str, dict[str, Any]]
    gearheads: dict[str, dict[str, Any]]
    kinds: dict[str, str]  # motor name -> kind (dc, stepper, servo, gearmotor)


def read_user_catalogues(paths: list[Path]) -> UserEntries:
    """Validated entries of the users' catalogue files (:func:`mechverify.components.catalogue.read_catalogue_file`);
    a name that is also a built-in catalogue name, or in two files, is an :class:`InputError`."""
    from mechverify.components.catalogue import normalise, read_catalogue_file
    from mechverify.components.gearheads import gearhead_from_dict, gearhead_names
    from mechverify.components.motors import motor_from_dict, motor_names
    from mechverify.errors import InputError

    builtin = {normalise(n) for n in (*motor_names(), *gearhead_names())}

    def is_builtin(name: str) -> bool:  # a primary name or an alias of a catalogue entry
        from mechverify.components.gearheads import gearhead
        from mechverify.components.motors import motor
        from mechverify.errors import UnknownNameError
        if normalise(name) in builtin:
            return True
        for get in (motor, gearhead):
            try:
                get(name)
                return True
            except UnknownNameError:
                pass
        return False
    motors: dict[str, dict[str, Any]] = {}
    gearheads: dict[str, dict[str, Any]] = {}
    kinds: dict[str, str] = {}
    for path in paths:
        data = read_catalogue_file(path, {"motor": motor_from_dict, "gearhead": gearhead_from_dict})
        for table, store in (("motor", motors), ("gearhead", gearheads)):
            for i, (name, raw, item) in enumerate(data.get(table, [])):
                if is_builtin(name) or name in motors or name in gearheads:
                    raise InputError(f"{path.name}: {table}[{i}].name: {name!r} is already a catalogue name "
                                     "(built-in or another file): rename it")
                raw = {k: v for k, v in raw.items() if k not in ("aliases", "name")}
                if "source" in raw:
                    raw["source"] = str(item.source) if getattr(item, "source", None) else raw["source"]
                store[name] = raw
                if table == "motor":
                    kinds[name] = item.kind
    return UserEntries(motors, gearheads, kinds)


def combinations(design: Any, drive: str, motors: list[str] | None = None,
                 gearheads: list[str | None] | None = None, user: UserEntries | None = None) -> list[Combination]:
    """Evaluate every combination on ``drive`` of ``design`` (a :class:`~mechverify.design.Design`), the
    built-in catalogues' and ``user``'s motors and gearheads (user entries run as inline datasheet tables)."""
    import copy
    import math

    from mechverify.components.gearheads import gearhead_names
    from mechverify.components.motors import motor, motor_names
    from mechverify.design.design import _rebuild
    from mechverify.errors import InputError, MechverifyError, UnknownNameError

    comps = design.data.components
    if drive not in comps:
        raise UnknownNameError("component", drive, list(comps))
    if comps[drive].type.name != "drive":
        raise InputError(f"component {drive!r} is a {comps[drive].type.name}, not a drive")
    user = user or UserEntries({}, {}, {})
    if motors is None:
        motors = [*motor_names(), *user.motors]
    else:
        motors = [m if m in user.motors else motor(m).name for m in motors]
    if gearheads is None:
        gearheads = [None, *gearhead_names(), *user.gearheads]
    out = []
    for mname in motors:
        kind = user.kinds[mname] if mname in user.motors else motor(mname).kind
        for g in gearheads if kind in ("dc", "stepper") else [None]:
            doc = copy.deepcopy(design.data.raw)
            entry = doc["components"][drive]
            for k in ("motor", "motor_data", "gearhead", "gearhead_data"):
                entry.pop(k, None)
            if mname in user.motors:
                entry["motor_data"] = {"name": mname, **user.motors[mname]}
            else:
                entry["motor"] = mname
            if g is not None and g in user.gearheads:
                entry["gearhead_data"] = {"name": g, **user.gearheads[g]}
            elif g is not None:
                entry["gearhead"] = g
            try:
                d = _rebuild(doc, design.data.path, list(design.data.files), {})
                rs = [r for r in d.verify() if r.component == drive]
            except MechverifyError as exc:
                reason = short_reason(exc)
                out.append(Combination(mname, g, False, -math.inf, "", reason))
                continue
            if not rs:
                out.append(Combination(mname, g, False, -math.inf, "", "no drive check ran"))
                continue
            worst = max(rs, key=lambda r: r.factored_utilisation)
            u = worst.factored_utilisation
            out.append(Combination(mname, g, all(r.verdict.value != "fail" for r in rs),
                                   math.inf if u == 0 else 1.0 / u, worst.check))
    return out


def run(args: argparse.Namespace) -> int:
    from rich.table import Table

    from mechverify.cli import Invalid
    from mechverify.cli._common import load_designs
    from mechverify.cli._console import out
    from mechverify.errors import MechverifyError

    (design,) = load_designs([args.design], args.allow_outside_includes)
    if args.top < 1:
        raise Invalid("--top: give a positive number")
    gh = None if args.gearhead is None else [None if g.lower() == "none" else g for g in args.gearhead]
    try:
        user = read_user_catalogues(args.catalogue) if args.catalogue else None
        found = combinations(design, args.drive, args.motor, gh, user)
    except MechverifyError as exc:
        raise Invalid(str(exc)) from exc
    passing = sorted((c for c in found if c.passed), key=lambda c: -c.margin)
    if passing:
        t = Table(title=f"{args.drive}: {len(passing)} of {len(found)} combinations pass every check",
                  title_justify="left")
        rows = passing[:args.top]
    else:
        t = Table(title=f"{args.drive}: no combination of {len(found)} passes; the three nearest",
                  title_justify="left")
        rows = sorted((c for c in found if not c.error), key=lambda c: -c.margin)[:3]
    for col in ("motor", "gearhead", "margin", "governing check" if passing else "failing check"):
        t.add_column(col)
    for c in rows:
        t.add_row(c.motor, c.gearhead or "-", f"{c.margin:.3g}", c.governing)
    out.print(t)
    skipped = [c for c in found if c.error]
    if skipped:
        out.print(f"{len(skipped)} combinations could not be evaluated (e.g. {skipped[0].motor} + "
                  f"{skipped[0].gearhead or 'no gearhead'}: {skipped[0].error})")
    out.print("ranked by margin (the smallest capacity/(demand·SF) of the drive's checks); the catalogues have no "
              "mass or price fields to rank by")
    return 0 if passing else 1
