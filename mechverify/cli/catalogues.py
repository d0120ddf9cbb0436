"""Browsing the data: ``mechverify materials``, ``threads``, ``bearings``, ``motors``."""

from __future__ import annotations

import argparse
from typing import Any

ORDER = 30


def add_parser(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("materials", help="list the material database, or show one material",
                       description="List the material database, or show one material with the source of every value.")
    p.add_argument("name", nargs="?", metavar="NAME", help="show one material in full")
    p.set_defaults(run=run_materials)
    p = sub.add_parser("threads", help="list the thread tables, or show one thread",
                       description="List the thread tables (ISO 2904 trapezoidal, ASME B1.5 Acme), or show one "
                                   "thread's geometry.")
    p.add_argument("name", nargs="?", metavar="NAME", help="a designation, e.g. Tr10x2 or '1/2-10 ACME'")
    p.set_defaults(run=run_threads)
    p = sub.add_parser("bearings", help="list the rolling-bearing catalogue, or show one bearing",
                       description="List the rolling-bearing catalogue, or show one bearing.")
    p.add_argument("name", nargs="?", metavar="NAME", help="a designation, e.g. 608-2Z")
    p.set_defaults(run=run_bearings)
    p = sub.add_parser("motors", help="list the motor and gearhead catalogues, or show one entry",
                       description="List the motor and gearhead catalogues, or show one entry with its source.")
    p.add_argument("name", nargs="?", metavar="NAME", help="a catalogue name")
    p.set_defaults(run=run_motors)


def run_materials(args: argparse.Namespace) -> int:
    from rich.table import Table

    from mechverify import materials as mats
    from mechverify.cli._console import out
    from mechverify.materials.material import PROPERTY_DIMENSIONS
    from mechverify.units import fmt

    if args.name:
        m = mats.get(args.name)
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
        return 0
    t = Table(title="materials", title_justify="left")
    for col in ("name", "category", "E", "yield", "ultimate", "density"):
        t.add_column(col)
    for m in mats.default_library():
        t.add_row(m.name, m.category, *(fmt(getattr(m, p), u, 3) if getattr(m, p) is not None else "-" for p, u in
                                        (("E", "GPa"), ("yield_strength", "MPa"), ("ultimate_strength", "MPa"),
                                         ("density", "kg/m**3"))))
    out.print(t)
    return 0


def run_threads(args: argparse.Namespace) -> int:
    from mechverify.cli._console import opt, out, table
    from mechverify.components.threads import known_designations, thread

    names = [args.name] if args.name else known_designations()
    rows = []
    for n in names:
        t = thread(n)
        rows.append([t.designation, opt(t.d, "mm"), opt(t.pitch, "mm"), opt(t.lead, "mm"), str(t.starts),
                     opt(t.d2, "mm"), opt(t.d3, "mm"), opt(t.H1, "mm"), opt(t.lead_angle, "deg", 3)])
    table("threads", ["designation", "d", "P", "lead", "starts", "d2", "d3", "H1", "lead angle"], rows)
    if args.name:
        t = thread(args.name)
        out.print(f"source: {t.source}")
        for n in t.notes:
            out.print(f"note: {n}")
    return 0


def run_bearings(args: argparse.Namespace) -> int:
    from mechverify.cli._console import opt, out, table
    from mechverify.components.bearings import bearing, bearing_names
    from mechverify.components.bearings_rolling import rolling_bearing, rolling_bearing_catalogue
    from mechverify.errors import UnknownNameError

    other = rolling_bearing_catalogue()
    if args.name:
        try:
            bearing(args.name)
            other = []
        except UnknownNameError:
            try:
                other = [rolling_bearing(args.name)]
            except UnknownNameError:
                raise UnknownNameError("bearing", args.name, [*bearing_names(), *(b.designation for b in other)]) \
                    from None
    if other:  # angular contact, thrust, tapered, cylindrical, needle (components/data/bearings_rolling.toml)
        table("other rolling bearings", ["designation", "kind", "d", "D", "B", "C", "C0", "Pu", "limit speed",
                                         "verified"],
              [[b.designation, b.kind.replace("_", " "), opt(b.d, "mm"), opt(b.D, "mm"), opt(b.B, "mm"),
                opt(b.C, "kN"), opt(b.C0, "kN"), opt(b.Pu, "kN"), opt(b.limiting_speed, "rpm", 5),
                "no" if b.unverified else "yes"] for b in other])
        if args.name:
            out.print(f"source: {other[0].source}")
            return 0
    rows, seen = [], set()
    for n in [args.name] if args.name else bearing_names():
        b = bearing(n)
        if b.designation in seen:  # a designation reachable under two names (an alias) is listed once
            continue
        seen.add(b.designation)
        rows.append([b.designation, opt(b.d, "mm"), opt(b.D, "mm"), opt(b.B, "mm"), opt(b.C, "kN"),
                     opt(b.C0, "kN"), opt(b.Pu, "kN"), opt(b.reference_speed, "rpm", 5),
                     opt(b.limiting_speed, "rpm", 5), f"{b.f0:g}"])
    table("ball bearings", ["designation", "d", "D", "B", "C", "C0", "Pu", "ref. speed", "limit speed", "f0"], rows)
    if args.name:
        out.print(f"source: {bearing(args.name).source}")
    return 0


def run_motors(args: argparse.Namespace) -> int:
    from mechverify.cli._console import opt, out, table
    from mechverify.components.gearheads import gearhead, gearhead_names
    from mechverify.components.motors import motor, motor_names
    from mechverify.errors import UnknownNameError

    if args.name:
        try:
            item: Any = motor(args.name)
        except UnknownNameError:
            try:
                item = gearhead(args.name)
            except UnknownNameError:
                raise UnknownNameError("motor or gearhead", args.name, motor_names() + gearhead_names()) from None
        out.print(repr(item))
        out.print(f"source: {getattr(item, 'source', '')}")
        return 0
    rows = []
    for n in motor_names():
        m = motor(n)
        torque = getattr(m, "holding_torque", None) or getattr(m, "stall_torque", None)
        rows.append([n, type(m).__name__, opt(getattr(m, "nominal_voltage", None), "V", 3),
                     opt(torque, "N*m", 3), opt(getattr(m, "nominal_torque", None), "N*m", 3),
                     opt(getattr(m, "rotor_inertia", None), "g*cm**2", 3)])
    table("motors", ["name", "kind", "voltage", "holding/stall torque", "nominal torque", "rotor inertia"], rows)
    rows = []
    for n in gearhead_names():
        g = gearhead(n)
        rows.append([n, f"{g.ratio:.5g}", f"{g.efficiency:.3g}", opt(g.continuous_torque, "N*m", 3),
                     opt(getattr(g, "intermittent_torque", None), "N*m", 3)])
    table("gearheads", ["name", "ratio", "efficiency", "continuous torque", "intermittent torque"], rows)
    return 0
