"""The plate mesher's geometry (task plateacc): round holes and cut-outs' rounded corners meshed ON their circles.

Expected values are geometry by hand: a 100 x 60 mm cut-out centred at (150, 100) mm with 10 mm corner radii has its
corner circles centred at (150 ± 40, 100 ± 20) mm; a hole of radius R meshed at size s has 4 ceil(pi R / 2 s) sides
(at least 48). The convergence test is a property of the code (the rim peak rises monotonically as the arc is
resolved), not a published value: on the 15-degree corner polygon it kept growing (37.2 / 40.1 / 42.8 / 45.7 MPa at
4.2 / 1 / 0.33 / 0.125 mm).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechverify.components import plates as pl
from mechverify.fea.plate import mesh_region, plate_mesh, ring_arcs, solve_plate


def _plate(holes=(), cutouts=()):
    return pl.Plate.rectangle("300 mm", "200 mm", "3 mm", "Structural Steel", holes=list(holes), cutouts=list(cutouts))


CUT = pl.rectangle_cutout(("150 mm", "100 mm"), ("100 mm", "60 mm"), "10 mm")


def test_ring_arcs_finds_the_four_rounded_corners():
    arcs = ring_arcs(_plate(cutouts=[CUT]).region.interiors[0].coords)
    assert len(arcs) == 4
    centres = sorted((round(c[0] * 1e3, 6), round(c[1] * 1e3, 6)) for _, c, _ in arcs)
    assert centres == [(110, 80), (110, 120), (190, 80), (190, 120)]
    assert all(r == pytest.approx(0.010, rel=1e-9) and len(segs) == 6 for segs, _, r in arcs)
    square = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
    assert ring_arcs(square) == []  # straight sides: no arc


def test_mesh_region_puts_rims_on_their_circles():
    hole = pl.Hole(("60 mm", "60 mm"), "20 mm", name="h")
    plate = _plate(holes=[hole], cutouts=[CUT])
    poly, ring_sizes, seg_sizes = mesh_region(plate, 12.5e-3, None)
    rim = np.asarray(poly.interiors[0].coords)[:-1]
    s = 0.010 / 30  # radius / 30
    assert ring_sizes[0] == pytest.approx(s)
    assert len(rim) == 4 * math.ceil(math.pi * 0.010 / (2 * s))  # sides about s long, a multiple of 4
    assert np.linalg.norm(rim - np.array([0.06, 0.06]), axis=1) == pytest.approx(0.010, rel=1e-12)
    assert np.any(np.all(np.isclose(rim, [0.06, 0.07]), axis=1))  # a vertex at the top of the hole
    cut = np.asarray(poly.interiors[1].coords)[:-1]
    on_arc = [np.linalg.norm(cut - np.array(c), axis=1) for c in ((0.19, 0.12), (0.11, 0.08))]
    for d in on_arc:
        near = d[d < 0.0105]
        # 6 chords of 2 r sin 7.5 deg = 2.61 mm, each in ceil(2.61 / 0.333) = 8 parts: 49 points, all on the circle
        assert near.size == 49 and near == pytest.approx(0.010, rel=1e-9)
    assert seg_sizes and all(v == pytest.approx(s) for v in seg_sizes.values())
    # an explicit hole size coarser than the 48-gon's side keeps the 48-gon
    poly2, _, seg2 = mesh_region(plate, 15e-3, 3e-3)
    assert len(poly2.interiors[0].coords) - 1 == 48


def test_plain_rectangle_mesh_is_unchanged():
    m = plate_mesh(_plate(), 25e-3)
    assert m.p.shape[1] == 13 * 9  # structured 12 x 8 cells


def test_rounded_corner_peak_converges_monotonically():
    model = pl.PlateModel(_plate(cutouts=[CUT]), [pl.EdgeSupport("all", "pinned")], [pl.PressureLoad("-10 kPa")])
    peaks = [solve_plate(model, None, f"{hh} mm").max_von_mises.value.m_as("MPa") for hh in (1.0, 0.5, 0.25)]
    assert peaks == sorted(peaks)  # code: 39.33, 39.99, 40.23 MPa
    assert peaks[-1] - peaks[-2] < peaks[-2] - peaks[-3]
