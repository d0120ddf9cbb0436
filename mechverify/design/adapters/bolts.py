"""``bolted_joint`` (one bolt, VDI 2230 Part 1) and ``bolt_group`` (equal bolts, elastic method): parse and call."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

from mechverify.checks import bolts as cb
from mechverify.checks.result import CheckResult
from mechverify.components import bolts as b
from mechverify.design.adapters.common import inline_table
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output
from mechverify.errors import InputError
from mechverify.units import Q, to_si


@dataclasses.dataclass(frozen=True)
class BoltGroup:
    """A design file's bolt group: the joint of one bolt and the pattern of their positions."""

    name: str
    pattern: b.BoltPattern
    labels: tuple[str, ...]


def _parts(p: Mapping[str, Any]) -> tuple[b.ClampedPart, ...]:
    out = []
    for i, t in enumerate(p["parts"]):
        path = f"parts[{i}]"
        t = inline_table(t, path, ("thickness", "material", "p_G", "thermal_expansion"), ("thickness", "material"))
        try:
            out.append(b.ClampedPart.of(t["thickness"], t["material"], p_G=t.get("p_G"),
                                        thermal_expansion=t.get("thermal_expansion")))
        except Exception as exc:  # named errors of the component, with the key path
            raise InputError(f"{path}: {exc}") from None
    return tuple(out)


def _mu(p: Mapping[str, Any], key: str) -> tuple[float, float] | None:
    if key not in p:
        return None
    v = p[key]
    lo, hi = (v, v) if isinstance(v, int | float) else tuple(v) if len(v) == 2 else (None, None)
    if lo is None:
        raise InputError(f"{key}: give one friction coefficient or [min, max], got {v!r}")
    if lo < 0 or hi < 0:
        raise InputError(f"{key}: friction coefficients must not be negative, got {v!r}")
    return float(lo), float(hi)


OPTIONAL = {"head_bearing_diameter": ("d_W", "length"), "nut_bearing_diameter": ("d_W_nut", "length"),
            "outer_diameter": ("D_A", "length"), "shank_length": ("shank_length", "length"),
            "tightening_torque": ("tightening_torque", "torque"), "residual_clamp_load": ("F_K_req", "force")}


def _joint(p: Mapping[str, Any]) -> b.BoltedJoint:
    th = b.metric_thread(p["thread"])
    grade = b.property_class(p["property_class"], Q(th.d, "m"))
    mu_cls = b.friction_class(p["friction_class"]) if "friction_class" in p else None
    mu_G = _mu(p, "mu_thread") or mu_cls or (0.10, 0.16)
    mu_K = _mu(p, "mu_head") or mu_cls or mu_G
    if "mu_interface" in p and p["mu_interface"] < 0:
        raise InputError(f"mu_interface: must not be negative, got {p['mu_interface']}")
    alpha_A = p.get("tightening_factor") or (b.tightening_factor(p["tightening"])[1] if "tightening" in p else 1.6)
    tapped = b.ClampedPart.of("1 mm", p["tapped_material"]) if "tapped_material" in p else None
    d_h = to_si(p["hole_diameter"], "length") if "hole_diameter" in p else b.clearance_hole(th, p["hole_fit"])
    kw = dict(head=p["head"], tapped=tapped, d_h=d_h, mu_G=mu_G, mu_K=mu_K, mu_T=p.get("mu_interface"),
              q_F=p["interfaces"], alpha_A=float(alpha_A), nu=float(p["utilisation"]), n=float(p["load_introduction"]),
              rolled_after_heat_treatment=p["rolled_after_heat_treatment"], roughness=to_si(p["roughness"], "length"))
    kw.update({attr: to_si(p[key], dim, key) for key, (attr, dim) in OPTIONAL.items() if key in p})
    return b.BoltedJoint(p["_name"], th, grade, _parts(p), to_si(p["length"], "length", "length"), **kw)


def _point(v: Any, unit: str, path: str) -> tuple[float, float]:
    from mechverify.design.adapters.common import parse_point
    x, y = parse_point(v, unit, path)
    return to_si(x, "length", path), to_si(y, "length", path)


def _group(p: Mapping[str, Any]) -> BoltGroup:
    pos = tuple(_point(v, p["unit"], f"positions[{i}]") for i, v in enumerate(p["positions"]))
    labels = tuple(p.get("labels") or [str(i + 1) for i in range(len(pos))])
    if len(labels) != len(pos):
        raise InputError(f"labels: {len(labels)} labels for {len(pos)} bolts")
    return BoltGroup(p["_name"], b.BoltPattern(_joint(p), pos, labels), labels)


def _analyse(j: b.BoltedJoint, loads: Mapping[str, Any] | None) -> b.JointAnalysis:
    L = loads or {}
    return j.analyse(L.get("axial_force", "0 N"), F_A_min=L.get("axial_force_min", "0 N"),
                     F_Q=L.get("transverse_force", "0 N"), dT=L.get("temperature_change", Q(0, "K")))


def _group_analyses(g: BoltGroup, loads: Mapping[str, Any] | None) -> list[b.JointAnalysis]:
    L = loads or {}
    si = {k: to_si(L[k], dim, k) for k, dim in (("axial_force", "force"), ("force_x", "force"), ("force_y", "force"),
                                                 ("moment_x", "torque"), ("moment_y", "torque"),
                                                 ("moment_z", "torque")) if k in L}
    at = _point(L["load_point"], "mm", "load_point") if "load_point" in L else None
    bl = g.pattern.distribute(F_z=si.get("axial_force", 0.0), F_x=si.get("force_x", 0.0), F_y=si.get("force_y", 0.0),
                              M_x=si.get("moment_x", 0.0), M_y=si.get("moment_y", 0.0), M_z=si.get("moment_z", 0.0),
                              at=at)
    return g.pattern.analyse(bl, dT=L.get("temperature_change", Q(0, "K")))


def _single(fn: Any) -> Any:
    return lambda c, loads, ctx: fn(c, _analyse(c, loads), required_sf=ctx.required_sf, load_case=ctx.load_case)


def _per_bolt(fn: Any) -> Any:
    def run(g: BoltGroup, loads: Mapping[str, Any] | None, ctx: Any) -> CheckResult:
        j, sf, lc = g.pattern.joint, ctx.required_sf, ctx.load_case
        return cb.governing_bolt([fn(j, a, required_sf=sf, load_case=lc) for a in _group_analyses(g, loads)], g.labels)
    return run


JOINT_FIELDS = (
    Field("thread", "str", "ISO metric thread: 'M8' (coarse) or 'M10x1.25' (ISO 262 fine)", required=True),
    Field("property_class", "str", "ISO 898-1 class 4.6 ... 12.9, or ISO 3506 A2-70 ...", default="8.8"),
    Field("length", "length", "bolt length under the head", required=True),
    Field("head", "choice", "head type: hex (ISO 4014/4017) or socket (ISO 4762)", default="hex",
          choices=("hex", "socket")),
    Field("parts", "list", "clamped parts from the head: {thickness, material, p_G (limiting surface pressure), "
                           "thermal_expansion (1/K)}", required=True, item="table"),
    Field("tapped_material", "material", "screwed into a tapped hole of this material (no nut); else a through bolt "
                                         "with an ISO 4032 nut"),
    Field("hole_fit", "choice", "ISO 273 clearance hole", default="medium", choices=("fine", "medium", "coarse")),
    Field("hole_diameter", "length", "clearance hole diameter d_h, instead of ISO 273"),
    Field("head_bearing_diameter", "length", "head (or washer) bearing diameter d_W, instead of the ISO head table"),
    Field("nut_bearing_diameter", "length", "nut (or washer) bearing diameter, instead of ISO 4032 d_w"),
    Field("outer_diameter", "length", "outer diameter D_A of the clamped body around the bolt (default: unbounded)"),
    Field("shank_length", "length", "unthreaded shank (default: length - standard thread length)"),
    Field("friction_class", "choice", "VDI 2230 Table A5 friction class for mu_G and mu_K",
          choices=("A", "B", "C", "D", "E")),
    Field("mu_thread", "list", "thread friction mu_G as [min, max] (default [0.10, 0.16])", item="float"),
    Field("mu_head", "list", "head friction mu_K as [min, max] (default: mu_thread)", item="float"),
    Field("mu_interface", "float", "friction mu_T,min between clamped parts (needed for transverse loads)"),
    Field("interfaces", "int", "friction interfaces q_F carrying the transverse load", default=1),
    Field("tightening", "choice", "VDI 2230 Table A8 technique (alpha_A = upper value of its range)",
          choices=("yield_controlled", "elongation", "torque_wrench", "torque_wrench_measured", "impact", "hand")),
    Field("tightening_factor", "float", "tightening factor alpha_A = F_M,max/F_M,min (default 1.6)"),
    Field("utilisation", "float", "nu: the assembly preload uses this fraction of R_p0.2 (VDI 2230)", default=0.9),
    Field("tightening_torque", "torque", "torque set at assembly (default: the R13 torque for F_M,zul at mu_min)"),
    Field("load_introduction", "float", "load-introduction factor n (VDI 2230 Sec. 5.2.2; 1 = at head and nut)",
          default=0.5),
    Field("roughness", "length", "mean roughness Rz of the surfaces (embedding, VDI 2230 Table 5.4/1)",
          default="16 um"),
    Field("rolled_after_heat_treatment", "bool", "threads rolled after heat treatment (sigma_ASG)", default=False),
    Field("residual_clamp_load", "force", "residual clamp load required in service (sealing, F_K,erf)"),
)
LOADS = (
    Field("axial_force", "force", "axial tension on the joint F_A,max (per bolt; total for a group)"),
    Field("axial_force_min", "force", "smallest axial tension of a cycle F_A,min (fatigue; default 0)"),
    Field("transverse_force", "force", "transverse force F_Q on the joint (carried by friction)"),
    Field("temperature_change", "temperature", "uniform temperature change of bolt and parts from assembly (K)"),
)
CHECKS = (cb.check_bolt_assembly_stress, cb.check_bolt_required_preload, cb.check_bolt_working_stress,
          cb.check_bolt_fatigue, cb.check_bolt_surface_pressure_head, cb.check_bolt_surface_pressure_nut,
          cb.check_bolt_thread_stripping, cb.check_bolt_separation, cb.check_bolt_slip, cb.check_bolt_tightening_torque)
_A = "axial_force|transverse_force|temperature_change"
_GA = "axial_force|force_x|force_y|moment_x|moment_y|moment_z|temperature_change"
# every load-dependent check runs in each case that loads the joint (a missing load counts as zero)
NEEDS = {n: (_A,) for n in ("bolt_required_preload", "bolt_working_stress", "bolt_fatigue",
                            "bolt_surface_pressure_head", "bolt_surface_pressure_nut", "bolt_separation", "bolt_slip")}
GROUP_NEEDS = {n: (_GA,) for n in NEEDS}


def _applies(fn: Any, group: bool) -> Any:
    run = _per_bolt(fn) if group else _single(fn)
    if fn is not cb.check_bolt_surface_pressure_nut:
        return run

    def nut_only(c: Any, loads: Any, ctx: Any) -> Any:  # a tapped joint has no nut
        return run(c, loads, ctx) if (c.pattern.joint if group else c).through else []
    return nut_only


BOLTED_JOINT = REGISTRY.register(ComponentType(
    name="bolted_joint",
    doc="One ISO metric bolt clamping plates, through-bolted with a nut or into a tapped hole: VDI 2230 Part 1 "
        "(2015) R0-R13 - resiliences, load factor, embedding, preload from alpha_A and nu, tightening torque, "
        "assembly and working stress, fatigue, surface pressure, thread stripping, separation and slip.",
    fields=JOINT_FIELDS,
    build=lambda p, ctx: _joint(p),
    loads=LOADS,
    checks=tuple(CheckSpec.of(fn, _applies(fn, False), needs=NEEDS.get(fn.check_def.name, ())) for fn in CHECKS),
    outputs=(
        Output("preload_min", "force", "smallest assembly preload F_M,min the tightening gives (VDI 2230 R5)",
               lambda c, loads: Q(c.preloads()[0], "N")),
        Output("tightening_torque", "torque", "tightening torque M_A to set (VDI 2230 R13)",
               lambda c, loads: Q(c.preloads()[2], "N*m")),
        Output("bolt_force_max", "force", "largest bolt force F_S,max = F_M,max + Phi_n F_A of the case",
               lambda c, loads: Q(sum(getattr(_analyse(c, loads), k) for k in ("F_M_max", "F_SA")), "N")),
    ),
))


BOLT_GROUP = REGISTRY.register(ComponentType(
    name="bolt_group",
    doc="Equal bolts at positions in the joint plane loaded by a force and moments: each bolt's share by the elastic "
        "method about the pattern centroid (rigid plate, no prying; Shigley 10th ed. Sec. 8-12), then the "
        "bolted_joint checks per bolt; the governing bolt is reported with every bolt's utilisation.",
    fields=(*JOINT_FIELDS,
            Field("positions", "list", "bolt positions \"x, y\" in the joint plane (z along the bolts)", required=True),
            Field("labels", "list", "a name per bolt (default 1, 2, ...)"),
            Field("unit", "str", "unit of bare numbers in positions", default="mm")),
    build=lambda p, ctx: _group(p),
    loads=(
        Field("axial_force", "force", "total force along the bolts (+ pulls them) at load_point"),
        Field("force_x", "force", "in-plane force along x at load_point (carried by friction)"),
        Field("force_y", "force", "in-plane force along y at load_point"),
        Field("moment_x", "torque", "moment about x through the pattern centroid"),
        Field("moment_y", "torque", "moment about y through the pattern centroid"),
        Field("moment_z", "torque", "torque about the bolt axis through the centroid"),
        Field("load_point", "str", "\"x, y\" where the forces act (mm; default the centroid)"),
        Field("temperature_change", "temperature", "uniform temperature change from assembly (K)"),
    ),
    checks=tuple(CheckSpec.of(fn, _applies(fn, True), needs=GROUP_NEEDS.get(fn.check_def.name, ())) for fn in CHECKS),
))


# ------------------------------------------------------------------ plate_fea outputs: bolt-hole support forces
G_STANDARD = 9.80665  # outputs are asked without the design's requirements: self-weight at standard gravity

def hole_support_forces(c: Any, loads: Mapping[str, Any] | None) -> dict[str, tuple[tuple[float, float], float]]:
    """Bolt tension at each bolt-hole support of a ``plate_fea`` component in a load case (solved once per loads)."""
    key = "outputs:" + repr(sorted((k, repr(v)) for k, v in (loads or {}).items()))
    _, res = c.solve(loads or {}, key, G_STANDARD)
    return b.hole_support_forces(c.plate, c.supports, res.points[:, :2], res.extra["reaction_z_N"], c.name)


def _resultants(c: Any, loads: Mapping[str, Any] | None) -> tuple[float, float, float]:
    return b.force_resultants(hole_support_forces(c, loads).values())


def plate_bolt_outputs() -> tuple[Output, ...]:
    """Outputs of ``plate_fea`` a ``bolted_joint`` or ``bolt_group`` reads as ``"<plate>.<name>"``."""
    needs = ("point_loads|patch_loads|pressure|self_weight",)
    return (
        Output("bolt_tension_max", "force", "largest bolt tension of one bolt-hole support (its FEA rim reactions)",
               lambda c, loads: Q(max(0.0, *(t for _, t in hole_support_forces(c, loads).values())), "N"), needs),
        Output("bolt_force_total", "force", "total bolt tension of the bolt-hole supports (F_z of a bolt_group)",
               lambda c, loads: Q(_resultants(c, loads)[0], "N"), needs),
        Output("bolt_moment_x", "torque", "moment about x of the bolt-hole forces about their centroid",
               lambda c, loads: Q(_resultants(c, loads)[1], "N*m"), needs),
        Output("bolt_moment_y", "torque", "moment about y of the bolt-hole forces about their centroid",
               lambda c, loads: Q(_resultants(c, loads)[2], "N*m"), needs),
    )
