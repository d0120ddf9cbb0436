"""A beam on two bolt-hole pins (the rotation-free ``PinSupport``, :mod:`mechverify.fea.pins`) against beam theory.

The model: review 3's finding 16 beam - 300 x 20 x 10 mm steel (E = 200 GPa, nu = 0.3, rho = 7850 kg/m³, the
materials database's "Structural Steel"), 6 mm holes at x = 10 and 290 mm on the neutral axis (y = 10 mm), so the
span between the pin axes is L = 280 mm; bending in y about z: I = 10 * 20³ / 12 = 6666.7 mm⁴, c = 10 mm,
A = 200 mm². 1000 N down on the top face over 140 <= x <= 160 mm.

Sources and what is printed where:
- Pinned-pinned, centre load: y_max = P L³ / (48 E I) - Budynas & Nisbett, Shigley's Mechanical Engineering Design,
  10th ed., Table A-9 case 5 (the closed form; checked against a numerical beam solution in
  ``test_shigley_beam_deflections.py``). Hand calculation: 1000 * 280³ / (48 * 200000 * 6666.7) = 0.3430 mm.
  Before the pin support existed the holes could only be held whole, which clamps the section: 0.136 mm, near the
  clamped-clamped P L³ / (192 E I) = 0.086 mm (Table A-9 case 14; review 3).
- Shear deflection (Timoshenko beam): P L / (4 kappa G A) with kappa = 5/6 for a rectangle (the classical value;
  Cowper 1966 gives 10(1 + nu)/(12 + 11 nu) = 0.850 for nu = 0.3, 2 % from 5/6 and 0.01 % of the total here):
  1000 * 280 / (4 * 0.8333 * 76923 * 200) = 0.00546 mm - hand calculation, not a printed value. Total 0.3485 mm.
- Mid-span moment under a load spread over w = 20 mm: M = P L / 4 - P w / 8 = 67 500 N mm, bottom fibre
  sigma = M c / I = 101.25 MPa (hand calculation from statics; P L / 4 * c / I = 105 MPa for a point load).
- Reactions: P / 2 = 500 N at each pin (statics).
- First in-plane bending frequency, pinned-pinned Euler-Bernoulli: f = (pi / (2 L²)) sqrt(E I / (rho A)) =
  583.9 Hz (the mode sin(pi x / L), exact for the Euler-Bernoulli beam; hand calculation). Timoshenko's first-order
  correction for rotary inertia and shear, f / f_EB = 1 - (pi r / L)² (1 + E / (kappa G)) / 2 with r² = I / A, is
  -0.86 % (hand calculation, not a printed value): 578.9 Hz. The pin axes are the hole centres; the 10 mm ends
  beyond them add a little mass (neglected).
- Euler column, pinned at a hole (the pin's axis along z) and held across at the far end face (free to turn):
  P_cr = pi² E I / L², L = 290 mm from the pin axis to the loaded end (Shigley 10th ed. Eq. 4-42, case pinned-pinned,
  C = 1; hand calculation).
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.fea import buckling, mesh, modal, solid
from mechverify.fea.loads import Fixed, Force, PinSupport, Restraint
from mechverify.fea.regions import Box, Named
from mechverify.units import Q

E, NU, RHO = 200e9, 0.3, 7850.0
L, B, H = 0.280, 0.010, 0.020
I = B * H**3 / 12
A = B * H
P = 1000.0
KAPPA = 5 / 6
G = E / (2 * (1 + NU))


@pytest.fixture(scope="module")
def beam_mesh():
    pytest.importorskip("gmsh")
    return mesh.block_with_holes((Q(300, "mm"), Q(20, "mm"), Q(10, "mm")),
                                 [((Q(10, "mm"), Q(10, "mm")), "6 mm"), ((Q(290, "mm"), Q(10, "mm")), "6 mm")], "5 mm")


def _load():
    return (Force(Box(("140 mm", "19 mm", "-1 mm"), ("160 mm", "21 mm", "11 mm")), ("0 N", "-1000 N", "0 N")),)


def _pinned(beam_mesh, loads=()):
    return solid.SolidModel(beam_mesh, "Structural Steel", supports=(PinSupport(Named("hole0"), axial=True),
                                                                     PinSupport(Named("hole1"))), loads=loads)


@pytest.fixture(scope="module")
def pinned(beam_mesh):
    return _pinned(beam_mesh, _load()).solve(method="direct")


def _at(res, x, y, z):
    return int(np.argmin(np.linalg.norm(res.points - np.array([x, y, z]), axis=1)))


def test_hand_values():
    """The hand calculations of the module docstring, from their formulas."""
    assert P * L**3 / (48 * E * I) * 1e3 == pytest.approx(0.3430, abs=1e-4)
    assert P * L / (4 * KAPPA * G * A) * 1e3 == pytest.approx(0.00546, abs=1e-5)
    assert (P * L / 4 - P * 0.020 / 8) * (H / 2) / I / 1e6 == pytest.approx(101.25)
    assert np.pi / (2 * L**2) * np.sqrt(E * I / (RHO * A)) == pytest.approx(583.9, abs=0.1)


def test_pinned_beam_deflects_as_pinned_pinned(pinned):
    """Mid-span deflection on the neutral axis within 1.5 % of P L³/48EI + P L/(4 kappa G A) = 0.3485 mm (measured
    0.3470 mm at mesh_size 5 mm, -0.4 %); a clamped section would give 0.136 mm."""
    expected = P * L**3 / (48 * E * I) + P * L / (4 * KAPPA * G * A)
    uy = pinned.u[_at(pinned, 0.150, 0.010, 0.005), 1]
    assert -uy == pytest.approx(expected, rel=0.015)


def test_pinned_beam_stress_is_the_beam_stress_at_mid_span(pinned):
    """Bottom fibre at mid-span sigma_xx within 3 % of M c / I = 101.25 MPa; the peak von Mises lies at mid-span, not
    at a hole (a clamped hole wall put 154 MPa there, review 3)."""
    bottom = (np.abs(pinned.points[:, 0] - 0.150) < 0.003) & (pinned.points[:, 1] < 1e-9)
    sxx = pinned.sigma[bottom, 0, 0]
    assert np.max(sxx) / 1e6 == pytest.approx(101.25, rel=0.03)
    vm = pinned.von_mises.m_as("Pa")
    peak = pinned.points[np.argmax(vm)]
    assert 0.12 < peak[0] < 0.18
    assert vm.max() / 1e6 == pytest.approx(101.25, rel=0.05)


def test_pin_reactions_are_half_the_load_each(pinned):
    """P/2 = 500 N in y at each pin (statics, within 0.5 %); the pin without axial hold takes no z force, and the
    pins on the neutral axis take almost no axial force (|Rx| < 2 % of P: both pins hold across, the span cannot
    lengthen freely, but the holes sit on the neutral axis)."""
    (p0,) = [r for r in pinned.regions if r.item.startswith("PinSupport 1")]
    (p1,) = [r for r in pinned.regions if r.item.startswith("PinSupport 2")]
    assert p0.resultant[1] == pytest.approx(P / 2, rel=5e-3)
    assert p1.resultant[1] == pytest.approx(P / 2, rel=5e-3)
    assert p0.resultant[1] + p1.resultant[1] == pytest.approx(P, rel=1e-9)
    assert abs(p1.resultant[2]) < 1e-6 * P
    assert abs(p0.resultant[0]) < 0.02 * P
    assert p0.count > 0 and p1.count > 0  # held nodes of each wall


def test_multigrid_cg_gives_the_direct_answer(beam_mesh, pinned):
    """The AMG-CG path (rotated stiffness, rotated P1 coarse space) converges to the direct solve's displacements."""
    res = _pinned(beam_mesh, _load()).solve(method="amg")
    assert res.info.method.startswith("amg") and res.info.iterations > 0
    np.testing.assert_allclose(res.u, pinned.u, atol=1e-7 * np.abs(pinned.u).max())


def test_holding_the_wall_clamps_where_the_pin_does_not(beam_mesh, pinned):
    """The same beam with the walls held whole (Fixed): between the clamped-clamped 0.086 mm and half the pinned
    0.343 mm (review 3: 0.136 mm), far stiffer than the pinned beam."""
    clamped = solid.SolidModel(beam_mesh, "Structural Steel", supports=(Fixed(Named("hole0")), Fixed(Named("hole1"))),
                               loads=_load()).solve()
    i = _at(pinned, 0.150, 0.010, 0.005)
    assert P * L**3 / (192 * E * I) < -clamped.u[i, 1] < 0.5 * P * L**3 / (48 * E * I)
    assert -pinned.u[i, 1] > 2 * -clamped.u[i, 1]


def test_pinned_beam_first_in_plane_frequency(beam_mesh):
    """The in-plane bending mode (the one with the y effective mass) within 1.5 % of Euler-Bernoulli's 583.9 Hz
    and 0.5 % of Timoshenko's first-order 578.9 Hz (measured 578.8 Hz at mesh_size 5 mm); the mode shapes come back
    in x, y, z (the mode's y effective mass is most of the beam's)."""
    res = modal.modal(_pinned(beam_mesh), 3)
    k = int(np.argmax(res.effective_mass[:, 1]))
    f_eb = np.pi / (2 * L**2) * np.sqrt(E * I / (RHO * A))
    f_t = f_eb * (1 - 0.5 * (np.pi / L) ** 2 * (I / A) * (1 + E / (KAPPA * G)))
    assert f_t == pytest.approx(578.9, abs=0.1)
    f = res.frequencies.m_as("Hz")[k]
    assert f == pytest.approx(f_eb, rel=0.015)
    assert f == pytest.approx(f_t, rel=0.005)
    assert res.effective_mass_fraction()[k, 1] > 0.7
    assert np.abs(res.shapes[k, :, 1]).max() > 10 * np.abs(res.shapes[k, :, 2]).max()


def test_column_on_a_pin_buckles_at_euler_pinned_pinned():
    """300 x 10 x 20 mm column (I = 20 * 10³/12 = 1666.7 mm⁴ about the pin's axis z), a 4 mm pin hole at x = 10 mm
    (axial = true), the end face x = 300 mm held in y and z only: pi² E I / L² with L = 290 mm is 39.12 kN, factor
    39.12 for 1 kN (within 1 %; measured 39.09). The mode bends in y, about the pin."""
    pytest.importorskip("gmsh")
    m = mesh.block_with_holes((Q(300, "mm"), Q(10, "mm"), Q(20, "mm")), [((Q(10, "mm"), Q(5, "mm")), "4 mm")], "5 mm")
    col = solid.SolidModel(m, "Structural Steel", supports=(PinSupport(Named("hole0"), axial=True),
                                                            Restraint(Named("xmax"), y=True, z=True)),
                           loads=(Force(Named("xmax"), ("-1000 N", "0 N", "0 N")),))
    res = buckling.buckling(col, 1)
    euler = np.pi**2 * E * (0.020 * 0.010**3 / 12) / 0.290**2 / P
    assert euler == pytest.approx(39.12, abs=0.01)
    assert res.first_factor == pytest.approx(euler, rel=0.01)
    shape = np.abs(res.shapes[0]).max(axis=0)
    assert shape[1] == pytest.approx(1.0) and shape[2] < 0.05
