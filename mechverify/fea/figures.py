"""Report figures of continuum results: a colour contour on the deformed shape, the maximum marked."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from mechverify.errors import InputError

if TYPE_CHECKING:
    from mechverify.fea.results import FieldResults

_FIELDS = {"von_mises": ("von Mises stress", "MPa", 1e-6), "displacement": ("displacement", "mm", 1e3),
           "safety": ("safety factor (yield)", "", 1.0)}


def _values(res: FieldResults, field: str) -> np.ndarray:
    if field == "von_mises":
        return res.von_mises.m_as("Pa")
    if field == "displacement":
        return np.linalg.norm(res.u, axis=1)
    if field == "safety":
        return np.minimum(res.safety_factor().m, 10.0)
    raise InputError(f"plot field must be one of {sorted(_FIELDS)}, got {field!r}")


def contour_figure(res: FieldResults, path: str | Path | None, field: str, scale: float | None,
                   title: str | None) -> Any:
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.tri import Triangulation

    label, unit, factor = _FIELDS.get(field, (field, "", 1.0))
    vals = _values(res, field) * factor
    size = float(np.linalg.norm(np.ptp(res.points, axis=0))) or 1.0
    umax = float(np.max(np.linalg.norm(res.u, axis=1)))
    if scale is None:
        scale = 0.05 * size / umax if umax > 0 else 1.0
    X = res.points + scale * res.u
    tri = res.surface
    flat = np.ptp(res.points[:, 2]) <= 1e-12 * size and np.ptp(X[:, 2]) <= 1e-12 * size
    worst = int(np.argmin(vals) if field == "safety" else np.argmax(vals))
    fig = plt.figure(figsize=(7.0, 5.0))
    if flat:
        ax = fig.add_subplot(111)
        T = Triangulation(X[:, 0] * 1e3, X[:, 1] * 1e3, tri)
        cs = ax.tripcolor(T, vals, shading="gouraud", cmap="turbo")
        ax.set_aspect("equal")
        ax.plot(X[worst, 0] * 1e3, X[worst, 1] * 1e3, "k*", ms=12)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
    else:
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        ax = fig.add_subplot(111, projection="3d")
        polys = X[tri] * 1e3
        fv = vals[tri].mean(axis=1)
        norm = matplotlib.colors.Normalize(vmin=float(vals.min()), vmax=float(vals.max()))
        cmap = matplotlib.colormaps["turbo"]
        coll = Poly3DCollection(polys, facecolors=cmap(norm(fv)), edgecolors="none")
        ax.add_collection3d(coll)
        lo, hi = X.min(axis=0) * 1e3, X.max(axis=0) * 1e3
        span = float(np.max(hi - lo))
        mid = (lo + hi) / 2
        for setter, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid):
            setter(m - span / 2, m + span / 2)
        ax.scatter(*(X[worst] * 1e3), color="k", marker="*", s=120, depthshade=False)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_zlabel("z [mm]")
        cs = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
    kind = "min" if field == "safety" else "max"
    fig.colorbar(cs, ax=ax, label=f"{label} [{unit}]" if unit else label, shrink=0.8)
    ax.set_title(title or f"{res.kind}: {label}, {kind} {vals[worst]:.4g} {unit} (★); deformation x{scale:.3g}")
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=120)
        plt.close(fig)
    return fig
