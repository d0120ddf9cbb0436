"""Plane stress and plane strain with quadratic triangles (P2, 6 nodes).

A flat part (a link outline with holes, an in-plane loaded plate) of thickness ``t`` in its x-y
plane, meshed by gmsh with the element size graded down at holes (:func:`mesh_region`), or any
scikit-fem ``MeshTri``. Supports and loads are those of the solids (:mod:`mechverify.fea.loads`)
on 2D regions: ``Plane(x=...)`` is a line, ``Cylinder(center=(x, y), radius=r)`` a hole's rim.
``Force`` spreads a total force over the region's boundary length (a pin load on a hole), ``Pressure``
acts normal to the boundary, ``Traction`` is any field t(x), ``Gravity`` defaults to -y. A gmsh
second-order mesh (:func:`mechverify.fea.mesh2d.from_gmsh_model`) gives curved (isoparametric)
triangles and named curves and points (:class:`~mechverify.fea.regions.Named`). Each load and support
reports what it caught (:meth:`PlaneModel.region_reports`, ``FieldResults.regions`` / ``warnings``).

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   ch. 6 (plane stress: λ* = 2λμ/(λ + 2μ); plane strain: σzz = ν(σxx + σyy)) and sec. 8.9
   (consistent loads of a quadratic edge: L/6, 2L/3, L/6; body force on a 6-node triangle: 0 at the
   corners, A/3 at the mid-side nodes).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
from skfem import Basis, ElementTriP2, MeshTri

from mechverify.errors import InputError, ModelError
from mechverify.fea import assembly as asm
from mechverify.fea import mesh2d
from mechverify.fea import recovery as rc
from mechverify.fea.linsolve import solve
from mechverify.fea.loads import (
    STANDARD_GRAVITY,
    Fixed,
    Force,
    Gravity,
    PinLoad,
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
from mechverify.fea.progress import Steps
from mechverify.fea.regions import Named, Region
from mechverify.fea.results import FieldResults
from mechverify.fea.solid import _as_material, _equilibrium, nodal_reactions
from mechverify.frozen import set_fields
from mechverify.materials.material import Material
from mechverify.units import QuantityLike, from_si, to_si


def mesh_region(region: Any, size: QuantityLike, hole_size: QuantityLike | None = None) -> MeshTri:
    """Triangles of a shapely polygon in metres (outline with holes), element ``size`` graded to
    ``hole_size`` (default size/3) at the holes. Needs gmsh."""
    h = to_si(size, "length", "size")
    hh = None if hole_size is None else to_si(hole_size, "length", "hole_size")
    return mesh2d.polygon(region, h, hh)


@dataclass(frozen=True, eq=False)
class PlaneModel:
    """A 2D part: mesh (metres), ``thickness``, material, supports, loads; ``plane`` is
    ``"stress"`` (thin parts) or ``"strain"`` (long prismatic bodies, thickness per unit length)."""

    mesh: MeshTri
    thickness: QuantityLike
    material: Material | str
    supports: tuple[Fixed | Restraint, ...] = ()
    loads: tuple[Force | Pressure | PinLoad | Traction | Gravity, ...] = ()
    plane: str = "stress"
    curved: bool | None = None  # None: curved (isoparametric) elements where the mesh has curved sides

    def __post_init__(self) -> None:
        if not isinstance(self.mesh, MeshTri):
            raise InputError(f"mesh: expected a scikit-fem MeshTri (see plane.mesh_region), got {self.mesh!r}")
        t = to_si(self.thickness, "length", "thickness")
        if t <= 0:
            raise InputError("thickness: must be positive")
        set_fields(self, thickness=from_si(t, "length"))  # a quantity: dataclasses.replace re-reads it
        if self.plane not in ("stress", "strain"):
            raise InputError(f"plane: 'stress' or 'strain', got {self.plane!r}")
        set_fields(self, material=_as_material(self.material), supports=tuple(self.supports), loads=tuple(self.loads))
        oriented = mesh2d.orient_triangles(self.mesh.p, self.mesh.t)
        set_fields(self, mesh=mesh2d.tri_mesh(self.mesh.p, oriented, self.mesh))

    @cached_property
    def thickness_si(self) -> float:
        """Thickness [m] as a float (``thickness`` is the quantity)."""
        return float(self.thickness.m_as("m"))

    @cached_property
    def basis(self) -> Basis:
        return Basis(self.mesh, ElementTriP2(), intorder=1)

    @cached_property
    def _curved_nodes(self) -> np.ndarray | None:
        c = getattr(self.mesh, "curved", None)
        if c is not None and self.curved is not False and c.shape == self.basis.doflocs.shape:
            return np.asarray(c, float)
        if self.curved:
            raise InputError("curved=True needs a mesh with curved mid-side nodes (mesh2d.from_gmsh_model of a "
                             "second-order gmsh mesh)")
        return None

    @property
    def nodes(self) -> np.ndarray:
        """Coordinates ``[2, n]`` of the P2 nodes: on the curved geometry where the mesh has it (gmsh
        second-order meshes, :func:`mechverify.fea.mesh2d.from_gmsh_model`) and ``curved`` is not False,
        else the straight mid-points."""
        c = self._curved_nodes
        return self.basis.doflocs if c is None else c

    @property
    def is_curved(self) -> bool:
        """Whether the elements are isoparametric with curved sides."""
        return self._curved_nodes is not None

    def _edge_rule(self, nodes: np.ndarray, normal: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Curved edges: shape functions ``[3, q]``, points ``[k, q, 2]`` and outward normals times length
        weights ``[k, q, 2]``."""
        from mechverify.fea import isoparametric as iso

        N, x, nw = iso.facet_rule(self.nodes, nodes)
        sign = np.sign(np.einsum("kqd,kd->k", nw, normal))
        return N, x, nw * sign[:, None, None]

    @cached_property
    def _boundary(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        m = self.mesh
        bf = m.boundary_facets()
        nodes = np.vstack([m.facets[:, bf], bf + m.nvertices]).T  # k, 3 (ends, middle)
        a, b = m.p[:, m.facets[0, bf]], m.p[:, m.facets[1, bf]]
        length = np.linalg.norm(b - a, axis=0)
        n = np.vstack([(b - a)[1], -(b - a)[0]]) / length
        elem = m.f2t[0, bf]
        ec = m.p[:, m.t[:, elem]].mean(axis=1)
        sign = np.sign(np.einsum("ik,ik->k", n, (a + b) / 2 - ec))
        return nodes, length, (n * sign).T

    @property
    def size(self) -> float:
        return float(np.linalg.norm(np.ptp(self.mesh.p, axis=1)))

    def _named_edges(self, name: str) -> np.ndarray:
        """Mask over the boundary edges of a named curve (scikit-fem boundary / gmsh physical curve)."""
        from mechverify.errors import UnknownNameError

        facets = (self.mesh.boundaries or {}).get(name)
        if facets is None:
            points = getattr(self.mesh, "named_points", {})
            if name in points:
                raise InputError(f"region {name!r} is a set of points; a load needs a named curve")
            raise UnknownNameError("mesh region", name, [*(self.mesh.boundaries or {}), *points])
        return np.isin(self.mesh.boundary_facets(), facets)

    def _edges(self, region: Region) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        nodes, length, normal = self._boundary
        if isinstance(region, Named):
            sel = self._named_edges(region.name)
        else:
            inside = region.contains(self.nodes, 1e-6 * self.size)
            sel = np.all(inside[nodes[:, :2]], axis=1)  # by the end vertices (a chord's middle is off an arc)
        if not np.any(sel):
            raise InputError(f"{region.describe()} contains no boundary edge of the mesh")
        return nodes[sel], length[sel], normal[sel]

    def _support_nodes(self, region: Region) -> np.ndarray:
        """Held nodes: boundary vertices in the region and the middles of boundary edges with both ends in it
        (a named curve: its edges' three nodes; named points: those vertices)."""
        nodes_all, _, _ = self._boundary
        if isinstance(region, Named):
            points = getattr(self.mesh, "named_points", {})
            if region.name in points:
                return np.asarray(points[region.name], np.int64)
            return np.unique(nodes_all[self._named_edges(region.name)])
        bverts = np.unique(nodes_all[:, :2])
        inside = np.zeros(self.basis.N, dtype=bool)
        inside[bverts] = region.contains(self.nodes[:, bverts], 1e-6 * self.size)
        if not np.any(inside):
            raise InputError(f"{region.describe()} contains no boundary node of the mesh")
        edge_in = inside[nodes_all[:, 0]] & inside[nodes_all[:, 1]]
        return np.unique(np.r_[np.flatnonzero(inside), nodes_all[edge_in, 2]])

    def load_vector(self, area: np.ndarray | None = None) -> np.ndarray:
        """The consistent nodal load vector ``[2n]`` [N] (node-interleaved DOFs)."""
        parts = self._load_parts(area)
        return np.sum([f for _, f in parts], axis=0) if parts else np.zeros(2 * self.basis.N)

    def _load_parts(self, area: np.ndarray | None = None) -> list[tuple[np.ndarray | None, np.ndarray]]:
        """Each load's nodal force vector ``[2n]`` and the lengths of the edges it acts on (None: gravity)."""
        b = self.basis
        if area is None:
            area = asm.barycentric_gradients(self.mesh.p, self.mesh.t)[1]
        t = self.thickness_si
        out: list[tuple[np.ndarray | None, np.ndarray]] = []
        for ld in self.loads:
            f = np.zeros(2 * b.N)
            fv = f.reshape(-1, 2)
            if isinstance(ld, Gravity):
                rho = self.material.require("density").m_as("kg/m**3")
                g = np.array(ld.acceleration[:2] if ld.acceleration is not None else (0.0, -STANDARD_GRAVITY))
                if self.is_curved:
                    from mechverify.fea import isoparametric as iso

                    _, W, N, dN = iso.reference(2, 4)
                    det, _ = iso.geometry(self.nodes, b.element_dofs, dN)
                    wN = np.einsum("aq,eq->ae", N, det * W[None, :]) * rho * t  # a, e
                    for i in range(2):
                        fv[:, i] += np.bincount(b.element_dofs.ravel(), weights=(wN * g[i]).ravel(), minlength=b.N)
                    out.append((None, f))
                    continue
                mids = b.element_dofs[3:]
                for i in range(2):
                    fv[:, i] += np.bincount(mids.ravel(), weights=np.repeat(area[None, :] / 3 * rho * g[i] * t, 3,
                                                                             axis=0).ravel(), minlength=b.N)
                out.append((None, f))
                continue
            nodes, length, normal = self._edges(ld.region)
            if self.is_curved:
                N, x, nw = self._edge_rule(nodes, normal)
                ds = np.linalg.norm(nw, axis=2)  # k, q
                if isinstance(ld, PinLoad):  # the cosine distribution on the curved rim, point by point
                    w = ds[:, :, None] * pin_tractions(ld.vector, ds.ravel() * t, (nw / ds[:, :, None]).reshape(-1, 2)
                                                       ).reshape(nw.shape)
                elif isinstance(ld, Force):
                    tr = np.broadcast_to(np.array(ld.vector[:2])[None, None, :] / (ds.sum() * t), nw.shape)
                    w = ds[:, :, None] * tr
                elif isinstance(ld, Traction):
                    w = ds[:, :, None] * ld.evaluate(x.reshape(-1, 2).T).T.reshape(x.shape)
                else:
                    w = -ld.value * nw
                loc = np.einsum("aq,kqd->kad", N, w) * t  # k, 3, 2
                for i in range(2):
                    fv[:, i] += np.bincount(nodes.ravel(), weights=loc[:, :, i].ravel(), minlength=b.N)
                out.append((ds.sum(axis=1), f))
                continue
            if isinstance(ld, Traction):
                # 3-point Gauss-Legendre on each straight edge; P2 edge shape functions (ends, middle)
                gs = 0.5 + 0.5 * np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
                gw = np.array([5 / 18, 8 / 18, 5 / 18])
                xa, xb = self.basis.doflocs[:, nodes[:, 0]], self.basis.doflocs[:, nodes[:, 1]]
                for s_, w_ in zip(gs, gw):
                    x = xa + s_ * (xb - xa)
                    tr = ld.evaluate(x)  # 2, k
                    N = np.array([(1 - s_) * (1 - 2 * s_), s_ * (2 * s_ - 1), 4 * s_ * (1 - s_)])
                    for i in range(2):
                        fv[:, i] += np.bincount(nodes.ravel(), weights=(length[:, None] * t * w_ * N[None, :]
                                                                        * tr[i][:, None]).ravel(), minlength=b.N)
                out.append((length, f))
                continue
            if isinstance(ld, Force):
                traction = np.broadcast_to(np.array(ld.vector[:2]) / (length.sum() * t), normal.shape)
            elif isinstance(ld, PinLoad):
                traction = pin_tractions(ld.vector, length * t, normal)
            else:
                traction = -ld.value * normal
            w = np.array([1 / 6, 1 / 6, 2 / 3])
            for i in range(2):
                fv[:, i] += np.bincount(nodes.ravel(), weights=(length[:, None] * t * w[None, :]
                                                                * traction[:, i:i + 1]).ravel(), minlength=b.N)
            out.append((length, f))
        return out

    def region_reports(self, reaction: np.ndarray | None = None) -> tuple[RegionReport, ...]:
        """What each load and support caught (edge count, boundary length, resultant) and a warning where the
        length differs from ``expect_length`` or the region's known length (an :class:`Arc`, a
        :class:`Polyline`, a named gmsh curve) by more than :data:`~mechverify.fea.regions.MEASURE_RTOL`.
        ``reaction[2n]`` (nodal reactions of a solution) gives each support's resultant."""
        out = []
        for k, (ld, (length, f)) in enumerate(zip(self.loads, self._load_parts())):
            total = tuple(f.reshape(-1, 2).sum(axis=0))
            if length is None:
                out.append(RegionReport(f"{type(ld).__name__} {k + 1}", 0, 0.0, "m", total, None, None))
                continue
            name = f"{type(ld).__name__} {k + 1} on {ld.region.describe()}"
            got = float(length.sum())
            expected = ld.expect_length if ld.expect_length is not None else self._known_length(ld.region)
            warn = _join(compare_measure(name, got, expected, "m"), self._straddle(name, ld.region))
            out.append(RegionReport(name, int(length.size), got, "m", total, expected, warn))
        nodes_all, blen, _ = self._boundary
        for k, s in enumerate(self.supports):
            name = f"{type(s).__name__} {k + 1} on {s.region.describe()}"
            nodes = self._support_nodes(s.region)
            held = np.zeros(self.basis.N, bool)
            held[nodes] = True
            got = float(blen[np.all(held[nodes_all], axis=1)].sum())
            res = None
            if reaction is not None:
                comp = np.array(s.components[:2], bool)
                res = tuple(np.where(comp, reaction.reshape(-1, 2)[nodes].sum(axis=0), 0.0))
            expected = s.expect_length if s.expect_length is not None else self._known_length(s.region)
            # a box cutting through edges holds only the whole ones inside it: the same WARN as loads and as the
            # solid's supports (review 3 #22; issue 23)
            cut = self._straddle(name, s.region)
            if cut:
                cut += f" (the support holds {got * 1e3:.6g} mm of boundary)"
            out.append(RegionReport(name, int(nodes.size), got, "m", res, expected,
                                    _join(compare_measure(name, got, expected, "m"), cut)))
        return tuple(out)

    def _straddle(self, name: str, region: Region) -> str | None:
        """:func:`~mechverify.fea.loads.straddle_warning` for an edge load's region."""
        if isinstance(region, Named):
            return None
        nodes, _, normal = self._boundary
        tol = 1e-6 * self.size
        caught = np.all(region.contains(self.nodes, tol)[nodes[:, :2]], axis=1)
        samples = np.array([[0.75, 0.25], [0.5, 0.5], [0.25, 0.75]])
        return straddle_warning(name, region, nodes[:, :2], normal, caught, self.mesh.p, tol, samples)

    def _known_length(self, region: Region) -> float | None:
        if isinstance(region, Named):
            return getattr(self.mesh, "measures", {}).get(region.name)
        return region.measure(2)

    def loads_on_held(self, held: np.ndarray | None = None) -> list[str]:
        """The loads that fall wholly on held DOFs (:func:`mechverify.fea.loads.held_load_names`; a
        :class:`ModelError` when that is every load)."""
        held = self.held_dofs() if held is None else held
        return held_load_names(self.loads, [f for _, f in self._load_parts()], held)

    def held_dofs(self) -> np.ndarray:
        """Indices of the DOFs the supports hold at zero."""
        if not self.supports:
            raise ModelError("the model has no supports; add Fixed(...) or Restraint(...) on a region")
        held = []
        for s in self.supports:
            if isinstance(s, Restraint) and s.z and not (s.x or s.y):
                raise InputError("Restraint(z=True) has no meaning in a 2D model; hold x and/or y")
            nodes = self._support_nodes(s.region)
            for i, on in enumerate(s.components[:2]):
                if on:
                    held.append(2 * nodes + i)
        return np.unique(np.concatenate(held))

    def solve(self, progress: bool | None = None, recovery: str = rc.DEFAULT_METHOD) -> FieldResults:
        """Assemble, check the supports, solve (sparse direct), recover stresses (``recovery``, one of
        :data:`mechverify.fea.recovery.METHODS`), check equilibrium."""
        mat = self.material
        E, nu = mat.E.m_as("Pa"), mat.nu.m_as("")
        lam3, mu = asm.lame(E, nu)
        lam = asm.lame(E, nu, "stress")[0] if self.plane == "stress" else lam3
        m, b = self.mesh, self.basis
        timings: dict[str, float] = {}
        with Steps(bool(progress), "plane") as step:
            t0 = time.perf_counter()
            step("assembling")
            pattern = asm.block_pattern(b.element_dofs, b.N)
            if self.is_curved:
                from mechverify.fea import isoparametric as iso

                blocks, area = iso.stiffness_blocks(self.nodes, b.element_dofs, lam, mu, self.thickness_si)
            else:
                blocks = asm.elasticity_blocks(m.p, m.t, lam, mu, self.thickness_si)
                _, area = asm.barycentric_gradients(m.p, m.t)
            K = asm.assemble_blocks(blocks, pattern, 2)
            del blocks  # 1.4 x K's data: not kept through the solve and the recovery (issue 23, as in solid.py)
            parts = [fi for _, fi in self._load_parts(area)]
            f = np.sum(parts, axis=0) if parts else np.zeros(2 * self.basis.N)
            held = self.held_dofs()
            on_held = held_load_names(self.loads, parts, held)
            timings["assembly"] = time.perf_counter() - t0
            u, info = solve(K, f, held, self.nodes, method="direct", progress=step)
            timings["solve"] = info.seconds
            t1 = time.perf_counter()
            if self.is_curved:
                rec = rc.recover_curved(recovery, self.nodes, m.t, b.element_dofs, u, lam, mu, E, nu,
                                        plane_strain=self.plane == "strain")
            else:
                rec = rc.recover(recovery, m.p, m.t, b.element_dofs, b.doflocs, u, lam, mu, E, nu, area, pattern,
                                 plane_strain=self.plane == "strain")
            s = rec.nodal
            timings["recovery"] = time.perf_counter() - t1
            reaction, applied = _equilibrium(K, u, f, held, self.nodes, 2)
            reports = self.region_reports(nodal_reactions(K, u, f, held))
        n = b.N
        sigma = np.zeros((n, 3, 3))
        sigma[:, 0, 0], sigma[:, 1, 1] = s[:, 0], s[:, 1]
        sigma[:, 0, 1] = sigma[:, 1, 0] = s[:, 2]
        if self.plane == "strain":
            sigma[:, 2, 2] = nu * (s[:, 0] + s[:, 1])
        pts = np.column_stack([self.nodes.T, np.zeros(n)])
        uu = np.zeros((n, 3))
        uu[:, :2] = u.reshape(-1, 2)
        return FieldResults(
            kind=f"plane {self.plane}", points=pts, u=uu, sigma=sigma, material=mat,
            reaction=np.r_[reaction, 0.0], applied=np.r_[applied, 0.0],
            cells=[("triangle6", b.element_dofs.T.copy())], surface=m.t.T.copy(), info=info, timings=timings,
            regions=reports, warnings=(*held_load_warnings(on_held), *(r.warning for r in reports if r.warning)),
            recovery=recovery,
            elements=b.element_dofs.T.copy(),
            ip_points=np.concatenate([rec.ip_points, np.zeros(rec.ip_points.shape[:2] + (1,))], axis=2),
            ip_sigma=_plane_tensors(rec.ip_values, nu if self.plane == "strain" else 0.0),
            element_error=rec.element_error, error_estimate=rec.error_estimate)


def _plane_tensors(c: np.ndarray, nu_zz: float) -> np.ndarray:
    """Plane components ``[..., 3]`` (xx yy xy) -> tensors ``[..., 3, 3]`` with σzz = ν_zz (σxx + σyy)."""
    out = np.zeros(c.shape[:-1] + (3, 3))
    out[..., 0, 0], out[..., 1, 1] = c[..., 0], c[..., 1]
    out[..., 0, 1] = out[..., 1, 0] = c[..., 2]
    out[..., 2, 2] = nu_zz * (c[..., 0] + c[..., 1])
    return out
