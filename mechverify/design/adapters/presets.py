"""``five_bar`` and ``lever_arm``: the mechanism presets over a workspace with joint limits, and the payload their
motors hold there (check ``workspace_payload``; sizing: ``mechverify size design.toml --vary parameters.W --until
<component>.workspace_payload``). Parsing only: :mod:`mechverify.mechanisms.workspace`."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from mechverify.checks import workspace as wc
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.mechanisms import workspace as ws
from mechverify.units import Q, fmt


@dataclass(frozen=True)
class PresetOnWorkspace:
    name: str
    preset: Any
    capacity: ws.WorkspaceCapacity
    payload: Any
    motor_torques: dict[str, Any]


def _pair(p: Mapping[str, Any], key: str) -> tuple[Any, Any]:
    v = p[key]
    if not isinstance(v, list) or len(v) != 2:
        raise InputError(f"{key}: expected [low, high] lengths, got {v!r}")
    return v[0], v[1]


def _limits(p: Mapping[str, Any], joints: tuple[str, ...], keys: Mapping[str, str]) -> dict[str, tuple]:
    out = {}
    for j in joints:
        k = keys.get(j, j)
        if f"{k}_min" in p and f"{k}_max" in p and not p[f"{k}_max"] > p[f"{k}_min"]:
            raise InputError(f"{k}_max: must be above {k}_min ({fmt(p[f'{k}_min'])}), got {fmt(p[f'{k}_max'])}")
        if f"{k}_min" in p or f"{k}_max" in p:
            out[j] = (p.get(f"{k}_min", Q(-1e6, "deg")), p.get(f"{k}_max", Q(1e6, "deg")))
    return out


def _torques(p: Mapping[str, Any], motors: tuple[str, ...], keys: Mapping[str, str]) -> dict[str, Any]:
    out = {}
    for m in motors:
        k = f"motor_torque_{keys.get(m, m)}"
        v = p.get(k, p.get("motor_torque"))
        if v is None:
            raise InputError(f"{k}: missing (or give motor_torque for every motor)")
        out[m] = v
    return out


_FB_KEYS = {"theta_left": "left", "theta_right": "right"}


def _five_bar(p: Mapping[str, Any], ctx: Any) -> PresetOnWorkspace:
    from mechverify.mechanisms.fivebar import FiveBar

    fb = FiveBar(p["base"], p["proximal_left"], p["distal_left"], p["distal_right"], p["proximal_right"],
                 name=p["_name"])
    T = _torques(p, ws.FIVE_BAR_JOINTS, _FB_KEYS)
    ws.check_grid_size(p.get("samples", 31), len(ws.FIVE_BAR_JOINTS), "samples")
    cap = ws.five_bar_capacity(fb, _pair(p, "x_range"), _pair(p, "y_range"), [T[m] for m in ws.FIVE_BAR_JOINTS],
                               direction=p.get("direction", "-90 deg"), n=p.get("samples", 31),
                               working_mode=p.get("working_mode", "-+"),
                               limits=_limits(p, ws.FIVE_BAR_JOINTS, {}),
                               singular_tol=p.get("singular_tol", 0.05))
    return PresetOnWorkspace(p["_name"], fb, cap, p["payload"], T)


def _lever_arm(p: Mapping[str, Any], ctx: Any) -> PresetOnWorkspace:
    from mechverify.mechanisms.lever_arm import LeverArm

    arm = LeverArm(*(p[k] for k in ("b", "c", "d", "p", "q", "r")), name=p["_name"])
    T = _torques(p, ws.LEVER_ARM_JOINTS, {})
    ws.check_grid_size(p.get("samples", 31), len(ws.LEVER_ARM_JOINTS), "samples")
    cap = ws.lever_arm_capacity(arm, _pair(p, "u_range"), _pair(p, "z_range"), [T[m] for m in ws.LEVER_ARM_JOINTS],
                                wrist=p.get("wrist", "0 deg"), n=p.get("samples", 31),
                                elbow_branch=p.get("elbow_branch", "up"), limits=_limits(p, ws.LEVER_ARM_JOINTS, {}),
                                singular_tol=p.get("singular_tol", 0.05))
    return PresetOnWorkspace(p["_name"], arm, cap, p["payload"], T)


def _check(c: PresetOnWorkspace, loads: Any, ctx: Any) -> Any:
    return wc.check_workspace_payload(c.name, c.capacity, c.payload, c.motor_torques,
                                      required_sf=getattr(ctx, "required_sf", 1.0))


_COMMON = (
    Field("payload", "force", "load at the tool (along direction for the five-bar, a weight for the lever arm)",
          required=True),
    Field("motor_torque", "torque", "holding torque of every motor (or per motor, see motor_torque_<joint>)"),
    Field("samples", "int", "grid points per axis (default 31; points x motors at most "
                            f"{ws.MAX_GRID_VALUES:,}: five_bar <= 707, lever_arm <= 577)"),
    Field("singular_tol", "float", "points whose singularity measure (|sin|) is at or below this are left out "
                                   "(in [0, 1); default 0.05)"),
)
_OUT = (Output("max_payload", "force", "largest load the motors hold everywhere in the limited workspace",
               lambda c, loads: Q(c.capacity.max_load, "N")),
        Output("workspace_fraction", "dimensionless", "share of the grid inside the limited workspace",
               lambda c, loads: Q(c.capacity.fraction, "")))
_CHECKS = (CheckSpec.of(wc.check_workspace_payload, _check),)

REGISTRY.register(ComponentType(
    name="five_bar",
    doc="A five-bar linkage (mechverify.mechanisms.fivebar) over a rectangular workspace grid with joint limits; "
        "the payload both motors hold everywhere (virtual work, massless links).",
    fields=(*(Field(k, "length", d, required=True) for k, d in (
        ("base", "distance between the motor axes"), ("proximal_left", "left crank"),
        ("distal_left", "left distal link"), ("distal_right", "right distal link"), ("proximal_right", "right crank"))),
        Field("x_range", "list", "[low, high] of the workspace grid in x", required=True, item="length"),
        Field("y_range", "list", "[low, high] of the workspace grid in y", required=True, item="length"),
        Field("working_mode", "choice", "inverse-kinematics branch per leg", choices=("++", "+-", "-+", "--")),
        Field("direction", "angle", "direction of the payload force from +x (default -90 deg: a weight)"),
        *(Field(f"theta_{s}_{e}", "angle", f"{s} motor angle limit") for s in ("left", "right")
          for e in ("min", "max")),
        Field("motor_torque_left", "torque", "left motor's holding torque"),
        Field("motor_torque_right", "torque", "right motor's holding torque"),
        *_COMMON),
    build=_five_bar, checks=_CHECKS, outputs=_OUT))

REGISTRY.register(ComponentType(
    name="lever_arm",
    doc="The parallelogram lever arm (seed 000; mechverify.mechanisms.lever_arm) over a (u, z) grid of its plane "
        "with the wrist at a fixed angle and joint limits; the weight the three plane motors hold everywhere.",
    fields=(*(Field(k, "length", f"seed 000 dimension {k}", required=True) for k in ("b", "c", "d", "p", "q", "r")),
            Field("u_range", "list", "[low, high] of the grid along the arm plane's horizontal", required=True,
                  item="length"),
            Field("z_range", "list", "[low, high] of the grid in height", required=True, item="length"),
            Field("wrist", "angle", "wrist angle psi over the grid (default 0 deg)"),
            Field("elbow_branch", "choice", "inverse-kinematics branch", choices=("up", "down")),
            *(Field(f"{j}_{e}", "angle", f"{j} angle limit") for j in ws.LEVER_ARM_JOINTS for e in ("min", "max")),
            *(Field(f"motor_torque_{j}", "torque", f"{j} motor's holding torque") for j in ws.LEVER_ARM_JOINTS),
            *_COMMON),
    build=_lever_arm, checks=_CHECKS, outputs=_OUT))
