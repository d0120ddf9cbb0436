"""Linear (eigenvalue) buckling of solids and plane models: the load factors ``μ`` at which
``(K + μ K_G) φ = 0``, with ``K_G`` the geometric (initial-stress) stiffness of the static stress state
under the model's loads.

    >>> from mechverify.fea import buckling, mesh, solid
    >>> from mechverify.fea.loads import Fixed, Force
    >>> from mechverify.fea.regions import Plane
    >>> col = solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (10, 1, 1)), "Structural Steel",
    ...     supports=(Fixed(Plane(x="0 mm")),), loads=(Force(Plane(x="200 mm"), ("-1 kN", "0 N", "0 N")),))
    >>> round(float(buckling.buckling(col, 1).factors[0]), 1)   # Euler fixed-free: π²EI/(4L²)/P = 10.3
    10.4

- :func:`geometric_stiffness` - ``K_G,ab = ∫ (∇N_a · σ · ∇N_b) dV · I`` (ref. 1, sec. 6.6; ref. 2, ch. 13), the
  stress from the linear static solution at the points of a degree-4 rule.
- :func:`buckling` - one static solve on the factorisation of ``K`` (CHOLMOD when installed, else SuperLU;
  :mod:`mechverify.fea.factor`), then the largest eigenvalues
  ``θ = 1/μ`` of ``-K_G φ = θ K φ`` by ARPACK's Lanczos iteration with that same factorisation
  (ref. 3, mode 2). Only positive factors (the loads as given, not reversed) are returned, ascending.
  The factors multiply *all* loads of the model; a factor below 1 means the structure buckles before
  the loads are reached.

References
----------
1. Bathe, Finite Element Procedures, 2nd ed., 2014, sec. 6.8.2 (linearized buckling analysis).
2. Zienkiewicz, Taylor & Fox, The Finite Element Method for Solid and Structural Mechanics, 7th ed.,
   2014, ch. 10 (initial-stress matrix).
3. Lehoucq, Sorensen & Yang, ARPACK Users' Guide, SIAM 1998, sec. 3.2.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError
from mechverify.fea import assembly as asm
from mechverify.fea import isoparametric as iso
from mechverify.fea.factor import METHODS, cholmod_available, factorize
from mechverify.fea.modal import _parts, _pattern, mode_count, require_memory, stiffness_matrix
from mechverify.fea.reproducible import reproducible


class NoBucklingFactorError(ModelError):
    """The loads have no positive buckling factor (a pull: only reversed loads would buckle the model).
    ``bound``: every positive factor, if there is one, exceeds it (inf when none exists at all)."""

    def __init__(self, message: str, bound: float) -> None:
        super().__init__(message)
        self.bound = float(bound)


def integration_stress(model: Any, u: np.ndarray, order: int = 4) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(σ[e, q, dim, dim], gradients[e, q, nb, dim], weights[e, q])`` of displacement ``u`` at a degree-``order``
    rule (in-plane stresses of a plane model; weights include the thickness)."""
    dim, ed, t, (lam, mu) = _parts(model)
    _, W, _, dN = iso.reference(dim, order)
    det, g = iso.geometry(model.nodes, ed, dN)
    ue = np.asarray(u).reshape(-1, dim)[ed.T]  # e, a, j
    grad = np.einsum("eqai,eaj->eqji", g, ue, optimize=True)
    eps = 0.5 * (grad + grad.transpose(0, 1, 3, 2))
    return asm.hooke(eps, lam, mu), g, det * W[None, :] * t


def geometric_stiffness(model: Any, u: np.ndarray) -> sp.bsr_matrix:
    """The geometric stiffness ``K_G`` [N/m] of the stress state of displacement ``u[dim*n]`` (ref. 1, 2)."""
    dim, ed, _, _ = _parts(model)
    sig, g, w = integration_stress(model, u)
    s = np.einsum("eqai,eqij,eqbj,eq->abe", g, sig, g, w, optimize=True)
    nb, ne = s.shape[0], s.shape[2]
    blocks = np.zeros((nb * nb, ne, dim * dim))
    for i in range(dim):
        blocks[:, :, i * dim + i] = s.reshape(nb * nb, ne)
    return asm.assemble_blocks(blocks, _pattern(model, dim, ed), dim)


@dataclass(frozen=True, eq=False)
class BucklingResults:
    """Buckling load factors ``factors[k]`` (ascending, multiplying all loads of the model), the mode shapes
    ``shapes[k, n, 3]`` (largest component 1) and the node coordinates ``points[n, 3]`` [m]."""

    factors: np.ndarray
    shapes: np.ndarray
    points: np.ndarray
    unknowns: int

    @property
    def first_factor(self) -> float:
        """The lowest positive buckling load factor."""
        return float(self.factors[0])


@reproducible  # one BLAS thread: the same bits whatever the process's thread count (issue 19)
def buckling(model: Any, n_modes: int = 1, method: str = "auto", memory: float | None = None) -> BucklingResults:
    """The ``n_modes`` lowest positive buckling load factors of ``model`` under its loads (see module doc).

    The model needs supports that prevent every rigid motion (the free one is named) and loads that
    compress something; a model whose loads cause no compressive stress is a :class:`ModelError`.
    ``method``: the factorisation of ``K`` ("auto": CHOLMOD when installed, else SuperLU;
    :mod:`mechverify.fea.factor`). A model whose factor would not fit in the available memory (``memory``
    [bytes] instead of the machine's; :func:`mechverify.fea.modal.memory_estimate`) is refused before
    assembly with the estimate and the largest model that fits.
    """
    n_modes = mode_count(n_modes)
    if method not in METHODS:
        raise InputError(f"method: one of {', '.join(METHODS)}, got {method!r}")
    if method == "auto":
        method = "cholmod" if cholmod_available() else "superlu"
    dim = 2 if hasattr(model, "plane") else 3
    if not model.loads:
        raise InputError("buckling needs loads: the factors multiply the model's loads")
    from mechverify.fea.modal import free_dofs

    free = free_dofs(model)
    if not model.supports:
        raise ModelError("buckling needs supports; the model has none")
    if n_modes < 1 or n_modes >= free.size // 2:
        raise InputError(f"n_modes: between 1 and {free.size // 2 - 1} for this model ({free.size} free DOFs), "
                         f"got {n_modes}")
    require_memory(free.size, dim, n_modes + 4, method, memory)  # before assembling: the factor's estimate
    basis = getattr(model, "dof_basis", None)  # pin supports: K, f and K_G in the pins' axes (fea.pins)
    K = (stiffness_matrix(model) if basis is None else basis.rotate(stiffness_matrix(model))).tocsr()
    Kf = K[free][:, free].tocsc()
    fac = factorize(Kf, method, what="the stiffness matrix")  # CHOLMOD when installed, else SuperLU
    f = model.load_vector() if basis is None else basis.inward(model.load_vector())
    if not np.any(f[free]):  # every load on held nodes: nothing is stressed (ARPACK would fail on K_G = 0)
        model.loads_on_held()  # names them (a ModelError)
        raise ModelError("buckling: the loads reach no free node, so nothing is stressed and nothing can buckle")
    u = np.zeros(K.shape[0])
    u[free] = fac.solve(f[free])
    G = geometric_stiffness(model, u if basis is None else basis.outward(u))
    G = (G if basis is None else basis.rotate(G)).tocsr()
    Gf = -G[free][:, free].tocsr()
    op = fac.operator()
    k = min(max(2 * n_modes, n_modes + 4), free.size - 2)
    v0 = np.random.default_rng(0).standard_normal(free.size)
    # the k eigenvalues of largest magnitude converge fast; the positive ones among them are the largest positive
    # ones (any other has a smaller magnitude). Only when too few are positive is the slow "LA" iteration needed
    # (every θ negative: the largest are a dense cluster at 0; a tension-only case took 30x the compressive one)
    try:
        theta, V = spl.eigsh(Gf, k=k, M=Kf, Minv=op, which="LM", v0=v0, tol=1e-10, maxiter=max(300, 20 * k))
    except spl.ArpackNoConvergence:
        theta, V = np.zeros(0), np.zeros((free.size, 0))
    if theta.size and not np.any(theta > 0):
        bound = 1.0 / float(np.min(np.abs(theta))) if theta.size and np.min(np.abs(theta)) > 0 else np.inf
        raise NoBucklingFactorError(
            "the loads cause no buckling: the load state has no compression that can destabilise the model "
            f"(the {theta.size} buckling eigenvalues of largest magnitude are all negative: reversed loads would "
            f"buckle it at {1.0 / float(np.max(np.abs(theta))):.4g} times the loads; any positive factor exceeds "
            f"{bound:.4g})", bound)
    if np.sum(theta > 0) < n_modes:  # too few positive among the largest magnitudes (or LM did not converge)
        try:
            theta, V = spl.eigsh(Gf, k=k, M=Kf, Minv=op, which="LA", v0=v0, tol=1e-10, maxiter=max(300, 20 * k))
        except spl.ArpackNoConvergence as exc:
            theta, V = exc.eigenvalues, exc.eigenvectors
            if np.sum(theta > 0) < n_modes and np.any(theta > 0):
                raise ModelError(f"the buckling eigenvalue iteration did not converge ({exc})") from None
    pos = theta > 1e-12 * np.max(np.abs(theta)) if theta.size else np.zeros(0, bool)
    if not np.any(pos):
        raise NoBucklingFactorError("the loads cause no buckling: the load state has no compression that can "
                                    "destabilise the model (all buckling factors are negative: reversed loads "
                                    "would buckle it)", np.inf)
    theta, V = theta[pos], V[:, pos]
    order = np.argsort(-theta)[:n_modes]
    mu, V = 1.0 / theta[order], V[:, order]
    n = model.nodes.shape[1]
    full = np.zeros((n * dim, len(mu)))
    full[free] = V
    if basis is not None:
        full = basis.outward(full)
    full /= np.max(np.abs(full), axis=0)[None, :]
    shapes = np.zeros((len(mu), n, 3))
    shapes[:, :, :dim] = full.T.reshape(len(mu), n, dim)
    pts = np.zeros((n, 3))
    pts[:, :dim] = model.nodes.T
    return BucklingResults(mu, shapes, pts, int(free.size))
