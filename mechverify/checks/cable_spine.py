"""Checks of a cable-driven spring spine (:mod:`mechverify.mechanisms.cable_spine`): the spine's buckling
ratio at a pose and the cable tension against the cable's rating.

The spring's own stresses and fatigue between rest and full tilt are the compression-spring checks of
:mod:`mechverify.checks.springs`, fed with the spine's axial force by a design-file connection.
"""

from __future__ import annotations

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult
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
        notes=(f"P/P_cr = {state.buckling_ratio:.3f} (bending only: {state.euler_ratio:.3f})",),
        load_case=load_case)


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
        inputs={"tilt": Q(state.tilt, "rad").to("deg"), "method": state.method}, load_case=load_case)
