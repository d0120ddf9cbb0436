"""Fields and parsing shared by the spring types of :mod:`mechverify.design.adapters.springs` (declares no type)."""

from __future__ import annotations

from typing import Any

import pint

from mechverify.components.spring_formulas import SPRING_CLASSES
from mechverify.design.adapters.common import pick
from mechverify.design.spec import Field
from mechverify.errors import InputError
from mechverify.units import fmt

END_TYPES = ("squared-ground", "squared", "plain-ground", "plain")
END_CONDITIONS = ("fixed-fixed", "fixed-pinned", "pinned-pinned", "fixed-guided", "fixed-free")
CRITERIA = ("gerber", "goodman", "sines", "asme_elliptic", "soderberg")
DIAMETERS = {"mean_diameter": "D", "outside_diameter": "OD", "inside_diameter": "ID"}


def wire_fields(coils: tuple[Field, ...]) -> tuple[Field, ...]:
    """The wire, coil-diameter and material fields of every spring type, with ``coils`` after the diameters."""
    return (
        Field("wire_diameter", "length", "wire diameter d", required=True),
        Field("mean_diameter", "length", "mean coil diameter D (or give outside_diameter or inside_diameter)"),
        Field("outside_diameter", "length", "outside coil diameter OD = D + d"),
        Field("inside_diameter", "length", "inside coil diameter ID = D - d"),
        *coils,
        Field("material", "material", "spring wire (Sut from its wire-strength table at d)",
              default="ASTM A228 music wire"),
        Field("shear_modulus", "pressure", "G, instead of the material's (Shigley Table 10-5 lists it by size)"),
        Field("elastic_modulus", "pressure", "E, instead of the material's"),
        Field("tensile_strength", "pressure", "minimum tensile strength Sut of the wire, instead of the table's"),
        Field("spring_class", "choice", "Shigley Table 10-6 wire class, instead of the one found from the "
                                        "material's ASTM code", choices=SPRING_CLASSES),
    )


def wire_kwargs(p: dict[str, Any], *, shear: bool = True) -> dict[str, Any]:
    """Keyword arguments of the spring classes from the wire fields (exactly one coil diameter given)."""
    given = [k for k in DIAMETERS if k in p]
    if len(given) != 1:
        raise InputError(f"give exactly one of mean_diameter, outside_diameter or inside_diameter "
                         f"(got {', '.join(given) or 'none'})")
    out = {"d": p["wire_diameter"], DIAMETERS[given[0]]: p[given[0]], "name": p["_name"]}
    out.update(pick(p, "material", "spring_class", E="elastic_modulus", Sut="tensile_strength"))
    if shear:
        out.update(pick(p, G="shear_modulus"))
    return out


def nonnegative(q: pint.Quantity, what: str) -> pint.Quantity:
    """``q`` itself, or an :class:`InputError` naming ``what`` when it is negative."""
    if q.magnitude < 0:
        raise InputError(f"{what} must be >= 0, got {fmt(q)}")
    return q
