"""Planar mechanisms: a general rigid-body statics solver, the five-bar and lever-arm presets, pose sweeps;
the cable-driven spring spine (``cable_spine``) and paths with the RP arm's kinematics and dynamics (``paths``).

Data flow: a preset's kinematics gives a pose, its ``statics(pose, ...)`` builds a
:class:`Mechanism`, :meth:`Mechanism.solve` gives joint reactions, actuator torques and member
diagrams, and :func:`sweep_statics` finds the governing pose of every member and actuator.
"""

from mechverify.errors import renamed
from mechverify.mechanisms.cable_spine import CableSpine, SpineState, UnreachableTiltError, tension_distribution
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.fivebar import FiveBar, FiveBarPose, WorkspaceSample
from mechverify.mechanisms.lever_arm import LeverArm, LeverArmPose, lever_arm_closed_form
from mechverify.mechanisms.paths import PathSamples, RPArm, RPJointMotion, walk_polar
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

__all__ = [
    "GROUND", "Body", "Pin", "Slider", "AppliedForce", "Couple", "Mechanism", "StaticsSolution", "MemberLoad",
    "solve_statics", "FiveBar", "FiveBarPose", "WorkspaceSample", "LeverArm", "LeverArmPose",
    "lever_arm_closed_form", "SweepResult", "MemberDemand", "ActuatorDemand", "sweep_statics",
    "UnreachablePoseError", "SingularPoseError", "CableSpine", "SpineState", "UnreachableTiltError",
    "tension_distribution", "PathSamples", "RPArm", "RPJointMotion", "walk_polar",
]

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"PointLoad": "AppliedForce"})
