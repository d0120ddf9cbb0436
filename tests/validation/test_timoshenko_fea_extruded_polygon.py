"""The extruded-polygon builder (issue 23, "design-file solid studies ... from the builders (block with holes, extruded
polygon)"; task fix23): a plate of any outline, meshed by gmsh, in the API (``fea.mesh.extruded_polygon``) and in a
design file (``solid_fea`` keys ``outline`` and ``thickness``).

Sources:
- [TG-M] Timoshenko & Gere, Mechanics of Materials, 4th ed., 1997: cantilever tip deflection P L^3 / (3 E I)
  (Table G-1, case 4) plus the shear deflection P L / (kappa G A), kappa = 5/6 for a rectangle (as in
  test_timoshenko_fea_solid.py).
- Tapered cantilever: the unit-load (Castigliano) integral delta = int_0^L P (L - x)^2 / (E I(x)) dx of [TG-M]
  ch. 9 with I(x) = t h(x)^3 / 12, evaluated numerically here: a hand calculation from the formula, not a printed
  value.
- Areas and volumes: plane geometry (hand).
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from mechverify.errors import InputError

gmsh = pytest.importorskip("gmsh")

from mechverify.design import load  # noqa: E402
from mechverify.design.loader import DesignFileError  # noqa: E402
from mechverify.fea import mesh, solid  # noqa: E402
from mechverify.fea.loads import Fixed, Force  # noqa: E402
from mechverify.fea.regions import Named  # noqa: E402

E, NU = 200e9, 0.3  # Structural Steel of the database


def _pts(*xy: tuple[float, float]) -> list[tuple[str, str]]:
    return [(f"{x} mm", f"{y} mm") for x, y in xy]


def test_regions_and_areas_of_an_l_shaped_bracket_with_a_hole():
    """An L outline (100 x 20 foot, 40 x 60 leg) 10 mm thick with a 10 mm hole: each side's area is its edge times the
    thickness (1000, 200, 600, 400, 400, 600 mm²), the flat faces 100·20 + 40·40 - π·5² = 3521.46 mm², the hole wall
    2π·5·10 = 314.16 mm² (hand); the tetrahedra's volume is the flat area times the thickness (within 0.2 %: the hole's chords)."""
    m = mesh.extruded_polygon(_pts((0, 0), (100, 0), (100, 20), (40, 20), (40, 60), (0, 60)), "10 mm", "5 mm",
                              holes=[(("20 mm", "40 mm"), "10 mm")])
    got = {k: v * 1e6 for k, v in m.measures.items()}
    sides = [1000, 200, 600, 400, 400, 600]
    assert sorted(got) == sorted(["zmin", "zmax", "hole0", *(f"side{k}" for k in range(6))])
    for k, a in enumerate(sides):
        assert got[f"side{k}"] == pytest.approx(a, rel=1e-9)
    flat = 100 * 20 + 40 * 40 - math.pi * 25
    assert got["zmin"] == pytest.approx(flat, rel=1e-6) and got["zmax"] == pytest.approx(flat, rel=1e-6)
    assert got["hole0"] == pytest.approx(2 * math.pi * 5 * 10, rel=1e-6)
    P, T = m.mesh.p, m.mesh.t  # the straight tetrahedra's volume (the hole's wall as chords: a little under)
    vol = np.abs(np.einsum("ik,ik->k", np.cross(P[:, T[1]] - P[:, T[0]], P[:, T[2]] - P[:, T[0]], axis=0),
                           P[:, T[3]] - P[:, T[0]])).sum() / 6
    assert vol * 1e9 == pytest.approx(flat * 10, rel=2e-3)


def test_rectangle_outline_cantilever_matches_beam_theory():
    """[TG-M]: a 200 x 20 mm outline, 10 mm thick, clamped on side3 (x = 0), 100 N along -y on side1 (x = 200 mm):
    in-plane bending, depth 20 mm: P L^3/(3EI) + P L/(kappa G A) = 0.2000 + 0.0016 mm (hand); the solid is a little
    stiffer at the clamp: 2 %."""
    m = mesh.extruded_polygon(_pts((0, 0), (200, 0), (200, 20), (0, 20)), "10 mm", "5 mm")
    res = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("side3")),),
                           loads=(Force(Named("side1"), ("0 N", "-100 N", "0 N")),)).solve()
    L, h, t, P = 0.2, 0.02, 0.01, 100.0
    I, G = t * h**3 / 12, E / (2 * (1 + NU))
    expect = P * L**3 / (3 * E * I) + P * L / (5 / 6 * G * h * t)
    tip = np.isclose(res.points[:, 0], L)
    assert -res.u[tip, 1].mean() == pytest.approx(expect, rel=0.02)


def _tapered_closed_form(L: float, h0: float, h1: float, t: float, P: float) -> float:
    """Hand calculation, the same integral in closed form: with c = 1 - h1/h0, d = 1 - c,
    delta = P L^3 / (E I0) * (2d - d^2/2 - ln d - 3/2) / c^3 (substituting u = 1 - c x/L)."""
    c = 1 - h1 / h0
    d = 1 - c
    return P * L**3 / (E * t * h0**3 / 12) * (2 * d - d * d / 2 - math.log(d) - 1.5) / c**3


def _tapered_deflection(L: float, h0: float, h1: float, t: float, P: float) -> float:
    """Hand calculation: int_0^L P (L - x)^2 / (E t h(x)^3 / 12) dx, h linear from h0 to h1 (Simpson, 2001 points)."""
    x = np.linspace(0, L, 2001)
    f = P * (L - x) ** 2 / (E * t * (h0 + (h1 - h0) * x / L) ** 3 / 12)
    w = np.ones_like(x)
    w[1:-1:2], w[2:-1:2] = 4, 2
    return float((x[1] - x[0]) / 3 * (w * f).sum())


def test_tapered_outline_cantilever_matches_the_unit_load_integral():
    """A trapezoid outline, depth 30 mm at the clamp tapering to 15 mm at x = 200 mm (symmetric about y = 15), 10 mm
    thick, 100 N along -y at the tip: the Euler-Bernoulli unit-load integral gives 0.09692 mm (hand: Simpson = closed form); the
    mild taper (7.5 mm over 200 mm per edge) and the shear part (~1 %) keep the solid within 4 %."""
    m = mesh.extruded_polygon(_pts((0, 0), (200, 7.5), (200, 22.5), (0, 30)), "10 mm", "4 mm")
    res = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("side3")),),
                           loads=(Force(Named("side1"), ("0 N", "-100 N", "0 N")),)).solve()
    expect = _tapered_deflection(0.2, 0.03, 0.015, 0.01, 100.0)
    assert expect == pytest.approx(_tapered_closed_form(0.2, 0.03, 0.015, 0.01, 100.0), rel=1e-9)
    assert expect * 1e3 == pytest.approx(0.09692, abs=5e-6)
    tip = np.isclose(res.points[:, 0], 0.2)
    assert -res.u[tip, 1].mean() == pytest.approx(expect, rel=0.04)


@pytest.mark.parametrize(("outline", "holes", "match"), [
    (((0, 0), (100, 0)), (), "at least three corners"),
    (((0, 0), (100, 20), (100, 0), (0, 20)), (), "do not make a simple polygon"),  # a bow tie
    (((0, 0), (100, 0), (100, 20), (0, 20)), [(("95 mm", "10 mm"), "12 mm")], r"holes\[0\].*does not lie inside"),
])
def test_bad_outlines_are_named(outline, holes, match):
    with pytest.raises(InputError, match=match):
        mesh.extruded_polygon(_pts(*outline), "10 mm", "5 mm", holes=holes)


DESIGN = """
    [design]
    name = "outline"
    [components.arm]
    type = "solid_fea"
    outline = {outline}
    thickness = "10 mm"
    mesh_size = "5 mm"
    material = "Structural Steel"
    supports = [{{ named = "{support}" }}]
    deflection_limit = "1 mm"
    [load_cases.tip.arm]
    forces = [{{ named = "side1", force = "0, -100, 0" }}]
    """
RECT = '["0, 0", "200, 0", "200, 20", "0, 20"]'


def _design(tmp_path, outline: str = RECT, support: str = "side3", extra: str = ""):
    p = tmp_path / "d.toml"
    keep = "" if extra.startswith("thickness") else 'thickness = "10 mm"\n'  # (extra: more keys, or a thickness)
    p.write_text(textwrap.dedent(DESIGN.format(outline=outline, support=support)).replace(
        'thickness = "10 mm"\n', keep + extra))
    return p


def test_design_file_outline_cantilever(tmp_path):
    """The rectangle cantilever of test_rectangle_outline_cantilever_matches_beam_theory from a design file: the
    largest displacement 0.2016 mm (hand, [TG-M]) within 2 %."""
    rs = load(_design(tmp_path)).verify()
    assert rs.get("arm", "solid_deflection").demand.m_as("mm") == pytest.approx(0.2016, rel=0.02)


@pytest.mark.parametrize(("outline", "support", "extra", "key", "match"), [
    (RECT, "side9", "", "components.arm.supports[0].named", "valid regions: hole|side0, side1, side2, side3"),
    ('["0, 0", "200, 20", "200, 0", "0, 20"]', "side3", "", "components.arm.outline", "simple polygon"),
    ('["0, 0", "200"]', "side3", "", "components.arm.outline[1]", r"expected a corner"),
    ('["0, 0", "200, 0"]', "side3", "", "components.arm.outline", r"at least three corners"),
    (RECT, "side3", 'holes = [{ center = "195, 10", diameter = "12 mm" }]\n', "components.arm.holes[0]",
     "does not lie inside the outline"),
    (RECT, "side3", 'thickness = "-1 mm"\n', "components.arm.thickness", "positive"),
])
def test_design_file_bad_outlines_are_named(tmp_path, outline, support, extra, key, match):
    with pytest.raises(DesignFileError) as exc:
        load(_design(tmp_path, outline, support, extra)).verify()
    errs = exc.value.errors
    assert errs[0][0] == key, errs
    assert any(__import__("re").search(match, e[1]) for e in errs), errs


def test_thickness_goes_with_outline(tmp_path):
    text = _design(tmp_path).read_text().replace('thickness = "10 mm"\n', "")
    (tmp_path / "d.toml").write_text(text)
    with pytest.raises(DesignFileError, match=r"components.arm.outline: needs thickness"):
        load(tmp_path / "d.toml")


def test_parameters_in_the_outline(tmp_path):
    """Corners may use [parameters] ("L, 0"): L = 100 mm gives PL^3/3EI + PL/kappa G A = 0.02500 + 0.00078 =
    0.02578 mm ([TG-M], hand), 2 %. Before, 'L' was 'expected a length'."""
    p = tmp_path / "d.toml"
    p.write_text('[parameters]\nL = "100 mm"\n' + textwrap.dedent(DESIGN.format(
        outline='["0, 0", "L, 0", "L, 20", "0, 20"]', support="side3")))
    rs = load(p).verify()
    L, h, t, P = 0.1, 0.02, 0.01, 100.0
    expect = P * L**3 / (3 * E * t * h**3 / 12) + P * L / (5 / 6 * E / (2 * (1 + NU)) * h * t)
    assert rs.get("arm", "solid_deflection").demand.m_as("m") == pytest.approx(expect, rel=0.02)


def test_a_closed_outline_is_the_open_one(tmp_path):
    """Review 4 finding 17: an outline closed by repeating its first corner (a CAD/CSV export, plate_fea's outline)
    was gmsh's 'Could not create line' (internal error); it is the same plate as the open outline: same regions
    (side0..side3) and the same tip deflection (0.2016 mm by hand, [TG-M], 2 %)."""
    rs = load(_design(tmp_path, '["0, 0", "200, 0", "200, 20", "0, 20", "0, 0"]')).verify()
    assert rs.get("arm", "solid_deflection").demand.m_as("mm") == pytest.approx(0.2016, rel=0.02)
    m = mesh.extruded_polygon(_pts((0, 0), (200, 0), (200, 20), (0, 20), (0, 0)), "10 mm", "10 mm")
    assert sorted(m.named) == ["side0", "side1", "side2", "side3", "zmax", "zmin"]


@pytest.mark.parametrize(("outline", "key", "match"), [
    ('["0, 0", "200, 0", "200, 20", "200, 20", "0, 20"]', "components.arm.outline[3]",
     r"the same corner as outline\[2\] \(200, 20\) mm"),
    ('["0, 0", "200, 20", "200, 0", "0, 20"]', "components.arm.outline", r"Self-intersection\[100 10\], in mm"),
])
def test_repeated_and_crossing_corners_are_named_in_the_file_unit(tmp_path, outline, key, match):
    with pytest.raises(DesignFileError) as exc:
        load(_design(tmp_path, outline)).verify()
    (k, msg), = exc.value.errors
    assert k == key and __import__("re").search(match, msg), msg
