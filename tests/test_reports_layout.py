"""The report's layout holds (issue 25): rendered with WeasyPrint, no layout box of the demo report
(reference project 004, every check in detail) extends past the A4 page's content box; figure text is
at least 7 pt at print size (font sizes read from the SVG, scaled by how much the page shrinks the
figure); summary bars share one scale; beyond-validity results read "n/a" with their reason; by default
only failing and warning checks are shown in detail.
"""

from __future__ import annotations

import base64
import re

import pytest

from mechverify.checks import CheckResult, ResultSet
from mechverify.reports import render_html
from mechverify.units import Q

A4_CONTENT_WIDTH_PT = (210 - 2 * 15) / 25.4 * 72  # report.css: @page A4, 15 mm side margins


@pytest.fixture(scope="module")
def demo_html():
    from mechverify.demo import EXAMPLE
    from mechverify.design import load

    d = load(EXAMPLE / "design.toml")
    return render_html([(d, d.verify())], detail="all")


def _boxes(box):
    for c in getattr(box, "children", None) or []:
        yield c
        yield from _boxes(c)


def test_no_box_outside_the_page_content_box(demo_html):
    from weasyprint import HTML

    doc = HTML(string=demo_html).render()
    outside = []
    for n, page in enumerate(doc.pages, 1):
        pb = page._page_box
        x0, x1 = pb.content_box_x(), pb.content_box_x() + pb.width
        assert x1 - x0 == pytest.approx(A4_CONTENT_WIDTH_PT * 96 / 72, rel=1e-3)  # CSS px
        for b in _boxes(pb):
            if getattr(b, "width", None) is None or not hasattr(b, "border_box_x"):
                continue
            left, right = b.border_box_x(), b.border_box_x() + b.border_width()
            if right > x1 + 0.5 or left < x0 - 0.5:
                outside.append((n, getattr(b, "element_tag", type(b).__name__), round(right - x1, 1)))
    assert not outside, outside[:10]
    assert len(doc.pages) > 3


def _figure_svgs(html: str) -> list[str]:
    uris = re.findall(r'<img src="data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)"', html)  # figures (not formulas)
    return [base64.b64decode(u).decode() for u in uris]


def test_figure_text_is_at_least_7pt_at_print_size(demo_html):
    svgs = _figure_svgs(demo_html)
    assert len(svgs) >= 5
    for svg in svgs:
        width_pt = float(re.search(r'<svg[^>]*\swidth="([\d.]+)pt"', svg).group(1))
        shrink = min(1.0, A4_CONTENT_WIDTH_PT / width_pt)
        sizes = [float(s) for s in re.findall(r"font(?:-size)?:\s*([\d.]+)px", svg)]
        assert sizes, "figure without text?"
        assert min(sizes) * shrink >= 7.0 - 1e-6, (min(sizes), shrink, svg[:300])


def test_summary_bars_share_one_scale(demo_html):
    """Bar widths are u·SF / scale with one scale for the table: width ratios equal u·SF ratios."""
    rows = re.findall(r'<span style="width:([\d.]+)%;background:var\(--\w+\)"></span><i style="left:([\d.]+)%"></i>'
                      r'</span><span class="over">(▶?)</span><span class="fu">([\d.]+)</span></td>', demo_html)
    assert len(rows) > 5
    limits = {left for _, left, _, _ in rows}
    assert len(limits) == 1  # the limit (u·SF = 1) at the same place on every row
    scale = 100 / float(limits.pop())
    for width, _, over, fu in rows:
        expected = min(float(fu), scale) / scale * 100
        assert float(width) == pytest.approx(expected, abs=0.6 + 100 * 0.005 * float(fu) / scale)
        assert (over == "▶") == (float(fu) > scale)


def test_summary_limit_line_at_one_place_on_the_page(demo_html):
    """Rendered (WeasyPrint), the limit mark of every summary bar sits at the same x and every bar starts at the
    same x, whatever the width of the value beside it (0.0141 and ▶ 5.94 used to shift the bar)."""
    from weasyprint import HTML

    doc = HTML(string=demo_html).render()
    marks, starts = set(), set()
    for page in doc.pages:
        for b in _boxes(page._page_box):
            el = getattr(b, "element", None)
            if el is None or el.get("class") != "bar" or getattr(b, "element_tag", "") != "span":
                continue
            starts.add(round(b.border_box_x(), 1))
            marks.update(round(c.border_box_x(), 1) for c in _boxes(b) if getattr(c, "element_tag", "") == "i")
    assert len(marks) == 1 and len(starts) == 1, (marks, starts)


def _na_result() -> CheckResult:
    return CheckResult(check="thread_stress", component="tiny_bolt", demand=Q(1.0), capacity=Q(0.0),
                       title="Thread stress", notes=("Not verifiable: d = 0.5 mm is below the table's 1 mm. The inputs "
                                                     "lie beyond the validity range of the method, so the check fails",))


def test_beyond_validity_reads_na_with_its_reason():
    ok = CheckResult(check="stress", component="rod", demand=Q(100, "MPa"), capacity=Q(250, "MPa"), title="Stress")
    html = render_html([(None, ResultSet([_na_result(), ok], "rig"))], date="2026-01-01")
    assert "below the table" in html and "n/a" in html
    summary = html.split('<table class="summary"')[1].split("</table>")[0]
    row = summary.split("<td>tiny_bolt</td>")[1].split("</tr>")[0]
    cells = re.findall(r'<td class="num">([^<]*)</td>', row)
    assert cells[:2] == ["n/a", "n/a"] and row.count("n/a") == 3  # demand, capacity, u·SF; not 1 against 0
    assert "∞" not in row


def test_detail_problems_by_default_all_on_request():
    ok = CheckResult(check="stress", component="rod", demand=Q(100, "MPa"), capacity=Q(250, "MPa"), title="Stress",
                     formula=r"\sigma = F/A")
    bad = CheckResult(check="stress", component="thin_rod", demand=Q(300, "MPa"), capacity=Q(250, "MPa"),
                      title="Stress", formula=r"\sigma = F/A")
    runs = [(None, ResultSet([ok, bad], "rig"))]
    default = render_html(runs, date="2026-01-01", detail="problems")  # the CLI's default
    full = render_html(runs, date="2026-01-01")
    assert 'id="thin-rod-stress"' in default and 'id="rod-stress"' not in default
    assert 'id="rod-stress"' in full and "--detail all" in default


def test_long_description_is_truncated_with_a_note():
    from mechverify.reports.render import TEXT_LIMIT, _truncate

    text = _truncate("x" * (TEXT_LIMIT + 1234))
    assert text.startswith("x" * TEXT_LIMIT) and "1,234 more characters not shown" in text


def test_big_design_summary_lists_the_worst_problems_and_counts_the_rest(monkeypatch):
    """A design above SUMMARY_ROWS checks: the summary lists the failing/warning checks (at most
    PROBLEM_ROWS, worst first) and counts the rest; the passing ones are counted with their highest u·SF."""
    from mechverify.reports import render

    monkeypatch.setattr(render, "SUMMARY_ROWS", 10)
    monkeypatch.setattr(render, "PROBLEM_ROWS", 5)
    rs = [CheckResult(check="stress", component=f"r{i}", demand=Q(10 * i, "MPa"), capacity=Q(250, "MPa"),
                      title="Stress") for i in range(1, 41)]  # u = 0.04 .. 1.6
    html = render_html([(None, ResultSet(rs, "bank"))], date="2026-01-01", detail="problems")
    summary = html.split('<table class="summary"')[1].split("</table>")[0]
    assert summary.count("<tr><td>r") == 5 and "<td>r40</td>" in summary and "<td>r35</td>" not in summary
    n_problems = sum(r.verdict.value != "pass" for r in rs)
    assert f"… and {n_problems - 5} more failing and warning checks" in html
    assert f"… and {40 - n_problems} more checks that pass" in html


def test_font_stack_names_no_colour_emoji_font():
    """With "Noto Color Emoji" in the CSS font-family list, WeasyPrint (Pango) drew every digit of the PDF from the
    emoji font ("2 0 2 6 - 1 1 - 2 4", seen with fonts-noto-color-emoji installed in a private fontconfig); emoji
    render from fontconfig's fallback without it. The stack must keep naming the CJK fallbacks."""
    from importlib import resources

    css = resources.files("mechverify.reports").joinpath("templates", "report.css").read_text(encoding="utf-8")
    stack = re.search(r"body \{ font-family: ([^;]+);", css).group(1)
    assert "emoji" not in stack.lower()
    assert "Noto Sans CJK SC" in stack


def test_shrunk_figure_is_laid_out_again():
    """A 10 in figure shrunk to the print width (the frame figure: 3D deformed shape beside the moments) keeps its
    titles and labels apart and inside the figure: titles wrap to their axes' width and the layout is redone
    (the five-bar report had the two titles running into each other and the x label cut off)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from mechverify.reports.plots import PRINT_WIDTH_IN, _fit_print

    fig = Figure(figsize=(10.0, 4.2))
    ax1 = fig.add_subplot(1, 2, 1, projection="3d")
    ax2 = fig.add_subplot(1, 2, 2)
    ax1.set_title("deformed shape x46.4; max 0.4177 mm (★) in link3", fontsize=9)
    ax2.set_title("bending moment along each member; max |M| 0.1462 N·m in link2", fontsize=9)
    ax2.set_xlabel("position along the member from its start [mm]")
    ax2.plot([0, 100], [0.15, 0.07])
    fig.tight_layout()
    _fit_print(fig)
    assert fig.get_size_inches()[0] == pytest.approx(PRINT_WIDTH_IN)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    r = canvas.get_renderer()
    W, H = fig.bbox.width, fig.bbox.height
    boxes = [t.get_window_extent(r) for t in (ax1.title, ax2.title, ax2.xaxis.label)]
    for b in boxes:
        assert b.x0 >= -1 and b.x1 <= W + 1 and b.y0 >= -1 and b.y1 <= H + 1, (b, W, H)
    assert boxes[0].x1 <= boxes[1].x0 + 1  # the two titles side by side, not overlapping
