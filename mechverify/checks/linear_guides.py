"""Checks of linear guides: rated life and static safety of profile-rail carriages and linear ball bushings,
and the drive force (binding) of a carriage on plain bushings under a moment.

Formulas in :mod:`mechverify.components.linear_guides` (THK, HIWIN catalogues; the igus / PBC Linear 2:1 rule).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import pint

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.components.linear_guides import guide_life, sliding_carriage_drive_force
from mechverify.errors import InputError, ValidityError
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, fmt, to_si

GUIDE_LIFE = f"{ref('thk_lm', 'rated life, equivalent factor K, load of four blocks')}; " \
             f"{ref('hiwin_lg', 'Secs. 1-3 to 1-5')}"
BINDING = (f"{ref('igus_drylin', 'eccentric forces, 2:1 rule')}; {ref('pbc_binding', 'binding ratio')}; "
           "edge-force equilibrium of a rigid carriage")


@dataclass(frozen=True)
class LinearGuide:
    """A guide system's ratings per block (carriage or bushing): C at ``rating_distance``, C0, static moment
    ratings, and the life factors; ``name`` labels the results."""

    C: pint.Quantity
    C0: pint.Quantity
    rating_distance: pint.Quantity = field(default_factory=lambda: Q(50, "km"))
    kind: str = "ball"
    fH: float = 1.0
    fT: float = 1.0
    fC: float = 1.0
    fW: float = 1.0
    M0_roll: pint.Quantity | None = None
    M0_pitch: pint.Quantity | None = None
    M0_yaw: pint.Quantity | None = None
    name: str = "linear guide"

    def __post_init__(self) -> None:
        for n in ("C", "C0"):
            if not to_si(getattr(self, n), "force", n) > 0:
                raise InputError(f"{self.name}: {n} must be positive")


@check("linear_guide_life", title="Linear guide rated life", sf_kind="bearing",
       source=GUIDE_LIFE,
       explain=("Nominal life of the most loaded block, L = (fH fT fC/fW C/P)^p L_C (p = 3 ball, 10/3 roller; "
                "L_C the rating distance of the maker's C: 50 km for THK/HIWIN, 100 km for others), with P the "
                "block's equivalent load from the forces and moments (moments through C0/M0), against the "
                "required travel (or hours from the stroke and cycles per minute)."))
def check_linear_guide_life(g: LinearGuide, P: QuantityLike, required_travel: QuantityLike, *,
                            km_per_hour: float | None = None, load_case: str = "") -> CheckResult:
    """Rated travel life of the most loaded block against ``required_travel`` (a distance) ([thk_lm], [hiwin_lg]).

    ``km_per_hour`` (travel per operating hour) adds the life in hours to the notes.
    """
    L = guide_life(g.C, P, rating_distance=g.rating_distance, kind=g.kind, fH=g.fH, fT=g.fT, fC=g.fC, fW=g.fW)
    req = Q(to_si(Q(required_travel) if isinstance(required_travel, str) else required_travel, "length",
                  "required_travel"), "m").to("km")
    Pq = Q(to_si(P, "force", "P"), "N")
    p = 3 if g.kind == "ball" else 10 / 3
    f = g.fH * g.fT * g.fC / g.fW
    notes = [f"P = {fmt(Pq)} on the most loaded block; C = {fmt(g.C.to('kN'))} rated for "
             f"{fmt(g.rating_distance.to('km'))}; fH fT fC/fW = {f:.3g}"]
    if km_per_hour:
        notes.append(f"{L.m_as('km') / km_per_hour:.4g} h at {km_per_hour:.4g} km of travel per hour")
    pt = "3" if p == 3 else r"\frac{10}{3}"

    def sub() -> str:
        return (rf"L = \left({tex(f)}\cdot \frac{{{tex(g.C, 'kN')}}}{{{tex(Pq, 'kN')}}}\right)^{{{pt}}}\cdot "
                rf"{tex(g.rating_distance, 'km')} = {tex(L, 'km')}") if Pq.magnitude > 0 else ""
    return CheckResult(
        check="linear_guide_life", component=g.name, demand=req, capacity=L, title="Linear guide rated life",
        formula=r"L = \left(\frac{f_H f_T f_C}{f_W}\frac{C}{P}\right)^p L_C", source=GUIDE_LIFE,
        inputs={"P": Pq, "C": g.C, "L_C": g.rating_distance, "fH": g.fH, "fT": g.fT, "fC": g.fC, "fW": g.fW},
        notes=tuple(notes), load_case=load_case, substituted=sub)


@check("linear_guide_static_safety", title="Linear guide static safety (fS)", sf_kind="bearing",
       source=GUIDE_LIFE,
       explain=("fS = C0/P0 of the most loaded block (forces plus moments through C0/M0) against the required "
                "fS (THK guideline: 1..2 normal, 2..3 with vibration or shock; the bearing class factor)."))
def check_linear_guide_static_safety(g: LinearGuide, P0: QuantityLike, *, required_fs: float = 1.0,
                                     load_case: str = "") -> CheckResult:
    """Static safety fS = C0/P0 of the most loaded block ([thk_lm])."""
    P = Q(to_si(P0, "force", "P0"), "N")
    return CheckResult(
        check="linear_guide_static_safety", component=g.name, demand=P, capacity=g.C0.to("N"),
        required_sf=required_fs, title="Linear guide static safety (fS)", formula=r"f_S = C_0/P_0",
        source=GUIDE_LIFE, inputs={"P0": P, "C0": g.C0},
        notes=(f"required fS = {required_fs:g} (THK: 1..2 normal, 2..3 with vibration or shock)",),
        load_case=load_case,
        substituted=lambda: (
            rf"f_S = \frac{{{tex(g.C0, 'kN')}}}{{{tex(P, 'kN')}}} = {tex(g.C0.m_as('N') / P.m_as('N'))}"
            if P.magnitude > 0 else ""))


@dataclass(frozen=True)
class SlidingGuide:
    """A carriage on plain bushings: friction ``mu``, contact ``length`` (bushing length, or the span of two
    bushings on one rod), the resisting force's and the drive's offsets across the guide, and the drive force
    available (what the drive was sized for)."""

    mu: float
    length: pint.Quantity
    load_offset: pint.Quantity = field(default_factory=lambda: Q(0, "m"))
    drive_offset: pint.Quantity = field(default_factory=lambda: Q(0, "m"))
    available_force: pint.Quantity | None = None
    name: str = "carriage"


def _jam_note(jam_number: float, Fe: float, Ra: float) -> str:
    """The jam rule with its condition and where this (moving) carriage stands; Fe = F e, Ra = R a [N·m]."""
    rule = "it jams only when 2 mu e/L >= 1 and the drive's moment governs, F e - R a > 0"
    if jam_number < 1:
        return f"2 mu e/L = {jam_number:.3g} < 1: the carriage does not jam ({rule})"
    return (f"2 mu e/L = {jam_number:.3g} >= 1 but the load's moment governs (F e = {Fe:.4g} N·m, R a = {Ra:.4g} "
            f"N·m, F e - R a = {Fe - Ra:.4g} N·m): the carriage does not jam ({rule})")


@check("carriage_binding", title="Sliding carriage drive force (binding)", sf_kind="limit",
       source=BINDING,
       explain=("A carriage on plain bushings carries the moment of an offset load or drive as two edge forces "
                "N = |M|/L; their friction 2 mu |M|/L adds to the load, F = R + 2 mu |F e - R a|/L (equilibrium of the "
                "rigid carriage; it reproduces the makers' 2:1 rule: with mu = 0.25 a drive offset of twice the "
                "bearing length jams, igus, PBC Linear). The drive force needed is compared with the force the drive "
                "provides. Jam rule: the carriage jams (no force moves it) when 2 mu e/L >= 1 AND the drive's own "
                "moment governs, F e - R a > 0; keep L > 2 mu e. A load moment R a larger than F e keeps it moving "
                "whatever 2 mu e/L (then F = R (1 + 2 mu a/L)/(1 + 2 mu e/L))."))
def check_carriage_binding(c: SlidingGuide, R: QuantityLike, *, load_case: str = "") -> CheckResult:
    """Drive force needed against the available drive force; a jammed carriage is a ValidityError (FAIL)."""
    if c.available_force is None:
        raise InputError(f"{c.name}: carriage_binding needs available_force (the force the drive was sized for)")
    s = sliding_carriage_drive_force(R, mu=c.mu, length=c.length, load_offset=c.load_offset,
                                     drive_offset=c.drive_offset)
    if s.jammed:
        raise ValidityError(f"{c.name}: the carriage jams — no drive force moves it (2 mu e/L = {s.jam_number:.3g} "
                            f">= 1 with mu = {c.mu:g}, e = {fmt(c.drive_offset)}, L = {fmt(c.length)}, and the "
                            f"drive's moment governs, F e - R a > 0; keep L > 2 mu e)")
    r = to_si(R, "force", "R")
    Rq = Q(r, "N")  # (Rq.m_as("N") is r itself)
    F = s.F.m_as("N")
    k = 2 * c.mu / to_si(c.length, "length")
    a, e = to_si(c.load_offset, "length"), to_si(c.drive_offset, "length")
    upper = F * e >= r * a and e != 0  # the branch F e >= R a (module text)
    x, y = (-k * a, -k * e) if upper else (k * a, k * e)

    def term(v: float) -> str:
        return f"1 {'+' if v >= 0 else '-'} {tex(abs(v))}"
    def sub() -> str:
        return rf"F = {tex(Rq, 'N')}\cdot \frac{{{term(x)}}}{{{term(y)}}} = {tex(s.F, 'N')}"
    return CheckResult(
        check="carriage_binding", component=c.name, demand=s.F, capacity=c.available_force.to("N"),
        title="Sliding carriage drive force (binding)",
        formula=r"F = R + \frac{2\mu\,|F e - R a|}{L}", source=BINDING,
        inputs={"R": Rq, "mu": c.mu, "L": c.length, "a": c.load_offset, "e": c.drive_offset},
        notes=(f"edge force at each end of the contact N = |M|/L = {fmt(s.edge_force)}; friction from the moment "
               f"{fmt(s.friction)}", _jam_note(s.jam_number, F * e, r * a),
               "rigid carriage, contacts at the bushing ends; the moment is shared by parallel rods, the friction "
               "sum is not"),
        load_case=load_case, details={"F": s.F, "edge_force": s.edge_force, "jam_number": s.jam_number},
        substituted=sub)


__all__ = ["LinearGuide", "SlidingGuide", "check_linear_guide_life", "check_linear_guide_static_safety",
           "check_carriage_binding"]

