"""Report figures for motor drives: torque-speed curve with the operating points, and the motion profile."""

from __future__ import annotations

from typing import Any

from mechverify.checks import CheckResult
from mechverify.reports.plots import new_figure, plotter


def _torque_speed(ax: Any, r: CheckResult) -> bool:
    """Draw the motor's limit curve, continuous limit and the profile's points on ``ax``; False without data."""
    import numpy as np

    d = r.details
    if not {"motor_speed", "motor_torque"} <= set(d):
        return False
    w = np.asarray(d["motor_speed"].m_as("rpm"), float)
    T = np.asarray(d["motor_torque"].m_as("mN*m"), float)
    top_w, top_T = float(np.max(w, initial=0.0)), float(np.max(T, initial=0.0))
    if "limit_speed" in d and "limit_torque" in d:
        lw = np.asarray(d["limit_speed"].m_as("rpm"), float)
        lt = np.asarray(d["limit_torque"].m_as("mN*m"), float)
        stepper = d.get("motor_kind") == "stepper"
        ax.plot(lw, lt, "o-" if stepper else "-", color="#0969da", lw=1.5, ms=4,
                label="pull-out torque (curve points)" if stepper else "speed-torque line (intermittent limit)")
        if stepper and lw[0] > 0:
            ax.plot([0, lw[0]], [lt[0], lt[0]], ":", color="#0969da", lw=1.2,
                    label="below the first point: its torque (assumed)")
        if "margin_speed" in d and "margin_torque" in d:
            ax.plot(d["margin_speed"].m_as("rpm"), d["margin_torque"].m_as("mN*m"), "--", color="#0969da", lw=1,
                    label=d.get("margin_label", "limit with the required SF"))
        margin = float(d.get("margin", 1.0))
        if margin > 1:
            ax.plot(lw, lt / margin, "--", color="#0969da", lw=1, label=f"limit / required SF {margin:g}")
        if stepper and lw[0] > 0:
            ax.plot([0, lw[0]], [lt[0] / margin] * 2, ":", color="#0969da", lw=0.8)
        top_w, top_T = max(top_w, float(lw.max())), max(top_T, float(lt.max()))
    if "continuous_torque" in d:
        tc = float(d["continuous_torque"].m_as("mN*m"))
        ax.axhline(tc, color="#bf8700", lw=1.2, label=f"continuous torque {tc:.4g} mN·m")
        top_T = max(top_T, tc)
    ax.plot(w, T, ".", color="#6e7781", ms=3, label="profile points |T|, |ω|")
    i = int(np.argmax(T)) if len(T) else 0
    if len(T):
        ax.plot([w[i]], [T[i]], "o", color="#cf222e", ms=7, label=f"peak {T[i]:.4g} mN·m at {w[i]:.4g} rpm")
    if "governing_speed" in d and "governing_torque" in d:
        gw, gt = float(d["governing_speed"].m_as("rpm")), float(d["governing_torque"].m_as("mN*m"))
        ax.plot([gw], [gt], "D", mfc="none", mec="k", ms=9, label=f"governing point {gt:.4g} mN·m at {gw:.4g} rpm")
    if "rms_torque" in d:
        trms = float(d["rms_torque"].m_as("mN*m"))
        ax.axhline(trms, color="#8250df", ls=":", lw=1.5, label=f"RMS {trms:.4g} mN·m")
    ax.set_xlim(0, top_w * 1.08 or 1.0)
    ax.set_ylim(0, top_T * 1.15 or 1.0)
    ax.set_xlabel("motor speed [rpm]")
    ax.set_ylabel("motor torque [mN·m]")
    ax.legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
    return True


@plotter("motor_rms_torque", "motor_max_speed", "motor_supply_voltage")
def torque_speed_plot(r: CheckResult) -> Any:
    """Torque-speed plane: the limit curve (DC line or stepper pull-out points), the continuous torque,
    every sample of the profile, the peak and the RMS torque."""
    fig, ax = new_figure(6.0, 4.4)
    if not _torque_speed(ax, r):
        import matplotlib.pyplot as plt

        plt.close(fig)
        return None
    return fig


@plotter("motor_peak_torque")
def peak_torque_plot(r: CheckResult) -> Any:
    """Torque-speed plane (left) and the governing case's motion profile: position, velocity and
    acceleration over time with the peak-torque instant marked (right)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d = r.details
    if not {"profile_time", "profile_position", "profile_velocity", "profile_acceleration"} <= set(d):
        return torque_speed_plot(r)
    fig = plt.figure(figsize=(9.5, 5.0), layout="constrained")
    grid = fig.add_gridspec(3, 2, width_ratios=(1.25, 1))
    ax = fig.add_subplot(grid[:, 0])
    ax.grid(True, lw=0.4, alpha=0.5)
    _torque_speed(ax, r)
    t = d["profile_time"].m_as("s")
    axes = []
    for k, (key, colour) in enumerate((("profile_position", "#0969da"), ("profile_velocity", "#1a7f37"),
                                       ("profile_acceleration", "#cf222e"))):
        a = fig.add_subplot(grid[k, 1], sharex=axes[0] if axes else None)
        q = d[key]
        word = key.split("_")[1]
        a.plot(t, q.magnitude, color=colour, lw=1.3)
        a.set_ylabel(f"{word}\n[{q.units:~P}]", fontsize=7)
        a.tick_params(labelsize=7)
        a.grid(True, lw=0.4, alpha=0.5)
        if "governing_time" in d:
            a.axvline(d["governing_time"].m_as("s"), color="k", ls="--", lw=0.8)
        if k < 2:
            a.tick_params(labelbottom=False)
        axes.append(a)
    axes[-1].set_xlabel("time [s] (dashed: governing point)", fontsize=7)
    return fig


@plotter("gearhead_continuous_torque", "gearhead_intermittent_torque")
def gearhead_torque_plot(r: CheckResult) -> Any:
    """Gearhead output torque over the cycle with its RMS, the rating and the rating / required SF."""
    import numpy as np

    d = r.details
    if not {"time", "output_torque"} <= set(d):
        return None
    t = np.asarray(d["time"].m_as("s"), float)
    T = np.asarray(d["output_torque"].m_as("N*m"), float)
    cap = float(r.capacity.m_as("N*m"))
    fig, ax = new_figure(6.0, 3.4)
    ax.plot(t, T, color="#0969da", lw=1.3, label="output torque T_out(t)")
    if len(t) > 1 and t[-1] > t[0]:
        rms = float(np.sqrt(np.trapezoid(T * T, t) / (t[-1] - t[0])))
        ax.axhline(rms, color="#8250df", ls=":", lw=1.5, label=f"RMS {rms:.4g} N·m")
    word = "continuous" if r.check == "gearhead_continuous_torque" else "intermittent"
    ax.axhline(cap, color="#bf8700", lw=1.2, label=f"{word} rating {cap:.4g} N·m")
    if r.required_sf > 1:
        ax.axhline(cap / r.required_sf, color="#bf8700", ls="--", lw=1,
                   label=f"rating / required SF {r.required_sf:g}")
    ax.set_ylim(min(0.0, float(T.min()) * 1.1), max(cap, float(np.abs(T).max())) * 1.15)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("gearhead output torque [N·m]")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, frameon=False)
    return fig
