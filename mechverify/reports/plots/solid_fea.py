"""Figures of the solid (and plane) FEA field checks ``solid_stress`` and ``solid_deflection``: the nodes of the
part's outer surface in the view of its two largest extents, coloured by the field (von Mises stress or
displacement magnitude), the governing node marked - from the check's details
(:func:`mechverify.checks.fea.field_details`)."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter

_LABEL = {"solid_stress": "von Mises stress", "solid_deflection": "displacement |u|"}


@plotter("solid_stress", "solid_deflection")
def field_figure(r: CheckResult) -> Any:
    """Surface nodes coloured by the field, the governing node as a star (view: the two largest extents)."""
    import numpy as np

    d = r.details
    if "field_points" not in d or not len(d["field_points"].magnitude):
        return None
    P = d["field_points"].m_as("mm")
    v = d["field_values"]
    unit = f"{v.units:~P}"
    V = np.asarray(v.magnitude, dtype=float)
    g = d["field_point"].m_as("mm")
    ext = np.ptp(np.vstack([P, g]), axis=0)
    i, j = (int(k) for k in np.argsort(ext, kind="stable")[::-1][:2])
    i, j = min(i, j), max(i, j)
    fig, ax = new_figure(5.5, 3.4)
    order = np.argsort(V)  # the largest values drawn last (on top)
    sc = ax.scatter(P[order, i], P[order, j], s=5, c=V[order], cmap="viridis", rasterized=True)
    what = _LABEL.get(r.check, r.check)
    fig.colorbar(sc, ax=ax, label=f"{what} [{unit}] (surface nodes)")
    gv = d["field_value"]
    ax.plot(g[i], g[j], "*", ms=13, color="#cf222e", mec="k", mew=0.6,
            label=f"governing node {d.get('field_node', '')}: {gv.m_as(v.units):.4g} {unit}")
    names = "xyz"
    ax.set_xlabel(f"{names[i]} [mm]")
    ax.set_ylabel(f"{names[j]} [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), fontsize=7, frameon=False)
    ax.set_title(f"{r.component}: {what}, view on the {names[i]}{names[j]} plane", fontsize=9)
    return fig
