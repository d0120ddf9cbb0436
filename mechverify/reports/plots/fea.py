"""Report figures of the FEA eigenvalue checks: the governing mode shape of ``natural_frequency`` and the first
buckling mode of ``buckling_load_factor`` (solids, plates and frames), drawn from the check's details
(node points and the mode's translations scaled to a largest component of 1, frame element lines)."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


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
    # view: the two axes of the largest extent of the deformed shape
    ext = np.ptp(np.vstack([P, D]), axis=0)
    i, j = (int(k) for k in np.argsort(ext)[::-1][:2])
    mag = np.linalg.norm(S, axis=1)
    fig, ax = new_figure()
    lines = d.get("mode_lines")
    if lines is not None and len(lines):
        L = np.asarray(lines, dtype=int)
        for a, b in L:
            ax.plot(P[[a, b], i], P[[a, b], j], color="0.75", lw=1.0)
            ax.plot(D[[a, b], i], D[[a, b], j], color="#0969da", lw=1.5)
        ax.plot([], [], color="0.75", label="undeformed")
        ax.plot([], [], color="#0969da", label=label)
    else:
        ax.scatter(P[:, i], P[:, j], s=2, color="0.8", label="undeformed", rasterized=True)
        sc = ax.scatter(D[:, i], D[:, j], s=3, c=mag, cmap="viridis", label=label, rasterized=True)
        fig.colorbar(sc, ax=ax, label="relative displacement of the mode")
    names = "xyz"
    ax.set_xlabel(f"{names[i]} [mm]")
    ax.set_ylabel(f"{names[j]} [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    # above the axes: inside them "best" still sat on the model's points (a mesh fills the whole view)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=2, fontsize=7, frameon=False, borderaxespad=0.0)
    return fig


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
