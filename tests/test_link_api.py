"""What the design file's ``link`` adds is in the Python API too (issue 16): the beam-column note of a
compressed link with a transverse load, and BTH-1's 1.20 folded into the lug capacity.

Sources: the Euler load P_e = pi^2 E I / l^2 (Timoshenko & Gere, Theory of Elastic Stability, Sec. 1.11;
Shigley 10th ed. Eq. 4-42 with C = 1) and the amplification 1/(1 - P/P_e) are hand calculations from
those formulas, not printed values; ASME BTH-1 Sec. 3-3.3.1: allowable = P_nominal / (1.20 N_d).
"""

from __future__ import annotations

import math
import re

import pytest

from mechverify.checks.members import lug_checks
from mechverify.components import sections
from mechverify.components.links import Link, Lug, link_section_forces


def _link() -> Link:
    return Link("200 mm", sections.rectangle("20 mm", "10 mm"), "S235JR",
                lug=Lug("10 mm", "20 mm", "10 mm", "10 mm"), pin_diameter="10 mm")


def test_compressed_link_with_a_transverse_load_names_the_beam_column_amplification():
    link = _link()
    E = link.material.require("E").m_as("Pa")
    I = link.section.Iy.m_as("m**4")
    pe = math.pi**2 * E * I / 0.2**2  # hand calculation
    f = link_section_forces(link, "-1000 N", transverse_load="50 N")
    note = next(n for n in f.notes if "beam-column" in n)
    got = float(re.search(r"1/\(1 - P/P_e\) = ([0-9.]+)", note).group(1))
    assert got == pytest.approx(1 / (1 - 1000 / pe), rel=2e-3)
    assert f"{pe:.4g} N" in note
    assert not any("beam-column" in n for n in link_section_forces(link, "1000 N", transverse_load="50 N").notes)


def test_lug_allowable_folds_1_20_into_the_capacity():
    link = _link()
    nominal = {r.check: r for r in lug_checks(link, "2 kN", design_factor=2.0)}
    allowed = {r.check: r for r in lug_checks(link, "2 kN", design_factor=2.0, allowable=True)}
    for mode in ("lug_tension", "lug_fracture_beyond", "lug_shear_out"):
        assert nominal[mode].required_sf == pytest.approx(2.4)
        assert allowed[mode].required_sf == 2.0
        assert allowed[mode].capacity.m_as("N") == pytest.approx(nominal[mode].capacity.m_as("N") / 1.2)
        assert allowed[mode].factored_utilisation == pytest.approx(nominal[mode].factored_utilisation)  # same verdict
    assert allowed["lug_bearing"].capacity == nominal["lug_bearing"].capacity
