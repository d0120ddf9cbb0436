"""Linear static analysis of 3D solids with quadratic tetrahedra (P2, 10 nodes).

    >>> from mechverify.fea import mesh, solid
    >>> from mechverify.fea.regions import Plane
    >>> from mechverify.fea.loads import Fixed, Force
    >>> m = mesh.box(("100 mm", "10 mm", "10 mm"), (10, 2, 2))
    >>> model = solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),),
    ...                          loads=(Force(Plane(x="100 mm"), ("0 N", "0 N", "-100 N")),))
    >>> res = model.solve()

Loads and supports are declared on regions (:mod:`mechverify.fea.regions`); a model the supports
leave free to move raises :class:`ModelError` naming the free motion. A :class:`~mechverify.fea.loads.PinSupport` on a
hole wall holds it radially and leaves it free to turn (a frictionless, bilateral pin; :mod:`mechverify.fea.pins`): the
wall's DOFs are then solved in their own radial, tangential and axial axes (``dof_basis``), ``u`` returned in x, y, z.
The reactions are checked to
balance the applied loads (forces and moments) before results are returned. Each load and support
reports what its region caught (:meth:`SolidModel.region_reports`, ``FieldResults.regions`` and
``warnings``). On a gmsh second-order mesh (curved CAD: the default of :func:`mechverify.fea.mesh.cylinder`,
``block_with_holes``, ``from_step``) the elements are curved (:mod:`mechverify.fea.isoparametric`).
Nodal stresses are recovered by superconvergent patch recovery unless ``solve(recovery=...)`` says
otherwise (:mod:`mechverify.fea.recovery`).

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   ch. 6 (3D elasticity) and sec. 8.9 (consistent loads of quadratic elements: a uniform traction on a
   6-node triangle loads only its mid-side nodes, A/3 each; a uniform body force on a 10-node
   tetrahedron gives -V/20 at corners and V/5 at mid-edge nodes).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np
import scipy.sparse as sp

from mechverify.errors import InputError, ModelError
from mechverify.fea import assembly as asm
from mechverify.fea import recovery as rc
from mechverify.fea.linsolve import p1_prolongation, solve
from mechverify.fea.loads import (
    STANDARD_GRAVITY,
    Fixed,
    Force,
    Gravity,
    PinLoad,
    PinSupport,
    Pressure,
    RegionReport,
    Restraint,
    Traction,
    _join,
    compare_measure,
    held_load_names,
    held_load_warnings,
    pin_tractions,
    straddle_warning,
)
from mechverify.fea.mesh import SolidMesh
from mechverify.fea.progress import Steps
from mechverify.fea.regions import Named, Region
from mechverify.fea.reproducible import reproducible
from mechverify.fea.results import FieldResults
from mechverify.frozen import set_fields
from mechverify.materials.database import get as get_material
from mechverify.materials.material import Material

#: Models with more unknowns than this show a progress line while they solve.
PROGRESS_DOFS = 60_000


@dataclass(frozen=True)
class Facets:
    """Boundary facets of a region: P2 node indices ``nodes[k, 6]`` (3 vertices, 3 mid-edges),
    areas ``[k]`` and outward unit normals ``[k, 3]``."""

    nodes: np.ndarray
    area: np.ndarray
    normal: np.ndarray


def _as_material(material: Material | str) -> Material:
    m = get_material(material) if isinstance(material, str) else material
    if not isinstance(m, Material):
        raise InputError(f"material: expected a Material or its name, got {material!r}")
    m.require("E")
    m.require("nu")
    return m


@dataclass(frozen=True, eq=False)
class SolidModel:
    """A solid: mesh, material, supports and loads. :meth:`solve` returns :class:`FieldResults`."""

    mesh: SolidMesh
    material: Material | str
    supports: tuple[Fixed | Restraint | PinSupport, ...] = ()
    loads: tuple[Force | Pressure | PinLoad | Traction | Gravity, ...] = ()
    curved: bool | None = None  # None: curved (isoparametric) elements where the mesh has curved sides

    def __post_init__(self) -> None:
        if not isinstance(self.mesh, SolidMesh):
            raise InputError(f"mesh: expected a SolidMesh (mechverify.fea.mesh), got {type(self.mesh).__name__}")
        set_fields(self, material=_as_material(self.material), supports=tuple(self.supports), loads=tuple(self.loads))
        for s in self.supports:
            if not isinstance(s, Fixed | Restraint | PinSupport):
                raise InputError(f"supports: expected Fixed, Restraint or PinSupport, got {s!r}")
        for ld in self.loads:
            if not isinstance(ld, Force | Pressure | PinLoad | Traction | Gravity):
                raise InputError(f"loads: expected Force, Pressure, PinLoad, Traction or Gravity, got {ld!r}")
        if self.curved and self.mesh.curved is None:
            raise InputError("curved=True needs a mesh with curved mid-side nodes (a gmsh second-order mesh)")

    @property
    def is_curved(self) -> bool:
        """Whether the elements are isoparametric with curved sides (the mesh has them, ``curved`` not False)."""
        return self.mesh.curved is not None and self.curved is not False

    @property
    def nodes(self) -> np.ndarray:
        """Coordinates ``[3, n]`` of the P2 nodes the model uses (curved or straight mid-side nodes)."""
        return self.mesh.curved if self.is_curved else self.mesh.basis.doflocs

    def _facet_rule(self, fc: Facets) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Curved facets: shape functions ``[6, q]``, points ``[k, q, 3]``, outward normals times area weights
        ``[k, q, 3]`` and the facet nodes in ElementTriP2 order (vertices, then pairs (0,1), (1,2), (0,2))."""
        from mechverify.fea import isoparametric as iso

        nodes = self._pair_ordered(fc.nodes)
        N, x, nw = iso.facet_rule(self.nodes, nodes)
        sign = np.sign(np.einsum("kqd,kd->k", nw, fc.normal))
        return N, x, nw * sign[:, None, None], nodes

    def _pair_ordered(self, fnodes: np.ndarray) -> np.ndarray:
        """Facet nodes ``[k, 6]`` with the mid-edge nodes reordered to the vertex pairs (0,1), (1,2), (0,2)."""
        P = self.mesh.basis.doflocs  # straight midpoints identify the pairs exactly
        verts, mids = P[:, fnodes[:, :3]], P[:, fnodes[:, 3:]]
        pairs = ((0, 1), (1, 2), (0, 2))
        pm = np.stack([(verts[:, :, i] + verts[:, :, j]) / 2 for i, j in pairs], axis=2)  # 3, k, pair
        which = np.argmin(np.linalg.norm(mids[:, :, :, None] - pm[:, :, None, :], axis=0), axis=1)  # k, pair->mid
        out = fnodes.copy()
        out[:, 3:] = np.take_along_axis(fnodes[:, 3:], which, axis=1)
        return out

    # -- geometry of regions ------------------------------------------------------------------
    @cached_property
    def _boundary(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        m = self.mesh.mesh
        bf = m.boundary_facets()
        nodes = np.vstack([m.facets[:, bf], m.f2e[:, bf] + m.nvertices]).T  # k, 6
        v = m.p[:, m.facets[:, bf]]  # 3, 3, k
        n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0], axis=0)
        area = 0.5 * np.linalg.norm(n, axis=0)
        n = n / (2 * area)
        # outward: away from the centroid of the element owning the facet
        elem = m.f2t[0, bf]
        ec = m.p[:, m.t[:, elem]].mean(axis=1)
        fc = v.mean(axis=1)
        sign = np.sign(np.einsum("ik,ik->k", n, fc - ec))
        return bf, nodes, area, (n * sign).T

    def facets(self, region: Region) -> Facets:
        """The boundary facets in ``region`` (all six P2 nodes inside it)."""
        bf, nodes, area, normal = self._boundary
        if isinstance(region, Named):
            sel = np.isin(bf, self.mesh.named_facets(region.name))
        else:
            # judged by the facet's vertices: a straight mid-edge node of a curved surface (a hole wall)
            # lies on the chord, inside the true surface
            tol = 1e-6 * self.mesh.size
            inside = region.contains(self.nodes, tol)
            sel = np.all(inside[nodes[:, :3]], axis=1)
        if not np.any(sel):
            raise InputError(f"{region.describe()} contains no boundary facet of the mesh")
        return Facets(nodes[sel], area[sel], normal[sel])

    # -- load vector and held DOFs ------------------------------------------------------------
    def _load_vector(self, measure: np.ndarray) -> np.ndarray:
        return np.sum([f for _, f in self._load_parts(measure)], axis=0) if self.loads else np.zeros(self.mesh.n_dofs)

    def _load_parts(self, measure: np.ndarray) -> list[tuple[Facets | None, np.ndarray]]:
        """Each load's nodal force vector ``[3n]`` and the facets it acts on (None for gravity)."""
        out: list[tuple[Facets | None, np.ndarray]] = []
        for ld in self.loads:
            f = np.zeros(self.mesh.n_dofs)
            fv = f.reshape(-1, 3)
            if isinstance(ld, Gravity):
                rho = self.material.require("density").m_as("kg/m**3")
                g = np.array(ld.acceleration if ld.acceleration is not None else (0.0, 0.0, -STANDARD_GRAVITY))
                ed = self.mesh.basis.element_dofs
                if self.is_curved:
                    from mechverify.fea import isoparametric as iso

                    _, W, N, dN = iso.reference(3, 4)
                    det, _ = iso.geometry(self.nodes, ed, dN)
                    wN = np.einsum("aq,eq->ae", N, det * W[None, :]) * rho
                    for i in range(3):
                        fv[:, i] += np.bincount(ed.ravel(), weights=(wN * g[i]).ravel(), minlength=fv.shape[0])
                    out.append((None, f))
                    continue
                w = np.r_[np.full(4, -1 / 20), np.full(6, 1 / 5)]
                for i in range(3):
                    fv[:, i] += np.bincount(ed.ravel(), weights=(w[:, None] * measure[None, :] * rho * g[i]).ravel(),
                                            minlength=fv.shape[0])
                out.append((None, f))
                continue
            fc = self.facets(ld.region)
            if self.is_curved:
                N, x, nw, fnodes = self._facet_rule(fc)
                dA = np.linalg.norm(nw, axis=2)  # k, q
                if isinstance(ld, PinLoad):  # the cosine distribution on the curved wall, point by point
                    w = dA[:, :, None] * pin_tractions(ld.vector, dA.ravel(), (nw / dA[:, :, None]).reshape(-1, 3)
                                                       ).reshape(nw.shape)
                elif isinstance(ld, Force):
                    w = dA[:, :, None] * (np.array(ld.vector, float) / dA.sum())[None, None, :]
                elif isinstance(ld, Traction):
                    w = dA[:, :, None] * ld.evaluate(x.reshape(-1, 3).T).T.reshape(x.shape)
                else:
                    w = -ld.value * nw
                loc = np.einsum("aq,kqd->kad", N, w)
                for i in range(3):
                    fv[:, i] += np.bincount(fnodes.ravel(), weights=loc[:, :, i].ravel(), minlength=fv.shape[0])
                out.append((Facets(fc.nodes, dA.sum(axis=1), fc.normal), f))
                continue
            if isinstance(ld, Traction):
                self._traction_loads(ld, fc, fv)
                out.append((fc, f))
                continue
            if isinstance(ld, Force):
                traction = np.broadcast_to(np.array(ld.vector, float) / fc.area.sum(), fc.normal.shape)
            elif isinstance(ld, PinLoad):
                traction = pin_tractions(ld.vector, fc.area, fc.normal)
            else:
                traction = -ld.value * fc.normal
            mids = fc.nodes[:, 3:]
            for i in range(3):
                fv[:, i] += np.bincount(mids.ravel(), weights=np.repeat(fc.area / 3 * traction[:, i], 3),
                                        minlength=fv.shape[0])
            out.append((fc, f))
        return out

    def _traction_loads(self, ld: Traction, fc: Facets, fv: np.ndarray) -> None:
        """Consistent nodal forces of a traction field on 6-node facets (degree-4 triangle rule)."""
        from skfem.quadrature import get_quadrature
        from skfem.refdom import RefTri

        X, W = get_quadrature(RefTri, 4)
        L = np.vstack([1 - X.sum(axis=0), X])  # 3, q
        P = self.mesh.basis.doflocs
        verts = P[:, fc.nodes[:, :3]]  # 3(xyz), k, 3(vertex)
        mids = P[:, fc.nodes[:, 3:]]
        # which vertex pair each mid-edge node sits between (straight facets: at the pair's midpoint)
        pairs = ((0, 1), (1, 2), (0, 2))
        pm = np.stack([(verts[:, :, i] + verts[:, :, j]) / 2 for i, j in pairs], axis=2)  # 3, k, pair
        d = np.linalg.norm(mids[:, :, :, None] - pm[:, :, None, :], axis=0)  # k, mid, pair
        which = np.argmin(d, axis=2)  # k, mid -> pair
        for q in range(L.shape[1]):
            x = np.einsum("dka,a->dk", verts, L[:, q])
            tr = ld.evaluate(x)  # 3, k
            Nc = L[:, q] * (2 * L[:, q] - 1)
            Npair = np.array([4 * L[i, q] * L[j, q] for i, j in pairs])
            Nm = Npair[which]  # k, mid
            wA = 2 * W[q] * fc.area  # reference triangle area 1/2
            for i in range(3):
                fv[:, i] += np.bincount(fc.nodes[:, :3].ravel(),
                                        weights=(wA[:, None] * Nc[None, :] * tr[i][:, None]).ravel(),
                                        minlength=fv.shape[0])
                fv[:, i] += np.bincount(fc.nodes[:, 3:].ravel(), weights=(wA[:, None] * Nm * tr[i][:, None]).ravel(),
                                        minlength=fv.shape[0])

    def region_reports(self, reaction: np.ndarray | None = None) -> tuple[RegionReport, ...]:
        """What each load and support caught (count, area, resultant) and a warning where the area differs
        from ``expect_area`` or the region's known area (a named CAD surface) by more than
        :data:`~mechverify.fea.regions.MEASURE_RTOL`. ``reaction[3n]`` (nodal reactions of a solution)
        gives each support's resultant."""
        _, measure = asm.barycentric_gradients(self.mesh.mesh.p, self.mesh.mesh.t)
        out = []
        for k, (ld, (fc, f)) in enumerate(zip(self.loads, self._load_parts(measure))):
            name = f"{type(ld).__name__} {k + 1} on {getattr(ld, 'region', None) and ld.region.describe()}"
            if fc is None:
                out.append(RegionReport(f"{type(ld).__name__} {k + 1}", 0, 0.0, "m**2",
                                        tuple(f.reshape(-1, 3).sum(axis=0)), None, None))
                continue
            area = float(fc.area.sum())  # curved facets: the curved area
            expected = ld.expect_area if ld.expect_area is not None else self._known_area(ld.region)
            warn = _join(compare_measure(name, area, expected, "m**2"), self._straddle(name, ld.region))
            out.append(RegionReport(name, len(fc.area), area, "m**2", tuple(f.reshape(-1, 3).sum(axis=0)), expected,
                                    warn))
        bf, bnodes, barea, _ = self._boundary
        for k, s in enumerate(self.supports):
            name = f"{type(s).__name__} {k + 1} on {s.region.describe()}"
            nodes = self._support_nodes(s.region, np.empty(0))
            held = np.zeros(self.mesh.n_nodes, bool)
            held[nodes] = True
            area = float(barea[np.all(held[bnodes], axis=1)].sum())
            res = None
            if reaction is not None:
                comp = np.array(s.components, bool)
                res = tuple(np.where(comp, reaction.reshape(-1, 3)[nodes].sum(axis=0), 0.0))
            expected = s.expect_area if s.expect_area is not None else self._known_area(s.region)
            # a box cutting through facets holds only the whole ones inside it: the same WARN as loads (review 3 #22)
            cut = self._straddle(name, s.region)
            if cut:
                cut += f" (the support holds {area * 1e6:.6g} mm² of boundary)"
            out.append(RegionReport(name, int(nodes.size), area, "m**2", res, expected,
                                    _join(compare_measure(name, area, expected, "m**2"), cut)))
        return tuple(out)

    def _straddle(self, name: str, region: Region) -> str | None:
        """:func:`~mechverify.fea.loads.straddle_warning` for a surface load's region."""
        bf, nodes, _, normal = self._boundary
        if isinstance(region, Named):
            return None
        tol = 1e-6 * self.mesh.size
        caught = np.all(region.contains(self.nodes, tol)[nodes[:, :3]], axis=1)
        samples = np.array([[1 / 3, 1 / 3, 1 / 3], [2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])
        return straddle_warning(name, region, nodes[:, :3], normal, caught, self.mesh.mesh.p, tol, samples)

    def _known_area(self, region: Region) -> float | None:
        if isinstance(region, Named):
            return self.mesh.measures.get(region.name) if self.mesh.named_dimension(region.name) == 2 else None
        return region.measure(3)

    def _support_nodes(self, region: Region, bnodes: np.ndarray) -> np.ndarray:
        """Nodes held by a support on ``region``: the boundary vertices in it and the mid-edge nodes of
        boundary edges with both ends in it (a face, an edge - a degenerate box - or a point)."""
        if isinstance(region, Named):
            return self.mesh.named_nodes(region.name)
        m = self.mesh.mesh
        bf = self._boundary[0]
        bverts = np.unique(m.facets[:, bf])
        inside = np.zeros(m.nvertices, dtype=bool)
        inside[bverts] = region.contains(m.p[:, bverts], 1e-6 * self.mesh.size)
        if not np.any(inside):
            raise InputError(f"{region.describe()} contains no boundary node of the mesh")
        edges = np.unique(m.f2e[:, bf])
        ends = m.edges[:, edges]
        held_edges = edges[inside[ends[0]] & inside[ends[1]]]
        return np.concatenate([np.flatnonzero(inside), m.nvertices + held_edges])

    def load_vector(self) -> np.ndarray:
        """The consistent nodal load vector ``[3n]`` [N] (node-interleaved DOFs)."""
        _, measure = asm.barycentric_gradients(self.mesh.mesh.p, self.mesh.mesh.t)
        return self._load_vector(measure)

    def support_near(self, node: int) -> int | None:
        """Index of the first support that holds ``node`` or a node of an element containing it (a peak there is
        usually the stress singularity of a rigid support: it grows as the mesh is refined), else None."""
        elems = np.asarray(self.mesh.basis.element_dofs)
        near = np.unique(elems[:, np.any(elems == int(node), axis=0)])
        near = np.union1d(near, [int(node)])
        for k, s in enumerate(self.supports):
            if np.intersect1d(self._support_nodes(s.region, np.empty(0)), near).size:
                return k
        return None

    def held_dofs(self) -> np.ndarray:
        """Indices of the DOFs (x, y, z of each node) the supports hold at zero. A model with a :class:`PinSupport`
        holds DOFs in the pins' axes instead: a :class:`ModelError` here (use :meth:`held_in_axes`), so that nothing
        applies them to the stiffness in x, y, z (a CalculiX export would need ``*TRANSFORM``)."""
        if self.dof_basis is not None:
            raise ModelError("a pin support holds the radial DOFs of its wall (in the pin's axes, not x, y, z): use "
                             "held_in_axes() and dof_basis (K' = T^T K T); exporting pins to CalculiX is not supported")
        return self._held()

    def held_in_axes(self) -> tuple[np.ndarray, Any]:
        """The held DOFs and the DOF axes they are in: ``(held, None)`` (x, y, z) without pins, ``(held, basis)``
        (:attr:`dof_basis`: radial, tangential, axial at each pinned wall node) with them; the bodies checked."""
        return self._held(), self.dof_basis

    @cached_property
    def dof_basis(self) -> Any:
        """The DOF axes of a model with :class:`PinSupport` supports (:class:`mechverify.fea.pins.DofBasis`: each pinned
        wall node in its radial, tangential and axial axes, the held DOFs in them), else None (x, y, z everywhere).
        A pin region that is not a cylinder, two pins sharing nodes, or a :class:`Restraint` holding a direction
        that is none of a pinned node's axes is an :class:`InputError`."""
        from mechverify.fea import pins

        if not any(isinstance(s, PinSupport) for s in self.supports):
            return None
        n = self.mesh.n_nodes
        R = np.broadcast_to(np.eye(3), (n, 3, 3)).copy()
        owner = np.full(n, -1)
        fits, pinned = {}, {}
        for k, s in enumerate(self.supports):
            if not isinstance(s, PinSupport):
                continue
            what = f"Pin {k + 1} on {s.region.describe()}"
            nodes = self._support_nodes(s.region, np.empty(0))
            fc = self.facets(s.region)
            fit = pins.fit_cylinder(self.nodes[:, np.unique(fc.nodes[:, :3])], fc.normal, fc.area, what)
            shared = owner[nodes] >= 0
            other = int(owner[nodes][shared][0]) if np.any(shared) else -1
            if other >= 0 and not pins.same_cylinder(fit, fits[other]):  # two faces of one hole may share a seam
                raise InputError(f"{what}: shares {int(shared.sum())} nodes with Pin {other + 1}, a pin about another "
                                 f"axis ({fit.describe()} against {fits[other].describe()}); a node can be on one pin "
                                 "only")
            owner[nodes] = k
            R[nodes] = pins.frames(self.nodes[:, nodes], fit)
            fits[k], pinned[k] = fit, nodes
        held = []
        for k, s in enumerate(self.supports):
            if isinstance(s, PinSupport):
                held += [3 * pinned[k]] + ([3 * pinned[k] + 2] if s.axial else [])
                continue
            nodes = self._support_nodes(s.region, np.empty(0))
            plain, rot = nodes[owner[nodes] < 0], nodes[owner[nodes] >= 0]
            for i, on in enumerate(s.components):
                if not on:
                    continue
                held.append(3 * plain + i)
                if isinstance(s, Fixed):  # all three held: the same in any axes
                    held.append(3 * rot + i)
                    continue
                along = R[rot][:, i, :]  # x, y or z in each pinned node's axes (rows of R)
                j = np.argmax(np.abs(along), axis=1)
                if np.any(np.abs(along[np.arange(rot.size), j]) < 1 - 1e-9):
                    raise InputError(f"{type(s).__name__} {k + 1} on {s.region.describe()} holds {'xyz'[i]} at nodes "
                                     f"of Pin {owner[rot][0] + 1}, a direction that is none of the pin's axes (radial, "
                                     "tangential, axial) there: hold the whole region, or only along the pin's axis")
                held.append(3 * rot + j)
        return pins.DofBasis(R, np.flatnonzero(owner >= 0), np.unique(np.concatenate(held)), fits, pinned)

    def loads_on_held(self, held: np.ndarray | None = None) -> list[str]:
        """The loads whose nodal forces all fall on held DOFs: they go straight into the supports and load
        nothing (a load on a supported face, or supports that catch the loaded face). Raises
        :class:`ModelError` when that is every load: the model would report zero stress and deflection."""
        held = self._held() if held is None else held
        _, measure = asm.barycentric_gradients(self.mesh.mesh.p, self.mesh.mesh.t)
        return held_load_names(self.loads, [f for _, f in self._load_parts(measure)], held)

    def _held(self) -> np.ndarray:
        """The held DOFs (in the pins' axes where there are pins: :attr:`dof_basis`), each body checked."""
        if not self.supports:
            raise ModelError("the model has no supports; add Fixed(...) or Restraint(...) on a region")
        if self.dof_basis is not None:
            self.check_bodies(self.dof_basis.held)
            return self.dof_basis.held
        held = []
        for s in self.supports:
            nodes = self._support_nodes(s.region, np.empty(0))
            for i, on in enumerate(s.components):
                if on:
                    held.append(3 * nodes + i)
        out = np.unique(np.concatenate(held))
        self.check_bodies(out)
        return out

    @cached_property
    def bodies(self) -> np.ndarray:
        """The body (0, 1, ...: tetrahedra connected through shared vertices) of each P2 node ``[n]``: a mesh of
        parts that share no node (separate solids of a STEP file that do not touch) has more than one."""
        from scipy.sparse.csgraph import connected_components

        m = self.mesh.mesh
        g = sp.coo_matrix((np.ones(3 * m.nelements), (np.tile(m.t[0], 3), m.t[1:].ravel())),
                          shape=(m.nvertices, m.nvertices))
        _, labels = connected_components(g, directed=False)
        return np.concatenate([labels, labels[m.edges[0]]])

    def body_description(self, body: int) -> str:
        """A body as the user can find it: the named faces on it and its bounding box."""
        at = self.bodies[: self.mesh.mesh.nvertices] == body
        names = sorted((k for k, v in self.mesh.named.items() if v.ndim == 2 and v.shape[1] == 3 and v.size
                        and at[v[0, 0]]), key=lambda s: (len(s), s))
        shown = ", ".join(names[:12]) + (f" and {len(names) - 12} more" if len(names) > 12 else "")
        p = self.mesh.mesh.p[:, at] * 1e3
        box = tuple(f"({', '.join(f'{c:.4g}' for c in corner)})" for corner in (p.min(axis=1), p.max(axis=1)))
        return f"body {body + 1} ({'faces ' + shown + ', ' if names else ''}from {box[0]} to {box[1]} mm)"

    def check_bodies(self, held: np.ndarray) -> None:
        """Each body of the mesh (:attr:`bodies`) held against every rigid motion by the DOFs ``held``, else a
        :class:`ModelError` naming the body (its faces and extent) and what is free: a second solid of a STEP file
        that touches no other and no support floated, and the solve reported "equilibrium not met" (review 3
        finding 11). One body: nothing to do here (the solver's rigid-body check names the free motion)."""
        from mechverify.fea.pins import check_supported

        nb = int(self.bodies.max()) + 1
        if nb == 1:
            return
        owner = self.bodies[held // 3]
        for b in range(nb):
            nodes = np.flatnonzero(self.bodies == b)
            mine = held[owner == b]
            what = (f"the model is not fully supported: the mesh is {nb} separate bodies (no shared nodes); "
                    f"{self.body_description(b)}")
            if mine.size == 0:
                raise ModelError(f"{what} touches no support, so it is free to move. Join it to the others in CAD "
                                 "(touching solids of a STEP file are bonded) or support it")
            local = np.full(self.bodies.size, -1)
            local[nodes] = np.arange(nodes.size)
            try:
                check_supported(self.nodes[:, nodes], 3 * local[mine // 3] + mine % 3,
                                None if self.dof_basis is None else self.dof_basis.R[nodes])
            except ModelError as exc:
                raise ModelError(f"{what}: {str(exc).removeprefix('the model is not fully supported: ')}") from None

    # -- solve --------------------------------------------------------------------------------
    def _stiffness(self, pattern: asm.BlockPattern, lam: float, mu: float) -> tuple[sp.bsr_matrix, np.ndarray]:
        """The assembled stiffness ``K`` (BSR, 3x3 blocks) and the element volumes ``[e]`` [m³].

        The element blocks ``[(a,b), e, 9]`` (100 * 9 floats per element, 2.3 times K's own data) die with this
        frame: held by :meth:`solve` they stayed alive through the linear solve and the stress recovery,
        +1.4 kB/DOF of peak memory (issue 23; ``tests/test_fea_memory.py``). Straight elements are summed a tenth
        of the blocks at a time (:func:`mechverify.fea.assembly.assemble_elasticity`: the assembly was the peak of
        a 200k-DOF solve, -1 kB/DOF).
        """
        m, b = self.mesh.mesh, self.mesh.basis
        if self.is_curved:
            from mechverify.fea import isoparametric as iso

            measure = np.empty(m.nelements)

            def blocks_of(e0: int, e1: int) -> np.ndarray:  # a chunk of elements (all at once: 5.8 kB/DOF peak)
                blocks, measure[e0:e1] = iso.stiffness_blocks(self.nodes, b.element_dofs[:, e0:e1], lam, mu)
                return blocks

            return asm.assemble_element_chunks(blocks_of, pattern, 3, m.nelements), measure
        _, measure = asm.barycentric_gradients(m.p, m.t)
        return asm.assemble_elasticity(m.p, m.t, lam, mu, pattern), measure

    @reproducible  # one BLAS thread: the same bits whatever the process's thread count (issue 19)
    def solve(self, method: str = "auto", progress: bool | None = None,
              recovery: str = rc.DEFAULT_METHOD, factorization: Any = None) -> FieldResults:
        """Assemble, check the supports, solve, recover stresses, check equilibrium.

        ``method``: ``"auto"`` (direct below ~12k unknowns, AMG-CG above), ``"direct"`` or ``"amg"``.
        ``recovery``: how nodal stresses are recovered (:data:`mechverify.fea.recovery.METHODS`).
        ``progress``: show a status line (default: for models above :data:`PROGRESS_DOFS`).
        ``factorization``: a :class:`mechverify.fea.study.SharedSolve` of this mesh, material and supports
        (many load cases on one factorisation: :func:`mechverify.fea.study.solve_cases`).
        """
        mat = self.material
        E, nu = mat.E.m_as("Pa"), mat.nu.m_as("")
        lam, mu = asm.lame(E, nu)
        m, b = self.mesh.mesh, self.mesh.basis
        show = self.mesh.n_dofs > PROGRESS_DOFS if progress is None else progress
        timings: dict[str, float] = {}
        basis = self.dof_basis  # pins: K, loads and held DOFs in the pins' axes (fea.pins), u = T u'
        with Steps(show, "solid") as step:
            t0 = time.perf_counter()
            step(f"assembling {m.nelements} quadratic tetrahedra ({self.mesh.n_dofs} DOF)")
            if basis is not None and factorization is None:  # linsolve.solve's rigid-body check is in x, y, z
                from mechverify.fea.study import SharedSolve

                factorization = SharedSolve.of(self, method)
            projection = recovery == "projection" and not self.is_curved
            pattern = asm.block_pattern(b.element_dofs, b.N) if factorization is None or projection else None
            if factorization is not None:
                K = factorization.K
                _, measure = asm.barycentric_gradients(m.p, m.t)
            else:
                K, measure = self._stiffness(pattern, lam, mu)
            if not projection:  # only the L2 projection needs it again (0.35 kB/DOF through the solve; issue 23)
                pattern = None
            parts = [fi for _, fi in self._load_parts(measure)] if self.loads else []
            f = np.sum(parts, axis=0) if parts else np.zeros(self.mesh.n_dofs)
            held = self._held()
            if basis is not None:
                f, parts = basis.inward(f), [basis.inward(fi) for fi in parts]
            on_held = held_load_names(self.loads, parts, held)
            pinned_loads = () if basis is None else basis.load_warnings(self.loads, parts, on_held)
            timings["assembly"] = time.perf_counter() - t0
            if factorization is not None:
                u, info = factorization.solve(f, held)
            else:
                P = p1_prolongation(m.nvertices, m.edges, 3)
                # K is handed over to the linear solve, which frees it once it has K's free part: the reactions
                # need only its held rows (K's 0.7 kB/DOF not kept through the multigrid setup and CG; issue 23)
                handed, K = [K], asm.held_rows(K, held)
                u, info = solve(handed.pop(), f, held, self.nodes, method=method, progress=step, prolongation=P)
            timings["solve"] = info.seconds
            r = nodal_reactions(K, u, f, held)
            if basis is not None:  # back to x, y, z
                u, f, r = basis.outward(u), basis.outward(f), basis.outward(r)
            info = replace(info, worst_quality=self.mesh.worst_quality)
            t1 = time.perf_counter()
            step("recovering stresses")
            if self.is_curved:
                rec = rc.recover_curved(recovery, self.nodes, m.t, b.element_dofs, u, lam, mu, E, nu)
            else:
                rec = rc.recover(recovery, m.p, m.t, b.element_dofs, b.doflocs, u, lam, mu, E, nu, measure, pattern)
            sigma = _tensors(rec.nodal)
            timings["recovery"] = time.perf_counter() - t1
            reaction, applied = _balance(r, f, self.nodes, 3)
            reports = self.region_reports(r)
        bf, nodes, _, _ = self._boundary
        return FieldResults(
            kind="solid", points=self.nodes.T.copy(), u=u.reshape(-1, 3), sigma=sigma, material=mat,
            reaction=reaction, applied=applied, cells=[("tetra10", b.element_dofs.T.copy())],
            surface=nodes[:, :3].copy(), info=info, timings=timings, regions=reports,
            warnings=(*held_load_warnings(on_held), *pinned_loads, *(r.warning for r in reports if r.warning),
                      *filter(None, [self.mesh.sliver_warning()])), recovery=recovery,
            elements=b.element_dofs.T.copy(), ip_points=rec.ip_points, ip_sigma=_tensors(rec.ip_values),
            element_error=rec.element_error, error_estimate=rec.error_estimate)

    def integration_point_stress(self, u: Any) -> np.ndarray:
        """Stress ``[e, 4, 3, 3]`` [Pa] at the 4 integration points of each element, in CalculiX's order.

        The points are those of the 4-point degree-2 rule: first the one nearest vertex 0, then nearest
        vertices 1, 2, 3 (CalculiX 2.20 manual, sec. 6.2.6).
        """
        mat = self.material
        lam, mu = asm.lame(mat.E.m_as("Pa"), mat.nu.m_as(""))
        m, b = self.mesh.mesh, self.mesh.basis
        if self.is_curved:
            from mechverify.fea import isoparametric as iso

            eps, _, _ = iso.strain(self.nodes, b.element_dofs, np.asarray(u).ravel(), rc.sample_bary(3)[:, 1:].T)
            return asm.hooke(eps, lam, mu)
        s = asm.hooke(asm.strain_at_points(m.p, m.t, b.element_dofs, np.asarray(u).ravel()), lam, mu)
        return s[:, asm.natural_point_order(3)]


def _tensors(c: np.ndarray) -> np.ndarray:
    """Components ``[..., 6]`` (xx yy zz xy yz zx) -> symmetric tensors ``[..., 3, 3]``."""
    out = np.empty(c.shape[:-1] + (3, 3))
    out[..., 0, 0], out[..., 1, 1], out[..., 2, 2] = c[..., 0], c[..., 1], c[..., 2]
    out[..., 0, 1] = out[..., 1, 0] = c[..., 3]
    out[..., 1, 2] = out[..., 2, 1] = c[..., 4]
    out[..., 0, 2] = out[..., 2, 0] = c[..., 5]
    return out


def nodal_reactions(K: Any, u: np.ndarray, f: np.ndarray, held: np.ndarray) -> np.ndarray:
    """Nodal reaction forces ``K u - f`` at the held DOFs, zero elsewhere ``[dofs]`` [N]."""
    r = np.zeros_like(f)
    r[held] = (K @ u)[held] - f[held]
    return r


def _equilibrium(K: Any, u: np.ndarray, f: np.ndarray, held: np.ndarray, points: np.ndarray,
                 dim: int) -> tuple[np.ndarray, np.ndarray]:
    """Total reaction and applied force; :class:`ModelError` unless forces and moments balance.

    Reactions are ``K u - f`` at the held DOFs.
    """
    r = np.zeros_like(f)
    r[held] = (K @ u)[held] - f[held]
    return _balance(r, f, points, dim)


def _balance(r: np.ndarray, f: np.ndarray, points: np.ndarray, dim: int) -> tuple[np.ndarray, np.ndarray]:
    """Total reaction and applied force of nodal reactions ``r`` and loads ``f`` (x, y, z); :class:`ModelError`
    unless forces and moments balance."""
    R, F = r.reshape(-1, dim), f.reshape(-1, dim)
    X = points.T - points.mean(axis=1)
    tot_r, tot_f = R.sum(axis=0), F.sum(axis=0)
    scale = max(np.abs(R).sum(), np.abs(F).sum(), 1e-300)
    if dim == 3:
        mom = np.cross(X, R + F).sum(axis=0)
    else:
        mom = np.array([(X[:, 0] * (R + F)[:, 1] - X[:, 1] * (R + F)[:, 0]).sum()])
    size = float(np.max(np.ptp(points, axis=1)))
    err = max(float(np.max(np.abs(tot_r + tot_f))), float(np.max(np.abs(mom))) / size)
    if err > 1e-6 * scale:
        raise ModelError(f"equilibrium not met: reactions {tot_r} N vs applied {tot_f} N "
                         f"(imbalance {err:.3g} N); the solve did not converge")
    return tot_r, tot_f
