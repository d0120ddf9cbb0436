"""The frame analysis: the mesh (members split at nodes, loads and supports; node lookup by a
spatial hash), assembly with condensed end releases and springs, support and mechanism checks,
and the solution of all load cases on one factorisation (combinations by superposition; one-way
springs by active-set iteration).

References
----------
1. W. McGuire, R. H. Gallagher, R. D. Ziemian, *Matrix Structural Analysis*, 2nd ed., Wiley 2000,
   Sec. 2.8 (prescribed displacements: ``K_ff u_f = f_f - K_fs u_s``), Sec. 7.3 (releases).
2. K.-J. Bathe, *Finite Element Procedures*, 2nd ed., 2014, Sec. 6.6 (contact by active sets).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from mechverify.errors import InputError, ModelError, UnknownNameError
from mechverify.fea import factorcache
from mechverify.fea.frame.element import (
    fixed_end_forces_linear,
    local_axes_batch,
)
from mechverify.fea.frame.mesh import _Mesh, _Props, _props, build_mesh
from mechverify.fea.frame.model import (
    DOF_NAMES,
    DOF_WORDS,
    THEORIES,
    DistributedLoad,
    FramePointLoad,
    FrameSelfWeight,
    FrameSupport,
    Hinge,
    Load,
    LoadCombination,
    Member,
    MemberPointLoad,
    Spring,
    SupportDisplacement,
    Where,
    _vector,
)
from mechverify.fea.frame.results import FrameAnalysis, FrameResults
from mechverify.fea.progress import Steps
from mechverify.units import to_si

#: Frames above this many unknowns show progress on stderr.
PROGRESS_THRESHOLD = 20_000
#: Dense null-space check of the stiffness up to this many unknowns (mechanism named precisely).
DENSE_CHECK_LIMIT = 3000
#: Active-set iterations allowed for one-way springs.
ONE_WAY_ITERATIONS = 50


class Frame:
    """A 3D frame: ``Frame(nodes, members, supports, hinges=(), theory="timoshenko", springs=())``.

    ``nodes`` maps names to points (three lengths); members, supports, hinges, springs and loads refer
    to nodes by name or by a point. A point on a member that is not a node splits it; a named node or
    a member end lying inside another member splits that member and joins them (with a note).
    Coincident named nodes stay separate nodes (joined only by what connects them, e.g. a
    :class:`Spring`).
    """

    def __init__(self, nodes: Mapping[str, Any] | None, members: Sequence[Member], supports: Sequence[FrameSupport],
                 hinges: Sequence[Hinge] = (), theory: str = "timoshenko", name: str = "frame",
                 springs: Sequence[Spring] = ()):
        if theory not in THEORIES:
            raise InputError(f"theory must be one of {THEORIES}, got {theory!r}")
        self.name, self.theory = name, theory
        self.nodes: dict[str, np.ndarray] = {}
        for n, p in (nodes or {}).items():
            self.nodes[str(n)] = _vector(p, "length", f"nodes.{n}")
        if not members and not springs:
            raise InputError("a frame needs at least one member (or spring)")
        self.members: list[Member] = []
        seen: set[str] = set()
        for i, m in enumerate(members):
            nm = m.name or f"M{i + 1}"
            if nm in seen:
                raise InputError(f"member name {nm!r} used twice")
            seen.add(nm)
            self.members.append(m if m.name else m.renamed(nm))
        self.springs: list[Spring] = []
        for i, s in enumerate(springs):
            if not isinstance(s, Spring):
                raise InputError(f"springs[{i}]: expected a Spring, got {type(s).__name__}")
            if not s.name:
                s = s.renamed(f"S{i + 1}")
            self.springs.append(s)
        self.ends = [(self.point(m.start, f"member {m.name}: start"), self.point(m.end, f"member {m.name}: end"))
                     for m in self.members]
        self.spring_ends = [(self.point(s.start, f"spring {s.name}: start"), self.point(s.end, f"spring {s.name}: end"))
                            for s in self.springs]
        pts = np.array([p for e in self.ends + self.spring_ends for p in e] + list(self.nodes.values()))
        self.size = float(np.max(np.ptp(pts, axis=0))) or 1.0
        self.tol = 1e-6 * self.size
        if self.members:
            self._a = np.array([e[0] for e in self.ends])
            self._d = np.array([e[1] - e[0] for e in self.ends])
        else:
            self._a = self._d = np.zeros((0, 3))
        short = np.flatnonzero(np.linalg.norm(self._d, axis=1) <= self.tol)
        if len(short):
            raise InputError(f"member {self.members[short[0]].name}: start and end coincide (zero length)")
        try:  # orientation across each member
            local_axes_batch(self._a, self._a + self._d, [m.orientation for m in self.members])
        except InputError as exc:
            i = int(str(exc).split(":")[0].split()[1])
            raise InputError(f"member {self.members[i].name}: orientation is parallel to the member; give a vector "
                             "across it") from None
        self.supports = tuple(supports)
        self.hinges = tuple(hinges)
        for s in self.supports:
            self._on_frame(s.at, "support")
        for h in self.hinges:
            self._on_frame(h.at, "hinge")
        self.member_index = {m.name: i for i, m in enumerate(self.members)}
        self.spring_index = {s.name: i for i, s in enumerate(self.springs)}
        self._prop_cache: dict[tuple[int, int, str], _Props] = {}

    # --------------------------------------------------------------------------- geometry helpers
    def point(self, where: Where, what: str = "point") -> np.ndarray:
        """The coordinates [m] of a node name or a point."""
        if isinstance(where, str):
            if where not in self.nodes:
                raise UnknownNameError("node", where, self.nodes)
            return self.nodes[where]
        return _vector(where, "length", what)

    def _locate(self, p: np.ndarray) -> list[tuple[int, float]]:
        """Members the point lies on, with the position along each (0..1)."""
        if not len(self._a):
            return []
        t = np.einsum("ij,ij->i", p - self._a, self._d) / np.einsum("ij,ij->i", self._d, self._d)
        dist = np.linalg.norm(self._a + t[:, None] * self._d - p, axis=1)
        ok = np.flatnonzero((t >= -1e-9) & (t <= 1 + 1e-9) & (dist <= self.tol))
        return [(int(i), min(max(float(t[i]), 0.0), 1.0)) for i in ok]

    def _on_spring(self, p: np.ndarray) -> bool:
        return any(min(np.linalg.norm(a - p), np.linalg.norm(b - p)) <= self.tol for a, b in self.spring_ends)

    def _on_frame(self, where: Where, what: str) -> np.ndarray:
        p = self.point(where, what)
        if not self._locate(p) and not self._on_spring(p):
            loc = ", ".join(f"{c * 1e3:.4g}" for c in p)
            raise InputError(f"{what} at {where if isinstance(where, str) else f'({loc}) mm'} is not on any member")
        return p

    def _member(self, name: str) -> int:
        if name not in self.member_index:
            raise UnknownNameError("member", name, self.member_index)
        return self.member_index[name]

    def _props_of(self, m: Member) -> _Props:
        key = (id(m.section), id(m.material), m.theory or self.theory)
        if key not in self._prop_cache:
            self._prop_cache[key] = _props(m.section, m.material, key[2], m.name)  # type: ignore[arg-type]
        return self._prop_cache[key]

    # ------------------------------------------------------------------------------- the mesh
    def _mesh(self, loads: Sequence[Load]) -> _Mesh:
        return build_mesh(self, loads)

    # ------------------------------------------------------------------------------- assembly
    def _stiffness(self, mesh: _Mesh) -> sp.csr_matrix:
        ne = len(mesh.L)
        rows, cols, vals = [], [], []
        if ne:
            kc = mesh.k.copy()
            for e, c in mesh.cond.items():
                kc[e] = c.P @ mesh.k[e]
                kc[e] = (kc[e] + kc[e].T) / 2
            T = _transforms(mesh.R)
            kg = np.transpose(T, (0, 2, 1)) @ kc @ T
            rows.append(np.repeat(mesh.dofs, 12, axis=1).ravel())
            cols.append(np.tile(mesh.dofs, (1, 12)).ravel())
            vals.append(kg.ravel())
        for s, a, b, n in mesh.springs:
            d = np.r_[6 * a:6 * a + 6, 6 * b:6 * b + 6]
            ks = np.zeros((6, 6))
            if s.axial is not None:
                ks[:3, :3] = s.axial * np.outer(n, n)
            for c, kv in s.stiffness.items():
                i = DOF_NAMES.index(c)
                ks[i, i] += kv
            k12 = np.block([[ks, -ks], [-ks, ks]])
            rows.append(np.repeat(d, 12))
            cols.append(np.tile(d, 12))
            vals.append(k12.ravel())
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(mesh.ndof, mesh.ndof))

    def _node(self, mesh: _Mesh, where: Where) -> int:
        if isinstance(where, str) and where in mesh.named:
            return mesh.named[where]
        k = mesh.index.find(self.point(where))
        if k is None:
            raise InputError(f"{where!r} is not a node of the analysis")
        return k

    def _case(self, mesh: _Mesh, loads: Sequence[Load], held: set[int]) -> _CaseData:
        """Load vector, local element loads, fixed-end forces, totals and imposed displacements of a case."""
        ne = len(mesh.L)
        f = np.zeros(mesh.ndof)
        q0, q1 = np.zeros((ne, 3)), np.zeros((ne, 3))
        F, Mo = np.zeros(3), np.zeros(3)
        presc: dict[int, float] = {}
        for ld in loads:
            if isinstance(ld, FramePointLoad | MemberPointLoad):
                fv, mv = ld.vectors()
                if isinstance(ld, MemberPointLoad):
                    i = self._member(ld.member)
                    s = min(max(to_si(ld.position, "length", "position"), 0.0), float(np.linalg.norm(self._d[i])))
                    p = self._a[i] + s * self._d[i] / np.linalg.norm(self._d[i])
                    if ld.axes == "local":
                        Rm = mesh.R[mesh.member_elems[i][0]]
                        fv, mv = Rm.T @ fv, Rm.T @ mv
                    els = mesh.member_elems[i]
                    Lm = float(np.linalg.norm(self._d[i]))
                    k = (int(mesh.elem_nodes[els[0], 0]) if s <= self.tol else int(mesh.elem_nodes[els[-1], 1])
                         if s >= Lm - self.tol else mesh.index.find(p))  # an end: the member's own end node
                    assert k is not None
                else:
                    k = self._node(mesh, ld.at)
                f[6 * k:6 * k + 3] += fv
                f[6 * k + 3:6 * k + 6] += mv
                F += fv
                Mo += mv + np.cross(mesh.points[k], fv)
            elif isinstance(ld, DistributedLoad):
                i = self._member(ld.member)
                w0, w1 = ld.values()
                Lm = float(np.linalg.norm(self._d[i]))
                sa = 0.0 if ld.start is None else to_si(ld.start, "length", "start")
                sb = Lm if ld.end is None else min(to_si(ld.end, "length", "end"), Lm)
                for e in mesh.member_elems[i]:
                    e0, e1 = mesh.elem_s0[e], mesh.elem_s0[e] + mesh.L[e]
                    if e1 <= sa + self.tol or e0 >= sb - self.tol:
                        continue
                    a = w0 + (w1 - w0) * (e0 - sa) / (sb - sa)
                    b = w0 + (w1 - w0) * (e1 - sa) / (sb - sa)
                    if ld.axes == "global":
                        a, b = mesh.R[e] @ a, mesh.R[e] @ b
                    q0[e] += a
                    q1[e] += b
            elif isinstance(ld, FrameSelfWeight):
                g = ld.vector()
                for e, pr in enumerate(mesh.props):
                    if not np.isfinite(pr.rho):
                        m = self.members[mesh.elem_member[e]]
                        raise InputError(f"member {m.name}: material {m.material.name!r} has no density "
                                         "(needed for self-weight)")
                    w = mesh.R[e] @ (pr.rho * pr.A * g)
                    q0[e] += w
                    q1[e] += w
            elif isinstance(ld, SupportDisplacement):
                k = self._node(mesh, ld.at)
                for c, v in ld.values.items():
                    dof = 6 * k + DOF_NAMES.index(c)
                    if dof not in held:
                        raise InputError(f"support displacement at {ld.at!r}: {DOF_WORDS[c]} is not held by a support "
                                         "there (only held motions can be imposed)")
                    presc[dof] = presc.get(dof, 0.0) + v
            else:
                raise InputError(f"unknown load {ld!r}: use FramePointLoad, MemberPointLoad, DistributedLoad, "
                                 "FrameSelfWeight or SupportDisplacement")
        loaded = np.flatnonzero(np.any(q0 != 0, axis=1) | np.any(q1 != 0, axis=1))
        fef = np.zeros((ne, 12))
        if len(loaded):
            pr = [mesh.props[e] for e in loaded]
            fef[loaded] = fixed_end_forces_linear(
                mesh.L[loaded], q0[loaded], q1[loaded], np.array([p.E * p.Iy for p in pr]),
                np.array([p.E * p.Iz for p in pr]), np.array([p.sy for p in pr]), np.array([p.sz for p in pr]))
            fe = fef[loaded].copy()
            for j, e in enumerate(loaded):
                if e in mesh.cond:
                    fe[j] = mesh.cond[e].P @ fe[j]
            Rl = mesh.R[loaded]
            fg = np.einsum("eji,ekj->eki", Rl, fe.reshape(-1, 4, 3)).reshape(-1, 12)
            np.add.at(f, mesh.dofs[loaded], fg)
            for j, e in enumerate(loaded):
                Le = mesh.L[e]
                w0, w1 = Rl[j].T @ q0[e], Rl[j].T @ q1[e]
                a = mesh.points[mesh.elem_nodes[e, 0]]
                F += (w0 + w1) * Le / 2
                Mo += np.cross(a, (w0 + w1) * Le / 2) + np.cross(mesh.R[e][0], Le**2 * (w0 / 6 + w1 / 3))
        return _CaseData(f, q0, q1, fef, F, Mo, presc)

    def _restraints(self, mesh: _Mesh) -> tuple[np.ndarray, dict[int, float], dict[int, tuple[float, int]],
                                                 list[tuple[FrameSupport, int]]]:
        held: set[int] = set()
        springs: dict[int, float] = {}
        one_way: dict[int, tuple[float, int]] = {}
        at: list[tuple[FrameSupport, int]] = []
        for s in self.supports:
            k = self._node(mesh, s.at)
            at.append((s, k))
            held.update(6 * k + d for d in s.held())
            for dname, val in s.springs.items():
                dof = 6 * k + DOF_NAMES.index(dname)
                if dname in s.one_way:
                    if dof in one_way:
                        raise InputError(f"support at {s.at!r}: two one-way springs on {DOF_WORDS[dname]}")
                    one_way[dof] = (val, s.one_way[dname])
                else:
                    springs[dof] = springs.get(dof, 0.0) + val
        return np.array(sorted(held), dtype=np.int64), springs, one_way, at

    def _system(self, mesh: _Mesh, held: np.ndarray, springs: dict[int, float],
                one_way: dict[int, tuple[float, int]]) -> tuple[sp.csr_matrix, sp.csr_matrix, sp.csr_matrix,
                                                                np.ndarray]:
        """The assembled stiffness ``K``, its free part with the support springs ``Kff``, the free-held coupling
        ``Kfs`` and the free DOFs, after the support, release and mechanism checks."""
        K = self._stiffness(mesh)
        self._check_supported(mesh, np.union1d(held, np.array(list(springs) + list(one_way), dtype=np.int64)))
        diag = np.zeros(mesh.ndof)
        for dof, kv in springs.items():
            diag[dof] += kv
        Ks = (K + sp.diags(diag)).tocsr()
        ow = np.zeros(mesh.ndof)
        for dof, (kv, _) in one_way.items():
            ow[dof] = kv
        self._check_releases(mesh, (Ks + sp.diags(ow)).tocsr(), held)
        free = np.setdiff1d(np.arange(mesh.ndof), held)
        Kff = Ks[free][:, free]
        Kfs = Ks[free][:, held]
        self._mechanism(mesh, Kff + sp.diags(ow[free]), free)
        return K, Kff, Kfs, free

    # -------------------------------------------------------------------------- support checks
    def _rigid_modes(self, mesh: _Mesh) -> tuple[np.ndarray, np.ndarray]:
        """The six rigid-body motions over all DOFs ``[ndof, 6]`` (rotations scaled by the model size)."""
        c = mesh.points.mean(axis=0)
        X = (mesh.points - c) / self.size
        n = len(X)
        B = np.zeros((n, 6, 6))
        B[:, 0, 0] = B[:, 1, 1] = B[:, 2, 2] = 1.0
        B[:, 1, 3], B[:, 2, 3] = -X[:, 2], X[:, 1]
        B[:, 0, 4], B[:, 2, 4] = X[:, 2], -X[:, 0]
        B[:, 0, 5], B[:, 1, 5] = -X[:, 1], X[:, 0]
        B[:, 3, 3] = B[:, 4, 4] = B[:, 5, 5] = 1.0
        return B.reshape(-1, 6), c

    def _check_supported(self, mesh: _Mesh, restrained: np.ndarray, what: str = "the supports") -> None:
        if not len(restrained):
            raise ModelError(f"frame {self.name!r} has no supports: add a fixed, pinned, roller or spring support")
        B, c = self._rigid_modes(mesh)
        G = B[restrained].T @ B[restrained]
        w, V = np.linalg.eigh(G)
        free = V[:, w <= 1e-10 * max(float(w.max()), 1.0)]
        if free.shape[1]:
            from mechverify.fea.linsolve import describe_mode

            names = [DOF_WORDS[d] for d in DOF_NAMES]
            motions = [describe_mode(free[:, k], names, c, self.size) for k in range(free.shape[1])]
            raise ModelError(f"frame {self.name!r} is not fully supported: {what} leave free "
                             + "; ".join(motions) + ". Add a support that prevents this motion.")

    def _check_releases(self, mesh: _Mesh, Ks: sp.csr_matrix, held: np.ndarray) -> None:
        """A release is effective only if something else at its node resists the released motion."""
        hs = set(held.tolist())
        for node, who in mesh.released_nodes.items():
            d = np.arange(6 * node, 6 * node + 6)
            keep = np.array([i for i in d if i not in hs], dtype=np.int64)
            if not len(keep):
                continue
            B = Ks[keep][:, keep].toarray()
            diag = np.sqrt(np.abs(np.diag(B)))
            zero = np.flatnonzero(diag <= 1e-12 * max(float(diag.max()), 1e-300))
            if len(zero):
                motion = [int(keep[zero[0]] - 6 * node)]
            else:
                w, V = np.linalg.eigh(B / diag[:, None] / diag[None, :])
                if w[0] > 1e-9 * max(float(w[-1]), 1.0):
                    continue
                v = np.abs(V[:, 0])
                motion = [int(keep[i] - 6 * node) for i in np.flatnonzero(v >= 0.5 * v.max())]
            words = " and ".join(DOF_WORDS[DOF_NAMES[i]] for i in motion)
            raise ModelError(f"frame {self.name!r} is a mechanism: nothing resists the {words} at node "
                             f"{mesh.node_words(node)}, where member ends are released (" + "; ".join(who)
                             + "): a release there has no effect (a free end, a pinned support, every member end "
                               "released, or releases in line). Remove the release or hold that motion.")

    def _mechanism(self, mesh: _Mesh, Kff: sp.spmatrix, free: np.ndarray) -> None:
        """Name an internal mechanism (e.g. a member free to spin about its axis between pins)."""
        if len(free) == 0 or len(free) > DENSE_CHECK_LIMIT:
            return
        A = Kff.toarray()
        d = np.sqrt(np.abs(np.diag(A)))
        zero = np.flatnonzero(d <= 1e-12 * max(float(d.max()), 1e-300))
        if not len(zero):
            A = A / d[:, None] / d[None, :]
            w, V = np.linalg.eigh(A)
            idx = np.flatnonzero(w <= 1e-12 * max(float(w.max()), 1.0))
            if not len(idx):
                return
            v = V[:, idx[0]]
            big = np.flatnonzero(np.abs(v) >= 0.5 * np.max(np.abs(v)))
        else:
            big = zero
        words = []
        for i in big[:4]:
            node, k = divmod(int(free[i]), 6)
            words.append(f"{DOF_WORDS[DOF_NAMES[k]]} at node {mesh.node_words(node)}")
        raise ModelError(f"frame {self.name!r} is a mechanism: nothing resists the " + ", ".join(words)
                         + " (e.g. a member between pins free to twist about its axis, or hinges in line). "
                           "Hold that motion with a support or remove a hinge or release.")

    # ----------------------------------------------------------------------- eigenvalue analyses
    def modes(self, n_modes: int = 6, **kw: Any) -> Any:
        """Natural frequencies and mode shapes: :func:`mechverify.fea.frame.modal.frame_modes` (``masses=``,
        ``elements_per_member=``, ``shift=``)."""
        from mechverify.fea.frame.modal import frame_modes

        return frame_modes(self, n_modes, **kw)

    def buckling(self, loads: Iterable[Load], n_modes: int = 1, **kw: Any) -> Any:
        """Linear buckling load factors of ``loads``: :func:`mechverify.fea.frame.modal.frame_buckling`."""
        from mechverify.fea.frame.modal import frame_buckling

        return frame_buckling(self, loads, n_modes, **kw)

    # ---------------------------------------------------------------------------------- solve
    def solve(self, loads: Iterable[Load] = (), *, name: str = "", progress: bool | None = None) -> FrameResults:
        """Linear static solution of one load case."""
        return self.analyse({name: tuple(loads)}, progress=progress).results[name]

    def analyse(self, cases: Mapping[str, Iterable[Load]], combinations: Sequence[LoadCombination] = (), *,
                progress: bool | None = None) -> FrameAnalysis:
        """All load cases on one factorisation of the stiffness, and the factored combinations.

        Linear models: a combination is the factored sum of its cases' results (superposition).
        With one-way springs the model is nonlinear: every case and combination is solved on its own
        (combined) loads by active-set iteration (``results[name].notes`` reports the iterations).
        """
        cases = {str(k): tuple(v) for k, v in cases.items()}
        combos = tuple(combinations)
        for c in combos:
            if not isinstance(c, LoadCombination):
                raise InputError(f"combinations: expected LoadCombination, got {type(c).__name__}")
            for k in c.factors:
                if k not in cases:
                    raise UnknownNameError(f"load case (in combination {c.name!r})", k, cases)
            if c.name in cases:
                raise InputError(f"combination {c.name!r} has the name of a load case")
        mesh = self._mesh([ld for v in cases.values() for ld in v])
        with Steps(progress if progress is not None else mesh.ndof > PROGRESS_THRESHOLD, "frame") as step:
            step("assembling")
            held, springs, one_way, at = self._restraints(mesh)
            # the stiffness, its checks and its factorisation depend on the mesh and the restraints only: kept per
            # process while only the loads change (a study over a load; mechverify/fea/factorcache.py)
            key = factorcache.key_of("frame", *_stiffness_inputs(mesh), held, sorted(springs.items()),
                                     sorted(one_way.items()), DENSE_CHECK_LIMIT)
            item, _ = factorcache.CACHE.entry(key)
            try:
                K, Kff, Kfs, free = factorcache.CACHE.part(
                    item, "system", lambda: self._system(mesh, held, springs, one_way))
            except Exception:
                factorcache.CACHE.forget(key)
                raise
            hs = set(held.tolist())
            data = {nm: self._case(mesh, lds, hs) for nm, lds in cases.items()}
            ctx = _Solve(self, mesh, K, Kff, Kfs, free, held, springs, one_way, at, item)
            results: dict[str, FrameResults] = {}
            if not one_way:
                step(f"solving {len(free)} unknowns, {len(cases)} load case(s)")
                U = ctx.linear(list(data.values()))
                for j, (nm, dat) in enumerate(data.items()):
                    results[nm] = ctx.results(U[:, j], dat, nm, cases[nm], {})
                for c in combos:
                    results[c.name] = FrameResults.combine(c.name, [(fac, results[k]) for k, fac in c.factors.items()])
            else:
                for nm, dat in data.items():
                    step(f"solving {nm!r} with one-way springs")
                    results[nm] = ctx.one_way_solve(dat, nm, cases[nm])
                for c in combos:
                    step(f"solving {c.name!r} with one-way springs")
                    dat = _CaseData.combine([(fac, data[k]) for k, fac in c.factors.items()])
                    lds = tuple(ld for k in c.factors for ld in cases[k])
                    results[c.name] = ctx.one_way_solve(dat, c.name, lds, factors=c.factors)
        return FrameAnalysis(self, results, tuple(cases), combos)


def _stiffness_inputs(mesh: _Mesh) -> tuple[Any, ...]:
    """What :meth:`Frame._system` reads of a mesh: node positions, elements, their local stiffness (section,
    material, theory and length), releases, springs (as numbers)."""
    return (mesh.points, mesh.elem_nodes, mesh.dofs, mesh.ndof, mesh.R, mesh.k,
            sorted((e, c.P) for e, c in mesh.cond.items()),
            [(s.axial, sorted(s.stiffness.items()), a, b, n) for s, a, b, n in mesh.springs],
            sorted(mesh.released_nodes))


def _transforms(R: np.ndarray) -> np.ndarray:
    T = np.zeros((len(R), 12, 12))
    for b in range(4):
        T[:, 3 * b:3 * b + 3, 3 * b:3 * b + 3] = R
    return T


def _node_order(A: sp.spmatrix, free: np.ndarray) -> np.ndarray:
    """A fill-reducing order of the DOFs ``free`` of ``A``: minimum degree (SuperLU's MMD on Aᵀ + A) of the node
    graph, each node's DOFs consecutive."""
    node = free // 6
    used, loc = np.unique(node, return_inverse=True)
    C = A.tocoo()
    n = len(used)
    G = sp.csc_matrix((np.full(len(C.row), -1.0), (loc[C.row], loc[C.col])), shape=(n, n))
    G = (G + G.T + sp.diags(np.full(n, 1.0 + 2.0 * np.max(np.abs(G).sum(axis=1))))).tocsc()
    rank = spl.splu(G, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}).perm_c
    return np.argsort(rank[loc] * 6 + free % 6, kind="stable")


@dataclass
class _Factor:
    """A factorisation of a permuted matrix; ``solve`` takes and returns the original order."""

    lu: Any
    p: np.ndarray

    def solve(self, b: np.ndarray) -> np.ndarray:
        x = np.empty_like(b, dtype=float)
        x[self.p] = self.lu.solve(np.ascontiguousarray(b[self.p]))
        return x


@dataclass
class _CaseData:
    f: np.ndarray
    q0: np.ndarray
    q1: np.ndarray
    fef: np.ndarray
    F: np.ndarray
    Mo: np.ndarray
    presc: dict[int, float] = field(default_factory=dict)

    @staticmethod
    def combine(parts: list[tuple[float, _CaseData]]) -> _CaseData:
        presc: dict[int, float] = {}
        for fac, d in parts:
            for k, v in d.presc.items():
                presc[k] = presc.get(k, 0.0) + fac * v
        return _CaseData(*(sum(fac * getattr(d, a) for fac, d in parts) for a in ("f", "q0", "q1", "fef", "F", "Mo")),
                         presc)


@dataclass
class _Solve:
    """One assembled model: factorisation, one-way iteration and the results of a solution."""

    frame: Frame
    mesh: _Mesh
    K: sp.csr_matrix  # elements + two-node springs
    Kff: sp.csr_matrix  # free part with linear support springs
    Kfs: sp.csr_matrix
    free: np.ndarray
    held: np.ndarray
    springs: dict[int, float]
    one_way: dict[int, tuple[float, int]]
    at: list[tuple[FrameSupport, int]]
    cached: dict[str, Any] = field(default_factory=dict)  # the factor cache's item of this stiffness

    def _factor(self, A: sp.spmatrix) -> _Factor:
        """SuperLU of ``A`` (the free DOFs) in an order found on the node graph: the minimum-degree order
        of the nodes, their six DOFs kept together (less fill and about half the time of ordering the DOFs)."""
        try:
            p = _node_order(A, self.free)
            lu = spl.splu(A.tocsr()[p][:, p].tocsc(), permc_spec="NATURAL", diag_pivot_thresh=0.0,
                          options={"SymmetricMode": True})
        except RuntimeError as exc:
            raise ModelError(f"frame {self.frame.name!r}: the stiffness matrix is singular ({exc}); the model has a "
                             "mechanism") from None
        return _Factor(lu, p)

    def _rhs(self, d: _CaseData) -> np.ndarray:
        us = np.array([d.presc.get(int(h), 0.0) for h in self.held])
        return d.f[self.free] - (self.Kfs @ us if len(us) and np.any(us) else 0.0)

    def _full(self, x: np.ndarray, d: _CaseData) -> np.ndarray:
        u = np.zeros(self.mesh.ndof)
        u[self.free] = x
        for k, v in d.presc.items():
            u[k] = v
        if not np.all(np.isfinite(u)):
            raise ModelError(f"frame {self.frame.name!r}: the solve gave non-finite displacements (a mechanism)")
        return u

    def linear(self, data: list[_CaseData]) -> np.ndarray:
        U = np.zeros((self.mesh.ndof, len(data)))
        if len(self.free):
            B = np.column_stack([self._rhs(d) for d in data])
            X = factorcache.CACHE.part(self.cached, "factor", lambda: self._factor(self.Kff)).solve(B)
            X = X.reshape(len(self.free), len(data))
        else:
            X = np.zeros((0, len(data)))
        for j, d in enumerate(data):
            U[:, j] = self._full(X[:, j], d)
        return U

    def one_way_solve(self, d: _CaseData, name: str, loads: tuple[Load, ...],
                      factors: Mapping[str, float] | None = None) -> FrameResults:
        dofs = np.array(sorted(self.one_way), dtype=np.int64)
        kv = np.array([self.one_way[int(k)][0] for k in dofs])
        sign = np.array([self.one_way[int(k)][1] for k in dofs])
        pos = np.searchsorted(self.free, dofs)
        active = np.ones(len(dofs), dtype=bool)
        rhs = self._rhs(d)
        history = []
        for it in range(1, ONE_WAY_ITERATIONS + 1):  # noqa: B007 (reported after the loop)
            restrained = np.union1d(self.held, np.array(list(self.springs) + list(dofs[active]), dtype=np.int64))
            lifted = f"with the one-way springs at {self._words(dofs[~active])} lifted, the supports"
            self.frame._check_supported(self.mesh, restrained, lifted)
            diag = np.zeros(len(self.free))
            diag[pos[active]] = kv[active]
            x = self._factor(self.Kff + sp.diags(diag)).solve(rhs)
            u = self._full(x, d)
            scale = max(float(np.max(np.abs(u))), 1e-300)
            new = sign * u[dofs] <= 1e-12 * scale
            history.append(int(np.sum(~new)))
            if np.array_equal(new, active):
                break
            active = new
        else:
            raise ModelError(f"frame {self.frame.name!r}, {name!r}: the one-way springs did not settle in "
                             f"{ONE_WAY_ITERATIONS} active-set iterations (lifted per iteration: {history})")
        act = {int(k): float(kk) for k, kk, a in zip(dofs, kv, active, strict=True) if a}
        lifted = self._words(dofs[~active])
        note = (f"one-way springs: active set converged in {it} iteration(s); "
                + (f"lifted (no reaction): {lifted}" if len(dofs[~active]) else "all in contact"))
        if factors is not None:
            note += "; solved on the combined loads (a one-way model does not superpose)"
        return self.results(u, d, name, loads, act, (note,))

    def _words(self, dofs: np.ndarray) -> str:
        return ", ".join(f"{DOF_NAMES[int(k) % 6]} at node {self.mesh.node_words(int(k) // 6)}" for k in dofs) or "none"

    def results(self, u: np.ndarray, d: _CaseData, name: str, loads: tuple[Load, ...], one_way_active: dict[int, float],
                notes: tuple[str, ...] = ()) -> FrameResults:
        mesh, fr = self.mesh, self.frame
        r = self.K @ u - d.f  # forces the supports exert on the frame (springs excluded)
        hs = set(self.held.tolist())
        reactions: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        RF, RM = np.zeros(3), np.zeros(3)
        absF = absM = 0.0
        seen: set[int] = set()
        for s, k in self.at:
            fr6 = np.zeros(6)
            for i in range(6):
                dof = 6 * k + i
                if dof in seen:
                    continue
                if dof in hs:
                    fr6[i] = r[dof]
                elif dof in self.springs:
                    fr6[i] = -self.springs[dof] * u[dof]
                elif dof in one_way_active:
                    fr6[i] = -one_way_active[dof] * u[dof]
                else:
                    continue
                seen.add(dof)
            label = s.at if isinstance(s.at, str) else mesh.names.get(k, f"support {len(reactions) + 1}")
            if label in reactions:
                label = f"{label} ({len(reactions) + 1})"
            reactions[label] = (fr6[:3], fr6[3:])
            RF += fr6[:3]
            RM += fr6[3:] + np.cross(mesh.points[k], fr6[:3])
            absF += float(np.linalg.norm(fr6[:3]))
            absM += float(np.linalg.norm(fr6[3:]))
        scaleF = max(np.linalg.norm(d.F), absF, (np.linalg.norm(d.Mo) + absM) / fr.size, 1e-30)
        scaleM = max(np.linalg.norm(d.Mo), absM, scaleF * fr.size, 1e-30)
        if np.linalg.norm(d.F + RF) > 1e-6 * scaleF or np.linalg.norm(d.Mo + RM) > 1e-6 * scaleM:
            raise ModelError(f"frame {fr.name!r}: reactions do not balance the loads (forces {d.F + RF} N, "
                             f"moments {d.Mo + RM} N·m); the model is ill-conditioned")
        ne = len(mesh.L)
        if ne:
            ug = u[mesh.dofs].reshape(ne, 4, 3)
            ul = np.einsum("eij,ekj->eki", mesh.R, ug).reshape(ne, 12)
            g = np.einsum("eij,ej->ei", mesh.k, ul) - d.fef
            end, ulocal = g.copy(), ul.copy()
            for e, c in mesh.cond.items():
                end[e] = c.P @ g[e]
                ulocal[e] = ul[e] - c.W @ g[e]
        else:
            end = ulocal = np.zeros((0, 12))
        spring_forces = {}
        for s, a, b, n in mesh.springs:
            du = u[6 * b:6 * b + 6] - u[6 * a:6 * a + 6]
            comps = np.zeros(6)
            for c, kv in s.stiffness.items():
                i = DOF_NAMES.index(c)
                comps[i] = kv * du[i]
            axial = s.axial * float(np.dot(n, du[:3])) if s.axial is not None else 0.0
            spring_forces[s.name] = (axial, comps)
        return FrameResults(fr, mesh, u, ulocal, end, d.q0, d.q1, reactions, d.F, d.Mo, name, loads,
                            mesh.notes + notes, spring_forces)
