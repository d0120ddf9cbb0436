"""Curved (isoparametric) quadratic simplices: the geometry is interpolated by the same P2 functions
as the displacement, so mid-side nodes placed on the CAD surface (gmsh ``setOrder(2)``) make element
sides follow the curve instead of its chord.

Straight-sided P2 elements on a curved boundary lose about 1 % of a stress concentration at practical
mesh sizes (issue 26, finding 3); :mod:`mechverify.fea.verification` measures the gain on the Lamé
cylinder and Kirsch's hole (``docs/verification.md``).

Everything here is vectorised over elements and works on plain SI arrays:

- :func:`geometry` - Jacobians, determinants and physical gradients at reference points; raises
  :class:`InvertedElementError` (a :class:`ModelError`) when any Jacobian is not positive;
- :func:`stiffness_blocks` - element stiffness as blocks for :func:`mechverify.fea.assembly.assemble_blocks`
  (degree-4 rule, since the integrand of a curved element is rational);
- :func:`strain` - small strain at reference points (integration points, element nodes);
- :func:`facet_rule` - points, shape functions and area-weighted normals on curved boundary facets.

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   ch. 5 (isoparametric mapping, Jacobian, its positivity) and sec. 5.10 (numerical integration).
2. C. Geuzaine & J.-F. Remacle, Gmsh reference manual, ``Mesh.ElementOrder`` / ``gmsh.model.mesh.setOrder``:
   high-order nodes placed on the CAD geometry.
"""

from __future__ import annotations

from functools import cache

import numpy as np
from skfem import ElementLineP2, ElementTetP2, ElementTriP2
from skfem.quadrature import get_quadrature
from skfem.refdom import RefLine, RefTet, RefTri

from mechverify.errors import ModelError


class InvertedElementError(ModelError):
    """A curved element whose mapping folds over (Jacobian ≤ 0 somewhere): its mid-side nodes are too far
    from the straight edge for its size - refine the mesh near the curved surface."""


def _element(dim: int) -> object:
    return {1: ElementLineP2(), 2: ElementTriP2(), 3: ElementTetP2()}[dim]


@cache
def reference(dim: int, order: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(X[dim, q], W[q], N[nb, q], dN[nb, dim, q])`` of the P2 simplex at the degree-``order`` rule."""
    X, W = get_quadrature({1: RefLine, 2: RefTri, 3: RefTet}[dim], order)
    N, dN = shape(dim, X)
    return X, W, N, dN


def shape(dim: int, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """P2 shape functions ``[nb, q]`` and reference gradients ``[nb, dim, q]`` at reference points ``X[dim, q]``."""
    el = _element(dim)
    nb = el.doflocs.shape[0]
    N = np.empty((nb, X.shape[1]))
    dN = np.empty((nb, dim, X.shape[1]))
    for a in range(nb):
        v, g = el.lbasis(X, a)
        N[a], dN[a] = v, g
    return N, dN


def geometry(nodes: np.ndarray, element_dofs: np.ndarray, dN: np.ndarray,
             what: str = "element") -> tuple[np.ndarray, np.ndarray]:
    """``(detJ[e, q], gradients[e, q, nb, dim])`` of the P2 mapping with node coordinates ``nodes[dim, n]`` at
    reference points (``dN[nb, dim, q]``); :class:`InvertedElementError` unless every ``detJ > 0``."""
    Xe = nodes[:, element_dofs].transpose(2, 1, 0)  # e, nb, dim(x)
    J = np.einsum("eai,akq->eqik", Xe, dN, optimize=True)  # e, q, x, ref
    det = np.linalg.det(J)
    if np.any(det <= 0):
        bad = np.unique(np.nonzero(det <= 0)[0])
        raise InvertedElementError(
            f"{bad.size} curved {what}s are inverted (Jacobian ≤ 0), the first near "
            f"{tuple(np.round(Xe[bad[0]].mean(axis=0) * 1e3, 3))} mm: their mid-side nodes sit too far off the "
            "straight sides for the element size; refine the mesh at the curved surface")
    inv = np.linalg.inv(J)  # e, q, ref, x
    grad = np.einsum("akq,eqki->eqai", dN, inv, optimize=True)
    return det, grad


def stiffness_blocks(nodes: np.ndarray, element_dofs: np.ndarray, lam: float, mu: float,
                     thickness: float = 1.0, order: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """Element stiffness blocks ``[(a,b), e, dim*dim]`` (as :func:`mechverify.fea.assembly.elasticity_blocks`)
    and element measures ``[e]`` of curved P2 elements: ``K_ab = Σ_q w |J| (λ g_a⊗g_b + μ g_b⊗g_a + μ g_a·g_b I)``."""
    dim = nodes.shape[0]
    _, W, _, dN = reference(dim, order)
    det, g = geometry(nodes, element_dofs, dN)
    wdet = det * W[None, :] * thickness  # e, q
    M = np.einsum("eqai,eqbj,eq->abeij", g, g, wdet, optimize=True)  # ∫ ∇N_a ⊗ ∇N_b
    K = lam * M + mu * M.transpose(0, 1, 2, 4, 3)
    tr = np.trace(M, axis1=3, axis2=4)
    for i in range(dim):
        K[..., i, i] += mu * tr
    nb, ne = M.shape[0], M.shape[2]
    return K.reshape(nb * nb, ne, dim * dim), (det * W[None, :]).sum(axis=1)


def strain(nodes: np.ndarray, element_dofs: np.ndarray, u: np.ndarray, X: np.ndarray) -> tuple[np.ndarray, ...]:
    """Small strain ``[e, q, dim, dim]`` at reference points ``X[dim, q]``, their physical coordinates
    ``[e, q, dim]`` and ``detJ[e, q]``."""
    dim = nodes.shape[0]
    N, dN = shape(dim, X)
    det, g = geometry(nodes, element_dofs, dN)
    ue = u.reshape(-1, dim)[element_dofs.T]  # e, nb, dim
    grad = np.einsum("eqai,eaj->eqji", g, ue, optimize=True)
    x = np.einsum("aq,dea->eqd", N, nodes[:, element_dofs].transpose(0, 2, 1))
    return 0.5 * (grad + grad.transpose(0, 1, 3, 2)), x, det


def facet_rule(nodes: np.ndarray, facet_nodes: np.ndarray, order: int = 4) -> tuple[np.ndarray, ...]:
    """Quadrature on curved P2 boundary facets ``facet_nodes[k, nbf]`` (2D: ends then middle; 3D: 3 vertices
    then the mid-edge nodes of pairs (0,1), (1,2), (0,2)): ``(N[nbf, q], x[k, q, dim], nw[k, q, dim])`` with
    ``nw`` the facet normal scaled by the local length/area element and the weight (not yet oriented)."""
    dim = nodes.shape[0]
    X, W, N, dN = reference(dim - 1, order)
    if dim == 2:  # ElementLineP2 orders ends 0, 1 then the middle
        Xf = nodes[:, facet_nodes].transpose(1, 2, 0)  # k, 3, 2
    else:  # ElementTriP2: vertices, then (0,1), (1,2), (0,2)
        Xf = nodes[:, facet_nodes].transpose(1, 2, 0)
    x = np.einsum("aq,kad->kqd", N, Xf)
    T = np.einsum("kad,arq->kqdr", Xf, dN)  # tangents ∂x/∂ξ_r
    if dim == 2:
        t = T[..., 0]
        nrm = np.stack([t[..., 1], -t[..., 0]], axis=-1)
    else:
        nrm = np.cross(T[..., 0], T[..., 1])
    return N, x, nrm * W[None, :, None]


def mid_side_offsets(nodes: np.ndarray, element_dofs: np.ndarray, dim: int) -> np.ndarray:
    """Distance of each element's mid-side nodes from the straight mid-points, relative to the edge length
    ``[e, n_edges]`` (zero for straight-sided elements)."""
    edges = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)) if dim == 3 else ((0, 1), (1, 2), (0, 2))
    Xe = nodes[:, element_dofs]  # dim, nb, e
    out = np.empty((element_dofs.shape[1], len(edges)))
    for m, (i, j) in enumerate(edges):
        mid = (Xe[:, i] + Xe[:, j]) / 2
        out[:, m] = np.linalg.norm(Xe[:, dim + 1 + m] - mid, axis=0) / np.linalg.norm(Xe[:, j] - Xe[:, i], axis=0)
    return out
