"""The ``lead_screw`` design-file type against hand calculations.

Tr10x2 (ISO 2904: d2 = 9 mm, H1 = 1 mm, P = lead = 2 mm), polymer nut 20 mm long (n = 10 turns),
mu = 0.09..0.25, F = 350 N at 18 mm/s (540 rpm), as in reference project 004.
Formulas: lead angle tan(lambda) = l/(pi d2); normal flank angle tan(alpha_n) = tan(alpha) cos(lambda);
self-locking while lambda <= atan(mu_min/cos(alpha_n)) (Shigley 9th ed. Sec. 8-2, Eq. 8-3 and the
Acme/trapezoidal form; Hamrock 3rd ed. Sec. 16.3); flank pressure p = F/(pi d2 H1 n) (DIN 103,
Roloff/Matek); sliding speed v = pi d2 n_rot / cos(lambda).
"""

import math
import textwrap

import pytest

from mechverify.design import DesignFileError, load

DESIGN = """
[design]
name = "lift"

[components.lift_screw]
type = "lead_screw"
{thread}
length = "450 mm"
material = "Structural Steel"
nut_length = "20 mm"
mu_min = 0.09
mu_max = 0.25
nut_p_allow = "23 MPa"
nut_pv_allow = "0.27 MPa*m/s"

[load_cases.raise.lift_screw]
axial_force = "350 N"
speed = "18 mm/s"
"""


def run(tmp_path, thread='thread = "Tr10x2"'):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(thread=thread)))
    return load(p).verify()


def test_tr10x2_numbers_by_hand(tmp_path):
    rs = run(tmp_path)
    lam = math.atan(2 / (math.pi * 9))
    an = math.atan(math.tan(math.radians(15)) * math.cos(lam))
    rho = math.atan(0.09 / math.cos(an))
    sl = rs.get("lift_screw", "self_locking")
    assert sl.demand.m_as("rad") == pytest.approx(lam, rel=1e-9)
    assert sl.capacity.m_as("rad") == pytest.approx(rho, rel=1e-9)
    assert sl.verdict == "pass"
    p = 350 / (math.pi * 9 * 1 * 10)  # N/mm^2 = MPa
    assert rs.get("lift_screw", "nut_flank_pressure").demand.m_as("MPa") == pytest.approx(p, rel=1e-9)
    v = math.pi * 0.009 * (18 / 2) / math.cos(lam)  # m/s at 9 rev/s
    pv = rs.get("lift_screw", "nut_pv")
    assert pv.demand.m_as("MPa*m/s") == pytest.approx(p * v, rel=1e-9)
    assert pv.verdict == "fail"  # 0.316 > 0.27: the document never checked pv
    assert pv.load_case == "raise"


def test_catalogue_screw_by_lead_and_starts(tmp_path):
    """8 mm lead, 4 starts, d2 = 7 mm (reference project 003): lambda = atan(8/(7 pi)) = 20.0 deg, not self-locking
    at mu_min = 0.09 since mu* = cos(alpha_n) tan(lambda) = 0.352."""
    rs = run(tmp_path, 'lead = "8 mm"\nstarts = 4\npitch_diameter = "7 mm"')
    lam = math.atan(8 / (7 * math.pi))
    sl = rs.get("lift_screw", "self_locking")
    assert sl.demand.m_as("rad") == pytest.approx(lam, rel=1e-9)
    assert sl.verdict == "fail"
    an = math.atan(math.tan(math.radians(15)) * math.cos(lam))
    assert sl.details["self_locking_mu"].m_as("") == pytest.approx(math.cos(an) * math.tan(lam), rel=1e-9)


def test_thread_errors(tmp_path):
    with pytest.raises(DesignFileError, match=r"components.lift_screw: .*did you mean 'Tr10x3'"):
        run(tmp_path, 'thread = "Tr10x4"')
    with pytest.raises(DesignFileError, match=r"components.lift_screw: give either thread"):
        run(tmp_path, 'thread = "Tr10x2"\nlead = "2 mm"')
    with pytest.raises(DesignFileError, match=r"missing: starts, pitch_diameter"):
        run(tmp_path, 'lead = "8 mm"')
    with pytest.raises(DesignFileError, match=r"components.lift_screw.lead: expected a length"):
        run(tmp_path, 'lead = "8 N"\nstarts = 4\npitch_diameter = "7 mm"')
