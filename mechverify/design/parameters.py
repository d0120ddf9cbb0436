"""Parameters, derived values and connections of a design file (the load path between components).

``[parameters]`` holds named quantities, plain numbers or expressions over other parameters
(:mod:`mechverify.design.expressions`), resolved in dependency order. Any value where a quantity
is expected may be an expression over parameters (evaluated while the file is validated) or over
another component's values, ``"<component>.<name>"``: a load the component is given in the same
load case, or an :class:`~mechverify.design.spec.Output` its type declares. Those connections are
:class:`Deferred` until the components are built, then resolved per load case in dependency order
(:func:`resolve_load_cases`); a cycle is an error that names it. Every derived value is recorded in
:class:`Trace` (key path -> expression, value) for the report and ``mechverify explain``.
"""

from __future__ import annotations

import functools
import keyword
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from mechverify.design.expressions import CONSTANTS, FUNCTIONS, Expression, ExpressionError, check_kind, parse
from mechverify.errors import MechverifyError, suggest
from mechverify.units import DIMENSIONS, Quantity, fmt

AddError = Callable[[str, str], None]


@dataclass(frozen=True)
class Deferred:
    """A value that reads other components (``expr``), resolved after they are built."""

    expr: Expression
    kind: str  # a dimension name, "float" or "int"
    path: str  # key path of the value in the design file
    field_name: str  # the field or load it gives


@dataclass
class Trace:
    """Where each derived value came from: key path -> (expression as written, value)."""

    entries: dict[str, tuple[str, Any]] = field(default_factory=dict)
    edges: dict[str, tuple[str, ...]] = field(default_factory=dict)  # key path -> names it reads
    invalid: set[str] = field(default_factory=set)  # parameters that failed (their error is reported once)

    def add(self, path: str, source: str, value: Any, names: tuple[str, ...] = ()) -> None:
        self.entries[path] = (source, value)
        if names:
            self.edges[path] = names

    def line(self, path: str, label: str | None = None) -> str:
        source, value = self.entries[path]
        return f"{label or path.rsplit('.', 1)[-1]} = {_shown(value)} ← {source}"


def _shown(value: Any) -> str:
    """:func:`show` of a value, remembered for a scalar quantity (a study's variants format the same derived values
    again: the unchanged ones cost pint formatting every sample)."""
    if type(value) is not Quantity or type(value._magnitude) not in (float, int):
        return show(value)
    key = (value._magnitude, value._units)
    text = _SHOWN.get(key)
    if text is None:
        if len(_SHOWN) >= 1024:
            _SHOWN.clear()
        text = _SHOWN[key] = show(value)
    return text


_SHOWN: dict[tuple[Any, Any], str] = {}


def simplify_units(q: Any, kind: str | None = None) -> Any:
    """A quantity whose unit mixes units of one dimension, in fewer units, the same value: ``0.0125 m/s/mm`` ->
    ``12.5 1/s`` (pint's ``to_reduced_units``); of ``kind`` ``"angular_velocity"`` then ``12.5 rad/s``, of
    ``"angle"`` a plain result in rad. Units already reduced (``rev/min``, ``N·m``) stay as written."""
    if not isinstance(q, Quantity) or len(q.units._units) <= 1:
        return q
    r = q.to_reduced_units()
    if len(r.units._units) >= len(q.units._units):
        return q
    if kind == "angular_velocity" and all(_dimensionality(u) == _dimensionality("[time]") for u in r.units._units):
        r = r.to("rad/s")  # 1/s (or 1/min) of an angular speed: rad/s
    elif kind == "angle" and r.unitless:
        r = Quantity(float(r.magnitude), "rad")
    return r


def show(v: Any) -> str:
    if isinstance(v, Quantity):
        if len(v.units._units) > 1:  # kg·m/s² -> N: the SI unit of its kind, when the kind is unambiguous
            kinds = [k for k, (dim, _) in DIMENSIONS.items()
                     if dim and k not in ("torque", "energy", "frequency", "angular_velocity", "torsional_stiffness")
                     and v.dimensionality == _dimensionality(dim)]
            v = v.to(DIMENSIONS[kinds[0]][1]) if len(kinds) == 1 else simplify_units(v)
        m = v.magnitude
        if isinstance(m, int | float) and not isinstance(m, bool):  # fmt's text, the unit's text cached
            text = fmt(Quantity(float(m), "dimensionless"))
            u = _unit_text(v.units)
            return f"{text} {u}" if u else text
        return fmt(v)
    return f"{v:.6g}" if isinstance(v, float) else str(v)


@functools.lru_cache(maxsize=256)
def _unit_text(u: Any) -> str:
    return f"{u:~P}"


@functools.lru_cache(maxsize=64)
def _dimensionality(dim: str) -> Any:
    from mechverify.units import ureg

    return ureg.get_dimensionality(dim)


# --------------------------------------------------------------------------------------------- parameters


def resolve_parameters(table: Any, add: AddError, trace: Trace) -> dict[str, Any]:
    """Validate and evaluate ``[parameters]``; name -> quantity or float. Errors go to ``add(path, msg)``."""
    if table is None:
        return {}
    if not isinstance(table, dict):
        add("parameters", "expected a table of named values, e.g. payload = \"3 kg\"")
        return {}
    exprs: dict[str, Expression] = {}
    values: dict[str, Any] = {}
    for name, v in table.items():
        path = f"parameters.{name}"
        if not name.isidentifier() or keyword.iskeyword(name) or name.startswith("_"):
            add(path, "a parameter name must be a plain identifier (letters, digits, '_'; not starting with '_' "
                      "or a digit)")
        elif name in FUNCTIONS or name in CONSTANTS:
            add(path, f"{name!r} is a built-in function or constant of expressions; choose another name")
        elif isinstance(v, bool) or not isinstance(v, int | float | str):
            add(path, f"expected a quantity (\"3 kg\"), a number or an expression, got {v!r}")
        elif isinstance(v, str):
            try:
                e = parse(v)
            except ExpressionError as exc:
                add(path, str(exc))
                continue
            dotted = sorted(n for n in e.names if "." in n)
            if dotted:
                add(path, f"a parameter may only read other parameters, not component values ({dotted[0]}); "
                          "use the component value where it is needed")
                continue
            exprs[name] = e
        else:
            values[name] = float(v) if isinstance(v, float) else v
    state: dict[str, int] = {}  # 1 visiting, 2 done

    def visit(name: str, stack: list[str]) -> bool:
        if state.get(name) == 2:
            return name in values
        if state.get(name) == 1:
            cyc = stack[stack.index(name):] + [name]
            add("parameters", "cycle " + " -> ".join(cyc))
            return False
        state[name] = 1
        e = exprs[name]
        ok = True
        for n in sorted(e.names):
            if n in values and n not in exprs:
                continue
            if n in table and n not in exprs:  # a parameter with its own error
                add(f"parameters.{name}", f"{e.source!r}: parameter {n!r} is invalid (see parameters.{n})")
                ok = False
            elif n not in exprs:
                known = [k for k in table if k != name]
                hint = suggest(n, known, 1)
                add(f"parameters.{name}", f"unknown name {n!r} in {e.source!r}"
                    + (f"; did you mean {hint[0]!r}?" if hint else f" (parameters: {', '.join(known) or 'none'})"))
                ok = False
            elif not visit(n, [*stack, name]):
                ok = False
        state[name] = 2
        if ok:
            try:
                values[name] = e.evaluate(values)
                if not e.is_constant:
                    trace.add(f"parameters.{name}", e.source, values[name], tuple(sorted(e.names)))
            except ExpressionError as exc:
                add(f"parameters.{name}", str(exc))
                return False
        return ok

    for name in exprs:
        visit(name, [])
    visit = None  # type: ignore[assignment]  # (the recursive closure's cycle: freed now, not by the garbage collector)
    trace.invalid = {k for k in table if k not in values}
    return {k: values[k] for k in table if k in values}


# ------------------------------------------------------------------------------------------- one value


def unknown_name(name: str, params: Mapping[str, Any], components: Mapping[str, Any] | None) -> str:
    """``unknown name 'x'`` with the closest parameter or component, else the parameters there are (and a word
    on units when the name is one: ``2 * g`` multiplies by a parameter g, ``2 g`` is two grams)."""
    hint = suggest(name, list(params) + list(components or {}), 1)
    msg = f"unknown name {name!r}" + (f"; did you mean {hint[0]!r}?" if hint else
                                      f" (parameters: {', '.join(params) or 'none'})")
    from mechverify.units import ureg

    try:
        ureg.parse_units(name)
    except Exception:
        return msg
    return msg + f"; a unit is written right after its number (\"2 {name}\"), not multiplied"


def value_or_deferred(text: str, kind: str, path: str, field_name: str, ctx: Mapping[str, Any]) -> Any:
    """An expression string of a quantity field: its value when it reads only parameters, a :class:`Deferred`
    when it reads component values, an :class:`ExpressionError` (raised) otherwise."""
    e = parse(text)
    params = ctx.get("parameters", {})
    comps = ctx.get("component_names") or {}
    if len(e.names) == 1 and e.source == next(iter(e.names)) and e.source in comps and e.source not in params:
        e = parse(f"{e.source}.{field_name}")  # shorthand: the same value of the component named
    for n in sorted(e.names):
        if "." in n:
            comp = n.split(".", 1)[0]
            if comp not in comps:
                hint = suggest(comp, comps, 1)
                raise ExpressionError(f"{e.source!r}: no component {comp!r}"
                                      + (f"; did you mean {hint[0]!r}?" if hint else ""))
        elif n not in params:
            if n in ctx["trace"].invalid:
                raise ExpressionError(f"{e.source!r}: parameter {n!r} is invalid (see parameters.{n})")
            legacy = _plain_quantity(text, kind, e, params, comps)
            if legacy is not None:
                return legacy
            raise ExpressionError(f"{e.source!r}: " + unknown_name(n, params, comps))
    if any("." in n for n in e.names):
        return Deferred(e, kind, path, field_name)
    v = e.evaluate(params)
    v = _as_kind(v, kind, e.source, len(e._code) > 1)
    ctx["trace"].add(path, e.source, v, tuple(sorted(e.names)))
    return v


def _plain_quantity(text: str, kind: str, e: Expression, params: Mapping[str, Any], comps: Any) -> Any:
    """``"5 N * m"``, ``"450 * mm"``: read as before parameters existed (the quantity parser), when no name of
    the text is a parameter or a component value; ``None`` otherwise or when that reading fails."""
    if kind not in DIMENSIONS or any("." in n or n in params or n in comps for n in e.names):
        return None
    from mechverify.units import as_quantity

    try:
        return as_quantity(text, kind, "value")
    except MechverifyError:
        return None


def _as_kind(v: Any, kind: str, source: str, computed: bool = True) -> Any:
    if kind in DIMENSIONS:
        q = simplify_units(check_kind(v, kind, source), kind)
        if computed and len(q.units._units) > 1 and kind not in ("angle", "angular_velocity", "dimensionless"):
            q = q.to(DIMENSIONS[kind][1])  # N·s²/m -> kg: a computed value in the SI unit of its kind
        return q
    q = v if isinstance(v, Quantity) else None
    if q is not None:
        if not q.dimensionless:
            raise ExpressionError(f"{source!r} gives {q.units:~P}, expected a plain number")
        v = float(q.to("dimensionless").magnitude)
    if kind == "int":
        if not float(v).is_integer():
            raise ExpressionError(f"{source!r} gives {v:g}, expected an integer")
        return int(v)
    return float(v)


def substitute(v: Any, path: str, ctx: Mapping[str, Any], skip: tuple[str, ...] = ()) -> Any:
    """Inside inline tables and lists: strings that are expressions over parameters only become the value's text
    (``format_value``), so the adapters read them as before. Names (``type``, ``at`` ...) stay as written."""
    from mechverify.design.expressions import format_value, is_expression

    params = ctx.get("parameters") or {}
    if not params:
        return v
    if isinstance(v, dict):
        return {k: (x if k in skip else substitute(x, f"{path}.{k}", ctx, skip)) for k, x in v.items()}
    if isinstance(v, list):
        return [substitute(x, f"{path}[{i}]", ctx, skip) for i, x in enumerate(v)]
    if is_expression(v):
        e = parse(v)
        if e.names <= set(params):
            val = e.evaluate(params)
            ctx["trace"].add(path, e.source, val, tuple(sorted(e.names)))
            return format_value(val)
    elif isinstance(v, str) and "," in v:  # a vector "fx, fy, fz" whose components use parameters ("0, 0, -P")
        parts = _top_level_split(v)
        exprs = [parse(x) if is_expression(x) else None for x in parts]
        if any(exprs) and all(e is None or e.names <= set(params) for e in exprs):
            vals = [x.strip() if e is None else format_value(e.evaluate(params)) for x, e in zip(parts, exprs)]
            names = tuple(sorted(set().union(*(e.names for e in exprs if e is not None))))
            ctx["trace"].add(path, v, ", ".join(vals), names)
            return ", ".join(vals)
    return v


def _top_level_split(text: str) -> list[str]:
    """``text`` split at the commas outside brackets (``"0, max(P, Q), 0"`` -> three parts)."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += (ch in "([") - (ch in ")]")
        if ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    return [*parts, text[start:]]


# ---------------------------------------------------------------------------------- per-case connections


class _Resolver:
    """Resolve the deferred loads of one load case in dependency order."""

    def __init__(self, case: str, loads: dict[str, dict[str, Any]], entries: Mapping[str, Any],
                 params: Mapping[str, Any], add: AddError, trace: Trace):
        self.case, self.loads, self.entries, self.params = case, loads, entries, params
        self.add, self.trace = add, trace
        self.visiting: list[str] = []
        self.failed: set[str] = set()
        self.outputs: dict[str, Any] = {}

    def load(self, comp: str, name: str) -> Any:
        v = self.loads[comp][name]
        if not isinstance(v, Deferred):
            return v
        key = f"{comp}.{name}"
        if key in self.failed:
            raise _Failed
        if key in self.visiting:
            cyc = self.visiting[self.visiting.index(key):] + [key]
            self.add(f"load_cases.{self.case}", "cycle " + " -> ".join(cyc))
            self.failed.update(cyc)
            raise _Failed
        self.visiting.append(key)
        try:
            env = dict(self.params)
            for n in v.expr.names:
                if "." in n:
                    env[n] = self.value(n, v)
            out = v.expr.evaluate(env)
            out = _as_kind(out, v.kind, v.expr.source, len(v.expr._code) > 1)
        except ExpressionError as exc:
            self.failed.add(key)
            self.add(v.path, str(exc))
            raise _Failed from None
        finally:
            self.visiting.pop()
        self.loads[comp][name] = out
        self.trace.add(v.path, v.expr.source, out, tuple(sorted(v.expr.names)))
        return out

    def value(self, ref: str, by: Deferred) -> Any:
        comp, name = ref.split(".", 1)
        entry = self.entries.get(comp)
        if entry is None:
            hint = suggest(comp, self.entries, 1)
            raise ExpressionError(f"{by.expr.source!r}: no component {comp!r}" +
                                  (f"; did you mean {hint[0]!r}?" if hint else ""))
        given = self.loads.get(comp, {})
        if name in given:
            return self.load(comp, name)
        out = entry.type.output(name)
        if out is None:
            load_names = [f.name for f in entry.type.loads]
            if name in load_names:
                raise ExpressionError(f"{by.expr.source!r}: {comp} is given no {name} in load case {self.case!r}")
            names = [o.name for o in entry.type.outputs] + load_names
            hint = suggest(name, names, 1)
            raise ExpressionError(f"{by.expr.source!r}: {comp} ({entry.type.name}) has no value {name!r}"
                                  + (f"; did you mean {hint[0]!r}?" if hint else
                                     f" (outputs: {', '.join(o.name for o in entry.type.outputs) or 'none'}; "
                                     f"loads: {', '.join(load_names) or 'none'})"))
        if ref in self.outputs:
            return self.outputs[ref]
        if entry.obj is None:
            raise ExpressionError(f"{by.expr.source!r}: {comp} is invalid (see its own errors)")
        loads = None
        if comp in self.loads:
            loads = {k: self.load(comp, k) for k in list(given)}
        missing = [n for n in out.needs if loads is None or not any(a in loads for a in n.split("|"))]
        if missing:
            raise ExpressionError(f"{by.expr.source!r}: {comp}.{name} needs {', '.join(missing)} of {comp} in "
                                  f"load case {self.case!r}")
        try:
            val = check_kind(out.fn(entry.obj, loads), out.kind, ref)
        except MechverifyError as exc:
            raise ExpressionError(f"{by.expr.source!r}: {ref}: {exc}") from None
        self.outputs[ref] = val
        self.trace.add(f"outputs.{self.case}.{ref}", f"output {out.name} of {comp} ({entry.type.name})", val,
                       tuple(f"{comp}.{a}" for n in out.needs for a in n.split("|") if a in (loads or {})))
        return val


class _Failed(Exception):
    pass


def resolve_load_cases(load_cases: dict[str, dict[str, dict[str, Any]]], entries: Mapping[str, Any],
                       params: Mapping[str, Any], add: AddError, trace: Trace) -> None:
    """Replace every :class:`Deferred` load by its value, case by case, in dependency order (in place)."""
    for case, loads in load_cases.items():
        r = _Resolver(case, loads, entries, params, add, trace)
        for comp in list(loads):
            for name in list(loads[comp]):
                try:
                    r.load(comp, name)
                except _Failed:
                    pass


def resolve_fields(entry: Any, entries: Mapping[str, Any], params: Mapping[str, Any], build: Callable[[Any], bool],
                   add: AddError, trace: Trace) -> bool:
    """Evaluate an entry's deferred fields (outputs of other components that need no load case); False on error."""
    ok = True
    for fname, v in list(entry.params.items()):
        if not isinstance(v, Deferred):
            continue
        env = dict(params)
        try:
            for n in v.expr.names:
                if "." not in n:
                    continue
                comp, name = n.split(".", 1)
                other = entries[comp]
                out = other.type.output(name)
                if out is None:
                    names = [o.name for o in other.type.outputs]
                    hint = suggest(name, names, 1)
                    raise ExpressionError(f"{v.expr.source!r}: {comp} ({other.type.name}) offers no value {name!r}"
                                          + (f"; did you mean {hint[0]!r}?" if hint else
                                             f" (outputs: {', '.join(names) or 'none'})"))
                if out.needs:
                    raise ExpressionError(f"{v.expr.source!r}: {n} depends on {comp}'s loads "
                                          f"({', '.join(out.needs)}): use it in a load case, not a component field")
                if not build(other):
                    raise ExpressionError(f"{v.expr.source!r}: {comp} is invalid or in a cycle (see its errors)")
                try:
                    env[n] = check_kind(out.fn(other.obj, None), out.kind, n)
                except MechverifyError as exc:
                    raise ExpressionError(f"{v.expr.source!r}: {n}: {exc}") from None
            val = _as_kind(v.expr.evaluate(env), v.kind, v.expr.source, len(v.expr._code) > 1)
        except ExpressionError as exc:
            add(v.path, str(exc))
            ok = False
            continue
        entry.params[fname] = val
        trace.add(v.path, v.expr.source, val, tuple(sorted(v.expr.names)))
    return ok


# ---------------------------------------------------------------------------------------------- reports


def parameters_report(design: Any) -> str:
    """Plain text: the parameters with their values and expressions, and the dependency graph of derived values.

    ``design`` is a :class:`~mechverify.design.Design` (or its ``data``). Used by ``mechverify explain`` and the
    report appendix.
    """
    data = getattr(design, "data", design)
    params: Mapping[str, Any] = getattr(data, "parameters", {}) or {}
    trace: Trace = getattr(data, "trace", None) or Trace()
    lines = []
    if params:
        lines.append("Parameters:")
        w = max(len(k) for k in params)
        for k, v in params.items():
            src = trace.entries.get(f"parameters.{k}")
            lines.append(f"  {k:<{w}} = {show(v)}" + (f"  ← {src[0]}" if src else ""))
    derived = [(p, s, v) for p, (s, v) in trace.entries.items() if not p.startswith("parameters.")]
    if derived:
        lines.append("Derived values (key path = value ← expression):")
        for p, s, v in derived:
            lines.append(f"  {p} = {show(v)} ← {s}")
    graph = dependency_graph(data)
    if graph:
        lines.append("Dependency graph (value <- what it reads):")
        for k, reads in graph.items():
            lines.append(f"  {k} <- {', '.join(reads)}")
    return "\n".join(lines) if lines else "No parameters and no derived values."


def dependency_graph(design: Any) -> dict[str, tuple[str, ...]]:
    """Key path of each derived value -> the names its expression reads (parameters, ``component.value``)."""
    data = getattr(design, "data", design)
    trace: Trace | None = getattr(data, "trace", None)
    return dict(trace.edges) if trace else {}
