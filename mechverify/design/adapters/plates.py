"""``plate``: a rectangular or circular plate on Roark's closed-form cases.

All edges simply supported or clamped; uniform pressure or a central load: bending stress and
deflection (:func:`mechverify.checks.plates.check_plate_stress_roark`,
:func:`~mechverify.checks.plates.check_plate_deflection_roark`). Plates on bolts or with cut-outs are
outside these cases and need the FEA plate model (``plate_fea``).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pint

from mechverify.checks import members as mc
from mechverify.checks import plates as pc
from mechverify.checks.result import CheckResult
from mechverify.components.plates import Plate, PlateEstimate, roark_circular_plate, roark_rectangular_plate
from mechverify.design.adapters.sections import why
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError
from mechverify.units import Q, fmt


def _with(r: CheckResult, notes: list[str] = (), details: dict[str, Any] | None = None, **kw: Any) -> CheckResult:
    return dataclasses.replace(r, notes=(*r.notes, *notes), details={**r.details, **(details or {})}, **kw)


FEA_NOTE = ("Roark's closed forms cover a whole plate on its edges only: a plate on bolts or corner supports, or "
            "with holes or cut-outs, needs the FEA plate model")


@dataclasses.dataclass(frozen=True)
class RoarkPlate:
    """A plate as a design file declares it for Roark's closed forms: ``plate`` (outline geometry,
    thickness, material), its shape and size, edge condition, central-load radius, deflection limit."""

    plate: Plate
    shape: str  # "rectangle" or "circle"
    size: tuple[pint.Quantity, ...]  # (width, height) or (diameter,)
    edges: str
    load_radius: pint.Quantity
    deflection_limit: Any

    @property
    def span(self) -> pint.Quantity:
        """The span of the deflection limit: the shorter side, or the diameter."""
        return min(self.size, key=lambda q: q.m_as("m"))

    def estimate(self, load: pint.Quantity, loading: str) -> PlateEstimate:
        E = self.plate.material.require("E")
        t = self.plate.thickness_q
        if self.shape == "rectangle":
            return roark_rectangular_plate(*self.size, t, E, load, self.edges, loading, self.load_radius)
        nu = self.plate.material.nu
        if nu is None:
            raise InputError(f"material {self.plate.material.name!r} has no Poisson's ratio (needed for a circular "
                             "plate)")
        return roark_circular_plate(self.size[0] / 2, t, E, nu, load, self.edges, loading, self.load_radius)


def _circle_outline(d: pint.Quantity, n: int = 96) -> pint.Quantity:
    r = d.m_as("m") / 2
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    return Q(np.column_stack((r + r * np.cos(a), r + r * np.sin(a))), "m")


def _build_plate(p: dict[str, Any], ctx: dict[str, Any]) -> RoarkPlate:
    name, shape = p["_name"], p["shape"]
    needs = ("width", "height") if shape == "rectangle" else ("diameter",)
    other = ("diameter",) if shape == "rectangle" else ("width", "height")
    for k in needs:
        if k not in p:
            raise InputError(f"{k}: missing; a {shape} plate needs {' and '.join(needs)}")
    for k in other:
        if k in p:
            raise InputError(f"{k}: not a dimension of a {shape} plate (it takes {' and '.join(needs)})")
    for k in (*needs, "thickness"):
        if p[k].magnitude <= 0:
            raise InputError(f"{k}: must be positive, got {fmt(p[k])}")
    if p.get("deflection_limit") is not None and p.get("deflection_limit_fraction") is not None:
        raise InputError("deflection_limit: give deflection_limit or deflection_limit_fraction, not both")
    limit: Any = p.get("deflection_limit")
    if limit is None:
        limit = p.get("deflection_limit_fraction", ctx["requirements"].get("deflection_limit", 0.002))
    size = tuple(p[k] for k in needs)
    try:
        mc.deflection_limit(limit, min(size, key=lambda q: q.m_as("m")))
    except (MechverifyError, ZeroDivisionError) as exc:
        key = "deflection_limit" if "deflection_limit" in p else "deflection_limit_fraction"
        raise InputError(f"{key}: expected a length (\"2 mm\"), \"L/250\" or a fraction of the span: "
                         + why(exc, limit)) from None
    if p["load_radius"].magnitude < 0:
        raise InputError(f"load_radius: must be zero or positive, got {fmt(p['load_radius'])}")
    if shape == "circle" and p["material"].nu is None:
        raise InputError(f"material: {p['material'].name!r} has no Poisson's ratio, which a circular plate needs; "
                         "define a derived material with nu = ...")
    if shape == "rectangle":
        plate = Plate.rectangle(p["width"], p["height"], p["thickness"], p["material"], name=name)
    else:
        plate = Plate(_circle_outline(p["diameter"]), p["thickness"], p["material"], name=name)
    return RoarkPlate(plate, shape, size, p["edges"], p["load_radius"], limit)


def _plate_load(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> tuple[pint.Quantity, str, list[str]]:
    """(load, loading, notes): pressure (+ self-weight) or central force."""
    if "pressure" in loads and "central_force" in loads:
        raise InputError("give pressure or central_force, not both (Roark's cases take one load)")
    notes: list[str] = []
    if "central_force" in loads:
        if loads.get("self_weight"):
            raise InputError("self_weight: only with a pressure load (Roark's cases take one load)")
        return loads["central_force"].to("N"), "central", notes
    q = loads["pressure"].to("Pa")
    if loads.get("self_weight"):
        g = ctx.requirements.get("g", Q(9.80665, "m/s**2"))
        qw = (rp.plate.material.require("density") * rp.plate.thickness_q * g).to("Pa")
        notes.append(f"self-weight rho g t = {fmt(qw, 'Pa')} added to the pressure {fmt(q, 'Pa')}")
        q = q + qw
    return q, "uniform", notes


def _plate_stress(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> CheckResult:
    load, loading, notes = _plate_load(rp, loads, ctx)
    est = rp.estimate(load, loading)
    r = pc.check_plate_stress_roark(rp.plate, est, required_sf=ctx.required_sf)
    inputs = {**r.inputs, ("q" if loading == "uniform" else "W"): load.to("kPa" if loading == "uniform" else "N"),
              "E": rp.plate.material.require("E").to("GPa")}
    inputs.update({k: v.to("mm") for k, v in zip(("a", "b") if rp.shape == "rectangle" else ("d",), rp.size,
                                                  strict=True)})
    formula = {("rectangle", "uniform"): r"\sigma_{max} = \beta \frac{q b^2}{t^2} \le S_y",
               ("rectangle", "central"): r"\sigma_{max} = \frac{3 W}{2 \pi t^2}\left[(1 + \nu)"
                                         r"\ln\frac{2 b}{\pi r_0'} + \beta\right] \le S_y",
               ("circle", "uniform"): r"\sigma_{max} = \frac{3 (3 + \nu) q a^2}{8 t^2}\ \mathrm{or}\ "
                                      r"\frac{3 q a^2}{4 t^2} \le S_y",
               ("circle", "central"): r"\sigma_{max} = \frac{3 W}{2 \pi t^2}\left[(1 + \nu)\ln\frac{a}{r_0'}"
                                      r" + 1\right]\ \mathrm{or}\ \ldots \le S_y"}[(rp.shape, loading)]
    coefs = ", ".join(f"{k} = {v:.4g}" for k, v in est.coefficients.items() if k != "r0_equivalent")
    if coefs:
        notes.append(f"coefficients {coefs} (nu = 0.3 table)")
    nu = rp.plate.material.nu
    if rp.shape == "rectangle" and nu is not None and abs(nu.m_as("") - 0.3) > 0.02:
        notes.append(f"Roark's Table 11.4 coefficients are for nu = 0.3; the material's nu = {nu.m_as(''):.3g}")
    return _with(r, [*notes, FEA_NOTE], inputs=inputs, formula=formula)


def _plate_deflection(rp: RoarkPlate, loads: dict[str, Any], ctx: Any) -> CheckResult:
    load, loading, notes = _plate_load(rp, loads, ctx)
    est = rp.estimate(load, loading)
    r = pc.check_plate_deflection_roark(rp.plate, est, rp.deflection_limit, span=rp.span)
    formula = (r"y_{max} = \alpha \frac{q b^4}{E t^3} \le \delta_{lim}" if rp.shape == "rectangle" and
               loading == "uniform" else r"y_{max} = \alpha \frac{W b^2}{E t^3} \le \delta_{lim}"
               if rp.shape == "rectangle" else r"y_{max} = \frac{q a^4}{64 D}\,\frac{5 + \nu}{1 + \nu}\ \mathrm{etc.},"
               r"\ D = \frac{E t^3}{12 (1 - \nu^2)}")
    return _with(r, [*notes, est.case, f"span for the limit: {fmt(rp.span, 'mm')} (shorter side or diameter)",
                     FEA_NOTE], formula=formula)


PLATE = REGISTRY.register(ComponentType(
    name="plate",
    doc="A rectangular or circular plate of uniform thickness on Roark's closed-form cases: all edges simply "
        "supported or clamped, uniform pressure or a central load. Plates on bolts or with cut-outs need the FEA "
        "plate model.",
    fields=(
        Field("shape", "choice", "plate outline", choices=("rectangle", "circle"), default="rectangle"),
        Field("width", "length", "side of a rectangular plate"),
        Field("height", "length", "other side of a rectangular plate"),
        Field("diameter", "length", "diameter of a circular plate"),
        Field("thickness", "length", "plate thickness", required=True),
        Field("material", "material", "plate material (E, yield strength; Poisson's ratio for a circle)",
              required=True),
        Field("edges", "choice", "all edges simply supported or clamped", choices=("simply_supported", "clamped"),
              default="simply_supported"),
        Field("load_radius", "length", "radius of the central load's contact (0: a point, Roark's r0')",
              default="0 mm"),
        Field("deflection_limit", "str", "deflection limit as a length ('0.5 mm') or 'L/250' of the shorter side "
                                         "(default: requirements.deflection_limit)"),
        Field("deflection_limit_fraction", "float", "deflection limit as a fraction of the shorter side"),
    ),
    build=lambda p, ctx: _build_plate(p, ctx),
    loads=(
        Field("pressure", "pressure", "uniform pressure over the whole plate"),
        Field("central_force", "force", "total force on a small central circle (radius load_radius)"),
        Field("self_weight", "bool", "add the plate's weight rho g t to the pressure", default=False),
    ),
    checks=(
        CheckSpec.of(pc.check_plate_stress_roark, _plate_stress, needs=("pressure|central_force",)),
        CheckSpec.of(pc.check_plate_deflection_roark, _plate_deflection, needs=("pressure|central_force",)),
    ),
))
