"""CalculiX ``*FREQUENCY`` and ``*BUCKLE`` on the same mesh, material, supports and loads as mechverify's
modal and buckling analyses (mechverify.fea.calculix_eigen writes the deck).

Source: CalculiX 2.20 (ccx), run here; both programs solve the same discrete problem (C3D10 = P2 tets,
consistent mass), so the eigenvalues must agree to ccx's printed digits and eigen-solver tolerance.
Measured: frequencies to 5e-7 (modes 1-2) and 1.4e-4 (mode 5: ccx's Lanczos tolerance), buckling
factors to 3e-6.
"""

from __future__ import annotations

import shutil

import pytest

from mechverify.fea import buckling, calculix_eigen, mesh, mesh2d, modal, plane, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane

pytestmark = [pytest.mark.ccx, pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) not installed")]


def _bar(**kw):
    return solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (10, 1, 1)), "Structural Steel",
                            supports=(Fixed(Plane(x="0 mm")),), **kw)


def test_frequencies_match_calculix_solid():
    model = _bar()
    ours = modal.modal(model, 5).frequencies.m
    ccx, _ = calculix_eigen.frequencies(model, 5)
    assert ours == pytest.approx(ccx, rel=5e-4)
    assert ours[:2] == pytest.approx(ccx[:2], rel=5e-6)


def test_frequencies_match_calculix_plane_stress():
    """CPS6: ccx expands plane elements to 3D wedges through the thickness, so plane stress holds only up to a
    (t/h)² effect (measured: 0.38 % at t/h = 0.5); a thin strip (t/h = 0.05) agrees to 5e-4."""
    model = plane.PlaneModel(mesh2d.rectangle(0.2, 0.01, 20, 2), "0.5 mm", "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),))
    ours = modal.modal(model, 3).frequencies.m
    ccx, _ = calculix_eigen.frequencies(model, 3)
    assert ours == pytest.approx(ccx, rel=5e-4)


def test_buckling_factors_match_calculix():
    model = _bar(loads=(Force(Plane(x="200 mm"), ("-1 kN", "0 N", "0 N")),))
    ours = buckling.buckling(model, 2).factors
    ccx, _ = calculix_eigen.buckling_factors(model, 2)
    assert ours == pytest.approx(ccx, rel=2e-5)


def test_lobpcg_frequencies_match_calculix_solid():
    """The LOBPCG path (multigrid-preconditioned, issue 23's large-solid eigensolver) against ccx *FREQUENCY on
    a 20 x 2 x 2 mesh of the same bar: modes 1-2 (a bending pair) to 5e-6, all five to ccx's Lanczos tolerance."""
    model = solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (20, 2, 2)), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),))
    res = modal.modal(model, 5, method="lobpcg")
    assert res.method == "lobpcg"
    ccx, _ = calculix_eigen.frequencies(model, 5)
    assert res.frequencies.m == pytest.approx(ccx, rel=5e-4)
    assert res.frequencies.m[:2] == pytest.approx(ccx[:2], rel=5e-6)
