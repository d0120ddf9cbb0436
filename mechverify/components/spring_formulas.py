"""Helical round-wire springs: the shared formulas (index, stress factors, rate, stress, wire data).

One function per published formula. The spring classes live in ``springs_compression``,
``springs_extension`` and ``springs_torsion``; :mod:`mechverify.components.springs` gathers everything.

References
----------
[1] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill 2015, Ch. 10.
[2] EN 13906-1:2013, Cylindrical helical springs made from round wire and bar - Compression springs.
[3] A. M. Wahl, Mechanical Springs, 2nd ed., McGraw-Hill 1963.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import cache, cached_property
from pathlib import Path
from typing import Any

import pint

from mechverify.errors import InputError, ValidityError
from mechverify.materials import database as _materials
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike, as_quantity, fmt, from_si, si_function, to_si


# --------------------------------------------------------------------------------------------- data
@cache
def spring_data() -> dict[str, Any]:
    """The spring design tables of ``components/data/springs.toml`` (loaded once)."""
    return tomllib.loads((Path(__file__).parent / "data" / "springs.toml").read_text(encoding="utf-8"))


def _ref(src: str) -> str:
    refs = spring_data()["references"]
    key = src.split(",")[0].strip()
    return src.replace(key, refs[key], 1) if key in refs else src


SPRING_CLASSES = ("cold_drawn", "hardened_tempered", "stainless", "nonferrous")


def spring_wire_class(material: Material, spring_class: str | None = None) -> str:
    """The Shigley Table 10-6 class of a spring material (explicit ``spring_class`` wins).

    Classes: ``cold_drawn`` (A227, A228), ``hardened_tempered`` (A229, A230, A232, A401),
    ``stainless`` (A313), ``nonferrous`` (B159, B197). The class is found from the ASTM designation
    in the material's name or aliases.
    """
    if spring_class is not None:
        if spring_class not in SPRING_CLASSES:
            from mechverify.errors import UnknownNameError
            raise UnknownNameError("spring wire class", spring_class, SPRING_CLASSES)
        return spring_class
    names = " ".join([material.name, *material.aliases]).upper().replace(" ", "")
    for cls, row in spring_data()["classes"].items():
        if any(code in names for code in row["astm"]):
            return cls
    raise InputError(f"material {material.name!r}: cannot tell its spring-wire class (Shigley Table 10-6) from "
                     f"its name; pass spring_class= one of {', '.join(SPRING_CLASSES)}")


def class_fraction(cls: str, key: str) -> float:
    """A fraction of Sut from the class table (``set_not_removed``, ``torsion_spring_bending``, ...)."""
    return float(spring_data()["classes"][cls][key])


def resolve_material(material: str | Material) -> Material:
    """A :class:`Material` from a name or a material record."""
    return _materials.get(material) if isinstance(material, str) else material


def wire_tensile_strength(material: Material, d: Any) -> pint.Quantity:
    """Minimum tensile strength Sut of spring wire of diameter ``d`` [Pa] (material wire-strength data)."""
    if material.wire_strength is not None:
        return material.wire_strength.min_tensile_strength(d).to("MPa")
    if material.ultimate_strength is not None:
        return material.ultimate_strength.to("MPa")
    raise InputError(f"material {material.name!r} has neither wire_strength data nor an ultimate_strength; "
                     "give the spring an Sut= value")


# ----------------------------------------------------------------------------------------- geometry
def coil_geometry(name: str, d: QuantityLike, D: Any = None, OD: Any = None, ID: Any = None) -> tuple[float, float]:
    """Wire and mean coil diameter [m] from ``d`` and exactly one of ``D`` (mean), ``OD`` or ``ID``.

    ``D = OD - d = ID + d``; raises :class:`InputError` for a non-positive wire or ``D <= d``.
    """
    dm = to_si(d, "length", "d")
    if dm <= 0:
        raise InputError(f"{name}: wire diameter d must be positive, got {fmt(as_quantity(d, 'length'))}")
    given = {k: v for k, v in (("D", D), ("OD", OD), ("ID", ID)) if v is not None}
    if len(given) != 1:
        raise InputError(f"{name}: give exactly one of D (mean), OD or ID coil diameter; got {list(given) or 'none'}")
    (key, value), = given.items()
    raw = to_si(value, "length", key)
    Dm = {"D": raw, "OD": raw - dm, "ID": raw + dm}[key]
    if Dm <= dm:
        raise InputError(f"{name}: mean coil diameter D = {fmt(Q(Dm, 'm'), 'mm')} must exceed the wire "
                         f"diameter d = {fmt(Q(dm, 'm'), 'mm')} (spring index C = D/d > 1)")
    return dm, Dm


@si_function(D="length", d="length")
def spring_index(D: float, d: float) -> float:
    """Spring index C = D/d [-], D mean coil diameter, d wire diameter. Shigley [1] Eq. (10-1)."""
    if d <= 0 or D <= d:
        raise InputError(f"spring geometry: mean diameter D must exceed wire diameter d > 0 "
                         f"(got D = {fmt(Q(D, 'm'), 'mm')}, d = {fmt(Q(d, 'm'), 'mm')})")
    return D / d


def _index(C: Any) -> float:
    c = float(as_quantity(C, "dimensionless", "C").m_as(""))
    if not c > 1:
        raise InputError(f"spring index C must exceed 1, got {c:g}")
    return c


def direct_shear_factor(C: Any) -> float:
    """Shear-stress correction factor Ks = (2C + 1)/(2C) [-] (direct shear only). Shigley [1] Eq. (10-3)."""
    c = _index(C)
    return (2 * c + 1) / (2 * c)


def wahl_factor(C: Any) -> float:
    """Wahl factor K_W = (4C - 1)/(4C - 4) + 0.615/C [-] (shear and curvature). Shigley [1] Eq. (10-4); Wahl [3]."""
    c = _index(C)
    return (4 * c - 1) / (4 * c - 4) + 0.615 / c


def bergstrasser_factor(C: Any) -> float:
    """Bergsträsser factor K_B = (4C + 2)/(4C - 3) [-]; within 1 % of K_W for 3 < C < 12 [1] Eq. (10-5).

    EN 13906-1 [2] Eq. (18) uses the same factor (its k = (C + 0.5)/(C - 0.75)).
    """
    c = _index(C)
    return (4 * c + 2) / (4 * c - 3)


def curvature_factor(C: Any) -> float:
    """Curvature correction factor K_c = K_B/K_s = 2C(4C + 2)/((4C - 3)(2C + 1)) [-]. Shigley [1] Eq. (10-6)."""
    return bergstrasser_factor(C) / direct_shear_factor(C)


def torsion_spring_factors(C: Any) -> tuple[float, float]:
    """Bending stress-correction factors of helical torsion springs (inner, outer fibre) [-].

    K_i = (4C² - C - 1)/(4C(C - 1)), K_o = (4C² + C - 1)/(4C(C + 1)). Shigley [1] Sec. 10-12, Eq. (10-43).
    """
    c = _index(C)
    return (4 * c * c - c - 1) / (4 * c * (c - 1)), (4 * c * c + c - 1) / (4 * c * (c + 1))


# ------------------------------------------------------------------------------- rate and stresses
@si_function(returns="force_per_length", d="length", D="length", G="pressure")
def helical_rate(d: float, D: float, Na: float, G: float) -> float:
    """Axial rate of a helical spring k = d⁴G/(8D³Nₐ) [N/m]. Shigley [1] Eq. (10-9); EN 13906-1 [2] Eq. (4).

    d wire diameter [m], D mean diameter [m], Nₐ active coils [-], G shear modulus [Pa].
    The direct-shear term (1 + 1/(2C²)) of Castigliano's solution is neglected, as in [1].
    """
    Na = float(Na)
    if Na <= 0:
        raise InputError(f"active coils must be positive, got {Na:g}")
    spring_index.si(D, d)
    return d**4 * G / (8 * D**3 * Na)


@si_function(returns="pressure", F="force", D="length", d="length")
def helical_shear_stress(F: float, D: float, d: float, K: float) -> float:
    """Torsional shear stress in the wire τ = K·8FD/(πd³) [Pa]. Shigley [1] Eqs. (10-2), (10-7).

    K is the stress factor: K_s (set removed), K_B or K_W (curvature included).
    """
    return K * 8 * F * D / (math.pi * d**3)


@si_function(returns="length", k="force_per_length", d="length", G="pressure")
def mean_diameter_for_rate(k: float, d: float, Na: float, G: float) -> float:
    """Sizing: the mean diameter giving rate k, D = (Gd⁴/(8kNₐ))^(1/3) [m] (Shigley [1] Eq. (10-9) inverted)."""
    if k <= 0 or float(Na) <= 0:
        raise InputError(f"rate and active coils must be positive (k = {k:g} N/m, Na = {float(Na):g})")
    D = (G * d**4 / (8 * k * float(Na))) ** (1 / 3)
    if D <= d:
        raise InputError(f"no spring of wire d = {fmt(Q(d, 'm'), 'mm')} with {float(Na):g} active coils is as "
                         f"soft as {k:g} N/m with D > d; use more coils or thinner wire")
    return D


def active_coils_for_rate(k: QuantityLike, d: QuantityLike, D: QuantityLike, G: QuantityLike) -> float:
    """Sizing: active coils Nₐ = Gd⁴/(8D³k) [-] for rate k (Shigley [1] Eq. (10-9) inverted)."""
    ks, ds, Ds, Gs = (to_si(k, "force_per_length", "k"), to_si(d, "length", "d"), to_si(D, "length", "D"),
                      to_si(G, "pressure", "G"))
    if ks <= 0:
        raise InputError(f"k: must be positive, got {ks:g} N/m")
    spring_index.si(Ds, ds)
    return Gs * ds**4 / (8 * Ds**3 * ks)


@si_function(returns="mass", d="length", D="length", density="density")
def active_coil_mass(d: float, D: float, Na: float, density: float) -> float:
    """Mass of the active coils m = ρ·π²d²DNₐ/4 [kg]. Shigley [1] Sec. 10-8 (weight W = π²d²DNₐγ/4)."""
    return density * math.pi**2 * d**2 * D * float(Na) / 4


@si_function(returns="frequency", k="force_per_length", m="mass")
def surge_frequency(k: float, m: float, one_end_free: bool = False) -> float:
    """Fundamental surge (critical) frequency of a helical spring [Hz]. Shigley [1] Sec. 10-8.

    Between two flat parallel plates, one of them driven: f = ½·√(k/m); one end against a flat plate
    and the other free: f = ¼·√(k/m). k rate [N/m], m mass of the active coils [kg].
    Shigley recommends the operating frequency stay below 1/15..1/20 of f.
    """
    return (0.25 if one_end_free else 0.5) * math.sqrt(k / m)


# --------------------------------------------------------------------------------------- strengths
def torsional_ultimate_strength(Sut: QuantityLike) -> pint.Quantity:
    """Torsional modulus of rupture of spring wire S_su = 0.67·S_ut [Pa]. Shigley [1] Sec. 10-9, Eq. (10-30)."""
    return from_si(0.67 * to_si(Sut, "pressure", "Sut"), "pressure").to("MPa")


@dataclass(frozen=True)
class ZimmerliData:
    """Zimmerli's infinite-life torsional strength components for spring steel, d < 10 mm (Shigley [1] Sec. 10-9)."""

    Ssa: pint.Quantity
    Ssm: pint.Quantity
    peened: bool
    source: str


def zimmerli(peened: bool = False, d: QuantityLike | None = None) -> ZimmerliData:
    """Zimmerli data: unpeened S_sa = 241 MPa (35 ksi), S_sm = 379 MPa (55 ksi); peened 398 / 534 MPa.

    With ``d`` given, wires of 10 mm and over raise :class:`ValidityError` (the data were measured on
    smaller sizes). Shigley [1] Sec. 10-9.
    """
    z = spring_data()["zimmerli"]
    if d is not None:
        dmax = Q(z["max_wire_diameter"])
        if to_si(d, "length", "d") >= dmax.m_as("m"):
            raise ValidityError(f"Zimmerli endurance data hold for wire under {fmt(dmax)}; "
                                f"d = {fmt(as_quantity(d, 'length', 'd'), 'mm')}")
    row = z["peened" if peened else "unpeened"]
    return ZimmerliData(Ssa=Q(row["Ssa"]).to("MPa"), Ssm=Q(row["Ssm"]).to("MPa"), peened=peened,
                        source=_ref(z["source"]))


def end_condition_constant(end: str) -> float:
    """End-condition constant α (Shigley [1] Table 10-2) = seating coefficient ν (EN 13906-1 [2] Fig. 5).

    ``fixed-fixed`` 0.5 (between flat parallel plates), ``fixed-pinned`` 0.707, ``pinned-pinned`` 1,
    ``fixed-guided`` 1, ``fixed-free`` 2.
    """
    table = {k: v for k, v in spring_data()["end_conditions"].items() if k != "source"}
    if end not in table:
        from mechverify.errors import UnknownNameError
        raise UnknownNameError("spring end condition", end, table)
    return float(table[end])


class HelicalSpring:
    """What the three helical spring classes share (compression, extension, torsion: one copy).

    A subclass is a frozen dataclass with the fields ``d``, ``D``/``OD``/``ID``, ``material``, ``Sut``,
    ``spring_class`` and ``name``; it defines ``_si_values()`` (its inputs in SI, validated) and
    calls ``self.validate()`` at the end of ``__post_init__``, so bad input fails at construction.
    The values are ``functools.cached_property`` (see :mod:`mechverify.frozen`): not fields, so ``==``,
    ``hash`` and ``repr`` ignore them, and ``pickle`` carries them.
    """

    name: str
    material: str | Material
    spring_class: str | None
    Sut: Any  # given wire tensile strength, or None: the material's (_wire_si)

    def _si_values(self) -> dict[str, float]:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def validate(self) -> None:
        """Compute the derived values once (their errors are construction errors)."""
        self.si  # noqa: B018
        self.wire_class  # noqa: B018

    @cached_property
    def si(self) -> dict[str, float]:
        """The spring's inputs in SI units [m, Pa, N] after validation (``d``, ``D``, coils, moduli,
        ``Sut``, ...); read it, do not change it."""
        return self._si_values()

    def _wire_si(self, d: float, moduli: tuple[str, ...]) -> dict[str, float]:
        """The wire's ``moduli`` (``"G"``, ``"E"``: the spring's field, else the material's; positive) and ``Sut``
        (the field, else :func:`wire_tensile_strength` of the material at the wire diameter ``d`` [m]) [Pa]."""
        mat = self.material_record
        out = {}
        for nm in moduli:
            given = getattr(self, nm)
            out[nm] = to_si(given if given is not None else mat.require(nm), "pressure", nm)
            if out[nm] <= 0:
                raise InputError(f"{self.name}: {nm} must be positive")
        Sut = self.Sut if self.Sut is not None else wire_tensile_strength(mat, Q(d, "m"))
        out["Sut"] = to_si(Sut, "pressure", "Sut")
        return out

    @cached_property
    def material_record(self) -> Material:
        """The wire's :class:`~mechverify.materials.material.Material`."""
        return resolve_material(self.material)

    @cached_property
    def wire_class(self) -> str:
        """Shigley Table 10-6 class of the wire (``cold_drawn``, ``hardened_tempered``, ...)."""
        return spring_wire_class(self.material_record, self.spring_class)

    @property
    def wire_diameter(self) -> pint.Quantity:
        """Wire diameter d [mm]."""
        return Q(self.si["d"], "m").to("mm")

    @property
    def mean_diameter(self) -> pint.Quantity:
        """Mean coil diameter D [mm]."""
        return Q(self.si["D"], "m").to("mm")

    @property
    def outside_diameter(self) -> pint.Quantity:
        """Outside coil diameter D + d [mm]."""
        return Q(self.si["D"] + self.si["d"], "m").to("mm")

    @property
    def inside_diameter(self) -> pint.Quantity:
        """Inside coil diameter D - d [mm]."""
        return Q(self.si["D"] - self.si["d"], "m").to("mm")

    @property
    def index(self) -> float:
        """Spring index C = D/d [-]."""
        return self.si["D"] / self.si["d"]

    @property
    def elastic_modulus(self) -> pint.Quantity:
        """Young's modulus E of the wire used [GPa]."""
        return Q(self.si["E"], "Pa").to("GPa")

    @property
    def tensile_strength(self) -> pint.Quantity:
        """Minimum tensile strength S_ut of the wire at this diameter [MPa]."""
        return Q(self.si["Sut"], "Pa").to("MPa")


__all__ = [
    "ZimmerliData", "spring_index", "direct_shear_factor", "wahl_factor", "bergstrasser_factor",
    "curvature_factor", "torsion_spring_factors", "helical_rate", "helical_shear_stress", "mean_diameter_for_rate",
    "active_coils_for_rate", "active_coil_mass", "surge_frequency", "torsional_ultimate_strength", "zimmerli",
    "end_condition_constant", "spring_wire_class", "class_fraction", "wire_tensile_strength", "resolve_material",
    "spring_data", "SPRING_CLASSES", "HelicalSpring",
]
