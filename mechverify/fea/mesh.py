"""Solid meshes: linear tetrahedra (scikit-fem ``MeshTet``) that the solver raises to quadratic (P2).

Builders: :func:`box` (structured, no mesher needed), :func:`cylinder`, :func:`block_with_holes`,
:func:`extruded_polygon` and :func:`from_stl` (gmsh,
an optional GPL extra imported only when called), :func:`from_arrays`. STL files are read and
checked with trimesh (:func:`stl_properties`: watertightness, volume, mass properties).

Named regions (gmsh physical groups of any dimension, or the faces a builder names) are stored as
vertex tuples - facet triples for surfaces, vertex pairs for curves, single vertices for points - so
that :class:`mechverify.fea.regions.Named` can select them; the CAD area or length of each group gmsh
knows is kept in ``SolidMesh.measures`` for the region reports.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np
from skfem import Basis, ElementTetP2, MeshTet

from mechverify.errors import InputError, ModelError, install_hint
from mechverify.fea.gmshstate import restore_step_unit
from mechverify.units import Q, QuantityLike, to_si

GMSH_HINT = "this needs the gmsh mesher, an optional extra (GPL-licensed): " + install_hint("mesh", "gmsh")


def import_gmsh() -> Any:
    """Import gmsh lazily; a clear :class:`ModelError` with the install command when it is missing."""
    try:
        import gmsh
    except (ImportError, OSError) as exc:
        raise ModelError(f"{GMSH_HINT} [{exc}]") from None
    return gmsh


def initialize_gmsh(gmsh: Any) -> None:
    """``gmsh.initialize`` without its side effect on the process: gmsh's C++ start-up sets SIGPIPE back to
    the default action behind Python's back (Python ignores it and raises ``BrokenPipeError`` instead), so a
    later write to a closed pipe (``mechverify check ... | head``, a dead study worker's queue) would kill
    the whole process. Python's own disposition is put back right after."""
    import signal

    gmsh.initialize(interruptible=False)
    if hasattr(signal, "SIGPIPE"):
        try:
            signal.signal(signal.SIGPIPE, signal.getsignal(signal.SIGPIPE) or signal.SIG_IGN)
        except ValueError:  # not the main thread: signal dispositions can only be set there
            pass


def contiguous(p: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points and cells in C order, as scikit-fem wants them (it copies and warns otherwise)."""
    return np.ascontiguousarray(p, dtype=float), np.ascontiguousarray(t)


def orient(p: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Tetrahedra with positive volume (vertices 1 and 2 swapped where negative); degenerate ones rejected."""
    t = np.array(t, dtype=np.int64, copy=True)
    a, b, c, d = (p[:, t[k]] for k in range(4))
    det = np.einsum("ie,ie->e", np.cross(b - a, c - a, axis=0), d - a)
    scale = np.max(np.ptp(p, axis=1)) ** 3
    if np.any(np.abs(det) <= 1e-14 * scale):
        raise ModelError(f"mesh has {int(np.sum(np.abs(det) <= 1e-14 * scale))} degenerate (zero-volume) tetrahedra")
    neg = det < 0
    t[1, neg], t[2, neg] = t[2, neg].copy(), t[1, neg].copy()
    return t


@dataclass(frozen=True, eq=False)
class SolidMesh:
    """A tetrahedral mesh in metres with named boundary regions.

    ``mesh`` is a scikit-fem ``MeshTet`` (linear geometry); the P2 basis and its DOF locations are
    built once on first use (:attr:`basis`).
    """

    mesh: MeshTet
    named: Mapping[str, np.ndarray] = field(default_factory=dict)  # name -> sorted vertex tuples [k, 3|2|1]
    measures: Mapping[str, float] = field(default_factory=dict)  # name -> CAD area [m²] / length [m]
    curved: np.ndarray | None = None  # [3, n] P2 nodes on the CAD geometry (gmsh second order), else None
    volumes: tuple[str, ...] = ()  # names of the volume groups of an imported mesh file (not regions)
    notes: tuple[str, ...] = ()  # what the import did to the geometry (touching solids bonded), for the reports
    slivers_removed: int = 0  # slivers the gmsh reader repaired (:func:`from_gmsh_model`)

    @cached_property
    def basis(self) -> Basis:
        return Basis(self.mesh, ElementTetP2(), intorder=1)

    @cached_property
    def quality(self) -> np.ndarray:
        """Radius ratio of each tetrahedron (:func:`mechverify.fea.meshquality.tet_quality`; 1 regular, 0 flat)."""
        from mechverify.fea.meshquality import tet_quality

        return tet_quality(self.mesh.p, self.mesh.t)

    @property
    def worst_quality(self) -> float:
        """The smallest radius ratio of the mesh's tetrahedra."""
        return float(self.quality.min())

    def sliver_warning(self) -> str | None:
        """A warning naming the slivers (radius ratio below :data:`~mechverify.fea.meshquality.SLIVER_QUALITY`) and
        where the worst is, or None when there are none."""
        from mechverify.fea.meshquality import SLIVER_QUALITY

        bad = np.flatnonzero(self.quality < SLIVER_QUALITY)
        if bad.size == 0:
            return None
        worst = int(bad[np.argmin(self.quality[bad])])
        at = tuple(round(float(c) * 1e3, 3) for c in self.mesh.p[:, self.mesh.t[:, worst]].mean(axis=1))
        what = "sliver tetrahedra" if bad.size > 1 else "sliver tetrahedron"
        return (f"the mesh has {bad.size} {what} (radius ratio below {SLIVER_QUALITY}; the worst "
                f"{self.quality[worst]:.2g} at {at} mm): the stress in them is unreliable and they slow the iterative "
                "solver; remesh (gmsh meshes made by mechverify are repaired when they are read)")

    @property
    def points(self) -> np.ndarray:
        """Coordinates of the P2 nodes (vertices, then edge mid-side nodes) ``[3, n]`` [m]: on the curved
        geometry when the mesh has it (:attr:`curved`), else the straight edge midpoints."""
        return self.basis.doflocs if self.curved is None else self.curved

    @property
    def n_nodes(self) -> int:
        return self.basis.N

    @property
    def n_dofs(self) -> int:
        return 3 * self.basis.N

    @property
    def size(self) -> float:
        """Bounding-box diagonal [m]."""
        return float(np.linalg.norm(np.ptp(self.mesh.p, axis=1)))

    def named_dimension(self, name: str) -> int:
        """2 for a named surface, 1 for a curve, 0 for points."""
        from mechverify.errors import UnknownNameError
        if name not in self.named:
            err = UnknownNameError("mesh region", name, list(self.named))
            names = ", ".join(sorted(self.named))
            if name in self.volumes:
                err.args = (f"mesh region {name!r} is a volume group of the mesh file, not a region: regions are "
                            f"its named surfaces, curves and points ({names or 'none'})",)
            elif not self.named:
                err.args = (f"unknown mesh region {name!r}: the mesh has no named regions (its file carries no "
                            "named groups, as VTK files do not); select the region with Box or Plane",)
            elif not err.suggestions:
                err.args = (f"{err.args[0]} (regions: {names})",)
            raise err
        return int(self.named[name].shape[1]) - 1

    def named_nodes(self, name: str) -> np.ndarray:
        """P2 node indices of a named region: its vertices and the mid-edge nodes of the mesh edges
        whose both ends it holds along its facets or curve segments."""
        dim = self.named_dimension(name)
        want = self.named[name].astype(np.int64)
        verts = np.unique(want)
        if dim == 0:
            return verts
        pairs = want[:, [0, 1]] if dim == 1 else np.vstack([want[:, [0, 1]], want[:, [1, 2]], want[:, [0, 2]]])
        n = self.mesh.nvertices
        e = np.sort(self.mesh.edges.T, axis=1).astype(np.int64)
        pairs = np.sort(pairs, axis=1)
        hit = np.flatnonzero(np.isin(e[:, 0] * n + e[:, 1], pairs[:, 0] * n + pairs[:, 1]))
        return np.concatenate([verts, n + hit])

    def named_facets(self, name: str) -> np.ndarray:
        """Boundary facet indices of the named region (a surface)."""
        if self.named_dimension(name) != 2:
            raise InputError(f"region {name!r} is a {('point set', 'curve')[self.named_dimension(name)]} of the "
                             "mesh; a surface load needs a named surface")
        fac = np.sort(self.mesh.facets.T, axis=1).astype(np.int64)
        want = self.named[name].astype(np.int64)
        n = self.mesh.nvertices
        key_all = (fac[:, 0] * n + fac[:, 1]) * n + fac[:, 2]
        key_want = (want[:, 0] * n + want[:, 1]) * n + want[:, 2]
        return np.flatnonzero(np.isin(key_all, key_want))


def from_arrays(points: Any, tetrahedra: Any, named: Mapping[str, Any] | None = None, unit: str = "m") -> SolidMesh:
    """A mesh from vertex coordinates ``[n, 3]`` (in ``unit``) and tetrahedra ``[e, 4]`` (0-based)."""
    p = np.asarray(points, float).T * Q(1, unit).m_as("m")
    t = np.asarray(tetrahedra, np.int64).T
    if p.shape[0] != 3 or t.shape[0] != 4:
        raise InputError("from_arrays: expected points [n, 3] and tetrahedra [e, 4]")
    if t.min() < 0 or t.max() >= p.shape[1]:
        raise InputError("from_arrays: tetrahedra refer to points that do not exist")
    nm = {k: np.sort(np.asarray(v, np.int64).reshape(len(v), -1), axis=1) for k, v in (named or {}).items()}
    if any(v.shape[1] not in (1, 2, 3) for v in nm.values()):
        raise InputError("from_arrays: named regions are vertex triples (facets), pairs (edges) or single vertices")
    return SolidMesh(MeshTet(*contiguous(p, orient(p, t))), nm)


def box(size: Any, divisions: tuple[int, int, int], origin: Any = ("0 m", "0 m", "0 m")) -> SolidMesh:
    """A structured tetrahedral mesh of a box; faces named ``xmin, xmax, ymin, ymax, zmin, zmax``.

    ``size`` is three lengths, ``divisions`` the number of cells along each (each cell is split into
    tetrahedra by scikit-fem's ``MeshTet.init_tensor``).
    """
    L = [to_si(s, "length", f"size[{i}]") for i, s in enumerate(size)]
    o = [to_si(s, "length", f"origin[{i}]") for i, s in enumerate(origin)]
    if len(L) != 3 or min(L) <= 0:
        raise InputError(f"box: size must be three positive lengths, got {size!r}")
    if len(divisions) != 3 or min(divisions) < 1:
        raise InputError(f"box: divisions must be three positive integers, got {divisions!r}")
    axes = [np.linspace(o[i], o[i] + L[i], int(divisions[i]) + 1) for i in range(3)]
    m = MeshTet.init_tensor(*axes)
    t = orient(m.p, m.t)
    m = MeshTet(*contiguous(m.p, t))
    named = {}
    bf = m.boundary_facets()
    fp = m.p[:, m.facets[:, bf]]  # 3, 3(vertex), k
    tol = 1e-9 * max(L)
    for i, c in enumerate("xyz"):
        for side, val in (("min", o[i]), ("max", o[i] + L[i])):
            on = np.all(np.abs(fp[i] - val) <= tol, axis=0)
            named[f"{c}{side}"] = np.sort(m.facets[:, bf[on]].T, axis=1)
    return SolidMesh(m, named)


def from_gmsh_model(gmsh: Any, repair: bool = True) -> SolidMesh:
    """Read the tetrahedra and named physical surfaces of the current gmsh model (coordinates in metres).

    ``repair`` (default): slivers (radius ratio below :data:`~mechverify.fea.meshquality.SLIVER_QUALITY`) are
    removed by local retriangulation (:func:`~mechverify.fea.meshquality.remove_slivers`; the boundary, the named
    regions and the volume stay as gmsh made them; a few interior vertices may be added). gmsh's thin parts have
    them where the two faces get nearly the same triangulation, and its optimisers leave them (issue 23: one sliver
    held CG at 203 iterations instead of 42 on the benchmark's 6 mm plate). Every gmsh path of this module (the
    builders, STEP and STL import) reads its mesh here."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    coords = coords.reshape(-1, 3).T
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    _, ntags = gmsh.model.mesh.getElementsByType(4)
    mids = None
    if ntags.size == 0:  # second-order mesh: 10-node tetrahedra, corners first
        _, ntags10 = gmsh.model.mesh.getElementsByType(11)
        if ntags10.size == 0:
            raise ModelError("gmsh produced no tetrahedra (is the geometry a closed volume?)")
        conn = index[ntags10.astype(np.int64)].reshape(-1, 10)
        ntags, mids = ntags10.reshape(-1, 10)[:, :4].ravel(), conn[:, 4:]
    t = index[ntags.astype(np.int64)].reshape(-1, 4).T
    used = np.unique(t)
    remap = np.full(tags.size, -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    p = coords[:, used]
    t = remap[t]
    named, measures = physical_groups(gmsh, lambda k: remap[index[k]], (2, 1, 0))
    removed = 0
    if repair:
        from mechverify.fea.meshquality import remove_slivers

        fixed = remove_slivers(p, t, protect=named_edges(named))
        p, t, removed = fixed.p, fixed.t, fixed.removed
    m = MeshTet(*contiguous(p, orient(p, t)))
    curved = None
    if mids is not None:  # edges made by the repair are interior: straight, their mid-side node halfway
        curved = curved_nodes(m, coords, used, index[ntags.astype(np.int64)].reshape(-1, 4), mids,
                              gmsh_edge_pairs(gmsh, 11), straight=removed > 0)
    return SolidMesh(m, named, measures, curved, slivers_removed=removed)


def named_edges(named: Mapping[str, np.ndarray]) -> set[tuple[int, int]]:
    """The vertex pairs (low, high) of the edges of named surfaces (facet triples) and curves (pairs)."""
    out: set[tuple[int, int]] = set()
    for v in named.values():
        if v.shape[1] in (2, 3):
            pairs = v[:, [0, 1]] if v.shape[1] == 2 else np.vstack([v[:, [0, 1]], v[:, [1, 2]], v[:, [0, 2]]])
            pairs = np.sort(pairs, axis=1)
            out.update(zip(pairs[:, 0].tolist(), pairs[:, 1].tolist()))
    return out


def gmsh_edge_pairs(gmsh: Any, etype: int) -> np.ndarray:
    """The corner pair ``[m, 2]`` of each mid-side node of a second-order gmsh element type, from the
    reference coordinates gmsh reports for its nodes (``getElementProperties``)."""
    _, dim, _, nn, local, nv = gmsh.model.mesh.getElementProperties(etype)
    X = np.asarray(local, float).reshape(nn, dim)
    pairs = []
    for k in range(nv, nn):
        for i in range(nv):
            for j in range(i + 1, nv):
                if np.allclose((X[i] + X[j]) / 2, X[k]):
                    pairs.append((i, j))
    if len(pairs) != nn - nv:
        raise ModelError(f"gmsh element type {etype}: not a second-order simplex with mid-side nodes")
    return np.array(pairs)


def curved_nodes(m: MeshTet | Any, coords: np.ndarray, used: np.ndarray, corners: np.ndarray,
                 mids: np.ndarray, pairs: np.ndarray, straight: bool = False) -> np.ndarray:
    """P2 node coordinates ``[d, n]`` of ``m`` (vertices, then scikit-fem's edges - for triangles its
    facets) with each edge's node where gmsh's second-order mesh put it. ``corners[e, nv]`` and
    ``mids[e, m]`` are gmsh's element nodes (indices into ``coords``), ``pairs`` their corner pairs
    (:func:`gmsh_edge_pairs`); ``used`` the gmsh node of each of ``m``'s vertices. ``straight``: an edge gmsh does
    not have (made by a sliver repair, or ending at a vertex it added beyond ``used``) gets its midpoint; else such
    an edge is a :class:`ModelError`."""
    a, b = corners[:, pairs[:, 0]], corners[:, pairs[:, 1]]
    n = coords.shape[1]
    key, first = np.unique((np.minimum(a, b) * n + np.maximum(a, b)).ravel(), return_index=True)
    edges = m.edges if isinstance(m, MeshTet) else m.facets
    known = np.all(edges < used.size, axis=0)
    e = np.sort(used[np.where(known, edges, 0)], axis=0)
    want = e[0] * n + e[1]
    pos = np.minimum(np.searchsorted(key, want), key.size - 1)
    found = known & (key[pos] == want)
    if not np.all(found) and not straight:
        raise ModelError("gmsh's second-order mesh has edges without a mid-side node")
    d = m.p.shape[0]
    mid = coords[:d, mids.ravel()[first][pos]]
    if not np.all(found):
        mid[:, ~found] = (m.p[:, edges[0, ~found]] + m.p[:, edges[1, ~found]]) / 2
    return np.hstack([m.p, mid])


#: Vertices of the linear element of each dimension (point, line, triangle).
_GMSH_LINEAR = {0: 1, 1: 2, 2: 3}


def physical_groups(gmsh: Any, to_vertex: Any, dims: tuple[int, ...]) -> tuple[dict[str, np.ndarray],
                                                                                 dict[str, float]]:
    """Named physical groups of the given dimensions of the current gmsh model: sorted vertex tuples per
    group (``to_vertex`` maps gmsh node tags to mesh vertex indices; high-order nodes are dropped) and the
    CAD measure of each group (OpenCASCADE mass: length or area) where gmsh knows it."""
    named: dict[str, np.ndarray] = {}
    measures: dict[str, float] = {}
    for dim, ptag in gmsh.model.getPhysicalGroups():
        if dim not in dims:
            continue
        name = gmsh.model.getPhysicalName(dim, ptag) or f"{('point', 'curve', 'surface')[dim]}{ptag}"
        nv = _GMSH_LINEAR[dim]
        chunks, total = [], 0.0
        for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, ptag):
            types, _, ent_nodes = gmsh.model.mesh.getElements(dim, ent)
            for ty, nodes in zip(types, ent_nodes):
                npe = gmsh.model.mesh.getElementProperties(int(ty))[3]
                if nodes.size:
                    chunks.append(to_vertex(nodes.astype(np.int64).reshape(-1, npe)[:, :nv]))
            if dim and total == total:  # not NaN yet: a CAD measure for every entity, or none
                try:
                    total += float(gmsh.model.occ.getMass(dim, ent))
                except Exception:  # built-in geo kernel: no CAD measure
                    total = float("nan")
        if chunks:
            named[name] = np.sort(np.vstack(chunks), axis=1)
            if dim and total == total and total > 0:
                measures[name] = total
    return named, measures


def refine_near(gmsh: Any, entities: str, tags: list[int], size_min: float, size_max: float, reach: float,
                sampling: int | None = None, background: bool = True) -> int:
    """Grade the mesh from ``size_min`` on the given curves or surfaces to ``size_max`` at distance ``reach``.

    ``entities`` is ``"CurvesList"`` or ``"SurfacesList"`` (gmsh Distance + Threshold field, set as the background
    mesh unless ``background`` is False: the caller combines several). Returns the Threshold field's tag.
    """
    f = gmsh.model.mesh.field
    dist = f.add("Distance")
    f.setNumbers(dist, entities, tags)
    if sampling is not None:
        f.setNumber(dist, "Sampling", sampling)
    thr = f.add("Threshold")
    f.setNumber(thr, "InField", dist)
    f.setNumber(thr, "SizeMin", size_min)
    f.setNumber(thr, "SizeMax", size_max)
    f.setNumber(thr, "DistMin", 0.0)
    f.setNumber(thr, "DistMax", reach)
    if background:
        f.setAsBackgroundMesh(thr)
    return thr


def second_order(gmsh: Any) -> None:
    """Raise the current gmsh mesh to second order with the new nodes on the CAD geometry (curved
    elements, :mod:`mechverify.fea.isoparametric`). Where that folds an element over (a coarse mesh on a
    tight curve: scaled Jacobian ≤ 0), gmsh's high-order optimiser moves the interior nodes; if elements
    stay inverted, :class:`~mechverify.fea.isoparametric.InvertedElementError` says where."""
    from mechverify.fea.isoparametric import InvertedElementError

    gmsh.model.mesh.setOrder(2)

    def inverted() -> tuple[int, list[float]]:
        bad, where = 0, []
        for etype in (11, 9) if gmsh.model.getDimension() == 3 else (9,):
            tags, nodes = gmsh.model.mesh.getElementsByType(etype)
            if not len(tags) or (etype == 9 and gmsh.model.getDimension() == 3):
                continue
            q = np.asarray(gmsh.model.mesh.getElementQualities(tags, "minSJ"))
            bad += int(np.sum(q <= 0))
            if bad and not where:
                first = int(nodes.reshape(len(tags), -1)[int(np.argmin(q)), 0])
                where = list(gmsh.model.mesh.getNode(first)[0])
        return bad, where

    if inverted()[0]:
        gmsh.model.mesh.optimize("HighOrder")
        bad, where = inverted()
        if bad:
            raise InvertedElementError(
                f"{bad} curved elements stay inverted after gmsh's high-order optimisation, the first near "
                f"{tuple(round(c * 1e3, 3) for c in where)} mm: the mesh is too coarse for the curvature there; "
                "refine it at the curved surface (e.g. hole_mesh_size) or pass curved=False to the mesh builder")


def gmsh_session(gmsh: Any, mesh_size: float) -> None:
    initialize_gmsh(gmsh)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", mesh_size)
    gmsh.option.setNumber("Mesh.MeshSizeMin", mesh_size / 10)
    gmsh.model.add("mechverify")


def cylinder(radius: QuantityLike, length: QuantityLike, mesh_size: QuantityLike, axis: str = "z",
             curved: bool = True) -> SolidMesh:
    """A solid round bar along ``axis`` from 0 to ``length``, meshed by gmsh; ``curved`` (default) puts the
    mid-side nodes on the round surface (isoparametric elements).

    Named regions: ``start`` and ``end`` (the flat ends) and ``side`` (the curved surface).
    """
    gmsh = import_gmsh()
    r, L, h = (to_si(radius, "length", "radius"), to_si(length, "length", "length"),
               to_si(mesh_size, "length", "mesh_size"))
    for name, v in (("radius", r), ("length", L), ("mesh_size", h)):
        if v <= 0:
            raise InputError(f"cylinder: {name} must be positive")
    if axis not in ("x", "y", "z"):
        raise InputError(f"cylinder: axis must be 'x', 'y' or 'z', got {axis!r}")
    d = [0.0, 0.0, 0.0]
    d["xyz".index(axis)] = L
    gmsh_session(gmsh, h)
    try:
        vol = gmsh.model.occ.addCylinder(0, 0, 0, *d, r)
        gmsh.model.occ.synchronize()
        faces = {}
        for _, tag in gmsh.model.getBoundary([(3, vol)], oriented=False):
            com = gmsh.model.occ.getCenterOfMass(2, tag)
            s = com["xyz".index(axis)]
            faces.setdefault("start" if abs(s) < 1e-9 * L else "end" if abs(s - L) < 1e-9 * L else "side",
                             []).append(tag)
        for name, tags in faces.items():
            gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
        gmsh.model.addPhysicalGroup(3, [vol])
        gmsh.model.mesh.generate(3)
        if curved:
            second_order(gmsh)
        return from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def block_with_holes(size: Any, holes: Any = (), mesh_size: QuantityLike = "5 mm",
                     hole_mesh_size: QuantityLike | None = None,
                     curved: bool = True) -> SolidMesh:
    """A rectangular block from the origin to ``size`` (x, y, z lengths) with through-holes along z,
    ``holes`` = [((x, y), diameter), ...] (bolt or pin holes; lengths or strings), meshed by gmsh
    with ``hole_mesh_size`` (default mesh_size / 2) at the holes.

    Named regions: ``xmin, xmax, ymin, ymax, zmin, zmax`` (faces) and ``hole0``, ``hole1``, ... (walls).
    With holes and ``curved`` (default) the mid-side nodes lie on the hole walls (isoparametric elements).
    """
    gmsh = import_gmsh()
    L = [to_si(v, "length", f"size[{i}]") for i, v in enumerate(size)]
    if len(L) != 3 or min(L) <= 0:
        raise InputError(f"block_with_holes: size must be three positive lengths, got {size!r}")
    h = to_si(mesh_size, "length", "mesh_size")
    hh = h / 2 if hole_mesh_size is None else to_si(hole_mesh_size, "length", "hole_mesh_size")
    hs = []
    for i, (center, d) in enumerate(holes):
        cx, cy = (to_si(c, "length", f"holes[{i}].center") for c in center)
        r = to_si(d, "length", f"holes[{i}].diameter") / 2
        if not (r > 0 and r < cx < L[0] - r and r < cy < L[1] - r):
            raise InputError(f"holes[{i}]: a hole of diameter {2 * r * 1e3:g} mm at ({cx * 1e3:g}, {cy * 1e3:g}) mm "
                             "does not fit inside the block")
        hs.append((cx, cy, r))
    gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        vol = occ.addBox(0, 0, 0, *L)
        if hs:
            tools = [(3, occ.addCylinder(cx, cy, -0.1 * L[2], 0, 0, 1.2 * L[2], r)) for cx, cy, r in hs]
            out, _ = occ.cut([(3, vol)], tools)
            vol = out[0][1]
        occ.synchronize()
        groups: dict[str, list[int]] = {}
        for _, tag in gmsh.model.getBoundary([(3, vol)], oriented=False):
            com = occ.getCenterOfMass(2, tag)
            name = None
            for i, c in enumerate("xyz"):
                if abs(com[i]) < 1e-9 * max(L):
                    name = f"{c}min"
                elif abs(com[i] - L[i]) < 1e-9 * max(L):
                    name = f"{c}max"
            if name is None:
                k = int(np.argmin([np.hypot(com[0] - cx, com[1] - cy) for cx, cy, _ in hs]))
                name = f"hole{k}"
            groups.setdefault(name, []).append(tag)
        return _mesh_named_solid(gmsh, vol, groups, h, hh, curved and bool(hs))
    finally:
        gmsh.finalize()


def polygon_corners(pts: list[tuple[float, float]], unit: str = "mm",
                    where: str = "outline") -> list[tuple[float, float]]:
    """The corners ``pts`` [m] of a simple polygon, checked: a last corner equal to the first (a closed outline, as a
    CAD or CSV export and plate_fea's ``outline`` write it) is dropped; a corner equal to the one before it, fewer
    than three corners, crossing edges or no area is an InputError at ``where`` (``outline[4]``), coordinates shown
    in ``unit`` (review 4 finding 17: a closed outline was gmsh's 'Could not create line')."""
    import shapely

    P = np.asarray(pts, float).reshape(-1, 2)
    scale = float(np.max(np.ptp(P, axis=0))) if len(P) else 0.0
    if len(P) > 3 and np.hypot(*(P[-1] - P[0])) <= 1e-9 * scale:
        P = P[:-1]
    f = Q(1, unit).m_as("m")
    for i in range(1, len(P)):
        if np.hypot(*(P[i] - P[i - 1])) <= 1e-9 * scale:
            raise InputError(f"{where}[{i}]: the same corner as {where}[{i - 1}] ({P[i, 0] / f:g}, {P[i, 1] / f:g}) "
                             f"{unit}; give each corner once")
    if len(P) < 3:
        raise InputError(f"{where}: a polygon needs at least three corners, got {len(P)}")
    poly = shapely.Polygon(P / f)
    if not poly.is_valid or poly.area <= 1e-12 * (scale / f) ** 2:
        from shapely.validation import explain_validity

        raise InputError(f"{where}: the corners do not make a simple polygon ({explain_validity(poly)}, in {unit}): "
                         "give them in order around the outline, without crossing edges")
    return [(float(x), float(y)) for x, y in P]


def extruded_polygon(outline: Any, thickness: QuantityLike, mesh_size: QuantityLike = "5 mm", holes: Any = (),
                     hole_mesh_size: QuantityLike | None = None, curved: bool = True) -> SolidMesh:
    """A plate of any outline: the polygon ``outline`` = [(x, y), ...] (three or more corners in order, lengths or
    strings; the last corner joins the first, a closing corner equal to the first is dropped) in the x-y plane,
    extruded along z from 0 to
    ``thickness``, with through-holes along z, ``holes`` = [((x, y), diameter), ...], meshed by gmsh with
    ``hole_mesh_size`` (default mesh_size / 2) at the holes (a bracket, a lug, a gusset from its drawing).

    Named regions: ``zmin`` and ``zmax`` (the flat faces), ``side0``, ``side1``, ... (``side k`` the face on the edge
    from corner k to corner k + 1), ``hole0``, ``hole1``, ... (walls). With holes and ``curved`` (default) the
    mid-side nodes lie on the hole walls (isoparametric elements).

    Raises:
        InputError: fewer than three corners, an outline that crosses itself or encloses no area, a hole that does
            not lie inside the outline, a length that is not positive.
    """
    import shapely

    gmsh = import_gmsh()
    pts = []
    for i, c in enumerate(outline):
        if isinstance(c, str) or len(c) != 2:
            raise InputError(f"outline[{i}]: expected a corner (x, y), got {c!r}")
        pts.append(tuple(to_si(v, "length", f"outline[{i}]") for v in c))
    pts = polygon_corners(pts)
    poly = shapely.Polygon(pts)
    scale = max(np.ptp(np.asarray(pts), axis=0))
    T = to_si(thickness, "length", "thickness")
    h = to_si(mesh_size, "length", "mesh_size")
    for name, v in (("thickness", T), ("mesh_size", h)):
        if not v > 0:
            raise InputError(f"extruded_polygon: {name} must be positive")
    hh = h / 2 if hole_mesh_size is None else to_si(hole_mesh_size, "length", "hole_mesh_size")
    hs = []
    for i, (center, d) in enumerate(holes):
        cx, cy = (to_si(c, "length", f"holes[{i}].center") for c in center)
        r = to_si(d, "length", f"holes[{i}].diameter") / 2
        if not (r > 0 and poly.contains(shapely.Point(cx, cy).buffer(r * (1 + 1e-6)))):
            raise InputError(f"holes[{i}]: a hole of diameter {2 * r * 1e3:g} mm at ({cx * 1e3:g}, {cy * 1e3:g}) mm "
                             "does not lie inside the outline")
        hs.append((cx, cy, r))
    for i, (cx, cy, r) in enumerate(hs):
        for j, (cx2, cy2, r2) in enumerate(hs[:i]):
            if np.hypot(cx - cx2, cy - cy2) <= r + r2:
                raise InputError(f"holes[{i}]: overlaps holes[{j}]")
    gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        corners = [occ.addPoint(x, y, 0.0) for x, y in pts]
        lines = [occ.addLine(corners[k], corners[(k + 1) % len(corners)]) for k in range(len(corners))]
        face = occ.addPlaneSurface([occ.addCurveLoop(lines)])
        vol = next(tag for dim, tag in occ.extrude([(2, face)], 0, 0, T) if dim == 3)
        if hs:
            tools = [(3, occ.addCylinder(cx, cy, -0.1 * T, 0, 0, 1.2 * T, r)) for cx, cy, r in hs]
            out, _ = occ.cut([(3, vol)], tools)
            vol = out[0][1]
        occ.synchronize()
        segments = [shapely.LineString([pts[k], pts[(k + 1) % len(pts)]]) for k in range(len(pts))]
        groups: dict[str, list[int]] = {}
        for _, tag in gmsh.model.getBoundary([(3, vol)], oriented=False):
            com = occ.getCenterOfMass(2, tag)
            if abs(com[2]) < 1e-9 * scale or abs(com[2] - T) < 1e-9 * scale:
                name = "zmin" if abs(com[2]) < 1e-9 * scale else "zmax"
            else:  # a side's centre lies on its edge, a hole wall's on the hole's axis
                at = shapely.Point(com[0], com[1])
                ds = [s.distance(at) for s in segments]
                dh = [np.hypot(com[0] - cx, com[1] - cy) for cx, cy, _ in hs]
                k = int(np.argmin(ds))
                name = f"side{k}" if not dh or ds[k] <= min(dh) else f"hole{int(np.argmin(dh))}"
            groups.setdefault(name, []).append(tag)
        return _mesh_named_solid(gmsh, vol, groups, h, hh, curved and bool(hs))
    finally:
        gmsh.finalize()


def bond_solids(gmsh: Any, vols: list[int]) -> tuple[list[int], dict[int, list[int]]]:
    """Fragment the solids ``vols`` of the current OpenCASCADE model (touching solids then share their common faces)
    and keep the face ids the file had: returns the volumes and, per original face id, the gmsh surfaces that are
    (parts of) it now. A surface is matched to the original faces of the same type whose bounding box holds its
    own, the tightest first (a face two solids shared gets both ids); one no original face holds (an intersection
    of overlapping solids) gets a new id after the largest."""
    occ = gmsh.model.occ
    scale = max(abs(c) for c in occ.getBoundingBox(3, vols[0])) or 1.0
    before = {tag: (gmsh.model.getType(2, tag), np.asarray(occ.getBoundingBox(2, tag)))
              for _, tag in gmsh.model.getEntities(2)}
    occ.fragment([(3, vols[0])], [(3, v) for v in vols[1:]])
    occ.synchronize()
    tol = 1e-7 * scale
    faces: dict[int, list[int]] = {}
    extra = max(before, default=0)
    for _, tag in gmsh.model.getEntities(2):
        kind, bb = gmsh.model.getType(2, tag), np.asarray(occ.getBoundingBox(2, tag))
        fits = [(float(np.sum(b[3:] - b[:3])), k) for k, (t, b) in before.items()
                if t == kind and np.all(b[:3] <= bb[:3] + tol) and np.all(bb[3:] <= b[3:] + tol)]
        if not fits:
            extra += 1
            faces[extra] = [tag]
            continue
        tight = min(f for f, _ in fits)
        for f, k in fits:
            if f <= tight + tol:
                faces.setdefault(k, []).append(tag)
    return [t for _, t in gmsh.model.getEntities(3)], faces


def _mesh_named_solid(gmsh: Any, vol: int, groups: Mapping[str, list[int]], h: float, hh: float,
                      curved: bool) -> SolidMesh:
    """Mesh the volume ``vol`` whose boundary faces are named by ``groups`` (name -> gmsh surface tags): the hole
    walls (``hole<k>``) refined to ``hh`` within 3 h, quadratic elements put on the curved faces when ``curved``."""
    for name, tags in groups.items():
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
    gmsh.model.addPhysicalGroup(3, [vol])
    hole_faces = [t for n, tags in groups.items() if n.startswith("hole") for t in tags]
    if hole_faces and hh < h:
        refine_near(gmsh, "SurfacesList", hole_faces, hh, h, 3 * h)
        gmsh.option.setNumber("Mesh.MeshSizeMin", hh / 2)
    gmsh.model.mesh.generate(3)
    if curved:
        second_order(gmsh)
    return from_gmsh_model(gmsh)


@contextmanager
def step_model(path: str | Path) -> Iterator[tuple[Any, list[int]]]:
    """gmsh (quiet) with the solids of the STEP file ``path`` read (:func:`import_step_solids`), yielded with their
    volume tags; afterwards OpenCASCADE's STEP unit is restored and gmsh finalised. A missing file is an
    :class:`InputError`."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"STEP file {str(path)!r} does not exist")
    gmsh = import_gmsh()
    initialize_gmsh(gmsh)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("step")
        yield gmsh, import_step_solids(gmsh, path)
    finally:
        restore_step_unit(gmsh)  # the unit is OpenCASCADE's, kept past finalize (fea.gmshstate)
        gmsh.finalize()


def import_step_solids(gmsh: Any, path: Path) -> list[int]:
    """Read the STEP file ``path`` into gmsh's current model, lengths in metres (OpenCASCADE's target unit: the
    caller restores it with :func:`mechverify.fea.gmshstate.restore_step_unit`), and return the volume tags.
    A file gmsh cannot read, or one that holds no solid, is a :class:`ModelError` naming the file."""
    gmsh.option.setString("Geometry.OCCTargetUnit", "M")
    try:
        ents = gmsh.model.occ.importShapes(str(path))
    except Exception as exc:  # gmsh raises a bare Exception with its log message
        raise ModelError(f"{path.name}: gmsh could not read the STEP file ({exc})") from None
    gmsh.model.occ.synchronize()
    vols = [t for d, t in ents if d == 3]
    if not vols:
        raise ModelError(f"{path.name}: the STEP file holds no solid (only surfaces or curves)")
    return vols


def from_step(path: str | Path, mesh_size: QuantityLike, unit: str = "mm", curved: bool = True) -> SolidMesh:
    """Tetrahedral mesh of the solid(s) in a STEP file (gmsh/OpenCASCADE); ``unit`` is the unit the
    file's lengths are in when it declares none (CAD exports are usually mm). Each CAD face becomes a
    named region ``face<k>`` (gmsh's face tag). ``curved`` (default) puts the mid-side nodes on the CAD
    faces where any face is not a plane (isoparametric elements).

    Several solids (a CAD assembly exported as one file) are **bonded** where they touch: OpenCASCADE's fragment
    (``occ.fragment``) makes their common faces one, so the mesh is conforming there and the parts act as glued
    (review 3 finding 11: meshed apart, an unsupported part floated; "equilibrium not met" or rigid-body modes
    reported as natural frequencies). ``SolidMesh.notes`` says so; a solid that touches none of the others stays a
    separate body, which :class:`~mechverify.fea.solid.SolidModel` refuses unless it is supported."""
    gmsh = import_gmsh()
    path = Path(path)
    if not path.exists():
        raise InputError(f"STEP file {str(path)!r} does not exist")
    h = to_si(mesh_size, "length", "mesh_size")
    gmsh_session(gmsh, h)
    try:
        vols = import_step_solids(gmsh, path)
        notes: tuple[str, ...] = ()
        faces = {tag: [tag] for _, tag in gmsh.model.getEntities(2)}  # face id -> gmsh surfaces
        if len(vols) > 1:  # an assembly: bond the solids where they touch (shared faces, a conforming mesh)
            solids = len(vols)
            vols, faces = bond_solids(gmsh, vols)
            notes = (f"{path.name} holds {solids} solids: they are bonded where "
                     "they touch (OpenCASCADE fragment: common faces shared, one conforming mesh; a glued assembly, "
                     "no contact or sliding)",)
        for k, tags in sorted(faces.items()):
            gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), f"face{k}")
        gmsh.model.addPhysicalGroup(3, vols)
        gmsh.model.mesh.generate(3)
        if curved and any(gmsh.model.getType(2, tag) != "Plane" for _, tag in gmsh.model.getEntities(2)):
            second_order(gmsh)
        out = from_gmsh_model(gmsh)
        return replace(out, notes=notes) if notes else out
    finally:
        restore_step_unit(gmsh)  # the unit is OpenCASCADE's, kept past finalize: later sessions read/wrote metres
        gmsh.finalize()


@dataclass(frozen=True)
class StlProperties:
    """What trimesh reports about a closed STL surface (SI)."""

    watertight: bool
    volume: Any  # m^3
    area: Any  # m^2
    centroid: Any  # m [3]
    mass: Any | None  # kg, when a density was given
    inertia: Any | None  # kg m^2 [3, 3] about the centroid, when a density was given


def stl_properties(path: str | Path, unit: str = "mm", density: QuantityLike | None = None) -> StlProperties:
    """Load an STL with trimesh and report watertightness and mass properties.

    ``unit`` is the length unit the file's coordinates are in (STL carries none; CAD exports mm).
    """
    import trimesh

    path = Path(path)
    if not path.exists():
        raise InputError(f"STL file {str(path)!r} does not exist")
    if path.suffix.lower() != ".stl":  # trimesh reads by the name's ending: base.toml was a NotImplementedError
        raise InputError(f"{path.name}: not an STL file (the name ends in {path.suffix or 'nothing'!r}, not '.stl')")
    with np.errstate(all="ignore"):  # an empty file: trimesh divides by its zero area
        try:
            tm = trimesh.load(path, force="mesh")
        except Exception as exc:  # trimesh's own errors (its parsers raise what they meet): named, with its reason
            raise InputError(f"{path.name}: trimesh cannot read it as an STL file ({type(exc).__name__}: "
                             f"{exc})") from None
    if len(getattr(tm, "faces", ())) == 0:
        raise InputError(f"{path.name}: no triangles read (not an STL file, or an empty one)")
    s = Q(1, unit).m_as("m")
    tm.apply_scale(s)
    rho = to_si(density, "density", "density") if density is not None else None
    mass = inertia = None
    if rho is not None:
        if not tm.is_watertight:
            raise ModelError(f"{path.name}: the surface is not watertight, so it encloses no volume to weigh")
        tm.density = rho
        mass = Q(tm.mass, "kg")
        inertia = Q(tm.moment_inertia, "kg*m**2")
    return StlProperties(bool(tm.is_watertight), Q(abs(tm.volume), "m**3"), Q(tm.area, "m**2"),
                         Q(np.asarray(tm.center_mass), "m"), mass, inertia)


#: Dihedral angle [deg] above which two STL triangles lie on different faces (gmsh ``classifySurfaces``; tutorial t13).
STL_FACE_ANGLE = 40.0


def from_stl(path: str | Path, mesh_size: QuantityLike, unit: str = "mm") -> SolidMesh:
    """Tetrahedral mesh of the volume inside a watertight STL surface (trimesh check, gmsh mesh).

    The surface is remeshed at ``mesh_size``: gmsh splits the triangles into faces where neighbours meet at more than
    :data:`STL_FACE_ANGLE` degrees (``classifySurfaces`` with the boundary curves, then ``createGeometry``: a
    reparametrised discrete surface per face, gmsh tutorial t13) and meshes those faces and the volume anew. A CAD
    export keeps few, long triangles (a box is 12): kept as the boundary mesh they made a 300 mm cantilever 30-50 %
    too stiff and its root stress half the beam-theory value (review 3 finding 1). The geometry stays the STL's
    facets (a round bar is the polygon the file has); the mesh is straight-sided.

    Named regions: ``face1``, ``face2``, ... (the classified faces, in gmsh's order) and ``surface`` (all of them).
    A surface gmsh cannot classify or remesh is a :class:`ModelError` (nothing is meshed on the raw triangles).
    """
    import math

    props = stl_properties(path, unit)
    if not props.watertight:
        raise ModelError(f"{Path(path).name}: the STL surface is not watertight (holes or non-manifold edges); "
                         "repair it in CAD before meshing")
    import trimesh

    gmsh = import_gmsh()
    h = to_si(mesh_size, "length", "mesh_size")
    tm = trimesh.load(Path(path), force="mesh")
    tm.apply_scale(Q(1, unit).m_as("m"))
    tm.merge_vertices()
    gmsh_session(gmsh, h)
    try:
        surf = gmsh.model.addDiscreteEntity(2)
        ntags = np.arange(1, len(tm.vertices) + 1)
        gmsh.model.mesh.addNodes(2, surf, ntags, np.asarray(tm.vertices, float).ravel())
        gmsh.model.mesh.addElementsByType(surf, 2, [], (np.asarray(tm.faces, np.int64) + 1).ravel())
        try:
            gmsh.model.mesh.classifySurfaces(math.radians(STL_FACE_ANGLE), True, True, math.pi)
            gmsh.model.mesh.createGeometry()
            faces = [t for _, t in gmsh.model.getEntities(2)]
            loop = gmsh.model.geo.addSurfaceLoop(faces)
            vol = gmsh.model.geo.addVolume([loop])
            gmsh.model.geo.synchronize()
            for k, tag in enumerate(faces, 1):
                gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [tag]), f"face{k}")
            gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, faces), "surface")
            gmsh.model.addPhysicalGroup(3, [vol])
            gmsh.model.mesh.generate(3)
        except Exception as exc:  # gmsh raises a bare Exception with its log message
            raise ModelError(f"{Path(path).name}: gmsh could not remesh the STL surface at mesh_size "
                             f"{h * 1e3:g} mm ({exc}); export the part as STEP, or repair the STL") from None
        out = from_gmsh_model(gmsh)
        if out.mesh.nelements == 0:
            raise ModelError(f"{Path(path).name}: gmsh made no tetrahedra inside the remeshed STL surface")
        return out
    finally:
        gmsh.finalize()
