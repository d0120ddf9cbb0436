"""``solid_fea``: a 3D solid (P2 tetrahedra) from a STEP or STL file or a block with through-holes.

Parses the design file and calls :mod:`mechverify.fea` (mesh, :class:`~mechverify.fea.solid.SolidModel`,
:mod:`~mechverify.fea.modal`, :mod:`~mechverify.fea.buckling`, :mod:`~mechverify.fea.study`) and
:mod:`mechverify.checks.fea`. Regions (supports and loads) are tables with one of ``named`` (a face of the
block ``xmin`` ... ``zmax``, ``hole0`` ...; ``face<k>`` of a STEP file, ``face = k`` for short), ``plane``
(``"x = 0"``), ``box`` (two corners). All load cases share one factorisation of the stiffness.
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from mechverify.checks import fea as fc
from mechverify.checks.result import CheckResult
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, UnknownNameError
from mechverify.units import Q, as_quantity

LOADS = ("forces|pressures|pin_loads|gravity",)


def _num(s: str, unit: str, dim: str, path: str) -> float:
    s = s.strip()
    try:
        return float(Q(float(s), unit).to_base_units().m)
    except ValueError:
        return float(as_quantity(s, dim, path).to_base_units().m)


def _vec(v: Any, unit: str, dim: str, path: str) -> tuple[float, float, float]:
    parts = v.split(",") if isinstance(v, str) else []
    if len(parts) != 3:
        raise InputError(f"{path}: expected three components \"x, y, z\" (numbers in {unit} or quantities), got {v!r}")
    return tuple(_num(p, unit, dim, f"{path}") for p in parts)  # type: ignore[return-value]


def _region(t: Any, unit: str, path: str) -> Any:
    from mechverify.fea.regions import Box, Named, Plane

    if not isinstance(t, Mapping):
        raise InputError(f"{path}: expected a table with named, face, plane or box, got {t!r}")
    keys = [k for k in ("named", "face", "plane", "box") if k in t]
    if len(keys) != 1:
        raise InputError(f"{path}: give exactly one of named, face, plane, box (got {keys or 'none'})")
    k = keys[0]
    if k == "named":
        return Named(str(t["named"]))
    if k == "face":
        return Named(f"face{int(t['face'])}")
    if k == "plane":
        axis, _, val = str(t["plane"]).partition("=")
        if axis.strip() not in ("x", "y", "z") or not val.strip():
            raise InputError(f"{path}.plane: expected \"x = value\" (or y, z), got {t['plane']!r}")
        return Plane(**{axis.strip(): Q(_num(val, unit, "length", f"{path}.plane"), "m")})
    b = t["box"]
    if not (isinstance(b, list) and len(b) == 2):
        raise InputError(f"{path}.box: expected two corners [\"x0, y0, z0\", \"x1, y1, z1\"], got {b!r}")
    lo, hi = (_vec(c, unit, "length", f"{path}.box[{i}]") for i, c in enumerate(b))
    return Box(tuple(Q(v, "m") for v in lo), tuple(Q(v, "m") for v in hi))


def _supports(items: Any, unit: str) -> tuple[Any, ...]:
    from mechverify.fea.loads import Fixed, Support

    out = []
    for i, s in enumerate(items or []):
        path = f"supports[{i}]"
        region = _region(s, unit, path)
        hold = s.get("hold", "x, y, z")
        comps = {c.strip() for c in str(hold).split(",")}
        if not comps <= {"x", "y", "z"} or not comps:
            raise InputError(f"{path}.hold: expected components such as \"x, z\", got {hold!r}")
        out.append(Fixed(region) if comps == {"x", "y", "z"} else Support(region, *(c in comps for c in "xyz")))
    if not out:
        raise InputError("supports: give at least one support ({named | face | plane | box, hold})")
    return tuple(out)


def _loads(loads: Mapping[str, Any], unit: str, path: str, g: Any) -> tuple[Any, ...]:
    from mechverify.fea.loads import Force, Gravity, PinLoad, Pressure

    out: list[Any] = []
    for key, cls in (("forces", Force), ("pin_loads", PinLoad)):
        for i, t in enumerate(loads.get(key, []) or []):
            p = f"{path}.{key}[{i}]"
            if not isinstance(t, Mapping) or "force" not in t:
                raise InputError(f"{p}: expected {{region..., force = \"fx, fy, fz\"}} (numbers in N or forces)")
            out.append(cls(_region(t, unit, p), tuple(Q(v, "N") for v in _vec(t["force"], "N", "force", f"{p}.force"))))
    for i, t in enumerate(loads.get("pressures", []) or []):
        p = f"{path}.pressures[{i}]"
        if not isinstance(t, Mapping) or "pressure" not in t:
            raise InputError(f"{p}: expected {{region..., pressure = \"1 MPa\"}}")
        out.append(Pressure(_region(t, unit, p), as_quantity(t["pressure"], "pressure", f"{p}.pressure")))
    if loads.get("gravity"):
        out.append(Gravity((0.0, 0.0, -g.m_as("m/s**2"))))
    return tuple(out)


@dataclasses.dataclass(eq=False)
class SolidStudy:
    """A solid as a design file declares it: the model's mesh, material and supports, the study settings and
    the solved load cases (one shared factorisation)."""

    name: str
    p: Mapping[str, Any]
    unit: str
    supports: tuple[Any, ...]
    _mesh: Any = None
    _shared: Any = None
    solved: dict[str, Any] = dataclasses.field(default_factory=dict)

    def mesh(self) -> Any:
        if self._mesh is None:
            self._mesh = _make_mesh(self.p, self.unit)
        return self._mesh

    def model(self, loads: tuple[Any, ...] = ()) -> Any:
        from mechverify.fea.solid import SolidModel

        return SolidModel(self.mesh(), self.p["material"], supports=self.supports, loads=loads)

    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> Any:
        if case not in self.solved:
            from mechverify.fea.study import SharedSolve

            model = self.model(_loads(loads, self.unit, f"load_cases.{case}.{self.name}", g))
            with self.regions():
                if self._shared is None:
                    self._shared = SharedSolve.of(model)
                self.solved[case] = model.solve(factorization=self._shared)
        return self.solved[case]

    @contextlib.contextmanager
    def regions(self) -> Iterator[None]:
        """An unknown region name becomes an InputError listing every region of the mesh."""
        try:
            yield
        except UnknownNameError as exc:
            names = ", ".join(sorted(self.mesh().named))
            raise InputError(f"{str(exc).split(';')[0]}; valid regions: {names}") from None


def _make_mesh(p: Mapping[str, Any], unit: str) -> Any:
    from mechverify.fea import mesh, study

    h = p["mesh_size"].m_as("m")
    what = f"components.{p['_name']}.mesh_size"
    if "step" in p:
        study.require_memory(study.step_volume(p["step"]), h, what)
        return mesh.from_step(p["step"], p["mesh_size"], unit=unit)
    if "stl" in p:
        study.require_memory(mesh.stl_properties(p["stl"], unit).volume.m_as("m**3"), h, what)
        return mesh.from_stl(p["stl"], p["mesh_size"], unit=unit)
    size = _vec(p["box"], unit, "length", "box")
    if min(size) <= 0:
        raise InputError(f"box: three positive lengths, got {p['box']!r}")
    study.require_memory(math.prod(size), h, what)
    holes = []
    for i, t in enumerate(p.get("holes", []) or []):
        if not isinstance(t, Mapping) or not {"center", "diameter"} <= set(t):
            raise InputError(f"holes[{i}]: expected {{center = \"x, y\", diameter = \"8.5 mm\"}}, got {t!r}")
        c = [_num(s, unit, "length", f"holes[{i}].center") for s in str(t["center"]).split(",")]
        if len(c) != 2:
            raise InputError(f"holes[{i}].center: expected \"x, y\", got {t['center']!r}")
        holes.append(((Q(c[0], "m"), Q(c[1], "m")), t["diameter"]))
    if not holes:
        divs = tuple(max(1, round(s / h)) for s in size)
        return mesh.box(tuple(Q(s, "m") for s in size), divs)
    return mesh.block_with_holes(tuple(Q(s, "m") for s in size), holes, p["mesh_size"])


def _build(p: dict[str, Any], ctx: Any) -> SolidStudy:
    sources = [k for k in ("step", "stl", "box") if k in p]
    if len(sources) != 1:
        raise InputError(f"step: give exactly one geometry: step, stl or box (got {sources or 'none'})")
    for k in ("step", "stl"):
        if k in p:
            design = ctx.get("path") if isinstance(ctx, Mapping) else None
            base = Path(design).resolve().parent if design else Path.cwd()
            path = Path(p[k]) if Path(p[k]).is_absolute() else base / p[k]
            if not path.exists():
                raise InputError(f"{k}: file {str(path)!r} does not exist")
            p[k] = str(path)
    if not p["mesh_size"].magnitude > 0:
        raise InputError("mesh_size: must be positive")
    if "min_frequency" in p and "excitation_band" in p:
        raise InputError("min_frequency: give min_frequency or excitation_band, not both")
    return SolidStudy(p["_name"], p, p["unit"], _supports(p.get("supports"), p["unit"]))


def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _stress(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult:
    return fc.check_solid_stress(c.solve(loads, ctx.load_case, _g(ctx)), component=c.name)


def _deflection(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    lim = c.p.get("deflection_limit")
    if lim is None:
        return []
    return fc.check_solid_deflection(c.solve(loads, ctx.load_case, _g(ctx)), lim, span=c.p.get("span"),
                                     component=c.name)


def _frequency(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    if "min_frequency" not in c.p and "excitation_band" not in c.p:
        return []
    from mechverify.fea.modal import modal

    with c.regions():
        res = modal(c.model(), int(c.p.get("modes", 6)))
    band = c.p.get("excitation_band")
    if band is not None and (not isinstance(band, list) or len(band) != 2):
        raise InputError(f"excitation_band: expected [\"lo Hz\", \"hi Hz\"], got {band!r}")
    return fc.check_natural_frequency(res, minimum=c.p.get("min_frequency"), band=band,
                                      margin=float(c.p.get("frequency_margin", 0.15)), component=c.name)


def _buckling(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult:
    from mechverify.fea.buckling import buckling

    model = c.model(_loads(loads, c.unit, f"load_cases.{ctx.load_case}.{c.name}", _g(ctx)))
    with c.regions():
        return fc.check_buckling_load_factor(buckling(model, 1), component=c.name)


SOLID_FEA = REGISTRY.register(ComponentType(
    name="solid_fea",
    doc="A 3D solid from a STEP or STL file or a block with through-holes, meshed with quadratic tetrahedra: "
        "supports and loads on named faces, planes or boxes; checks of von Mises stress, deflection, natural "
        "frequency and linear buckling.",
    fields=(
        Field("step", "str", "STEP file (path relative to the design file; gmsh needed); faces are face<k>"),
        Field("stl", "str", "watertight STL file (gmsh needed); its surface is the region 'surface'"),
        Field("box", "str", "a block \"x, y, z\" from the origin (faces xmin ... zmax)"),
        Field("holes", "list", "through-holes along z of the block: {center = \"x, y\", diameter} (walls hole0, "
                               "hole1, ...; gmsh needed)", item="table"),
        Field("unit", "str", "unit of bare numbers (points, box, STEP files without units)", default="mm"),
        Field("material", "material", "material (E, nu, yield strength; density for frequency and gravity)",
              required=True),
        Field("mesh_size", "length", "element size", required=True),
        Field("supports", "list", "supports: {named | face | plane = \"x = 0\" | box = [corner, corner], hold = "
                                  "\"x, y, z\" (default all)}", required=True, item="table"),
        Field("deflection_limit", "str", "limit on the largest displacement: a length or 'L/250' of span"),
        Field("span", "length", "span of an 'L/n' deflection limit"),
        Field("min_frequency", "frequency", "the first natural frequency must reach this"),
        Field("excitation_band", "list", "[lo, hi] excitation frequencies no mode may come near", item="str"),
        Field("frequency_margin", "float", "separation from the excitation band (0.15 = 15 %)", default=0.15),
        Field("modes", "int", "natural frequencies computed", default=6),
    ),
    build=lambda p, ctx: _build(p, ctx),
    loads=(
        Field("forces", "list", "{region..., force = \"fx, fy, fz\"} spread evenly over the region", item="table"),
        Field("pin_loads", "list", "{region..., force} on a hole wall, cosine bearing pressure", item="table"),
        Field("pressures", "list", "{region..., pressure} normal to the faces (positive pushes in)", item="table"),
        Field("gravity", "bool", "self-weight along -z (requirements.g)"),
    ),
    checks=(
        CheckSpec.of(fc.check_solid_stress, _stress, needs=LOADS),
        CheckSpec.of(fc.check_solid_deflection, _deflection, needs=LOADS),
        CheckSpec.of(fc.check_natural_frequency, _frequency),
        CheckSpec.of(fc.check_buckling_load_factor, _buckling, needs=LOADS, default=False),
    ),
))
