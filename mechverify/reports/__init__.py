"""Design-review reports: one self-contained HTML file, and a PDF made from it by WeasyPrint.

``write_report(runs, "review.html")`` or ``"review.pdf"``, where ``runs`` is a list of
``(Design, ResultSet)`` pairs (what ``mechverify check`` verified). Writing is atomic: the file
appears complete or not at all.
"""

from mechverify.reports.render import render_html, write_report

__all__ = ["render_html", "write_report"]
