"""Helical torsion springs of round wire: rate, bending stress with the curvature factor, static strength.

References
----------
[1] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill 2015, Sec. 10-12:
    σ = K_i·32M/(πd³) with K_i, K_o (Eq. (10-43)); end coils Nₑ = (l₁ + l₂)/(3πD); rate
    k = d⁴E/(64DNₐ) per radian, k' = d⁴E/(10.8DNₐ) per turn (friction-corrected, Eq. (10-51));
    static strength S_y = 0.78/0.87/0.61 S_ut (Eq. (10-57)); coil diameter under load D' = DN_b/(N_b + θ').
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import pint

from mechverify.components import spring_formulas as sf
from mechverify.errors import InputError
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike, fmt, to_si


@dataclass(frozen=True)
class TorsionSpring(sf.HelicalSpring):
    """A helical torsion spring: wire ``d``, one of ``D``/``OD``/``ID``, ``Nb`` body turns, straight legs
    ``l1``, ``l2`` (from the coil centre to the load, default 0), ``material`` (default A228)."""

    d: Any
    Nb: float
    D: Any = None
    OD: Any = None
    ID: Any = None
    l1: QuantityLike = "0 mm"
    l2: QuantityLike = "0 mm"
    material: str | Material = "A228"
    E: Any = None
    Sut: Any = None
    spring_class: str | None = None
    name: str = "torsion spring"

    def __post_init__(self) -> None:
        self.validate()

    def _si_values(self) -> dict[str, float]:
        d, D = sf.coil_geometry(self.name, self.d, self.D, self.OD, self.ID)
        Nb = float(self.Nb)
        if Nb <= 0:
            raise InputError(f"{self.name}: body turns must be positive, got Nb = {Nb:g}")
        l1, l2 = to_si(self.l1, "length", "l1"), to_si(self.l2, "length", "l2")
        if l1 < 0 or l2 < 0:
            raise InputError(f"{self.name}: leg lengths must be >= 0")
        return dict(d=d, D=D, Nb=Nb, l1=l1, l2=l2, **self._wire_si(d, ("E",)))

    @property
    def active_turns(self) -> float:
        """Nₐ = N_b + (l₁ + l₂)/(3πD) (legs as equivalent turns, [1] Sec. 10-12)."""
        s = self.si
        return s["Nb"] + (s["l1"] + s["l2"]) / (3 * math.pi * s["D"])

    def rate(self, friction_corrected: bool = True) -> pint.Quantity:
        """Angular rate [N·m/rad]: d⁴E/(10.8DNₐ) per turn (Shigley's friction-corrected Eq. (10-51)) divided
        by 2π, or the theoretical d⁴E/(64DNₐ) per radian with ``friction_corrected=False``."""
        s = self.si
        if friction_corrected:
            k = s["d"] ** 4 * s["E"] / (10.8 * s["D"] * self.active_turns) / (2 * math.pi)
        else:
            k = s["d"] ** 4 * s["E"] / (64 * s["D"] * self.active_turns)
        return Q(k, "N*m/rad")

    def angle(self, moment: QuantityLike, friction_corrected: bool = True) -> pint.Quantity:
        """Angular deflection θ = M/k."""
        M = to_si(moment, "torque", "moment")
        return Q(M / self.rate(friction_corrected).m_as("N*m/rad"), "rad").to("deg")

    def bending_stress(self, moment: QuantityLike, fibre: str = "inner") -> pint.Quantity:
        """σ = K·32M/(πd³) with K_i (inner fibre, default) or K_o ([1] Sec. 10-12)."""
        M = to_si(moment, "torque", "moment")
        Ki, Ko = sf.torsion_spring_factors(self.index)
        if fibre not in ("inner", "outer"):
            raise InputError(f"fibre: 'inner' or 'outer', got {fibre!r}")
        K = Ki if fibre == "inner" else Ko
        return Q(K * 32 * M / (math.pi * self.si["d"] ** 3), "Pa").to("MPa")

    @property
    def yield_strength(self) -> pint.Quantity:
        """Static bending yield S_y = 0.78 S_ut (music wire, cold-drawn), 0.87 (hardened and tempered),
        0.61 (stainless, nonferrous) ([1] Eq. (10-57))."""
        return (sf.class_fraction(self.wire_class, "torsion_spring_bending") * self.tensile_strength).to("MPa")

    @property
    def yield_moment(self) -> pint.Quantity:
        """Moment at which the inner fibre reaches S_y: M_y = πd³S_y/(32K_i)."""
        Ki, _ = sf.torsion_spring_factors(self.index)
        return Q(math.pi * self.si["d"] ** 3 * self.yield_strength.m_as("Pa") / (32 * Ki), "N*m")

    def loaded_inside_diameter(self, moment: Any) -> pint.Quantity:
        """Inside diameter when wound up by M: D' = DN_b/(N_b + θ'_c) - d, θ'_c body turns ([1] Sec. 10-12).

        The body rotation excludes the legs: θ'_c = M/k'·N_b/Nₐ.
        """
        s = self.si
        turns = to_si(self.angle(moment), "angle") / (2 * math.pi) * s["Nb"] / self.active_turns
        return Q(s["D"] * s["Nb"] / (s["Nb"] + turns) - s["d"], "m").to("mm")

    def __repr__(self) -> str:
        return (f"<TorsionSpring {self.name!r} d={fmt(Q(self.si['d'], 'm'), 'mm')} "
                f"D={fmt(Q(self.si['D'], 'm'), 'mm')} Nb={self.si['Nb']:g}>")


__all__ = ["TorsionSpring"]
