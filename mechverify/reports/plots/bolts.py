"""Figures of bolted joints: the joint diagram (VDI 2230 Fig. 3.2/3: force over elongation of bolt and clamped parts
with F_M, F_A, F_SA, F_PA), the tightening-torque table over the friction range, and a per-bolt bar for a group."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


def joint_diagram(ax: Any, d: dict[str, Any]) -> None:
    """Draw the force-elongation triangle of a preloaded joint from a bolt check's ``details`` (SI floats)."""
    dS, dP, FM, FA = d["delta_S"], d["delta_P"], d["F_M_max"], d["F_A"]
    FSA, FPA = d["F_SA"], d["F_PA"]
    fS, fP = FM * dS * 1e3, FM * dP * 1e3  # elongation of the bolt and shortening of the parts at F_M [mm]
    k = 1e-3
    ax.plot([0, fS], [0, FM * k], color="#0969da", lw=1.8, label="bolt (slope 1/δ_S)")
    ax.plot([fS, fS + fP], [FM * k, 0], color="#8250df", lw=1.8, label="clamped parts (slope 1/δ_P)")
    ax.plot([0, fS], [FM * k, FM * k], color="0.4", lw=0.6, ls=":", label=f"F_M,max = {FM / 1e3:.3g} kN")
    if FA > 0:
        x = fS + FSA * dS * 1e3
        ax.plot([fS, x], [FM * k, (FM + FSA) * k], color="#0969da", lw=1.8)
        ax.plot([x, x], [(FM - FPA) * k, (FM + FSA) * k], color="#cf222e", lw=2.4,
                label=f"F_A = {FA / 1e3:.3g} kN: F_SA {FSA / 1e3:.3g} (bolt) + F_PA {FPA / 1e3:.3g} (parts)")
        ax.plot([x, fS + fP], [(FM - FPA) * k, 0], color="#8250df", lw=0.8, ls="--")
    ax.axhline(d["F_M_min"] * k, color="#bf8700", lw=0.8, ls="--",
               label=f"F_M,min = F_M,max/α_A = {d['F_M_min'] / 1e3:.3g} kN")
    ax.set_xlabel("elongation of bolt / shortening of parts [mm]")
    ax.set_ylabel("force [kN]")
    ax.set_xlim(0, (fS + fP) * 1.05)
    ax.set_ylim(0, (FM + max(FSA, 0)) * k * 1.2)
    ax.legend(fontsize=6.5, loc="lower center", framealpha=0.9)


def per_bolt_bars(ax: Any, per: list[tuple[str, float]], title: str) -> None:
    labels = [p[0] for p in per]
    u = [p[1] for p in per]
    colours = ["#cf222e" if x > 1 else "#bf8700" if x > 0.9 else "#2da44e" for x in u]
    ax.bar(labels, u, color=colours)
    ax.axhline(1.0, color="k", lw=0.8)
    ax.set_xlabel("bolt")
    ax.set_ylabel("utilisation")
    ax.set_title(title, fontsize=9)


@plotter("bolt_working_stress", "bolt_separation", "bolt_slip", "bolt_fatigue")
def bolt_figure(result: CheckResult) -> Any:
    d = result.details
    if "delta_S" not in d:
        return None
    per = d.get("per_bolt")
    if per:
        import matplotlib.pyplot as plt

        fig, (a1, a2) = plt.subplots(1, 2, figsize=(8.5, 3.3), layout="constrained")
        for ax in (a1, a2):
            ax.grid(True, lw=0.4, alpha=0.5)
        joint_diagram(a1, d)
        a1.set_title(f"joint diagram, bolt {d.get('governing_bolt', '')}", fontsize=9)
        per_bolt_bars(a2, per, result.check)
        return fig
    fig, ax = new_figure(5.5, 3.3)
    joint_diagram(ax, d)
    ax.set_title(f"joint diagram {d.get('thread', '')}", fontsize=9)
    return fig


@plotter("bolt_tightening_torque")
def torque_table_figure(result: CheckResult) -> Any:
    rows = result.details.get("torque_table")
    if not rows:
        return None
    mu = [r[0] for r in rows]
    fig, ax = new_figure(5.5, 3.0)
    ax.plot(mu, [r[1] / 1e3 for r in rows], "o-", color="#0969da", label="F_M,zul [kN]")
    ax.set_xlabel("μ_G = μ_K")
    ax.set_ylabel("F_M,zul [kN]")
    ax2 = ax.twinx()
    ax2.plot(mu, [r[2] for r in rows], "s--", color="#cf222e", label="M_A [N·m]")
    ax2.set_ylabel("M_A [N·m]")
    ax.set_title(f"assembly preload and torque, {result.details.get('thread', '')} {result.details.get('grade', '')}",
                 fontsize=9)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="center right")
    return fig
