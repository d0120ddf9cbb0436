"""Reference project 001 (cable-driven neck): cable tension over the tilt, spine as a beam-column.

The document's model (its Sec. 3.2.2, Eqs. (3.7)-(3.19), one cable pulling, T3 = 0): the spring is a
column clamped on the fixed base with its top free, carrying the platform weight W at the top centre and
the cable tension T1 at the platform edge (radius a), the cable running to the fixed plate at radius b.
Small-deflection beam-column equation with Timoshenko's flexural rigidity of the compressed spring:

    beta(l) y'' + P y = P (y_b + a0) + P a1 z,   P = W + T1 cos(alpha1),   w = sqrt(P / beta),
    a0 = T1 (a cos(alpha1 - theta) ... ) / P  (moment of the cable about the top),   a1 = T1 sin(alpha1) / P,

with y(0) = y'(0) = 0, tip deflection y_b and tip slope tan(theta) (Eqs. (3.9), (3.12), (3.13) — the
standard cantilever beam-column, Timoshenko & Gere, Theory of Elastic Stability, 2nd ed. 1961, Sec. 1.2:
an end moment M0 alone gives y' (l) = (M0/P) w tan(wl)), the spring shortened to l = L0 - P/k (Eq. (3.19)),
the top lowered by z_y = 1/2 Int y'^2 dz, and the cable angle alpha1 from the deformed geometry
(Eqs. (3.15)-(3.18)). beta(l) = beta0 l/L0 and k come from ``CompressionSpring.rigidities`` and ``.rate``
(Timoshenko & Gere Sec. 2.18). The model is linear in the curvature: the document itself limits it to
about 15 deg; it stops where P reaches the spine's fixed-free buckling load (w l -> pi/2).

Run ``python examples/cable_neck/run.py`` for the table in docs/examples/cable_neck.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, fsolve

from mechverify.components.springs import CompressionSpring
from mechverify.errors import ModelError
from mechverify.units import Q, as_quantity, to_si

G0 = 9.80665  # standard gravity [m/s^2]


def spine(**overrides) -> CompressionSpring:
    """The neck's spring as the document specifies it (Tabla 4; ends not stated, squared-ground assumed)."""
    kw = dict(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", end="squared-ground", material="A228",
              G="79.3 GPa", E="206.8 GPa", name="spine")
    kw.update(overrides)
    return CompressionSpring(**kw)


@dataclass(frozen=True)
class TiltState:
    """Equilibrium of the neck for one cable tension (SI units: N, m, rad)."""

    tension: float  # T1 [N]
    theta: float  # platform tilt [rad]
    y_b: float  # lateral displacement of the spring top [m]
    z_y: float  # lowering of the top by bending [m]
    length: float  # compressed spring length l [m]
    alpha1: float  # cable angle from the vertical [rad]
    axial_force: float  # P = W + T1 cos(alpha1) [N]
    wl: float  # sqrt(P/beta) l; pi/2 is the fixed-free buckling load
    beta: float  # flexural rigidity at l [N m^2]

    @property
    def buckling_ratio(self) -> float:
        """P / P_cr with P_cr = pi^2 beta / (4 l^2) (fixed-free Euler column on beta(l))."""
        return self.axial_force / (math.pi**2 * self.beta / (4 * self.length**2))


class NeckStatics:
    """Planar statics of the neck with one pulling cable (the document's simplification T3 = 0)."""

    def __init__(self, spring: CompressionSpring, weight="1.25 N", a="50 mm", b="50 mm",
                 beta0=None):
        self.spring = spring
        self.k = spring.rate.m_as("N/m")
        self.L0 = spring.free_length.m_as("m")
        self.beta0 = spring.rigidities().beta.m_as("N*m**2") if beta0 is None else Q(beta0).m_as("N*m**2")
        self.W = to_si(weight, "force", "weight")
        self.a, self.b = to_si(a, "length", "a"), to_si(b, "length", "b")
        self._guess = None

    def _residual(self, x, T1):
        l, al, zy = x
        P = self.W + T1 * math.cos(al)
        beta = self.beta0 * l / self.L0
        w = math.sqrt(P / beta)
        wl = w * l
        if P <= 0 or wl >= math.pi / 2:
            raise ModelError(f"axial force {P:.3g} N reaches the spine's fixed-free buckling load")
        a, b = self.a, self.b
        th = 0.0
        for _ in range(200):  # a0 depends on the tilt through the lever arms of the cable force
            a0 = (T1 * math.cos(al) * a * math.cos(th) + T1 * math.sin(al) * a * math.sin(th)
                  - T1 * math.sin(al) * l) / P
            a1 = T1 * math.sin(al) / P
            th_new = math.atan(a0 * w * math.tan(wl) + a1 * (1 - 1 / math.cos(wl) + wl * math.tan(wl)))
            if abs(th_new - th) < 1e-15:
                break
            th = 0.5 * (th + th_new)
        yb = (1 - math.cos(wl)) / math.cos(wl) * a0 - a1 / w * math.tan(wl) + a1 * l / math.cos(wl)
        z = np.linspace(0.0, l, 201)
        slope = (yb + a0) * w * np.sin(w * z) - a1 * np.cos(w * z) + a1
        zy_new = 0.5 * float(np.trapezoid(slope**2, z))
        al_new = math.atan2(yb + a * math.cos(th) - b, l - zy - a * math.sin(th))
        state = TiltState(T1, th, yb, zy, l, al, P, wl, beta)
        return [self.L0 - P / self.k - l, al_new - al, zy_new - zy], state

    def at_tension(self, tension) -> TiltState:
        """Equilibrium for a cable tension T1 (quantity or string)."""
        T1 = tension if isinstance(tension, float) else to_si(tension, "force", "tension")
        starts = [self._guess, [self.L0 - self.W / self.k, 0.0, 0.0]] if self._guess else \
            [[self.L0 - self.W / self.k, 0.0, 0.0]]
        for x0 in starts:  # from the last equilibrium (continuation), else from the upright spine
            x, _info, ier, msg = fsolve(lambda x: self._residual(x, T1)[0], x0, xtol=1e-12, full_output=True)
            res, state = self._residual(x, T1)
            if ier == 1 and max(abs(r) for r in res) <= 1e-9:
                break
        else:
            raise ModelError(f"no equilibrium found for T1 = {T1:.4g} N: {msg}")
        self._guess = list(x)
        return state

    def at_tilt(self, theta) -> TiltState:
        """Cable tension and shape that hold the platform at tilt ``theta`` (quantity or string)."""
        target = to_si(theta, "angle", "theta")
        T_hi, last = 0.5, None
        while True:  # march in tension (continuation) until the tilt is passed or the model ends
            try:
                last = self.at_tension(T_hi)
            except ModelError as exc:
                raise ModelError(f"tilt {math.degrees(target):.3g} deg is not reached before the spine buckles "
                                 f"(largest tilt {math.degrees(last.theta) if last else 0:.3g} deg at "
                                 f"T1 = {last.tension if last else 0:.3g} N)") from exc
            if last.theta >= target:
                break
            T_hi *= 1.25
        self._guess = None
        T1 = brentq(lambda T: self.at_tension(T).theta - target, 0.0, T_hi, xtol=1e-10)
        return self.at_tension(T1)


def drum_torque(tension, drum_diameter="20 mm", efficiency=0.85):
    """Torque at the drum, M = (d1/2) F_L / eta (the document's Eq. (3.23), maxon 'crane' transmission)."""
    r = as_quantity(drum_diameter, "length", "drum_diameter") / 2
    return (r * as_quantity(tension, "force", "tension") / efficiency).to("N*m")


def tilt_table(weight, angles_deg=(1, 2, 5, 10, 15, 20, 30, 40), beta0=None):
    """Rows (angle, state or None) over the tilt range; None where the model has no equilibrium."""
    model = NeckStatics(spine(), weight=weight, beta0=beta0)
    rows = []
    for ang in angles_deg:
        try:
            rows.append((ang, model.at_tilt(Q(ang, "deg"))))
        except ModelError:
            rows.append((ang, None))
    return rows


def main() -> None:
    s = spine()
    r = s.rigidities()
    print(f"spine: k = {s.rate.to('N/m'):.1f~P}, beta0 = {r.beta:.4f~P} (document: 0.554), "
          f"gamma0 = {r.gamma:.1f~P}, lateral rate (fixed-free) = {s.lateral_rate('fixed-free'):.4f~P}, "
          f"y_cr fixed-free = {s.critical_deflection('fixed-free'):.2f~P}")
    cases = [("platform only, W = 1.25 N (document's Tabla 6, its beta0 = 0.554)", Q(1.25, "N"), "0.554 N*m**2"),
             ("platform only, W = 1.25 N, correct beta0", Q(1.25, "N"), None),
             ("1 kg head + platform, W = 11.06 N, correct beta0", Q(1.25 + G0, "N"), None)]
    for title, W, b0 in cases:
        print(f"\n{title}")
        print(f"{'tilt':>5} {'T1 [N]':>8} {'y_b [mm]':>9} {'l [mm]':>7} {'P/Pcr':>6} {'M drum [N m]':>12}")
        for ang, st in tilt_table(W, beta0=b0):
            if st is None:
                print(f"{ang:>5} {'buckles before this tilt (no equilibrium)':>45}")
                continue
            M = drum_torque(Q(st.tension, "N")).m_as("N*m")
            print(f"{ang:>5} {st.tension:8.3f} {st.y_b * 1e3:9.2f} {st.length * 1e3:7.2f} "
                  f"{st.buckling_ratio:6.3f} {M:12.4f}")


if __name__ == "__main__":
    main()
