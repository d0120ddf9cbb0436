"""An arm walking a path: the arm built from its bodies, its joint motion, joint efforts and joint inertias.

What a design file's ``planar_arm`` computes, as a Python API: :func:`rp_arm_on_path`, :func:`rr_arm_on_path` and
:func:`five_bar_on_path` take a walked path (:func:`~mechverify.mechanisms.paths.walk_curve`) and return an
:class:`ArmOnPath` (SI arrays). The bodies on a link (:class:`~mechverify.mechanisms.paths.LinkBody`) are composed
into the link's mass, centre of mass and inertia (:func:`~mechverify.mechanisms.paths.compose_bodies`); kinematics
and Lagrange dynamics are those of :class:`~mechverify.mechanisms.paths.RPArm`,
:class:`~mechverify.mechanisms.paths.RRArm` and the five-bar (:func:`~mechverify.mechanisms.paths.five_bar_inverse`,
massless links, payload torques by virtual work).

Example::

    >>> from mechverify.mechanisms import paths as mp
    >>> path = mp.walk_polar(lambda phi: 0.08 + 0 * phi, "0.1 m/s", centre=(0.0, 0.2))
    >>> arm = rp_arm_on_path(path, [mp.LinkBody("rod", "99 g", "25 cm")], carriage_mass="0.2 kg")
    >>> float(abs(arm.efforts[0]).max()) > 0
    True
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from mechverify.mechanisms import paths as mp
from mechverify.units import Q, QuantityLike, to_si


@dataclasses.dataclass(frozen=True)
class ArmOnPath:
    """The built arm, the path it walks, its joint motion and joint efforts (SI arrays)."""

    name: str
    arm: Any  # RPArm, RRArm or FiveBar
    path: mp.PathSamples
    motion: mp.JointMotion  # the joints of the RP, RR or five-bar arm
    efforts: tuple[np.ndarray, np.ndarray]  # q1's torque [N m], q2's torque [N m] or force [N] at every sample
    q1_inertia: np.ndarray  # inertia about the first joint at every sample [kg m^2]
    kinds: tuple[str, str]  # "angle" / "length" of q1, q2
    q2_inertia: np.ndarray | None = None  # five-bar: the payload's inertia about the right motor

    def joint(self, name: str) -> tuple[str, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(kind, q, q', q'', effort) of joint ``q1`` or ``q2``."""
        i = {"q1": 0, "q2": 1}[name]
        m = self.motion
        q, dq, ddq = ((m.q1, m.dq1, m.ddq1), (m.q2, m.dq2, m.ddq2))[i]
        return self.kinds[i], q, dq, ddq, self.efforts[i]

    def joint_inertia(self, name: str) -> float:
        """The largest inertia [kg m^2] (a prismatic joint: the mass [kg]) joint ``q1`` or ``q2`` moves on the path."""
        if name == "q1":
            return float(np.max(self.q1_inertia))
        if self.q2_inertia is not None:
            return float(np.max(self.q2_inertia))
        if self.kinds[1] == "length":
            return to_si(self.arm.carriage_mass, "mass", "carriage_mass")
        return float(self.arm.joint_inertias(self.motion.q2)[1])  # RR: d22


def rp_arm_on_path(path: mp.PathSamples, bodies: Sequence[mp.LinkBody] = (), *, reach_min: QuantityLike = "0 m",
                   reach_max: QuantityLike | None = None, carriage_mass: QuantityLike = "0 kg",
                   payload: QuantityLike = "0 kg", arm_inertia: QuantityLike = "0 kg*m^2",
                   gravity: QuantityLike = "9.80665 m/s^2", q1_min: QuantityLike | None = None,
                   q1_max: QuantityLike | None = None, name: str = "RP arm") -> ArmOnPath:
    """An RP arm along ``path``: ``bodies`` turn with q1 (their mass, centre and inertia about the revolute axis,
    plus ``arm_inertia``), the carriage and the ``payload`` are one point mass at the extension q2;
    ``reach_max`` None: no stroke limit. q1's inertia J + m q2^2 at every sample."""
    m_a, r_a, J_a = mp.compose_bodies(list(bodies))
    J = J_a + to_si(arm_inertia, "inertia", "arm_inertia")
    mc = to_si(carriage_mass, "mass", "carriage_mass") + to_si(payload, "mass", "payload")
    arm = mp.RPArm(reach_min=reach_min, reach_max=reach_max, carriage_mass=Q(mc, "kg"), arm_inertia=Q(J, "kg*m^2"),
                   arm_mass=Q(m_a, "kg"), arm_com=Q(r_a, "m"), gravity=gravity, name=name, q1_min=q1_min,
                   q1_max=q1_max)
    motion = arm.inverse(path)
    J1 = J + mc * motion.q2**2
    return ArmOnPath(name, arm, path, motion, arm.joint_loads(motion), np.asarray(J1, float), ("angle", "length"))


def rr_arm_on_path(path: mp.PathSamples, l1: QuantityLike, l2: QuantityLike, *,
                   link1_bodies: Sequence[mp.LinkBody] = (), link2_bodies: Sequence[mp.LinkBody] = (),
                   elbow: str = "down", payload: QuantityLike = "0 kg", gravity: QuantityLike = "9.80665 m/s^2",
                   q1_min: QuantityLike | None = None, q1_max: QuantityLike | None = None,
                   q2_min: QuantityLike | None = None, q2_max: QuantityLike | None = None,
                   name: str = "RR arm") -> ArmOnPath:
    """An RR arm along ``path``: each link's bodies composed into its mass, centre of mass and centroidal inertia
    (J about the joint minus m c^2), the payload at the tip; q1's inertia d11 at every sample."""
    links = []
    for bodies in (link1_bodies, link2_bodies):
        m, c, Jj = mp.compose_bodies(list(bodies))
        links.append((m, c, Jj - m * c * c))  # centroidal
    arm = mp.RRArm(l1, l2, elbow, Q(links[0][0], "kg"), Q(links[1][0], "kg"),
                   Q(links[0][1], "m") if links[0][0] > 0 else None,
                   Q(links[1][1], "m") if links[1][0] > 0 else None,
                   Q(links[0][2], "kg*m^2"), Q(links[1][2], "kg*m^2"), payload, gravity,
                   q1_min=q1_min, q1_max=q1_max, q2_min=q2_min, q2_max=q2_max, name=name)
    motion = arm.inverse(path)
    J1 = arm.joint_inertias(motion.q2)[0]
    return ArmOnPath(name, arm, path, motion, arm.joint_loads(motion), np.asarray(J1, float), ("angle", "angle"))


def five_bar_on_path(fb: Any, path: mp.PathSamples, *, working_mode: str = "-+", payload: QuantityLike = "0 kg",
                     gravity: QuantityLike = "9.80665 m/s^2",
                     limits: Mapping[str, tuple[QuantityLike | None, QuantityLike | None]] | None = None,
                     name: str | None = None) -> ArmOnPath:
    """A :class:`~mechverify.mechanisms.fivebar.FiveBar` (massless links, the payload a point mass at the tool)
    along ``path``: q1 = left motor, q2 = right motor; torques by virtual work of the payload's d'Alembert force;
    the payload's inertia about each motor m |dP/dtheta_k|^2 at every sample. ``limits``
    {"theta_left": (lo, hi), "theta_right": ...}."""
    motion = mp.five_bar_inverse(fb, path, working_mode, dict(limits) if limits else {})
    efforts = mp.five_bar_payload_torques(fb, path, motion, payload, gravity, working_mode)
    m = to_si(payload, "mass", "payload")
    J = np.zeros((len(path.t), 2))
    for i in range(len(path.t)):
        jac = fb.jacobian(fb.inverse((Q(path.x[i], "m"), Q(path.y[i], "m")), working_mode)).m_as("m")
        J[i] = m * np.sum(jac**2, axis=0)
    return ArmOnPath(name if name is not None else fb.name, fb, path, motion, efforts, J[:, 0], ("angle", "angle"),
                     J[:, 1])


__all__ = ["ArmOnPath", "rp_arm_on_path", "rr_arm_on_path", "five_bar_on_path"]
