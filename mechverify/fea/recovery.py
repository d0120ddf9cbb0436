"""Stress recovery: the element-wise stress field of P2 elements smoothed to the nodes, and the error
indicator that comes with it.

Three methods (:data:`METHODS`), compared on published benchmarks in ``docs/verification.md``:

- ``"spr"`` - superconvergent patch recovery (ref. 2): least-squares quadratic fits to the stresses at
  the integration points of each interior vertex's patch, averaged at every node they reach;
- ``"average"`` - extrapolate-and-average (what CalculiX does): each element's stress at its nodes,
  averaged over the elements sharing the node;
- ``"projection"`` - L2 projection onto continuous P2 (ref. 1), described next.

The stress of a straight-sided P2 element is linear (P1, discontinuous between elements). Its L2
projection onto the continuous P2 space solves ``M s = ∫ φ σ dV`` with the consistent P2 mass
matrix ``M``; all six (plane: three) components are solved together by Jacobi-preconditioned
conjugate gradients (the mass matrix is well conditioned, so a few dozen iterations suffice).

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   sec. 15.3 (recovery by L2 projection), sec. 15.4 (SPR), sec. 15.6 (ZZ error estimate).
2. O. C. Zienkiewicz & J. Z. Zhu, The superconvergent patch recovery and a posteriori error estimates,
   Int. J. Numer. Methods Eng. 33 (1992), part 1: the recovery technique, pp. 1331-1364.
3. O. C. Zienkiewicz & J. Z. Zhu, A simple error estimator and adaptive procedure for practical
   engineering analysis, Int. J. Numer. Methods Eng. 24 (1987), pp. 337-357.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np
import scipy.sparse as sp
from skfem import ElementTetP2, ElementTriP2
from skfem.quadrature import get_quadrature
from skfem.refdom import RefTet, RefTri

from mechverify.errors import InputError
from mechverify.fea.assembly import BlockPattern, _add_product, assemble_blocks, stable_argsort


@cache
def _tables(dim: int) -> tuple[np.ndarray, np.ndarray]:
    """``M_ref[a, b] = ⟨φ_a φ_b⟩`` and ``T_ref[a, c] = ⟨φ_a L_c⟩``, averages over the reference simplex."""
    elem, ref = (ElementTetP2(), RefTet) if dim == 3 else (ElementTriP2(), RefTri)
    X, W = get_quadrature(ref, 4)
    W = W / W.sum()
    nb = elem.doflocs.shape[0]
    phi = np.array([elem.lbasis(X, i)[0] for i in range(nb)])
    L = np.vstack([1.0 - X.sum(axis=0), X])
    return np.einsum("aq,bq,q->ab", phi, phi, W), np.einsum("aq,cq,q->ac", phi, L, W)


def project(corner_values: np.ndarray, measure: np.ndarray, element_dofs: np.ndarray, pattern: BlockPattern,
            rtol: float = 1e-9) -> np.ndarray:
    """L2 projection of an element-wise linear field onto continuous P2.

    ``corner_values[e, nv, m]`` are the field's ``m`` components at each element's vertices,
    ``measure[e]`` element volumes (areas). Returns nodal values ``[n, m]``.
    """
    ne, nv, m = corner_values.shape
    dim = nv - 1
    M_ref, T_ref = _tables(dim)
    nb = M_ref.shape[0]
    blocks = (M_ref.reshape(nb * nb, 1) * measure[None, :]).reshape(nb * nb, ne, 1)
    M = assemble_blocks(blocks, pattern, 1).tocsr()
    local = np.einsum("ac,ecm,e->eam", T_ref, corner_values, measure, optimize=True)  # e, a, m
    b = np.zeros((pattern.n, m))
    idx = element_dofs.T.ravel()
    for k in range(m):
        b[:, k] = np.bincount(idx, weights=local[:, :, k].ravel(), minlength=pattern.n)
    return _pcg_multi(M, b, rtol)


def _pcg_multi(M: sp.csr_matrix, B: np.ndarray, rtol: float, maxiter: int = 500) -> np.ndarray:
    """Jacobi-PCG on several right-hand sides at once (columns of ``B``); ref. 1 of linsolve, Alg. 9.1."""
    d = M.diagonal()
    inv = 1.0 / d
    X = B * inv[:, None]
    R = B - M @ X
    Z = R * inv[:, None]
    P = Z.copy()
    rz = np.einsum("ij,ij->j", R, Z)
    bnorm = np.maximum(np.linalg.norm(B, axis=0), 1e-300)
    for _ in range(maxiter):
        if np.all(np.linalg.norm(R, axis=0) <= rtol * bnorm):
            break
        MP = M @ P
        alpha = rz / np.where(np.einsum("ij,ij->j", P, MP) != 0, np.einsum("ij,ij->j", P, MP), 1.0)
        X += P * alpha
        R -= MP * alpha
        Z = R * inv[:, None]
        rz_new = np.einsum("ij,ij->j", R, Z)
        P = Z + P * (rz_new / np.where(rz != 0, rz, 1.0))
        rz = rz_new
    return X


# ------------------------------------------------------------------------------------------------
# Extrapolate-and-average, superconvergent patch recovery, ZZ error indicator, point evaluation
# ------------------------------------------------------------------------------------------------
#: Recovery methods :func:`recover` knows.
METHODS = ("spr", "average", "projection")


def _edge_mid_values(corner_values: np.ndarray) -> np.ndarray:
    """Element-wise values ``[e, nb, m]`` at all P2 nodes of a field linear in each element (mid-edge =
    mean of the edge's ends; straight-sided elements)."""
    nv = corner_values.shape[1]
    edges = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)) if nv == 4 else ((0, 1), (1, 2), (0, 2))
    mids = np.stack([(corner_values[:, i] + corner_values[:, j]) / 2 for i, j in edges], axis=1)
    return np.concatenate([corner_values, mids], axis=1)


def extrapolate_average(corner_values: np.ndarray, element_dofs: np.ndarray, n: int) -> np.ndarray:
    """Nodal values ``[n, m]``: each element's field taken to its nodes (linear in a straight P2 element,
    so its vertex values are the extrapolation of its integration-point values), then the plain
    average over the elements sharing the node - what CalculiX does (ref. 1 of calculix, sec. 6.2)."""
    vals = _edge_mid_values(corner_values)  # e, nb, m
    idx = element_dofs.T.ravel()
    cnt = np.bincount(idx, minlength=n).astype(float)
    out = np.empty((n, vals.shape[2]))
    for k in range(vals.shape[2]):
        out[:, k] = np.bincount(idx, weights=vals[:, :, k].ravel(), minlength=n) / np.maximum(cnt, 1)
    return out


def _monomials(X: np.ndarray, degree: int) -> np.ndarray:
    """Complete polynomial basis of ``degree`` (1 or 2) at points ``X[..., d]``: ``[..., m]``."""
    d = X.shape[-1]
    cols = [np.ones(X.shape[:-1])] + [X[..., i] for i in range(d)]
    if degree == 2:
        cols += [X[..., i] * X[..., j] for i in range(d) for j in range(i, d)]
    return np.stack(cols, axis=-1)


#: Vertex-element pairs handled at once by :func:`patch_recovery` (its work arrays are ~2.5 kB per pair: the whole
#: mesh at once made the recovery the peak of the 200k-DOF solve, +2 kB/DOF; issue 23).
PATCH_CHUNK = 1 << 14


def patch_recovery(points: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, sample_points: np.ndarray,
                   sample_values: np.ndarray, n: int, fallback: np.ndarray, degree: int = 2,
                   interior_only: bool = True, chunk: int = PATCH_CHUNK) -> np.ndarray:
    """Superconvergent patch recovery (ref. 2): around each vertex, a least-squares polynomial of
    ``degree`` fitted to the sampled stresses of the elements sharing it; each node gets the average
    of the fits of all patches that contain it (ref. 2, part 1, sec. 3 - nodes on the boundary are
    reached from interior patches).

    ``points[dim, n]`` P2 node coordinates, ``t[dim+1, e]`` vertices, ``element_dofs[nb, e]``,
    ``sample_points[e, q, dim]`` and ``sample_values[e, q, m]`` (the order-2 integration points of P2
    elements, superconvergent for stresses), ``fallback[n, m]`` for nodes no valid patch reaches.
    A patch is valid when its normal matrix is well conditioned (enough points, not all on a line or
    plane); ``interior_only`` leaves out the patches of boundary vertices (their fits extrapolate), so a
    node no interior patch reaches keeps ``fallback``. The (vertex, element) pairs are taken ``chunk`` at a time
    (bounded work memory; the sums run in the same order, so the result does not depend on ``chunk``).
    """
    nv = t.shape[0]
    nverts = int(t.max()) + 1
    v = t.T.ravel()  # pair k = (vertex v[k], element k // nv)
    npairs = v.size
    spans = [(k0, min(k0 + chunk, npairs)) for k0 in range(0, npairs, max(int(chunk), 1))]
    # patch size: the largest distance from the vertex to its elements' vertices
    h = np.zeros(nverts)
    for k0, k1 in spans:
        e = np.arange(k0, k1) // nv
        xv = points[:, v[k0:k1]].T  # k, d
        reach = np.linalg.norm(points[:, t[:, e]].transpose(2, 1, 0) - xv[:, None, :], axis=2).max(axis=1)
        np.maximum.at(h, v[k0:k1], reach)
    mm = _monomials(np.zeros((1, points.shape[0])), degree).shape[-1]
    A = np.zeros((nverts, mm, mm))
    B = np.zeros((nverts, mm, sample_values.shape[2]))
    for k0, k1 in spans:
        e, vk = np.arange(k0, k1) // nv, v[k0:k1]
        X = (sample_points[e] - points[:, vk].T[:, None, :]) / h[vk][:, None, None]  # k, q, d
        P = _monomials(X, degree)  # k, q, mm
        S = _scatter(vk, nverts)
        _add_product(S, np.einsum("kqa,kqb->kab", P, P).reshape(vk.size, -1), A.reshape(nverts, -1))
        _add_product(S, np.einsum("kqa,kqc->kac", P, sample_values[e]).reshape(vk.size, -1), B.reshape(nverts, -1))
    w = np.linalg.eigvalsh(A)
    valid = w[:, 0] > 1e-8 * np.maximum(w[:, -1], 1e-300)
    del w
    coef = np.zeros_like(B)
    coef[valid] = np.linalg.solve(A[valid], B[valid])
    del A, B
    out = fallback.copy()
    # only interior patches by default: nodes they do not reach keep the fallback (extrapolate-and-average).
    # Boundary patches extrapolate their fit: measured on the thin 3D Lamé ring (few interior vertices)
    # they put the bore stress at +1.8 % against +0.35 % for the fallback.
    passes = [valid & ~_boundary_vertices(t, nverts)] if interior_only else [valid]
    done = np.zeros(n, bool)
    for use in passes:
        ok = np.flatnonzero(use[v])
        if not ok.size:
            continue
        cnt = np.zeros(n)
        total = np.zeros((n, coef.shape[2]))
        for k0 in range(0, ok.size, max(int(chunk), 1)):
            pk = ok[k0:k0 + chunk]
            vk = v[pk]
            nodes = element_dofs[:, pk // nv].T  # k', nb
            Xn = (points[:, nodes].transpose(1, 2, 0) - points[:, vk].T[:, None, :]) / h[vk][:, None, None]
            vals = np.einsum("kba,kac->kbc", _monomials(Xn, degree), coef[vk])
            idx = nodes.ravel()
            S = _scatter(idx, n)
            cnt += np.diff(S.indptr)
            _add_product(S, vals.reshape(idx.size, -1), total)  # sequential sums in pair order
        reached = (cnt > 0) & ~done
        out[reached] = total[reached] / cnt[reached, None]
        done |= reached
    return out


def _scatter(index: np.ndarray, n: int) -> sp.csr_matrix:
    """The 0/1 matrix ``S[n, k]`` with ``S[index[i], i] = 1``, columns sorted within each row: ``Y += S @ X`` by
    :func:`~mechverify.fea.assembly._add_product` adds ``X[i]`` to ``Y[index[i]]`` one after the other in ``i``
    order - ``np.add.at(Y, index, X)`` bit for bit, at a fraction of its time (0.035 s a solve of the 37k-DOF
    plate, task thinperf)."""
    order = stable_argsort(index)
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(index, minlength=n), out=indptr[1:])
    return sp.csr_matrix((np.ones(index.size), order, indptr), shape=(n, index.size))


def _boundary_vertices(t: np.ndarray, nverts: int) -> np.ndarray:
    """Vertices on the boundary of a simplex mesh (on a facet that belongs to one element only)."""
    nv = t.shape[0]
    faces = np.vstack([np.delete(t, k, axis=0).T for k in range(nv)])
    faces = np.sort(faces, axis=1)
    on = np.zeros(nverts, bool)
    if nverts ** (nv - 1) < 2 ** 62:  # each sorted face as one integer: a 1D sort instead of np.unique's row sort
        key = np.zeros(faces.shape[0], dtype=np.int64)
        for k in range(nv - 1):
            key *= nverts
            key += faces[:, k]
        order = stable_argsort(key)
        key = key[order]
        single = np.ones(key.size, bool)  # a face met once (no equal neighbour in the sorted keys)
        same = key[1:] == key[:-1]
        single[1:] &= ~same
        single[:-1] &= ~same
        on[faces[order[single]].ravel()] = True
        return on
    _, inv, cnt = np.unique(faces, axis=0, return_inverse=True, return_counts=True)
    on[np.unique(faces[cnt[inv.ravel()] == 1])] = True
    return on


def p2_values(element_dofs: np.ndarray, nodal: np.ndarray, bary: np.ndarray) -> np.ndarray:
    """A P2 nodal field ``nodal[n, m]`` at barycentric points ``bary[q, nv]`` (the same in every element) or
    ``bary[e, q, nv]`` of each element: ``[e, q, m]``."""
    nv = bary.shape[-1]
    edges = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)) if nv == 4 else ((0, 1), (1, 2), (0, 2))
    N = [bary[..., a] * (2 * bary[..., a] - 1) for a in range(nv)] + [4 * bary[..., i] * bary[..., j] for i, j in edges]
    N = np.stack(N, axis=-1)  # (e,) q, nb
    return np.einsum("eqb,ebm->eqm" if N.ndim == 3 else "qb,ebm->eqm", N, nodal[element_dofs.T])


def zz_indicator(points: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, recovered: np.ndarray,
                 sample_bary: np.ndarray, sample_values: np.ndarray, weights: np.ndarray, measure: np.ndarray,
                 E: float, nu: float) -> tuple[np.ndarray, float]:
    """Zienkiewicz-Zhu error indicator (ref. 3): per element ``η_e² = ∫_e (σ* - σ_h) : C⁻¹ (σ* - σ_h) dV``
    with the recovered field σ* and the element field σ_h at the integration points (``sample_*``,
    ``weights`` summing to 1); returns ``(η_e [e], η/√(‖σ*‖² + η²))`` - the estimated relative error in
    energy norm. Stress components in ``sample_values[..., 6]`` (xx yy zz xy yz zx)."""
    star = p2_values(element_dofs, recovered, sample_bary)

    def energy(s: np.ndarray) -> np.ndarray:  # σ : C⁻¹ σ for isotropic compliance, [e, q]
        tr = s[..., 0] + s[..., 1] + s[..., 2]
        ss = (s[..., :3] ** 2).sum(axis=-1) + 2 * (s[..., 3:] ** 2).sum(axis=-1)
        return ((1 + nu) * ss - nu * tr**2) / E

    eta2 = measure * (energy(star - sample_values) * weights).sum(axis=1)
    u2 = float((measure * (energy(star) * weights).sum(axis=1)).sum())
    total = float(eta2.sum())
    return np.sqrt(eta2), float(np.sqrt(total / max(u2 + total, 1e-300)))


#: Default recovery of the solid and plane models: measured best on the benchmarks of
#: docs/verification.md (benchmarks/verification.py).
DEFAULT_METHOD = "spr"


def sample_bary(dim: int) -> np.ndarray:
    """Barycentric coordinates ``[q, dim+1]`` of the order-2 integration points (natural order)."""
    from mechverify.fea.assembly import natural_point_order

    ref = RefTet if dim == 3 else RefTri
    X, _ = get_quadrature(ref, 2)
    X = X[:, natural_point_order(dim)]
    return np.vstack([1.0 - X.sum(axis=0), X]).T


def _voigt(s: np.ndarray) -> np.ndarray:
    """Tensors ``[..., d, d]`` -> components ``[..., 6]`` (xx yy zz xy yz zx) or plane ``[..., 3]`` (xx yy xy)."""
    if s.shape[-1] == 3:
        return np.stack([s[..., 0, 0], s[..., 1, 1], s[..., 2, 2], s[..., 0, 1], s[..., 1, 2], s[..., 0, 2]], axis=-1)
    return np.stack([s[..., 0, 0], s[..., 1, 1], s[..., 0, 1]], axis=-1)


@dataclass(frozen=True)
class Recovered:
    """Output of :func:`recover`: nodal components ``[n, m]``, integration points ``[e, q, dim]`` and their
    components ``[e, q, m]``, ZZ indicator per element and the estimated relative energy-norm error."""

    nodal: np.ndarray
    ip_points: np.ndarray
    ip_values: np.ndarray
    element_error: np.ndarray
    error_estimate: float


def recover(method: str, p: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, doflocs: np.ndarray,
            u: np.ndarray, lam: float, mu: float, E: float, nu: float, measure: np.ndarray, pattern: BlockPattern,
            plane_strain: bool = False) -> Recovered:
    """Stresses of a straight-sided P2 solution ``u`` recovered at the nodes by ``method`` (:data:`METHODS`),
    with the integration-point stresses and the ZZ error indicator of the recovered field."""
    from mechverify.fea import assembly as asm

    if method not in METHODS:
        raise InputError(f"recovery must be one of {METHODS}, got {method!r}")
    dim = p.shape[0]
    n = doflocs.shape[1]
    corner = _voigt(asm.hooke(asm.strain_at_nodes(p, t, element_dofs, u, corners_only=True), lam, mu))
    ipv = _voigt(asm.hooke(asm.strain_at_points(p, t, element_dofs, u), lam, mu)[:, asm.natural_point_order(dim)])
    bary = sample_bary(dim)
    xq = np.einsum("qa,dea->eqd", bary, p[:, t].transpose(0, 2, 1))
    if method == "projection":
        nodal = project(corner, measure, element_dofs, pattern)
    else:
        nodal = extrapolate_average(corner, element_dofs, n)
        if method == "spr":
            nodal = patch_recovery(doflocs, t, element_dofs, xq, ipv, n, nodal, 2, True)
    full = (lambda v: v) if dim == 3 else (lambda v: _plane_full(v, nu, plane_strain))
    weights = np.full(bary.shape[0], 1.0 / bary.shape[0])
    eta_e, rel = zz_indicator(doflocs, t, element_dofs, full(nodal), bary, full(ipv), weights, measure, E, nu)
    return Recovered(nodal, xq, ipv, eta_e, rel)


def _plane_full(v: np.ndarray, nu: float, plane_strain: bool) -> np.ndarray:
    """Plane components (xx yy xy) -> six (xx yy zz xy yz zx); σzz = ν(σxx + σyy) in plane strain."""
    out = np.zeros(v.shape[:-1] + (6,))
    out[..., 0], out[..., 1], out[..., 3] = v[..., 0], v[..., 1], v[..., 2]
    if plane_strain:
        out[..., 2] = nu * (v[..., 0] + v[..., 1])
    return out


def recover_curved(method: str, nodes: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, u: np.ndarray,
                   lam: float, mu: float, E: float, nu: float, plane_strain: bool = False) -> Recovered:
    """:func:`recover` for curved (isoparametric) P2 elements with node coordinates ``nodes[dim, n]``: the
    element stresses are evaluated at the element's own nodes (``average``) and integration points
    (``spr``, the ZZ indicator) through the curved mapping and extrapolated linearly from them to the
    element's nodes (``average``). L2 projection is for straight sides only."""
    from mechverify.fea import assembly as asm
    from mechverify.fea import isoparametric as iso

    if method not in METHODS:
        raise InputError(f"recovery must be one of {METHODS}, got {method!r}")
    if method == "projection":
        raise InputError("recovery='projection' is for straight-sided elements; use 'spr' or 'average' on a "
                         "curved mesh")
    dim = nodes.shape[0]
    n = nodes.shape[1]
    bary = sample_bary(dim)
    eps_q, xq, det = iso.strain(nodes, element_dofs, u, bary[:, 1:].T)
    ipv = _voigt(asm.hooke(eps_q, lam, mu))
    # each element's stress extrapolated linearly from its integration points to its corners (mid-side
    # nodes: the mean of their edge's ends), as CalculiX does: the values at the integration points are
    # the accurate ones, the curved element's own field at its vertices is not
    corner = np.einsum("aq,eqm->eam", np.linalg.inv(bary).T, ipv)  # bary[q, a]: ip q = Σ_a bary[q,a] corner a
    nodal = extrapolate_average(corner, element_dofs, n)
    if method == "spr":
        nodal = patch_recovery(nodes, t, element_dofs, xq, ipv, n, nodal, 2, True)
    full = (lambda v: v) if dim == 3 else (lambda v: _plane_full(v, nu, plane_strain))
    w = det * (1.0 / bary.shape[0]) * (0.5 if dim == 2 else 1.0 / 6.0)  # e, q: the order-2 rule's weights
    eta_e, rel = zz_indicator(nodes, t, element_dofs, full(nodal), bary, full(ipv), w,
                              np.ones(element_dofs.shape[1]), E, nu)
    return Recovered(nodal, xq, ipv, eta_e, rel)
