"""A load that falls wholly on held nodes goes straight into the supports (review finding 20, session 3: a
force on the supported face, or a support box catching the loaded face by a unit slip, gave 0 MPa and 0 mm
and a silent PASS; with buckling on, an internal ArpackError). Every such load is named in the results'
warnings; when it is every load, the solve is a ModelError."""

import numpy as np
import pytest

from mechverify.errors import ModelError
from mechverify.fea import buckling, mesh, mesh2d
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.plane import PlaneModel
from mechverify.fea.regions import Plane
from mechverify.fea.solid import SolidModel

BOX = mesh.box(("100 mm", "10 mm", "10 mm"), (10, 1, 1))


def test_solid_every_load_on_held_nodes_is_an_error():
    model = SolidModel(BOX, "Structural Steel", supports=(Fixed(Plane(x="0 mm")), Fixed(Plane(x="100 mm"))),
                       loads=(Force(Plane(x="100 mm"), ("0 N", "0 N", "-50 N")),))
    with pytest.raises(ModelError, match=r"every load acts only on held nodes.*load 0 \(force on"):
        model.solve()
    with pytest.raises(ModelError, match="every load acts only on held nodes"):  # not ARPACK's "zero vector"
        buckling.buckling(model, 1)


def test_solid_one_load_on_held_nodes_is_named_and_the_other_solved():
    """Tip load P = 50 N on a 100 x 10 x 10 mm steel cantilever beside a load on the clamped face: the tip
    deflection is the cantilever's alone, P L^3 / 3 E I = 50 * 0.1^3 / (3 * 200e9 * 1e-8 / 12) = 0.1 mm
    (hand calculation, Euler-Bernoulli; the coarse 10 x 1 x 1 P2 mesh within 10 %)."""
    model = SolidModel(BOX, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
                       loads=(Force(Plane(x="0 mm"), ("0 N", "0 N", "-500 N")),
                              Force(Plane(x="100 mm"), ("0 N", "0 N", "-50 N"))))
    res = model.solve()
    assert any(w.startswith("load 0 (force on") and "held nodes" in w for w in res.warnings)
    assert not any(w.startswith("load 1 ") for w in res.warnings)
    assert float(np.abs(res.u[:, 2]).max()) == pytest.approx(0.1e-3, rel=0.1)


def test_plane_every_load_on_held_nodes_is_an_error():
    model = PlaneModel(mesh2d.rectangle(0.1, 0.02, 10, 2), "5 mm", "Structural Steel",
                       supports=(Fixed(Plane(x="0 m")),), loads=(Force(Plane(x="0 m"), ("0 N", "-10 N")),))
    with pytest.raises(ModelError, match="every load acts only on held nodes"):
        model.solve()
