"""Interactive exploration in Jupyter: sliders for a design's parameters, re-verified on every change.

``explore(design)`` shows one slider per numeric ``[parameters]`` value (not for a parameter written as an
expression: it follows its inputs), or per key path given, from half to twice today's value unless a range
is given, the summary table of
u·SF per check and the governing check's figure. Needs ``ipywidgets`` (the ``explore`` extra:
``scripts/install.sh -e '.[explore]'`` in a clone). Each change builds the variant with
:meth:`Design.with_overrides` and verifies it; an invalid combination shows its message instead of the table.
"""

from __future__ import annotations

import html
from collections.abc import Mapping, Sequence
from typing import Any

from mechverify.errors import InputError, MechverifyError, UnknownNameError, install_hint
from mechverify.studies.params import Parameter, resolver
from mechverify.studies.study import design_and_source
from mechverify.units import Q

COLOURS = {"pass": "#1a7f37", "warn": "#9a6700", "fail": "#cf222e"}


def _parameters(design: Any, doc: Mapping[str, Any], names: Sequence[str] | Mapping[str, Any] | None
                ) -> list[tuple[Parameter, float, float]]:
    """(parameter, low, high) per slider."""
    res = resolver(design)
    if names is None:
        table = doc.get("parameters", {}) if isinstance(doc.get("parameters"), dict) else {}
        out = []
        for k, raw in table.items():
            if _is_expression(raw):
                continue  # a derived parameter follows its inputs' sliders (a slider of its own would freeze it)
            try:
                p = Parameter.of(doc, f"parameters.{k}", res)
            except MechverifyError:
                continue  # a text or table parameter: no slider
            out.append((p, *_default_range(p)))
        if not out:
            raise InputError("explore: the design has no numeric [parameters]; name key paths to vary, e.g. "
                             "explore(design, ['components.lift.mass'])")
        return out
    items = names.items() if isinstance(names, Mapping) else [(n, None) for n in names]
    out = []
    for path, rng in items:
        p = Parameter.of(doc, path, res)
        if rng is None:
            lo, hi = _default_range(p)
        else:
            if len(rng) != 2:
                raise InputError(f"explore: {path}: expected (low, high), got {rng!r}")
            lo, hi = p.value(rng[0]), p.value(rng[1])
            if not lo < hi:
                raise InputError(f"explore: {path}: expected low < high, got {rng!r}")
        out.append((p, lo, hi))
    return out


def _is_expression(raw: Any) -> bool:
    """A text value that is not a quantity: an expression such as ``"2 * load"``."""
    if not isinstance(raw, str):
        return False
    try:
        Q(raw)
    except MechverifyError:
        return True
    return False


def _default_range(p: Parameter) -> tuple[float, float]:
    b = p.base
    if p.offset:  # a temperature in degC or degF: ± 50 degrees (half of 70 degC is no temperature of interest)
        return b - 50.0, b + 50.0
    if b > 0:
        return b / 2, b * 2
    if b < 0:
        return b * 2, b / 2
    return -1.0, 1.0


def summary_html(rs: Any) -> str:
    """The table of checks (component, check, u·SF, verdict), highest u·SF first, and the governing figure."""
    from mechverify.reports.plots import figure_for

    rows = sorted(rs, key=lambda r: -r.factored_utilisation)
    cells = "".join(
        f"<tr><td>{html.escape(r.component)}</td><td>{html.escape(r.title or r.check)}</td>"
        f"<td style='text-align:right'>{r.factored_utilisation:.3g}</td>"
        f"<td style='color:{COLOURS[r.verdict.value]}'><b>{r.verdict.value}</b></td></tr>" for r in rows)
    out = ("<table><tr><th>component</th><th>check</th><th>u·SF</th><th>verdict</th></tr>" + cells + "</table>")
    if rows:
        name = lambda r: f"{html.escape(r.component)} / {html.escape(r.title or r.check)}"  # noqa: E731
        out += f"<p>Governing: {name(rows[0])}</p>"
        for r in rows[:5]:  # the figure of the most utilised check that has one (not every check draws one)
            try:
                fig = figure_for(r)
            except Exception:  # (a figure is a nicety: never lose the table for it)
                fig = None
            if fig:  # another check's figure says whose it is (review 3 finding 23)
                caption = "" if r is rows[0] else (f"<p class='small'>{name(rows[0])} draws no figure; the figure "
                                                   f"of the next check that has one: {name(r)}</p>")
                out += f"{caption}<img style='max-width:40rem' src='{fig}'>"
                break
    return out


class Explorer:
    """Sliders and the verified summary; ``update({path: value})`` re-verifies without a browser (tests)."""

    def __init__(self, design: Any, names: Sequence[str] | Mapping[str, Any] | None = None, steps: int = 100):
        try:
            import ipywidgets as w
        except ImportError:
            raise InputError(f"explore() needs ipywidgets: {install_hint('explore', 'ipywidgets')}") from None
        self.doc, self.path, self.design = design_and_source(design)
        self.params = _parameters(self.design, self.doc, names)
        self.html = ""
        self.sliders = {}
        for p, lo, hi in self.params:
            label = p.path.split(".", 1)[-1] if p.path.startswith("parameters.") else p.path
            s = w.FloatSlider(value=p.base, min=lo, max=hi, step=(hi - lo) / steps, continuous_update=False,
                              description=f"{label} [{p.unit}]" if p.unit else label,
                              style={"description_width": "initial"}, layout=w.Layout(width="36rem"),
                              readout_format=".4g")
            s.observe(lambda change: self._changed(), names="value")
            self.sliders[p.path] = s
        self.output = w.HTML()
        self.widget = w.VBox([*self.sliders.values(), self.output])
        self.update({})

    def _changed(self) -> None:
        # only the sliders moved away from the file's value: an unmoved slider must not replace what the file
        # writes (a parameter named explicitly may be an expression of another slider's parameter)
        base = {p.path: p.base for p, _, _ in self.params}
        self.update({path: s.value for path, s in self.sliders.items() if s.value != base[path]})

    def update(self, values: Mapping[str, float]) -> str:
        """Verify with ``values`` (key path -> number in the parameter's unit); the summary HTML.
        A path that has no slider is an :class:`~mechverify.errors.UnknownNameError`."""
        by_path = {p.path: p for p, _, _ in self.params}
        for k in values:
            if k not in by_path:
                raise UnknownNameError("explore slider", k, by_path)
        overrides = {k: by_path[k].text(v) for k, v in values.items()}
        try:
            design = self.design.with_overrides(overrides) if overrides else self.design
            self.html = summary_html(design.verify())
        except MechverifyError as exc:
            self.html = f"<pre style='color:#cf222e'>{html.escape(str(exc))}</pre>"
        self.output.value = self.html
        return self.html

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        return self.widget._repr_mimebundle_(**kwargs)


def explore(design: Any, names: Sequence[str] | Mapping[str, Any] | None = None, steps: int = 100) -> Explorer:
    """Sliders for the design's numeric ``[parameters]`` (or the key paths ``names``, optionally mapping to
    ``(low, high)``); displayed by Jupyter when it is the cell's value."""
    return Explorer(design, names, steps)
