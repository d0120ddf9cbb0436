"""VTU (VTK XML unstructured grid) export: meshio's writer, and a small writer of our own as the fallback.

:func:`write_vtu` writes with meshio when it imports and writes; if meshio is missing or fails (an
incompatible numpy, a regression in an unmaintained release), :func:`write_vtu_own` writes the same file:
ASCII VTK XML (format version 0.1), cell types and node orders of the VTK file-format specification
(quadratic tetrahedron 24 and triangle 22: corners first, then the mid-edge nodes of edges 01, 12, 20,
03, 13, 23 - the order of scikit-fem's P2 elements). Both are checked against the ``vtk`` package's own
reader in the tests.

Reference: Kitware, "VTK File Formats" (XML formats, UnstructuredGrid; cell types in vtkCellType.h).
"""

from __future__ import annotations

import io
import os
import tempfile
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

#: meshio cell type -> (VTK cell type id, nodes per cell)
VTK_TYPES = {"vertex": (1, 1), "line": (3, 2), "triangle": (5, 3), "quad": (9, 4), "tetra": (10, 4),
             "hexahedron": (12, 8), "wedge": (13, 6), "pyramid": (14, 5), "line3": (21, 3), "triangle6": (22, 6),
             "quad8": (23, 8), "tetra10": (24, 10)}


def write_vtu(path: str | Path, points: np.ndarray, cells: Sequence[tuple[str, np.ndarray]],
              point_data: Mapping[str, np.ndarray] | None = None, writer: str = "auto") -> Path:
    """Write a VTU file; ``writer`` is ``"auto"`` (meshio, else our own), ``"meshio"`` or ``"own"``."""
    if writer not in ("auto", "meshio", "own"):
        raise ValueError(f"writer: 'auto', 'meshio' or 'own', got {writer!r}")
    path = Path(path)
    if writer != "own":
        try:
            import meshio

            meshio.Mesh(np.asarray(points, float), [(t, np.asarray(c)) for t, c in cells],
                        point_data=dict(point_data or {})).write(path, file_format="vtu")
            return path
        except Exception as exc:  # ImportError, or meshio failing on this numpy
            if writer == "meshio":
                raise
            warnings.warn(f"meshio could not write {path.name} ({type(exc).__name__}: {exc}); "
                          "using mechverify's own VTU writer", RuntimeWarning, stacklevel=2)
    return write_vtu_own(path, points, cells, point_data)


def write_vtu_own(path: str | Path, points: np.ndarray, cells: Sequence[tuple[str, np.ndarray]],
                  point_data: Mapping[str, np.ndarray] | None = None) -> Path:
    """Write an ASCII VTU file without meshio (atomically: a temporary file renamed into place)."""
    path = Path(path)
    p = np.asarray(points, float)
    if p.ndim != 2 or p.shape[1] not in (2, 3):
        raise ValueError(f"points: expected [n, 2] or [n, 3], got shape {p.shape}")
    if p.shape[1] == 2:
        p = np.column_stack([p, np.zeros(len(p))])
    conn, offsets, types = [], [], []
    end = 0
    for ctype, c in cells:
        if ctype not in VTK_TYPES:
            raise ValueError(f"cell type {ctype!r} has no VTK id here; known: {', '.join(VTK_TYPES)}")
        vid, nn = VTK_TYPES[ctype]
        c = np.asarray(c, np.int64).reshape(-1, nn)
        conn.append(c.ravel())
        offsets.append(end + nn * np.arange(1, len(c) + 1))
        end += nn * len(c)
        types.append(np.full(len(c), vid, np.uint8))
    n_cells = sum(len(t) for t in types)
    out = io.StringIO()
    out.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
              f'<UnstructuredGrid>\n<Piece NumberOfPoints="{len(p)}" NumberOfCells="{n_cells}">\n')
    out.write("<Points>\n")
    _array(out, "Points", p)
    out.write("</Points>\n<Cells>\n")
    _array(out, "connectivity", np.concatenate(conn) if conn else np.zeros(0, np.int64), "Int64")
    _array(out, "offsets", np.concatenate(offsets) if offsets else np.zeros(0, np.int64), "Int64")
    _array(out, "types", np.concatenate(types) if types else np.zeros(0, np.uint8), "UInt8")
    out.write("</Cells>\n")
    if point_data:
        out.write("<PointData>\n")
        for name, values in point_data.items():
            v = np.asarray(values, float)
            if v.shape[0] != len(p):
                raise ValueError(f"point data {name!r}: {v.shape[0]} values for {len(p)} points")
            _array(out, name, v.reshape(len(p), -1) if v.ndim > 1 else v)
        out.write("</PointData>\n")
    out.write("</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="ascii") as f:
            f.write(out.getvalue())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def _array(out: io.StringIO, name: str, a: np.ndarray, dtype: str = "Float64") -> None:
    comps = 1 if a.ndim == 1 else a.shape[1]
    out.write(f'<DataArray type="{dtype}" Name="{name}" NumberOfComponents="{comps}" format="ascii">\n')
    if a.size:
        fmt = "%d" if dtype != "Float64" else "%.17g"
        np.savetxt(out, a.reshape(-1, comps) if a.ndim > 1 else a.reshape(1, -1), fmt=fmt)
    out.write("</DataArray>\n")


__all__ = ["write_vtu", "write_vtu_own", "VTK_TYPES"]
