"""Check of a mechanism preset over its workspace: the payload its motors hold everywhere in the workspace with
joint limits (:mod:`mechverify.mechanisms.workspace`)."""

from __future__ import annotations

from typing import Any

import numpy as np

from mechverify.checks.registry import check
from mechverify.checks.result import CheckResult, tex
from mechverify.references import ref
from mechverify.units import Q, QuantityLike

SOURCE = ref("meriam_kraige7", "Ch. 7 (virtual work: motor torque = generalised force of the load)")


@check("workspace_payload", title="Payload the motors hold over the workspace", sf_kind="motor", source=SOURCE,
       explain=("The payload at the tool against the largest load every motor holds at every point of the "
                "sampled workspace (inverse kinematics closes, joint angles within their limits, away from "
                "singularities): the motor torques per unit load come from virtual work (massless links), so the "
                "limit is min over points and motors of T_motor/|tau per unit load|."))
def check_workspace_payload(name: str, capacity: Any, payload: QuantityLike, motor_torques: dict[str, Any], *,
                            required_sf: float = 1.0, load_case: str = "") -> CheckResult:
    """``payload`` against ``capacity.max_load`` (a :class:`~mechverify.mechanisms.workspace.WorkspaceCapacity`)."""
    c = capacity
    i, m = c.governing_point, c.governing_motor
    j = c.motors.index(m)
    per = abs(float(c.torque_per_load[i, j]))
    T = Q(motor_torques[m]).to("N*m")
    x, y = c.points[i]
    return CheckResult(
        check="workspace_payload", component=name, demand=Q(payload).to("N"), capacity=Q(c.max_load, "N"),
        required_sf=required_sf, title="Payload the motors hold over the workspace",
        formula=r"W \le W_{max} = \min_{points,\,motors} \frac{T_{motor}}{|\tau/W|}", source=SOURCE,
        substituted=(rf"W_{{max}} = \frac{{{tex(T, 'N*m')}}}{{{tex(Q(per, 'm'), 'mm')}}} = "
                     rf"{tex(Q(c.max_load, 'N'))}"),
        inputs={"motor": m, "point": f"({x * 1e3:.4g}, {y * 1e3:.4g}) mm", "torque_per_load": Q(per * 1e3, "mm"),
                "motor_torque": T},
        notes=(f"governs: the {m} motor at ({x * 1e3:.4g}, {y * 1e3:.4g}) mm; {int(np.sum(c.inside))} of "
               f"{len(c.inside)} grid points in the workspace ({', '.join(f'{k}: {v}' for k, v in c.excluded.items())}"
               ")",),
        load_case=load_case, details=_map_details(c, motor_torques, Q(payload).m_as("N")))


def _map_details(c: Any, motor_torques: dict[str, Any], payload: float) -> dict[str, Any]:
    """What the workspace map needs: the grid points inside the limited workspace with the largest load there,
    W_max(x, y) = min over motors of T_motor / |tau per unit load| [N], the points left out, the governing point."""
    T = np.array([Q(motor_torques[m]).m_as("N*m") for m in c.motors], dtype=float)
    per = np.abs(np.asarray(c.torque_per_load, dtype=float)[c.inside])
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.min(np.where(per > 0, T / per, np.inf), axis=1)
    finite = np.isfinite(w)  # a point no motor has to hold (no torque per unit load) has no limit: left out
    pts = np.asarray(c.points, dtype=float)
    return {"map_points": Q(pts[c.inside][finite] * 1e3, "mm"), "map_wmax": Q(w[finite], "N"),
            "map_outside": Q(pts[~np.asarray(c.inside, dtype=bool)] * 1e3, "mm"),
            "map_governing": Q(pts[c.governing_point] * 1e3, "mm"), "map_motor": c.governing_motor,
            "map_payload": Q(payload, "N")}
