"""The Python API behind design files' ``planar_arm`` and plate cut-outs (issue 16: adapters parse and call).

``mechverify.mechanisms.arm_on_path`` does what the ``planar_arm`` adapter did (bodies composed into the arm,
joint motion, efforts, joint inertias); ``components.plates.rectangle_cutout`` the rounded rectangular cut-out of
``plate_fea``. Expected values: the design file's own result (the same computation through the adapter: equal to
the last bit) and closed forms computed here by hand (a point mass m at distance d has inertia m d^2 about the
axis; a quarter circle drawn with 6 chords has the area 6 * r^2 sin(15 deg) / 2). Not printed values.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechverify.components.plates import rectangle_cutout
from mechverify.design import load
from mechverify.errors import InputError
from mechverify.mechanisms import paths as mp
from mechverify.mechanisms.arm_on_path import ArmOnPath, rp_arm_on_path, rr_arm_on_path

ROOT = Path(__file__).resolve().parents[1]


def test_rp_arm_on_path_equals_the_design_file():
    """examples/rp_robot: the arm built through the Python API from the file's inputs (Eqs. 8-9 of the document:
    a 99 g screw and three 8.5 g guide rods of 25 cm, a 98 g carriage, g = 9.8) equals the design file's arm."""
    d = load(ROOT / "examples" / "rp_robot" / "design.toml")
    built = d.data.components["arm"].obj
    assert isinstance(built, ArmOnPath)
    bodies = [mp.LinkBody("rod", "99 g", "25 cm"), *(mp.LinkBody("rod", "8.5 g", "25 cm") for _ in range(3))]
    arm = rp_arm_on_path(built.path, bodies, carriage_mass="98 g", gravity="9.8 m/s^2", q1_min="0 deg",
                         q1_max="180 deg", name="arm")
    for a, b in zip(arm.efforts, built.efforts, strict=True):
        assert np.array_equal(a, b)
    assert np.array_equal(arm.q1_inertia, built.q1_inertia)
    # hand: J = sum m L^2 / 3 of rods about their end, plus the carriage m q2^2
    J = (0.099 + 3 * 0.0085) * 0.25**2 / 3
    assert arm.q1_inertia == pytest.approx(J + 0.098 * arm.motion.q2**2, rel=1e-12)
    assert arm.joint_inertia("q2") == pytest.approx(0.098, rel=1e-12)  # the prismatic joint moves the carriage


def test_rr_arm_joint_inertias_of_a_point_payload():
    """RR arm with massless links and a payload m at the tip: d11 = m |tip|^2 = m (l1^2 + l2^2 + 2 l1 l2 cos q2),
    d22 = m l2^2 (hand calculation)."""
    path = mp.walk_polar(lambda phi: 0.03 + 0 * phi, "5 cm/s", centre=(0.15, 0.15), samples=60)
    arm = rr_arm_on_path(path, "20 cm", "15 cm", payload="0.3 kg", gravity="0 m/s^2")
    q2 = arm.motion.q2
    assert arm.q1_inertia == pytest.approx(0.3 * (0.2**2 + 0.15**2 + 2 * 0.2 * 0.15 * np.cos(q2)), rel=1e-12)
    assert arm.joint_inertia("q1") == pytest.approx(float(np.max(arm.q1_inertia)))
    assert arm.joint_inertia("q2") == pytest.approx(0.3 * 0.15**2, rel=1e-12)


def test_rectangle_cutout_area_and_errors():
    """A 40 x 20 mm cut-out with 5 mm corner radii: area dx dy - 4 (r^2 - 3 r^2 sin 15 deg) (6 chords per quarter
    circle, vertices on the arc); a bare rectangle has its four corners; bad sizes name the key."""
    from shapely.geometry import Polygon

    pts = rectangle_cutout(("10 mm", "20 mm"), ("40 mm", "20 mm"), "5 mm").m_as("m")
    r = 0.005
    assert Polygon(pts).area == pytest.approx(0.04 * 0.02 - 4 * (r * r - 3 * r * r * math.sin(math.pi / 12)),
                                              rel=1e-12)
    assert pts[:, 0].min() == pytest.approx(-0.01) and pts[:, 1].max() == pytest.approx(0.03)
    assert len(rectangle_cutout((0, 0), (4, 2), unit="mm")) == 4
    with pytest.raises(InputError, match="^corner_radius: must be less than half the shorter side"):
        rectangle_cutout((0, 0), (40, 20), 10, unit="mm")
    with pytest.raises(InputError, match="^size: both sides must be positive"):
        rectangle_cutout((0, 0), (40, 0), unit="mm")
