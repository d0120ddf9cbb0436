"""Report figures of the FEA eigenvalue checks: the governing mode shape of ``natural_frequency`` and the first
buckling mode of ``buckling_load_factor`` (solids, plates and frames), drawn from the check's details
(node points and the mode's translations scaled to a largest component of 1, frame element lines)."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter

UNDEFORMED = "0.4"  # the undeformed members: dark grey, dashed (the grid is light grey, solid)


def _mode_figure(r: CheckResult, label: str) -> Any:
    import numpy as np

    d = r.details
    if "mode_points" not in d or "mode_shape" not in d:
        return None
    P = d["mode_points"].m_as("mm")
    S = np.asarray(d["mode_shape"], dtype=float)
    span = float(np.max(np.ptp(P, axis=0))) or 1.0
    flat = [k for k in range(3) if np.ptp(P[:, k]) <= 1e-9 * span and np.all(np.delete(S, k, axis=1) == 0)]
    if flat and d.get("mode_lines") is None:  # a plate: plan view coloured by the signed deflection (half-waves)
        k = flat[0]
        i, j = (a for a in range(3) if a != k)
        fig, ax = new_figure()
        sc = ax.scatter(P[:, i], P[:, j], s=6, c=S[:, k], cmap="RdBu_r", vmin=-1, vmax=1, rasterized=True)
        fig.colorbar(sc, ax=ax, label=f"deflection along {'xyz'[k]} (largest 1)")
        ax.set_title(label, fontsize=8)
        ax.set_xlabel(f"{'xyz'[i]} [mm]")
        ax.set_ylabel(f"{'xyz'[j]} [mm]")
        ax.set_aspect("equal", adjustable="datalim")
        return fig
    D = P + 0.12 * span * S  # deformed, the largest motion drawn at 12 % of the model's size
    views = _views(P, S)
    mag = np.linalg.norm(S, axis=1)
    fig, ax = new_figure(7.5 if len(views) > 1 else 5.5, 3.2)
    axes = [ax]
    if len(views) > 1:  # the model's plane and a view that shows the out-of-plane mode
        fig.clear()
        axes = list(fig.subplots(1, 2))
        for a in axes:
            a.grid(True, lw=0.4, alpha=0.5)
    lines = d.get("mode_lines")
    names = "xyz"
    for n, (a, (i, j)) in enumerate(zip(axes, views, strict=True)):
        if lines is not None and len(lines):
            L = np.asarray(lines, dtype=int)
            for p, q in L:  # undeformed dashed and darker than the grid: on a grid line it stayed invisible
                a.plot(P[[p, q], i], P[[p, q], j], color=UNDEFORMED, lw=1.0, ls="--", zorder=2.5)  # (review 4 #21)
                a.plot(D[[p, q], i], D[[p, q], j], color="#0969da", lw=1.5, zorder=3)
            a.plot([], [], color=UNDEFORMED, ls="--", label="undeformed")
            a.plot([], [], color="#0969da", label=label)
        else:
            a.scatter(P[:, i], P[:, j], s=2, color="0.8", label="undeformed", rasterized=True)
            sc = a.scatter(D[:, i], D[:, j], s=3, c=mag, cmap="viridis", label=label, rasterized=True)
            if n == len(views) - 1:
                fig.colorbar(sc, ax=a, label="relative displacement of the mode")
        a.set_xlabel(f"{names[i]} [mm]")
        a.set_ylabel(f"{names[j]} [mm]")
        a.set_aspect("equal", adjustable="datalim")
    if len(views) > 1:
        out = names[views[1][0] if views[1][0] not in views[0] else views[1][1]]
        axes[0].set_title(f"model plane: mode out of plane ({out})", fontsize=8)
        axes[1].set_title(f"side view: the mode along {out}", fontsize=8)
    # above the axes: inside them "best" still sat on the model's points (a mesh fills the whole view)
    axes[0].legend(loc="lower left", bbox_to_anchor=(0.0, 1.01 if len(views) == 1 else 1.08), ncol=2, fontsize=7,
                   frameon=False, borderaxespad=0.0)
    return fig


def _views(P: Any, S: Any) -> list[tuple[int, int]]:
    """The (horizontal, vertical) axes of the figure's views (review 3 finding 15): the model's plane, its two
    largest extents, drawn with the higher axis index up (z up when z is in the view: gravity down the page, a
    portal in x-z stands upright); and when the mode's largest translation is along the third axis (a portal
    swaying out of its plane, invisible in that view), a second view of that axis against the plane's axis
    that keeps z (or its longer one). Members on one line (a beam) have no plane: one view of the line's axis
    against the mode's largest translation (review 4 finding 8: a cantilever bending along y was an x-z view with
    a straight line and a y-z end view)."""
    import numpy as np

    ext = np.ptp(P, axis=0)
    main = int(np.argmax(np.max(np.abs(S), axis=0)))
    long = int(np.argmax(ext))
    if np.sort(ext)[-2] <= 1e-6 * ext[long]:  # members on one line (a beam): one view, along it against the mode
        other = main if main != long else (2 if long != 2 else 0)  # (an axial mode: against z, or x for a column)
        return [tuple(sorted((long, other)))]  # type: ignore[list-item]  # (review 4 finding 8)
    a, b = sorted(int(k) for k in np.argsort(ext, kind="stable")[::-1][:2])  # ties go to the higher axis (z)
    if main in (a, b):
        return [(a, b)]
    keep = b if b == 2 else (a if ext[a] > ext[b] else b)
    return [(a, b), tuple(sorted((keep, main)))]  # type: ignore[list-item]


@plotter("natural_frequency")
def mode_shape_plot(r: CheckResult) -> Any:
    """The governing mode (largest motion drawn at 12 % of the model size) over the undeformed model."""
    d = r.details
    f = d.get("mode_value")
    label = f"mode {d.get('mode_number', '')}" + (f", f = {f.m_as('Hz'):.4g} Hz" if f is not None else "")
    return _mode_figure(r, label)


@plotter("buckling_load_factor")
def buckling_shape_plot(r: CheckResult) -> Any:
    """The first buckling mode over the undeformed model."""
    mu = r.details.get("mode_value")
    return _mode_figure(r, "buckling mode 1" + (f", λ = {float(mu):.4g}" if mu is not None else ""))
