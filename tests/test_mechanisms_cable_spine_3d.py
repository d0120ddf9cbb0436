"""The cable spine tilted between cables (mechverify.mechanisms.cable_spine_3d: a 3D Kirchhoff rod).

Checks: along a cable the 3D rod reproduces the planar elastica (CableSpine.at_tilt(..., "elastica")); midway
between two cables (a plane of symmetry) the two tensions are equal, the twist is zero and the top stays in the
tilt plane, and the result equals a planar shooting built in this test from the two cables' in-plane resultant
(integrate_elastica, the planar integrator, with the cable geometry written here); near a cable the pan is
continuous. Timoshenko & Gere Sec. 2.18 rigidities as in the package; consistency and limit checks, not printed
values.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechverify.components.springs import CompressionSpring
from mechverify.mechanisms.cable_spine import CableSpine, integrate_elastica
from mechverify.mechanisms.cable_spine_3d import bracketing_cables, state_3d


def spine(weight: str = "1.25 N") -> CableSpine:
    s = CompressionSpring(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", end="squared-ground", material="A228",
                          G="79.3 GPa", E="206.8 GPa", name="spine")
    return CableSpine(s, weight=weight, name="neck")


def test_along_a_cable_equals_the_planar_elastica():
    sp = spine()
    pl = sp.at_tilt("30 deg", "elastica")
    st = state_3d(sp, "30 deg", "0 deg")
    assert st.tensions[0] == pytest.approx(pl.tension, rel=1e-7) and np.all(st.tensions[1:] == 0)
    assert st.top[0] == pytest.approx(pl.lateral, rel=1e-7) and abs(st.top[1]) < 1e-12
    assert st.top[2] == pytest.approx(pl.height, rel=1e-8)
    assert st.axial_force == pytest.approx(pl.axial_force, rel=1e-7)
    assert abs(st.twist) < 1e-12


def test_midway_is_a_planar_problem_with_two_cables():
    """Pan 60 deg between the cables at 0 and 120 deg: T0 = T1, no twist, top in the tilt plane, and the same
    state from a planar shooting of the two cables' in-plane resultant (x along the pan, z up)."""
    sp = spine()
    tilt, pan = math.radians(25), math.radians(60)
    st = state_3d(sp, "25 deg", "60 deg")
    assert st.tensions[0] == pytest.approx(st.tensions[1], rel=1e-9) and st.tensions[2] == 0
    assert abs(st.twist) < 1e-10
    assert math.atan2(st.top[1], st.top[0]) == pytest.approx(pan, abs=1e-9)
    a = b = 0.05
    sg = sp.spring
    beta0, L0, k = sg.rigidities().beta.m_as("N*m**2"), sg.free_length.m_as("m"), sg.rate.m_as("N/m")
    W = 1.25
    # the two cables' anchors in the tilt plane's frame (x along the pan, y across, z up), gamma = +-60 deg from
    # the pan; the platform turns by the tilt about y
    gam = (-math.radians(60), math.radians(60))

    def loads(xt: float, zt: float, T: float) -> tuple[float, float, float]:
        Fx, Fz, M = 0.0, -W, 0.0
        for g in gam:
            ax, ay = a * math.cos(g), a * math.sin(g)  # anchor on the untilted platform
            px, pz = ax * math.cos(tilt), -ax * math.sin(tilt)  # after the tilt about y
            bx, by = b * math.cos(g), b * math.sin(g)
            u = np.array([bx - (xt + px), by - ay, -(zt + pz)])
            u /= np.linalg.norm(u)
            Fx, Fz = Fx + T * u[0], Fz + T * u[2]
            M += pz * T * u[0] - px * T * u[2]  # about y at the top: (r x f)_y = r_z f_x - r_x f_z
        return Fx, Fz, M

    def residual(v: np.ndarray) -> list[float]:
        xt, zt, T = v
        x, z, th = integrate_elastica(*loads(xt, zt, T), xt, zt, beta0, L0, k * L0)
        return [x - xt, z - zt, th - tilt]

    xt, zt, T = fsolve(residual, [math.hypot(*st.top[:2]), st.top[2], st.tensions[0]], xtol=1e-12)
    assert T == pytest.approx(st.tensions[0], rel=1e-6)
    assert xt == pytest.approx(math.hypot(*st.top[:2]), rel=1e-6)
    assert zt == pytest.approx(st.top[2], rel=1e-8)


def test_pan_between_is_continuous_and_both_cables_pull():
    """At 1 deg from the cable the tensions approach the planar ones; at 30 deg both pull and the cable nearer the
    pan pulls harder; the twist the cables leave is small (< 0.1 deg)."""
    sp = spine()
    pl = sp.at_tilt("20 deg", "elastica")
    near = state_3d(sp, "20 deg", "1 deg")
    assert near.tensions[0] == pytest.approx(pl.tension, rel=0.05) and near.tensions[1] < 0.05 * pl.tension
    mid = state_3d(sp, "20 deg", "30 deg")
    assert mid.tensions[0] > mid.tensions[1] > 0 and mid.tensions[2] == 0
    assert abs(math.degrees(mid.twist)) < 0.1
    assert bracketing_cables(np.radians([0, 120, 240]), math.radians(200)) == (1, 2)
