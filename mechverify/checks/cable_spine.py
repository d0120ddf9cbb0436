"""Checks of a cable-driven spring spine (:mod:`mechverify.mechanisms.cable_spine`): the spine's buckling
ratio at a pose and the cable tension against the cable's rating.

The spring's own stresses and fatigue between rest and full tilt are the compression-spring checks of
:mod:`mechverify.checks.springs`, fed with the spine's axial force by a design-file connection.
"""

from __future__ import annotations

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.mechanisms.cable_spine import CableSpine, SpineState
from mechverify.references import ref
from mechverify.units import Q, to_si

TG = "timoshenko_gere_stability"


@check("spine_buckling_ratio", title="Spring spine buckling (fixed-free, with shear)", sf_kind="buckling",
       source=ref(TG, "Sec. 2.18, Eq. (2-46)"),
       explain=("The vertical load on the spring top (platform weight plus the vertical part of the cable "
                "tension at the pose) against the spine's fixed-free critical load P_cr = P_e/(1 + P_e/gamma), "
                "P_e = pi^2 beta/(4 l^2), with Timoshenko's bending rigidity beta and shear rigidity gamma of the "
                "helical spring at its compressed length l = L0 - P/k (Timoshenko & Gere Sec. 2.18)."))
def check_spine_buckling_ratio(spine: CableSpine, state: SpineState, *, required_sf: float = 1.0,
                               load_case: str = "") -> CheckResult:
    """P at the pose against P_cr(l) of the fixed-free spring column with shear."""
    return CheckResult(
        check="spine_buckling_ratio", component=spine.name, demand=Q(state.axial_force, "N"),
        capacity=Q(state.critical_load, "N"), required_sf=required_sf,
        title="Spring spine buckling (fixed-free, with shear)",
        formula=r"P \le P_{cr} = \frac{P_e}{1 + P_e/\gamma},\ P_e = \frac{\pi^2 \beta}{4 l^2}",
        source=ref(TG, "Sec. 2.18, Eq. (2-46)"),
        inputs={"tilt": Q(state.tilt, "rad").to("deg"), "T": Q(state.tension, "N"), "l": Q(state.length * 1e3, "mm"),
                "beta": Q(state.beta, "N*m**2"), "gamma": Q(state.gamma, "N"), "method": state.method},
        substituted=_critical_substituted(state.beta, state.gamma, state.length, state.critical_load),
        notes=(f"P/P_cr = {state.buckling_ratio:.3f} (bending only: {state.euler_ratio:.3f})",),
        load_case=load_case)


def _rigidities(spine: CableSpine, P: float) -> tuple[float, float, float]:
    """(beta [N m^2], gamma [N], l [m]) of the spine's spring under the axial load P [N]: Timoshenko & Gere's
    rigidities scaled with the compressed length, beta = beta0 l/L0, gamma = gamma0 l/L0, l = L0 - P/k."""
    r = spine.spring.rigidities()
    L0, k = spine.spring.free_length.m_as("m"), spine.spring.rate.m_as("N/m")
    beta0 = r.beta.m_as("N*m**2") if spine.beta0 is None else Q(spine.beta0).m_as("N*m**2")
    l = L0 - P / k
    return beta0 * l / L0, r.gamma.m_as("N") * l / L0, l


def _critical_substituted(beta: float, gamma: float, length: float, p_cr: float) -> str:
    """P_cr = P_e/(1 + P_e/gamma), P_e = pi^2 beta/(4 l^2), with the numbers (SI inputs)."""
    pe = rf"\frac{{\pi^{{2}}\cdot {tex(Q(beta, 'N*m**2'))}}}{{4\cdot \left({tex(Q(length * 1e3, 'mm'))}\right)^{{2}}}}"
    return (rf"P_{{cr}} = \frac{{{pe}}}{{1 + {pe}/\left({tex(Q(gamma, 'N'))}\right)}}"
            rf" = {tex(Q(p_cr, 'N'))}")


def check_spine_past_buckling(spine: CableSpine, reason: str, *, required_sf: float = 1.0,
                              load_case: str = "") -> CheckResult:
    """The ``spine_buckling_ratio`` result when no equilibrium exists at the asked tilt: the largest axial
    load the spine can carry against the top load it would need (at least the weight), a FAIL."""
    Pcr = spine.critical_load()
    W = to_si(spine.weight, "force", "weight")
    return CheckResult(
        check="spine_buckling_ratio", component=spine.name, demand=Q(max(W, Pcr), "N"), capacity=Q(Pcr, "N"),
        required_sf=max(required_sf, 1.0 + 1e-9), title="Spring spine buckling (fixed-free, with shear)",
        formula=r"P \le P_{cr} = \frac{P_e}{1 + P_e/\gamma},\ P_e = \frac{\pi^2 \beta}{4 l^2}",
        source=ref(TG, "Sec. 2.18, Eq. (2-46)"), inputs={"W": Q(W, "N")},
        substituted=_critical_substituted(*_rigidities(spine, Pcr), Pcr),
        notes=(f"no equilibrium at this tilt: {reason}",), load_case=load_case)


@check("cable_tension", title="Cable tension against the cable rating", sf_kind="static",
       source=ref(TG, "Sec. 2.18 (spine model); the rating is the cable maker's"),
       explain=("The largest cable tension that holds the platform at the pose (spine beam-column or elastica "
                "equilibrium) against the cable's rated (breaking or working) load from its data sheet."))
def check_cable_tension(spine: CableSpine, state: SpineState, rating: object, *, required_sf: float = 1.0,
                        load_case: str = "") -> CheckResult:
    """Tension of the pulling cable against its rating."""
    return CheckResult(
        check="cable_tension", component=spine.name, demand=Q(state.tension, "N"), capacity=Q(rating).to("N"),
        required_sf=required_sf, title="Cable tension against the cable rating", formula=r"T \le T_{rated}",
        source=ref(TG, "Sec. 2.18 (spine model)"),
        substituted=(rf"SF = \frac{{{tex(Q(rating).to('N'))}}}{{{tex(Q(state.tension, 'N'))}}}"
                     rf" = {tex(Q(rating).m_as('N') / state.tension)}") if state.tension > 0 else "",
        inputs={"tilt": Q(state.tilt, "rad").to("deg"), "method": state.method}, load_case=load_case)
