"""Report figures for rolling bearings: rating life against equivalent load."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


@plotter("bearing_life")
def life_load_plot(r: CheckResult) -> Any:
    """L_nh = a1 (C/P)^p 10^6/(60 n) over P (log-log; p = 3 ball, 10/3 roller), the operating point, the required
    life and the largest equivalent load that meets it."""
    import numpy as np

    d, inp = r.details, r.inputs
    if "P" not in d or not {"C", "n"} <= set(inp):
        return None
    C, n = inp["C"].m_as("N"), inp["n"].m_as("rpm")
    P, a1 = d["P"].m_as("N"), float(d.get("a1", 1.0))
    req, Lh = r.demand.m_as("hour"), r.capacity.m_as("hour")
    if n <= 0 or P <= 0:
        return None
    e = float(inp.get("p", 3.0))
    life = lambda p: a1 * (C / p) ** e * 1e6 / (60 * n)  # noqa: E731
    P_allow = C * (a1 * 1e6 / (60 * n * req)) ** (1 / e)
    lo, hi = min(P, P_allow, C) / 10, max(P, P_allow, C) * 1.5
    p = np.geomspace(lo, hi, 200)
    fig, ax = new_figure()
    exp = "³" if e == 3 else "^(10/3)"
    ax.loglog(p, life(p), color="#0969da", lw=1.5, label=f"L = a1 (C/P){exp} at {n:.4g} r/min, C = {C:.4g} N")
    ax.axhline(req, color="k", lw=1.1, label=f"required {req:.4g} h")
    ax.axvline(P_allow, color="#cf222e", ls="--", lw=1, label=f"largest P for it: {P_allow:.4g} N")
    ax.plot([P], [Lh], "o", color="#2da44e" if Lh >= req else "#cf222e", ms=6,
            label=f"operating point P = {P:.4g} N, L = {Lh:.4g} h")
    ax.set_xlabel("equivalent dynamic load P [N]")
    ax.set_ylabel("rating life [h]")
    ax.legend(fontsize=7, loc="upper right")
    return fig
