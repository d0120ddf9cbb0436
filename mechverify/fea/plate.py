"""Thin-plate bending (Kirchhoff) of a declarative :class:`mechverify.components.plates.PlateModel`.

The plate is meshed in its x-y plane (structured triangles for a plain rectangle, gmsh for any
outline with holes and cut-outs, graded towards the holes) and discretised with Morley triangles
(scikit-fem ``ElementTriMorley``: deflection at the vertices, normal slope at the edge midpoints),
the classic non-conforming Kirchhoff element, which converges without shear locking because it
has no transverse shear at all. It is meant for thin plates (span/thickness above about 10, as
the 4-8 mm aluminium plates it was written for); moderately thick (Reissner-Mindlin) plates are not
modelled, and a warning says so when span/thickness < 10.

Supports: outline edges, bolt-hole rims (optionally widened to the washer), points - simply
supported (deflection held) or clamped (slope held as well). Loads: point loads (moments as a
force couple across one element), patches, uniform pressure, self-weight; all along z.

Stresses: the surfaces carry the bending stress ``σ = ± 6 M / t²`` with the moments
``M = -D[(1-ν) κ + ν tr(κ) I]`` from the curvatures ``κ = ∇∇w`` (constant per Morley element), smoothed to the
vertices by lumped L2 projection, plus, when in-plane edge loads are given, the membrane stress ``N / t``
(:mod:`mechverify.fea.plate_stress`): ``σ = N/t ± 6 M/t²`` on the top and bottom faces.
``FieldResults.sigma`` holds at each vertex the face with the larger von Mises stress (the top face, z = +t/2,
where they tie, as they do without membrane loads: the bottom is then its negative).

References
----------
1. Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., McGraw-Hill 1959, ch. 4
   (D = E t³ / 12(1 - ν²), moment-curvature relations, eq. 101).
2. Morley, "The constant-moment plate-bending element", J. Strain Analysis 6 (1971) 20-24.
3. Young & Budynas, Roark's Formulas for Stress and Strain, 7th ed., 2002, Tables 11.2 and 11.4.
"""

from __future__ import annotations

import copy
import math
import time
from typing import Any

import numpy as np
import scipy.sparse as sp
from skfem import Basis, BilinearForm, ElementTriMorley, LinearForm, MeshTri, asm
from skfem.helpers import dd, ddot, eye, trace

from mechverify.errors import InputError, ModelError
from mechverify.fea import factorcache, mesh2d
from mechverify.fea.linsolve import SolveInfo
from mechverify.fea.results import FieldResults
from mechverify.units import QuantityLike

try:  # the declarative plate belongs to the components layer (issue 6)
    from mechverify.components import plates as _plates
except ImportError:  # pragma: no cover - components always ship with mechverify
    _plates = None


#: The default element size at a round hole's rim is its radius / RIM_DIVISIONS (at most mesh_size / 3): the rim's
#: bending peak on the lumped-projection moments converges as O(h) (measured, 400 x 200 x 4 mm steel plate, pinned,
#: 10 kPa, 20 mm hole: 27.07 / 27.66 / 27.84 / 27.93 / 28.08 / 28.15 MPa at radius / 10 / 20 / 30 / 40 / 80 / 160,
#: about -1.3 % at /30 from the converged ~28.2 MPa; tests/validation/test_timoshenko_plate_hole_rim_accuracy.py;
#: a cut-out's 10 mm corner: 40.08 MPa at /30 against ~40.5).
#: The same fraction of a cut-out's corner radius is used on its rounded corners (:func:`ring_arcs`).
RIM_DIVISIONS = 30.0
#: The rim's fine size grows to mesh_size over this many mesh_size from the rim (gmsh Threshold field).
RIM_REACH = 4.0


def _circumcircle(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, float] | None:
    """Centre and radius of the circle through three points (None when they are collinear)."""
    d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    scale = max(float(np.ptp(np.array([a, b, c]), axis=0).max()), 1e-300)
    if abs(d) <= 1e-9 * scale**2:
        return None
    sa, sb, sc = a @ a, b @ b, c @ c
    ux = (sa * (b[1] - c[1]) + sb * (c[1] - a[1]) + sc * (a[1] - b[1])) / d
    uy = (sa * (c[0] - b[0]) + sb * (a[0] - c[0]) + sc * (b[0] - a[0])) / d
    centre = np.array([ux, uy])
    return centre, float(np.linalg.norm(a - centre))


def ring_arcs(coords: Any) -> list[tuple[list[int], np.ndarray, float]]:
    """The circular arcs of a polygon ring (a cut-out's rounded corners: runs of three or more consecutive vertices
    whose circles through their two neighbours agree to 0.1 %): per arc the indices of its segments (segment i runs
    from vertex i to i + 1, the arc's end segments to its tangent points included), its centre and radius [m]."""
    pts = np.asarray(coords, dtype=float)
    if len(pts) > 1 and np.allclose(pts[0], pts[-1]):
        pts = pts[:-1]
    n = len(pts)
    circ = [_circumcircle(pts[i - 1], pts[i], pts[(i + 1) % n]) for i in range(n)]

    def same(i: int, j: int) -> bool:
        ci, cj = circ[i % n], circ[j % n]
        if ci is None or cj is None:
            return False
        tol = 1e-3 * max(ci[1], cj[1])
        return float(np.linalg.norm(ci[0] - cj[0])) <= tol and abs(ci[1] - cj[1]) <= tol

    if n < 3 or all(same(i, i + 1) for i in range(n)):  # a whole circle (round holes are handled by their circle)
        return []
    start = next(i for i in range(n) if not same(i, i + 1))  # a run ends here: start scanning after it
    arcs: list[tuple[list[int], np.ndarray, float]] = []
    run: list[int] = []
    for k in range(1, n + 2):
        i = (start + k) % n
        if run and same(run[-1], i):
            run.append(i)
            continue
        if len(run) >= 3:  # a straight side between two arcs gives a pair of vertices on one (huge) circle
            segs = sorted({(run[0] - 1) % n, *run})
            centre, r = circ[run[len(run) // 2]]
            arcs.append((segs, centre, r))
        run = [i] if circ[i] is not None else []
    return arcs


def hole_sizes(plate: Any, size: float, hole_size: float | None = None, refine: float = 1.0) -> list[float]:
    """The element size [m] at each interior ring of ``plate.region`` (its round holes, then its cut-outs):
    ``hole_size`` where given, else a round hole's radius / :data:`RIM_DIVISIONS` (at most size / 3) and size / 3
    at a cut-out (its rounded corners: :func:`mesh_region`); all divided by ``refine`` (``size`` is taken as already
    refined)."""
    if hole_size is not None:
        return [hole_size / refine] * (len(plate.holes) + len(plate.cutouts))
    return ([min(size / 3, hole.radius / RIM_DIVISIONS / refine) for hole in plate.holes]
            + [size / 3] * len(plate.cutouts))


def _arc_points(centre: np.ndarray, r: float, a: np.ndarray, b: np.ndarray, size: float) -> list[np.ndarray]:
    """Points on the circle (centre, r) from ``a`` to ``b`` (the shorter way, ``a`` included, ``b`` not) about
    ``size`` apart (at least one: ``a``)."""
    t0 = math.atan2(a[1] - centre[1], a[0] - centre[0])
    dt = math.atan2(b[1] - centre[1], b[0] - centre[0]) - t0
    dt = (dt + math.pi) % (2 * math.pi) - math.pi
    m = max(1, math.ceil(abs(dt) * r / size - 1e-9))
    return [a] + [centre + r * np.array([math.cos(t0 + dt * j / m), math.sin(t0 + dt * j / m)]) for j in range(1, m)]


def mesh_region(plate: Any, size: float, hole_size: float | None = None, refine: float = 1.0
                ) -> tuple[Any, dict[int, float], dict[tuple[int, int], float]]:
    """The polygon the plate is meshed on [m] and its element sizes: each round hole as a polygon of vertices ON
    its circle about as far apart as its element size (:func:`hole_sizes`; at least the plate's
    :data:`~mechverify.components.plates.HOLE_SEGMENTS` sides), each rounded corner of a cut-out
    (:func:`ring_arcs`) likewise on its circle at its radius / :data:`RIM_DIVISIONS` (at most size / 3; the cut-out's
    other sides at size / 3). Returns the polygon, ``interior ring -> size`` and ``(interior ring, segment) -> size``
    for :func:`mechverify.fea.mesh2d.polygon` (``size`` is taken as already refined).

    Why on the circle: the plate's geometry holds a hole as a polygon of 48 sides (a rounded corner as 6 per quarter
    circle) whose corners are slightly re-entrant, and a mesh finer than a side resolves them as weak corner
    singularities: the rim's bending peak then overshoots and keeps growing (20 mm hole: 28.77 / 29.41 MPa at 0.25 /
    0.125 mm against a converged ~28.2; 10 mm hole 29.94 at 0.0625 mm against 28.75 by hand; a cut-out's 10 mm corner
    37.2 / 40.1 / 42.8 / 45.7 MPa at 4.2 / 1 / 0.33 / 0.125 mm). Moving the mesh's boundary vertices onto the circle
    afterwards distorts elements smaller than the polygon's sagitta; a polygon on the circle at the mesh's own
    resolution converges monotonically."""
    import shapely

    region = plate.region
    sizes = hole_sizes(plate, size, hole_size, refine)
    rings, ring_sizes, seg_sizes = [], {}, {}
    nh = len(plate.holes)
    for k, ring in enumerate(region.interiors):
        hk = sizes[k]
        if k < nh:
            hole = plate.holes[k]
            # a multiple of 4 sides: vertices on the hole's axes (where a uniaxial field peaks), as the 48-gon's
            n = max(len(ring.coords) - 1, 4 * math.ceil(math.pi * hole.radius / (2 * hk) - 1e-9))
            t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
            rings.append(np.c_[hole.center[0] + hole.radius * np.cos(t), hole.center[1] + hole.radius * np.sin(t)])
            ring_sizes[k] = hk
            continue
        pts = np.asarray(ring.coords, dtype=float)[:-1]
        arcs = {i: (c, r) for segs, c, r in ring_arcs(ring.coords) for i in segs}
        out: list[np.ndarray] = []
        for i in range(len(pts)):
            if i in arcs:
                c, r = arcs[i]
                hs = hk if hole_size is not None else min(hk, r / RIM_DIVISIONS / refine)
                new = _arc_points(c, r, pts[i], pts[(i + 1) % len(pts)], hs)
                seg_sizes.update({(k, len(out) + j): hs for j in range(len(new))})
                out += new
            else:
                out.append(pts[i])
        rings.append(np.array(out))
        ring_sizes[k] = hk
    poly = shapely.Polygon(region.exterior.coords, [r for r in rings])
    return poly, ring_sizes, seg_sizes


def plate_mesh(plate: Any, size: float | None = None, hole_size: float | None = None, refine: float = 1.0
               ) -> MeshTri:
    """Triangles covering ``plate.region``: structured for a plain rectangle, else gmsh on :func:`mesh_region` (the
    round holes and cut-outs' rounded corners on their circles), graded to :func:`hole_sizes` at the holes and
    cut-outs; all element sizes divided by ``refine``."""
    region = plate.region
    x0, y0, x1, y1 = region.bounds
    span = min(x1 - x0, y1 - y0)
    h = span / 16 if size is None else float(size)
    if h <= 0:
        raise InputError("plate mesh size must be positive")
    h = h / refine
    plain_rect = (not plate.holes and not plate.cutouts and len(plate.outline) == 4
                  and abs(region.area - (x1 - x0) * (y1 - y0)) <= 1e-12 * region.area)
    if plain_rect:
        nx = max(2, int(round((x1 - x0) / h)))
        ny = max(2, int(round((y1 - y0) / h)))
        return mesh2d.rectangle(x1 - x0, y1 - y0, nx + nx % 2, ny + ny % 2, (x0, y0))
    other = h / 3 if hole_size is None else hole_size / refine  # curved runs of the outline
    poly, ring_sizes, seg_sizes = mesh_region(plate, h, hole_size, refine)
    return mesh2d.polygon(poly, h, other, ring_sizes, seg_sizes, RIM_REACH)


def mesh_sizes(plate: Any, mesh_size: QuantityLike | None = None, hole_mesh_size: QuantityLike | None = None
               ) -> tuple[float, float]:
    """The element sizes [m] :func:`solve_plate` uses: ``mesh_size`` (default: the shorter side of the plate's
    bounding box / 16) and the finest at holes and cut-outs: ``hole_mesh_size`` where given, else the smallest of
    :func:`hole_sizes` (a round hole's radius / :data:`RIM_DIVISIONS`, at most mesh_size / 3)."""
    from mechverify.units import to_si

    x0, y0, x1, y1 = plate.region.bounds
    h = min(x1 - x0, y1 - y0) / 16 if mesh_size is None else to_si(mesh_size, "length", "mesh_size")
    if hole_mesh_size is not None:
        return h, to_si(hole_mesh_size, "length", "hole_mesh_size")
    return h, min([h / 3, *hole_sizes(plate, h)])


class _PlateSystem:
    """Mesh, Morley basis and the DOF bookkeeping of one plate model."""

    def __init__(self, model: Any, mesh: MeshTri):
        # Morley's normal-derivative DOFs take their sign from scikit-fem's sorted vertex order, so
        # the plate works on a sorted copy (mesh2d keeps triangles counter-clockwise, unsorted)
        mesh = MeshTri(np.ascontiguousarray(mesh.p), np.ascontiguousarray(mesh.t))
        self.model = model
        self.plate = model.plate
        self.mesh = mesh
        self.basis = Basis(mesh, ElementTriMorley())
        mat = self.plate.material
        self.E, self.nu = mat.require("E").m_as("Pa"), mat.require("nu").m_as("")
        self.t = self.plate.thickness
        self.D = self.E * self.t**3 / (12 * (1 - self.nu**2))
        self.bfacets = mesh.boundary_facets()
        edges = mesh.p[:, mesh.facets]
        self.edge_length = float(np.mean(np.linalg.norm(edges[:, 1] - edges[:, 0], axis=0)))

    # -- geometry helpers ----------------------------------------------------------------------
    def facets_on_segment(self, a: tuple[float, float], b: tuple[float, float], tol: float) -> np.ndarray:
        m = self.mesh
        f = self.bfacets
        P = m.p[:, m.facets[:, f]]  # 2, 2(vertex), k
        A, B = np.asarray(a)[:, None, None], np.asarray(b)[:, None, None]
        AB = B - A
        L2 = float((AB**2).sum())
        s = np.clip(((P - A) * AB).sum(axis=0) / L2, 0, 1)
        d = np.linalg.norm(P - (A + s * AB), axis=0)
        return f[np.all(d <= tol, axis=0)]

    def facets_on_circle(self, c: tuple[float, float], r: float, tol: float) -> np.ndarray:
        m = self.mesh
        f = self.bfacets
        P = m.p[:, m.facets[:, f]]
        d = np.linalg.norm(P - np.asarray(c)[:, None, None], axis=0)
        return f[np.all(np.abs(d - r) <= tol, axis=0)]

    def facets_within(self, c: tuple[float, float], r: float) -> np.ndarray:
        m = self.mesh
        P = m.p[:, m.facets]
        d = np.linalg.norm(P - np.asarray(c)[:, None, None], axis=0)
        return np.flatnonzero(np.all(d <= r * (1 + 1e-9), axis=0))

    def nearest_vertex(self, pt: tuple[float, float]) -> int:
        return int(np.argmin(np.linalg.norm(self.mesh.p - np.asarray(pt)[:, None], axis=0)))


def _stiffness(sys_: _PlateSystem) -> sp.csr_matrix:
    nu, D = sys_.nu, sys_.D

    @BilinearForm
    def bending(u: Any, v: Any, w: Any) -> Any:
        T = dd(u)
        return D * ddot((1 - nu) * T + nu * eye(trace(T), 2), dd(v))

    return asm(bending, sys_.basis).tocsr()


def _load_vector(sys_: _PlateSystem) -> tuple[np.ndarray, float]:
    """Consistent load vector (along +z) and the total applied force [N]."""
    P = _plates
    plate, basis = sys_.plate, sys_.basis
    f = np.zeros(basis.N)
    total = 0.0
    import shapely

    for ld in sys_.model.loads:
        if isinstance(ld, P.PressureLoad | P.PlateSelfWeight):
            q = ld.pressure if isinstance(ld, P.PressureLoad) else ld.pressure(plate)

            @LinearForm
            def uniform(v: Any, w: Any, q: float = q) -> Any:
                return q * v

            fu = asm(uniform, basis)
            f += fu
            # the integral of q over the mesh (the vertex shape functions sum to 1): a hole rim meshed on its
            # circle (mesh_region) makes the meshed area differ from the polygon's by ~1e-3 of the hole's area
            total += float(fu[basis.nodal_dofs[0]].sum())
        elif isinstance(ld, P.PatchLoad):
            poly = shapely.Polygon(ld.polygon)
            covered = poly.intersection(plate.region).area

            @LinearForm
            def patch(v: Any, w: Any, poly: Any = poly, q: float = ld.pressure) -> Any:
                x, y = w.x
                inside = shapely.contains_xy(poly, x.ravel(), y.ravel()).reshape(x.shape)
                return q * inside * v

            fb = Basis(sys_.mesh, ElementTriMorley(), intorder=8)
            fp = asm(patch, fb)
            got = float(fp[basis.nodal_dofs[0]].sum())
            if covered <= 0 or got == 0:
                raise InputError("PatchLoad: the patch covers no part of the meshed plate; refine the mesh "
                                 "or enlarge the patch")
            f += fp * (ld.pressure * covered / got)  # exact resultant
            total += ld.pressure * covered
        elif isinstance(ld, P.PlatePointLoad):
            x, y = ld.point
            pts = [((x, y), ld.force)]
            if ld.moment_x or ld.moment_y:
                d = 0.5 * sys_.edge_length
                # a moment about x (right-hand rule) lifts the +y side: forces ±M/(2d) at y ± d
                pts += [((x, y + d), ld.moment_x / (2 * d)), ((x, y - d), -ld.moment_x / (2 * d)),
                        ((x + d, y), -ld.moment_y / (2 * d)), ((x - d, y), ld.moment_y / (2 * d))]
            for (px, py), F in pts:
                if F == 0:
                    continue
                try:
                    probe = basis.probes(np.array([[px], [py]]))
                except (ValueError, IndexError):
                    raise InputError(f"point load at ({px * 1e3:.4g}, {py * 1e3:.4g}) mm is off the meshed plate"
                                     ) from None
                f += F * np.asarray(probe.todense()).ravel()
            total += ld.force
        else:
            raise InputError(f"plate load {ld!r} is not supported")
    return f, total


def _supports(sys_: _PlateSystem) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Held DOFs, and for the rigid-body check the held points ``[2, k]`` and the held slopes
    (facet normals ``[2, k]``)."""
    P = _plates
    m, basis, plate = sys_.mesh, sys_.basis, sys_.plate
    tol = 1e-6 * float(np.sqrt(plate.region.area))
    vdofs, fdofs = basis.nodal_dofs[0], basis.facet_dofs[0]
    held_v: list[np.ndarray] = []
    held_f: list[np.ndarray] = []
    for s in sys_.model.supports:
        clamped = s.condition == "clamped"
        if isinstance(s, P.EdgeSupport):
            n = len(plate.outline)
            facets = np.concatenate([sys_.facets_on_segment(plate.outline[i], plate.outline[(i + 1) % n], tol)
                                     for i in s.edge_indices(plate)])
            if facets.size == 0:
                raise ModelError("EdgeSupport: no mesh edge lies on the chosen outline edges")
            held_v.append(m.facets[:, facets].ravel())
            if clamped:
                held_f.append(facets)
        elif isinstance(s, P.HoleSupport):
            for hole in s.resolve(plate):
                facets = sys_.facets_on_circle(hole.center, hole.radius, 0.01 * hole.radius)
                if facets.size == 0:
                    raise ModelError(f"HoleSupport: no mesh edge on the rim of hole {hole!r}")
                held_v.append(m.facets[:, facets].ravel())
                if clamped:
                    held_f.append(facets)
                if s.washer_diameter is not None:
                    ring = sys_.facets_within(hole.center, s.washer_diameter / 2)
                    held_v.append(m.facets[:, ring].ravel())
                    if clamped:
                        held_f.append(ring)
        elif isinstance(s, P.PointSupport):
            k = sys_.nearest_vertex(s.point)
            held_v.append(np.array([k]))
            if clamped:
                held_f.append(np.flatnonzero(np.any(m.facets == k, axis=0)))
        else:
            raise InputError(f"plate support {s!r} is not supported")
    verts = np.unique(np.concatenate(held_v)) if held_v else np.array([], dtype=np.int64)
    facets = np.unique(np.concatenate(held_f)) if held_f else np.array([], dtype=np.int64)
    held = np.unique(np.concatenate([vdofs[verts], fdofs[facets]]))
    fp = m.p[:, m.facets[:, facets]]
    tangent = fp[:, 1] - fp[:, 0]
    normals = np.vstack([tangent[1], -tangent[0]]) / np.maximum(np.linalg.norm(tangent, axis=0), 1e-300)
    return held, m.p[:, verts], normals, verts


def check_plate_supported(points: np.ndarray, slope_normals: np.ndarray) -> None:
    """:class:`ModelError` naming the rigid plate motion (w = a + b x + c y) the supports leave free.

    Held deflection at ``points[2, k]`` demands a + b x + c y = 0; a held slope across an edge with
    normal n demands b n_x + c n_y = 0 (ref. 1, sec. 4: rigid motions of a plate).
    """
    rows = [np.column_stack([np.ones(points.shape[1]), points[0], points[1]]),
            np.column_stack([np.zeros(slope_normals.shape[1]), slope_normals[0], slope_normals[1]])]
    A = np.vstack(rows)
    if A.shape[0] == 0:
        raise ModelError("the plate has no supports")
    scale = max(float(np.max(np.abs(points))) if points.size else 1.0, 1e-9)
    As = A * np.array([1.0, scale, scale])
    _, s, Vt = np.linalg.svd(As, full_matrices=True)
    rank = int(np.sum(s > 1e-9 * max(s.max(), 1e-300)))
    if rank == 3:
        return
    from mechverify.fea.motions import rotation_words

    motions = []
    null = Vt[rank:]
    if null.shape[0] == 2:  # a point support: the lines through it along x and along y, not a random pair
        picks = [np.array([null[0, k], -null[1, k]]) @ null[::-1] for k in (2, 1)]  # c = 0, then b = 0
        independent = abs(picks[0][1] * picks[1][2] - picks[0][2] * picks[1][1]) > 1e-12
        if all(np.linalg.norm(q) > 1e-9 for q in picks) and independent:
            null = np.array([q / np.linalg.norm(q) for q in picks])
    for v in null:
        a, b, c = v[0], v[1] * scale, v[2] * scale
        if np.hypot(b, c) < 1e-9 * max(abs(a), 1e-300) * 1.0 / scale:
            motions.append("translation along z (the supports hold no deflection)")
            continue
        # rotation about the line a + b x + c y = 0 (words rounded to the plate's size: fea.motions)
        n = np.array([b, c]) / np.hypot(b, c)
        p0 = -a * n / np.hypot(b, c)
        motions.append("rotation about " + rotation_words(np.array([-n[1], n[0]]), p0, scale))
    raise ModelError("the plate is not fully supported: the supports leave free " + "; ".join(motions)
                     + ". Add a support off that line, or clamp an edge.")


def solve_plate(model: Any, mesh_size: QuantityLike | None = None,
                hole_mesh_size: QuantityLike | None = None, in_plane: Any = None, *,
                membrane: str = "auto", in_plane_supports: tuple[Any, ...] = (), refine: float = 1.0,
                span: QuantityLike | None = None) -> FieldResults:
    """Solve a :class:`mechverify.components.plates.PlateModel` for deflection and surface stresses.

    ``mesh_size`` (default: shorter side / 16) and ``hole_mesh_size`` (default: a round hole's radius / 30, at most
    mesh_size / 3: :func:`hole_sizes`) are lengths; ``refine`` divides every element size (a convergence study).
    ``in_plane`` (a :class:`mechverify.fea.plate_buckling.InPlaneLoad`, optional) adds the membrane stress of in-plane
    loads (:func:`mechverify.fea.plate_stress.membrane_stress`, ``membrane`` its method, on the
    :class:`~mechverify.fea.plate_stress.InPlaneSupport` items ``in_plane_supports``) to
    the bending stress: each face carries ``sigma = N/t ± 6 M/t²``. Returns :class:`FieldResults`
    (``kind="plate"``): vertex deflections along z; in ``sigma`` at each vertex the stress tensor of the face with
    the larger von Mises stress (the top face on a tie, so without membrane loads the top face, the bottom being its
    negative); ``extra`` with both faces' von Mises stresses (``von_mises_top_Pa``, ``von_mises_bottom_Pa``), the
    face in ``sigma`` (``face_sign``: +1 top, -1 bottom), the membrane stress ``membrane_{xx,yy,xy}_Pa`` (N/t, zero
    without ``in_plane``), the top face's bending stress ``bending_{xx,yy,xy}_Pa`` (6 M/t²) and the moments.
    The thin-plate test (span / thickness < 10: :func:`thick_plate_warning`) takes ``span`` where given, else the span
    the supports make through the point of largest deflection (:func:`mechverify.fea.plate_span.plate_span`).
    """
    from mechverify.units import to_si

    if _plates is None or not isinstance(model, _plates.PlateModel):
        raise InputError(f"solve_plate: expected a mechverify.components.plates.PlateModel, got {model!r}")
    h = None if mesh_size is None else to_si(mesh_size, "length", "mesh_size")
    hh = None if hole_mesh_size is None else to_si(hole_mesh_size, "length", "hole_mesh_size")
    t0 = time.perf_counter()
    # mesh, stiffness, supports and factorisation depend on the plate, its supports and the mesh sizes only:
    # kept per process and reused while only the loads change (mechverify/fea/factorcache.py)
    cache = factorcache.CACHE
    key = factorcache.key_of("plate", model.plate, tuple(model.supports), h, hh, float(refine))
    item, _ = cache.entry(key)
    try:
        mesh, sys0, K = cache.part(item, "system", lambda: _system(model, h, hh, refine))
        sys_ = copy.copy(sys0)
        sys_.model = model  # this model's loads
        f, total = _load_vector(sys_)
        held = cache.part(item, "supports", lambda: _checked_supports(sys_))
        t_asm = time.perf_counter() - t0
        t1 = time.perf_counter()
        free, Kff, lu = cache.part(item, "factor", lambda: _factorise(K, held))
    except Exception:
        if "factor" not in item:
            cache.forget(key)
        raise
    w = np.zeros(K.shape[0])
    w[free] = lu.solve(f[free])
    res_norm = float(np.linalg.norm(Kff @ w[free] - f[free]) / max(np.linalg.norm(f[free]), 1e-300))
    t_solve = time.perf_counter() - t1
    # reactions: vertical forces at held vertex DOFs
    r = K @ w - f
    vd = sys_.basis.nodal_dofs[0]
    held_mask = np.zeros(K.shape[0], dtype=bool)
    held_mask[held] = True
    reaction = float(r[vd][held_mask[vd]].sum())
    scale = max(abs(total), float(np.abs(f[vd]).sum()))  # balanced loads (total 0): the loads' own size
    if abs(reaction + total) > 1e-6 * max(scale, 1e-12) + 1e-9:
        raise ModelError(f"plate equilibrium not met: reactions {reaction:.6g} N vs loads {total:.6g} N")
    t2 = time.perf_counter()
    sigma_top, moments = _surface_stress(sys_, w)
    bending = np.column_stack([sigma_top[:, 0, 0], sigma_top[:, 1, 1], sigma_top[:, 0, 1]])
    if in_plane is None:
        mem = np.zeros_like(bending)
        mem_notes: tuple[str, ...] = ()
        mem_warns: tuple[str, ...] = ()
    else:
        from mechverify.fea.plate_stress import membrane_stress

        ms = membrane_stress(model.plate, mesh, in_plane, membrane, tuple(in_plane_supports))
        mem, mem_notes, mem_warns = ms.stress, ms.notes, ms.warnings
    faces = _faces(mem, bending)
    t_rec = time.perf_counter() - t2
    n = mesh.nvertices
    pts = np.column_stack([mesh.p.T, np.zeros(n)])
    u = np.zeros((n, 3))
    u[:, 2] = w[vd]

    if span is None and not np.any(u[:, 2]):  # in-plane loads alone: no point of largest deflection
        span_m = min(np.ptp(mesh.p[0]), np.ptp(mesh.p[1]))
    elif span is None:  # the supports' span through the point of largest deflection (review 4 finding 30)
        from mechverify.fea.plate_span import plate_span

        span_m = plate_span(model, mesh.p[:, int(np.argmax(np.abs(u[:, 2])))])[0]
    else:
        span_m = to_si(span, "length", "span")
    if in_plane is None:
        notes = ["Kirchhoff thin-plate bending (Morley triangles); stresses are bending stresses at the surfaces, "
                 "sigma = top surface (z = +t/2), bottom = -top; no in-plane loads, so no membrane stress."]
    else:
        notes = ["Kirchhoff thin-plate bending (Morley triangles) plus the membrane stress of the in-plane loads: "
                 "sigma = N/t +- 6 M/t^2 on the top and bottom faces; sigma = the face with the larger von Mises "
                 "stress at each vertex.", *mem_notes]
    warns = [f"in-plane model: {w}" for w in mem_warns]
    if span_m / sys_.t < 10:
        kinds = {s.condition for s in model.supports}
        warns.append(thick_plate_warning(span_m, sys_.t, model.plate.material.nu.m_as(""),
                                         kinds.pop() if len(kinds) == 1 else "mixed"))
    info = SolveInfo("direct", int(free.size), 0, res_norm, t_solve)
    return FieldResults(
        kind="plate", points=pts, u=u, sigma=faces["sigma"], material=model.plate.material,
        reaction=np.array([0.0, 0.0, reaction]), applied=np.array([0.0, 0.0, total]),
        cells=[("triangle", mesh.t.T.copy())], surface=mesh.t.T.copy(), info=info,
        timings={"assembly": t_asm, "solve": t_solve, "recovery": t_rec},
        extra={"reaction_z_N": np.where(held_mask[vd], r[vd], 0.0),  # vertical reaction per vertex (0 where free)
               "von_mises_top_Pa": faces["top"], "von_mises_bottom_Pa": faces["bottom"],
               "face_sign": faces["sign"],
               "membrane_xx_Pa": mem[:, 0], "membrane_yy_Pa": mem[:, 1], "membrane_xy_Pa": mem[:, 2],
               "bending_xx_Pa": bending[:, 0], "bending_yy_Pa": bending[:, 1], "bending_xy_Pa": bending[:, 2],
               "moment_xx_N": moments[:, 0], "moment_yy_N": moments[:, 1], "moment_xy_N": moments[:, 2]},
        notes=tuple(notes), warnings=tuple(warns))


def _faces(membrane: np.ndarray, bending: np.ndarray) -> dict[str, np.ndarray]:
    """Both faces' von Mises stresses [Pa] (``top``, ``bottom``), ``sign`` (+1 where the top face governs, ties
    included, else -1) and ``sigma[n, 3, 3]`` the governing face's stress tensors: sigma = N/t ± 6 M/t²
    (:func:`mechverify.fea.plate_stress.surface_stresses`)."""
    from mechverify.fea.plate_stress import plane_von_mises, surface_stresses

    top, bottom = surface_stresses(membrane, bending)
    vt, vb = plane_von_mises(top), plane_von_mises(bottom)
    sign = np.where(vt >= vb, 1.0, -1.0)
    c = np.where(sign[:, None] > 0, top, bottom)
    sig = np.zeros((c.shape[0], 3, 3))
    sig[:, 0, 0], sig[:, 1, 1] = c[:, 0], c[:, 1]
    sig[:, 0, 1] = sig[:, 1, 0] = c[:, 2]
    return {"top": vt, "bottom": vb, "sign": sign, "sigma": sig}


def _system(model: Any, h: float | None, hh: float | None, refine: float = 1.0
            ) -> tuple[MeshTri, _PlateSystem, sp.csr_matrix]:
    mesh = plate_mesh(model.plate, h, hh, refine)
    sys_ = _PlateSystem(model, mesh)
    return mesh, sys_, _stiffness(sys_)


def _checked_supports(sys_: _PlateSystem) -> np.ndarray:
    held, held_pts, normals, _ = _supports(sys_)
    check_plate_supported(held_pts, normals)
    return held


def _factorise(K: sp.csr_matrix, held: np.ndarray) -> tuple[np.ndarray, sp.csc_matrix, Any]:
    """The free DOFs, their stiffness and its factorisation (:func:`mechverify.fea.factor.factorize`: CHOLMOD when
    installed, else SuperLU); a stiffness that is not positive definite is a :class:`ModelError`."""
    from mechverify.fea.factor import factorize

    free = np.setdiff1d(np.arange(K.shape[0]), held)
    Kff = K[free][:, free].tocsc()
    try:
        return free, Kff, factorize(Kff, what="the plate stiffness")
    except ModelError as exc:
        raise ModelError(f"{exc}; check the supports") from None


def _surface_stress(sys_: _PlateSystem, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Top-surface stress tensors ``[n, 3, 3]`` and moments ``[n, 3]`` (Mxx, Myy, Mxy per unit width)."""
    m, basis = sys_.mesh, sys_.basis
    hess = basis.interpolate(w).hess  # 2, 2, e, q
    kap = hess.mean(axis=3)  # constant on a Morley element
    kxx, kyy, kxy = kap[0, 0], kap[1, 1], kap[0, 1]
    D, nu = sys_.D, sys_.nu
    Mxx = -D * (kxx + nu * kyy)
    Myy = -D * (kyy + nu * kxx)
    Mxy = -D * (1 - nu) * kxy
    # lumped L2 projection onto P1 = area-weighted averaging at the vertices
    a = m.p[:, m.t]
    area = 0.5 * np.abs((a[0, 1] - a[0, 0]) * (a[1, 2] - a[1, 0]) - (a[0, 2] - a[0, 0]) * (a[1, 1] - a[1, 0]))
    wsum = np.bincount(m.t.ravel(), weights=np.repeat(area[None, :], 3, axis=0).ravel(), minlength=m.nvertices)
    nodal = np.empty((m.nvertices, 3))
    for k, M in enumerate((Mxx, Myy, Mxy)):
        nodal[:, k] = np.bincount(m.t.ravel(), weights=np.repeat((M * area)[None, :], 3, axis=0).ravel(),
                                  minlength=m.nvertices) / wsum
    # sigma = 12 M z / t^3 with M = -D(...) => at z = +t/2: sigma = 6 M / t^2 ... sign: M as defined is
    # the stress resultant ∫ sigma z dz, so sigma(z) = 12 M z / t^3.
    s = 6.0 / sys_.t**2 * nodal
    sig = np.zeros((m.nvertices, 3, 3))
    sig[:, 0, 0], sig[:, 1, 1] = s[:, 0], s[:, 1]
    sig[:, 0, 1] = sig[:, 1, 0] = s[:, 2]
    return sig, nodal


#: Kirchhoff centre deflections of the uniformly loaded square plate [q a⁴ / D]: simply supported 0.00406 (Timoshenko &
#: Woinowsky-Krieger Table 8), clamped 0.00126 (Roark 8th ed. Table 11.4 case 8a: alpha 0.0138 q a⁴/(E t³) =
#: 0.0138 / (12 (1 - 0.3²)) = 0.00126, the value in components/data/roark_plates.toml).
KIRCHHOFF_CENTRE = {"simply_supported": 0.00406, "clamped": 0.00126}
#: The shear deflection at the centre of the square: M / (κ G t) with the simply supported plate's moment sum
#: M = (M_x + M_y) / (1 + ν) = 2 · 0.0479 / 1.3 q a² = 0.0737 q a² (T&WK Table 8).
SHEAR_CENTRE = 0.0737


def mindlin_factor(span: float, t: float, nu: float, edges: str = "simply_supported") -> float:
    """w_Mindlin / w_Kirchhoff at the centre of a uniformly loaded square plate of side ``span`` and thickness ``t``:
    1 + (0.0737 q a² / (κ G t)) / (c q a⁴ / D) = 1 + 0.0737 / c · t² / (6 (1 - ν) κ a²), κ = 5/6, c =
    :data:`KIRCHHOFF_CENTRE` [``edges``]: 1 + 5.19 (t/a)² simply supported, 1 + 16.7 (t/a)² clamped at ν = 0.3.
    Simply supported: the Kirchhoff-Mindlin relationship w_M = w_K + M/(κGt) (Wang, Reddy & Lee, Shear Deformable
    Beams and Plates, 2000, ch. 5 [not seen here]). Clamped: the same shear deflection added to the clamped plate's
    smaller bending deflection - exact for a circular plate (the shear force q r / 2 and so the shear deflection
    q (a² - r²) / (4 κ G t) do not depend on the edge), an estimate for the square: hand calculations, not printed
    values. Review 4 finding 29 measured a clamped 80 x 80 x 16 mm steel plate as a solid: 1.63x Kirchhoff
    (this gives 1.67x); the simply supported 1.21x at a/t = 5 it confirmed."""
    return 1 + SHEAR_CENTRE / KIRCHHOFF_CENTRE[edges] * (t / span) ** 2 / (6 * (1 - nu) * 5 / 6)


def thick_plate_warning(span: float, t: float, nu: float, edges: str = "simply_supported") -> str:
    """The warning of a plate too thick for Kirchhoff theory (span/thickness < 10), with the deflection factor of a
    shear-deformable (Mindlin) plate for its edges (:func:`mindlin_factor`): ``edges`` "simply_supported",
    "clamped" or "mixed" (both factors, as a range). An estimate of the order, not a bound."""
    if edges == "mixed":
        lo, hi = (mindlin_factor(span, t, nu, e) for e in ("simply_supported", "clamped"))
        how = (f"{lo:.3g}x (simply supported) to {hi:.3g}x (clamped) as much (square plate under uniform load; its "
               "supports are of both kinds)")
    else:
        how = (f"{mindlin_factor(span, t, nu, edges):.3g}x as much ({edges.replace('_', ' ')} square plate under "
               "uniform load)")
    return (f"THICK PLATE: span/thickness = {span / t:.3g} < 10, outside the Kirchhoff (thin-plate) model: transverse "
            f"shear deformation is ignored, so deflections are underestimated - a Mindlin plate deflects about "
            f"{how} - and stresses near supports and loads are unreliable; model the part as a solid (type solid_fea) "
            "instead")
