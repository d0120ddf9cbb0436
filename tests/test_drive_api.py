"""The Python API of a drive gives what a design file's ``drive`` gives (issue 16: no check or load
composition only behind the design file).

No published numbers here: the motor-fit numbers themselves are validated in tests/test_motor_fit.py and
tests/test_design_drives.py; this test proves that :func:`mechverify.checks.drives.drive_checks` on
:class:`mechverify.motion.drive.Drive` reproduces the design file's results exactly, and that the load
composition of a load case (payload, load_factor) is the hand calculation m' = (m + payload)·k.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mechverify.checks.drives import DRIVE_CHECKS, drive_checks
from mechverify.components.motors import motor
from mechverify.components.transmissions import Drum
from mechverify.design.design import load
from mechverify.errors import InputError
from mechverify.motion import profiles
from mechverify.motion.drive import Drive, load_kind
from mechverify.units import Q

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


def test_drive_checks_in_python_equal_the_design_file_results():
    d = load(LIFT)
    from_file = {(r.check, r.load_case): r for r in d.verify() if r.component == "lift"}
    assert len(from_file) >= 3
    drive = d.data.components["lift"].obj
    assert isinstance(drive, Drive)
    cases = [(c, comps["lift"]) for c, comps in d.data.load_cases.items() if "lift" in comps]
    ours = drive_checks(drive, cases=cases, profiles=d.profiles, required_sf=d.data.safety_factors["motor"])
    got = {(r.check, r.load_case): r for r in ours}
    assert set(got) == set(from_file)
    for k, r in got.items():
        f = from_file[k]
        assert (r.demand, r.capacity, r.utilisation) == (f.demand, f.capacity, f.utilisation), k
        assert set(r.notes) <= set(f.notes), k  # the framework adds notes of its own (derived inputs, ...)


def test_load_case_composition_is_mass_plus_payload_times_factor():
    prof = profiles.trapezoidal("100 mm", max_velocity="50 mm/s", acceleration="0.5 m/s^2")
    d = Drive.single("axis", motor("NEMA 17 stepper 0.56 N·m (004 Table 8)"), load={"mass": "2 kg"}, profile=prof,
                     stages=[Drum("30 mm", name="drum")])
    assert d.kind == "length" and d.missing_ratings() == []
    m = d.make_load({"payload": Q(1, "kg"), "load_factor": 1.5}).mass_or_inertia_si
    assert m == pytest.approx((2 + 1) * 1.5)  # hand calculation
    [(case, p, [(variant, dem)])] = d.demands()
    assert (case, variant, p) == ("", "", prof)
    assert [r.check for r in drive_checks(d)] == ["motor_peak_torque", "motor_max_speed", "inertia_ratio"]
    with pytest.raises(InputError, match="load_factor"):
        d.make_load({"load_factor": 0})
    with pytest.raises(InputError, match="rotary-load key"):
        load_kind({"mass": Q(1, "kg"), "gravity_torque": Q(1, "N*m")})


def test_every_drive_check_is_a_registered_motor_check():
    from mechverify.checks.registry import CHECKS

    assert {fn.__name__.removeprefix("check_") for fn in DRIVE_CHECKS} <= set(CHECKS)
