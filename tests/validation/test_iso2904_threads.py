"""ISO metric trapezoidal threads against the basic dimensions of ISO 2904 / DIN 103-4.

Table values (mm) of ISO 2904:1977, Table 1 (= DIN 103-4), as reproduced by RoyMech, "Trapezoidal
threads, table of threads to DIN 103-4" (roymech.org/Useful_Tables/Screws/Trapezoidal.html) and the
ICAD worked result for Tr10x2 (ac = 0.25, h3 = 1.25, H1 = 1, z = 0.5). The code computes them from d
and P with the ISO 2904 formulas and the crest-clearance table, so each row tests both.
"""

import pytest

from mechverify.components.threads import crest_clearance, thread

# designation: (d2 = D2, D4, d3, D1)
ISO_2904 = {
    "Tr8x1.5": (7.250, 8.300, 6.200, 6.500),
    "Tr9x1.5": (8.250, 9.300, 7.200, 7.500),
    "Tr10x2": (9.000, 10.500, 7.500, 8.000),
    "Tr11x2": (10.000, 11.500, 8.500, 9.000),
    "Tr11x3": (9.500, 11.500, 7.500, 8.000),
    "Tr12x2": (11.000, 12.500, 9.500, 10.000),
    "Tr12x3": (10.500, 12.500, 8.500, 9.000),
    "Tr14x2": (13.000, 14.500, 11.500, 12.000),
    "Tr14x3": (12.500, 14.500, 10.500, 11.000),
    "Tr16x2": (15.000, 16.500, 13.500, 14.000),
    "Tr42x3": (40.500, 42.500, 38.500, 39.000),
    "Tr42x7": (38.500, 43.000, 34.000, 35.000),
    "Tr44x7": (40.500, 45.000, 36.000, 37.000),
    "Tr44x12": (38.000, 45.000, 31.000, 32.000),
    "Tr46x3": (44.500, 46.500, 42.500, 43.000),
    "Tr46x8": (42.000, 47.000, 37.000, 38.000),
    "Tr46x12": (40.000, 47.000, 33.000, 34.000),
    "Tr48x3": (46.500, 48.500, 44.500, 45.000),
    "Tr48x8": (44.000, 49.000, 39.000, 40.000),
}


@pytest.mark.parametrize("name", sorted(ISO_2904))
def test_basic_dimensions(name):
    d2, D4, d3, D1 = ISO_2904[name]
    t = thread(name)
    assert t.d2.m_as("mm") == pytest.approx(d2, abs=5e-4)
    assert t.D4.m_as("mm") == pytest.approx(D4, abs=5e-4)
    assert t.d3.m_as("mm") == pytest.approx(d3, abs=5e-4)
    assert t.D1.m_as("mm") == pytest.approx(D1, abs=5e-4)


def test_tr10x2_profile_icad():
    """ICAD, Tr10x2 example (ISO 2901/2904): ac = 0.25, h3 = 1.25, H1 = 1, flank angle 15 deg."""
    t = thread("Tr10x2")
    assert crest_clearance(t.pitch).m_as("mm") == pytest.approx(0.25)
    assert ((t.d - t.d3) / 2).m_as("mm") == pytest.approx(1.25)
    assert t.H1.m_as("mm") == pytest.approx(1.0)
    assert t.flank_angle.m_as("deg") == pytest.approx(15.0)


@pytest.mark.parametrize(("name", "single", "starts", "lead"), [
    ("Tr12x6P3", "Tr12x3", 2, 6.0), ("Tr16x8P4", "Tr16x4", 2, 8.0), ("Tr20x8P4", "Tr20x4", 2, 8.0),
    ("Tr16x8(P4)", "Tr16x4", 2, 8.0),
])
def test_multistart_uses_profile_of_its_pitch(name, single, starts, lead):
    """ISO 2902 designation Tr d x Ph P P: lead Ph = starts x P, profile of the pitch P (ISO 2904)."""
    m, s = thread(name), thread(single)
    assert m.starts == starts and m.lead.m_as("mm") == pytest.approx(lead)
    for dim in ("d2", "d3", "D1", "D4", "H1"):
        assert getattr(m, dim) == getattr(s, dim)
