"""Rainflow counting against ASTM E1049-85 (Reapproved 2017), Sec. 5.4.4, Fig. 6: the example history
A..I = -2, 1, -3, 5, -1, 3, -4, 4, -2 and its published count:
range 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5 (ranges 1, 2, 5, 7, 10: none)."""

import pytest

from mechverify import Q
from mechverify.fatigue.rainflow import rainflow, rainflow_table, reversals

HISTORY = [-2, 1, -3, 5, -1, 3, -4, 4, -2]
PUBLISHED = {3.0: 0.5, 4.0: 1.5, 6.0: 0.5, 8.0: 1.0, 9.0: 0.5}


def test_astm_example_count():
    assert rainflow_table(HISTORY) == PUBLISHED


def test_astm_example_with_intermediate_samples_and_units():
    """The same history sampled finely (non-reversal points, a plateau) and in MPa counts the same."""
    fine = []
    for a, b in zip(HISTORY[:-1], HISTORY[1:], strict=False):
        fine.extend([a, a + (b - a) / 3, a + 2 * (b - a) / 3])
    fine += [HISTORY[-1], HISTORY[-1]]
    assert list(reversals(fine)) == pytest.approx(HISTORY)
    table = rainflow_table(Q(fine, "MPa"))
    assert table == pytest.approx(PUBLISHED)
    cycles = rainflow(Q(HISTORY, "MPa"))
    full = [c for c in cycles if c.count == 1.0]
    assert len(full) == 1 and full[0].range.m_as("MPa") == 4 and full[0].mean.m_as("MPa") == 1  # E-F: -1..3
