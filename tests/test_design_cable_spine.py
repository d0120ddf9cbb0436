"""The ``cable_spine`` design-file type: outputs by connection, the buckling check, bad input.

Expected numbers are the package model's API solved again here (mechverify.mechanisms.cable_spine, whose
limits are tested against closed forms in tests/test_mechanisms_cable_spine.py), and Timoshenko & Gere
Sec. 2.18 / Eq. (2-46) for the critical load (hand calculation by fixed-point iteration).
"""

from __future__ import annotations

import math

import pytest

from mechverify.components.springs import CompressionSpring
from mechverify.design import DesignFileError, load
from mechverify.errors import InputError
from mechverify.mechanisms.cable_spine import CableSpine

SPINE = """
[components.neck]
type = "cable_spine"
wire_diameter = "3.07 mm"
mean_diameter = "30 mm"
active_coils = 15
free_length = "100 mm"
material = "A228"
shear_modulus = "79.3 GPa"
elastic_modulus = "206.8 GPa"
weight = "{weight}"
method = "{method}"
cable_rating = "5 N"

[components.spring]
type = "compression_spring"
wire_diameter = "3.07 mm"
mean_diameter = "30 mm"
active_coils = 15
free_length = "100 mm"
material = "A228"
shear_modulus = "79.3 GPa"
elastic_modulus = "206.8 GPa"

[load_cases.tilt]
[load_cases.tilt.neck]
tilt = "{tilt}"
{pan}
[load_cases.tilt.spring]
force = "neck.axial_force"
"""


def _design(tmp_path, weight="1.25 N", tilt="20 deg", method="linear", pan="", spring=True):
    text = SPINE.format(weight=weight, tilt=tilt, method=method, pan=pan)
    if not spring:  # the spring's load would need the (non-existent) equilibrium
        text = text.replace('force = "neck.axial_force"', 'force = "10 N"')
    p = tmp_path / "d.toml"
    p.write_text("[design]\nname = \"spine\"\n" + text)
    return load(p)


def _model(weight: str) -> CableSpine:
    s = CompressionSpring(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", material="A228", G="79.3 GPa", E="206.8 GPa")
    return CableSpine(s, weight=weight)


def test_outputs_feed_the_spring_and_the_checks_run(tmp_path):
    res = _design(tmp_path).verify()
    st = _model("1.25 N").at_tilt("20 deg")
    [b] = res.where(component="neck", check="spine_buckling_ratio")
    assert b.demand.m_as("N") == pytest.approx(st.axial_force, rel=1e-9)
    assert b.capacity.m_as("N") == pytest.approx(st.critical_load, rel=1e-9)
    [t] = res.where(component="neck", check="cable_tension")
    assert t.demand.m_as("N") == pytest.approx(st.tension, rel=1e-9)
    assert t.capacity.m_as("N") == pytest.approx(5)
    [s] = res.where(component="spring", check="spring_static_stress")
    C = 30 / 3.07
    KB = (4 * C + 2) / (4 * C - 3)  # Shigley Eq. (10-5)
    assert s.demand.m_as("Pa") == pytest.approx(KB * 8 * st.axial_force * 0.030 / (math.pi * 3.07e-3**3), rel=1e-3)


def test_weight_above_the_critical_load_is_a_fail_not_a_crash(tmp_path):
    """15 N on a spine whose fixed-free critical load (with shear, Timoshenko & Gere Eq. 2-46) is about 14.2 N:
    the buckling check FAILs with the load ratio; a value read from the missing equilibrium is a named error."""
    with pytest.raises(DesignFileError, match="alone buckles the spine"):
        _design(tmp_path, weight="15 N")
    d = _design(tmp_path, weight="15 N", spring=False)
    res = d.verify()
    [b] = res.where(component="neck", check="spine_buckling_ratio")
    assert not b.passed
    assert b.demand.m_as("N") == pytest.approx(15)
    assert 14 < b.capacity.m_as("N") < 14.5
    assert any("alone buckles" in n for n in b.notes)


def test_pan_between_cables(tmp_path):
    """A pan between cables is the 3D rod (mechverify.mechanisms.cable_spine_3d): the design's cable tension is
    its most loaded cable; midway (60 deg) both pulling cables carry the same tension. The linear model is planar:
    a named error."""
    from mechverify.mechanisms.cable_spine_3d import state_3d

    with pytest.raises(DesignFileError, match="pan between cables .* method = \"elastica\""):
        _design(tmp_path, pan='pan = "60 deg"').verify()
    d = _design(tmp_path, pan='pan = "60 deg"', method="elastica")
    r = d.verify().get("neck", "cable_tension")
    st = state_3d(d["neck"].spine, "20 deg", "60 deg")
    assert st.tensions[0] == pytest.approx(st.tensions[1], rel=1e-8) and st.tensions[2] == 0
    assert r.demand.m_as("N") == pytest.approx(float(max(st.tensions)), rel=1e-9)


@pytest.mark.parametrize("angles", ['["0 deg", "0 deg", "90 deg"]', '["0 deg", "120 deg", "360 deg"]'])
def test_coincident_cable_angles_are_named(tmp_path, angles):
    """Review item 9: two cables on the same anchor angle (modulo 360 deg) were accepted."""
    text = SPINE.format(weight="1.25 N", tilt="20 deg", method="linear", pan="").replace(
        'cable_rating = "5 N"', f'cable_rating = "5 N"\ncable_angles = {angles}', 1)
    p = tmp_path / "d.toml"
    p.write_text("[design]\nname = \"spine\"\n" + text)
    with pytest.raises(DesignFileError, match=r"components\.neck\.cable_angles: cables 0 and [12] have the same "
                                              r"anchor angle"):
        load(p)
    with pytest.raises(InputError, match="cable_angles: cables 0 and 1"):
        CableSpine(_model("1 N").spring, cable_angles=("10 deg", "-350 deg", "90 deg"))
