"""A plate strip in tension (or compression) and bending at once: plate_stress_fea's faces carry sigma = N/t ± 6 M/t²
(task 23e).

Source: Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., 1959, ch. 1 (cylindrical bending of a
plate strip: the strip simply supported on two opposite edges under a uniform load q carries M_x = q x (L - x) / 2 per
unit width, M = q L² / 8 at mid-span) and ch. 4 (sigma = 12 M z / t³, i.e. ±6 M/t² at the faces); the membrane stress
N/t adds to it (linear theory, no P-delta). With Poisson's ratio 0 the strip's free edges carry no anticlastic
moment, so the beam formula holds across the whole width exactly. No printed number: hand calculations from these
formulas. Strip 200 x 50 x 2 mm, q = 10 kPa, nx = ±100 N/mm: M = 10e3 x 0.2² / 8 = 50 N·m/m, 6 M/t² = 75 MPa,
N/t = ±50 MPa: tension + bending 125 MPa on the top face (the convex one under a +z load) and -25 MPa on the bottom;
in compression +25 MPa on the top and -125 MPa on the bottom, which then governs.
"""

import numpy as np
import pytest

from mechverify.checks.plates import check_plate_stress_fea
from mechverify.components import plates as P
from mechverify.fea.plate import solve_plate
from mechverify.fea.plate_buckling import InPlaneLoad
from mechverify.fea.plate_stress import governing_stress, plane_von_mises, surface_stresses
from mechverify.materials.material import Material
from mechverify.units import Q

MAT = Material("steel, nu = 0", "metal", E=Q(200, "GPa"), nu=Q(0.0, ""), yield_strength=Q(500, "MPa"))
L, T, q = 0.2, 0.002, 10e3
M = q * L**2 / 8
SB = 6 * M / T**2


def _model() -> P.PlateModel:
    plate = P.Plate.rectangle("200 mm", "50 mm", "2 mm", MAT)
    return P.PlateModel(plate, (P.EdgeSupport((1, 3), "simply_supported"),), (P.PressureLoad(Q(q, "Pa")),))


def test_hand_values():
    assert M == pytest.approx(50.0) and SB == pytest.approx(75e6)
    top, bottom = surface_stresses(np.array([50e6, 0, 0]), np.array([SB, 0, 0]))
    assert top[0] == pytest.approx(125e6) and bottom[0] == pytest.approx(-25e6)
    assert plane_von_mises(np.array([100.0, -100.0, 0.0])) == pytest.approx(100 * np.sqrt(3))  # pure shear


@pytest.mark.parametrize("membrane", ["given", "solve"])
@pytest.mark.parametrize(("n", "face", "top", "bottom"), [(100e3, "top", 125e6, -25e6), (-100e3, "bottom", 25e6, -125e6)])
def test_strip_tension_or_compression_plus_bending(membrane, n, face, top, bottom):
    """Mid-span faces against the hand values, the bending part within 0.05 % (2.5 mm mesh; measured 0.023 %; the membrane field given or solved in plane
    stress, which is exact for a uniform field); the governing face and the check's demand follow."""
    res = solve_plate(_model(), "2.5 mm", None, InPlaneLoad(nx=Q(n, "N/m")), membrane=membrane)
    ex = res.extra
    mid = np.isclose(res.points[:, 0], L / 2)
    m, b = ex["membrane_xx_Pa"][mid], ex["bending_xx_Pa"][mid]
    assert m == pytest.approx(np.full(m.shape, n / T), rel=1e-9)
    assert b + m == pytest.approx(np.full(m.shape, top), rel=0, abs=5e-4 * SB)  # the bending part within 0.05 %
    assert m - b == pytest.approx(np.full(m.shape, bottom), rel=0, abs=5e-4 * SB)
    g = governing_stress(res)
    assert g.face == face and g.point[0] == pytest.approx(L / 2, abs=2.6e-3)
    assert g.von_mises == pytest.approx(125e6, rel=5e-4)
    assert g.membrane[0] == pytest.approx(n / T) and abs(g.bending[0]) == pytest.approx(SB, rel=5e-4)
    r = check_plate_stress_fea(_model(), res)
    assert r.demand.m_as("MPa") == pytest.approx(125.0, rel=5e-4) and r.details["face"] == face
    assert r.details["membrane_stress"].m_as("MPa")[0] == pytest.approx(n / T / 1e6)


def test_without_in_plane_the_faces_are_opposite():
    """No in-plane load: the top face governs on a tie, bottom = -top (the bending-only result of before)."""
    res = solve_plate(_model(), "5 mm")
    assert np.all(res.extra["face_sign"] == 1.0)
    assert res.extra["von_mises_top_Pa"] == pytest.approx(res.extra["von_mises_bottom_Pa"], rel=1e-12)
    assert not np.any(res.extra["membrane_xx_Pa"])
    assert res.max_von_mises.value.m_as("MPa") == pytest.approx(75.0, rel=2e-3)
