"""Parsing of a ``drive`` component's tables: transmission stages, motor and gearhead (catalogue or inline).

Used by :mod:`mechverify.design.adapters.drives`; declares no component type.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from mechverify.components.gearheads import Gearhead, gearhead, gearhead_from_dict
from mechverify.components.motors import motor, motor_from_dict
from mechverify.components.transmissions import BeltDrive, DirectDrive, Drum
from mechverify.components.transmissions import ScrewDrive as ScrewStage
from mechverify.errors import InputError, MechverifyError, suggest
from mechverify.units import as_quantity

STAGE_KEYS: dict[str, dict[str, str]] = {
    "screw": {"screw": "str", "mu": "dimensionless", "collar_mu": "dimensionless", "collar_diameter": "length",
              "inertia": "inertia"},
    "drum": {"diameter": "length", "efficiency": "dimensionless", "backdrive_efficiency": "dimensionless",
             "inertia": "inertia"},
    "belt": {"driver": "count_or_length", "driven": "count_or_length", "efficiency": "dimensionless",
             "backdrive_efficiency": "dimensionless", "inertia": "inertia"},
    "direct": {"efficiency": "dimensionless", "inertia": "inertia"},
}
_STAGE_REQUIRED = {"screw": ("screw",), "drum": ("diameter",), "belt": ("driver", "driven"), "direct": ()}


def stage_values(i: int, table: Mapping[str, Any]) -> tuple[str, dict[str, Any]]:
    path = f"transmission[{i}]"
    kind = table.get("type")
    if kind not in STAGE_KEYS:
        hint = suggest(str(kind), STAGE_KEYS, 1)
        raise InputError(f"{path}.type: expected one of {', '.join(STAGE_KEYS)}, got {kind!r}"
                         + (f"; did you mean {hint[0]!r}?" if hint else ""))
    keys = STAGE_KEYS[kind]
    out: dict[str, Any] = {}
    for k, v in table.items():
        if k in ("type", "name"):
            continue
        if k not in keys:
            hint = suggest(k, keys, 1)
            raise InputError(f"{path}.{k}: unknown key for a {kind} stage"
                             + (f"; did you mean {hint[0]!r}?" if hint else f" (allowed: {', '.join(keys)}, name)"))
        dim = keys[k]
        if dim == "str":
            if not isinstance(v, str):
                raise InputError(f"{path}.{k}: expected a name, got {v!r}")
            out[k] = v
        elif dim == "count_or_length":
            if isinstance(v, int) and not isinstance(v, bool):
                out[k] = v
            else:
                out[k] = as_quantity(v, "length", f"{path}.{k}")
        else:
            out[k] = as_quantity(v, dim, f"{path}.{k}")
    missing = [k for k in _STAGE_REQUIRED[kind] if k not in out]
    if missing:
        raise InputError(f"{path}.{missing[0]}: missing ({'a name' if missing[0] == 'screw' else 'required'})")
    return kind, out


def _screw_component(i: int, name: str, ctx: Mapping[str, Any]) -> Any:
    comps = ctx.get("components", {})
    entry = comps.get(name)
    if entry is None or entry.type.name != "lead_screw":
        screws = [k for k, e in comps.items() if e.type.name == "lead_screw"]
        hint = suggest(name, screws, 1)
        raise InputError(f"transmission[{i}].screw: expected the name of a lead_screw component, got {name!r}"
                         + (f"; did you mean {hint[0]!r}?" if hint
                            else f" (lead screws: {', '.join(screws) or 'none'})"))
    if entry.obj is None:
        if "thread" not in entry.params or "length" not in entry.params:
            raise InputError(f"transmission[{i}].screw: the lead screw {name!r} is invalid (see its own errors)")
        entry.obj = entry.type.build({**entry.params, "_name": name}, ctx)
    return entry.obj


def _screw_stages(ls: Any, table: Mapping[str, Any], name: str, v: dict[str, Any]) -> list[tuple[str, Any]]:
    """The stage(s) of a screw stage ``table`` on the lead screw component ``ls``: one per end of the nut's friction
    range. Kept per (screw object, table): a study's variant that takes the base design's lead screw over
    (:func:`mechverify.design.reuse.reused_object`) takes its stages too, whose efficiencies cost pint arithmetic.
    The stages are frozen and depend on nothing else."""
    from mechverify.design.reuse import _canon

    key = (id(ls), _canon(table))
    hit = _SCREW_STAGES.get(key)
    if hit is not None and hit[0] is ls:
        return list(hit[1])
    if "inertia" not in v and ls.screw.material is not None and ls.screw.material.density is not None:
        v["inertia"] = ls.screw.rotor_inertia()
    if "mu" in v:
        mus = [("", v.pop("mu"))]
    else:
        lo, hi = ls.nut.require_mu()
        mus = [(f"mu_max = {hi:g}", hi)] + ([(f"mu_min = {lo:g}", lo)] if lo != hi else [])
    out = [(lab, ScrewStage(ls.screw, mu, name=name, **v)) for lab, mu in mus]
    if len(_SCREW_STAGES) >= 64:
        _SCREW_STAGES.clear()
    _SCREW_STAGES[key] = (ls, tuple(out))  # holds ls: its id stays its own
    return out


_SCREW_STAGES: dict[Any, tuple[Any, tuple[tuple[str, Any], ...]]] = {}


def parse_stages(tables: list[Any], ctx: Mapping[str, Any]) -> list[list[tuple[str, Any]]]:
    """Per stage the list of (variant label, stage object): a screw with a friction range gives two."""
    errors, out = [], []
    for i, table in enumerate(tables):
        try:
            if not isinstance(table, dict):
                raise InputError(f"transmission[{i}]: expected a table such as {{ type = \"drum\", diameter = "
                                 f"\"30 mm\" }}, got {table!r}")
            kind, v = stage_values(i, table)
            name = table.get("name") or {"screw": v.get("screw"), "belt": "belt drive"}.get(kind, kind)
            if kind == "screw":
                ls = _screw_component(i, v.pop("screw"), ctx)
                out.append(_screw_stages(ls, table, name, v))
            else:
                cls = {"drum": Drum, "belt": BeltDrive, "direct": DirectDrive}[kind]
                out.append([("", cls(name=name, **v))])
        except MechverifyError as exc:
            msg = str(exc)
            errors.append(msg if msg.startswith(f"transmission[{i}]") else f"transmission[{i}]: {msg}")
    if errors:
        raise InputError("; ".join(errors))
    return out


# ------------------------------------------------------------------------------------ motor, gearhead


def _inline(kind: str, table: dict[str, Any], default_name: str, make: Callable[[dict[str, Any]], Any]) -> Any:
    d = {"name": default_name, **table}
    try:
        return make(d)
    except MechverifyError as exc:
        msg = str(exc)
        for prefix in (f"{d['name']}.", f"{kind} {d['name']!r}."):
            if msg.startswith(prefix):
                raise InputError(f"{kind}_data.{msg[len(prefix):]}") from None
        raise InputError(f"{kind}_data: {msg}") from None


def parse_motor(p: Mapping[str, Any]) -> Any:
    if ("motor" in p) == ("motor_data" in p):
        raise InputError("motor: give either motor (a catalogue name, see `mechverify motors`) or a motor_data table")
    if "motor" in p:
        try:
            return motor(p["motor"])
        except MechverifyError as exc:
            raise InputError(f"motor: {exc}") from None
    return _inline("motor", dict(p["motor_data"]), f"{p['_name']} motor", motor_from_dict)


def parse_gearhead(p: Mapping[str, Any]) -> Gearhead | None:
    if "gearhead" in p and "gearhead_data" in p:
        raise InputError("gearhead: give either gearhead (a catalogue name) or a gearhead_data table, not both")
    if "gearhead" in p:
        try:
            return gearhead(p["gearhead"])
        except MechverifyError as exc:
            raise InputError(f"gearhead: {exc}") from None
    if "gearhead_data" in p:
        return _inline("gearhead", dict(p["gearhead_data"]), f"{p['_name']} gearhead", gearhead_from_dict)
    return None
