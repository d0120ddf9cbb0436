"""Reference project 003: RP robot drawing a clover on a vertical board (worked example).

What a design file cannot hold yet is done here with the Python API:

1. The clover path r(phi) = 8 cm - 1.5 cm cos(4 phi) around (12.5 cm, 37.5 cm), walked at the
   document's constant tangential speed of 1.4 cm/s, and the RP inverse kinematics
   q2 = sqrt(x^2 + y^2) (prismatic), q1 = atan2(y, x) (revolute) at every sample. The joint
   motions are written to ``clover_profiles.toml`` as two ``sampled`` profiles, which
   ``design.toml`` includes for the revolute-joint drives.
2. The prismatic joint: the Ø8 mm four-start lead screw with an 8 mm lead is not an ISO 2902
   designation, so it is built with :func:`mechverify.components.threads.generic` (the
   ``lead_screw`` design-file type takes designations only). Its torques, efficiencies,
   back-drivability and reflected inertia come from :class:`~mechverify.components.power_screw.LeadScrew`;
   the motor fits from ``DriveTrain(...).demand(profile)`` and :mod:`mechverify.checks.motors`.
3. Sensor resolutions (potentiometer + 10-bit ADC on the revolute joint, 10° encoder steps on the screw).

``python examples/rp_robot/run.py`` regenerates ``clover_profiles.toml``, ``report.html`` and
``report.pdf`` (add ``--no-pdf`` to skip the PDF).
"""

from __future__ import annotations

import dataclasses
import math
import sys
from pathlib import Path

import numpy as np

from mechverify.checks import motors as mc
from mechverify.checks import screws as sc
from mechverify.checks.result import ResultSet
from mechverify.components.gearheads import gearhead
from mechverify.components.motors import motor
from mechverify.components.power_screw import LeadScrew, Nut
from mechverify.components.threads import generic
from mechverify.components.transmissions import ScrewDrive
from mechverify.motion import profiles as pr
from mechverify.motion.drive_train import DriveTrain, LinearLoad, TorqueDemand
from mechverify.units import Q

HERE = Path(__file__).resolve().parent

# ---------------------------------------------------------------- document data (reference project 003)
CENTRE = (0.125, 0.375)  # clover centre in the robot frame [m] (Eq. 5)
R0, R1, LOBES = 0.08, 0.015, 4  # r(phi) = 8 - 1.5 cos(4 phi) [cm] (Eq. 3)
SPEED = 0.014  # constant tangential speed [m/s] (§5.6, item 3: "aproximadamente 1,4 cm/s")
N_SAMPLES = 400  # samples on one loop (the document used 1021 points; 400 keep the files small)

CARRIAGE_MASS = Q(98, "g")  # m_l with the marker (§5.1)
SCREW_MASS, SCREW_RADIUS = 0.099, 0.004  # kg, m (Eq. 8)
SCREW_INERTIA = Q(0.5 * SCREW_MASS * SCREW_RADIUS**2, "kg*m**2")  # ½ m r² = 7.92e-7 (Eq. 18)
COUPLING_INERTIA = Q(1.8e-7, "kg*m**2")  # Eq. 18
MU_STATIC = 0.22  # steel on bronze, static (Eq. 19 text, Engineering Toolbox)
PITCH_DIAMETER = Q(7.5, "mm")  # d_p assumed by the document (Eq. 19, 24)
LEAD, STARTS = Q(8, "mm"), 4


# ---------------------------------------------------------------- path and inverse kinematics
def clover_path(n: int = N_SAMPLES, speed: float = SPEED) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t [s], x [m], y [m]) of one loop of the clover, equally spaced in arc length (constant speed).

    The polar curve r(phi) is sampled finely, its arc length s(phi) integrated by the trapezoidal rule,
    and phi found at n equal steps of s; t = s / speed. The last sample closes the loop.
    """
    phi = np.linspace(0.0, 2 * math.pi, 20001)
    r = R0 - R1 * np.cos(LOBES * phi)
    dr = LOBES * R1 * np.sin(LOBES * phi)
    ds = np.sqrt(r**2 + dr**2)
    s = np.concatenate([[0.0], np.cumsum(0.5 * (ds[1:] + ds[:-1]) * np.diff(phi))])
    s_k = np.linspace(0.0, s[-1], n + 1)
    phi_k = np.interp(s_k, s, phi)
    r_k = R0 - R1 * np.cos(LOBES * phi_k)
    return s_k / speed, r_k * np.cos(phi_k) + CENTRE[0], r_k * np.sin(phi_k) + CENTRE[1]


def inverse_kinematics(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """RP robot, revolute axis at the origin: q1 = atan2(y, x) [rad], q2 = sqrt(x² + y²) [m] (Eq. 6)."""
    return np.arctan2(y, x), np.hypot(x, y)


def joint_profiles() -> tuple[pr.SampledProfile, pr.SampledProfile]:
    """(revolute, prismatic) sampled profiles along the clover."""
    t, x, y = clover_path()
    q1, q2 = inverse_kinematics(x, y)
    return pr.sampled(Q(t, "s"), Q(q1, "rad")), pr.sampled(Q(t, "s"), Q(q2, "m"))


def screw_angle_profile() -> pr.SampledProfile:
    """The screw's rotation for the prismatic motion: theta = 2 pi q2 / lead."""
    _, pris = joint_profiles()
    s = pris.sample()
    return pr.sampled(Q(s.t, "s"), Q(2 * math.pi * s.x / LEAD.m_as("m"), "rad"))


def write_profiles(path: Path = HERE / "clover_profiles.toml") -> Path:
    """Write the two joint motions as ``sampled`` profiles (times in s, angles in deg, lengths in mm)."""
    t, x, y = clover_path()
    q1, q2 = inverse_kinematics(x, y)

    def arr(values: np.ndarray, unit: str) -> str:
        items = [f'"{v:.6f} {unit}"' for v in values]
        return "[\n" + ",\n".join("  " + ", ".join(items[i:i + 6]) for i in range(0, len(items), 6)) + ",\n]"

    text = (
        "# Generated by examples/rp_robot/run.py: the clover path of reference project 003 (Eq. 3, 5) walked at\n"
        f"# {SPEED * 100:g} cm/s, {N_SAMPLES} samples equally spaced in arc length, joint motions by the RP inverse\n"
        "# kinematics q1 = atan2(y, x), q2 = sqrt(x^2 + y^2) (Eq. 6). Do not edit by hand.\n\n"
        "[profiles.clover_revolute]\ntype = \"sampled\"\n"
        f"t = {arr(t, 's')}\nx = {arr(np.degrees(q1), 'deg')}\n\n"
        "[profiles.clover_prismatic]\ntype = \"sampled\"\n"
        f"t = {arr(t, 's')}\nx = {arr(q2 * 1e3, 'mm')}\n"
    )
    path.write_text(text, encoding="utf-8")
    return path


# ---------------------------------------------------------------- prismatic joint: screw and motor fits
def lead_screw(d2: Q = PITCH_DIAMETER) -> LeadScrew:
    """The Ø8 mm, 4-start, 8 mm-lead screw; Acme form (29°, flank 14.5°) as the document names it."""
    thread = generic(LEAD, STARTS, d2, flank_angle="14.5 deg",
                     designation=f"Ø8 Acme 4-start, lead 8 mm, d2 {d2.m_as('mm'):g} mm (003)")
    return LeadScrew(thread=thread, length="250 mm", name="prismatic screw")


def nut() -> Nut:
    return Nut(mu=MU_STATIC, name="bronze nut")


def carriage_weight() -> Q:
    return (CARRIAGE_MASS * Q(9.8, "m/s**2")).to("N")  # the document's g = 9.8 m/s²


def screw_numbers() -> dict[str, Q]:
    """The power-screw quantities the document computes (§5.1-5.3), by the standard method."""
    s, W = lead_screw(), carriage_weight()
    return {
        "lead_angle": s.lead_angle.to("deg"),
        "raise_torque": s.raise_torque(W, MU_STATIC).to("mN*m"),
        "lower_torque": s.lower_torque(W, MU_STATIC).to("mN*m"),
        "efficiency": s.efficiency(MU_STATIC),
        "backdrive_efficiency": s.backdrive_efficiency(MU_STATIC),
        "reflected_inertia": s.reflected_inertia(CARRIAGE_MASS).to("kg*m**2"),
        "total_inertia": (SCREW_INERTIA + COUPLING_INERTIA + s.reflected_inertia(CARRIAGE_MASS)).to("kg*m**2"),
    }


def prismatic_demand(motor_name: str, gearhead_name: str | None) -> TorqueDemand:
    """Torque demand at the motor for the clover's prismatic motion, axis vertical (q1 = 90°, worst case)."""
    stages = [] if gearhead_name is None else [gearhead(gearhead_name)]
    stages.append(ScrewDrive(lead_screw(), MU_STATIC, inertia=SCREW_INERTIA + COUPLING_INERTIA, name="lead screw"))
    load = LinearLoad(mass=CARRIAGE_MASS, incline="90 deg", name="carriage")
    name = f"prismatic ({motor_name}{' + ' + gearhead_name if gearhead_name else ''})"
    train = DriveTrain(motor(motor_name), tuple(stages), load, name=name)
    return train.demand(joint_profiles()[1])


def python_results(safety_factors: dict[str, float] | None = None) -> ResultSet:
    """Checks the design file cannot express yet: the screw (generic thread) and the prismatic drives.

    Each result gets the required safety factor of its class from ``safety_factors`` (the design's
    ``[requirements.safety_factors]``), as the design-file framework would give it.
    """
    from mechverify.design import adapters  # noqa: F401  (registers the component types)
    from mechverify.design.spec import DEFAULT_SAFETY_FACTORS, REGISTRY

    sf = {**DEFAULT_SAFETY_FACTORS, **(safety_factors or {})}
    kind = {c.name: c.sf_kind for t in ("drive", "lead_screw") for c in REGISTRY.types[t].checks}
    screw, n = lead_screw(), nut()
    tagged = [("prismatic_screw", sc.check_self_locking(screw, n))]
    for comp, motor_name, gear in (("prismatic_maxon", "maxon RE13", "GP 13 A 17:1"),
                                   ("prismatic_pololu", "Pololu 150:1", None)):
        dem = prismatic_demand(motor_name, gear)
        tagged += [(comp, r) for r in mc.motor_fit_checks(dem, margin=sf["motor"])]
    out = [dataclasses.replace(r, component=comp, required_sf=sf[kind[r.check]]) for comp, r in tagged]
    return ResultSet(out, "prismatic joint (Python API)")


# ---------------------------------------------------------------- sensors
def sensor_resolutions() -> dict[str, Q]:
    """Revolute: 1.2-turn potentiometer on a 10-bit ADC; prismatic: encoder steps of 10° (±5°) on the screw."""
    pot_range = Q(1.2 * 360, "deg")
    step = pot_range / 2**10
    q2_max = float(np.max(inverse_kinematics(*clover_path()[1:])[1]))
    return {
        "revolute_step": step.to("deg"),
        "revolute_counts_over_180deg": Q(180 / step.m_as("deg"), ""),
        "revolute_tip_step": Q(q2_max * step.m_as("rad") * 1e3, "mm"),
        "prismatic_step": (LEAD * Q(10, "deg") / Q(360, "deg")).to("mm"),
    }


def main(argv: list[str]) -> int:
    from mechverify.design import load
    from mechverify.reports import write_report

    write_profiles()
    design = load(HERE / "design.toml")
    rs_design = design.verify()
    rs = ResultSet(list(rs_design) + list(python_results(dict(design.data.safety_factors))), rs_design.name)
    write_report([(design, rs)], HERE / "report.html")
    if "--no-pdf" not in argv:
        write_report([(design, rs)], HERE / "report.pdf")
    for k, v in {**screw_numbers(), **sensor_resolutions()}.items():
        print(f"{k:30s} {v:~.4g}")
    for r in rs:
        print(r.summary())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
