"""Planar mechanisms: a general rigid-body statics solver, the five-bar and lever-arm presets, pose sweeps;
the cable-driven spring spine (``cable_spine``, ``cable_spine_3d`` for a pan between cables), paths with the RP,
RR and five-bar arms' kinematics and dynamics (``paths``), workspaces with joint limits and payload capacity
(``workspace``).

Data flow: a preset's kinematics gives a pose, its ``statics(pose, ...)`` builds a
:class:`Mechanism`, :meth:`Mechanism.solve` gives joint reactions, actuator torques and member
diagrams, and :func:`sweep_statics` finds the governing pose of every member and actuator.
"""

from mechverify.errors import renamed
from mechverify.mechanisms.cable_spine import CableSpine, SpineState, UnreachableTiltError, tension_distribution
from mechverify.mechanisms.cable_spine_3d import SpineState3D, state_3d
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.fivebar import FiveBar, FiveBarPose, WorkspaceSample
from mechverify.mechanisms.lever_arm import LeverArm, LeverArmPose, lever_arm_closed_form
from mechverify.mechanisms.paths import (
    JointMotion,
    LinkBody,
    PathSamples,
    RPArm,
    RRArm,
    Timing,
    five_bar_inverse,
    spline_through,
    walk_curve,
    walk_polar,
)
from mechverify.mechanisms.statics import (
    GROUND,
    AppliedForce,
    Body,
    Couple,
    Mechanism,
    MemberLoad,
    Pin,
    Slider,
    StaticsSolution,
    solve_statics,
)
from mechverify.mechanisms.sweep import ActuatorDemand, MemberDemand, SweepResult, sweep_statics
from mechverify.mechanisms.workspace import WorkspaceCapacity, five_bar_capacity, lever_arm_capacity

__all__ = [
    "GROUND", "Body", "Pin", "Slider", "AppliedForce", "Couple", "Mechanism", "StaticsSolution", "MemberLoad",
    "solve_statics", "FiveBar", "FiveBarPose", "WorkspaceSample", "LeverArm", "LeverArmPose",
    "lever_arm_closed_form", "SweepResult", "MemberDemand", "ActuatorDemand", "sweep_statics",
    "UnreachablePoseError", "SingularPoseError", "CableSpine", "SpineState", "UnreachableTiltError",
    "tension_distribution", "PathSamples", "RPArm", "JointMotion", "walk_polar", "walk_curve", "spline_through",
    "Timing", "RRArm", "LinkBody", "five_bar_inverse", "SpineState3D",
    "state_3d", "WorkspaceCapacity", "five_bar_capacity", "lever_arm_capacity",
]

# Former names (issue 16: one meaning per public class name across the package; one JointMotion for the RP, RR
# and five-bar arms), deprecated.
__getattr__ = renamed(__name__, {"PointLoad": "AppliedForce", "RPJointMotion": "JointMotion",
                                 "RRJointMotion": "JointMotion", "FiveBarJointMotion": "JointMotion"})
