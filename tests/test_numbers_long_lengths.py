"""Long travel lengths read in km (review item 12): linear_guide_life's demand 5000 km and rating distance
50 km were shown as "5.00×10⁶ m" and "50000 m" where the design file says km. Display rule, no published
numbers: mm below 10 m, m up to 10 km, km from there."""

from __future__ import annotations

from mechverify.checks import linear_guides as lc
from mechverify.reports.numbers import quantity
from mechverify.units import Q


def test_lengths_from_10_km_in_km():
    assert quantity(Q(5e6, "m")) == "5000 km"
    assert quantity(Q(50, "km")) == "50.0 km"
    assert quantity(Q(15000, "m")) == "15.0 km"
    assert quantity(Q(9, "km")) == "9000 m"  # below 10 km: metres, as before
    assert quantity(Q(3, "m")) == "3000 mm"


def test_linear_guide_life_demand_and_rating_distance_in_km():
    g = lc.LinearGuide(C=Q(14.7, "kN"), C0=Q(23.5, "kN"), name="rail")
    r = lc.check_linear_guide_life(g, "1900 N", "5000 km")
    assert quantity(r.demand) == "5000 km"
    assert quantity(r.inputs["L_C"]).endswith(" km")
