"""The unknowns and memory of a plate FE model before it is meshed (review 4 finding 13: ``plate_fea`` with
``mesh_size = "0.01 mm"`` was killed after 1 min 45 s - "internal error: MemoryError" under a memory limit - and
0.3 mm took 11.3 GB and 300+ s; solid_fea refuses such meshes by :func:`mechverify.fea.study.require_memory`).

- :func:`estimate_unknowns` - the Morley unknowns (one deflection per vertex, one slope per edge: about 2 per triangle)
  of the mesh :func:`mechverify.fea.plate.plate_mesh` makes: exact for a plain rectangle (structured), else the
  triangles of gmsh's frontal mesh at size h (about A / (0.433 h²), equilateral) plus each hole's or cut-out's
  graded rim (the size grows linearly from the rim's size s to h over :data:`mechverify.fea.plate.RIM_REACH` h:
  the integral of the ring's perimeter over the size squared).
- :func:`require_plate_memory` - an :class:`InputError` at ``mesh_size`` with the estimate and the largest element
  size that fits when the analyses would need more than :data:`mechverify.fea.study.MEMORY_SHARE` of the memory
  available.

Measured (300 x 300 x 3 mm plate, pinned edges, one solve, peak RSS above the imports; load average 2.2-2.5):
structured 4 / 2 / 1 mm: 23 105 / 90 001 / 360 001 unknowns, 69 / 258 / 972 MB = 3.0 / 2.9 / 2.7 kB per unknown;
with a 20 mm hole (gmsh, rim r/30) at 2 mm: 108 340 unknowns, 342 MB = 3.2 kB. The estimate against the meshes made
(free unknowns): structured +0.7 to +2.6 % (the held edges' unknowns counted); the 20 mm hole at 2 / 8 / 25 mm
+5 / +12 / +22 %; 4 bolt holes of 6.6 mm and a rounded cut-out at 15 mm (4 mm at holes) +21 %, 15 / 5 mm (default
rims r/30) +8 / +8 %, 5 mm (1 mm at holes) +10 % (:data:`RIM_FACTOR`, :data:`UNKNOWNS_PER_TRIANGLE`). The reviewer's
0.3 mm plate (4.0 M unknowns, 14 GB estimated) measured 11.3 GB: 2.8 kB per unknown.
"""

from __future__ import annotations

import math
from typing import Any

from mechverify.errors import InputError

#: Peak bytes per unknown of a plate solve (assembly, CHOLMOD/SuperLU factor kept in the factor cache, recovery):
#: measured 2.7-3.2 kB (module docstring), rounded up.
BYTES_PER_UNKNOWN = 3500.0
#: Morley unknowns per triangle: vertices + edges = T/2 + 3T/2 (measured 2.00); 2.1 covers the estimate's low side.
UNKNOWNS_PER_TRIANGLE = 2.1
#: gmsh puts more triangles at a graded rim than the linear size field's integral (its Distance field's sampling
#: and the Min of the fields): measured 1.23-1.44x (holes of 6.6 and 20 mm, rims r/30, mesh 2-25 mm; a rounded
#: cut-out); 1.45 covers them.
RIM_FACTOR = 1.45
#: Area of a gmsh frontal-Delaunay triangle of size h, as a fraction of h² (equilateral: sqrt(3)/4).
TRIANGLE_AREA = math.sqrt(3) / 4


def _rim_triangles(perimeter: float, s: float, h: float, reach: float) -> float:
    """Triangles added by a rim of ``perimeter`` graded from size ``s`` to ``h`` over ``reach`` (sizes linear in the
    distance d; the ring's length perimeter + 2 pi d): the integral of length / size² minus the uniform mesh's."""
    if s >= h:
        return 0.0
    k = (h - s) / reach
    graded = perimeter / k * (1 / s - 1 / h) + 2 * math.pi / k**2 * (math.log(h / s) + s / h - 1)
    uniform = (perimeter * reach + math.pi * reach**2) / h**2
    return RIM_FACTOR * max(0.0, graded - uniform) / TRIANGLE_AREA


def estimate_unknowns(plate: Any, mesh_size: float | None = None, hole_mesh_size: float | None = None,
                      refine: float = 1.0) -> int:
    """The Morley unknowns of :func:`mechverify.fea.plate.plate_mesh` of ``plate`` (sizes [m] as there: default
    mesh size the shorter side / 16; every size divided by ``refine``), without meshing."""
    import shapely

    from mechverify.fea.plate import RIM_REACH, hole_sizes

    region = plate.region
    x0, y0, x1, y1 = region.bounds
    h = (min(x1 - x0, y1 - y0) / 16 if mesh_size is None else float(mesh_size)) / refine
    if not plate.holes and not plate.cutouts and len(plate.outline) == 4 \
            and abs(region.area - (x1 - x0) * (y1 - y0)) <= 1e-12 * region.area:  # structured: exact
        nx, ny = (max(2, round(s / h)) for s in (x1 - x0, y1 - y0))
        nx, ny = nx + nx % 2, ny + ny % 2
        return (nx + 1) * (ny + 1) + nx * (ny + 1) + ny * (nx + 1) + nx * ny
    tri = region.area / (TRIANGLE_AREA * h * h)
    rings = [2 * math.pi * hole.radius for hole in plate.holes]
    rings += [shapely.Polygon(c).length for c in plate.cutouts]
    for perimeter, s in zip(rings, hole_sizes(plate, h, hole_mesh_size, refine), strict=False):
        tri += _rim_triangles(perimeter, s, h, RIM_REACH * h)
    return int(UNKNOWNS_PER_TRIANGLE * tri)


def plate_bytes(unknowns: int, *, refine: float = 1.5, convergence: bool = False, modes: int = 0) -> float:
    """Peak memory [bytes] of ``plate_fea`` on a design mesh of ``unknowns``: its solve (:data:`BYTES_PER_UNKNOWN`),
    whose factor stays cached while the meshes ``refine`` times finer are solved - the frequencies' estimate (one,
    when ``modes`` are asked) and the convergence check (two) - and ``modes`` Lanczos vectors (2 modes + 1) on the
    finest mesh."""
    finer = [refine**2, refine**4] if convergence else ([refine**2] if modes else [])
    total = unknowns * BYTES_PER_UNKNOWN * (1 + sum(finer))
    return total + 8.0 * (2 * modes + 1) * unknowns * (finer[-1] if finer else 1.0) * (modes > 0)


def require_plate_memory(plate: Any, mesh_size: float | None, hole_mesh_size: float | None, *,
                         convergence: bool = False, modes: int = 0, memory: float | None = None) -> int:
    """The estimated unknowns of the design mesh (:func:`estimate_unknowns`); an :class:`InputError` at
    ``mesh_size`` (or ``hole_mesh_size`` when no mesh size would do) with the estimate, the memory needed
    (:func:`plate_bytes`) and the largest mesh size that fits when it exceeds
    :data:`mechverify.fea.study.MEMORY_SHARE` of ``memory`` (default: the memory available now)."""
    from mechverify.fea.study import MEMORY_SHARE, available_memory

    avail = (available_memory() if memory is None else memory) * MEMORY_SHARE
    n = estimate_unknowns(plate, mesh_size, hole_mesh_size)
    need = plate_bytes(n, convergence=convergence, modes=modes)
    if need <= avail:
        return n
    x0, y0, x1, y1 = plate.region.bounds
    short = min(x1 - x0, y1 - y0)
    h = short / 16 if mesh_size is None else float(mesh_size)
    what = f"a mesh of {h * 1e3:.4g} mm elements" + ("" if hole_mesh_size is None
                                                     else f" ({hole_mesh_size * 1e3:.4g} mm at holes)")
    said = (f"{what} would have about {n:,} unknowns and need about {need / 1e9:.3g} GB"
            f"{' (with the convergence check' if convergence else ''}"
            f"{' and ' if convergence and modes else (' (with ' if modes else '')}"
            f"{f'{modes} modes' if modes else ''}{')' if convergence or modes else ''}, "
            f"more than the {avail / 1e9:.3g} GB available")

    def fits(size: float) -> bool:
        return plate_bytes(estimate_unknowns(plate, size, hole_mesh_size), convergence=convergence,
                           modes=modes) <= avail

    if not fits(short):
        raise InputError(f"hole_mesh_size: {said}; even a mesh size of the plate's shorter side does not fit: "
                         "a coarser hole_mesh_size")
    lo, hi = h, short  # bisection in log h: the smallest size that fits
    for _ in range(60):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if not fits(mid) else (lo, mid)
    return_at = "" if hole_mesh_size is None else " with this hole_mesh_size"
    raise InputError(f"mesh_size: {said}; the finest mesh that fits{return_at} has mesh_size >= "
                     f"{hi * 1e3:.3g} mm")


__all__ = ["estimate_unknowns", "plate_bytes", "require_plate_memory", "BYTES_PER_UNKNOWN", "UNKNOWNS_PER_TRIANGLE"]
