"""The report figure of a frame solution: deformed shape and bending moments along the members."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from mechverify.fea.frame.results import FrameResults


def frame_figure(res: FrameResults, path: str | Path | None = None, scale: float | None = None,
                 title: str | None = None) -> Any:
    """The report figure of a frame solution: undeformed (grey) and deformed shape with the largest
    displacement marked (★), and the bending moments along each member."""
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    ds = res.diagrams()
    mx = res.max_displacement
    umax = mx.value.m_as("m")
    size = res.frame.size
    if scale is None:
        scale = 0.1 * size / umax if umax > 0 else 1.0
    pts = np.vstack([d.points.m_as("m") for d in ds])
    dis = np.vstack([d.displacement.m_as("m") for d in ds])
    span = np.ptp(np.vstack((pts, pts + scale * dis)), axis=0)
    flat = [i for i in range(3) if span[i] <= 1e-9 * size]
    fig = plt.figure(figsize=(10.0, 4.2))
    if flat:
        a, b = [i for i in range(3) if i != flat[0]]
        ax = fig.add_subplot(1, 2, 1)
        for d in ds:
            p, u = d.points.m_as("mm"), d.displacement.m_as("mm")
            ax.plot(p[:, a], p[:, b], color="0.7", lw=1.5)
            ax.plot(p[:, a] + scale * u[:, a], p[:, b] + scale * u[:, b], lw=2)
        i = int(np.argmin(np.linalg.norm(pts - mx.location.m_as("m"), axis=1)))
        tip = (pts[i] + scale * dis[i]) * 1e3
        ax.plot(tip[a], tip[b], "k*", ms=12)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{'xyz'[a]} [mm]")
        ax.set_ylabel(f"{'xyz'[b]} [mm]")
    else:
        ax = fig.add_subplot(1, 2, 1, projection="3d")
        for d in ds:
            p, u = d.points.m_as("mm"), d.displacement.m_as("mm")
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color="0.7", lw=1.5)
            ax.plot(*(p + scale * u).T, lw=2)
        i = int(np.argmin(np.linalg.norm(pts - mx.location.m_as("m"), axis=1)))
        ax.scatter(*((pts[i] + scale * dis[i]) * 1e3), color="k", marker="*", s=120, depthshade=False)
        both = np.vstack((pts, pts + scale * dis)) * 1e3
        lo, hi = both.min(axis=0), both.max(axis=0)
        mid, half = (lo + hi) / 2, float(np.max(hi - lo)) / 2 or 1.0
        ax.set_xlim(mid[0] - half, mid[0] + half)
        ax.set_ylim(mid[1] - half, mid[1] + half)
        ax.set_zlim(mid[2] - half, mid[2] + half)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_zlabel("z [mm]")
    ax.set_title(f"deformed shape x{scale:.3g}; max {mx.value.m_as('mm'):.4g} mm (★) in {mx.member}", fontsize=9)
    ax2 = fig.add_subplot(1, 2, 2)
    for d in ds:
        s = d.s.m_as("mm")
        my, mz = d.My.m_as("N*m"), d.Mz.m_as("N*m")
        if np.max(np.abs(my)) >= np.max(np.abs(mz)):
            ax2.plot(s, my, lw=1.8, label=f"{d.member}: M_y")
        else:
            ax2.plot(s, mz, lw=1.8, ls="--", label=f"{d.member}: M_z")
    ax2.axhline(0.0, color="0.5", lw=0.8)
    mm = res.max_bending_moment
    ax2.set_title(f"bending moment along each member; max |M| {mm.value.m_as('N*m'):.4g} N·m in {mm.member}",
                  fontsize=9)
    ax2.set_xlabel("position along the member from its start [mm]")
    ax2.set_ylabel("moment [N·m]")
    ax2.legend(fontsize=7, ncol=2 if len(ds) > 6 else 1)
    ax2.grid(alpha=0.3)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=120)
        plt.close(fig)
    return fig
