"""Plane-model supports whose box cuts through boundary edges (issue 23, task fixsolid2's note on review 3 finding
22): a support box holds only the vertices inside it and the middles of the edges with both ends inside, so the held
length depends on where the mesh's nodes fall; the same WARN as a load's box and a solid's support box, with the
held length. The lengths are hand counts of the structured mesh's edges (mesh2d.rectangle), not printed values."""

from __future__ import annotations

import pytest

from mechverify.fea import mesh2d
from mechverify.fea.loads import Fixed, Force, Restraint
from mechverify.fea.plane import PlaneModel
from mechverify.fea.regions import Box, Plane


def _model(hi: str) -> PlaneModel:
    """A 100 x 30 mm plate, 10 x 3 cells (nodes at y = 0, 10, 20, 30 mm on x = 0), held on x = 0 from y = 0 to ``hi``
    in x and y, pulled along x at x = 100 mm."""
    return PlaneModel(mesh2d.rectangle(0.1, 0.03, 10, 3), "5 mm", "Structural Steel",
                      supports=(Fixed(Box(("-1 mm", "-1 mm"), ("1 mm", hi))),
                                Restraint(Plane(x="0 mm"), x=True)),
                      loads=(Force(Plane(x="100 mm"), ("1000 N", "0 N")),))


@pytest.mark.parametrize(("hi", "warned", "held_mm"), [("15 mm", True, 10.0), ("20 mm", False, 20.0)])
def test_support_box_cutting_through_edges_warns_with_the_held_length(hi, warned, held_mm):
    """Box to y = 15 mm: edge 0-10 held whole, edge 10-20 cut (its vertex at 10 held, its middle and far end free):
    WARN, held length 10 mm (hand count: one 10 mm edge). Box to y = 20 mm ends on a node: no WARN, 20 mm held.
    Before, plane supports compared only the length with an expectation and said nothing."""
    rep = next(r for r in _model(hi).region_reports() if r.item.startswith("Fixed"))
    assert rep.measure * 1e3 == pytest.approx(held_mm)
    if warned:
        assert rep.warning is not None and "cuts through 1 boundary facet(s)" in rep.warning
        assert "the support holds 10 mm of boundary" in rep.warning
    else:
        assert rep.warning is None


def test_support_warning_reaches_the_solved_results():
    """The WARN is in the field results' warnings after a solve (as the loads' WARN is)."""
    res = _model("15 mm").solve()
    assert any("Fixed 1" in w and "cuts through" in w for w in res.warnings)
    assert not any("cuts through" in w for w in _model("20 mm").solve().warnings)
