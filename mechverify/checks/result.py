"""The one result type every check returns, and the collection of results for a design.

Verdict rule (documented in ``docs/architecture.md``): with utilisation ``u = demand / capacity``
and the required safety factor ``SF``, the *factored utilisation* is ``u·SF``.

* **fail** when ``u·SF > 1`` (the safety factor achieved, ``capacity/demand``, is below ``SF``);
* **warn** when ``u·SF > WARN_LEVEL`` (less than 10 % of the requirement left) or when the result
  carries a validity warning (an input outside the range the formula was derived for);
* **pass** otherwise.
"""

from __future__ import annotations

import dataclasses
import html
import math
import re
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from enum import Enum, StrEnum
from functools import cached_property
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnitError
from mechverify.frozen import set_fields
from mechverify.units import Q, Quantity, fmt, same_units

WARN_LEVEL = 0.9
#: Compute lazy ``details`` and ``substituted`` when a result is made (for tests comparing lazy and eager values).
EAGER = False


class Verdict(StrEnum):
    PASS = "pass"
    WARN = "warn"
    FAIL = "fail"

    @property
    def rank(self) -> int:
        return {"pass": 0, "warn": 1, "fail": 2}[self.value]


class LazyDetails(Mapping[str, Any]):
    """The figure data of a :class:`CheckResult` computed when first read (issue 19: a study never reads them).

    ``CheckResult(details=lambda: {...})`` stores one of these; it is a read-only
    :class:`~collections.abc.Mapping`, so every reader (report figures, ``to_dict``, ``{**r.details}``,
    ``r.details.get``) sees the same keys and values as an eagerly built dict. The function runs once;
    pickling and copying carry the computed dict (a process pool or Dask never sees the function).
    """

    __slots__ = ("_fn", "_data")

    def __init__(self, fn: Callable[[], Mapping[str, Any]]):
        self._fn: Callable[[], Mapping[str, Any]] | None = fn
        self._data: dict[str, Any] | None = None

    @property
    def resolved(self) -> bool:
        """True once the data have been computed."""
        return self._data is not None

    def data(self) -> dict[str, Any]:
        """The computed dict (computing it on the first call)."""
        if self._data is None:
            assert self._fn is not None
            self._data, self._fn = dict(self._fn()), None
        return self._data

    def __getitem__(self, key: str) -> Any:
        return self.data()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self.data())

    def __len__(self) -> int:
        return len(self.data())

    def __contains__(self, key: object) -> bool:
        return key in self.data()

    def __eq__(self, other: object) -> bool:
        if isinstance(other, LazyDetails):
            other = other.data()
        return self.data() == other if isinstance(other, Mapping) else NotImplemented

    __hash__ = None  # type: ignore[assignment]  # like a dict

    def __repr__(self) -> str:
        return repr(self.data()) if self.resolved else "LazyDetails(<not computed>)"

    def __reduce__(self) -> tuple[Any, ...]:
        return (dict, (self.data(),))


class _Pending:
    """A :attr:`CheckResult.substituted` not yet read: the text or the function that makes it, and (once one
    result read it) the finished text, which the copies made by :meth:`CheckResult.replace` share."""

    __slots__ = ("raw", "text")

    def __init__(self, raw: str | Callable[[], str]):
        self.raw = raw
        self.text: str | None = None


class _Substituted:
    """Descriptor of :attr:`CheckResult.substituted`: a string, or a zero-argument function returning it, is
    stored as given; on the first read the function runs, negative operands are bracketed
    (:func:`bracket_negative_operands`) and the text replaces what was stored. So a check that is never
    reported (a study sample) neither formats its numbers nor runs the regular expression."""

    def __get__(self, obj: Any, owner: type | None = None) -> Any:
        if obj is None:
            return ""  # the dataclass field's default
        v = obj.__dict__.get("substituted", "")
        if type(v) is _Pending:
            if v.text is None:
                raw = v.raw() if callable(v.raw) else v.raw
                if not isinstance(raw, str):
                    raise TypeError(f"{obj.component}/{obj.check}: substituted must be a str, got "
                                    f"{type(raw).__name__}")
                v.text, v.raw = (bracket_negative_operands(raw) if raw else raw), ""
            v = obj.__dict__["substituted"] = v.text
        return v

    def __set__(self, obj: Any, value: Any) -> None:
        _store_substituted(obj, value)


def _store_substituted(obj: Any, value: Any) -> None:
    """What the constructor does with ``substituted``: "" as it is, anything else kept until first read."""
    obj.__dict__["substituted"] = value if type(value) is _Pending or (isinstance(value, str) and not value) \
        else _Pending(value)


_UNSET = object()

#: Fields :meth:`CheckResult.replace` may change without running the validation of ``__post_init__`` again
#: (it validates the demand, capacity and safety factor only).
_FAST_FIELDS = frozenset({"check", "component", "title", "formula", "source", "load_case", "notes", "warnings",
                          "inputs", "details", "substituted", "required_sf"})


def _utilisation(d: float, c: float) -> float:
    """demand / capacity from their magnitudes in one unit (``inf`` for zero capacity, 0 for 0/0)."""
    if c == 0:
        return 0.0 if d == 0 else math.inf
    return d / c


def _details(details: Any) -> Mapping[str, Any]:
    """A result's details as stored: a function becomes a :class:`LazyDetails`, a mapping a new dict."""
    if isinstance(details, LazyDetails):
        return details
    return LazyDetails(details) if callable(details) else dict(details)


@dataclass(frozen=True)
class CheckResult:
    """One check of one component: demand against capacity, with its formula and source.

    ``demand`` and ``capacity`` are quantities of the same dimension, both oriented so that the
    check passes while ``demand <= capacity / required_sf`` (for a "must exceed" check such as
    bearing life, the demand is the required life and the capacity the life achieved).

    ``details`` (figure data) and ``substituted`` (LaTeX) may be given as zero-argument functions: they run
    when the value is first read (report, JSON, figure), never for a result only its verdict is read from
    (a study sample). Reading gives the same values as passing them computed. Use :meth:`replace` (not
    ``dataclasses.replace``, which reads and so computes every field) to keep them unread.
    """

    check: str
    component: str
    demand: pint.Quantity
    capacity: pint.Quantity
    required_sf: float = 1.0
    title: str = ""
    formula: str = ""  # LaTeX, rendered by the reports
    source: str = ""  # book, edition, equation or table
    inputs: Mapping[str, Any] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()  # validity concerns; any makes the verdict at least "warn"
    load_case: str = ""  # governing load case or operating point
    # data for plots (quantities, arrays): a mapping, or a function returning one (then a LazyDetails)
    details: Mapping[str, Any] = field(default_factory=dict)
    # LaTeX: the formula with its inputs substituted (with units) = the result, see tex(); or a function returning it
    substituted: str = _Substituted()  # type: ignore[assignment]

    def __init__(self, check: str, component: str, demand: pint.Quantity, capacity: pint.Quantity,
                 required_sf: float = 1.0, title: str = "", formula: str = "", source: str = "",
                 inputs: Mapping[str, Any] | None = None, notes: tuple[str, ...] = (), warnings: tuple[str, ...] = (),
                 load_case: str = "", details: Mapping[str, Any] | Callable[[], Mapping[str, Any]] | None = None,
                 substituted: str | Callable[[], str] = "") -> None:
        """The dataclass's fields in order (what the generated ``__init__`` of a frozen dataclass stores one
        ``object.__setattr__`` at a time, stored at once: a study sample makes ~20 results)."""
        set_fields(self, check=check, component=component, demand=demand, capacity=capacity,
                   required_sf=required_sf, title=title, formula=formula, source=source,
                   inputs={} if inputs is None else inputs, notes=notes, warnings=warnings,
                   load_case=load_case, details={} if details is None else details)
        _store_substituted(self, substituted)
        self.__post_init__()

    def __post_init__(self) -> None:
        fields = self.__dict__
        for name in ("demand", "capacity"):
            v = fields[name]
            if type(v) is not Quantity and not isinstance(v, Quantity):
                set_fields(self, **{name: Q(v)})
        d, c = self._magnitudes()
        if not (math.isfinite(d) and not math.isnan(c)):
            raise InputError(f"{self.component}/{self.check}: demand must be finite, got {fmt(self.demand)}")
        if d < 0 or c < 0:
            raise InputError(f"{self.component}/{self.check}: demand and capacity must be >= 0 "
                             f"(got {fmt(self.demand)}, {fmt(self.capacity)})")
        if not self.required_sf > 0:
            raise InputError(f"{self.component}/{self.check}: required safety factor must be > 0")
        details = _details(fields["details"])
        set_fields(self, notes=tuple(fields["notes"]), warnings=tuple(fields["warnings"]),
                   inputs=dict(fields["inputs"]), details=details)
        # utilisation (a cached_property) from the magnitudes just read: the same value, one conversion less
        fields["utilisation"] = _utilisation(d, c)
        if EAGER:
            self.substituted  # noqa: B018  # computed now (tests compare with the lazy values)
            if isinstance(details, LazyDetails):
                details.data()

    def replace(self, **changes: Any) -> CheckResult:
        """A copy with ``changes`` (as :func:`dataclasses.replace`), leaving ``details`` and ``substituted``
        uncomputed when they are. When neither the demand nor the capacity changes, their validation is not
        repeated (a new safety factor is checked, the other fields are normalised as by the constructor)."""
        if changes.keys() <= _FAST_FIELDS:
            if "required_sf" in changes and not changes["required_sf"] > 0:
                raise InputError(f"{self.component}/{self.check}: required safety factor must be > 0")
            new = object.__new__(type(self))
            new.__dict__.update(self.__dict__)
            for k in ("notes", "warnings"):
                if k in changes:
                    changes[k] = tuple(changes[k])
            if "inputs" in changes:
                changes["inputs"] = dict(changes["inputs"])
            if "details" in changes:
                changes["details"] = _details(changes["details"])
            substituted = changes.pop("substituted", _UNSET)
            new.__dict__.update(changes)
            if substituted is not _UNSET:
                _store_substituted(new, substituted)
            if EAGER:
                new.__post_init__()
            return new
        raw = self.__dict__.get("substituted", "")
        if "substituted" not in changes and type(raw) is _Pending:
            changes["substituted"] = raw
        return dataclasses.replace(self, **changes)

    __replace__ = replace  # copy.replace (Python 3.13)

    def __getstate__(self) -> dict[str, Any]:
        """Pickled with ``details`` and ``substituted`` computed (a function does not cross processes)."""
        self.substituted  # noqa: B018
        state = dict(self.__dict__)
        if isinstance(state.get("details"), LazyDetails):
            state["details"] = state["details"].data()
        return state

    def _magnitudes(self) -> tuple[float, float]:
        """The demand in the capacity's unit and the capacity, as floats (no conversion when the units agree)."""
        dem, cap = self.__dict__["demand"], self.__dict__["capacity"]
        if same_units(dem, cap):  # the same unit: the magnitude as it is (what m_as returns then)
            return float(dem.magnitude), float(cap.magnitude)
        if dem.dimensionality != cap.dimensionality:
            raise UnitError(f"{self.component}/{self.check}: demand {fmt(dem)} and capacity {fmt(cap)} have "
                            "different dimensions")
        return float(dem.m_as(cap.units)), float(cap.magnitude)

    @cached_property
    def utilisation(self) -> float:
        """demand / capacity (dimensionless; ``inf`` for zero capacity)."""
        return _utilisation(*self._magnitudes())

    @property
    def factored_utilisation(self) -> float:
        return self.utilisation * self.required_sf

    @property
    def safety_factor(self) -> float:
        """capacity / demand (``inf`` for zero demand)."""
        u = self.utilisation
        return math.inf if u == 0 else 1.0 / u

    @property
    def verdict(self) -> Verdict:
        fu = self.factored_utilisation
        if fu > 1.0:
            return Verdict.FAIL
        if fu > WARN_LEVEL or self.warnings:
            return Verdict.WARN
        return Verdict.PASS

    @property
    def passed(self) -> bool:
        return self.verdict is not Verdict.FAIL

    # ------------------------------------------------------------------ output
    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict; :meth:`from_dict` restores an equal result."""
        return {
            "check": self.check,
            "component": self.component,
            "title": self.title,
            "demand": _encode(self.demand),
            "capacity": _encode(self.capacity),
            "required_sf": self.required_sf,
            "utilisation": _finite_or_none(self.utilisation),
            "safety_factor": _finite_or_none(self.safety_factor),
            "verdict": self.verdict.value,
            "formula": self.formula,
            "source": self.source,
            "inputs": {k: _encode(v) for k, v in self.inputs.items()},
            "notes": list(self.notes),
            "warnings": list(self.warnings),
            "load_case": self.load_case,
            "details": {k: _encode(v) for k, v in self.details.items()},
            "substituted": self.substituted,
        }

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> CheckResult:
        return cls(
            check=d["check"], component=d["component"], title=d.get("title", ""),
            demand=_decode(d["demand"]), capacity=_decode(d["capacity"]),
            required_sf=d.get("required_sf", 1.0), formula=d.get("formula", ""),
            source=d.get("source", ""), inputs={k: _decode(v) for k, v in d.get("inputs", {}).items()},
            notes=tuple(d.get("notes", ())), warnings=tuple(d.get("warnings", ())),
            load_case=d.get("load_case", ""), details={k: _decode(v) for k, v in d.get("details", {}).items()},
            substituted=d.get("substituted", ""),
        )

    def summary(self) -> str:
        """One line: component, check, demand/capacity, utilisation, verdict."""
        sf = f" (SF req {self.required_sf:g})" if self.required_sf != 1 else ""
        case = f" [{self.load_case}]" if self.load_case else ""
        return (f"{self.verdict.value.upper():4}  {self.component}: {self.title or self.check}  "
                f"{fmt(self.demand)} / {fmt(self.capacity)}  u={self.utilisation:.3g}{sf}{case}")

    def __repr__(self) -> str:
        return f"<CheckResult {self.summary()}>"

    def _repr_html_(self) -> str:
        return ResultSet([self])._repr_html_()


class ResultSet:
    """An ordered collection of :class:`CheckResult` with an overall verdict."""

    def __init__(self, results: Iterable[CheckResult] = (), name: str = ""):
        self.results: tuple[CheckResult, ...] = tuple(results)
        self.name = name
        for r in self.results:
            if not isinstance(r, CheckResult):
                raise TypeError(f"ResultSet holds CheckResult, got {type(r).__name__}")

    def __iter__(self) -> Iterator[CheckResult]:
        return iter(self.results)

    def __len__(self) -> int:
        return len(self.results)

    def __getitem__(self, i: int) -> CheckResult:
        return self.results[i]

    def __add__(self, other: Iterable[CheckResult]) -> ResultSet:
        return ResultSet([*self.results, *other], self.name)

    @property
    def verdict(self) -> Verdict:
        """The worst verdict of all results; ``warn`` for an empty set (no check ran: nothing was verified)."""
        return max((r.verdict for r in self.results), key=lambda v: v.rank, default=Verdict.WARN)

    @property
    def passed(self) -> bool:
        return self.verdict is not Verdict.FAIL

    def sorted(self) -> ResultSet:
        """Failures first, then by factored utilisation, highest first."""
        key = lambda r: (-r.verdict.rank, -r.factored_utilisation, r.component, r.check)  # noqa: E731
        return ResultSet(sorted(self.results, key=key), self.name)

    def where(self, *, component: str | None = None, check: str | None = None) -> ResultSet:
        return ResultSet([r for r in self.results if (component is None or r.component == component)
                          and (check is None or r.check == check)], self.name)

    def get(self, component: str, check: str) -> CheckResult:
        hits = self.where(component=component, check=check).results
        if len(hits) != 1:
            raise KeyError(f"{len(hits)} results for {component}/{check}")
        return hits[0]

    def to_dict(self) -> dict[str, Any]:
        return {"name": self.name, "verdict": self.verdict.value,
                "counts": {v.value: sum(r.verdict is v for r in self.results) for v in Verdict},
                "results": [r.to_dict() for r in self.results]}

    def to_json(self, **kw: Any) -> str:
        """Deterministic JSON: same results, identical bytes."""
        from mechverify.fileio import json_text

        return json_text(self.to_dict(), sort_keys=True, indent=2, **kw)

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> ResultSet:
        return cls([CheckResult.from_dict(r) for r in d["results"]], d.get("name", ""))

    def table(self) -> str:
        return "\n".join(r.summary() for r in self.sorted()) + f"\nOVERALL: {self.verdict.value.upper()}"

    def __repr__(self) -> str:
        return f"<ResultSet {self.name!r}: {len(self)} checks, {self.verdict.value}>\n{self.table()}"

    def _repr_html_(self) -> str:
        colour = {"pass": "#1a7f37", "warn": "#9a6700", "fail": "#cf222e"}
        rows = []
        for r in self.sorted():
            rows.append(
                "<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in (
                    r.component, r.title or r.check, fmt(r.demand), fmt(r.capacity), f"{r.utilisation:.3g}",
                    f"{r.required_sf:g}")) +
                f'<td style="color:{colour[r.verdict.value]};font-weight:bold">{r.verdict.value}</td>'
                f"<td>{html.escape(r.load_case)}</td></tr>")
        head = "".join(f"<th>{h}</th>" for h in ("component", "check", "demand", "capacity", "utilisation",
                                                  "SF req.", "verdict", "case"))
        return (f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
                f"<p>Overall: <b style='color:{colour[self.verdict.value]}'>{self.verdict.value}</b></p>")


def tex(q: Any, unit: str | None = None, digits: int = 4) -> str:
    """A quantity (or number) as LaTeX for :attr:`CheckResult.substituted`: ``tex(Q(350, "N")) ->
    '350\\,\\mathrm{N}'``, ``tex(Q(1.5e5, "Pa"), "MPa") -> '0.15\\,\\mathrm{MPa}'``; ``digits``
    significant digits, ``a\\times10^{n}`` outside 1e-3..1e6. The units are pint's short names with
    ``\\cdot`` and ``^{n}``, so the substituted line reads back as a unit-aware expression."""
    if isinstance(q, Quantity):
        if unit:
            q = q.to(unit)
        m, u = float(q.magnitude), f"{q.units:~C}"
    else:
        m, u = float(q), ""
    text = f"{m:.{digits}g}"
    if "e" in text:
        mant, exp = text.split("e")
        text = rf"{mant}\times10^{{{int(exp)}}}"
    if not u:
        return text
    u = re.sub(r"\*\*(-?\d+)", r"^{\1}", u).replace("*", r"\cdot ")
    return rf"{text}\,\mathrm{{{u}}}"


def tex_term(q: Any, unit: str | None = None, digits: int = 4) -> str:
    r""":func:`tex` of an operand that follows a binary operator: a negative value in parentheses, so
    ``a - b`` with b = -6.246 MPa prints ``a - (-6.246\,\mathrm{MPa})``, never ``a - -6.246 MPa``."""
    text = tex(q, unit, digits)
    return f"({text})" if text.startswith("-") else text


def tex_minus(a: Any, b: Any, unit: str | None = None, digits: int = 4) -> str:
    """``a - b`` as LaTeX for a substituted line; ``b`` in parentheses when negative (see :func:`tex_term`)."""
    return f"{tex(a, unit, digits)} - {tex_term(b, unit, digits)}"


# A signed number (with its x10^{n} and \,\mathrm{unit}) right after a binary operator: "- -6.2", "+ -3", "\cdot -2".
_NEGATIVE_OPERAND = re.compile(
    r"(?P<op>(?<![=(,{])[-+]|\\cdot|\\times)(?P<sp>\s*)"
    r"(?P<num>-\d[\d.]*(?:\\times10\^\{-?\d+\})?(?:\\,\\mathrm\{(?:[^{}]|\{[^{}]*\})*\})?)")


def bracket_negative_operands(latex: str) -> str:
    r"""Put a negative number that directly follows ``-``, ``+``, ``\cdot`` or ``\times`` in parentheses
    (the safety net behind :func:`tex_term`, applied to every :attr:`CheckResult.substituted`); the value
    of the expression does not change."""
    return _NEGATIVE_OPERAND.sub(lambda m: f"{m['op']}{m['sp']}({m['num']})", latex)


def _finite_or_none(x: float) -> float | None:
    return x if math.isfinite(x) else None


def _encode(v: Any) -> Any:
    if isinstance(v, Quantity):
        m = v.magnitude
        m = m.tolist() if isinstance(m, np.ndarray) else float(m)
        return {"value": m, "unit": f"{v.units:~C}"}
    if isinstance(v, np.ndarray):
        return {"array": v.tolist()}
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, Enum):
        return v.value
    if isinstance(v, list | tuple):
        return [_encode(x) for x in v]
    if isinstance(v, dict):
        return {str(k): _encode(x) for k, x in v.items()}
    return v


def _decode(v: Any) -> Any:
    if isinstance(v, dict) and set(v) == {"value", "unit"}:
        m = v["value"]
        return Q(np.asarray(m, dtype=float) if isinstance(m, list) else m, v["unit"] or "dimensionless")
    if isinstance(v, dict) and set(v) == {"array"}:
        return np.asarray(v["array"])
    if isinstance(v, list):
        return [_decode(x) for x in v]
    if isinstance(v, dict):
        return {k: _decode(x) for k, x in v.items()}
    return v
