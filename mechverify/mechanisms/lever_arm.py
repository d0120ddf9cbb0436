"""The 4-DOF parallelogram lever arm with all motors at the base (seed 000): kinematics and statics.

Layout (seed 000, Fig. 1 and Eqs. 1-10, notation kept). In the arm plane (``u`` horizontal,
``z`` up) with the shoulder axis at ``O``:

* ``OA = b`` at the **shoulder** angle ``varphi``: ``A = b(-cos varphi, sin varphi)``;
* the **elbow** lever ``EAB`` (straight, pivoted at ``A``, ``AE = p``, ``AB = c``) is set to the
  angle ``phi`` by the crank ``OD = p`` through the parallelogram ``OAED`` (coupler ``DE = b``):
  ``D = p(-cos phi, sin phi)``, ``B = A + c(cos phi, -sin phi)``;
* the **wrist** lever ``IBC`` (``BC = d``, ``BI = r``, right angle at ``B``) is set to ``psi`` by
  the crank ``OF = q`` through two parallelograms: ``OFGA`` (coupler ``FG = b``) turns the bell
  crank ``GAH`` (``AG = q``, ``AH = r``, right angle at ``A``), and ``ABIH`` (coupler ``HI = c``)
  turns ``IBC``: ``F = q(cos psi, sin psi)``, ``C = B + d(cos psi, sin psi)``;
* the **base** angle ``theta`` turns the arm plane about the vertical axis:
  ``(x, y, z) = (u cos theta, u sin theta, z)``.

The three plane motors (shoulder on ``OA``, elbow on ``OD``, wrist on ``OF``) sit on the base axis
``O``. :meth:`LeverArm.statics` builds the nine-body statics model;
:func:`lever_arm_closed_form` gives the member forces and motor torques for a load ``W`` at ``C``
with massless members, derived here by equilibrium of each body and checked by virtual work (the
closed forms printed in seed 000, Eqs. 28-40, contain errors; see the issue-10 note).

References
----------
1. E. Garrote Pérez, *Diseño preliminar de un brazo robótico de cuatro grados de libertad basado
   en palancas*, Univ. de Matanzas, 2021, Sec. 2.1-2.3 and 3.1 (seed 000; geometry only).
2. J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Statics*, 7th ed., Wiley, 2012, Art. 4/6
   (frames and machines) and Ch. 7 (virtual work).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pint

from mechverify.errors import InputError
from mechverify.frozen import set_fields
from mechverify.mechanisms.errors import SingularPoseError, UnreachablePoseError
from mechverify.mechanisms.statics import GROUND, AppliedForce, Body, Mechanism, Pin
from mechverify.mechanisms.sweep import LinearSweep
from mechverify.units import Q, from_si, require_positive, to_si

_POINTS = ("O", "A", "B", "C", "D", "E", "F", "G", "H", "I")


def _wrap(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


@dataclass(frozen=True)
class LeverArmPose:
    """Joint angles and the plane positions (SI, ``u``-``z``) of every point of the arm."""

    base: pint.Quantity  # theta
    shoulder: pint.Quantity  # varphi
    elbow: pint.Quantity  # phi
    wrist: pint.Quantity  # psi
    plane: dict[str, np.ndarray]

    @property
    def tool(self) -> pint.Quantity:
        """The tool point C in 3-D (x, y, z)."""
        u, z = self.plane["C"]
        th = float(self.base.m_as("rad"))
        return from_si(np.array([u * math.cos(th), u * math.sin(th), z]), "length")

    def label(self) -> str:
        return (f"theta={self.base.m_as('deg'):.1f} deg, varphi={self.shoulder.m_as('deg'):.1f} deg, "
                f"phi={self.elbow.m_as('deg'):.1f} deg, psi={self.wrist.m_as('deg'):.1f} deg")


@dataclass(frozen=True)
class LeverArm:
    """The lever arm's dimensions (seed 000 Eq. 1: ``OA = DE = FG = b``, ``AB = HI = c``, ``BC = d``,
    ``OD = AE = p``, ``OF = AG = q``, ``AH = BI = r``); seed 000 simulates b = 200, c = 150,
    d = 50, p = q = r = 30 mm."""

    b: Any
    c: Any
    d: Any
    p: Any
    q: Any
    r: Any
    name: str = "lever arm"

    def __post_init__(self) -> None:
        for f in ("b", "c", "d", "p", "q", "r"):
            v = to_si(getattr(self, f), "length", f)
            require_positive(v, f, dim="length")
            set_fields(self, **{f: from_si(v, "length")})

    def _dims(self) -> tuple[float, ...]:
        return tuple(float(getattr(self, f).m_as("m")) for f in ("b", "c", "d", "p", "q", "r"))

    # ---------------------------------------------------------------- kinematics
    def forward(self, shoulder: Any, elbow: Any, wrist: Any, base: Any = "0 deg") -> LeverArmPose:
        """Positions of all points for the joint angles (seed 000 Eqs. 2-10, 12-20, corrected)."""
        vp = to_si(shoulder, "angle", "shoulder")
        ph = to_si(elbow, "angle", "elbow")
        ps = to_si(wrist, "angle", "wrist")
        th = to_si(base, "angle", "base")
        b, c, d, p, q, r = self._dims()
        O = np.zeros(2)
        A = b * np.array([-math.cos(vp), math.sin(vp)])
        D = p * np.array([-math.cos(ph), math.sin(ph)])
        E = A + D
        B = A + c * np.array([math.cos(ph), -math.sin(ph)])
        F = q * np.array([math.cos(ps), math.sin(ps)])
        G = A + F
        n_psi = np.array([-math.sin(ps), math.cos(ps)])
        H = A + r * n_psi
        I = B + r * n_psi
        C = B + d * np.array([math.cos(ps), math.sin(ps)])
        plane = dict(zip(_POINTS, (O, A, B, C, D, E, F, G, H, I), strict=True))
        return LeverArmPose(from_si(th, "angle").to("deg"), from_si(vp, "angle").to("deg"),
                            from_si(ph, "angle").to("deg"), from_si(ps, "angle").to("deg"), plane)

    def inverse(self, tool: Any, wrist: Any, elbow_branch: str = "up", base_branch: str = "front") -> LeverArmPose:
        """Joint angles that put C at ``tool`` (x, y, z) with the wrist at ``wrist``.

        ``base_branch``: ``"front"`` (C on the +u side of the arm plane, ``theta = atan2(y, x)``) or
        ``"back"`` (``theta + 180 deg``, C on the -u side). ``elbow_branch``: ``"up"`` puts A on the
        left of the directed line O -> B (above it when B is in front), ``"down"`` the other
        triangle. Raises :class:`UnreachablePoseError` when B is out of the reach of OA and AB.
        """
        if elbow_branch not in ("up", "down"):
            raise InputError(f"elbow_branch: expected 'up' or 'down', got {elbow_branch!r}")
        if base_branch not in ("front", "back"):
            raise InputError(f"base_branch: expected 'front' or 'back', got {base_branch!r}")
        if isinstance(tool, pint.Quantity):
            xyz = np.atleast_1d(to_si(tool, "length", "tool"))
        elif isinstance(tool, (tuple, list)) and len(tool) == 3:
            xyz = np.array([to_si(v, "length", "tool") for v in tool])
        else:
            raise InputError(f"tool: expected (x, y, z) lengths, got {tool!r}")
        if xyz.shape != (3,):
            raise InputError(f"tool: expected (x, y, z), got shape {xyz.shape}")
        ps = to_si(wrist, "angle", "wrist")
        b, c, d, _p, _q, _r = self._dims()
        x, y, z = xyz
        theta = math.atan2(y, x)  # atan2(0, 0) = 0: on the base axis any theta works; 0 is taken
        u = math.hypot(x, y)
        if base_branch == "back":
            theta, u = _wrap(theta + math.pi), -u
        Bu, Bz = u - d * math.cos(ps), z - d * math.sin(ps)
        t = math.hypot(Bu, Bz)
        if t > (b + c) * (1 + 1e-9) or t < abs(b - c) - 1e-9 * (b + c):  # boundary points close (round-off)
            raise UnreachablePoseError(
                f"{self.name}: tool point out of reach: the wrist pivot B would be {t * 1e3:.4g} mm from the "
                f"shoulder axis, but OA = {b * 1e3:.4g} mm and AB = {c * 1e3:.4g} mm reach only "
                f"{abs(b - c) * 1e3:.4g} to {(b + c) * 1e3:.4g} mm")
        cos_delta = max(-1.0, min(1.0, (t * t - b * b - c * c) / (2 * b * c)))
        delta = math.acos(cos_delta) * (-1.0 if elbow_branch == "up" else 1.0)  # delta = angle(AB) - angle(OA)
        a1 = math.atan2(Bz, Bu) - math.atan2(c * math.sin(delta), b + c * math.cos(delta))
        a2 = a1 + delta
        shoulder, elbow = _wrap(math.pi - a1), _wrap(-a2)
        return self.forward(from_si(shoulder, "angle"), from_si(elbow, "angle"), from_si(ps, "angle"),
                            from_si(theta, "angle"))

    def singularity_measures(self, pose: LeverArmPose) -> dict[str, float]:
        """|sin| of the angle of each parallelogram (0 = flattened, its coupler then carries no moment):
        ``OAED`` = sin(phi - varphi), ``OFGA`` = sin(varphi + psi), ``ABIH`` = cos(phi + psi)."""
        vp, ph, ps = (float(a.m_as("rad")) for a in (pose.shoulder, pose.elbow, pose.wrist))
        return {"OAED": abs(math.sin(ph - vp)), "OFGA": abs(math.sin(vp + ps)), "ABIH": abs(math.cos(ph + ps))}

    def check_singularity(self, pose: LeverArmPose, tol: float = 1e-3) -> None:
        for k, v in self.singularity_measures(pose).items():
            if v <= tol:
                raise SingularPoseError(f"{self.name}: parallelogram {k} is flattened at {pose.label()} "
                                        f"(|sin| = {v:.3g} <= {tol:g}); its coupler cannot drive the lever")

    # ---------------------------------------------------------------- statics
    def statics(self, pose: LeverArmPose, load: Any = "0 N", masses: dict[str, Any] | None = None,
                gravity: Any = "9.80665 m/s**2") -> Mechanism:
        """The nine-body planar statics model at ``pose``: ``load`` (a weight, acting downward) at C,
        optional ``masses`` by body name (``OA, OD, DE, EAB, OF, FG, GAH, HI, IBC``; weight spread
        along each body's segments). Motors: ``shoulder`` (ground -> OA), ``elbow`` (ground -> OD),
        ``wrist`` (ground -> OF), all on the axis O."""
        W = to_si(load, "force", "load")
        g = to_si(gravity, "acceleration", "gravity")
        masses = dict(masses or {})
        pts = {k: from_si(v.copy(), "length") for k, v in pose.plane.items()}
        layout = {
            "OA": (("O", "A"), (("O", "A"),)), "OD": (("O", "D"), (("O", "D"),)), "DE": (("D", "E"), (("D", "E"),)),
            "EAB": (("E", "A", "B"), (("E", "A"), ("A", "B"))), "OF": (("O", "F"), (("O", "F"),)),
            "FG": (("F", "G"), (("F", "G"),)), "GAH": (("G", "A", "H"), (("A", "G"), ("A", "H"))),
            "HI": (("H", "I"), (("H", "I"),)), "IBC": (("I", "B", "C"), (("B", "I"), ("B", "C"))),
        }
        unknown = set(masses) - set(layout)
        if unknown:
            raise InputError(f"masses: unknown body {sorted(unknown)}; bodies are {sorted(layout)}")
        bodies = tuple(Body(n, {p: pts[p] for p in ps}, mass=masses.get(n, "0 kg"), segments=segs)
                       for n, (ps, segs) in layout.items())
        joints = (
            Pin("shoulder", GROUND, "OA", "O", actuated=True),
            Pin("elbow", GROUND, "OD", "O", actuated=True),
            Pin("wrist", GROUND, "OF", "O", actuated=True),
            Pin("A_EAB", "OA", "EAB", "A"), Pin("A_GAH", "OA", "GAH", "A"),
            Pin("D", "OD", "DE", "D"), Pin("E", "DE", "EAB", "E"),
            Pin("F", "OF", "FG", "F"), Pin("G", "FG", "GAH", "G"),
            Pin("H", "GAH", "HI", "H"), Pin("I", "HI", "IBC", "I"), Pin("B", "EAB", "IBC", "B"),
        )
        loads = (AppliedForce("IBC", "C", (from_si(0.0, "force"), from_si(-W, "force")), name="tool load W"),)
        return Mechanism(bodies, joints, loads, gravity=(from_si(0.0, "acceleration"), from_si(-g, "acceleration")),
                         name=f"{self.name} at {pose.label()}")


def lever_arm_closed_form(arm: LeverArm, pose: LeverArmPose, load: Any) -> dict[str, pint.Quantity]:
    """Coupler axial forces (tension +) and motor torques (counter-clockwise in the u-z plane, on the
    cranks) for a weight ``W`` at C, massless members.

    Equilibrium of IBC about B, GAH about A and EAB about A (Meriam & Kraige 7th ed., Art. 4/6):

    * ``N_HI = W d cos psi / (r cos(phi + psi))``
    * ``N_FG = -W d cos psi / (q sin(varphi + psi))``
    * ``N_DE = W c cos phi / (p sin(varphi - phi))``
    * ``tau_shoulder = -W b cos varphi``, ``tau_elbow = W c cos phi``, ``tau_wrist = W d cos psi``
      (the motor torques equal the virtual-work generalised forces of the load on each crank).

    Seed 000 prints (Eq. 36a) ``M_OA = [cos varphi + d sin(phi - varphi) cos psi/(r cos(phi + psi))] W d``,
    (28a-b) ``varphi`` for ``psi``, (30a) ``r`` for ``q``, (30b) a factor 2 and a dropped term, (38b)
    ``cos`` for ``sin`` and (40b) a sign error; see the issue-10 note.
    """
    W = to_si(load, "force", "load")
    b, c, d, p, q, r = arm._dims()
    vp, ph, ps = (float(a.m_as("rad")) for a in (pose.shoulder, pose.elbow, pose.wrist))
    arm.check_singularity(pose)
    return {
        "HI": from_si(W * d * math.cos(ps) / (r * math.cos(ph + ps)), "force"),
        "FG": from_si(-W * d * math.cos(ps) / (q * math.sin(vp + ps)), "force"),
        "DE": from_si(W * c * math.cos(ph) / (p * math.sin(vp - ph)), "force"),
        "shoulder": from_si(-W * b * math.cos(vp), "torque"),
        "elbow": from_si(W * c * math.cos(ph), "torque"),
        "wrist": from_si(W * d * math.cos(ps), "torque"),
    }


# ---------------------------------------------------------------- pose sweep with self-weight
#: The arm's straight members (design-file names) -> (body, segment): one per body segment of :meth:`LeverArm.statics`.
MEMBERS: dict[str, tuple[str, tuple[str, str]]] = {
    "OA": ("OA", ("O", "A")), "OD": ("OD", ("O", "D")), "DE": ("DE", ("D", "E")),
    "EAB_EA": ("EAB", ("E", "A")), "EAB_AB": ("EAB", ("A", "B")), "OF": ("OF", ("O", "F")), "FG": ("FG", ("F", "G")),
    "GAH_AG": ("GAH", ("A", "G")), "GAH_AH": ("GAH", ("A", "H")), "HI": ("HI", ("H", "I")),
    "IBC_BI": ("IBC", ("B", "I")), "IBC_BC": ("IBC", ("B", "C")),
}
#: The plane motors (the base rotation carries no gravity load).
MOTORS = ("shoulder", "elbow", "wrist")


def member_name(solver_key: str) -> str:
    """Design-file name of a statics member key: ``"EAB:A-B"`` -> ``"EAB_AB"``, ``"OA"`` -> ``"OA"``."""
    return solver_key.replace(":", "_").replace("-", "")


def member_length(arm: LeverArm, member: str) -> pint.Quantity:
    """Pin-centre length of a member (the same at every pose): ``OA = DE = FG = b``, ``AB = HI = c``, ``BC = d``,
    ``OD = AE = p``, ``OF = AG = q``, ``AH = BI = r``."""
    if member not in MEMBERS:
        raise InputError(f"member: unknown {member!r}; the lever arm's members are {', '.join(MEMBERS)}")
    pose = arm.forward("45 deg", "10 deg", "20 deg")
    a, b = MEMBERS[member][1]
    return from_si(float(np.linalg.norm(pose.plane[a] - pose.plane[b])), "length")


def sweep_label(pose: LeverArmPose) -> str:
    """Short pose name of a sweep: ``"varphi 0, phi 60, psi 70 deg"``."""
    return (f"varphi {pose.shoulder.m_as('deg'):.0f}, phi {pose.elbow.m_as('deg'):.0f}, "
            f"psi {pose.wrist.m_as('deg'):.0f} deg")


def pose_grid(arm: LeverArm, shoulder: tuple[float, float], elbow: tuple[float, float], wrist: tuple[float, float],
              step: float, min_transmission: float) -> list[LeverArmPose]:
    """Poses on a grid of the three plane joints (ranges and ``step`` in degrees, ends included) whose three
    parallelograms are all at least ``min_transmission`` degrees from flat (``asin`` of
    :meth:`LeverArm.singularity_measures`; nearer to flat the coupler forces grow as 1/sin, unbounded)."""
    if not step > 0:
        raise InputError(f"step: must be positive, got {step:g} deg")
    for name, (lo, hi) in (("shoulder_range", shoulder), ("elbow_range", elbow), ("wrist_range", wrist)):
        if not hi >= lo:
            raise InputError(f"{name}: expected [low, high] with high >= low, got [{lo:g}, {hi:g}] deg")
    n = math.prod(int((hi - lo) / step + 1e-9) + 1 for lo, hi in (shoulder, elbow, wrist))
    if n > 20_000:
        raise InputError(f"step: {n:,} grid poses (at most 20,000); use a coarser step")
    out = []
    for vp in np.arange(shoulder[0], shoulder[1] + 1e-9, step):
        for ph in np.arange(elbow[0], elbow[1] + 1e-9, step):
            for ps in np.arange(wrist[0], wrist[1] + 1e-9, step):
                pose = arm.forward(Q(vp, "deg"), Q(ph, "deg"), Q(ps, "deg"))
                angles = [math.degrees(math.asin(min(1.0, v))) for v in arm.singularity_measures(pose).values()]
                if min(angles) >= min_transmission - 1e-9:
                    out.append(pose)
    if not out:
        raise InputError(f"min_transmission_angle: no pose of the grid has every parallelogram at least "
                         f"{min_transmission:g} deg from flat")
    return out


def sweep_envelope(arm: LeverArm, shoulder: tuple[float, float], elbow: tuple[float, float],
                   wrist: tuple[float, float], step: float, min_transmission: float,
                   masses: dict[str, Any] | None = None, gravity: Any = "9.80665 m/s**2") -> LinearSweep:
    """The pose sweep of the arm with its links' self-weight, linear in the payload ``W`` at C
    (:class:`~mechverify.mechanisms.sweep.LinearSweep`: the self-weight sweep and the unit-payload sweep of
    :meth:`LeverArm.statics` over :func:`pose_grid`; members named as in :data:`MEMBERS`). Cached per geometry,
    grid, masses and gravity (a verify or a sizing run over ``W`` solves the sweeps once)."""
    g = to_si(gravity, "acceleration", "gravity")
    m = tuple(sorted((k, to_si(v, "mass", f"masses.{k}")) for k, v in (masses or {}).items()))
    key = (arm._dims(), arm.name, tuple(map(float, shoulder)), tuple(map(float, elbow)), tuple(map(float, wrist)),
           float(step), float(min_transmission), m, g)
    return _envelope(key)


@functools.lru_cache(maxsize=16)
def _envelope(key: tuple) -> LinearSweep:
    from mechverify.mechanisms.sweep import linear_sweep

    dims, name, shoulder, elbow, wrist, step, min_t, masses, g = key
    arm = LeverArm(*(from_si(v, "length") for v in dims), name=name)
    kg = {k: from_si(v, "mass") for k, v in masses}
    gq = from_si(g, "acceleration")
    poses = pose_grid(arm, shoulder, elbow, wrist, step, min_t)
    res = linear_sweep(poses, lambda p: arm.statics(p, "0 N", masses=kg, gravity=gq),
                       lambda p: arm.statics(p, from_si(1.0, "force"), gravity=gq), label=sweep_label)
    ren = {k: member_name(k) for k in res.N}
    return LinearSweep(res.labels, {ren[k]: v for k, v in res.lengths.items()}, {ren[k]: v for k, v in res.N.items()},
                       {ren[k]: v for k, v in res.V.items()}, {ren[k]: v for k, v in res.M.items()}, res.efforts)
