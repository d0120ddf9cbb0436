"""What a study varies: key paths into a design file's data, and the values they take.

A *parameter* is a key path of the design file (``components.lift.mass``,
``components.lift.transmission[0].mu``, ``load_cases.raise.lift_screw.axial_force``,
``parameters.payload``) whose value in the file is a quantity string (``"35.68 kg"``) or a number.
Values are held as plain floats in the unit the file writes (kg above) and written back as
``"<value> <unit>"`` strings. Axes: a sweep ``START:STOP:N`` (``N`` evenly spaced values, both ends
included) or a distribution ``normal:MEAN:SD``, ``uniform:LO:HI``, ``triangular:LO:MODE:HI``.
A bare number in a spec takes the unit of the file's value; a number with a unit must have the
same dimension (``UnitError`` otherwise). For a value written as an expression (``"lifted_load / g"``)
the file writes no unit: bare numbers are refused there (``InputError``), give a unit.
"""

from __future__ import annotations

import copy
import math
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError, MechverifyError, UnitError, UnknownNameError
from mechverify.units import Q, Quantity, rate_to

_STEP = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def split_path(path: str) -> list[str | int]:
    """``"a.b[0].c"`` -> ``["a", "b", 0, "c"]``."""
    if not isinstance(path, str) or not path.strip():
        raise InputError(f"parameter: expected a key path such as 'components.lift.mass', got {path!r}")
    out: list[str | int] = []
    pos = 0
    text = path.strip()
    while pos < len(text):
        if text[pos] == "." and out:
            pos += 1
        m = _STEP.match(text, pos)
        if not m:
            raise InputError(f"parameter {path!r}: not a key path (names joined by '.', list items as [i])")
        out.append(m.group(1) if m.group(1) is not None else int(m.group(2)))
        pos = m.end()
    return out


def _paths_under(node: Any, prefix: str) -> Iterable[str]:
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _paths_under(v, f"{prefix}.{k}" if prefix else str(k))
    elif isinstance(node, list) and any(isinstance(x, dict) for x in node):
        for i, v in enumerate(node):
            yield from _paths_under(v, f"{prefix}[{i}]")
    else:
        yield prefix


def _unknown(path: str, doc: Mapping[str, Any]) -> UnknownNameError:
    return UnknownNameError("parameter (no such key in the design file)", path, list(_paths_under(doc, "")))


def _template_of(doc: Mapping[str, Any], steps: list[str | int]) -> dict[str, Any] | None:
    """A component's template table (``extends``) when ``steps`` is components.<name>.<key>."""
    if len(steps) == 3 and steps[0] == "components":
        comp = doc.get("components", {}).get(steps[1])
        if isinstance(comp, dict) and isinstance(comp.get("extends"), str):
            t = doc.get("templates", {}).get(comp["extends"])
            return t if isinstance(t, dict) else None
    return None


def _type_default(doc: Mapping[str, Any], steps: list[str | int]) -> tuple[bool | None, Any]:
    """For components.<name>.<key> that the file does not write: (whether the component's type declares the key,
    its default ``Field.default`` or None); (None, None) when that is not known (another path, an unknown type)."""
    if len(steps) != 3 or steps[0] != "components" or not isinstance(steps[2], str):
        return None, None
    comp = doc.get("components", {}).get(steps[1])
    if not isinstance(comp, dict):
        return None, None
    kind = comp.get("type")
    if kind is None and isinstance(comp.get("extends"), str):
        kind = (doc.get("templates", {}).get(comp["extends"]) or {}).get("type")
    from mechverify.design import adapters  # noqa: F401  (registers the component types)
    from mechverify.design.spec import REGISTRY

    ct = REGISTRY.types.get(kind) if isinstance(kind, str) else None
    if ct is None:
        return None, None
    field = next((f for f in ct.fields if f.name == steps[2]), None)
    return field is not None, None if field is None else field.default


_TEXT_KINDS = ("str", "material", "choice", "ref", "bool")


def _field_of(doc: Mapping[str, Any], steps: list[str | int]) -> Any:
    """The :class:`~mechverify.design.spec.Field` declared for ``components.<name>.<key>`` or
    ``load_cases.<case>.<name>.<key>`` by the component's type; None when not known (another path, an unknown type)."""
    if len(steps) == 3 and steps[0] == "components":
        name, key, group = steps[1], steps[2], "fields"
    elif len(steps) == 4 and steps[0] == "load_cases":
        name, key, group = steps[2], steps[3], "loads"
    else:
        return None
    comp = (doc.get("components") or {}).get(name) if isinstance(doc.get("components"), dict) else None
    if not isinstance(comp, dict) or not isinstance(key, str):
        return None
    kind = comp.get("type")
    if kind is None and isinstance(comp.get("extends"), str):
        kind = ((doc.get("templates") or {}).get(comp["extends"]) or {}).get("type")
    from mechverify.design import adapters  # noqa: F401  (registers the component types)
    from mechverify.design.spec import REGISTRY

    ct = REGISTRY.types.get(kind) if isinstance(kind, str) else None
    if ct is None:
        return None
    return next((f for f in getattr(ct, group, ()) if f.name == key), None)


def _is_quantity(text: str) -> bool:
    try:
        Q(text)
    except MechverifyError:
        return False
    return True


def _is_measure(text: str) -> bool:
    """A number with a unit of some dimension (``"1 mm"``): what a text field that also takes a quantity holds when it
    holds one (``deflection_limit = "1 mm"`` or ``"L/250"``); ``"608"`` (dimensionless) and ``"circle"`` are not."""
    if not any(c.isdigit() for c in text):
        return False
    try:
        q = Q(text)
    except MechverifyError:
        return False
    return isinstance(q, Quantity) and not q.dimensionless


def _refuse_text(path: str, raw: Any, field: Any, resolved: Any = None) -> None:
    """Refuse a value a study cannot vary as one number, before any sample runs: a vector or list written as text
    (``force = "10000, 0, 0"``: pint reads it as 0), a key whose type declares text (``section = "circle"``: pint
    reads it as 1 turn; a bearing ``model = "608"``), or a name with no digit (a parameter ``"steel"``)."""
    if not isinstance(raw, str):
        return
    if "," in raw:
        raise InputError(f"{path} is a vector ({raw!r}): a study varies one number; vary a parameter used in it "
                         "(e.g. force = \"P, 0, 0\" with [parameters] P = \"10 kN\", then --vary parameters.P=...)")
    if field is not None and field.kind in _TEXT_KINDS and not _is_measure(raw):
        raise InputError(f"{path} is a text field ({raw!r}): a study varies numbers only")
    if field is None and not any(c.isdigit() for c in raw) and _is_quantity(raw) and not (
            resolved is not None and isinstance(resolved(path), Quantity)):  # not an expression ("payload + m")
        raise InputError(f"{path}: its value {raw!r} is text, not a number: a study varies numbers only")


#: ``"L/250"``, ``"span/250"``: a limit written as a fraction of the span (checks.members' form of it)
_SPAN_FRACTION = re.compile(r"^\s*(?:l|L|span)\s*/\s*([0-9.]+)\s*$")


def _refuse_span_fraction(doc: Mapping[str, Any], path: str, raw: Any) -> None:
    """Refuse a key written as a fraction of the span (``deflection_limit = "L/250"``), naming the way to vary it:
    pint reads "L/250" as a litre / 250 (a volume, review 4 finding 7), and a sample's number would replace it by a
    length or a bare number the key reads otherwise. The type's numeric ``<key>_fraction`` when it has one."""
    m = _SPAN_FRACTION.match(raw) if isinstance(raw, str) else None
    steps = split_path(path)
    if m is None or _field_of(doc, steps) is None or not isinstance(steps[-1], str):
        return
    try:
        frac = 1.0 / float(m.group(1))
    except (ValueError, ZeroDivisionError):
        return
    key = steps[-1]
    table = path.rsplit(".", 1)[0]
    if _field_of(doc, [*steps[:-1], f"{key}_fraction"]) is not None:
        how = (f"write {key}_fraction = {frac:.6g} in its place (the same limit) and vary "
               f"{table}.{key}_fraction (e.g. {frac / 2:.6g}:{frac * 2:.6g}:5)")
    else:
        how = f"write the limit as a length in the file ({key} = \"2 mm\") and vary that"
    raise InputError(f"{path} is written {raw!r}, a fraction of the span: a study varies numbers only; {how}")


def _not_written(path: str, doc: Mapping[str, Any], steps: list[str | int], table: Mapping[str, Any]) -> InputError:
    """A key the file does not write in a table that exists: it may be a key whose default is not one number (a
    screw stage's mu: the nut material's friction range, both ends checked), so it cannot be varied as is."""
    key = steps[-1]
    where = path[: len(path) - len(str(key)) - 1]
    hint = [k for k in table if isinstance(k, str)]
    return InputError(f"parameter {path!r}: the design file does not write {key!r} in {where} (keys there: "
                      f"{', '.join(hint) or 'none'}). A key the file leaves to its default can be varied when the "
                      "component type gives one number as the default; otherwise (a screw stage's mu defaults to "
                      "the nut material's friction range, both ends checked) write the key into the file with "
                      f"today's value ({key} = ...) and vary that")


def get_path(doc: Mapping[str, Any], path: str, defaults: bool = False) -> Any:
    """The value at ``path`` (a component's template value when the component does not set it). With
    ``defaults``, a component key the file does not write gives its type's default (a number or a quantity
    string), and a key missing from an existing table is an :class:`InputError` that says how to vary it."""
    steps = split_path(path)
    node: Any = doc
    for i, s in enumerate(steps):
        if isinstance(s, int):
            if not isinstance(node, list) or not 0 <= s < len(node):
                raise _unknown(path, doc)
            node = node[s]
        else:
            if not isinstance(node, dict):
                raise _unknown(path, doc)
            if s not in node:
                last = i == len(steps) - 1
                tpl = _template_of(doc, steps) if last else None
                if tpl is not None and s in tpl:
                    return tpl[s]
                if defaults and last and i >= 2:
                    known, d = _type_default(doc, steps)
                    if known and isinstance(d, int | float | str) and not isinstance(d, bool):
                        return d
                    if known or (known is None and not _near(s, node)):
                        raise _not_written(path, doc, steps, node)
                raise _unknown(path, doc)
            node = node[s]
    return node


def _near(key: str, table: Mapping[str, Any]) -> list[str]:
    from mechverify.errors import suggest

    return list(suggest(key, [k for k in table if isinstance(k, str)], 1))


def unwritten_stage_mu(doc: Mapping[str, Any], path: str) -> str | None:
    """The lead screw's name when ``path`` is ``components.<drive>.transmission[i].mu`` of a screw stage that does not
    write ``mu`` (its friction is then the nut's range, both ends checked); else None."""
    try:
        steps = split_path(path)
    except InputError:
        return None
    if len(steps) != 5 or steps[0] != "components" or steps[2] != "transmission" or steps[4] != "mu":
        return None
    comp = (doc.get("components") or {}).get(steps[1])
    stages = comp.get("transmission") if isinstance(comp, dict) else None
    i = steps[3]
    if not (isinstance(stages, list) and isinstance(i, int) and 0 <= i < len(stages)):
        return None
    stage = stages[i]
    if not isinstance(stage, dict) or stage.get("type") != "screw" or "mu" in stage:
        return None
    screw = stage.get("screw")
    return screw if isinstance(screw, str) else None


def set_path(doc: dict[str, Any], path: str, value: Any) -> None:
    """Set ``path`` in ``doc`` in place (the key must exist, come from the component's template, be a key of
    the component's type with a default, or be a screw stage's ``mu`` left to the nut's friction range)."""
    steps = split_path(path)
    if unwritten_stage_mu(doc, path) is None:
        get_path(doc, path, defaults=True)  # raises for an unknown path
    node: Any = doc
    for s in steps[:-1]:
        node = node[s]
    node[steps[-1]] = value


def apply_overrides(doc: Mapping[str, Any], overrides: Mapping[str, Any]) -> dict[str, Any]:
    """A deep copy of ``doc`` with each key path set to its value."""
    out = copy.deepcopy(dict(doc))
    for path, value in overrides.items():
        set_path(out, path, value)
    return out


# ============================================================================ parameters


@dataclass(frozen=True)
class Parameter:
    """A numeric value of the design file: its key path, the file's value and unit ('' for a bare number)."""

    path: str
    base: float
    unit: str
    integer: bool = False
    #: the file's expression when the value is written as one (``"144 N*m / lifted_load"``); its ``unit`` is
    #: then mechverify's unit for the result's dimension, which the file never wrote: bare numbers are refused
    expression: str = ""
    #: (lo, hi, where) of a value the file leaves to a range checked at both ends (a screw stage's ``mu``: the nut's
    #: friction range); ``base`` is then ``hi``, and a study's values are checked against the range
    default_range: tuple[float, float, str] | None = None

    @classmethod
    def of(cls, doc: Mapping[str, Any], path: str, resolved: Any = None) -> Parameter:
        """The parameter at ``path``. A value written as an expression (``"lifted_load / g"``) takes its
        resolved value from ``resolved(path)`` (a quantity or None); varying it replaces the expression. A screw
        stage's ``mu`` the file does not write takes the nut's friction range from ``resolved(path)``."""
        screw = unwritten_stage_mu(doc, path)
        if screw is not None and resolved is not None:
            rng = resolved(path)
            if isinstance(rng, tuple) and len(rng) == 2:
                lo, hi = (float(x) for x in rng)
                return cls(path, hi, "", default_range=(lo, hi, f"the nut friction range of lead screw {screw!r}"))
        raw = get_path(doc, path, defaults=True)
        _refuse_span_fraction(doc, path, raw)
        _refuse_text(path, raw, _field_of(doc, split_path(path)), resolved)
        if isinstance(raw, str) and resolved is not None:
            try:
                Q(raw)
            except MechverifyError:
                q = resolved(path)
                if isinstance(q, Quantity) and isinstance(q.magnitude, int | float):
                    unit = _si_unit(q)
                    return cls(path, float(rate_to(q, unit).magnitude), unit, expression=raw)
        if isinstance(raw, bool) or not isinstance(raw, int | float | str):
            raise InputError(f"parameter {path!r}: its value {raw!r} is not numeric; only numbers and quantities "
                             "(a number with a unit, e.g. \"35 kg\") can be varied")
        if isinstance(raw, int | float):
            return cls(path, float(raw), "", isinstance(raw, int))
        try:
            q = Q(raw)
        except MechverifyError:
            raise InputError(f"parameter {path!r}: its value {raw!r} is not numeric; only numbers and quantities "
                             "(a number with a unit, e.g. \"35 kg\") can be varied") from None
        if not isinstance(q.magnitude, int | float) or isinstance(q.magnitude, bool):
            raise InputError(f"parameter {path!r}: its value {raw!r} is not a single number")
        unit = _written_unit(raw, q) or _unit_text(q)
        return cls(path, float(q.magnitude), unit)

    @property
    def offset(self) -> bool:
        """Whether the file's unit is an offset one (degC, degF): its readings are not proportional to the quantity,
        so ranges around today's value are taken as differences (sizing's default bounds, explore's sliders)."""
        if not self.unit:
            return False
        try:
            return not Q(1.0, self.unit)._is_multiplicative
        except Exception:  # (not a pint unit)
            return False

    def value(self, token: str | float | int) -> float:
        """A spec value (``"20 kg"``, ``20``) as a float in this parameter's unit."""
        if isinstance(token, bool):
            raise InputError(f"{self.path}: expected a number, got {token!r}")
        if isinstance(token, int | float):
            return self._bare(float(token), token)
        if isinstance(token, Quantity):
            q = token
        else:
            text = str(token).strip()
            try:
                x = float(text)
            except ValueError:
                pass
            else:
                return self._bare(x, token)
            try:
                q = Q(text)
            except MechverifyError:
                raise InputError(f"{self.path}: cannot read {text!r} as a number or a quantity") from None
        target = Q(1.0, self.unit) if self.unit else Q(1.0)
        if q.dimensionality != target.dimensionality:
            have, want = dimension_name(q), dimension_name(target)
            base = f"{self.base:.6g} {self.unit}".strip()
            raise UnitError(f"{self.path}: {token!s} is {have} but the design file's value ({base}) is {want}; "
                            "a range cannot change a quantity's dimension")
        return float(rate_to(q, target.units).magnitude)  # (a revolution is 2 pi rad: 9 Hz = 540 rpm, not pint's 86)

    def difference(self, token: str | float | int) -> float:
        """A spec value that is a difference of two values (a normal's standard deviation) in this parameter's unit:
        an offset unit's zero is not counted (a spread of ``"5 K"`` for a value in degC is 5 degC, not -268.15;
        ``"5 degC"`` for a value in K is 5 K, not 278.15)."""
        x = self.value(token)
        if isinstance(token, int | float):
            return x
        q = token
        if not isinstance(q, Quantity):
            text = str(token).strip()
            try:
                float(text)
            except ValueError:
                q = Q(text)  # (value() read it already)
            else:
                return x
        if not isinstance(q, Quantity):
            return x
        return x - self.value(Quantity(0.0, q.units))

    def _bare(self, x: float, token: Any) -> float:
        """A bare number: in the file's unit; refused for a value written as an expression (no unit was written)."""
        if self.expression and self.unit:
            raise InputError(f"{self.path}: the bare number {token!s} has no unit, and the design file writes this "
                             f"value as an expression ({self.expression!r} = {self.base:.6g} {self.unit}); give the "
                             f"unit with every number, e.g. '{_example(self.base)} {self.unit}' or in any unit of "
                             "the same dimension")
        return x

    def text(self, x: float) -> str | float | int:
        """The design-file value for ``x``: ``"21.5 kg"``, a number, or an integer."""
        if self.integer:
            return int(round(x))
        if not self.unit:
            return float(x)
        return f"{float(x)!r} {self.unit}"


def dimension_name(q: Any) -> str:
    """mechverify's name for q's dimension, with its article ("a force", "a torque, energy or torsional
    stiffness", "dimensionless");
    pint's ``[mass] * [length] / [time] ** 2`` only for a dimension mechverify has no name for."""
    from mechverify.units import DIMENSIONS, ureg

    if q.dimensionless:
        return "dimensionless"
    names = [n.replace("_", " ") for n, (dim, _) in DIMENSIONS.items()
             if dim and ureg.get_dimensionality(dim) == q.dimensionality]
    if not names:
        return str(q.dimensionality)
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]
    return ("an " if names[0][0] in "aeiou" else "a ") + listed


def _example(x: float) -> str:
    return f"{x:.3g}"


def _si_unit(q: Any) -> str:
    """The unit mechverify uses for q's dimension ("kg" for N·s²/m), else its SI base units."""
    from mechverify.units import DIMENSIONS, rate_kind, ureg

    if rate_kind(q.units) == "cycles":  # (a frequency: rad/s, the first unit of 1/[time], would be 2 pi off)
        return "Hz"
    for dim, unit in DIMENSIONS.values():
        if dim and unit and ureg.get_dimensionality(dim) == q.dimensionality:
            return unit
    return _unit_text(q.to_base_units())


def resolver(design: Any) -> Any:
    """``path -> resolved value`` of a loaded design (parameters, component fields, load-case values)."""
    def get(path: str) -> Any:
        steps = split_path(path)
        data = design.data
        try:
            if steps[0] == "parameters" and len(steps) == 2:
                return design.parameters.get(steps[1])
            if steps[0] in ("components", "profiles") and len(steps) == 3:
                return getattr(data, steps[0])[steps[1]].params.get(steps[2])
            if steps[0] == "load_cases" and len(steps) == 4:
                return data.load_cases[steps[1]][steps[2]].get(steps[3])
            screw = unwritten_stage_mu(data.raw, path)
            if screw is not None:  # the nut's friction range (mu_min, mu_max)
                obj = data.components[screw].obj
                return None if obj is None else obj.nut.require_mu()
        except (KeyError, AttributeError, TypeError, MechverifyError):
            return None
        return None
    return get


_NUMBER_THEN_UNIT = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*(\S.*?)\s*$")


def _written_unit(raw: str, q: Any) -> str:
    """The unit as the file writes it (``m/s^2`` of ``"0.1 m/s^2"``), when it reads back as q's unit; else ''."""
    m = _NUMBER_THEN_UNIT.match(raw)
    if not m:
        return ""
    try:
        return m.group(1) if Q(1.0, m.group(1)).units == q.units else ""
    except Exception:  # (pint raises several types)
        return ""


def _unit_text(q: Any) -> str:
    """A unit string that reads back to the same unit ("kg", "N*m", "mN*m")."""
    for spec in ("~C", "C"):
        s = format(q.units, spec)
        try:
            if Q(1.0, s).units == q.units:
                return s
        except Exception:  # (pint raises several types)
            continue
    return str(q.units)


# ============================================================================ axes


@dataclass(frozen=True)
class Axis:
    """One varied parameter: ``kind`` "sweep" (values) or a distribution ("normal", "uniform", "triangular")."""

    param: Parameter
    kind: str
    args: tuple[float, ...]
    spec: str

    @property
    def name(self) -> str:
        return self.param.path

    @property
    def is_sweep(self) -> bool:
        return self.kind == "sweep"

    def sweep_values(self) -> np.ndarray:
        start, stop, n = self.args
        return np.linspace(start, stop, int(n))

    def ppf(self, u: np.ndarray) -> np.ndarray:
        """Values at the cumulative probabilities ``u`` (inverse transform of uniform samples)."""
        from scipy import stats

        u = np.clip(np.asarray(u, float), 1e-12, 1 - 1e-12)
        if self.kind == "normal":
            mean, sd = self.args
            return stats.norm.ppf(u, loc=mean, scale=sd)
        if self.kind == "uniform":
            lo, hi = self.args
            return lo + (hi - lo) * u
        lo, mode, hi = self.args
        return stats.triang.ppf(u, (mode - lo) / (hi - lo), loc=lo, scale=hi - lo)

    def to_dict(self) -> dict[str, Any]:
        return {"name": self.name, "kind": self.kind, "args": list(self.args), "unit": self.param.unit,
                "spec": self.spec, "base": self.param.base}


_ARITY = {"normal": 2, "uniform": 2, "triangular": 3}


def parse_axis(doc: Mapping[str, Any], name: str, spec: Any, resolved: Any = None) -> Axis:
    """``spec``: ``"START:STOP:N"``, ``"normal:MEAN:SD"``, ``"uniform:LO:HI"``, ``"triangular:LO:MODE:HI"``."""
    p = Parameter.of(doc, name, resolved)
    if not isinstance(spec, str):
        raise InputError(f"{name}: expected a spec string such as '20 kg:60 kg:5' or 'normal:35 kg:1 kg', "
                         f"got {spec!r}")
    parts = [s.strip() for s in spec.split(":")]
    head = parts[0].lower()
    if head == "uniform" and len(parts) == 1 and p.default_range is not None:  # over the range the file leaves
        lo, hi, _ = p.default_range
        if not lo < hi:
            raise InputError(f"{name}: 'uniform': {p.default_range[2]} is the single value {lo:g}; nothing to vary")
        return Axis(p, "uniform", (lo, hi), spec)
    axis = _parse_axis(p, name, spec, parts, head)
    if p.default_range is not None:
        _check_range(axis)
    return axis


class OutsideRangeWarning(UserWarning):
    """A study's values of an input go outside the published range the design's default takes it from."""


def _check_range(axis: Axis) -> None:
    """Warn when the axis's values leave the default range (a screw stage's mu outside the nut's friction range)."""
    import warnings

    lo, hi, where = axis.param.default_range or (0.0, 0.0, "")
    if axis.kind == "sweep":
        a, b, what = min(axis.args[:2]), max(axis.args[:2]), "the sweep"
    elif axis.kind == "normal":
        a, b, what = axis.args[0] - 3 * axis.args[1], axis.args[0] + 3 * axis.args[1], "mean ± 3 SD"
    else:
        a, b, what = axis.args[0], axis.args[-1], "the distribution"
    if a < lo or b > hi:
        warnings.warn(f"{axis.name}: {what} spans {a:.4g}..{b:.4g}, outside {where}, {lo:g}..{hi:g} (the values "
                      "mechverify checks when the file writes no mu); is the wider range published for this pairing?",
                      OutsideRangeWarning, stacklevel=4)


def _parse_axis(p: Parameter, name: str, spec: str, parts: list[str], head: str) -> Axis:
    if head in _ARITY:
        if len(parts) != _ARITY[head] + 1:
            form = {"normal": "normal:MEAN:SD", "uniform": "uniform:LO:HI", "triangular": "triangular:LO:MODE:HI"}
            raise InputError(f"{name}: {spec!r}: expected {form[head]}")
        vals = tuple(p.difference(x) if head == "normal" and k == 1 else p.value(x) for k, x in enumerate(parts[1:]))
        if not all(math.isfinite(v) for v in vals):
            raise InputError(f"{name}: {spec!r}: values must be finite")
        if head == "normal" and not vals[1] > 0:
            raise InputError(f"{name}: {spec!r}: the standard deviation must be > 0")
        if head == "uniform" and not vals[0] < vals[1]:
            raise InputError(f"{name}: {spec!r}: LO must be below HI")
        if head == "triangular" and not (vals[0] < vals[2] and vals[0] <= vals[1] <= vals[2]):
            raise InputError(f"{name}: {spec!r}: expected LO <= MODE <= HI with LO < HI")
        return Axis(p, head, vals, spec)
    if len(parts) > 1 and parts[0] and not any(c.isdigit() for c in parts[0]):  # a word where a start value goes
        from mechverify.errors import suggest

        near = list(suggest(head, list(_ARITY), 1))
        hint = f"; did you mean {near[0]!r}?" if near else ""
        raise InputError(f"{name}: {spec!r}: unknown distribution {parts[0]!r} ({', '.join(_ARITY)}){hint}")
    if len(parts) != 3:
        raise InputError(f"{name}: {spec!r}: expected START:STOP:N (a sweep) or normal:MEAN:SD, uniform:LO:HI, "
                         "triangular:LO:MODE:HI (a distribution)")
    try:
        n = int(parts[2])
    except ValueError:
        raise InputError(f"{name}: {spec!r}: N (the number of values) must be an integer, got {parts[2]!r}") from None
    if n < 1:
        raise InputError(f"{name}: {spec!r}: zero samples; N must be at least 1")
    start, stop = p.value(parts[0]), p.value(parts[1])
    if not (math.isfinite(start) and math.isfinite(stop)):
        raise InputError(f"{name}: {spec!r}: values must be finite")
    if n == 1 and start != stop:
        raise InputError(f"{name}: {spec!r}: one value cannot span {parts[0]}..{parts[1]}; use N >= 2")
    return Axis(p, "sweep", (start, stop, float(n)), spec)


def parse_vary(doc: Mapping[str, Any], vary: Any, resolved: Any = None) -> list[Axis]:
    """Axes from ``{"path": "spec"}``, ``["path=spec", ...]`` or one ``"path=spec"`` string."""
    if isinstance(vary, str):
        vary = [vary]
    items: list[tuple[str, Any]] = []
    if isinstance(vary, Mapping):
        items = list(vary.items())
    elif isinstance(vary, Iterable):
        for v in vary:
            if not isinstance(v, str) or "=" not in v:
                raise InputError(f"vary: expected NAME=SPEC, e.g. 'components.lift.mass=20 kg:60 kg:5', got {v!r}")
            k, s = v.split("=", 1)
            items.append((k.strip(), s.strip()))
    else:
        raise InputError(f"vary: expected a mapping or NAME=SPEC strings, got {vary!r}")
    if not items:
        raise InputError("vary: nothing to vary; give at least one NAME=SPEC")
    names = [k for k, _ in items]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise InputError(f"vary: {', '.join(sorted(dup))} given more than once")
    return [parse_axis(doc, k, s, resolved) for k, s in items]
