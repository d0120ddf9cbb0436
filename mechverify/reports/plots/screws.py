"""Report figures for power screws."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("self_locking")
def self_locking_plot(r: CheckResult) -> Any:
    """Lead angle against the friction angle rho'(mu) = atan(mu / cos(alpha_n)), with the nut's mu range."""
    import numpy as np

    d = r.details
    if not {"lead_angle", "normal_flank_angle", "self_locking_mu"} <= set(d):
        return None
    lam = d["lead_angle"].m_as("deg")
    an = d["normal_flank_angle"].m_as("rad")
    mu_star = float(d["self_locking_mu"].m_as(""))
    mu_lo = float(r.inputs["mu_min"].m_as("")) if "mu_min" in r.inputs else mu_star
    top = max(0.3, 1.6 * mu_lo, 1.6 * mu_star)
    mu = np.linspace(0, top, 200)
    fig, ax = new_figure()
    ax.plot(mu, np.degrees(np.arctan(mu / np.cos(an))), label="friction angle ρ'(μ)")
    ax.axhline(lam, color="k", lw=1.2, label=f"lead angle λ = {lam:.3g}°")
    ax.axvline(mu_star, color="#cf222e", ls="--", lw=1, label=f"back-drives below μ* = {mu_star:.3g}")
    ax.axvspan(mu_lo, top, color="#2da44e", alpha=0.08)
    ax.plot([mu_lo], [np.degrees(np.arctan(mu_lo / np.cos(an)))], "o", color="#2da44e",
            label=f"nut's lowest μ = {mu_lo:.3g}")
    ax.set_xlabel("friction coefficient μ")
    ax.set_ylabel("angle [deg]")
    ax.set_xlim(0, top)
    ax.legend(fontsize=7, loc="upper left")
    return fig
