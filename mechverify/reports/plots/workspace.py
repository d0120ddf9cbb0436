"""Figure of the workspace check: a map of the sampled workspace, each grid point inside the limited workspace
coloured by the payload the motors hold there (W_max(x, y) = min over motors of T_motor / |tau per unit load|),
points left out in grey, the governing point marked."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("workspace_payload")
def workspace_map(r: CheckResult) -> Any:
    """Workspace map coloured by W_max with the governing point (star) and the points below the payload x SF."""
    import numpy as np

    d = r.details
    if "map_points" not in d or not len(d["map_points"].magnitude):
        return None
    P = d["map_points"].m_as("mm")
    W = d["map_wmax"].m_as("N")
    fig, ax = new_figure(5.5, 4.2)
    out = d.get("map_outside")
    if out is not None and len(out.magnitude):
        O = out.m_as("mm")
        ax.scatter(O[:, 0], O[:, 1], s=4, color="0.85", label="left out (unreachable, limits, singular)",
                   rasterized=True)
    from matplotlib.colors import LogNorm

    # near a singularity W_max grows without bound: a log scale when it spans more than a decade
    lo, hi = float(np.min(W)), float(np.max(W))
    norm = LogNorm(lo, hi) if lo > 0 and hi > 10 * lo else None
    sc = ax.scatter(P[:, 0], P[:, 1], s=14, c=W, cmap="viridis", norm=norm, marker="s", rasterized=True)
    fig.colorbar(sc, ax=ax, label="W_max [N]: payload the motors hold" + (" (log scale)" if norm else ""))
    need = d["map_payload"].m_as("N") * r.required_sf
    low = W < need
    if np.any(low):
        ax.scatter(P[low, 0], P[low, 1], s=16, facecolors="none", edgecolors="#cf222e", lw=0.8, marker="s",
                   label=f"W_max < payload × SF ({need:.4g} N)")
    g = d["map_governing"].m_as("mm")
    ax.plot(g[0], g[1], "*", ms=13, color="#cf222e", mec="k", mew=0.6,
            label=f"governs: {d.get('map_motor', '')} motor, W_max = {r.capacity.m_as('N'):.4g} N")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), fontsize=7, ncol=1, frameon=False)
    ax.set_title(f"{r.component}: workspace map", fontsize=9)
    return fig
