"""Parsing of a ``frame`` component (:mod:`mechverify.design.adapters.frame`): points, vectors, sections by
properties, members, supports' and loads' inline tables, load combinations. Declares no type."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from mechverify.components.sections import Section
from mechverify.design.adapters.common import inline_table
from mechverify.design.adapters.sections import SECTION_ALIASES, SECTION_DIMENSIONS, SECTION_KINDS, build_section
from mechverify.errors import InputError, MechverifyError, suggest
from mechverify.fea import frame as fe
from mechverify.units import as_quantity

PROPERTIES = {"area": "area", "Iy": "second_moment", "Iz": "second_moment", "J": "second_moment", "Asy": "area",
              "Asz": "area", "c_y": "length", "c_z": "length", "Wt": "volume"}


def where(v: Any, path: str) -> Any:
    if isinstance(v, str):
        return v
    if isinstance(v, list) and len(v) == 3:
        return [as_quantity(c, "length", f"{path}[{i}]") for i, c in enumerate(v)]
    raise InputError(f"{path}: expected a node name or three lengths [x, y, z], got {v!r}")


def vec(v: Any, dim: str, path: str) -> list[Any]:
    if not isinstance(v, list) or len(v) != 3:
        raise InputError(f"{path}: expected three components [x, y, z] with units, got {v!r}")
    return [as_quantity(c, dim, f"{path}[{i}]") for i, c in enumerate(v)]


def make(path: str, fn: Any, *args: Any, **kw: Any) -> Any:
    try:
        return fn(*args, **kw)
    except MechverifyError as exc:
        raise InputError(f"{path}: {exc}") from None


def section_table(t: Any, path: str) -> Section:
    if isinstance(t, dict) and t.get("kind") == "properties":
        t = inline_table(t, path, ("kind", *PROPERTIES), ("kind", "area", "Iy", "Iz", "J"))
        p = {k: as_quantity(v, PROPERTIES[k], f"{path}.{k}") for k, v in t.items() if k != "kind"}
        return make(path, fe.section_from_properties, p.pop("area"), p.pop("Iy"), p.pop("Iz"), p.pop("J"), **p)
    t = inline_table(t, path, ("kind", *SECTION_DIMENSIONS), ("kind",))
    if t["kind"] not in (*SECTION_KINDS, *SECTION_ALIASES):
        raise InputError(f"{path}.kind: expected one of {', '.join(SECTION_KINDS)} or properties, got {t['kind']!r}")
    p = {"section": t["kind"], **{k: as_quantity(v, "length", f"{path}.{k}") for k, v in t.items() if k != "kind"}}
    return make(path[:path.rindex(".")], build_section, p)


#: Largest ``divisions`` of a member (review 4 finding 14).
MAX_DIVISIONS = 1000

MEMBER_KEYS = ("name", "start", "end", "section", "material", "orientation", "theory", "divisions", "releases_start",
               "releases_end")


def parse_members(p: dict[str, Any], ctx: dict[str, Any]) -> list[fe.Member]:
    default = make("section", build_section, p) if "section" in p else None
    out = []
    for i, t in enumerate(p["members"]):
        path = f"members[{i}]"
        t = inline_table(t, path, MEMBER_KEYS, ("start", "end"))
        sec = section_table(t["section"], f"{path}.section") if "section" in t else default
        if sec is None:
            raise InputError(f"{path}.section: missing, and the frame gives no default section (section = ...)")
        mat = make(f"{path}.material", ctx["materials"].get, t["material"]) if "material" in t else p.get("material")
        if mat is None:
            raise InputError(f"{path}.material: missing, and the frame gives no default material")
        orient = t.get("orientation")
        if orient is not None and (not isinstance(orient, list) or len(orient) != 3
                                   or not all(isinstance(c, int | float) for c in orient)):
            raise InputError(f"{path}.orientation: expected three numbers (a direction), got {orient!r}")
        div = t.get("divisions", 1)
        if not isinstance(div, int) or isinstance(div, bool) or div < 1:
            raise InputError(f"{path}.divisions: expected a whole number >= 1, got {div!r}")
        if div > MAX_DIVISIONS:  # review 4 #14: 1e6 ran a minute into a MemoryError; 80 000 took 6 min and 1.7 GB
            raise InputError(f"{path}.divisions: at most {MAX_DIVISIONS}, got {div} (the frame element is exact "
                             "between its nodes for end loads, and a few tens of elements per member resolve any "
                             "distributed load or mode shape; measured about 20 kB and 4 ms per element)")
        out.append(make(path, fe.Member, where(t["start"], f"{path}.start"), where(t["end"], f"{path}.end"), sec,
                         mat, str(t.get("name", f"M{i + 1}")), orient, t.get("theory"), div, t.get("releases_start"),
                         t.get("releases_end")))
    return out


def items(p: Mapping[str, Any], key: str, keys: tuple[str, ...], required: tuple[str, ...], base: str = ""
           ) -> list[tuple[str, dict[str, Any]]]:
    return [(f"{base}{key}[{i}]", inline_table(t, f"{base}{key}[{i}]", keys, required))
            for i, t in enumerate(p.get(key, []))]


def case_loads(loads: Mapping[str, Any], case: str, comp: str, g: Any) -> list[Any]:
    b = f"load_cases.{case}.{comp}."
    out: list[Any] = []
    for path, t in items(loads, "point_loads", ("at", "force", "moment"), ("at",), b):
        if "force" not in t and "moment" not in t:
            raise InputError(f"{path}: give force and/or moment")
        out.append(fe.FramePointLoad(where(t["at"], f"{path}.at"),
                                vec(t["force"], "force", f"{path}.force") if "force" in t else None,
                                vec(t["moment"], "torque", f"{path}.moment") if "moment" in t else None))
    for path, t in items(loads, "member_loads", ("member", "position", "force", "moment", "axes"),
                          ("member", "position"), b):
        out.append(make(path, fe.MemberPointLoad, str(t["member"]), as_quantity(t["position"], "length", path),
                         vec(t["force"], "force", f"{path}.force") if "force" in t else None,
                         vec(t["moment"], "torque", f"{path}.moment") if "moment" in t else None,
                         t.get("axes", "local")))
    for path, t in items(loads, "distributed_loads", ("member", "load", "axes", "start", "end", "load_end"),
                          ("member", "load"), b):
        w = vec(t["load"], "force_per_length", f"{path}.load")
        w1 = vec(t["load_end"], "force_per_length", f"{path}.load_end") if "load_end" in t else None
        out.append(make(path, fe.DistributedLoad, str(t["member"]), w, t.get("axes", "global"), t.get("start"),
                         t.get("end"), w1))
    for path, t in items(loads, "settlements", ("at", "values"), ("at", "values"), b):
        out.append(make(path, fe.SupportDisplacement, where(t["at"], f"{path}.at"), t["values"]))
    if loads.get("self_weight"):
        out.append(fe.FrameSelfWeight(g))
    return out


def combination(loads: Mapping[str, Any], case: str, comp: str, cases: Mapping[str, Any]) -> fe.LoadCombination:
    path = f"load_cases.{case}.{comp}"
    others = [k for k in loads if k != "combination"]
    if others:
        raise InputError(f"{path}.{others[0]}: a combination case takes no loads of its own (add a load case)")
    f = loads["combination"]
    if not isinstance(f, dict) or not f:
        raise InputError(f"{path}.combination: expected a table {{case = factor, ...}}, got {f!r}")
    for k in f:
        if k not in cases:
            close = suggest(str(k), cases)
            raise InputError(f"{path}.combination.{k}: not a load case of {comp} (without a combination of its own)"
                             + (f"; did you mean {', '.join(repr(c) for c in close)}?" if close else "")
                             + f" (its load cases: {', '.join(cases) or 'none'})")
    return make(f"{path}.combination", fe.LoadCombination, case, f)


def frame_cases(load_cases: Mapping[str, Any], comp: str, g: Any,
                wanted: str) -> tuple[dict[str, Any], list[fe.LoadCombination]]:
    """Every load case (parsed loads) and combination of frame ``comp`` in the design's ``load_cases``. A case or
    combination whose keys are wrong is left out, unless it is ``wanted`` (then its error is raised): all cases
    are solved together at the first check, and the error of another case is reported by that case's own checks,
    once at its key, not again under every check of every other case (review 2 finding 12). A combination of a
    case left out is left out too."""
    mine = {c: comps[comp] for c, comps in load_cases.items() if comp in comps}
    cases: dict[str, Any] = {}
    failed: dict[str, MechverifyError] = {}
    for c, v in mine.items():
        if "combination" not in v:
            try:
                cases[c] = case_loads(v, c, comp, g)
            except MechverifyError as exc:
                if c == wanted:
                    raise
                failed[c] = exc
    combos = []
    for c, v in mine.items():
        if "combination" in v:
            try:
                combo = combination(v, c, comp, {**cases, **failed})
            except MechverifyError:
                if c == wanted:
                    raise
                continue
            bad = [k for k in combo.factors if k in failed]
            if bad and c == wanted:
                raise InputError(f"combination.{bad[0]}: the load case {bad[0]!r} has an error of its own "
                                 f"(at load_cases.{bad[0]}.{comp})")
            if not bad:
                combos.append(combo)
    return cases, combos


def point_masses(p: Mapping[str, Any]) -> tuple[Any, ...]:
    """``masses = [{at, mass, inertia}]`` of a frame (natural frequencies only): PointMass es, validated."""
    from mechverify.fea.frame.modal import PointMass

    out = []
    for path, t in items(p, "masses", ("at", "mass", "inertia"), ("at", "mass")):
        J = t.get("inertia")
        if isinstance(J, list):
            if len(J) != 3:
                raise InputError(f"{path}.inertia: one value or three [Ix, Iy, Iz], got {J!r}")
            J = [as_quantity(v, "inertia", f"{path}.inertia[{i}]") for i, v in enumerate(J)]
        elif J is not None:
            J = as_quantity(J, "inertia", f"{path}.inertia")
        pm = PointMass(where(t["at"], f"{path}.at"), as_quantity(t["mass"], "mass", f"{path}.mass"), J)
        make(path, pm.values)
        out.append(pm)
    return tuple(out)
