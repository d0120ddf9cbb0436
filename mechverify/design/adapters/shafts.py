"""``shaft``: a stepped shaft on bearings with gears, pulleys, couplings and masses (parse and call).

The load case gives the transmitted ``torque`` (a number or another component's torque output); each element
takes ``torque_share`` of it (+1 the input, -1 the output, -0.5 each of two hubs). Outputs
``reaction_<support>_radial`` and ``reaction_<support>_axial`` give the bearing force at every support by its
name (any number of supports; ``reaction_A_radial`` ... ``reaction_D_axial`` also name the first four by
position), for the ``ball_bearing`` load cases that name the shaft; a name the shaft has no support for is a
named error at the referring key.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Mapping
from typing import Any

from mechverify.checks import shafts as cs
from mechverify.components import shafts as s
from mechverify.design.adapters.common import inline_table
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.fea import shafts as fs
from mechverify.materials.database import get as material
from mechverify.units import Q, to_si

LETTERS = "ABCD"
SEG_KEYS = ("length", "diameter", "bore")
FEAT_KEYS = ("kind", "at", "radius", "depth", "width", "length", "keyseat", "Kt", "Kts", "name")
SUP_KEYS = ("name", "at", "kind", "stiffness", "locating", "bearing")
EL_KEYS = ("name", "kind", "at", "torque_share", "pitch_diameter", "pressure_angle", "helix_angle", "module", "angle",
           "diameter", "ratio", "tension_tight", "tension_slack", "force", "axial_force", "mass")


def _si(t: Mapping[str, Any], k: str, dim: str, path: str, default: float = 0.0) -> float:
    return to_si(t[k], dim, f"{path}.{k}") if k in t else default


@dataclasses.dataclass(frozen=True)
class ShaftDesign:
    """A design file's shaft: everything but the load case's torque; :meth:`shaft` builds it for one torque."""

    name: str
    params: Mapping[str, Any]
    _cache: dict[float, tuple[s.Shaft, fs.ShaftAnalysis]] = dataclasses.field(default_factory=dict, compare=False)

    def shaft(self, torque: float = 0.0) -> s.Shaft:
        p = self.params
        segs = []
        for i, t in enumerate(p["segments"]):
            path = f"segments[{i}]"
            t = inline_table(t, path, SEG_KEYS, ("length", "diameter"))
            try:
                segs.append(s.Segment(_si(t, "length", "length", path), _si(t, "diameter", "length", path),
                                      _si(t, "bore", "length", path)))
            except InputError as exc:
                raise InputError(f"{path}: {exc}") from None
        sups = []
        for i, t in enumerate(p["supports"]):
            path = f"supports[{i}]"
            t = inline_table(t, path, SUP_KEYS, ("at",))
            try:
                sups.append(s.Support(t.get("name", LETTERS[i] if i < len(LETTERS) else f"S{i + 1}"),
                                      _si(t, "at", "length", path), t.get("kind", "pinned"),
                                      _si(t, "stiffness", "force_per_length", path), bool(t.get("locating", i == 0)),
                                      t.get("bearing", "deep_groove_ball")))
            except InputError as exc:
                raise InputError(f"{path}: {exc}") from None
        feats = []
        for i, t in enumerate(p.get("features") or []):
            path = f"features[{i}]"
            t = inline_table(t, path, FEAT_KEYS, ("kind", "at"))
            try:
                feats.append(s.Feature(t["kind"], _si(t, "at", "length", path), _si(t, "radius", "length", path),
                                       _si(t, "depth", "length", path), _si(t, "width", "length", path),
                                       _si(t, "length", "length", path), t.get("keyseat", "profile"), t.get("Kt"),
                                       t.get("Kts"), t.get("name", f"{t['kind']}{i + 1}")))
            except InputError as exc:
                raise InputError(f"{path}: {exc}") from None
        loads = [self._element(i, t, torque) for i, t in enumerate(p.get("elements") or [])]
        return s.Shaft(self.name, tuple(segs), material(p["material"]), tuple(sups), tuple(loads), tuple(feats),
                       finish=p["finish"], reliability=float(p["reliability"]),
                       speed=to_si(p["speed"], "angular_velocity", "speed") if p.get("speed") else 0.0,
                       rotating=p["rotating"], torque_alternating_fraction=float(p["torque_alternating_fraction"]),
                       shaft_mass=p["shaft_mass"], key_standard=p["key_standard"])

    @staticmethod
    def _element(i: int, t: Any, torque: float) -> s.ShaftLoad:
        path = f"elements[{i}]"
        t = inline_table(t, path, EL_KEYS, ("kind", "at"))
        name, x, T = t.get("name", f"e{i + 1}"), _si(t, "at", "length", path), float(t.get("torque_share", 0)) * torque
        m = _si(t, "mass", "mass", path)
        ang = _si(t, "angle", "angle", path, 1.5707963267948966) * 57.29577951308232
        try:
            if t["kind"] == "gear":
                return s.gear_load(name, x, _si(t, "pitch_diameter", "length", path), T,
                                   pressure_angle=_si(t, "pressure_angle", "angle", path, 0.3490658503988659)
                                   * 57.29577951308232, helix_angle=_si(t, "helix_angle", "angle", path)
                                   * 57.29577951308232, angle=ang, mass=m, module=_si(t, "module", "length", path))
            if t["kind"] == "pulley":
                ten = ((_si(t, "tension_tight", "force", path), _si(t, "tension_slack", "force", path))
                       if "tension_tight" in t else None)
                return s.pulley_load(name, x, _si(t, "diameter", "length", path), torque=T, ratio=t.get("ratio"),
                                     tensions=ten, angle=ang, mass=m)
            if t["kind"] in ("coupling", "mass", "force"):
                import math
                F = _si(t, "force", "force", path)
                return s.force_load(name, x, (_si(t, "axial_force", "force", path), F * math.cos(math.radians(ang)),
                                              F * math.sin(math.radians(ang))), T, m, t["kind"])
        except InputError as exc:
            raise InputError(f"{path}: {exc}") from None
        raise InputError(f"{path}.kind: one of gear, pulley, coupling, mass, force; got {t['kind']!r}")

    def solved(self, loads: Mapping[str, Any] | None) -> tuple[s.Shaft, fs.ShaftAnalysis]:
        T = to_si((loads or {}).get("torque", Q(0, "N*m")), "torque", "torque")
        if T not in self._cache:
            sh = self.shaft(T)
            self._cache[T] = (sh, fs.analyse(sh))
        return self._cache[T]


def _build(p: Mapping[str, Any], ctx: Any) -> ShaftDesign:
    d = ShaftDesign(p["_name"], dict(p))
    d.shaft(0.0)  # geometry errors at load time, with their key path
    return d


def _run(fn: Any, **kw: Any) -> Any:
    def run(c: ShaftDesign, loads: Any, ctx: Any) -> Any:
        sh, a = c.solved(loads)
        return fn(sh, a, required_sf=ctx.required_sf, load_case=ctx.load_case, **kw)
    return run


def _governing(fn: Any) -> Any:
    """A per-item check (each keyseat, each gear) as one result per load case: the governing item, the others'
    utilisations as a note (the report keeps one result per check and case)."""
    def run(c: ShaftDesign, loads: Any, ctx: Any) -> Any:
        out = _run(fn)(c, loads, ctx)
        if not out:
            return []
        g = max(out, key=lambda r: r.utilisation)
        others = [f"{r.title}: u = {r.utilisation:.3g}" for r in out if r is not g]
        return dataclasses.replace(g, notes=(*g.notes, "other items: " + "; ".join(others))) if others else g
    return run


def _critical(c: ShaftDesign, loads: Any, ctx: Any) -> Any:
    sh, _ = c.solved(loads)
    modal = fs.frame_critical_speeds(sh) if sh.shaft_mass else fs.modal_critical_speeds(sh)
    return cs.check_shaft_critical_speed(sh, fs.critical_speed(sh), modal=modal, required_sf=ctx.required_sf,
                                         load_case=ctx.load_case)


def _reaction_named(support: str, which: str) -> Any:
    def fn(c: ShaftDesign, loads: Any) -> Any:
        sh, a = c.solved(loads)
        if support not in a.reactions:
            raise InputError(f"{c.name} has no support named {support!r} (supports: "
                             f"{', '.join(sp.name for sp in sh.supports)}); a bearing reads the reaction of a support "
                             "the shaft has at its seat")
        r = a.reactions[support]
        return Q(r.radial if which == "radial" else r.axial, "N")
    return fn


_NAMED = re.compile(r"reaction_(.+)_(radial|axial)")


@dataclasses.dataclass(frozen=True)
class _ShaftType(ComponentType):
    """The shaft's component type: besides its fixed outputs, ``reaction_<support>_radial|axial`` for every
    support name (the names are the design's, so these outputs are made when asked for)."""

    def output(self, name: str) -> Output | None:
        out = super().output(name)
        if out is not None:
            return out
        m = _NAMED.fullmatch(name)
        if m is None:
            return None
        return Output(name, "force", f"{m[2]} force on support {m[1]}", _reaction_named(m[1], m[2]))


def _reaction(i: int, which: str) -> Any:
    def fn(c: ShaftDesign, loads: Any) -> Any:
        sh, a = c.solved(loads)
        if LETTERS[i] in a.reactions:  # a support of that name first, else the i-th support
            r = a.reactions[LETTERS[i]]
        elif i >= len(sh.supports):
            raise InputError(f"{c.name}: output reaction_{LETTERS[i]}_{which}: the shaft has {len(sh.supports)} "
                             f"supports ({', '.join(sp.name for sp in sh.supports)})")
        else:
            r = a.reactions[sh.supports[i].name]
        return Q(r.radial if which == "radial" else r.axial, "N")
    return fn


SHAFT = REGISTRY.register(_ShaftType(
    name="shaft",
    doc="A stepped round shaft on bearings (pinned, fixed or elastic) with gears, pulleys, couplings and masses; "
        "reactions, bending in two planes, torque, slope and deflection on the frame FEA; fatigue at every feature "
        "by the DE criteria (Shigley 10th ed. Ch. 7), yield, slope at bearings, critical speed and keys.",
    fields=(
        Field("material", "material", "shaft material (needs E, G, density, Sut, Sy)", required=True),
        Field("segments", "list", "segments from the left end: {length, diameter, bore}", required=True,
              item="table"),
        Field("supports", "list", "bearings: {at, kind = pinned|fixed|spring, stiffness, locating, bearing (Table "
              "7-2 type), name (default A, B, ...)}", required=True, item="table"),
        Field("features", "list", "stress raisers: {kind = shoulder|keyseat|groove|cross_hole|press_fit, at, radius, "
              "depth, width, length, keyseat = profile|sled_runner, Kt, Kts, name}", item="table"),
        Field("elements", "list", "gears, pulleys, couplings, masses: {kind, at, torque_share, ...} (see docs)",
              item="table"),
        Field("speed", "angular_velocity", "operating speed (critical-speed check)"),
        Field("finish", "choice", "surface finish for ka", default="machined",
              choices=("ground", "machined", "cold_drawn", "hot_rolled", "as_forged")),
        Field("reliability", "float", "reliability for ke (Shigley Table 6-5)", default=0.99),
        Field("rotating", "bool", "the shaft turns under the loads (bending fully reversed)", default=True),
        Field("torque_alternating_fraction", "float", "alternating torque as a fraction of the steady", default=0.0),
        Field("shaft_mass", "bool", "include the shaft's own mass in the critical speed", default=True),
        Field("key_standard", "choice", "parallel-key sizes when a keyseat gives none: DIN 6885-1 or Shigley "
              "Table 7-6 (inch square keys)", default="din6885", choices=("din6885", "ansi")),
        Field("fatigue_criterion", "choice", "DE criterion of shaft_fatigue", default="goodman",
              choices=cs.CRITERIA),
    ),
    build=_build,
    loads=(Field("torque", "torque", "torque transmitted (each element takes torque_share of it)"),),
    checks=(
        CheckSpec.of(cs.check_shaft_fatigue, lambda c, loads, ctx: _run(
            cs.check_shaft_fatigue, criterion=c.params["fatigue_criterion"])(c, loads, ctx), needs=("torque",)),
        CheckSpec.of(cs.check_shaft_static_yield, _run(cs.check_shaft_static_yield), needs=("torque",)),
        CheckSpec.of(cs.check_shaft_bearing_slope, _run(cs.check_shaft_bearing_slope), needs=("torque",)),
        CheckSpec.of(cs.check_shaft_gear_deflection, _governing(cs.check_shaft_gear_deflection), needs=("torque",)),
        CheckSpec.of(cs.check_shaft_critical_speed, _critical),
        CheckSpec.of(cs.check_shaft_key_shear, _governing(cs.check_shaft_key_shear), needs=("torque",)),
        CheckSpec.of(cs.check_shaft_key_crushing, _governing(cs.check_shaft_key_crushing), needs=("torque",)),
    ),
    outputs=tuple(Output(f"reaction_{L}_{w}", "force", f"{w} force on the support named {L}, else on the "
                         f"{i + 1}. support in order (reaction_<support name>_{w} for any support)",
                         _reaction(i, w)) for i, L in enumerate(LETTERS) for w in ("radial", "axial")),
))
