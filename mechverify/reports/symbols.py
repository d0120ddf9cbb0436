"""The symbols of the formulas and a short description for the inputs of every check (report inputs tables).

A check's ``inputs`` are keyed by short names (``d3``, ``yield_strength``, ``F_M_max``); the report shows
each as the symbol the formula uses (``d₃``, ``S_y``, ``F_M,max`` typeset with subscripts) beside a plain
description. ``(check, key)`` entries override a key's meaning for one check (``n`` is a speed for a bearing,
a number of bolts for a joint). A key without an entry is shown as written, with no description.
"""

from __future__ import annotations

import html
import re
from functools import lru_cache

from markupsafe import Markup

_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "eta": "η", "lambda": "λ", "mu": "μ", "nu": "ν",
          "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "φ", "Phi": "Φ", "theta": "θ", "xi": "ξ", "omega": "ω",
          "Delta": "Δ", "dF": "ΔF"}

#: key -> (symbol as ``base_sub``, description)
SYMBOLS: dict[str, tuple[str, str]] = {
    # forces, moments, speeds
    "F": ("F", "axial force"), "F_max": ("F_max", "largest working force"),
    "F_min": ("F_min", "smallest working force"),
    "F_solid": ("F_s", "force at solid length"), "Fa": ("F_a", "axial load"), "Fr": ("F_r", "radial load"),
    "N": ("N", "normal (axial) force at the section"), "My": ("M_y", "bending moment about y"),
    "Mz": ("M_z", "bending moment about z"), "T": ("T", "torque"), "V": ("V", "transverse shear force"),
    "M": ("M", "bending moment"), "P": ("P", "compressive force"), "torque": ("T", "drive torque on the screw"),
    "holding_torque": ("T_available", "torque available at rest (holding torque or brake)"),
    "rotational_speed": ("n", "rotational speed"),
    # geometry
    "d": ("d", "wire, pin or shaft diameter"), "D": ("D", "mean coil diameter"), "d2": ("d_2", "pitch diameter"),
    "d3": ("d_3", "minor (root) diameter of the thread"), "H1": ("H_1", "thread engagement depth"),
    "lead": ("l", "lead (axial advance per turn)"), "flank_angle": ("α", "flank angle"),
    "length": ("L", "unsupported length"), "l": ("l", "length"), "L0": ("L_0", "free length"),
    "Ls": ("L_s", "solid length"), "Na": ("N_a", "active coils"), "C": ("C", "spring index D/d"),
    "end": ("", "end type"), "A": ("A", "cross-section area"), "I_min": ("I_min", "least second moment of area"),
    "Wel_y": ("W_y", "elastic section modulus about y"), "Wel_z": ("W_z", "elastic section modulus about z"),
    "t": ("t", "thickness"), "w": ("w", "width of the eye"), "Dh": ("D_h", "hole diameter"),
    "Dp": ("D_p", "pin diameter"), "R": ("R", "distance from the hole centre to the edge"),
    "engaged_threads": ("n", "thread turns carrying the load"), "b": ("b", "key width"), "h": ("h", "key height"),
    "deflection": ("δ", "largest deflection"), "limit": ("δ_lim", "deflection limit"), "span": ("L", "span"),
    "r1": ("r_1", "hook bend radius"), "r2": ("r_2", "hook side-bend radius"),
    # material
    "E": ("E", "Young's modulus"), "G": ("G", "shear modulus"), "nu": ("ν", "Poisson's ratio"),
    "density": ("ρ", "density"), "yield_strength": ("S_y", "yield strength"), "Sy": ("S_y", "yield strength"),
    "Sut": ("S_ut", "ultimate tensile strength"), "Fy": ("F_y", "yield strength (BTH-1)"),
    "Fu": ("F_u", "ultimate strength (BTH-1)"), "S_f": ("S_f", "fatigue strength at the life"),
    "Se": ("S_e", "endurance limit"),
    # friction
    "mu_min": ("μ_min", "lowest friction coefficient of the nut's range"),
    "mu_G": ("μ_G", "thread friction (min..max)"), "mu_K": ("μ_K", "head friction (min..max)"),
    "mu_T": ("μ_T", "interface friction"), "q_F": ("q_F", "force-transmitting interfaces"),
    # stresses and factors
    "sigma": ("σ", "normal stress at the fibre"), "tau": ("τ", "shear stress at the fibre"),
    "sigma_a": ("σ_a", "alternating stress"), "sigma_m": ("σ_m", "mean stress"),
    "sigma_a'": ("σ_a'", "von Mises alternating stress"), "sigma_m'": ("σ_m'", "von Mises mean stress"),
    "sigma_x": ("σ_x", "surface bending stress along x"), "sigma_y": ("σ_y", "surface bending stress along y"),
    "tau_xy": ("τ_xy", "surface shear stress"), "Kf": ("K_f", "fatigue stress-concentration factor (bending)"),
    "Kfs": ("K_fs", "fatigue stress-concentration factor (torsion)"), "Kt": ("K_t", "stress-concentration factor"),
    "Kts": ("K_ts", "stress-concentration factor (torsion)"),
    # bolts (VDI 2230)
    "thread": ("", "thread"), "class": ("", "property class"), "clamp_length": ("l_K", "clamp length"),
    "d_W": ("d_W", "head bearing diameter"), "d_h": ("d_h", "hole diameter"),
    "alpha_A": ("α_A", "tightening factor"), "F_M_max": ("F_M,max", "largest assembly preload"),
    "F_M_zul": ("F_M,zul", "permissible assembly preload"), "M_A": ("M_A", "tightening torque"),
    "F_KR": ("F_KR", "required residual clamp load"), "F_A": ("F_A", "axial working load"),
    "F_A_max": ("F_A,max", "largest axial working load"), "F_A_min": ("F_A,min", "smallest axial working load"),
    "F_Z": ("F_Z", "preload loss from embedding"), "dF_Vth": ("ΔF_Vth", "thermal preload change"),
    "F_K_req": ("F_K,erf", "required clamp load (sealing, user)"), "F_Q": ("F_Q", "transverse load"),
    "F_SA": ("F_SA", "additional bolt force"), "Phi_n": ("Φ_n", "load factor"),
    "m_ges": ("m_ges", "engaged thread length"), "m_eff": ("m_eff", "load-bearing engaged length"),
    "D_Km": ("D_Km", "friction diameter under the head"),
    # bearings
    "C0": ("C_0", "basic static load rating"), "f0": ("f_0", "bearing factor"), "p": ("p", "life exponent"),
    "reliability": ("", "reliability"),
    # drives
    "ratio": ("i", "gear ratio"), "efficiency": ("η", "efficiency"),
}

#: (check, key) -> (symbol, description) where a key means something else in that check
OVERRIDES: dict[tuple[str, str], tuple[str, str]] = {
    **{(c, "C"): ("C", "basic dynamic load rating") for c in ("bearing_life", "bearing_modified_life")},
    **{(c, "n"): ("n", "rotational speed") for c in ("bearing_life", "bearing_speed", "bearing_static_safety",
                                                       "bearing_modified_life")},
    **{(c, "d"): ("d", "shaft diameter") for c in ("shaft_fatigue", "shaft_static_yield", "shaft_key_shear",
                                                     "shaft_key_crushing")},
    ("pin_shear", "d"): ("d", "pin diameter"), ("pin_shear", "n"): ("n", "shear planes"),
    ("pin_shear", "F"): ("F", "force on the pin"), ("eye_net_section", "F"): ("F", "axial force on the eye"),
    ("eye_net_section", "D"): ("D", "hole diameter"), ("eye_net_section", "Kt"): ("K_t", "open-hole factor (Peterson)"),
    ("member_buckling", "l"): ("l", "pin-centre length"), ("frame_stress", "T"): ("T", "torque at the section"),
    ("screw_strength", "F"): ("F", "axial force on the screw"),
    ("extension_body_stress", "d"): ("d", "wire diameter"), ("torsion_spring_stress", "M"): ("M", "moment on the legs"),
    ("shaft_key_shear", "l"): ("l", "key length"), ("shaft_key_crushing", "l"): ("l", "key length"),
}
OVERRIDES.update({
    # sliding carriage and linear guides (THK/HIWIN catalogue life; binding by the carriage's equilibrium)
    ("carriage_binding", "R"): ("R", "load moved along the guide (resistance the drive overcomes)"),
    ("carriage_binding", "mu"): ("μ", "friction coefficient of the bushings"),
    ("carriage_binding", "L"): ("L", "bearing length of the carriage (contact span along the rod)"),
    ("carriage_binding", "a"): ("a", "offset of the load's line of action from the guide axis"),
    ("carriage_binding", "e"): ("e", "offset of the drive's line of action from the guide axis"),
    ("linear_guide_life", "P"): ("P", "equivalent load on the most loaded block"),
    ("linear_guide_life", "C"): ("C", "basic dynamic load rating of the block"),
    ("linear_guide_life", "L_C"): ("L_C", "rating distance of C (50 km THK/HIWIN, 100 km others)"),
    ("linear_guide_life", "fH"): ("f_H", "hardness factor"), ("linear_guide_life", "fT"): ("f_T", "temperature factor"),
    ("linear_guide_life", "fC"): ("f_C", "contact factor"), ("linear_guide_life", "fW"): ("f_W", "load factor"),
    ("linear_guide_static_safety", "C0"): ("C_0", "basic static load rating of the block"),
    ("linear_guide_static_safety", "P0"): ("P_0", "static equivalent load on the most loaded block"),
    # bearings (ISO 281 Sec. 9)
    ("bearing_modified_life", "P"): ("P", "equivalent dynamic load"),
    ("bearing_modified_life", "Pu"): ("P_u", "fatigue load limit"),
    ("bearing_modified_life", "nu"): ("ν", "lubricant viscosity at the operating temperature"),
    # shafts
    ("shaft_critical_speed", "Rayleigh"): ("n_c,R", "first critical speed, Rayleigh estimate"),
    ("shaft_critical_speed", "Dunkerley"): ("n_c,D", "first critical speed, Dunkerley estimate"),
    ("shaft_critical_speed", "modal"): ("n_c", "first critical speed, beam model eigenvalue"),
    ("shaft_critical_speed", "masses"): ("", "lumped masses of the model"),
    ("shaft_bearing_slope", "bearing"): ("", "bearing type (sets the slope limit)"),
    ("shaft_gear_deflection", "module"): ("m", "gear module"),
    ("shaft_gear_deflection", "P"): ("P", "diametral pitch"),
    # cable-driven spring spine (Timoshenko & Gere Sec. 2.18)
    **{(c, "tilt"): ("θ", "tilt of the spine") for c in ("spine_buckling_ratio", "cable_tension")},
    **{(c, "method"): ("", "solution method") for c in ("spine_buckling_ratio", "cable_tension")},
    ("spine_buckling_ratio", "T"): ("T", "cable tension"), ("spine_buckling_ratio", "l"): ("l", "spine length"),
    ("spine_buckling_ratio", "beta"): ("β", "bending stiffness of the spine"),
    ("spine_buckling_ratio", "gamma"): ("γ", "shear stiffness of the spine"),
    ("spine_buckling_ratio", "W"): ("W", "top load (weight) to carry"),
    # workspace payload (tau = -J^T F)
    ("workspace_payload", "motor"): ("", "joint whose motor governs"),
    ("workspace_payload", "point"): ("", "governing point of the workspace"),
    ("workspace_payload", "torque_per_load"): ("τ/F", "joint torque per newton of payload at the point"),
    ("workspace_payload", "motor_torque"): ("T_m", "torque the joint's motor provides"),
    # FEA, motors
    ("buckling_load_factor", "lambda_cr"): ("λ_cr", "lowest buckling load factor"),
    ("natural_frequency", "margin"): ("", "separation required from the excitation band (0.15 = 15 %)"),
    ("natural_frequency", "f_req"): ("f_req", "required lowest natural frequency"),
    ("motor_peak_torque", "peak torque"): ("T_peak", "largest torque of the cycle at the motor"),
    ("motor_peak_torque", "peak speed"): ("n_peak", "speed at the peak torque"),
    ("motor_rms_torque", "cycle time"): ("t_cycle", "duration of the duty cycle"),
    ("inertia_ratio", "load inertia at motor"): ("J_L", "load inertia reflected to the motor"),
    ("inertia_ratio", "rotor inertia"): ("J_M", "rotor inertia"),
    ("drive_regeneration", "C"): ("C", "bus capacitance"),
})
for _bolt in ("bolt_assembly_stress", "bolt_required_preload", "bolt_working_stress", "bolt_fatigue",
              "bolt_surface_pressure_head", "bolt_surface_pressure_nut", "bolt_thread_stripping", "bolt_separation",
              "bolt_slip", "bolt_tightening_torque"):
    OVERRIDES[(_bolt, "n")] = ("n", "load-introduction factor")
for _spring in ("spring_static_stress", "spring_solid_stress", "spring_buckling", "spring_fatigue", "spring_clash"):
    OVERRIDES[(_spring, "d")] = ("d", "wire diameter")


#: global keys whose meaning belongs to one domain: key -> the check modules (``mechverify.checks.<m>``) where the
#: global entry holds; elsewhere a key without an override gets no description rather than a wrong one
GLOBAL_DOMAIN: dict[str, tuple[str, ...]] = {
    "C": ("springs",), "D": ("springs",), "R": ("members",), "P": ("members",),
    "nu": ("plates", "fea", "frames", "members"),
}


def _module(check: str) -> str:
    from mechverify.checks.registry import get_check

    try:
        return get_check(check).module.rsplit(".", 1)[-1]
    except Exception:  # an unregistered name (a result built by hand): no domain known
        return ""


def describe(check: str, key: str) -> tuple[str, str]:
    """(symbol as ``base_sub``, description) of input ``key`` of ``check``; (key, "") when unknown, and for a
    domain-specific global key (:data:`GLOBAL_DOMAIN`) used by a check of another domain without an override."""
    if (check, key) in OVERRIDES:
        return OVERRIDES[(check, key)]
    if key in GLOBAL_DOMAIN and _module(check) not in GLOBAL_DOMAIN[key]:
        return (key, "")
    return SYMBOLS.get(key) or (key, "")


@lru_cache(maxsize=1024)
def symbol_html(symbol: str) -> Markup:
    """``"F_M,max"`` → ``F<sub>M,max</sub>`` (Greek names as letters, the base in italics)."""
    if not symbol:
        return Markup("")
    base, _, sub = symbol.partition("_")
    base = _GREEK.get(base, base)
    out = f"<i>{html.escape(base)}</i>" if re.fullmatch(r"[A-Za-zα-ωΑ-Ω]", base) else html.escape(base)
    if sub:
        out += f"<sub>{html.escape(_GREEK.get(sub, sub))}</sub>"
    return Markup(out)


__all__ = ["SYMBOLS", "OVERRIDES", "GLOBAL_DOMAIN", "describe", "symbol_html"]
