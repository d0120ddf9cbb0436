"""Workspaces with joint limits and the payload the preset's motors hold over them (mechverify.mechanisms.workspace,
design-file types five_bar and lever_arm, check workspace_payload, sizing).

Expected values are hand calculations: the motor torque of a load F at the tool by virtual work,
tau_i = -F . dP/dq_i (Meriam & Kraige, Engineering Mechanics: Statics, 7th ed., Ch. 7), with dP/dq_i by central
differences of the presets' forward kinematics (independent of the Jacobian/closed forms the package uses);
the lever arm's shoulder torque W b cos(varphi) <= W b gives W_max -> T/b when the grid reaches varphi = 0.
Not printed values.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import FIVE_BAR_LINKS

from mechverify.design import load
from mechverify.errors import InputError
from mechverify.mechanisms.fivebar import FiveBar
from mechverify.mechanisms.lever_arm import LeverArm
from mechverify.mechanisms.workspace import five_bar_capacity, lever_arm_capacity

FB = FiveBar("100 mm", "100 mm", "100 mm", "100 mm", "100 mm")
ARM = LeverArm("200 mm", "150 mm", "50 mm", "30 mm", "30 mm", "30 mm")


def _fd_five_bar(x: float, y: float, force: tuple[float, float]) -> np.ndarray:
    pose = FB.inverse((f"{x} m", f"{y} m"), "-+")
    t1, t2 = pose.theta_left.m_as("rad"), pose.theta_right.m_as("rad")
    mode = pose.assembly_mode
    h = 1e-6
    out = []
    for k in range(2):
        dp = []
        for s in (h, -h):
            a = [t1, t2]
            a[k] += s
            dp.append(FB.forward(f"{a[0]} rad", f"{a[1]} rad", mode).P)
        dPdq = (dp[0] - dp[1]) / (2 * h)
        out.append(-(force[0] * dPdq[0] + force[1] * dPdq[1]))
    return np.array(out)


def test_five_bar_single_point_by_virtual_work():
    """One grid point (40, 120) mm, weight direction: W_max = min_i T_i/|tau_i(1 N)|, tau by finite differences."""
    c = five_bar_capacity(FB, ("40 mm", "40 mm"), ("120 mm", "120 mm"), ("3 N*m", "2 N*m"), n=2)
    tau = _fd_five_bar(0.04, 0.12, (0.0, -1.0))
    assert c.torque_per_load[0] == pytest.approx(tau, rel=1e-6)
    assert c.max_load == pytest.approx(min(3 / abs(tau[0]), 2 / abs(tau[1])), rel=1e-6)
    assert c.inside.all() and c.fraction == 1.0


def test_five_bar_direction_and_limits():
    """A horizontal force (direction 0 deg) by finite differences too; joint limits that exclude the point make
    the workspace empty (a named error); limits that hold it change nothing."""
    c = five_bar_capacity(FB, ("40 mm", "40 mm"), ("120 mm", "120 mm"), ("3 N*m", "3 N*m"), n=2, direction="0 deg")
    assert c.torque_per_load[0] == pytest.approx(_fd_five_bar(0.04, 0.12, (1.0, 0.0)), rel=1e-6)
    th = FB.inverse(("40 mm", "120 mm")).theta_left.m_as("deg")
    with pytest.raises(InputError, match="outside the joint limits: 4"):
        five_bar_capacity(FB, ("40 mm", "40 mm"), ("120 mm", "120 mm"), ("3 N*m", "3 N*m"), n=2,
                          limits={"theta_left": ("0 deg", f"{th - 1} deg")})
    ok = five_bar_capacity(FB, ("40 mm", "40 mm"), ("120 mm", "120 mm"), ("3 N*m", "3 N*m"), n=2, direction="0 deg",
                           limits={"theta_left": (f"{th - 1 + 360} deg", f"{th + 1 + 360} deg")})  # a turn up
    assert ok.max_load == pytest.approx(c.max_load, rel=1e-12)
    with pytest.raises(InputError, match="unknown joint 'theta_middle'"):
        five_bar_capacity(FB, ("0 mm", "1 mm"), ("0 mm", "1 mm"), ("1 N*m", "1 N*m"), limits={"theta_middle": (0, 1)})


def test_five_bar_limits_shrink_the_workspace():
    """Every point kept satisfies the limits; the limited workspace is a subset of the free one."""
    free = five_bar_capacity(FB, ("-50 mm", "150 mm"), ("0 mm", "200 mm"), ("3 N*m", "3 N*m"), n=15)
    lim = five_bar_capacity(FB, ("-50 mm", "150 mm"), ("0 mm", "200 mm"), ("3 N*m", "3 N*m"), n=15,
                            limits={"theta_left": ("0 deg", "120 deg"), "theta_right": ("60 deg", "180 deg")})
    assert np.all(free.inside[lim.inside]) and lim.inside.sum() < free.inside.sum()
    for x, y in lim.points[lim.inside]:
        p = FB.inverse((f"{x} m", f"{y} m"))
        assert -1e-9 <= p.theta_left.m_as("deg") <= 120 + 1e-9 and 60 - 1e-9 <= p.theta_right.m_as("deg") <= 180 + 1e-9
    assert lim.max_load >= free.max_load  # fewer points cannot lower the limit


def test_lever_arm_by_virtual_work_and_shoulder_limit():
    """One point: tau_i = W dC_z/dq_i (weight -z) by finite differences of forward(); the grid through
    varphi = 0 gives W_max -> T_shoulder/b = 1/0.2 = 5 N from above (shoulder governs: elbow 1/0.15, wrist 1/0.05)."""
    pose = ARM.inverse(("250 mm", "0 mm", "50 mm"), "0 deg")
    q = [pose.shoulder.m_as("rad"), pose.elbow.m_as("rad"), pose.wrist.m_as("rad")]
    h, tau = 1e-6, []
    for k in range(3):
        zs = []
        for s in (h, -h):
            a = list(q)
            a[k] += s
            zs.append(ARM.forward(f"{a[0]} rad", f"{a[1]} rad", f"{a[2]} rad").plane["C"][1])
        tau.append((zs[0] - zs[1]) / (2 * h))  # -F . dC/dq with F = (0, -1 N)
    c = lever_arm_capacity(ARM, ("250 mm", "250 mm"), ("50 mm", "50 mm"), ("1 N*m", "1 N*m", "1 N*m"), n=2)
    # magnitudes: the package's motor torques are counter-clockwise, the shoulder and elbow angles run clockwise
    assert np.abs(c.torque_per_load[0]) == pytest.approx(np.abs(tau), rel=1e-6, abs=1e-9)
    g = lever_arm_capacity(ARM, ("50 mm", "350 mm"), ("-100 mm", "300 mm"), ("1 N*m", "1 N*m", "1 N*m"), n=21)
    assert g.governing_motor == "shoulder"
    assert 5.0 <= g.max_load <= 5.0 * 1.01
    lim = lever_arm_capacity(ARM, ("50 mm", "350 mm"), ("-100 mm", "300 mm"), ("1 N*m", "1 N*m", "1 N*m"), n=21,
                             limits={"shoulder": ("30 deg", "150 deg")})
    vp = [ARM.inverse((f"{u} m", "0 m", f"{z} m"), "0 deg").shoulder.m_as("rad") for u, z in lim.points[lim.inside]]
    assert lim.max_load == pytest.approx(1 / (0.2 * max(abs(math.cos(v)) for v in vp)), rel=1e-6)


DESIGN = """
[design]
name = "five-bar payload"

[parameters]
W = "1 N"

[requirements.safety_factors]
motor = 1.5

[components.fb]
""" + FIVE_BAR_LINKS + """x_range = ["-50 mm", "150 mm"]
y_range = ["0 mm", "200 mm"]
samples = 11
motor_torque = "3 N*m"
theta_left_min = "0 deg"
theta_left_max = "150 deg"
payload = "W"
"""


def test_design_file_check_and_sizing(tmp_path):
    """The design file's check is W against W_max (the same grid by the Python API); `mechverify size` on the
    payload parameter finds W = W_max / SF (u SF = W SF / W_max = 1)."""
    from mechverify.cli import main
    from mechverify.studies.sizing import size

    p = tmp_path / "fb.toml"
    p.write_text(DESIGN, encoding="utf-8")
    d = load(p)
    r = d.verify().get("fb", "workspace_payload")
    c = five_bar_capacity(FB, ("-50 mm", "150 mm"), ("0 mm", "200 mm"), ("3 N*m", "3 N*m"), n=11,
                          limits={"theta_left": ("0 deg", "150 deg")})
    assert r.capacity.m_as("N") == pytest.approx(c.max_load, rel=1e-12)
    assert r.demand.m_as("N") == 1.0 and r.required_sf == 1.5
    res = size(p, "parameters.W", "fb.workspace_payload", ("0.01 N", "100 N"))
    assert res.limit == pytest.approx(c.max_load / 1.5, rel=1e-6)
    assert main(["size", str(p), "--vary", "parameters.W", "--until", "fb.workspace_payload",
                 "--bounds", "0.01 N:100 N"]) == 0
    assert d["fb"].capacity.fraction < 1  # the grid's corners are out of reach


def test_workspace_payload_substituted_line(tmp_path):
    """W_max = T/|tau per unit load| with the numbers evaluates back to the check's capacity (issue 25's parser)."""
    import importlib.util
    from pathlib import Path

    spec = importlib.util.spec_from_file_location("_subst", Path(__file__).parent / "test_reports_substituted.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    p = tmp_path / "fb.toml"
    p.write_text(DESIGN, encoding="utf-8")
    r = load(p).verify().get("fb", "workspace_payload")
    mod.assert_substituted(r)


@pytest.mark.parametrize(("old", "new", "message"), [
    ("samples = 11", "samples = 100000", r"components\.fb\.samples: 100000 samples per axis .* use at most 707"),
    ("samples = 11", "samples = 708", r"fb\.samples: .*more than the limit of 1,000,000 values"),
    ("samples = 11", "samples = 1", r"fb\.samples: need at least 2"),
    ("samples = 11", "samples = 11\nsingular_tol = -1", r"components\.fb\.singular_tol: expected a number in \[0, 1\)"),
    ("samples = 11", "samples = 11\nsingular_tol = 1.5", r"fb\.singular_tol: expected a number in \[0, 1\)"),
])
def test_grid_size_and_singular_tol_are_named_at_the_key(tmp_path, old, new, message):
    """Review items 2 and 9: samples = 100000 died with MemoryError (74.5 GiB), singular_tol = -1 was accepted."""
    from mechverify.design.loader import DesignFileError

    p = tmp_path / "fb.toml"
    p.write_text(DESIGN.replace(old, new), encoding="utf-8")
    with pytest.raises(DesignFileError, match=message):
        load(p)


def test_grid_limits_in_the_python_api():
    """The API names n: a float, and n x n x motors above MAX_GRID_VALUES (lever arm: 3 motors, n <= 577)."""
    from mechverify.mechanisms.workspace import MAX_GRID_VALUES

    assert MAX_GRID_VALUES == 1_000_000 and 577**2 * 3 <= MAX_GRID_VALUES < 578**2 * 3
    with pytest.raises(InputError, match="n: expected a whole number"):
        five_bar_capacity(FB, ("0 mm", "100 mm"), ("100 mm", "180 mm"), ("1 N*m", "1 N*m"), n=2.5)
    with pytest.raises(InputError, match="use at most 577"):
        lever_arm_capacity(ARM, ("100 mm", "300 mm"), ("-100 mm", "100 mm"), ("1 N*m",) * 3, n=578)
    with pytest.raises(InputError, match="singular_tol"):
        five_bar_capacity(FB, ("0 mm", "100 mm"), ("100 mm", "180 mm"), ("1 N*m", "1 N*m"), n=5, singular_tol=-1)
