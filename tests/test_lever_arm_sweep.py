"""The lever arm's pose sweep through the design file (component type ``lever_arm_sweep``, issue 19/23 task lever).

Sources and what each expected number is:
- massless links, W at C: the motor torques are the virtual-work generalised forces tau_shoulder = -W b cos varphi,
  tau_elbow = W c cos phi, tau_wrist = W d cos psi (seed 000 Eqs. 36a/40a/38a as corrected in
  mechverify.mechanisms.lever_arm.lever_arm_closed_form; Meriam & Kraige, Statics, 7th ed., Ch. 7). The sweep
  reaches cos = 1 for each (varphi = 0, phi = 0, psi = 0 are on the grid), so the peaks are W b, W c, W d: a hand
  calculation from those formulas, not a printed value (the document gives W symbolically, no number);
- with the links' self-weight the shoulder torque at varphi = 0 is g b (m_EA + m_AB + m_AG + m_AH + m_BI + m_BC + m_HI
  + (m_OA + m_DE + m_FG)/2) + W b (virtual work with potential energy, Meriam & Kraige Art. 7/3; the bodies'
  motions are written out in tests/examples/test_lever_arm.py), linear in W;
- the largest payload the shoulder stepper holds with SF 1.5: W_max = (T_hold/1.5 - T_self)/(dT/dW) with T_hold =
  66 oz-in (seed 000 Annex 3) = 0.46606 N m; T_self and dT/dW by hand as above, and again from two sweeps (W = 0
  and W = 2 N) of the design file: both against ``mechverify size``;
- the oracle of the rewritten example: the constants run.py pasted into design.toml before (commit 3a376ce), six
  significant digits each, for the outputs that fed them.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError, parse
from mechverify.errors import InputError
from mechverify.mechanisms.lever_arm import LeverArm, pose_grid, sweep_envelope
from mechverify.mechanisms.sweep import sweep_statics

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "lever_arm"
G = 9.80665
b, c, d, p, q, r = 0.200, 0.150, 0.050, 0.030, 0.030, 0.030  # seed 000 Sec. 2.2 [m]
RHO = 2700.0  # 6061-T6 [kg/m^3] (the design's material)
A_MAIN, A_LINK = 20e-3 * 4e-3, 12e-3 * 3e-3  # the ASSUMED flats [m^2]
HOLDING = 66 * 0.0070615518  # 66 ozf in [N m]

ARM = """
[design]
name = "arm"
[parameters]
W = "{W}"
[components.arm]
type = "lever_arm_sweep"
b = "200 mm"
c = "150 mm"
d = "50 mm"
p = "30 mm"
q = "30 mm"
r = "30 mm"
payload = "W"
shoulder_range = ["0 deg", "180 deg"]
elbow_range = ["0 deg", "90 deg"]
wrist_range = ["0 deg", "90 deg"]
step = "{step}"
{extra}
"""


def _arm(W: str = "10 N", step: str = "30 deg", extra: str = "") -> object:
    import tomllib

    return parse(tomllib.loads(ARM.format(W=W, step=step, extra=extra))).components["arm"].obj


def test_massless_peaks_are_w_times_the_lever():
    """Massless links, W = 10 N: peaks W b = 2.000, W c = 1.500, W d = 0.500 N m (hand, corrected Eq. 36a/40a/38a)."""
    a = _arm()
    for motor, lever in (("shoulder", b), ("elbow", c), ("wrist", d)):
        assert a.motors[motor].peak.m_as("N*m") == pytest.approx(10 * lever, rel=1e-9)
    assert a.motors["shoulder"].peak_pose.startswith("varphi 0,")


def test_linear_superposition_equals_a_direct_sweep():
    """The sweep at W from the self-weight and unit-payload sweeps (LinearSweep) equals the statics solved at W
    at every pose: every governing value to 1e-9 (a coarse 45 deg grid keeps it fast)."""
    arm = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")
    masses = {"OA": "43.2 g", "EAB": "38.88 g", "IBC": "17.28 g", "DE": "19.44 g", "HI": "14.58 g"}
    env = sweep_envelope(arm, (0, 180), (0, 90), (0, 90), 45.0, 40.0, masses=masses)
    poses = pose_grid(arm, (0, 180), (0, 90), (0, 90), 45.0, 40.0)
    direct = sweep_statics(poses, lambda x: arm.statics(x, "3.7 N", masses=masses))
    lin = env.member_demands(3.7)
    for key, dm in direct.member_demands().items():
        mine = lin[key.replace(":", "_").replace("-", "")]
        for attr, unit in (("tension", "N"), ("compression", "N"), ("moment", "N*m"), ("shear", "N")):
            assert getattr(mine, attr).m_as(unit) == pytest.approx(getattr(dm, attr).m_as(unit), rel=1e-9, abs=1e-12)
    for name, ad in direct.actuator_demands().items():
        assert env.actuator_demands(3.7)[name].peak.m_as("N*m") == pytest.approx(ad.peak.m_as("N*m"), rel=1e-9)


# the constants run.py wrote into design.toml before this rewrite (commit 3a376ce), as printed there
PRINTED = {
    "shoulder": 0.630676, "elbow": 0.352871, "wrist": 0.109225,
    "OA": (13.9594, 18.5077, 0.630676), "OD": (14.1485, 14.1485, 0.352871), "DE": (18.5308, 14.1485, 0.00476603),
    "EAB_EA": (14.1485, 14.1485, 0.359973), "EAB_AB": (6.53312, 3.82661, 0.359973), "OF": (4.20833, 4.20833, 0.109225),
    "FG": (4.01928, 5.55486, 0.00476603), "GAH_AG": (4.20833, 4.20833, 0.102648), "GAH_AH": (2.98983, 4.17778, 0.102648),
    "HI": (5.37782, 4.04592, 0.00268089), "IBC_BI": (4.00621, 3.14804, 0.102648), "IBC_BC": (0.0, 2.10591, 0.102648),
}


@pytest.fixture(scope="module")
def example():
    return load(EXAMPLE / "design.toml")


def test_example_outputs_equal_the_former_constants(example):
    """Every output that replaced a pasted constant equals it to its six printed digits."""
    a = example.components["arm"]
    for m in ("shoulder", "elbow", "wrist"):
        assert a.motors[m].peak.m_as("N*m") == pytest.approx(PRINTED[m], rel=5e-6)
    for k, v in PRINTED.items():
        if not isinstance(v, tuple):
            continue
        t, cmp, mom = v
        dm = a.members[k]
        assert dm.tension.m_as("N") == pytest.approx(t, rel=5e-6, abs=1e-9)
        assert dm.compression.m_as("N") == pytest.approx(cmp, rel=5e-6)
        assert dm.moment.m_as("N*m") == pytest.approx(mom, rel=5e-6)


def test_example_loads_read_the_outputs(example):
    """The load cases hold the outputs (connections), not numbers: the resolved link loads are the arm's values."""
    lc = example.data.load_cases
    a = example.components["arm"]
    assert lc["envelope_compression"]["OA"]["axial_force"].m_as("N") == pytest.approx(
        -a.members["OA"].compression.m_as("N"))
    assert lc["peak_holding"]["shoulder_motor"]["external_torque"].m_as("N*m") == pytest.approx(
        a.motors["shoulder"].peak.m_as("N*m"))
    text = (EXAMPLE / "design.toml").read_text(encoding="utf-8")
    assert '"arm.shoulder_peak_torque"' in text and "BEGIN generated" not in text


def _masses_kg() -> dict[str, float]:
    m = {"OA": A_MAIN * b, "EA": A_MAIN * p, "AB": A_MAIN * c, "BI": A_MAIN * r, "BC": A_MAIN * d,
         "OD": A_LINK * p, "OF": A_LINK * q, "AG": A_LINK * q, "AH": A_LINK * r, "DE": A_LINK * b, "FG": A_LINK * b,
         "HI": A_LINK * c}
    return {k: v * RHO for k, v in m.items()}


def test_size_payload_against_the_hand_calculation(example):
    """W_max where the shoulder stepper's torque reaches T_hold/1.5, three ways:
    hand: T_self = g b (m_EA + m_AB + m_AG + m_AH + m_BI + m_BC + m_HI + (m_OA + m_DE + m_FG)/2) = 0.230676 N m,
    dT/dW = b = 0.2 m, W_max = (0.466062/1.5 - 0.230676)/0.2 = 0.40016 N;
    two sweeps of the design file (W = 0 and W = 2 N): T_self = T(0), dT/dW = (T(2) - T(0))/2;
    mechverify size --vary parameters.W --until governing --bounds "0.1 N:50 N"."""
    from mechverify.studies.sizing import size

    m = _masses_kg()
    t_self = G * b * (m["EA"] + m["AB"] + m["AG"] + m["AH"] + m["BI"] + m["BC"] + m["HI"]
                      + (m["OA"] + m["DE"] + m["FG"]) / 2)
    w_hand = (HOLDING / 1.5 - t_self) / b
    assert t_self == pytest.approx(0.230676, abs=1e-6) and w_hand == pytest.approx(0.40016, abs=1e-5)

    T0 = example.with_overrides({"parameters.W": "0 N"}).components["arm"].motors["shoulder"].peak.m_as("N*m")
    T2 = example.components["arm"].motors["shoulder"].peak.m_as("N*m")
    slope = (T2 - T0) / 2.0
    assert T0 == pytest.approx(t_self, rel=1e-9) and slope == pytest.approx(b, rel=1e-9)
    w_two_sweeps = (HOLDING / 1.5 - T0) / slope

    res = size(EXAMPLE / "design.toml", "parameters.W", "governing", ("0.1 N", "50 N"))
    assert res.governing == "shoulder_motor.motor_peak_torque"
    assert res.limit == pytest.approx(w_hand, rel=1e-6)
    assert res.limit == pytest.approx(w_two_sweeps, rel=1e-6)


def test_w_moves_every_check(example):
    """Doubling W changes the motor and link demands (the loads are not constants)."""
    v = example.with_overrides({"parameters.W": "4 N"})
    before = {(x.component, x.check, x.load_case.split(" (")[0]): x.demand for x in example.verify()}
    after = {(x.component, x.check, x.load_case.split(" (")[0]): x.demand for x in v.verify()}
    assert before.keys() == after.keys()
    changed = [k for k in before if not math.isclose(before[k].m_as(after[k].units), after[k].magnitude, rel_tol=1e-9)]
    assert len(changed) == len(before)


@pytest.mark.parametrize("extra, where, message", [
    ('links = { OA = "nope" }', "links", "every member needs its link component"),
    ('masses = { XY = "1 g" }', "masses.XY", "not a body of the lever arm"),
    ('min_transmission_angle = "91 deg"', "min_transmission_angle", "no pose of the grid"),
])
def test_bad_input_is_named(extra, where, message):
    with pytest.raises(DesignFileError) as e:
        _arm(extra=extra)
    assert f"components.arm.{where}" in str(e.value) and message in str(e.value)


def test_step_must_be_positive():
    with pytest.raises(DesignFileError, match=r"components\.arm\.step: must be positive"):
        _arm(step="0 deg")


def test_link_length_must_match_the_arm():
    import tomllib

    text = (EXAMPLE / "arm.toml").read_text(encoding="utf-8").replace('length = "150 mm"', 'length = "160 mm"', 1)
    doc = {"design": {"name": "x"}, "parameters": {"W": "2 N"}, **tomllib.loads(text)}
    with pytest.raises(DesignFileError, match=r"components\.arm\.links\.EAB_AB: EAB_AB is 160 mm long"):
        parse(doc)


def test_pose_grid_refuses_a_huge_grid():
    arm = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")
    with pytest.raises(InputError, match="20,000"):
        pose_grid(arm, (0, 180), (0, 90), (0, 90), 0.5, 40.0)
