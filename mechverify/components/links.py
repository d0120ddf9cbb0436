"""Straight links between two pin holes (or bars with end conditions) and their closed-form formulas.

* :class:`Lug` — the eye at a pin hole: hole diameter, width across the hole, thickness, distance
  from the hole centre to the end (``R``), straight or rounded end.
* :class:`Link` — length between pin centres, body :class:`~mechverify.components.sections.Section`,
  material, optional lug (same at both ends), pin diameter, buckling end condition and an optional
  strength knock-down for 3D-printed parts (``strength_factor``, e.g. printed orientation).

Formulas (one function each):

* body stresses under axial force, bending and torsion (elementary beam theory; von Mises);
* stress-concentration factor of the eye's hole (Peterson Eq. (4.1), via :mod:`mechverify.fatigue.notch`);
* pin shear, pin bearing, net-section tension;
* lug strength after ASME BTH-1 (Duerr's empirical pinned-plate equations): tension through the
  pinhole, fracture (tear-out) beyond the pinhole, double-plane shear-out, bearing;
* column buckling via :mod:`mechverify.components.columns`;
* maximum deflection and moment of the common beam cases (Shigley Table A-9).

References
----------
1. ASME BTH-1-2008, *Design of Below-the-Hook Lifting Devices*, Sec. 3-3.3 (pinned connections),
   Eqs. (3-45) to (3-52), Commentary Eq. (C3-2); D. Duerr, "Pinned connection strength and
   behavior", J. Struct. Eng. 132(2) (2006) 182-194.
2. W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., Wiley 2008,
   Eq. (4.1), Chart 4.1 (circular hole in a finite-width plate in tension).
3. R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015,
   Table A-9 (shear, moment and deflection of beams); Sec. 3-13 (Kt for static loading).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pint

from mechverify.components import columns
from mechverify.components.sections import Section, make_section
from mechverify.errors import InputError, UnknownNameError
from mechverify.fatigue.notch import kt_plate_hole
from mechverify.frozen import set_fields
from mechverify.materials import Material
from mechverify.materials import get as get_material
from mechverify.references import ref
from mechverify.units import fmt, from_si, si_function, to_si

BTH1_SOURCE = ref("asme_bth1", "Sec. 3-3.3.1, Eqs. (3-45) to (3-52), Commentary Eq. (C3-2)")
BRITTLE_ELONGATION = 0.05  # elongation at break below which a material is treated as brittle (Shigley Sec. 2-1)


def _pos(v: Any, dim: str, name: str, *, allow_zero: bool = False) -> float:
    x = to_si(v, dim, name)
    if x < 0 or (x == 0 and not allow_zero):
        raise InputError(f"{name}: must be {'zero or ' if allow_zero else ''}positive, got {v!r}")
    return x


# ------------------------------------------------------------------------------------ formulas
@si_function(returns="pressure", force="force", d="length")
def pin_shear_stress(force: float, d: float, planes: int = 2) -> float:
    """Average shear stress in a pin ``tau = F / (n pi d^2 / 4)`` [Pa], ``n`` shear planes (2: clevis)."""
    if not (isinstance(planes, int) and planes > 0):
        raise InputError(f"planes: a positive whole number of shear planes, got {planes!r}")
    if d <= 0:
        raise InputError("pin diameter must be positive")
    return abs(force) / (planes * math.pi * d * d / 4)


@si_function(returns="pressure", force="force", d="length", t="length")
def bearing_stress(force: float, d: float, t: float) -> float:
    """Projected-area bearing stress ``sigma_br = F / (d t)`` [Pa] of a pin of diameter d in a plate of thickness t."""
    if d <= 0 or t <= 0:
        raise InputError("bearing_stress: d and t must be positive")
    return abs(force) / (d * t)


@si_function(returns="pressure", force="force", w="length", d="length", t="length")
def net_section_stress(force: float, w: float, d: float, t: float) -> float:
    """Nominal net-section stress at a hole ``sigma = F / ((w - d) t)`` [Pa]."""
    if not 0 < d < w or t <= 0:
        raise InputError("net_section_stress: need 0 < d < w and t > 0")
    return force / ((w - d) * t)


@si_function(returns="dimensionless", pin_d="length", hole_d="length")
def bth1_pin_clearance_factor(pin_d: float, hole_d: float) -> float:
    """``Cr = 1 - 0.275 sqrt(1 - Dp^2/Dh^2)`` [-], strength reduction for pin-to-hole clearance (BTH-1 Eq. 3-46)."""
    if not 0 < pin_d <= hole_d:
        raise InputError(f"pin diameter {pin_d * 1e3:g} mm must be positive and not exceed the hole "
                         f"{hole_d * 1e3:g} mm")
    return 1.0 - 0.275 * math.sqrt(1.0 - (pin_d / hole_d) ** 2)


@dataclass(frozen=True)
class Lug:
    """The eye of a link at a pin hole (plate-type lug), dimensions in the plane of the link.

    ``width``: across the hole, perpendicular to the load; ``edge_distance`` ``R``: from the hole
    centre to the end of the lug along the load; ``thickness`` ``t``; ``rounded_end``: a curved
    (semicircular) end of radius ``R`` rather than a square one.
    """

    hole_diameter: Any
    width: Any
    thickness: Any
    edge_distance: Any
    rounded_end: bool = True

    def __post_init__(self) -> None:
        D = _pos(self.hole_diameter, "length", "lug.hole_diameter")
        w = _pos(self.width, "length", "lug.width")
        t = _pos(self.thickness, "length", "lug.thickness")
        R = _pos(self.edge_distance, "length", "lug.edge_distance")
        if D >= w:
            raise InputError(f"lug: hole diameter {D * 1e3:g} mm must be smaller than the lug width {w * 1e3:g} mm")
        if R <= D / 2:
            raise InputError(f"lug: edge distance {R * 1e3:g} mm must exceed the hole radius {D * 500:g} mm "
                             "(the hole would break through the end)")
        set_fields(self, hole_diameter=from_si(D, "length"), width=from_si(w, "length"), thickness=from_si(t, "length"),
                   edge_distance=from_si(R, "length"))

    @property
    def be(self) -> pint.Quantity:
        """Side ligament: plate width beside the hole, perpendicular to the load, ``(w - D)/2`` [m]."""
        return (self.width - self.hole_diameter) / 2

    @property
    def a(self) -> pint.Quantity:
        """End ligament: from the edge of the hole to the end of the lug along the load, ``R - D/2`` [m]."""
        return self.edge_distance - self.hole_diameter / 2


@dataclass(frozen=True)
class LugStrength:
    """Nominal (ultimate, unfactored) lug strengths after ASME BTH-1; the standard's allowable is
    ``P / (1.20 Nd)`` for the first three and ``P / Nd`` for bearing."""

    tension: pint.Quantity  # through the pinhole, Pt
    fracture_beyond: pint.Quantity  # single-plane fracture (tear-out) beyond the hole, Pb
    shear_out: pint.Quantity  # double-plane shear beyond the hole, Pv
    bearing: pint.Quantity  # 1.25 Fy Dp t
    Cr: float
    b_eff: pint.Quantity
    shear_area: pint.Quantity  # Av
    phi: pint.Quantity  # shear-plane angle
    source: str = BTH1_SOURCE

    @property
    def governing(self) -> tuple[str, pint.Quantity]:
        """Weakest of tension, fracture beyond, shear-out (after the 1.20 factor these share one design factor)."""
        modes = {"tension": self.tension, "fracture_beyond": self.fracture_beyond, "shear_out": self.shear_out}
        k = min(modes, key=lambda m: modes[m].m_as("N"))
        return k, modes[k]


def lug_strength(lug: Lug, pin_diameter: Any, Fy: Any, Fu: Any) -> LugStrength:
    """Nominal strengths of a plate lug after ASME BTH-1-2008 Sec. 3-3.3.1 (Duerr 2006).

    * ``b_eff = min(be, 4t, 0.6 (Fu/Fy) sqrt(Dh/be) be)``                       (3-47), (3-48)
    * tension through the pinhole ``Pt = Cr Fu 2 t b_eff``                       (3-45)
    * fracture beyond the pinhole ``Pb = Cr Fu [1.13 (R - Dh/2) + 0.92 be/(1 + be/Dh)] t``   (3-49)
    * double-plane shear ``Pv = 0.70 Fu Av``, ``Av = 2 [a + Dp/2 (1 - cos phi) - Z'] t``,
      ``phi = 55 Dp/Dh`` [deg], ``Z' = r - sqrt(r^2 - (Dp/2 sin phi)^2)`` for a rounded end of
      radius ``r = R`` (0 for a square end)                                      (3-50)-(3-52), (C3-2)
    * bearing ``Pp = 1.25 Fy Dp t``                                              (Sec. 3-3.3.3)

    ``Cr`` from :func:`bth1_pin_clearance_factor`. The equations were fitted to tests on steel
    plates; for other materials they are an estimate.
    """
    Dh, w, t, R = (lug.hole_diameter.m_as("m"), lug.width.m_as("m"), lug.thickness.m_as("m"),
                   lug.edge_distance.m_as("m"))
    Dp = _pos(pin_diameter, "length", "pin_diameter")
    fy, fu = _pos(Fy, "pressure", "Fy"), _pos(Fu, "pressure", "Fu")
    if fy > fu:
        raise InputError("lug_strength: Fy exceeds Fu")
    Cr = bth1_pin_clearance_factor.si(Dp, Dh)
    be, a = (w - Dh) / 2, R - Dh / 2
    b_eff = min(be, 4 * t, 0.6 * (fu / fy) * math.sqrt(Dh / be) * be)
    Pt = Cr * fu * 2 * t * b_eff
    Pb = Cr * fu * (1.13 * (R - Dh / 2) + 0.92 * be / (1 + be / Dh)) * t
    phi = math.radians(55.0 * Dp / Dh)
    z_prime = R - math.sqrt(R * R - (Dp / 2 * math.sin(phi)) ** 2) if lug.rounded_end else 0.0
    Av = 2 * (a + Dp / 2 * (1 - math.cos(phi)) - z_prime) * t
    Pv = 0.70 * fu * Av
    Pp = 1.25 * fy * Dp * t
    return LugStrength(tension=from_si(Pt, "force"), fracture_beyond=from_si(Pb, "force"),
                       shear_out=from_si(Pv, "force"), bearing=from_si(Pp, "force"), Cr=Cr,
                       b_eff=from_si(b_eff, "length"), shear_area=from_si(Av, "area"), phi=from_si(phi, "angle"))


# --------------------------------------------------------------------------------- beam cases
@dataclass(frozen=True)
class BeamCase:
    """One case of Shigley Table A-9: ``y_max = c_deflection P l^n / (E I)``, ``M_max = c_moment P l^m``."""

    name: str
    table_case: str
    load_kind: str  # "force", "line_load" or "moment"
    c_deflection: float
    c_moment: float
    where: str
    #: largest end reaction (= largest shear force) as a multiple of ``F`` or ``w l`` (statics of the case)
    c_reaction: float = 0.0


_BEAM_CASES = {c.name: c for c in (
    BeamCase("cantilever_end_load", "A-9-1", "force", 1 / 3, 1.0, "free end; moment at the wall", 1.0),
    BeamCase("cantilever_uniform", "A-9-3", "line_load", 1 / 8, 1 / 2, "free end; moment at the wall", 1.0),
    BeamCase("cantilever_end_moment", "A-9-4", "moment", 1 / 2, 1.0, "free end; uniform moment"),
    BeamCase("simply_supported_center_load", "A-9-5", "force", 1 / 48, 1 / 4, "mid-span", 0.5),
    BeamCase("simply_supported_uniform", "A-9-7", "line_load", 5 / 384, 1 / 8, "mid-span", 0.5),
    BeamCase("fixed_pinned_center_load", "A-9-11", "force", 1 / (48 * math.sqrt(5)), 3 / 16,
             "deflection at l/sqrt(5) from the pinned end; moment at the fixed end", 11 / 16),
    BeamCase("fixed_pinned_uniform", "A-9-13", "line_load", (39 + 55 * math.sqrt(33)) / 65536, 1 / 8,
             "deflection at 0.4215 l from the pinned end; moment at the fixed end", 5 / 8),
    BeamCase("fixed_fixed_center_load", "A-9-14", "force", 1 / 192, 1 / 8, "mid-span; moment at ends and centre", 0.5),
    BeamCase("fixed_fixed_uniform", "A-9-16", "line_load", 1 / 384, 1 / 12, "deflection mid-span; moment at the ends",
             0.5),
)}
_LOAD_DIMS = {"force": ("force", 3, 1), "line_load": ("force_per_length", 4, 2), "moment": ("torque", 2, 0)}


def beam_cases() -> list[str]:
    return list(_BEAM_CASES)


def beam_case(name: str) -> BeamCase:
    key = name.strip().lower().replace("-", "_").replace(" ", "_").replace("centre", "center")
    if key not in _BEAM_CASES:
        raise UnknownNameError("beam case", name, list(_BEAM_CASES))
    return _BEAM_CASES[key]


def beam_max_deflection(case: str, load: Any, length: Any, E: Any, I: Any) -> pint.Quantity:
    """Largest deflection magnitude of a prismatic beam [m] (Shigley 10th ed., Table A-9).

    ``load`` is a force (point-load cases), a force per length (uniform cases) or a moment.
    Cases: see :func:`beam_cases` (e.g. ``"cantilever_end_load"``: ``F l^3 / (3 E I)``;
    ``"simply_supported_uniform"``: ``5 w l^4 / (384 E I)``; ``"fixed_pinned_uniform"``: ``w l^4/(185 E I)``).
    """
    c = beam_case(case)
    dim, n, _ = _LOAD_DIMS[c.load_kind]
    P = abs(to_si(load, dim, "load"))
    L, e, i = _pos(length, "length", "length"), _pos(E, "pressure", "E"), _pos(I, "second_moment", "I")
    return from_si(c.c_deflection * P * L**n / (e * i), "length")


def beam_max_moment(case: str, load: Any, length: Any) -> pint.Quantity:
    """Largest bending-moment magnitude [N m] for a case of Shigley Table A-9 (see :func:`beam_max_deflection`)."""
    c = beam_case(case)
    dim, _, m = _LOAD_DIMS[c.load_kind]
    P = abs(to_si(load, dim, "load"))
    L = _pos(length, "length", "length")
    return from_si(c.c_moment * P * L**m, "torque")


#: Link end condition -> (Table A-9 support name, name of the point-load case's load position).
BEAM_SUPPORT = {"pinned-pinned": ("simply_supported", "center_load"), "fixed-free": ("cantilever", "end_load"),
                "fixed-pinned": ("fixed_pinned", "center_load"), "fixed-fixed": ("fixed_fixed", "center_load")}


def beam_case_name(end: str, uniform: bool) -> str:
    """The Table A-9 case of a transverse load on a member with end condition ``end`` (a key of
    :data:`BEAM_SUPPORT`): a point load at mid-span (tip of a cantilever) or a uniform load."""
    if end not in BEAM_SUPPORT:
        raise UnknownNameError("end condition", end, list(BEAM_SUPPORT))
    support, point = BEAM_SUPPORT[end]
    return f"{support}_{'uniform' if uniform else point}"


def beam_max_reaction(case: str, load: Any, length: Any) -> pint.Quantity:
    """Largest end reaction (= largest shear force) [N] of a Table A-9 case by statics: ``c F`` for a
    point load, ``c w l`` for a uniform load (e.g. fixed-pinned, centre load: ``11 F/16`` at the fixed end)."""
    c = beam_case(case)
    dim, _, _ = _LOAD_DIMS[c.load_kind]
    P = abs(to_si(load, dim, "load"))
    L = _pos(length, "length", "length")
    return from_si(c.c_reaction * P * (L if c.load_kind == "line_load" else 1.0), "force")


def beam_moment_diagram(case: str, load: float, length: float, n: int = 201) -> tuple[np.ndarray, np.ndarray]:
    """Bending moment along the beam [N m] (sagging positive, load downward, fixed end at x = 0) by
    statics with the Table A-9 reactions; ``load`` in N (point cases) or N/m (uniform cases), SI floats.

    Shigley 10th ed. Table A-9, cases 1, 3, 5, 7, 11, 13, 14, 16 (their moment diagrams).
    """
    x = np.linspace(0.0, length, n)
    L, P = length, load
    step = np.where(x > L / 2, x - L / 2, 0.0)  # Macaulay bracket <x - l/2>
    M = {
        "simply_supported_center_load": P / 2 * x - P * step,
        "simply_supported_uniform": P * x * (L - x) / 2,
        "cantilever_end_load": -P * (L - x),
        "cantilever_uniform": -P * (L - x) ** 2 / 2,
        "fixed_pinned_center_load": -3 * P * L / 16 + 11 * P / 16 * x - P * step,
        "fixed_pinned_uniform": -P * L**2 / 8 + 5 * P * L / 8 * x - P * x**2 / 2,
        "fixed_fixed_center_load": -P * L / 8 + P / 2 * x - P * step,
        "fixed_fixed_uniform": -P * L**2 / 12 + P * L / 2 * x - P * x**2 / 2,
    }[beam_case(case).name]
    return x, M


def beam_deflection_curve(case: str, load: float, length: float, EI: float, n: int = 201
                          ) -> tuple[np.ndarray, np.ndarray]:
    """Deflection along the beam [m] (upward positive) from ``E I y'' = M`` integrated twice with the
    kinematic conditions of the supports (y = y' = 0 at a fixed x = 0; y = 0 at both simple supports)."""
    x, M = beam_moment_diagram(case, load, length, n)
    k = M / EI
    slope = np.concatenate(([0.0], np.cumsum((k[1:] + k[:-1]) / 2 * np.diff(x))))
    y = np.concatenate(([0.0], np.cumsum((slope[1:] + slope[:-1]) / 2 * np.diff(x))))
    if beam_case(case).name.startswith("simply_supported"):
        y = y - y[-1] * x / length  # add c1 x so that y(l) = 0
    return x, y


# --------------------------------------------------------------------------------------- links
@dataclass(frozen=True)
class LinkStresses:
    """Nominal stresses in the link body (away from holes) [Pa]."""

    axial: pint.Quantity
    bending: pint.Quantity  # |My|/Wel_y + |Mz|/Wel_z (extreme fibre, conservative for biaxial bending)
    torsion: pint.Quantity  # |T| / Wt
    shear: pint.Quantity  # average transverse shear V / A_s (added to torsion, conservative)
    von_mises: pint.Quantity  # sqrt((|sigma_axial| + sigma_bending)^2 + 3 tau^2)


@dataclass(frozen=True)
class Link:
    """A straight link: pin-centre ``length``, body ``section``, ``material`` and optional pin eyes.

    ``section`` is a :class:`Section` or a table for :func:`make_section` (``{"kind": "rectangle",
    "width": "10 mm", "height": "4 mm"}``); ``material`` a :class:`Material` or a database name.
    ``lug`` describes both eyes (a :class:`Lug` or a table of its fields), ``pin_diameter`` defaults
    to the hole diameter. ``end`` is the buckling end condition (name or C, see
    :mod:`~mechverify.components.columns`). ``strength_factor`` (0 < f <= 1) scales the material's
    strengths, e.g. for a printed orientation weaker than the test bars; ``print_orientation`` is
    the label reported with it.
    """

    length: Any
    section: Any
    material: Any
    lug: Any = None
    pin_diameter: Any = None
    end: str | float = "pinned-pinned"
    strength_factor: float = 1.0
    print_orientation: str = ""
    name: str = "link"

    def __post_init__(self) -> None:
        set_fields(self, length=from_si(_pos(self.length, "length", f"{self.name}.length"), "length"))
        sec = self.section
        if isinstance(sec, dict):
            sec = make_section(sec.get("kind", ""), **{k: v for k, v in sec.items() if k != "kind"})
        if not isinstance(sec, Section):
            raise InputError(f"{self.name}.section: expected a Section or a table with 'kind', "
                             f"got {type(sec).__name__}")
        set_fields(self, section=sec)
        mat = self.material if isinstance(self.material, Material) else get_material(self.material)
        set_fields(self, material=mat)
        lug = self.lug
        if isinstance(lug, dict):
            lug = Lug(**lug)
        if lug is not None and not isinstance(lug, Lug):
            raise InputError(f"{self.name}.lug: expected a Lug or a table, got {type(lug).__name__}")
        set_fields(self, lug=lug)
        if self.pin_diameter is not None:
            dp = from_si(_pos(self.pin_diameter, "length", f"{self.name}.pin_diameter"), "length")
            if lug is not None and dp > lug.hole_diameter:
                raise InputError(f"{self.name}: pin diameter {dp.to('mm'):~P} exceeds the hole "
                                 f"{lug.hole_diameter.to('mm'):~P}")
            set_fields(self, pin_diameter=dp)
        elif lug is not None:
            set_fields(self, pin_diameter=lug.hole_diameter)
        f = float(self.strength_factor)
        if not 0 < f <= 1:
            raise InputError(f"{self.name}.strength_factor: must lie in (0, 1], got {self.strength_factor!r}")
        set_fields(self, strength_factor=f)
        columns.end_condition_constant(self.end)  # validates the name now
        if self.lug is not None and 2 * self.lug.edge_distance > self.length:
            raise InputError(f"{self.name}: the two eyes (edge distance {self.lug.edge_distance.to('mm'):~P}) "
                             f"overlap in a link {self.length.to('mm'):~P} long")

    # ------------------------------------------------------------- material
    @property
    def yield_strength(self) -> pint.Quantity:
        """Material yield strength times ``strength_factor``."""
        return self.material.require("yield_strength") * self.strength_factor

    @property
    def ultimate_strength(self) -> pint.Quantity:
        m = self.material
        su = m.ultimate_strength if m.ultimate_strength is not None else m.require("yield_strength")
        return su * self.strength_factor

    @property
    def is_brittle(self) -> bool | None:
        """True when elongation at break < 5 % (Shigley Sec. 2-1); None when the material has no elongation."""
        el = self.material.elongation
        return None if el is None else float(el.m_as("")) < BRITTLE_ELONGATION

    # ------------------------------------------------------------- stresses
    def stresses(self, axial: Any = "0 N", moment_y: Any = "0 N*m", moment_z: Any = "0 N*m", torque: Any = "0 N*m",
                 shear: Any = "0 N") -> LinkStresses:
        """Nominal body stresses: ``N/A``, ``|My|/Wel_y + |Mz|/Wel_z``, ``|T|/Wt`` (+ ``|V|/A_s``), von Mises."""
        s = self.section.si()
        N = to_si(axial, "force", "axial")
        My, Mz = to_si(moment_y, "torque", "moment_y"), to_si(moment_z, "torque", "moment_z")
        T, V = to_si(torque, "torque", "torque"), to_si(shear, "force", "shear")
        sa = N / s["area"]
        sb = abs(My) / s["Wel_y"] + abs(Mz) / s["Wel_z"]
        tt = abs(T) / s["Wt"]
        tv = abs(V) / min(s["Asy"], s["Asz"])
        vm = math.sqrt((abs(sa) + sb) ** 2 + 3 * (tt + tv) ** 2)
        return LinkStresses(axial=from_si(sa, "pressure"), bending=from_si(sb, "pressure"),
                            torsion=from_si(tt, "pressure"), shear=from_si(tv, "pressure"),
                            von_mises=from_si(vm, "pressure"))

    def eye_net_stress(self, axial: Any) -> pint.Quantity:
        """Nominal net-section stress across the pin hole ``F / ((w - D) t)`` [Pa]."""
        if self.lug is None:
            raise InputError(f"{self.name}: no lug (pin eye) defined")
        L = self.lug
        return net_section_stress(axial, L.width, L.hole_diameter, L.thickness)

    def eye_kt(self) -> pint.Quantity:
        """Net-section Kt of the eye's hole as an open hole in a strip in tension (Peterson Eq. (4.1),
        :func:`mechverify.fatigue.notch.kt_plate_hole`); a pin-loaded hole concentrates more."""
        if self.lug is None:
            raise InputError(f"{self.name}: no lug (pin eye) defined")
        return kt_plate_hole(self.lug.width, self.lug.hole_diameter)

    def lug_strength(self) -> LugStrength:
        """BTH-1 nominal strengths of the eye (see :func:`lug_strength`), with knocked-down strengths."""
        if self.lug is None:
            raise InputError(f"{self.name}: no lug (pin eye) defined")
        return lug_strength(self.lug, self.pin_diameter, self.yield_strength, self.ultimate_strength)

    # ------------------------------------------------------------- stability and stiffness
    def buckling(self, end: str | float | None = None, basis: str = "recommended") -> columns.ColumnBuckling:
        """Euler/Johnson buckling about the least principal axis (``I2``) over the pin-centre length."""
        s = self.section
        return columns.column_buckling(self.material.require("E"), self.yield_strength, s.area, s.I2, self.length,
                                       self.end if end is None else end, basis)

    def deflection(self, case: str, load: Any, axis: str = "z") -> pint.Quantity:
        """Max deflection for a Table A-9 case over the link length; ``axis`` = direction of the load (y or z)."""
        I = self.second_moment(axis)
        return beam_max_deflection(case, load, self.length, self.material.require("E"), I)

    def second_moment(self, axis: str) -> pint.Quantity:
        """Second moment of area [m^4] resisting a transverse load along ``axis`` (``"z"``: bending about
        y, ``Iy``; ``"y"``: ``Iz``); an :class:`InputError` for any other axis."""
        if axis == "z":
            return self.section.Iy  # load along z bends about y
        if axis == "y":
            return self.section.Iz
        raise InputError(f"axis: 'y' or 'z', got {axis!r}")

    def mass(self) -> pint.Quantity:
        """Body mass over the pin-centre length (eyes not modelled) [kg]."""
        rho = self.material.require("density")
        return (self.section.area * self.length * rho).to("kg")



# ------------------------------------------------------------------------------- link section forces
@dataclass(frozen=True)
class LinkSectionForces:
    """Section forces of a link in one load case, composed from its loads (see :func:`link_section_forces`).

    ``moment_y`` is the given bending moment plus the largest moment of the transverse load's Table A-9
    case (added, conservative: they may peak at different sections); ``shear`` the largest end reaction
    of that case. ``beam_case`` and ``transverse`` (the load, N or N/m, SI) are ``None`` without a
    transverse load. ``notes`` say how each value was found.
    """

    axial: pint.Quantity
    moment_y: pint.Quantity
    moment_z: pint.Quantity
    torque: pint.Quantity
    shear: pint.Quantity
    beam_case: str | None = None
    transverse: float | None = None
    notes: tuple[str, ...] = ()


def link_transverse_case(link: Link, transverse_load: Any = None, distributed_load: Any = None
                         ) -> tuple[str, float] | None:
    """``(Table A-9 case, load in SI)`` of a transverse load on ``link`` (by its end condition), or ``None``.

    Raises:
        InputError: both a point and a distributed load are given, or the end condition has no beam case.
    """
    if transverse_load is not None and distributed_load is not None:
        raise InputError("give transverse_load or distributed_load, not both")
    if transverse_load is None and distributed_load is None:
        return None
    if str(link.end) not in BEAM_SUPPORT:
        raise InputError(f"{link.name}: a transverse load needs an end condition of {', '.join(BEAM_SUPPORT)}, "
                         f"got {link.end!r}")
    uniform = distributed_load is not None
    q = distributed_load if uniform else transverse_load
    key = "distributed_load" if uniform else "transverse_load"
    P = abs(to_si(q, "force_per_length" if uniform else "force", key))
    return beam_case_name(str(link.end), uniform), P


def link_section_forces(link: Link, axial_force: Any = "0 N", bending_moment: Any = "0 N*m",
                        lateral_moment: Any = "0 N*m", torque: Any = "0 N*m", *, transverse_load: Any = None,
                        distributed_load: Any = None) -> LinkSectionForces:
    """Section forces for the body-strength check of ``link``: ``N``, ``M_y``, ``M_z``, ``T`` and ``V``.

    A transverse point load [N] (mid-span; tip of a cantilever) or distributed load [N/m] across the
    link in the plane of the section's height adds the largest moment and end reaction of its Shigley
    10th ed. Table A-9 case, chosen from the link's end condition (:data:`BEAM_SUPPORT`). With a
    compressive axial force, a note gives the beam-column amplification 1/(1 - P/P_e) that is left out.
    """
    M = abs(to_si(bending_moment, "torque", "bending_moment"))
    V, notes, case, P = 0.0, [], None, None
    tr = link_transverse_case(link, transverse_load, distributed_load)
    if tr is not None:
        case, P = tr
        c = beam_case(case)
        load = from_si(P, "force" if c.load_kind == "force" else "force_per_length")
        Mt = beam_max_moment(case, load, link.length).m_as("N*m")
        V = beam_max_reaction(case, load, link.length).m_as("N")
        given = transverse_load if transverse_load is not None else distributed_load
        given = fmt(given) if isinstance(given, pint.Quantity) else given
        notes.append(f"transverse load {given}: Shigley's Mechanical Engineering Design, 10th ed., Table A-9-"
                     f"{c.table_case[4:]} ({case.replace('_', ' ')}), M_max = {Mt:.4g} N·m ({c.where}), "
                     f"V_max = {V:.4g} N")
        if M:
            notes.append("bending_moment and the transverse load's largest moment added (conservative: they may "
                         "peak at different sections)")
        M += Mt
        N = to_si(axial_force, "force", "axial_force")
        if N < 0:
            E, I = link.material.require("E"), link.section.Iy
            pe = (math.pi**2 * E * I / link.length**2).m_as("N")  # Euler load in the plane of the transverse load
            notes.append(f"compression with a transverse load: the beam-column amplification of the moment, about "
                         f"1/(1 - P/P_e) = {1 / max(1 - abs(N) / pe, 1e-9):.3g} (P_e = pi^2 E I_y/l^2 = {pe:.4g} N; "
                         "Timoshenko & Gere, Theory of Elastic Stability, Sec. 1.11), is not included")
    return LinkSectionForces(axial=from_si(to_si(axial_force, "force", "axial_force"), "force"),
                             moment_y=from_si(M, "torque"),
                             moment_z=from_si(to_si(lateral_moment, "torque", "lateral_moment"), "torque"),
                             torque=from_si(to_si(torque, "torque", "torque"), "torque"), shear=from_si(V, "force"),
                             beam_case=case, transverse=P, notes=tuple(notes))


def link_pin_force(link: Link, axial_force: Any = "0 N", *, transverse_load: Any = None,
                   distributed_load: Any = None, pin_force: Any = None) -> tuple[pint.Quantity, str]:
    """``(force through each pin [N], how it was found)``: ``pin_force`` when given, else the resultant of
    the axial force and the largest end reaction of the transverse load's Table A-9 case."""
    if pin_force is not None:
        return from_si(abs(to_si(pin_force, "force", "pin_force")), "force"), "pin_force given by the load case"
    N = abs(to_si(axial_force, "force", "axial_force"))
    tr = link_transverse_case(link, transverse_load, distributed_load)
    R = 0.0
    if tr is not None:
        case, P = tr
        load = from_si(P, "force" if beam_case(case).load_kind == "force" else "force_per_length")
        R = beam_max_reaction(case, load, link.length).m_as("N")
    if R:
        return from_si(math.hypot(N, R), "force"), (
            f"pin force = resultant of the axial force {N:.4g} N and the largest end reaction {R:.4g} N of the "
            "transverse load (Table A-9)")
    return from_si(N, "force"), "pin force = |axial force| (no pin_force given)"

__all__ = ["Lug", "LugStrength", "Link", "LinkStresses", "BeamCase", "lug_strength", "pin_shear_stress",
           "bearing_stress", "net_section_stress", "bth1_pin_clearance_factor", "beam_cases", "beam_case",
           "beam_max_deflection", "beam_max_moment", "BTH1_SOURCE", "BEAM_SUPPORT", "beam_case_name",
           "beam_max_reaction", "beam_moment_diagram", "beam_deflection_curve", "LinkSectionForces",
           "link_transverse_case", "link_section_forces", "link_pin_force"]
