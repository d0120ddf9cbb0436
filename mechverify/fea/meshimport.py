"""Meshes made by other tools, read with meshio, for the solid and plane models.

``read_solid_mesh("part.msh")`` returns a :class:`~mechverify.fea.mesh.SolidMesh`, ``read_plane_mesh(...)``
a :class:`~mechverify.fea.mesh2d.NamedMeshTri`; ``read_mesh`` picks by the cells present. Formats are
meshio's, by file extension: Gmsh ``.msh`` (2.2 and 4.1), Abaqus/CalculiX ``.inp`` (gmsh's second-order export
with CPS6 boundary triangles included), Nastran ``.bdf``/``.nas`` (free-field bulk data with a ``BEGIN BULK`` line;
gmsh's own Nastran export has none and is refused with meshio's reason), VTK ``.vtu``/``.vtk`` (no named groups:
select regions with Box or Plane) (:data:`FORMATS`). A file meshio cannot read is an :class:`InputError` with
meshio's reason; a ``unit`` that is not a length a :class:`~mechverify.errors.UnitError`; a volume group used as a
region is named as such with the list of regions.

- Elements: tetrahedra (4 or 10 nodes) for solids, triangles (3 or 6 nodes) for plane models. The models
  always solve with quadratic elements (P2) on the mesh's vertices: a linear mesh is promoted, a quadratic
  one keeps its corner nodes (its mid-side nodes, which a CAD mesher may have put on a curved surface, are
  rebuilt at the straight edges' midpoints). Hexahedra, wedges, pyramids and quadrilaterals are refused
  with a :class:`~mechverify.errors.ModelError` naming them.
- Named groups become regions (:class:`~mechverify.fea.regions.Named`): Gmsh physical groups and Abaqus
  element sets of boundary cells (triangles in 3D, lines in 2D) are named surfaces/curves; a node set
  (Abaqus ``*NSET``) that holds whole boundary faces of a solid is the surface of those faces, else (and in
  2D) a set of named points, as are vertex cells. Volume groups are not regions and are skipped.
- Coordinates are in ``unit`` (default metres: Gmsh and CalculiX have no units; give ``unit="mm"`` for a
  CAD mesh in millimetres).

meshio (MIT) is the common reader of these formats; its import is guarded (a :class:`ModelError` with the
install command), and it is pinned to the tested range in ``pyproject.toml``.
"""

from __future__ import annotations

import contextlib
import io
import re
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.errors import InputError, ModelError, install_hint
from mechverify.units import Q

if TYPE_CHECKING:
    from mechverify.fea.mesh import SolidMesh
    from mechverify.fea.mesh2d import NamedMeshTri

#: File extension -> meshio format name.
FORMATS = {".msh": "gmsh", ".inp": "abaqus", ".bdf": "nastran", ".nas": "nastran", ".fem": "nastran",
           ".vtu": "vtu", ".vtk": "vtk"}
_VOLUME = {"tetra": 4, "tetra10": 4}
_SURFACE = {"triangle": 3, "triangle6": 3}
_LINE = {"line": 2, "line3": 2}
_REFUSED = {"hexahedron", "hexahedron20", "hexahedron27", "wedge", "wedge15", "wedge18", "pyramid", "pyramid13",
            "pyramid14", "quad", "quad8", "quad9", "tetra4", "tetra20"}
MESHIO_HINT = ("reading other tools' meshes needs meshio, a base dependency: reinstall "
               + install_hint("", "'meshio>=5.3,<5.4'"))


def import_meshio() -> Any:
    """meshio, or a :class:`ModelError` with the install command (it is a base dependency, but may be broken)."""
    try:
        import meshio
    except Exception as exc:  # ImportError, or an incompatible numpy failing inside meshio
        raise ModelError(f"{MESHIO_HINT} [{type(exc).__name__}: {exc}]") from None
    return meshio


def _read(path: str | Path) -> Any:
    path = Path(path)
    fmt = FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise InputError(f"{path.name}: unknown mesh format {path.suffix!r}; known: {', '.join(sorted(FORMATS))}")
    if not path.is_file():
        raise InputError(f"{path}: no such mesh file")
    meshio = import_meshio()
    if fmt == "abaqus":
        _abaqus_types(meshio)
    said = io.StringIO()
    try:
        with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
            return meshio.read(path, file_format=fmt)
    except (Exception, SystemExit) as exc:  # ReadError, KeyError, ValueError ...; its readers may sys.exit
        # meshio prints its reason and then exits: keep what it said, not "SystemExit: 1"
        text = re.sub(r"\x1b\[[0-9;]*m", "", said.getvalue()).split("Error: Couldn't read file")[0]
        lines = [x.strip() for x in text.splitlines() if x.strip()]
        if isinstance(exc, SystemExit):
            reason = "; ".join(lines) or "meshio found no valid data of that format in it"
        else:
            reason = f"{type(exc).__name__}: {exc}"
        raise InputError(f"{path.name}: cannot read it as {FORMAT_NAMES[fmt]} mesh ({reason})") from None


#: How a message names each format.
FORMAT_NAMES = {"gmsh": "a Gmsh", "abaqus": "an Abaqus/CalculiX", "nastran": "a Nastran (free-field bulk data)",
                "vtu": "a VTU", "vtk": "a VTK"}

#: Abaqus element types gmsh writes that meshio 5.3 does not know (gmsh's second-order boundary triangles of a
#: C3D10 mesh are CPS6): the same cells as their known siblings.
ABAQUS_EXTRA = {"CPS6": "triangle6", "CPE3": "triangle", "CAX3": "triangle", "CAX6": "triangle6"}


def _abaqus_types(meshio: Any) -> None:
    try:
        from meshio.abaqus import _abaqus
    except Exception:  # another meshio layout: its own table applies
        return
    table = getattr(_abaqus, "abaqus_to_meshio_type", None)
    if isinstance(table, dict):
        for k, v in ABAQUS_EXTRA.items():
            table.setdefault(k, v)


def read_mesh(path: str | Path, unit: str = "m") -> SolidMesh | NamedMeshTri:
    """A solid mesh if the file has tetrahedra, else a plane mesh of its triangles."""
    m = _read(path)
    types = {b.type for b in m.cells}
    if types & set(_VOLUME):
        return _solid(m, Path(path).name, unit)
    return _plane(m, Path(path).name, unit)


def read_solid_mesh(path: str | Path, unit: str = "m") -> SolidMesh:
    """The tetrahedra of a mesh file and its named groups, for :class:`~mechverify.fea.solid.SolidModel`."""
    return _solid(_read(path), Path(path).name, unit)


def read_plane_mesh(path: str | Path, unit: str = "m") -> NamedMeshTri:
    """The triangles of a flat mesh file (in a plane z = const) and its named groups, for
    :class:`~mechverify.fea.plane.PlaneModel`."""
    return _plane(_read(path), Path(path).name, unit)


# ------------------------------------------------------------------------------------- internals
def _refuse(m: Any, name: str, allowed: Mapping[str, int]) -> None:
    bad = sorted({b.type for b in m.cells} & _REFUSED)
    if bad:
        raise ModelError(f"{name}: element types {', '.join(bad)} are not supported; mechverify solves "
                         f"{' / '.join(sorted(allowed))} meshes (mesh the part with tetrahedra or triangles)")


def _blocks(m: Any, kinds: Mapping[str, int]) -> list[tuple[int, np.ndarray]]:
    """(block index, corner connectivity) of the cell blocks of the given types."""
    return [(i, np.asarray(b.data, np.int64)[:, :kinds[b.type]]) for i, b in enumerate(m.cells) if b.type in kinds]


def _groups(m: Any, kinds: Mapping[str, int]) -> dict[str, np.ndarray]:
    """Named cell sets restricted to cells of ``kinds``: name -> corner connectivity [k, nc]."""
    out: dict[str, list[np.ndarray]] = {}
    blocks = dict(_blocks(m, kinds))
    for name, per_block in (m.cell_sets or {}).items():
        if name.startswith("gmsh:"):
            continue
        for i, idx in enumerate(per_block):
            if i in blocks and idx is not None and len(idx):
                out.setdefault(name, []).append(blocks[i][np.asarray(idx, np.int64)])
    # Gmsh files without cell_sets (older meshio paths): physical tags + field_data names
    phys = (m.cell_data or {}).get("gmsh:physical")
    if not out and phys is not None and m.field_data:
        tag_name = {int(v[0]): (k, int(v[1])) for k, v in m.field_data.items()}
        for i, conn in blocks.items():
            for tag in np.unique(phys[i]):
                if int(tag) in tag_name:
                    out.setdefault(tag_name[int(tag)][0], []).append(conn[np.asarray(phys[i]) == tag])
    return {k: np.vstack(v) for k, v in out.items()}


def _scale(unit: str) -> float:
    from mechverify.errors import UnitError

    try:
        return float(Q(1, unit).m_as("m"))
    except Exception as exc:  # an unknown unit or one that is not a length
        raise UnitError(f"unit: the mesh's coordinates need a length unit (m, mm, in), got {unit!r} "
                        f"({type(exc).__name__})") from None


def _cells(m: Any, name: str, unit: str, kinds: Mapping[str, int],
           what: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The corner connectivity of the mesh's cells of ``kinds`` (the file's node numbers), the file's -> compact node
    numbers of the nodes they use (-1 for the others) and those nodes' coordinates in metres (a row each). A mesh
    without such cells (``what``: "tetrahedra") or with element types mechverify does not solve: :class:`ModelError`."""
    _refuse(m, name, kinds)
    cells = [c for _, c in _blocks(m, kinds)]
    if not cells:
        raise ModelError(f"{name}: no {what} in the mesh (cell types: "
                         f"{', '.join(sorted({b.type for b in m.cells})) or 'none'})")
    t = np.vstack(cells)
    used = np.unique(t)
    remap = np.full(len(m.points), -1, np.int64)
    remap[used] = np.arange(used.size)
    return t, remap, np.asarray(m.points, float)[used] * _scale(unit)


def _solid(m: Any, name: str, unit: str) -> SolidMesh:
    from skfem import MeshTet

    from mechverify.fea.mesh import SolidMesh, contiguous, orient

    t, remap, pts = _cells(m, name, unit, _VOLUME, "tetrahedra")
    p = pts.T
    if p.shape[0] == 2:
        raise ModelError(f"{name}: the mesh points are 2D; a solid needs 3D coordinates")
    named: dict[str, np.ndarray] = {}
    for kinds in (_SURFACE, _LINE, {"vertex": 1}):
        for gname, conn in _groups(m, kinds).items():
            r = remap[conn]
            r = r[np.all(r >= 0, axis=1)]
            if len(r):
                named.setdefault(gname, np.unique(np.sort(r, axis=1), axis=0))
    tt = remap[t].T
    tet = MeshTet(*contiguous(p, orient(p, tt)))
    boundary = np.sort(tet.facets[:, tet.boundary_facets()].T, axis=1)
    volumes = tuple(sorted(_groups(m, _VOLUME)))
    for gname, idx in (m.point_sets or {}).items():
        r = remap[np.asarray(idx, np.int64)]
        r = np.unique(r[r >= 0])  # mid-side nodes of a quadratic mesh are not vertices: dropped
        if not len(r) or gname in named or gname in volumes:  # gmsh writes an *NSET of each volume group too
            continue
        # a node set holding whole boundary facets (an Abaqus *NSET of a face) is that surface, so that its
        # mid-side nodes are held too; otherwise a set of points
        faces = boundary[np.all(np.isin(boundary, r), axis=1)]
        named[gname] = faces if len(faces) else r[:, None]
    return SolidMesh(tet, named, volumes=volumes)


def _plane(m: Any, name: str, unit: str) -> NamedMeshTri:
    from mechverify.fea.mesh2d import NamedMeshTri, _facets_of, orient_triangles, tri_mesh

    t, remap, pts = _cells(m, name, unit, _SURFACE, "triangles")
    if pts.shape[1] == 3:
        z = pts[:, 2]
        if np.ptp(z) > 1e-9 * max(float(np.ptp(pts[:, :2], axis=0).max()), 1e-300):
            raise ModelError(f"{name}: the triangles do not lie in a plane z = const (z spans "
                             f"{np.ptp(z):.3g} m); a plane model needs a flat mesh in x-y")
    p = pts[:, :2].T
    tt = remap[t].T
    base = tri_mesh(p, orient_triangles(p, tt))
    points: dict[str, np.ndarray] = {}
    for gname, conn in _groups(m, {"vertex": 1}).items():
        r = remap[conn.ravel()]
        points[gname] = np.unique(r[r >= 0])
    for gname, idx in (m.point_sets or {}).items():
        r = remap[np.asarray(idx, np.int64)]
        if gname not in points and np.any(r >= 0):
            points[gname] = np.unique(r[r >= 0])
    mesh = NamedMeshTri(base.p, base.t, sort_t=False, named_points=points)
    curves = {}
    for gname, conn in _groups(m, _LINE).items():
        r = remap[conn]
        r = r[np.all(r >= 0, axis=1)]
        if len(r):
            curves[gname] = _facets_of(mesh, r.T)
    return mesh.with_boundaries(curves) if curves else mesh


__all__ = ["FORMATS", "read_mesh", "read_solid_mesh", "read_plane_mesh", "import_meshio"]
