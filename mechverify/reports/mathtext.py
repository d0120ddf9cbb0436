"""Formulas rendered as mathematics: LaTeX through matplotlib's mathtext to SVG (no network, no TeX).

The SVG (glyphs as paths) is embedded as a data URI, so it is legible in the HTML report and in the
PDF that WeasyPrint makes from the same HTML. A formula mathtext cannot parse is shown as code.
"""

from __future__ import annotations

import base64
import html
import re
from functools import lru_cache
from typing import Any

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
    """SVG text of a formula (glyphs as one path), or ``None`` when mathtext cannot typeset it.

    matplotlib's mathtext lays the formula out once and gives its glyph outlines (``TextToPath``); the
    SVG is written here rather than through a figure and ``savefig``, which parsed the formula twice
    and cost three times as much (the formulas were half of a report's rendering time, issue 27), and
    wrote the date into every image.
    """
    if not latex.strip():
        return None
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.font_manager import FontProperties

    text = _prepare(latex)
    try:
        with matplotlib.rc_context({"mathtext.fontset": "dejavuserif"}):
            ttp = _text_to_path()
            prop = FontProperties(size=fontsize)
            width, height, depth = ttp.get_text_width_height_descent(text, prop, ismath=True)
            verts, codes = ttp.get_text_path(prop, text, ismath=True)
    except (ValueError, RuntimeError, KeyError):
        return None
    w, h = max(width, 1.0), max(height, 1.0)
    k = fontsize / ttp.FONT_SCALE  # the outlines come at TextToPath's layout size
    return (f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{_num(w)}pt" height="{_num(h)}pt" '
            f'viewBox="0 0 {_num(w)} {_num(h)}"><path transform="matrix({k:g} 0 0 {-k:g} 0 {_num(h - depth)})" '
            f'd="{_path_data(verts, codes)}"/></svg>')


@lru_cache(maxsize=1)
def _text_to_path() -> Any:
    from matplotlib.textpath import TextToPath

    return TextToPath()  # one instance: its mathtext parser caches a layout between the two calls above


def _num(v: float) -> str:
    return f"{v:.3f}".rstrip("0").rstrip(".") or "0"


def _path_data(verts: Any, codes: Any) -> str:
    """SVG path data of matplotlib path vertices and codes (MOVETO 1, LINETO 2, CURVE3 3, CURVE4 4, CLOSEPOLY 79)."""
    out: list[str] = []
    i, n = 0, len(codes)
    while i < n:
        c = codes[i]
        if c == 3:
            (x1, y1), (x2, y2) = verts[i], verts[i + 1]
            out.append(f"Q{_num(x1)} {_num(y1)} {_num(x2)} {_num(y2)}")
            i += 2
        elif c == 4:
            (x1, y1), (x2, y2), (x3, y3) = verts[i], verts[i + 1], verts[i + 2]
            out.append(f"C{_num(x1)} {_num(y1)} {_num(x2)} {_num(y2)} {_num(x3)} {_num(y3)}")
            i += 3
        elif c == 79:
            out.append("z")
            i += 1
        else:
            x, y = verts[i]
            out.append(f"{'M' if c == 1 else 'L'}{_num(x)} {_num(y)}")
            i += 1
    return "".join(out)


def formula_html(latex: str) -> str:
    """An ``<img>`` with the typeset formula (alt text: the LaTeX), or the LaTeX as code."""
    svg = formula_svg(latex)
    if svg is None:
        return f'<code class="latex">{html.escape(latex)}</code>' if latex else ""
    uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode()).decode()
    return f'<img class="formula" src="{uri}" alt="{html.escape(latex)}">'
