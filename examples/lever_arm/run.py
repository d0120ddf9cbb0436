"""Reference project 000 (4-DOF lever arm, motors at the base): kinematics, pose sweep, member and motor loads.

The document (Univ. de Matanzas, 2021) gives the geometry (Sec. 2.1-2.2: b = 200, c = 150, d = 50,
p = q = r = 30 mm), the forward and inverse position analysis (Eqs. 2-24), closed-form member forces and
motor torques for a symbolic load W at the tool point C with massless members (Eqs. 27-40) and the
stepper's data sheet (Annex 3, SureStep STP-42D3018). It sizes nothing: no payload value, no link
sections, no motor check. This script does, with the Python API:

1. Kinematics: ``LeverArm.forward``/``inverse`` at a reference pose, next to the document's printed
   Eqs. (5), (7), (12)-(14) and (21)-(24) evaluated as printed.
2. Statics at the reference pose (W = 10 N, massless, as in the document): the nine-body solver's pin
   forces and motor torques next to the document's Eqs. (28)-(40) evaluated as printed.
3. The designs (``design.toml``, ``design_corrected.toml``): the pose sweep with the links' self-weight is
   the component ``arm`` of ``arm.toml`` (type ``lever_arm_sweep``), computed when a design is verified; its
   outputs (each motor's peak holding torque, each member's governing tension, compression and moment) are
   the load cases' values, so ``[parameters] W`` drives every check. This script prints the governing pose
   of each output and the check results, and writes ``report.html`` and ``report.pdf`` (``--no-pdf`` skips
   the PDF). The largest payload: ``mechverify size examples/lever_arm/design.toml --vary parameters.W
   --until governing --bounds "0.1 N:50 N"``.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from mechverify.mechanisms.lever_arm import LeverArm, LeverArmPose
from mechverify.units import Q

HERE = Path(__file__).resolve().parent

# ---------------------------------------------------------------- document data (reference project 000)
DIMENSIONS = dict(b="200 mm", c="150 mm", d="50 mm", p="30 mm", q="30 mm", r="30 mm")  # Sec. 2.2, Fig. 2
REFERENCE_POSE = dict(base="30 deg", shoulder="70 deg", elbow="20 deg", wrist="10 deg")  # for the comparison
REFERENCE_LOAD = Q(10, "N")  # W is symbolic in the document; 10 N makes per-newton values easy to read

# ---------------------------------------------------------------- assumptions (the document gives none)
MIN_TRANSMISSION_ANGLE = 40.0  # deg: as arm.toml's min_transmission_angle (Alt's guideline, see the docs page)


def arm() -> LeverArm:
    return LeverArm(**DIMENSIONS, name="lever arm (000)")


def reference_pose() -> LeverArmPose:
    return arm().forward(**REFERENCE_POSE)


# ---------------------------------------------------------------- the document's printed formulas
def document_kinematics(pose: LeverArmPose) -> dict[str, np.ndarray]:
    """Points as the document prints them (Eqs. 5, 7, 12-14; A terms with the elbow angle phi) [mm]."""
    b, c, d, p, q, r = (Q(v).m_as("mm") for v in DIMENSIONS.values())
    vp, ph, ps, th = (a.m_as("rad") for a in (pose.shoulder, pose.elbow, pose.wrist, pose.base))
    B = np.array([-b * math.cos(ph) + c * math.cos(ph), b * math.sin(ph) - c * math.sin(ph)])  # Eq. (5), (13)
    G = np.array([-b * math.cos(ph) + q * math.cos(ps), b * math.sin(ph) + q * math.sin(ps)])  # Eq. (7)
    A = np.array([-b * math.cos(ph), b * math.sin(ph)])  # Eq. (12)
    u_c = -b * math.cos(ph) + c * math.cos(ph) + d * math.cos(ps)  # Eq. (14)
    C = np.array([u_c * math.cos(th), u_c * math.sin(th), b * math.sin(ph) - c * math.sin(ph) + d * math.sin(ps)])
    return {"A": A, "B": B, "G": G, "C": C}


def document_inverse(tool_mm: np.ndarray, wrist_deg: float) -> dict[str, float]:
    """The document's inverse analysis as printed: theta = tan^-1(y0/x0) (Eq. 21), r_B (22), t (23), lambda (24)."""
    d = Q(DIMENSIONS["d"]).m_as("mm")
    x0, y0, z0 = tool_mm
    ps = math.radians(wrist_deg)
    theta = math.atan(y0 / x0) if x0 != 0 else float("nan")  # Eq. (21): tan^-1 loses the quadrant, fails at x0 = 0
    xb, yb, zb = x0 - d * math.cos(ps) * math.cos(theta), y0 - d * math.cos(ps) * math.sin(theta), z0 - d * math.sin(ps)
    t = math.sqrt(xb**2 + yb**2 + zb**2)
    return {"theta": math.degrees(theta), "t": t, "lambda": math.degrees(math.asin(zb / t))}


def document_statics(pose: LeverArmPose, W: Q) -> dict[str, np.ndarray]:
    """Eqs. (28a)-(40b) evaluated exactly as printed: (i', k) components [N] and moments [N m]."""
    b, c, d, p, q, r = (Q(v).m_as("m") for v in DIMENSIONS.values())
    vp, ph, ps = (a.m_as("rad") for a in (pose.shoulder, pose.elbow, pose.wrist))
    w = W.m_as("N")
    cos, sin = math.cos, math.sin
    with np.errstate(divide="ignore", invalid="ignore"):
        den = r * cos(vp + ph)  # the printed (28) divisor: zero at varphi + phi = 90 deg
        k28 = d * cos(vp) / den if abs(den) > 1e-12 else math.inf
        kA = d * cos(ph) * cos(ps) / (r * cos(ph + ps))
        kE = c * cos(vp) * cos(ph) / (p * sin(vp - ph))
        kEz = c * sin(vp) * cos(ph) / (p * sin(vp - ph))
        kAz = d * sin(ph) * cos(ps) / (r * cos(ph + ps))
        out = {
            "F_I (28a)": np.array([-k28 * cos(ph), k28 * sin(ph)]) * w,
            "F_B (28b)": np.array([k28 * cos(ph), 1 - k28 * sin(ph)]) * w,
            "F_G (30a)": np.array([-d * cos(vp) * cos(ps) / (q * sin(vp + ps)),
                                   d * sin(vp) * cos(ps) / (r * sin(vp + ps))]) * w,
            "F_A (30b)": np.array([-2 * kA, 2 * kAz]) * w,
            "F_E (32a)": np.array([kE, -kEz]) * w,
            "F'_A (32b)": np.array([kA - kE, 1 - kAz + kEz]) * w,
            "F''_A (34)": np.array([-(kA + kE), 1 + kAz + kEz]) * w,
            "M_OA (36a)": np.array([(cos(vp) + d * sin(ph - vp) * cos(ps) / (r * cos(ph + ps))) * w * d]),
            "F_O (36b)": np.array([-(kA + kE), 1 + kAz + kEz]) * w,
            "M_OF (38a)": np.array([-cos(ps) * w * d]),
            "F'_O (38b)": np.array([-d * cos(vp) * cos(ps) / (q * cos(vp + ps)),
                                    d * sin(vp) * cos(ps) / (q * cos(vp + ps))]) * w,
            "M_OD (40a)": np.array([-cos(ph) * w * c]),
            "F''_O (40b)": np.array([kE, kEz]) * w,
        }
    return out


def solver_statics(pose: LeverArmPose, W: Q) -> dict[str, np.ndarray]:
    """The same quantities from the nine-body statics solver (massless, load W down at C)."""
    s = arm().statics(pose, W).solve()

    def f(joint: str, body: str) -> np.ndarray:
        return s.force_on(joint, body).m_as("N")

    tau = {k: v.m_as("N*m") for k, v in s.actuator_efforts.items()}
    return {
        "F_I (28a)": f("I", "IBC"), "F_B (28b)": f("B", "IBC"), "F_G (30a)": f("G", "GAH"),
        "F_A (30b)": f("A_GAH", "GAH"), "F_E (32a)": f("E", "EAB"), "F'_A (32b)": f("A_EAB", "EAB"),
        "F''_A (34)": -(f("A_EAB", "EAB") + f("A_GAH", "GAH")),  # force of EAB and GAH on OA at A
        "M_OA (36a)": np.array([tau["shoulder"]]), "F_O (36b)": f("shoulder", "OA"),
        "M_OF (38a)": np.array([tau["wrist"]]), "F'_O (38b)": f("wrist", "OF"),
        "M_OD (40a)": np.array([tau["elbow"]]), "F''_O (40b)": f("elbow", "OD"),
        "N_DE": np.array([s.axial_forces["DE"].m_as("N")]), "N_FG": np.array([s.axial_forces["FG"].m_as("N")]),
        "N_HI": np.array([s.axial_forces["HI"].m_as("N")]),
    }


# ---------------------------------------------------------------- pose sweep
def transmission_angles(pose: LeverArmPose) -> dict[str, float]:
    """Angle of each parallelogram [deg], 0-90: asin of LeverArm.singularity_measures."""
    return {k: math.degrees(math.asin(min(1.0, v))) for k, v in arm().singularity_measures(pose).items()}


def print_comparison() -> None:
    """The numbers of docs/examples/lever_arm.md: printed formulas against the solver at the reference pose."""
    a, pose = arm(), reference_pose()
    print(f"reference pose {pose.label()}, W = {REFERENCE_LOAD:~}")
    doc = document_kinematics(pose)
    print("points [mm]: correct vs document")
    for k in ("A", "B", "G"):
        print(f"  {k}: {np.round(pose.plane[k] * 1e3, 2)} vs {np.round(doc[k], 2)}")
    print(f"  C (xyz): {np.round(pose.tool.m_as('mm'), 2)} vs {np.round(doc['C'], 2)}")
    for th in (30.0, 135.0):
        p = a.forward(pose.shoulder, pose.elbow, pose.wrist, Q(th, "deg"))
        inv = document_inverse(p.tool.m_as("mm"), pose.wrist.m_as("deg"))
        back = a.inverse(p.tool, pose.wrist, elbow_branch="up")
        print(f"  theta {th:g}: document Eq.21 {inv['theta']:.2f} deg, t {inv['t']:.2f} mm, lambda "
              f"{inv['lambda']:.2f} deg; inverse() -> {back.label()}")
    printed, solved = document_statics(pose, REFERENCE_LOAD), solver_statics(pose, REFERENCE_LOAD)
    print("statics (i', k) [N] or M [N m]: document as printed vs solver")
    for k, v in printed.items():
        print(f"  {k:12s} {np.round(v, 3)} |{np.linalg.norm(v):.4g}|  vs  {np.round(solved[k], 3)} "
              f"|{np.linalg.norm(solved[k]):.4g}|")
    for k in ("N_DE", "N_FG", "N_HI"):
        print(f"  {k} {solved[k][0]:.4g} N")
    print("transmission angles at the reference pose:", {k: round(v, 1) for k, v in transmission_angles(pose).items()})


def main(argv: list[str]) -> int:
    print_comparison()
    from mechverify.design import load
    from mechverify.reports import write_report

    designs = [load(HERE / "design.toml"), load(HERE / "design_corrected.toml")]
    runs = [(d, d.verify()) for d in designs]
    print("the pose sweep (component 'arm' of arm.toml, design.toml's W):")
    for line in designs[0].components["arm"].notes():
        print("  " + line)
    write_report(runs, HERE / "report.html")
    if "--no-pdf" not in argv:
        write_report(runs, HERE / "report.pdf")
    for _, rs in runs:
        for r in rs:
            print(r.summary())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
