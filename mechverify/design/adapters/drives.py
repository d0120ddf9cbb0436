"""Motion profiles (section ``profiles``) and the ``drive`` component: motor, gearhead, transmission, load.

A ``drive`` is the unit the motor-fit checks run on: one motor (catalogue name or inline data), an
optional gearhead, transmission stages from the motor side (``screw`` naming a ``lead_screw``
component, ``drum``, ``belt``, ``direct``) and a linear or rotary load moved along a profile. The
torque demand comes from :meth:`mechverify.motion.drive_train.DriveTrain.demand`; the checks are
those of :mod:`mechverify.checks.motors`, one design-file check each.

Load cases: the motor-fit checks need no load-case data (the drive runs its own profile once). When
load cases name the drive, every such case runs instead, with its replacements (profile, mass,
external force, ...) applied to the drive's own load; the framework keeps the governing case.
A screw whose nut gives a friction range is evaluated at both ends (mu_max: motoring torque,
mu_min: braking torque when the load back-drives the screw) and the worse governs.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.checks import motors as mc
from mechverify.checks.result import CheckResult
from mechverify.components.gearheads import Gearhead, gearhead, gearhead_from_dict
from mechverify.components.motors import THERMAL_FIELDS, motor, motor_from_dict
from mechverify.components.transmissions import BeltDrive, DirectDrive, Drum
from mechverify.components.transmissions import ScrewDrive as ScrewStage
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError, UnitError
from mechverify.motion import profiles as pr
from mechverify.motion.drive_train import DriveTrain, LinearLoad, RotaryLoad, TorqueDemand
from mechverify.units import Q, as_quantity, to_si

# ============================================================================ profiles


def _trapezoidal(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    kw = {k: p[k] for k in ("max_velocity", "acceleration", "duration", "deceleration") if k in p}
    return pr.trapezoidal(p["distance"], allow_triangular=p.get("allow_triangular", True), **kw)


def _triangular(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.triangular(p["distance"], **{k: p[k] for k in ("duration", "acceleration") if k in p})


def _s_curve(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.s_curve(p["distance"], max_velocity=p["max_velocity"], acceleration=p["acceleration"], jerk=p["jerk"])


def _dwell(p: Mapping[str, Any], ctx: Any) -> pr.Profile:
    return pr.dwell(p["duration"], "angle" if p.get("axis") == "rotary" else "length")


def _profile_obj(name: str, ctx: Mapping[str, Any], stack: tuple[str, ...]) -> Any:
    """The built profile ``name``, building it first when it comes later in the file."""
    entry = ctx["profiles"][name]
    if entry.obj is None:
        if any(f.required and f.name not in entry.params for f in entry.type.fields):
            raise InputError(f"steps: profile {name!r} is invalid (see its own errors)")
        if name in stack:
            raise InputError(f"steps: sequence refers to itself through {' -> '.join((*stack, name))}")
        if entry.type.name == "sequence":
            entry.obj = _sequence({**entry.params, "_name": name}, ctx, (*stack, name))
        else:
            entry.obj = entry.type.build({**entry.params, "_name": name}, ctx)
    return entry.obj


def _sequence(p: Mapping[str, Any], ctx: Any, stack: tuple[str, ...] = ()) -> pr.Profile:
    parts = []
    for i, name in enumerate(p["steps"]):
        obj = _profile_obj(name, ctx, stack or (p["_name"],))
        if not isinstance(obj, pr.Profile):
            raise InputError(f"steps[{i}]: {name!r} is a sampled profile; a sequence joins analytic moves only")
        parts.append(obj)
    return pr.sequence(*parts)


def _sampled(p: Mapping[str, Any], ctx: Any) -> pr.SampledProfile:
    x = p["x"]
    kind = "length"
    try:
        as_quantity(x[0], "length", "x[0]")
    except UnitError:
        kind = "angle"
    xs = Q(np.array([to_si(v, kind, f"x[{i}]") for i, v in enumerate(x)]), "m" if kind == "length" else "rad")
    ts = Q(np.array([to_si(v, "time", f"t[{i}]") for i, v in enumerate(p["t"])]), "s")
    return pr.sampled(ts, xs)


_DIST = Field("distance", "str", "move length or angle, e.g. '200 mm' or '90 deg' (negative moves backwards)",
              required=True)
_VMAX = "peak speed: 'mm/s' for a linear move, 'rpm' or 'deg/s' for a rotary one"
_ACC = "acceleration: 'm/s^2' or 'rad/s^2'"
for _ct in (
    ComponentType("trapezoidal", "Trapezoidal velocity move over a distance; give two of max_velocity, acceleration "
                  "and duration (Biagiotti & Melchiorri, Trajectory Planning for Automatic Machines, 2008, Sec. 3.2).",
                  fields=(_DIST, Field("max_velocity", "str", _VMAX), Field("acceleration", "str", _ACC),
                          Field("duration", "time", "move time"),
                          Field("deceleration", "str", "deceleration if it differs (with max_velocity and "
                                                       "acceleration)"),
                          Field("allow_triangular", "bool", "a move too short to reach max_velocity becomes "
                                                            "triangular (false: an error)", default=True)),
                  build=_trapezoidal, section="profiles"),
    ComponentType("triangular", "Triangular velocity move: accelerate half the time, decelerate the other half; "
                  "give duration or acceleration (Biagiotti & Melchiorri 2008, Sec. 3.2).",
                  fields=(_DIST, Field("duration", "time", "move time"), Field("acceleration", "str", _ACC)),
                  build=_triangular, section="profiles"),
    ComponentType("s_curve", "Jerk-limited (double-S, seven-segment) move from rest to rest (Biagiotti & Melchiorri "
                  "2008, Sec. 3.4).",
                  fields=(_DIST, Field("max_velocity", "str", _VMAX, required=True),
                          Field("acceleration", "str", _ACC, required=True),
                          Field("jerk", "str", "jerk: 'm/s^3' or 'rad/s^3'", required=True)),
                  build=_s_curve, section="profiles"),
    ComponentType("dwell", "Standing still (holding the load) for a time.",
                  fields=(Field("duration", "time", "dwell time", required=True),
                          Field("axis", "choice", "linear or rotary (only matters when the dwell stands alone)",
                                choices=("linear", "rotary"), default="linear")),
                  build=_dwell, section="profiles"),
    ComponentType("sequence", "Profiles one after another, each starting where the previous ended.",
                  fields=(Field("steps", "list", "names of other profiles, in order", required=True, item="ref",
                                ref="profiles"),),
                  build=lambda p, ctx: _sequence(p, ctx), section="profiles"),
    ComponentType("sampled", "A measured or planned move as samples; velocity and acceleration by central "
                  "differences (numpy.gradient), so smooth noisy data first.",
                  fields=(Field("t", "list", "times, strictly increasing", required=True, item="time"),
                          Field("x", "list", "positions (lengths or angles), as many as t", required=True,
                                item="str")),
                  build=_sampled, section="profiles"),
):
    REGISTRY.register(_ct)


# ============================================================================ drive: stages

#: Keys of each transmission stage table and their kinds ("count_or_length": teeth or a diameter).
STAGE_KEYS: dict[str, dict[str, str]] = {
    "screw": {"screw": "str", "mu": "dimensionless", "collar_mu": "dimensionless", "collar_diameter": "length",
              "inertia": "inertia"},
    "drum": {"diameter": "length", "efficiency": "dimensionless", "backdrive_efficiency": "dimensionless",
             "inertia": "inertia"},
    "belt": {"driver": "count_or_length", "driven": "count_or_length", "efficiency": "dimensionless",
             "backdrive_efficiency": "dimensionless", "inertia": "inertia"},
    "direct": {"efficiency": "dimensionless", "inertia": "inertia"},
}
_STAGE_REQUIRED = {"screw": ("screw",), "drum": ("diameter",), "belt": ("driver", "driven"), "direct": ()}


def _stage_values(i: int, table: Mapping[str, Any]) -> tuple[str, dict[str, Any]]:
    from mechverify.errors import suggest

    path = f"transmission[{i}]"
    kind = table.get("type")
    if kind not in STAGE_KEYS:
        hint = suggest(str(kind), STAGE_KEYS, 1)
        raise InputError(f"{path}.type: expected one of {', '.join(STAGE_KEYS)}, got {kind!r}"
                         + (f"; did you mean {hint[0]!r}?" if hint else ""))
    keys = STAGE_KEYS[kind]
    out: dict[str, Any] = {}
    for k, v in table.items():
        if k in ("type", "name"):
            continue
        if k not in keys:
            hint = suggest(k, keys, 1)
            raise InputError(f"{path}.{k}: unknown key for a {kind} stage"
                             + (f"; did you mean {hint[0]!r}?" if hint else f" (allowed: {', '.join(keys)}, name)"))
        dim = keys[k]
        if dim == "str":
            if not isinstance(v, str):
                raise InputError(f"{path}.{k}: expected a name, got {v!r}")
            out[k] = v
        elif dim == "count_or_length":
            if isinstance(v, int) and not isinstance(v, bool):
                out[k] = v
            else:
                out[k] = as_quantity(v, "length", f"{path}.{k}")
        else:
            out[k] = as_quantity(v, dim, f"{path}.{k}")
    missing = [k for k in _STAGE_REQUIRED[kind] if k not in out]
    if missing:
        raise InputError(f"{path}.{missing[0]}: missing ({'a name' if missing[0] == 'screw' else 'required'})")
    return kind, out


def _screw_component(i: int, name: str, ctx: Mapping[str, Any]) -> Any:
    from mechverify.errors import suggest

    comps = ctx.get("components", {})
    entry = comps.get(name)
    if entry is None or entry.type.name != "lead_screw":
        screws = [k for k, e in comps.items() if e.type.name == "lead_screw"]
        hint = suggest(name, screws, 1)
        raise InputError(f"transmission[{i}].screw: expected the name of a lead_screw component, got {name!r}"
                         + (f"; did you mean {hint[0]!r}?" if hint
                            else f" (lead screws: {', '.join(screws) or 'none'})"))
    if entry.obj is None:
        if "thread" not in entry.params or "length" not in entry.params:
            raise InputError(f"transmission[{i}].screw: the lead screw {name!r} is invalid (see its own errors)")
        entry.obj = entry.type.build({**entry.params, "_name": name}, ctx)
    return entry.obj


def _stages(tables: list[Any], ctx: Mapping[str, Any]) -> list[list[tuple[str, Any]]]:
    """Per stage the list of (variant label, stage object): a screw with a friction range gives two."""
    errors, out = [], []
    for i, table in enumerate(tables):
        try:
            if not isinstance(table, dict):
                raise InputError(f"transmission[{i}]: expected a table such as {{ type = \"drum\", diameter = "
                                 f"\"30 mm\" }}, got {table!r}")
            kind, v = _stage_values(i, table)
            name = table.get("name") or {"screw": v.get("screw"), "belt": "belt drive"}.get(kind, kind)
            if kind == "screw":
                ls = _screw_component(i, v.pop("screw"), ctx)
                if "inertia" not in v and ls.screw.material is not None and ls.screw.material.density is not None:
                    v["inertia"] = ls.screw.rotor_inertia()
                if "mu" in v:
                    mus = [("", v.pop("mu"))]
                else:
                    lo, hi = ls.nut.require_mu()
                    mus = [(f"mu_max = {hi:g}", hi)] + ([(f"mu_min = {lo:g}", lo)] if lo != hi else [])
                out.append([(lab, ScrewStage(ls.screw, mu, name=name, **v)) for lab, mu in mus])
            else:
                cls = {"drum": Drum, "belt": BeltDrive, "direct": DirectDrive}[kind]
                out.append([("", cls(name=name, **v))])
        except MechverifyError as exc:
            msg = str(exc)
            errors.append(msg if msg.startswith(f"transmission[{i}]") else f"transmission[{i}]: {msg}")
    if errors:
        raise InputError("; ".join(errors))
    return out


# ============================================================================ drive: motor, gearhead, load


def _inline(kind: str, table: dict[str, Any], default_name: str, make: Callable[[dict[str, Any]], Any]) -> Any:
    d = {"name": default_name, **table}
    try:
        return make(d)
    except MechverifyError as exc:
        msg = str(exc)
        for prefix in (f"{d['name']}.", f"{kind} {d['name']!r}."):
            if msg.startswith(prefix):
                raise InputError(f"{kind}_data.{msg[len(prefix):]}") from None
        raise InputError(f"{kind}_data: {msg}") from None


def _motor(p: Mapping[str, Any]) -> Any:
    if ("motor" in p) == ("motor_data" in p):
        raise InputError("motor: give either motor (a catalogue name, see `mechverify motors`) or a motor_data table")
    if "motor" in p:
        try:
            return motor(p["motor"])
        except MechverifyError as exc:
            raise InputError(f"motor: {exc}") from None
    return _inline("motor", dict(p["motor_data"]), f"{p['_name']} motor", motor_from_dict)


def _gearhead(p: Mapping[str, Any]) -> Gearhead | None:
    if "gearhead" in p and "gearhead_data" in p:
        raise InputError("gearhead: give either gearhead (a catalogue name) or a gearhead_data table, not both")
    if "gearhead" in p:
        try:
            return gearhead(p["gearhead"])
        except MechverifyError as exc:
            raise InputError(f"gearhead: {exc}") from None
    if "gearhead_data" in p:
        return _inline("gearhead", dict(p["gearhead_data"]), f"{p['_name']} gearhead", gearhead_from_dict)
    return None


LINEAR_KEYS = ("mass", "incline", "friction_coefficient", "friction_force", "external_force")
ROTARY_KEYS = ("inertia", "gravity_torque", "gravity_phase", "friction_torque", "external_torque")


def _load_kind(p: Mapping[str, Any]) -> str:
    lin, rot = [k for k in LINEAR_KEYS if k in p], [k for k in ROTARY_KEYS if k in p]
    if "mass" in p and "inertia" in p:
        raise InputError("mass, inertia: give mass for a linear load or inertia for a rotary one, not both")
    if "mass" not in p and "inertia" not in p:
        raise InputError("mass: missing; give the load's mass (linear) or inertia (rotary)")
    if "mass" in p and rot:
        raise InputError(f"{rot[0]}: a rotary-load key on a linear load (mass given)")
    if "inertia" in p and lin:
        raise InputError(f"{lin[0]}: a linear-load key on a rotary load (inertia given)")
    return "length" if "mass" in p else "angle"


@dataclass(frozen=True)
class Drive:
    """A motor with its gearhead, transmission stages and load, and the profile it moves the load along."""

    name: str
    motor: Any
    gearhead: Gearhead | None
    stage_variants: tuple[tuple[tuple[str, Any], ...], ...]  # per stage: (friction label, stage) options
    load: Mapping[str, Any]  # the load keys as validated (quantities)
    kind: str  # "length" (linear load) or "angle" (rotary)
    profile: str
    cycle_time: Any = None
    supply_voltage: Any = None
    driver_current: Any = None
    inertia_ratio_limit: float | None = None
    ambient_temperature: str | None = None
    bus_capacitance: str | None = None
    overvoltage_limit: Any = None
    reported: dict[str, Any] = dataclasses.field(default_factory=dict, compare=False, repr=False)
    #: the last demands computed, (design, result): the 9 motor checks of one verify share them
    memo: list[Any] = dataclasses.field(default_factory=list, compare=False, repr=False)

    def make_load(self, case: Mapping[str, Any]) -> LinearLoad | RotaryLoad:
        """The load with a load case's replacements: mass/inertia/external/gravity replaced, payload added,
        load_factor multiplying mass or inertia, external force or torque and gravity torque."""
        p = {**self.load, **{k: case[k] for k in ("mass", "inertia", "external_force", "external_torque",
                                                  "gravity_torque") if k in case}}
        k = float(case.get("load_factor", 1.0))
        if not k > 0:
            raise InputError(f"load_factor: must be positive, got {k:g}")
        if self.kind == "length":
            if "inertia" in case or "external_torque" in case or "gravity_torque" in case:
                raise InputError("a rotary-load key in a load case of a linear drive")
            m = (p["mass"] + case.get("payload", Q(0, "kg"))) * k
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

    def demands(self, ctx: Any) -> list[tuple[str, Any, list[tuple[str, TorqueDemand]]]]:
        """(load case, profile, [(variant, demand)]) for every case that names the drive, or its own profile once.

        Computed once per design (every motor check of a verify asks for the same demands).
        """
        design = getattr(ctx, "design", None) if ctx is not None else None
        if design is not None and self.memo and self.memo[0] is design:
            return self.memo[1]
        out = self._demands(ctx)
        if design is not None:
            self.memo[:] = [design, out]
        return out

    def _demands(self, ctx: Any) -> list[tuple[str, Any, list[tuple[str, TorqueDemand]]]]:
        cases = []
        if ctx is not None and getattr(ctx, "design", None) is not None:
            for case, comps in ctx.design.data.load_cases.items():
                if self.name in comps:
                    cases.append((case, comps[self.name]))
        if not cases:
            cases = [("", {})]
        profiles = ctx.design.profiles if ctx is not None and getattr(ctx, "design", None) is not None else {}
        out = []
        for case, loads in cases:
            where = f"load case {case!r}: " if case else ""
            prof_name = loads.get("profile", self.profile)
            prof = profiles[prof_name]
            cycle = loads.get("cycle_time", self.cycle_time)
            try:
                trains = self.trains(loads)
            except MechverifyError as exc:
                raise InputError(f"{where}{exc}") from None
            try:
                out.append((case, prof, [(lab, tr.demand(prof, cycle_time=cycle)) for lab, tr in trains]))
            except MechverifyError as exc:
                raise InputError(f"{where}profile {prof_name!r}: {exc}") from None
        return out


def _build_drive(p: Mapping[str, Any], ctx: Mapping[str, Any]) -> Drive:
    errors: list[str] = []

    def attempt(f: Callable[[], Any]) -> Any:
        try:
            return f()
        except MechverifyError as exc:
            errors.append(str(exc))
            return None

    m = attempt(lambda: _motor(p))
    g = attempt(lambda: _gearhead(p))
    stages = attempt(lambda: _stages(list(p.get("transmission", [])), ctx))
    kind = attempt(lambda: _load_kind(p))
    limit = p.get("inertia_ratio_limit")
    if limit is not None and not limit > 0:
        errors.append(f"inertia_ratio_limit: must be positive, got {limit!r}")
    if errors:
        raise InputError("; ".join(errors))
    load = {k: p[k] for k in (*LINEAR_KEYS, *ROTARY_KEYS) if k in p}
    for key, unit in (("ambient_temperature", "degC"), ("bus_capacitance", "F")):
        if key in p:
            try:
                Q(p[key]).to(unit)
            except Exception:  # pint raises several types for text that is not such a quantity
                raise InputError(f"{key}: expected a value in {unit} units, got {p[key]!r}") from None
    d = Drive(p["_name"], m, g, tuple(tuple(s) for s in stages), load, kind, p["profile"],
              p.get("cycle_time"), p.get("supply_voltage"), p.get("driver_current"), limit,
              ambient_temperature=p.get("ambient_temperature"), bus_capacitance=p.get("bus_capacitance"),
              overvoltage_limit=p.get("overvoltage_limit"))
    # validate the chain (linear/rotary) and the own profile now, so the errors carry the drive's key path
    tr = d.trains()[0][1]
    prof = ctx.get("profile_objects", {}).get(p["profile"])
    if prof is not None and prof.kind != tr.load.kind:
        words = {"length": "linear", "angle": "rotary"}
        raise InputError(f"profile: {p['profile']!r} is a {words[prof.kind]} move but the load is "
                         f"{words[tr.load.kind]} ({'mass' if kind == 'length' else 'inertia'} given)")
    if prof is not None and "cycle_time" in p and p["cycle_time"] < prof.duration * (1 - 1e-9):
        raise InputError(f"cycle_time: {p['cycle_time']:~P} is shorter than the profile {p['profile']!r} "
                         f"({prof.duration:~P})")
    return d


# ============================================================================ drive: checks


def _with_rms(r: CheckResult, dem: TorqueDemand, drive: Drive, prof: Any, margin: float) -> CheckResult:
    """Add the RMS torque, continuous rating and the profile samples to the details for the report plots."""
    det = dict(r.details)
    det["rms_torque"] = dem.rms_torque
    if r.check == "motor_peak_torque":
        det["margin"] = margin
    elif r.check == "motor_supply_voltage" and margin > 0:  # the line the check allows: at U/SF
        U = to_si(drive.supply_voltage, "voltage", "supply_voltage") / margin
        w, T = drive.motor.torque_speed_curve(Q(U, "V"), n=50)
        det["margin_speed"], det["margin_torque"] = w.to("rpm"), T
        det["margin_label"] = f"speed-torque line at U/SF = {U:.4g} V"
    det["motor_kind"] = drive.motor.kind
    if drive.motor.continuous_torque is not None:
        det["continuous_torque"] = drive.motor.continuous_torque
    s = prof.sample()
    u = {"length": ("mm", "mm/s", "m/s**2"), "angle": ("deg", "deg/s", "rad/s**2")}[prof.kind]
    base = {"length": ("m", "m/s", "m/s**2"), "angle": ("rad", "rad/s", "rad/s**2")}[prof.kind]
    det["profile_time"] = Q(s.t, "s")
    det["profile_position"] = Q(s.x - s.x[0], base[0]).to(u[0])
    det["profile_velocity"] = Q(s.v, base[1]).to(u[1])
    det["profile_acceleration"] = Q(s.a, base[2]).to(u[2])
    T = np.abs(dem.motor_torque)
    i = int(np.argmax(T))
    if r.check == "motor_peak_torque":  # the point of highest utilisation T/T_avail(omega), as the check found it
        U = None if drive.supply_voltage is None else to_si(drive.supply_voltage, "voltage", "supply_voltage")
        avail = drive.motor.available_torque_si(dem.motor_speed, U)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.where(avail > 0, T / np.where(avail > 0, avail, 1.0), np.where(T > 0, np.inf, 0.0))
        i = int(np.argmax(u))
        det["governing_speed"] = Q(abs(float(dem.motor_speed[i])), "rad/s").to("rpm")
        det["governing_torque"] = Q(float(T[i]), "N*m")
    det["governing_time"] = Q(float(dem.t[i]), "s")
    return dataclasses.replace(r, details=det)


def _drive_check(fn: Callable[[Drive, TorqueDemand, Any, Any], CheckResult | None]) -> Callable[..., Any]:
    """Run ``fn(drive, demand, ctx, profile)`` for every load case and friction variant; per case keep the worst."""

    def run(drive: Drive, loads: Any, ctx: Any) -> list[CheckResult]:
        try:
            demands = drive.demands(ctx)
        except MechverifyError as exc:  # report a bad load case at one check, not at every one
            if drive.reported.setdefault(str(exc), fn) is not fn:
                return []
            raise
        results = []
        for case, prof, variants in demands:
            found = []
            for label, dem in variants:
                r = fn(drive, dem, ctx, prof)
                if r is None:
                    continue
                if len(variants) > 1:
                    others = [lab for lab, _ in variants if lab != label]
                    r = dataclasses.replace(r, notes=(*r.notes, f"screw friction {label} governs (also evaluated: "
                                                                f"{', '.join(others)})"))
                found.append(r)
            if found:
                gov = max(found, key=lambda r: r.utilisation)
                if case:
                    gov = dataclasses.replace(gov, load_case=f"{case} ({gov.load_case})")
                results.append(gov)
        return results

    return run


def _sf(ctx: Any) -> float:
    return float(getattr(ctx, "required_sf", 1.0) or 1.0)


def _peak(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult:
    r = mc.check_motor_peak_torque(dem, margin=_sf(ctx), supply_voltage=d.supply_voltage)
    missing = _not_checked(d)
    if missing:
        r = dataclasses.replace(r, notes=(*r.notes, "not checked, rating missing: " + "; ".join(missing)))
    return _with_rms(r, dem, d, prof, _sf(ctx))


def _rms(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    if d.motor.kind == "stepper":
        return None
    return _with_rms(mc.check_motor_rms_torque(dem), dem, d, prof, _sf(ctx))


def _not_checked(d: Drive) -> list[str]:
    """Motor-fit checks that cannot run because a rating is missing (named in the peak-torque check's notes)."""
    m, g, out = d.motor, d.gearhead, []
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
    if d.driver_current is not None and m.kind == "gearmotor" and m.stall_current is None:
        out.append("driver current (no stall current)")
    return out


def _or_none(fn: Callable[[], CheckResult]) -> CheckResult | None:
    """The check, or None when the data lack the rating it needs (listed by :func:`_not_checked`)."""
    try:
        return fn()
    except InputError:
        return None


def _speed(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    r = _or_none(lambda: mc.check_motor_max_speed(dem))
    return None if r is None else _with_rms(r, dem, d, prof, _sf(ctx))


def _gear(fn: Callable[..., CheckResult]) -> Callable[..., CheckResult | None]:
    def run(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
        return None if d.gearhead is None else _or_none(lambda: fn(dem, d.gearhead))

    return run


def _inertia(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    if d.motor.kind == "servo":
        return None
    return _or_none(lambda: mc.check_inertia_ratio(dem, max_ratio=d.inertia_ratio_limit))


def _voltage(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    if d.supply_voltage is None or d.motor.kind != "dc":
        return None
    return _with_rms(mc.check_motor_supply_voltage(dem, d.supply_voltage), dem, d, prof, _sf(ctx))


def _current(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    if d.driver_current is None or not hasattr(d.motor, "current_si"):
        return None
    return _or_none(lambda: mc.check_driver_current(dem, d.driver_current))


def _thermal(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    """The winding temperature: DC motors with thermal data; asked for explicitly without them, the named error."""
    entry = ctx.design.data.components.get(ctx.component) if getattr(ctx, "design", None) is not None else None
    asked = entry is not None and entry.checks.get("motor_winding_temperature", {}).get("enabled") is True
    if not asked and (d.motor.kind != "dc" or any(getattr(d.motor, f) is None for f in THERMAL_FIELDS)):
        return None
    return mc.check_motor_winding_temperature(dem, ambient_temperature=d.ambient_temperature or "25 degC")


def _regen(d: Drive, dem: TorqueDemand, ctx: Any, prof: Any) -> CheckResult | None:
    if d.bus_capacitance is None or d.overvoltage_limit is None or d.motor.kind != "dc":
        return None
    if d.supply_voltage is None:
        raise InputError("drive_regeneration needs supply_voltage (the bus voltage before braking)")
    return mc.check_drive_regeneration(dem, d.supply_voltage, d.bus_capacitance, d.overvoltage_limit)


DRIVE = REGISTRY.register(ComponentType(
    name="drive",
    doc="A motor (catalogue name or inline data) with an optional gearhead and transmission stages moving a linear "
        "or rotary load along a motion profile; the motor-fit checks run on the torque the profile demands.",
    fields=(
        Field("motor", "str", "catalogue motor name or alias (see `mechverify motors`)"),
        Field("motor_data", "table", "inline motor: type = dc | stepper | servo | gearmotor and its datasheet values"),
        Field("gearhead", "str", "catalogue gearhead name or alias"),
        Field("gearhead_data", "table", "inline gearhead: ratio, efficiency, continuous_torque, ..."),
        Field("transmission", "list", "stages from the motor side: screw, drum, belt, direct (tables with type)",
              item="table"),
        Field("profile", "ref", "the move (a name in [profiles])", required=True, ref="profiles"),
        Field("cycle_time", "time", "duty cycle for the RMS torque (standstill after the move included)"),
        Field("mass", "mass", "linear load: moving mass"),
        Field("incline", "angle", "linear load: axis angle above horizontal (90 deg = vertical lift, +x upward)"),
        Field("friction_coefficient", "dimensionless", "linear load: guide friction coefficient (mu·m·g·cos)"),
        Field("friction_force", "force", "linear load: constant friction force against the motion"),
        Field("external_force", "force", "linear load: constant force against positive motion"),
        Field("inertia", "inertia", "rotary load: inertia about the output axis"),
        Field("gravity_torque", "torque", "rotary load: unbalance m·g·r (torque = gravity_torque·cos(x + phase))"),
        Field("gravity_phase", "angle", "rotary load: arm angle above horizontal at the profile's start"),
        Field("friction_torque", "torque", "rotary load: constant friction torque against the motion"),
        Field("external_torque", "torque", "rotary load: constant torque against positive motion"),
        Field("supply_voltage", "voltage", "DC motors: supply (driver output) voltage"),
        Field("driver_current", "current", "maximum current of the driver"),
        Field("inertia_ratio_limit", "float", "allowed load-to-rotor inertia ratio (default 10)"),
        Field("ambient_temperature", "str", "motor ambient temperature (motor_winding_temperature; default '25 degC')"),
        Field("bus_capacitance", "str", "supply/driver bus capacitance for drive_regeneration, e.g. '2200 uF'"),
        Field("overvoltage_limit", "voltage", "driver's overvoltage limit for drive_regeneration"),
    ),
    build=lambda p, ctx: _build_drive(p, ctx),
    loads=(
        Field("profile", "ref", "the move in this case (replaces the drive's)", ref="profiles"),
        Field("cycle_time", "time", "duty cycle in this case"),
        Field("mass", "mass", "load mass (replaces)"),
        Field("payload", "mass", "mass added to the load"),
        Field("inertia", "inertia", "load inertia (replaces)"),
        Field("external_force", "force", "external force (replaces)"),
        Field("external_torque", "torque", "external torque (replaces)"),
        Field("gravity_torque", "torque", "gravity torque (replaces)"),
        Field("load_factor", "float", "multiplies mass or inertia, external force or torque and gravity torque"),
    ),
    checks=(
        CheckSpec.of(mc.check_motor_peak_torque, _drive_check(_peak)),
        CheckSpec.of(mc.check_motor_rms_torque, _drive_check(_rms)),
        CheckSpec.of(mc.check_motor_max_speed, _drive_check(_speed)),
        CheckSpec.of(mc.check_gearhead_continuous_torque, _drive_check(_gear(mc.check_gearhead_continuous_torque))),
        CheckSpec.of(mc.check_gearhead_intermittent_torque,
                     _drive_check(_gear(mc.check_gearhead_intermittent_torque))),
        CheckSpec.of(mc.check_gearhead_input_speed, _drive_check(_gear(mc.check_gearhead_input_speed))),
        CheckSpec.of(mc.check_inertia_ratio, _drive_check(_inertia)),
        CheckSpec.of(mc.check_motor_supply_voltage, _drive_check(_voltage)),
        CheckSpec.of(mc.check_driver_current, _drive_check(_current)),
        CheckSpec.of(mc.check_motor_winding_temperature, _drive_check(_thermal)),
        CheckSpec.of(mc.check_drive_regeneration, _drive_check(_regen)),
    ),
))
