"""Report figures for links and plates: the beam case's moment and deflection diagrams, the column curve."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("link_deflection", "member_body_strength")
def beam_diagram(r: CheckResult) -> Any:
    """Bending moment and deflection along the link for its Shigley Table A-9 case (from the result's details)."""
    from mechverify.components.links import beam_deflection_curve, beam_moment_diagram

    d = r.details
    if not {"beam_case", "load_si", "length", "EI"} <= set(d):
        return None
    L = d["length"].m_as("m")
    x, y = beam_deflection_curve(d["beam_case"], d["load_si"], L, d["EI"].m_as("N*m**2"))
    _, M = beam_moment_diagram(d["beam_case"], d["load_si"], L)
    fig, ax = new_figure(5.5, 4.2)
    fig.delaxes(ax)
    top, bottom = fig.subplots(2, 1, sharex=True)
    for a in (top, bottom):
        a.grid(True, lw=0.4, alpha=0.5)
    top.fill_between(x * 1e3, M, color="#0969da", alpha=0.15)
    top.plot(x * 1e3, M, color="#0969da")
    top.set_ylabel("bending moment M [N·m]")
    top.set_title(d["beam_case"].replace("_", " ") + " (Table A-9)", fontsize=8)
    ymax = float(abs(y).max()) * 1e3
    bottom.plot(x * 1e3, y * 1e3, color="#0969da", label=f"deflection (max {ymax:.3g} mm)")
    if "limit" in d:
        lim = d["limit"].m_as("mm")
        if lim < 3 * ymax:  # draw the limit where it is comparable; otherwise name it
            bottom.axhline(-lim, color="#cf222e", ls="--", lw=1, label=f"limit {lim:.3g} mm")
            bottom.axhline(lim, color="#cf222e", ls="--", lw=1)
        else:
            bottom.plot([], [], " ", label=f"limit {lim:.3g} mm (off scale)")
    bottom.axhline(0, color="k", lw=0.6)
    bottom.set_xlabel("position along the link x [mm]")
    bottom.set_ylabel("deflection y [mm]")
    bottom.legend(fontsize=7, loc="best")
    return fig


@plotter("member_buckling")
def column_curve(r: CheckResult) -> Any:
    """Critical stress against slenderness: Euler C π² E/(l/k)² beyond (l/k)_1, Johnson parabola below it,
    with the allowable (critical / required SF) and the link's operating point."""
    import numpy as np

    d = r.details
    if not {"C", "E", "Sy", "area", "slenderness"} <= set(d):
        return None
    C, E, Sy = float(d["C"]), d["E"].m_as("MPa"), d["Sy"].m_as("MPa")
    lk, lk1 = float(d["slenderness"]), float(d["transition_slenderness"])
    s_op = r.demand.m_as("N") / d["area"].m_as("mm**2")
    top = max(2.0 * lk1, 1.3 * lk)
    s = np.linspace(1e-3, top, 400)
    euler = C * np.pi**2 * E / s**2
    johnson = Sy - (Sy * s / (2 * np.pi)) ** 2 / (C * E)
    crit = np.where(s < lk1, johnson, euler)
    fig, ax = new_figure()
    ax.plot(s, np.minimum(euler, 1.5 * Sy), color="#8c959f", ls=":", lw=1, label="Euler (beyond its range)")
    ax.plot(s, crit, color="#0969da", label="critical stress (Johnson | Euler)")
    ax.plot(s, crit / r.required_sf, color="#0969da", ls="--", lw=1, label=f"allowable (÷ SF {r.required_sf:g})")
    ax.axvline(lk1, color="k", lw=0.6, ls="-.", label=f"(l/k)₁ = {lk1:.3g}")
    colour = {"pass": "#2da44e", "warn": "#bf8700", "fail": "#cf222e"}[r.verdict.value]
    ax.plot([lk], [s_op], "o", color=colour, label=f"link: l/k = {lk:.3g}, P/A = {s_op:.3g} MPa")
    ax.set_xlim(0, top)
    ax.set_ylim(0, 1.1 * Sy)
    ax.set_xlabel("slenderness ratio l/k")
    ax.set_ylabel("stress P/A [MPa]")
    ax.legend(fontsize=7, loc="upper right")
    return fig
