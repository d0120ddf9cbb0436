"""One results object for every continuum model (solid, plane stress, plate): fields at the nodes,
maxima and where they occur, reactions, safety factors, VTU export and a report figure.

Stresses are nodal tensors recovered from the element stresses (superconvergent patch recovery by
default, see :mod:`mechverify.fea.recovery`); von Mises and principal stresses are derived from them.
The raw integration-point stresses, the stress at any point (:meth:`FieldResults.stress_at`) and the
Zienkiewicz-Zhu error indicator (:attr:`FieldResults.element_error`, :attr:`FieldResults.error_estimate`)
come with the solid and plane results. Everything is stored in SI and returned as
pint quantities.

References
----------
1. von Mises equivalent stress: Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed.,
   2015, eq. 5-12. Principal stresses: ibid., sec. 3-7 (eigenvalues of the stress tensor).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import pint

from mechverify.errors import InputError, renamed
from mechverify.materials.material import Material
from mechverify.units import Q, QuantityLike

if TYPE_CHECKING:  # annotations only: results are read without scipy (a fast cold start)
    from mechverify.fea.linsolve import SolveInfo


@dataclass(frozen=True)
class FieldExtreme:
    """A field's extreme value, where it occurs (node coordinates) and the node's index."""

    value: pint.Quantity
    location: pint.Quantity  # [3] m
    node: int

    def __str__(self) -> str:
        loc = ", ".join(f"{c:.4g}" for c in self.location.m_as("mm"))
        v = self.value
        unit = {"[length]": "mm", "[mass] / [length] / [time] ** 2": "MPa"}.get(str(v.dimensionality))
        text = f"{v.m_as(unit):.4g} {unit}" if unit else f"{v.m:.4g}"
        return f"{text} at ({loc}) mm"


def von_mises(s: np.ndarray) -> np.ndarray:
    """Von Mises stress of tensors ``s[..., 3, 3]`` [Pa] (ref. 1, eq. 5-12)."""
    dev = s - np.trace(s, axis1=-2, axis2=-1)[..., None, None] / 3.0 * np.eye(3)
    return np.sqrt(1.5 * np.einsum("...ij,...ij->...", dev, dev))


def principal(s: np.ndarray) -> np.ndarray:
    """Principal stresses ``[..., 3]`` in descending order (σ1 ≥ σ2 ≥ σ3)."""
    return np.linalg.eigvalsh(s)[..., ::-1]


@dataclass(frozen=True, eq=False)
class FieldResults:
    """Results of a linear static continuum analysis.

    Raw SI arrays: ``points[n, 3]`` (m), ``u[n, 3]`` (m), ``sigma[n, 3, 3]`` (Pa, nodal, projected),
    ``reaction[3]`` and ``applied[3]`` (N, totals), ``cells`` meshio blocks for export,
    ``surface[k, 3]`` triangles (node indices) for figures, ``extra`` further nodal fields
    (e.g. top/bottom surface stresses of a plate).
    """

    kind: str
    points: np.ndarray
    u: np.ndarray
    sigma: np.ndarray
    material: Material
    reaction: np.ndarray
    applied: np.ndarray
    cells: list[tuple[str, np.ndarray]]
    surface: np.ndarray
    info: SolveInfo
    timings: Mapping[str, float] = field(default_factory=dict)
    extra: Mapping[str, np.ndarray] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    regions: tuple[Any, ...] = ()  # RegionReport per load and support (mechverify.fea.loads)
    warnings: tuple[str, ...] = ()  # e.g. a load region that caught less than the named geometry
    recovery: str = ""  # how sigma was recovered at the nodes (mechverify.fea.recovery.METHODS)
    elements: np.ndarray | None = None  # [e, nb] P2 node indices (vertices first), for stress_at
    ip_points: np.ndarray | None = None  # [e, q, 3] m, order-2 integration points (CalculiX order)
    ip_sigma: np.ndarray | None = None  # [e, q, 3, 3] Pa at those points (unsmoothed)
    element_error: np.ndarray | None = None  # [e] ZZ indicator η_e, sqrt of energy (J^0.5)
    error_estimate: float | None = None  # η / sqrt(‖σ*‖² + η²), estimated relative energy-norm error

    # -- fields -------------------------------------------------------------------------------
    @property
    def displacement(self) -> pint.Quantity:
        """Nodal displacement vectors ``[n, 3]``."""
        return Q(self.u, "m")

    @property
    def stress(self) -> pint.Quantity:
        """Nodal stress tensors ``[n, 3, 3]`` (projected)."""
        return Q(self.sigma, "Pa")

    @cached_property
    def _vm(self) -> np.ndarray:
        return von_mises(self.sigma)

    @property
    def von_mises(self) -> pint.Quantity:
        """Nodal von Mises stress ``[n]``."""
        return Q(self._vm, "Pa")

    @property
    def principal_stresses(self) -> pint.Quantity:
        """Nodal principal stresses ``[n, 3]``, σ1 ≥ σ2 ≥ σ3."""
        return Q(principal(self.sigma), "Pa")

    @property
    def reactions(self) -> pint.Quantity:
        """Total support reaction force ``[3]`` (balances the applied loads)."""
        return Q(self.reaction, "N")

    @property
    def applied_load(self) -> pint.Quantity:
        """Total applied force ``[3]`` (surface loads plus self-weight)."""
        return Q(self.applied, "N")

    @property
    def integration_point_stress(self) -> pint.Quantity:
        """Stress tensors ``[e, q, 3, 3]`` at the integration points of each element (unsmoothed)."""
        if self.ip_sigma is None:
            raise InputError(f"{self.kind} results carry no integration-point stresses")
        return Q(self.ip_sigma, "Pa")

    def stress_at(self, points: QuantityLike) -> pint.Quantity:
        """The recovered stress tensor ``[k, 3, 3]`` at points ``[k, 2|3]`` (lengths: a quantity array or
        strings; plain numbers are metres), interpolated in the element containing each point with the
        P2 shape functions. A point outside the mesh raises :class:`InputError`. In curved elements the
        point is located and interpolated in the straight-sided element of the same vertices (exact at
        the nodes and on straight faces)."""
        from mechverify.units import to_si

        if self.elements is None:
            raise InputError(f"{self.kind} results do not support stress_at (no element connectivity)")
        if hasattr(points, "units"):
            X = np.atleast_2d(np.asarray(to_si(points, "length", "points"), float))
        else:
            X = np.atleast_2d(np.array([[float(c) if isinstance(c, int | float | np.number) else
                                         to_si(c, "length", "points") for c in row]
                                        for row in np.atleast_2d(np.asarray(points, dtype=object))], float))
        dim = 3 if self.kind == "solid" else 2
        if X.shape[1] < dim:
            raise InputError(f"stress_at: points need {dim} coordinates, got shape {X.shape}")
        X = X[:, :dim]
        elem, bary = self._locate(X)
        from mechverify.fea.recovery import _voigt, p2_values

        comps = _voigt(self.sigma if dim == 3 else self.sigma[:, :2, :2])
        out = np.empty((X.shape[0], 3, 3))
        for k in range(X.shape[0]):
            v = p2_values(self.elements[elem[k]:elem[k] + 1].T, comps, bary[k][None])[0, 0]
            out[k] = self._tensor(v, dim)
        return Q(out, "Pa")

    def _tensor(self, v: np.ndarray, dim: int) -> np.ndarray:
        s = np.zeros((3, 3))
        if dim == 3:
            s[0, 0], s[1, 1], s[2, 2] = v[0], v[1], v[2]
            s[0, 1] = s[1, 0] = v[3]
            s[1, 2] = s[2, 1] = v[4]
            s[0, 2] = s[2, 0] = v[5]
        else:
            s[0, 0], s[1, 1] = v[0], v[1]
            s[0, 1] = s[1, 0] = v[2]
            if self.kind == "plane strain":
                s[2, 2] = self.material.nu.m_as("") * (v[0] + v[1])
        return s

    def _locate(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Element index and barycentric coordinates of each point (nearest centroids first)."""
        from scipy.spatial import cKDTree

        dim = X.shape[1]
        verts = self.points[self.elements[:, : dim + 1], :dim]  # e, nv, d
        cent = verts.mean(axis=1)
        tree = cKDTree(cent)
        k = min(32, cent.shape[0])
        _, cand = tree.query(X, k=k)
        cand = np.atleast_2d(cand).reshape(X.shape[0], -1)
        elem = np.full(X.shape[0], -1)
        bary = np.zeros((X.shape[0], dim + 1))
        size = float(np.linalg.norm(np.ptp(self.points, axis=0)))
        for i, x in enumerate(X):
            for pool in (cand[i], np.arange(cent.shape[0])):
                V = verts[pool]  # c, nv, d
                T = (V[:, 1:] - V[:, :1]).transpose(0, 2, 1)  # c, d, d
                lam = np.linalg.solve(T, (x - V[:, 0])[:, :, None])[:, :, 0]
                L = np.column_stack([1 - lam.sum(axis=1), lam])
                tol = 1e-9 * (1 + size)
                ok = np.flatnonzero(L.min(axis=1) >= -tol)
                if ok.size:
                    j = ok[np.argmax(L[ok].min(axis=1))]
                    elem[i], bary[i] = pool[j], L[j]
                    break
            if elem[i] < 0:
                raise InputError(f"stress_at: the point {tuple(np.round(x * 1e3, 4))} mm lies outside the mesh")
        return elem, bary

    # -- extremes -----------------------------------------------------------------------------
    def _extreme(self, values: np.ndarray, unit: str, largest: bool = True) -> FieldExtreme:
        i = int(np.argmax(values) if largest else np.argmin(values))
        return FieldExtreme(Q(float(values[i]), unit), Q(self.points[i], "m"), i)

    @property
    def max_displacement(self) -> FieldExtreme:
        """Largest displacement magnitude and where."""
        return self._extreme(np.linalg.norm(self.u, axis=1), "m")

    @property
    def max_von_mises(self) -> FieldExtreme:
        """Largest von Mises stress and where."""
        return self._extreme(self._vm, "Pa")

    @property
    def max_principal(self) -> FieldExtreme:
        """Largest (most tensile) principal stress and where."""
        return self._extreme(principal(self.sigma)[:, 0], "Pa")

    @property
    def min_principal(self) -> FieldExtreme:
        """Most compressive principal stress and where."""
        return self._extreme(principal(self.sigma)[:, 2], "Pa", largest=False)

    # -- safety -------------------------------------------------------------------------------
    def safety_factor(self, strength: str = "yield_strength") -> pint.Quantity:
        """Nodal static safety factor ``strength / σ_vM`` against the material (distortion energy).

        ``strength`` names a material property (``yield_strength`` or ``ultimate_strength``);
        unstressed nodes get ``inf``. Ref. 1, eq. 5-19 (n = Sy/σ').
        """
        if strength not in ("yield_strength", "ultimate_strength"):
            raise InputError(f"strength must be 'yield_strength' or 'ultimate_strength', got {strength!r}")
        S = self.material.require(strength).m_as("Pa")
        sf = np.full(self._vm.shape, np.inf)
        stressed = self._vm > 1e-12 * S
        sf[stressed] = S / self._vm[stressed]
        return Q(sf, "")

    def min_safety_factor(self, strength: str = "yield_strength") -> FieldExtreme:
        """Smallest static safety factor and where (at the largest von Mises stress)."""
        return self._extreme(self.safety_factor(strength).m, "", largest=False)

    def signed_von_mises(self) -> pint.Quantity:
        """Von Mises stress with the sign of the principal stress of largest magnitude (tension +),
        the equivalent stress FEA tools use for fatigue with mean stress."""
        p = principal(self.sigma)
        dominant = np.where(np.abs(p[:, 0]) >= np.abs(p[:, 2]), p[:, 0], p[:, 2])
        return Q(np.where(dominant < 0, -self._vm, self._vm), "Pa")

    def fatigue_safety_factor(self, criterion: str = "goodman", stress_ratio: float = -1.0,
                              cycles: float | None = None, endurance: QuantityLike | None = None,
                              load_line: str = "proportional") -> pint.Quantity:
        """Nodal fatigue safety factor when the loads cycle between ``stress_ratio`` x this load case and
        the load case itself (R = -1 fully reversed, R = 0 repeated on-off).

        Equivalent stress: signed von Mises ``σ_eq``; amplitude ``|1 - R|/2 |σ_eq|``, mean ``(1 + R)/2 σ_eq``.
        Fatigue strength ``Se``: ``endurance`` if given, else the material's S-N curve (fully reversed
        amplitudes) at ``cycles`` (its last point, the endurance level, when ``cycles`` is None), else its
        endurance limit. Mean-stress ``criterion`` from :mod:`mechverify.fatigue.criteria` (Goodman
        default: Shigley 10th ed., eq. 6-46, n = 1/(σa/Se + σm/Sut)).
        """
        from mechverify.fatigue import criteria
        from mechverify.units import to_si

        mat = self.material
        if endurance is not None:
            Se = to_si(endurance, "pressure", "endurance")
        elif mat.sn_curve is not None:
            sn = mat.sn_curve
            Se = sn.stress_at(cycles if cycles is not None else sn.cycles[-1]).m_as("Pa")
        elif mat.endurance_limit is not None:
            Se = mat.endurance_limit.m_as("Pa")
        else:
            raise InputError(f"material {mat.name!r} has no S-N curve or endurance limit; give endurance=")
        if not -1.0 <= float(stress_ratio) < 1.0:
            raise InputError(f"stress_ratio must lie in [-1, 1), got {stress_ratio!r}")
        seq = self.signed_von_mises().m_as("Pa")
        sa = abs(1 - stress_ratio) / 2 * np.abs(seq)
        sm = (1 + stress_ratio) / 2 * seq
        kw = {"Sut": mat.ultimate_strength.m_as("Pa") if mat.ultimate_strength is not None else None,
              "Sy": mat.yield_strength.m_as("Pa") if mat.yield_strength is not None else None}
        n = criteria.safety_factor.si(criterion, sa, sm, Se, load_line=load_line, **kw)
        return Q(np.asarray(n, float), "")

    def min_fatigue_safety_factor(self, **kw: Any) -> FieldExtreme:
        """Smallest fatigue safety factor and where (arguments of :meth:`fatigue_safety_factor`)."""
        return self._extreme(self.fatigue_safety_factor(**kw).m, "", largest=False)

    # -- export -------------------------------------------------------------------------------
    def to_vtu(self, path: str | Path) -> Path:
        """Write nodes, cells and fields (displacement, stress, von Mises, principal, safety) to VTU
        (meshio's writer, or mechverify's own if meshio fails: :func:`mechverify.fea.vtu.write_vtu`)."""
        from mechverify.fea.vtu import write_vtu

        path = Path(path)
        s = self.sigma
        data: dict[str, np.ndarray] = {
            "displacement_m": self.u,
            "von_mises_Pa": self._vm,
            "principal_Pa": principal(s),
            "stress_Pa": np.column_stack([s[:, 0, 0], s[:, 1, 1], s[:, 2, 2], s[:, 0, 1], s[:, 1, 2], s[:, 0, 2]]),
        }
        if self.material.yield_strength is not None:
            data["safety_factor_yield"] = np.minimum(self.safety_factor().m, 1e6)
        for k, v in self.extra.items():
            data[k] = v
        return write_vtu(path, self.points, self.cells, data)

    def plot(self, path: str | Path | None = None, field: str = "von_mises", scale: float | None = None,
             title: str | None = None) -> Any:
        """Contour of ``field`` (``von_mises``, ``displacement``, ``safety``) on the deformed shape,
        the maximum marked. Deformation is magnified to 5 % of the model size unless ``scale`` is
        given. Saves to ``path`` when given; returns the matplotlib figure.
        """
        from mechverify.fea.figures import contour_figure

        return contour_figure(self, path, field, scale, title)

    def summary(self) -> dict[str, Any]:
        """Headline numbers: maxima with locations, minimum safety factor, reactions, solver."""
        out: dict[str, Any] = {
            "max_displacement": self.max_displacement,
            "max_von_mises": self.max_von_mises,
            "reaction": self.reactions,
            "applied": self.applied_load,
            "solver": self.info,
        }
        if self.regions:
            out["regions"] = [str(r) for r in self.regions]
        if self.warnings:
            out["warnings"] = list(self.warnings)
        if self.material.yield_strength is not None:
            out["min_safety_factor"] = self.min_safety_factor()
        return out

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"Extreme": "FieldExtreme"})
