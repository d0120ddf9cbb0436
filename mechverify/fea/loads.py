"""Supports and loads of continuum models, declared in physical terms on regions (never node numbers).

- :class:`Fixed` - every displacement component of a region held at zero (a clamped face).
- :class:`Restraint` - chosen components held (a roller or symmetry plane: ``Restraint(r, x=True)``).
- :class:`PinSupport` - a frictionless pin in a hole: the wall held radially, free tangentially and (unless ``axial``)
  along the axis (:mod:`mechverify.fea.pins`).
- :class:`Force` - a total force spread uniformly (per unit area) over a region: a bolt or pin
  load on a hole wall, a load on a face.
- :class:`Pressure` - a pressure acting on a region, pushing into the surface when positive.
- :class:`PinLoad` - a pin bearing on a hole: a total force spread over the half of the hole's wall
  the pin presses on, as a pressure ``p0 cos θ`` normal to the wall (θ from the force direction).
- :class:`Traction` - a traction field t(x) [Pa] given as a function of position (an exact boundary
  condition of a benchmark, a hydrostatic pressure), integrated exactly enough by Gauss points.
- :class:`Gravity` - self-weight, ρ·g over the volume.

Every load and support may state what its region should catch, ``expect_area=`` (solids: the loaded
or held surface) or ``expect_length=`` (plane models: the boundary length); the model reports what
each caught as a :class:`RegionReport` (count, length or area, resultant) and warns when it differs
by more than :data:`mechverify.fea.regions.MEASURE_RTOL` from that or from the region's own measure.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.errors import InputError, ModelError, renamed
from mechverify.fea.regions import MEASURE_RTOL, Region
from mechverify.frozen import set_fields
from mechverify.units import QuantityLike, to_si


@dataclass(frozen=True)
class RegionReport:
    """What one load or support caught: ``count`` facets (solids: boundary triangles, plane models:
    boundary edges; supports: held nodes), their total ``measure`` (m² or m, ``unit``), the
    ``resultant`` force [N] (a load's total, a support's reaction once solved), the ``expected`` measure
    (stated or the region's own) and a ``warning`` when they differ by more than ``MEASURE_RTOL``."""

    item: str
    count: int
    measure: float
    unit: str
    resultant: tuple[float, ...] | None
    expected: float | None
    warning: str | None

    def __str__(self) -> str:
        scale, u = (1e6, "mm²") if self.unit == "m**2" else (1e3, "mm")
        what = "nodes" if self.item.startswith(("Fixed", "Restraint", "Pin")) else "facets"
        text = f"{self.item}: {self.count} {what}, {self.measure * scale:.6g} {u}"
        if self.resultant is not None:
            text += ", resultant (" + ", ".join(f"{v:.4g}" for v in self.resultant) + ") N"
        return text + (f" - {self.warning}" if self.warning else "")


def compare_measure(item: str, caught: float, expected: float | None, unit: str) -> str | None:
    """A warning when ``caught`` differs from ``expected`` by more than :data:`MEASURE_RTOL`, else None."""
    if expected is None or expected <= 0:
        return None
    ratio = caught / expected
    if abs(ratio - 1.0) <= MEASURE_RTOL:
        return None
    scale, u = (1e6, "mm²") if unit == "m**2" else (1e3, "mm")
    return (f"WARNING: {item} caught {caught * scale:.6g} {u}, {100 * ratio:.1f} % of the expected "
            f"{expected * scale:.6g} {u}; the region misses (or over-reaches) part of the intended boundary")


def straddle_warning(item: str, region: Region, facet_vertices: Any, normals: Any, caught: Any, points: Any,
                     tol: float, samples: Any) -> str | None:
    """A warning when ``region``'s boundary cuts through boundary facets of the surface it selects: an
    uncaught facet that continues a caught one (shares a vertex, normal within 30°) and has an interior
    sample point inside the region - the caught area then depends on where the mesh's nodes fall.

    ``facet_vertices[k, nv]`` vertex indices, ``normals[k, d]`` unit outward normals, ``caught[k]`` mask,
    ``points[d, n]`` coordinates, ``samples[s, nv]`` barycentric interior sample points of a facet.
    """
    import numpy as np

    from mechverify.fea.regions import Named

    if isinstance(region, Named) or not np.any(caught):
        return None
    n = points.shape[1]
    vn = np.zeros((n, normals.shape[1]))
    np.add.at(vn, facet_vertices[caught].ravel(), np.repeat(normals[caught], facet_vertices.shape[1], axis=0))
    touched = np.linalg.norm(vn, axis=1) > 0
    vn[touched] /= np.linalg.norm(vn[touched], axis=1)[:, None]
    cand = np.flatnonzero(~caught & touched[facet_vertices].any(axis=1))
    if cand.size == 0:
        return None
    fv = facet_vertices[cand]
    same = (np.einsum("kvd,kd->kv", vn[fv], normals[cand]) > np.cos(np.radians(30))) & touched[fv]
    cand, fv = cand[same.any(axis=1)], fv[same.any(axis=1)]
    if cand.size == 0:
        return None
    X = np.einsum("sv,dkv->dks", samples, points[:, fv])  # d, k, s
    inside = region.contains(X.reshape(points.shape[0], -1), tol).reshape(cand.size, -1).any(axis=1)
    k = int(inside.sum())
    if k == 0:
        return None
    return (f"WARNING: {item}: the region's boundary cuts through {k} boundary facet(s) of the surface it "
            "selects, so it caught only the whole facets inside it and the caught size depends on the mesh; "
            "align the region with element edges, name the surface in the mesh, or state expect_area/"
            "expect_length")


def _join(*warnings: str | None) -> str | None:
    parts = [w for w in warnings if w]
    return " ".join(parts) if parts else None


def _expect(area: Any, length: Any) -> tuple[float | None, float | None]:
    a = None if area is None else to_si(area, "area", "expect_area")
    ln = None if length is None else to_si(length, "length", "expect_length")
    for name, v in (("expect_area", a), ("expect_length", ln)):
        if v is not None and v <= 0:
            raise InputError(f"{name} must be positive")
    return a, ln


def pin_tractions(vector: Any, area: Any, normal: Any) -> Any:
    """Tractions ``[k, d]`` on wall facets (areas ``[k]``, outward normals ``[k, d]``) for a pin force.

    The body's outward normal on a hole wall points into the hole, so ``cos θ = -n·F̂``; facets with
    cos θ > 0 carry ``p0 cos θ`` along ``-n``; a uniform share on the loaded facets removes the small
    resultant error of a faceted wall, so the facets' resultant is exactly ``vector``. In 3D the cosine
    distribution comes from the force's part across the hole only: the hole's axis is the direction the wall
    normals do not span (the smallest principal direction of the area-weighted normals), and the part along it
    is a uniform shear on the loaded facets (on the whole wall when the force is along the axis: a pin pushed
    along its hole). Before, a force along the axis drove the cosine with facet noise, and its bearing pressure
    exploded (review 3 finding 21: 2510 MPa where beam theory gives 87 MPa).
    """
    import numpy as np

    F = np.asarray(vector, float)[: normal.shape[1]]
    size = float(np.linalg.norm(F))
    Ft = F
    if normal.shape[1] == 3 and len(area) >= 3:
        w, v = np.linalg.eigh((normal * area[:, None]).T @ normal)
        if w[0] <= 1e-3 * w[-1]:  # a wall of one axis (a cylinder, or part of one)
            axis = v[:, 0]
            Ft = F - (F @ axis) * axis
    across = float(np.linalg.norm(Ft))
    if size > 0 and across <= 1e-9 * size:  # along the hole's axis: a uniform shear on the wall
        return np.broadcast_to(F / area.sum(), normal.shape).copy()
    fhat = Ft / across
    c = np.clip(-normal @ fhat, 0.0, None)
    if not np.any(c > 0):
        raise InputError("PinLoad: no wall facet faces the force direction")
    shape = c[:, None] * -normal  # traction per unit p0
    R = (area[:, None] * shape).sum(axis=0)
    p0 = float(Ft @ fhat) / float(R @ fhat)
    t = p0 * shape
    loaded = c > 0
    t[loaded] += (F - p0 * R) / area[loaded].sum()
    return t


def _region(region: Any, what: str) -> Region:
    if not isinstance(region, Region):
        raise InputError(f"{what}: expected a region (Plane, Box, Cylinder, Named, ...), got {region!r}")
    return region


def _vector(value: Any, dim: str, name: str) -> tuple[float, ...]:
    if isinstance(value, str) or not isinstance(value, Sequence) or len(value) not in (2, 3):
        raise InputError(f"{name}: expected 2 or 3 components, got {value!r}")
    return tuple(to_si(v, dim, f"{name}[{i}]") for i, v in enumerate(value))


@dataclass(frozen=True)
class Fixed:
    """All displacement components of ``region`` are zero."""

    region: Region
    expect_area: Any = None
    expect_length: Any = None

    def __post_init__(self) -> None:
        _region(self.region, "Fixed")
        a, ln = _expect(self.expect_area, self.expect_length)
        set_fields(self, expect_area=a, expect_length=ln)

    @property
    def components(self) -> tuple[bool, bool, bool]:
        return (True, True, True)


@dataclass(frozen=True)
class Restraint:
    """The chosen displacement components of ``region`` are zero (roller, slider, symmetry)."""

    region: Region
    x: bool = False
    y: bool = False
    z: bool = False
    expect_area: Any = None
    expect_length: Any = None

    def __post_init__(self) -> None:
        _region(self.region, "Restraint")
        a, ln = _expect(self.expect_area, self.expect_length)
        set_fields(self, expect_area=a, expect_length=ln)
        if not (self.x or self.y or self.z):
            raise InputError("Restraint: hold at least one of x, y, z")

    @property
    def components(self) -> tuple[bool, bool, bool]:
        return (self.x, self.y, self.z)


@dataclass(frozen=True)
class PinSupport:
    """A frictionless pin in a hole: the wall of ``region`` (a cylinder: a hole wall, a STEP cylinder face) held
    **radially** - both ways, bilateral, no contact - and free tangentially, so the part turns about the pin; free
    along the pin's axis unless ``axial`` (then held along it too). The wall's axis is fitted to its nodes
    (:mod:`mechverify.fea.pins`). Unlike :class:`Fixed` on the wall, which clamps the section at the hole, a beam on
    two pinned holes is simply supported. A pin that would lift off the wall is not modelled (no contact)."""

    region: Region
    axial: bool = False
    expect_area: Any = None
    expect_length: Any = None

    def __post_init__(self) -> None:
        _region(self.region, "PinSupport")
        a, ln = _expect(self.expect_area, self.expect_length)
        set_fields(self, expect_area=a, expect_length=ln, axial=bool(self.axial))

    @property
    def components(self) -> tuple[bool, bool, bool]:
        """The reaction's components reported (x, y, z: a pin's reaction is radial, in every direction across)."""
        return (True, True, True)

    @property
    def note(self) -> str:
        """What the support is, for a result's notes."""
        return ("pin: radial held, tangential and rotation free" + (", axial held" if self.axial else ", axial free")
                + " (bilateral: the whole wall held radially both ways, no contact; a pin that lifts off is not "
                  "modelled)")


@dataclass(frozen=True, init=False)
class Force:
    """A total force vector [N] spread uniformly over the area of ``region``."""

    region: Region
    vector: tuple[float, ...]
    expect_area: float | None
    expect_length: float | None

    def __init__(self, region: Region, vector: Any, *, expect_area: Any = None, expect_length: Any = None):
        set_fields(self, region=_region(region, "Force"), vector=_vector(vector, "force", "Force.vector"))
        a, ln = _expect(expect_area, expect_length)
        set_fields(self, expect_area=a, expect_length=ln)


@dataclass(frozen=True, init=False)
class PinLoad:
    """A pin pressing on the wall of a hole (``region``, usually a :class:`Cylinder`) with a total
    force ``vector`` [N]: normal pressure ``p0 cos θ`` on the half of the wall facing the force,
    ``p0`` chosen so the resultant is exactly the force (the cosine bearing distribution usually assumed
    for a close-fitting pin)."""

    region: Region
    vector: tuple[float, ...]
    expect_area: float | None
    expect_length: float | None

    def __init__(self, region: Region, vector: Any, *, expect_area: Any = None, expect_length: Any = None):
        set_fields(self, region=_region(region, "PinLoad"))
        vec = _vector(vector, "force", "PinLoad.vector")
        if not any(vec):
            raise InputError("PinLoad.vector: the force must not be zero")
        set_fields(self, vector=vec)
        a, ln = _expect(expect_area, expect_length)
        set_fields(self, expect_area=a, expect_length=ln)


@dataclass(frozen=True, init=False)
class Pressure:
    """A pressure [Pa] on ``region``; positive pushes into the body (along the inward normal)."""

    region: Region
    value: float
    expect_area: float | None
    expect_length: float | None

    def __init__(self, region: Region, value: QuantityLike, *, expect_area: Any = None, expect_length: Any = None):
        set_fields(self, region=_region(region, "Pressure"), value=to_si(value, "pressure", "Pressure.value"))
        a, ln = _expect(expect_area, expect_length)
        set_fields(self, expect_area=a, expect_length=ln)


@dataclass(frozen=True, init=False)
class Traction:
    """A traction field on ``region``: ``function(points) -> tractions``, with ``points[dim, k]`` in metres
    and tractions ``[dim, k]`` in Pa (force per area on the body's surface, any direction), evaluated at
    Gauss points of each boundary facet (plane models: 3 per edge; solids: 6 per triangle, degree 4)."""

    region: Region
    function: Any
    expect_area: float | None
    expect_length: float | None

    def __init__(self, region: Region, function: Any, *, expect_area: Any = None, expect_length: Any = None):
        set_fields(self, region=_region(region, "Traction"))
        if not callable(function):
            raise InputError(f"Traction: function must be callable (points [dim, k] m -> tractions [dim, k] Pa), "
                             f"got {function!r}")
        set_fields(self, function=function)
        a, ln = _expect(expect_area, expect_length)
        set_fields(self, expect_area=a, expect_length=ln)

    def evaluate(self, points: Any) -> Any:
        """Tractions ``[dim, k]`` at ``points[dim, k]``; an :class:`InputError` when the shape is wrong."""
        import numpy as np

        out = np.asarray(self.function(points), float)
        if out.shape != points.shape:
            out = np.broadcast_to(out, points.shape) if out.shape in ((points.shape[0], 1),) else out
        if out.shape != points.shape or not np.all(np.isfinite(out)):
            raise InputError(f"Traction: the function returned shape {out.shape} (or non-finite values) for "
                             f"points of shape {points.shape}")
        return out


@dataclass(frozen=True, init=False)
class Gravity:
    """Self-weight: a body force ρ·g; ``acceleration`` defaults to standard gravity along -z (-y in 2D)."""

    acceleration: tuple[float, ...] | None

    def __init__(self, acceleration: Any = None):
        acc = None if acceleration is None else _vector(acceleration, "acceleration", "Gravity.acceleration")
        set_fields(self, acceleration=acc)


STANDARD_GRAVITY = 9.80665  # m/s^2, CGPM 1901 (ISO 80000-3)


def held_load_names(loads: Sequence[Any], parts: Sequence[np.ndarray], held: np.ndarray) -> list[str]:
    """Names of the ``loads`` whose nodal force vectors ``parts`` lie wholly on the ``held`` DOFs (solid and
    plane models); a :class:`ModelError` when every load does (nothing would be loaded: zero stress, a silent
    PASS). No loads at all (a load case of ``gravity = false`` only) name none."""
    if not parts:
        return []
    free = np.ones(parts[0].size, bool)
    free[held] = False
    out = []
    for i, (ld, fi) in enumerate(zip(loads, parts, strict=True)):
        total = float(np.abs(fi).sum())
        if total > 0 and float(np.abs(fi[free]).sum()) <= 1e-12 * total:
            region = getattr(ld, "region", None)
            out.append(f"load {i} ({type(ld).__name__.lower()}"
                       + (f" on {region.describe()})" if region is not None else ")"))
    if out and len(out) == len(loads):
        raise ModelError("every load acts only on held nodes (" + "; ".join(out) + "): it goes straight into the "
                         "supports and the model carries nothing; check that the loaded face is not also a "
                         "supported face and that no support region catches it")
    return out


def held_load_warnings(names: Sequence[str]) -> tuple[str, ...]:
    """The result warning for each load of :func:`held_load_names`."""
    return tuple(f"{name} acts only on held nodes: all of it goes straight into the supports and it loads nothing "
                 "(a load on a supported face, or a support region that catches the loaded face)" for name in names)

# Former name (issue 16: one meaning per public class name across the package), deprecated.
__getattr__ = renamed(__name__, {"Support": "Restraint"})
