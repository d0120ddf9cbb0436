"""Reference project 002 (five-bar pick-and-place manipulator, ESPOL 2017): critical pose, link structure,
payload, motor and gearhead.

The document analyses the mechanism's kinematics and dynamics (Sec. 2.3), picks the "critical pose" with both
legs straight (Sec. 2.4.2), checks the links with ANSYS under the out-of-plane weight of gripper and object at
the tool point (Sec. 3: PLA links 1.5 N, SF 3.9, 3.3 mm; steel links 15 N, SF 3.56, fatigue SF 1.229 at 1e6
cycles) and selects NEMA-17 steppers with 100:1 gearheads (Sec. 2.5, Table 2.20). This script:

1. Kinematics (``FiveBar``): the critical pose from inverse kinematics, next to the document's printed angles.
2. The document's own FEA numbers scaled linearly (no section needed): the payload that meets its criteria.
3. The link grillage of ``design.toml`` (beam FEA, ``mechverify.fea.frame``) for 1 N: deflection and stress per
   newton, and the payload that meets the criteria with the assumed section and the links' own weight.
4. Motor and gearhead: torque of the out-of-plane payload about the vertical motor axes (virtual work), the
   axial load and tilting moment on each gearhead shaft (frame reactions), the in-plane force the gearhead's
   3 N·m permits over the workspace.
5. ``mechverify check`` of design.toml and design_corrected.toml, writing report(.html/.pdf) and
   report_corrected(.html/.pdf) here.

``python examples/five_bar/run.py`` (``--no-pdf`` skips the PDFs).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from mechverify.components.gearheads import gearhead
from mechverify.design import load
from mechverify.mechanisms.fivebar import FiveBar
from mechverify.units import Q

HERE = Path(__file__).resolve().parent
G = 9.80665

# ---------------------------------------------------------------- document data (reference project 002)
LINK = "100 mm"  # every link and the base, Sec. 2.3
PRINTED_ANGLES = ("76.4 deg", "103.6 deg")  # Sec. 2.4.2: "theta2 = 76,4 y theta5 = 103,6"
PLA_LOAD, PLA_SF, PLA_DEFLECTION = 1.5, 3.9, 3.3  # Sec. 3 [N], [-], [mm]
STEEL_LOAD, STEEL_SF, STEEL_FATIGUE_SF = 15.0, 3.56, 1.229  # Sec. 3
OBJECT_MASS = 0.077  # kg, "0,077 kg" (Sec. 3)
REQUIRED_SF = 4.0  # Sec. 2.4.2 / 2.4.3
DEFLECTION_LIMITS = {"1 mm (1 % of the 100 mm links, Sec. 2.4.2)": 1.0,
                     "2 mm (1 % of the 200 mm leg)": 2.0,
                     "2.68 mm (the document's '2 % of the beam', Sec. 3)": 2.68}
GEARHEAD = "PG100"  # STEPPERONLINE 100:1 of the 17HS19-1684S-PG100 (Table 2.20)
AXIAL_LIMIT = 50.0  # N, "Máxima Carga Axial aplicable el Eje" (Table 2.20)


def five_bar() -> FiveBar:
    return FiveBar(LINK, LINK, LINK, LINK, LINK, name="002 five-bar")


def critical_pose():
    """Both legs straight: P on the base's mid-line at 2 x 100 mm from each motor (type-1 singular for both legs)."""
    fb = five_bar()
    y = math.sqrt(0.2**2 - 0.05**2)
    return fb.inverse((Q(0.05, "m"), Q(y, "m")), "-+")


def document_scaling() -> dict[str, float]:
    """The payload that meets the document's criteria from its own FEA results (linear in the load)."""
    gripper = PLA_LOAD - OBJECT_MASS * G  # 1.5 N = gripper + object (Sec. 3)
    out = {"gripper_weight": gripper}
    out["F_static_sf4"] = PLA_LOAD * PLA_SF / REQUIRED_SF
    for name, lim in DEFLECTION_LIMITS.items():
        out[f"F_deflection {name}"] = PLA_LOAD * lim / PLA_DEFLECTION
    out["sigma_steel_MPa"] = 250.0 / STEEL_SF  # ANSYS Structural Steel Sy = 250 MPa
    out["sigma_pla_MPa_from_steel"] = out["sigma_steel_MPa"] * PLA_LOAD / STEEL_LOAD
    out["pla_strength_implied_MPa"] = out["sigma_pla_MPa_from_steel"] * PLA_SF
    return out


def frame_per_newton(component: str = "pla_links") -> dict[str, float]:
    """Deflection [mm/N] and stress [MPa/N] of the design's grillage for 1 N at P, and the self-weight effects."""
    design = load(HERE / "design.toml")
    comp = design.data.components[component].obj
    from mechverify.fea.frame import FramePointLoad, FrameSelfWeight

    unit = comp.frame.solve([FramePointLoad("P", force=["0 N", "0 N", "-1 N"])])
    sw = comp.frame.solve([FrameSelfWeight()])
    mat = comp.frame.members[0].material
    return {"delta_per_N": unit.max_displacement.value.m_as("mm"), "sigma_per_N": unit.max_von_mises.value.m_as("MPa"),
            "delta_self": sw.max_displacement.value.m_as("mm"), "sigma_self": sw.max_von_mises.value.m_as("MPa"),
            "Sy": mat.require("yield_strength").m_as("MPa"),
            "reaction_A1": unit.reactions["A1"]}


def payload_capacity(per_newton: dict[str, float], limit_mm: float = 1.0) -> dict[str, float]:
    """Largest load at P with SF >= 4 and deflection <= limit, the links' own weight included (superposition:
    the tip deflection and the root stress of the two cases add; conservative for the stress)."""
    f_sf = (per_newton["Sy"] / REQUIRED_SF - per_newton["sigma_self"]) / per_newton["sigma_per_N"]
    f_def = (limit_mm - per_newton["delta_self"]) / per_newton["delta_per_N"]
    return {"F_static": f_sf, "F_deflection": f_def, "F_max": min(f_sf, f_def)}


def gearhead_fit(point_mm: tuple[float, float] = (50.0, 150.0)) -> dict[str, float]:
    """Motor torques per newton of in-plane force at P (tau = -J^T F, worst direction = the largest singular value
    of the force-to-torque map) at a mid-workspace pose, and the in-plane force the gearhead's rating permits."""
    fb = five_bar()
    pose = fb.inverse((Q(point_mm[0], "mm"), Q(point_mm[1], "mm")), "-+")
    cols = [np.array([t.m_as("N*m") for t in fb.holding_torques(pose, (Q(fx, "N"), Q(fy, "N")))])
            for fx, fy in ((1, 0), (0, 1))]
    k = float(np.linalg.norm(np.column_stack(cols), 2))
    gh = gearhead(GEARHEAD)
    return {"torque_per_N": k, "pose": pose.label(), "theta_left_deg": pose.theta_left.m_as("deg"),
            "theta_right_deg": pose.theta_right.m_as("deg"), "continuous": gh.continuous_torque.m_as("N*m"),
            "intermittent": gh.intermittent_torque.m_as("N*m"), "F_allow": gh.continuous_torque.m_as("N*m") / k,
            "ratio": float(gh.ratio), "efficiency": float(gh.efficiency),
            "motor_torque_for_40Nm": 40.0 / (float(gh.ratio) * float(gh.efficiency))}


def main(argv: list[str]) -> int:
    from mechverify.cli import main as cli

    fb = five_bar()
    pose = critical_pose()
    printed = fb.forward(*PRINTED_ANGLES)
    print("critical pose (both legs straight):", pose.label())
    print("document's printed angles 76.4 / 103.6 deg give:", printed.label(),
          f"(legs bent by {abs(printed.theta_distal_left.m_as('deg') - 76.4):.2f} deg)")
    tau = fb.holding_torques(printed, (Q(0, "N"), Q(0, "N")))
    print("motor torque from the out-of-plane payload (vertical motor axes):", [f"{t:.3g~P}" for t in tau])
    for k, v in document_scaling().items():
        print(f"document scaling: {k} = {v:.4g}")
    pn = frame_per_newton()
    cap = payload_capacity(pn)
    print(f"grillage (PLA, assumed section): {pn['delta_per_N']:.4g} mm/N, {pn['sigma_per_N']:.4g} MPa/N; "
          f"self-weight {pn['delta_self']:.3g} mm, {pn['sigma_self']:.3g} MPa")
    print("payload meeting SF 4 and 1 mm with the assumed section:", {k: round(v, 3) for k, v in cap.items()})
    st = frame_per_newton("steel_links")
    print(f"steel grillage: {st['delta_per_N']:.4g} mm/N, {st['sigma_per_N']:.4g} MPa/N; reactions at A1 for 1 N:",
          st["reaction_A1"])
    gh = gearhead_fit()
    print("gearhead fit:", gh)
    no_pdf = "--no-pdf" in argv
    for design, out in (("design.toml", "report"), ("design_corrected.toml", "report_corrected")):
        for ext in ("html",) if no_pdf else ("html", "pdf"):
            code = cli(["check", str(HERE / design), "--report", str(HERE / f"{out}.{ext}")])
        print(f"mechverify check {design}: exit {code}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
