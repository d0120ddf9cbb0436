"""Reference project 003: RP robot drawing a clover on a vertical board (worked example).

``design.toml`` holds the whole machine from the document's inputs: the arm walks the clover (inverse kinematics,
Lagrange's equations) and hands each joint's motion and load to its drives; the prismatic screw is a
``lead_screw`` given by its geometry. What remains here is the one-off comparison with the document's own
numbers: its peak revolute load torque (0.22 N·m, Fig. 10), its inertia about the revolute axis at full reach
(about 0.026 kg·m², Eq. 8-10), its peak joint speed, its screw torques (§5.1-5.3, at q1 = 90°, the document's
worst case) and the sensor resolutions it quotes.

``python examples/rp_robot/run.py`` prints the comparison and writes ``report.html`` and ``report.pdf``
(add ``--no-pdf`` to skip the PDF).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import numpy as np

from mechverify.units import Q

HERE = Path(__file__).resolve().parent

# ---------------------------------------------------------------- the document's own results (compared, not used)
DOCUMENT = {
    "revolute_peak_load_torque": Q(220, "mN*m"),  # Fig. 10, Eq. 13 (440 mN·m with its SF 2, §4.3)
    "arm_inertia_full_reach": Q(0.026, "kg*m**2"),  # Eq. 8-10 at q2 = 0.49 m (screw, rods, 98 g carriage)
    "revolute_peak_speed": Q(3, "deg/s"),  # §4.3
    "lead_angle": Q(18.75, "deg"),  # Eq. 19
    "raise_torque": Q(2.59, "mN*m"),  # Eq. 24
    "lower_torque": Q(-0.462, "mN*m"),  # Eq. 25
    "reflected_inertia": Q(1.736e-7, "kg*m**2"),  # Eq. 17
    "prismatic_step": Q(0.22, "mm"),  # Presentación 2, §3.1
}
CARRIAGE_MASS = Q(98, "g")  # m_l with the marker (§5.1): the screw numbers at q1 = 90° as the document takes them
G_DOC = Q(9.8, "m/s**2")


def design() -> Any:
    from mechverify.design import load

    return load(HERE / "design.toml")


def arm(d: Any = None) -> Any:
    """The built ``planar_arm`` (path, joint motion, joint efforts; see mechverify.design.adapters.arms)."""
    return (d or design()).data.components["arm"].obj


def revolute_numbers(d: Any = None) -> dict[str, Any]:
    """Peak revolute load torque, largest inertia about the revolute axis, peak joint speeds along the clover."""
    a = arm(d)
    return {
        "revolute_peak_load_torque": Q(float(np.max(np.abs(a.efforts[0]))), "N*m").to("mN*m"),
        "arm_inertia_full_reach": Q(float(np.max(a.q1_inertia)), "kg*m**2"),
        "revolute_peak_speed": Q(float(np.max(np.abs(a.motion.dq1))), "rad/s").to("deg/s"),
        "prismatic_peak_speed": Q(float(np.max(np.abs(a.motion.dq2))), "m/s").to("mm/s"),
        "q2_range": (Q(float(np.min(a.motion.q2)), "m").to("cm"), Q(float(np.max(a.motion.q2)), "m").to("cm")),
    }


def screw_numbers(d: Any = None) -> dict[str, Any]:
    """The power-screw quantities the document computes (§5.1-5.3), by the standard method, for the design's
    screw with the carriage's weight along the axis (q1 = 90°, the document's worst case)."""
    ls = (d or design()).data.components["prismatic_screw"].obj
    s, mu = ls.screw, 0.22
    W = (CARRIAGE_MASS * G_DOC).to("N")
    return {
        "lead_angle": s.lead_angle.to("deg"),
        "raise_torque": s.raise_torque(W, mu).to("mN*m"),
        "lower_torque": s.lower_torque(W, mu).to("mN*m"),
        "efficiency": s.efficiency(mu),
        "backdrive_efficiency": s.backdrive_efficiency(mu),
        "reflected_inertia": s.reflected_inertia(CARRIAGE_MASS).to("kg*m**2"),
    }


def sensor_resolutions(d: Any = None) -> dict[str, Any]:
    """Revolute: 1.2-turn potentiometer on a 10-bit ADC; prismatic: encoder steps of 10° (±5°) on the 8 mm lead."""
    step = Q(1.2 * 360, "deg") / 2**10
    q2_max = float(np.max(arm(d).motion.q2))
    return {
        "revolute_step": step.to("deg"),
        "revolute_counts_over_180deg": Q(180 / step.m_as("deg"), ""),
        "revolute_tip_step": Q(q2_max * step.m_as("rad") * 1e3, "mm"),
        "prismatic_step": (Q(8, "mm") * Q(10, "deg") / Q(360, "deg")).to("mm"),
    }


def comparison(d: Any = None) -> list[tuple[str, Any, Any]]:
    """(quantity, document, mechverify) rows."""
    d = d or design()
    ours = {**revolute_numbers(d), **screw_numbers(d), **sensor_resolutions(d)}
    return [(k, v, ours[k]) for k, v in DOCUMENT.items()]


def main(argv: list[str]) -> int:
    from mechverify.reports import write_report

    d = design()
    rs = d.verify()
    write_report([(d, rs)], HERE / "report.html")
    if "--no-pdf" not in argv:
        write_report([(d, rs)], HERE / "report.pdf")
    for k, doc, ours in comparison(d):
        diff = (ours.to(doc.units).magnitude / doc.magnitude - 1) * 100 if doc.magnitude else math.nan
        print(f"{k:28s} document {doc:~.4g}   mechverify {ours.to(doc.units):~.4g}   ({diff:+.1f} %)")
    for r in rs:
        print(r.summary())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
