"""A one-way support spring in a frame's natural-frequency check (review 3 finding 25): the eigenvalue analysis is
linear, so the spring is taken as in contact (acting both ways) - the result says so in its notes."""

import math

import pytest

import mechverify.design as mvd

BAR = """
[design]
name = "hinged rigid bar on a spring"
[materials.light]
base = "Structural Steel"
density = "1 kg/m^3"
E = "2000 GPa"
[components.f]
type = "frame"
material = "light"
section = "circle"
diameter = "40 mm"
theory = "euler"
nodes = {{ A = ["0 mm", "0 mm", "0 mm"], B = ["500 mm", "0 mm", "0 mm"] }}
members = [ {{ name = "m", start = "A", end = "B" }} ]
supports = [ {{ at = "A", type = "custom", hold = ["x", "y", "z", "rx", "rz"] }},
             {{ at = "B", type = "spring", springs = {{ y = "1e9 N/m", z = "1e4 N/m" }}{one_way} }} ]
masses = [ {{ at = "B", mass = "1 kg" }} ]
min_frequency = "5 Hz"
modes = 2
[components.f.checks]
frame_stress = false
frame_deflection = false
"""


@pytest.mark.filterwarnings("ignore:.*implausible")  # E = 2000 GPa: a near-rigid bar on purpose
@pytest.mark.parametrize("one_way", [", one_way = { z = \"+\" }", ""])
def test_one_way_spring_is_linearised_and_said_so(tmp_path, one_way):
    """A near-rigid bar hinged at A with a 1 kg mass on a 1e4 N/m spring at its tip: f = sqrt(k/m) / 2π
    = 15.915 Hz (hand calculation, single degree of freedom, the bar's mass 1 kg/m³ negligible). The one-way
    spring gives the same frequency (linearised as in contact) and a note saying so; the two-way spring no note."""
    p = tmp_path / "d.toml"
    p.write_text(BAR.format(one_way=one_way))
    r = next(x for x in mvd.load(p).verify() if x.check == "natural_frequency")
    assert r.capacity.m_as("Hz") == pytest.approx(math.sqrt(1e4 / 1.0) / (2 * math.pi), rel=1e-3)
    said = [n for n in r.notes if "one-way springs are linearised as in contact" in n]
    assert len(said) == (1 if one_way else 0)
