"""Cable-driven spring spine (mechverify.mechanisms.cable_spine) against closed forms and limit cases.

Sources: Timoshenko & Gere, Theory of Elastic Stability, 2nd ed. (1961): Sec. 1.2-1.3 (cantilever
beam-column with end moment and lateral force), Sec. 2.18 (helical-spring rigidities), Eq. (2-46)
(shear correction of the critical load). Spring of seed 001 Tabla 4 (d = 3.07 mm, D = 30 mm, Na = 15,
L0 = 100 mm, G = 79.3 GPa, E = 206.8 GPa). Every expected value below is a hand calculation from the
formula named (not a printed value) unless it says "document".
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from mechverify.components.springs import CompressionSpring
from mechverify.errors import InputError
from mechverify.mechanisms.cable_spine import (
    CableSpine,
    UnreachableTiltError,
    free_spring_length,
    rotation,
    tension_distribution,
)

d, D, Na, L0, G, E = 3.07e-3, 30e-3, 15, 0.100, 79.3e9, 206.8e9
I = math.pi * d**4 / 64
BETA0 = 2 * E * G * I * L0 / (math.pi * Na * (D / 2) * (E + 2 * G))  # Sec. 2.18: 0.0554 N m^2
GAMMA0 = E * I * L0 / (math.pi * Na * (D / 2) ** 3)  # Sec. 2.18 shear rigidity
K = d**4 * G / (8 * D**3 * Na)  # Shigley Eq. (10-9)


def spring() -> CompressionSpring:
    return CompressionSpring(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", end="squared-ground", material="A228",
                             G="79.3 GPa", E="206.8 GPa", name="spine")


def test_zero_tension_is_the_free_spring():
    """No cable tension: upright spring, l = L0 - W/k, no tilt, no lateral displacement."""
    m = CableSpine(spring(), weight="1.25 N")
    st = m.linear_state(0.0)
    assert st.tilt == 0 and st.lateral == 0
    assert st.length == pytest.approx(L0 - 1.25 / K, rel=1e-10)
    assert free_spring_length(spring(), "1.25 N").m_as("m") == pytest.approx(L0 - 1.25 / K, rel=1e-12)
    assert m.at_tilt("0 deg").tension == 0


def test_small_tension_matches_the_end_moment_closed_form():
    """Timoshenko & Gere Sec. 1.2: cantilever under axial P and end moment M0, tip slope (M0/P) w tan(wl),
    w = sqrt(P/beta). With a = b the cable starts vertical: M0 = T a, P = W + T, l = L0 - P/k, beta = beta0 l/L0."""
    W, T, a = 9.81, 0.01, 0.05
    st = CableSpine(spring(), weight=f"{W} N").linear_state(T)
    P = W + T
    l = L0 - P / K
    beta = BETA0 * l / L0
    w = math.sqrt(P / beta)
    assert st.tilt == pytest.approx(T * a / P * w * math.tan(w * l), rel=1e-2)


@pytest.mark.parametrize("tilt_deg", [2, 10, 20])
def test_corrected_tabla6_rows_satisfy_the_beam_column_closed_forms(tilt_deg):
    """The document's Tabla 6 recomputed with the correct beta0 (platform only, W = 1.25 N): each row is
    checked by hand against the cantilever beam-column closed forms (Timoshenko & Gere Sec. 1.2-1.3) with
    the row's own P, l, cable angle alpha and tilt: lateral force H = -T sin(alpha) and the moment of the cable
    about the top M0 = T a cos(alpha - theta)... written out: M0 = T a (cos a cos th + sin a sin th);
    tip slope  theta = M0 w tan(wl)/P + H (1/cos(wl) - 1)/P,
    tip deflection y = M0 (1/cos(wl) - 1)/P + H (tan(wl) - wl)/(P w)."""
    m = CableSpine(spring(), weight="1.25 N")
    st = m.at_tilt(f"{tilt_deg} deg")
    a, T, al, th = 0.05, st.tension, st.cable_angle, st.tilt
    P = 1.25 + T * math.cos(al)
    assert st.axial_force == pytest.approx(P, rel=1e-12)
    assert st.length == pytest.approx(L0 - P / K, rel=1e-9)
    beta = BETA0 * st.length / L0
    w = math.sqrt(P / beta)
    wl = w * st.length
    M0 = T * a * (math.cos(al) * math.cos(th) + math.sin(al) * math.sin(th))
    H = -T * math.sin(al)
    slope = M0 * w * math.tan(wl) / P + H * (1 / math.cos(wl) - 1) / P
    y = M0 * (1 / math.cos(wl) - 1) / P + H * (math.tan(wl) - wl) / (P * w)
    assert math.tan(th) == pytest.approx(slope, rel=1e-6)
    assert st.lateral == pytest.approx(y, rel=1e-6)
    assert st.tilt == pytest.approx(math.radians(tilt_deg), abs=1e-9)


def test_documents_tabla6_with_its_beta0_within_10_percent():
    """Document Tabla 6 (beta0 = 0.554 as printed, W = 1.25 N): T = 1.7462 N at 1 deg, 17.4874 N at 10 deg
    (document values). The same model gives 1.91 and 19.0 N (its solver settings and z_y integration are not
    given): within 10 %."""
    m = CableSpine(spring(), weight="1.25 N", beta0="0.554 N*m**2")
    assert m.at_tilt("1 deg").tension == pytest.approx(1.7462, rel=0.10)
    assert m.at_tilt("10 deg").tension == pytest.approx(17.4874, rel=0.10)


def test_elastica_reduces_to_the_linear_beam_column_at_small_tilt():
    """Shooting on the large-deflection elastica: at 1 deg the two models agree to 0.1 %; at 40 deg
    (bare platform, correct beta0) the elastica needs less tension (the linear model overstates the
    lever arms); the gap is reported, not asserted against a source."""
    m = CableSpine(spring(), weight="1.25 N")
    lin, ela = m.at_tilt("1 deg"), m.at_tilt("1 deg", "elastica")
    assert ela.tension == pytest.approx(lin.tension, rel=1e-3)
    assert ela.lateral == pytest.approx(lin.lateral, rel=2e-3)
    big_l, big_e = m.at_tilt("40 deg"), m.at_tilt("40 deg", "elastica")
    assert big_e.tilt == pytest.approx(math.radians(40), abs=1e-9)
    assert big_e.tension < big_l.tension


def test_critical_load_with_shear_and_reduced_length():
    """Timoshenko & Gere Sec. 2.18 + Eq. (2-46): P = P_e/(1 + P_e/gamma), P_e = pi^2 beta/(4 l^2), with
    beta = beta0 l/L0, gamma = gamma0 l/L0, l = L0 - P/k; solved here by fixed-point iteration."""
    P = 10.0
    for _ in range(200):
        l = L0 - P / K
        Pe = math.pi**2 * BETA0 * l / L0 / (4 * l * l)
        P = Pe / (1 + Pe / (GAMMA0 * l / L0))
    m = CableSpine(spring())
    assert m.critical_load() == pytest.approx(P, rel=1e-8)
    assert 13 < P < 15  # about 14 N, as Shigley's Eq. (10-10) y_cr = 6.55 mm (x k = 14.2 N) says
    head = CableSpine(spring(), weight="11.06 N").linear_state(0.0)
    assert head.buckling_ratio == pytest.approx(11.06 / head.critical_load, rel=1e-12)


def test_tilt_past_buckling_is_a_named_error_with_the_range():
    """A weight above the spine's critical load (about 14.2 N): no tilt is reachable, a named error. With the
    1 kg head an 89 deg tilt is out of reach of the small-deflection model: named error with the range."""
    with pytest.raises(UnreachableTiltError, match="alone buckles the spine"):
        CableSpine(spring(), weight="15 N").at_tilt("10 deg")
    with pytest.raises(UnreachableTiltError, match="reachable: 0 to|stops growing"):
        CableSpine(spring(), weight="11.06 N").at_tilt("89 deg", "linear")


def test_inverse_kinematics_one_cable_in_the_tilt_plane():
    """Eq. (4.7): l_i = |P + R B_i - A_i|. Tilt th about Y (pan 0), top at (y, 0, h), cable 1 at 0 deg:
    B_1 = (y + a cos th, 0, h - a sin th), A_1 = (b, 0, 0)."""
    m = CableSpine(spring(), platform_radius="50 mm", base_radius="60 mm")
    th, y, h = math.radians(20), 0.01, 0.09
    g = m.cable_geometry(f"{math.degrees(th)} deg", "0 deg", f"{y} m", f"{h} m")
    assert g.lengths[0] == pytest.approx(math.hypot(y + 0.05 * math.cos(th) - 0.06, h - 0.05 * math.sin(th)), rel=1e-12)
    up = m.cable_geometry("0 deg")
    assert up.lengths == pytest.approx([math.hypot(0.1, 0.01)] * 3, rel=1e-12)
    assert np.linalg.norm(g.directions, axis=1) == pytest.approx([1, 1, 1])
    R = rotation(0.3, 1.1)
    assert R @ R.T == pytest.approx(np.eye(3), abs=1e-12)


def test_tension_distribution_of_three_cables():
    """Platform of radius a, vertical cables (a = b): a moment M about Y needs r x u with r = (a,0,0),
    u = (0,0,-1): (r x u)_y = a, so cable 1 alone gives M = T a; least-tension solution T1 = M/a, others 0.
    A moment about -Y needs the two cables at 120 and 240 deg: each T = M/(a (1/2 + 1/2)) ... = M/a."""
    a, M = 0.05, 0.2
    angles = np.radians([0, 120, 240])
    arms = np.column_stack([a * np.cos(angles), a * np.sin(angles), np.zeros(3)])
    u = np.tile([0.0, 0.0, -1.0], (3, 1))
    T = tension_distribution(u, arms, np.array([0.0, M, 0.0]))
    assert T == pytest.approx([M / a, 0, 0], abs=1e-9)
    T2 = tension_distribution(u, arms, np.array([0.0, -M, 0.0]))
    assert T2 == pytest.approx([0, M / a, M / a], abs=1e-9)
    with pytest.raises(UnreachableTiltError):
        tension_distribution(u[:2], arms[:2], np.array([0.0, -M, 0.0]))


def test_bad_input_named():
    with pytest.raises(InputError, match="at least 3 cables"):
        CableSpine(spring(), cable_angles=("0 deg", "180 deg"))
    with pytest.raises(InputError, match="pan along a cable"):
        CableSpine(spring()).pulling_cable("60 deg")


@pytest.mark.parametrize("alpha_deg", [30.0, 60.0, 120.0])
def test_elastica_integrator_matches_the_postbuckled_cantilever(alpha_deg):
    """Timoshenko & Gere Sec. 2.7 (the elastica, fixed-free bar under a vertical load P beyond buckling, tip
    slope alpha): k L = K(p), p = sin(alpha/2), k = sqrt(P/EI); tip lateral deflection 2p/k, height of the tip
    (2E(p) - K(p))/k (complete elliptic integrals K, E of modulus p). The shooting on integrate_elastica
    (inextensible, the spine's integrator) must land on that shape."""
    from scipy.optimize import fsolve
    from scipy.special import ellipe, ellipk

    from mechverify.mechanisms.cable_spine import integrate_elastica

    beta, L = BETA0, L0
    p = math.sin(math.radians(alpha_deg) / 2)
    K, Ek = ellipk(p * p), ellipe(p * p)
    k = K / L
    P = k * k * beta
    x_cf, z_cf = 2 * p / k, (2 * Ek - K) / k

    def res(g):
        x, z, _th = integrate_elastica(0.0, -P, 0.0, g[0], g[1], beta, L)
        return [x - g[0], z - g[1]]

    sol = fsolve(res, [x_cf * 1.05, z_cf + 0.02 * L], xtol=1e-13)
    assert max(abs(r) for r in res(sol)) < 1e-10
    x, z, th = integrate_elastica(0.0, -P, 0.0, sol[0], sol[1], beta, L)
    assert th == pytest.approx(math.radians(alpha_deg), rel=1e-6)
    assert x == pytest.approx(x_cf, rel=1e-6)
    assert z == pytest.approx(z_cf, rel=1e-5, abs=1e-9)


def test_cable_spine_checks_substituted():
    """The spine's check lines (issue 25's substituted formulas): P_cr = P_e/(1 + P_e/gamma), P_e = pi^2 beta/(4 l^2)
    and SF = T_rated/T evaluate back (tests/test_reports_substituted.py's parser) to the check's capacity and
    safety factor; past buckling too (P_cr at the critical length). A consistency check, no published number."""
    import importlib.util
    from pathlib import Path

    from mechverify.checks import cable_spine as cc

    spec = importlib.util.spec_from_file_location("_subst", Path(__file__).parent / "test_reports_substituted.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    spine = CableSpine(spring(), weight="1.25 N", name="neck")
    st = spine.at_tilt("20 deg", "elastica")
    results = [cc.check_spine_buckling_ratio(spine, st), cc.check_cable_tension(spine, st, "50 N"),
               cc.check_spine_past_buckling(spine, "test")]
    for r in results:
        mod.assert_substituted(r)
    bad = dataclasses.replace(results[0], substituted=results[0].substituted.replace("^{2}", "", 1))
    with pytest.raises(AssertionError):
        mod.assert_substituted(bad)
