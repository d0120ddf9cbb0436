"""Bolted joints: ISO metric bolt data, Shigley's joint-stiffness method and VDI 2230 Part 1 (single bolt).

Two methods, one small function per published formula:

* **Shigley** (Ch. 8): bolt stiffness ``k_b`` (Eq. 8-17), member stiffness by the 30-degree frustum
  (Eqs. 8-19/8-20, two equal members Eq. 8-22) and Wileman's exponential fit (Eq. 8-23), the joint
  constant ``C``, the recommended preload (Eq. 8-31), the yielding, load and separation factors
  (Eqs. 8-28 to 8-30) and the fatigue strength amplitudes of a preloaded bolt (Goodman, Gerber, proof line).
* **VDI 2230 Part 1 (2015)**: bolt resilience by sections, plate resilience by the substitute deformation
  cone, load factor ``Phi_n = n delta_P/(delta_S + delta_P)``, embedding and thermal preload changes, the
  required and maximum assembly preloads (R4, R5), the permissible assembly preload at a utilisation
  ``nu`` of the yield strength (R7), the working stress (R8), alternating stress against the endurance of
  rolled threads (R9), surface pressure (R10), thread stripping (R11, Alexander), slip (R12) and the
  tightening torque (R13).

:class:`BoltedJoint` (a frozen dataclass) holds one bolt and its clamped parts; :meth:`BoltedJoint.analyse`
returns a :class:`JointAnalysis` for one load case. :class:`BoltPattern` distributes an eccentric force and
moment over a group of equal bolts by the elastic method (linear in the distance from the pattern
centroid) and analyses each bolt.

Formulas are written in SI floats (``f.si``) and called with quantities. Data (threads, property
classes, heads, nuts, clearance holes; VDI tables) live in ``components/data/bolts_iso.toml`` and
``bolts_vdi2230.toml`` with a source and a ``verified`` flag per row.

References
----------
1. Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, Secs. 8-7 to 8-11.
2. VDI 2230 Part 1:2015, Systematic calculation of highly stressed bolted joints.
3. ISO 724:1993 (basic thread dimensions), ISO 898-1:2013 (property classes, stress areas).
4. Wileman, Choudhury & Green, "Computation of member stiffness in bolted connections", J. Mech. Des. 113 (1991).
5. Alexander, E. M., "Analysis and design of threaded assemblies", SAE 770420 (1977) (via VDI 2230 Sec. 5.5.5).
"""

from __future__ import annotations

import functools
import math
import tomllib
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnknownNameError
from mechverify.units import Q, QuantityLike, as_quantity, fmt, si_function, to_si

_DATA = Path(__file__).parent / "data"
SHIGLEY = "Shigley's Mechanical Engineering Design, 10th ed."
VDI = "VDI 2230 Part 1:2015"

#: Young's modulus and thermal expansion of steel bolts (VDI 2230 uses E_S = 205 GPa at room temperature).
E_STEEL_BOLT = 205e9
ALPHA_STEEL = 11.5e-6
#: Shear strength ratio tau_B/R_m by material category (VDI 2230 Table 5.5/5 as reproduced in third-party code,
#: S. Vargas-Ortega's 'DVI bolt design tool'; not checked against the guideline): steel 0.60, austenitic cold-worked
#: 0.65, grey cast iron 0.90, aluminium alloys 0.70, titanium 0.60.
SHEAR_RATIO = {"steel": 0.60, "stainless steel": 0.65, "cast iron": 0.90, "aluminium": 0.70, "titanium": 0.60}
#: Coefficients of thermal expansion [1/K] by material category, used when a clamped part gives none.
THERMAL_EXPANSION = {"steel": 11.5e-6, "stainless steel": 16.0e-6, "aluminium": 23.4e-6, "copper alloy": 18.0e-6,
                     "cast iron": 10.5e-6}

# ============================================================================================ data files


@functools.cache
def _load(name: str) -> dict[str, Any]:
    with open(_DATA / name, "rb") as fh:
        return tomllib.load(fh)


@dataclass(frozen=True)
class MetricThread:
    """An ISO metric thread (ISO 261/262) with its ISO 724 basic dimensions [m] and stress area [m^2]."""

    designation: str
    d: float
    P: float
    coarse: bool
    As_published: float | None = None  # ISO 898-1 nominal stress area, where the data file has it
    verified: bool = False

    @property
    def d2(self) -> float:
        return pitch_diameter.si(self.d, self.P)

    @property
    def d3(self) -> float:
        return minor_diameter.si(self.d, self.P)

    @property
    def As(self) -> float:
        return stress_area.si(self.d, self.P)

    @property
    def d0(self) -> float:
        """Stress diameter d_S = (d2 + d3)/2 [m]."""
        return 0.5 * (self.d2 + self.d3)

    @property
    def size(self) -> float:
        """Nominal diameter in mm (the key of the head/nut/hole tables)."""
        return round(self.d * 1e3, 3)


def _thread_rows() -> list[dict[str, Any]]:
    return _load("bolts_iso.toml")["thread"]


def _mm(x: float) -> str:
    return f"{x:g}"


def metric_thread(designation: str) -> MetricThread:
    """The ISO metric thread ``"M10"`` (coarse) or ``"M10x1.25"`` (fine, ISO 262 selected sizes).

    Raises :class:`UnknownNameError` for a size or pitch outside ISO 261/262, suggesting the nearest.
    """
    text = str(designation).strip().upper().replace(" ", "").replace("×", "X")
    if not text.startswith("M"):
        raise InputError(f"thread: expected an ISO metric designation such as 'M10' or 'M10x1.25', got {designation!r}")
    body = text[1:]
    try:
        if "X" in body:
            d_txt, p_txt = body.split("X", 1)
            d_mm, p_mm = float(d_txt), float(p_txt)
        else:
            d_mm, p_mm = float(body), None
    except ValueError:
        raise InputError(f"thread: cannot read {designation!r}; write 'M10' or 'M10x1.25'") from None
    rows = _thread_rows()
    row = next((r for r in rows if abs(r["d"] - d_mm) < 1e-9), None)
    if row is None:
        near = sorted(rows, key=lambda r: abs(r["d"] - d_mm))[:2]
        near_names = [f"M{_mm(r['d'])}" for r in sorted(near, key=lambda r: r["d"])]
        raise UnknownNameError("ISO 261 thread size", designation, near_names)
    if p_mm is None or abs(p_mm - row["P"]) < 1e-9:
        return MetricThread(f"M{_mm(d_mm)}", d_mm * 1e-3, row["P"] * 1e-3, True,
                            row.get("As", None) and row["As"] * 1e-6, bool(row.get("verified", False)))
    if not any(abs(p_mm - f) < 1e-9 for f in row["fine"]):
        known = [f"M{_mm(d_mm)}"] + [f"M{_mm(d_mm)}x{_mm(f)}" for f in row["fine"]]
        raise UnknownNameError("ISO 262 pitch for this size", designation, known)
    return MetricThread(f"M{_mm(d_mm)}x{_mm(p_mm)}", d_mm * 1e-3, p_mm * 1e-3, False, None, False)


def thread_sizes() -> list[str]:
    """All coarse designations in the data file, smallest first."""
    return [f"M{_mm(r['d'])}" for r in _thread_rows()]


@dataclass(frozen=True)
class PropertyClass:
    """A bolt property class: minimum tensile strength R_m, minimum yield/0.2 % proof strength R_p0.2 and
    proof stress S_p [Pa]; Shigley's fully corrected endurance strength S_e where tabulated."""

    name: str
    Rm: float
    Rp02: float
    Sp: float
    Se: float | None = None
    source: str = ""
    verified: bool = False


def property_class(name: str, d: QuantityLike | None = None) -> PropertyClass:
    """The ISO 898-1 (4.6 ... 12.9) or ISO 3506-1 (A2/A4-50/70/80) class ``name`` for a bolt of diameter ``d``.

    8.8 has different values for d <= 16 mm and d > 16 mm; 9.8 exists only up to 16 mm (ISO 898-1 Table 3).
    """
    data = _load("bolts_iso.toml")
    refs = data["references"]
    key = str(name).strip().upper()
    dm = None if d is None else to_si(d, "length", "d") * 1e3
    rows = [r for r in data["property_class"] if key in [r["name"].upper(), *(a.upper() for a in r.get("aliases", []))]]
    if not rows:
        names = sorted({r["name"] for r in data["property_class"]} | {a for r in data["property_class"]
                                                                      for a in r.get("aliases", [])})
        raise UnknownNameError("property class", str(name), names)
    fits = [r for r in rows if dm is None or (r.get("d_min", 0) < dm <= r.get("d_max", 1e9)) or
            ("d_min" not in r and "d_max" not in r)]
    if not fits:
        lim = rows[0].get("d_max")
        raise InputError(f"property class {name}: not specified for d = {dm:g} mm (up to {lim:g} mm in its standard)")
    r = fits[0]
    return PropertyClass(r["name"] if key == r["name"].upper() else key, r["Rm"] * 1e6, r["Rp02"] * 1e6, r["Sp"] * 1e6,
                         r.get("Se") and r["Se"] * 1e6, refs.get(r["source"], r["source"]), bool(r.get("verified")))


def _size_row(d_mm: float) -> dict[str, Any]:
    for r in _load("bolts_iso.toml")["size"]:
        if abs(r["d"] - d_mm) < 1e-9:
            return r
    sizes = ", ".join(f"M{_mm(r['d'])}" for r in _load("bolts_iso.toml")["size"])
    raise InputError(f"M{_mm(d_mm)} is not in the head, nut and clearance-hole tables ({sizes}); give "
                     "head_bearing_diameter and hole_diameter (a through bolt also needs a tabulated nut: use a tapped "
                     "joint or a tabulated size)")


def head_bearing_diameter(thread: MetricThread, head: str) -> float:
    """Outer diameter d_W [m] of the head bearing face: ISO 4762 d_k (socket head) or ISO 4014/4017 d_w (hex)."""
    r = _size_row(thread.size)
    if head == "socket":
        return r["socket"]["dk"] * 1e-3
    if head == "hex":
        return r["hex"]["dw"] * 1e-3
    raise InputError(f"head: expected 'hex' or 'socket', got {head!r}")


def head_height(thread: MetricThread, head: str) -> float:
    r = _size_row(thread.size)
    return r["socket" if head == "socket" else "hex"]["k"] * 1e-3


def nut_dimensions(thread: MetricThread) -> dict[str, float]:
    """ISO 4032 style-1 nut: width across flats s, height m (max), bearing diameter d_w (min) [m]."""
    n = _size_row(thread.size)["nut"]
    return {"s": n["s"] * 1e-3, "m": n["m"] * 1e-3, "dw": n["dw"] * 1e-3}


def clearance_hole(thread: MetricThread, fit: str = "medium") -> float:
    """ISO 273 clearance hole diameter [m] for the ``fit`` 'fine', 'medium' or 'coarse'."""
    h = _size_row(thread.size)["hole"]
    if fit not in ("fine", "medium", "coarse"):
        raise InputError(f"hole fit: expected 'fine', 'medium' or 'coarse', got {fit!r}")
    return h[fit] * 1e-3


def friction_class(name: str) -> tuple[float, float]:
    """VDI 2230 Table A5 friction class A..E -> (mu_min, mu_max)."""
    for r in _load("bolts_vdi2230.toml")["friction_class"]:
        if r["name"] == str(name).strip().upper():
            return float(r["mu"][0]), float(r["mu"][1])
    names = [r["name"] for r in _load("bolts_vdi2230.toml")["friction_class"]]
    raise UnknownNameError("VDI 2230 friction class", str(name), names)


def embedding_amount(roughness: QuantityLike, *, interfaces: int, nut: bool, transverse: bool = False) -> float:
    """Amount of embedding f_Z [m] from VDI 2230 Table 5.4/1 for surfaces of mean roughness ``Rz``.

    f_Z = thread + head + (nut face, for a through bolt) + ``interfaces`` x inner interface.
    """
    rz = to_si(roughness, "length", "roughness") * 1e6
    rows = _load("bolts_vdi2230.toml")["embedding"]
    row = next((r for r in rows if rz < r["Rz_max"]), None)
    if row is None:
        raise InputError(f"roughness: Table 5.4/1 covers Rz < 160 um, got {rz:g} um")
    v = row["transverse" if transverse else "axial"]
    f = v["thread"] + v["head_or_nut"] * (2 if nut else 1) + v["inner_interface"] * interfaces
    return f * 1e-6


def limiting_surface_pressure(material: str) -> float | None:
    """VDI 2230 Table A9 limiting surface pressure p_G [Pa] for a clamped-part material named in the data file
    (case and punctuation ignored; the name or its bracketed alias must match), else None."""
    def norm(t: str) -> str:
        return "".join(ch for ch in t.lower() if ch.isalnum())

    key = norm(material)
    for r in _load("bolts_vdi2230.toml")["surface_pressure"]:
        names = [r["material"], *[x.strip(" )") for x in r["material"].split("(")[1:]]]
        if key in (norm(n) for n in names) or key == norm(r["material"].split("(")[0]):
            return float(r["p_G"]) * 1e6
    return None


def tightening_factor(technique: str) -> tuple[float, float]:
    """VDI 2230 Table A8 range of the tightening factor alpha_A for a tightening technique."""
    for r in _load("bolts_vdi2230.toml")["tightening"]:
        if r["name"] == technique:
            return float(r["alpha_A"][0]), float(r["alpha_A"][1])
    names = [r["name"] for r in _load("bolts_vdi2230.toml")["tightening"]]
    raise UnknownNameError("tightening technique", technique, names)


# ============================================================================================ thread geometry


@si_function(returns="length", d="length", P="length")
def pitch_diameter(d: float, P: float) -> float:
    """Pitch diameter of an ISO metric external thread, d2 = d - 0.649519 P [m].

    Source: ISO 724:1993 (basic profile, d2 = d - 3H/4 with H = 0.866025 P); Shigley 10th ed., Table 8-1 note.
    """
    return d - 0.649519 * P


@si_function(returns="length", d="length", P="length")
def minor_diameter(d: float, P: float) -> float:
    """Minor diameter of an ISO metric external thread, d3 = d - 1.226869 P [m].

    Source: ISO 724:1993 / ISO 898-1 (d3 = d1 - H/6, the external thread's root); Shigley 10th ed., Table 8-1 note.
    """
    return d - 1.226869 * P


@si_function(returns="area", d="length", P="length")
def stress_area(d: float, P: float) -> float:
    """Tensile stress area A_s = pi/4 ((d2 + d3)/2)^2 [m^2].

    Source: ISO 898-1:2013, clause 9.1.6.1 (As,nom); Shigley 10th ed., Eq. (a) of Table 8-1: pi/4 (d - 0.938194 P)^2.
    """
    return math.pi / 4 * (d - 0.938194 * P) ** 2


# ============================================================================================ Shigley Ch. 8


@si_function(returns="force_per_length", A_d="area", A_t="area", E="pressure", l_d="length", l_t="length")
def shigley_bolt_stiffness(A_d: float, A_t: float, E: float, l_d: float, l_t: float) -> float:
    """Bolt stiffness k_b = A_d A_t E / (A_d l_t + A_t l_d) [N/m] (shank of area A_d and length l_d in series with
    the threaded part of area A_t and length l_t in the grip). Source: Shigley 10th ed., Eq. (8-17)."""
    if l_d < 0 or l_t < 0 or l_d + l_t <= 0:
        raise InputError(f"bolt stiffness: grip lengths must be >= 0 and not both zero (l_d={l_d:g}, l_t={l_t:g} m)")
    return A_d * A_t * E / (A_d * l_t + A_t * l_d)


@si_function(returns="force_per_length", E="pressure", d="length", D="length", t="length", alpha="angle")
def frustum_stiffness(E: float, d: float, D: float, t: float, alpha: float | None = None) -> float:
    """Stiffness of one conical frustum of a member: k = pi E d tan(a) / ln[(2 t tan a + D - d)(D + d) /
    ((2 t tan a + D + d)(D - d))] [N/m]; d hole (bolt) diameter, D smaller cone diameter, t frustum height.

    Source: Shigley 10th ed., Eq. (8-19); with a = 30 deg (the default), 0.5774 pi E d / ln(...) (Eq. 8-20).
    Valid D > d.
    """
    alpha = math.radians(30) if alpha is None else alpha
    if D <= d:
        raise InputError(f"frustum: the cone's small diameter D must exceed the hole diameter d (D={D:g}, d={d:g} m)")
    ta = math.tan(alpha)
    return math.pi * E * d * ta / math.log((2 * t * ta + D - d) * (D + d) / ((2 * t * ta + D + d) * (D - d)))


def shigley_member_stiffness(parts: Sequence[tuple[QuantityLike, QuantityLike]], d: QuantityLike, d_w: QuantityLike,
                             alpha: QuantityLike = "30 deg") -> pint.Quantity:
    """Member stiffness of layered clamped parts by frusta: two cones of half-angle alpha grow from the bearing faces
    (diameter d_w) to mid-grip; each cone is cut at the part interfaces into frusta of Eq. (8-19), each with its
    part's modulus and the cone diameter at its start, and all frusta act in series, k_m = (sum 1/k_i)^-1 [N/m].
    ``parts`` = [(thickness, E), ...] from the head. Source: Shigley 10th ed., Sec. 8-5, Eqs. (8-18), (8-19)/(8-20)
    and Fig. 8-15 (the procedure of Ex. 8-3 and Probs. 8-22 ff.).
    """
    layers = [(to_si(t, "length", "thickness"), to_si(E, "pressure", "E")) for t, E in parts]
    dd, dw = to_si(d, "length", "d"), to_si(d_w, "length", "d_w")
    a = to_si(alpha, "angle", "alpha")
    if not layers or any(t <= 0 for t, _ in layers):
        raise InputError("shigley_member_stiffness: give parts as (thickness > 0, E)")
    grip = sum(t for t, _ in layers)
    half = grip / 2
    flex = 0.0
    for seq in (layers, layers[::-1]):          # the cone from the head, then from the nut face
        x = 0.0                                 # distance from this cone's bearing face
        for t, E in seq:
            seg = min(t, half - x)
            if seg <= 0:
                break
            D = dw + 2 * x * math.tan(a)
            flex += 1.0 / frustum_stiffness.si(E, dd, D, seg, a)
            x += seg
    return Q(1.0 / flex, "N/m")


@si_function(returns="force_per_length", E="pressure", d="length", l="length")
def member_stiffness_equal(E: float, d: float, l: float) -> float:
    """Member stiffness of two equal-thickness members of one material, 30-degree frusta from a washer face
    d_w = 1.5 d: k_m = 0.5774 pi E d / (2 ln[5 (0.5774 l + 0.5 d)/(0.5774 l + 2.5 d)]) [N/m], l = grip.

    Source: Shigley 10th ed., Eq. (8-22).
    """
    return 0.5774 * math.pi * E * d / (2 * math.log(5 * (0.5774 * l + 0.5 * d) / (0.5774 * l + 2.5 * d)))


#: Wileman's constants (A, B) of Eq. (8-23) by material; Shigley 10th ed., Table 8-8.
WILEMAN = {"steel": (0.78715, 0.62873), "aluminium": (0.79670, 0.63816), "copper": (0.79568, 0.63553),
           "gray cast iron": (0.77871, 0.61616), "general": (0.78952, 0.62914)}


@si_function(returns="force_per_length", E="pressure", d="length", l="length")
def wileman_member_stiffness(E: float, d: float, l: float, A: float = 0.78715, B: float = 0.62873) -> float:
    """Member stiffness by Wileman's finite-element fit, k_m = E d A exp(B d / l) [N/m], l = grip.

    Source: Shigley 10th ed., Eq. (8-23) and Table 8-8 (A, B by material; defaults steel); Wileman et al. (1991).
    Both members of one material.
    """
    return E * d * A * math.exp(B * d / l)


def joint_constant(k_b: QuantityLike, k_m: QuantityLike) -> float:
    """Stiffness constant of the joint C = k_b / (k_b + k_m), the fraction of the external load the bolt takes.

    Source: Shigley 10th ed., Sec. 8-7, Eq. (f) (equal to VDI 2230's Phi_K for load introduction at the head)."""
    kb, km = to_si(k_b, "force_per_length", "k_b"), to_si(k_m, "force_per_length", "k_m")
    return kb / (kb + km)


@si_function(returns="force", A_t="area", S_p="pressure")
def shigley_preload(A_t: float, S_p: float, permanent: bool = False) -> float:
    """Recommended preload F_i = 0.75 F_p (reused connections) or 0.90 F_p (permanent), F_p = A_t S_p [N].

    Source: Shigley 10th ed., Eq. (8-31).
    """
    return (0.90 if permanent else 0.75) * A_t * S_p


def shigley_yielding_factor(S_p: QuantityLike, A_t: QuantityLike, C: float, P: QuantityLike,
                            F_i: QuantityLike) -> float:
    """Yielding factor of safety against the proof strength n_p = S_p A_t / (C P + F_i).
    Source: Shigley 10th ed., Eq. (8-28)."""
    Sp, At = to_si(S_p, "pressure", "S_p"), to_si(A_t, "area", "A_t")
    p, fi = to_si(P, "force", "P"), to_si(F_i, "force", "F_i")
    return Sp * At / (C * p + fi)


def shigley_load_factor(S_p: QuantityLike, A_t: QuantityLike, C: float, P: QuantityLike, F_i: QuantityLike) -> float:
    """Load factor n_L = (S_p A_t - F_i)/(C P). Source: Shigley 10th ed., Eq. (8-29)."""
    Sp, At = to_si(S_p, "pressure", "S_p"), to_si(A_t, "area", "A_t")
    p, fi = to_si(P, "force", "P"), to_si(F_i, "force", "F_i")
    return (Sp * At - fi) / (C * p)


def shigley_separation_factor(F_i: QuantityLike, C: float, P: QuantityLike) -> float:
    """Load factor against joint separation n_0 = F_i / (P (1 - C)). Source: Shigley 10th ed., Eq. (8-30)."""
    return to_si(F_i, "force", "F_i") / (to_si(P, "force", "P") * (1 - C))


@si_function(returns="pressure", S_e="pressure", S_ut="pressure", sigma_i="pressure")
def bolt_goodman_strength(S_e: float, S_ut: float, sigma_i: float) -> float:
    """Strength amplitude S_a = S_e (S_ut - sigma_i)/(S_ut + S_e) where the load line of a preloaded bolt (slope 1
    from sigma_i) meets the modified Goodman line. Source: Shigley 10th ed., Sec. 8-11 (Goodman, Eq. 8-38)."""
    return S_e * (S_ut - sigma_i) / (S_ut + S_e)


@si_function(returns="pressure", S_e="pressure", S_ut="pressure", sigma_i="pressure")
def bolt_gerber_strength(S_e: float, S_ut: float, sigma_i: float) -> float:
    """Strength amplitude on the Gerber parabola: S_a = [S_ut sqrt(S_ut^2 + 4 S_e (S_e + sigma_i)) - S_ut^2
    - 2 sigma_i S_e] / (2 S_e). Source: Shigley 10th ed., Sec. 8-11 (Gerber fatigue criterion)."""
    return (S_ut * math.sqrt(S_ut**2 + 4 * S_e * (S_e + sigma_i)) - S_ut**2 - 2 * sigma_i * S_e) / (2 * S_e)


@si_function(returns="pressure", S_p="pressure", sigma_i="pressure")
def bolt_proof_line_strength(S_p: float, sigma_i: float) -> float:
    """Amplitude where the load line meets the (Langer) proof-strength line S_a + S_m = S_p: S_a = (S_p - sigma_i)/2.
    Source: Shigley 10th ed., Sec. 8-11, Fig. 8-20 (proof-strength line)."""
    return 0.5 * (S_p - sigma_i)


@si_function(returns=("pressure", "pressure"), C="dimensionless", P_max="force", P_min="force", F_i="force", A_t="area")
def bolt_stress_components(C: float, P_max: float, P_min: float, F_i: float, A_t: float) -> tuple[float, float]:
    """Alternating and mean bolt stress under a fluctuating external load: sigma_a = C (P_max - P_min)/(2 A_t),
    sigma_m = C (P_max + P_min)/(2 A_t) + F_i/A_t. Source: Shigley 10th ed., Eqs. (8-35), (8-36)."""
    return C * (P_max - P_min) / (2 * A_t), C * (P_max + P_min) / (2 * A_t) + F_i / A_t


# ============================================================================================ VDI 2230


def _cyl(l: float, dia: float, E: float) -> float:
    return 4.0 * l / (E * math.pi * dia * dia)


@si_function(l="length", dia="length", E="pressure")
def cylinder_resilience(l: float, dia: float, E: float) -> float:
    """Elastic resilience of a cylindrical bolt section delta_i = l_i / (E_S A_i), A_i = pi d_i^2/4 [m/N, SI float].
    Source: VDI 2230 Part 1:2015, Eq. (5.1/2) ff. (Sec. 5.1.1)."""
    return _cyl(l, dia, E)


@si_function(d="length", E="pressure")
def head_resilience(d: float, E: float, head: str = "hex") -> float:
    """Resilience of the bolt head delta_SK = l_SK / (E_S A_N), l_SK = 0.5 d (hexagon head) or 0.4 d (socket head),
    A_N = pi d^2/4 [m/N, SI float]. Source: VDI 2230 Part 1:2015, Sec. 5.1.1.1."""
    if head not in ("hex", "socket"):
        raise InputError(f"head: expected 'hex' or 'socket', got {head!r}")
    return _cyl((0.5 if head == "hex" else 0.4) * d, d, E)


@si_function(d="length", d3="length", E_S="pressure", E_M="pressure")
def engaged_thread_resilience(d: float, d3: float, E_S: float, E_M: float, nut: bool = True) -> float:
    """Resilience of the engaged thread delta_GM = delta_G + delta_M: the bolt's thread l_G = 0.5 d of area A_d3 and
    the nut (l_M = 0.4 d) or tapped thread (l_M = 0.33 d) of area A_N with the internal thread's modulus E_M
    [m/N, SI float]. Source: VDI 2230 Part 1:2015, Sec. 5.1.1.1 (Eqs. 5.1/7 to 5.1/11)."""
    return _cyl(0.5 * d, d3, E_S) + _cyl((0.4 if nut else 0.33) * d, d, E_M)


@si_function(l_K="length", d_W="length", D_A="length")
def cone_angle_tan(l_K: float, d_W: float, D_A: float | None = None, through: bool = True) -> float:
    """tan(phi) of the substitute deformation cone: through-bolted (DSV) tan phi_D = 0.362 + 0.032 ln(beta_L/2)
    + 0.153 ln y; tapped (ESV) tan phi_E = 0.348 + 0.013 ln beta_L + 0.193 ln y; beta_L = l_K/d_W, y = D_A/d_W
    (y is capped where the cone stays inside D_A; an unbounded part uses the cone's full width).
    Source: VDI 2230 Part 1:2015, Sec. 5.1.2.1, Eqs. (5.1/21), (5.1/22)."""
    beta = l_K / d_W
    w = 1.0 if through else 2.0
    if D_A is None:
        # the cone's own limiting diameter D_A,Gr = d_W + w l_K tan(phi): solve y = D_A,Gr/d_W by fixed point
        y = 1.0 + w * beta * 0.6
        for _ in range(50):
            t = (0.362 + 0.032 * math.log(beta / 2) + 0.153 * math.log(y)) if through else \
                (0.348 + 0.013 * math.log(beta) + 0.193 * math.log(y))
            y_new = 1.0 + w * beta * t
            if abs(y_new - y) < 1e-12:
                break
            y = y_new
        return t
    y = max(D_A / d_W, 1.0)
    return (0.362 + 0.032 * math.log(beta / 2) + 0.153 * math.log(y)) if through else \
        (0.348 + 0.013 * math.log(beta) + 0.193 * math.log(y))


@si_function(l_K="length", d_W="length", d_h="length", E_P="pressure", D_A="length")
def plate_resilience(l_K: float, d_W: float, d_h: float, E_P: float, D_A: float | None = None,
                     through: bool = True) -> float:
    """Resilience delta_P of the clamped parts (one material) by the substitute deformation cone [m/N, SI float].

    Cone only (D_A >= D_A,Gr = d_W + w l_K tan phi, or D_A not given)::

        delta_P = 2 ln[(d_W + d_h)(d_W + w l_K tan phi - d_h) / ((d_W - d_h)(d_W + w l_K tan phi + d_h))]
                  / (w E_P pi d_h tan phi)

    Cone and sleeve (d_W < D_A < D_A,Gr)::

        delta_P = [2/(w d_h tan phi) ln((d_W + d_h)(D_A - d_h)/((d_W - d_h)(D_A + d_h)))
                   + 4/(D_A^2 - d_h^2) (l_K - (D_A - d_W)/(w tan phi))] / (E_P pi)

    with w = 1 through-bolted (DSV), w = 2 tapped (ESV). Source: VDI 2230 Part 1:2015, Sec. 5.1.2.2, Eqs. (5.1/24),
    (5.1/25). Valid d_W > d_h.
    """
    if d_W <= d_h:
        raise InputError(f"head bearing diameter d_W = {d_W * 1e3:g} mm must exceed the hole diameter "
                         f"d_h = {d_h * 1e3:g} mm")
    w = 1.0 if through else 2.0
    t = cone_angle_tan.si(l_K, d_W, D_A, through)
    d_gr = d_W + w * l_K * t
    if D_A is None or D_A >= d_gr:
        num = (d_W + d_h) * (d_W + w * l_K * t - d_h)
        den = (d_W - d_h) * (d_W + w * l_K * t + d_h)
        return 2 * math.log(num / den) / (w * E_P * math.pi * d_h * t)
    if D_A <= d_W:  # a sleeve only
        return 4 * l_K / (E_P * math.pi * (D_A**2 - d_h**2))
    cone = 2 / (w * d_h * t) * math.log((d_W + d_h) * (D_A - d_h) / ((d_W - d_h) * (D_A + d_h)))
    sleeve = 4 / (D_A**2 - d_h**2) * (l_K - (D_A - d_W) / (w * t))
    return (cone + sleeve) / (E_P * math.pi)


def load_factor(delta_S: float, delta_P: float, n: float = 1.0) -> float:
    """Load factor Phi_n = n delta_P / (delta_S + delta_P) (n = load-introduction factor; n = 1: load at the head and
    nut faces, Phi_K). Source: VDI 2230 Part 1:2015, Sec. 5.3.1, Eq. (5.3/11). Resiliences in m/N."""
    if not 0 < n <= 1:
        raise InputError(f"load-introduction factor n must be within (0, 1], got {n:g}")
    return n * delta_P / (delta_S + delta_P)


@si_function(returns="force", f_Z="length")
def embedding_loss(f_Z: float, delta_S: float, delta_P: float) -> float:
    """Preload loss by embedding F_Z = f_Z / (delta_S + delta_P) [N]. Source: VDI 2230 Part 1:2015, Eq. (5.4/1), R6."""
    return f_Z / (delta_S + delta_P)


@si_function(returns="force", l_K="length", dT_S="temperature", dT_P="temperature")
def thermal_preload_change(l_K: float, alpha_S: float, alpha_P: float, dT_S: float, dT_P: float,
                           delta_S: float, delta_P: float) -> float:
    """Preload change by temperature (positive = loss):
    Delta F_Vth = l_K (alpha_S dT_S - alpha_P dT_P)/(delta_S + delta_P) [N] (elastic moduli at room temperature):
    a bolt expanding more than the parts loses preload.
    Source: VDI 2230 Part 1:2015, Sec. 5.4.2.3 (Eq. 5.4/18, moduli held constant)."""
    return l_K * (alpha_S * dT_S - alpha_P * dT_P) / (delta_S + delta_P)


@si_function(returns="force", F_KR="force", F_A="force", F_Z="force", dF_Vth="force")
def min_assembly_preload(F_KR: float, F_A: float, Phi_n: float, F_Z: float, dF_Vth: float = 0.0) -> float:
    """Minimum assembly preload F_M,min = F_KR + (1 - Phi_n) F_A,max + F_Z + Delta F_Vth (losses only) [N].
    Source: VDI 2230 Part 1:2015, R4, Eq. (R4/1)."""
    return F_KR + (1 - Phi_n) * F_A + F_Z + max(dF_Vth, 0.0)


@si_function(returns="force", A_S="area", d2="length", d0="length", P="length", Rp02="pressure")
def permissible_assembly_preload(A_S: float, d2: float, d0: float, P: float, Rp02: float, mu_G: float,
                                 nu: float = 0.9) -> float:
    """Permissible assembly preload at a utilisation nu of the minimum yield strength (von Mises with the thread
    torsion at mu_G,min): F_M,zul = A_0 nu R_p0.2min / sqrt(1 + 3 [3/2 d2/d0 (P/(pi d2) + 1.155 mu_G,min)]^2) [N],
    A_0 = A_S, d0 = (d2 + d3)/2. Source: VDI 2230 Part 1:2015, R7, Eq. (R7/2) (the F_M,Tab of Table A1 at nu = 0.9)."""
    if mu_G < 0:
        raise InputError(f"mu_G must be >= 0, got {mu_G:g}")
    k = 1.5 * d2 / d0 * (P / (math.pi * d2) + 1.155 * mu_G)
    return A_S * nu * Rp02 / math.sqrt(1 + 3 * k * k)


@si_function(returns="torque", F_M="force", P="length", d2="length", D_Km="length")
def tightening_torque(F_M: float, P: float, d2: float, D_Km: float, mu_G: float, mu_K: float) -> float:
    """Tightening torque M_A = F_M (0.16 P + 0.58 d2 mu_G + D_Km/2 mu_K) [N m], D_Km = mean head-bearing diameter.
    Source: VDI 2230 Part 1:2015, R13, Eq. (R13/1) (60-degree ISO thread)."""
    if mu_G < 0 or mu_K < 0:
        raise InputError(f"friction coefficients must be >= 0, got mu_G={mu_G:g}, mu_K={mu_K:g}")
    return F_M * (0.16 * P + 0.58 * d2 * mu_G + 0.5 * D_Km * mu_K)


@si_function(returns="torque", F_M="force", P="length", d2="length")
def thread_torque(F_M: float, P: float, d2: float, mu_G: float) -> float:
    """Thread torque M_G = F_M d2/2 (P/(pi d2) + 1.155 mu_G) [N m]. Source: VDI 2230 Part 1:2015, Eq. (5.4/20)."""
    return F_M * 0.5 * d2 * (P / (math.pi * d2) + 1.155 * mu_G)


@si_function(returns="pressure", F_S="force", M_G="torque", d0="length")
def working_stress(F_S: float, M_G: float, d0: float, k_tau: float = 0.5) -> float:
    """Reduced (von Mises) working stress sigma_red,B = sqrt(sigma_z^2 + 3 (k_tau tau)^2), sigma_z = F_S,max/A_0,
    tau = M_G / W_P, W_P = pi d0^3/16, k_tau = 0.5 (torsion relaxed in service). Source: VDI 2230 Part 1:2015, R8."""
    A0 = math.pi / 4 * d0 * d0
    tau = M_G / (math.pi * d0**3 / 16)
    return math.sqrt((F_S / A0) ** 2 + 3 * (k_tau * tau) ** 2)


@si_function(returns="pressure", d="length")
def endurance_rolled_before_ht(d: float) -> float:
    """Endurance limit (stress amplitude) of threads rolled before heat treatment, sigma_ASV = 0.85 (150/d + 45) MPa
    with d in mm, N_D = 2e6 cycles. Source: VDI 2230 Part 1:2015, R9, Eq. (R9/4). Valid d <= 40 mm."""
    return 0.85 * (150.0 / (d * 1e3) + 45.0) * 1e6


@si_function(returns="pressure", d="length", F_Sm="force", F_02="force")
def endurance_rolled_after_ht(d: float, F_Sm: float, F_02: float) -> float:
    """Endurance limit of threads rolled after heat treatment, sigma_ASG = (2 - F_Sm/F_0.2min) sigma_ASV, valid
    0.3 < F_Sm/F_0.2min < 1 (the ratio is clamped to that range). Source: VDI 2230 Part 1:2015, R9, Eq. (R9/5)."""
    r = min(max(F_Sm / F_02, 0.3), 1.0)
    return (2.0 - r) * endurance_rolled_before_ht.si(d)


@si_function(returns="pressure", F="force", d_W="length", d_h="length")
def bearing_pressure(F: float, d_W: float, d_h: float) -> float:
    """Surface pressure under the head or nut p = F / A_p, A_p = pi/4 (d_W^2 - d_h^2) [Pa].
    Source: VDI 2230 Part 1:2015, R10, Eqs. (R10/1)-(R10/3)."""
    if d_W <= d_h:
        raise InputError(f"bearing diameter d_W = {d_W * 1e3:g} mm must exceed the hole diameter "
                         f"d_h = {d_h * 1e3:g} mm")
    return F / (math.pi / 4 * (d_W**2 - d_h**2))


def alexander_C1(s_over_d: float | None) -> float:
    """Nut-dilation factor C1 = 3.8 s/d - (s/d)^2 - 2.61 for 1.4 <= s/d < 1.9, 1 for a tapped hole (None) or s/d >= 1.9.
    Source: VDI 2230 Part 1:2015, Sec. 5.5.5.2 (Alexander 1977)."""
    if s_over_d is None or s_over_d >= 1.9:
        return 1.0
    if s_over_d < 1.4:
        raise InputError(f"nut width across flats / d = {s_over_d:.3g} is below 1.4, outside Alexander's range")
    return 3.8 * s_over_d - s_over_d**2 - 2.61


def alexander_C3(R_S: float) -> float:
    """Thread-bending factor of the internal thread C3 = 0.728 + 1.769 R_S - 2.896 R_S^2 + 1.296 R_S^3 for
    0.4 < R_S < 1, 0.897 for R_S >= 1 (R_S = internal/external thread shear strength ratio); below 0.4 (outside the
    model) the value at 0.4 is used. Source: VDI 2230 Part 1:2015, Sec. 5.5.5.2 (Alexander 1977); C1 and C3 as
    quoted, corroborated by a third-party code reproduction (S. Vargas-Ortega, 'DVI bolt design tool', VD_555)."""
    r = min(max(R_S, 0.4), 1.0)
    return 0.728 + 1.769 * r - 2.896 * r**2 + 1.296 * r**3


@si_function(returns="area", d="length", P="length", m_eff="length")
def internal_thread_shear_area(d: float, P: float, m_eff: float) -> float:
    """Shear area of the internal thread A_SGM = pi d m_eff/P [P/2 + (d - D2) tan 30 deg] [m^2], D2 = d2 (basic).
    Source: VDI 2230 Part 1:2015, Sec. 5.5.5.2, Eq. (5.5/44) (Alexander)."""
    D2 = d - 0.649519 * P
    return math.pi * d * m_eff / P * (P / 2 + (d - D2) * math.tan(math.radians(30)))


@si_function(returns="area", d="length", P="length", m_eff="length")
def external_thread_shear_area(d: float, P: float, m_eff: float) -> float:
    """Shear area of the bolt thread A_SGS = pi d1 m_eff/P [P/2 + (d2 - D1) tan 30 deg] [m^2]
    (basic d2, D1 = d - 1.082532 P).
    Source: VDI 2230 Part 1:2015, Sec. 5.5.5.2, Eq. (5.5/42) (Alexander)."""
    D1 = d - 1.082532 * P
    d2 = d - 0.649519 * P
    return math.pi * D1 * m_eff / P * (P / 2 + (d2 - D1) * math.tan(math.radians(30)))


@si_function(returns="force", F_Q="force")
def slip_clamp_load(F_Q: float, mu_T: float, q_F: int = 1) -> float:
    """Clamp load required against slip F_KQerf = F_Q,max / (q_F mu_T,min) [N] (q_F force-transmitting interfaces).
    Source: VDI 2230 Part 1:2015, R2, Eq. (R2/1)."""
    if mu_T <= 0:
        raise InputError(f"interface friction mu_T must be > 0 for a transverse load, got {mu_T:g}")
    if q_F < 1:
        raise InputError(f"q_F (friction interfaces) must be >= 1, got {q_F}")
    return F_Q / (q_F * mu_T)


# ============================================================================================ the joint


@dataclass(frozen=True)
class ClampedPart:
    """One clamped plate: thickness [m], Young's modulus [Pa], thermal expansion [1/K], tensile strength R_m and
    limiting surface pressure p_G [Pa] (p_G None: its compressive yield strength is used, with a note)."""

    thickness: float
    E: float
    alpha: float
    name: str = ""
    Rm: float | None = None
    p_G: float | None = None
    yield_strength: float | None = None
    shear_ratio: float = 0.6    # tau_B / R_m of the material (SHEAR_RATIO by category)

    @classmethod
    def of(cls, thickness: QuantityLike, material: Any, *, p_G: QuantityLike | None = None,
           thermal_expansion: float | None = None) -> ClampedPart:
        """A part of ``material`` (a :class:`mechverify.materials.Material` or its name)."""
        from mechverify import materials as _m  # components may use materials (layer order)

        mat = _m.get(material) if isinstance(material, str) else material
        t = to_si(thickness, "length", "thickness")
        if t <= 0:
            raise InputError(f"clamped part {mat.name}: thickness must be > 0, got {fmt(Q(t, 'm'), 'mm')}")
        if mat.E is None:
            raise InputError(f"clamped part material {mat.name} has no Young's modulus")
        alpha = thermal_expansion if thermal_expansion is not None else THERMAL_EXPANSION.get(mat.category, ALPHA_STEEL)
        cy = mat.compressive_yield_strength or mat.yield_strength
        pg = to_si(p_G, "pressure", "p_G") if p_G is not None else limiting_surface_pressure(mat.name)
        return cls(t, to_si(mat.E, "pressure"), float(alpha), mat.name,
                   None if mat.ultimate_strength is None else to_si(mat.ultimate_strength, "pressure"), pg,
                   None if cy is None else to_si(cy, "pressure"), SHEAR_RATIO.get(mat.category, 0.6))

    @property
    def limiting_pressure(self) -> float | None:
        return self.p_G if self.p_G is not None else self.yield_strength


@dataclass(frozen=True)
class JointAnalysis:
    """Every intermediate value of one single-bolt calculation (SI floats: N, m, Pa, N m, m/N)."""

    delta_S: float
    delta_P: float
    Phi_K: float
    Phi_n: float
    F_A_max: float
    F_A_min: float
    F_Q: float
    F_Z: float
    dF_Vth: float
    F_KQ: float          # clamp load required against slip
    F_K_req: float       # residual clamp load required (user, sealing)
    F_M_min: float       # the smallest assembly preload the tightening gives
    F_M_max: float       # the largest
    F_M_zul: float       # permissible at nu, mu_G,min
    F_M_req: float       # required minimum assembly preload (R4)
    F_SA: float          # additional bolt force at F_A,max
    F_PA: float          # plate relief at F_A,max
    sigma_red_M: float   # assembly stress at F_M_max (mu_G,min)
    sigma_red_B: float   # working stress
    sigma_a: float
    sigma_AS: float
    p_head: float
    p_nut: float | None
    stripping_capacity: float
    stripping_demand: float
    F_KR_min: float      # smallest residual clamp load in service
    M_A: float           # tightening torque to set (or given)
    torque_table: tuple[tuple[float, float, float], ...]  # (mu, F_M_zul, M_A) rows for mu_G = mu_K in the range
    notes: tuple[str, ...] = ()
    strength_ratio: float = 1.0  # R_S of Alexander's stripping model (internal/external thread shear strength)


@dataclass(frozen=True)
class BoltedJoint:
    """One ISO metric bolt clamping ``parts`` (VDI 2230 Part 1, concentric, axially loaded; transverse loads by
    friction).

    ``tapped=None``: through-bolted joint with an ISO 4032 nut (DSV); else the bolt is screwed into a tapped hole
    in the part ``tapped`` (ESV, its thickness unused), the engagement being ``length - clamp length``. Friction
    pairs are (min, max).
    Preload: ``tightening_torque`` when given, else tightened to F_M,zul at ``nu`` (mu_G,min) and scattered down
    by ``alpha_A``.
    """

    name: str
    thread: MetricThread
    grade: PropertyClass
    parts: tuple[ClampedPart, ...]
    length: float
    head: str = "hex"
    tapped: ClampedPart | None = None
    d_W: float = 0.0            # head bearing diameter (0: from the ISO head table)
    d_h: float = 0.0            # hole diameter (0: ISO 273 medium)
    d_W_nut: float = 0.0        # nut (or washer) bearing diameter (0: ISO 4032 d_w)
    D_A: float | None = None    # outer diameter of the clamped body (None: unbounded, full cone)
    shank_length: float | None = None  # unthreaded shank (None: L - thread length of the standard)
    mu_G: tuple[float, float] = (0.10, 0.16)
    mu_K: tuple[float, float] = (0.10, 0.16)
    mu_T: float | None = None   # interface friction (min) for transverse loads
    q_F: int = 1
    alpha_A: float = 1.6
    nu: float = 0.9
    tightening_torque: float | None = None
    n: float = 0.5
    roughness: float = 16e-6
    rolled_after_heat_treatment: bool = False
    E_S: float = E_STEEL_BOLT
    alpha_S: float = ALPHA_STEEL
    F_K_req: float = 0.0
    internal_Rm: float | None = None  # R_m of the nut / tapped part (None: nut = bolt class, tapped = its part)
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for label, pair in (("mu_G", self.mu_G), ("mu_K", self.mu_K)):
            lo, hi = pair
            if lo < 0 or hi < 0:
                raise InputError(f"{self.name}: {label} must not be negative, got {lo:g}..{hi:g}")
            if lo > hi:
                raise InputError(f"{self.name}: {label} range reversed ({lo:g} > {hi:g})")
        if self.mu_T is not None and self.mu_T < 0:
            raise InputError(f"{self.name}: mu_T must not be negative, got {self.mu_T:g}")
        if not self.parts:
            raise InputError(f"{self.name}: at least one clamped part is needed")
        if self.head not in ("hex", "socket"):
            raise InputError(f"{self.name}: head must be 'hex' or 'socket', got {self.head!r}")
        if self.alpha_A < 1:
            raise InputError(f"{self.name}: tightening factor alpha_A must be >= 1, got {self.alpha_A:g}")
        if not 0 < self.nu <= 1:
            raise InputError(f"{self.name}: utilisation nu must be within (0, 1], got {self.nu:g}")
        lk = self.clamp_length
        if lk <= 0:
            raise InputError(f"{self.name}: clamp length must be > 0, got {lk * 1e3:g} mm")
        if lk >= self.length:
            raise InputError(f"{self.name}: clamp length {lk * 1e3:g} mm is not shorter than the bolt "
                             f"({self.length * 1e3:g} mm)")
        if self.d_W_eff <= self.d_h_eff:
            raise InputError(f"{self.name}: head bearing diameter {self.d_W_eff * 1e3:g} mm is not larger than the "
                             f"hole {self.d_h_eff * 1e3:g} mm")
        if not self.through and self.engagement <= 0:
            raise InputError(f"{self.name}: no thread engagement left in the tapped hole")

    # ------------------------------------------------------------------------------------ geometry
    @property
    def through(self) -> bool:
        """True for a through-bolted joint with a nut (DSV), False for a tapped thread (ESV)."""
        return self.tapped is None

    @property
    def interfaces(self) -> int:
        """Inner interfaces between clamped parts (and the tapped body)."""
        return len(self.parts) - 1 + (0 if self.through else 1)

    @property
    def clamp_length(self) -> float:
        return sum(p.thickness for p in self.parts)

    @property
    def d_W_eff(self) -> float:
        return self.d_W or head_bearing_diameter(self.thread, self.head)

    @property
    def d_h_eff(self) -> float:
        return self.d_h or clearance_hole(self.thread, "medium")

    @property
    def engagement(self) -> float:
        """Engaged thread length m_eff [m]: the nut height (through) or what enters the tapped hole."""
        if self.through:
            return nut_dimensions(self.thread)["m"]
        return self.length - self.clamp_length

    @property
    def effective_engagement(self) -> float:
        """Load-bearing engaged length m_eff = m_ges - m_zu, m_zu = 2 P of non-bearing thread (chamfers and run-out).

        Source: VDI 2230 Part 1:2015, Sec. 5.5.5 (m_ges = m_eff + m_zu, m_zu = 2P), as summarised in HEXAGON Info
        Letter No. 148 (2014) on the new VDI 2230 release (not checked against the guideline itself)."""
        return self.engagement - 2 * self.thread.P

    @property
    def thread_length(self) -> float:
        """Threaded length b: 2d + 6 mm (hex bolts, Shigley Table 8-7 for L <= 125 mm) or 2d + 12 mm (ISO 4762)."""
        b = 2 * self.thread.d + (6e-3 if self.head == "hex" else 12e-3)
        return min(b, self.length)

    @property
    def grip_sections(self) -> tuple[float, float]:
        """(shank length l_d, free threaded length l_t) within the clamp length."""
        shank = self.shank_length if self.shank_length is not None else max(self.length - self.thread_length, 0.0)
        l_d = min(shank, self.clamp_length)
        return l_d, self.clamp_length - l_d

    # ------------------------------------------------------------------------------------ resiliences
    @property
    def delta_S(self) -> float:
        """Bolt resilience: head + shank + free loaded thread + engaged thread (+ nut) [m/N]. VDI 2230 Sec. 5.1.1."""
        th, E = self.thread, self.E_S
        l_d, l_t = self.grip_sections
        E_M = E if self.tapped is None else self.tapped.E
        return (head_resilience.si(th.d, E, self.head) + _cyl(l_d, th.d, E) + _cyl(l_t, th.d3, E)
                + engaged_thread_resilience.si(th.d, th.d3, E, E_M, self.through))

    @property
    def delta_P(self) -> float:
        """Plate resilience by the substitute cone, parts in series with their own moduli (the cone of the whole
        clamp length, each part's share by thickness) [m/N]. VDI 2230 Sec. 5.1.2."""
        lk = self.clamp_length
        return sum(plate_resilience.si(lk, self.d_W_eff, self.d_h_eff, p.E, self.D_A, self.through) * p.thickness / lk
                   for p in self.parts)

    @property
    def stiffness_bolt(self) -> float:
        return 1.0 / self.delta_S

    @property
    def stiffness_parts(self) -> float:
        return 1.0 / self.delta_P

    def shigley_constant(self) -> tuple[float, float, float]:
        """(k_b, k_m, C) by Shigley's method for comparison with VDI's Phi_K: k_b of Eq. (8-17) over the grip, k_m of
        the layered frusta from the bearing diameters (a tapped body adds d/2 to the grip, Table 8-7)."""
        th = self.thread
        layers = [(Q(p.thickness, "m"), Q(p.E, "Pa")) for p in self.parts]
        if self.tapped is not None:
            layers.append((Q(th.d / 2, "m"), Q(self.tapped.E, "Pa")))
        grip = sum(t.m_as("m") for t, _ in layers)
        l_d = min(self.grip_sections[0], grip)
        kb = shigley_bolt_stiffness.si(math.pi / 4 * th.d**2, th.As, self.E_S, l_d, grip - l_d)
        km = shigley_member_stiffness(layers, Q(th.d, "m"), Q(self.d_W_eff, "m")).m_as("N/m")
        return kb, km, kb / (kb + km)

    @property
    def D_Km(self) -> float:
        """Effective diameter of the head friction moment D_Km = (d_W + d_h)/2 [m]."""
        return 0.5 * (self.d_W_eff + self.d_h_eff)

    def F_M_zul(self, mu_G: float | None = None, nu: float | None = None) -> float:
        th = self.thread
        return permissible_assembly_preload.si(th.As, th.d2, th.d0, th.P, self.grade.Rp02,
                                               self.mu_G[0] if mu_G is None else mu_G, self.nu if nu is None else nu)

    def torque_factor(self, mu_G: float, mu_K: float) -> float:
        """M_A / F_M [m] at the given friction (R13)."""
        th = self.thread
        return tightening_torque.si(1.0, th.P, th.d2, self.D_Km, mu_G, mu_K)

    def preloads(self) -> tuple[float, float, float, list[str]]:
        """(F_M,min, F_M,max, M_A) the tightening gives, with notes."""
        notes = []
        lo_G, hi_G = self.mu_G
        lo_K, hi_K = self.mu_K
        if self.tightening_torque is not None:
            MA = self.tightening_torque
            fmax = MA / self.torque_factor(lo_G, lo_K)
            fmin = MA / self.torque_factor(hi_G, hi_K) / self.alpha_A
            notes.append(f"tightening torque {MA:.4g} N·m given: F_M,max at mu_min = {fmax / 1e3:.4g} kN, F_M,min at "
                         f"mu_max / alpha_A ({self.alpha_A:g}, torque scatter) = {fmin / 1e3:.4g} kN")
            return fmin, fmax, MA, notes
        fmax = self.F_M_zul()
        MA = fmax * self.torque_factor(lo_G, lo_K)
        notes.append(f"tightened to F_M,zul = {fmax / 1e3:.4g} kN ({self.nu:g} R_p0.2 at mu_G,min = {lo_G:g}) with "
                     f"M_A = {MA:.4g} N·m (R13 at mu_min); F_M,min = F_M,zul/alpha_A, alpha_A = {self.alpha_A:g}")
        return fmax / self.alpha_A, fmax, MA, notes

    # ------------------------------------------------------------------------------------ analysis
    def analyse(self, F_A: QuantityLike = "0 N", *, F_A_min: QuantityLike = "0 N", F_Q: QuantityLike = "0 N",
                dT: QuantityLike = "0 K") -> JointAnalysis:
        """The single-bolt calculation (VDI 2230 R0-R13) for an axial working load cycling between ``F_A_min`` and
        ``F_A`` (tension > 0), a transverse load ``F_Q`` and a uniform temperature change ``dT`` of bolt and parts."""
        FA = to_si(F_A, "force", "F_A")
        FAmin = to_si(F_A_min, "force", "F_A_min")
        FQ = abs(to_si(F_Q, "force", "F_Q"))
        dTk = as_quantity(dT, "temperature", "dT")
        if not dTk._is_multiplicative:  # an absolute (offset) temperature such as 20 degC
            raise InputError(f"{self.name}: dT is a temperature change; give it in K or delta_degC, not {dTk.units}")
        dT_K = float(dTk.to("K").magnitude)
        if FA < 0:
            raise InputError(f"{self.name}: F_A is the axial tension on the joint (>= 0); a compressive load only "
                             f"adds clamp load, give 0")
        if FAmin > FA:
            raise InputError(f"{self.name}: F_A_min ({FAmin:g} N) exceeds F_A ({FA:g} N)")
        if FQ > 0 and self.mu_T is None:
            raise InputError(f"{self.name}: a transverse load of {FQ:g} N needs the interface friction mu_T "
                             f"(friction data) of the joint")
        th, g = self.thread, self.grade
        dS, dP = self.delta_S, self.delta_P
        PhiK = load_factor(dS, dP, 1.0)
        Phin = load_factor(dS, dP, self.n)
        nut_face = self.through
        fZ = embedding_amount(Q(self.roughness, "m"), interfaces=self.interfaces, nut=nut_face, transverse=FQ > 0)
        FZ = embedding_loss.si(fZ, dS, dP)
        alpha_P = sum(p.alpha * p.thickness for p in self.parts) / self.clamp_length
        dFth = thermal_preload_change.si(self.clamp_length, self.alpha_S, alpha_P, dT_K, dT_K, dS, dP)
        FKQ = slip_clamp_load.si(FQ, self.mu_T, self.q_F) if FQ > 0 else 0.0
        FKR = max(FKQ, self.F_K_req)
        F_M_req = min_assembly_preload.si(FKR, FA, Phin, FZ, dFth)
        fmin, fmax, MA, notes = self.preloads()
        FMzul = self.F_M_zul()
        FSA = Phin * FA
        FPA = (1 - Phin) * FA
        # assembly stress at F_M,max, thread torque at mu_G,min (R7 inverted)
        k = 1.5 * th.d2 / th.d0 * (th.P / (math.pi * th.d2) + 1.155 * self.mu_G[0])
        sig_M = fmax / th.As * math.sqrt(1 + 3 * k * k)
        # working stress (R8)
        gain = max(-dFth, 0.0)  # a thermal preload gain adds to the bolt force, a loss is not relied on here
        F_S_max = fmax + FSA + gain
        M_G = thread_torque.si(fmax, th.P, th.d2, self.mu_G[0])
        sig_B = working_stress.si(F_S_max, M_G, th.d0)
        # fatigue (R9/1): amplitude on the stress area A_S, to which sigma_ASV/ASG refer (VDI 2230:2015)
        sig_a = Phin * (FA - FAmin) / (2 * th.As)
        F_Sm = fmax + Phin * (FA + FAmin) / 2
        F02 = th.As * g.Rp02
        sig_AS = endurance_rolled_after_ht.si(th.d, F_Sm, F02) if self.rolled_after_heat_treatment else \
            endurance_rolled_before_ht.si(th.d)
        # surface pressure (R10): assembly and service, the larger
        F_V_max = fmax - FZ
        F_press = max(fmax, F_V_max + FSA + gain)
        p_head = bearing_pressure.si(F_press, self.d_W_eff, self.d_h_eff)
        p_nut = None
        if self.through:
            dw_nut = self.d_W_nut or nut_dimensions(th)["dw"]
            if dw_nut <= self.d_h_eff:
                raise InputError(f"{self.name}: nut bearing diameter {dw_nut * 1e3:g} mm is not larger than the hole "
                                 f"{self.d_h_eff * 1e3:g} mm; give a washer's nut_bearing_diameter")
            p_nut = bearing_pressure.si(F_press, dw_nut, self.d_h_eff)
        # stripping (R11): internal thread against the bolt's breaking force
        strip_cap, strip_dem, R_S = self._stripping()
        # residual clamp load in service (R12)
        F_KR_min = fmin - FPA - FZ - max(dFth, 0.0)
        table = tuple((float(mu), self.F_M_zul(mu), self.F_M_zul(mu) * self.torque_factor(mu, mu))
                      for mu in _mu_grid(self.mu_G[0], self.mu_G[1]))
        if th.d > 0.040:
            notes.append("sigma_ASV is given for d <= 40 mm; extrapolated")
        _, _, C = self.shigley_constant()
        notes.append(f"load factor: VDI Phi_K = {PhiK:.3g} (n = 1), Phi_n = {Phin:.3g} (n = {self.n:g}); Shigley's "
                     f"frusta give C = {C:.3g} (Sec. 8-7)")
        return JointAnalysis(dS, dP, PhiK, Phin, FA, FAmin, FQ, FZ, dFth, FKQ, self.F_K_req, fmin, fmax, FMzul, F_M_req,
                             FSA, FPA, sig_M, sig_B, sig_a, sig_AS, p_head, p_nut, strip_cap, strip_dem, F_KR_min, MA,
                             table, tuple(notes), R_S)

    def _stripping(self) -> tuple[float, float, float]:
        """(capacity, demand, R_S) of the internal thread: tau_BM A_SGM C1 C3 against R_m A_S of the bolt (R11)."""
        th, g = self.thread, self.grade
        ratio_S = 0.65 if g.name.upper().startswith("A") else 0.60   # austenitic A2/A4 classes, else steel
        if self.internal_Rm is not None:
            Rm_M, ratio_M = self.internal_Rm, 0.6
        elif self.tapped is None:
            Rm_M, ratio_M = g.Rm, ratio_S   # nut of the bolt's class
        else:
            Rm_M, ratio_M = self.tapped.Rm or g.Rm, self.tapped.shear_ratio
        tau_BM, tau_BS = ratio_M * Rm_M, ratio_S * g.Rm
        m = self.effective_engagement
        if m <= 0:
            return 0.0, g.Rm * th.As, 1.0
        A_M = internal_thread_shear_area.si(th.d, th.P, m)
        A_S_ = external_thread_shear_area.si(th.d, th.P, m)
        R_S = tau_BM * A_M / (tau_BS * A_S_)
        C1 = alexander_C1(nut_dimensions(th)["s"] / th.d) if self.through else 1.0
        cap = tau_BM * A_M * C1 * alexander_C3(R_S)
        return cap, g.Rm * th.As, R_S

    def with_(self, **changes: Any) -> BoltedJoint:
        return replace(self, **changes)


def _mu_grid(lo: float, hi: float) -> list[float]:
    inner = [round(float(x), 2) for x in np.arange(0.08, 0.241, 0.02) if lo < x < hi]
    return sorted({round(lo, 4), round(hi, 4), *inner})


def bolted_joint(name: str, thread: str, grade: str, parts: Sequence[tuple[QuantityLike, Any]], length: QuantityLike,
                 **kw: Any) -> BoltedJoint:
    """Build a :class:`BoltedJoint` from designations and quantities: ``parts`` = [(thickness, material), ...];
    keyword quantities (``d_W``, ``d_h``, ``D_A``, ``shank_length``, ``tightening_torque``, ``roughness``,
    ``F_K_req``) accept strings with units."""
    th = metric_thread(thread)
    gr = property_class(grade, Q(th.d, "m"))
    ps = tuple(p if isinstance(p, ClampedPart) else ClampedPart.of(*p) for p in parts)
    tapped = kw.pop("tapped", None)
    if tapped is not None and not isinstance(tapped, ClampedPart):
        tapped = ClampedPart.of("1 mm", tapped)  # the tapped body's thickness is not used
    kw["tapped"] = tapped
    dims = {"d_W": "length", "d_h": "length", "d_W_nut": "length", "D_A": "length", "shank_length": "length",
            "roughness": "length", "tightening_torque": "torque", "F_K_req": "force", "internal_Rm": "pressure",
            "E_S": "pressure"}
    conv = {k: ((None if v is None else to_si(v, dims[k], k)) if k in dims else v) for k, v in kw.items()}
    return BoltedJoint(name, th, gr, ps, to_si(length, "length", "length"), **conv)


# ============================================================================================ bolt pattern


@dataclass(frozen=True)
class BoltLoad:
    """The share of one bolt of a pattern: axial tension [N] and transverse force (x, y) [N]."""

    index: int
    position: tuple[float, float]
    axial: float
    transverse: tuple[float, float]

    @property
    def transverse_magnitude(self) -> float:
        return math.hypot(*self.transverse)


@dataclass(frozen=True)
class BoltPattern:
    """Equal bolts at ``positions`` (x, y) [m] in the joint plane (z along the bolts, + pulls them)."""

    joint: BoltedJoint
    positions: tuple[tuple[float, float], ...]
    names: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        if len(self.positions) < 1:
            raise InputError("a bolt pattern needs at least one bolt")

    @property
    def centroid(self) -> tuple[float, float]:
        p = np.asarray(self.positions, dtype=float)
        return float(p[:, 0].mean()), float(p[:, 1].mean())

    def distribute(self, *, F_z: float = 0.0, F_x: float = 0.0, F_y: float = 0.0, M_x: float = 0.0, M_y: float = 0.0,
                   M_z: float = 0.0, at: tuple[float, float] | None = None) -> list[BoltLoad]:
        """Bolt loads by the elastic method about the pattern centroid (SI floats).

        Axial: F_i = F_z/n + b u_i + c v_i with [[sum u^2, sum uv], [sum uv, sum v^2]] [b, c] = [-M_y, M_x] (a
        linear distribution: rigid plate, equal bolt stiffness, no prying). Transverse: F/n each plus the torque
        share M_z (-v_i, u_i)/sum r^2. The forces act at ``at`` (default the centroid); moments are about the
        centroid. Source: Shigley 10th ed., Sec. 8-12 (shear of bolt groups, centroid); the linear axial
        distribution is the same elastic assumption applied to the out-of-plane moment.
        """
        p = np.asarray(self.positions, dtype=float)
        xc, yc = self.centroid
        u, v = p[:, 0] - xc, p[:, 1] - yc
        n = len(p)
        if at is not None:
            uf, vf = at[0] - xc, at[1] - yc
            M_x, M_y = M_x + vf * F_z, M_y - uf * F_z
            M_z = M_z + uf * F_y - vf * F_x
        axial = np.full(n, F_z / n)
        if M_x or M_y:
            A = np.array([[np.sum(u * u), np.sum(u * v)], [np.sum(u * v), np.sum(v * v)]])
            if abs(np.linalg.det(A)) < 1e-18 * max(1.0, float(np.trace(A)) ** 2):
                # bolts on a line: only the moment about that line's normal can be taken
                r = u * u + v * v
                if np.sum(r) == 0:
                    raise InputError("a moment on a single bolt (or coincident bolts) cannot be taken by the pattern")
                sol = np.linalg.lstsq(A, np.array([-M_y, M_x]), rcond=None)[0]
                resid = A @ sol - np.array([-M_y, M_x])
                if np.linalg.norm(resid) > 1e-9 * max(abs(M_x), abs(M_y)):
                    raise InputError("the bolts lie on one line: a moment about that line cannot be taken by the "
                                     "pattern")
                b, c = sol
            else:
                b, c = np.linalg.solve(A, np.array([-M_y, M_x]))
            axial = axial + b * u + c * v
        r2 = float(np.sum(u * u + v * v))
        tx = np.full(n, F_x / n)
        ty = np.full(n, F_y / n)
        if M_z:
            if r2 == 0:
                raise InputError("a torque about the bolt axis on a single bolt cannot be taken by friction-free shear")
            tx = tx - M_z * v / r2
            ty = ty + M_z * u / r2
        return [BoltLoad(i, (float(p[i, 0]), float(p[i, 1])), float(axial[i]), (float(tx[i]), float(ty[i])))
                for i in range(n)]

    def analyse(self, loads: Sequence[BoltLoad], *, dT: QuantityLike = "0 K") -> list[JointAnalysis]:
        """The single-bolt calculation per bolt; a bolt in compression (axial < 0) is analysed with F_A = 0."""
        out = []
        for bl in loads:
            out.append(self.joint.analyse(Q(max(bl.axial, 0.0), "N"), F_Q=Q(bl.transverse_magnitude, "N"), dT=dT))
        return out


def hole_support_forces(plate: Any, supports: Sequence[Any], xy: Any, reaction_z: Any,
                        name: str = "") -> dict[str, tuple[tuple[float, float], float]]:
    """Bolt tension at each bolt-hole support of a plate-bending FEA: hole name -> ((x, y) [m], tension [N]).

    The sum of the vertical reactions ``reaction_z`` [N] at the vertices ``xy`` [m] on the hole's rim or washer
    ring (:class:`mechverify.components.plates.HoleSupport`), its sign turned so that a plate pulled off its
    support puts the bolt in tension. The moments a clamped rim also takes are not counted: they load the
    bolted interface, not the bolt's axis (VDI 2230's eccentric clamping is not modelled).
    """
    xy = np.asarray(xy, dtype=float)
    rz = np.asarray(reaction_z, dtype=float)
    out: dict[str, tuple[tuple[float, float], float]] = {}
    for s in supports:
        if type(s).__name__ != "HoleSupport":
            continue
        holes = plate.holes if s.holes == "all" else [plate.hole(k) for k in s.holes]
        w = s.washer_diameter
        w = 0.0 if w is None else (w if isinstance(w, float) else to_si(w, "length", "washer_diameter"))
        for h in holes:
            r = 0.5 * max(h.diameter, w) * (1 + 1e-6) + 1e-9
            near = np.hypot(xy[:, 0] - h.center[0], xy[:, 1] - h.center[1]) <= r
            out[h.name] = ((float(h.center[0]), float(h.center[1])), float(-rz[near].sum()))
    if not out:
        raise InputError(f"{name}: the plate has no bolt-hole supports")
    return out


def force_resultants(forces: Any) -> tuple[float, float, float]:
    """(F_z, M_x, M_y) of bolt forces ``[((x, y), F), ...]`` about their centroid: sum F, sum F v, -sum F u."""
    f = list(forces)
    xc = sum(p[0] for p, _ in f) / len(f)
    yc = sum(p[1] for p, _ in f) / len(f)
    return (sum(t for _, t in f), sum(t * (p[1] - yc) for p, t in f), -sum(t * (p[0] - xc) for p, t in f))


__all__ = [
    "MetricThread", "metric_thread", "thread_sizes", "PropertyClass", "property_class", "head_bearing_diameter",
    "nut_dimensions", "clearance_hole", "friction_class", "limiting_surface_pressure", "embedding_amount",
    "tightening_factor",
    "pitch_diameter", "minor_diameter", "stress_area", "shigley_bolt_stiffness", "frustum_stiffness",
    "member_stiffness_equal", "shigley_member_stiffness", "WILEMAN", "wileman_member_stiffness", "joint_constant",
    "shigley_preload",
    "shigley_yielding_factor", "shigley_load_factor", "shigley_separation_factor", "bolt_goodman_strength",
    "bolt_gerber_strength", "bolt_proof_line_strength", "bolt_stress_components", "cylinder_resilience",
    "head_resilience", "engaged_thread_resilience", "cone_angle_tan", "plate_resilience", "load_factor",
    "embedding_loss", "thermal_preload_change", "min_assembly_preload", "permissible_assembly_preload",
    "tightening_torque", "thread_torque", "working_stress", "endurance_rolled_before_ht", "endurance_rolled_after_ht",
    "bearing_pressure", "alexander_C1", "alexander_C3", "internal_thread_shear_area", "external_thread_shear_area",
    "slip_clamp_load", "hole_support_forces", "force_resultants",
    "ClampedPart", "JointAnalysis", "BoltedJoint", "bolted_joint", "BoltLoad", "BoltPattern",
]
