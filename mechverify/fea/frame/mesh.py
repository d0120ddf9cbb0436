"""The analysis model of a frame: node lookup by a spatial hash, members split at supports, loads and
nodes lying inside them (with a note), element properties converted once, end releases condensed."""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from mechverify.components.sections import Section
from mechverify.errors import InputError
from mechverify.fea.frame.element import Condensed, condense, local_axes_batch, local_stiffness_batch
from mechverify.fea.frame.model import (
    DOF_NAMES,
    NO_SHEAR_AREAS,
    DistributedLoad,
    FramePointLoad,
    Load,
    MemberPointLoad,
    Spring,
    SupportDisplacement,
    _axis,
)
from mechverify.materials.material import Material
from mechverify.units import to_si

if TYPE_CHECKING:
    from mechverify.fea.frame.analysis import Frame


@dataclass(frozen=True)
class _Props:
    E: float
    G: float
    A: float
    Iy: float
    Iz: float
    J: float
    Asy: float | None  # None: Euler-Bernoulli (no shear deformation)
    Asz: float | None
    rho: float
    roll: float  # principal-axis rotation of the section [rad]

    @property
    def sy(self) -> float:
        return 1 / (self.G * self.Asy) if self.Asy and math.isfinite(self.Asy) else 0.0

    @property
    def sz(self) -> float:
        return 1 / (self.G * self.Asz) if self.Asz and math.isfinite(self.Asz) else 0.0


def _props(section: Section, mat: Material, theory: str, name: str) -> _Props:
    s = section.si()
    E = to_si(mat.require("E"), "pressure", "E")
    if mat.G is None:
        raise InputError(f"member {name}: material {mat.name!r} has no shear modulus G (nor nu)")
    G = to_si(mat.G, "pressure", "G")
    rho = to_si(mat.density, "density", "density") if mat.density is not None else float("nan")
    Iy, Iz, roll = s["Iy"], s["Iz"], 0.0
    if abs(s["Iyz"]) > 1e-9 * (s["Iy"] + s["Iz"]):
        Iy, Iz, roll = s["I1"], s["I2"], s["principal_angle"]
    tim = theory == "timoshenko" and NO_SHEAR_AREAS not in section.method
    return _Props(E, G, s["area"], Iy, Iz, s["J"], s["Asy"] if tim else None, s["Asz"] if tim else None, rho, roll)


class _PointIndex:
    """Points with a tolerance: a spatial hash of cells 2·tol wide (neighbouring cells searched)."""

    def __init__(self, tol: float):
        self.tol, self.h = tol, 2 * tol
        self.cells: dict[tuple[int, int, int], list[int]] = defaultdict(list)
        self.pts: list[np.ndarray] = []

    def _key(self, p: np.ndarray) -> tuple[int, int, int]:
        return (math.floor(p[0] / self.h), math.floor(p[1] / self.h), math.floor(p[2] / self.h))

    def add(self, p: np.ndarray) -> int:
        self.pts.append(p)
        self.cells[self._key(p)].append(len(self.pts) - 1)
        return len(self.pts) - 1

    def find(self, p: np.ndarray) -> int | None:
        kx, ky, kz = self._key(p)
        best = None
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for i in self.cells.get((kx + dx, ky + dy, kz + dz), ()):
                        q = self.pts[i]
                        if (best is None or i < best) and math.dist(p, q) <= self.tol:
                            best = i
        return best

    def get(self, p: np.ndarray) -> int:
        i = self.find(p)
        return self.add(p) if i is None else i


@dataclass(frozen=True)
class _Mesh:
    """The analysis model: nodes (members split at nodes, supports, loads), elements, springs."""

    points: np.ndarray  # [n, 3]
    names: dict[int, str]  # node -> user name
    named: dict[str, int]  # user name -> node
    index: _PointIndex
    dofs: np.ndarray  # [ne, 12]
    ndof: int
    elem_nodes: np.ndarray  # [ne, 2]
    elem_member: np.ndarray  # [ne]
    elem_s0: np.ndarray  # [ne] start position along the member [m]
    R: np.ndarray  # [ne, 3, 3]
    L: np.ndarray  # [ne]
    props: list[_Props]  # per element
    k: np.ndarray  # [ne, 12, 12] local stiffness
    cond: dict[int, Condensed]  # released elements
    member_elems: list[np.ndarray]  # per member, its elements in order
    springs: list[tuple[Spring, int, int, np.ndarray]]  # spring, node a, node b, axial direction
    released_nodes: dict[int, list[str]]  # node -> "member M end" words
    notes: tuple[str, ...]

    def node_words(self, node: int) -> str:
        return self.names.get(node, "(" + ", ".join(f"{c * 1e3:.4g}" for c in self.points[node]) + ") mm")



def build_mesh(fr: Frame, loads: Sequence[Load]) -> _Mesh:
    """The analysis model of ``fr`` for ``loads``: members split at supports, loads and inner nodes."""
    tol = fr.tol
    idx = _PointIndex(tol)
    named: dict[str, int] = {}
    for nm in [w for m in fr.members for w in (m.start, m.end)] + \
              [w for s in fr.springs for w in (s.start, s.end)]:
        if isinstance(nm, str) and nm not in named:
            named[nm] = idx.add(fr.nodes[nm])
    lengths = np.linalg.norm(fr._d, axis=1)
    splits: list[list[float]] = [[0.0, 1.0] + [k / m.divisions for k in range(1, m.divisions)]
                                 for m in fr.members]
    for where in [s.at for s in fr.supports] + [h.at for h in fr.hinges] + \
                 [ld.at for ld in loads if isinstance(ld, FramePointLoad | SupportDisplacement)]:
        for i, t in fr._locate(fr._on_frame(where, "load or support")):
            splits[i].append(t)
    for ld in loads:
        if isinstance(ld, MemberPointLoad):
            i = fr._member(ld.member)
            s = to_si(ld.position, "length", "position")
            if not -tol <= s <= lengths[i] + tol:
                raise InputError(f"member point load on {ld.member}: position {s * 1e3:.4g} mm is outside the "
                                 f"member (length {lengths[i] * 1e3:.4g} mm)")
            splits[i].append(min(max(s / lengths[i], 0.0), 1.0))
        elif isinstance(ld, DistributedLoad):
            i = fr._member(ld.member)
            sa = 0.0 if ld.start is None else to_si(ld.start, "length", "start")
            if sa >= lengths[i] - tol:
                raise InputError(f"distributed load on {ld.member}: start {sa * 1e3:.4g} mm is not before the "
                                 f"member's end (length {lengths[i] * 1e3:.4g} mm)")
            for v in (ld.start, ld.end):
                if v is not None:
                    s = to_si(v, "length", "position")
                    if s > lengths[i] + tol:
                        raise InputError(f"distributed load on {ld.member}: {s * 1e3:.4g} mm lies beyond the "
                                         f"member's end (length {lengths[i] * 1e3:.4g} mm)")
                    splits[i].append(min(s / lengths[i], 1.0))
    notes = _join_inner_nodes(fr, splits, lengths)
    # elements
    enodes, emember, es0, member_elems = [], [], [], []
    for i, m in enumerate(fr.members):
        a, d = fr._a[i], fr._d[i]
        ts = sorted(set(splits[i]))
        keep = [0.0]
        for t in ts[1:]:
            if (t - keep[-1]) * lengths[i] > tol:
                keep.append(t)
        keep[-1] = 1.0
        ids = [named[m.start] if isinstance(m.start, str) else idx.get(a)]
        ids += [idx.get(a + t * d) for t in keep[1:-1]]
        ids.append(named[m.end] if isinstance(m.end, str) else idx.get(a + d))
        first = len(enodes)
        for k in range(len(keep) - 1):
            enodes.append((ids[k], ids[k + 1]))
            emember.append(i)
            es0.append(keep[k] * lengths[i])
        member_elems.append(np.arange(first, len(enodes)))
    spring_nodes = []
    for s, (a, b) in zip(fr.springs, fr.spring_ends, strict=True):
        na = named[s.start] if isinstance(s.start, str) else idx.get(a)
        nb = named[s.end] if isinstance(s.end, str) else idx.get(b)
        if na == nb:
            raise InputError(f"spring {s.name}: both ends are the same node")
        spring_nodes.append((na, nb))
    points = np.array(idx.pts)
    names: dict[int, str] = {}
    for nm, p in fr.nodes.items():
        k = named.get(nm)
        if k is None:
            k = idx.find(p)
            if k is None:
                continue
            named[nm] = k
        names.setdefault(k, nm)
    n = len(points)
    ne = len(enodes)
    en = np.array(enodes, dtype=np.int64).reshape(-1, 2)
    dofs = (6 * en[:, [0] * 6 + [1] * 6] + np.tile(np.arange(6), 2)).astype(np.int64)
    props = [fr._props_of(fr.members[i]) for i in emember]
    R = np.zeros((ne, 3, 3))
    if fr.members:
        Rm = local_axes_batch(fr._a, fr._a + fr._d, [m.orientation for m in fr.members],
                              np.array([fr._props_of(m).roll for m in fr.members]))
        R = Rm[np.array(emember, dtype=np.int64)] if ne else R
    L = np.linalg.norm(points[en[:, 1]] - points[en[:, 0]], axis=1) if ne else np.zeros(0)
    P = np.array([[p.E, p.G, p.A, p.Iy, p.Iz, p.J, p.sy, p.sz] for p in props]).reshape(-1, 8)
    k = local_stiffness_batch(L, *P.T) if ne else np.zeros((0, 12, 12))
    cond, released_nodes = _releases(fr, en, np.array(emember, dtype=np.int64), member_elems, R, k, idx, named)
    springs = []
    for s, (na, nb) in zip(fr.springs, spring_nodes, strict=True):
        d = points[nb] - points[na]
        ln = float(np.linalg.norm(d))
        if s.axial is not None and ln <= tol:
            raise InputError(f"spring {s.name}: an axial spring needs two distinct points (its line of action)")
        for c in s.stiffness:
            i = DOF_NAMES.index(c)
            if i < 3 and ln > tol and np.linalg.norm(np.cross(np.eye(3)[i], d)) > 1e-9 * ln:
                raise InputError(f"spring {s.name}: component {c} acts across the offset between its nodes (it "
                                 "would not be in equilibrium); use coincident nodes or an axial spring")
        springs.append((s, na, nb, d / ln if ln > tol else np.zeros(3)))
    return _Mesh(points, names, named, idx, dofs, 6 * n, en, np.array(emember, dtype=np.int64),
                 np.array(es0, dtype=float), R, L, props, k, cond, member_elems, springs, released_nodes,
                 tuple(notes))

def _join_inner_nodes(fr: Frame, splits: list[list[float]], lengths: np.ndarray) -> list[str]:
    """Split members at named nodes and member ends lying inside them (a T-joint, a node on a beam)."""
    if not fr.members:
        return []
    from scipy.spatial import cKDTree

    names = list(fr.nodes)
    cand = np.array([fr.nodes[n] for n in names] + [p for e in fr.ends for p in e] +
                    [p for e in fr.spring_ends for p in e])
    tree = cKDTree(cand)
    mids = fr._a + fr._d / 2
    notes: list[str] = []
    count = 0
    for i, lst in enumerate(tree.query_ball_point(mids, lengths / 2 + fr.tol)):
        if len(lst) <= 2:
            continue
        P = cand[lst]
        t = (P - fr._a[i]) @ fr._d[i] / lengths[i] ** 2
        dist = np.linalg.norm(fr._a[i] + t[:, None] * fr._d[i] - P, axis=1)
        inner = (t * lengths[i] > fr.tol) & ((1 - t) * lengths[i] > fr.tol) & (dist <= fr.tol)
        done: set[float] = set()
        for j in np.flatnonzero(inner):
            tt = round(float(t[j]), 9)
            if tt in done:
                continue
            done.add(tt)
            splits[i].append(float(t[j]))
            count += 1
            if len(notes) < 5:
                c = lst[j]
                what = f"node {names[c]}" if c < len(names) else \
                    (f"the end of member {fr.members[(c - len(names)) // 2].name}"
                     if c < len(names) + 2 * len(fr.ends) else "a spring end")
                notes.append(f"member {fr.members[i].name} passes through {what} at s = "
                             f"{t[j] * lengths[i] * 1e3:.4g} mm: split there and joined to it")
    if count > len(notes):
        notes.append(f"... {count - len(notes)} more member splits at nodes lying inside members")
    return notes

def _releases(fr: Frame, en: np.ndarray, emember: np.ndarray, member_elems: list[np.ndarray], R: np.ndarray,
              k: np.ndarray, idx: _PointIndex, named: dict[str, int]
              ) -> tuple[dict[int, Condensed], dict[int, list[str]]]:
    vecs: dict[int, list[np.ndarray]] = defaultdict(list)
    released_nodes: dict[int, list[str]] = defaultdict(list)
    for i, m in enumerate(fr.members):
        for end, rel in ((0, m.releases_start), (1, m.releases_end)):
            if not rel:
                continue
            e = int(member_elems[i][0] if end == 0 else member_elems[i][-1])
            for j in rel.indices:
                v = np.zeros(12)
                v[6 * end + j] = 1.0
                vecs[e].append(v)
            released_nodes[int(en[e, end])].append(f"member {m.name} {'start' if end == 0 else 'end'} "
                                                    f"({rel})")
    for h in fr.hinges:
        p = fr.point(h.at)
        node = named.get(h.at) if isinstance(h.at, str) and h.at in named else idx.find(p)
        ends = [(int(e), int(s)) for e, s in zip(*np.nonzero(en == node), strict=True)] if node is not None else []
        if not ends:
            raise InputError(f"hinge at {h.at!r}: no member ends there (a hinge releases member ends)")
        ax = np.eye(3)[_axis(h.axis, "hinge axis")]
        for e, end in (ends[1:] if len(ends) > 1 else ends):
            v = np.zeros(12)
            v[6 * end + 3:6 * end + 6] = R[e] @ ax
            vecs[e].append(v)
            released_nodes[int(en[e, end])].append(f"member {fr.members[emember[e]].name} "
                                                    f"{'start' if end == 0 else 'end'} (hinge about {h.axis})")
    cond: dict[int, Condensed] = {}
    for e, vs in vecs.items():
        U, S, _ = np.linalg.svd(np.column_stack(vs), full_matrices=False)
        C = U[:, S > 1e-9 * S[0]]
        cond[e] = condense(k[e], C, fr.members[emember[e]].name)
    return cond, dict(released_nodes)
