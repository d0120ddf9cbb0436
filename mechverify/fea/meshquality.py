"""Tetrahedron quality and the removal of slivers from a tetrahedral mesh.

- :func:`tet_quality` - the radius ratio ``3 r_in / R_circ`` of each tetrahedron (1 for the regular one, 0 for a
  flat one; ref. 1).
- :func:`remove_slivers` - local repairs of the tetrahedra below :data:`SLIVER_QUALITY`: edge removal (ref. 2) or a
  vertex inserted where a flat tetrahedron's two crossing edges pass each other. The boundary triangles, the
  volume and every vertex stay as they were; only interior tetrahedra change (and a few interior vertices are
  added).

Why: a sliver (four nearly coplanar vertices) makes the stiffness matrix ill-conditioned (ref. 1). On the FEA
benchmark's 6 mm plate with a hole at 66 942 DOF a single sliver of quality 2.3e-4 held multigrid CG at 203
iterations against 42 once it was removed (37k and 181k meshes: 43 and 30). gmsh's thin parts produce them where
the top and bottom faces get almost the same triangulation: a tetrahedron spans the thickness across a vertical
quadrilateral whose two diagonals both became edges. gmsh's own and Netgen's optimisers (``Mesh.Optimize``,
``Mesh.OptimizeNetgen``, ``optimize("Netgen")``) left that sliver in place (they cannot move the four boundary
vertices, and the neighbouring tetrahedra repeat the pattern, so an edge flip only moves the flat tetrahedron on);
the HXT mesher (``Mesh.Algorithm3D = 10``) avoided it but produced a zero-volume tetrahedron on another size.

References
----------
1. J. R. Shewchuk, "What is a good linear finite element? Interpolation, conditioning, anisotropy, and quality
   measures", 2002 (radius ratio; the stiffness matrix's condition number and the worst element).
2. J. R. Shewchuk, "Two discrete optimization algorithms for the topological improvement of tetrahedral
   meshes", 2002 (edge removal: the tetrahedra around an edge replaced by a triangulation of its ring).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache

import numpy as np

#: Tetrahedra below this radius ratio are slivers: :func:`remove_slivers` repairs them, and a solve on a mesh that
#: still has one warns. On the 66 942-DOF plate, removing those below 0.02 left a worst quality of 0.022 and 51 CG
#: iterations, below 0.05 a worst of 0.115 and 42 iterations (its neighbours 37k and 181k: worst 0.17 and 0.25).
SLIVER_QUALITY = 0.05
#: The largest ring of tetrahedra around an edge that edge removal retriangulates (7: 42 triangulations).
MAX_RING = 7


def tet_quality(p: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Radius ratio ``3 r_in / R_circ`` [-] of each tetrahedron ``t[4, e]`` of the vertices ``p[3, n]`` (ref. 1):
    1 for the regular tetrahedron, 0 for a flat one; ``r_in = 3 V / S`` (S the four faces' area),
    ``R_circ = sqrt(s (s - a) (s - b) (s - c)) / (6 V)`` with a, b, c the products of opposite edge lengths and
    s their half sum (Crelle's formula)."""
    a, b, c, d = (p[:, t[k]] for k in range(4))
    vol = np.abs(np.einsum("ie,ie->e", np.cross(b - a, c - a, axis=0), d - a)) / 6

    def area(x: np.ndarray, y: np.ndarray, z: np.ndarray) -> np.ndarray:
        return 0.5 * np.linalg.norm(np.cross(y - x, z - x, axis=0), axis=0)

    surface = area(b, c, d) + area(a, c, d) + area(a, b, d) + area(a, b, c)
    length = lambda x, y: np.linalg.norm(y - x, axis=0)  # noqa: E731
    pa, pb, pc = length(a, b) * length(c, d), length(a, c) * length(b, d), length(a, d) * length(b, c)
    s = (pa + pb + pc) / 2
    six_v_r = np.sqrt(np.maximum(s * (s - pa) * (s - pb) * (s - pc), 0.0))  # 6 V R_circ
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((six_v_r > 0) & (surface > 0), 3 * (3 * vol / surface) * 6 * vol / six_v_r, 0.0)


@dataclass(frozen=True)
class SliverRepair:
    """What :func:`remove_slivers` did: the new vertices ``p[3, n']`` (the old ones first, unchanged) and
    tetrahedra ``t[4, e']``, how many slivers it ``removed``, how many tetrahedra stay below the threshold
    (``left``), and the worst quality before and after."""

    p: np.ndarray
    t: np.ndarray
    removed: int
    left: int
    worst_before: float
    worst_after: float


@cache
def _triangulations(m: int) -> tuple[tuple[tuple[int, int, int], ...], ...]:
    """All triangulations of the polygon 0, 1, ..., m-1 (as index triples)."""

    def tri(i: int, j: int) -> list[tuple[tuple[int, int, int], ...]]:
        if j - i < 2:
            return [()]
        return [left + ((i, k, j),) + right for k in range(i + 1, j) for left in tri(i, k) for right in tri(k, j)]

    return tuple(tri(0, m - 1))


def _closest(p0: np.ndarray, p1: np.ndarray, q0: np.ndarray, q1: np.ndarray) -> tuple[float, float] | None:
    """Parameters (s, t) of the closest points ``p0 + s (p1 - p0)`` and ``q0 + t (q1 - q0)`` of two lines."""
    u, v, w = p1 - p0, q1 - q0, p0 - q0
    a, b, c, d, e = u @ u, u @ v, v @ v, u @ w, v @ w
    den = a * c - b * b
    if den <= 1e-12 * a * c:
        return None  # parallel
    return (b * e - c * d) / den, (a * e - b * d) / den


def remove_slivers(p: np.ndarray, t: np.ndarray, protect: Iterable[tuple[int, int]] = (),
                   threshold: float = SLIVER_QUALITY) -> SliverRepair:
    """Repair the tetrahedra ``t[4, e]`` (vertices ``p[3, n]``) whose :func:`tet_quality` is below ``threshold``,
    worst first. For each, the better of two local changes is taken when it raises the worst quality of the
    tetrahedra it replaces:

    - edge removal (ref. 2): the tetrahedra around one of the sliver's edges (an interior edge, at most
      :data:`MAX_RING` of them) are replaced by the best triangulation of the edge's ring joined to its two ends;
    - vertex insertion: a flat sliver's two crossing edges (each point of closest approach inside both) pass each
      other near a point X; the tetrahedra around both edges are replaced by X joined to the boundary triangles
      of their union.

    Each change keeps the boundary of the region it replaces (so the mesh's boundary and its named faces), is
    checked to fill the same volume with consistently oriented tetrahedra, and never touches an edge in
    ``protect`` (vertex pairs, e.g. the edges of named surfaces that might lie inside the volume). Boundary edges
    are never removed (their ring is open)."""
    t = np.asarray(t, dtype=np.int64)
    q = tet_quality(p, t)
    worst = float(q.min()) if q.size else 1.0
    bad = np.flatnonzero(q < threshold)
    if bad.size == 0:
        return SliverRepair(p, t, 0, 0, worst, worst)
    nv = p.shape[1]
    flat = t.T.ravel()
    order = np.argsort(flat, kind="stable")
    ptr = np.r_[0, np.cumsum(np.bincount(flat, minlength=nv))]
    tets = [tuple(int(v) for v in col) for col in t.T]  # grows with the new tetrahedra
    alive = [True] * len(tets)
    quality = [float(x) for x in q]
    added: dict[int, list[int]] = {}  # vertex -> new tetrahedra holding it
    new_points: list[np.ndarray] = []
    keep = {(min(a, b), max(a, b)) for a, b in protect}

    def point(v: int) -> np.ndarray:
        return p[:, v] if v < nv else new_points[v - nv]

    def around(v: int) -> list[int]:
        old = [int(e) // 4 for e in order[ptr[v]:ptr[v + 1]]] if v < nv else []
        return [e for e in (*old, *added.get(v, ())) if alive[e]]

    def ring(a: int, b: int) -> tuple[list[int], list[int]] | None:
        """The tetrahedra around the edge (a, b) and its ring of vertices in order; None for a boundary edge."""
        ts = [e for e in around(a) if b in tets[e]]
        if not 3 <= len(ts) <= MAX_RING:
            return None
        nxt: dict[int, list[int]] = {}
        for e in ts:
            c, d = (v for v in tets[e] if v != a and v != b)
            nxt.setdefault(c, []).append(d)
            nxt.setdefault(d, []).append(c)
        if any(len(v) != 2 for v in nxt.values()):
            return None  # an open ring: the edge lies on the boundary
        cycle, prev = [next(iter(nxt))], -1
        while True:
            cur = cycle[-1]
            step = nxt[cur][0] if nxt[cur][0] != prev else nxt[cur][1]
            if step == cycle[0]:
                break
            cycle.append(step)
            prev = cur
        return (ts, cycle) if len(cycle) == len(ts) else None

    def coords(rows: np.ndarray, x: np.ndarray | None = None) -> np.ndarray:
        """``[3, k, 4]`` coordinates of tetrahedra ``rows[k, 4]``; vertex -1 is the point ``x``."""
        return np.stack([np.column_stack([point(v) if v >= 0 else x for v in row]) for row in rows], axis=1)

    def signed(rows: np.ndarray, x: np.ndarray | None = None) -> np.ndarray:
        X = coords(rows, x)
        a, b, c, d = X[:, :, 0], X[:, :, 1], X[:, :, 2], X[:, :, 3]
        return np.einsum("ie,ie->e", np.cross(b - a, c - a, axis=0), d - a) / 6

    def quality_of(rows: np.ndarray, x: np.ndarray | None = None) -> np.ndarray:
        X = coords(rows, x)
        return tet_quality(X.reshape(3, -1), np.arange(4 * len(rows)).reshape(-1, 4).T)

    def volume(ts: Iterable[int]) -> float:
        return float(np.abs(signed(np.array([tets[e] for e in ts]))).sum())

    Candidate = tuple[float, list[int], np.ndarray, np.ndarray, np.ndarray | None]

    def edge_removal(s: int) -> Candidate | None:
        best: Candidate | None = None
        for i, j in itertools.combinations(range(4), 2):
            a, b = tets[s][i], tets[s][j]
            r = None if (min(a, b), max(a, b)) in keep else ring(a, b)
            if r is None:
                continue
            ts, cycle = r
            old_q, old_vol = min(quality[e] for e in ts), volume(ts)
            cyc = np.array(cycle)
            for tri in _triangulations(len(cycle)):
                faces = cyc[np.array(tri)]
                k = len(faces)
                cand = np.vstack([np.c_[np.full(k, a), faces], np.c_[np.full(k, b), faces]])
                vol = signed(cand)
                sa = np.sign(vol[0])
                if not (sa != 0 and np.all(np.sign(vol[:k]) == sa) and np.all(np.sign(vol[k:]) == -sa)):
                    continue
                if abs(np.abs(vol).sum() - old_vol) > 1e-9 * old_vol:
                    continue
                nq = quality_of(cand)
                if nq.min() > old_q and (best is None or nq.min() > best[0]):
                    best = (float(nq.min()), ts, cand, nq, None)
        return best

    def insertion(s: int) -> Candidate | None:
        best: Candidate | None = None
        T = tets[s]
        for (i, j), (k, m) in (((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2))):
            e1, e2 = (T[i], T[j]), (T[k], T[m])
            if any((min(e), max(e)) in keep for e in (e1, e2)):
                continue
            c = _closest(point(e1[0]), point(e1[1]), point(e2[0]), point(e2[1]))
            if c is None or not (0.05 < c[0] < 0.95 and 0.05 < c[1] < 0.95):
                continue  # the edges do not cross
            r1, r2 = ring(*e1), ring(*e2)
            if r1 is None or r2 is None:
                continue
            cavity = sorted(set(r1[0]) | set(r2[0]))
            p0, q0 = point(e1[0]), point(e2[0])
            x = 0.5 * (p0 + c[0] * (point(e1[1]) - p0) + q0 + c[1] * (point(e2[1]) - q0))
            faces: dict[tuple[int, ...], list[int]] = {}
            for e in cavity:
                tt = tets[e]
                for o in range(4):
                    faces.setdefault(tuple(sorted(tt[:o] + tt[o + 1:])), []).append(tt[o])
            rows = np.array([[v[0], *f] for f, v in faces.items() if len(v) == 1])  # opposite vertex, boundary face
            cand = rows.copy()
            cand[:, 0] = -1
            vol = signed(cand, x)
            if np.any(np.sign(vol) != np.sign(signed(rows))) or np.any(vol == 0):
                continue  # x does not see every boundary face from inside
            old_vol = volume(cavity)
            if abs(np.abs(vol).sum() - old_vol) > 1e-9 * old_vol:
                continue
            nq = quality_of(cand, x)
            if nq.min() > min(quality[e] for e in cavity) and (best is None or nq.min() > best[0]):
                best = (float(nq.min()), cavity, cand, nq, x)
        return best

    removed = 0
    for s in bad[np.argsort(q[bad], kind="stable")]:
        if not alive[s]:
            continue
        options = [c for c in (edge_removal(int(s)), insertion(int(s))) if c is not None]
        if not options:
            continue
        _, ts, cand, nq, x = max(options, key=lambda c: c[0])
        if x is not None:
            new_points.append(x)
            cand = np.where(cand < 0, nv + len(new_points) - 1, cand)
        for e in ts:
            alive[e] = False
        for row, qq in zip(cand, nq):
            e = len(tets)
            tets.append(tuple(int(v) for v in row))
            alive.append(True)
            quality.append(float(qq))
            for v in row:
                added.setdefault(int(v), []).append(e)
        removed += 1
    out = np.array([tt for tt, ok in zip(tets, alive) if ok], dtype=np.int64).T
    q_out = np.array(quality)[np.array(alive)]
    if new_points:
        p = np.hstack([p, np.column_stack(new_points)])
    return SliverRepair(p, out, removed, int(np.sum(q_out < threshold)), worst, float(q_out.min()))
