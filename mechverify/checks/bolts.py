"""Checks of bolted joints (VDI 2230 Part 1:2015, steps R7 to R13): assembly stress, working stress, fatigue,
surface pressure under head and nut, thread stripping, separation, slip, and the tightening-torque table.

Each check takes the :class:`~mechverify.components.bolts.BoltedJoint` and its
:class:`~mechverify.components.bolts.JointAnalysis` for one load case (``BoltedJoint.analyse``); a bolt group
runs them per bolt and keeps the governing bolt (:func:`governing_bolt`), the others' utilisations in
``details["per_bolt"]``.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex, tex_term
from mechverify.components.bolts import BoltedJoint, JointAnalysis, nut_dimensions, thread_torque
from mechverify.references import ref
from mechverify.units import Q

VDI = "vdi2230"


def _kN(x: float) -> object:
    return Q(x / 1e3, "kN")


def _MPa(x: float) -> object:
    return Q(x / 1e6, "MPa")


def _inputs(j: BoltedJoint) -> dict[str, object]:
    return {"thread": j.thread.designation, "class": j.grade.name, "clamp_length": Q(j.clamp_length * 1e3, "mm"),
            "d_W": Q(j.d_W_eff * 1e3, "mm"), "d_h": Q(j.d_h_eff * 1e3, "mm"),
            "mu_G": f"{j.mu_G[0]:g}..{j.mu_G[1]:g}", "mu_K": f"{j.mu_K[0]:g}..{j.mu_K[1]:g}",
            "alpha_A": Q(j.alpha_A, ""), "n": Q(j.n, "")}


def _diagram(j: BoltedJoint, a: JointAnalysis) -> dict[str, object]:
    """What the joint-diagram figure needs (SI floats)."""
    return {"delta_S": a.delta_S, "delta_P": a.delta_P, "F_M_max": a.F_M_max, "F_M_min": a.F_M_min, "F_Z": a.F_Z,
            "F_A": a.F_A_max, "F_SA": a.F_SA, "F_PA": a.F_PA, "Phi_n": a.Phi_n, "F_KR_min": a.F_KR_min,
            "dF_Vth": a.dF_Vth, "thread": j.thread.designation}


def _mm(x: float) -> str:
    return tex(Q(x * 1e3, "mm"))


def _N(x: float) -> str:
    return tex(Q(x / 1e3, "kN"))


def _N_term(x: float) -> str:
    """_N() of an operand after a minus sign (a negative value in parentheses)."""
    return tex_term(Q(x / 1e3, "kN"))


def _gain(a: JointAnalysis) -> float:
    """Thermal preload gain added to the bolt force in service (a loss is not relied on)."""
    return max(-a.dF_Vth, 0.0)


def _pressure_substituted(a: JointAnalysis, d_W: float, d_h: float, p: float) -> str:
    """p = max(F_M,max, F_V,max + Phi_n F_A) / (pi/4 (d_W^2 - d_h^2)) with the numbers (VDI 2230 R10)."""
    F = max(a.F_M_max, a.F_M_max - a.F_Z + a.F_SA + _gain(a))
    return (rf"p = \frac{{{_N(F)}}}{{\frac{{\pi}}{{4}}\cdot (({_mm(d_W)})^{{2}} - ({_mm(d_h)})^{{2}})}}"
            rf" = {tex(Q(p / 1e6, 'MPa'))}")


@check("bolt_assembly_stress", title="Bolt stress at assembly", sf_kind="limit",
       source=ref(VDI, "R7, Eq. (R7/2); Sec. 5.5.1"),
       explain=("Von Mises stress in the bolt thread at the largest assembly preload F_M,max (tension F_M/A_S plus "
                "the thread torsion at the lowest thread friction mu_G,min) against the minimum yield strength "
                "R_p0.2; VDI 2230 tightens to nu = 0.9 of it (F_M,zul, Table A1), so 0.9 is the planned "
                "utilisation and a torque above it shows as more."))
def check_bolt_assembly_stress(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                               load_case: str = "") -> CheckResult:
    """sigma_red,M at F_M,max against R_p0.2min (VDI 2230 R7)."""
    return CheckResult(
        check="bolt_assembly_stress", component=joint.name, demand=_MPa(a.sigma_red_M), capacity=_MPa(joint.grade.Rp02),
        required_sf=required_sf, title=f"Bolt stress at assembly, {joint.thread.designation} {joint.grade.name}",
        formula=r"\sigma_{red,M} = \frac{F_{M,max}}{A_S}\sqrt{1 + 3\left[\frac{3}{2}\frac{d_2}{d_0}"
                r"\left(\frac{P}{\pi d_2} + 1.155\mu_{G,min}\right)\right]^2} \le R_{p0.2}",
        source=ref(VDI, "R7, Eq. (R7/2)"),
        inputs={**_inputs(joint), "F_M_max": _kN(a.F_M_max), "F_M_zul": _kN(a.F_M_zul), "M_A": Q(a.M_A, "N*m")},
        substituted=(rf"\sigma_{{red,M}} = \frac{{{_N(a.F_M_max)}}}{{{tex(Q(joint.thread.As * 1e6, 'mm**2'))}}}\cdot "
                     rf"\sqrt{{1 + 3\cdot \left(1.5\cdot "
                     rf"\frac{{{_mm(joint.thread.d2)}}}{{{_mm(joint.thread.d0)}}}\cdot "
                     rf"\left(\frac{{{_mm(joint.thread.P)}}}{{\pi\cdot {_mm(joint.thread.d2)}}} + 1.155\cdot "
                     rf"{tex(joint.mu_G[0])}\right)\right)^{{2}}}} = {tex(_MPa(a.sigma_red_M))}"),
        notes=(*a.notes, f"VDI 2230 plans nu = {joint.nu:g} of R_p0.2 (F_M,zul = {a.F_M_zul / 1e3:.4g} kN)"),
        load_case=load_case, details=_diagram(joint, a))


@check("bolt_required_preload", title="Required assembly preload (VDI 2230 R4, R7)", sf_kind="limit",
       source=ref(VDI, "R4, R5, R7; Eqs. (R4/1), (R7/1)"),
       explain=("The assembly preload the joint needs, F_M,min,req = F_KR + (1 - Phi_n) F_A,max + F_Z + Delta F_Vth "
                "(clamp load for slip or sealing, plate relief, embedding and thermal losses; R4), against the "
                "smallest preload the tightening gives, F_M,min = F_M,max/alpha_A; with F_M,max = F_M,zul this is "
                "VDI 2230's sizing criterion alpha_A F_M,min,req <= F_M,zul (R7)."))
def check_bolt_required_preload(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                                load_case: str = "") -> CheckResult:
    """F_M,min,req (R4) against F_M,min from the tightening (R5/R7)."""
    return CheckResult(
        check="bolt_required_preload", component=joint.name, demand=_kN(a.F_M_req), capacity=_kN(a.F_M_min),
        required_sf=required_sf, title=f"Required assembly preload, {joint.thread.designation} {joint.grade.name}",
        formula=r"F_{M,min,erf} = F_{KR} + (1-\Phi_n)F_{A,max} + F_Z + \Delta F_{Vth} \le F_{M,min} = "
                r"\frac{F_{M,max}}{\alpha_A}",
        source=ref(VDI, "R4, R7"),
        inputs={**_inputs(joint), "F_KR": _kN(max(a.F_KQ, a.F_K_req)), "F_A": _kN(a.F_A_max), "F_Z": _kN(a.F_Z),
                "dF_Vth": _kN(a.dF_Vth), "F_M_zul": _kN(a.F_M_zul)},
        substituted=(rf"F_{{M,min,erf}} = {_N(max(a.F_KQ, a.F_K_req))} + (1 - {tex(a.Phi_n)})\cdot {_N(a.F_A_max)} + "
                     rf"{_N(a.F_Z)} + {_N(max(a.dF_Vth, 0.0))} = {_N(a.F_M_req)}"),
        notes=(f"F_KR = max(F_KQerf = {a.F_KQ / 1e3:.4g} kN, F_K,erf = {a.F_K_req / 1e3:.4g} kN)",
               f"alpha_A F_M,min,req = {joint.alpha_A * a.F_M_req / 1e3:.4g} kN against F_M,zul = "
               f"{a.F_M_zul / 1e3:.4g} kN"),
        load_case=load_case, details=_diagram(joint, a))


@check("bolt_working_stress", title="Bolt working stress", sf_kind="limit",
       source=ref(VDI, "R8, Eqs. (R8/1)-(R8/4)"),
       explain=("Von Mises stress of the bolt in service: the largest bolt force F_S,max = F_M,max + Phi_n F_A "
                "(+ a thermal preload gain) over A_S with half the assembly thread torsion (k_tau = 0.5), against "
                "R_p0.2; VDI 2230 R8 asks S_F = R_p0.2/sigma_red,B >= 1.0."))
def check_bolt_working_stress(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                              load_case: str = "") -> CheckResult:
    """sigma_red,B against R_p0.2min (VDI 2230 R8)."""
    return CheckResult(
        check="bolt_working_stress", component=joint.name, demand=_MPa(a.sigma_red_B), capacity=_MPa(joint.grade.Rp02),
        required_sf=required_sf, title=f"Bolt working stress, {joint.thread.designation} {joint.grade.name}",
        formula=r"\sigma_{red,B} = \sqrt{\left(\frac{F_{M}+\Phi_n F_A}{A_S}\right)^2 + 3\left(k_\tau "
                r"\frac{M_G}{W_P}\right)^2},\ k_\tau = 0.5",
        source=ref(VDI, "R8"),
        inputs={**_inputs(joint), "F_A": _kN(a.F_A_max), "Phi_n": Q(a.Phi_n, ""), "F_SA": _kN(a.F_SA)},
        substituted=_working_substituted(joint, a),
        notes=(f"F_S,max = {(a.F_M_max + a.F_SA + max(-a.dF_Vth, 0)) / 1e3:.4g} kN",), load_case=load_case,
        details=_diagram(joint, a))


def _working_substituted(joint: BoltedJoint, a: JointAnalysis) -> str:
    """sigma_red,B = sqrt((F_S,max/A_0)^2 + 3 (k_tau M_G/W_P)^2), A_0 = pi d0^2/4, W_P = pi d0^3/16 (VDI 2230 R8)."""
    th = joint.thread
    F_S = a.F_M_max + a.F_SA + _gain(a)
    M_G = thread_torque.si(a.F_M_max, th.P, th.d2, joint.mu_G[0])
    d0 = _mm(th.d0)
    return (rf"\sigma_{{red,B}} = \sqrt{{\left(\frac{{{_N(F_S)}}}{{\pi\cdot ({d0})^{{2}}/4}}\right)^{{2}} + 3\cdot "
            rf"\left(0.5\cdot \frac{{{tex(Q(M_G, 'N*m'))}}}{{\pi\cdot ({d0})^{{3}}/16}}\right)^{{2}}}}"
            rf" = {tex(_MPa(a.sigma_red_B))}")


@check("bolt_fatigue", title="Bolt fatigue (thread endurance)", sf_kind="fatigue",
       source=ref(VDI, "R9, Eqs. (R9/1)-(R9/5)"),
       explain=("Stress amplitude on the stress area sigma_a = Phi_n (F_A,max - F_A,min)/(2 A_S) against the "
                "endurance limit of rolled threads: sigma_ASV = 0.85 (150/d + 45) MPa rolled before heat treatment, "
                "(2 - F_Sm/F_0.2) sigma_ASV rolled after (VDI 2230 R9, N_D = 2e6); VDI asks S_D >= 1.2."))
def check_bolt_fatigue(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.2,
                       load_case: str = "") -> CheckResult:
    """sigma_a against sigma_ASV / sigma_ASG (VDI 2230 R9)."""
    how = "after" if joint.rolled_after_heat_treatment else "before"
    warnings = ("sigma_ASV is stated for d <= 40 mm",) if joint.thread.d > 0.040 else ()
    return CheckResult(
        check="bolt_fatigue", component=joint.name, demand=_MPa(a.sigma_a), capacity=_MPa(a.sigma_AS),
        required_sf=required_sf, title=f"Bolt fatigue, {joint.thread.designation} (rolled {how} heat treatment)",
        formula=(r"\sigma_a = \frac{\Phi_n (F_{A,max} - F_{A,min})}{2 A_S} \le \sigma_{ASV} = "
                 r"0.85\left(\frac{150}{d} + 45\right)" if how == "before" else
                 r"\sigma_a = \frac{\Phi_n (F_{A,max} - F_{A,min})}{2 A_S} \le \sigma_{ASG} = "
                 r"\left(2 - \frac{F_{Sm}}{F_{0.2}}\right)\sigma_{ASV}"),
        source=ref(VDI, "R9"),
        inputs={**_inputs(joint), "F_A_max": _kN(a.F_A_max), "F_A_min": _kN(a.F_A_min), "Phi_n": Q(a.Phi_n, "")},
        substituted=(rf"\sigma_a = \frac{{{tex(a.Phi_n)}\cdot ({_N(a.F_A_max)} - {_N_term(a.F_A_min)})}}{{2\cdot "
                     rf"{tex(Q(joint.thread.As * 1e6, 'mm**2'))}}} = {tex(_MPa(a.sigma_a))}"
                     + ("" if how == "after" else
                        rf",\quad \sigma_{{ASV}} = 0.85\cdot \left(\frac{{150}}{{{joint.thread.d * 1e3:g}}} + 45\right)"
                        rf"\,\mathrm{{MPa}} = {tex(_MPa(a.sigma_AS))}")),
        notes=(f"threads rolled {how} heat treatment; VDI 2230 asks S_D >= 1.2",), warnings=warnings,
        load_case=load_case, details=_diagram(joint, a))


def _pressure_note(j: BoltedJoint, side: str) -> tuple[float | None, str]:
    part = j.parts[0] if side == "head" else j.parts[-1]
    if part.p_G is not None:
        return part.p_G, (f"p_G = {part.p_G / 1e6:.4g} MPa for {part.name} (given, or VDI 2230 Table A9 as quoted in "
                          "the data file, not checked against a found source)")
    if part.yield_strength is not None:
        return part.yield_strength, (f"no p_G given for {part.name}: its yield strength {part.yield_strength / 1e6:.4g}"
                                     " MPa is used (conservative: VDI 2230 Table A9 limits are above R_p0.2)")
    return None, ""


@check("bolt_surface_pressure_head", title="Surface pressure under the bolt head", sf_kind="pressure",
       source=ref(VDI, "R10, Eqs. (R10/1)-(R10/4)"),
       explain=("Pressure under the head, the larger of assembly (F_M,max) and service (F_V,max + Phi_n F_A), over "
                "the annulus pi/4 (d_W^2 - d_h^2), against the limiting surface pressure p_G of the clamped part "
                "(VDI 2230 Table A9; its yield strength when p_G is not given)."))
def check_bolt_surface_pressure_head(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                                     load_case: str = "") -> CheckResult:
    """p under the head against p_G of the first clamped part (VDI 2230 R10)."""
    return _surface_pressure(joint, a, "head", required_sf, load_case)


@check("bolt_surface_pressure_nut", title="Surface pressure under the nut", sf_kind="pressure",
       source=ref(VDI, "R10, Eqs. (R10/1)-(R10/4)"),
       explain=("As under the head, with the ISO 4032 nut's bearing diameter d_w against the last clamped part "
                "(through-bolted joints only)."))
def check_bolt_surface_pressure_nut(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                                    load_case: str = "") -> CheckResult:
    """p under the nut against p_G of the last clamped part (VDI 2230 R10); through-bolted joints."""
    if a.p_nut is None:
        raise ValueError(f"{joint.name}: a tapped joint has no nut")
    return _surface_pressure(joint, a, "nut", required_sf, load_case)


def _surface_pressure(joint: BoltedJoint, a: JointAnalysis, side: str, required_sf: float,
                      load_case: str) -> CheckResult:
    """The pressure under the head (first clamped part, d_W) or the nut (last clamped part, the nut's d_w) against
    that part's p_G (VDI 2230 R10)."""
    pG, note = _pressure_note(joint, side)
    part = joint.parts[0] if side == "head" else joint.parts[-1]
    if pG is None:
        raise ValueError(f"{joint.name}: no p_G or yield strength for {part.name}")
    if side == "head":
        p, d_w, d_w_tex = a.p_head, joint.d_W_eff, "d_W"
    else:
        p, d_w, d_w_tex = a.p_nut, joint.d_W_nut or nut_dimensions(joint.thread)["dw"], "d_{w,nut}"
    assert p is not None  # a tapped joint's nut is refused by check_bolt_surface_pressure_nut
    return CheckResult(
        check=f"bolt_surface_pressure_{side}", component=joint.name, demand=_MPa(p), capacity=_MPa(pG),
        required_sf=required_sf, title=f"Surface pressure under the {side} ({part.name})",
        formula=(r"p_{max} = \frac{\max(F_{M,max},\ F_{V,max} + \Phi_n F_A)}"
                 rf"{{\frac{{\pi}}{{4}}({d_w_tex}^2 - d_h^2)}} \le p_G"),
        source=ref(VDI, "R10"), inputs=_inputs(joint), notes=(note,), load_case=load_case,
        substituted=_pressure_substituted(a, d_w, joint.d_h_eff, p),
        details=_diagram(joint, a))


@check("bolt_thread_stripping", title="Thread stripping (engagement length)", sf_kind="limit",
       source=ref(VDI, "R11, Sec. 5.5.5 (Alexander)"),
       explain=("The internal thread (nut or tapped part) must carry the bolt's breaking force R_m A_S: its "
                "stripping force tau_BM A_SGM C1 C3 (Alexander's shear area, nut dilation C1 and thread bending C3, "
                "tau_B = 0.6 R_m for steel) over the load-bearing engaged length m_eff = m_ges - 2P, so that an "
                "overload breaks the bolt, not the thread."))
def check_bolt_thread_stripping(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                                load_case: str = "") -> CheckResult:
    """R_m A_S against the internal thread's stripping force (VDI 2230 R11)."""
    where = "nut (ISO 4032, bolt-class strength)" if joint.through else f"tapped {joint.tapped.name}"  # type: ignore[union-attr]
    return CheckResult(
        check="bolt_thread_stripping", component=joint.name, demand=_kN(a.stripping_demand),
        capacity=_kN(a.stripping_capacity), required_sf=required_sf,
        title=f"Thread stripping in the {where}, m_eff = {joint.effective_engagement * 1e3:.3g} mm",
        formula=r"R_{m,S} A_S \le \tau_{BM} A_{SGM} C_1 C_3,\ A_{SGM} = \frac{\pi d\, m_{eff}}{P}"
                r"\left[\frac{P}{2} + (d - D_2)\tan 30^\circ\right]",
        source=ref(VDI, "Sec. 5.5.5"),
        inputs={**_inputs(joint), "m_ges": Q(joint.engagement * 1e3, "mm"),
                "m_eff": Q(joint.effective_engagement * 1e3, "mm")},
        substituted=(rf"R_{{m,S}} A_S = {tex(Q(joint.grade.Rm / 1e6, 'MPa'))}\cdot "
                     rf"{tex(Q(joint.thread.As * 1e6, 'mm**2'))} = {_N(a.stripping_demand)}"),
        notes=("m_eff = m_ges - 2P: two non-bearing thread turns (VDI 2230:2015 m_zu)",
               "tau_B/R_m = 0.6 steel, 0.65 austenitic, 0.7 aluminium, 0.9 grey iron (VDI 2230 Table 5.5/5 as "
               "reproduced in third-party code, not checked against the guideline)",
               "Alexander's C1, C3 as quoted from VDI 2230 Sec. 5.5.5.2 (corroborated by third-party code only)",
               f"strength ratio R_S = {a.strength_ratio:.3g}"),
        warnings=(("R_S < 0.4: outside Alexander's model (C3 taken at 0.4)",) if a.strength_ratio < 0.4 else ()),
        load_case=load_case)


@check("bolt_separation", title="Joint separation (residual clamp load)", sf_kind="limit",
       source=f"{ref(VDI, 'R4, R12')}; {ref('shigley10', 'Eq. (8-30)')}",
       explain=("The smallest preload in service, F_M,min - F_Z - Delta F_Vth (tightening scatter alpha_A, "
                "embedding, thermal loss), against the plate relief (1 - Phi_n) F_A plus any required residual "
                "clamp load: the joint opens when the relief exceeds it (Shigley's n_0)."))
def check_bolt_separation(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                          load_case: str = "") -> CheckResult:
    """(1 - Phi_n) F_A + F_K,req against F_M,min - F_Z - Delta F_Vth."""
    avail = a.F_M_min - a.F_Z - max(a.dF_Vth, 0.0)
    return CheckResult(
        check="bolt_separation", component=joint.name, demand=_kN(a.F_PA + a.F_K_req), capacity=_kN(max(avail, 0.0)),
        required_sf=required_sf, title=f"Joint separation, {joint.thread.designation}",
        formula=r"(1 - \Phi_n) F_{A,max} + F_{K,erf} \le F_{M,min} - F_Z - \Delta F_{Vth}",
        source=ref(VDI, "R4"),
        inputs={**_inputs(joint), "F_A": _kN(a.F_A_max), "F_Z": _kN(a.F_Z), "F_K_req": _kN(a.F_K_req)},
        substituted=(rf"(1 - \Phi_n) F_{{A,max}} + F_{{K,erf}} = (1 - {tex(a.Phi_n)})\cdot {_N(a.F_A_max)} + "
                     rf"{_N(a.F_K_req)} = {_N(a.F_PA + a.F_K_req)}"
                     rf",\quad F_{{M,min}} - F_Z - \Delta F_{{Vth}} = {_N(a.F_M_min)} - {_N_term(a.F_Z)} - "
                     rf"{_N(max(a.dF_Vth, 0.0))} = {_N(avail)}"),
        notes=(f"F_M,min = {a.F_M_min / 1e3:.4g} kN; required assembly preload (R4) F_M,min,req = "
               f"{a.F_M_req / 1e3:.4g} kN",),
        load_case=load_case, details=_diagram(joint, a))


@check("bolt_slip", title="Slip of the friction-grip joint", sf_kind="limit",
       source=ref(VDI, "R2, R12, Eqs. (R2/1), (R12/1)"),
       explain=("Clamp load needed to carry the transverse load by friction, F_KQerf = F_Q/(q_F mu_T,min), against "
                "the smallest residual clamp load F_KR,min = F_M,min - (1 - Phi_n) F_A - F_Z - Delta F_Vth; VDI 2230 "
                "asks S_G >= 1.2 (static) or 1.8 (alternating) - set the component's required SF accordingly."))
def check_bolt_slip(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                    load_case: str = "") -> CheckResult:
    """F_KQerf against F_KR,min (VDI 2230 R12)."""
    return CheckResult(
        check="bolt_slip", component=joint.name, demand=_kN(a.F_KQ), capacity=_kN(max(a.F_KR_min, 0.0)),
        required_sf=required_sf, title=f"Slip under {a.F_Q:.4g} N transverse load",
        formula=r"\frac{F_Q}{q_F \mu_{T,min}} \le F_{KR,min} = F_{M,min} - (1-\Phi_n)F_{A,max} - F_Z - \Delta F_{Vth}",
        source=ref(VDI, "R12"),
        inputs={**_inputs(joint), "F_Q": _kN(a.F_Q), "mu_T": Q(joint.mu_T or 0.0, ""), "q_F": Q(joint.q_F, "")},
        substituted=((rf"F_{{KQerf}} = \frac{{{_N(a.F_Q)}}}{{{joint.q_F}\cdot {tex(joint.mu_T)}}} = {_N(a.F_KQ)},\quad "
                      if a.F_Q > 0 and joint.mu_T else "")
                     + rf"F_{{KR,min}} = {_N(a.F_M_min)} - (1 - {tex(a.Phi_n)})\cdot {_N(a.F_A_max)} - "
                     rf"{_N_term(a.F_Z)} - {_N(max(a.dF_Vth, 0.0))} = {_N(a.F_KR_min)}"),
        notes=("VDI 2230 R12 asks S_G >= 1.2 for static and 1.8 for alternating transverse loads",
               *(("no transverse load in this case",) if a.F_Q == 0 else ())),
        load_case=load_case, details=_diagram(joint, a))


@check("bolt_tightening_torque", title="Tightening torque and preload table", sf_kind="limit",
       source=ref(VDI, "R13, Eq. (R13/1); Table A1"),
       explain=("The torque to set, M_A = F_M (0.16 P + 0.58 d2 mu_G + D_Km/2 mu_K) at the lowest friction, against "
                "the torque that would bring the bolt to its yield strength (nu = 1) at that friction; the result "
                "carries the table of F_M,zul and M_A over the friction range for the assembly instructions."))
def check_bolt_tightening_torque(joint: BoltedJoint, a: JointAnalysis, *, required_sf: float = 1.0,
                                 load_case: str = "") -> CheckResult:
    """M_A against the torque reaching R_p0.2 at mu_min, with the F_M/M_A table (VDI 2230 R13)."""
    lo_G, lo_K = joint.mu_G[0], joint.mu_K[0]
    M_yield = joint.F_M_zul(lo_G, 1.0) * joint.torque_factor(lo_G, lo_K)
    rows = tuple(f"mu = {mu:.3g}: F_M,zul = {F / 1e3:.4g} kN, M_A = {M:.4g} N·m" for mu, F, M in a.torque_table)
    return CheckResult(
        check="bolt_tightening_torque", component=joint.name, demand=Q(a.M_A, "N*m"), capacity=Q(M_yield, "N*m"),
        required_sf=required_sf, title=f"Tightening torque {a.M_A:.3g} N·m, {joint.thread.designation} "
                                       f"{joint.grade.name}",
        formula=r"M_A = F_M\left(0.16P + 0.58 d_2 \mu_G + \frac{D_{Km}}{2}\mu_K\right)",
        source=ref(VDI, "R13"), inputs={**_inputs(joint), "D_Km": Q(joint.D_Km * 1e3, "mm")},
        substituted=(rf"M_A = {_N(a.F_M_max)}\cdot \left(0.16\cdot {_mm(joint.thread.P)} + 0.58\cdot "
                     rf"{_mm(joint.thread.d2)}\cdot {tex(lo_G)} + \frac{{{_mm(joint.D_Km)}}}{{2}}\cdot "
                     rf"{tex(lo_K)}\right)"
                     rf" = {tex(Q(a.M_A, 'N*m'))}"),
        notes=(f"set M_A = {a.M_A:.4g} N·m (mu_G = mu_K = {lo_G:g}); preload table (mu_G = mu_K, nu = {joint.nu:g}):",
               *rows),
        load_case=load_case,
        details={"torque_table": [(mu, F, M) for mu, F, M in a.torque_table], "thread": joint.thread.designation,
                 "grade": joint.grade.name})


def governing_bolt(results: Sequence[CheckResult], labels: Sequence[str]) -> CheckResult:
    """The result of the most utilised bolt of a group, with every bolt's utilisation in ``details["per_bolt"]``."""
    if not results:
        raise ValueError("no bolt results")
    utils = [r.utilisation if math.isfinite(r.utilisation) else float("inf") for r in results]
    i = max(range(len(results)), key=lambda k: utils[k])
    worst = results[i]
    per = [(lab, float(u)) for lab, u in zip(labels, utils, strict=True)]
    same = max(utils) - min(utils) <= 1e-9 * max(abs(max(utils)), 1e-300)
    title = f"{worst.title} - {'every bolt alike' if same else f'bolt {labels[i]} governs'}"
    return dataclasses.replace(worst, title=title,
                               details={**worst.details, "per_bolt": per, "governing_bolt": labels[i]})
