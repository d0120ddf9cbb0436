"""A drive: motor, optional gearhead, transmission stages and a load, moved along a profile per load case.

:class:`Drive` is what a design file's ``drive`` component builds (and what a Python user builds
directly): it composes the load of a load case (replacements, added payload, a load factor), one
:class:`~mechverify.motion.drive_train.DriveTrain` per friction variant (a screw whose nut gives a
friction range is evaluated at mu_max, the motoring case, and mu_min, the back-driving case), and the
:class:`~mechverify.motion.drive_train.TorqueDemand` of every load case. The motor-fit checks on
these demands are :func:`mechverify.checks.drives.drive_checks` (all of them) and the single checks
of :mod:`mechverify.checks.motors`.

Example::

    from mechverify.checks.drives import drive_checks
    from mechverify.components.motors import motor
    from mechverify.components.transmissions import Drum
    from mechverify.motion import profiles
    from mechverify.motion.drive import Drive

    d = Drive.single("axis", motor("NEMA 17 stepper 0.56 N·m (004 Table 8)"), load={"mass": "2 kg"},
                     stages=[Drum("30 mm")],
                     profile=profiles.trapezoidal("100 mm", max_velocity="50 mm/s", acceleration="0.5 m/s^2"))
    results = drive_checks(d)   # motor_peak_torque, motor_max_speed, inertia_ratio
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from mechverify.components.gearheads import Gearhead
from mechverify.errors import InputError, MechverifyError
from mechverify.motion.drive_train import DriveTrain, LinearLoad, RotaryLoad, TorqueDemand
from mechverify.units import Q, Quantity

#: Load keys of a linear load (``mass`` given) and of a rotary load (``inertia`` given).
LINEAR_KEYS = ("mass", "incline", "friction_coefficient", "friction_force", "external_force")
ROTARY_KEYS = ("inertia", "gravity_torque", "gravity_phase", "friction_torque", "external_torque")

#: (load case name, profile, [(friction variant label, demand)]) as :meth:`Drive.demands` returns it.
CaseDemands = tuple[str, Any, list[tuple[str, TorqueDemand]]]


def _positive_float(q: Any) -> bool:
    """A quantity with a finite positive float magnitude (x + 0 and x·1.0 give x itself)."""
    return isinstance(q, Quantity) and type(q.magnitude) is float and 0.0 < q.magnitude < math.inf


def load_kind(load: Mapping[str, Any]) -> str:
    """``"length"`` for a linear load (``mass``), ``"angle"`` for a rotary one (``inertia``).

    Raises:
        InputError: both or neither of mass and inertia, or a key of the other kind of load.
    """
    lin, rot = [k for k in LINEAR_KEYS if k in load], [k for k in ROTARY_KEYS if k in load]
    if "mass" in load and "inertia" in load:
        raise InputError("mass, inertia: give mass for a linear load or inertia for a rotary one, not both")
    if "mass" not in load and "inertia" not in load:
        raise InputError("mass: missing; give the load's mass (linear) or inertia (rotary)")
    if "mass" in load and rot:
        raise InputError(f"{rot[0]}: a rotary-load key on a linear load (mass given)")
    if "inertia" in load and lin:
        raise InputError(f"{lin[0]}: a linear-load key on a rotary load (inertia given)")
    return "length" if "mass" in load else "angle"


@dataclass(frozen=True)
class Drive:
    """A motor with its gearhead, transmission stages and load, and the profile it moves the load along.

    Args:
        name: the drive's name (in messages and results).
        motor: a :mod:`mechverify.components.motors` motor.
        gearhead: a :class:`~mechverify.components.gearheads.Gearhead`, or None.
        stage_variants: per transmission stage from the motor side, the (label, stage) options; a stage
            with one option has the label ``""`` (a screw with a friction range: ``mu_max``, ``mu_min``).
        load: the load keys (:data:`LINEAR_KEYS` or :data:`ROTARY_KEYS`) as quantities.
        kind: ``"length"`` (linear load) or ``"angle"`` (rotary), see :func:`load_kind`.
        profile: the move: a profile of :mod:`mechverify.motion.profiles`, or its name in ``profiles``
            of :meth:`demands`.
        cycle_time: duty cycle for the RMS torque [s] (standstill after the move included).
        supply_voltage: DC motors: the supply (driver output) voltage [V].
        driver_current: the driver's maximum current [A].
        inertia_ratio_limit: the allowed load-to-rotor inertia ratio (None: the check's default).
        ambient_temperature: the motor's ambient temperature (winding-temperature check).
        bus_capacitance: the bus capacitance [F] (regeneration check, with overvoltage_limit).
        overvoltage_limit: the driver's overvoltage limit [V].

    A rating left None skips the check that needs it.
    """

    name: str
    motor: Any
    gearhead: Gearhead | None
    stage_variants: tuple[tuple[tuple[str, Any], ...], ...]
    load: Mapping[str, Any]
    kind: str
    profile: Any
    cycle_time: Any = None
    supply_voltage: Any = None
    driver_current: Any = None
    inertia_ratio_limit: float | None = None
    ambient_temperature: str | None = None
    bus_capacitance: str | None = None
    overvoltage_limit: Any = None
    #: scratch of a caller that evaluates the drive repeatedly (the design adapter: the demands of the last
    #: verify, and the load-case errors already reported); not part of the drive's value
    memo: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    @classmethod
    def single(cls, name: str, motor: Any, *, load: Mapping[str, Any], profile: Any, gearhead: Gearhead | None = None,
               stages: Sequence[Any] = (), **ratings: Any) -> Drive:
        """A drive whose stages have one variant each (the Python shorthand; ``ratings`` as the fields)."""
        values = {k: Q(v) if isinstance(v, str) else v for k, v in load.items()}  # "2 kg" as well as Q(2, "kg")
        return cls(name, motor, gearhead, tuple((("", s),) for s in stages), values, load_kind(values), profile,
                   **ratings)

    def make_load(self, case: Mapping[str, Any] | None = None) -> LinearLoad | RotaryLoad:
        """The load with a load case's replacements: mass/inertia/external/gravity replaced, payload added,
        load_factor multiplying mass or inertia, external force or torque and gravity torque.

        Raises:
            InputError: a non-positive load_factor or a key of the other kind of load.
        """
        case = case or {}
        p = {**self.load, **{k: case[k] for k in ("mass", "inertia", "external_force", "external_torque",
                                                  "gravity_torque") if k in case}}
        k = float(case.get("load_factor", 1.0))
        if not k > 0:
            raise InputError(f"load_factor: must be positive, got {k:g}")
        if self.kind == "length":
            if "inertia" in case or "external_torque" in case or "gravity_torque" in case:
                raise InputError("a rotary-load key in a load case of a linear drive")
            m = p["mass"]
            if "payload" in case or k != 1.0 or not _positive_float(m):  # else (m + 0 kg)·1 is m: pint's value
                m = (m + case.get("payload", Q(0, "kg"))) * k
            return LinearLoad(mass=m, incline=p.get("incline", Q(0, "deg")),
                              friction_coefficient=p.get("friction_coefficient", 0.0),
                              coulomb_friction=p.get("friction_force"),
                              external_force=None if "external_force" not in p else p["external_force"] * k,
                              name=self.name)
        if "mass" in case or "payload" in case or "external_force" in case:
            raise InputError("a linear-load key (mass, payload, external_force) in a load case of a rotary drive")
        return RotaryLoad(inertia=p["inertia"] * k,
                          gravity_torque=None if "gravity_torque" not in p else p["gravity_torque"] * k,
                          gravity_phase=p.get("gravity_phase", Q(0, "deg")), coulomb_friction=p.get("friction_torque"),
                          external_torque=None if "external_torque" not in p else p["external_torque"] * k,
                          name=self.name)

    def trains(self, case: Mapping[str, Any] | None = None) -> list[tuple[str, DriveTrain]]:
        """One drive train per friction variant (a screw's nut range gives mu_max and mu_min)."""
        load = self.make_load(case or {})
        combos: list[tuple[str, list[Any]]] = [("", [self.gearhead] if self.gearhead is not None else [])]
        for options in self.stage_variants:
            combos = [(", ".join(x for x in (lab, olab) if x), [*st, o]) for lab, st in combos for olab, o in options]
        return [(lab, DriveTrain(self.motor, tuple(st), load, name=self.name)) for lab, st in combos]

    def demands(self, cases: Sequence[tuple[str, Mapping[str, Any]]] = (),
                profiles: Mapping[str, Any] | None = None) -> list[CaseDemands]:
        """(load case, profile, [(variant, demand)]) for every case, or the drive's own move once.

        Args:
            cases: (name, loads) of the load cases that name the drive; a case's ``profile``,
                ``cycle_time`` and load keys replace the drive's (see :meth:`make_load`).
            profiles: profiles by name, for a ``profile`` given as a name.

        Raises:
            InputError: a bad load case (prefixed with its name) or a profile the train cannot follow.
        """
        out = []
        for case, loads in (list(cases) or [("", {})]):
            where = f"load case {case!r}: " if case else ""
            prof_name = loads.get("profile", self.profile)
            prof = (profiles or {})[prof_name] if isinstance(prof_name, str) else prof_name
            cycle = loads.get("cycle_time", self.cycle_time)
            try:
                trains = self.trains(loads)
            except MechverifyError as exc:
                raise InputError(f"{where}{exc}") from None
            try:
                out.append((case, prof, [(lab, tr.demand(prof, cycle_time=cycle)) for lab, tr in trains]))
            except MechverifyError as exc:
                what = f"profile {prof_name!r}" if isinstance(prof_name, str) else "profile"
                raise InputError(f"{where}{what}: {exc}") from None
        return out

    def missing_ratings(self) -> list[str]:
        """Motor-fit checks that cannot run because a rating is missing (named in the peak-torque check's notes)."""
        m, g, out = self.motor, self.gearhead, []
        if m.speed_limit is None:
            out.append("motor speed (no speed rating)")
        if m.kind == "dc" and m.continuous_torque is None:
            out.append("RMS torque (no nominal torque)")
        if m.kind != "servo" and m.rotor_inertia is None:
            out.append("inertia ratio (no rotor inertia)")
        if g is not None:
            for attr, what in (("continuous_torque", "gearhead continuous torque"),
                               ("intermittent_torque", "gearhead intermittent torque")):
                if getattr(g, attr) is None:
                    out.append(f"{what} (no rating)")
            if g.max_input_speed is None and g.max_input_speed_intermittent is None:
                out.append("gearhead input speed (no max. input speed)")
        if self.driver_current is not None and m.kind == "gearmotor" and m.stall_current is None:
            out.append("driver current (no stall current)")
        return out
