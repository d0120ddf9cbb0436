"""plate_fea: a load case with `in_plane` loads and a lateral load (review 2 finding 1, session 3: the bending
stress check PASSed at 8.7 MPa while the membrane stress was 1000 MPa, with only a note). The bending model carries
no membrane stress, so plate_stress_fea WARNs with the membrane stress's size.

Number: nx = 2000 N/mm on a 2 mm plate is sigma_x = N/t = 1000 MPa, von Mises 1000 MPa (uniaxial); with
nx = 300 N/mm and ny = -300 N/mm (pure shear in principal axes) sigma_vM = sqrt(3) * 150 = 259.8 MPa (hand
calculations from the von Mises criterion, not printed values)."""

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
[load_cases.pull.panel]
pressure = "1 kPa"
in_plane = {{ {in_plane} }}
"""


def _stress(tmp_path, in_plane):
    f = tmp_path / "m.toml"
    text = DESIGN.format(in_plane=in_plane)
    f.write_text(text if in_plane else text.replace("in_plane = {  }\n", ""))
    checks = [r for r in mechverify.load(f).verify() if r.check == "plate_stress_fea"]
    assert len(checks) == 1
    return checks[0]


def test_membrane_stress_is_named_in_a_warning(tmp_path):
    r = _stress(tmp_path, 'nx = "2000 N/mm"')
    assert r.verdict.value == "warn"
    assert any("membrane stress of 1000 MPa" in w for w in r.warnings)
    plain = _stress(tmp_path, "")  # the same plate without in_plane: no such warning
    assert not any("membrane" in w for w in plain.warnings)
    assert plain.demand == r.demand  # the bending stress itself is the lateral load's


def test_nominal_membrane_von_mises_hand_values():
    bounds = (0.0, 0.0, 0.3, 0.2)
    assert nominal_membrane_von_mises(InPlaneLoad(nx="300 N/mm", ny="-300 N/mm"), bounds, 2e-3) == pytest.approx(
        math.sqrt(3) * 150e6, rel=1e-12)
    # a linear nx from 0 to -400 N/mm across y: the peak at the high side, 200 MPa
    assert nominal_membrane_von_mises(InPlaneLoad(nx=("0 N/mm", "-400 N/mm")), bounds, 2e-3) == pytest.approx(
        200e6, rel=1e-12)
