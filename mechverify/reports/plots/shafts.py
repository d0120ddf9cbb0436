"""Figures of shafts: the shaft drawn to scale with its features, bearings and loads; bending moments in two
planes with the resultant and the torque; the deflection curve; and the fatigue safety factor per section."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import plotter

_MARK = {"shoulder": "^", "keyseat": "s", "groove": "v", "cross_hole": "o", "press_fit": "D"}


def label_levels(spans: list[tuple[float, float]], gap: float = 0.0) -> list[int]:
    """Rows for labels ``(centre, width)`` (any order) so that no two labels of a row overlap: each label takes
    the lowest row whose last label ends before it starts (greedy, by centre)."""
    ends: list[float] = []
    rows = [0] * len(spans)
    for i in sorted(range(len(spans)), key=lambda k: spans[k][0]):
        c, w = spans[i]
        for r, e in enumerate(ends):
            if c - w / 2 > e + gap:
                ends[r], rows[i] = c + w / 2, r
                break
        else:
            ends.append(c + w / 2)
            rows[i] = len(ends) - 1
    return rows


def draw_shaft(ax: Any, d: dict[str, Any], width_pt: float = 400.0) -> None:
    """The shaft to scale (x and diameter in mm, equal aspect), features, bearings (triangles) and loads (arrows).

    Labels are horizontal, in rows (offsets in points, so they keep clear of each other whatever the aspect):
    features and loads above the shaft, bearings below; ``width_pt`` is the axes width the label widths are
    estimated for."""
    from matplotlib.patches import Rectangle

    for x0, x1, D, bore in d["segments"]:
        ax.add_patch(Rectangle((x0 * 1e3, -D / 2 * 1e3), (x1 - x0) * 1e3, D * 1e3, fc="#d0d7de", ec="0.3", lw=0.8))
        if bore:
            ax.add_patch(Rectangle((x0 * 1e3, -bore / 2 * 1e3), (x1 - x0) * 1e3, bore * 1e3, fc="white", ec="0.5",
                                   lw=0.5))
    Dmax = max(D for *_, D, _ in d["segments"]) * 1e3
    L = d["segments"][-1][1] * 1e3
    mm_per_pt = 1.06 * L / width_pt
    font = 7.0

    def width(text: str) -> float:
        return (len(text) * 0.58 * font + 4) * mm_per_pt

    above = [(x * 1e3, name or kind, "feature", kind) for x, kind, name in d["features"]]
    above += [(x * 1e3, name if name == kind or not kind else f"{name} ({kind})", "load", kind)
              for x, kind, name in d["loads"]]
    def centre(x: float, text: str) -> float:  # a label near an end moved inwards, to stay inside the axes
        w = width(text)
        return min(max(x, -0.03 * L + w / 2), 1.03 * L - w / 2)

    rows = label_levels([(centre(x, t), width(t)) for x, t, *_ in above])
    top = Dmax / 2
    for (x, text, what, kind), row in zip(above, rows, strict=True):
        if what == "feature":
            ax.plot(x, top, _MARK.get(kind, "o"), color="#8250df", ms=4, zorder=3)
            arrow = {"arrowstyle": "-", "color": "#8250df", "lw": 0.5}
        else:
            arrow = {"arrowstyle": "->", "color": "#cf222e", "lw": 0.8}
        ax.annotate(text, (x, top), xytext=((centre(x, text) - x) / mm_per_pt, 8 + 9.5 * row),
                    textcoords="offset points", fontsize=font, ha="center", va="bottom",
                    color="#cf222e" if what == "load" else "0.15", arrowprops=arrow,
                    # a lower row above the leaders of higher rows, its text on white: no line through a label
                    zorder=4 - 0.01 * row, bbox={"fc": "white", "ec": "none", "pad": 0.3, "alpha": 0.9})
    sups = [(x * 1e3, name) for x, name in d["supports"]]
    for (x, name), row in zip(sups, label_levels([(centre(x, n), width(n)) for x, n in sups]), strict=True):
        ax.plot(x, -Dmax / 2, "^", color="#0969da", ms=7, zorder=3)
        ax.annotate(name, (x, -Dmax / 2), xytext=((centre(x, name) - x) / mm_per_pt, -10 - 9.5 * row),
                    textcoords="offset points", fontsize=font, ha="center", va="top", color="#0969da")
    ax.set_xlim(-0.03 * L, 1.03 * L)
    # room for the label rows (equal aspect: y span = x span x box height / box width, set by the figure)
    ax.plot([0, 0], [-1.5 * Dmax, 2.5 * Dmax], alpha=0)  # more room above (set_ylim would fight the aspect)
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

    fig, axs = plt.subplots(4, 1, figsize=(6.5, 9.0), layout="constrained", height_ratios=(1.4, 1, 1, 1))
    for ax in axs:
        ax.grid(True, lw=0.4, alpha=0.5)
    draw_shaft(axs[0], d, width_pt=6.5 * 72 * 0.84)
    axs[0].set_title(f"shaft {result.component}: layout to scale (features ▲■▼, bearings, loads)", fontsize=9,
                     pad=4)
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
    axs[3].bar([s.get("label", s["name"]) for s in secs], n, color=colours)
    axs[3].axhline(result.required_sf, color="k", lw=0.8)
    axs[3].set_ylabel(f"n (DE-{d['criterion']})")
    axs[3].tick_params(axis="x", labelsize=7, rotation=20)
    return fig
