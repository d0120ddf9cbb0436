"""A rotation-free pin support on a hole wall: the wall's displacement held **radially**, free tangentially
(the part turns about the pin) and, unless ``axial``, along the pin's axis - a frictionless pin, bilateral.

This is the standard linear model of a pin in a hole (ANSYS "cylindrical support" with the radial direction fixed
and the tangential one free; Abaqus/CalculiX ``*TRANSFORM, TYPE=C`` and a boundary condition on the radial DOF).
It is **not** a contact model: a real pin bears on half the wall and only pushes; here the whole wall is held
radially both ways, so a wall that would lift off the pin is held to it. The part is not clamped at the hole: a
beam on two pinned holes deflects as a pinned-pinned beam (``tests/validation/test_shigley_pinned_beam_solid.py``),
where holding the whole wall (``Fixed``) clamps the section.

How: every node of the wall gets its own axes, ``[e_r, e_θ, e_z]`` (radial from the fitted axis, tangential, axial),
and the displacement there is written in them, ``u = T u'`` with ``T`` block-diagonal and orthogonal (identity away
from the pins). The stiffness becomes ``K' = Tᵀ K T`` (the same sparsity, still symmetric positive definite, so
the factorisation and multigrid CG work unchanged), the loads ``f' = Tᵀ f``, the mass ``M' = Tᵀ M T``; the radial
DOF (and the axial one with ``axial = true``) is then held like any other, and ``u = T u'``, the reactions
``r = T r'``. No penalty. The rigid-body check uses the rotated rigid motions ``Tᵀ B``: one pin leaves the slide
along its axis and the rotation about it free (named), two parallel pins the slide only.

The wall's axis, centre and radius are fitted to its nodes (:func:`fit_cylinder`): the axis is the direction the
facet normals of a cylinder are all perpendicular to, the circle a least-squares fit of the vertices projected
across it; a region that is not a cylinder within :data:`CYLINDER_RTOL` of its radius is refused.

References
----------
1. Cook, Malkus, Plesha & Witt, Concepts and Applications of Finite Element Analysis, 4th ed., Wiley 2002 (skew
   supports: nodal DOFs in rotated axes, ``K' = Tᵀ K T``; the section number not checked here).
2. Dhondt, CalculiX CrunchiX User's Manual, the ``*TRANSFORM`` keyword (cylindrical local axes for boundary
   conditions; section number not checked here).
3. Shakarji, "Least-squares fitting algorithms of the NIST algorithm testing system", J. Res. NIST 103 (1998)
   633-641 (cylinder fit: the geometric distances minimised by Gauss-Newton from an algebraic start).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp

from mechverify.errors import InputError

#: A pin's wall must lie within this fraction of its fitted radius of a cylinder (its vertices: a mesh of a true
#: cylinder puts them on it to round-off; a cone's or a sphere's miss any cylinder by far more). The facet normals
#: only start the fit: a coarse mesh's triangles across a hole lean along its axis (0.16 on a 6 mm hole of a STEP file).
CYLINDER_RTOL = 0.02
#: A load with more than this share of its nodal forces on a pin's held DOFs is said to go into the pin (WARN).
PINNED_LOAD_SHARE = 0.5
#: Below this share of the normals' scatter across the axis the region is flat (a plane face), not a cylinder.
FLAT_RTOL = 0.02


@dataclass(frozen=True)
class CylinderFit:
    """A cylinder fitted to a wall: a point ``center[3]`` on the axis (at the nodes' mean axial position), the unit
    ``axis[3]``, the ``radius`` [m] and the largest radial deviation of the wall's vertices from it [m]."""

    center: np.ndarray
    axis: np.ndarray
    radius: float
    deviation: float

    def describe(self) -> str:
        c = ", ".join(f"{v * 1e3:.4g}" for v in self.center)
        a = ", ".join(f"{v:.4g}" for v in (self.axis + 0.0))
        return f"cylinder r = {self.radius * 1e3:.4g} mm, axis ({a}) through ({c}) mm"


def _circle(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float]:
    """Least-squares circle through ``(x, y)``: algebraic (Kasa) start, then Gauss-Newton on the distances."""
    A = np.column_stack([x, y, np.ones_like(x)])
    sol, *_ = np.linalg.lstsq(A, -(x * x + y * y), rcond=None)
    cx, cy = -sol[0] / 2, -sol[1] / 2
    r = float(np.sqrt(max(cx * cx + cy * cy - sol[2], 0.0)))
    for _ in range(20):
        dx, dy = x - cx, y - cy
        d = np.hypot(dx, dy)
        d = np.where(d > 0, d, 1e-300)
        J = np.column_stack([-dx / d, -dy / d, -np.ones_like(d)])
        step, *_ = np.linalg.lstsq(J, -(d - r), rcond=None)
        cx, cy, r = cx + step[0], cy + step[1], r + step[2]
        if np.max(np.abs(step)) <= 1e-13 * max(abs(r), 1e-300):
            break
    return float(cx), float(cy), float(abs(r))


def _refine(points: np.ndarray, axis: np.ndarray, p: np.ndarray, q: np.ndarray, start: tuple[float, float, float]
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[float, float, float]]:
    """The axis tilted and the circle moved to minimise the vertices' radial distances (Gauss-Newton, ref. 3): the
    facet normals of a faceted cylinder lean a little along the axis, the vertices lie on the cylinder."""
    def frame(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        a = axis + t[0] * p + t[1] * q
        a = a / np.linalg.norm(a)
        pp = p - (p @ a) * a
        pp = pp / np.linalg.norm(pp)
        return a, pp, np.cross(a, pp)

    def residual(t: np.ndarray) -> np.ndarray:
        _, pp, qq = frame(t)
        return np.hypot(pp @ points - t[2], qq @ points - t[3]) - t[4]

    t = np.array([0.0, 0.0, *start])
    step = np.array([1e-7, 1e-7, *[1e-7 * start[2]] * 3])  # central differences (scipy.optimize costs 0.8 s to import)
    for _ in range(30):
        res = residual(t)
        J = np.column_stack([(residual(t + e) - residual(t - e)) / (2 * e[k]) for k, e in enumerate(np.diag(step))])
        dt, *_ = np.linalg.lstsq(J, -res, rcond=None)
        t = t + dt
        if np.all(np.abs(dt) <= 1e-12 * np.r_[1.0, 1.0, [abs(start[2])] * 3]):
            break
    a, pp, qq = frame(t)
    return a, pp, qq, (float(t[2]), float(t[3]), float(abs(t[4])))


def fit_cylinder(points: np.ndarray, normals: np.ndarray, areas: np.ndarray, what: str) -> CylinderFit:
    """The cylinder of a wall: vertices ``points[3, k]`` [m], its facets' unit normals ``normals[m, 3]`` and areas
    ``areas[m]``. :class:`InputError` (``what`` names the region) when the wall is flat or not a cylinder within
    :data:`CYLINDER_RTOL` of its radius."""
    S = np.einsum("k,ki,kj->ij", areas, normals, normals)
    w, V = np.linalg.eigh(S)
    total = float(np.trace(S))
    if total <= 0 or points.shape[1] < 4:
        raise InputError(f"{what}: a pin needs a hole wall (a cylindrical face); the region has too few facets")
    if w[1] < FLAT_RTOL * total:
        raise InputError(f"{what}: a pin needs a hole wall (a cylindrical face); this region is flat (its facets all "
                         "face one way). Hold a flat face with hold = \"...\" instead")
    axis = V[:, 0]
    axis = axis * (1 if axis[np.argmax(np.abs(axis))] > 0 else -1)
    p = V[:, 1]
    q = np.cross(axis, p)
    x, y = p @ points, q @ points
    cx, cy, r = _circle(x, y)
    axis, p, q, (cx, cy, r) = _refine(points, axis, p, q, (cx, cy, r))
    x, y = p @ points, q @ points
    along = float(np.mean(axis @ points))
    center = cx * p + cy * q + along * axis
    dev = float(np.max(np.abs(np.hypot(x - cx, y - cy) - r)))
    fit = CylinderFit(center, axis, r, dev)
    if dev > CYLINDER_RTOL * r:
        raise InputError(f"{what}: a pin needs a hole wall (a cylindrical face); the region is not a cylinder: the "
                         f"best fit, {fit.describe()}, misses its nodes by up to {dev * 1e3:.3g} mm "
                         f"({dev / r:.1%} of the radius; {CYLINDER_RTOL:.0%} allowed)")
    return fit


def same_cylinder(a: CylinderFit, b: CylinderFit, rtol: float = CYLINDER_RTOL) -> bool:
    """Whether two fits are one cylinder (two faces of one hole, split by the CAD system, pinned each): parallel axes
    (within 1 mrad), the axes within ``rtol`` of the radius of each other, the radii within ``rtol``."""
    d = b.center - a.center
    off = d - (d @ a.axis) * a.axis
    return bool(abs(a.axis @ b.axis) >= 1 - 5e-7 and np.linalg.norm(off) <= rtol * a.radius
                and abs(a.radius - b.radius) <= rtol * a.radius)


def frames(points: np.ndarray, fit: CylinderFit) -> np.ndarray:
    """The pin axes ``[k, 3, 3]`` of nodes ``points[3, k]``: columns ``e_r`` (radial from the axis), ``e_θ`` and
    ``e_z`` (the axis), a right-handed orthonormal frame per node."""
    a = fit.axis
    d = points.T - fit.center[None, :]
    d = d - (d @ a)[:, None] * a[None, :]
    n = np.linalg.norm(d, axis=1)
    if np.any(n <= 1e-9 * fit.radius):
        raise InputError("a pin's wall node lies on its axis")
    er = d / n[:, None]
    et = np.cross(np.broadcast_to(a, er.shape), er)
    return np.stack([er, et, np.broadcast_to(a, er.shape)], axis=2)


@dataclass(frozen=True, eq=False)
class DofBasis:
    """The DOF axes of a model with pins: ``R[n, 3, 3]`` per node (columns: the node's axes in x, y, z; identity
    away from the pins), the ``rotated`` node indices, ``held`` DOFs in these axes, ``pinned[k]`` the nodes of each
    pin support (by support index) and ``fits`` their cylinders. ``u = T u'`` (:meth:`outward`)."""

    R: np.ndarray
    rotated: np.ndarray
    held: np.ndarray
    fits: dict[int, CylinderFit]
    pinned: dict[int, np.ndarray]

    @property
    def T(self) -> sp.csr_matrix:
        """``T[3n, 3n]``: block-diagonal, orthogonal; ``u = T u'``."""
        n = self.R.shape[0]
        return sp.block_diag(list(self.R), format="csr") if n < 64 else _block_diag(self.R)

    def rotate(self, A: sp.spmatrix) -> sp.bsr_matrix:
        """``Tᵀ A T`` of a node-interleaved ``A`` (3x3 BSR, the assembly's format), keeping its sparsity and block
        order; the blocks away from the pins are untouched."""
        A = A.tobsr(blocksize=(3, 3)) if not (sp.issparse(A) and A.format == "bsr" and A.blocksize == (3, 3)) \
            else A.copy()
        rows = np.repeat(np.arange(A.shape[0] // 3), np.diff(A.indptr))
        cols = A.indices
        on = np.zeros(self.R.shape[0], bool)
        on[self.rotated] = True
        touch = np.flatnonzero(on[rows] | on[cols])
        A.data[touch] = np.einsum("bji,bjk,bkl->bil", self.R[rows[touch]], A.data[touch], self.R[cols[touch]])
        return A

    def inward(self, f: np.ndarray) -> np.ndarray:
        """``Tᵀ f`` of node-interleaved vectors ``f[3n]`` or ``f[3n, k]``."""
        return self._apply(f, transpose=True)

    def outward(self, u: np.ndarray) -> np.ndarray:
        """``T u'``: displacements (or reactions) ``[3n]`` or ``[3n, k]`` from the pin axes back to x, y, z."""
        return self._apply(u, transpose=False)

    def _apply(self, v: np.ndarray, transpose: bool) -> np.ndarray:
        v = np.asarray(v, dtype=float)
        out = v.copy()
        n = self.R.shape[0]
        V = v.reshape(n, 3, -1)[self.rotated]
        R = self.R[self.rotated]
        out.reshape(n, 3, -1)[self.rotated] = np.einsum("kji,kjc->kic" if transpose else "kij,kjc->kic", R, V)
        return out

    def prolongation(self, P: sp.spmatrix) -> sp.csr_matrix:
        """The P1 -> P2 interpolation in the pin axes, ``Tᵀ P T₁`` (``T₁``: the vertices' axes; vertices are
        the first nodes), for the multigrid's coarse level."""
        T = self.T
        nv = P.shape[1]
        return (T.T @ P @ T[:nv][:, :nv]).tocsr()

    def load_warnings(self, loads: Sequence[Any], parts: Sequence[np.ndarray], named: Sequence[str]) -> tuple[str, ...]:
        """A warning for each load (nodal forces ``parts`` in these axes; not one of ``named``, those already said to
        act only on held DOFs) of which more than :data:`PINNED_LOAD_SHARE` falls on a pin's held DOFs: a load on a
        pinned wall (a ``PinLoad`` on the pinned hole) goes mostly straight into the pin."""
        on = np.zeros(self.R.shape[0] * 3, bool)
        on[self.held] = True
        pin_dofs = np.zeros_like(on)
        for nodes in self.pinned.values():
            pin_dofs[3 * nodes] = pin_dofs[3 * nodes + 2] = True
        on &= pin_dofs
        out = []
        for i, (ld, fi) in enumerate(zip(loads, parts, strict=True)):
            total = float(np.abs(fi).sum())
            region = getattr(ld, "region", None)
            name = f"load {i} ({type(ld).__name__.lower()}" + (f" on {region.describe()})" if region else ")")
            share = float(np.abs(fi[on]).sum()) / total if total > 0 else 0.0
            if share > PINNED_LOAD_SHARE and name not in named:
                out.append(f"{name} acts on a pinned wall: {share:.0%} of its nodal forces go straight into the pin "
                           "(the wall is held radially there) and load nothing; load the part elsewhere, or model the "
                           "pin as a load on an unsupported hole (pin_loads)")
        return tuple(out)

    def calculix(self, axial: Sequence[bool]) -> tuple[list[str], list[str]]:
        """The pins in a CalculiX deck: per pin ``k`` the node set ``PIN<k>`` with its cylindrical ``*TRANSFORM,
        TYPE=C`` (two points on the fitted axis; local direction 1 radial, 2 tangential, 3 axial), to go before
        ``*MATERIAL``, and the ``*BOUNDARY`` lines (radial, and axial where ``axial[k]``) for the step. The same
        model (``tests/validation/test_calculix_pinned_beam.py``: displacements agree to 1.6e-6)."""
        from mechverify.fea.calculix import fortran_field

        sets, bc = [], []
        for k, nodes in self.pinned.items():
            fit = self.fits[k]
            a, c = fit.center, fit.center + fit.radius * fit.axis
            sets.append(f"*NSET, NSET=PIN{k}")
            sets += [", ".join(str(n + 1) for n in nodes[i:i + 8]) for i in range(0, nodes.size, 8)]
            sets += [f"*TRANSFORM, NSET=PIN{k}, TYPE=C", ", ".join(fortran_field(float(v)) for v in (*a, *c))]
            bc += [f"PIN{k}, 1, 1"] + ([f"PIN{k}, 3, 3"] if axial[k] else [])
        return sets, bc

    def rigid_modes(self, points: np.ndarray) -> tuple[np.ndarray, list[str]]:
        """The rigid motions of :func:`mechverify.fea.linsolve.rigid_modes` in the pin axes (``Tᵀ B``)."""
        from mechverify.fea.linsolve import rigid_modes

        B, names = rigid_modes(points)
        return self.inward(B), names

    def check_supported(self, points: np.ndarray, held: np.ndarray | None = None) -> None:
        """:func:`mechverify.fea.linsolve.check_supported` with the rotated rigid motions: a :class:`ModelError`
        naming every rigid motion the held DOFs (default :attr:`held`) do not prevent."""
        check_supported(points, self.held if held is None else held, self.R)


def _block_diag(R: np.ndarray) -> sp.csr_matrix:
    n = R.shape[0]
    return sp.bsr_matrix((R, np.arange(n), np.arange(n + 1)), shape=(3 * n, 3 * n)).tocsr()


def checked_held(model: Any) -> np.ndarray:
    """The DOFs ``model``'s supports hold, in the axes it is solved in (the pins' at pinned wall nodes,
    ``model.dof_basis``; x, y, z otherwise), sorted and unique, after the rigid-motion check (a
    :class:`ModelError` naming every motion they leave free): what a static, modal or buckling solve removes."""
    basis = getattr(model, "dof_basis", None)
    if basis is None:
        from mechverify.fea.linsolve import check_supported as check

        held = np.unique(model.held_dofs())
        check(model.nodes, held)
        return held
    held = np.unique(model.held_in_axes()[0])
    basis.check_supported(model.nodes, held)
    return held


def check_supported(points: np.ndarray, held: np.ndarray, R: np.ndarray | None = None) -> None:
    """Raise :class:`ModelError` naming every rigid motion that the DOFs ``held`` (in the node axes ``R[n, 3, 3]``;
    None: x, y, z) do not prevent (:func:`mechverify.fea.linsolve.check_supported` with the pins' axes)."""
    from mechverify.fea.linsolve import check_supported as check

    check(points, held, axes=R, hint=" (a pin leaves the rotation about its axis and, without axial = true, the "
                                     "slide along it free)" if R is not None else "")
