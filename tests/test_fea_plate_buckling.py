"""Bad input and bookkeeping of mechverify.fea.plate_buckling (the numbers are validated in
tests/validation/test_timoshenko_gere_plate_buckling.py)."""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.components import plates as P
from mechverify.errors import InputError, ModelError, UnitError
from mechverify.fea.plate_buckling import InPlaneLoad, plate_buckling

PLATE = P.Plate.rectangle("200 mm", "100 mm", "2 mm", "Structural Steel")
SS = P.PlateModel(PLATE, supports=(P.EdgeSupport("all"),))


def test_field_values_and_linear_variation():
    """nx = [-10, 10] N/mm from the lowest to the highest y: -10 at y = 0, 0 at mid-height, +10 at the top; ny = [a, b]
    likewise in x; nxy uniform."""
    N = InPlaneLoad(nx=["-10 N/mm", "10 N/mm"], ny=["1 N/mm", "3 N/mm"], nxy="2 N/mm").field((0.0, 0.0, 0.2, 0.1))
    nxx, nyy, nxy = N(np.array([0.1, 0.0, 0.2]), np.array([0.0, 0.05, 0.1]))
    assert nxx == pytest.approx([-10e3, 0.0, 10e3])
    assert nyy == pytest.approx([2e3, 1e3, 3e3])
    assert nxy == pytest.approx([2e3] * 3)


@pytest.mark.parametrize(("load", "err", "match"), [
    (InPlaneLoad(nx="-10"), UnitError, "nx"),
    (InPlaneLoad(nx="-10 N"), UnitError, "nx"),
    (InPlaneLoad(nx=["-10 N/mm"]), InputError, "nx: one value or two"),
    (InPlaneLoad(), InputError, "all zero"),
    (InPlaneLoad(nx="10 N/mm", ny="5 N/mm"), ModelError, "compresses no part"),
])
def test_bad_loads(load, err, match):
    with pytest.raises(err, match=match):
        plate_buckling(SS, load, 1, mesh_size="20 mm")


def test_bad_requests():
    load = InPlaneLoad(nx="-10 N/mm")
    with pytest.raises(InputError, match="n_modes: ask for at least one"):
        plate_buckling(SS, load, 0)
    with pytest.raises(InputError, match="free unknowns"):
        plate_buckling(SS, load, 10_000, mesh_size="50 mm")
    with pytest.raises(InputError, match="PlateModel"):
        plate_buckling(PLATE, load)
    with pytest.raises(InputError, match="InPlaneLoad"):
        plate_buckling(SS, {"nx": "-10 N/mm"})
    with pytest.raises(InputError, match="membrane: one of"):
        plate_buckling(SS, load, 1, mesh_size="20 mm", membrane="exact")
    loose = P.PlateModel(PLATE, supports=(P.PointSupport(("0 mm", "0 mm")),))
    with pytest.raises(ModelError, match="not fully supported"):
        plate_buckling(loose, load, 1, mesh_size="20 mm")


def test_shapes_and_membrane_bookkeeping():
    """Shapes are vertex deflections along z scaled to a largest magnitude of 1 (ascending factors); a plain outline
    takes the given field, which the solved one reproduces (uniform field, quadratic triangles: to roundoff)."""
    res = plate_buckling(SS, InPlaneLoad(nx="-10 N/mm"), 3, mesh_size="10 mm")
    assert res.shapes.shape == (3, res.points.shape[0], 3)
    assert np.all(np.diff(res.factors) >= 0)
    assert np.allclose(np.max(np.abs(res.shapes[:, :, 2]), axis=1), 1.0)
    assert not np.any(res.shapes[:, :, :2]) and res.membrane_method == "given"
    assert res.membrane[..., 0] == pytest.approx(-10e3) and not np.any(res.membrane[..., 1:])
    solved = plate_buckling(SS, InPlaneLoad(nx="-10 N/mm"), 3, mesh_size="10 mm", membrane="solve")
    assert solved.membrane == pytest.approx(res.membrane, abs=1e-6)
    assert solved.factors == pytest.approx(res.factors, rel=1e-9)
