"""Checks of solid and plane FEA studies: stress, deflection, natural frequency, buckling.

- ``solid_stress`` - the largest nodal von Mises stress (recovered, :mod:`mechverify.fea.recovery`)
  against the yield strength.
- ``solid_deflection`` - the largest displacement against a limit.
- ``natural_frequency`` - the first elastic natural frequency above a required minimum, or every
  computed frequency outside an excitation band widened by a margin.
- ``buckling_load_factor`` - the lowest linear buckling load factor against the required safety factor.

Each returns a :class:`CheckResult` that passes while demand <= capacity / required_sf; the results of
the FEA layer (``FieldResults``, ``ModalResults``, ``BucklingResults``) are passed in, so importing the
checks does not import the FEA layer.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.checks.members import deflection_check
from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex, tex_minus
from mechverify.errors import InputError
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, to_si

if TYPE_CHECKING:
    from mechverify.fea.buckling import BucklingResults
    from mechverify.fea.modal import ModalResults
    from mechverify.fea.results import FieldResults

FEA_SOURCE = ref("zienkiewicz_taylor_zhu", "ch. 6 (3D elasticity, quadratic tetrahedra)")
MODAL_SOURCE = (f"{ref('zienkiewicz_taylor_zhu', 'sec. 16.2 (consistent mass, eigenproblem)')}; verified against "
                f"{ref('blevins', 'Table 8-1')} and CalculiX *FREQUENCY")
BUCKLE_SOURCE = (f"linearized buckling with the initial-stress matrix; verified against "
                 f"{ref('timoshenko_gere_stability', 'sec. 2.1 (columns), ch. 9 (plates)')} and CalculiX *BUCKLE")


def _where(res: Any, node: int) -> str:
    x = res.points[node] * 1e3
    return f"at node {node}, ({x[0]:.4g}, {x[1]:.4g}, {x[2]:.4g}) mm"


#: Most nodes a mode-shape figure keeps (the check's details are stored with the results).
FIGURE_NODES = 2000


def shape_details(res: Any, mode: int, value: Any = None) -> dict[str, Any]:
    """Figure data of mode ``mode`` of modal or buckling results: node points [mm] and the translations of the
    mode scaled to a largest component of 1 (at most :data:`FIGURE_NODES` nodes, evenly picked), the lines of a
    frame's elements when there are any."""
    pts = np.asarray(res.points, dtype=float)
    shape = np.asarray(res.shapes[mode], dtype=float)[:, :3]
    scale = float(np.max(np.abs(shape))) or 1.0
    keep = np.arange(len(pts))
    lines = getattr(res, "elements", None)
    if lines is None and len(pts) > FIGURE_NODES:
        keep = np.linspace(0, len(pts) - 1, FIGURE_NODES).astype(int)
    out = {"mode_points": Q(pts[keep] * 1e3, "mm"), "mode_shape": shape[keep] / scale, "mode_number": mode + 1}
    if lines is not None:
        out["mode_lines"] = np.asarray(lines, dtype=int)
    if value is not None:
        out["mode_value"] = value
    return out


def field_details(res: Any, values: Any, node: int, unit: str) -> dict[str, Any]:
    """Figure data of a field check: the nodes of the outer surface [mm] (all nodes when there is no surface;
    at most :data:`FIGURE_NODES`, evenly picked) with the field's nodal ``values`` there (a quantity array), and
    the governing ``node``'s point and value."""
    pts = np.asarray(res.points, dtype=float)
    surf = getattr(res, "surface", None)
    keep = np.unique(np.asarray(surf, dtype=int)) if surf is not None and np.size(surf) else np.arange(len(pts))
    if len(keep) > FIGURE_NODES:
        keep = keep[np.linspace(0, len(keep) - 1, FIGURE_NODES).astype(int)]
    v = values.to(unit)
    return {"field_points": Q(pts[keep] * 1e3, "mm"), "field_values": Q(np.asarray(v.magnitude)[keep], unit),
            "field_node": node, "field_point": Q(pts[node] * 1e3, "mm"), "field_value": v[node]}


@check("solid_stress", title="Solid FEA von Mises stress", sf_kind="static",
       source=f"{ref('shigley10', 'Eq. (5-13)')}; {FEA_SOURCE}",
       explain=("Largest von Mises stress of the solid (or plane) FEA field, nodal stresses recovered by "
                "superconvergent patch recovery, against the material's yield strength. The notes give the "
                "location and the Zienkiewicz-Zhu estimate of the discretisation error."))
def check_solid_stress(res: FieldResults, *, component: str = "", required_sf: float = 1.0, load_case: str = "",
                       notes: Sequence[str] = (), warnings: Sequence[str] = ()) -> CheckResult:
    """The largest von Mises stress of ``res`` against the yield strength."""
    mx = res.max_von_mises
    sy = res.material.require("yield_strength").to("MPa")
    extra = [f"governing {_where(res, int(mx.node))}"]
    p1, p2, p3 = (Q(float(x), "Pa") for x in np.linalg.eigvalsh(np.asarray(res.sigma[int(mx.node)]))[::-1])
    sub = (rf"\sigma_{{vM}} = \sqrt{{\frac{{({tex_minus(p1, p2, 'MPa')})^{{2}} + ({tex_minus(p2, p3, 'MPa')})^{{2}} + "
           rf"({tex_minus(p3, p1, 'MPa')})^{{2}}}}{{2}}}} = "
           rf"{tex(mx.value, 'MPa')}")
    if res.error_estimate is not None:
        extra.append(f"Zienkiewicz-Zhu relative energy-norm error estimate {100 * float(res.error_estimate):.3g} % "
                     "(a global figure for the whole model, not the error of the peak)")
    return CheckResult(
        check="solid_stress", component=component, demand=mx.value.to("MPa"), capacity=sy, required_sf=required_sf,
        title="Solid FEA von Mises stress", formula=r"\sigma_{vM,max} \le S_y",
        source=f"{ref('shigley10', 'Eq. (5-13)')}; {FEA_SOURCE}", inputs={"Sy": sy},
        notes=(*extra, *notes), warnings=(*res.warnings, *warnings), load_case=load_case, substituted=sub,
        details={"node": int(mx.node), "location": Q(res.points[int(mx.node)], "m").to("mm"),
                 **field_details(res, res.von_mises, int(mx.node), "MPa")})


@check("solid_deflection", title="Solid FEA deflection", sf_kind="deflection", source=FEA_SOURCE,
       explain="Largest displacement magnitude of the solid (or plane) FEA field against the limit of the design file.")
def check_solid_deflection(res: FieldResults, limit: Any, *, span: QuantityLike | None = None, component: str = "",
                           required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """The largest displacement of ``res`` against ``limit`` (a length, ``"L/250"`` of ``span``, or a fraction)."""
    mx = res.max_displacement
    r = deflection_check(mx.value, limit, span=span, component=component, load_case=load_case, source=FEA_SOURCE)
    ux, uy, uz = (Q(float(c), "m") for c in np.asarray(res.u)[int(mx.node)])
    sub = (rf"|u| = \sqrt{{({tex(ux, 'mm')})^{{2}} + ({tex(uy, 'mm')})^{{2}} + ({tex(uz, 'mm')})^{{2}}}} = "
           rf"{tex(mx.value, 'mm')}")
    return CheckResult(
        check="solid_deflection", component=component, demand=r.demand, capacity=r.capacity, required_sf=required_sf,
        title="Solid FEA deflection", formula=r.formula, source=FEA_SOURCE, inputs=r.inputs,
        notes=(*r.notes, f"governing {_where(res, int(mx.node))}"), warnings=res.warnings, load_case=load_case,
        substituted=sub,
        details=field_details(res, Q(np.linalg.norm(np.asarray(res.u), axis=1), "m"), int(mx.node), "mm"))


@check("natural_frequency", title="Natural frequency", sf_kind="limit", source=MODAL_SOURCE,
       explain=("First elastic natural frequency of the FEA model (consistent mass, shift-invert Lanczos) against "
                "the required minimum; or, with an excitation band, every computed frequency must lie below the "
                "band's lower edge / (1 + margin) or above its upper edge x (1 + margin)."))
def check_natural_frequency(res: ModalResults, *, minimum: QuantityLike | None = None,
                            band: tuple[QuantityLike, QuantityLike] | None = None, margin: float = 0.15,
                            component: str = "", required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """``minimum``: the first elastic frequency must reach it (demand = minimum, capacity = first frequency).
    ``band`` (lo, hi): no computed frequency within [lo/(1+margin), hi·(1+margin)]; the governing mode is the
    one nearest that interval (demand and capacity are its frequency and the interval edge, oriented so the
    check passes when the mode lies outside)."""
    if (minimum is None) == (band is None):
        raise InputError("natural_frequency: give either minimum or band (lo, hi)")
    f = res.frequencies.m_as("Hz")[res.rigid_body_modes:]
    w2 = np.asarray(res.omega2, dtype=float)[res.rigid_body_modes:]
    if f.size == 0:
        raise InputError("natural_frequency: the modal results hold no elastic mode; compute more modes")
    notes = ["frequencies " + ", ".join(f"{x:.4g}" for x in f) + " Hz",
             f"{res.rigid_body_modes} rigid-body modes (free body)" if res.rigid_body_modes else "",
             "effective mass of the modes computed: " + ", ".join(
                 f"{100 * float(m):.3g} % along {ax}" for ax, m in zip("xyz", res.effective_mass_fraction().sum(0)))
             + " of the total"]
    warnings: list[str] = []
    if minimum is not None:
        fmin = to_si(minimum, "frequency", "minimum")
        demand, capacity, mode = fmin, float(f[0]), 1
        formula = r"f_1 \ge f_{req}"
    else:
        lo, hi = (to_si(b, "frequency", "band") for b in band)
        if not 0 <= lo <= hi:
            raise InputError(f"natural_frequency: band must be (lo, hi) with 0 <= lo <= hi, got {band!r}")
        below, above = lo / (1 + margin), hi * (1 + margin)
        util = np.where(f <= np.sqrt(below * above), f / max(below, 1e-300), above / f)
        k = int(np.argmax(util))
        mode = k + 1
        demand, capacity = (f[k], below) if f[k] <= np.sqrt(below * above) else (above, f[k])
        formula = r"f_i \le f_{lo}/(1+m)\ \text{or}\ f_i \ge f_{hi}(1+m)"
        if f[-1] < above:
            warnings.append(f"the highest computed frequency ({f[-1]:.4g} Hz) is below the band's upper edge with "
                            f"margin ({above:.4g} Hz): compute more modes to see whether one lies in the band")
    sub = (rf"f_{{{mode}}} = \frac{{\sqrt{{{tex(Q(float(w2[mode - 1]), '1/s**2'))}}}}}{{2\cdot \pi}} = "
           rf"{tex(Q(float(f[mode - 1]), 'Hz'))}")
    details: dict[str, Any] = {"frequencies": Q(f, "Hz")}
    if getattr(res, "shapes", None) is not None:
        details.update(shape_details(res, res.rigid_body_modes + mode - 1, Q(float(f[mode - 1]), "Hz")))
    return CheckResult(
        check="natural_frequency", component=component, demand=Q(demand, "Hz"), capacity=Q(capacity, "Hz"),
        required_sf=required_sf, title="Natural frequency", formula=formula, source=MODAL_SOURCE,
        inputs={"margin": margin} if band is not None else {"f_req": Q(demand, "Hz")},  # the margin: bands only
        notes=tuple(n for n in notes if n) + (f"governing mode {mode}",),
        warnings=tuple(warnings), load_case=load_case, substituted=sub, details=details)


def no_buckling_result(bound: float, reason: str, *, component: str = "", required_sf: float = 1.0,
                      load_case: str = "") -> CheckResult:
    """``buckling_load_factor`` of a load case whose loads have no positive buckling factor (no compression that
    can destabilise the model): demand 1, capacity ``bound`` (every positive factor, if any, exceeds it; inf when
    there is none), and ``reason`` as a note. The envelope over the load cases is governed by the others. The
    note and the substituted line say "no buckling under this load case"; a finite bound is named as the
    capacity (an infinite one is no number to print: "> ∞" read as a false inequality, review 2 finding 7)."""
    cap = float(bound)
    none = "no buckling under this load case"
    notes = (f"{none}: no compression that can buckle the model: {reason}",)
    sub = r"\text{" + none + "}"
    if np.isfinite(cap):
        notes += (f"capacity: {cap:.4g}, the factor every positive buckling factor would exceed",)
        sub = rf"\lambda_{{cr}} > {cap:.4g}\ " + sub.replace("{", "{(", 1).replace("}", ")}", 1)
    return CheckResult(
        check="buckling_load_factor", component=component, demand=Q(1.0, ""), capacity=Q(cap, ""),
        required_sf=required_sf, title="Buckling load factor (FEA)", formula=r"\lambda_{cr} \ge SF",
        source=BUCKLE_SOURCE, inputs={"lambda_cr": cap}, notes=notes, load_case=load_case, substituted=sub)


@check("buckling_load_factor", title="Buckling load factor (FEA)", sf_kind="buckling", source=BUCKLE_SOURCE,
       explain=("Lowest linear (eigenvalue) buckling load factor of the FEA model under its loads, the geometric "
                "stiffness from the static stress state, against the required buckling safety factor. Linear "
                "buckling ignores imperfections and plasticity: it is an upper bound for real columns and shells."))
def check_buckling_load_factor(res: BucklingResults, *, component: str = "", required_sf: float = 1.0,
                               load_case: str = "") -> CheckResult:
    """Demand 1 (the loads as applied), capacity the lowest buckling factor."""
    mu = float(res.factors[0])
    details: dict[str, Any] = {"factors": np.asarray(res.factors, dtype=float)}
    if getattr(res, "shapes", None) is not None:
        details.update(shape_details(res, 0, mu))
    sub = rf"\lambda_{{cr}} = \frac{{1}}{{{tex(1.0 / mu, digits=6)}}} = {tex(mu)}"  # θ_max = 1/λ_cr
    return CheckResult(
        check="buckling_load_factor", component=component, demand=Q(1.0, ""), capacity=Q(mu, ""),
        required_sf=required_sf, title="Buckling load factor (FEA)", formula=r"\lambda_{cr} \ge SF",
        source=BUCKLE_SOURCE, inputs={"lambda_cr": mu},
        notes=("factors " + ", ".join(f"{x:.4g}" for x in res.factors),
               "linear buckling: no imperfections or plasticity (an upper bound)",
               "θ_max: the largest eigenvalue of -K_G φ = θ K φ (λ_cr = 1/θ_max)"), load_case=load_case,
        substituted=sub, details=details)
