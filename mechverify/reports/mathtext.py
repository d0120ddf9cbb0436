"""Formulas rendered as mathematics: LaTeX through matplotlib's mathtext to SVG (no network, no TeX).

The SVG (glyphs as paths) is embedded as a data URI, so it is legible in the HTML report and in the
PDF that WeasyPrint makes from the same HTML. A formula mathtext cannot parse is shown as code.
"""

from __future__ import annotations

import base64
import html
import io
import re
from functools import lru_cache

# LaTeX commands mathtext lacks, mapped to ones it has.
_REWRITES = [
    (re.compile(r"\\text\{([^}]*)\}"), lambda m: r"\mathrm{" + m.group(1).replace(" ", r"\ ") + "}"),
    (re.compile(r"\\operatorname\{([^}]*)\}"), r"\\mathrm{\1}"),
    (re.compile(r"\\left\\\{"), r"\\{"),
    (re.compile(r"\\right\\\}"), r"\\}"),
    (re.compile(r"\\dfrac"), r"\\frac"),
    (re.compile(r"\\tfrac"), r"\\frac"),
    # \, \; \! are mathtext's own thin, thick and negative spaces: kept (a number and its unit stay apart)
    (re.compile(r"\\quad"), r"\\ \\ "),
    (re.compile(r"\\le(?![a-zA-Z])"), r"\\leq"),
    (re.compile(r"\\ge(?![a-zA-Z])"), r"\\geq"),
    (re.compile(r"\\lvert|\\rvert"), r"|"),
    (re.compile(r"\\middle"), ""),
]


def _prepare(latex: str) -> str:
    s = latex.strip()
    if s.startswith("$") and s.endswith("$"):
        s = s.strip("$")
    for pat, rep in _REWRITES:
        s = pat.sub(rep, s)
    return f"${s}$"


@lru_cache(maxsize=512)
def formula_svg(latex: str, fontsize: float = 15.0) -> str | None:
    """SVG text of a formula, or ``None`` when mathtext cannot typeset it."""
    if not latex.strip():
        return None
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import mathtext
    from matplotlib.font_manager import FontProperties

    buf = io.BytesIO()
    try:
        with matplotlib.rc_context({"svg.fonttype": "path", "mathtext.fontset": "dejavuserif"}):
            mathtext.math_to_image(_prepare(latex), buf, prop=FontProperties(size=fontsize), format="svg")
    except (ValueError, RuntimeError, KeyError):
        return None
    return buf.getvalue().decode("utf-8")


def formula_html(latex: str) -> str:
    """An ``<img>`` with the typeset formula (alt text: the LaTeX), or the LaTeX as code."""
    svg = formula_svg(latex)
    if svg is None:
        return f'<code class="latex">{html.escape(latex)}</code>' if latex else ""
    uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode()).decode()
    return f'<img class="formula" src="{uri}" alt="{html.escape(latex)}">'
