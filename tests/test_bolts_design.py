"""Design-file types bolted_joint and bolt_group: parsing, checks per load case, named errors with key paths."""

from __future__ import annotations

import pytest

from mechverify import design
from mechverify.design.loader import DesignFileError

BASE = """
[design]
name = "bolt test"

[components.flange]
type = "bolted_joint"
thread = "{thread}"
property_class = "8.8"
length = "45 mm"
parts = [{{ thickness = "10 mm", material = "S235JR" }}, {{ thickness = "10 mm", material = "S235JR" }}]
{extra}

[components.group]
type = "bolt_group"
thread = "M8"
length = "35 mm"
head = "socket"
parts = [{{ thickness = "8 mm", material = "S235JR" }}, {{ thickness = "8 mm", material = "S235JR" }}]
positions = ["0, 0", "80, 0", "80, 120", "0, 120"]
mu_interface = 0.15

[load_cases.run.flange]
axial_force = "5 kN"
transverse_force = "1 kN"
temperature_change = "20 K"
[load_cases.run.group]
axial_force = "2 kN"
moment_x = "300 N*m"
force_x = "800 N"
"""


def _load(tmp_path, thread="M10", extra="mu_interface = 0.15"):
    p = tmp_path / "d.toml"
    p.write_text(BASE.format(thread=thread, extra=extra))
    return design.load(p)


def test_joint_and_group_run_every_check(tmp_path):
    rs = list(_load(tmp_path).verify())
    names = {(r.component, r.check) for r in rs}
    for comp in ("flange", "group"):
        for chk in ("bolt_assembly_stress", "bolt_required_preload", "bolt_working_stress", "bolt_fatigue", "bolt_surface_pressure_head",
                    "bolt_surface_pressure_nut", "bolt_thread_stripping", "bolt_separation", "bolt_slip",
                    "bolt_tightening_torque"):
            assert (comp, chk) in names
    group = {r.check: r for r in rs if r.component == "group"}
    # moment_x = 300 N m over rows 120 mm apart: the top bolts (3, 4) carry 500 + 1250 N, they govern
    assert group["bolt_working_stress"].details["governing_bolt"] in ("3", "4")
    per = dict(group["bolt_separation"].details["per_bolt"])
    assert per["3"] == pytest.approx(per["4"]) and per["3"] > per["1"]
    assert "every bolt alike" in group["bolt_assembly_stress"].title


def test_unknown_size_is_a_design_file_error(tmp_path):
    with pytest.raises(DesignFileError, match="M11.*(M10|M12)"):
        _load(tmp_path, thread="M11")


def test_transverse_load_without_friction_is_named(tmp_path):
    """A transverse load on a joint declared without mu_interface: a design-file error naming the check and case."""
    d = _load(tmp_path, extra="")
    with pytest.raises(DesignFileError, match=r"components.flange.checks.bolt_slip \[run\].*mu_T"):
        d.verify()


def test_negative_friction_is_rejected(tmp_path):
    with pytest.raises(DesignFileError, match="negative"):
        _load(tmp_path, extra="mu_thread = [-0.1, 0.12]\nmu_interface = 0.15")


def test_report_figures(tmp_path):
    """The joint diagram (with the per-bolt bars for a group) and the torque-table figure render as SVG."""
    from mechverify.reports.plots import figure_for

    rs = {(r.component, r.check): r for r in _load(tmp_path).verify()}
    for key in (("flange", "bolt_working_stress"), ("group", "bolt_separation"), ("flange", "bolt_tightening_torque")):
        uri = figure_for(rs[key])
        assert uri is not None and uri.startswith("data:image/svg+xml;base64,")


PLATE = """
[design]
name = "plate on four bolts"

[components.p]
type = "plate_fea"
width = "200 mm"
height = "200 mm"
thickness = "5 mm"
material = "S235JR"
holes = [{ name = "b", diameter = "6.6 mm", centers = ["30, 30", "170, 30", "170, 170", "30, 170"] }]
supports = [{ holes = ["b"], type = "fixed", washer_diameter = "11 mm" }]
mesh_size = "20 mm"
hole_mesh_size = "3 mm"

[components.j]
type = "bolted_joint"
thread = "M6"
length = "20 mm"
parts = [{ thickness = "5 mm", material = "S235JR" }, { thickness = "5 mm", material = "S235JR" }]

[components.g]
type = "bolt_group"
thread = "M6"
length = "20 mm"
parts = [{ thickness = "5 mm", material = "S235JR" }, { thickness = "5 mm", material = "S235JR" }]
positions = ["30, 30", "170, 30", "170, 170", "30, 170"]

[load_cases.pull.p]
point_loads = [{ at = "100, 100", force = "2000 N" }]
[load_cases.pull.j]
axial_force = "p.bolt_tension_max"
[load_cases.pull.g]
axial_force = "p.bolt_force_total"
moment_x = "p.bolt_moment_x"
moment_y = "p.bolt_moment_y"
"""


def test_plate_fea_bolt_reactions_feed_the_joints(tmp_path):
    """A square plate on four symmetric bolt-hole supports pulled by 2000 N at its centre: by statics the hole
    forces sum to 2000 N exactly and, by symmetry, each is 500 N (here within 2 %: the gmsh mesh is not symmetric);
    the connections "p.bolt_tension_max" / "p.bolt_force_total" carry these FEA reactions into the bolt checks."""
    from mechverify.design.adapters.bolts import hole_support_forces

    path = tmp_path / "p.toml"
    path.write_text(PLATE)
    d = design.load(path)
    forces = hole_support_forces(d.data.components["p"].obj, d.data.load_cases["pull"]["p"])
    assert sum(t for _, t in forces.values()) == pytest.approx(2000, rel=1e-9)
    assert [t for _, t in forces.values()] == pytest.approx([500] * 4, rel=0.02)
    rs = d.verify()
    assert rs.get("j", "bolt_working_stress").inputs["F_A"].m_as("N") == pytest.approx(max(
        t for _, t in forces.values()), rel=1e-9)
    g = rs.get("g", "bolt_separation")
    assert g.inputs["F_A"].m_as("N") == pytest.approx(500, rel=0.02)
