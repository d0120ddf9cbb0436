"""The solid_fea design-file type (mechverify/design/adapters/solid_fea.py): parse and call, named errors.

Numbers: a cantilever block 200 x 10 x 10 mm fixed at x = 0 with 100 N down at the free end: the tip deflection
PL³/3EI = 1.6 mm (hand calculation from Euler-Bernoulli beam theory, Shigley 10th ed. Table A-9 case 1, not
a printed value); the first frequency 203.8 Hz (tests/validation/test_blevins_cantilever_modes.py).
"""

from __future__ import annotations

from pathlib import Path

import pytest

import mechverify
from mechverify.errors import MechverifyError

BASE = """
[design]
name = "solid test"

[components.bar]
type = "solid_fea"
box = "200, 10, 10"
material = "Structural Steel"
mesh_size = "5 mm"
supports = [{{ named = "xmin" }}]
deflection_limit = "2 mm"
min_frequency = "150 Hz"
modes = 2
{extra}

[load_cases.tip.bar]
forces = [{{ {region}, force = "0, 0, -100" }}]
[load_cases.tip2.bar]
forces = [{{ plane = "x = 200", force = "0, 0, -50 N" }}]
"""


def _load(tmp_path: Path, extra: str = "", region: str = 'named = "xmax"'):
    f = tmp_path / "d.toml"
    f.write_text(BASE.format(extra=extra, region=region))
    return mechverify.load(f)


def test_box_cantilever_checks(tmp_path):
    res = _load(tmp_path).verify()
    by = {r.check: r for r in res}
    assert by["solid_deflection"].demand.m_as("mm") == pytest.approx(1.6, rel=0.03)
    assert by["solid_deflection"].load_case == "tip"  # the larger of the two cases governs
    assert by["natural_frequency"].capacity.m_as("Hz") == pytest.approx(203.8, rel=0.03)
    # root bending stress M/Z = 100·0.2 / (0.01³/6) = 120 MPa (hand calculation); the clamp adds a little
    assert by["solid_stress"].demand.m_as("MPa") == pytest.approx(120, rel=0.1)
    # both load cases were solved on one factorisation
    d = _load(tmp_path)
    d.verify()
    assert len(d["bar"].solved) == 2 and all("(shared)" in r.info.method for r in d["bar"].solved.values())


def test_unknown_face_lists_the_names(tmp_path):
    with pytest.raises(MechverifyError, match=r"'xmaxx'.*valid regions: xmax, xmin, ymax, ymin, zmax, zmin"):
        _load(tmp_path, region='named = "xmaxx"').verify()


def test_too_large_mesh_is_refused_with_estimate(tmp_path):
    d = tmp_path / "d.toml"
    d.write_text(BASE.format(extra="", region='named = "xmax"').replace('box = "200, 10, 10"', 'box = "2000, 2000, 2000"'))
    with pytest.raises(MechverifyError, match=r"unknowns.*mesh_size >="):
        mechverify.load(d).verify()


def test_geometry_must_be_one(tmp_path):
    with pytest.raises(MechverifyError, match="exactly one geometry"):
        _load(tmp_path, extra='stl = "part.stl"')
    with pytest.raises(MechverifyError, match="does not exist"):
        f = tmp_path / "e.toml"
        f.write_text(BASE.format(extra="", region='named = "xmax"').replace('box = "200, 10, 10"', 'step = "no.step"'))
        mechverify.load(f)


def test_example_bracket_runs():
    pytest.importorskip("gmsh")
    path = Path(__file__).parents[1] / "examples" / "solid_bracket" / "design.toml"
    res = mechverify.load(path).verify()
    assert {r.check for r in res} == {"solid_stress", "solid_deflection", "natural_frequency", "buckling_load_factor"}
    assert all(r.verdict == "pass" for r in res)


def test_convergence_check_and_fatigue(tmp_path):
    """The two-mesh check solves again on a finer mesh (mesh_size / 1.5) and reports the change of the peak (119.1
    -> 119.0 MPa, 0.03 %: a WARN naming the refinement against a 0.01 % tolerance); the fatigue check of the field
    runs on request, fully reversed by default (alternating = peak von Mises, mean 0)."""
    extra = ('convergence_check = true\nconvergence_tolerance = 0.0001\n'
             'checks.fatigue_field = true\nfatigue_life = 1e6')
    res = _load(tmp_path, extra=extra).verify()
    by = {r.check: r for r in res}
    stress = by["solid_stress"]
    assert any("two-mesh check" in n and "mesh_size / 1.5" in n for n in stress.notes)
    # the advice is a mesh_size (review finding 7): 5 mm · (0.0001 / 0.000305)^(1/2) = 2.87 mm
    assert any("mesh convergence" in w and "a mesh_size of about 2.8" in w for w in stress.warnings)
    fat = by["fatigue_field"]
    assert fat.load_case == "tip"
    # fully reversed: alternating = the peak von Mises of the case (= solid_stress demand), mean 0
    assert fat.inputs["sigma_a"].m_as("MPa") == pytest.approx(stress.demand.m_as("MPa"), rel=1e-9)
    assert fat.inputs["sigma_m"].m_as("MPa") == 0
    assert fat.verdict == "fail"  # 119 MPa against S_f = 86 MPa at 1e6 cycles (structural steel, Shigley Marin)


def test_gravity_load_case(tmp_path):
    """`gravity = true` in a solid_fea load case (review finding 32: it was refused as "bare number 0.0").
    Self-weight of the 200 x 10 x 10 mm steel cantilever: w = rho g A = 7850 * 9.80665 * 1e-4 = 7.698 N/m,
    tip deflection w L^4 / (8 E I) = 7.698 * 0.2^4 / (8 * 200e9 * 1e-8 / 12) = 9.24e-3 mm (hand calculation,
    Euler-Bernoulli, Shigley 10th ed. Table A-9 case 3; not a printed value)."""
    f = tmp_path / "g.toml"
    f.write_text(BASE.format(extra="", region='named = "xmax"').split("[load_cases.tip.bar]")[0]
                 + "[load_cases.g.bar]\ngravity = true\n")
    by = {r.check: r for r in mechverify.load(f).verify()}
    w = 7850 * 9.80665 * 1e-4
    assert by["solid_deflection"].demand.m_as("mm") == pytest.approx(w * 0.2**4 / (8 * 200e9 * 1e-8 / 12) * 1e3,
                                                                   rel=0.03)
