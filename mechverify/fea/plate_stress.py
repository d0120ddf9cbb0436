"""Surface stresses of a thin plate that carries bending and membrane (in-plane) loads together.

A Kirchhoff plate's stress through the thickness is the membrane part, uniform across it, plus the bending part,
linear in z and of opposite sign on the two faces (ref. 1 ch. 4, ref. 2 Sec. 10.1):

    sigma(z = ±t/2) = N / t ± 6 M / t²        [Pa; N in N/m, M in N·m/m, t in m]

(tension positive; the top face is z = +t/2). Linear theory superposes the two: the membrane field does not change
the bending moments (no P-delta), so the lateral loads' moments come from :func:`mechverify.fea.plate.solve_plate`
and the membrane field from the in-plane problem on the same mesh:

- :func:`membrane_stress` - ``N / t`` at the plate's vertices: the in-plane load's own field where it is exact (an
  outline without holes or cut-outs), else the plane-stress solution of the plate loaded by the edge tractions
  ``N n`` (:class:`mechverify.fea.plane.PlaneModel`, P2 triangles on the plate's own mesh, superconvergent patch
  recovery at the nodes): holes and cut-outs are free edges, so the stress concentrates around them (ref. 3: Kirsch,
  K_t = 3 at a small round hole under uniaxial tension);
- :func:`surface_stresses` - the two faces' in-plane stress components from both parts;
- :func:`plane_von_mises` and :func:`plane_principal` - von Mises and principal stresses of a plane stress state
  (ref. 4, Eqs. 3-13 and 5-13);
- :func:`governing_stress` - the point and face of the largest von Mises stress of a solved plate with both parts
  named (:class:`GoverningStress`).

References
----------
1. S. Timoshenko, S. Woinowsky-Krieger, *Theory of Plates and Shells*, 2nd ed., McGraw-Hill 1959, ch. 4 (bending
   stresses sigma = 12 M z / t³).
2. O. C. Zienkiewicz, R. L. Taylor, D. D. Fox, *The Finite Element Method for Solid and Structural Mechanics*, 7th
   ed., 2014, ch. 10 (plates: membrane and bending resultants).
3. W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., 2008, Chart 4.1.
4. R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., 2015, Eq. (3-13) (principal
   stresses) and Eq. (5-13) (von Mises, plane stress).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.errors import InputError
from mechverify.units import Q

if TYPE_CHECKING:
    from mechverify.fea.plate_buckling import InPlaneLoad
    from mechverify.fea.results import FieldResults

#: How the membrane field is found: "auto" (the given field on a plate without holes or cut-outs, else solved),
#: "given" (the load's own field N(x, y)) or "solve" (plane stress on the plate's mesh).
MEMBRANE_METHODS = ("auto", "given", "solve")


def plane_von_mises(s: np.ndarray) -> np.ndarray:
    """Von Mises stress [Pa] of plane stress states ``s[..., 3]`` = (sigma_x, sigma_y, tau_xy) [Pa]:
    ``sqrt(sx² - sx sy + sy² + 3 txy²)`` (ref. 4, Eq. 5-13)."""
    sx, sy, txy = s[..., 0], s[..., 1], s[..., 2]
    return np.sqrt(np.maximum(sx**2 - sx * sy + sy**2 + 3 * txy**2, 0.0))


def plane_principal(s: np.ndarray) -> np.ndarray:
    """In-plane principal stresses ``[..., 2]`` (sigma_1 >= sigma_2) [Pa] of ``s[..., 3]`` = (sx, sy, txy):
    ``(sx + sy)/2 ± sqrt(((sx - sy)/2)² + txy²)`` (ref. 4, Eq. 3-13)."""
    c = (s[..., 0] + s[..., 1]) / 2
    r = np.hypot((s[..., 0] - s[..., 1]) / 2, s[..., 2])
    return np.stack([c + r, c - r], axis=-1)


def surface_stresses(membrane: np.ndarray, bending_top: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The top (z = +t/2) and bottom (z = -t/2) face stresses ``[..., 3]`` [Pa] = membrane ± bending:
    ``sigma = N/t ± 6 M/t²`` with ``membrane = N/t`` and ``bending_top = 6 M/t²`` (ref. 1 ch. 4)."""
    return membrane + bending_top, membrane - bending_top


@dataclass(frozen=True)
class InPlaneSupport:
    """An in-plane support of the membrane problem: the displacement along x and/or y held on outline ``edges``
    (indices, names as :class:`mechverify.components.plates.EdgeSupport` reads them, or ``"all"``) or on the rims of
    ``holes`` (names or indices, or ``"all"``: a pin or bolt that holds the plate in its plane)."""

    edges: Any = ()
    holes: Any = ()
    x: bool = True
    y: bool = True

    def __post_init__(self) -> None:
        if not (self.x or self.y):
            raise InputError("InPlaneSupport: hold x, y or both")
        if (self.edges in ((), [], None)) == (self.holes in ((), [], None)):
            raise InputError("InPlaneSupport: give edges or holes (one of them)")

    def regions(self, plate: Any) -> list[tuple[str, Any]]:
        """``(description, region)`` of each held edge or hole rim of ``plate`` (:mod:`mechverify.fea.regions`)."""
        from mechverify.components import plates as pl
        from mechverify.fea.regions import Cylinder, Polyline

        tol = Q(1e-6 * float(np.sqrt(plate.region.area)), "m")
        if self.edges not in ((), [], None):
            edges = plate.edges()
            return [(f"outline edge {i}", Polyline(Q(np.array(edges[i], float), "m"), tol=tol))
                    for i in pl.EdgeSupport(self.edges).edge_indices(plate)]
        return [(f"hole {h.name!r}", Cylinder(tuple(Q(c, "m") for c in h.center), Q(h.radius, "m"), rel_tol=0.02))
                for h in pl.HoleSupport(self.holes, "simply_supported").resolve(plate)]


@dataclass(frozen=True)
class MembraneStress:
    """The membrane stress ``N / t`` [Pa] at the plate's vertices (``stress[n, 3]``: sigma_x, sigma_y, tau_xy), the
    method used ("given" or "solve"), notes and warnings, and for "solve" the plane-stress ``model``
    (:class:`mechverify.fea.plane.PlaneModel`) and its result ``field`` (:class:`mechverify.fea.results.FieldResults`,
    P2 nodes, vertices first in the plate's vertex order)."""

    stress: np.ndarray
    method: str
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    field: Any = None
    model: Any = None


def _outline_traction(outline: np.ndarray, N: Any, t: float) -> Any:
    """``points[2, k] -> N n / t [2, k]`` [Pa] on the outline polygon ``outline[v, 2]`` [m] of a plate of thickness
    ``t`` [m]: each point takes the outward normal of the nearest outline edge."""
    P = np.asarray(outline, float)
    A, B = P, np.roll(P, -1, axis=0)
    area2 = float(np.sum(A[:, 0] * B[:, 1] - B[:, 0] * A[:, 1]))  # > 0: counter-clockwise
    d = B - A
    normals = np.column_stack([d[:, 1], -d[:, 0]]) / np.linalg.norm(d, axis=1)[:, None] * (1 if area2 > 0 else -1)

    def traction(x: np.ndarray) -> np.ndarray:
        X = x[:2].T  # k, 2
        s = np.clip(np.einsum("kve,ve->kv", X[:, None, :] - A[None], d) / np.einsum("ve,ve->v", d, d), 0, 1)
        dist = np.linalg.norm(X[:, None, :] - (A[None] + s[..., None] * d[None]), axis=2)
        n = normals[np.argmin(dist, axis=1)].T  # 2, k
        nxx, nyy, nxy = N(x[0], x[1])
        return np.array([nxx * n[0] + nxy * n[1], nxy * n[0] + nyy * n[1]]) / t

    return traction


def round_hole_mesh(plate: Any, mesh: Any) -> Any:
    """A copy of the plate's triangle ``mesh`` (same vertices and triangles, counter-clockwise) whose boundary vertices
    on each round hole lie on its circle and whose P2 mid-side nodes on the rim lie on it too (``curved``, for the
    isoparametric triangles of :class:`mechverify.fea.plane.PlaneModel`). The plate's geometry holds a hole as a
    polygon (a few dozen sides), and mesh refinement below its side length resolves the polygon's re-entrant corners:
    a plate with a 20 mm hole (48 sides) in tension gave K_t = 3.07 and 3.17 at 1 and 0.5 mm instead of 3.02; on the
    circle it converges (tests/validation/test_roark_plate_membrane_hole.py)."""
    from mechverify.fea.mesh2d import NamedMeshTri, orient_triangles

    p = np.array(mesh.p, float)
    t = orient_triangles(p, mesh.t)
    m0 = NamedMeshTri(p, t, sort_t=False)
    bf = m0.boundary_facets()
    ends = m0.facets[:, bf]
    rim = np.zeros(bf.size, bool)
    for hole in plate.holes:
        c, r = np.asarray(hole.center, float)[:, None], float(hole.radius)
        v = np.unique(ends)
        d = np.linalg.norm(p[:, v] - c, axis=0)
        on = v[np.abs(d - r) <= 0.02 * r]
        p[:, on] = c + r * (p[:, on] - c) / np.linalg.norm(p[:, on] - c, axis=0)
        onmask = np.zeros(p.shape[1], bool)
        onmask[on] = True
        rim |= onmask[ends[0]] & onmask[ends[1]]
    m = NamedMeshTri(p, t, sort_t=False)
    mids = 0.5 * (p[:, m.facets[0]] + p[:, m.facets[1]])
    for hole in plate.holes:
        c, r = np.asarray(hole.center, float)[:, None], float(hole.radius)
        f = bf[rim]
        mf = mids[:, f]
        near = np.abs(np.linalg.norm(mf - c, axis=0) - r) <= 0.02 * r
        mids[:, f[near]] = c + r * (mf[:, near] - c) / np.linalg.norm(mf[:, near] - c, axis=0)
    m.curved = np.hstack([p, mids])
    return m


def membrane_stress(plate: Any, mesh: Any, load: InPlaneLoad, method: str = "auto",
                    supports: tuple[InPlaneSupport, ...] = ()) -> MembraneStress:
    """The membrane stress ``N / t`` [Pa] at the vertices of ``mesh`` (a scikit-fem ``MeshTri`` of ``plate``, the
    :class:`mechverify.components.plates.Plate`) under the in-plane ``load``
    (:class:`mechverify.fea.plate_buckling.InPlaneLoad`: edge loads on the outline, forces on hole rims) on the
    in-plane ``supports`` (:class:`InPlaneSupport`). ``method``: one of :data:`MEMBRANE_METHODS`; "auto" solves
    when the plate has holes or cut-outs, supports or hole loads.

    "solve": a :class:`mechverify.fea.plane.PlaneModel` (plane stress, P2, round holes on their circles:
    :func:`round_hole_mesh`) of the same mesh, loaded by the tractions ``N n`` on the outline edges and the hole
    forces (:class:`mechverify.fea.loads.PinLoad`); holes and cut-outs are otherwise free. Without supports the
    loads must balance by themselves and the model holds only a rigid in-plane motion (x and y at one outline vertex,
    one component at the farthest); loads that do not balance are an :class:`InputError` asking for supports.
    Supports that leave a rigid motion free are a :class:`ModelError` naming it. Edge loads alone are solved as the
    sum of five unit solutions kept per plate, mesh and supports (:func:`_superposed`: a study over the loads).
    """
    if method not in MEMBRANE_METHODS:
        raise InputError(f"membrane: one of {', '.join(MEMBRANE_METHODS)}, got {method!r}")
    t = plate.thickness
    N = load.field(plate.region.bounds)
    special = bool(supports or load.hole_loads)
    if method == "auto":
        method = "solve" if (plate.holes or plate.cutouts or special) else "given"
    if method == "given":
        if special:
            raise InputError("membrane: 'given' takes the edge loads' own field; in-plane supports and hole loads "
                             "need 'solve'")
        nxx, nyy, nxy = (np.broadcast_to(np.asarray(c, float), mesh.p[0].shape) for c in N(mesh.p[0], mesh.p[1]))
        return MembraneStress(np.column_stack([nxx, nyy, nxy]) / t, "given",
                              ("membrane stress: the in-plane load's own field N/t (no holes or cut-outs)",))
    if not load.hole_loads:
        cached = _superposed(plate, mesh, load, tuple(supports))
        if cached is not None:
            return cached
    return _solve(plate, mesh, load, tuple(supports))


#: The unit edge loads whose plane-stress solutions superpose to any InPlaneLoad without hole loads: nx at the low
#: and the high side, ny likewise, nxy (the field is linear in these five numbers).
_UNIT_LOADS = ((("1 N/m", "0 N/m"), 0.0, 0.0), (("0 N/m", "1 N/m"), 0.0, 0.0), (0.0, ("1 N/m", "0 N/m"), 0.0),
               (0.0, ("0 N/m", "1 N/m"), 0.0), (0.0, 0.0, "1 N/m"))


def _superposed(plate: Any, mesh: Any, load: InPlaneLoad, supports: tuple[InPlaneSupport, ...]
                ) -> MembraneStress | None:
    """The membrane stress of edge loads as the sum of the five unit solutions (:data:`_UNIT_LOADS`), kept in
    :data:`mechverify.fea.factorcache.CACHE` per plate, mesh and supports: a study that varies the in-plane loads
    solves the plane-stress model five times, not once per sample (and always the same way, so a result's last digits
    do not depend on what the process solved before). None when a unit load cannot be solved alone."""
    from dataclasses import replace

    from mechverify.fea import factorcache
    from mechverify.fea.plate_buckling import InPlaneLoad

    key = factorcache.key_of("plate membrane", plate, np.asarray(mesh.p).tobytes(), np.asarray(mesh.t).tobytes(),
                             supports)
    if key is None:
        return None
    item, _ = factorcache.CACHE.entry(key)
    try:
        units = factorcache.CACHE.part(item, "units", lambda: [_solve(plate, mesh, InPlaneLoad(*u), supports)
                                                                 for u in _UNIT_LOADS])
    except InputError:
        factorcache.CACHE.forget(key)
        return None
    (a0, a1), (b0, b1), nxy = load.values()
    c = (a0, a1, b0, b1, nxy)
    f0 = units[0].field

    def total(get: Any) -> np.ndarray:
        return sum(ci * get(u) for ci, u in zip(c, units, strict=True) if ci)  # type: ignore[return-value]

    field = replace(f0, u=total(lambda u: u.field.u), sigma=total(lambda u: u.field.sigma),
                    reaction=total(lambda u: u.field.reaction), applied=total(lambda u: u.field.applied),
                    ip_sigma=None, element_error=None, error_estimate=None, regions=(), warnings=())
    note = units[0].notes[0].replace("edge loads N n", "edge loads N n (superposed unit solutions)")
    return MembraneStress(total(lambda u: u.stress), "solve", (note,), units[0].warnings, field, None)


def _solve(plate: Any, mesh: Any, load: InPlaneLoad, supports: tuple[InPlaneSupport, ...]) -> MembraneStress:
    """:func:`membrane_stress` by one plane-stress solve of ``load``."""
    from mechverify.fea.loads import PinLoad, Restraint, Traction
    from mechverify.fea.plane import PlaneModel
    from mechverify.fea.regions import Box, Cylinder, Polyline

    t = plate.thickness
    N = load.field(plate.region.bounds)
    outline = np.asarray(plate.outline, float)
    size = float(np.sqrt(plate.region.area))
    tol = 1e-6 * size
    loads: list[Any] = []
    if load.has_edge_loads:
        ring = Polyline(Q(np.vstack([outline, outline[:1]]), "m"), tol=Q(tol, "m"))
        loads.append(Traction(ring, _outline_traction(outline, N, t)))
    for hf in load.hole_loads:
        h = plate.hole(hf.hole)
        loads.append(PinLoad(Cylinder(tuple(Q(c, "m") for c in h.center), Q(h.radius, "m"), rel_tol=0.02),
                             tuple(Q(f, "N") for f in hf.force)))
    rmesh = round_hole_mesh(plate, mesh)
    p = rmesh.p
    if supports:
        held = tuple(Restraint(r, x=s.x, y=s.y) for s in supports for _, r in s.regions(plate))
    else:
        a = int(np.argmin(np.linalg.norm(p - outline[0][:, None], axis=0)))
        far = np.linalg.norm(outline - p[:, a], axis=1)
        b = int(np.argmin(np.linalg.norm(p - outline[int(np.argmax(far))][:, None], axis=0)))
        d = p[:, b] - p[:, a]

        def point(k: int) -> Box:
            return Box(tuple(Q(c, "m") for c in p[:, k] - tol), tuple(Q(c, "m") for c in p[:, k] + tol))

        hold_x = abs(d[1]) >= abs(d[0])  # at b, hold the component across the line a-b
        held = (Restraint(point(a), x=True, y=True), Restraint(point(b), x=hold_x, y=not hold_x))
    model = PlaneModel(rmesh, Q(t, "m"), plate.material, held, tuple(loads))
    if not supports:
        f = model.load_vector().reshape(-1, 2)
        X = model.nodes.T - model.nodes.mean(axis=1)
        scale = float(np.abs(f).sum()) or 1.0
        imbalance = max(float(np.max(np.abs(f.sum(axis=0)))),
                        abs(float((X[:, 0] * f[:, 1] - X[:, 1] * f[:, 0]).sum())) / size)
        if imbalance > 1e-6 * scale:
            raise InputError("in-plane load: the loads are not in equilibrium by themselves (hole loads, or a "
                             "cut-out or notch that breaks a loaded outline edge): hold the plate in its plane with "
                             "in-plane supports (edges or hole rims)")
    res = model.solve()
    s = res.sigma[: mesh.nvertices]
    what = []
    if load.has_edge_loads:
        what.append(f"edge loads N n on {res.regions[0].count} outline edges")
    what += [f"({hf.force[0]:.6g}, {hf.force[1]:.6g}) N on hole {plate.hole(hf.hole).name!r}"
             for hf in load.hole_loads]
    held_words = ("supports: " + "; ".join(f"{d} holds {'x' if s_.x else ''}{'y' if s_.y else ''}"
                                          for s_ in supports for d, _ in s_.regions(plate))) if supports else \
        "no in-plane supports (the loads balance)"
    return MembraneStress(np.column_stack([s[:, 0, 0], s[:, 1, 1], s[:, 0, 1]]), "solve",
                          (f"membrane stress: plane stress (P2 triangles on the plate mesh, {res.recovery} recovery), "
                           f"{'; '.join(what)}; {held_words}",), tuple(res.warnings), res, model)


@dataclass(frozen=True)
class GoverningStress:
    """The largest surface von Mises stress of a solved plate and its parts: ``node``, ``point`` [m] (x, y), the
    ``face`` ("top": z = +t/2, or "bottom"), and in-plane components (sigma_x, sigma_y, tau_xy) [Pa] there:
    ``membrane`` (N/t), ``bending`` (±6 M/t² on that face) and ``total`` (their sum); ``von_mises`` [Pa] and the
    in-plane ``principal`` stresses (sigma_1 >= sigma_2) [Pa] of the total."""

    node: int
    point: np.ndarray
    face: str
    membrane: np.ndarray
    bending: np.ndarray
    total: np.ndarray
    von_mises: float
    principal: np.ndarray


def governing_stress(res: FieldResults, node: int | None = None) -> GoverningStress:
    """The point and face of the largest surface von Mises stress of a plate result of
    :func:`mechverify.fea.plate.solve_plate` (its ``extra`` fields ``membrane_*_Pa`` and ``bending_*_Pa``), or the
    worse face at vertex ``node``."""
    ex = res.extra
    if "bending_xx_Pa" not in ex:
        raise InputError(f"governing_stress: expected a plate result of fea.plate.solve_plate, got {res.kind!r}")
    m = np.column_stack([ex["membrane_xx_Pa"], ex["membrane_yy_Pa"], ex["membrane_xy_Pa"]])
    b = np.column_stack([ex["bending_xx_Pa"], ex["bending_yy_Pa"], ex["bending_xy_Pa"]])
    top, bottom = surface_stresses(m, b)
    vt, vb = plane_von_mises(top), plane_von_mises(bottom)
    k = int(np.argmax(np.maximum(vt, vb))) if node is None else int(node)
    on_top = vt[k] >= vb[k]
    bend = b[k] if on_top else -b[k]
    total = top[k] if on_top else bottom[k]
    return GoverningStress(k, np.asarray(res.points[k, :2], float), "top" if on_top else "bottom", m[k].copy(),
                           bend.copy(), total.copy(), float(max(vt[k], vb[k])), plane_principal(total))


__all__ = ["MEMBRANE_METHODS", "InPlaneSupport", "MembraneStress", "GoverningStress", "plane_von_mises",
           "plane_principal", "surface_stresses", "round_hole_mesh", "membrane_stress", "governing_stress"]
