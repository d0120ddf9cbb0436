"""Frame natural frequencies and buckling loads (mechverify.fea.frame.modal) against closed forms.

Sources (formulas; every number below is a hand calculation from them, not a printed value):
1. Euler-Bernoulli beam: f_n = (β_n L)² / (2π L²) √(EI/(ρA)); cantilever: cos βL cosh βL = -1; simply
   supported: β_n L = nπ (S. Timoshenko, D. H. Young, W. Weaver, *Vibration Problems in Engineering*, 4th ed.,
   Wiley 1974, Sec. 5.3-5.4; the same in Blevins, *Formulas for Natural Frequency and Mode Shape*, Table 8-1,
   not seen here). The roots β_n L are found below by root bracketing (1.8751, 4.6941, 7.8548).
2. Timoshenko beam, simply supported (S. P. Timoshenko, Phil. Mag. 41 (1921) 744): with w = W sin kx,
   θ = Θ cos kx, k = nπ/L: (κGA k² - ρA ω²)(EI k² + κGA - ρI ω²) - (κGA k)² = 0; the lower root.
3. Timoshenko beam, cantilever: the exact solution of the same equations (EI θ')' + κGA(w' - θ) + ρI ω² θ = 0,
   (κGA(w' - θ))' + ρA ω² w = 0 by the transfer matrix exp(A L) of the first-order system (no finite elements):
   the frequencies are the roots of det(T[2:4, 2:4]) for w(0) = θ(0) = 0, M(L) = Q(L) = 0; a tip mass m and
   tip rotary inertia J change the end conditions to Q(L) = m ω² w(L), M(L) = J ω² θ(L) (natural conditions
   of the Lagrangian).
4. S. P. Timoshenko, J. M. Gere, *Theory of Elastic Stability*, 2nd ed., McGraw-Hill 1961, Sec. 2.1
   (P_cr = π² EI / (4 L²) fixed-free, π² EI / L² pinned-pinned) and Sec. 2.17 (shear: P_cr = P_e / (1 + P_e / (κ G A))).
"""

import math

import numpy as np
import pytest
from scipy.linalg import expm
from scipy.optimize import brentq

import mechverify.fea.frame as frame_pkg
from mechverify.components import sections
from mechverify.errors import InputError, ModelError
from mechverify.fea.frame import Frame, Member
from mechverify.fea.frame.element import local_stiffness
from mechverify.fea.frame.modal import PointMass, bending_shapes, element_mass, frame_buckling, frame_modes
from mechverify.materials.database import get

PointLoad = frame_pkg.FramePointLoad
Support = frame_pkg.FrameSupport
STEEL = get("Structural Steel")
E, G, RHO = 200e9, 200e9 / 2.6, 7850.0


def beam(section, L_mm, supports, theory="euler", **kw):
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": [f"{L_mm} mm", "0 mm", "0 mm"]}
    return Frame(nodes, [Member("A", "B", section, STEEL, "beam")], supports, theory=theory, **kw)


def nearest(values, x):
    values = np.asarray(values)
    return float(values[np.argmin(np.abs(values - x))])


def cantilever_roots(n):
    f = lambda x: math.cos(x) * math.cosh(x) + 1  # noqa: E731
    return [brentq(f, (k + 0.2) * math.pi, (k + 0.8) * math.pi) for k in range(n)]


def test_material_values():
    """The hand calculations use E = 200 GPa, ν = 0.3, ρ = 7850 kg/m³ of the database's Structural Steel."""
    assert STEEL.E.m_as("Pa") == pytest.approx(E)
    assert STEEL.G.m_as("Pa") == pytest.approx(G)
    assert STEEL.density.m_as("kg/m**3") == pytest.approx(RHO)


def test_euler_cantilever_first_three_frequencies():
    """Round 20 mm x 500 mm cantilever, Euler-Bernoulli (ref. 1): f_n = (β_n L)²/(2πL²) √(EI/ρA); 10 elements."""
    d, L = 0.020, 0.5
    I, A = math.pi * d**4 / 64, math.pi * d**2 / 4
    bl = cantilever_roots(3)
    assert bl[0] == pytest.approx(1.8751, abs=1e-4)  # the root itself (ref. 1 quotes 1.875)
    hand = [b**2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A)) for b in bl]  # 56.49, 354.03, 991.3 Hz
    res = frame_modes(beam(sections.circle("20 mm"), 500, [Support("A", "fixed")]), 8, elements_per_member=20)
    f = res.frequencies.m_as("Hz")
    bending = f[np.array([0, 2, 4])]  # each bending mode twice (y and z: round section)
    assert f[1] == pytest.approx(f[0], rel=1e-9)
    assert bending == pytest.approx(hand, rel=2e-4)
    # the first mode's effective mass: 61.3 % of the beam's (ref. 1: the cantilever's first-mode participation)
    frac = res.effective_mass_fraction()
    assert frac[0, 1] + frac[0, 2] == pytest.approx(0.613, abs=0.003)


def test_euler_simply_supported_frequencies():
    """Simply supported 20x10 mm bar, 400 mm (bending about the weak axis): f_n = (nπ)²/(2πL²)√(EI/ρA) (ref. 1)."""
    b, h, L = 0.020, 0.010, 0.4
    A, I = b * h, b * h**3 / 12
    sec = sections.rectangle("20 mm", "10 mm")  # width along local y, height along local z: bending about y uses Iy
    assert sec.si()["Iy"] == pytest.approx(I)
    fr = beam(sec, 400, [Support("A", "pinned"), Support("B", "custom", hold=("y", "z", "rx"))])
    res = frame_modes(fr, 4)
    hand = [(n * math.pi) ** 2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A)) for n in (1, 2, 3)]
    f = res.frequencies.m_as("Hz")
    assert f[0] == pytest.approx(hand[0], rel=1e-5)  # 142.5 Hz
    assert nearest(f, hand[1]) == pytest.approx(hand[1], rel=2e-4)


def timoshenko_ss(n, L, EI, kGA, rhoA, rhoI):
    """Lower root ω of (κGA k² - ρAω²)(EI k² + κGA - ρIω²) - (κGA k)² = 0 (ref. 2)."""
    k = n * math.pi / L
    a = rhoA * rhoI
    b = -(rhoA * (EI * k**2 + kGA) + rhoI * kGA * k**2)
    c = kGA * k**2 * (EI * k**2 + kGA) - (kGA * k) ** 2
    return math.sqrt((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a))


def test_timoshenko_simply_supported_deep_beam():
    """Square 20 mm bar, 100 mm span (L/h = 5): the Timoshenko frequency (ref. 2, κ = 5/6 of the section's shear
    area) is 6.0 % below Euler-Bernoulli's; the element with rotary inertia and shear follows ref. 2."""
    a, L = 0.020, 0.1
    sec = sections.rectangle("20 mm", "20 mm")
    s = sec.si()
    A, I, As = a * a, a**4 / 12, s["Asz"]
    assert As == pytest.approx(5 / 6 * A, rel=1e-9)
    fr = beam(sec, 100, [Support("A", "pinned"), Support("B", "custom", hold=("y", "z", "rx"))], theory="timoshenko")
    f = frame_modes(fr, 2, elements_per_member=20).frequencies.m_as("Hz")
    hand = timoshenko_ss(1, L, E * I, G * As, RHO * A, RHO * I) / (2 * math.pi)
    euler = math.pi**2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A))
    assert hand / euler < 0.95  # 0.940 (hand calculation)
    assert f[0] == pytest.approx(hand, rel=2e-4)
    assert f[1] == pytest.approx(hand, rel=2e-4)


def timoshenko_transfer(omega, L, EI, kGA, rhoA, rhoI):
    """Transfer matrix of y = (w, θ, M, Q): w' = θ + Q/κGA, θ' = M/EI, M' = -Q - ρIω²θ, Q' = -ρAω²w (ref. 3)."""
    A = np.array([[0, 1, 0, 1 / kGA], [0, 0, 1 / EI, 0], [0, -rhoI * omega**2, 0, -1], [-rhoA * omega**2, 0, 0, 0]])
    return expm(A * L)


def cantilever_exact(L, EI, kGA, rhoA, rhoI, n, tip_mass=0.0, tip_J=0.0, f_max=10000.0, points=800):
    def det(f):
        w = 2 * math.pi * f
        T = timoshenko_transfer(w, L, EI, kGA, rhoA, rhoI)
        # y(L) = T[:, 2:4] (M0, Q0); end conditions M(L) - J ω² θ(L) = 0, Q(L) - m ω² w(L) = 0
        B = np.array([T[2, 2:4] - tip_J * w**2 * T[1, 2:4], T[3, 2:4] - tip_mass * w**2 * T[0, 2:4]])
        return np.linalg.det(B)
    grid = np.linspace(1.0, f_max, points)
    vals = [det(f) for f in grid]
    roots = [brentq(det, grid[i], grid[i + 1], xtol=1e-10) for i in range(len(grid) - 1)
             if np.sign(vals[i]) != np.sign(vals[i + 1])]
    return roots[:n]


def test_timoshenko_cantilever_against_the_exact_solution():
    """Square 20 mm cantilever of 120 mm (L/h = 6), Timoshenko with rotary inertia: first two bending frequencies
    against the exact solution of the beam equations (ref. 3, transfer matrix; no finite elements)."""
    a, L = 0.020, 0.12
    A, I = a * a, a**4 / 12
    sec = sections.rectangle("20 mm", "20 mm")
    As = sec.si()["Asz"]
    exact = cantilever_exact(L, E * I, G * As, RHO * A, RHO * I, 2)
    euler = cantilever_roots(1)[0] ** 2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A))
    assert exact[0] < 0.99 * euler  # shear and rotary inertia lower it by > 1 %
    fr = beam(sec, 120, [Support("A", "fixed")], theory="timoshenko")
    f = frame_modes(fr, 6, elements_per_member=20).frequencies.m_as("Hz")
    bending = sorted(f)[0::2][:3]  # pairs (y, z); the torsion mode lies between
    assert f[0] == pytest.approx(exact[0], rel=2e-4)
    assert nearest(f, exact[1]) == pytest.approx(exact[1], rel=5e-4)
    assert bending[0] == pytest.approx(exact[0], rel=2e-4)


def test_cantilever_with_a_tip_disc():
    """Round 20 mm, 300 mm cantilever, Euler-Bernoulli, with a 2 kg disc at the tip (J = 0.001 kg m² about
    the bending axes): the exact solution with the tip mass and inertia as end conditions (ref. 3, κGA → ∞,
    ρI = 0)."""
    d, L = 0.020, 0.3
    A, I = math.pi * d**2 / 4, math.pi * d**4 / 64
    exact = cantilever_exact(L, E * I, 1e20, RHO * A, 0.0, 2, tip_mass=2.0, tip_J=1e-3, f_max=1500.0, points=300)
    fr = beam(sections.circle("20 mm"), 300, [Support("A", "fixed")])
    res = frame_modes(fr, 4, masses=[PointMass("B", "2 kg", ["0.002 kg*m**2", "0.001 kg*m**2", "0.001 kg*m**2"])])
    f = res.frequencies.m_as("Hz")
    assert f[0] == pytest.approx(exact[0], rel=1e-4)
    assert nearest(f, exact[1]) == pytest.approx(exact[1], rel=1e-3)  # f[2] is the disc's torsion mode
    assert res.critical_speeds.m_as("rpm")[0] == pytest.approx(60 * exact[0], rel=1e-4)


def test_free_free_frame_has_six_rigid_modes_then_the_free_beam():
    """No supports: six rigid-body modes at zero, then the free-free beam's β L = 4.7300 (cos βL cosh βL = 1, ref. 1)."""
    d, L = 0.020, 0.5
    I, A = math.pi * d**4 / 64, math.pi * d**2 / 4
    res = frame_modes(beam(sections.circle("20 mm"), 500, []), 8)
    assert res.rigid_body_modes == 6
    bl = brentq(lambda x: math.cos(x) * math.cosh(x) - 1, 4.5, 5.0)
    hand = bl**2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A))
    assert res.first_frequency.m_as("Hz") == pytest.approx(hand, rel=2e-4)


def test_euler_columns():
    """Round 20 mm column, 500 mm: fixed-free P = π²EI/(4L²) and pinned-pinned π²EI/L² (ref. 4, Sec. 2.1) under 1 kN."""
    d, L = 0.020, 0.5
    I = math.pi * d**4 / 64
    load = [PointLoad("B", force=["-1 kN", "0 N", "0 N"])]
    fixed_free = frame_buckling(beam(sections.circle("20 mm"), 500, [Support("A", "fixed")]), load, 2)
    assert fixed_free.first_factor == pytest.approx(math.pi**2 * E * I / (4 * L**2) / 1000, rel=1e-5)  # 15.50
    pp = beam(sections.circle("20 mm"), 500, [Support("A", "pinned"), Support("B", "custom", hold=("y", "z", "rx"))])
    assert frame_buckling(pp, load).first_factor == pytest.approx(math.pi**2 * E * I / L**2 / 1000, rel=3e-5)


def test_shear_flexible_column():
    """Square 20 mm pinned column of 100 mm (L/h = 5), Timoshenko: P = P_e/(1 + P_e/(κGA)) (ref. 4, Sec. 2.17):
    9.3 % below Euler's load."""
    a, L = 0.020, 0.1
    I = a**4 / 12
    sec = sections.rectangle("20 mm", "20 mm")
    As = sec.si()["Asz"]
    Pe = math.pi**2 * E * I / L**2
    hand = Pe / (1 + Pe / (G * As))
    fr = beam(sec, 100, [Support("A", "pinned"), Support("B", "custom", hold=("y", "z", "rx"))], theory="timoshenko")
    res = frame_buckling(fr, [PointLoad("B", force=["-1 N", "0 N", "0 N"])], elements_per_member=20)
    assert res.first_factor == pytest.approx(hand, rel=3e-4)
    assert res.first_factor < 0.92 * Pe


def test_element_matrices_against_the_printed_forms():
    """With Φ = 0 the translational mass is ρAL/420 [156, 22L, 54, -13L; 22L, 4L², 13L, -3L²; ...] (Przemieniecki,
    Eq. 11.41); the shape functions' strain energy reproduces the element's exact Timoshenko stiffness."""
    L = 0.3
    m = element_mass(L, 1.0, 1.0, 0.0, 0.0, rotary=False)
    idx = [1, 5, 7, 11]
    printed = np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                        [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L**2, -22 * L, 4 * L**2]]) * L / 420
    assert m[np.ix_(idx, idx)] == pytest.approx(printed, rel=1e-12, abs=1e-15)
    EI, GAs = 2.0e3, 5.0e5
    phi = 12 * EI / (GAs * L**2)
    x, w = np.polynomial.legendre.leggauss(6)
    x, w = (x + 1) / 2, w / 2
    Nv, dNv, Nt = bending_shapes(L, phi, x)
    dNt = np.gradient(Nt, axis=1)  # not used for accuracy: exact derivative below
    del dNt
    c = 1 / (1 + phi)
    dNt = c * np.array([6 * (2 * x - 1) / L, 6 * x - (4 + phi), -6 * (2 * x - 1) / L, 6 * x - (2 - phi)]) / L
    gam = dNv - Nt
    k = L * (EI * np.einsum("aq,bq,q->ab", dNt, dNt, w) + GAs * np.einsum("aq,bq,q->ab", gam, gam, w))
    ref = local_stiffness(L, 1.0, 1.0, 1.0, 1.0, EI, 1.0, GAs, GAs)[np.ix_(idx, idx)]
    assert k == pytest.approx(ref, rel=1e-10)


def test_bad_requests():
    """Too many modes, no density, a mechanism: named errors."""
    fr = beam(sections.circle("20 mm"), 500, [Support("A", "fixed")])
    with pytest.raises(InputError, match="free unknowns"):
        frame_modes(fr, 100, elements_per_member=1)
    with pytest.raises(InputError, match="at least one"):
        frame_modes(fr, 0)
    with pytest.raises(ModelError, match="not fully supported"):
        frame_modes(beam(sections.circle("20 mm"), 500, [Support("A", "pinned")]), 2)
    with pytest.raises(ModelError, match="compression"):
        frame_buckling(fr, [PointLoad("B", force=["1 kN", "0 N", "0 N"])])
    with pytest.raises(InputError, match="PointMass"):
        frame_modes(fr, 2, masses=["2 kg"])


def test_vtu_export(tmp_path):
    """Every mode is written (translations and rotations) on line cells."""
    res = frame_modes(beam(sections.circle("20 mm"), 500, [Support("A", "fixed")]), 3)
    p = res.to_vtu(tmp_path / "modes.vtu")
    text = p.read_text()
    assert text.count("mode_") == 3 and "rot_3" in text


def test_frame_methods_and_package_exports():
    """Frame.modes / Frame.buckling delegate to frame_modes / frame_buckling (exported by mechverify.fea.frame)."""
    fr = beam(sections.circle("20 mm"), 500, [Support("A", "fixed")])
    assert frame_pkg.frame_modes is frame_modes and frame_pkg.PointMass is PointMass
    assert fr.modes(2).frequencies.m == pytest.approx(frame_modes(fr, 2).frequencies.m, rel=1e-12)
    load = [PointLoad("B", force=["-1 kN", "0 N", "0 N"])]
    assert fr.buckling(load).first_factor == pytest.approx(frame_buckling(fr, load).first_factor, rel=1e-12)
