"""Cross-check of the plane model against CalculiX 2.20 (ccx) CPE6 / CPS6 elements on the identical mesh.

Source: G. Dhondt, CalculiX CrunchiX User's Manual 2.20, sec. 6.2.3 (CPS6) and 6.2.5 (CPE6): ccx
expands each 6-node triangle into a 15-node wedge of the given thickness and solves it in 3D. For
plane strain (z held) that is the same discrete problem: displacements agree to solver/output
precision (1e-5). For plane stress the wedge layer is a genuine 3D plate whose faces are free,
so it differs from the plane-stress idealisation by a through-thickness effect that vanishes as
(t/L)^2: measured 0.22 % at t = 5 mm, 0.013 % at 1 mm, 0.0035 % at 0.2 mm on a 100 x 20 mm strip;
the test uses 0.2 mm and 1e-4. A gmsh mesh with a hole checks the counter-clockwise orientation
(ccx stops on "nonpositive jacobian" for a clockwise triangle).
"""

import shutil

import numpy as np
import pytest
from shapely.geometry import Point
from shapely.geometry import box as shapely_box

from mechverify.fea import calculix, mesh2d
from mechverify.fea.loads import Fixed, Force, Pressure, Restraint
from mechverify.fea.plane import PlaneModel, mesh_region
from mechverify.fea.regions import Box, Plane

pytestmark = [pytest.mark.ccx, pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) not installed")]


def strip_model(plane, thickness):
    m = mesh2d.rectangle(0.1, 0.02, 10, 4)  # nodes at x = 30 and 70 mm: the pressure edge is whole
    return PlaneModel(m, thickness, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                      loads=(Force(Plane(x="100 mm"), ("20 N", "-50 N")),
                             Pressure(Box(("30 mm", "20 mm"), ("70 mm", "20 mm")), "1 MPa")), plane=plane)


@pytest.mark.parametrize(("plane", "thickness", "tol"), [("strain", "5 mm", 1e-5), ("stress", "0.2 mm", 1e-4)])
def test_plane_model_matches_ccx_on_the_same_mesh(plane, thickness, tol):
    model = strip_model(plane, thickness)
    res = model.solve()
    ccx = calculix.run_model(model, ip_stress=True)
    assert np.abs(ccx.displacement[:, :2] - res.u[:, :2]).max() <= tol * np.abs(res.u).max()
    # the supports carry the applied load (read from ccx's .dat): 20 N, -50 N - 1 MPa x 40 mm x t
    t = float(thickness.split()[0]) * 1e-3
    assert ccx.support_force[:2] == pytest.approx([-20.0, 50.0 + 1e6 * 0.04 * t], rel=1e-5)


def test_plate_with_hole_gmsh_mesh_runs_in_ccx():
    shape = shapely_box(0, 0, 0.1, 0.04).difference(Point(0.05, 0.02).buffer(0.008, 32))
    m = mesh_region(shape, "5 mm")
    model = PlaneModel(m, "1 mm", "Structural Steel", supports=(Restraint(Plane(x="0 m"), x=True),
                                                                 Restraint(Box(("0 m", "0 m"), ("0 m", "0 m")), y=True)),
                       loads=(Force(Plane(x="100 mm"), ("400 N", "0 N")),), plane="strain")
    res = model.solve()
    ccx = calculix.run_model(model)
    assert np.abs(ccx.displacement[:, :2] - res.u[:, :2]).max() <= 1e-5 * np.abs(res.u).max()
