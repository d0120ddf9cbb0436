"""Design-file type ``plate_fea`` (plate-bending FEA): Roark's and Timoshenko's plate coefficients reproduced
through the design file, a plate on bolt holes, key-path errors and the report (typeset formulas, figure).

References: Young & Budynas, Roark's Formulas for Stress and Strain, 7th ed. (2002), Table 11.4 cases 1a and 8a
(nu = 0.3; the same values in the 8th ed.); Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed.
(1959), Table 8 (corner reactions of a simply supported square plate). The FEA's verified tolerance (issue 7,
tests/test_fea_plane_plate.py): alpha within 1 %, beta within 3 %.
"""

import math
import textwrap

import numpy as np
import pytest

from mechverify.design import DesignFileError, load
from mechverify.reports import render_html

# Aluminium with Roark's nu = 0.3 (Table 11.4 is tabulated for nu = 0.3).
MATERIALS = """
[materials.al]
base = "Inventor Aluminum 6061"
E = "70 GPa"
nu = 0.3
"""

RECT = """
[components.p]
type = "plate_fea"
width = "{a}"
height = "{b}"
thickness = "4 mm"
material = "al"
supports = [{{ edges = "all", type = "{support}" }}]
mesh_size = "{h}"
deflection_limit = "5 mm"
[load_cases.q.p]
pressure = "10 kPa"
"""


def design(tmp_path, body, materials=MATERIALS):
    p = tmp_path / "design.toml"
    p.write_text(textwrap.dedent('[design]\nname = "plates"\n' + materials + body))
    return load(p)


def nearest(res, x, y):
    return int(np.argmin(np.hypot(res.points[:, 0] - x, res.points[:, 1] - y)))


def test_simply_supported_rectangle_matches_roark_table_11_4_case_1a(tmp_path):
    """Roark 7th ed. Table 11.4 case 1a (all edges simply supported, uniform q), a/b = 2.0: beta = 0.6102,
    alpha = 0.1110. a = 400, b = 200, t = 4 mm, q = 10 kPa, E = 70 GPa:
    sigma_max (centre, across the short span) = beta q b^2 / t^2 = 0.6102 * 1e4 * 0.2^2 / 0.004^2 = 15.255 MPa;
    y_max = alpha q b^4 / (E t^3) = 0.1110 * 1e4 * 0.2^4 / (70e9 * 0.004^3) = 0.3964 mm."""
    d = design(tmp_path, RECT.format(a="400 mm", b="200 mm", support="pinned", h="10 mm"))
    rs = d.verify()
    y = rs.get("p", "plate_deflection_fea")
    assert y.demand.m_as("mm") == pytest.approx(0.1110 * 1e4 * 0.2**4 / (70e9 * 0.004**3) * 1e3, rel=0.01)
    model, res = d["p"].solved["q"]
    centre = nearest(res, 0.2, 0.1)
    assert res.sigma[centre, 1, 1] / 1e6 == pytest.approx(0.6102 * 1e4 * 0.2**2 / 0.004**2 / 1e6, rel=0.02)
    s = rs.get("p", "plate_stress_fea")
    assert s.capacity.m_as("MPa") == pytest.approx(275)
    # von Mises at the centre is at most the larger normal stress (sigma_x and sigma_y of one sign there)
    assert s.demand.m_as("MPa") <= 15.255 * 1.02
    assert "governing location" in s.notes[0]


def test_clamped_rectangle_deflection_matches_roark_table_11_4_case_8a(tmp_path):
    """Roark 7th ed. Table 11.4 case 8a (all edges fixed, uniform q), a/b = 2.0: alpha = 0.0277, beta1 = 0.4974
    (edge stress at the centre of the long edge, where sigma_x = nu sigma_y because the edge stays straight,
    so sigma_vM = beta1 q b^2/t^2 sqrt(1 - nu + nu^2) = 15.544 * 0.8888 = 13.82 MPa).
    y_max = 0.0277 * 1e4 * 0.2^4 / (70e9 * 0.004^3) = 0.09893 mm. Morley elements converge to a fixed edge
    from the flexible side: within 3 % at b/32."""
    d = design(tmp_path, RECT.format(a="400 mm", b="200 mm", support="fixed", h="6.25 mm"))
    rs = d.verify()
    assert rs.get("p", "plate_deflection_fea").demand.m_as("mm") == pytest.approx(
        0.0277 * 1e4 * 0.2**4 / (70e9 * 0.004**3) * 1e3, rel=0.03)
    vm_edge = 0.4974 * 1e4 * 0.2**2 / 0.004**2 * math.sqrt(1 - 0.3 + 0.3**2) / 1e6
    assert rs.get("p", "plate_stress_fea").demand.m_as("MPa") == pytest.approx(vm_edge, rel=0.03)
    assert "outline edge" in rs.get("p", "plate_stress_fea").notes[0]


def test_square_plate_corner_twist_matches_timoshenko_table_8(tmp_path):
    """Timoshenko & Woinowsky-Krieger 2nd ed., Table 8 (b/a = 1, nu = 0.3): corner reaction R = 0.065 q a^2 = 2 M_xy,
    so the corners carry pure twist M_xy = 0.0325 q a^2, tau = 6 M_xy / t^2 and sigma_vM = sqrt(3) tau:
    a = 400 mm, t = 4 mm, q = 10 kPa: sigma_vM = sqrt(3) * 6 * 0.0325 * 1e4 * 0.16 / 0.004^2 = 33.775 MPa. This
    exceeds the centre stress (beta = 0.2874: 28.74 MPa, equal biaxial, so von Mises 28.74 MPa): the governing
    stress of a simply supported square plate is at its corners."""
    d = design(tmp_path, RECT.format(a="400 mm", b="400 mm", support="pinned", h="12.5 mm"))
    s = d.verify().get("p", "plate_stress_fea")
    assert s.demand.m_as("MPa") == pytest.approx(math.sqrt(3) * 6 * 0.0325 * 1e4 * 0.16 / 0.004**2 / 1e6, rel=0.02)
    assert "(0, 0) mm" in s.notes[0] or "(400, 400) mm" in s.notes[0] or "(0, 400)" in s.notes[0] \
        or "(400, 0)" in s.notes[0]


BOLTED = """
[components.base]
type = "plate_fea"
width = "300 mm"
height = "200 mm"
thickness = "6 mm"
material = "al"
holes = [{ name = "bolt", diameter = "6.6 mm", centers = ["15, 15", "285, 15", "285, 185", "15, 185"] }]
cutouts = [{ center = "150, 100", size = "80, 60", corner_radius = "10 mm" }]
supports = [{ holes = ["bolt"], type = "fixed", washer_diameter = "11 mm" }]
mesh_size = "15 mm"
hole_mesh_size = "4 mm"
deflection_limit_fraction = 0.005
[load_cases.lift.base]
patch_loads = [{ center = "150, 150", size = "40, 20", force = "-400 N" }]
self_weight = true
"""


def test_plate_on_bolt_holes_runs_and_exceeds_the_statics_lower_bound(tmp_path):
    """Four fixed bolt holes, a cut-out, a 400 N patch and self-weight. Statics gives a lower bound on the
    peak: the total moment across the section x = 150 mm from the two bolts on one side is at least
    (P/2)(150 - 15) mm minus the moment of the load about that line; for the load on the line itself the mean
    stress over the net width (200 - 60 mm) is sigma = 6 M / (b t^2) = 6 * 200 * 0.135 / (0.14 * 0.006^2) =
    32.1 MPa; the FEA peak must exceed it. Equilibrium: the reactions balance the loads (checked by the solver),
    and the applied load is 400 N + the weight rho g t A_net."""
    d = design(tmp_path, BOLTED)
    rs = d.verify()
    s, y = rs.get("base", "plate_stress_fea"), rs.get("base", "plate_deflection_fea")
    assert s.demand.m_as("MPa") > 6 * 200 * 0.135 / (0.14 * 0.006**2) / 1e6
    model, res = d["base"].solved["lift"]
    net = 0.3 * 0.2 - 4 * math.pi * 0.0033**2 - (0.08 * 0.06 - (4 - math.pi) * 0.01**2)
    assert res.applied[2] == pytest.approx(-400 - 2700 * 9.80665 * 0.006 * net, rel=1e-3)
    # span (review 4 finding 30; was the bounding box's shorter side, 200 mm): the clear distance between the
    # washers (11 mm) of the bolts at x = 15 and 285 mm on the line through the point of largest deflection, by hand
    # 285 - 15 - 11 = 259 mm
    assert y.capacity.m_as("mm") == pytest.approx(0.005 * 259)
    assert 0 < y.demand.m_as("mm") < 1
    assert any("fixed rims of holes" in n for n in s.notes)


def test_polygon_outline_and_point_support_warning(tmp_path):
    """An L-shaped outline given as points; a point load at a point support's neighbour is singular in plate
    theory, so the check warns when the peak sits at a concentrated load."""
    body = """
    [components.l]
    type = "plate_fea"
    outline = ["0, 0", "200, 0", "200, 80", "80, 80", "80, 200", "0, 200"]
    thickness = "3 mm"
    material = "al"
    supports = [{ edges = [0], type = "fixed" }]
    mesh_size = "20 mm"
    [load_cases.tip.l]
    point_loads = [{ at = "40, 190", force = "-20 N" }]
    """
    rs = design(tmp_path, body).verify()
    s = rs.get("l", "plate_stress_fea")
    assert s.demand.m_as("MPa") > 0
    # a clamped edge 0 (200 mm long) carrying the tip load: the root moment is 20 N * 0.19 m = 3.8 N m
    # over 200 mm, a mean 6 M/(b t^2) = 12.7 MPa; the peak is at least that
    assert s.demand.m_as("MPa") > 6 * 3.8 / (0.2 * 0.003**2) / 1e6
    assert any("concentrated" in w for w in s.warnings) == ("point load" in s.notes[0])


def errors_of(tmp_path, body):
    with pytest.raises(DesignFileError) as exc:
        design(tmp_path, body).verify()
    return str(exc.value)


def test_errors_have_key_paths(tmp_path):
    msg = errors_of(tmp_path, BOLTED.replace('"285, 185"', '"298, 185"'))
    assert "components.base.holes[0].centers[2]: the hole of 6.6 mm at (298, 185) lies across the plate's edge" in msg
    msg = errors_of(tmp_path, BOLTED.replace('"15, 185"', '"15; 185"'))
    assert 'components.base.holes[0].centers[3]: expected a point "x, y"' in msg
    msg = errors_of(tmp_path, BOLTED.replace('holes = ["bolt"]', 'holes = ["blot"]'))
    assert "components.base.supports[0].holes[0]: no hole or hole group 'blot'; did you mean 'bolt'?" in msg
    msg = errors_of(tmp_path, BOLTED.replace('type = "fixed"', 'type = "fixd"'))
    assert "supports[0].type: expected fixed or pinned, got 'fixd'; did you mean 'fixed'?" in msg
    msg = errors_of(tmp_path, BOLTED.replace('size = "80, 60"', 'size = "80 N, 60"'))
    assert "components.base.cutouts[0].size: expected a length" in msg
    msg = errors_of(tmp_path, BOLTED.replace('center = "150, 150"', 'center = "150, 150", polygon = ["0, 0"]'))
    assert "load_cases.lift.base.patch_loads[0]: give either polygon" in msg
    msg = errors_of(tmp_path, BOLTED.replace('force = "-400 N"', 'force = "-400 N", pressure = "1 kPa"'))
    assert "load_cases.lift.base.patch_loads[0]: give exactly one of force" in msg
    msg = errors_of(tmp_path, BOLTED.replace('width = "300 mm"', 'outline = ["0, 0", "1, 1"]'))
    assert "components.base.outline: give either width and height" in msg
    msg = errors_of(tmp_path, RECT.format(a="400 mm", b="200 mm", support="pinned", h="10 mm").replace(
        'edges = "all"', "edges = [7]"))
    assert "components.p.supports[0].edges[0]: expected an edge index 0..3" in msg
    msg = errors_of(tmp_path, RECT.format(a="400 mm", b="200 mm", support="pinned", h="10 mm").replace(
        'edges = "all"', 'point = "100, 100"'))
    assert "components.p.checks.plate_stress_fea [q]: the plate is not fully supported" in msg
    msg = errors_of(tmp_path, RECT.format(a="400 mm", b="200 mm", support="pinned", h="10 mm").replace(
        'pressure = "10 kPa"', 'point_loads = [{ at = "500, 0", force = "1 N" }]'))
    assert "load_cases.q.p.loads[0]: point load at (500 mm, 0 mm) is not on p" in msg


def test_report_typesets_and_shows_the_contour(tmp_path):
    d = design(tmp_path, BOLTED)
    html = render_html([(d, d.verify())], date="2025-01-01")
    assert 'class="latex"' not in html  # every formula typeset by mathtext, no raw-LaTeX fallback
    assert "von Mises stress at the plate surfaces" in html
    assert html.count("data:image/svg+xml") >= 2  # utilisation chart and the plate contour
