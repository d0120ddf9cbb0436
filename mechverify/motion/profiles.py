"""Motion profiles: position, velocity, acceleration and jerk of one axis over time.

A profile is a sequence of constant-jerk segments (a trapezoidal move is a sequence of
constant-acceleration segments, i.e. jerk 0 inside each), or sampled ``(t, x)`` data. The axis is
linear (positions in metres) or rotary (radians); a profile knows which from the unit of its
distance.

Builders: :func:`trapezoidal`, :func:`triangular`, :func:`s_curve` (jerk-limited, 7 segments),
:func:`dwell`, :func:`sequence` (moves one after another) and :func:`sampled`.

References
----------
1. Biagiotti, L. & Melchiorri, C., *Trajectory Planning for Automatic Machines and Robots*,
   Springer 2008, §3.2 (trapezoidal velocity profile, eqs. 3.8-3.12) and §3.4 (double-S / seven
   segment profile, eqs. 3.30-3.33).
2. Oriental Motor, *Technical Reference: Motor Sizing Calculations* (acceleration/deceleration
   operation: a = v / t_acc).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError, UnitError, renamed
from mechverify.units import Q, as_quantity, fmt, to_si

_KIND_UNIT = {"length": ("m", "m/s", "m/s**2", "m/s**3"), "angle": ("rad", "rad/s", "rad/s**2", "rad/s**3")}
_VEL_DIM = {"length": "velocity", "angle": "angular_velocity"}
_ACC_DIM = {"length": "acceleration", "angle": "angular_acceleration"}


def _kind_of(distance: Any, name: str = "distance") -> tuple[str, float]:
    """('length' | 'angle', SI value) of a distance given as a length or an angle."""
    q = as_quantity(distance, "length", name) if _is_length(distance) else None
    if q is not None:
        return "length", to_si(q, "length", name)
    try:
        return "angle", to_si(distance, "angle", name)
    except UnitError:
        raise UnitError(f"{name}: expected a length or an angle, got {distance!r}") from None


def _is_length(v: Any) -> bool:
    try:
        as_quantity(v, "length")
        return True
    except UnitError:
        return False


def _rate(value: Any, kind: str, order: int, name: str) -> float:
    """SI value of a velocity (order 1), acceleration (2) or jerk (3) matching the axis kind."""
    unit = _KIND_UNIT[kind][order]
    q = Q(value) if isinstance(value, str) else value
    if not isinstance(q, pint.Quantity):
        raise UnitError(f"{name}: expected a quantity in units like {unit}, got the bare value {value!r}")
    target = Q(1, unit)
    if q.dimensionality != target.dimensionality:
        raise UnitError(f"{name}: expected a quantity in units like {unit}, got {fmt(q)}")
    v = float(q.to(unit).magnitude)
    if not math.isfinite(v):
        raise UnitError(f"{name}: must be finite")
    return v


@dataclass(frozen=True)
class JerkSegment:
    """A constant-jerk piece: starts at ``(x0, v0, a0)``, lasts ``duration`` [s], jerk ``j``. SI floats."""

    duration: float
    j: float
    x0: float
    v0: float
    a0: float
    label: str = ""

    def state(self, tau: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """x, v, a, j at local times ``tau`` (0..duration)."""
        tau = np.asarray(tau, float)
        a = self.a0 + self.j * tau
        v = self.v0 + self.a0 * tau + 0.5 * self.j * tau**2
        x = self.x0 + self.v0 * tau + 0.5 * self.a0 * tau**2 + self.j * tau**3 / 6.0
        return x, v, a, np.full_like(tau, self.j)

    @cached_property
    def end(self) -> tuple[float, float, float]:
        """x, v, a at the end (computed once: the segment is immutable)."""
        x, v, a, _ = self.state(np.array([self.duration]))
        return float(x[0]), float(v[0]), float(a[0])


@dataclass(frozen=True)
class ProfileSamples:
    """Sampled profile: arrays of time and state, SI floats, with the label of each sample's phase.

    JerkSegment boundaries appear twice (end of one, start of the next) so that jumps in
    acceleration are kept exactly; the zero-length interval adds nothing to integrals.
    """

    kind: str
    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    labels: tuple[str, ...]

    def quantities(self) -> dict[str, pint.Quantity]:
        u = _KIND_UNIT[self.kind]
        return {"t": Q(self.t, "s"), "x": Q(self.x, u[0]), "v": Q(self.v, u[1]), "a": Q(self.a, u[2]),
                "j": Q(self.j, u[3])}


#: :meth:`Profile.sample` results: ``id(profile) -> (profile, {points_per_segment: samples})``. The entry holds the
#: profile, so its id is not reused while the entry lives; bounded (cleared when full: a study builds a profile
#: per sample whose inputs change).
_SAMPLES: dict[int, tuple[Any, dict[int, ProfileSamples]]] = {}
_SAMPLES_MAX = 256


@dataclass(frozen=True)
class Profile:
    """A motion profile made of constant-jerk :class:`JerkSegment` s (SI inside)."""

    kind: str  # "length" or "angle"
    segments: tuple[JerkSegment, ...]
    name: str = ""
    reached_max_velocity: bool = True  # False when a trapezoidal move became triangular

    def __post_init__(self) -> None:
        if self.kind not in _KIND_UNIT:
            raise InputError(f"profile kind must be 'length' or 'angle', got {self.kind!r}")
        if not self.segments:
            raise InputError("a profile needs at least one segment")

    # -- summary values
    @property
    def duration(self) -> pint.Quantity:
        return Q(sum(s.duration for s in self.segments), "s")

    @property
    def start(self) -> float:
        return self.segments[0].x0

    @property
    def end_state(self) -> tuple[float, float, float]:
        return self.segments[-1].end

    @property
    def distance(self) -> pint.Quantity:
        """Net displacement end - start."""
        return Q(self.end_state[0] - self.start, _KIND_UNIT[self.kind][0])

    def _bounds(self) -> np.ndarray:
        return np.concatenate([[0.0], np.cumsum([s.duration for s in self.segments])])

    def sample(self, points_per_segment: int = 41) -> ProfileSamples:
        """Sample every segment at ``points_per_segment`` points, boundaries included.

        Computed once per profile and number of points (a drive's demand and its figure data read the same
        samples); the arrays are read-only, so a caller cannot change what the next one gets. The memo lives
        outside the profile (:data:`_SAMPLES`), so the profile stays immutable all the way down and the
        variants of a study share it with its samples (``mechverify.design.reuse.shareable``).
        """
        if points_per_segment < 2:
            raise InputError("points_per_segment must be >= 2")
        hit = _SAMPLES.get(id(self))
        if hit is None or hit[0] is not self:
            if len(_SAMPLES) >= _SAMPLES_MAX:
                _SAMPLES.clear()
            hit = _SAMPLES[id(self)] = (self, {})
        s = hit[1].get(points_per_segment)
        if s is None:
            s = hit[1][points_per_segment] = self._sample(points_per_segment)
        return s

    def _sample(self, points_per_segment: int) -> ProfileSamples:
        ts, xs, vs, as_, js, labels = [], [], [], [], [], []
        t0 = 0.0
        for seg in self.segments:
            n = points_per_segment if seg.duration > 0 else 1
            tau = np.linspace(0.0, seg.duration, n)
            x, v, a, j = seg.state(tau)
            ts.append(t0 + tau)
            xs.append(x)
            vs.append(v)
            as_.append(a)
            js.append(j)
            labels.extend([seg.label] * n)
            t0 += seg.duration
        arrays = [np.concatenate(c) for c in (ts, xs, vs, as_, js)]
        for arr in arrays:
            arr.setflags(write=False)
        return ProfileSamples(self.kind, *arrays, tuple(labels))

    def at(self, t: Any) -> dict[str, pint.Quantity]:
        """Position, velocity, acceleration and jerk at time(s) ``t`` (a time quantity)."""
        tt = np.atleast_1d(np.asarray(to_si(t, "time", "t"), float))
        bounds = self._bounds()
        if np.any(tt < -1e-12) or np.any(tt > bounds[-1] * (1 + 1e-12) + 1e-15):
            raise InputError(f"t: outside the profile (0 .. {bounds[-1]:g} s)")
        idx = np.clip(np.searchsorted(bounds, tt, side="right") - 1, 0, len(self.segments) - 1)
        out = np.zeros((4, len(tt)))
        for k in np.unique(idx):
            m = idx == k
            out[:, m] = np.array(self.segments[k].state(tt[m] - bounds[k]))
        u = _KIND_UNIT[self.kind]
        res = {n: Q(out[i] if np.ndim(t) else float(out[i][0]), u[i]) for i, n in enumerate("xvaj")}
        return res

    @property
    def peak_velocity(self) -> pint.Quantity:
        s = self.sample()
        return Q(float(np.max(np.abs(s.v))), _KIND_UNIT[self.kind][1])

    @property
    def peak_acceleration(self) -> pint.Quantity:
        s = self.sample()
        return Q(float(np.max(np.abs(s.a))), _KIND_UNIT[self.kind][2])

    def then(self, other: Profile) -> Profile:
        """This profile followed by ``other`` (shifted to start where this one ends)."""
        return sequence(self, other)

    def __repr__(self) -> str:
        return (f"<Profile {self.name or self.kind}: {fmt(self.distance)} in {fmt(self.duration)}, "
                f"{len(self.segments)} segments>")


# ---------------------------------------------------------------------------------------- builders
def _mirror(segs: list[JerkSegment], sign: float) -> list[JerkSegment]:
    if sign > 0:
        return segs
    return [JerkSegment(s.duration, -s.j, -s.x0, -s.v0, -s.a0, s.label) for s in segs]


def _chain(pieces: list[tuple[float, float, float, str]], x0: float = 0.0) -> list[JerkSegment]:
    """Build segments from (duration, jerk, start acceleration, label), integrating the state."""
    segs: list[JerkSegment] = []
    x, v = x0, 0.0
    for dur, j, a0, label in pieces:
        if dur <= 0:
            continue
        s = JerkSegment(dur, j, x, v, a0, label)
        segs.append(s)
        x, v, _ = s.end
    return segs


def _positive(v: float, name: str) -> float:
    if not v > 0:
        raise InputError(f"{name}: must be positive, got {v!r} (SI)")
    return v


def trapezoidal(distance: Any, *, max_velocity: Any = None, acceleration: Any = None, duration: Any = None,
                deceleration: Any = None, allow_triangular: bool = True) -> Profile:
    """Trapezoidal velocity move over ``distance`` (a length or an angle; negative moves backwards).

    Give two of ``max_velocity``, ``acceleration``, ``duration`` [1, §3.2]:

    * v and a: accelerate at a to v, cruise, decelerate (at ``deceleration``, default a). If the
      distance is too short to reach v (D < v²/2a + v²/2d) the move is triangular with peak
      ``sqrt(2D·a·d/(a+d))`` (``allow_triangular=False`` makes that an error);
    * T and a: t_a = (T - sqrt(T² - 4D/a))/2; needs a >= 4D/T²;
    * T and v: t_a = T - D/v; needs D/T <= v <= 2D/T.

    The profile reaches ``distance`` exactly. Impossible combinations raise :class:`InputError`
    saying which limit to change.
    """
    kind, D = _kind_of(distance)
    sign = 1.0 if D >= 0 else -1.0
    D = abs(D)
    _positive(D, "distance")
    given = {k for k, v in (("v", max_velocity), ("a", acceleration), ("T", duration)) if v is not None}
    if len(given) != 2:
        raise InputError("trapezoidal: give exactly two of max_velocity, acceleration, duration "
                         f"(got {', '.join(sorted(given)) or 'none'})")
    if deceleration is not None and given != {"v", "a"}:
        raise InputError("trapezoidal: deceleration can only be given with max_velocity and acceleration")
    vu, au = _KIND_UNIT[kind][1], _KIND_UNIT[kind][2]
    reached = True
    if given == {"v", "a"}:
        v = _positive(_rate(max_velocity, kind, 1, "max_velocity"), "max_velocity")
        a = _positive(_rate(acceleration, kind, 2, "acceleration"), "acceleration")
        d = a if deceleration is None else _positive(_rate(deceleration, kind, 2, "deceleration"), "deceleration")
        d_ramps = v * v / (2 * a) + v * v / (2 * d)
        if D < d_ramps:
            if not allow_triangular:
                raise InputError(f"distance {D:g} too short to reach max_velocity {v:g} {vu} with acceleration "
                                 f"{a:g} {au}: needs at least {d_ramps:g} ({_KIND_UNIT[kind][0]})")
            v = math.sqrt(2 * D * a * d / (a + d))
            reached = False
        ta, td = v / a, v / d
        tc = (D - v * v / (2 * a) - v * v / (2 * d)) / v
    elif given == {"T", "a"}:
        T = _positive(to_si(duration, "time", "duration"), "duration")
        a = _positive(_rate(acceleration, kind, 2, "acceleration"), "acceleration")
        disc = T * T - 4 * D / a
        if disc < -1e-12 * T * T:
            raise InputError(f"distance {D:g} {_KIND_UNIT[kind][0]} is not reachable in {T:g} s with acceleration "
                             f"{a:g} {au}: needs acceleration >= 4D/T² = {4 * D / T**2:.6g} {au} "
                             f"or duration >= 2·sqrt(D/a) = {2 * math.sqrt(D / a):.6g} s")
        ta = (T - math.sqrt(max(disc, 0.0))) / 2
        td, v = ta, a * ta
        tc = T - 2 * ta
        d = a
        reached = tc > 0
    else:
        T = _positive(to_si(duration, "time", "duration"), "duration")
        v = _positive(_rate(max_velocity, kind, 1, "max_velocity"), "max_velocity")
        if v < D / T * (1 - 1e-12):
            raise InputError(f"distance {D:g} {_KIND_UNIT[kind][0]} is not reachable in {T:g} s at max_velocity "
                             f"{v:g} {vu}: even cruising all the way needs v >= D/T = {D / T:.6g} {vu}")
        if v > 2 * D / T * (1 + 1e-12):
            raise InputError(f"max_velocity {v:g} {vu} cannot be the peak of a {T:g} s move over {D:g}: "
                             f"a trapezoid's peak lies between D/T = {D / T:.6g} and 2D/T = {2 * D / T:.6g} {vu}")
        ta = min(T - D / v, T / 2)
        td, tc = ta, T - 2 * ta
        a = d = v / ta
        reached = tc > 0
    pieces = [(ta, 0.0, a, "accelerating"), (tc, 0.0, 0.0, "constant speed"), (td, 0.0, -d, "decelerating")]
    segs = _mirror(_chain(pieces), sign)
    # remove round-off so the move ends exactly at D
    last = segs[-1]
    err = last.end[0] - sign * D
    if abs(err) > 0:
        segs[-1] = JerkSegment(last.duration, last.j, last.x0 - err, last.v0, last.a0, last.label)
    return Profile(kind, tuple(segs), name="trapezoidal" if reached else "triangular", reached_max_velocity=reached)


def triangular(distance: Any, *, duration: Any = None, acceleration: Any = None) -> Profile:
    """Triangular velocity move: accelerate for half the time, decelerate for the other half.

    Give ``duration`` (then a = 4D/T²) or ``acceleration`` (then T = 2·sqrt(D/a)) [1, §3.2].
    """
    kind, D = _kind_of(distance)
    if (duration is None) == (acceleration is None):
        raise InputError("triangular: give exactly one of duration, acceleration")
    sign = 1.0 if D >= 0 else -1.0
    D = _positive(abs(D), "distance")
    if duration is not None:
        T = _positive(to_si(duration, "time", "duration"), "duration")
        a = 4 * D / T**2
    else:
        a = _positive(_rate(acceleration, kind, 2, "acceleration"), "acceleration")
        T = 2 * math.sqrt(D / a)
    pieces = [(T / 2, 0.0, a, "accelerating"), (T / 2, 0.0, -a, "decelerating")]
    return Profile(kind, tuple(_mirror(_chain(pieces), sign)), name="triangular", reached_max_velocity=False)


def s_curve(distance: Any, *, max_velocity: Any, acceleration: Any, jerk: Any) -> Profile:
    """Jerk-limited (double-S, seven-segment) move from rest to rest [1, §3.4].

    With limits V, A, J: the acceleration phase lasts T_a = V/A + A/J when V·J >= A² (constant-
    acceleration part present), else T_a = 2·sqrt(V/J). If the distance D < V·T_a the peak
    velocity is lowered so that V·T_a(V) = D (the cruise vanishes) and, when needed, the peak
    acceleration too.
    """
    kind, D = _kind_of(distance)
    sign = 1.0 if D >= 0 else -1.0
    D = _positive(abs(D), "distance")
    V = _positive(_rate(max_velocity, kind, 1, "max_velocity"), "max_velocity")
    A = _positive(_rate(acceleration, kind, 2, "acceleration"), "acceleration")
    J = _positive(_rate(jerk, kind, 3, "jerk"), "jerk")

    def accel_phase(v: float) -> tuple[float, float]:  # (T_a, T_j)
        if v * J >= A * A:
            return v / A + A / J, A / J
        tj = math.sqrt(v / J)
        return 2 * tj, tj

    Ta, Tj = accel_phase(V)
    reached = True
    if D < V * Ta:
        reached = False
        # cruise vanishes: find V with V·T_a(V) = D
        v1 = A / 2 * (-A / J + math.sqrt((A / J) ** 2 + 4 * D / A))  # branch with constant-acc part
        V = v1 if v1 * J >= A * A else (D * math.sqrt(J) / 2) ** (2 / 3)
        Ta, Tj = accel_phase(V)
    a_peak = J * Tj
    Tv = max(D / V - Ta, 0.0)
    Tconst = max(Ta - 2 * Tj, 0.0)
    pieces = [(Tj, J, 0.0, "accelerating"), (Tconst, 0.0, a_peak, "accelerating"), (Tj, -J, a_peak, "accelerating"),
              (Tv, 0.0, 0.0, "constant speed"),
              (Tj, -J, 0.0, "decelerating"), (Tconst, 0.0, -a_peak, "decelerating"), (Tj, J, -a_peak, "decelerating")]
    segs = _mirror(_chain(pieces), sign)
    last = segs[-1]
    err = last.end[0] - sign * D
    segs[-1] = JerkSegment(last.duration, last.j, last.x0 - err, last.v0, last.a0, last.label)
    return Profile(kind, tuple(segs), name="s-curve", reached_max_velocity=reached)


def dwell(duration: Any, kind: str = "length") -> Profile:
    """Standing still for ``duration`` (kind 'length' or 'angle' to match the moves around it)."""
    T = _positive(to_si(duration, "time", "duration"), "duration")
    return Profile(kind, (JerkSegment(T, 0.0, 0.0, 0.0, 0.0, "dwell"),), name="dwell")


def sequence(*profiles: Profile) -> Profile:
    """Profiles one after another; each starts where the previous ended.

    Velocities must match at the joins (moves from rest to rest always do).
    """
    if not profiles:
        raise InputError("sequence: give at least one profile")
    kinds = {p.kind for p in profiles if p.name != "dwell"} or {profiles[0].kind}
    if len(kinds) > 1:
        raise InputError("sequence: cannot mix linear and rotary profiles")
    kind = kinds.pop()
    segs: list[JerkSegment] = []
    x_end, v_end = profiles[0].start, 0.0
    for i, p in enumerate(profiles):
        v0 = p.segments[0].v0
        if i and abs(v0 - v_end) > 1e-9 * max(1.0, abs(v_end)):
            raise InputError(f"sequence: profile {i} starts at velocity {v0:g} but the previous ends at {v_end:g}")
        shift = x_end - p.start
        for s in p.segments:
            segs.append(JerkSegment(s.duration, s.j, s.x0 + shift, s.v0, s.a0, s.label or p.name))
        x_end, v_end, _ = segs[-1].end
    reached = all(p.reached_max_velocity for p in profiles)
    return Profile(kind, tuple(segs), name="sequence", reached_max_velocity=reached)


@dataclass(frozen=True)
class SampledProfile:
    """A profile given as sampled ``(t, x)`` data; v, a and j by finite differences.

    Derivatives use second-order central differences on the (possibly uneven) time grid
    (``numpy.gradient``); noisy data give noisy accelerations, so smooth before if needed.
    """

    kind: str
    t: np.ndarray
    x: np.ndarray
    name: str = "sampled"
    labels: tuple[str, ...] = field(default=())

    @property
    def duration(self) -> pint.Quantity:
        return Q(float(self.t[-1] - self.t[0]), "s")

    @property
    def distance(self) -> pint.Quantity:
        return Q(float(self.x[-1] - self.x[0]), _KIND_UNIT[self.kind][0])

    def sample(self, points_per_segment: int = 0) -> ProfileSamples:
        t = self.t - self.t[0]
        v = np.gradient(self.x, t, edge_order=2) if len(t) > 2 else np.gradient(self.x, t)
        a = np.gradient(v, t, edge_order=2) if len(t) > 2 else np.zeros_like(v)
        j = np.gradient(a, t, edge_order=2) if len(t) > 2 else np.zeros_like(v)
        labels = self.labels or tuple(f"sample {i}" for i in range(len(t)))
        return ProfileSamples(self.kind, t, self.x.copy(), v, a, j, labels)

    @property
    def peak_velocity(self) -> pint.Quantity:
        return Q(float(np.max(np.abs(self.sample().v))), _KIND_UNIT[self.kind][1])


def sampled(t: Any, x: Any) -> SampledProfile:
    """A profile from measured or planned samples: ``t`` (time array), ``x`` (length or angle array)."""
    tt = np.asarray(to_si(t, "time", "t"), float)
    if _is_length(x):
        kind, xx = "length", np.asarray(to_si(x, "length", "x"), float)
    else:
        kind, xx = "angle", np.asarray(to_si(x, "angle", "x"), float)
    if tt.ndim != 1 or xx.shape != tt.shape:
        raise InputError(f"sampled: t and x must be 1-D arrays of equal length (got {tt.shape} and {xx.shape})")
    if len(tt) < 3:
        raise InputError("sampled: need at least 3 samples to differentiate")
    if np.any(np.diff(tt) <= 0):
        raise InputError("sampled: times must be strictly increasing")
    return SampledProfile(kind, tt, xx)


AnyProfile = Profile | SampledProfile

__all__ = ["Profile", "SampledProfile", "JerkSegment", "ProfileSamples", "trapezoidal", "triangular", "s_curve",
           "dwell", "sequence", "sampled", "AnyProfile"]

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"Segment": "JerkSegment"})
