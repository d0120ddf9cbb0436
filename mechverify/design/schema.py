"""The JSON Schema of the design-file format, generated from the registered component types.

Editors that understand JSON Schema for TOML (e.g. Taplo / Even Better TOML) validate and complete
design files with it: ``mechverify schema > design.schema.json``.
"""

from __future__ import annotations

from typing import Any

from mechverify.design.loader import DESIGN_KEYS, REQUIREMENT_FIELDS
from mechverify.design.spec import DEFAULT_SAFETY_FACTORS, REGISTRY, ComponentType, Field
from mechverify.materials.material import PROPERTY_DIMENSIONS
from mechverify.units import DIMENSIONS

QUANTITY_PATTERN = r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[^\d\s].*$"
#: An expression over parameters and component values (design/expressions.py): at least one name, no quotes,
#: line breaks, ';' or '#'; at most 1,000 characters. The loader checks the grammar itself.
EXPRESSION_PATTERN = r"^[^'\"\n\r;#\\]*[A-Za-z_][^'\"\n\r;#\\]*$"
EXPRESSION = {"type": "string", "pattern": EXPRESSION_PATTERN, "maxLength": 1000,
              "description": "an expression: numbers with units, parameters, <component>.<value>, + - * / ** ( ), "
                             "sqrt sin cos tan atan2 min max abs pi"}


def field_schema(f: Field) -> dict[str, Any]:
    doc = f.doc
    if f.kind in DIMENSIONS and f.kind != "dimensionless":
        s: dict[str, Any] = {"type": "string", "anyOf": [{"pattern": QUANTITY_PATTERN}, EXPRESSION],
                             "description": f"{doc} [{f.kind.replace('_', ' ')}, e.g. '{DIMENSIONS[f.kind][1]}'; or an "
                                           "expression over parameters and component values]"}
    elif f.kind == "dimensionless":
        s = {"type": ["number", "string"], "description": doc}
    elif f.kind in ("str", "material", "ref"):
        s = {"type": "string", "description": doc}
    elif f.kind == "choice":
        s = {"enum": list(f.choices), "description": doc}
    elif f.kind == "int":
        s = {"anyOf": [{"type": "integer"}, EXPRESSION], "description": doc}
    elif f.kind == "float":
        s = {"anyOf": [{"type": "number"}, EXPRESSION], "description": doc}
    elif f.kind == "bool":
        s = {"type": "boolean", "description": doc}
    elif f.kind == "list":
        s = {"type": "array", "items": field_schema(Field(f.name, f.item or "str", choices=f.choices)),
             "description": doc}
    elif f.name in _DATASHEET_TABLES:
        s = {**_datasheet_table(f.name), "description": doc}
    else:
        s = {"type": "object", "description": doc}
    if f.default is not None:
        s["default"] = f.default
    return s


_DATASHEET_TABLES = ("motor_data", "gearhead_data")


def _datasheet_table(name: str) -> dict[str, Any]:
    """The keys of an inline datasheet table (``motor_data``: one variant per motor ``type``;
    ``gearhead_data``), read from the component dataclasses so that they never drift apart."""
    from dataclasses import MISSING, fields

    from mechverify.components.gearheads import Gearhead
    from mechverify.components.motors import _TYPES

    def variant(cls: type, kind: str | None) -> dict[str, Any]:
        fs = [f for f in fields(cls) if f.init and f.name != "derived"]
        props: dict[str, Any] = {f.name: {"description": f"{cls.__name__}.{f.name}"} for f in fs}
        props["name"] = {"type": "string", "description": "name shown in reports (default: '<component> motor')"}
        props["notes"] = {"type": "array", "items": {"type": "string"}}
        req = [f.name for f in fs if f.name != "name" and f.default is MISSING and f.default_factory is MISSING]
        if kind is not None:
            props["type"] = {"const": kind}
            req = ["type", *req]
        out: dict[str, Any] = {"type": "object", "properties": props, "additionalProperties": False}
        if req:
            out["required"] = req
        return out

    if name == "motor_data":
        return {"oneOf": [variant(cls, kind) for kind, cls in sorted(_TYPES.items())]}
    return variant(Gearhead, None)


def _object(fields: tuple[Field, ...], extra: dict[str, Any] | None = None) -> dict[str, Any]:
    props = {f.name: field_schema(f) for f in fields}
    props.update(extra or {})
    req = [f.name for f in fields if f.required]
    out: dict[str, Any] = {"type": "object", "properties": props, "additionalProperties": False}
    if req:
        out["required"] = req
    return out


def _typed(ct: ComponentType) -> dict[str, Any]:
    check_setting = {"oneOf": [{"type": "boolean"}, {
        "type": "object", "additionalProperties": False,
        "properties": {"enabled": {"type": "boolean"}, "required_sf": {"type": "number", "exclusiveMinimum": 0}}}]}
    checks = {c.name: {**check_setting, "description": c.title} for c in ct.checks}
    checks.update({a: {**check_setting, "description": f"former name of {c.name} (deprecated)", "deprecated": True}
                   for c in ct.checks for a in c.aliases})
    body = _object(ct.fields, {"type": {"const": ct.name},
                               "checks": {"type": "object", "properties": checks, "additionalProperties": False}})
    body["required"] = ["type", *body.get("required", [])]
    body["description"] = ct.doc
    return body


def _load_keys(types: Any) -> dict[str, Any]:
    """Every load-case key of the component types (``ComponentType.loads``), for completion and documentation: a load
    case names its components, not their types, so the keys are the union over the types (a key two types read
    differently takes either's form); which keys a component takes is checked by the loader. ``in_plane`` (plate_fea)
    lists its own keys."""
    from mechverify.design.adapters.modal_parsing import IN_PLANE_KEYS
    from mechverify.design.adapters.plate_in_plane import HOLE_LOAD_KEYS

    forms: dict[str, list[dict[str, Any]]] = {}
    for ct in types:
        for f in ct.loads:
            s = field_schema(f)
            if f.name == "in_plane":
                pair = {"anyOf": [field_schema(Field("n", "force_per_length")),
                                  {"type": "array", "minItems": 2, "maxItems": 2,
                                   "items": field_schema(Field("n", "force_per_length"))}]}
                s["properties"] = {k: {**(field_schema(Field(k, "force_per_length")) if k == "nxy" else pair),
                                       "description": f"{k} [force per length, tension positive]"}
                                   for k in IN_PLANE_KEYS}
                hole = {k: field_schema(Field(k, "force", f"{k[-1]} component of the force on each hole [N]"))
                        for k in HOLE_LOAD_KEYS[1:]}
                hole["holes"] = {"anyOf": [{"type": "string"}, {"type": "array", "items": {"type": "string"}}],
                                 "description": "\"all\" or hole or group names"}
                s["properties"]["hole_loads"] = {
                    "type": "array", "description": "in-plane forces on hole rims (a pin bearing on each)",
                    "items": {"type": "object", "properties": hole, "required": ["holes"],
                              "additionalProperties": False}}
                s["additionalProperties"] = False
            if s not in forms.setdefault(f.name, []):
                forms[f.name].append(s)
    return {k: v[0] if len(v) == 1 else {"anyOf": v, "description": " | ".join(dict.fromkeys(x.get("description", "")
                                                                                           for x in v))}
            for k, v in sorted(forms.items())}


def design_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a design file."""
    from mechverify.design import adapters  # noqa: F401

    comps = REGISTRY.in_section("components")
    profiles = REGISTRY.in_section("profiles")
    material_props = {k: field_schema(Field(k, v)) for k, v in PROPERTY_DIMENSIONS.items()}
    loads_any = {"type": "object", "description": "loads of one component in this case (keys depend on its type)",
                 "properties": _load_keys(comps.values())}
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "mechverify design file",
        "type": "object",
        "additionalProperties": False,
        "required": ["design"],
        "properties": {
            "design": {"type": "object", "additionalProperties": False, "required": ["name"],
                       "properties": {k: ({"type": "array", "items": {"type": "string"}} if k == "include"
                                          else {"type": ["string", "integer"]}) for k in DESIGN_KEYS}},
            "parameters": {"type": "object", "description": "named values usable in any expression: quantities "
                           "('3 kg'), numbers, or expressions over other parameters",
                           "propertyNames": {"pattern": "^[A-Za-z][A-Za-z0-9_]*$"},
                           "additionalProperties": {"oneOf": [{"type": "number"}, {"type": "string",
                                                                                  "maxLength": 1000}]}},
            "requirements": _object(REQUIREMENT_FIELDS[:-1], {"safety_factors": {
                "type": "object", "additionalProperties": False,
                "properties": {k: {"type": "number", "exclusiveMinimum": 0, "default": v}
                               for k, v in DEFAULT_SAFETY_FACTORS.items()}}}),
            "materials": {"type": "object", "additionalProperties": {
                "type": "object", "properties": {"base": {"type": "string"}, **material_props}}},
            "templates": {"type": "object", "additionalProperties": {"type": "object"}},
            "profiles": {"type": "object", "additionalProperties": {"oneOf": [_typed(p) for p in profiles.values()]}
                         if profiles else {"type": "object"}},
            "components": {"type": "object", "additionalProperties": {
                "oneOf": [_typed(c) for c in comps.values()] + [{"type": "object", "required": ["extends"]}]}},
            "load_cases": {"type": "object", "additionalProperties": {
                "type": "object", "properties": {"description": {"type": "string"}},
                "additionalProperties": loads_any}},
        },
    }
