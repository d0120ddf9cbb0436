"""Checks of frames solved by :mod:`mechverify.fea.frame` (one load case or combination each).

* ``frame_stress`` — the largest von Mises stress ``sqrt(sigma² + 3 tau²)`` at the section fibres along
  every member (the stationary points of the moments included, so the extreme is exact) against the
  yield strength of that member's material;
* ``frame_deflection`` — the largest translation anywhere along the members (exact: stationary points
  of the closed-form element fields) against a limit;
* ``frame_fatigue`` — every point along the members against the material's S-N curve for the stated
  loading (fully reversed, or zero to max with a mean-stress criterion).
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.checks.fatigue import check_fatigue_field
from mechverify.checks.members import deflection_check
from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.references import ref
from mechverify.units import Q, QuantityLike

if TYPE_CHECKING:  # annotations only: importing the checks does not import the FEA layer
    from mechverify.fea.frame import FrameExtreme, FrameResults
    from mechverify.materials.material import Material

ELEMENT = f"the exact 3D beam element ({ref('przemieniecki', 'Sec. 5.6')}; {ref('mcguire2', 'Sec. 4.3-4.5, 7.3')})"
VM_SOURCE = f"{ref('shigley10', 'Eq. 5-15')} (von Mises of a beam fibre); member forces by {ELEMENT}"
FATIGUE_LOADINGS = ("fully_reversed", "zero_to_max")


def where_text(e: FrameExtreme) -> str:
    """``member M at s = ... mm from its start, point (x, y, z) mm``."""
    loc = ", ".join(f"{c:.4g}" for c in e.location.m_as("mm"))
    return f"member {e.member} at s = {e.position.m_as('mm'):.4g} mm from its start, point ({loc}) mm"


def _case_notes(res: FrameResults) -> tuple[str, ...]:
    return tuple(res.notes)


@check("frame_stress", title="Frame member stress (von Mises)", sf_kind="static", aliases=("frame.stress",),
       source=VM_SOURCE,
       formula=r"\sigma_{vM} = \sqrt{\left(\frac{N}{A} + \frac{M_y z}{I_y} - \frac{M_z y}{I_z}\right)^2"
               r" + 3\left(\frac{|T|}{W_t} + \frac{|V|}{A_s}\right)^2} \le S_y",
       explain=("Largest von Mises stress sqrt(sigma^2 + 3 tau^2) over the section fibres along every member "
                "(sigma from N and biaxial bending, tau = |T|/W_t + |V|/A_s; the stationary points of the "
                "moment diagrams are included, so the peak is exact) against the yield strength of that "
                "member's material; Shigley 10th ed. Eq. 5-15. One load case or combination per result."))
def check_frame_stress(results: FrameResults, *, required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """The frame's smallest yield safety factor over all members and fibres, with where it occurs."""
    n, ext = results.min_safety_factor()
    d = results.diagram(ext.member)
    i = int(np.argmin(np.abs(d.s.m_as("mm") - ext.position.m_as("mm"))))
    j = int(np.argmin(np.linalg.norm(d.fibres.m_as("mm") - ext.fibre.m_as("mm"), axis=1))) if ext.fibre is not None \
        else 0
    m = results.frame.members[results.frame.member_index[ext.member]]
    fib = d.fibres[j].m_as("mm")
    Sy = m.material.require("yield_strength").to("MPa")
    notes = [f"at {where_text(ext)}",
             f"governing fibre (y, z) = ({fib[0]:.3g}, {fib[1]:.3g}) mm from the centroid, section {m.section.kind}, "
             f"material {m.material.name}",
             f"there N = {d.N[i].m_as('N'):.4g} N, M_y = {d.My[i].m_as('N*m'):.4g} N·m, "
             f"M_z = {d.Mz[i].m_as('N*m'):.4g} N·m, T = {d.T[i].m_as('N*m'):.4g} N·m, "
             f"V = ({d.Vy[i].m_as('N'):.4g}, {d.Vz[i].m_as('N'):.4g}) N",
             "tau = |T|/W_t + |V|/A_s taken at the same fibre (conservative: the transverse shear is zero at the "
             "extreme fibres of solid sections)",
             f"{results.frame.theory} beam elements; loads at the centroidal axis; stress raisers at joints and holes "
             "are not in a beam model", *_case_notes(results)]
    return CheckResult(
        check="frame_stress", component=results.frame.name, demand=Q(float(d.von_mises[i, j].m_as("MPa")), "MPa"),
        capacity=Sy, required_sf=required_sf, title="Frame member stress (von Mises)",
        formula=check_frame_stress.check_def.formula, source=VM_SOURCE,  # type: ignore[attr-defined]
        inputs={"N": d.N[i].to("N"), "My": d.My[i].to("N*m"), "Mz": d.Mz[i].to("N*m"), "T": d.T[i].to("N*m"),
                "sigma": d.normal_stress[i, j].to("MPa"), "tau": d.shear_stress[i].to("MPa"), "Sy": Sy},
        substituted=(rf"\sigma_{{vM}} = \sqrt{{({tex(d.normal_stress[i, j], 'MPa')})^{{2}} + 3\cdot "
                     rf"({tex(d.shear_stress[i], 'MPa')})^{{2}}}} = {tex(d.von_mises[i, j], 'MPa')}"),
        notes=tuple(notes), load_case=load_case,
        details={"member": d.member, "position": d.s[i], "location": d.points[i], "safety_factor": n})


@check("frame_deflection", title="Frame deflection", sf_kind="deflection", aliases=("frame.deflection",),
       source=f"limit set by the design; deflection by {ELEMENT}",
       formula=r"\delta_{max} = \max |\mathbf{u}(s)| \le \delta_{lim}",
       explain=("Largest translation anywhere along the members — the exact maximum of the closed-form element "
                "fields, not a sampled one — against the limit (a length, 'L/250' or a fraction of the span; "
                "requirements.deflection_limit by default)."))
def check_frame_deflection(results: FrameResults, limit: Any, *, span: QuantityLike | None = None,
                           load_case: str = "", span_rule: str | None = None) -> CheckResult:
    """The largest translation along the members against ``limit`` (a length, ``"L/250"`` or a fraction of
    ``span``); ``span_rule`` says where ``span`` came from (the result's note)."""
    mx = results.max_displacement
    r = deflection_check(mx.value, limit, span=span, component=results.frame.name, load_case=load_case,
                         source=f"limit set by the design; deflection by {ELEMENT}")
    rg = results.ranges(mx.member)
    comps = ", ".join(f"ux {rg['ux'].min.m_as('mm'):.4g}..{rg['ux'].max.m_as('mm'):.4g}" if k == "ux" else
                      f"{k} {rg[k].min.m_as('mm'):.4g}..{rg[k].max.m_as('mm'):.4g}" for k in ("ux", "uy", "uz"))
    return dataclasses.replace(
        r, check="frame_deflection", title="Frame deflection",
        formula=r"\delta_{max} = \max |\mathbf{u}(s)| \le \delta_{lim}",
        notes=(*r.notes, f"largest translation (magnitude) at {where_text(mx)}; along that member {comps} mm",
               "span for a fractional limit: " + (span_rule or "the 'span' field, else the largest distance from a "
                                                  "support to a member end"), *_case_notes(results)))


@check("frame_fatigue", title="Frame fatigue", sf_kind="fatigue", aliases=("frame.fatigue",),
       source=f"{ref('shigley10', 'Sec. 6-12')}; stresses by {ELEMENT}",
       explain=("Every point along the members: amplitude and mean of the fibre von Mises stress for the stated "
                "loading (fully reversed, or zero to max with Goodman etc.) against the material's S-N curve at "
                "fatigue_life (or its endurance estimate), Langer yield included; mechverify.checks.fatigue, "
                "Shigley 10th ed. Sec. 6-12."))
def check_frame_fatigue(results: FrameResults, *, loading: str = "zero_to_max", life: float | None = None,
                        criterion: str = "goodman", Kf: float = 1.0, required_sf: float = 1.0,
                        load_case: str = "") -> CheckResult:
    """Fatigue of every point along the members (worst material group governs)."""
    if loading not in FATIGUE_LOADINGS:
        raise ValueError(f"loading must be one of {FATIGUE_LOADINGS}, got {loading!r}")
    results.require_stresses()
    groups: dict[str, tuple[Material, list[np.ndarray], list[np.ndarray]]] = {}
    for d in results.diagrams():
        m = results.frame.members[results.frame.member_index[d.member]]
        g = groups.setdefault(m.material.name, (m.material, [], []))
        g[1].append(np.max(d.von_mises.m_as("Pa"), axis=1))
        g[2].append(d.points.m_as("m"))
    worst = None
    for mat, vms, pts in groups.values():
        vm = np.concatenate(vms)
        sa, sm = (vm, np.zeros_like(vm)) if loading == "fully_reversed" else (vm / 2, vm / 2)
        r = check_fatigue_field(results.frame.name, Q(sa, "Pa"), Q(sm, "Pa"), mat, coordinates=Q(np.vstack(pts), "m"),
                                life=life, criterion=criterion, Kf=Kf, required_sf=required_sf)
        if worst is None or r.factored_utilisation > worst.factored_utilisation:
            worst = r
    assert worst is not None
    how = ("fully reversed (R = -1): amplitude = the peak von Mises stress, no mean stress" if
           loading == "fully_reversed" else
           f"zero to max (R = 0): amplitude = mean = half the peak von Mises stress, {criterion} mean-stress criterion")
    return dataclasses.replace(worst, check="frame_fatigue", title="Frame fatigue", load_case=load_case,
                               notes=(*worst.notes, f"loading {how}", "stress at each point along the members: the "
                                      f"largest fibre von Mises stress of the load case (Kf = {Kf:g}; joints, holes "
                                      "and surface finish not modelled)", *_case_notes(results)))


__all__ = ["FATIGUE_LOADINGS", "check_frame_deflection", "check_frame_fatigue", "check_frame_stress", "where_text"]
