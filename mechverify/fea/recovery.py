"""Stress recovery: the element-wise stress field smoothed to nodes by L2 projection.

The stress of a straight-sided P2 element is linear (P1, discontinuous between elements). Its L2
projection onto the continuous P2 space solves ``M s = ∫ φ σ dV`` with the consistent P2 mass
matrix ``M``; all six (plane: three) components are solved together by Jacobi-preconditioned
conjugate gradients (the mass matrix is well conditioned, so a few dozen iterations suffice).

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   sec. 15.3 (recovery by L2 projection).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import scipy.sparse as sp
from skfem import ElementTetP2, ElementTriP2
from skfem.quadrature import get_quadrature
from skfem.refdom import RefTet, RefTri

from mechverify.fea.assembly import BlockPattern, assemble_blocks


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
