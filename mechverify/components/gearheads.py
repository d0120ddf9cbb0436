"""Gearheads: ratio (exact from its stages when given), efficiency, output torque limits, input
speed limit, inertia and backlash, with the catalogue lookup :func:`gearhead`.

A gearhead is also a transmission stage (rotary to rotary) usable in a drive train: torque is
reflected with the ratio and the efficiency (T_in = T_out/(i·η) when motoring), inertia with the
square of the ratio (J_in = J_out/i²) [1, 2].

References
----------
1. maxon motor ag, *maxon gear: Key information* (catalogue): reduction i = n_in/n_out,
   M_out = M_in·i·η; the max. continuous torque is compared with the load's RMS torque and the
   intermittent torque with its peak; the gearhead's mass inertia is given at its input.
2. Oriental Motor, *Technical Reference: Motor Sizing Calculations* (gearhead: T_M = T_L/(i·η),
   J_M = J_L/i²).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
import pint

from mechverify.components.catalogue import Catalogue, catalogue_entry
from mechverify.components.transmissions import _Reduction, effort_to_input
from mechverify.errors import InputError
from mechverify.frozen import set_fields
from mechverify.units import QuantityLike, fmt, from_si, to_si

_DATA = Path(__file__).parent / "data" / "gearheads.toml"


def parse_ratio(value: QuantityLike, name: str = "ratio") -> float:
    """A reduction ratio from a number, a fraction string ('531441/625') or 'a:b' ('850:1')."""
    if isinstance(value, bool):
        raise InputError(f"{name}: expected a number or a fraction string, got {value!r}")
    if isinstance(value, int | float):
        r = float(value)
    elif isinstance(value, str):
        text = value.strip().replace(" ", "")
        try:
            if ":" in text:
                a, b = text.split(":")
                r = float(Fraction(a) / Fraction(b))
            else:
                r = float(Fraction(text))
        except (ValueError, ZeroDivisionError):
            raise InputError(f"{name}: cannot read {value!r} as a ratio (give 3.7, '26/7' or '850:1')") from None
    elif isinstance(value, pint.Quantity):
        r = float(to_si(value, "dimensionless", name))
    else:
        raise InputError(f"{name}: expected a number or a fraction string, got {type(value).__name__}")
    if not (math.isfinite(r) and r > 0):
        raise InputError(f"{name}: must be positive, got {r:g}")
    return r


@dataclass(frozen=True)
class Gearhead(_Reduction):
    """A gearhead (planetary, spur, harmonic...) rated at its output.

    ``ratio`` is the exact (absolute) reduction n_in/n_out: a number or a fraction string such
    as maxon's "531441/625"; ``stage_ratios`` lists each stage's ratio (numbers or fractions),
    whose product then fixes the ratio (a ``ratio`` given as well must agree to 1e-6).
    ``nominal_ratio`` is the catalogue label ("850:1"). ``efficiency`` is the maximum (catalogue)
    efficiency, used in both directions unless ``backdrive_efficiency`` is given. ``inertia`` is the
    gearhead's mass inertia at its input shaft.
    """

    name: str
    ratio: Any = None
    efficiency: Any = 1.0
    continuous_torque: Any = None  # output
    intermittent_torque: Any = None  # output
    max_input_speed: Any = None  # continuous
    max_input_speed_intermittent: Any = None
    inertia: Any = None
    backlash: Any = None
    stages: int | None = None
    stage_ratios: tuple[Any, ...] = ()
    nominal_ratio: str = ""
    backdrive_efficiency: Any = None
    source: str = ""
    notes: tuple[str, ...] = ()
    input_kind: str = field(default="angle", init=False)
    output_kind: str = field(default="angle", init=False)

    def __post_init__(self) -> None:
        n = self.name
        stage = tuple(parse_ratio(s, f"{n}.stage_ratios[{i}]") for i, s in enumerate(self.stage_ratios))
        if stage:
            exact = float(np.prod(stage))
            if self.ratio is not None:
                r = parse_ratio(self.ratio, f"{n}.ratio")
                if abs(r - exact) > 1e-6 * exact:
                    raise InputError(f"gearhead {n!r}: ratio {r:.8g} disagrees with the product of its stage ratios "
                                     f"{exact:.8g}")
            if self.stages is not None and self.stages != len(stage):
                raise InputError(f"gearhead {n!r}: stages = {self.stages} but {len(stage)} stage ratios given")
            set_fields(self, stages=len(stage))
            ratio = exact
        elif self.ratio is not None:
            ratio = parse_ratio(self.ratio, f"{n}.ratio")
        else:
            raise InputError(f"gearhead {n!r}: give ratio or stage_ratios")
        set_fields(self, stage_ratios=stage, ratio=ratio)
        self._normalise_efficiencies(negative_backdrive=True)
        dims = {"continuous_torque": "torque", "intermittent_torque": "torque", "max_input_speed": "angular_velocity",
                "max_input_speed_intermittent": "angular_velocity", "inertia": "inertia", "backlash": "angle"}
        for f, d in dims.items():
            v = getattr(self, f)
            if v is not None:
                x = to_si(v, d, f"{n}.{f}")
                if x < 0 or (x == 0 and f != "backlash"):
                    raise InputError(f"{n}.{f}: must be positive")
                set_fields(self, **{f: from_si(x, d)})
        if (self.continuous_torque is not None and self.intermittent_torque is not None
                and self.intermittent_torque < self.continuous_torque):
            raise InputError(f"gearhead {n!r}: intermittent torque {fmt(self.intermittent_torque)} below continuous "
                             f"{fmt(self.continuous_torque)}")
        if self.stages is not None and self.stages < 1:
            raise InputError(f"gearhead {n!r}: stages must be >= 1")
        set_fields(self, notes=tuple(self.notes))

    ratio_si = property(lambda self: self.ratio)
    efficiency_forward = property(lambda self: self.efficiency)

    def input_effort_si(self, effort_out: Any, direction: Any) -> np.ndarray:
        return effort_to_input(effort_out, direction, self.ratio, self.efficiency, self.backdrive_efficiency)

    @property
    def output_backlash_at_motor(self) -> pint.Quantity | None:
        """Backlash seen as motor-shaft angle (backlash·i)."""
        return None if self.backlash is None else self.backlash * self.ratio

    def __repr__(self) -> str:
        lim = f" {fmt(self.continuous_torque)} cont." if self.continuous_torque is not None else ""
        return f"<Gearhead {self.name!r} i={self.ratio:.6g} η={self.efficiency:g}{lim}>"


def gearhead_from_dict(d: Mapping[str, Any], references: Mapping[str, str] | None = None) -> Gearhead:
    """Build a gearhead from a TOML-style mapping (a catalogue entry, a design file's ``gearhead_data``)."""
    return Gearhead(**catalogue_entry(Gearhead, d, f"gearhead {d.get('name')!r}", "a gearhead", references,
                                      tuples=("notes", "stage_ratios")))


_CATALOGUE: Catalogue[Gearhead] = Catalogue("gearhead", _DATA, "gearhead", gearhead_from_dict)


def gearhead(name: str | Gearhead) -> Gearhead:
    """A catalogue gearhead by name or alias (``components/data/gearheads.toml``)."""
    if not isinstance(name, str):
        return name
    return _CATALOGUE.get(name)


def gearhead_names() -> list[str]:
    return _CATALOGUE.names()


__all__ = ["Gearhead", "gearhead", "gearhead_names", "gearhead_from_dict", "parse_ratio"]
