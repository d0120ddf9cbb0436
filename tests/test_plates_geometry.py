"""Plate geometry, supports and loads: areas and masses by hand, and every degenerate-geometry error.

Hand values: a 450 x 400 mm rectangle with four 6.5 mm holes and a 150 x 160 mm cut-out has net area
180000 - 4*pi*3.25^2 - 24000 = 155867.3 mm^2 (elementary geometry).
"""

import math

import pytest

from mechverify import Q
from mechverify.components.plates import (
    EdgeSupport,
    Hole,
    HoleSupport,
    PatchLoad,
    Plate,
    PlateModel,
    PlatePointLoad,
    PlateSelfWeight,
    PointSupport,
    PressureLoad,
    corner_holes,
    hole_grid,
)
from mechverify.errors import InputError, UnitError, UnknownNameError
from mechverify.materials import Material

AL = Material(name="test Al", category="aluminium", E="70 GPa", nu=0.33, density="2700 kg/m**3",
              yield_strength="240 MPa")


def base_plate(t="6 mm"):
    holes = corner_holes("450 mm", "400 mm", "20 mm", "6.5 mm")
    cut = Q([[150, 120], [300, 120], [300, 280], [150, 280]], "mm")
    return Plate.rectangle("450 mm", "400 mm", t, AL, holes=holes, cutouts=[cut], name="base")


def test_net_area_mass_and_weight():
    p = base_plate()
    a = 450 * 400 - 4 * math.pi * 3.25**2 - 150 * 160
    assert p.area.m_as("mm**2") == pytest.approx(a, rel=1e-12)
    assert p.mass.m_as("kg") == pytest.approx(a * 1e-6 * 0.006 * 2700, rel=1e-12)
    assert p.weight.m_as("N") == pytest.approx(p.mass.m_as("kg") * 9.80665, rel=1e-12)
    assert p.is_rectangle()
    assert [h.name for h in p.holes] == ["corner_sw", "corner_se", "corner_ne", "corner_nw"]
    assert p.hole("corner_ne").center == pytest.approx((0.430, 0.380))
    # the meshable region: outline with 5 interior rings
    assert len(p.region.interiors) == 5


def test_model_resultant_includes_self_weight_and_drops_patch_over_hole():
    p = base_plate()
    m = PlateModel(p, [HoleSupport("all")],
                   [PlatePointLoad(("225 mm", "50 mm"), "-80 N"), PlateSelfWeight(),
                    PatchLoad(center=("225 mm", "60 mm"), size=("20 mm", "10 mm"), pressure="-1 MPa"),
                    PressureLoad("-100 Pa")])
    expected = -80 - p.weight.m_as("N") - 1e6 * 200e-6 - 100 * p.area.m_as("m**2")
    assert m.total_force().m_as("N") == pytest.approx(expected, rel=1e-9)
    assert m.warnings() == ()
    m2 = PlateModel(p, [EdgeSupport("all")], [PatchLoad(center=("225 mm", "200 mm"), size=("100 mm", "100 mm"),
                                                        force="-10 N")])
    assert m2.total_force().m_as("N") == pytest.approx(0.0, abs=1e-12)
    assert "over a hole" in m2.warnings()[0]


def test_numbers_with_unit_from_toml_style_input():
    p = Plate(outline=[[0, 0], [100, 0], [100, 50], [0, 50]], thickness=3, material=AL, unit="mm",
              holes=[{"center": [50, 25], "diameter": 10, "name": "pin"}])
    assert p.thickness == pytest.approx(0.003)
    assert p.hole("pin").diameter == pytest.approx(0.010)
    assert len(hole_grid(("10 mm", "10 mm"), 3, 2, "20 mm", "30 mm", "4 mm")) == 6


@pytest.mark.parametrize(("kwargs", "match"), [
    (dict(outline=[[0, 0], [1, 1], [1, 0], [0, 1]]), "crosses itself"),
    (dict(outline=[[0, 0], [1, 0], [2, 0]]), "no area"),
    (dict(thickness=0), "thickness: must be positive"),
    (dict(holes=[Hole(("150 mm", "50 mm"), "5 mm")]), "outside the plate"),
    (dict(holes=[Hole(("98 mm", "50 mm"), "5 mm")]), "across the plate edge"),
    (dict(holes=[Hole(("50 mm", "50 mm"), "5 mm"), Hole(("53 mm", "50 mm"), "5 mm")]), "overlaps"),
    (dict(cutouts=[[[10, 10], [90, 90], [90, 10], [10, 90]]]), "crosses itself"),
    (dict(cutouts=[[[50, 50], [150, 50], [150, 60], [50, 60]]]), "not inside"),
])
def test_degenerate_geometry(kwargs, match):
    base = dict(outline=[[0, 0], [100, 0], [100, 100], [0, 100]], thickness=2, material=AL, unit="mm")
    with pytest.raises(InputError, match=match):
        Plate(**{**base, **kwargs})


def test_support_and_load_errors():
    p = base_plate()
    with pytest.raises(UnknownNameError, match="corner_se"):
        PlateModel(p, [HoleSupport(["corner_sx"])])
    with pytest.raises(InputError, match="edge 7 does not exist"):
        PlateModel(p, [EdgeSupport([7])])
    with pytest.raises(InputError, match="not on base"):
        PlateModel(p, [EdgeSupport()], [PlatePointLoad(("225 mm", "200 mm"), "1 N")])  # in the cut-out
    with pytest.raises(InputError, match="not on base"):
        PlateModel(p, [PointSupport(("500 mm", "0 mm"))])
    with pytest.raises(InputError, match="at least one support"):
        PlateModel(p, [])
    with pytest.raises(InputError, match="beyond the outline"):
        PlateModel(p, [EdgeSupport()], [PatchLoad(center=("440 mm", "200 mm"), size=("40 mm", "10 mm"),
                                                  force="1 N")])
    with pytest.raises(UnknownNameError, match="clamped"):
        EdgeSupport(condition="clampd")
    with pytest.raises(InputError, match="exactly one of force"):
        PatchLoad(center=("1 mm", "1 mm"), size=("1 mm", "1 mm"))
    with pytest.raises(UnitError, match="force"):
        PlatePointLoad(("1 mm", "1 mm"), "5 mm")
    with pytest.raises(InputError, match="all zero"):
        PlatePointLoad(("1 mm", "1 mm"))
    assert PointSupport((0.0, 0.0), unit="mm").condition == "simply_supported"
    assert HoleSupport("corner_sw", condition="bolted").condition == "clamped"
