"""plate_fea in-plane supports and hole loads (task 23e): `in_plane_supports` hold outline edges or hole rims in the
plate's plane, `in_plane.hole_loads` press pins on hole rims; their membrane stress enters plate_stress_fea and their
field buckling_load_factor.

Numbers: hand calculations (equilibrium; N/t far from a held edge, Saint-Venant), not printed values; the pin-loaded
hole's field is checked against CalculiX on the same plane-stress model in
tests/validation/test_calculix_plate_membrane_bending.py.
"""

import pytest

import mechverify
from mechverify.components import plates as P
from mechverify.errors import MechverifyError
from mechverify.fea.plate import plate_mesh, solve_plate
from mechverify.fea.plate_buckling import HoleForce, InPlaneLoad, plate_buckling
from mechverify.fea.plate_stress import InPlaneSupport, membrane_stress

LUG = """
[design]
name = "lug"
[components.lug]
type = "plate_fea"
width = "100 mm"
height = "60 mm"
thickness = "5 mm"
material = "AISI 1045 CD"
holes = [{{ name = "pin", diameter = "20 mm", centers = ["80, 30"] }}]
supports = [{{ edges = "all", type = "pinned" }}]
mesh_size = "5 mm"
hole_mesh_size = "1 mm"
{supports}
[load_cases.pull.lug]
in_plane = {{ {in_plane} }}
"""


def _design(tmp_path, in_plane='hole_loads = [{ holes = "pin", force_x = "10 kN" }]',
            supports='in_plane_supports = [{ edges = ["left"] }]'):
    f = tmp_path / "lug.toml"
    f.write_text(LUG.format(in_plane=in_plane, supports=supports))
    return mechverify.load(f)


def _lug():
    plate = P.Plate.rectangle("100 mm", "60 mm", "5 mm", "AISI 1045 CD",
                              holes=[P.Hole(("80 mm", "30 mm"), "20 mm", name="pin")])
    return plate, P.PlateModel(plate, (P.EdgeSupport("all", "simply_supported"),), ())


def test_pin_load_on_a_lug_held_at_its_edge(tmp_path):
    """10 kN on the pin hole, the left edge held: the reactions balance the pin force; the stress check reports the
    membrane stress at the hole (about 4.5 x the net-section 50 MPa; checked against CalculiX elsewhere)."""
    plate, model = _lug()
    ld = InPlaneLoad(hole_loads=(HoleForce("pin", ("10 kN", "0 N")),))
    ms = membrane_stress(plate, plate_mesh(plate, 5e-3, 1e-3), ld, "auto", (InPlaneSupport(edges=(3,)),))
    assert ms.method == "solve"
    assert ms.field.reactions.m_as("N")[:2] == pytest.approx([-10e3, 0.0], abs=1e-6)
    r = next(r for r in _design(tmp_path).verify() if r.check == "plate_stress_fea")
    api = solve_plate(model, "5 mm", "1 mm", ld, in_plane_supports=(InPlaneSupport(edges=(3,)),))
    assert r.demand.m_as("Pa") == pytest.approx(api.max_von_mises.value.m_as("Pa"), rel=1e-9)
    assert 150 < r.demand.m_as("MPa") < 300 and "hole 'pin'" in r.notes[0]
    assert any("(10000, 0) N on hole 'pin'" in n and "outline edge 3 holds xy" in n for n in r.notes)


def test_edge_held_in_plane_far_field(tmp_path):
    """The left edge held, nx = 100 N/mm on a 300 x 100 x 2 mm plate: 50 MPa at the centre (N/t)."""
    plate = P.Plate.rectangle("300 mm", "100 mm", "2 mm", "AISI 1045 CD")
    model = P.PlateModel(plate, (P.EdgeSupport("all", "simply_supported"),), ())
    res = solve_plate(model, "10 mm", None, InPlaneLoad(nx="100 N/mm"), in_plane_supports=(InPlaneSupport(edges=(3,)),))
    import numpy as np

    c = int(np.argmin(np.hypot(res.points[:, 0] - 0.15, res.points[:, 1] - 0.05)))
    assert res.extra["membrane_xx_Pa"][c] == pytest.approx(50e6, rel=1e-3)
    assert abs(res.extra["membrane_yy_Pa"][c]) < 1e-3 * 50e6


def test_pushing_the_pin_buckles_the_lug(tmp_path):
    """A 10 kN push towards the held edge compresses the lug: buckling_load_factor runs on that field (pulling
    compresses nothing along x, yet the bearing pressure compresses the rim locally: both give a finite factor,
    the push a lower one)."""
    push = _design(tmp_path, 'hole_loads = [{ holes = "pin", force_x = "-10 kN" }]').verify()
    bk = next(r for r in push if r.check == "buckling_load_factor")
    _, model = _lug()
    api = plate_buckling(model, InPlaneLoad(hole_loads=(HoleForce("pin", ("-10 kN", "0 N")),)), 1, "5 mm", "1 mm",
                         in_plane_supports=(InPlaneSupport(edges=(3,)),))
    assert bk.capacity.m == pytest.approx(api.first_factor, rel=1e-9)
    assert 1 < api.first_factor < 1e4


def test_supports_do_not_change_a_balanced_uniform_case():
    """Holding one edge (x) and one edge (y) under a uniform nx gives the same buckling factor as the free-floating
    balanced case (the field is uniform either way): 14.38, T&G eq. 9-9 k = 4: 14.46 (hand)."""
    plate = P.Plate.rectangle("400 mm", "200 mm", "2 mm", "Structural Steel")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all"),))
    free = plate_buckling(model, InPlaneLoad(nx="-10 N/mm"), mesh_size="10 mm").first_factor
    held = plate_buckling(model, InPlaneLoad(nx="-10 N/mm"), mesh_size="10 mm",
                          in_plane_supports=(InPlaneSupport(edges=(3,), y=False),
                                             InPlaneSupport(edges=(0,), x=False))).first_factor
    assert held == pytest.approx(free, rel=1e-6)


@pytest.mark.parametrize(("in_plane", "supports", "message"), [
    ('hole_load = [{ holes = "pin", force_x = "1 kN" }]', 'in_plane_supports = [{ edges = ["left"] }]',
     "load_cases.pull.lug.in_plane.hole_load: not a key of in_plane"),
    ('hole_loads = [{ holes = "pn", force_x = "1 kN" }]', 'in_plane_supports = [{ edges = ["left"] }]',
     "load_cases.pull.lug.in_plane.hole_loads[0].holes[0]: no hole or hole group 'pn'; did you mean 'pin'?"),
    ('hole_loads = [{ holes = "pin" }]', 'in_plane_supports = [{ edges = ["left"] }]',
     "load_cases.pull.lug.in_plane.hole_loads[0]: give force_x and/or force_y"),
    ('hole_loads = [{ holes = "pin", force_x = "1 kN" }]', 'in_plane_supports = [{ edges = ["left"], hold = "z" }]',
     "components.lug.in_plane_supports[0].hold: one of xy, x, y"),
    ('hole_loads = [{ holes = "pin", force_x = "1 kN" }]', "",
     "load_cases.pull.lug.in_plane: in-plane load: the loads are not in equilibrium by themselves"),
])
def test_bad_in_plane_input_is_named(tmp_path, in_plane, supports, message):
    with pytest.raises(MechverifyError) as exc:
        _design(tmp_path, in_plane, supports).verify()
    assert message in str(exc.value)


def test_edge_loads_superpose_unit_solutions_once_per_plate():
    """Edge loads alone are the sum of five unit plane-stress solutions kept per plate, mesh and supports: the same
    field as one direct solve (to rounding), and a second load on the same plate builds nothing new (a study)."""
    import numpy as np

    from mechverify.fea import factorcache
    from mechverify.fea.plate_stress import _solve

    plate, _ = _lug()
    mesh = plate_mesh(plate, 5e-3, 1e-3)
    sup = (InPlaneSupport(edges=(3,)),)
    loads = (InPlaneLoad(nx=("-50 N/mm", "80 N/mm"), ny="30 N/mm", nxy="-20 N/mm"), InPlaneLoad(nx="100 N/mm"))
    first = membrane_stress(plate, mesh, loads[0], "solve", sup)
    builds = factorcache.CACHE.builds
    second = membrane_stress(plate, mesh, loads[1], "solve", sup)
    assert factorcache.CACHE.builds == builds  # the unit solutions were reused
    for ms, ld in ((first, loads[0]), (second, loads[1])):
        direct = _solve(plate, mesh, ld, sup)
        assert np.max(np.abs(ms.stress - direct.stress)) <= 1e-12 * np.max(np.abs(direct.stress))
        assert "superposed unit solutions" in ms.notes[0]


def test_held_edge_corner_peak_is_named_singular(tmp_path):
    """A plate held on its left edge and pulled: the peak sits at an end of the held edge, a singular corner of plane
    elasticity (measured 63, 74, 87 MPa at mesh 10, 5, 2.5 mm for 50 MPa nominal). The check WARNs, names it and
    gives the largest stress a plate thickness (two elements) away, near the nominal N/t = 50 MPa."""
    import re

    f = tmp_path / "edge.toml"
    f.write_text("""
[design]
name = "edge"
[components.p]
type = "plate_fea"
width = "300 mm"
height = "100 mm"
thickness = "2 mm"
material = "AISI 1045 CD"
supports = [{ edges = "all", type = "pinned" }]
in_plane_supports = [{ edges = ["left"] }]
mesh_size = "5 mm"

[load_cases.pull.p]
in_plane = { nx = "100 N/mm" }
""")
    results = mechverify.load(f).verify()
    r = next(r for r in results if r.check == "plate_stress_fea")
    assert r.verdict.value == "warn" and r.demand.m_as("MPa") > 60
    w = next(w for w in r.warnings if "held in the plate's plane" in w)
    assert "of outline edge 3" in w and "grows as the mesh is refined" in w
    away = float(re.search(r"every singular point: ([\d.]+) MPa", w).group(1))
    assert 45 < away < 60  # about the nominal 50 MPa

    # buckling: the pull compresses only the held edge's corners (2.85 N/mm); ARPACK does not converge on that
    # field, so the factor is the Rayleigh bound (biaxial 1 N/m factor: hand N_cr = pi^2 D (1/a^2 + 1/b^2) =
    # 1.654e5 N/m for the simply supported 300 x 100 x 2 mm plate, D = 150.8 N m) / 2.85 N/mm = 58
    bk = next(r for r in results if r.check == "buckling_load_factor")
    assert bk.notes[0].startswith("LOWER BOUND") and bk.passed
    assert bk.capacity.m == pytest.approx(1.654e5 / 2851, rel=0.02)
