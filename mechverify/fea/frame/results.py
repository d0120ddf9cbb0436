"""Frame results: node displacements and rotations, reactions, spring forces, diagrams along the
members with fibre stresses, exact extremes (stationary points of the closed-form element fields),
combinations by superposition and envelopes over load cases and combinations."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import pint

from mechverify.components.sections import Section
from mechverify.errors import InputError, UnknownNameError, renamed
from mechverify.fea.frame.element import element_polynomials, poly_extremes, stationary_points
from mechverify.fea.frame.model import NO_FIBRES, Load, LoadCombination, Where
from mechverify.units import Q, QuantityLike, to_si

if TYPE_CHECKING:
    from mechverify.fea.frame.analysis import Frame
    from mechverify.fea.frame.mesh import _Mesh

_ROUND_KINDS = ("circle", "tube")
#: Quantities with exact extremes per member: resultants (local axes), displacements (global).
EXTREME_QUANTITIES = ("N", "Vy", "Vz", "T", "My", "Mz", "M", "ux", "uy", "uz", "u")
_UNITS = {"N": "N", "Vy": "N", "Vz": "N", "T": "N*m", "My": "N*m", "Mz": "N*m", "M": "N*m", "ux": "mm", "uy": "mm",
          "uz": "mm", "u": "mm"}


@dataclass(frozen=True)
class Diagram:
    """Fields along one member: position ``s`` from its start, internal resultants (local axes), global
    displacement, and stresses at the section fibres (max over the fibres per position)."""

    member: str
    s: pint.Quantity
    N: pint.Quantity
    Vy: pint.Quantity
    Vz: pint.Quantity
    T: pint.Quantity
    My: pint.Quantity
    Mz: pint.Quantity
    displacement: pint.Quantity  # [n, 3] global
    points: pint.Quantity  # [n, 3] undeformed positions
    normal_stress: pint.Quantity  # [n, nfibre]
    shear_stress: pint.Quantity  # [n]
    von_mises: pint.Quantity  # [n, nfibre]
    fibres: pint.Quantity  # [nfibre, 2] section (y, z) from the centroid

    @property
    def bending_moment(self) -> pint.Quantity:
        """Resultant bending moment ``sqrt(My² + Mz²)``."""
        return (self.My**2 + self.Mz**2) ** 0.5


@dataclass(frozen=True)
class FrameExtreme:
    """A maximum along the frame: value, member, position along it, point in space (and fibre)."""

    value: pint.Quantity
    member: str
    position: pint.Quantity
    location: pint.Quantity
    fibre: pint.Quantity | None = None
    case: str = ""

    def __str__(self) -> str:
        loc = ", ".join(f"{c:.4g}" for c in self.location.m_as("mm"))
        where = f" ({self.case})" if self.case else ""
        return (f"{self.value:.4g~P} in member {self.member} at s = {self.position.m_as('mm'):.4g} mm ({loc}) mm"
                + where)


@dataclass(frozen=True)
class Range:
    """The exact maximum and minimum of one quantity along a member (or over combinations: ``case_max``)."""

    quantity: str
    max: pint.Quantity
    s_max: pint.Quantity
    min: pint.Quantity
    s_min: pint.Quantity
    case_max: str = ""
    case_min: str = ""


def section_fibres(section: Section, n_round: int = 180) -> np.ndarray:
    """Candidate extreme fibres ``[k, 2]`` (y, z from the centroid) [m]: the vertices of the section's
    convex hull (the normal stress is linear over the section, so its extremes lie there); a circle of
    ``n_round`` points for round sections."""
    s = section.si()
    if section.kind in _ROUND_KINDS:
        r = s["c_y_pos"]
        a = np.linspace(0, 2 * math.pi, n_round, endpoint=False)
        return np.column_stack((r * np.cos(a), r * np.sin(a)))
    if section.geometry is None:
        if section.kind == "properties":  # tabulated: the corners of the bounding box are the extreme fibres
            return np.array([[s["c_y_pos"], s["c_z_pos"]], [-s["c_y_neg"], s["c_z_pos"]],
                             [-s["c_y_neg"], -s["c_z_neg"]], [s["c_y_pos"], -s["c_z_neg"]]])
        return np.array([[s["c_y_pos"], 0], [-s["c_y_neg"], 0], [0, s["c_z_pos"]], [0, -s["c_z_neg"]]])
    hull = np.asarray(section.geometry.convex_hull.exterior.coords)[:-1]
    return hull - np.array([s["centroid_y"], s["centroid_z"]])


class FrameResults:
    """Results of one load case or combination; SI arrays inside, quantities out."""

    def __init__(self, frame: Frame, mesh: _Mesh, u: np.ndarray, ulocal: np.ndarray, end_forces: np.ndarray,
                 q0: np.ndarray, q1: np.ndarray, reactions: dict[str, tuple[np.ndarray, np.ndarray]],
                 applied_force: np.ndarray, applied_moment: np.ndarray, name: str, loads: tuple[Load, ...],
                 notes: tuple[str, ...] = (), spring_forces: dict[str, tuple[float, np.ndarray]] | None = None):
        self.frame, self.mesh, self.u, self.ulocal, self.end_forces = frame, mesh, u, ulocal, end_forces
        self.q0, self.q1 = q0, q1
        self._reactions = reactions
        self._F, self._M = applied_force, applied_moment
        self.applied_force = Q(applied_force, "N")
        self.applied_moment = Q(applied_moment, "N*m")
        self.name, self.loads, self.notes = name, loads, tuple(notes)
        self._springs = spring_forces or {}
        self._diagrams: dict[tuple[str, int], Diagram] = {}
        self._ranges: dict[str, dict[str, Range]] = {}

    @staticmethod
    def combine(name: str, parts: Sequence[tuple[float, FrameResults]]) -> FrameResults:
        """The factored sum of results of one model (superposition of a linear model)."""
        r0 = parts[0][1]

        def lin(attr: str) -> Any:
            return sum(f * getattr(r, attr) for f, r in parts)

        reactions = {k: (sum(f * r._reactions[k][0] for f, r in parts), sum(f * r._reactions[k][1] for f, r in parts))
                     for k in r0._reactions}
        springs = {k: (sum(f * r._springs[k][0] for f, r in parts), sum(f * r._springs[k][1] for f, r in parts))
                   for k in r0._springs}
        notes = tuple(dict.fromkeys(n for _, r in parts for n in r.notes))
        loads = tuple(ld for _, r in parts for ld in r.loads)
        factors = " + ".join(f"{f:g}×{r.name}" for f, r in parts)
        return FrameResults(r0.frame, r0.mesh, lin("u"), lin("ulocal"), lin("end_forces"), lin("q0"), lin("q1"),
                            reactions, lin("_F"), lin("_M"), name, loads, (*notes, f"combination {name}: {factors}"),
                            springs)

    # ------------------------------------------------------------------------------- nodes
    def _node(self, where: Where) -> int:
        if isinstance(where, str) and where in self.mesh.named:
            return self.mesh.named[where]
        k = self.mesh.index.find(self.frame.point(where))
        if k is None:
            raise InputError(f"{where!r} is not a node of the analysis; use the member diagram at a position")
        return k

    def displacement(self, where: Where) -> pint.Quantity:
        """Translation (three global components) of a node."""
        k = self._node(where)
        return Q(self.u[6 * k:6 * k + 3].copy(), "m").to("mm")

    def rotation(self, where: Where) -> pint.Quantity:
        """Rotation (three global components) of a node (a released member end turns on its own:
        see ``end_rotation``)."""
        k = self._node(where)
        return Q(self.u[6 * k + 3:6 * k + 6].copy(), "rad")

    def end_rotation(self, member: str, end: str = "start") -> pint.Quantity:
        """Rotation (global components) of a member's own end (differs from the node's at a release)."""
        els = self._elements(member)
        e = int(els[0] if end == "start" else els[-1])
        o = 3 if end == "start" else 9
        return Q(self.mesh.R[e].T @ self.ulocal[e][o:o + 3], "rad")

    @property
    def reactions(self) -> dict[str, tuple[pint.Quantity, pint.Quantity]]:
        """Per support: (force [N], moment [N·m]) the support exerts on the frame, global components."""
        return {k: (Q(f, "N"), Q(m, "N*m")) for k, (f, m) in self._reactions.items()}

    def spring_force(self, name: str) -> dict[str, pint.Quantity]:
        """Forces of a two-node spring: ``axial`` (tension positive) or the six components (force on its end node
        from its start, ``force`` [N] and ``moment`` [N·m], global axes)."""
        if name not in self._springs:
            raise UnknownNameError("spring", name, self._springs)
        axial, comps = self._springs[name]
        return {"axial": Q(axial, "N"), "force": Q(-comps[:3], "N"), "moment": Q(-comps[3:], "N*m")}

    # ------------------------------------------------------------------------- along members
    def _elements(self, member: str) -> np.ndarray:
        if member not in self.frame.member_index:
            raise UnknownNameError("member", member, self.frame.member_index)
        return self.mesh.member_elems[self.frame.member_index[member]]

    def polynomials(self, e: int) -> dict[str, np.ndarray]:
        """Exact fields of element ``e`` as polynomial coefficients in s (local resultants; ``ux``..``uz`` global)."""
        m, pr = self.mesh, self.mesh.props[e]
        c = element_polynomials(m.L[e], self.end_forces[e], self.ulocal[e], self.q0[e], self.q1[e], pr.E, pr.G, pr.A,
                                pr.Iy, pr.Iz, pr.sy, pr.sz)
        loc = np.vstack((c["u"], c["v"], c["w"]))
        glob = m.R[e].T @ loc
        c["ux"], c["uy"], c["uz"] = glob
        return c

    def _element_fields(self, e: int, s: np.ndarray) -> dict[str, np.ndarray]:
        """Internal resultants and global displacements at positions ``s`` (0..L) of element ``e``."""
        c = self.polynomials(e)
        pv = np.polynomial.polynomial.polyval
        out = {k: pv(s, c[k]) for k in ("N", "Vy", "Vz", "T", "My", "Mz")}
        out["disp"] = np.column_stack([pv(s, c[k]) for k in ("ux", "uy", "uz")])
        return out

    def ranges(self, member: str) -> dict[str, Range]:
        """Exact maxima and minima along ``member`` of N, Vy, Vz, T, My, Mz (local axes), the resultant
        moment M, the global displacements ux, uy, uz and their magnitude u: the ends and the stationary
        points of the closed-form fields of each element (no sampling)."""
        if member in self._ranges:
            return self._ranges[member]
        els = self._elements(member)
        best: dict[str, list[float]] = {}
        P = np.polynomial.polynomial
        for e in els:
            c = self.polynomials(int(e))
            c["M"] = P.polyadd(P.polymul(c["My"], c["My"]), P.polymul(c["Mz"], c["Mz"]))
            c["u"] = P.polyadd(P.polyadd(P.polymul(c["ux"], c["ux"]), P.polymul(c["uy"], c["uy"])),
                               P.polymul(c["uz"], c["uz"]))
            s0 = self.mesh.elem_s0[e]
            for k in EXTREME_QUANTITIES:
                hi, shi, lo, slo = poly_extremes(c[k], self.mesh.L[e])
                if k in ("M", "u"):
                    hi, lo = math.sqrt(max(hi, 0.0)), math.sqrt(max(lo, 0.0))
                b = best.get(k)
                if b is None:
                    best[k] = [hi, s0 + shi, lo, s0 + slo]
                else:
                    if hi > b[0]:
                        b[0], b[1] = hi, s0 + shi
                    if lo < b[2]:
                        b[2], b[3] = lo, s0 + slo
        out = {}
        for k, (hi, shi, lo, slo) in best.items():
            unit = _UNITS[k]
            conv = 1e3 if unit == "mm" else 1.0
            out[k] = Range(k, Q(hi * conv, unit), Q(shi * 1e3, "mm"), Q(lo * conv, unit), Q(slo * 1e3, "mm"),
                           self.name, self.name)
        self._ranges[member] = out
        return out

    def diagram(self, member: str, points_per_element: int = 41, fibres: QuantityLike | None = None) -> Diagram:
        """Internal forces, displacements and fibre stresses along ``member`` (the stationary points of the
        moments, shears and axial force are included, so the sampled extremes are the exact ones).

        ``fibres``: points of the section (y, z from the centroid, lengths ``[k, 2]``) where stresses
        are wanted; default the convex-hull vertices (every extreme fibre).
        """
        key = (member, points_per_element)
        if fibres is None and key in self._diagrams:
            return self._diagrams[key]
        els = self._elements(member)
        mem = self.frame.members[self.frame.member_index[member]]
        parts: dict[str, list[np.ndarray]] = {k: [] for k in ("s", "N", "Vy", "Vz", "T", "My", "Mz", "disp", "pts")}
        P = np.polynomial.polynomial
        for e in els:
            Le = self.mesh.L[e]
            c = self.polynomials(int(e))
            extra = [stationary_points(c[k], Le) for k in ("N", "Vy", "Vz", "My", "Mz")]
            extra.append(stationary_points(P.polyadd(P.polymul(c["My"], c["My"]), P.polymul(c["Mz"], c["Mz"])), Le))
            s = np.unique(np.concatenate([np.linspace(0.0, Le, points_per_element), *extra]))
            pv = P.polyval
            a = self.mesh.points[self.mesh.elem_nodes[e, 0]]
            parts["s"].append(self.mesh.elem_s0[e] + s)
            parts["pts"].append(a + np.outer(s, self.mesh.R[e][0]))
            parts["disp"].append(np.column_stack([pv(s, c[k]) for k in ("ux", "uy", "uz")]))
            for k in ("N", "Vy", "Vz", "T", "My", "Mz"):
                parts[k].append(pv(s, c[k]) + 0 * s)
        c2 = {k: np.concatenate(v) for k, v in parts.items()}
        sec = mem.section.si()
        pr = self.mesh.props[els[0]]
        yz = section_fibres(mem.section) if fibres is None else np.atleast_2d(to_si(fibres, "length", "fibres"))
        cr, sr = math.cos(pr.roll), math.sin(pr.roll)
        yp = cr * yz[:, 0] + sr * yz[:, 1]  # fibre in principal axes
        zp = -sr * yz[:, 0] + cr * yz[:, 1]
        sigma = c2["N"][:, None] / pr.A + np.outer(c2["My"], zp) / pr.Iy - np.outer(c2["Mz"], yp) / pr.Iz
        asy = sec["Asy"] if math.isfinite(sec["Asy"]) else sec["area"]
        asz = sec["Asz"] if math.isfinite(sec["Asz"]) else sec["area"]
        tau = np.abs(c2["T"]) / sec["Wt"] + np.hypot(c2["Vy"] / asy, c2["Vz"] / asz)
        vm = np.sqrt(sigma**2 + 3 * tau[:, None] ** 2)
        if NO_FIBRES in mem.section.method:  # stresses unknown: NaN, and asking for them is an error
            sigma, tau, vm = sigma * np.nan, tau * np.nan, vm * np.nan
        d = Diagram(member, Q(c2["s"], "m").to("mm"), Q(c2["N"], "N"), Q(c2["Vy"], "N"), Q(c2["Vz"], "N"),
                    Q(c2["T"], "N*m"), Q(c2["My"], "N*m"), Q(c2["Mz"], "N*m"), Q(c2["disp"], "m").to("mm"),
                    Q(c2["pts"], "m").to("mm"), Q(sigma, "Pa").to("MPa"), Q(tau, "Pa").to("MPa"),
                    Q(vm, "Pa").to("MPa"), Q(yz, "m").to("mm"))
        if fibres is None:
            self._diagrams[key] = d
        return d

    def diagrams(self) -> list[Diagram]:
        return [self.diagram(m.name) for m in self.frame.members]

    # ------------------------------------------------------------------------------- maxima
    def _point_at(self, member: str, s_mm: float) -> pint.Quantity:
        i = self.frame.member_index[member]
        a, d = self.frame._a[i], self.frame._d[i]
        return Q((a + d / np.linalg.norm(d) * s_mm * 1e-3) * 1e3, "mm")

    def _largest(self, key: str) -> FrameExtreme:
        best: tuple[float, str, pint.Quantity] | None = None
        for m in self.frame.members:
            r = self.ranges(m.name)[key]
            v = float(r.max.magnitude)
            if best is None or v > best[0]:
                best = (v, m.name, r.s_max)
        assert best is not None
        return FrameExtreme(Q(best[0], _UNITS[key]), best[1], best[2], self._point_at(best[1], best[2].m_as("mm")),
                       case=self.name)

    @property
    def max_displacement(self) -> FrameExtreme:
        """The largest translation (magnitude) anywhere along the members (exact: stationary points)."""
        return self._largest("u")

    @property
    def max_bending_moment(self) -> FrameExtreme:
        """The largest resultant bending moment ``sqrt(My² + Mz²)`` (exact: stationary points)."""
        return self._largest("M")

    def require_stresses(self) -> None:
        """Raise :class:`~mechverify.errors.InputError` when a member's section has no extreme-fibre distances
        (tabulated properties without ``c_y``, ``c_z``), so that its stresses are unknown."""
        for m in self.frame.members:
            if NO_FIBRES in m.section.method:
                raise InputError(f"member {m.name}: its section (tabulated properties) has no extreme-fibre distances "
                                 "c_y, c_z, so its stresses are unknown; give them in section_from_properties")

    def _extreme(self, values: Any, with_fibre: bool = False) -> FrameExtreme:
        self.require_stresses()
        best: tuple[float, Diagram, int, int] | None = None
        for d in self.diagrams():
            v = np.asarray(values(d))
            idx = np.unravel_index(int(np.argmax(v)), v.shape)
            if best is None or v[idx] > best[0]:
                best = (float(v[idx]), d, int(idx[0]), int(idx[1]) if len(idx) > 1 else -1)
        assert best is not None
        val, d, i, j = best
        return FrameExtreme(val, d.member, d.s[i], d.points[i], d.fibres[j] if with_fibre and j >= 0 else None,
                       case=self.name)

    @property
    def max_von_mises(self) -> FrameExtreme:
        """The largest von Mises stress at any fibre of any member (with the fibre)."""
        e = self._extreme(lambda d: d.von_mises.m_as("MPa"), with_fibre=True)
        return FrameExtreme(Q(e.value, "MPa"), e.member, e.position, e.location, e.fibre, self.name)

    def min_safety_factor(self) -> tuple[float, FrameExtreme]:
        """Smallest yield safety factor ``Sy / sigma_vm`` over all members (each with its material) and where."""
        self.require_stresses()
        best: tuple[float, FrameExtreme] | None = None
        for d in self.diagrams():
            m = self.frame.members[self.frame.member_index[d.member]]
            Sy = m.material.require("yield_strength").m_as("MPa")
            vm = d.von_mises.m_as("MPa")
            i, j = np.unravel_index(int(np.argmax(vm)), vm.shape)
            n = Sy / vm[i, j] if vm[i, j] > 0 else math.inf
            if best is None or n < best[0]:
                best = (n, FrameExtreme(Q(vm[i, j], "MPa"), d.member, d.s[i], d.points[i], d.fibres[j], self.name))
        assert best is not None
        return best

    # ------------------------------------------------------------------------------- figure
    def figure(self, path: str | Path | None = None, scale: float | None = None, title: str | None = None) -> Any:
        """Deformed shape (maximum marked) beside the bending-moment diagram of every member."""
        from mechverify.fea.frame.figure import frame_figure

        return frame_figure(self, path, scale, title)


@dataclass(frozen=True)
class Envelope:
    """Maxima and minima over load cases/combinations: per member (exact along it) and per node."""

    members: dict[str, dict[str, Range]]
    nodes: dict[str, Range]  # "NODE.ux" etc. [mm]
    reactions: dict[str, Range]  # "SUPPORT.Fz" etc. [N, N·m]
    cases: tuple[str, ...]


class FrameAnalysis:
    """All load cases and combinations of one model (one factorisation): ``results[name]``, ``envelope()``."""

    def __init__(self, frame: Frame, results: dict[str, FrameResults], cases: tuple[str, ...],
                 combinations: tuple[LoadCombination, ...]):
        self.frame, self.results, self.cases, self.combinations = frame, results, cases, combinations

    def __getitem__(self, name: str) -> FrameResults:
        if name not in self.results:
            raise UnknownNameError("load case or combination", name, self.results)
        return self.results[name]

    def envelope(self, names: Iterable[str] | None = None) -> Envelope:
        """Max/min of every member quantity (exact) and node/reaction component over ``names`` (default: the
        combinations, or the load cases when there are none), each with the case that governs."""
        names = list(names) if names is not None else ([c.name for c in self.combinations] or list(self.cases))
        res = [self[n] for n in names]
        members: dict[str, dict[str, Range]] = {}
        for m in self.frame.members:
            per: dict[str, Range] = {}
            for r in res:
                for k, rg in r.ranges(m.name).items():
                    per[k] = _merge(per.get(k), rg, r.name)
            members[m.name] = per
        nodes: dict[str, Range] = {}
        reactions: dict[str, Range] = {}
        zero = Q(0.0, "mm")
        for r in res:
            for node, nm in r.mesh.names.items():
                for i, ax in enumerate(("ux", "uy", "uz")):
                    v = Q(r.u[6 * node + i] * 1e3, "mm")
                    nodes[f"{nm}.{ax}"] = _merge(nodes.get(f"{nm}.{ax}"), Range(ax, v, zero, v, zero), r.name)
            for sup, (f, mo) in r.reactions.items():
                for i, ax in enumerate(("Fx", "Fy", "Fz", "Mx", "My", "Mz")):
                    v = (f if i < 3 else mo)[i % 3]
                    reactions[f"{sup}.{ax}"] = _merge(reactions.get(f"{sup}.{ax}"), Range(ax, v, zero, v, zero),
                                                      r.name)
        return Envelope(members, nodes, reactions, tuple(names))


def _merge(a: Range | None, b: Range, case: str) -> Range:
    if a is None:
        return Range(b.quantity, b.max, b.s_max, b.min, b.s_min, case, case)
    hi = (b.max, b.s_max, case) if b.max > a.max else (a.max, a.s_max, a.case_max)
    lo = (b.min, b.s_min, case) if b.min < a.min else (a.min, a.s_min, a.case_min)
    return Range(a.quantity, hi[0], hi[1], lo[0], lo[1], hi[2], lo[2])

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"Extreme": "FrameExtreme"})
