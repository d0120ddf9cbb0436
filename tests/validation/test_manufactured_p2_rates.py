"""Manufactured-solution convergence rates of the P2 solid and plane-stress elements.

Source: a priori error estimates of Lagrange elements of degree k on quasi-uniform meshes, for smooth
solutions: ‖u - u_h‖_L2 = O(h^(k+1)) and the energy norm ‖u - u_h‖_E = O(h^k) (Brenner & Scott, The
Mathematical Theory of Finite Element Methods, 3rd ed., 2008, Theorems 5.4.8 and 5.7.6 [rates as stated
there, not seen here]; Zienkiewicz, Taylor & Zhu 7th ed. sec. 14.2). For P2: rates 3 and 2. The
manufactured solution u_i = A sin πx sin πy (sin πz) on the unit square (cube), with the body force
f = -(μ Δu + (λ + μ) ∇(∇·u)) it needs (a hand derivation, below) and the exact values held on the whole
boundary, is solved on three meshes (h, h/2, h/4); the observed rates log2(e_h / e_(h/2)) must approach
the theory (the test accepts > 2.8 and > 1.85 on the finest pair).
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.fea import isoparametric as iso
from mechverify.fea import mesh, mesh2d, modal, plane, solid
from mechverify.fea.linsolve import solve

A = 1e-3  # amplitude [m]


def exact(x: np.ndarray, dim: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """u [dim, ...], ∇u [dim(i), dim(j), ...] = ∂u_i/∂x_j and ∂_j(∇·u) [dim, ...] of u_i = A Π_k sin(π x_k)."""
    s, c = np.sin(np.pi * x), np.cos(np.pi * x)
    prod = np.prod(s, axis=0)
    u = np.repeat((A * prod)[None], dim, axis=0)
    du = np.empty((dim,) + x.shape[1:])  # ∂(Π sin)/∂x_j
    for j in range(dim):
        du[j] = np.pi * c[j] * np.prod(np.delete(s, j, axis=0), axis=0)
    grad = A * np.repeat(du[None], dim, axis=0)
    # ∇·u = A Σ_i du_i; ∂_j(∇·u) = A Σ_i ∂_j du_i with ∂_j du_j = -π² Π sin, ∂_j du_i = π² c_i c_j Π_(k≠i,j) s_k
    ggdiv = np.zeros((dim,) + x.shape[1:])
    for j in range(dim):
        for i in range(dim):
            if i == j:
                ggdiv[j] += -np.pi**2 * prod
            else:
                others = [k for k in range(dim) if k not in (i, j)]
                rest = np.prod(s[others], axis=0) if others else 1.0
                ggdiv[j] += np.pi**2 * c[i] * c[j] * rest
    return u, grad, A * ggdiv


def errors(model, dim: int) -> tuple[float, float]:
    _, ed, t, (lam, mu) = modal._parts(model)
    K = modal.stiffness_matrix(model)
    nodes = model.nodes
    X, W, N, dN = iso.reference(dim, 6)
    det, g = iso.geometry(nodes, ed, dN)
    xq = np.einsum("aq,dea->deq", N, nodes[:, ed].transpose(0, 2, 1))  # dim, e, q
    u, grad, gdiv = exact(xq, dim)
    lap = -dim * np.pi**2 * u
    f_body = -(mu * lap + (lam + mu) * gdiv)  # dim, e, q
    w = det * W[None, :] * t
    F = np.zeros(nodes.shape[1] * dim)
    Fv = F.reshape(-1, dim)
    for i in range(dim):
        np.add.at(Fv[:, i], ed.T, np.einsum("aq,eq,eq->ea", N, f_body[i], w))
    on_boundary = np.any((np.abs(nodes) < 1e-12) | (np.abs(nodes - 1) < 1e-12), axis=0)
    bn = np.flatnonzero(on_boundary)
    held = (dim * bn[:, None] + np.arange(dim)[None, :]).ravel()
    ub, _, _ = exact(nodes[:, bn], dim)
    uh, _ = solve(K, F, held, nodes, prescribed=ub.T.ravel(), method="direct")
    ue = uh.reshape(-1, dim)[ed.T]  # e, a, j
    uq = np.einsum("aq,eaj->jeq", N, ue)
    gq = np.einsum("eqai,eaj->jieq", g, ue)  # ∂u_j/∂x_i -> [j, i]
    e = uq - u
    ge = gq - grad
    eps = 0.5 * (ge + ge.transpose(1, 0, 2, 3))
    tr = np.trace(eps)
    energy = np.einsum("eq,eq->", lam * tr**2 + 2 * mu * np.einsum("ijeq,ijeq->eq", eps, eps), w)
    l2 = np.sqrt(np.einsum("jeq,jeq,eq->", e, e, w))
    return float(l2), float(np.sqrt(energy))


def rates(errs: list[tuple[float, float]]) -> tuple[np.ndarray, np.ndarray]:
    e = np.array(errs)
    return np.log2(e[:-1, 0] / e[1:, 0]), np.log2(e[:-1, 1] / e[1:, 1])


def test_plane_stress_p2_rates():
    errs = [errors(plane.PlaneModel(mesh2d.rectangle(1.0, 1.0, n, n), "1 m", "Structural Steel"), 2)
            for n in (4, 8, 16)]
    l2, en = rates(errs)
    assert l2[-1] == pytest.approx(3.0, abs=0.2) and l2[-1] > 2.8
    assert en[-1] == pytest.approx(2.0, abs=0.15) and en[-1] > 1.85


def test_solid_p2_rates():
    errs = [errors(solid.SolidModel(mesh.box(("1 m",) * 3, (n, n, n)), "Structural Steel"), 3) for n in (2, 4, 8)]
    l2, en = rates(errs)
    assert l2[-1] > 2.8 and l2[-1] < 3.3
    assert en[-1] > 1.85 and en[-1] < 2.3
