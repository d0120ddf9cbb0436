"""Refinement convergence of frame natural frequencies (mechverify.fea.frame.modal.frame_modes) with point masses.

Consistent-mass Hermite (Euler) elements are a Rayleigh-Ritz method: halving every element nests the trial spaces,
so each frequency must decrease monotonically towards the exact one (Zienkiewicz, Taylor & Zhu, Sec. 16.2; the
Rayleigh-Ritz minimax principle). The shafts session found the opposite on a stepped shaft with short members
(issue 23): the dense solver factored the mass matrix, whose conditioning grows as (1/element length)⁴ for Euler
members (rotational mass ρAL³/105), and the lowest ω² erred by 3e-5, up or down.

Exact reference (not finite elements, not a printed value): the Euler-Bernoulli beam EI w'''' = ρAω² w solved by the
transfer matrix exp(A x) of the first-order system (w, w', EI w'', EI w'''), a point mass m at x = a adding the
jump m ω² w(a) to the shear EI w''' (Timoshenko, Young & Weaver, Vibration Problems in Engineering, 4th ed.,
Sec. 5.3-5.4 for the equation); simply supported ends: w = w'' = 0; the frequency is the root of the 2x2 determinant.
"""

import math

import numpy as np
import pytest
from scipy.linalg import expm
from scipy.optimize import brentq

import mechverify.fea.frame as fe
from mechverify.components import sections
from mechverify.fea.frame.modal import PointMass, frame_modes

E, RHO, D, L = 200e9, 7850.0, 0.02, 1.0  # the database's Structural Steel, a round 20 mm bar of 1 m
MASSES = ((0.25, 2.0), (0.75, 2.0))  # (position [m], mass [kg])


def exact_first(masses=MASSES) -> float:
    """ω1 [rad/s] of the simply supported Euler beam with point masses, by the transfer matrix (hand method)."""
    A, I = math.pi * D**2 / 4, math.pi * D**4 / 64

    def det(w: float) -> float:
        Am = np.array([[0, 1, 0, 0], [0, 0, 1 / (E * I), 0], [0, 0, 0, 1], [RHO * A * w**2, 0, 0, 0]], dtype=float)
        T, x = np.eye(4), 0.0
        for a, m in masses:
            T = expm(Am * (a - x)) @ T
            J = np.eye(4)
            J[3, 0] = m * w**2
            T, x = J @ T, a
        T = expm(Am * (L - x)) @ T
        return float(np.linalg.det(T[np.ix_([0, 2], [1, 3])]))  # w(L) = M(L) = 0 from w'(0), V(0)

    ws = np.linspace(1.0, 400.0, 800)
    vals = [det(w) for w in ws]
    k = next(i for i in range(len(ws) - 1) if vals[i] * vals[i + 1] < 0)
    return brentq(det, ws[k], ws[k + 1], xtol=1e-12)


def beam(theory="euler") -> fe.Frame:
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": [f"{L * 1e3} mm", "0 mm", "0 mm"]}
    sup = [fe.FrameSupport("A", "pinned"), fe.FrameSupport("B", "custom", hold=("y", "z", "rx"))]
    return fe.Frame(nodes, [fe.Member("A", "B", sections.circle(f"{D * 1e3} mm"), "Structural Steel", "beam")], sup,
                    theory=theory)


def omega1(n: int, theory="euler") -> float:
    pm = [PointMass([f"{a * 1e3} mm", "0 mm", "0 mm"], f"{m} kg") for a, m in MASSES]
    res = frame_modes(beam(theory), 1, masses=pm, elements_per_member=n)
    return 2 * math.pi * float(res.frequencies.m[0])


def test_exact_reference_without_masses():
    """The transfer-matrix root without masses is the closed form π² √(EI/(ρA)) / L² (hand calculation)."""
    A, I = math.pi * D**2 / 4, math.pi * D**4 / 64
    assert exact_first(()) == pytest.approx(math.pi**2 * math.sqrt(E * I / (RHO * A)) / L**2, rel=1e-9)


def test_point_masses_converge_monotonically_from_above():
    """Masses at L/4 and 3L/4 of one member: 4, 8, ..., 64 elements per member are uniform, nested meshes."""
    exact = exact_first()
    assert exact == pytest.approx(153.395, abs=1e-3)  # hand method above (the bare beam: 140.4 rad/s)
    w = [omega1(n) for n in (1, 4, 8, 16, 32, 64)]
    assert all(a > b for a, b in zip(w, w[1:], strict=False)), w  # nested meshes: strictly decreasing
    assert all(x > exact for x in w)  # an upper bound
    assert w[-1] == pytest.approx(exact, rel=2e-9)
    errs = [x / exact - 1 for x in w[1:5]]
    assert all(14 < a / b < 17 for a, b in zip(errs, errs[1:], strict=False)), errs  # h⁴ (Hermite element)


def test_stepped_drum_shaft_refinement_is_monotonic():
    """The conveyor drum shaft (examples/conveyor_drum): Euler frame, 5 → 10 → 20 → 40 elements per member
    decrease (they rose by 3e-5 before the fix) and agree with the shaft's own planar Hermite solver
    (mechverify.fea.shafts.modal_critical_speeds: an independent code path, not a published value) to 1e-7."""
    from pathlib import Path

    import mechverify
    from mechverify.fea.shafts import frame_critical_speeds, modal_critical_speeds

    d = mechverify.load(Path(__file__).parents[1] / "examples" / "conveyor_drum" / "design.toml")
    sh = d["drum_shaft"].shaft()
    w = [frame_critical_speeds(sh, 1, theory="euler", elements_per_member=n).first for n in (5, 10, 20, 40)]
    assert all(a >= b * (1 - 2e-9) for a, b in zip(w, w[1:], strict=False)), w
    assert w[2] == pytest.approx(modal_critical_speeds(sh, 1).first, rel=1e-7)


def test_user_shift_solves_like_the_unshifted_path():
    """A user ``shift`` (the modes nearest above a frequency) on the dense path factored M as well (eigh(K - σM, M)):
    on the drum shaft with 40 elements per member it moved ω1 by -8e-5 and split the y/z pair. It now solves
    M φ = θ K φ like the unshifted path: the modes above the shift equal the unshifted ones to 1e-12 (10 elements per
    member), and at 40 the pair agrees with the shaft's own planar solver to 1e-7 (modal_critical_speeds, an
    independent code path; the unshifted path agrees to 8e-9). The simply supported beam's modes above a shift between f1 and f2 are f2, f2, f3, f3 of
    the closed form (nπ/L)² √(EI/(ρA)) / 2π (hand calculation) within 1e-5 at 32 elements."""
    from pathlib import Path

    import mechverify
    from mechverify.fea import shafts as S
    from mechverify.units import Q

    d = mechverify.load(Path(__file__).parents[1] / "examples" / "conveyor_drum" / "design.toml")
    sh = d["drum_shaft"].shaft()
    lm = [(ld.x, ld.mass) for ld in sh.loads if ld.mass > 0]
    fr = S._frame(sh, S._stations(sh, [x for x, _ in lm]), "euler")
    pm = [PointMass(Q([x, 0, 0], "m"), Q(m, "kg")) for x, m in lm]
    w = np.sqrt(frame_modes(fr, 4, masses=pm, elements_per_member=10).omega2)
    ws = np.sqrt(frame_modes(fr, 4, masses=pm, elements_per_member=10, shift=Q(w[0] / 4 / math.pi, "Hz")).omega2)
    assert ws == pytest.approx(w, rel=1e-12)
    ws = np.sqrt(frame_modes(fr, 2, masses=pm, elements_per_member=40, shift=Q(w[0] / 4 / math.pi, "Hz")).omega2)
    assert ws == pytest.approx(S.modal_critical_speeds(sh, 1).first, rel=1e-7)  # the y and z whirl: was -8e-5
    A, I = math.pi * D**2 / 4, math.pi * D**4 / 64
    f = [(k * math.pi / L) ** 2 * math.sqrt(E * I / (RHO * A)) / (2 * math.pi) for k in (1, 2, 3)]
    fs = frame_modes(beam(), 4, elements_per_member=32, shift=f"{(f[0] + f[1]) / 2} Hz").frequencies.m
    assert fs == pytest.approx([f[1], f[1], f[2], f[2]], rel=1e-5)  # f3: 5.2e-6 at 32 elements (h⁴)
    from mechverify.errors import InputError

    with pytest.raises(InputError, match="above the shift"):
        frame_modes(beam(), 4, elements_per_member=2, shift="1e6 Hz")
