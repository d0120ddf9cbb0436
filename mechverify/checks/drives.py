"""The motor-fit checks of a :class:`~mechverify.motion.drive.Drive`: which apply, over load cases and variants.

The single checks are those of :mod:`mechverify.checks.motors` (one limit each, on one
:class:`~mechverify.motion.drive_train.TorqueDemand`). This module runs them on a whole drive the way a
design file's ``drive`` component does:

* which checks apply (a stepper has no RMS-torque rating, a servo's inertia ratio is not limited,
  the supply-voltage and regeneration checks need a DC motor and the ratings, a check whose rating
  is missing in the data is skipped and named in the peak-torque check's notes);
* every load case and every friction variant (a screw's nut friction range: mu_max and mu_min) is
  evaluated, the worst variant governs per case (named in the notes);
* the results carry the RMS torque, the motor ratings and the profile samples for the report figures.

:func:`drive_checks` runs them all (the Python equivalent of a design file's ``drive``);
:func:`run_drive_check` one of them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from mechverify.checks import motors as mc
from mechverify.checks.result import CheckResult
from mechverify.components.motors import THERMAL_FIELDS
from mechverify.errors import InputError
from mechverify.motion.drive import CaseDemands, Drive
from mechverify.motion.drive_train import TorqueDemand
from mechverify.units import Q, to_si


def with_plot_data(r: CheckResult, dem: TorqueDemand, drive: Drive, prof: Any, margin: float) -> CheckResult:
    """Add the RMS torque, continuous rating and the profile samples to the details for the report plots
    (computed when the details are first read: a study sample never reads them)."""
    base = r.details
    return r.replace(details=lambda: _plot_data(base, r.check, dem, drive, prof, margin))


def _plot_data(base: Mapping[str, Any], check: str, dem: TorqueDemand, drive: Drive, prof: Any,
               margin: float) -> dict[str, Any]:
    """The details of :func:`with_plot_data`: ``base`` (the check's own) and the drive's figure data."""
    det = dict(base)
    det["rms_torque"] = dem.rms_torque
    if check == "motor_peak_torque":
        det["margin"] = margin
    elif check == "motor_supply_voltage" and margin > 0:  # the line the check allows: at U/SF
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
    if check == "motor_peak_torque":  # the point of highest utilisation T/T_avail(omega), as the check found it
        U = None if drive.supply_voltage is None else to_si(drive.supply_voltage, "voltage", "supply_voltage")
        avail = drive.motor.available_torque_si(dem.motor_speed, U)
        with np.errstate(divide="ignore", invalid="ignore"):
            ut = np.where(avail > 0, T / np.where(avail > 0, avail, 1.0), np.where(T > 0, np.inf, 0.0))
        i = int(np.argmax(ut))
        det["governing_speed"] = Q(abs(float(dem.motor_speed[i])), "rad/s").to("rpm")
        det["governing_torque"] = Q(float(T[i]), "N*m")
    det["governing_time"] = Q(float(dem.t[i]), "s")
    return det


def _or_none(fn: Callable[[], CheckResult]) -> CheckResult | None:
    """The check, or None when the data lack the rating it needs (listed by :meth:`Drive.missing_ratings`)."""
    try:
        return fn()
    except InputError:
        return None


#: One drive check on one demand: (drive, demand, profile, margin, asked) -> result or None (does not apply).
DriveCheck = Callable[[Drive, TorqueDemand, Any, float, bool], "CheckResult | None"]


def _peak(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult:
    r = mc.check_motor_peak_torque(dem, margin=sf, supply_voltage=d.supply_voltage)
    missing = d.missing_ratings()
    if missing:
        r = r.replace(notes=(*r.notes, "not checked, rating missing: " + "; ".join(missing)))
    return with_plot_data(r, dem, d, prof, sf)


def _rms(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    if d.motor.kind == "stepper":
        return None
    return with_plot_data(mc.check_motor_rms_torque(dem), dem, d, prof, sf)


def _speed(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    r = _or_none(lambda: mc.check_motor_max_speed(dem))
    return None if r is None else with_plot_data(r, dem, d, prof, sf)


def _gear(fn: Callable[..., CheckResult]) -> DriveCheck:
    def run(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
        return None if d.gearhead is None else _or_none(lambda: fn(dem, d.gearhead))

    return run


def _inertia(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    if d.motor.kind == "servo":
        return None
    return _or_none(lambda: mc.check_inertia_ratio(dem, max_ratio=d.inertia_ratio_limit))


def _voltage(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    if d.supply_voltage is None or d.motor.kind != "dc":
        return None
    return with_plot_data(mc.check_motor_supply_voltage(dem, d.supply_voltage), dem, d, prof, sf)


def _current(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    if d.driver_current is None or not hasattr(d.motor, "current_si"):
        return None
    return _or_none(lambda: mc.check_driver_current(dem, d.driver_current))


def _thermal(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    """The winding temperature: DC motors with thermal data; asked for explicitly without them, the named error."""
    if not asked and (d.motor.kind != "dc" or any(getattr(d.motor, f) is None for f in THERMAL_FIELDS)):
        return None
    return mc.check_motor_winding_temperature(dem, ambient_temperature=d.ambient_temperature or "25 degC")


def _regen(d: Drive, dem: TorqueDemand, prof: Any, sf: float, asked: bool) -> CheckResult | None:
    if d.bus_capacitance is None or d.overvoltage_limit is None or d.motor.kind != "dc":
        return None
    if d.supply_voltage is None:
        raise InputError("drive_regeneration needs supply_voltage (the bus voltage before braking)")
    return mc.check_drive_regeneration(dem, d.supply_voltage, d.bus_capacitance, d.overvoltage_limit)


#: The check functions of a drive, in report order, with how each runs on one demand.
DRIVE_CHECKS: dict[Callable[..., Any], DriveCheck] = {
    mc.check_motor_peak_torque: _peak,
    mc.check_motor_rms_torque: _rms,
    mc.check_motor_max_speed: _speed,
    mc.check_gearhead_continuous_torque: _gear(mc.check_gearhead_continuous_torque),
    mc.check_gearhead_intermittent_torque: _gear(mc.check_gearhead_intermittent_torque),
    mc.check_gearhead_input_speed: _gear(mc.check_gearhead_input_speed),
    mc.check_inertia_ratio: _inertia,
    mc.check_motor_supply_voltage: _voltage,
    mc.check_driver_current: _current,
    mc.check_motor_winding_temperature: _thermal,
    mc.check_drive_regeneration: _regen,
}


def run_drive_check(fn: Callable[..., Any], drive: Drive, demands: Sequence[CaseDemands], *, required_sf: float = 1.0,
                asked: bool = False) -> list[CheckResult]:
    """One check (``fn``, a key of :data:`DRIVE_CHECKS`) over the demands of every load case.

    Per case the worst friction variant governs (the others are named in its notes); a case's result
    names the case. An empty list when the check does not apply to this drive.

    Args:
        fn: the check function, e.g. :func:`mechverify.checks.motors.check_motor_peak_torque`.
        drive: the drive.
        demands: what :meth:`Drive.demands` returns.
        required_sf: the margin of the peak-torque check (and of the supply-voltage figure line).
        asked: the check was enabled explicitly (the winding temperature then runs without thermal data,
            to name what is missing).
    """
    one = DRIVE_CHECKS[fn]
    results = []
    for case, prof, variants in demands:
        found = []
        for label, dem in variants:
            r = one(drive, dem, prof, required_sf, asked)
            if r is None:
                continue
            if len(variants) > 1:
                others = [lab for lab, _ in variants if lab != label]
                r = r.replace(notes=(*r.notes, f"screw friction {label} governs (also evaluated: "
                                              f"{', '.join(others)})"))
            found.append(r)
        if found:
            gov = max(found, key=lambda r: r.utilisation)
            if case:
                gov = gov.replace(load_case=f"{case} ({gov.load_case})")
            results.append(gov)
    return results


def drive_checks(drive: Drive, *, cases: Sequence[tuple[str, Mapping[str, Any]]] = (),
                profiles: Mapping[str, Any] | None = None, required_sf: float = 1.0) -> list[CheckResult]:
    """Every motor-fit check that applies to ``drive``, over its load cases (see :meth:`Drive.demands`).

    Raises:
        InputError: a bad load case or a profile the drive train cannot follow.
    """
    demands = drive.demands(cases, profiles)
    return [r for fn in DRIVE_CHECKS for r in run_drive_check(fn, drive, demands, required_sf=required_sf)]
