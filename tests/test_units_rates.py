"""Rates: a revolution is 2 pi rad, 1 Hz = 1 rev/s = 60 rpm (review 3 finding 17).

pint reads Hz as 1/s and keeps the radian dimensionless, so its own ``Q("1200 rpm").to("Hz")`` is 125.7 Hz and
``Q("9 Hz").to("rpm")`` 85.9 rpm: 2 pi off. Definitions (ISO 80000-3:2006, items 3-15 and 3-16): the rotational
frequency n is revolutions per time (unit s^-1, r/s), the angular velocity omega = 2 pi n (rad/s), and a frequency f
in Hz counts cycles per second. So a speed written "9 Hz" is 9 rev/s = 540 rpm, and an excitation written
"1200 rpm" is 20 Hz. The numbers below are those definitions worked by hand, not the code's output.
"""

from __future__ import annotations

import math
import textwrap

import pytest

from mechverify.design import load
from mechverify.reports.numbers import quantity
from mechverify.units import Q, as_quantity, rate_to, to_si
from tests.builders import LIFT


@pytest.mark.parametrize(("text", "dim", "si"), [
    ("1200 rpm", "frequency", 20.0),                       # 1200 rev/min / 60 s/min
    ("9 Hz", "angular_velocity", 9 * 2 * math.pi),          # 9 rev/s x 2 pi rad/rev
    ("540 rpm", "angular_velocity", 540 * 2 * math.pi / 60),
    ("20 Hz", "frequency", 20.0),
    ("3 rad/s", "angular_velocity", 3.0),
    ("2 pi rad/s", "frequency", 1.0),                      # one revolution per second
    ("1 cycle/s", "frequency", 1.0),
    ("0.5 kHz", "angular_velocity", 500 * 2 * math.pi),
])
def test_rates_convert_with_a_revolution_of_2_pi(text: str, dim: str, si: float) -> None:
    assert to_si(text, dim) == pytest.approx(si, rel=1e-12)
    assert to_si(as_quantity(text, dim), dim) == pytest.approx(si, rel=1e-12)  # the quantity, converted, again


def test_rate_to_and_the_report_display() -> None:
    assert rate_to(Q(1200, "rpm"), "Hz").m == pytest.approx(20.0)
    assert rate_to(Q(9, "Hz"), "rpm").m == pytest.approx(540.0)
    assert quantity(Q(540, "rpm"), unit="Hz") == "9.00 Hz"   # the table printed "540 rpm (56.5 Hz)"
    assert quantity(Q(90.7, "Hz"), unit="rpm") == "5440 rpm"  # review 1's "866 rpm (90.7 Hz)"


def test_screw_speed_in_hz_checks_as_the_same_speed_in_rpm() -> None:
    """The lift's screw at 9 Hz (9 rev/s) is the lift at 540 rpm: the nut pv, critical speed and bearing speed are
    the same numbers (the pv check read 9 Hz as 85.9 rpm and passed at u·SF 0.372 instead of failing at 2.34)."""
    base = load(LIFT)
    hz = base.with_overrides({"parameters.screw_speed": "9 Hz"})
    rpm, in_hz = base.verify(), hz.verify()
    by_key = {(r.component, r.check, r.load_case): r for r in rpm.results}
    compared = 0
    for r in in_hz.results:
        ref = by_key[(r.component, r.check, r.load_case)]
        if r.check in ("nut_pv", "screw_critical_speed", "bearing_speed"):
            assert r.utilisation == pytest.approx(ref.utilisation, rel=1e-9), r.check
            compared += 1
    assert compared >= 3


def test_excitation_band_in_rpm_is_the_band_in_hz(tmp_path) -> None:
    """A cantilever rod with a 2 kg tip mass (f1 about 20.4 Hz): an excitation band of 1000-1500 rpm is 16.7-25 Hz
    and holds f1, so the check fails as with the band written in Hz (it passed: the band was read as 105-157 Hz)."""
    text = textwrap.dedent("""
        [design]
        name = "rod"
        [components.rod]
        type = "frame"
        material = "Structural Steel"
        section = "circle"
        diameter = "20 mm"
        theory = "euler"
        nodes = { A = ["0 mm", "0 mm", "0 mm"], B = ["500 mm", "0 mm", "0 mm"] }
        members = [ { name = "m", start = "A", end = "B" } ]
        supports = [ { at = "A", type = "fixed" } ]
        masses = [ { at = "B", mass = "2 kg" } ]
        excitation_band = BAND
        modes = 4
        [components.rod.checks]
        frame_stress = false
        frame_deflection = false
        """)
    out = {}
    for name, band in (("rpm", '["1000 rpm", "1500 rpm"]'), ("hz", '["16.666666666666667 Hz", "25 Hz"]')):
        p = tmp_path / f"{name}.toml"
        p.write_text(text.replace("BAND", band))
        (r,) = [r for r in load(p).verify().results if r.check == "natural_frequency"]
        out[name] = r
    assert out["rpm"].verdict.value == "fail"
    assert out["rpm"].utilisation == pytest.approx(out["hz"].utilisation, rel=1e-9)
