"""Report figures for linear guides: the drive force a sliding carriage needs over its bushing length."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("carriage_binding")
def drive_force_plot(r: CheckResult) -> Any:
    """F(L) = R (1 ± 2 mu a/L)/(1 ± 2 mu e/L) over the contact length L, the available force, the operating point
    and, with a drive offset, the jamming length L = 2 mu e."""
    import numpy as np

    from mechverify.components.linear_guides import drive_force_si

    inp = r.inputs
    if not {"R", "mu", "L", "a", "e"} <= set(inp):
        return None
    R, mu = inp["R"].m_as("N"), float(inp["mu"])
    L0, a, e = inp["L"].m_as("m"), inp["a"].m_as("m"), inp["e"].m_as("m")
    if not (L0 > 0 and R > 0):
        return None
    Ls = np.geomspace(L0 / 5, L0 * 20, 200)
    F = np.array([drive_force_si(R, mu, L, a, e) for L in Ls])
    fig, ax = new_figure()
    ok = np.isfinite(F)
    ax.loglog(Ls[ok] * 1e3, F[ok], color="#0969da", lw=1.5, label=f"drive force needed (mu = {mu:g})")
    ax.axhline(r.capacity.m_as("N"), color="k", lw=1.1, label=f"available {r.capacity.m_as('N'):.4g} N")
    if e != 0:
        ax.axvline(2 * mu * abs(e) * 1e3, color="#cf222e", ls="--", lw=1,
                   label=f"jams below L = 2 mu e = {2 * mu * abs(e) * 1e3:.3g} mm")
    ax.plot([L0 * 1e3], [r.demand.m_as("N")], "o", color="#2da44e" if r.passed else "#cf222e", ms=6,
            label=f"L = {L0 * 1e3:.3g} mm: F = {r.demand.m_as('N'):.4g} N")
    ax.set_xlabel("contact length L [mm]")
    ax.set_ylabel("drive force [N]")
    ax.legend(fontsize=7, loc="upper right")
    return fig
