"""Design-review reports: the HTML renders in headless Chromium with no console output and no
network, a screenshot is produced; the PDF's text holds the verdicts and numbers and its pages render.

Numbers come from the rod type of ``conftest.py``: 2 kN on 20 mm^2 is 100 MPa (Shigley 10th ed.,
Eq. 3-22) against 250 MPa yield (ANSYS Structural Steel); with SF 2 the utilisation bar is 0.8.
"""

import re
import shutil
import subprocess
import textwrap

import pytest

from mechverify.design import load
from mechverify.reports import render_html, write_report
from tests.builders import two_rods

DESIGN = two_rods("Test rig", "C")

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--enable-logging=stderr", "--v=0", "--window-size=1100,1600"]


@pytest.fixture
def runs(tmp_path, rod_type):
    p = tmp_path / "rig.toml"
    p.write_text(textwrap.dedent(DESIGN))
    d = load(p)
    return [(d, d.verify())]


def test_html_is_self_contained_and_complete(runs):
    text = render_html(runs, date="2026-01-01")
    assert not re.search(r'(src|href)="(https?:)?//', text)  # nothing fetched from the network
    assert "<script" not in text
    for needle in ("Test rig", "Revision", "100 MPa", "400 MPa", ">fail<", ">pass<", "Shigley 10th ed., Eq. 3-22",
                   "Structural Steel", "scikit-fem", 'class="formula"', "rig.toml"):
        assert needle in text, needle
    # failures first in the summary table
    summary = text.split('class="summary"')[1].split("</table>")[0]
    assert summary.index("thin_rod") < summary.index(">rod<")


@pytest.mark.chromium
@pytest.mark.skipif(shutil.which("chromium") is None, reason="chromium not installed (make test installs it)")
def test_html_renders_in_chromium_without_console_output(runs, tmp_path):
    html = write_report(runs, tmp_path / "review.html")
    shot = tmp_path / "review.png"
    proc = subprocess.run(["chromium", *CHROMIUM_FLAGS, f"--user-data-dir={tmp_path / 'profile'}",
                           f"--screenshot={shot}", html.as_uri()], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "CONSOLE" not in proc.stderr and "Failed to load" not in proc.stderr
    assert shot.stat().st_size > 20_000  # a real page, not a blank one


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler-utils not installed")
def test_pdf_text_and_pages(runs, tmp_path):
    pdf = write_report(runs, tmp_path / "review.pdf")
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                          check=True).stdout
    assert "Test rig" in text and "FAIL" in text and "PASS" in text
    assert "100 MPa" in text and "400 MPa" in text and "page 1 of" in text
    subprocess.run(["pdftoppm", "-r", "40", "-png", str(pdf), str(tmp_path / "page")], check=True)
    assert len(list(tmp_path.glob("page-*.png"))) >= 2


def test_failed_pdf_write_leaves_nothing(runs, tmp_path, monkeypatch):
    """A renderer that dies half-way through writing leaves neither the PDF nor a temporary file."""
    import weasyprint

    def half_then_die(self, target=None, **kw):
        with open(target, "wb") as fh:
            fh.write(b"%PDF-1.7 half")
        raise RuntimeError("renderer died")

    monkeypatch.setattr(weasyprint.HTML, "write_pdf", half_then_die)
    (tmp_path / "old.pdf").write_bytes(b"previous report")
    with pytest.raises(RuntimeError):
        write_report(runs, tmp_path / "old.pdf")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.pdf", "rig.toml"]
    assert (tmp_path / "old.pdf").read_bytes() == b"previous report"
