"""Material records: elastic and strength data, S-N curves, spring-wire strength, polymer-bearing limits.

Every value carries its source (``Material.sources`` maps a property name to a reference; the
``source`` of the material is the default). Values are pint quantities; ``None`` means "not known".
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, ValidityError
from mechverify.frozen import set_fields
from mechverify.units import Q, as_quantity, fmt, to_si

#: Property name -> dimension name, for every quantity-valued property of a Material.
PROPERTY_DIMENSIONS: dict[str, str] = {
    "E": "pressure",
    "G": "pressure",
    "nu": "dimensionless",
    "density": "density",
    "yield_strength": "pressure",
    "ultimate_strength": "pressure",
    "shear_yield_strength": "pressure",
    "shear_ultimate_strength": "pressure",
    "compressive_yield_strength": "pressure",
    "elongation": "dimensionless",
    "endurance_limit": "pressure",
    "p_max": "pressure",
    "pv_max": "pv",
    "v_max": "velocity",
    "mu_min": "dimensionless",
    "mu_max": "dimensionless",
    "max_temperature": "temperature",
}


@dataclass(frozen=True)
class SNCurve:
    """Stress amplitude against cycles to failure, interpolated log-log between table points.

    ``stress_ratio`` is the R = σmin/σmax the data were measured at (-1: fully reversed).
    Below the first tabulated life the curve is not defined (:class:`ValidityError`); above the
    last it stays at the last stress when ``constant_beyond_last`` (an endurance limit, as the
    FEA tools assume), otherwise it is an error.
    """

    cycles: tuple[float, ...]
    stress: tuple[float, ...]  # [Pa], amplitude
    stress_ratio: float = -1.0
    constant_beyond_last: bool = True
    source: str = ""

    def __post_init__(self) -> None:
        n, s = np.asarray(self.cycles, float), np.asarray(self.stress, float)
        if len(n) < 2 or len(n) != len(s):
            raise InputError("S-N curve: need at least two (cycles, stress) points of equal count")
        if np.any(np.diff(n) <= 0) or np.any(n <= 0):
            raise InputError("S-N curve: cycles must be positive and strictly increasing")
        if np.any(np.diff(s) > 0) or np.any(s <= 0):
            raise InputError("S-N curve: stress must be positive and non-increasing with cycles")

    def stress_at(self, cycles: float) -> pint.Quantity:
        """Stress amplitude [Pa] for a life of ``cycles`` (log-log interpolation)."""
        n = float(cycles)
        N, S = np.log10(self.cycles), np.log10(self.stress)
        if n < self.cycles[0]:
            raise ValidityError(f"S-N curve starts at {self.cycles[0]:g} cycles; asked for {n:g}")
        if n > self.cycles[-1]:
            if not self.constant_beyond_last:
                raise ValidityError(f"S-N curve ends at {self.cycles[-1]:g} cycles; asked for {n:g}")
            return Q(self.stress[-1], "Pa")
        return Q(10 ** float(np.interp(np.log10(n), N, S)), "Pa")

    def life_at(self, stress: Any) -> float:
        """Cycles to failure at a stress amplitude; ``inf`` below the endurance (last) stress."""
        s = to_si(stress, "pressure", "stress")
        if s > self.stress[0]:
            raise ValidityError(f"stress {fmt(Q(s, 'Pa'), 'MPa')} is above the S-N curve's first point "
                                f"({fmt(Q(self.stress[0], 'Pa'), 'MPa')} at {self.cycles[0]:g} cycles)")
        if s < self.stress[-1]:
            if self.constant_beyond_last:
                return float("inf")
            raise ValidityError("stress below the last S-N point and the curve has no endurance limit")
        logS = np.log10(self.stress)[::-1]
        logN = np.log10(self.cycles)[::-1]
        return float(10 ** np.interp(np.log10(s), logS, logN))


@dataclass(frozen=True)
class WireStrength:
    """Minimum tensile strength of spring wire as a function of wire diameter.

    Two kinds of data, either or both:

    * the power law ``Sut = A / d^m`` (Shigley, Table 10-4) over its diameter range ``d_min..d_max``;
      a wire whose law changes with diameter (A313 stainless, B159 phosphor bronze) lists the further
      laws in ``segments`` as ``(A [Pa], m, d_min [m], d_max [m])`` tuples, in ``d_unit`` like the
      first one;
    * a table of minimum tensile strength by diameter (e.g. ASTM A228 Table 1), interpolated linearly.

    :meth:`min_tensile_strength` uses the table inside its diameter range and the power law elsewhere
    (``method="auto"``); ``method="table"`` or ``"power_law"`` forces one of them. Outside the data,
    :class:`ValidityError`.
    """

    A: float  # [Pa] with d in the unit d_unit
    m: float
    d_unit: str = "mm"
    d_min: float = 0.0  # [m] validity of the power law
    d_max: float = float("inf")
    table_d: tuple[float, ...] = ()  # [m]
    table_sut: tuple[float, ...] = ()  # [Pa]
    source: str = ""
    table_source: str = ""
    segments: tuple[tuple[float, float, float, float], ...] = ()  # further (A [Pa], m, d_min [m], d_max [m])

    def __post_init__(self) -> None:
        set_fields(self, segments=tuple(tuple(float(x) for x in seg) for seg in self.segments))
        for A, _m, lo, hi in self.laws():
            if A <= 0 or not lo < hi:
                raise InputError(f"wire strength: power law needs A > 0 and d_min < d_max (got A={A:g} Pa, "
                                 f"range {lo:g}..{hi:g} m)")
        if len(self.table_d) != len(self.table_sut):
            raise InputError("wire strength: table_d and table_sut differ in length")
        if self.table_d and any(b <= a for a, b in zip(self.table_d, self.table_d[1:])):
            raise InputError("wire strength: table diameters must be strictly increasing")

    def laws(self) -> tuple[tuple[float, float, float, float], ...]:
        """All power laws as ``(A [Pa], m, d_min [m], d_max [m])``, the main one first."""
        return ((self.A, self.m, self.d_min, self.d_max), *self.segments)

    def power_law(self, d: Any) -> pint.Quantity:
        """``Sut = A / d^m`` with d in ``d_unit`` [Pa], from the law whose range holds ``d``."""
        dm = to_si(d, "length", "d")
        for A, m, lo, hi in self.laws():
            if lo <= dm <= hi:
                return Q(A / Q(dm, "m").m_as(self.d_unit) ** m, "Pa")
        ranges = ", ".join(f"{fmt(Q(lo, 'm'), 'mm')}..{fmt(Q(hi, 'm'), 'mm')}" for _, _, lo, hi in self.laws())
        raise ValidityError(f"wire diameter {fmt(Q(dm, 'm'), 'mm')} outside the power law's range {ranges}")

    def table_value(self, d: Any) -> pint.Quantity:
        """The tabulated minimum tensile strength at ``d``, interpolated linearly [Pa]."""
        dm = to_si(d, "length", "d")
        if not self.table_d:
            raise ValidityError("this wire has no tensile-strength table")
        if not self.table_d[0] <= dm <= self.table_d[-1]:
            raise ValidityError(f"wire diameter {fmt(Q(dm, 'm'), 'mm')} outside the table's range "
                                f"{fmt(Q(self.table_d[0], 'm'), 'mm')}..{fmt(Q(self.table_d[-1], 'm'), 'mm')}")
        return Q(float(np.interp(dm, self.table_d, self.table_sut)), "Pa")

    def min_tensile_strength(self, d: Any, method: str = "auto") -> pint.Quantity:
        """Minimum tensile strength at diameter ``d`` [Pa]: table inside its range, else the power law."""
        if method == "power_law":
            return self.power_law(d)
        if method == "table":
            return self.table_value(d)
        if method != "auto":
            raise InputError(f"wire strength: method must be 'auto', 'table' or 'power_law', got {method!r}")
        dm = to_si(d, "length", "d")
        if self.table_d and self.table_d[0] <= dm <= self.table_d[-1]:
            return self.table_value(Q(dm, "m"))
        return self.power_law(Q(dm, "m"))


@dataclass(frozen=True)
class Material:
    """A material record. Quantity fields are pint quantities or ``None`` where unknown."""

    name: str
    category: str
    E: pint.Quantity | None = None
    G: pint.Quantity | None = None
    nu: pint.Quantity | None = None
    density: pint.Quantity | None = None
    yield_strength: pint.Quantity | None = None
    ultimate_strength: pint.Quantity | None = None
    shear_yield_strength: pint.Quantity | None = None
    shear_ultimate_strength: pint.Quantity | None = None
    compressive_yield_strength: pint.Quantity | None = None
    elongation: pint.Quantity | None = None
    endurance_limit: pint.Quantity | None = None
    p_max: pint.Quantity | None = None
    pv_max: pint.Quantity | None = None
    v_max: pint.Quantity | None = None
    mu_min: pint.Quantity | None = None
    mu_max: pint.Quantity | None = None
    max_temperature: pint.Quantity | None = None
    sn_curve: SNCurve | None = None
    wire_strength: WireStrength | None = None
    aliases: tuple[str, ...] = ()
    source: str = ""
    sources: Mapping[str, str] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    derived: frozenset[str] = frozenset()  # properties computed from others (e.g. G from E, nu)

    def __post_init__(self) -> None:
        for prop, dim in PROPERTY_DIMENSIONS.items():
            v = getattr(self, prop)
            if v is not None:
                set_fields(self, **{prop: as_quantity(v, dim, f"{self.name}.{prop}")})
        for prop in ("E", "G", "density", "yield_strength", "ultimate_strength", "p_max", "pv_max"):
            v = getattr(self, prop)
            if v is not None and v.magnitude <= 0:
                raise InputError(f"{self.name}.{prop}: must be positive, got {fmt(v)}")
        if self.nu is not None and not (-1.0 < self.nu.m_as("") < 0.5):
            raise InputError(f"{self.name}.nu: Poisson's ratio must lie in (-1, 0.5), got {self.nu.m_as(''):g}")
        if (self.yield_strength is not None and self.ultimate_strength is not None
                and self.yield_strength > self.ultimate_strength):
            raise InputError(f"{self.name}: yield strength {fmt(self.yield_strength, 'MPa')} exceeds "
                             f"ultimate strength {fmt(self.ultimate_strength, 'MPa')}")
        if self.mu_min is not None and self.mu_max is not None and self.mu_min > self.mu_max:
            raise InputError(f"{self.name}: friction range reversed (mu_min > mu_max)")
        derived = set(self.derived)
        if self.G is None and self.E is not None and self.nu is not None:
            set_fields(self, G=(self.E / (2 * (1 + self.nu))).to(self.E.units))
            derived.add("G")
        elif self.nu is None and self.E is not None and self.G is not None:
            set_fields(self, nu=(self.E / (2 * self.G) - 1).to(""))
            derived.add("nu")
        set_fields(self, derived=frozenset(derived), aliases=tuple(self.aliases), notes=tuple(self.notes),
                   sources=dict(self.sources))

    def source_of(self, prop: str) -> str:
        """The reference for one property ("derived: G = E/(2(1+nu))" for computed ones)."""
        if prop in self.derived:
            return "derived: G = E / (2(1 + nu))" if prop == "G" else "derived: nu = E / (2G) - 1"
        return self.sources.get(prop, self.source)

    def require(self, prop: str) -> pint.Quantity:
        """The property, or an :class:`InputError` saying the material lacks it."""
        v = getattr(self, prop)
        if v is None:
            raise InputError(f"material {self.name!r} has no {prop.replace('_', ' ')}; "
                             f"derive one with .with_({prop}=...)")
        return v

    def with_(self, name: str | None = None, **changes: Any) -> Material:
        """A derived material: ``get("PLA").with_(yield_strength="38 MPa")``.

        Changed values are sourced "user". ``G`` (or ``nu``) derived from the old ``E``/``nu`` is
        derived again from the new ones.
        """
        fields = {f.name for f in dataclasses.fields(self)}
        unknown = set(changes) - fields
        if unknown:
            from mechverify.errors import suggest
            bad = sorted(unknown)[0]
            hint = suggest(bad, fields)
            raise InputError(f"Material has no property {bad!r}" + (f"; did you mean {hint[0]!r}?" if hint else ""))
        new = dict(changes)
        derived = set(self.derived) - set(changes)
        for p in list(derived):
            if {"E", "nu", "G"} & set(changes):
                new.setdefault(p, None)
                derived.discard(p)
        sources = {**self.sources, **{k: "user" for k in changes}}
        try:
            return dataclasses.replace(self, name=name or f"{self.name} (modified)", aliases=(),
                                       sources=sources, derived=frozenset(derived), **new)
        except InputError as exc:
            # yield <= ultimate holds for every material; a new yield above the base's ultimate needs both
            pair = {"yield_strength", "ultimate_strength"}
            if "exceeds ultimate" in str(exc) and len(pair & set(changes)) == 1:
                given = (pair & set(changes)).pop()
                other = (pair - {given}).pop()
                raise InputError(f"{exc}; {self.name} has {other} {fmt(getattr(self, other), 'MPa')}: give "
                                 f"{other} as well, e.g. with_({given}=..., {other}=...)") from None
            raise

    def __repr__(self) -> str:
        parts = [f"{p}={fmt(getattr(self, p))}" for p in ("E", "yield_strength", "ultimate_strength", "density")
                 if getattr(self, p) is not None]
        return f"<Material {self.name!r} ({self.category}) {' '.join(parts)}>"
