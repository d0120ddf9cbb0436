"""Natural frequencies of a cantilever (Euler-Bernoulli): the P2 solid and plane-stress models against the
closed form f_i = (β_i L)² / (2π L²) · sqrt(E I / (ρ A)).

Sources: the constants β1L = 1.8751 and β2L = 4.6941 of the clamped-free beam are printed in Thomson,
Theory of Vibration with Applications, 5th ed., Appendix D.3 (found with the search tool); the same
constants are tabulated in Blevins, Formulas for Natural Frequency and Mode Shape (1979), Table 8-1 (not
seen here). The frequencies below are hand calculations from that formula, not printed values. The first
mode's effective mass, 61.3 % of the beam (Chopra, Dynamics of Structures, sec. 17.2 / Blevins), is a
hand calculation check: ∫φ / sqrt(∫φ²) for the first clamped-free shape gives 0.6131 (not a printed value).
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.fea import mesh, mesh2d, modal, plane, solid
from mechverify.fea.loads import Fixed
from mechverify.fea.regions import Plane

BETA1L = 1.8751  # Thomson, App. D.3 (clamped-free), printed
BETA2L = 4.6941  # Thomson, App. D.3, printed
E, RHO = 200e9, 7850.0  # "Structural Steel" of the materials database


def euler_bernoulli(beta_l: float, L: float, I: float, A: float) -> float:
    """Hand calculation: f = (βL)² / (2π L²) sqrt(EI / ρA) [Hz]."""
    return beta_l**2 / (2 * np.pi * L**2) * np.sqrt(E * I / (RHO * A))


def test_solid_cantilever_first_bending_frequency():
    """L/h = 20 square bar, 20x2x2 cells of P2 tets: within 0.5 % of Euler-Bernoulli (the solid is slightly
    stiff from the coarse cross-section, slightly soft from shear and rotary inertia, both < 0.5 % here)."""
    L, h = 0.2, 0.01
    model = solid.SolidModel(mesh.box((f"{L} m", f"{h} m", f"{h} m"), (20, 2, 2)), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),))
    res = modal.modal(model, 4)
    f1 = euler_bernoulli(BETA1L, L, h**4 / 12, h * h)  # 203.8 Hz
    assert f1 == pytest.approx(203.85, abs=0.01)
    assert res.frequencies.m[0] == pytest.approx(f1, rel=5e-3)
    assert res.frequencies.m[1] == pytest.approx(f1, rel=5e-3)  # the square bar: the same in y and z
    # first two modes: bending in y and z (any mix); their effective masses add to 61.3 % per axis in y+z
    frac = res.effective_mass_fraction()[:2].sum(axis=0)
    assert frac[1] + frac[2] == pytest.approx(2 * 0.6131, rel=0.02)


def test_plane_stress_cantilever_two_modes():
    """In-plane bending of a 200 x 10 mm plane-stress strip: f1 within 0.5 %, f2 within 3 % (shear and rotary
    inertia lower the second mode of a beam of L/h = 20 by about 2 %, Timoshenko beam theory)."""
    L, h, t = 0.2, 0.01, 0.005
    m = mesh2d.rectangle(L, h, 40, 2)
    model = plane.PlaneModel(m, f"{t} m", "Structural Steel", supports=(Fixed(Plane(x="0 mm")),))
    res = modal.modal(model, 3)
    I, A = t * h**3 / 12, t * h
    f = res.frequencies.m
    assert f[0] == pytest.approx(euler_bernoulli(BETA1L, L, I, A), rel=5e-3)
    bend2 = [x for x in f[1:] if abs(x / euler_bernoulli(BETA2L, L, I, A) - 1) < 0.03]
    assert len(bend2) == 1
