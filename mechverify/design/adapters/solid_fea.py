"""``solid_fea``: a 3D solid (P2 tetrahedra) from a STEP or STL file, a block with through-holes or another tool's mesh.

Parses the design file and calls :mod:`mechverify.fea` (mesh, :class:`~mechverify.fea.solid.SolidModel`,
:mod:`~mechverify.fea.modal`, :mod:`~mechverify.fea.buckling`, :mod:`~mechverify.fea.study`) and
:mod:`mechverify.checks.fea`. Regions (supports and loads) are tables with one of ``named`` (a face of the
block ``xmin`` ... ``zmax``, ``hole0`` ...; ``face<k>`` of a STEP file, ``face = k`` for short), ``plane``
(``"x = 0"``), ``box`` (two corners). All load cases share one factorisation of the stiffness.
"""

from __future__ import annotations

import contextlib
import dataclasses
from collections.abc import Iterator, Mapping
from typing import Any

from mechverify.checks import fea as fc
from mechverify.checks.fatigue import check_fatigue_field
from mechverify.checks.result import CheckResult
from mechverify.design.adapters import solid_parsing as sp
from mechverify.design.adapters.modal_parsing import modal_settings
from mechverify.design.adapters.solid_parsing import _loads, _make_mesh, _supports, named_regions, resolve_files
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field
from mechverify.errors import InputError, MechverifyError, ModelError, UnknownNameError
from mechverify.fea.reproducible import reproducible
from mechverify.units import Q

LOADS = ("forces|pressures|pin_loads|gravity",)


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
    _parts: Any = None

    def parts(self) -> dict[str, Any]:
        """What this process already built for the same solid (fea.factorcache.parts_of: the mesh, the factorised
        stiffness, the modes): a study that changes only loads meshes and factorises once per worker (issue 19)."""
        if self._parts is None:
            from mechverify.fea.factorcache import parts_of

            files = tuple(str(self.p[k]) for k in ("step", "stl", "mesh") if self.p.get(k))
            self._parts = parts_of("solid_fea", dict(self.p), files)
        return self._parts

    def part(self, name: str, build: Any) -> Any:
        """``parts()[name]``, built by ``build()`` when this process has not built it yet (an error is not kept)."""
        parts = self.parts()
        if name not in parts:
            parts[name] = build()
        return parts[name]

    def mesh(self) -> Any:
        """The mesh, made once; a failure (gmsh missing, a STEP file gmsh cannot read) is raised at the geometry's
        key (``step``, ``stl``, ``holes``), so each check and load case reports it as one error, there."""
        if isinstance(self._mesh, Exception):
            raise self._mesh
        if self._mesh is None:
            try:
                self._mesh = self.part("mesh", lambda: _make_mesh(self.p, self.unit))
            except MechverifyError as exc:
                msg = str(exc)
                if not msg.startswith(("components.", "mesh_size", "box", "holes", "outline", "thickness")):
                    key = next((k for k in ("step", "stl", "holes", "outline") if self.p.get(k)), "box")
                    exc = InputError(f"{key}: {msg}")
                self._mesh = exc
                raise exc from None
        return self._mesh

    def noted(self, result: Any) -> Any:
        """``result`` (a CheckResult or a list of them) with what the import did to the geometry in its notes
        (``SolidMesh.notes``: a STEP file's touching solids bonded)."""
        notes = getattr(self._mesh, "notes", ()) if not isinstance(self._mesh, Exception) else ()
        notes = (*notes, *sp.clamp_notes(self.p.get("supports")),  # a held hole wall is a clamp (review 3 #16)
                 *sp.pin_notes(self.p.get("supports")))
        if not notes:
            return result
        if isinstance(result, list):
            return [r.replace(notes=(*r.notes, *notes)) for r in result]
        return result.replace(notes=(*result.notes, *notes))

    def model(self, loads: tuple[Any, ...] = ()) -> Any:
        from mechverify.fea.solid import SolidModel

        return SolidModel(self.mesh(), self.p["material"], supports=self.supports, loads=loads)

    def case_model(self, loads: Mapping[str, Any], case: str, g: Any) -> Any:
        """The model under one load case; a region name the mesh lacks is an error at its key (a STEP/STL file's
        names are known after meshing), the same for every analysis of the case (review 3 finding 6). A solid
        without supports (free-free) takes no load case: an error at ``supports``."""
        if not self.supports:
            raise InputError(f"supports: none given (a free-free solid): only natural_frequency can be checked; the "
                             f"load case {case!r} loads {self.name}, which needs supports for stress, deflection, "
                             "buckling and fatigue")
        model = self.model(_loads(loads, self.unit, f"load_cases.{case}.{self.name}", g))
        try:
            sp.case_regions(model, self.p.get("supports"), loads, self.unit, f"load_cases.{case}.{self.name}")
            sp.pin_regions(model, self.p.get("supports"))
        except InputError as exc:
            raise self.with_faces(exc) from None
        return model

    def with_faces(self, exc: InputError) -> InputError:
        """``exc`` with the STEP or STL file's faces listed when it names an unknown mesh region (``face = 99``), else
        ``exc``: the same text from every analysis (stress of a load case, natural frequency), so the design file
        reports it once, at its key."""
        key = "step" if "step" in self.p else "stl" if "stl" in self.p else None
        if "unknown mesh region" not in str(exc) or key is None:
            return exc
        from pathlib import Path

        from mechverify.fea.stepfaces import describe_faces

        return InputError(f"{exc}. The faces of {Path(self.p[key]).name} (`mechverify faces` lists them):\n"
                          + "\n".join(f"    {ln}" for ln in describe_faces(self.p[key], self.unit).splitlines()))

    @reproducible  # one BLAS thread: the same bits whatever the process's thread count (issue 19)
    def solve(self, loads: Mapping[str, Any], case: str, g: Any) -> Any:
        if case not in self.solved:
            from mechverify.fea.study import SharedSolve

            model = self.case_model(loads, case, g)
            with self.regions(loads):
                if self._shared is None:
                    self._shared = self.part("shared", lambda: SharedSolve.of(model))
                self.solved[case] = model.solve(factorization=self._shared)
            self.export(self.solved[case], case)
        return self.solved[case]

    def export(self, res: Any, name: str) -> None:
        """``res`` (field or modal results) written to ``<vtu>/<component>_<name>.vtu`` when the design file gives the
        folder ``vtu`` (made if missing; ParaView reads it)."""
        folder = self.p.get("_vtu")
        if folder is not None:
            from pathlib import Path

            path = Path(folder) / f"{self.name}_{name}.vtu"
            try:
                Path(folder).mkdir(parents=True, exist_ok=True)
                res.to_vtu(path)
            except OSError as exc:  # a folder the build's check let through (review 4 #1: /proc as root)
                raise InputError(f"vtu: cannot write into the folder {folder!r}: {exc.strerror or exc}") from None

    @contextlib.contextmanager
    def regions(self, loads: Mapping[str, Any] | None = None) -> Iterator[None]:
        """An unknown region name becomes an InputError listing every region of the mesh; supports that leave a
        rigid motion free are an error at the key ``supports``, and loads that all act on held nodes at the
        load case's load key (``forces`` ...), once each instead of once per check (review finding 9)."""
        try:
            yield
        except UnknownNameError as exc:
            names = ", ".join(sorted(self.mesh().named))
            raise InputError(f"{str(exc).split(';')[0]}; valid regions: {names}") from None
        except ModelError as exc:
            msg = str(exc)
            if "not fully supported" in msg:
                raise InputError(f"supports: {msg}") from None
            key = next((k for k in ("forces", "pressures", "pin_loads", "gravity") if (loads or {}).get(k)), None)
            if key and msg.startswith("every load acts only on held nodes"):
                raise InputError(f"{key}: {msg}") from None
            raise


def _build(p: dict[str, Any], ctx: Any) -> SolidStudy:
    sources = [k for k in ("step", "stl", "box", "outline", "mesh") if k in p]
    if len(sources) != 1:
        raise InputError(f"step: give exactly one geometry: step, stl, box, outline or mesh (got {sources or 'none'})")
    if ("thickness" in p) != ("outline" in p):
        raise InputError("thickness: give it with outline (the plate extruded along z), and only then" if "thickness"
                         in p else "outline: needs thickness (the length the outline is extruded along z)")
    resolve_files(p, ctx, tuple(f.name for f in SOLID_FEA.fields if f.file and f.name != "vtu"))  # vtu: an output
    if isinstance(p.get("box"), str) and isinstance(ctx, Mapping) and ctx.get("parameters"):
        from mechverify.design.parameters import substitute  # "300, 10, t": parameters in the block's size

        p["box"] = substitute(p["box"], f"components.{p['_name']}.box", ctx)
    if isinstance(p.get("supports"), list) and isinstance(ctx, Mapping) and ctx.get("parameters"):
        p["supports"] = sp.substitute_planes(p["supports"], f"components.{p['_name']}.supports", ctx)
    if isinstance(p.get("outline"), list) and isinstance(ctx, Mapping) and ctx.get("parameters"):
        from mechverify.design.parameters import substitute  # "L, 0": parameters in the corners

        p["outline"] = substitute(p["outline"], f"components.{p['_name']}.outline", ctx)
    imported = None
    if "mesh" in p:  # another tool's mesh: read now, so that its errors are reported once, at the key
        if p.get("convergence_check"):
            raise InputError("convergence_check: needs a mesh mechverify makes (step, stl or box) to refine; "
                             "an imported mesh is solved as it is")
        from mechverify.fea.meshimport import read_solid_mesh

        try:
            imported = read_solid_mesh(p["mesh"], unit=p["unit"])
        except MechverifyError as exc:
            raise InputError(f"mesh: {exc}") from None
    elif p.get("mesh_size") is None:
        raise InputError("mesh_size: required with step, stl, box or outline (the element size)")
    elif not p["mesh_size"].magnitude > 0:
        raise InputError("mesh_size: must be positive")
    p["_modal"] = modal_settings(p)  # modes, band and margin checked at their keys
    sp.deflection_limit_keys(p)
    if "outline" in p:
        sp.outline_corners(p, p["unit"])  # corners, simple polygon and thickness at their keys, before meshing
    if "box" in p or "outline" in p:  # a builder's region names are known before meshing: a misspelt one is
        holes = p.get("holes") or []    # reported here, once
        names = ([f"{c}{e}" for c in "xyz" for e in ("min", "max")] if "box" in p else
                 ["zmin", "zmax", *(f"side{i}" for i in range(len(p["outline"] or [])))])
        named_regions(p.get("supports"), names + [f"hole{i}" for i in range(len(holes))], "supports")
    if imported is not None:
        named_regions(p.get("supports"), imported.named, "supports")
    if p.get("vtu"):
        from pathlib import Path

        design = ctx.get("path") if isinstance(ctx, Mapping) else None
        folder = Path(p["vtu"])
        p["_vtu"] = str(folder if folder.is_absolute() else (Path(design).resolve().parent if design else Path.cwd())
                        / folder)
        sp.output_folder(p["_vtu"], "vtu")  # before meshing and solving, not after (review 4 #1)
    if "convergence_tolerance" in p:  # a fraction (review 4 #3: -1 was taken and WARNed 'tolerance -100 %')
        tol = float(p["convergence_tolerance"])
        if not 0 < tol < 1:
            hint = f"; did you mean {tol / 100:g} ({tol:g} %)?" if 1 <= tol < 100 else ""
            raise InputError(f"convergence_tolerance: a fraction between 0 and 1 (0.05 = 5 %), got {tol:g}{hint}")
    return SolidStudy(p["_name"], p, p["unit"], _supports(p.get("supports"), p["unit"]), _mesh=imported)


def _g(ctx: Any) -> Any:
    return ctx.requirements.get("g", Q(9.80665, "m/s**2"))


def _stress(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult:
    res = c.solve(loads, ctx.load_case, _g(ctx))
    if not c.p.get("convergence_check"):  # (with it, two_mesh_stress names a support's singular peak)
        from mechverify.fea.study import support_peak_warning

        warn = support_peak_warning(c.model(), int(res.max_von_mises.node), c.p.get("supports"))
        return c.noted(fc.check_solid_stress(res, component=c.name, warnings=(warn,) if warn else ()))
    from mechverify.fea.solid import SolidModel
    from mechverify.fea.study import REFINE, two_mesh_stress

    # the second mesh's memory is estimated before meshing like the first one's
    fine_p = {**c.p, "mesh_size": c.p["mesh_size"] / REFINE, "_fine_mesh": True}
    fine = SolidModel(_make_mesh(fine_p, c.unit), c.p["material"],
                      supports=c.supports, loads=_loads(loads, c.unit, f"load_cases.{ctx.load_case}.{c.name}", _g(ctx)))
    with c.regions():
        governing, notes, warns = two_mesh_stress(res, fine, c.p["mesh_size"], c.p.get("supports"),
                                                  float(c.p.get("convergence_tolerance", 0.05)))
    return c.noted(fc.check_solid_stress(governing, component=c.name, notes=notes, warnings=warns))


def _fatigue(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult:
    res = c.solve(loads, ctx.load_case, _g(ctx))
    r = float(c.p.get("fatigue_stress_ratio", -1.0))
    if not -1.0 <= r < 1.0:
        raise InputError(f"fatigue_stress_ratio: R = sigma_min / sigma_max in [-1, 1), got {r}")
    s = res.signed_von_mises().m_as("Pa")  # the load case is the peak of the cycle; R gives its valley
    life = c.p.get("fatigue_life")
    return c.noted(check_fatigue_field(c.name, Q(abs(s) * (1 - r) / 2, "Pa"), Q(s * (1 + r) / 2, "Pa"), res.material,
                                       coordinates=Q(res.points, "m"), life=float(life) if life is not None else None))


def _deflection(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    lim = c.p.get("deflection_limit")
    if lim is None:
        return []
    return c.noted(fc.check_solid_deflection(c.solve(loads, ctx.load_case, _g(ctx)), lim, span=c.p.get("span"),
                                             component=c.name))


def _frequency(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    settings = c.p.get("_modal")
    if settings is None:
        return []
    from mechverify.fea.modal import modal

    with c.regions():
        model = c.model()
        try:  # the supports' regions on the mesh, as a load case checks them (a STEP file's faces listed; issue 23)
            sp.named_regions(c.p.get("supports"), model.mesh.named, "supports")
            sp.geometric_regions(model, c.p.get("supports"), c.unit, "supports")
        except InputError as exc:
            raise c.with_faces(exc) from None
        sp.pin_regions(model, c.p.get("supports"))
        if not c.supports:  # free-free: the six rigid-body modes are set apart, `modes` elastic ones computed beside
            n_bodies = int(model.bodies.max()) + 1
            if n_bodies > 1:  # each separate body has six more zero modes: they would pass as frequencies
                raise InputError(f"supports: a free-free solid must be one body; the mesh is {n_bodies} separate "
                                 f"bodies, {model.body_description(1)} touches no other")
        hint = "ask fewer modes" if "mesh" in c.p else "use a smaller mesh_size (more elements) or ask fewer modes"
        if not c.supports:
            n = model.mesh.n_dofs  # all free; ARPACK gives at most n - 1 modes, six of them rigid-body motions
            if settings.modes + 6 > n - 1:
                raise InputError(f"modes: {settings.modes} elastic modes asked, but a free-free model of {n} degrees "
                                 f"of freedom has at most {n - 7} (six of its modes are rigid-body motions); {hint}")
            settings = dataclasses.replace(settings, modes=settings.modes + 6)
        res = c.part("modes", lambda: settings.solve(modal, model, hint=hint))  # no load changes them
    c.export(res, "modes")
    return c.noted(settings.check(res, c.name))


def _buckling(c: SolidStudy, loads: Any, ctx: Any) -> CheckResult:
    """buckling_load_factor of one load case; a case without compression (a pull) cannot buckle: its result passes
    with the bound every positive factor would exceed as capacity and a note, so the envelope is governed by the
    compressive cases (it made the whole design an error, review finding 8)."""
    from mechverify.fea.buckling import NoBucklingFactorError, buckling

    model = c.case_model(loads, ctx.load_case, _g(ctx))
    with c.regions(loads):
        try:
            return c.noted(fc.check_buckling_load_factor(buckling(model, 1), component=c.name))
        except NoBucklingFactorError as exc:
            return fc.no_buckling_result(exc.bound, str(exc), component=c.name)


SOLID_FEA = REGISTRY.register(ComponentType(
    name="solid_fea",
    doc="A 3D solid from a STEP or STL file or a block with through-holes, meshed with quadratic tetrahedra: "
        "supports and loads on named faces, planes or boxes; checks of von Mises stress, deflection, natural "
        "frequency and linear buckling.",
    fields=(
        Field("step", "str", "STEP file (path relative to the design file; gmsh needed); faces are face<k>",
              file=True),
        Field("stl", "str", "watertight STL file (gmsh needed), remeshed at mesh_size: faces face1, face2, ... "
                            "(split at 40 deg), all of them 'surface'", file=True),
        Field("box", "str", "a block \"x, y, z\" from the origin (faces xmin ... zmax)"),
        Field("mesh", "str", "a tetrahedral mesh made by another tool (.msh, .inp, .bdf, .vtu, .vtk; coordinates in "
                             "unit): its named groups are the regions, no mesh_size", file=True),
        Field("outline", "list", "a plate of any outline: its corners [\"x, y\", ...] in order, extruded along z by "
                                 "thickness (faces zmin, zmax, side0 = corner 0 to 1, side1, ...; gmsh needed)",
              item="str"),
        Field("thickness", "length", "the outline's extrusion along z"),
        Field("holes", "list", "through-holes along z of the block or outline: {center = \"x, y\", diameter} (walls "
                               "hole0, hole1, ...; gmsh needed)", item="table"),
        Field("unit", "str", "unit of bare numbers (points, box, STEP files without units)", default="mm"),
        Field("material", "material", "material (E, nu, yield strength; density for frequency and gravity)",
              required=True),
        Field("mesh_size", "length", "element size (required with step, stl, box or outline)"),
        Field("supports", "list", "supports: {named | face | plane = \"x = 0\" | box = [corner, corner], hold = "
                                  "\"x, y, z\" (default all) | pin = true (a hole wall held radially, free to turn; "
                                  "axial = true also holds it along the pin)}; [] for a free-free solid "
                                  "(natural_frequency only)",
              required=True, item="table"),
        Field("vtu", "str", "folder (relative to the design file; made if missing) for ParaView files: "
                            "<component>_<load case>.vtu (displacement, stress) and <component>_modes.vtu",
              file=True),
        Field("deflection_limit", "str", "limit on the largest displacement: a length or 'L/250' of span"),
        Field("span", "length", "span of an 'L/n' deflection limit"),
        Field("min_frequency", "frequency", "the first natural frequency must reach this"),
        Field("excitation_band", "list", "[lo, hi] excitation frequencies no mode may come near", item="str"),
        Field("frequency_margin", "float", "separation from the excitation band (0.15 = 15 %)", default=0.15),
        Field("modes", "int", "natural frequencies computed", default=6),
        Field("convergence_check", "bool", "also solve at mesh_size / 1.5 and WARN when the peak stress changes "
                                           "more than convergence_tolerance (with the mesh_size needed, or a "
                                           "peak at a support named singular); the demand is the larger peak"),
        Field("convergence_tolerance", "float", "tolerance of the two-mesh check", default=0.05),
        Field("fatigue_stress_ratio", "float", "R = sigma_min/sigma_max of the cycle whose peak is the load case "
                                               "(check fatigue_field; -1 fully reversed)", default=-1.0),
        Field("fatigue_life", "float", "design life in cycles (default: infinite life)"),
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
        CheckSpec.of(check_fatigue_field, _fatigue, needs=LOADS, default=False),
    ),
))
