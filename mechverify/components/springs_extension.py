"""Helical extension springs with full-loop (machine) hooks: rate, initial tension, body and hook stresses.

References
----------
[1] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill 2015, Sec. 10-11
    (extension springs: Nₐ = N_b + G/E, L₀ = (2C - 1 + N_b)d, hook stresses at A (bending) and B (torsion),
    preferred initial stress range, Fig. 10-7) and Table 10-7 (static allowables).
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


def hook_bending_factor(C1: float) -> float:
    """(K)_A = (4C₁² - C₁ - 1)/(4C₁(C₁ - 1)), C₁ = 2r₁/d (Shigley [1] Sec. 10-11)."""
    if not C1 > 1:
        raise InputError(f"hook bend index C1 = 2 r1/d must exceed 1, got {C1:g}")
    return (4 * C1 * C1 - C1 - 1) / (4 * C1 * (C1 - 1))


def hook_torsion_factor(C2: float) -> float:
    """(K)_B = (4C₂ - 1)/(4C₂ - 4), C₂ = 2r₂/d (Shigley [1] Sec. 10-11)."""
    if not C2 > 1:
        raise InputError(f"hook side-bend index C2 = 2 r2/d must exceed 1, got {C2:g}")
    return (4 * C2 - 1) / (4 * C2 - 4)


@dataclass(frozen=True)
class ExtensionSpring(sf.HelicalSpring):
    """A helical extension spring with full-loop hooks.

    ``d`` wire, one of ``D``/``OD``/``ID``, ``Nb`` body coils, ``Fi`` initial tension, ``r1`` the
    mean radius of the hook bend at A (default D/2, a full loop), ``r2`` the side-bend radius at B
    (needed only for the hook torsion stress), ``material`` (default A228 music wire).
    """

    d: Any
    Nb: float
    D: Any = None
    OD: Any = None
    ID: Any = None
    Fi: QuantityLike = "0 N"
    r1: QuantityLike | None = None
    r2: QuantityLike | None = None
    material: str | Material = "A228"
    G: Any = None
    E: Any = None
    Sut: Any = None
    spring_class: str | None = None
    name: str = "extension spring"

    def __post_init__(self) -> None:
        self.validate()

    def _si_values(self) -> dict[str, float]:
        d, D = sf.coil_geometry(self.name, self.d, self.D, self.OD, self.ID)
        Nb = float(self.Nb)
        if Nb <= 0:
            raise InputError(f"{self.name}: body coils must be positive, got Nb = {Nb:g}")
        Fi = to_si(self.Fi, "force", "Fi")
        if Fi < 0:
            raise InputError(f"{self.name}: initial tension must be >= 0")
        r1 = D / 2 if self.r1 is None else to_si(self.r1, "length", "r1")
        r2 = math.nan if self.r2 is None else to_si(self.r2, "length", "r2")
        return dict(d=d, D=D, Nb=Nb, Fi=Fi, r1=r1, r2=r2, **self._wire_si(d, ("G", "E")))

    @property
    def body_coils(self) -> float:
        """Body coils N_b [-]."""
        return self.si["Nb"]

    @property
    def hook_bend_radius(self) -> pint.Quantity:
        """Mean radius r1 of the hook bend at section A [mm] (default D/2, a full loop)."""
        return Q(self.si["r1"], "m").to("mm")

    @property
    def hook_side_radius(self) -> pint.Quantity | None:
        """Side-bend radius r2 at section B [mm], or ``None`` when not given."""
        return None if math.isnan(self.si["r2"]) else Q(self.si["r2"], "m").to("mm")

    @property
    def active_coils(self) -> float:
        """Nₐ = N_b + G/E (the hooks add G/E coils; Shigley [1] Sec. 10-11)."""
        s = self.si
        return s["Nb"] + s["G"] / s["E"]

    @property
    def free_length(self) -> pint.Quantity:
        """Free length inside the hooks L₀ = 2(D - d) + (N_b + 1)d = (2C - 1 + N_b)d ([1] Sec. 10-11)."""
        s = self.si
        return Q(2 * (s["D"] - s["d"]) + (s["Nb"] + 1) * s["d"], "m").to("mm")

    @property
    def rate(self) -> pint.Quantity:
        s = self.si
        return sf.helical_rate(Q(s["d"], "m"), Q(s["D"], "m"), self.active_coils, Q(s["G"], "Pa")).to("N/mm")

    @property
    def initial_tension(self) -> pint.Quantity:
        return Q(self.si["Fi"], "N")

    def force(self, extension: QuantityLike) -> pint.Quantity:
        """F = F_i + k·y."""
        y = to_si(extension, "length", "extension")
        if y < 0:
            raise InputError(f"{self.name}: extension must be >= 0")
        return Q(self.si["Fi"] + self.rate.m_as("N/m") * y, "N")

    def extension(self, force: QuantityLike) -> pint.Quantity:
        """y = (F - F_i)/k; zero below the initial tension."""
        F = to_si(force, "force", "force")
        return Q(max(F - self.si["Fi"], 0.0) / self.rate.m_as("N/m"), "m").to("mm")

    def body_stress(self, force: Any) -> pint.Quantity:
        """Body shear stress τ = K_B·8FD/(πd³) ([1] Eq. (10-7))."""
        s = self.si
        KB = sf.bergstrasser_factor(self.index)
        return sf.helical_shear_stress(force, Q(s["D"], "m"), Q(s["d"], "m"), KB).to("MPa")

    def hook_bending_stress(self, force: QuantityLike) -> pint.Quantity:
        """Bending + tension at hook section A: σ_A = F[(K)_A·16D/(πd³) + 4/(πd²)], C₁ = 2r₁/d ([1] Sec. 10-11)."""
        s = self.si
        F = to_si(force, "force", "force")
        KA = hook_bending_factor(2 * s["r1"] / s["d"])
        return Q(F * (KA * 16 * s["D"] / (math.pi * s["d"] ** 3) + 4 / (math.pi * s["d"] ** 2)), "Pa").to("MPa")

    def hook_torsion_stress(self, force: Any) -> pint.Quantity:
        """Torsion at hook section B: τ_B = (K)_B·8FD/(πd³), C₂ = 2r₂/d ([1] Sec. 10-11)."""
        s = self.si
        if math.isnan(s["r2"]):
            raise InputError(f"{self.name}: the hook torsion stress needs the side-bend radius r2")
        KB = hook_torsion_factor(2 * s["r2"] / s["d"])
        return sf.helical_shear_stress(force, Q(s["D"], "m"), Q(s["d"], "m"), KB).to("MPa")

    @property
    def initial_stress(self) -> pint.Quantity:
        """Uncorrected initial torsional stress τᵢ = 8FᵢD/(πd³) (as plotted in [1] Fig. 10-7)."""
        s = self.si
        return sf.helical_shear_stress(Q(s["Fi"], "N"), Q(s["D"], "m"), Q(s["d"], "m"), 1.0).to("MPa")

    def initial_stress_range(self) -> tuple[pint.Quantity, pint.Quantity]:
        """Preferred range of τᵢ: 33 500/exp(0.105C) ± 1000(4 - (C - 3)/6.5) [psi] ([1] Sec. 10-11, Fig. 10-7)."""
        C = self.index
        mid = 33500 / math.exp(0.105 * C)
        half = 1000 * (4 - (C - 3) / 6.5)
        return Q(mid - half, "psi").to("MPa"), Q(mid + half, "psi").to("MPa")

    def allowable(self, where: str = "body") -> pint.Quantity:
        """Static allowable stress ([1] Table 10-7): ``body`` torsion, hook ``end_torsion``, hook ``end_bending``."""
        key = {"body": "extension_body", "end_torsion": "extension_end_torsion",
               "end_bending": "extension_end_bending"}
        if where not in key:
            from mechverify.errors import UnknownNameError
            raise UnknownNameError("extension-spring stress location", where, key)
        return (sf.class_fraction(self.wire_class, key[where]) * Q(self.si["Sut"], "Pa")).to("MPa")

    def __repr__(self) -> str:
        return (f"<ExtensionSpring {self.name!r} d={fmt(Q(self.si['d'], 'm'), 'mm')} "
                f"D={fmt(Q(self.si['D'], 'm'), 'mm')} Nb={self.si['Nb']:g} Fi={fmt(self.initial_tension)}>")


__all__ = ["ExtensionSpring", "hook_bending_factor", "hook_torsion_factor"]
