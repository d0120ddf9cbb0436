"""Vectorised assembly kernels for isoparametric-free (straight-sided) quadratic simplices.

scikit-fem supplies the meshes, element definitions (reference basis functions) and quadrature;
the element matrices of linear elasticity are formed here for all elements at once with batched
matrix products (no Python loop over elements), then scattered into one CSR matrix.

DOF numbering: scalar P2 DOF ``k`` (vertex ``k`` for ``k < nverts``, else edge ``k - nverts``, as
scikit-fem numbers them) carries displacement components ``dim*k + i``; node-interleaved, so
algebraic multigrid can use the block size.

Everything here works in plain SI floats and ndarrays.

References
----------
1. Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013,
   ch. 6 (elasticity, B-matrix form) and Table 6.3 (tetrahedron quadrature).
2. Hughes, The Finite Element Method, Dover 2000, sec. 3.10 (element assembly).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cache

import numpy as np
import scipy.sparse as sp
from skfem import ElementTetP2, ElementTriP2
from skfem.quadrature import get_quadrature
from skfem.refdom import RefTet, RefTri


@cache
def reference_gradients(dim: int, order: int = 2) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Reference P2 basis values and gradients at a quadrature rule of ``order``.

    Returns ``(phi[nb, nq], dphi[nb, dim, nq], weights[nq])`` on the reference simplex.
    """
    elem, ref = (ElementTetP2(), RefTet) if dim == 3 else (ElementTriP2(), RefTri)
    X, W = get_quadrature(ref, order)
    nb = elem.doflocs.shape[0]
    phi = np.empty((nb, X.shape[1]))
    dphi = np.empty((nb, dim, X.shape[1]))
    for i in range(nb):
        p, dp = elem.lbasis(X, i)
        phi[i], dphi[i] = p, dp
    return phi, dphi, W


def reference_gradients_at_nodes(dim: int) -> np.ndarray:
    """Gradients ``[nb(node), nb(basis), dim]`` of the reference P2 basis at the element's own nodes."""
    elem = ElementTetP2() if dim == 3 else ElementTriP2()
    X = elem.doflocs.T
    nb = X.shape[1]
    out = np.empty((nb, nb, dim))
    for i in range(nb):
        _, dp = elem.lbasis(X, i)
        out[:, i, :] = dp.T
    return out


def jacobians(p: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-element inverse Jacobian ``invJ[e, dim, dim]`` and determinant ``detJ[e]`` (straight sides)."""
    x0 = p[:, t[0]]
    J = np.stack([p[:, t[k]] - x0 for k in range(1, t.shape[0])], axis=2).transpose(1, 0, 2)  # e, xyz, ref
    return np.linalg.inv(J), np.linalg.det(J)


def global_gradients(invJ: np.ndarray, dref: np.ndarray) -> np.ndarray:
    """Physical gradients ``g[e, q, a, i]`` from reference ones ``dref[a, k, q]``: g = dref · J^-1."""
    return np.einsum("akq,eki->eqai", dref, invJ, optimize=True)


def lame(E: float, nu: float, plane: str | None = None) -> tuple[float, float]:
    """Lamé constants (λ, μ) [Pa]; ``plane="stress"`` gives the plane-stress λ* = 2λμ/(λ+2μ)."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    if plane == "stress":
        lam = 2 * lam * mu / (lam + 2 * mu)
    return lam, mu


#: Local edges of scikit-fem's P2 simplices (vertex pairs of the mid-edge DOFs, in DOF order).
EDGES = {3: ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)), 2: ((0, 1), (1, 2), (0, 2))}

#: 4-point (tet) and 3-point (triangle) degree-2 rules in barycentric coordinates, weights summing to 1.
_A, _B = 0.5854101966249685, 0.1381966011250105
_RULES = {3: (np.full((4, 4), _B) + np.eye(4) * (_A - _B), np.full(4, 0.25)),
          2: (np.full((3, 3), 1 / 6) + np.eye(3) * (2 / 3 - 1 / 6), np.full(3, 1 / 3))}


@cache
def _barycentric_coefficients(dim: int) -> np.ndarray:
    """``R[(a,b), (k,l)] = Σ_q w_q (∂N_a/∂L_k)(∂N_b/∂L_l)`` for the P2 basis written in barycentrics.

    With ``∇N_a = Σ_k (∂N_a/∂L_k) ∇L_k``, the element integral ``∫ ∇N_a ⊗ ∇N_b dV`` is
    ``V Σ_kl R[a,b,k,l] ∇L_k ⊗ ∇L_l``; the rule is exact because the integrand is quadratic.
    Vertex basis ``L_a(2L_a - 1)``, edge basis ``4 L_i L_j`` (ref. 1, sec. 6.3).
    """
    L, w = _RULES[dim]
    nv = dim + 1
    edges = EDGES[dim]
    nb = nv + len(edges)
    C = np.zeros((L.shape[0], nb, nv))  # q, a, k
    for a in range(nv):
        C[:, a, a] = 4 * L[:, a] - 1
    for m, (i, j) in enumerate(edges):
        C[:, nv + m, i] = 4 * L[:, j]
        C[:, nv + m, j] = 4 * L[:, i]
    R = np.einsum("q,qak,qbl->abkl", w, C, C)
    return R.reshape(nb * nb, nv * nv)


def barycentric_gradients(p: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``∇L_k[e, k, i]`` of the barycentric coordinates and element measures (volume/area)."""
    dim = p.shape[0]
    invJ, detJ = jacobians(p, t[: dim + 1])
    gL = np.empty((invJ.shape[0], dim + 1, dim))
    gL[:, 1:, :] = invJ
    gL[:, 0, :] = -invJ.sum(axis=1)
    measure = np.abs(detJ) / (6.0 if dim == 3 else 2.0)
    return gL, measure


def _lame_table(p: np.ndarray, t: np.ndarray, lam: float, mu: float, thickness: float) -> np.ndarray:
    """``λ P + μ Pᵀ + μ tr(P) I`` of the per-element products ``P = V ∇L_k ⊗ ∇L_l``: ``[(k,l), e * dim * dim]``."""
    dim = p.shape[0]
    gL, measure = barycentric_gradients(p, t)
    ne, nv = gL.shape[0], dim + 1
    P = np.einsum("eki,elj->kleij", gL, gL * (measure * thickness)[:, None, None], optimize=True)
    # λ M + μ Mᵀ + μ tr(M) I is linear in M, so form it on the small ∇L ⊗ ∇L table before the product.
    Pc = lam * P + mu * P.transpose(0, 1, 2, 4, 3)
    tr = np.trace(P, axis1=3, axis2=4)
    del P
    for i in range(dim):
        Pc[:, :, :, i, i] += mu * tr
    return Pc.reshape(nv * nv, ne * dim * dim)


def elasticity_blocks(p: np.ndarray, t: np.ndarray, lam: float, mu: float, thickness: float = 1.0) -> np.ndarray:
    """Element stiffness of isotropic linear elasticity as 3x3 (2x2) blocks ``K[(a,b), e, i*dim+j]``.

    Block ``(a, b)`` couples displacement component ``i`` of node ``a`` with ``j`` of node ``b``:
    ``K_ab = λ M_ab + μ M_abᵀ + μ tr(M_ab) I`` with ``M_ab = ∫ ∇N_a ⊗ ∇N_b dV`` (ref. 1, eq. 6.13).
    All ``M_ab`` of all elements come from one matrix product of the constant table
    :func:`_barycentric_coefficients` with the per-element products ``∇L_k ⊗ ∇L_l``.
    """
    dim = p.shape[0]
    K = _barycentric_coefficients(dim) @ _lame_table(p, t, lam, mu, thickness)
    return K.reshape(-1, t.shape[1], dim * dim)


#: Local node pairs (a, b) whose element blocks :func:`assemble_elasticity` forms at once (of 100 for a P2
#: tetrahedron): all blocks at once were 1.6 kB per DOF, the peak of a 200k-DOF solve (issue 23).
PAIRS_PER_CHUNK = 10


def assemble_elasticity(p: np.ndarray, t: np.ndarray, lam: float, mu: float, pattern: BlockPattern,
                        thickness: float = 1.0, pairs: int = PAIRS_PER_CHUNK) -> sp.bsr_matrix:
    """The assembled stiffness of :func:`elasticity_blocks` (BSR, ``dim x dim`` blocks) without holding every
    element block: the blocks of ``pairs`` local node pairs ``(a, b)`` at a time are summed into K's data in place.
    Each target block receives the same terms in the same order as ``assemble_blocks(elasticity_blocks(...))``."""
    dim = p.shape[0]
    ne = t.shape[1]
    table = _lame_table(p, t, lam, mu, thickness)
    R = _barycentric_coefficients(dim)
    S = pattern.summation
    data = np.zeros((S.shape[0], dim * dim))
    for a0 in range(0, R.shape[0], max(int(pairs), 1)):
        a1 = min(a0 + max(int(pairs), 1), R.shape[0])
        blocks = (R[a0:a1] @ table).reshape(-1, dim * dim)  # rows (a b, e), as the summation's columns
        _add_product(S[:, a0 * ne:a1 * ne], blocks, data)
    n = pattern.n * dim
    return sp.bsr_matrix((data.reshape(-1, dim, dim), pattern.indices, pattern.indptr), shape=(n, n))


#: Elements whose blocks :func:`assemble_element_chunks` forms at once (curved P2 tetrahedra: ~20 kB of work arrays
#: per element; all at once, the assembly of a 473k-DOF curved cylinder peaked at 5.8 kB per DOF, now 0.8; issue 23).
ELEMENTS_PER_CHUNK = 2048


def assemble_element_chunks(blocks_of: Callable[[int, int], np.ndarray], pattern: BlockPattern, dim: int,
                            n_elements: int, elements: int = ELEMENTS_PER_CHUNK) -> sp.bsr_matrix:
    """A BSR matrix (``dim x dim`` blocks) summed from the element blocks ``blocks_of(e0, e1)``
    ``[(a,b), e1 - e0, dim*dim]`` of ``elements`` elements at a time (the curved elements' stiffness), so the blocks
    of all elements never exist at once. Each target block receives its terms chunk by chunk: the same sums as
    ``assemble_blocks`` up to the order of the additions (last-bit differences)."""
    S = pattern.summation.tocsc()
    nb2 = S.shape[1] // max(n_elements, 1)
    data = np.zeros((S.shape[0], dim * dim))
    step = max(int(elements), 1)
    for e0 in range(0, n_elements, step):
        e1 = min(e0 + step, n_elements)
        cols = (np.arange(nb2)[:, None] * n_elements + np.arange(e0, e1)).ravel()  # (a b, e) as the blocks' rows
        _add_product(S[:, cols], blocks_of(e0, e1).reshape(-1, dim * dim), data)
    n = pattern.n * dim
    return sp.bsr_matrix((data.reshape(-1, dim, dim), pattern.indices, pattern.indptr), shape=(n, n))


def _add_product(A: sp.csr_matrix, X: np.ndarray, Y: np.ndarray) -> None:
    """``Y += A @ X`` in place (``A`` CSR or CSC, ``Y`` a C-contiguous 2D float array): SciPy's own kernel for
    ``A @ X`` (which accumulates into a zeroed result), so each row of ``Y`` receives the same terms in the same
    (column) order as in one product with the whole matrix."""
    try:
        from scipy.sparse import _sparsetools
        kernel = getattr(_sparsetools, f"{A.format}_matvecs")
    except (ImportError, AttributeError):  # a SciPy without the private kernel: a temporary of Y's size
        Y += A @ X
        return
    X = np.ascontiguousarray(X, dtype=float)
    if not (Y.flags.c_contiguous and Y.dtype == np.float64):
        raise ValueError("_add_product: Y must be a C-contiguous float64 array")
    kernel(A.shape[0], A.shape[1], X.shape[1], A.indptr, A.indices, A.data, X.ravel(), Y.ravel())


@dataclass(frozen=True)
class BlockPattern:
    """Where each element block lands in a block-sparse (BSR) matrix; computed once per mesh.

    ``summation`` is the 0/1 matrix (target blocks x element blocks; CSC, one 1 per column) whose product with the
    stacked element blocks sums them into the BSR data - one sparse product instead of a scatter.
    """

    indptr: np.ndarray
    indices: np.ndarray
    summation: sp.csr_matrix
    n: int  # number of block rows (scalar DOFs)


def stable_argsort(key: np.ndarray) -> np.ndarray:
    """``np.argsort(key, kind="stable")`` of non-negative integers, by least-significant-digit radix sort on 16-bit
    digits (NumPy's stable sort of 16-bit integers is a radix sort): the same permutation in two or three linear
    passes. The block pattern's 606k keys at 37k DOF: 0.013 against 0.042 s, at 67k 0.030 against 0.074 s (task
    thinperf). Keys of more than 48 bits go to NumPy's stable sort."""
    key = np.asarray(key)
    if key.size == 0 or key.dtype.kind not in "iu" or int(key.min()) < 0 or int(key.max()) >= 1 << 48:
        return np.argsort(key, kind="stable")
    order = None
    for shift in range(0, max(int(key.max()).bit_length(), 1), 16):
        digit = ((key if order is None else key[order]) >> shift).astype(np.uint16)  # the low 16 bits
        o = np.argsort(digit, kind="stable")
        del digit
        order = o if order is None else order[o]
    return order


def block_pattern(element_dofs: np.ndarray, n: int) -> BlockPattern:
    """The BSR pattern of ``element_dofs[nb, e]`` (scalar DOFs) coupling every pair of local nodes."""
    nb, ne = element_dofs.shape
    # key (a,b) -> ed[a] * n + ed[b], built in place (the pattern's work arrays were 9 x 8 bytes per element block,
    # the peak of the solve before the assembly; issue 23)
    key = np.repeat(element_dofs, nb, axis=0).astype(np.int64, copy=False)
    key *= n
    key += np.tile(element_dofs, (nb, 1))
    key = key.ravel()
    order = stable_argsort(key)
    key = key[order]  # sorted
    first = np.empty(key.size, dtype=bool)
    first[:1] = True
    np.not_equal(key[1:], key[:-1], out=first[1:])
    starts = np.flatnonzero(first)
    del first
    uniq = key[starts]
    del key
    brow = uniq // n
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(brow, minlength=n), out=indptr[1:])
    # column c (element block c) has its one 1 in the row of its target block; stored by columns, so the element
    # blocks of a range of local node pairs are a cheap column slice (assemble_elasticity)
    target = np.empty(order.size, dtype=np.int32 if order.size < np.iinfo(np.int32).max else np.int64)
    target[order] = np.repeat(np.arange(starts.size, dtype=target.dtype), np.diff(np.r_[starts, order.size]))
    del order
    S = sp.csc_matrix((np.ones(target.size), target, np.arange(target.size + 1, dtype=target.dtype)),
                      shape=(starts.size, target.size))
    return BlockPattern(indptr, (uniq % n).astype(np.int32), S, n)


def assemble_blocks(blocks: np.ndarray, pattern: BlockPattern, dim: int) -> sp.bsr_matrix:
    """Sum element blocks ``[(a,b), e, dim*dim]`` into a BSR matrix with ``dim x dim`` blocks."""
    data = (pattern.summation @ blocks.reshape(-1, dim * dim)).reshape(-1, dim, dim)
    n = pattern.n * dim
    return sp.bsr_matrix((data, pattern.indices, pattern.indptr), shape=(n, n))


def free_submatrix(K: sp.spmatrix, free: np.ndarray, chunk: int = 1 << 16) -> sp.csr_matrix:
    """``K[free][:, free]`` as CSR (the same entries in the same order as SciPy's slicing, so a solve on it gives the
    same bits), read straight from a BSR ``K`` without a CSR copy of the whole matrix.

    ``free`` is a boolean mask ``[n]`` of the kept rows and columns. SciPy's ``K.tocsr()[free][:, free]`` holds
    K's CSR copy, the row slice and the result (2-3 times the result's bytes) beside ``K`` at its peak; here only
    the result and work arrays of at most ``chunk`` blocks exist beside ``K`` (issue 23: memory per DOF).
    """
    return _submatrix(K, free, free, chunk)


def node_graph(K: sp.bsr_matrix, free: np.ndarray) -> tuple[sp.csr_matrix, np.ndarray, int]:
    """The graph of the nodes (block rows of the BSR ``K``) that keep a free DOF (boolean mask ``free`` of K's rows),
    the starts of each such node's run of free DOFs in the free numbering (plus their count at the end: the
    ``groups`` of :func:`mechverify.fea.factor.symbolic_cost`), and the non-zeros of ``K[free][:, free]`` - all from
    K's block pattern, before any scalar matrix is extracted (the pattern of ``K[free][:, free]`` at its nodes' first
    free DOFs, so the ordering found on it is the same)."""
    R = K.blocksize[0]
    fc = np.asarray(free, dtype=bool).reshape(-1, R).sum(axis=1)  # free DOFs per node
    kept = fc > 0
    nbr = fc.size
    G = sp.csr_matrix((np.ones(K.indices.size, dtype=np.int8), K.indices, K.indptr), shape=(nbr, nbr))
    brow = np.repeat(np.arange(nbr), np.diff(K.indptr))
    nnz = int(np.dot(fc[brow].astype(np.int64), fc[K.indices]))
    G = G[kept][:, kept]
    G.sort_indices()
    return G, np.r_[0, np.cumsum(fc[kept])], nnz


def free_lower_permuted(K: sp.bsr_matrix, free: np.ndarray, perm: np.ndarray, rows: int = 1 << 15) -> sp.csc_matrix:
    """The lower triangle of ``Aᵀ[perm][:, perm]`` with ``A = K[free][:, free]``, as CSC with sorted row indices, read
    straight from the BSR ``K`` (task thinperf): what :func:`mechverify.fea.factor.factorize_lower` factors, without
    the full ``A`` (1.2 kB/DOF), its permuted copy and the sort of that copy. Column ``j`` is K's row of the DOF
    ``perm[j]`` at the columns that come at or after it in the new order (``Aᵀ``: :func:`mechverify.fea.factor.
    factorize` gave CHOLMOD the CSR ``A`` read as CSC, and K's two triangles may differ in the last bit, so this is the
    same factor bit for bit). ``perm`` keeps each node's free DOFs together and in order (as
    :func:`mechverify.fea.factor.symbolic_cost` on :func:`node_graph` does), so only K's blocks are sorted (by the
    new positions of their two nodes), and a column's entries, emitted block by block and lane by lane, come out with
    their rows in order - no sort of the scalar entries. ``rows`` columns are emitted at a time (bounded work
    arrays). ``K``'s block pattern must be symmetric (a stiffness matrix's is)."""
    R = K.blocksize[0]
    if K.format != "bsr" or K.blocksize != (R, R) or K.shape[0] != K.shape[1]:
        raise ValueError("free_lower_permuted: a square BSR matrix with square blocks")
    free = np.asarray(free, dtype=bool)
    nf = int(free.sum())
    perm = np.asarray(perm)
    if perm.size != nf:
        raise ValueError(f"free_lower_permuted: a permutation of the {nf} free DOFs, got {perm.size}")
    n = K.shape[0]
    idx = np.int32 if max(n, K.data.size) < np.iinfo(np.int32).max else np.int64
    col_dofs = np.flatnonzero(free)[perm]  # K's DOF of each new column
    new = np.full(n, -1, dtype=idx)  # new index of each DOF (-1: held)
    new[col_dofs] = np.arange(nf, dtype=idx)
    nbr = n // R
    node_pos = new.reshape(nbr, R).max(axis=1)  # a node's position in the new order (-1: all held)
    bptr, bcol = K.indptr, K.indices
    brow = np.repeat(np.arange(nbr, dtype=idx), np.diff(bptr))
    pq, pp = node_pos[brow], node_pos[bcol]
    blocks = np.flatnonzero((pq >= 0) & (pp >= pq)).astype(idx)  # block (Q, P): P at or after Q in the new order
    del brow
    key = pq[blocks].astype(np.int64) * n + pp[blocks]
    del pq, pp
    order = stable_argsort(key)  # by column node, then row node (distinct keys)
    blocks = blocks[order]
    qpos = key[order] // n
    del key, order
    kept = node_pos >= 0
    first = np.zeros(nbr, dtype=np.int64)  # each node's run in `blocks`
    last = np.zeros(nbr, dtype=np.int64)
    first[kept] = np.searchsorted(qpos, node_pos[kept], side="left")
    last[kept] = np.searchsorted(qpos, node_pos[kept], side="right")
    del qpos
    data = K.data.reshape(-1)
    lanes = np.arange(R, dtype=idx)
    colptr = np.zeros(nf + 1, dtype=idx)
    parts_r, parts_v = [], []
    step = max(int(rows), 1)
    for j0 in range(0, nf, step):
        j1 = min(j0 + step, nf)
        d = col_dofs[j0:j1]
        q, c = d // R, (d % R).astype(idx)
        counts = last[q] - first[q]  # >= 1: the node's own block
        at = np.repeat(first[q] - np.cumsum(counts) + counts, counts) + np.arange(int(counts.sum()))
        blk = blocks[at]
        del at
        rows_new = new[(R * bcol[blk])[:, None] + lanes]  # [block, lane]: the new rows of the block's row node
        keep = rows_new >= np.repeat(np.arange(j0, j1, dtype=idx), counts)[:, None]  # at or below the diagonal
        np.cumsum(np.add.reduceat(keep.sum(axis=1), np.r_[0, np.cumsum(counts)[:-1]]), out=colptr[j0 + 1:j1 + 1])
        colptr[j0 + 1:j1 + 1] += colptr[j0]
        parts_r.append(rows_new[keep])
        parts_v.append(data[((R * R) * blk + R * np.repeat(c, counts))[:, None] + lanes][keep])
    rows_out = np.concatenate(parts_r)
    del parts_r
    vals = np.concatenate(parts_v)
    del parts_v
    out = sp.csc_matrix((vals, rows_out, colptr), shape=(nf, nf))
    out.has_sorted_indices = True
    return out


def held_rows(K: sp.spmatrix, held: np.ndarray, chunk: int = 1 << 16) -> sp.csr_matrix:
    """``K`` with only the rows ``held`` (indices) kept, all columns, the other rows empty: ``(held_rows(K, h) @ u)[h]``
    is ``(K @ u)[h]`` (the reactions) for the memory of those rows alone, so ``K`` itself can go before the solve."""
    mask = np.zeros(K.shape[0], bool)
    mask[np.asarray(held, dtype=np.int64)] = True
    if sp.issparse(K) and K.format == "bsr" and K.blocksize[0] == K.blocksize[1] and K.shape[0] == K.shape[1]:
        # straight from the held rows' blocks (all columns kept): _submatrix walks all K's blocks (0.012 s at 37k DOF)
        K.sort_indices()
        R = K.blocksize[0]
        rows = np.flatnonzero(mask)
        q, r = rows // R, rows % R
        counts = np.diff(K.indptr)[q]
        blk = np.repeat(K.indptr[q] - np.cumsum(counts) + counts, counts) + np.arange(int(counts.sum()))
        index_type = np.int32 if K.shape[0] < np.iinfo(np.int32).max else np.int64
        indptr = np.zeros(K.shape[0] + 1, dtype=index_type)
        indptr[1:][mask] = counts * R
        np.cumsum(indptr, out=indptr)
        cols = (R * K.indices[blk].astype(index_type))[:, None] + np.arange(R, dtype=index_type)
        vals = K.data[blk, np.repeat(r, counts), :]
        return sp.csr_matrix((vals.ravel(), cols.ravel(), indptr), shape=K.shape)
    A = _submatrix(K, mask, np.ones(K.shape[1], bool), chunk)
    indptr = np.zeros(K.shape[0] + 1, dtype=A.indptr.dtype)
    indptr[1:][mask] = np.diff(A.indptr)
    np.cumsum(indptr, out=indptr)
    return sp.csr_matrix((A.data, A.indices, indptr), shape=K.shape)


def _submatrix(K: sp.spmatrix, rows: np.ndarray, columns: np.ndarray, chunk: int) -> sp.csr_matrix:
    """``K[rows][:, columns]`` (boolean masks) as CSR from a BSR (or any sparse) ``K``, a chunk of blocks at a time."""
    rows, columns = np.asarray(rows, dtype=bool), np.asarray(columns, dtype=bool)
    if not sp.issparse(K) or K.format != "bsr":
        K = sp.bsr_matrix(K.tocsr(), blocksize=(1, 1))
    R = K.blocksize[0]
    if K.blocksize != (R, R) or K.shape[0] != K.shape[1] or not rows.shape == columns.shape == (K.shape[0],):
        raise ValueError("free_submatrix: a square BSR matrix with square blocks and masks of its size")
    K.sort_indices()
    nbr = K.shape[0] // R
    bptr, bcol, data = K.indptr, K.indices, K.data  # data[block, i, j]
    rb, cb = rows.reshape(nbr, R), columns.reshape(nbr, R)
    # kept columns of each block, and each block row's kept entries per row (the same for its R rows)
    per_block = cb.sum(axis=1)[bcol]
    row_len = np.add.reduceat(np.r_[per_block, 0], bptr[:-1]) * (np.diff(bptr) > 0)
    lengths = (row_len[:, None] * rb).ravel()[rows]  # each kept row's length
    index_type = np.int32 if max(lengths.sum(), K.shape[0]) < np.iinfo(np.int32).max else np.int64
    indptr = np.zeros(lengths.size + 1, dtype=index_type)
    np.cumsum(lengths, out=indptr[1:])
    nnz = int(indptr[-1])
    out_data = np.empty(nnz)
    out_ind = np.empty(nnz, dtype=index_type)
    new_row = (np.cumsum(rows) - 1).astype(index_type)  # new index of each kept row
    new_col = (np.cumsum(columns) - 1).astype(index_type)  # and column
    small = np.int32 if K.shape[0] < np.iinfo(np.int32).max // R else np.int64  # work arrays of entry indices
    brow = np.repeat(np.arange(nbr, dtype=small), np.diff(bptr))  # block row of each block
    lanes = np.arange(R, dtype=small)
    start = 0
    while start < nbr:  # chunks of whole block rows, at most ~chunk blocks each
        stop = max(int(np.searchsorted(bptr, bptr[start] + chunk, side="right")) - 1, start + 1)
        b0, b1 = bptr[start], bptr[stop]
        if not np.any(rb[start:stop]):
            start = stop
            continue
        cols = (R * bcol[b0:b1, None].astype(small) + lanes).ravel()  # [blocks * R], (block, j) order
        keep = columns[cols]
        # position of each kept (block, j) in its row: running count minus the count before its block row
        pos = np.cumsum(keep, dtype=small)
        before = np.r_[small(0), pos[R - 1::R]][bptr[start:stop] - b0]
        pos -= np.repeat(before, np.diff(bptr[start:stop + 1]) * R)
        pos = pos[keep] - 1
        brows = np.repeat(brow[b0:b1], R)[keep]
        cols = new_col[cols[keep]]
        block = data[b0:b1]
        for i in range(R):
            if not np.any(rb[start:stop, i]):
                continue
            on = rb[brows, i]  # entries of kept rows R * block_row + i
            dst = indptr[new_row[R * brows[on] + i]] + pos[on]
            out_data[dst] = block[:, i, :].reshape(-1)[keep][on]
            out_ind[dst] = cols[on]
        start = stop
    return sp.csr_matrix((out_data, out_ind, indptr), shape=(lengths.size, int(columns.sum())))


def vector_dofs(element_dofs: np.ndarray, dim: int) -> np.ndarray:
    """Vector DOFs ``[e, nb*dim]`` ordered (node a, component i) -> dim*dof + i."""
    return (dim * element_dofs.T[:, :, None] + np.arange(dim)[None, None, :]).reshape(element_dofs.shape[1], -1)


def mass_element_matrices(p: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Scalar P2 mass matrices ``Me[e, nb, nb] = ∫ φ_a φ_b dV`` (order-4 rule, exact for P2·P2)."""
    dim = p.shape[0]
    phi, _, W = reference_gradients(dim, 4)
    _, detJ = jacobians(p, t[: dim + 1])
    ref = np.einsum("aq,bq,q->ab", phi, phi, W)
    return np.abs(detJ)[:, None, None] * ref[None]


def strain_at_nodes(p: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, u: np.ndarray,
                    corners_only: bool = False) -> np.ndarray:
    """Small strain ``eps[e, a, dim, dim]`` at the P2 nodes of every element (exact, P2 gradients are linear).

    With ``corners_only`` just the ``dim + 1`` vertices (enough to define the linear strain field).
    """
    dim = p.shape[0]
    gref = reference_gradients_at_nodes(dim)  # node, basis, k
    if corners_only:
        gref = gref[: dim + 1]
    invJ, _ = jacobians(p, t[: dim + 1])
    g = np.einsum("nak,eki->enai", gref, invJ, optimize=True)  # e node basis i
    ue = u.reshape(-1, dim)[element_dofs.T]  # e basis j
    grad = np.einsum("enai,eaj->enji", g, ue, optimize=True)  # du_j/dx_i
    return 0.5 * (grad + grad.transpose(0, 1, 3, 2))


def natural_point_order(dim: int) -> np.ndarray:
    """Permutation of scikit-fem's order-2 simplex rule into natural order: the point nearest vertex 0,
    then those nearest vertices 1, 2, (3) - the order CalculiX uses for C3D10 integration points."""
    elem, ref = (ElementTetP2(), RefTet) if dim == 3 else (ElementTriP2(), RefTri)
    X, _ = get_quadrature(ref, 2)
    first = int(np.argmin(X.sum(axis=0)))
    return np.array([first] + [int(np.argmax(X[k])) for k in range(dim)])


def strain_at_points(p: np.ndarray, t: np.ndarray, element_dofs: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Small strain ``eps[e, q, dim, dim]`` at the order-2 quadrature points (CalculiX's integration points)."""
    dim = p.shape[0]
    _, dref, _ = reference_gradients(dim)
    invJ, _ = jacobians(p, t[: dim + 1])
    g = global_gradients(invJ, dref)  # e q a i
    ue = u.reshape(-1, dim)[element_dofs.T]
    grad = np.einsum("eqai,eaj->eqji", g, ue, optimize=True)
    return 0.5 * (grad + grad.transpose(0, 1, 3, 2))


def hooke(eps: np.ndarray, lam: float, mu: float) -> np.ndarray:
    """Isotropic stress σ = λ tr(ε) I + 2μ ε for a batch of tensors ``[..., d, d]``."""
    d = eps.shape[-1]
    tr = np.trace(eps, axis1=-2, axis2=-1)
    return lam * tr[..., None, None] * np.eye(d) + 2 * mu * eps
