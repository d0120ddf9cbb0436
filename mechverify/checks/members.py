"""Checks of structural members: link body strength, pin eye (Kt, lug, pin), buckling, deflection.

Each returns a :class:`CheckResult` oriented so that it passes while demand <= capacity / required_sf.
"""

from __future__ import annotations

import dataclasses
import re
from typing import Any

import pint

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components.links import _LOAD_DIMS, BTH1_SOURCE, Link, beam_case, pin_shear_stress
from mechverify.errors import InputError
from mechverify.materials import Material
from mechverify.materials import get as get_material
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, to_si

SHIGLEY_KT = ref("shigley10", "Sec. 3-13 (Kt under static loading)")
PETERSON_HOLE = ref("peterson3", "Eq. (4.1), Chart 4.1")


def _strength_notes(link: Link) -> list[str]:
    notes = [f"yield strength {fmt(link.yield_strength, 'MPa')} of {link.material.name}"]
    if link.strength_factor != 1:
        label = f" ({link.print_orientation})" if link.print_orientation else ""
        notes.append(f"strength knock-down {link.strength_factor:g}{label} applied to the material strengths")
    return notes


@check("member_body_strength", title="Link body stress", sf_kind="static",
       aliases=('link.body_strength',),
       source=ref("shigley10", "Sec. 5-5 (distortion energy)"),
       explain=("Von Mises stress of N/A, M_y/W_y + M_z/W_z (the transverse load's Table A-9 maximum moment added), "
                'T/W_t + V/A_s against S_y (knocked down by strength_factor); Shigley 10th ed. Sec. 5-5.'))
def check_member_body_strength(link: Link, axial: QuantityLike = "0 N", moment_y: QuantityLike = "0 N*m",
                               moment_z: QuantityLike = "0 N*m", torque: QuantityLike = "0 N*m",
                               shear: QuantityLike = "0 N", *, required_sf: float = 1.0,
                               load_case: str = "") -> CheckResult:
    """Von Mises stress in the link body (away from the holes) against the yield strength."""
    s = link.stresses(axial, moment_y, moment_z, torque, shear)
    notes = [*_strength_notes(link),
             "bending stresses of both axes added at one corner fibre and transverse shear added to torsion: "
             "conservative for combined loading (distortion-energy criterion)"]
    return CheckResult(
        check="member_body_strength", component=link.name, demand=s.von_mises.to("MPa"),
        capacity=link.yield_strength.to("MPa"), required_sf=required_sf, title="Link body stress (von Mises)",
        formula=r"\sigma_{vM} = \sqrt{\left(\left|\frac{N}{A}\right| + \frac{|M_y|}{W_y} + \frac{|M_z|}{W_z}\right)^2"
                r" + 3\left(\frac{|T|}{W_t} + \frac{|V|}{A_s}\right)^2} \le S_y",
        source=f"elementary beam theory; distortion-energy criterion ({ref('shigley10', 'Sec. 5-5')})",
        inputs={"N": Q(to_si(axial, "force", "axial"), "N"), "My": Q(to_si(moment_y, "torque", "moment_y"), "N*m"),
                "Mz": Q(to_si(moment_z, "torque", "moment_z"), "N*m"), "T": Q(to_si(torque, "torque", "torque"), "N*m"),
                "A": link.section.area.to("mm**2"), "Wel_y": link.section.Wel_y.to("mm**3"),
                "Wel_z": link.section.Wel_z.to("mm**3")},
        substituted=_body_substituted(link, axial, moment_y, moment_z, torque, shear, s.von_mises),
        notes=tuple(notes), load_case=load_case,
        details={"axial": s.axial, "bending": s.bending, "torsion": s.torsion, "shear": s.shear})


def _body_substituted(link: Link, axial: Any, moment_y: Any, moment_z: Any, torque: Any, shear: Any,
                      vm: Any) -> str:
    """sigma_vM = sqrt((|N|/A + |M_y|/W_y + |M_z|/W_z)^2 + 3 (|T|/W_t + |V|/A_s)^2) with the numbers (zero terms
    left out)."""
    sec = link.section.si()
    N, My, Mz = (abs(to_si(v, k, n)) for v, k, n in ((axial, "force", "axial"), (moment_y, "torque", "moment_y"),
                                                    (moment_z, "torque", "moment_z")))
    T, V = abs(to_si(torque, "torque", "torque")), abs(to_si(shear, "force", "shear"))

    def terms(pairs: list[tuple[float, str, float, str, tuple[str, str]]]) -> str:
        """``x/w + ...`` for the non-zero terms, each printed in the display units (du, dw)."""
        out = [rf"\frac{{{tex(Q(x, u), du)}}}{{{tex(Q(w, wu), dw)}}}" for x, u, w, wu, (du, dw) in pairs if x != 0]
        return " + ".join(out) or r"0\,\mathrm{MPa}"

    sig = terms([(N, "N", sec["area"], "m**2", ("N", "mm**2")), (My, "N*m", sec["Wel_y"], "m**3", ("N*mm", "mm**3")),
                 (Mz, "N*m", sec["Wel_z"], "m**3", ("N*mm", "mm**3"))])
    tau = terms([(T, "N*m", sec["Wt"], "m**3", ("N*mm", "mm**3")),
                 (V, "N", min(sec["Asy"], sec["Asz"]), "m**2", ("N", "mm**2"))])
    return (rf"\sigma_{{vM}} = \sqrt{{\left({sig}\right)^{{2}} + 3\cdot \left({tau}\right)^{{2}}}}"
            rf" = {tex(vm, 'MPa')}")


def column_substituted(b: Any, E: Any, Sy: Any, A: Any, I: Any, l: Any) -> str:
    """The Euler (``C pi^2 E I / l^2``) or Johnson (``A [S_y - (S_y l/(2 pi k))^2/(C E)]``, ``k = sqrt(I/A)``) critical
    load of :func:`mechverify.components.columns.column_buckling` with the numbers."""
    e, ll, ii, aa = tex(E, "MPa"), tex(l, "mm"), tex(I, "mm**4"), tex(A, "mm**2")
    if b.regime == "euler":
        return (rf"P_{{cr}} = \frac{{{tex(b.C)}\cdot \pi^{{2}}\cdot {e}\cdot {ii}}}{{({ll})^{{2}}}}"
                rf" = {tex(b.critical_load, 'N')}")
    sy = tex(Sy, "MPa")
    return (rf"P_{{cr}} = {aa}\cdot \left({sy} - \left(\frac{{{sy}\cdot {ll}}}{{2\cdot \pi\cdot "
            rf"\sqrt{{\frac{{{ii}}}{{{aa}}}}}}}\right)^{{2}}\cdot \frac{{1}}{{{tex(b.C)}\cdot {e}}}\right)"
            rf" = {tex(b.critical_load, 'N')}")


@check("eye_net_section", title="Pin eye net section", sf_kind="static",
       source=f"{SHIGLEY_KT}; {PETERSON_HOLE}",
       explain=('F/((w - D) t) across the hole against S_y; the open-hole Kt (Peterson Eq. 4.1) is applied to brittle'
                ' materials or unknown elongation, not to ductile ones under static load (Shigley 10th ed. Sec. '
                '3-13). Runs when hole_diameter is given.'))
def check_eye_net_section(link: Link, axial: QuantityLike, *, required_sf: float = 1.0, apply_kt: bool | None = None,
                    load_case: str = "") -> CheckResult:
    """Net-section tension across the pin hole, with Kt where it matters.

    ``apply_kt=None`` (default) applies the open-hole Kt (Peterson Eq. (4.1)) for brittle materials
    (elongation < 5 %) and when the elongation is unknown; ductile materials under static load are
    checked on the nominal net stress (Shigley 10th ed., Sec. 3-13: local yielding relieves the peak).
    """
    if link.lug is None:
        raise InputError(f"{link.name}: check_eye_net_section needs a lug (pin eye)")
    sigma = link.eye_net_stress(axial)
    kt = float(link.eye_kt().m_as(""))
    brittle = link.is_brittle
    use_kt = (brittle is not False) if apply_kt is None else bool(apply_kt)
    demand = abs(sigma) * (kt if use_kt else 1.0)
    notes = _strength_notes(link)
    warnings: list[str] = []
    if use_kt:
        if apply_kt:
            why = "requested"
        elif brittle:
            why = "brittle material (elongation < 5 %)"
        else:
            why = "elongation unknown: Kt applied conservatively"
        notes.append(f"Kt = {kt:.3g} applied ({why}); it is the open-hole value, a pin-loaded hole "
                     "concentrates more")
        if apply_kt is None and brittle:
            warnings.append("brittle material at a pin-loaded hole: the unloaded-hole Kt may be unconservative; "
                            "confirm with FEA or a test")
    else:
        notes.append(f"Kt = {kt:.3g} not applied: ductile material under static load ({SHIGLEY_KT})")
    if axial is not None and to_si(axial, "force", "axial") < 0:
        notes.append("compressive axial force: the net section bears on the pin; checked as tension (conservative)")
    L = link.lug
    kt_tex = tex(kt) + r"\cdot " if use_kt else ""
    return CheckResult(
        check="eye_net_section", component=link.name, demand=demand.to("MPa"), capacity=link.yield_strength.to("MPa"),
        required_sf=required_sf, title="Pin eye net section",
        formula=r"\sigma = K_t \frac{F}{(w - D) t} \le S_y" if use_kt else r"\sigma = \frac{F}{(w - D) t} \le S_y",
        source=f"{PETERSON_HOLE}; {SHIGLEY_KT}",
        inputs={"F": Q(to_si(axial, "force", "axial"), "N"), "w": L.width.to("mm"), "D": L.hole_diameter.to("mm"),
                "t": L.thickness.to("mm"), "Kt": kt},
        substituted=(rf"\sigma = {kt_tex}\frac{{{tex(Q(abs(to_si(axial, 'force', 'axial')), 'N'))}}}"
                     rf"{{({tex(L.width, 'mm')} - {tex(L.hole_diameter, 'mm')})\cdot {tex(L.thickness, 'mm')}}}"
                     rf" = {tex(demand, 'MPa')}"),
        notes=tuple(notes), warnings=tuple(warnings), load_case=load_case,
        details={"sigma_net": sigma.to("MPa"), "Kt": kt, "kt_applied": use_kt})


def lug_checks(link: Link, force: QuantityLike, *, design_factor: float = 2.0,
               load_case: str = "", allowable: bool = False) -> list[CheckResult]:
    """Lug strength after ASME BTH-1: tension through the pinhole, fracture beyond it, double-plane
    shear-out (each with required SF ``1.20 Nd``) and pin bearing (``Nd``).

    ``design_factor`` Nd: 2.0 for BTH-1 Design Category A, 3.0 for Category B. ``allowable=True``
    folds the 1.20 of the plate modes into the capacity (P/1.20, BTH-1 Sec. 3-3.3.1: allowable =
    P/(1.20 Nd)), so every mode's required SF is Nd (how a design file reports them).
    """
    if link.lug is None:
        raise InputError(f"{link.name}: lug_checks needs a lug (pin eye)")
    if not design_factor > 0:
        raise InputError(f"design_factor must be positive, got {design_factor!r}")
    F = Q(abs(to_si(force, "force", "force")), "N")
    s = link.lug_strength()
    L = link.lug
    notes = [*_strength_notes(link), f"Nd = {design_factor:g}; BTH-1 allowable = nominal / (1.20 Nd) for the "
             "plate failure modes, nominal / Nd for bearing", f"pin-hole clearance factor Cr = {s.Cr:.3g}"]
    warnings: list[str] = []
    if not str(link.material.category).startswith(("steel", "aluminium", "aluminum")):
        warnings.append(f"BTH-1's pinned-plate equations were fitted to steel tests; {link.material.name} "
                        f"({link.material.category}) is outside their basis")
    if L.thickness > L.width:
        warnings.append("lug thicker than wide: outside the plate-type lug geometry of BTH-1")
    inputs = {"F": F, "Dh": L.hole_diameter.to("mm"), "Dp": link.pin_diameter.to("mm"), "w": L.width.to("mm"),
              "t": L.thickness.to("mm"), "R": L.edge_distance.to("mm"), "Fy": link.yield_strength.to("MPa"),
              "Fu": link.ultimate_strength.to("MPa")}
    modes = [
        ("lug_tension", "Lug tension through the pinhole", s.tension, 1.2 * design_factor,
         r"P_t = C_r F_u 2 t b_{eff}", "Eq. (3-45)"),
        ("lug_fracture_beyond", "Lug fracture (tear-out) beyond the pinhole", s.fracture_beyond, 1.2 * design_factor,
         r"P_b = C_r F_u \left[1.13\left(R - \frac{D_h}{2}\right) + \frac{0.92 b_e}{1 + b_e/D_h}\right] t",
         "Eq. (3-49)"),
        ("lug_shear_out", "Lug double-plane shear-out", s.shear_out, 1.2 * design_factor,
         r"P_v = 0.70 F_u A_v,\ A_v = 2\left[a + \frac{D_p}{2}(1 - \cos\phi) - Z'\right] t", "Eqs. (3-50)-(3-52)"),
        ("lug_bearing", "Pin bearing on the lug", s.bearing, design_factor, r"P_p = 1.25 F_y D_p t", "Sec. 3-3.3.3"),
    ]
    Cr, Fu, Fy = tex(s.Cr), tex(link.ultimate_strength, "MPa"), tex(link.yield_strength, "MPa")
    t, Dh, Dp = tex(L.thickness, "mm"), tex(L.hole_diameter, "mm"), tex(link.pin_diameter, "mm")
    be = tex((L.width - L.hole_diameter) / 2, "mm")
    subs = {
        "lug_tension": rf"P_t = {Cr}\cdot {Fu}\cdot 2\cdot {t}\cdot {tex(s.b_eff, 'mm')}",
        "lug_fracture_beyond": (rf"P_b = {Cr}\cdot {Fu}\cdot \left(1.13\cdot \left({tex(L.edge_distance, 'mm')} - "
                                rf"\frac{{{Dh}}}{{2}}\right) + "
                                rf"\frac{{0.92\cdot {be}}}{{1 + \frac{{{be}}}{{{Dh}}}}}\right)"
                                rf"\cdot {t}"),
        "lug_shear_out": rf"P_v = 0.70\cdot {Fu}\cdot {tex(s.shear_area, 'mm**2')}",
        "lug_bearing": rf"P_p = 1.25\cdot {Fy}\cdot {Dp}\cdot {t}",
    }
    out = [CheckResult(check=name, component=link.name, demand=F, capacity=cap.to("N"), required_sf=sf,
                        substituted=f"{subs[name]} = {tex(cap, 'N')}",
                        title=title, formula=formula, source=f"{BTH1_SOURCE}: {eq}", inputs=inputs,
                        notes=tuple(notes), warnings=tuple(warnings), load_case=load_case,
                        details={"b_eff": s.b_eff.to("mm"), "Av": s.shear_area.to("mm**2"), "Cr": s.Cr})
            for name, title, cap, sf, formula, eq in modes]
    if allowable:
        out = [r if r.check == "lug_bearing" else dataclasses.replace(
            r, capacity=(r.capacity / 1.2).to("N"), required_sf=design_factor,
            formula=r.formula + r",\ \ P_{allow} = P / (1.20\,N_d)",
            notes=(*r.notes, "capacity = BTH-1 nominal strength / 1.20, so the required SF is Nd (BTH-1 "
                             "Sec. 3-3.3.1: allowable = P / (1.20 Nd))")) for r in out]
    return out


def _lug_mode(name: str, link: Link, force: Any, design_factor: float, load_case: str,
              allowable: bool = False) -> CheckResult:
    return next(r for r in lug_checks(link, force, design_factor=design_factor, load_case=load_case,
                                      allowable=allowable) if r.check == name)


_LUG_EXPLAIN = (" ASME BTH-1-2008 Sec. 3-3.3.1 pinned-plate strength with the design factor Nd (2.0 = Design "
                "Category A): allowable = P/(1.20 Nd) for the plate modes, P/Nd for bearing. In a design file the "
                "required SF is Nd. Runs when hole_diameter is given.")


@check("lug_tension", title="Lug tension through the pinhole (BTH-1)", sf_kind="static", aliases=("link.lug",),
       source=ref("asme_bth1", "Sec. 3-3.3.1, Eq. (3-45)"),
       explain="Tensile strength through the pinhole P_t = C_r F_u 2 t b_eff." + _LUG_EXPLAIN)
def check_lug_tension(link: Link, force: Any, *, design_factor: float = 2.0, load_case: str = "",
                      allowable: bool = False) -> CheckResult:
    """Lug tension through the pinhole after ASME BTH-1 (required SF ``1.20 Nd``, ``Nd`` with ``allowable``);
    see :func:`lug_checks`."""
    return _lug_mode("lug_tension", link, force, design_factor, load_case, allowable)


@check("lug_fracture_beyond", title="Lug fracture beyond the pinhole (BTH-1)", sf_kind="static",
       source=ref("asme_bth1", "Sec. 3-3.3.1, Eq. (3-49)"),
       explain="Single-plane fracture (tear-out) strength beyond the pinhole, BTH-1 Eq. (3-49)." + _LUG_EXPLAIN)
def check_lug_fracture_beyond(link: Link, force: Any, *, design_factor: float = 2.0,
                              load_case: str = "", allowable: bool = False) -> CheckResult:
    """Lug fracture beyond the pinhole after ASME BTH-1 (required SF ``1.20 Nd``, or ``Nd`` with ``allowable``);
    see :func:`lug_checks`."""
    return _lug_mode("lug_fracture_beyond", link, force, design_factor, load_case, allowable)


@check("lug_shear_out", title="Lug double-plane shear-out (BTH-1)", sf_kind="static",
       source=ref("asme_bth1", "Sec. 3-3.3.1, Eqs. (3-50) to (3-52)"),
       explain="Double-plane shear-out strength P_v = 0.70 F_u A_v, BTH-1 Eqs. (3-50) to (3-52)." + _LUG_EXPLAIN)
def check_lug_shear_out(link: Link, force: Any, *, design_factor: float = 2.0, load_case: str = "",
                        allowable: bool = False) -> CheckResult:
    """Lug double-plane shear-out after ASME BTH-1 (required SF ``1.20 Nd``, ``Nd`` with ``allowable``);
    see :func:`lug_checks`."""
    return _lug_mode("lug_shear_out", link, force, design_factor, load_case, allowable)


@check("lug_bearing", title="Pin bearing on the lug (BTH-1)", sf_kind="static",
       source=ref("asme_bth1", "Sec. 3-3.3.3"),
       explain="Bearing strength of the pin on the lug P_p = 1.25 F_y D_p t, BTH-1 Sec. 3-3.3.3." + _LUG_EXPLAIN)
def check_lug_bearing(link: Link, force: Any, *, design_factor: float = 2.0, load_case: str = "",
                      allowable: bool = False) -> CheckResult:
    """Pin bearing on the lug after ASME BTH-1 (required SF ``Nd``); see :func:`lug_checks`."""
    return _lug_mode("lug_bearing", link, force, design_factor, load_case, allowable)


@check("pin_shear", title="Pin shear", sf_kind="static",
       source=ref("shigley10", "Eq. (5-21)"),
       explain=('Average shear F/(n pi d^2/4) in the pin against its S_sy (material value or 0.577 S_y, Shigley 10th '
                'ed. Eq. 5-21). Runs when hole_diameter or pin_diameter is given.'))
def check_pin_shear(link: Link, force: QuantityLike, pin_material: Any, *, planes: int = 2, required_sf: float = 1.0,
              load_case: str = "") -> CheckResult:
    """Average shear stress in the pin ``F/(n pi d^2/4)`` against the pin's shear yield strength.

    Shear yield is the material's ``shear_yield_strength``, else ``0.577 Sy`` (distortion energy,
    Shigley 10th ed., Eq. (5-21)).
    """
    if link.pin_diameter is None:
        raise InputError(f"{link.name}: check_pin_shear needs a pin diameter (lug or pin_diameter)")
    mat = pin_material if isinstance(pin_material, Material) else get_material(pin_material)
    tau = pin_shear_stress(force, link.pin_diameter, planes)
    if mat.shear_yield_strength is not None:
        cap, how = mat.shear_yield_strength, "material shear yield strength"
    else:
        cap, how = 0.577 * mat.require("yield_strength"), "0.577 Sy (distortion energy, Shigley Eq. (5-21))"
    return CheckResult(
        check="pin_shear", component=link.name, demand=tau.to("MPa"), capacity=cap.to("MPa"), required_sf=required_sf,
        title="Pin shear", formula=r"\tau = \frac{F}{n \pi d^2 / 4} \le S_{sy}",
        source=f"average direct shear tau = F/A; Ssy = 0.577 Sy ({ref('shigley10', 'Eq. (5-21)')})",
        inputs={"F": Q(to_si(force, "force", "force"), "N"), "d": link.pin_diameter.to("mm"), "n": planes},
        substituted=(rf"\tau = \frac{{{tex(Q(abs(to_si(force, 'force', 'force')), 'N'))}}}{{{planes}\cdot \pi\cdot "
                     rf"({tex(link.pin_diameter, 'mm')})^{{2}}/4}} = {tex(tau, 'MPa')}"),
        notes=(f"{planes} shear plane(s); pin {mat.name}, S_sy = {how}",
               "average shear stress; the peak in a round pin is 4/3 of it (transverse shear)"),
        load_case=load_case)


@check("member_buckling", title="Link buckling", sf_kind="buckling",
       aliases=('link.buckling',),
       source=ref("shigley10", "Secs. 4-11 to 4-13, Eqs. (4-43), (4-46), Table 4-2"),
       explain=('Compression against the Euler (C pi^2 E I/l^2, Shigley Eq. 4-42) or Johnson (Eq. 4-46) critical load'
                ' about the least principal axis, C from the end condition (Table 4-2). Runs in the load cases that '
                'give axial_force.'))
def check_member_buckling(link: Link, compression: QuantityLike, *, required_sf: float = 1.0,
                          end: str | float | None = None,
                    basis: str = "recommended", load_case: str = "") -> CheckResult:
    """Compressive force against the Euler/Johnson critical load about the least principal axis."""
    P = to_si(compression, "force", "compression")
    b = link.buckling(end, basis)
    notes = [f"end condition {b.end}, C = {b.C:g} ({basis}, Shigley Table 4-2)",
             f"l/k = {b.slenderness:.4g}, (l/k)_1 = {b.transition_slenderness:.4g}: {b.regime} column",
             *_strength_notes(link)]
    if P < 0:
        notes.append("the given force is negative (tension): no buckling demand")
    formula = (r"P_{cr} = \frac{C \pi^2 E I_{min}}{l^2}" if b.regime == "euler" else
               r"P_{cr} = A\left[S_y - \left(\frac{S_y l}{2\pi k}\right)^2 \frac{1}{C E}\right]")
    return CheckResult(
        check="member_buckling", component=link.name, demand=Q(max(P, 0.0), "N"), capacity=b.critical_load.to("N"),
        required_sf=required_sf, title="Link buckling", formula=formula, source=b.source,
        inputs={"P": Q(P, "N"), "l": link.length.to("mm"), "I_min": link.section.I2.to("mm**4"),
                "A": link.section.area.to("mm**2"), "E": link.material.require("E").to("GPa")},
        substituted=column_substituted(b, link.material.require("E"), link.yield_strength, link.section.area,
                                       link.section.I2, link.length),
        notes=tuple(notes), load_case=load_case,
        details={"slenderness": b.slenderness, "transition_slenderness": b.transition_slenderness, "regime": b.regime,
                 "C": b.C, "E": link.material.require("E").to("GPa"), "Sy": link.yield_strength.to("MPa"),
                 "area": link.section.area.to("mm**2"),
                 "critical_stress": (b.critical_load / link.section.area).to("MPa")})  # column-curve figure


_FRACTION = re.compile(r"^\s*(?:l|L|span)\s*/\s*([0-9.]+)\s*$")


def deflection_limit(limit: QuantityLike, span: QuantityLike | None = None) -> pint.Quantity:
    """A deflection limit as a length: a length (``"1 mm"``), a fraction of the span (``0.01``) or
    ``"L/250"`` / ``"span/250"``."""
    if isinstance(limit, str):
        m = _FRACTION.match(limit)
        if m:
            frac = 1.0 / float(m.group(1))
        else:
            return Q(to_si(limit, "length", "limit"), "m")
    elif isinstance(limit, int | float) and not isinstance(limit, bool):
        frac = float(limit)
    else:
        return Q(to_si(limit, "length", "limit"), "m")
    if not 0 < frac < 1:
        raise InputError(f"limit: a fraction of the span must lie in (0, 1), got {frac:g}")
    if span is None:
        raise InputError(f"limit {limit!r} is a fraction of the span: give span")
    return Q(frac * to_si(span, "length", "span"), "m")


def deflection_check(deflection: QuantityLike, limit: Any, *, span: QuantityLike | None = None,
                     component: str = "member",
                     load_case: str = "", source: str = "") -> CheckResult:
    """Deflection against a limit given as a length, a fraction of ``span`` (0.01) or ``"L/250"``."""
    y = Q(abs(to_si(deflection, "length", "deflection")), "m")
    lim = deflection_limit(limit, span)
    if lim.magnitude <= 0:
        raise InputError("limit: must be positive")
    inputs: dict[str, Any] = {"deflection": y.to("mm"), "limit": lim.to("mm")}
    sub = ""
    if span is not None:
        inputs["span"] = Q(to_si(span, "length", "span"), "m").to("mm")
        m = _FRACTION.match(limit) if isinstance(limit, str) else None
        if m:  # "L/250": the limit is the span over the number
            sub = rf"\delta_{{lim}} = \frac{{{tex(inputs['span'], 'mm')}}}{{{m.group(1)}}} = {tex(lim, 'mm')}"
        elif isinstance(limit, int | float) and not isinstance(limit, bool):
            sub = rf"\delta_{{lim}} = {tex(float(limit))}\cdot {tex(inputs['span'], 'mm')} = {tex(lim, 'mm')}"
    return CheckResult(
        check="deflection", component=component, demand=y.to("mm"), capacity=lim.to("mm"),
        title="Deflection", formula=r"\delta \le \delta_{lim}", source=source or "limit set by the design",
        substituted=sub,
        inputs=inputs, notes=(f"limit {limit!r}" + (f" of span {fmt(Q(to_si(span, 'length', 'span'), 'm'), 'mm')}"
                                                   if span is not None and not isinstance(limit, pint.Quantity)
                                                   else ""),),
        load_case=load_case)


@check("link_deflection", title="Link deflection", sf_kind="deflection",
       aliases=('link.deflection',),
       source=ref("shigley10", "Table A-9"),
       explain=('Largest deflection of the Table A-9 case (end condition and load kind) against the limit: a length, '
                "'L/250' or a fraction of the length (requirements.deflection_limit). Runs in the load cases that "
                'give transverse_load or distributed_load.'))
def check_link_deflection(link: Link, case: str, load: Any, limit: Any, *, axis: str = "z", load_case: str = ""
                    ) -> CheckResult:
    """Deflection of the link for a Shigley Table A-9 case (over its pin-centre length) against a limit."""
    y = link.deflection(case, load, axis)
    r = deflection_check(y, limit, span=link.length, component=link.name, load_case=load_case,
                         source=ref("shigley10", f"Table A-9 ({case})"))
    c = beam_case(case)
    dim, n, _ = _LOAD_DIMS[c.load_kind]
    unit = {"force": "N", "force_per_length": "N/mm", "torque": "N*mm"}.get(dim, "")
    P = Q(abs(to_si(load, dim, "load")), {"force": "N", "force_per_length": "N/m", "torque": "N*m"}.get(dim, ""))
    I = link.second_moment(axis)
    sub = (rf"\delta_{{max}} = \frac{{{tex(c.c_deflection)}\cdot {tex(P, unit or None)}\cdot "
           rf"({tex(link.length, 'mm')})^{{{n}}}}}{{{tex(link.material.require('E'), 'MPa')}\cdot {tex(I, 'mm**4')}}}"
           rf" = {tex(y, 'mm')}")
    E = link.material.require("E")
    return dataclasses.replace(
        r, check="link_deflection", title="Link deflection",
        inputs={**r.inputs, "load": load, "E": E.to("GPa"), "I": I.to("mm**4")},
        details={**r.details, "beam_case": case, "load_si": P.magnitude, "length": link.length.to("mm"),
                 "EI": (E * I).to("N*m**2"), "limit": r.capacity},  # beam-diagram figure
        substituted=sub + (rf",\quad {r.substituted}" if r.substituted else ""),
        formula=r"\delta_{max} = c\,\frac{F l^3}{E I}\ \mathrm{or}\ c\,\frac{w l^4}{E I} \le \delta_{lim}")


__all__ = ["check_member_body_strength", "check_eye_net_section", "lug_checks", "check_lug_tension",
           "check_lug_fracture_beyond", "check_lug_shear_out", "check_lug_bearing", "check_pin_shear",
           "check_member_buckling", "deflection_limit", "deflection_check", "check_link_deflection"]
