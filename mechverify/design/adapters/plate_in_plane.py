"""Parsing of the in-plane (membrane) keys of ``plate_fea``: the component's ``in_plane_supports`` and a load case's
``in_plane`` table (edge loads ``nx``, ``ny``, ``nxy`` and ``hole_loads`` on hole rims).

The membrane model is :func:`mechverify.fea.plate_stress.membrane_stress` (its stress enters ``plate_stress_fea``,
its field ``buckling_load_factor``). Used by :mod:`mechverify.design.adapters.plate_fea`; declares no component type.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from mechverify.components import plates as pl
from mechverify.design.adapters import modal_parsing as mp
from mechverify.design.adapters.common import inline_table
from mechverify.design.adapters.plate_parsing import _edges, _hole_names
from mechverify.design.spec import Field
from mechverify.errors import InputError, MechverifyError
from mechverify.units import as_quantity

HOLE_LOAD_KEYS = ("holes", "force_x", "force_y")
IN_PLANE_TABLE_KEYS = (*mp.IN_PLANE_KEYS, "hole_loads")
HOLDS = {"x": (True, False), "y": (False, True), "xy": (True, True)}

IN_PLANE_SUPPORTS_FIELD = Field(
    "in_plane_supports", "list", "in-plane supports of the membrane problem (in_plane loads): {edges = \"all\" | "
    "[indices or bottom/right/top/left] | holes = \"all\" | [group or hole names], hold = \"xy\" | \"x\" | \"y\"}; "
    "without them the in_plane loads must balance by themselves", item="table")


def in_plane_supports(p: Mapping[str, Any], plate: pl.Plate, groups: dict[str, list[str]]) -> tuple[Any, ...]:
    """The :class:`mechverify.fea.plate_stress.InPlaneSupport` items of the component's ``in_plane_supports``."""
    from mechverify.fea.plate_stress import InPlaneSupport

    out = []
    for i, t in enumerate(p.get("in_plane_supports") or []):
        path = f"in_plane_supports[{i}]"
        t = inline_table(t, path, ("edges", "holes", "hold"))
        if ("edges" in t) == ("holes" in t):
            raise InputError(f"{path}: give exactly one of edges or holes")
        hold = t.get("hold", "xy")
        if hold not in HOLDS:
            raise InputError(f"{path}.hold: one of xy, x, y, got {hold!r}")
        x, y = HOLDS[hold]
        if "edges" in t:
            out.append(InPlaneSupport(edges=_edges(t["edges"], plate, len(plate.outline), f"{path}.edges"), x=x, y=y))
        else:
            out.append(InPlaneSupport(holes=tuple(_hole_names(t["holes"], groups, f"{path}.holes")), x=x, y=y))
    return tuple(out)


def in_plane_load(v: Any, path: str, groups: dict[str, list[str]]) -> Any:
    """The :class:`mechverify.fea.plate_buckling.InPlaneLoad` of a load case's ``in_plane`` table at key ``path``:
    ``nx``, ``ny``, ``nxy`` (:func:`mechverify.design.adapters.modal_parsing.in_plane_load`) and ``hole_loads =
    [{holes, force_x, force_y}]`` (the force on each hole named, a pin bearing on its rim)."""
    from mechverify.fea.plate_buckling import HoleForce, InPlaneLoad

    if not isinstance(v, Mapping) or not v:
        raise InputError(f"{path}: expected a table {{nx = \"-10 N/mm\", ny = ..., nxy = ..., hole_loads = [...]}}, "
                         f"got {v!r}")
    bad = [k for k in v if k not in IN_PLANE_TABLE_KEYS]
    if bad:
        raise InputError(f"{path}.{bad[0]}: not a key of in_plane ({', '.join(IN_PLANE_TABLE_KEYS)})")
    edge = {k: x for k, x in v.items() if k != "hole_loads"}
    load = mp.in_plane_load(edge, path) if edge else InPlaneLoad()
    items = v.get("hole_loads", [])
    if not isinstance(items, list):
        raise InputError(f"{path}.hole_loads: expected a list of tables {{holes, force_x, force_y}}, got {items!r}")
    forces = []
    for i, t in enumerate(items):
        where = f"{path}.hole_loads[{i}]"
        t = inline_table(t, where, HOLE_LOAD_KEYS, ("holes",))
        if "force_x" not in t and "force_y" not in t:
            raise InputError(f"{where}: give force_x and/or force_y")
        f = tuple(as_quantity(t.get(k, "0 N"), "force", f"{where}.{k}") for k in ("force_x", "force_y"))
        for name in _hole_names(t["holes"], groups, f"{where}.holes"):
            try:
                forces.append(HoleForce(name, f))
            except MechverifyError as exc:
                raise InputError(f"{where}: {str(exc).split(': ', 1)[-1]}") from None
    out = InPlaneLoad(load.nx, load.ny, load.nxy, tuple(forces))
    try:
        out.values()
    except InputError as exc:
        raise InputError(f"{path}: {str(exc).split(': ', 1)[-1]}") from None
    return out
