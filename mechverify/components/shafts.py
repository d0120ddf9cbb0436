"""Shafts: a stepped round shaft, its stress-raising features, bearing supports and the loads of gears,
pulleys, couplings and masses; stress concentration per feature and the critical-speed closed forms.

The model lives here (geometry, load resolution into forces and torques, Kt of each feature); the
beam analysis on the frame FEA is :mod:`mechverify.fea.shafts` (the layer order puts ``fea`` above
``components``), the checks are :mod:`mechverify.checks.shafts`.

Coordinates: x along the shaft from its left end (the start of the first segment); y and z across
it, gravity along -z. A load's ``angle`` is measured in the y-z plane from +y towards +z.

References
----------
1. R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015: Sec. 7-4
   (Eqs. 7-7 to 7-16, Table 7-1), Sec. 7-5 (Table 7-2), Sec. 7-6 (Eqs. 7-22 to 7-24), Sec. 13-14
   (Eq. 13-36, gear force components), Sec. 14-... and Sec. 17-2 (belt tensions), Sec. 7-7 (keys).
2. W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., 2008 (the shoulder
   fillet and groove fits of :mod:`mechverify.fatigue.notch`).
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

from mechverify.errors import InputError, ValidityError
from mechverify.fatigue import notch
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike, to_si

G_STANDARD = 9.80665
DATA = Path(__file__).with_name("data") / "shafts.toml"
SUPPORT_KINDS = ("pinned", "fixed", "spring")
META_KEYS = ("source", "verified", "checked_against", "unverified_reason")  # table keys that are not rows
KEYSEAT_KINDS = ("profile", "sled_runner")


@cache
def data() -> dict[str, Any]:
    """The tables of ``components/data/shafts.toml`` (Shigley Tables 7-1, 7-2; DIN 6885-1)."""
    with DATA.open("rb") as f:
        return tomllib.load(f)


def _len(v: QuantityLike | float, name: str) -> float:
    return float(v) if isinstance(v, int | float) else to_si(v, "length", name)


# ------------------------------------------------------------------------------------------ geometry
@dataclass(frozen=True)
class Segment:
    """A cylindrical length of the shaft: outer ``diameter``, ``length``, optional ``bore`` (hollow). SI floats."""

    length: float
    diameter: float
    bore: float = 0.0

    def __post_init__(self) -> None:
        if not self.length > 0 or not self.diameter > 0:
            raise InputError(f"segment: length and diameter must be positive (got {self.length}, {self.diameter} m)")
        if not 0 <= self.bore < self.diameter:
            raise InputError(f"segment: the bore {self.bore * 1e3:g} mm must be smaller than the diameter "
                             f"{self.diameter * 1e3:g} mm")

    @classmethod
    def of(cls, length: QuantityLike, diameter: QuantityLike, bore: QuantityLike | None = None) -> Segment:
        return cls(_len(length, "length"), _len(diameter, "diameter"), _len(bore, "bore") if bore else 0.0)


@dataclass(frozen=True)
class Feature:
    """A stress raiser at ``x`` [m]: ``kind`` shoulder, keyseat, groove (retaining ring or U-groove), cross_hole
    or press_fit (the last two with given ``Kt``/``Kts``). ``radius``: fillet, keyseat-bottom or groove
    root radius; ``depth``: keyseat or groove depth; ``width``/``length``: key width and keyseat length;
    ``Kt``/``Kts`` override the fits; ``name`` labels it in results."""

    kind: str
    x: float
    radius: float = 0.0
    depth: float = 0.0
    width: float = 0.0
    length: float = 0.0
    keyseat: str = "profile"
    Kt: float | None = None
    Kts: float | None = None
    name: str = ""

    @property
    def label(self) -> str:
        """The name, or for an unnamed feature its kind and place in words (``"shoulder at 120 mm"``)."""
        return self.name or f"{self.kind.replace('_', ' ')} at {self.x * 1e3:g} mm"

    def __post_init__(self) -> None:
        if self.kind not in ("shoulder", "keyseat", "groove", "cross_hole", "press_fit"):
            raise InputError(f"feature {self.label}: kind must be shoulder, keyseat, groove, cross_hole or press_fit, "
                             f"got {self.kind!r}")
        if self.kind == "keyseat" and self.keyseat not in KEYSEAT_KINDS:
            raise InputError(f"feature {self.label}: keyseat must be one of {KEYSEAT_KINDS}, got {self.keyseat!r}")
        if self.kind in ("cross_hole", "press_fit") and self.Kt is None:
            raise InputError(f"feature {self.label}: a {self.kind} needs Kt (and Kts): no fit for it is built in")
        for k in ("radius", "depth", "width", "length"):
            if getattr(self, k) < 0:
                raise InputError(f"feature {self.label}: {k} must not be negative")


@dataclass(frozen=True)
class Support:
    """A bearing at ``x`` [m]: ``kind`` pinned (rotation free), fixed (rotation held) or spring (radial
    ``stiffness`` [N/m]); ``locating`` holds the axial motion (one bearing per shaft normally);
    ``bearing`` names the Table 7-2 type for the slope check."""

    name: str
    x: float
    kind: str = "pinned"
    stiffness: float = 0.0
    locating: bool = False
    bearing: str = "deep_groove_ball"

    def __post_init__(self) -> None:
        if self.kind not in SUPPORT_KINDS:
            raise InputError(f"support {self.name}: kind must be one of {SUPPORT_KINDS}, got {self.kind!r}")
        if self.kind == "spring" and not self.stiffness > 0:
            raise InputError(f"support {self.name}: a spring support needs a positive stiffness")
        if self.bearing not in data()["slope_allowance"] or self.bearing in META_KEYS:
            raise InputError(f"support {self.name}: bearing must be one of "
                             f"{sorted(k for k in data()['slope_allowance'] if k not in META_KEYS)}, "
                             f"got {self.bearing!r}")


@dataclass(frozen=True)
class ShaftLoad:
    """A resolved load at ``x`` [m]: force (Fx, Fy, Fz) [N], moment (Mx, My, Mz) [N m] with Mx the torque
    the element applies to the shaft; ``mass`` [kg] for the critical speed (weight included in Fz when
    ``weight`` is true); ``kind`` and ``name`` label it; ``pitch`` the diametral pitch [1/in] of a gear."""

    name: str
    x: float
    force: tuple[float, float, float] = (0.0, 0.0, 0.0)
    moment: tuple[float, float, float] = (0.0, 0.0, 0.0)
    kind: str = "force"
    mass: float = 0.0
    module: float = 0.0

    @property
    def torque(self) -> float:
        return self.moment[0]


def gear_load(name: str, x: float, pitch_diameter: float, torque: float, *, pressure_angle: float = 20.0,
              helix_angle: float = 0.0, angle: float = 90.0, mass: float = 0.0, module: float = 0.0) -> ShaftLoad:
    """Forces of a spur or helical gear on its shaft (Shigley 10th ed. Eq. 13-36 and Sec. 13-16).

    ``torque`` [N m]: the torque the gear applies to the shaft (+ about +x; negative for a driving
    pinion taking torque off the shaft). ``angle`` [deg]: the position of the mesh point around the
    shaft (from +y towards +z). Tangential ``Wt = 2 T / d`` (at the mesh, in the sense that makes the
    torque), radial ``Wr = Wt tan(phi_n) / cos(psi)`` towards the gear centre, axial
    ``Wa = Wt tan(psi)`` along +x for a positive product of torque and helix angle; the axial force
    acting at the pitch radius adds a bending moment ``Wa d / 2``.
    """
    if not pitch_diameter > 0:
        raise InputError(f"gear {name}: pitch diameter must be positive")
    if not 0 <= pressure_angle < 45 or not -45 < helix_angle < 45:
        raise InputError(f"gear {name}: pressure angle in [0, 45) deg and helix angle in (-45, 45) deg")
    r = pitch_diameter / 2
    th = math.radians(angle)
    ey, ez = math.cos(th), math.sin(th)  # mesh point direction
    Ft = torque / r  # along t = (-sin, cos): (r e) x (Ft t) = r Ft x-hat
    Wt = abs(Ft)
    Wr = Wt * math.tan(math.radians(pressure_angle)) / math.cos(math.radians(helix_angle))
    Fa = Ft * math.tan(math.radians(helix_angle))
    Fy = -Ft * ez - Wr * ey
    Fz = Ft * ey - Wr * ez
    # moment of the axial force at the mesh point about the axis: (r e) x (Fa x-hat)
    My, Mz = r * ez * Fa, -r * ey * Fa
    return ShaftLoad(name, x, (Fa, Fy, Fz - mass * G_STANDARD), (torque, My, Mz), "gear", mass, module)


def belt_tensions(torque: float, diameter: float, ratio: float) -> tuple[float, float]:
    """Tight and slack belt tensions (T1, T2) [N] for a torque [N m] and ratio T1/T2 > 1: ``T1 - T2 = 2|T|/D``
    (Shigley 10th ed. Sec. 17-2; the ratio is exp(f phi) for a flat belt at the slip limit, Eq. 17-7)."""
    if not ratio > 1:
        raise InputError(f"belt tension ratio T1/T2 must exceed 1, got {ratio!r}")
    dT = 2 * abs(torque) / diameter
    T2 = dT / (ratio - 1)
    return T2 * ratio, T2


def pulley_load(name: str, x: float, diameter: float, *, torque: float = 0.0, ratio: float | None = None,
                tensions: tuple[float, float] | None = None, angle: float = 90.0, mass: float = 0.0) -> ShaftLoad:
    """A belt or chain pulley: the shaft carries ``T1 + T2`` along the belt direction ``angle`` [deg] (both
    strands taken parallel) and the torque ``torque`` [N m] (+ about +x); tensions from ``ratio`` and the
    torque (:func:`belt_tensions`) or given as ``tensions`` (T1, T2), whose difference then sets the torque
    magnitude (with the sign of ``torque``, + when zero)."""
    if not diameter > 0:
        raise InputError(f"pulley {name}: diameter must be positive")
    if tensions is not None:
        T1, T2 = tensions
        if T1 < 0 or T2 < 0:
            raise InputError(f"pulley {name}: tensions must not be negative")
        torque = math.copysign(abs(T1 - T2) * diameter / 2, torque if torque else 1.0)
    elif ratio is not None:
        T1, T2 = belt_tensions(torque, diameter, ratio)
    else:
        raise InputError(f"pulley {name}: give the tension ratio or the tensions")
    th = math.radians(angle)
    F = T1 + T2
    return ShaftLoad(name, x, (0.0, F * math.cos(th), F * math.sin(th) - mass * G_STANDARD), (torque, 0.0, 0.0),
                     "pulley", mass)


def force_load(name: str, x: float, force: Sequence[float] = (0.0, 0.0, 0.0), torque: float = 0.0,
               mass: float = 0.0, kind: str = "force") -> ShaftLoad:
    """A given force (Fx, Fy, Fz) [N] and torque [N m] at x; ``mass`` [kg] adds its weight (-z) and enters the
    critical speed (an overhung mass, a coupling hub, a drum)."""
    fx, fy, fz = (float(c) for c in force)
    return ShaftLoad(name, x, (fx, fy, fz - mass * G_STANDARD), (torque, 0.0, 0.0), kind, mass)


# ------------------------------------------------------------------------------------------ the shaft
@dataclass(frozen=True)
class Shaft:
    """A stepped round shaft: segments from x = 0, features, supports, loads and material.

    Raises:
        InputError: a feature, support or load outside the shaft; a fillet larger than its step; a keyseat
            or groove deeper than the radius; fewer than one support; torques that do not balance.
    """

    name: str
    segments: tuple[Segment, ...]
    material: Material
    supports: tuple[Support, ...]
    loads: tuple[ShaftLoad, ...] = ()
    features: tuple[Feature, ...] = ()
    finish: str = "machined"
    reliability: float = 0.99
    speed: float = 0.0  # rad/s
    rotating: bool = True
    torque_alternating_fraction: float = 0.0
    shaft_mass: bool = True  # the shaft's own mass in the critical speed
    key_standard: str = "din6885"  # or "ansi" (Shigley Table 7-6 square keys)
    notes: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        if not self.segments:
            raise InputError(f"shaft {self.name}: give at least one segment")
        if not self.supports:
            raise InputError(f"shaft {self.name}: no supports; give the bearings")
        L = self.length
        tol = 1e-9
        for s in self.supports:
            if not -tol <= s.x <= L + tol:
                raise InputError(f"shaft {self.name}: support {s.name} at x = {s.x * 1e3:g} mm is outside the shaft "
                                 f"(0 .. {L * 1e3:g} mm)")
        for ld in self.loads:
            if not -tol <= ld.x <= L + tol:
                raise InputError(f"shaft {self.name}: load {ld.name} at x = {ld.x * 1e3:g} mm is outside the shaft "
                                 f"(0 .. {L * 1e3:g} mm)")
        for f in self.features:
            self._check_feature(f)
        if len({s.name for s in self.supports}) != len(self.supports):
            raise InputError(f"shaft {self.name}: support names must be unique")
        T = sum(ld.torque for ld in self.loads)
        scale = max([abs(ld.torque) for ld in self.loads] + [1e-9])
        if abs(T) > 1e-6 * scale and abs(T) > 1e-9:
            raise InputError(f"shaft {self.name}: the torques do not balance (sum {T:.4g} N m); a shaft turning at "
                             "steady speed needs torque in = torque out")

    # ---------------------------------------------------------------- geometry
    @property
    def length(self) -> float:
        return sum(s.length for s in self.segments)

    @property
    def boundaries(self) -> list[float]:
        xs = [0.0]
        for s in self.segments:
            xs.append(xs[-1] + s.length)
        return xs

    def segment_at(self, x: float, side: int = 0) -> Segment:
        """The segment holding ``x``; at a step, ``side`` -1 picks the left one, +1 the right, 0 the smaller."""
        b = self.boundaries
        for i, s in enumerate(self.segments):
            if b[i] - 1e-12 <= x <= b[i + 1] + 1e-12:
                if abs(x - b[i + 1]) < 1e-9 and i + 1 < len(self.segments):
                    nxt = self.segments[i + 1]
                    if side > 0 or (side == 0 and nxt.diameter < s.diameter):
                        return nxt
                return s
        raise InputError(f"shaft {self.name}: x = {x * 1e3:g} mm is outside the shaft (0 .. {self.length * 1e3:g} mm)")

    def step_at(self, x: float) -> tuple[Segment, Segment] | None:
        """(smaller, larger) segments meeting at x, or None when x is not a step."""
        b = self.boundaries
        for i in range(1, len(b) - 1):
            if abs(b[i] - x) < 1e-6:
                a, c = self.segments[i - 1], self.segments[i]
                return (a, c) if a.diameter <= c.diameter else (c, a)
        return None

    def _check_feature(self, f: Feature) -> None:
        where = f"shaft {self.name}: feature {f.name or f.kind} at x = {f.x * 1e3:g} mm"
        if not -1e-9 <= f.x <= self.length + 1e-9:
            raise InputError(f"{where} is outside the shaft (0 .. {self.length * 1e3:g} mm)")
        seg = self.segment_at(f.x)
        if f.kind == "shoulder":
            st = self.step_at(f.x)
            if st is None:
                raise InputError(f"{where}: a shoulder must sit at a diameter step (steps at "
                                 f"{', '.join(f'{b * 1e3:g}' for b in self.boundaries[1:-1])} mm)")
            small, large = st
            h = (large.diameter - small.diameter) / 2
            if f.Kt is None and not f.radius > 0:
                raise InputError(f"{where}: give the fillet radius")
            if f.radius > h + 1e-12:
                raise InputError(f"{where}: fillet radius {f.radius * 1e3:g} mm is larger than the step height "
                                 f"{h * 1e3:g} mm")
        if f.kind in ("keyseat", "groove") and f.depth >= seg.diameter / 2:
            raise InputError(f"{where}: {f.kind} depth {f.depth * 1e3:g} mm is not less than the radius "
                             f"{seg.diameter / 2 * 1e3:g} mm")
        if f.kind == "keyseat" and f.length and f.x + f.length > self.length + 1e-9:
            raise InputError(f"{where}: the keyseat runs past the end of the shaft")

    # ---------------------------------------------------------------- stress concentration
    def stress_concentration(self, f: Feature) -> tuple[float, float, str]:
        """(Kt bending, Kts torsion, source) of a feature: the Peterson fits for shoulder fillets and
        U-grooves, Shigley Table 7-1 for keyseats and retaining-ring grooves without a root radius, given
        values otherwise. Outside a fit's range the Table 7-1 estimate is used (stated in the source)."""
        return self._kt(f)[:3]  # type: ignore[return-value]

    def data_warnings(self, f: Feature) -> tuple[str, ...]:
        """The caveat of a Table 7-1 row the feature's Kt comes from when that row is flagged unverified."""
        key = self._kt(f)[3]
        return table_caveat("kt_first_iteration", key, f"Kt of {f.label}") if key else ()

    def _kt(self, f: Feature) -> tuple[float, float, str, str | None]:
        t71 = data()["kt_first_iteration"]
        if f.Kt is not None:
            return f.Kt, f.Kts if f.Kts is not None else f.Kt, "given", None
        d = self.segment_at(f.x).diameter
        if f.kind == "shoulder":
            small, large = self.step_at(f.x)  # type: ignore[misc]
            try:
                D_, d_, r_ = (Q(v, "m") for v in (large.diameter, small.diameter, f.radius))
                kt = notch.kt_shoulder_fillet(D_, d_, r_, "bending").m
                kts = notch.kt_shoulder_fillet(D_, d_, r_, "torsion").m
                return kt, kts, "Peterson 3rd ed. Charts 3.4/3.12 fits", None
            except ValidityError as exc:
                key = "shoulder_sharp" if f.radius / small.diameter < 0.06 else "shoulder_well_rounded"
                row = t71[key]
                return row["bending"], row["torsion"], f"Shigley 10th ed. Table 7-1 (fit out of range: {exc})", key
        if f.kind == "keyseat":
            if f.keyseat == "sled_runner":
                row = t71["keyseat_sled_runner"]
                return row["bending"], t71["keyseat_end_mill"]["torsion"], \
                    "Shigley 10th ed. Table 7-1 (sled runner; Kts of the profile keyseat)", "keyseat_sled_runner"
            row = t71["keyseat_end_mill"]
            return row["bending"], row["torsion"], "Shigley 10th ed. Table 7-1 (end-mill keyseat, r/d = 0.02)", \
                "keyseat_end_mill"
        if f.kind == "groove":
            row = t71["retaining_ring_groove"]
            if f.radius > 0:
                try:
                    kt = notch.kt_groove(Q(d, "m"), Q(d - 2 * f.depth, "m"), Q(f.radius, "m"), "bending").m
                    return kt, min(kt, row["torsion"]), "Peterson 3rd ed. U-groove fit (bending); Kts <= Table 7-1", \
                        "retaining_ring_groove"
                except ValidityError:
                    pass
            return row["bending"], row["torsion"], "Shigley 10th ed. Table 7-1 (retaining-ring groove)", \
                "retaining_ring_groove"
        raise InputError(f"feature {f.name}: no Kt")  # pragma: no cover (validated)

    def notch_radius(self, f: Feature) -> float:
        """The root radius for the notch sensitivity: given, or r/d = 0.02 of Table 7-1 for a keyseat or groove."""
        if f.radius > 0:
            return f.radius
        return 0.02 * self.segment_at(f.x).diameter

    def net_diameter(self, f: Feature) -> tuple[float, float]:
        """(outer, bore) diameters of the nominal section at a feature (the smaller side of a step; a groove's
        root diameter; a keyseat's full diameter, as Table 7-1's Kt refers to it)."""
        seg = self.segment_at(f.x)
        if f.kind == "groove":
            return seg.diameter - 2 * f.depth, seg.bore
        return seg.diameter, seg.bore


def section_moduli(D: float, d: float = 0.0) -> tuple[float, float]:
    """(bending W = pi (D^4 - d^4) / (32 D), torsion Wt = 2 W) [m^3] of a round (hollow) section."""
    W = math.pi * (D**4 - d**4) / (32 * D)
    return W, 2 * W


# ------------------------------------------------------------------------------------------ critical speed
def critical_speed_uniform(length: float, E: float, I: float, mass_per_length: float) -> float:
    """First critical speed [rad/s] of a uniform simply supported shaft, Shigley 10th ed. Eq. 7-22:
    ``omega_1 = (pi / l)^2 sqrt(E I / (m'))`` with m' = A gamma / g the mass per length [kg/m]."""
    if not (length > 0 and E > 0 and I > 0 and mass_per_length > 0):
        raise InputError("critical_speed_uniform: all inputs must be positive")
    return (math.pi / length) ** 2 * math.sqrt(E * I / mass_per_length)


def rayleigh_critical_speed(masses: Sequence[float], deflections: Sequence[float], g: float = G_STANDARD) -> float:
    """Rayleigh's first critical speed [rad/s], Shigley 10th ed. Eq. 7-23:
    ``omega_1 = sqrt(g sum(w_i y_i) / sum(w_i y_i^2))`` with w_i = m_i g and y_i the static deflections [m]
    under all the weights together (signs: in the direction of each weight)."""
    num = sum(m * y for m, y in zip(masses, deflections, strict=True))
    den = sum(m * y * y for m, y in zip(masses, deflections, strict=True))
    if not num > 0 or not den > 0:
        raise InputError("rayleigh_critical_speed: the deflections under the weights must be non-zero")
    return math.sqrt(g * num / den)


def dunkerley_critical_speed(masses: Sequence[float], self_influence: Sequence[float]) -> float:
    """Dunkerley's estimate [rad/s] (a lower bound), Shigley 10th ed. Eq. 7-24 / 7-32:
    ``1/omega_1^2 = sum(m_i delta_ii)`` with delta_ii the deflection at i under a unit force at i [m/N]."""
    s = sum(m * d for m, d in zip(masses, self_influence, strict=True))
    if not s > 0:
        raise InputError("dunkerley_critical_speed: need at least one mass with a positive influence coefficient")
    return 1.0 / math.sqrt(s)


# ------------------------------------------------------------------------------------------ provenance
def table_caveat(table: str, row: str | None = None, what: str = "") -> tuple[str, ...]:
    """("data not verified against source: ...",) when a table of ``shafts.toml`` (or its ``row``) is flagged
    ``verified = false``; () for a verified one. A row's own flag wins over the table's."""
    tab = data()[table]
    entry = tab.get(row, {}) if row else {}
    ok = entry.get("verified", tab.get("verified", False)) if isinstance(entry, dict) else tab.get("verified", False)
    if ok:
        return ()
    why = (entry.get("unverified_reason") if isinstance(entry, dict) else None) or tab.get("unverified_reason",
                                                                                           "not checked")
    return (f"data not verified against source: {what or table}{f' ({row})' if row else ''} "
            f"[{tab.get('source', table)}: {why}]",)


# ------------------------------------------------------------------------------------------ keys
def _din6885_row(d: float) -> dict[str, Any]:
    dm = d * 1e3
    for row in data()["din6885"]["rows"]:
        if row["d_min"] < dm <= row["d_max"]:
            return row
    raise ValidityError(f"DIN 6885-1 table covers shaft diameters 10..110 mm, got {dm:g} mm")


def din6885_key(d: float) -> dict[str, float]:
    """DIN 6885-1 parallel key for shaft diameter d [m]: {b, h, t1} [m] (rows checked against the public tables
    named in the data file)."""
    row = _din6885_row(d)
    return {"b": row["b"] / 1e3, "h": row["h"] / 1e3, "t1": row["t1"] / 1e3}


def key_caveat(d: float, standard: str = "din6885") -> tuple[str, ...]:
    """The caveat of the standard key row for shaft diameter d [m] when it is flagged unverified."""
    if standard == "din6885":
        row = _din6885_row(d)
        if row.get("verified", data()["din6885"].get("verified", False)):
            return ()
        return (f"data not verified against source: DIN 6885-1 key row {row['d_min']}..{row['d_max']} mm",)
    return table_caveat("ansi_square_keys", what="Shigley Table 7-6 key row")


def ansi_square_key(d: float) -> dict[str, float]:
    """Inch square key for shaft diameter d [m] (Shigley 10th ed. Table 7-6): {b, h, t1} [m] (t1 the keyway depth)."""
    di = d / 0.0254
    for row in data()["ansi_square_keys"]["rows"]:
        if row["d_min"] < di <= row["d_max"] + 1e-9:
            return {"b": row["w"] * 0.0254, "h": row["h"] * 0.0254, "t1": row["depth"] * 0.0254}
    raise ValidityError(f"Table 7-6 square keys cover shaft diameters 5/16..3 1/4 in, got {di:.4g} in")


def standard_key(d: float, standard: str = "din6885") -> dict[str, float]:
    """The parallel key of a standard ("din6885" or "ansi") for shaft diameter d [m]: {b, h, t1} [m]."""
    if standard == "din6885":
        return din6885_key(d)
    if standard == "ansi":
        return ansi_square_key(d)
    raise InputError(f"key standard must be 'din6885' or 'ansi', got {standard!r}")


def key_stresses(torque: float, d: float, b: float, h: float, t1: float, length: float) -> tuple[float, float]:
    """(shear tau = F/(b l), crushing p = F/((h - t1) l)) [Pa] of a parallel key with F = 2T/d at the shaft
    surface (Shigley 10th ed. Sec. 7-7, Ex. 7-6: shear on b l, bearing on the hub-side height; DIN 6885
    keys stand h - t1 above the shaft)."""
    if not (d > 0 and b > 0 and h > t1 >= 0 and length > 0):
        raise InputError("key: need d, b, length > 0 and h > t1")
    F = 2 * abs(torque) / d
    return F / (b * length), F / ((h - t1) * length)


def slope_allowance(bearing: str) -> tuple[float, float]:
    """(lower, upper) typical maximum slope [rad] of a bearing or gear type, Shigley 10th ed. Table 7-2."""
    tab = data()["slope_allowance"]
    if bearing not in tab or bearing in META_KEYS:
        raise InputError(f"bearing type {bearing!r}: one of "
                         f"{sorted(k for k in tab if k not in META_KEYS)}")
    lo, hi = tab[bearing]
    return float(lo), float(hi)


def gear_deflection_allowance(diametral_pitch: float) -> float:
    """Allowed transverse deflection [m] at a spur gear by diametral pitch P [1/in], Shigley 10th ed. Table 7-2."""
    t = data()["gear_deflection_allowance_in"]
    v = t["P_up_to_10"] if diametral_pitch <= 10 else t["P_11_to_19"] if diametral_pitch < 20 else t["P_20_to_50"]
    return v * 0.0254


__all__ = ["Segment", "Feature", "Support", "ShaftLoad", "Shaft", "gear_load", "pulley_load", "force_load",
           "belt_tensions", "section_moduli", "critical_speed_uniform", "rayleigh_critical_speed",
           "dunkerley_critical_speed", "din6885_key", "ansi_square_key", "standard_key",
           "key_stresses", "slope_allowance", "gear_deflection_allowance", "table_caveat", "key_caveat"]
