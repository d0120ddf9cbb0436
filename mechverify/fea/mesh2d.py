"""Triangle meshes of flat parts (plates, plane-stress parts) in metres.

- :func:`rectangle` - structured, no mesher needed.
- :func:`polygon` - any shapely polygon with holes (outline, bolt holes, cut-outs), meshed by gmsh
  (an optional GPL extra, imported only here) with the element size graded down towards the holes.
- :func:`from_gmsh_model` - the triangles of a 2D gmsh model with its physical curves (scikit-fem named
  boundaries) and physical points (:attr:`NamedMeshTri.named_points`) for
  :class:`mechverify.fea.regions.Named`.

Triangles are kept counter-clockwise (:func:`tri_mesh`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from skfem import MeshTri
from skfem.mesh import MeshTri1

from mechverify.errors import InputError, ModelError
from mechverify.fea.mesh import contiguous, gmsh_session, import_gmsh, refine_near


def orient_triangles(p: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Counter-clockwise triangles (vertices 1 and 2 swapped where clockwise); degenerate ones rejected."""
    t = np.array(t, dtype=np.int64, copy=True)
    a, b, c = (p[:, t[k]] for k in range(3))
    det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    scale = float(np.max(np.ptp(p, axis=1))) ** 2
    if np.any(np.abs(det) <= 1e-14 * scale):
        raise ModelError("mesh has degenerate (zero-area) triangles")
    neg = det < 0
    t[1, neg], t[2, neg] = t[2, neg].copy(), t[1, neg].copy()
    return t


@dataclass(repr=False)
class NamedMeshTri(MeshTri1):
    """A scikit-fem ``MeshTri`` that also knows named vertex sets (gmsh physical points) and the CAD
    length of its named boundaries (``measures``, m); everything else is scikit-fem's."""

    named_points: dict[str, np.ndarray] = field(default_factory=dict)
    measures: dict[str, float] = field(default_factory=dict)
    curved: np.ndarray | None = None  # [2, n] P2 node coordinates on the geometry (vertices, then edges)


def tri_mesh(p: np.ndarray, t: np.ndarray, like: MeshTri | None = None) -> MeshTri:
    """A scikit-fem ``MeshTri`` that keeps the vertex order of ``t`` (counter-clockwise after
    :func:`orient_triangles`).

    scikit-fem sorts each triangle's vertex indices by default (``sort_t=True``), which turns about half
    of the triangles clockwise: harmless for scikit-fem's own assembly (it uses ``|det J|``), fatal for an
    exported mesh (CalculiX stops on a "nonpositive jacobian"). ``sort_t=False`` keeps the order. The named
    boundaries of ``like`` (``MeshTri.boundaries``: facet index sets) are carried over by their vertices.
    """
    p, t = contiguous(p, t)
    if isinstance(like, NamedMeshTri):
        m: MeshTri = NamedMeshTri(p, t, sort_t=False, named_points=dict(like.named_points),
                                  measures=dict(like.measures), curved=like.curved)
    else:
        m = MeshTri(p, t, sort_t=False)
    if like is not None and like.boundaries:
        m = m.with_boundaries({k: _facets_of(m, like.facets[:, v]) for k, v in like.boundaries.items()})
    return m


def _facets_of(m: MeshTri, pairs: np.ndarray) -> np.ndarray:
    """Facet indices of ``m`` whose vertex pairs are the columns of ``pairs``."""
    n = m.nvertices
    f = np.sort(m.facets, axis=0)
    key = f[0].astype(np.int64) * n + f[1]
    want = np.sort(pairs, axis=0)
    k = want[0].astype(np.int64) * n + want[1]
    return np.flatnonzero(np.isin(key, k))


def rectangle(width: float, height: float, nx: int, ny: int, origin: tuple[float, float] = (0.0, 0.0)) -> MeshTri:
    """Structured triangles on ``[x0, x0 + width] x [y0, y0 + height]`` (SI floats), ``nx x ny`` cells,
    each cut along alternating diagonals (a criss-cross-free "union jack" pattern avoids a preferred
    direction)."""
    if width <= 0 or height <= 0 or nx < 1 or ny < 1:
        raise InputError("rectangle mesh: positive size and at least one cell each way")
    x = np.linspace(origin[0], origin[0] + width, nx + 1)
    y = np.linspace(origin[1], origin[1] + height, ny + 1)
    X, Y = np.meshgrid(x, y, indexing="ij")
    p = np.vstack([X.ravel(), Y.ravel()])
    idx = np.arange((nx + 1) * (ny + 1)).reshape(nx + 1, ny + 1)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    flip = ((np.arange(nx)[:, None] + np.arange(ny)[None, :]) % 2).astype(bool)
    t1 = np.where(flip, np.stack([a, b, d]), np.stack([a, b, c]))
    t2 = np.where(flip, np.stack([b, c, d]), np.stack([a, c, d]))
    t = np.hstack([t1.reshape(3, -1), t2.reshape(3, -1)])
    return tri_mesh(p, orient_triangles(p, t))


def polygon(region: Any, size: float, hole_size: float | None = None,
            ring_sizes: Mapping[int, float] | None = None,
            segment_sizes: Mapping[tuple[int, int], float] | None = None, rim_reach: float = 4.0) -> MeshTri:
    """Mesh a shapely polygon (metres) with element size ``size``, graded to ``hole_size`` (default
    size/3) at the holes and at curved parts of the outline (runs of segments shorter than size/2:
    fillets, arcs). ``ring_sizes`` (interior ring index -> element size) overrides ``hole_size`` at single holes
    (a round hole's rim, graded from its own size: :func:`mechverify.fea.plate.hole_sizes`), and ``segment_sizes``
    (``(interior ring, segment i from vertex i to i + 1) -> size``) single segments of an interior ring (a cut-out's
    rounded corners: :func:`mechverify.fea.plate.mesh_region`); those two grade to ``size`` over ``rim_reach`` times
    ``size`` (the others over 4 ``size``). Straight segments of the polygon are kept as mesh edges."""
    gmsh = import_gmsh()
    if size <= 0:
        raise InputError("mesh size must be positive")
    hole_size = size / 3 if hole_size is None else hole_size
    ring_sizes = dict(ring_sizes or {})
    segment_sizes = dict(segment_sizes or {})
    gmsh_session(gmsh, size)
    gmsh.option.setNumber("Mesh.MeshSizeMin", min(hole_size, size, *ring_sizes.values(), *segment_sizes.values()) / 2)
    try:
        geo = gmsh.model.geo

        def ring(coords: Any) -> tuple[int, list[int]]:
            pts = np.asarray(coords)[:-1]
            tags = [geo.addPoint(float(x), float(y), 0.0) for x, y in pts]
            lines = [geo.addLine(tags[i], tags[(i + 1) % len(tags)]) for i in range(len(tags))]
            return geo.addCurveLoop(lines), lines

        outer, outer_lines = ring(region.exterior.coords)
        inner, hole_lines = [], []
        # (element size, reach, samples per curve) -> curves graded to it; the rims given by ring_sizes and
        # segment_sizes are polygons of sides about their size long (mechverify.fea.plate.mesh_region): RIM_SAMPLING
        by_size: dict[tuple[float, float, int], list[int]] = {}
        reach = rim_reach * size
        for k, interior in enumerate(region.interiors):
            loop, lines = ring(interior.coords)
            inner.append(loop)
            for i, line in enumerate(lines):
                if (k, i) in segment_sizes:
                    by_size.setdefault((float(segment_sizes[(k, i)]), reach, RIM_SAMPLING), []).append(line)
                elif k in ring_sizes:
                    by_size.setdefault((float(ring_sizes[k]), reach, RIM_SAMPLING), []).append(line)
                else:
                    hole_lines.append(line)
        # arcs of the outline (fillets, a hole cut by a symmetry line) come as runs of short segments
        ext = np.asarray(region.exterior.coords)
        seg = np.linalg.norm(np.diff(ext, axis=0), axis=1)
        hole_lines += [line for line, s in zip(outer_lines, seg) if s < size / 2]
        geo.addPlaneSurface([outer, *inner])
        geo.synchronize()
        if hole_lines:
            by_size.setdefault((float(hole_size), 4 * size, 20), []).extend(hole_lines)
        by_size = {sr: lines for sr, lines in by_size.items() if sr[0] < size}
        if len(by_size) == 1:
            ((s, r, n), lines), = by_size.items()
            refine_near(gmsh, "CurvesList", lines, s, size, r, sampling=n)
        elif by_size:
            _graded_min(gmsh, by_size, size)
        if by_size:
            gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.model.mesh.generate(2)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
        index[tags.astype(np.int64)] = np.arange(tags.size)
        _, ntags = gmsh.model.mesh.getElementsByType(2)
        t = index[ntags.astype(np.int64)].reshape(-1, 3).T
    finally:
        gmsh.finalize()
    used = np.unique(t)
    remap = np.full(tags.size, -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    p = coords.reshape(-1, 3).T[:2, used]
    t = remap[t]
    return tri_mesh(p, orient_triangles(p, t))


#: Distance-field sample points per side of a rim meshed at its own size (:func:`polygon`'s ring_sizes and
#: segment_sizes). 5 would halve gmsh's time on many holes (24 holes, 73k triangles: 6.4 -> 3.5 s CPU) but moves the
#: meshes enough to make a three-mesh convergence sequence noisy (holeplate's observed order 1.4 -> 0.33): kept at 20.
RIM_SAMPLING = 20


def _graded_min(gmsh: Any, by_size: Mapping[tuple[float, float, int], list[int]], size: float) -> None:
    """The background size field: the smallest of one :func:`refine_near` grading per (element size, reach, samples
    per curve) (from that size on its curves to ``size`` at ``reach`` from them)."""
    f = gmsh.model.mesh.field
    fields = [refine_near(gmsh, "CurvesList", lines, s, size, reach, sampling=samples, background=False)
              for (s, reach, samples), lines in by_size.items()]
    low = f.add("Min")
    f.setNumbers(low, "FieldsList", fields)
    f.setAsBackgroundMesh(low)


def from_gmsh_model(gmsh: Any) -> NamedMeshTri:
    """The triangles of the current (2D, meshed) gmsh model in its x-y plane, counter-clockwise, with
    its physical curves as named boundaries and its physical points as named vertex sets."""
    from mechverify.fea.mesh import physical_groups

    tags, coords, _ = gmsh.model.mesh.getNodes()
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    tris, mids = [], []
    for ty, npe in ((2, 3), (9, 6)):  # linear or quadratic triangles: the corners (and mid-side nodes)
        _, ntags = gmsh.model.mesh.getElementsByType(ty)
        if ntags.size:
            conn = index[ntags.astype(np.int64)].reshape(-1, npe)
            tris.append(conn[:, :3])
            if npe == 6:
                mids.append(conn[:, 3:])
    if not tris:
        raise ModelError("gmsh produced no triangles (is the geometry a closed surface, meshed in 2D?)")
    t = np.vstack(tris).T
    corners = t.T.copy()
    used = np.unique(t)
    remap = np.full(tags.size, -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    p = coords.reshape(-1, 3).T[:2, used]
    t = remap[t]
    named, measures = physical_groups(gmsh, lambda k: remap[index[k]], (1, 0))
    base = tri_mesh(p, orient_triangles(p, t))
    points = {k: np.unique(v) for k, v in named.items() if v.shape[1] == 1}
    curved = None
    if mids and len(tris) == 1:
        from mechverify.fea.mesh import curved_nodes, gmsh_edge_pairs

        curved = curved_nodes(base, coords.reshape(-1, 3).T, used, corners, mids[0], gmsh_edge_pairs(gmsh, 9))
    m = NamedMeshTri(base.p, base.t, sort_t=False, named_points=points, measures=measures, curved=curved)
    curves = {k: _facets_of(m, v.T) for k, v in named.items() if v.shape[1] == 2}
    return m.with_boundaries(curves) if curves else m
