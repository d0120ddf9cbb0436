"""``cable_spine``: a cable-driven spring spine (seed 001's neck): spring column, platform, N cables.

Parses the design file and calls :class:`mechverify.mechanisms.cable_spine.CableSpine`; checks from
:mod:`mechverify.checks.cable_spine` (buckling ratio, cable rating). Outputs other components read:
``cable_tension`` (the pulling cable's tension at the case's ``tilt``/``pan``, e.g. a cable drive's
``external_force = "neck.cable_tension"``) and ``axial_force`` (the spring's compressive load at the
pose, for the compression-spring stress and fatigue checks of the same spring).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from mechverify.checks import cable_spine as cc
from mechverify.components.springs import CompressionSpring
from mechverify.design.adapters.common import pick
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.mechanisms.cable_spine import CableSpine, SpineState, UnreachableTiltError
from mechverify.mechanisms.cable_spine_3d import as_spine_state, bracketing_cables, spine_parameters, state_3d
from mechverify.units import Q

DIAMETERS = {"mean_diameter": "D", "outside_diameter": "OD", "inside_diameter": "ID"}


@dataclasses.dataclass(frozen=True)
class SpineInstallation:
    """The built spine, how its statics are solved, the cable rating, and a per-pose cache."""

    spine: CableSpine
    method: str = "elastica"
    cable_rating: Any = None
    cache: dict = dataclasses.field(default_factory=dict, compare=False, repr=False)

    def state(self, loads: Any) -> SpineState:
        """Equilibrium at the case's tilt. Pan along a cable (default the first cable's angle): the planar model
        (``method``); a pan between cables: the 3D rod (:mod:`mechverify.mechanisms.cable_spine_3d`), its most
        loaded cable as the pulling cable's tension."""
        tilt = loads["tilt"].m_as("rad")
        pan = Q(loads["pan"] if "pan" in loads else self.spine.cable_angles[0]).m_as("rad")
        _i, j = bracketing_cables(spine_parameters(self.spine)["g"], pan)
        key = (round(tilt, 12), self.method if j is None else "3d", 0.0 if j is None else round(pan, 12))
        if key not in self.cache:
            if j is None:
                self.cache[key] = self.spine.at_tilt(Q(tilt, "rad"), self.method)
            elif self.method != "elastica":
                raise InputError(f"{self.spine.name}: a pan between cables ({math.degrees(pan):g} deg) is solved as a "
                                 "3D elastic rod; set method = \"elastica\" (the linear model is planar)")
            else:
                self.cache[key] = as_spine_state(self.spine, state_3d(self.spine, Q(tilt, "rad"), Q(pan, "rad")))
        return self.cache[key]


def _build(p: dict[str, Any], ctx: Any) -> SpineInstallation:
    given = [k for k in DIAMETERS if k in p]
    if len(given) != 1:
        raise InputError(f"give exactly one of mean_diameter, outside_diameter or inside_diameter "
                         f"(got {', '.join(given) or 'none'})")
    spring = CompressionSpring(d=p["wire_diameter"], L0=p["free_length"], Na=p["active_coils"], end=p["ends"],
                               name=p["_name"], **{DIAMETERS[given[0]]: p[given[0]]},
                               **pick(p, "material", G="shear_modulus", E="elastic_modulus"))
    kw = pick(p, platform_radius="platform_radius", base_radius="base_radius", weight="weight",
              beta0="bending_rigidity")
    if "cable_angles" in p:
        kw["cable_angles"] = tuple(p["cable_angles"])
    return SpineInstallation(CableSpine(spring, name=p["_name"], **kw), p["method"], p.get("cable_rating"))


def _buckling(c: SpineInstallation, loads: Any, ctx: Any) -> Any:
    try:
        state = c.state(loads)
    except UnreachableTiltError as exc:  # past buckling: a FAIL with the load ratio, not a solver failure
        return cc.check_spine_past_buckling(c.spine, str(exc), required_sf=ctx.required_sf, load_case=ctx.load_case)
    return cc.check_spine_buckling_ratio(c.spine, state, required_sf=ctx.required_sf, load_case=ctx.load_case)


def _rating(c: SpineInstallation, loads: Any, ctx: Any) -> Any:
    if c.cable_rating is None:
        return []
    return cc.check_cable_tension(c.spine, c.state(loads), c.cable_rating, required_sf=ctx.required_sf,
                                  load_case=ctx.load_case)


CABLE_SPINE = REGISTRY.register(ComponentType(
    name="cable_spine",
    doc="A cable-driven spring spine: a helical compression spring clamped on a base, a platform on its free top "
        "and N cables from platform anchors (radius a) to base anchors (radius b); statics of the spring as a "
        "beam-column with Timoshenko & Gere's rigidities (Sec. 2.18), small-deflection or elastica.",
    fields=(
        Field("wire_diameter", "length", "spring wire diameter d", required=True),
        Field("mean_diameter", "length", "mean coil diameter D (or outside_diameter / inside_diameter)"),
        Field("outside_diameter", "length", "outside coil diameter"),
        Field("inside_diameter", "length", "inside coil diameter"),
        Field("active_coils", "float", "active coils n", required=True),
        Field("free_length", "length", "free length L0", required=True),
        Field("ends", "choice", "end type", choices=("squared-ground", "squared", "plain-ground", "plain"),
              default="squared-ground"),
        Field("material", "material", "spring wire", default="ASTM A228 music wire"),
        Field("shear_modulus", "pressure", "G, instead of the material's"),
        Field("elastic_modulus", "pressure", "E, instead of the material's"),
        Field("bending_rigidity", "str", "beta0 instead of Timoshenko's (e.g. \"0.554 N*m**2\" to reproduce a "
                                         "document's value)"),
        Field("platform_radius", "length", "cable anchor radius a on the platform", default="50 mm"),
        Field("base_radius", "length", "cable anchor radius b on the base", default="50 mm"),
        Field("cable_angles", "list", "anchor angles of the cables about the spine axis", item="angle"),
        Field("weight", "force", "platform + payload weight at the top centre", default="0 N"),
        Field("cable_rating", "force", "rated load of a cable (the cable_tension check runs when given)"),
        Field("method", "choice", "statics: small-deflection beam-column or large-deflection elastica",
              choices=("linear", "elastica"), default="elastica"),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("tilt", "angle", "platform tilt"),
        Field("pan", "angle", "direction of the tilt about the spine axis (default the first cable's angle; between "
                              "cables: the 3D rod, method elastica)"),
    ),
    checks=(
        CheckSpec.of(cc.check_spine_buckling_ratio, _buckling, needs=("tilt",)),
        CheckSpec.of(cc.check_cable_tension, _rating, needs=("tilt",)),
    ),
    outputs=(
        Output("cable_tension", "force", "tension of the (most loaded) pulling cable that holds the case's tilt",
               lambda c, loads: Q(c.state(loads).tension, "N"), needs=("tilt",)),
        Output("axial_force", "force", "compressive load on the spring at the case's tilt (P = W + T cos alpha)",
               lambda c, loads: Q(c.state(loads).axial_force, "N"), needs=("tilt",)),
    ),
))
