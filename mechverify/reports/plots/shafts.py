"""Figures of shafts: the shaft drawn to scale with its features, bearings and loads; bending moments in two
planes with the resultant and the torque; the deflection curve; and the fatigue safety factor per section."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import plotter

_MARK = {"shoulder": "^", "keyseat": "s", "groove": "v", "cross_hole": "o", "press_fit": "D"}


def draw_shaft(ax: Any, d: dict[str, Any]) -> None:
    """The shaft to scale (x and diameter in mm, equal aspect), features, bearings (triangles) and loads (arrows)."""
    from matplotlib.patches import Rectangle

    for x0, x1, D, bore in d["segments"]:
        ax.add_patch(Rectangle((x0 * 1e3, -D / 2 * 1e3), (x1 - x0) * 1e3, D * 1e3, fc="#d0d7de", ec="0.3", lw=0.8))
        if bore:
            ax.add_patch(Rectangle((x0 * 1e3, -bore / 2 * 1e3), (x1 - x0) * 1e3, bore * 1e3, fc="white", ec="0.5",
                                   lw=0.5))
    Dmax = max(D for *_, D, _ in d["segments"]) * 1e3
    for x, kind, name in d["features"]:
        ax.plot(x * 1e3, Dmax * 0.62, _MARK.get(kind, "o"), color="#8250df", ms=5)
        ax.annotate(name, (x * 1e3, Dmax * 0.7), fontsize=6, ha="center", rotation=60)
    for x, name in d["supports"]:
        ax.plot(x * 1e3, -Dmax * 0.62, "^", color="#0969da", ms=8)
        ax.annotate(name, (x * 1e3, -Dmax * 0.95), fontsize=7, ha="center")
    for x, kind, name in d["loads"]:
        ax.annotate(f"{name} ({kind})", (x * 1e3, 0), (x * 1e3, Dmax * 1.1), fontsize=6, ha="center",
                    arrowprops={"arrowstyle": "->", "color": "#cf222e"})
    L = d["segments"][-1][1] * 1e3
    ax.set_xlim(-0.03 * L, 1.03 * L)
    ax.plot([0, 0], [-Dmax * 1.2, Dmax * 1.5], alpha=0)  # room for the labels (equal aspect adjusts the limits)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_ylabel("D [mm]")


@plotter("shaft_fatigue")
def shaft_figure(result: CheckResult) -> Any:
    """Layout, M/T diagrams, deflection and the fatigue safety factor per section."""
    d = result.details
    if "segments" not in d:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, axs = plt.subplots(4, 1, figsize=(6.5, 8.0), layout="constrained")
    for ax in axs:
        ax.grid(True, lw=0.4, alpha=0.5)
    draw_shaft(axs[0], d)
    axs[0].set_title(f"shaft {result.component}: layout to scale (features ▲■▼, bearings, loads)", fontsize=9)
    x = np.asarray(d["x"]) * 1e3
    axs[1].plot(x, d["My"], lw=0.9, label="M_y (x-z plane)")
    axs[1].plot(x, d["Mz"], lw=0.9, label="M_z (x-y plane)")
    axs[1].plot(x, d["M"], lw=1.6, color="k", label="resultant M")
    axs[1].plot(x, d["T"], lw=1.2, ls="--", color="#cf222e", label="torque T")
    axs[1].set_ylabel("[N·m]")
    axs[1].legend(fontsize=6.5, ncol=4)
    axs[2].plot(x, np.asarray(d["deflection"]) * 1e3, color="#0969da")
    axs[2].set_ylabel("deflection [mm]")
    axs[2].set_xlabel("x [mm]")
    secs = d["sections"]
    n = [min(s["n"], 20.0) for s in secs]
    colours = ["#cf222e" if v < result.required_sf else "#2da44e" for v in n]
    axs[3].bar([s["name"] for s in secs], n, color=colours)
    axs[3].axhline(result.required_sf, color="k", lw=0.8)
    axs[3].set_ylabel(f"n (DE-{d['criterion']})")
    axs[3].tick_params(axis="x", labelsize=7, rotation=20)
    return fig
