"""Plane stress and plane strain with quadratic triangles (P2, 6 nodes).

A flat part (a link outline with holes, an in-plane loaded plate) of thickness ``t`` in its x-y
plane, meshed by gmsh with the element size graded down at holes (:func:`mesh_region`), or any
scikit-fem ``MeshTri``. Supports and loads are those of the solids (:mod:`mechverify.fea.loads`)
on 2D regions: ``Plane(x=...)`` is a line, ``Cylinder(center=(x, y), radius=r)`` a hole's rim.
``Force`` spreads a total force over the region's boundary length (a pin load on a hole), ``Pressure``
acts normal to the boundary, ``Gravity`` defaults to -y.

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
from mechverify.fea.linsolve import solve
from mechverify.fea.loads import STANDARD_GRAVITY, Fixed, Force, Gravity, PinLoad, Pressure, Support, pin_tractions
from mechverify.fea.progress import Steps
from mechverify.fea.recovery import project
from mechverify.fea.regions import Named, Region
from mechverify.fea.results import FieldResults
from mechverify.fea.solid import _as_material, _equilibrium
from mechverify.materials.material import Material
from mechverify.units import to_si


def mesh_region(region: Any, size: Any, hole_size: Any = None) -> MeshTri:
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
    thickness: Any
    material: Material | str
    supports: tuple[Fixed | Support, ...] = ()
    loads: tuple[Force | Pressure | PinLoad | Gravity, ...] = ()
    plane: str = "stress"

    def __post_init__(self) -> None:
        if not isinstance(self.mesh, MeshTri):
            raise InputError(f"mesh: expected a scikit-fem MeshTri (see plane.mesh_region), got {self.mesh!r}")
        object.__setattr__(self, "thickness", to_si(self.thickness, "length", "thickness"))
        if self.thickness <= 0:
            raise InputError("thickness: must be positive")
        if self.plane not in ("stress", "strain"):
            raise InputError(f"plane: 'stress' or 'strain', got {self.plane!r}")
        object.__setattr__(self, "material", _as_material(self.material))
        object.__setattr__(self, "supports", tuple(self.supports))
        object.__setattr__(self, "loads", tuple(self.loads))
        oriented = mesh2d.orient_triangles(self.mesh.p, self.mesh.t)
        object.__setattr__(self, "mesh", mesh2d.tri_mesh(self.mesh.p, oriented, self.mesh))

    @cached_property
    def basis(self) -> Basis:
        return Basis(self.mesh, ElementTriP2(), intorder=1)

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

    def _edges(self, region: Region) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if isinstance(region, Named):
            raise InputError("named regions are not available on 2D meshes; use Plane, Box or Cylinder")
        nodes, length, normal = self._boundary
        inside = region.contains(self.basis.doflocs, 1e-6 * self.size)
        sel = np.all(inside[nodes[:, :2]], axis=1)  # by the end vertices (a chord's middle is off an arc)
        if not np.any(sel):
            raise InputError(f"{region.describe()} contains no boundary edge of the mesh")
        return nodes[sel], length[sel], normal[sel]

    def load_vector(self, area: np.ndarray | None = None) -> np.ndarray:
        """The consistent nodal load vector ``[2n]`` [N] (node-interleaved DOFs)."""
        b = self.basis
        if area is None:
            area = asm.barycentric_gradients(self.mesh.p, self.mesh.t)[1]
        f = np.zeros(2 * b.N)
        fv = f.reshape(-1, 2)
        t = self.thickness
        for ld in self.loads:
            if isinstance(ld, Gravity):
                rho = self.material.require("density").m_as("kg/m**3")
                g = np.array(ld.acceleration[:2] if ld.acceleration is not None else (0.0, -STANDARD_GRAVITY))
                mids = b.element_dofs[3:]
                for i in range(2):
                    fv[:, i] += np.bincount(mids.ravel(), weights=np.repeat(area[None, :] / 3 * rho * g[i] * t, 3,
                                                                             axis=0).ravel(), minlength=b.N)
                continue
            nodes, length, normal = self._edges(ld.region)
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
        return f

    def held_dofs(self) -> np.ndarray:
        if not self.supports:
            raise ModelError("the model has no supports; add Fixed(...) or Support(...) on a region")
        nodes_all, _, _ = self._boundary
        bverts = np.unique(nodes_all[:, :2])
        held = []
        for s in self.supports:
            inside = np.zeros(self.basis.N, dtype=bool)
            inside[bverts] = s.region.contains(self.basis.doflocs[:, bverts], 1e-6 * self.size)
            if not np.any(inside):
                raise InputError(f"{s.region.describe()} contains no boundary node of the mesh")
            edge_in = inside[nodes_all[:, 0]] & inside[nodes_all[:, 1]]
            nodes = np.unique(np.r_[np.flatnonzero(inside), nodes_all[edge_in, 2]])
            for i, on in enumerate(s.components[:2]):
                if on:
                    held.append(2 * nodes + i)
            if isinstance(s, Support) and s.z and not (s.x or s.y):
                raise InputError("Support(z=True) has no meaning in a 2D model; hold x and/or y")
        return np.unique(np.concatenate(held))

    def solve(self, progress: bool | None = None) -> FieldResults:
        """Assemble, check the supports, solve (sparse direct), project stresses, check equilibrium."""
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
            K = asm.assemble_blocks(asm.elasticity_blocks(m.p, m.t, lam, mu, self.thickness), pattern, 2)
            _, area = asm.barycentric_gradients(m.p, m.t)
            f = self.load_vector(area)
            held = self.held_dofs()
            timings["assembly"] = time.perf_counter() - t0
            u, info = solve(K, f, held, b.doflocs, method="direct", progress=step)
            timings["solve"] = info.seconds
            t1 = time.perf_counter()
            eps = asm.strain_at_nodes(m.p, m.t, b.element_dofs, u, corners_only=True)  # e, 3, 2, 2
            sig = asm.hooke(eps, lam, mu)
            comps = np.stack([sig[..., 0, 0], sig[..., 1, 1], sig[..., 0, 1]], axis=-1)
            s = project(comps, area, b.element_dofs, pattern)
            timings["recovery"] = time.perf_counter() - t1
            reaction, applied = _equilibrium(K, u, f, held, b.doflocs, 2)
        n = b.N
        sigma = np.zeros((n, 3, 3))
        sigma[:, 0, 0], sigma[:, 1, 1] = s[:, 0], s[:, 1]
        sigma[:, 0, 1] = sigma[:, 1, 0] = s[:, 2]
        if self.plane == "strain":
            sigma[:, 2, 2] = nu * (s[:, 0] + s[:, 1])
        pts = np.column_stack([b.doflocs.T, np.zeros(n)])
        uu = np.zeros((n, 3))
        uu[:, :2] = u.reshape(-1, 2)
        return FieldResults(
            kind=f"plane {self.plane}", points=pts, u=uu, sigma=sigma, material=mat,
            reaction=np.r_[reaction, 0.0], applied=np.r_[applied, 0.0],
            cells=[("triangle6", b.element_dofs.T.copy())], surface=m.t.T.copy(), info=info, timings=timings)
