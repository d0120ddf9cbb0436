"""Independent cross-check of the cable spine's large-deflection (elastica) equilibrium by a discrete model.

The package solves the spine as an extensible elastica by shooting (``CableSpine.elastica_state``: solve_ivp on
dtheta/ds0 = M/beta0 with the cable force and moment at the top, fsolve on the top position). Here the same column
is a Hencky bar chain, written in this file: N rigid links of length ds = L0/N, each stretched by
lam = 1 + (Fx sin theta + Fz cos theta)/alpha0 (alpha0 = k L0, the spring's axial stiffness), joined by rotational
springs beta0/ds (the base one to the clamp); equilibrium of the part above every joint,
(beta0/ds) (theta_k - theta_{k-1}) = M0 + Fx (z_t - z_k) - Fz (x_t - x_k), solved by fsolve. The chain converges
to the continuous elastica at first order in 1/N (checked: the error halves with N), so Richardson's
extrapolation 2 f(2N) - f(N) removes the leading error. The top loads are those of the package's equilibrium
(the cable from the platform anchor to the base anchor, the weight); the chain must put the top where the package
found it. Sources: H. Hencky (1921), the bar-chain model of a beam (e.g. Wang, Zhang & Xiang, "Hencky bar-chain
model for buckling analysis of non-uniform columns", Structures 2016: first-order convergence of the plain chain);
the beam's rigidities are Timoshenko & Gere Sec. 2.18 (as the package). Hand-built numerics, not printed values.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import fsolve

from mechverify.components.springs import CompressionSpring
from mechverify.mechanisms.cable_spine import CableSpine


def spring() -> CompressionSpring:
    return CompressionSpring(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", end="squared-ground", material="A228",
                             G="79.3 GPa", E="206.8 GPa", name="spine")


def chain_top(N: int, Fx: float, Fz: float, M0: float, beta0: float, L0: float, alpha0: float,
              tilt_guess: float) -> np.ndarray:
    """Top (x, z, theta) of the Hencky chain under dead end loads."""
    ds, c = L0 / N, beta0 * N / L0

    def geom(th: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        lam = 1.0 + (Fx * np.sin(th) + Fz * np.cos(th)) / alpha0
        return (np.concatenate([[0.0], np.cumsum(lam * ds * np.sin(th))]),
                np.concatenate([[0.0], np.cumsum(lam * ds * np.cos(th))]))

    def residual(th: np.ndarray) -> np.ndarray:
        x, z = geom(th)
        M = M0 + Fx * (z[-1] - z[:-1]) - Fz * (x[-1] - x[:-1])
        return c * np.diff(np.concatenate([[0.0], th])) - M

    th = fsolve(residual, tilt_guess * np.linspace(0.5 / N, 1 - 0.5 / N, N), xtol=1e-12)
    assert np.max(np.abs(residual(th))) < 1e-9 * max(abs(Fx), abs(Fz), 1.0)
    x, z = geom(th)
    return np.array([x[-1], z[-1], th[-1]])


@pytest.mark.parametrize("weight, tilt_deg", [("1.25 N", 40.0), ("0 N", 25.0), ("5 N", 15.0)])
def test_elastica_state_is_the_limit_of_the_bar_chain(weight, tilt_deg):
    """At 40 deg the spring top moves 33 mm sideways on a 100 mm spring (far from the small-angle form): the
    Richardson-extrapolated chain (N = 100, 200) puts the top within 2e-4 of the package's lateral displacement,
    height and tilt (relative), and the chain's own error halves from N = 100 to 200 (first order, as assumed)."""
    sp = CableSpine(spring(), weight=weight)
    st = sp.at_tilt(f"{tilt_deg} deg", "elastica")
    sg = spring()
    s = {"a": 0.05, "b": 0.05, "W": float(weight.split()[0]), "beta0": sg.rigidities().beta.m_as("N*m**2"),
         "L0": sg.free_length.m_as("m"), "k": sg.rate.m_as("N/m")}  # the spine's defaults: a = b = 50 mm
    assert (sp.platform_radius, sp.base_radius) == ("50 mm", "50 mm")
    a, T = s["a"], st.tension
    xt, zt, tht = st.lateral, st.height, st.tilt
    bx, bz = xt + a * math.cos(tht), zt - a * math.sin(tht)  # platform anchor of the pulling cable
    L = math.hypot(s["b"] - bx, -bz)
    ux, uz = (s["b"] - bx) / L, -bz / L  # towards the base anchor at (b, 0)
    Fx, Fz = T * ux, T * uz - s["W"]
    M0 = -a * math.sin(tht) * T * ux - a * math.cos(tht) * T * uz  # moment of the cable force about the top
    args = (Fx, Fz, M0, s["beta0"], s["L0"], s["k"] * s["L0"], tht)
    f1, f2, f4 = (chain_top(n, *args) for n in (100, 200, 400))
    ratio = (f1 - f2) / (f2 - f4)
    assert ratio == pytest.approx(np.full(3, 2.0), rel=0.05)  # first-order convergence
    extrap = 2 * f4 - f2
    pkg = np.array([xt, zt, tht])
    assert extrap == pytest.approx(pkg, rel=2e-4)
    assert np.max(np.abs(f1 - pkg) / np.abs(pkg)) > 1e-3  # the plain chain at N = 100 is visibly off: the test can fail
