"""Figures for the report: matplotlib figures embedded as vector SVG data URIs.

Plotters are registered per check name (:func:`plotter`), the name of a registered check
(:mod:`mechverify.checks.registry`; an unknown name is an error when the module loads); each receives a
:class:`~mechverify.checks.CheckResult` and returns a figure from its ``details``, or ``None``.
One module per domain (``plots/screws.py``, ...) holds its plotters; every module of this package is
imported on first use (a new domain needs no list entry).
"""

from __future__ import annotations

import base64
import io
from collections.abc import Callable
from typing import Any

from mechverify.checks import CheckResult

PLOTTERS: dict[str, Callable[[CheckResult], Any]] = {}

def domains() -> list[str]:
    """The plot modules of this package (found with :mod:`pkgutil`, not listed by hand)."""
    import pkgutil

    return [m.name for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_")]


def _load_domains() -> None:
    import importlib

    for d in domains():
        importlib.import_module(f"{__name__}.{d}")


def plotter(*check_names: str) -> Callable:
    """Register a plot function for the named checks (registered check names, not former names).

    Raises:
        UnknownNameError: a name no check has (with suggestions).
        ValueError: a former name (an alias) instead of the check's name.
    """
    from mechverify.checks.registry import CHECKS, get_check

    for n in check_names:
        d = get_check(n)
        if n not in CHECKS:
            raise ValueError(f"plotter: {n!r} is a former name; use the check's name {d.name!r}")

    def deco(f: Callable[[CheckResult], Any]) -> Callable[[CheckResult], Any]:
        for n in check_names:
            PLOTTERS[n] = f
        return f

    return deco


def new_figure(width: float = 5.5, height: float = 3.2) -> tuple[Any, Any]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(width, height), layout="constrained")
    ax.grid(True, lw=0.4, alpha=0.5)
    return fig, ax


def svg_data_uri(fig: Any) -> str:
    """The figure as an SVG data URI (vector, self-contained); closes the figure."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    _fit_print(fig)
    buf = io.BytesIO()
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "mechverify", "font.family": "DejaVu Sans"}):
        fig.savefig(buf, format="svg", metadata={"Date": None})
    plt.close(fig)
    return "data:image/svg+xml;base64," + base64.b64encode(buf.getvalue()).decode()


PRINT_WIDTH_IN = 6.9  # the A4 report's content width (180 mm = 7.09 in) less a small margin
MIN_FONT_PT = 7.0  # smallest text size at print size


def _fit_print(fig: Any) -> None:
    """Readable when printed: no wider than the page's content box (so it is not scaled down) and no
    text below 7 pt. A figure that shrinks has its axes titles wrapped to their axes' width and its layout
    redone (tight layout; a constrained layout re-flows by itself), so titles and labels do not run into
    each other or off the figure."""
    import textwrap
    import warnings

    from matplotlib.text import Text

    w, h = fig.get_size_inches()
    shrunk = w > PRINT_WIDTH_IN
    if shrunk:
        fig.set_size_inches(PRINT_WIDTH_IN, h * PRINT_WIDTH_IN / w)
    for t in fig.findobj(Text):
        if t.get_text() and t.get_fontsize() < MIN_FONT_PT:
            t.set_fontsize(MIN_FONT_PT)
    for ax in fig.axes:  # tick labels are created lazily: set their size through the axis
        for axis in (ax.xaxis, ax.yaxis):
            for lab in axis.get_ticklabels(which="both"):
                if lab.get_fontsize() < MIN_FONT_PT:
                    axis.set_tick_params(labelsize=MIN_FONT_PT, which="both")
                    break
    if not shrunk:
        return
    fig_w_pt, fig_h_pt = (x * 72 for x in fig.get_size_inches())
    for ax in fig.axes:
        pos = ax.get_position()
        across = [(t, pos.width * fig_w_pt) for t in (ax.title, ax._left_title, ax._right_title, ax.xaxis.label)]
        for label, room_pt in (*across, (ax.yaxis.label, pos.height * fig_h_pt)):  # y label: along the axes' height
            text = label.get_text()
            chars = max(12, int(room_pt / (0.62 * label.get_fontsize())))  # DejaVu Sans: ~0.6 em per character
            if text and "\n" not in text and len(text) > chars:
                label.set_text(textwrap.fill(text, chars))
    if type(fig.get_layout_engine()).__name__ != "ConstrainedLayoutEngine":
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a layout that cannot be redone is kept as it was
            try:
                fig.set_layout_engine("constrained")  # re-flows at draw time, 3D axes included
            except (ValueError, RuntimeError):
                pass
            if type(fig.get_layout_engine()).__name__ != "ConstrainedLayoutEngine":  # colour bars made before
                try:
                    fig.tight_layout()
                except (ValueError, RuntimeError):
                    pass


CHART_ROWS = 40  # the summary chart shows at most this many checks (the worst), so it fits one page


def figure_for(result: CheckResult) -> str | None:
    """A data URI of the check's figure, when a plotter is registered and has data."""
    _load_domains()
    f = PLOTTERS.get(result.check)
    if f is None:
        return None
    fig = f(result)
    return svg_data_uri(fig) if fig is not None else None


def utilisation_chart(results: list[CheckResult]) -> str:
    """Horizontal bars of factored utilisation per check, coloured by verdict, with the limit line."""
    colours = {"pass": "#2da44e", "warn": "#bf8700", "fail": "#cf222e"}
    rs = sorted(results, key=lambda r: r.factored_utilisation)[-CHART_ROWS:]
    fig, ax = new_figure(6.5, 0.2 * max(len(rs), 3) + 0.8)
    vals = [min(r.factored_utilisation, 2.0) for r in rs]
    ax.barh(range(len(rs)), vals, color=[colours[r.verdict.value] for r in rs])
    ax.set_yticks(range(len(rs)), [f"{r.component}: {r.title or r.check}" for r in rs], fontsize=7)
    ax.axvline(1.0, color="k", lw=1)
    for i, r in enumerate(rs):  # a value beyond the scale: its number at the bar's end
        if r.factored_utilisation > 2.0:
            ax.text(1.98, i, f"{r.factored_utilisation:.3g} ▶", va="center", ha="right", fontsize=7, color="white")
    ax.set_xlim(0, max(1.2, max(vals, default=1) * 1.05))
    more = len(results) - len(rs)
    ax.set_xlabel("utilisation × required SF (fail above 1)"
                  + (f"; the {len(rs)} highest of {len(results)} checks" if more > 0 else ""))
    return svg_data_uri(fig)
