"""Helical compression springs of round wire: geometry by end type, rate, stresses, buckling, surge,
fatigue (Zimmerli data with a mean-stress criterion) and the spring as a bendable column (Timoshenko).

References
----------
[1] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill 2015, Ch. 10:
    Table 10-1 (end types), Sec. 10-5 Eqs. (10-10)..(10-13) (stability), Table 10-6 (static allowables),
    Sec. 10-8 (surge), Secs. 10-9, 10-10 (fatigue with Zimmerli data).
[2] EN 13906-1:2013, Sec. 9 (buckling, same formula as [1] Eq. (10-10)); Sec. 10 (minimum sum of gaps).
[3] S. P. Timoshenko, J. M. Gere, Theory of Elastic Stability, 2nd ed., McGraw-Hill 1961, Sec. 2.18
    (buckling of helical springs: compressive, bending and shear rigidities α₀, β₀, γ₀).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from typing import Any

import pint

from mechverify.components import spring_formulas as sf
from mechverify.errors import InputError, UnknownNameError
from mechverify.fatigue import criteria
from mechverify.frozen import set_fields
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike, fmt, from_si, to_si

SHIGLEY = "Shigley's Mechanical Engineering Design, 10th ed. (2015)"


class EndType(StrEnum):
    """End type of a compression spring (Shigley [1] Table 10-1)."""

    PLAIN = "plain"
    PLAIN_GROUND = "plain-ground"
    SQUARED = "squared"
    SQUARED_GROUND = "squared-ground"

    @classmethod
    def of(cls, value: str | EndType) -> EndType:
        if isinstance(value, EndType):
            return value
        key = str(value).strip().lower().replace("_", "-").replace(" and ", "-").replace(" ", "-")
        key = {"closed": "squared", "closed-ground": "squared-ground", "squared-and-ground": "squared-ground",
               "plain-and-ground": "plain-ground"}.get(key, key)
        try:
            return cls(key)
        except ValueError:
            raise UnknownNameError("spring end type", str(value), [e.value for e in cls]) from None

    @property
    def end_coils(self) -> int:
        """Inactive end coils Nₑ: plain 0, plain-ground 1, squared 2, squared-ground 2 ([1] Table 10-1)."""
        return {"plain": 0, "plain-ground": 1, "squared": 2, "squared-ground": 2}[self.value]

    def solid_length(self, d: float, Nt: float) -> float:
        """Solid length Lₛ [m]: d(Nₜ + 1) for plain and squared ends, dNₜ for ground ends ([1] Table 10-1)."""
        return d * Nt if self.value.endswith("ground") else d * (Nt + 1)

    def pitch(self, L0: float, d: float, Na: float) -> float:
        """Pitch p [m]: (L₀ - d)/Nₐ, L₀/(Nₐ + 1), (L₀ - 3d)/Nₐ, (L₀ - 2d)/Nₐ ([1] Table 10-1)."""
        return {"plain": (L0 - d) / Na, "plain-ground": L0 / (Na + 1), "squared": (L0 - 3 * d) / Na,
                "squared-ground": (L0 - 2 * d) / Na}[self.value]


@dataclass(frozen=True)
class SpringFatigue:
    """Fatigue of a spring cycling between two forces (Shigley [1] Secs. 10-9, 10-10)."""

    criterion: str
    tau_a: pint.Quantity  # stress amplitude, curvature-corrected
    tau_m: pint.Quantity  # mean stress
    Ssu: pint.Quantity  # torsional modulus of rupture, 0.67 Sut
    Sse: pint.Quantity  # torsional endurance (fully reversed) from the Zimmerli point and the criterion
    Ssa: pint.Quantity  # strength amplitude on the proportional load line, n_f * tau_a
    n_f: float  # fatigue safety factor
    n_y: float  # first-cycle torsional yield (Langer) safety factor, Ssy / tau_max
    Ssy: pint.Quantity
    zimmerli: sf.ZimmerliData


@dataclass(frozen=True)
class SpringRigidities:
    """Timoshenko's equivalent-column rigidities of a helical spring at length L ([3] Sec. 2.18).

    ``alpha`` compressive rigidity [N] (force per unit axial strain), ``beta`` flexural rigidity
    [N·m²] (the spring's "EI"), ``gamma`` shear rigidity [N] (force per unit shear strain).
    """

    alpha: pint.Quantity
    beta: pint.Quantity
    gamma: pint.Quantity
    length: pint.Quantity


@dataclass(frozen=True)
class CompressionSpring(sf.HelicalSpring):
    """A helical compression spring of round wire.

    Give the wire diameter ``d``, one of ``D`` (mean), ``OD`` (outside) or ``ID`` (inside) coil
    diameter, one of ``Na`` (active) or ``Nt`` (total) coils, the ``end`` type, the free length ``L0``
    and the ``material`` (name or :class:`Material`; default ASTM A228 music wire). ``G``, ``E``,
    ``Sut`` override the material's values (Shigley Table 10-5 lists G and E by wire size);
    ``spring_class`` overrides the Table 10-6 class found from the ASTM designation; ``set_removed``
    selects the allowable for springs whose set was removed; ``peened`` the Zimmerli data.
    """

    d: Any
    L0: QuantityLike
    D: Any = None
    OD: Any = None
    ID: Any = None
    Na: float | None = None
    Nt: float | None = None
    end: str | EndType = EndType.SQUARED_GROUND
    material: str | Material = "A228"
    G: QuantityLike | None = None
    E: QuantityLike | None = None
    Sut: QuantityLike | None = None
    density: QuantityLike | None = None
    spring_class: str | None = None
    set_removed: bool = False
    peened: bool = False
    name: str = "spring"

    def __post_init__(self) -> None:
        set_fields(self, end=EndType.of(self.end))
        self.validate()

    def _si_values(self) -> dict[str, float]:
        d, D = sf.coil_geometry(self.name, self.d, self.D, self.OD, self.ID)
        end = EndType.of(self.end)
        if (self.Na is None) == (self.Nt is None):
            raise InputError(f"{self.name}: give exactly one of Na (active coils) or Nt (total coils)")
        Na = float(self.Na) if self.Na is not None else float(self.Nt) - end.end_coils
        Nt = Na + end.end_coils
        if Na <= 0:
            raise InputError(f"{self.name}: active coils must be positive, got Na = {Na:g} "
                             f"({end.value} ends have {end.end_coils} inactive coils)")
        L0 = to_si(self.L0, "length", "L0")
        Ls = end.solid_length(d, Nt)
        if L0 <= Ls:
            raise InputError(f"{self.name}: solid length {fmt(Q(Ls, 'm'), 'mm')} is not below the free length "
                             f"L0 = {fmt(Q(L0, 'm'), 'mm')}; the spring cannot be compressed")
        mat = self.material_record
        wire = self._wire_si(d, ("G", "E"))
        rho = (to_si(self.density, "density", "density") if self.density is not None
               else (to_si(mat.density, "density", "density") if mat.density is not None else float("nan")))
        return dict(d=d, D=D, Na=Na, Nt=Nt, L0=L0, Ls=Ls, **wire, rho=rho)

    # ------------------------------------------------------------------------------ geometry
    @property
    def shear_modulus(self) -> pint.Quantity:
        """Shear modulus G of the wire used [GPa]."""
        return Q(self.si["G"], "Pa").to("GPa")

    @property
    def active_coils(self) -> float:
        return self.si["Na"]

    @property
    def total_coils(self) -> float:
        return self.si["Nt"]

    @property
    def free_length(self) -> pint.Quantity:
        return Q(self.si["L0"], "m").to("mm")

    @property
    def solid_length(self) -> pint.Quantity:
        """Lₛ by end type (Shigley [1] Table 10-1)."""
        return Q(self.si["Ls"], "m").to("mm")

    @property
    def pitch(self) -> pint.Quantity:
        """Coil pitch p by end type (Shigley [1] Table 10-1)."""
        s = self.si
        return Q(self.end.pitch(s["L0"], s["d"], s["Na"]), "m").to("mm")

    @property
    def bergstrasser_factor(self) -> float:
        return sf.bergstrasser_factor(self.index)

    @property
    def wahl_factor(self) -> float:
        return sf.wahl_factor(self.index)

    @property
    def direct_shear_factor(self) -> float:
        return sf.direct_shear_factor(self.index)

    @property
    def stress_factor(self) -> float:
        """The factor used for working stresses: K_s with set removed, else K_B (Shigley [1] Table 10-6)."""
        return self.direct_shear_factor if self.set_removed else self.bergstrasser_factor

    # ------------------------------------------------------------------------------ rate, forces
    @property
    def rate(self) -> pint.Quantity:
        """k = d⁴G/(8D³Nₐ) (Shigley [1] Eq. (10-9))."""
        s = self.si
        return from_si(sf.helical_rate.si(s["d"], s["D"], s["Na"], s["G"]), "force_per_length").to("N/mm")

    def _k(self) -> float:
        s = self.si
        return sf.helical_rate.si(s["d"], s["D"], s["Na"], s["G"])

    @property
    def solid_deflection(self) -> pint.Quantity:
        """Deflection from free to solid length, L₀ - Lₛ."""
        return Q(self.si["L0"] - self.si["Ls"], "m").to("mm")

    @property
    def solid_force(self) -> pint.Quantity:
        """Force to close the spring solid, k(L₀ - Lₛ)."""
        return from_si(self._k() * (self.si["L0"] - self.si["Ls"]), "force")

    def force(self, deflection: QuantityLike) -> pint.Quantity:
        """F = k·y for a deflection y up to the solid deflection."""
        y = to_si(deflection, "length", "deflection")
        self._within_travel(y)
        return from_si(self._k() * y, "force")

    def deflection(self, force: QuantityLike) -> pint.Quantity:
        """y = F/k; forces beyond the solid force raise :class:`InputError` (the spring would be solid)."""
        F = to_si(force, "force", "force")
        y = F / self._k()
        self._within_travel(y)
        return Q(y, "m").to("mm")

    def length_at(self, force: Any) -> pint.Quantity:
        """Working length L = L₀ - F/k."""
        return (self.free_length - self.deflection(force)).to("mm")

    def _within_travel(self, y: float) -> None:
        if y < 0:
            raise InputError(f"{self.name}: deflection must be >= 0 (compression), got {fmt(Q(y, 'm'), 'mm')}")
        if y > self.si["L0"] - self.si["Ls"] * (1 - 1e-12):
            raise InputError(f"{self.name}: deflection {fmt(Q(y, 'm'), 'mm')} exceeds the travel to solid "
                             f"{fmt(self.solid_deflection)} (solid force {fmt(self.solid_force, 'N')})")

    # ------------------------------------------------------------------------------ stresses
    def shear_stress(self, force: QuantityLike, factor: str = "auto") -> pint.Quantity:
        """τ = K·8FD/(πd³) (Shigley [1] Eqs. (10-2), (10-7)).

        ``factor``: ``"auto"`` (K_s with set removed, else K_B), ``"bergstrasser"``, ``"wahl"``,
        ``"direct"`` (K_s) or ``"none"`` (K = 1).
        """
        F = to_si(force, "force", "force")
        K = self._factor(factor)
        return from_si(sf.helical_shear_stress.si(F, self.si["D"], self.si["d"], K), "pressure").to("MPa")

    def _factor(self, factor: str) -> float:
        table = {"auto": self.stress_factor, "bergstrasser": self.bergstrasser_factor, "wahl": self.wahl_factor,
                 "direct": self.direct_shear_factor, "none": 1.0}
        if factor not in table:
            raise UnknownNameError("stress factor", factor, table)
        return table[factor]

    @property
    def solid_stress(self) -> pint.Quantity:
        """Shear stress when closed solid (force k(L₀ - Lₛ))."""
        return self.shear_stress(self.solid_force)

    @property
    def allowable_static_stress(self) -> pint.Quantity:
        """Torsional yield S_sy for static service, a fraction of S_ut by wire class (Shigley [1] Table 10-6).

        Music wire and cold-drawn carbon steel 45 % (60 % with set removed); hardened and tempered
        carbon and low-alloy 50 % (65 %); austenitic stainless and nonferrous 35 % (55 %).
        """
        key = "set_removed" if self.set_removed else "set_not_removed"
        return (sf.class_fraction(self.wire_class, key) * self.tensile_strength).to("MPa")

    # ------------------------------------------------------------------------------ buckling
    def critical_deflection(self, end: str = "fixed-fixed") -> pint.Quantity | None:
        """Deflection at which the spring buckles, or ``None`` if it is absolutely stable.

        y_cr = L₀·C₁'[1 - √(1 - C₂'/λ²)], λ = αL₀/D, C₁' = E/(2(E - G)), C₂' = 2π²(E - G)/(2G + E)
        (Shigley [1] Eqs. (10-10)..(10-12); identical to EN 13906-1 [2] Eq. (27) with ν = α).
        ``end`` names the end condition (``fixed-fixed`` between parallel plates, ``fixed-pinned``,
        ``pinned-pinned``, ``fixed-guided``, ``fixed-free``) or is α itself.
        """
        alpha = self._alpha(end)
        s = self.si
        E, G = s["E"], s["G"]
        lam = alpha * s["L0"] / s["D"]
        C1 = E / (2 * (E - G))
        C2 = 2 * math.pi**2 * (E - G) / (2 * G + E)
        disc = 1 - C2 / lam**2
        if disc < 0:
            return None
        return Q(s["L0"] * C1 * (1 - math.sqrt(disc)), "m").to("mm")

    def critical_free_length(self, end: str = "fixed-fixed") -> pint.Quantity:
        """Longest free length for absolute stability L₀ < (πD/α)·√(2(E - G)/(2G + E)).

        Shigley [1] Eq. (10-13) (for steels L₀ < 2.63 D/α, Eq. (10-14)).
        """
        alpha = self._alpha(end)
        s = self.si
        E, G = s["E"], s["G"]
        return Q(math.pi * s["D"] / alpha * math.sqrt(2 * (E - G) / (2 * G + E)), "m").to("mm")

    @staticmethod
    def end_condition_constant(end: str | float) -> float:
        """The end-condition constant alpha of Shigley Table 10-2 (EN 13906-1 nu) for ``end`` (a name of
        Shigley Table 10-2 end condition or a positive number)."""
        return CompressionSpring._alpha(end)

    @staticmethod
    def _alpha(end: str | float) -> float:
        if isinstance(end, int | float) and not isinstance(end, bool):
            if end <= 0:
                raise InputError(f"end-condition constant alpha must be positive, got {end!r}")
            return float(end)
        return sf.end_condition_constant(str(end))

    # ------------------------------------------------------------------------------ dynamics
    @property
    def active_mass(self) -> pint.Quantity:
        s = self.si
        if not math.isfinite(s["rho"]):
            raise InputError(f"material {self.material_record.name!r} has no density; give density=")
        return from_si(sf.active_coil_mass.si(s["d"], s["D"], s["Na"], s["rho"]), "mass").to("g")

    def surge_frequency(self, one_end_free: bool = False) -> pint.Quantity:
        """Fundamental surge frequency: ½√(k/m) between plates, ¼√(k/m) with one end free (Shigley [1] Sec. 10-8)."""
        return sf.surge_frequency(self.rate, self.active_mass, one_end_free=one_end_free).to("Hz")

    # ------------------------------------------------------------------------------ fatigue
    def fatigue(self, F_min: QuantityLike, F_max: QuantityLike, criterion: str = "gerber") -> SpringFatigue:
        """Infinite-life fatigue of the spring cycling between ``F_min`` and ``F_max`` (both compressive, >= 0).

        Shigley [1] Secs. 10-9, 10-10: τₐ = K_B·8FₐD/(πd³), τₘ = K_B·8FₘD/(πd³) with Fₐ = (F_max - F_min)/2,
        Fₘ = (F_max + F_min)/2; S_su = 0.67 S_ut; Zimmerli's (S_sa, S_sm) point gives the fully reversed
        torsional endurance S_se through the criterion (Gerber S_se = S_sa/(1 - (S_sm/S_su)²), Goodman
        S_se = S_sa/(1 - S_sm/S_su)); the safety factor is along the proportional load line
        (:mod:`mechverify.fatigue.criteria`). ``criterion="sines"`` takes S_se = S_sa and ignores the
        mean stress (n = S_sa/τₐ). The curvature factor K_B is applied to both components, as in [1].
        """
        F1, F2 = to_si(F_min, "force", "F_min"), to_si(F_max, "force", "F_max")
        if F1 < 0 or F2 < F1:
            raise InputError(f"{self.name}: need 0 <= F_min <= F_max, got F_min = {fmt(Q(F1, 'N'))}, "
                             f"F_max = {fmt(Q(F2, 'N'))}")
        self._within_travel(F2 / self._k())
        z = sf.zimmerli(self.peened, Q(self.si["d"], "m"))
        KB = self.bergstrasser_factor
        D, d = self.si["D"], self.si["d"]
        ta = sf.helical_shear_stress.si((F2 - F1) / 2, D, d, KB)
        tm = sf.helical_shear_stress.si((F2 + F1) / 2, D, d, KB)
        Ssu = 0.67 * self.si["Sut"]
        Ssy = to_si(self.allowable_static_stress, "pressure")
        Ssa_z, Ssm_z = z.Ssa.m_as("Pa"), z.Ssm.m_as("Pa")
        if criterion == "sines":
            Sse = Ssa_z
            n_f = math.inf if ta == 0 else Sse / ta
        elif criterion in ("gerber", "goodman"):
            Sse = float(criteria.equivalent_amplitude.si(criterion, Ssa_z, Ssm_z, Sut=Ssu))
            n_f = float(criteria.safety_factor.si(criterion, ta, tm, Sse, Sut=Ssu))
        elif criterion in ("asme_elliptic", "soderberg"):
            Sse = float(criteria.equivalent_amplitude.si(criterion, Ssa_z, Ssm_z, Sy=Ssy))
            n_f = float(criteria.safety_factor.si(criterion, ta, tm, Sse, Sy=Ssy))
        else:
            raise UnknownNameError("spring fatigue criterion", criterion,
                                   ["gerber", "goodman", "sines", "asme_elliptic", "soderberg"])
        n_y = float(criteria.langer.si(ta, tm, Ssy))
        P = lambda v: Q(v, "Pa").to("MPa")  # noqa: E731
        return SpringFatigue(criterion=criterion, tau_a=P(ta), tau_m=P(tm), Ssu=P(Ssu), Sse=P(Sse),
                             Ssa=P(n_f * ta) if math.isfinite(n_f) else P(Sse), n_f=n_f, n_y=n_y, Ssy=P(Ssy),
                             zimmerli=z)

    # ------------------------------------------------------------------------------ as a column
    def rigidities(self, length: QuantityLike | None = None) -> SpringRigidities:
        """Timoshenko's equivalent-column rigidities at working length L (default: the free length).

        Unloaded ([3] Sec. 2.18), with n active coils, R = D/2, I = πd⁴/64:
        α₀ = GIL₀/(πnR³), β₀ = 2EGIL₀/(πnR(E + 2G)), γ₀ = EIL₀/(πnR³).
        Compressed to L the coils per unit length grow by L₀/L, so each rigidity scales by L/L₀.
        α₀/L₀ is the axial rate k; β is the spring's flexural rigidity ("EI").
        """
        s = self.si
        L = s["L0"] if length is None else to_si(length, "length", "length")
        if not (s["Ls"] <= L <= s["L0"]):
            raise InputError(f"{self.name}: length {fmt(Q(L, 'm'), 'mm')} outside solid..free "
                             f"({fmt(self.solid_length)}..{fmt(self.free_length)})")
        I = math.pi * s["d"] ** 4 / 64
        n, R, E, G, L0 = s["Na"], s["D"] / 2, s["E"], s["G"], s["L0"]
        a0 = G * I * L0 / (math.pi * n * R**3)
        b0 = 2 * E * G * I * L0 / (math.pi * n * R * (E + 2 * G))
        g0 = E * I * L0 / (math.pi * n * R**3)
        f = L / L0
        return SpringRigidities(alpha=Q(a0 * f, "N"), beta=Q(b0 * f, "N*m**2"), gamma=Q(g0 * f, "N"),
                                length=Q(L, "m").to("mm"))

    def lateral_rate(self, end: str = "fixed-free", length: Any = None) -> pint.Quantity:
        """Lateral stiffness of the spring as a Timoshenko beam (bending + shear), axial load neglected.

        ``fixed-free`` (cantilever, tip force): 1/k = L³/(3β) + L/γ; ``fixed-guided`` (ends kept
        parallel): 1/k = L³/(12β) + L/γ. β, γ from :meth:`rigidities` at length L ([3] Sec. 2.18).
        """
        r = self.rigidities(length)
        L, b, g = r.length.m_as("m"), r.beta.m_as("N*m**2"), r.gamma.m_as("N")
        coeff = {"fixed-free": 3.0, "fixed-guided": 12.0}
        if end not in coeff:
            raise UnknownNameError("lateral end condition", end, coeff)
        return Q(1.0 / (L**3 / (coeff[end] * b) + L / g), "N/m").to("N/mm")

    def bending_stiffness(self, length: Any = None) -> pint.Quantity:
        """Rotational stiffness of the spring under a pure end moment, M/θ = β/L [N·m/rad] ([3] Sec. 2.18)."""
        r = self.rigidities(length)
        return Q(r.beta.m_as("N*m**2") / r.length.m_as("m"), "N*m/rad")

    def __repr__(self) -> str:
        return (f"<CompressionSpring {self.name!r} d={fmt(self.wire_diameter, 'mm')} D={fmt(self.mean_diameter, 'mm')} "
                f"Na={self.active_coils:g} {self.end.value} L0={fmt(self.free_length, 'mm')} "
                f"k={fmt(self.rate, 'N/mm')}>")


def en13906_min_gap_sum(d: QuantityLike, D: QuantityLike, n: float, dynamic: bool = False) -> pint.Quantity:
    """Minimum sum of gaps between active coils at the largest working length, EN 13906-1 [2] Sec. 10.

    Sₐ = (0.0015·D²/d + 0.1·d)·n for cold-coiled springs under static loading (D, d in mm);
    doubled for dynamic loading.
    """
    dm, Dm = to_si(d, "length", "d") * 1e3, to_si(D, "length", "D") * 1e3
    Sa = (0.0015 * Dm**2 / dm + 0.1 * dm) * float(n) * (2.0 if dynamic else 1.0)
    return Q(Sa, "mm")


__all__ = ["CompressionSpring", "EndType", "SpringFatigue", "SpringRigidities", "en13906_min_gap_sum"]
