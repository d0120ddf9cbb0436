"""Linear buckling of thin (Kirchhoff) plates under in-plane (membrane) loads: the load factors ``μ`` at which
``(K + μ K_G) φ = 0`` for the plate model of :mod:`mechverify.fea.plate` (Morley triangles).

    >>> from mechverify.components import plates as P
    >>> from mechverify.fea.plate_buckling import InPlaneLoad, plate_buckling
    >>> plate = P.Plate.rectangle("400 mm", "200 mm", "2 mm", "Structural Steel")
    >>> res = plate_buckling(P.PlateModel(plate, supports=(P.EdgeSupport("all"),)), InPlaneLoad(nx="-10 N/mm"),
    ...                      mesh_size="10 mm")
    >>> round(res.first_factor, 1)   # k = 4: N_cr = 4 π² D / b² = 144.6 N/mm (Timoshenko & Gere eq. 9-9)
    14.4

- :class:`InPlaneLoad` - the membrane stress resultants ``N = [[Nx, Nxy], [Nxy, Ny]]`` [N/m, tension positive]
  acting on the plate's outline edges as the tractions ``N n``: uniform, or ``Nx`` varying linearly across the
  plate in y and ``Ny`` in x (in-plane bending of a web; such a field is in equilibrium and compatible).
- :func:`membrane_field` - the stress resultants at the integration points: the given field itself where it is
  exact (an outline without holes or cut-outs), else the plane-stress solution of the plate loaded by those edge
  tractions (quadratic triangles on the plate's own mesh; holes and cut-outs are free edges, so the field
  concentrates around them, ref. 3).
- :func:`geometric_stiffness` - ``K_G = ∫ ∇w · N · ∇v dA`` (ref. 1 Sec. 9.2: the work of the membrane forces on
  the slopes; ref. 2 Sec. 10.2).
- :func:`plate_buckling` - the lowest positive factors: the largest eigenvalues ``θ = 1/μ`` of
  ``-K_G φ = θ K φ`` (dense ``eigh`` for small models, else ARPACK Lanczos on one sparse factorisation of ``K``,
  :func:`mechverify.fea.factor.factorize`). The plate's supports act on the deflection (and slope when clamped)
  only; in its plane the plate is held by nothing but the edge loads (a rigid in-plane motion is removed).

Lateral loads of the plate model are ignored (they cause no membrane force in linear theory). The Morley element is
non-conforming: the factors converge with the square of the element size, not bounded from either side in general.

References
----------
1. S. P. Timoshenko, J. M. Gere, *Theory of Elastic Stability*, 2nd ed., McGraw-Hill 1961, ch. 9 (eq. 9-9: the
   simply supported plate in uniaxial compression, ``N_cr = k π² D / b²``, ``k = (m b/a + a/(m b))²``; Sec. 9.3:
   Levy-type solutions for clamped unloaded edges; Sec. 9.6: in-plane bending; Sec. 9.7: shear).
2. O. C. Zienkiewicz, R. L. Taylor, D. D. Fox, *The Finite Element Method for Solid and Structural Mechanics*,
   7th ed., 2014, ch. 10 (initial-stress matrix).
3. W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., 2008, Chart 4.1 (Kirsch: a
   small circular hole in uniaxial tension, K_t = 3).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from skfem import Basis, BilinearForm, ElementTriMorley, ElementTriP2, ElementVector, FacetBasis, LinearForm, asm
from skfem.helpers import grad

from mechverify.errors import InputError, ModelError
from mechverify.frozen import set_fields
from mechverify.units import QuantityLike, to_si

#: Largest number of free unknowns solved by the dense symmetric eigensolver.
DENSE_LIMIT = 1500
MEMBRANE_METHODS = ("auto", "given", "solve")


def _resultant(v: Any, name: str) -> tuple[float, float]:
    """A stress resultant [N/m] or a pair (at the low and the high side) of them."""
    if isinstance(v, list | tuple):
        if len(v) != 2:
            raise InputError(f"{name}: one value or two (at the low and the high side), got {len(v)}")
        return (to_si(v[0], "force_per_length", f"{name}[0]"), to_si(v[1], "force_per_length", f"{name}[1]"))
    x = 0.0 if v == 0 else to_si(v, "force_per_length", name)
    return (x, x)


@dataclass(frozen=True, init=False)
class HoleForce:
    """An in-plane force ``(fx, fy)`` [N] on the rim of the plate hole named ``hole`` (a pin or bolt bearing on it:
    the cosine pressure distribution of :class:`mechverify.fea.loads.PinLoad`)."""

    hole: str | int
    force: tuple[float, float]

    def __init__(self, hole: str | int, force: Sequence[QuantityLike]):
        if isinstance(force, str) or len(force) != 2:
            raise InputError(f"HoleForce.force: expected two components (fx, fy), got {force!r}")
        f = tuple(to_si(v, "force", f"force[{i}]") for i, v in enumerate(force))
        if not any(f):
            raise InputError("HoleForce.force: the force must not be zero")
        set_fields(self, hole=hole, force=f)


@dataclass(frozen=True)
class InPlaneLoad:
    """Membrane stress resultants on the plate's outline edges (force per length, tension positive):
    ``nx`` (one value, or a pair: at the lowest and the highest y of the plate, linear between), ``ny`` (one value
    or a pair at the lowest and highest x), ``nxy`` (uniform). The outline edges carry the tractions ``N n`` of
    this field; holes and cut-outs are free, except that ``hole_loads`` (:class:`HoleForce`) press on hole rims."""

    nx: QuantityLike | Sequence[QuantityLike] | float = 0.0
    ny: QuantityLike | Sequence[QuantityLike] | float = 0.0
    nxy: QuantityLike | float = 0.0
    hole_loads: tuple[HoleForce, ...] = ()

    def values(self) -> tuple[tuple[float, float], tuple[float, float], float]:
        """``((nx_low, nx_high), (ny_low, ny_high), nxy)`` [N/m]."""
        nx, ny = _resultant(self.nx, "nx"), _resultant(self.ny, "ny")
        nxy = 0.0 if self.nxy == 0 else to_si(self.nxy, "force_per_length", "nxy")
        if not any((*nx, *ny, nxy)) and not self.hole_loads:
            raise InputError("in-plane load: nx, ny and nxy are all zero and no hole loads, so nothing loads the "
                             "plate in its plane")
        if not all(isinstance(h, HoleForce) for h in self.hole_loads):
            raise InputError(f"in-plane load: hole_loads must be HoleForce items, got {self.hole_loads!r}")
        return nx, ny, nxy

    @property
    def has_edge_loads(self) -> bool:
        """Whether nx, ny or nxy is not zero."""
        nx, ny, nxy = self.values()
        return any((*nx, *ny, nxy))

    def field(self, bounds: tuple[float, float, float, float]) -> Any:
        """``N(x, y) -> (Nxx, Nyy, Nxy)`` arrays [N/m] of this load on a plate with ``bounds`` (x0, y0, x1, y1)."""
        (a0, a1), (b0, b1), nxy = self.values()
        x0, y0, x1, y1 = bounds

        def N(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            sy = (y - y0) / (y1 - y0)
            sx = (x - x0) / (x1 - x0)
            return a0 + (a1 - a0) * sy, b0 + (b1 - b0) * sx, np.full_like(x, nxy)

        return N


def nominal_membrane_von_mises(load: InPlaneLoad, bounds: tuple[float, float, float, float], thickness: float
                               ) -> float:
    """The largest von Mises stress [Pa] of the in-plane ``load``'s own field ``N / t`` on a plate with ``bounds``
    [m] and ``thickness`` [m]: the field is linear, so the peak of the (convex) von Mises norm is at a corner
    (Hill, The Mathematical Theory of Plasticity, 1950: the von Mises criterion). Before any concentration at
    holes (Kirsch: up to 3x the nominal stress at a round hole under uniaxial load)."""
    N = load.field(bounds)
    x0, y0, x1, y1 = bounds
    nxx, nyy, nxy = (np.asarray(c, float) / thickness for c in N(np.array([x0, x1, x0, x1]),
                                                                np.array([y0, y0, y1, y1])))
    return float(np.max(np.sqrt(nxx**2 - nxx * nyy + nyy**2 + 3 * nxy**2)))


@dataclass(frozen=True, eq=False)
class PlateBuckling:
    """Buckling load factors ``factors[k]`` (ascending, positive, multiplying the in-plane load), mode shapes
    ``shapes[k, n, 3]`` (deflection along z at the vertices, largest 1), ``points[n, 3]`` [m] and ``triangles``;
    ``membrane[e, q, 3]`` the stress resultants (Nxx, Nyy, Nxy) [N/m] at the integration points of the load as
    given, ``membrane_method`` "given" or "solve"."""

    factors: np.ndarray
    shapes: np.ndarray
    points: np.ndarray
    triangles: np.ndarray
    membrane: np.ndarray
    membrane_method: str
    unknowns: int
    notes: tuple[str, ...] = ()

    @property
    def first_factor(self) -> float:
        """The lowest positive buckling load factor."""
        return float(self.factors[0])


def _outline_facets(sys_: Any) -> np.ndarray:
    """Boundary facets lying on the plate's declared outline (not on holes, cut-outs or notches)."""
    import shapely

    m = sys_.mesh
    f = sys_.bfacets
    ring = shapely.LinearRing(sys_.plate.outline)
    tol = 1e-6 * float(np.sqrt(sys_.plate.region.area))
    P = m.p[:, m.facets[:, f]]  # 2, 2, k
    d = [shapely.distance(shapely.points(P[0, i], P[1, i]), ring) for i in range(2)]
    return f[(d[0] <= tol) & (d[1] <= tol)]


def _plane_stress_field(sys_: Any, N: Any, quad: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, list[str]]:
    """Stress resultants ``[3, e, q]`` at the points of ``quad`` of the plate loaded in its plane by the tractions
    ``N n`` on the outline (P2 plane stress; a rigid in-plane motion removed at three unknowns)."""
    from skfem.helpers import dot, sym_grad, trace

    m, t, E, nu = sys_.mesh, sys_.t, sys_.E, sys_.nu
    e = ElementVector(ElementTriP2())
    ib = Basis(m, e)
    lam, mu = E * nu / (1 - nu**2), E / (2 * (1 + nu))  # plane stress: λ* = 2λμ/(λ + 2μ)

    @BilinearForm
    def membrane(u: Any, v: Any, w: Any) -> Any:
        eu, ev = sym_grad(u), sym_grad(v)
        return t * (2 * mu * (eu[0, 0] * ev[0, 0] + eu[1, 1] * ev[1, 1] + 2 * eu[0, 1] * ev[0, 1])
                    + lam * trace(eu) * trace(ev))

    facets = _outline_facets(sys_)
    fb = FacetBasis(m, e, facets=facets, intorder=4)

    @LinearForm
    def traction(v: Any, w: Any) -> Any:
        nxx, nyy, nxy = N(w.x[0], w.x[1])
        n = w.n
        return dot(np.array([nxx * n[0] + nxy * n[1], nxy * n[0] + nyy * n[1]]), v)

    K = asm(membrane, ib).tocsr()
    f = asm(traction, fb)
    # remove the rigid in-plane motion: hold x and y at the vertex nearest the centroid, and the motion normal
    # to the line to the farthest vertex there
    c = m.p.mean(axis=1)
    a = int(np.argmin(np.linalg.norm(m.p - c[:, None], axis=0)))
    b = int(np.argmax(np.linalg.norm(m.p - m.p[:, [a]], axis=0)))
    d = m.p[:, b] - m.p[:, a]
    nd = ib.nodal_dofs  # [2, nvertices]
    held = [int(nd[0, a]), int(nd[1, a]), int(nd[0 if abs(d[1]) >= abs(d[0]) else 1, b])]
    free = np.setdiff1d(np.arange(K.shape[0]), held)
    from mechverify.fea.factor import factorize

    u = np.zeros(K.shape[0])
    u[free] = factorize(K[free][:, free], what="the plate's in-plane stiffness").solve(f[free])
    r = K @ u - f
    scale = float(np.sum(np.abs(f))) or 1.0
    if np.max(np.abs(r[held])) > 1e-6 * scale:
        raise InputError("in-plane load: the outline's edge loads are not in equilibrium (a cut-out or notch on the "
                         "outline breaks the loaded edges?): the plate would need in-plane supports, which are not "
                         "modelled")
    qb = Basis(m, e, quadrature=quad)
    g = qb.interpolate(u).grad  # 2, 2, e, q
    exx, eyy, exy = g[0, 0], g[1, 1], 0.5 * (g[0, 1] + g[1, 0])
    tr = exx + eyy
    nxx = t * (2 * mu * exx + lam * tr)
    nyy = t * (2 * mu * eyy + lam * tr)
    nxy = t * 2 * mu * exy
    return np.array([nxx, nyy, nxy]), [f"membrane field: P2 plane stress on the plate mesh, edge loads on "
                                       f"{len(facets)} outline edges"]


def _supported_field(sys_: Any, load: InPlaneLoad, quad: tuple[np.ndarray, np.ndarray], supports: tuple[Any, ...],
                     mesh: Any) -> tuple[np.ndarray, list[str]]:
    """Stress resultants ``[3, e, q]`` at the points of ``quad`` of the membrane problem with in-plane supports or hole
    loads (:func:`mechverify.fea.plate_stress.membrane_stress`, solved on ``mesh``, the plate's unsorted mesh whose
    triangles are those of the system's mesh in the same order): its recovered P2 nodal stresses interpolated at the
    points (barycentric coordinates in each straight triangle)."""
    from mechverify.fea.plate_stress import membrane_stress

    ms = membrane_stress(sys_.plate, mesh, load, "solve", supports)
    res = ms.field
    qb = Basis(sys_.mesh, ElementTriP2(), quadrature=quad)
    x = np.asarray(qb.global_coordinates())  # 2, e, q
    el = np.asarray(res.elements)  # e, 6
    P = res.points[el[:, :3], :2]  # e, 3, 2
    T = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]], axis=2)  # e, 2, 2
    rhs = x.transpose(1, 2, 0) - P[:, None, 0, :]  # e, q, 2
    lam = np.linalg.solve(np.broadcast_to(T[:, None], rhs.shape[:2] + (2, 2)), rhs[..., None])[..., 0]
    l1, l2 = lam[..., 0], lam[..., 1]
    l0 = 1 - l1 - l2
    N = np.stack([l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l0 * l2])
    s = res.sigma
    comps = np.stack([s[:, 0, 0], s[:, 1, 1], s[:, 0, 1]]) * sys_.t  # 3, nodes
    field = np.einsum("aeq,cae->ceq", N, comps[:, el.T])
    return field, [*ms.notes, *ms.warnings]


def membrane_field(sys_: Any, load: InPlaneLoad, quad: tuple[np.ndarray, np.ndarray], method: str = "auto",
                   supports: tuple[Any, ...] = (), mesh: Any = None) -> tuple[np.ndarray, str, list[str]]:
    """Stress resultants ``[3, e, q]`` [N/m] (Nxx, Nyy, Nxy) at the points of ``quad`` on the plate system's mesh, the
    method used ("given": the load's own field, exact for an outline without holes or cut-outs; "solve": the
    plane-stress solution of the edge loads) and notes. With in-plane ``supports``
    (:class:`mechverify.fea.plate_stress.InPlaneSupport`) or hole loads, the field is that of
    :func:`mechverify.fea.plate_stress.membrane_stress` on ``mesh`` (the plate's own mesh), interpolated."""
    if method not in MEMBRANE_METHODS:
        raise InputError(f"membrane: one of {', '.join(MEMBRANE_METHODS)}, got {method!r}")
    if supports or load.hole_loads:
        if method == "given":
            raise InputError("membrane: 'given' takes the edge loads' own field; in-plane supports and hole loads "
                             "need 'solve'")
        field, notes = _supported_field(sys_, load, quad, tuple(supports), mesh)
        return field, "solve", notes
    plate = sys_.plate
    N = load.field(plate.region.bounds)
    if method == "auto":
        method = "solve" if (plate.holes or plate.cutouts) else "given"
    if method == "solve":
        field, notes = _plane_stress_field(sys_, N, quad)
        return field, "solve", notes
    qb = Basis(sys_.mesh, ElementTriP2(), quadrature=quad)
    x = np.asarray(qb.global_coordinates())  # 2, e, q
    return np.array(N(x[0], x[1])), "given", ["membrane field: the given stress resultants (no holes or cut-outs)"]


def geometric_stiffness(basis: Any, field: np.ndarray) -> sp.csr_matrix:
    """``K_G = ∫ ∇w · N · ∇v dA`` [N/m] of the Morley ``basis`` for the stress resultants ``field[3, e, q]`` at its
    integration points (ref. 1 Sec. 9.2, ref. 2 ch. 10)."""

    @BilinearForm
    def kg(u: Any, v: Any, w: Any) -> Any:
        gu, gv = grad(u), grad(v)
        return (w["nxx"] * gu[0] * gv[0] + w["nyy"] * gu[1] * gv[1]
                + w["nxy"] * (gu[0] * gv[1] + gu[1] * gv[0]))

    return asm(kg, basis, nxx=field[0], nyy=field[1], nxy=field[2]).tocsr()


def _no_compression() -> ModelError:
    """The error of a load that compresses nothing: :class:`mechverify.fea.frame.modal.NoCompressionError` (a
    ModelError), so a design file's pull case passes as 'cannot buckle' as a frame's does."""
    from mechverify.fea.frame.modal import NoCompressionError

    return NoCompressionError("plate buckling: the in-plane load compresses no part of the plate, so it cannot buckle "
                              "(reverse the load to study the other direction)")


def _lower_bound(sys_: Any, gb: Any, Kf: Any, F: Any, free: np.ndarray, ndof: int, n_c: float, field: np.ndarray,
                 method: str, notes: list[str]) -> PlateBuckling:
    """A lower bound of the buckling factor when the eigensolver does not converge on the load's own field (a
    field that is mostly tension, with a little compression in corners: its positive eigenvalues are tiny and
    crowded): the membrane field's compression nowhere exceeds ``n_c`` [N/m] in any direction, so
    ``-K_G <= n_c L`` with ``L`` the geometric stiffness of a uniform biaxial compression of 1 N/m (a Rayleigh
    quotient bound, ref. 1 Sec. 9.2), and the factor is at least ``μ_1 / n_c`` with ``μ_1`` that compression's
    (well-conditioned) buckling factor. Returns it as the only factor, its mode the biaxial one, with a note."""
    iso = np.zeros_like(field)
    iso[0], iso[1] = -1.0, -1.0
    Lf = (-geometric_stiffness(gb, iso))[free][:, free]
    try:
        th, V = spl.eigsh(Lf.tocsc(), k=1, M=Kf.tocsc(), Minv=F.operator(), which="LA", tol=1e-8, maxiter=5000,
                          v0=np.random.default_rng(0).standard_normal(free.size))
    except spl.ArpackNoConvergence:
        raise ModelError("plate buckling: the eigensolver did not converge (the compressed region is tiny, or its "
                         "buckling factors lie very close together); ask fewer modes or change the mesh") from None
    bound = 1.0 / (float(th[0]) * n_c)
    full = np.zeros(ndof)
    full[free] = V[:, 0]
    n = sys_.mesh.nvertices
    shape = np.zeros((1, n, 3))
    w = full[sys_.basis.nodal_dofs[0]]
    shape[0, :, 2] = w / (w[np.argmax(np.abs(w))] or 1.0)
    note = (f"LOWER BOUND: the eigensolver did not converge on this field (mostly tension, its largest compression "
            f"only {n_c / 1e3:.4g} N/mm); the factor is at least {bound:.4g} = (buckling factor of a uniform biaxial "
            f"compression of 1 N/m, {1.0 / float(th[0]):.4g}) / (the largest compression), a Rayleigh-quotient bound; "
            "the mode shown is that of the biaxial compression")
    return PlateBuckling(np.array([bound]), shape, np.column_stack([sys_.mesh.p.T, np.zeros(n)]),
                         sys_.mesh.t.T.copy(), np.moveaxis(field, 0, -1), method, int(free.size), (*notes, note))


def plate_buckling(model: Any, load: InPlaneLoad, n_modes: int = 1, mesh_size: QuantityLike | None = None,
                   hole_mesh_size: QuantityLike | None = None, *, membrane: str = "auto",
                   in_plane_supports: tuple[Any, ...] = ()) -> PlateBuckling:
    """The lowest ``n_modes`` positive buckling load factors and mode shapes of the
    :class:`mechverify.components.plates.PlateModel` ``model`` (its supports hold the deflection; its lateral loads
    are ignored) under the in-plane ``load`` (:class:`InPlaneLoad`).

    ``mesh_size`` and ``hole_mesh_size`` as for :func:`mechverify.fea.plate.solve_plate`; ``membrane``: "auto" (the
    given field on a plate without holes or cut-outs, else solved), "given" or "solve" (see :func:`membrane_field`);
    ``in_plane_supports``: :class:`mechverify.fea.plate_stress.InPlaneSupport` items holding the plate in its plane
    (with them, or with ``load.hole_loads``, the membrane field is solved with them).
    A load that compresses nothing (no positive factor) is a :class:`ModelError`; supports that leave a rigid motion
    free are a :class:`ModelError` naming it; asking for as many modes as free unknowns is an :class:`InputError`.
    """
    from mechverify.components import plates as P
    from mechverify.fea.plate import _PlateSystem, _stiffness, _supports, check_plate_supported, plate_mesh

    if not isinstance(model, P.PlateModel):
        raise InputError(f"plate_buckling: expected a mechverify.components.plates.PlateModel, got {model!r}")
    if not isinstance(load, InPlaneLoad):
        raise InputError(f"plate_buckling: expected an InPlaneLoad, got {load!r}")
    n_modes = int(n_modes)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    load.values()
    h = None if mesh_size is None else to_si(mesh_size, "length", "mesh_size")
    hh = None if hole_mesh_size is None else to_si(hole_mesh_size, "length", "hole_mesh_size")
    mesh = plate_mesh(model.plate, h, hh)
    sys_ = _PlateSystem(model, mesh)
    K = _stiffness(sys_).tocsr()
    held, held_pts, normals, _ = _supports(sys_)
    check_plate_supported(held_pts, normals)
    free = np.setdiff1d(np.arange(K.shape[0]), held)
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} modes asked, but the plate mesh has only {free.size} free unknowns; "
                         "refine the mesh or ask fewer")
    gb = Basis(sys_.mesh, ElementTriMorley(), intorder=4)
    field, method, notes = membrane_field(sys_, load, (gb.quadrature[0], gb.quadrature[1]), membrane,
                                          tuple(in_plane_supports), mesh)
    nxx, nyy, nxy = field
    n_min = (nxx + nyy) / 2 - np.sqrt(((nxx - nyy) / 2) ** 2 + nxy**2)  # the smaller principal stress resultant
    if not np.any(n_min < -1e-9 * max(float(np.max(np.abs(field))), 1e-300)):
        raise _no_compression()
    G = geometric_stiffness(gb, field)
    Kf, Gf = K[free][:, free], G[free][:, free]
    if free.size <= DENSE_LIMIT:
        th, V = sla.eigh(-Gf.toarray(), Kf.toarray())
    else:
        from mechverify.fea.factor import factorize

        F = factorize(Kf, what="the plate's bending stiffness")
        k = min(n_modes + 4, free.size - 1)
        try:
            th, V = spl.eigsh(-Gf.tocsc(), k=k, M=Kf.tocsc(), Minv=F.operator(), which="LA", tol=1e-10,
                              maxiter=300, v0=np.random.default_rng(0).standard_normal(free.size))
        except spl.ArpackNoConvergence:
            return _lower_bound(sys_, gb, Kf, F, free, K.shape[0], float(np.max(-n_min)), field, method, notes)
    order = np.argsort(-th)
    th, V = th[order], V[:, order]
    pos = th > 1e-9 * max(float(np.max(np.abs(th))), 1e-300)
    th, V = th[pos][:n_modes], V[:, pos][:, :n_modes]
    if not len(th):
        raise _no_compression()
    full = np.zeros((K.shape[0], len(th)))
    full[free] = V
    vd = sys_.basis.nodal_dofs[0]
    n = sys_.mesh.nvertices
    shapes = np.zeros((len(th), n, 3))
    shapes[:, :, 2] = full[vd].T
    for k in range(len(th)):
        w = shapes[k, :, 2]
        shapes[k] /= w[np.argmax(np.abs(w))] if np.max(np.abs(w)) > 0 else 1.0
    pts = np.column_stack([sys_.mesh.p.T, np.zeros(n)])
    return PlateBuckling(1.0 / th, shapes, pts, sys_.mesh.t.T.copy(), np.moveaxis(field, 0, -1), method,
                         int(free.size), tuple(notes))
