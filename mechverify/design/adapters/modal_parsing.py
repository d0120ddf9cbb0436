"""Design-file keys of a natural-frequency requirement, shared by the ``frame`` and ``plate_fea`` types (the same
keys and meaning as ``solid_fea``): ``min_frequency`` or ``excitation_band`` with ``frequency_margin``, and
``modes`` (how many are computed); and the ``in_plane`` load-case key of ``plate_fea`` (membrane edge loads for
``buckling_load_factor``). Parsing only; the checks are :func:`mechverify.checks.fea.check_natural_frequency` and
:func:`~mechverify.checks.fea.check_buckling_load_factor`. Declares no component type."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from mechverify.checks import fea as fc
from mechverify.checks.result import CheckResult
from mechverify.design.spec import Field
from mechverify.errors import InputError, MechverifyError
from mechverify.units import as_quantity, fmt

MODAL_FIELDS = (
    Field("min_frequency", "frequency", "the first natural frequency must reach this (check natural_frequency)"),
    Field("excitation_band", "list", "[lo, hi] excitation frequencies no mode may come near (check "
                                     "natural_frequency)", item="str"),
    Field("frequency_margin", "float", "separation from the excitation band (0.15 = 15 %)", default=0.15),
    Field("modes", "int", "natural frequencies computed", default=6),
)


IN_PLANE_FIELD = Field(
    "in_plane", "table", "in-plane (membrane) edge loads: {nx, ny, nxy} force per length on the outline edges, "
    "tension positive (\"-10 N/mm\" compresses); nx = [at the lowest y, at the highest y] varies linearly, ny = [at "
    "the lowest x, at the highest x] likewise; their membrane stress N/t adds to the bending stress in "
    "plate_stress_fea and they load buckling_load_factor", item="table")
IN_PLANE_KEYS = ("nx", "ny", "nxy")


def in_plane_load(v: Any, path: str) -> Any:
    """The :class:`mechverify.fea.plate_buckling.InPlaneLoad` of a load case's ``in_plane`` table at key ``path``;
    bad values are an :class:`InputError` naming the key."""
    from mechverify.fea.plate_buckling import InPlaneLoad

    if not isinstance(v, Mapping) or not v:
        raise InputError(f"{path}: expected a table {{nx = \"-10 N/mm\", ny = ..., nxy = ...}}, got {v!r}")
    bad = [k for k in v if k not in IN_PLANE_KEYS]
    if bad:
        raise InputError(f"{path}.{bad[0]}: not a key of in_plane (nx, ny, nxy)")
    vals: dict[str, Any] = {}
    for k, x in v.items():
        if isinstance(x, list) and k != "nxy":
            if len(x) != 2:
                raise InputError(f"{path}.{k}: one value or two [at the low side, at the high side], got {x!r}")
            vals[k] = tuple(as_quantity(q, "force_per_length", f"{path}.{k}[{i}]") for i, q in enumerate(x))
        else:
            vals[k] = as_quantity(x, "force_per_length", f"{path}.{k}")
    load = InPlaneLoad(**vals)
    try:
        load.values()
    except InputError as exc:
        raise InputError(f"{path}: {str(exc).split(': ', 1)[-1]}") from None
    return load


@dataclass(frozen=True)
class ModalSettings:
    """A frequency requirement: ``minimum`` or ``band`` (lo, hi) with ``margin``; ``modes`` computed."""

    modes: int
    minimum: Any = None
    band: tuple[Any, Any] | None = None
    margin: float = 0.15

    def solve(self, fn: Any, *args: Any, hint: str = "", **kw: Any) -> Any:
        """``fn(args[0], self.modes, *args[1:], **kw)`` (frame_modes, plate_modes); its "n_modes" errors name the
        key ``modes``, and ``hint`` (in design-file keys) replaces the API's advice after the last "; " of a
        too-many-modes message."""
        try:
            return fn(*args[:1], self.modes, *args[1:], **kw)
        except InputError as exc:
            msg = str(exc).split(": ", 1)[-1]
            if hint and "modes asked" in msg and "; " in msg:
                msg = f"{msg.rsplit('; ', 1)[0]}; {hint}"
            raise InputError(f"modes: {msg}") from None

    def check(self, res: Any, component: str) -> CheckResult:
        """The natural_frequency check of modal results ``res`` (frame or plate)."""
        return fc.check_natural_frequency(res, minimum=self.minimum, band=self.band, margin=self.margin,
                                          component=component)


def modal_settings(p: Mapping[str, Any]) -> ModalSettings | None:
    """The frequency requirement of a component's fields ``p`` (None when it gives neither ``min_frequency`` nor
    ``excitation_band``); bad values are an :class:`InputError` naming the key."""
    modes = p.get("modes", 6)
    if isinstance(modes, bool) or not isinstance(modes, int) or modes < 1:
        raise InputError(f"modes: the number of natural frequencies computed, a whole number >= 1, got {modes!r}")
    margin = p.get("frequency_margin", 0.15)
    if isinstance(margin, bool) or not isinstance(margin, int | float) or not 0 <= margin < 10:
        raise InputError(f"frequency_margin: a fraction >= 0 (0.15 = 15 %), got {margin!r}")
    if "min_frequency" in p and "excitation_band" in p:
        raise InputError("min_frequency: give min_frequency or excitation_band, not both")
    if "min_frequency" in p:
        fmin = p["min_frequency"]
        if not fmin.magnitude > 0:
            raise InputError(f"min_frequency: must be positive, got {fmt(fmin, 'Hz')}")
        return ModalSettings(modes, minimum=fmin, margin=float(margin))
    if "excitation_band" not in p:
        return None
    band = p["excitation_band"]
    if not isinstance(band, list) or len(band) != 2:
        raise InputError(f"excitation_band: expected [\"lo Hz\", \"hi Hz\"], got {band!r}")
    try:
        lo, hi = (as_quantity(b, "frequency", f"excitation_band[{i}]") for i, b in enumerate(band))
    except MechverifyError as exc:
        raise InputError(f"excitation_band: {str(exc).split(': ', 1)[-1]}") from None
    if not 0 <= lo.m_as("Hz") <= hi.m_as("Hz"):
        raise InputError(f"excitation_band: expected [lo, hi] with 0 <= lo <= hi, got {band!r}")
    return ModalSettings(modes, band=(lo, hi), margin=float(margin))
