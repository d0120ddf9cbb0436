"""Mean effective load of a bearing under a repeating load cycle.

Source: Mott, Machine Elements in Mechanical Design, 4th ed., Eq. (14-11) and Example Problem 14-6:
6308 bearing, 650 lb for 30 min, 750 lb for 10 min, 250 lb for 20 min at 600 rpm; printed F_m = 597 lb.
"""

from __future__ import annotations

import pytest

from mechverify.components.bearings import duty_cycle_load


def test_mott_example_14_6_mean_effective_load():
    """Printed F_m = 597 lb; hand calculation ((30*650^3 + 10*750^3 + 20*250^3)/60)^(1/3) = 597.0 lb."""
    d = duty_cycle_load(["650 lbf", "750 lbf", "250 lbf"], [30, 10, 20])
    assert d.P.m_as("lbf") == pytest.approx(597, abs=0.5)
    # the same cycle as time shares with one speed: the speed cancels out, n_m = 600 rpm
    d2 = duty_cycle_load(["650 lbf", "750 lbf", "250 lbf"], [0.5, 1 / 6, 1 / 3], speeds=["600 rpm"] * 3)
    assert d2.P.m_as("lbf") == pytest.approx(d.P.m_as("lbf"), rel=1e-12)
    assert d2.mean_speed.m_as("rpm") == pytest.approx(600)
