"""Linear guides: profile-rail carriages and linear ball bushings (rated life over a travel distance, the
equivalent load from forces and moments, block loads of a carriage pair on two rails), and the binding
check of a sliding carriage (plain bushings on rods) under a moment.

Rolling guides [1, 2]:

* nominal life L = (f_H·f_T·f_C/f_W · C/P)^p · L_C with p = 3 (ball), 10/3 (roller) and the rating
  distance L_C of the maker's C: 50 km (THK, HIWIN ball guides) or 100 km (many European makers). The
  rating at another distance: C_50 = C_100·2^(1/p) (= 1.26·C_100 for ball guides) [1, 2];
* life in hours for a reciprocating stroke l_s at n_1 cycles per minute: L_h = L/(2·l_s·n_1·60) [1];
* equivalent load of one block from forces and moments: P = |F_r| + |F_t| + C0·(|M_R|/M_R0 + |M_P|/M_P0
  + |M_Y|/M_Y0) (each moment turned into a load through the block's static moment rating, the makers'
  "equivalent factor" K = C0/M0) [1, 2];
* four blocks (two rails at spacing W, two blocks per rail at spacing L) under a load F at (x, y) from the
  centre of the block pattern (x across the rails, y along them): P_i = F/4 ± F·y/(2L) ± F·x/(2W) [1];
* static safety f_S = C0/P0 (THK: 1..2 normal, 2..3 with vibration or shock) [1].

Sliding carriage on plain bushings (equilibrium of a rigid carriage; [3]): a carriage driven along its guide by a
force F at lateral offset e from the guide axis, against a resisting force R (load, weight) acting at offset a,
with the contact length L (bushing length, or the span of two bushings on one rod) and friction coefficient mu.
The net moment M = F·e − R·a is carried by two edge contacts N = |M|/L, whose friction 2·mu·|M|/L adds to R:

    F = R + 2 mu |F e − R a| / L  ->  F = R (1 − 2 mu a/L)/(1 − 2 mu e/L)  (F e >= R a)
                                     F = R (1 + 2 mu a/L)/(1 + 2 mu e/L)  (F e <  R a)

The carriage jams (no finite drive force moves it) when neither branch is consistent: with the drive alone
off-axis (a = 0) that is 2·mu·e/L >= 1, the contact length must exceed 2·mu times the
drive offset. With mu = 0.25 that is the makers' "2:1 rule" (a drive offset of twice the bearing length jams)
[3]. Several parallel rods share the moment but not the
friction sum, so the result does not depend on their number (rigid carriage, equal bushings).

References
----------
[1] THK, General Catalog, LM Guide, Technical Descriptions: rated life L = (f_H f_T f_C/f_W · C/P_C)^3·50 km,
    L_h = L·10^3/(2 l_s n_1 60), equivalent factor K, load of four blocks, static safety factor f_S.
[2] HIWIN, Linear Guideway Technical Information, Sec. 1-3, 1-4 (basic dynamic load rating for 50 km,
    C_50 = 1.26 C_100, L = (f_h f_t C/(f_w P))^3·50 km), 1-5 (acting load).
[4] THK, Linear Bushing, Rated Load and Nominal Life (thk.com, Linear Bushing selection): Table 1 (rated
    load by ball-row position), nominal life based on 50 km, conversion C_50/C_100 by ISO 14728-1.
[3] igus, drylin R design tips, eccentric forces: "if the distance between the driving force point and the fixed
    bearings is more than twice the bearing spacing (2:1 rule), a static coefficient of friction of 0.25 can
    theoretically result in jamming"; J. R. Schroeder, Demystifying the 2:1 Ratio, PBC Linear, 2010.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pint

from mechverify.errors import InputError
from mechverify.units import Q, QuantityLike, to_si

#: THK's guideline static safety factors f_S [1]
STATIC_SAFETY_NORMAL, STATIC_SAFETY_SHOCK = 1.0, 2.0


def _distance(value: QuantityLike, name: str) -> float:
    """A travel distance [m]: tens of km are normal here (no small-machine plausibility warning)."""
    return to_si(Q(value) if isinstance(value, str) else value, "length", name)


def _exponent(kind: str) -> float:
    if kind not in ("ball", "roller"):
        raise InputError(f"linear guide rolling elements must be 'ball' or 'roller', got {kind!r}")
    return 3.0 if kind == "ball" else 10.0 / 3.0


def convert_rating(C: QuantityLike, from_distance: QuantityLike, to_distance: QuantityLike,
                   kind: str = "ball") -> pint.Quantity:
    """A dynamic load rating for another rating distance: C_to = C_from·(L_from/L_to)^(1/p) ([1, 2]:
    C_50 = 1.26·C_100 for ball guides, 2^(0.3) = 1.23 for roller guides)."""
    c = to_si(C, "force", "C")
    lf, lt = _distance(from_distance, "from_distance"), _distance(to_distance, "to_distance")
    if not (c > 0 and lf > 0 and lt > 0):
        raise InputError("rating conversion: C and both rating distances must be positive")
    return Q(c * (lf / lt) ** (1.0 / _exponent(kind)), "N").to("kN")


def guide_life(C: QuantityLike, P: QuantityLike, *, rating_distance: QuantityLike = "50 km", kind: str = "ball",
               fH: float = 1.0, fT: float = 1.0, fC: float = 1.0, fW: float = 1.0) -> pint.Quantity:
    """Nominal life L = (fH·fT·fC/fW · C/P)^p · L_C [km] ([1, 2]). fH hardness, fT temperature, fC contact
    (several blocks close together), fW load factor (1..1.5 smooth, up to 3 with shocks)."""
    c, p = to_si(C, "force", "C"), to_si(P, "force", "P")
    lc = _distance(rating_distance, "rating_distance")
    for name, f in (("fH", fH), ("fT", fT), ("fC", fC), ("fW", fW)):
        if not 0 < f <= 10:
            raise InputError(f"linear guide life: {name} must be in (0, 10], got {f!r}")
    if not (c > 0 and lc > 0) or p < 0:
        raise InputError("linear guide life: C and the rating distance must be positive, P >= 0")
    if p == 0:
        return Q(math.inf, "km")
    return Q((fH * fT * fC / fW * c / p) ** _exponent(kind) * lc, "m").to("km")


def life_hours_reciprocating(L: QuantityLike, stroke: QuantityLike, cycles_per_minute: float) -> pint.Quantity:
    """L_h = L/(2·l_s·n_1·60) [h] for a stroke l_s travelled back and forth n_1 times a minute [1]."""
    dist, ls = _distance(L, "L"), to_si(stroke, "length", "stroke")
    n1 = float(cycles_per_minute)
    if not (ls > 0 and n1 > 0):
        raise InputError("stroke and cycles per minute must be positive")
    return Q(dist / (2 * ls * n1 * 60), "hour")


def block_equivalent_load(Fr: QuantityLike = "0 N", Ft: QuantityLike = "0 N", *, C0: QuantityLike,
                          M_roll: QuantityLike = "0 N*m", M_pitch: QuantityLike = "0 N*m",
                          M_yaw: QuantityLike = "0 N*m",
                          M0_roll: QuantityLike | None = None, M0_pitch: QuantityLike | None = None,
                          M0_yaw: QuantityLike | None = None) -> pint.Quantity:
    """P = |Fr| + |Ft| + C0·Σ|M_i|/M0_i of one block ([1, 2]); a moment without its rating M0 is an error."""
    c0 = to_si(C0, "force", "C0")
    if not c0 > 0:
        raise InputError("C0 must be positive")
    P = abs(to_si(Fr, "force", "Fr")) + abs(to_si(Ft, "force", "Ft"))
    for name, M, M0 in (("roll", M_roll, M0_roll), ("pitch", M_pitch, M0_pitch), ("yaw", M_yaw, M0_yaw)):
        m = abs(to_si(M, "torque", f"M_{name}"))
        if m == 0:
            continue
        if M0 is None or not to_si(M0, "torque", f"M0_{name}") > 0:
            raise InputError(f"a {name} moment on the block needs its static moment rating M0_{name} (catalogue)")
        P += c0 * m / to_si(M0, "torque", f"M0_{name}")
    return Q(P, "N")


def four_block_loads(F: QuantityLike, x: QuantityLike, y: QuantityLike, rail_spacing: QuantityLike,
                     block_spacing: QuantityLike) -> tuple[pint.Quantity, ...]:
    """Loads of four blocks (rigid table, two rails at spacing W, two blocks each at spacing L) under a force F
    at (x, y) from the pattern's centre: P_i = F/4 ± F·y/(2L) ± F·x/(2W), in the order (+x+y, +x−y, −x+y, −x−y)
    ([1] calculating the applied load). Positive = pressing the block onto its rail."""
    f = to_si(F, "force", "F")
    xx, yy = to_si(x, "length", "x"), to_si(y, "length", "y")
    W, L = to_si(rail_spacing, "length", "rail_spacing"), to_si(block_spacing, "length", "block_spacing")
    if not (W > 0 and L > 0):
        raise InputError("rail and block spacings must be positive")
    return tuple(Q(f / 4 + sy * f * yy / (2 * L) + sx * f * xx / (2 * W), "N")
                 for sx, sy in ((1, 1), (1, -1), (-1, 1), (-1, -1)))


def pair_moment_loads(M: QuantityLike, spacing: QuantityLike) -> pint.Quantity:
    """Force couple ±M/s on two blocks (or two rails) at spacing s carrying a moment M."""
    s = to_si(spacing, "length", "spacing")
    if not s > 0:
        raise InputError("spacing must be positive")
    return Q(abs(to_si(M, "torque", "M")) / s, "N")


#: THK linear bushings: rated load when the load falls between two ball rows (two rows share it), by the
#: bushing's number of ball rows ([4] Table 1: 3 rows 1.0, 4 rows 1.41, 5 rows 1.46, 6 rows 1.28, 8 rows 1.25)
BUSHING_ROW_FACTOR = {3: 1.0, 4: 1.41, 5: 1.46, 6: 1.28, 8: 1.25}


def guide_block_loads(F: QuantityLike, *, offset_x: QuantityLike = "0 m", offset_y: QuantityLike = "0 m",
                      lateral: QuantityLike = "0 N", rails: int = 2, blocks_per_rail: int = 2,
                      rail_spacing: QuantityLike | None = None, block_spacing: QuantityLike | None = None
                      ) -> tuple[pint.Quantity, pint.Quantity, pint.Quantity, pint.Quantity]:
    """Most loaded block of a rigid table on 1 or 2 rails with 1 or 2 blocks each, under F (normal to the
    rails) at (x across, y along) from the block pattern's centre and a lateral force: returns
    (Fr, Ft, M_roll, M_pitch) of that block. Two supports in a direction share the moment as a force couple
    (F/n ± F·x/(2W) or ± F·y/(2L), [1]); a single support carries it as a moment on its block."""
    f, ft = to_si(F, "force", "F"), abs(to_si(lateral, "force", "lateral"))
    x, y = to_si(offset_x, "length", "offset_x"), to_si(offset_y, "length", "offset_y")
    if rails not in (1, 2) or blocks_per_rail not in (1, 2):
        raise InputError(f"rails and blocks_per_rail must be 1 or 2, got {rails}, {blocks_per_rail}")
    n = rails * blocks_per_rail

    def spacing(v: QuantityLike | None, name: str) -> float:
        if v is None or not to_si(v, "length", name) > 0:
            raise InputError(f"two {'rails' if name == 'rail_spacing' else 'blocks per rail'} need a positive {name}")
        return to_si(v, "length", name)

    fr, m_roll, m_pitch = abs(f) / n, 0.0, 0.0
    if rails == 2:
        fr += abs(f * x) / (spacing(rail_spacing, "rail_spacing") * blocks_per_rail)
    else:
        m_roll = abs(f * x) / blocks_per_rail
    if blocks_per_rail == 2:
        fr += abs(f * y) / (spacing(block_spacing, "block_spacing") * rails)
    else:
        m_pitch = abs(f * y) / rails
    return Q(fr, "N"), Q(ft / n, "N"), Q(m_roll, "N*m"), Q(m_pitch, "N*m")


def drive_force_si(R: float, mu: float, L: float, a: float, e: float) -> float:
    """The drive force [N] of :func:`sliding_carriage_drive_force` in plain SI floats (R [N], L, a, e [m]);
    ``math.inf`` when the carriage jams."""
    r, k = R, 2 * mu / L
    F = math.inf
    den1 = 1 - k * e
    if den1 > 0:
        f1 = r * (1 - k * a) / den1
        if f1 >= 0 and f1 * e >= r * a - 1e-12 * max(r, 1.0):
            F = f1
    f2 = r * (1 + k * a) / (1 + k * e) if 1 + k * e > 0 else math.inf
    if math.isinf(F) and 0 <= f2 < math.inf and f2 * e < r * a + 1e-12 * max(r, 1.0):
        F = f2
    return F


@dataclass(frozen=True)
class SlidingCarriage:
    """Drive force of a carriage on plain bushings (see the module text, [3])."""

    F: pint.Quantity  # required drive force (inf when jammed)
    R: pint.Quantity  # resisting force along the guide
    friction: pint.Quantity  # 2 mu |M|/L (inf when jammed)
    edge_force: pint.Quantity  # N = |M|/L at each contact edge
    jam_number: float  # 2 mu e/L of the drive offset alone (jams at >= 1)
    jammed: bool


def sliding_carriage_drive_force(R: QuantityLike, *, mu: float, length: QuantityLike, load_offset: QuantityLike = "0 m",
                                 drive_offset: QuantityLike = "0 m") -> SlidingCarriage:
    """Drive force F moving a carriage on plain bushings against R acting at ``load_offset`` a, driven at
    ``drive_offset`` e (both signed, on the same axis across the guide), contact length L, friction mu (rigid-body
    equilibrium; jamming as in [3])."""
    r = to_si(R, "force", "R")
    L = to_si(length, "length", "length")
    a, e = to_si(load_offset, "length", "load_offset"), to_si(drive_offset, "length", "drive_offset")
    if not 0 <= mu < 5:
        raise InputError(f"friction coefficient must be in 0..5, got {mu!r}")
    if not L > 0 or r < 0:
        raise InputError("contact length must be positive and the resisting force >= 0")
    k = 2 * mu / L
    F = drive_force_si(r, mu, L, a, e)
    jam_number = k * abs(e)
    if math.isinf(F):
        return SlidingCarriage(F=Q(math.inf, "N"), R=Q(r, "N"), friction=Q(math.inf, "N"),
                               edge_force=Q(math.inf, "N"), jam_number=jam_number, jammed=True)
    M = abs(F * e - r * a)
    return SlidingCarriage(F=Q(F, "N"), R=Q(r, "N"), friction=Q(k * M, "N"), edge_force=Q(M / L, "N"),
                           jam_number=jam_number, jammed=False)


__all__ = ["BUSHING_ROW_FACTOR", "guide_block_loads", "convert_rating", "guide_life", "life_hours_reciprocating",
           "block_equivalent_load", "four_block_loads", "pair_moment_loads", "SlidingCarriage",
           "sliding_carriage_drive_force", "drive_force_si"]
