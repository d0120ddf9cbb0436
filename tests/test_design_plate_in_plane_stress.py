"""plate_fea: plate_stress_fea checks membrane + bending, sigma = N/t +- 6 M/t^2 on both faces (task 23e; review 2
finding 1: a 1000 MPa membrane stress PASSed at 8.7 MPa bending). The membrane field is the in_plane load's own
field on a plate without holes and the plane-stress solution around holes.

Numbers (hand calculations from sigma = N/t and the von Mises criterion, not printed values):
- nx = 2000 N/mm on a 2 mm plate: sigma_x = N/t = 1000 MPa (uniaxial, von Mises 1000 MPa);
- nx = 300 N/mm, ny = -300 N/mm (pure shear in principal axes): sigma_vM = sqrt(3) * 150 = 259.8 MPa;
- a 20 mm hole in a 200 mm wide plate (d/H = 0.1) under nx = 2000 N/mm: Peterson's eq. (4.1) / Roark 8th ed.
  Table 17.1 (central circular hole, axial tension) K_tn = 3 - 3.13 (0.1) + 3.66 (0.1)^2 - 1.53 (0.1)^3 = 2.7221
  on the net section, K_tg = 2.7221 / 0.9 = 3.0245 on the gross: about 3025 MPa at the hole
  (tests/validation/test_roark_plate_membrane_hole.py checks it closely on a fine mesh).
"""

import math

import pytest

import mechverify
from mechverify.fea.plate_buckling import InPlaneLoad, nominal_membrane_von_mises

DESIGN = """
[design]
name = "membrane"
[components.panel]
type = "plate_fea"
width = "300 mm"
height = "200 mm"
thickness = "2 mm"
material = "AISI 1045 CD"
supports = [{{ edges = "all", type = "pinned" }}]
mesh_size = "25 mm"
{holes}
[load_cases.pull.panel]
{pressure}
{in_plane}
"""


def _stress(tmp_path, in_plane, pressure='pressure = "1 kPa"', holes=""):
    f = tmp_path / "m.toml"
    f.write_text(DESIGN.format(in_plane=f"in_plane = {{ {in_plane} }}" if in_plane else "", pressure=pressure,
                               holes=holes))
    checks = [r for r in mechverify.load(f).verify() if r.check == "plate_stress_fea"]
    assert len(checks) == 1
    return checks[0]


def test_membrane_stress_is_added_to_the_bending_stress(tmp_path):
    plain = _stress(tmp_path, "")  # bending only: about 8.7 MPa
    r = _stress(tmp_path, 'nx = "2000 N/mm"')
    assert plain.passed and r.verdict.value == "fail"
    assert r.details["membrane_stress"].m_as("MPa")[0] == pytest.approx(1000.0, rel=1e-9)
    # the governing face is the one where the bending stress adds to the tension
    mem, bend = (r.details[k].m_as("MPa") for k in ("membrane_stress", "bending_stress"))
    assert bend[0] > 0 and r.demand.m_as("MPa") > 1000.0
    assert r.demand.m_as("MPa") < 1000.0 + plain.demand.m_as("MPa") + 1e-9  # von Mises is convex: at most the sum
    assert r.details["face"] in ("top", "bottom")
    assert any("membrane N/t" in n and "bending" in n for n in r.notes)
    assert not any("membrane stress of" in w for w in r.warnings)  # the stop-gap WARN is gone


def test_in_plane_alone_is_checked(tmp_path):
    """A buckling-only panel (in_plane, no lateral load) now runs plate_stress_fea on the membrane stress."""
    r = _stress(tmp_path, 'nx = "300 N/mm", ny = "-300 N/mm"', pressure="")
    assert r.demand.m_as("MPa") == pytest.approx(math.sqrt(3) * 150.0, rel=1e-9)
    assert r.details["bending_stress"].m_as("MPa") == pytest.approx([0.0, 0.0, 0.0], abs=1e-9)
    assert r.details["principal_stresses"].m_as("MPa") == pytest.approx([150.0, -150.0], rel=1e-9)


def test_hole_concentrates_the_membrane_stress(tmp_path):
    holes = 'holes = [{ name = "h", diameter = "20 mm", centers = ["150, 100"] }]\nhole_mesh_size = "2 mm"'
    r = _stress(tmp_path, 'nx = "2000 N/mm"', pressure="", holes=holes)
    ktg = (3 - 3.13 * 0.1 + 3.66 * 0.01 - 1.53 * 0.001) / 0.9
    assert ktg == pytest.approx(3.0245, abs=1e-4)
    assert r.demand.m_as("MPa") == pytest.approx(1000 * ktg, rel=0.02)
    assert "hole 'h'" in r.notes[0]
    x, y = r.details["location"].m_as("mm")
    assert x == pytest.approx(150, abs=0.5) and abs(y - 100) == pytest.approx(10, abs=0.5)  # the top/bottom of the hole
    assert any("plane stress" in n for n in r.notes)


def test_no_in_plane_note(tmp_path):
    r = _stress(tmp_path, "")
    assert any("no in-plane loads, so no membrane stress" in n for n in r.notes)
    assert "membrane_stress" in r.details and not r.details["membrane_stress"].m.any()


def test_nominal_membrane_von_mises_hand_values():
    bounds = (0.0, 0.0, 0.3, 0.2)
    assert nominal_membrane_von_mises(InPlaneLoad(nx="300 N/mm", ny="-300 N/mm"), bounds, 2e-3) == pytest.approx(
        math.sqrt(3) * 150e6, rel=1e-12)
    # a linear nx from 0 to -400 N/mm across y: the peak at the high side, 200 MPa
    assert nominal_membrane_von_mises(InPlaneLoad(nx=("0 N/mm", "-400 N/mm")), bounds, 2e-3) == pytest.approx(
        200e6, rel=1e-12)


def test_substituted_line_and_figure_name_both_parts(tmp_path):
    """The substituted line writes each component as membrane + bending and evaluates back to the result
    (tests/test_reports_substituted.py's parser); the figure caption names both parts at the governing point."""
    from test_reports_substituted import evaluate

    holes = 'holes = [{ name = "h", diameter = "20 mm", centers = ["150, 100"] }]'
    f = tmp_path / "m.toml"
    f.write_text(DESIGN.format(in_plane='in_plane = { nx = "200 N/mm", nxy = "20 N/mm" }', pressure='pressure = "3 kPa"',
                               holes=holes))
    d = mechverify.load(f)
    r = next(r for r in d.verify() if r.check == "plate_stress_fea")
    assert r.substituted.count(r"\mathrm{MPa} + (") == 5  # sigma_x, sigma_y twice each, tau_xy once: membrane + (bending)
    expr, printed = evaluate(r.substituted)
    assert expr.m_as("MPa") == pytest.approx(printed.m_as("MPa"), rel=5e-4)
    assert printed.m_as("MPa") == pytest.approx(r.demand.m_as("MPa"), rel=5e-4)
    from mechverify.fea.plate_figure import design_figure

    comp = d["panel"]
    model, res = comp.solved["pull"]
    caption, fig = design_figure("panel", model, comp.supports, res, "pull")
    assert "membrane + bending, the worse face" in caption and "sigma_x = " in caption
    import matplotlib.pyplot as plt

    plt.close(fig)
