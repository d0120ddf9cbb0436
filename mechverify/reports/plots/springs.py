"""Report figures for helical compression springs: force-deflection line and the fatigue (Haigh) diagram."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("spring_buckling")
def force_deflection_plot(r: CheckResult) -> Any:
    """F = k y from free length to solid, with each load case's force, the solid and the buckling limit."""
    import numpy as np

    d = r.details
    if not {"rate", "solid_deflection", "operating_forces"} <= set(d):
        return None
    k = d["rate"].m_as("N/mm")
    ys = d["solid_deflection"].m_as("mm")
    fig, ax = new_figure()
    ax.plot([0, ys], [0, k * ys], color="#0969da", lw=1.5, label=f"F = k y, k = {k:.4g} N/mm")
    ax.axvline(ys, color="k", lw=1.2, label=f"solid: y = {ys:.4g} mm, F = {k * ys:.4g} N")
    y_cr = d.get("critical_deflection")
    if y_cr is not None and y_cr.m_as("mm") < ys:
        yc = y_cr.m_as("mm")
        ax.axvline(yc, color="#cf222e", ls="--", lw=1.2,
                   label=f"buckling ({d.get('end_condition', '')}): y_cr = {yc:.4g} mm")
        ax.axvspan(yc, ys, color="#cf222e", alpha=0.06)
    else:
        ax.plot([], [], " ", label=f"absolutely stable ({d.get('end_condition', '')})")
    forces = np.atleast_1d(d["operating_forces"].m_as("N"))
    names = list(d.get("operating_cases", []))
    for i, F in enumerate(forces):
        ax.plot([F / k], [F], "o", color="#2da44e", ms=5, label="load cases" if i == 0 else None)
        if i < len(names):
            ax.annotate(names[i], (F / k, F), textcoords="offset points", xytext=(5, -10), fontsize=7)
    ax.set_xlabel("deflection y [mm]")
    ax.set_ylabel("force F [N]")
    ax.set_xlim(0, ys * 1.08)
    ax.set_ylim(0, k * ys * 1.08)
    ax.legend(fontsize=7, loc="upper left")
    return fig


@plotter("spring_fatigue")
def haigh_plot(r: CheckResult) -> Any:
    """Haigh diagram in shear: Gerber and Goodman lines through the Zimmerli point, Langer's first-cycle
    yield line, the operating point and the proportional load line to the criterion."""
    import numpy as np

    d = r.details
    need = {"tau_m", "Ssu", "Sse", "Ssy", "n_f", "criterion", "Ssa_zimmerli", "Ssm_zimmerli"}
    if not need <= set(d):
        return None
    ta, tm = r.demand.m_as("MPa"), d["tau_m"].m_as("MPa")
    Ssu, Sse, Ssy = d["Ssu"].m_as("MPa"), d["Sse"].m_as("MPa"), d["Ssy"].m_as("MPa")
    crit = str(d["criterion"])
    x = np.linspace(0, Ssu, 200)
    fig, ax = new_figure(5.5, 3.6)
    lines = {"gerber": Sse * (1 - (x / Ssu) ** 2), "goodman": Sse * (1 - x / Ssu)}
    for name, y in lines.items():
        used = name == crit
        ax.plot(x, y, lw=1.8 if used else 0.9, ls="-" if used else ":", color="#0969da" if used else "#57606a",
                label=f"{name.capitalize()}" + (" (used)" if used else ""))
    if crit not in lines:
        ax.axhline(Sse, color="#0969da", lw=1.8, label=f"{crit} (used), S_se = {Sse:.4g} MPa")
    xs = np.linspace(0, Ssy, 2)
    ax.plot(xs, Ssy - xs, color="#cf222e", lw=1, ls="--", label=f"first-cycle yield τa + τm = S_sy ({Ssy:.4g})")
    ax.plot([d["Ssm_zimmerli"].m_as("MPa")], [d["Ssa_zimmerli"].m_as("MPa")], "s", color="k", ms=5,
            label="Zimmerli point")
    n_f = float(d["n_f"])
    if tm > 0 and np.isfinite(n_f):
        ax.plot([0, n_f * tm], [0, n_f * ta], color="#2da44e", lw=1, label=f"load line, n_f = {n_f:.3g}")
    ax.plot([tm], [ta], "o", color="#2da44e", ms=6, label=f"operating point ({tm:.4g}, {ta:.4g})")
    ax.set_xlabel("mean shear stress τm [MPa]")
    ax.set_ylabel("shear stress amplitude τa [MPa]")
    ax.set_xlim(0, Ssu * 1.02)
    ax.set_ylim(0, max(Sse, Ssy) * 1.05)
    ax.legend(fontsize=7, loc="upper right")
    return fig
