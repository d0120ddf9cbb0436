"""Kt fits against published values.

Sources:
- Pilkey & Pilkey, Peterson's Stress Concentration Factors, 3rd ed. (2008), Eq. (4.1)/Chart 4.1: a small hole
  in a wide plate gives Ktn -> 3 (Kirsch), and Howland's value for d/W = 0.5 is Ktn = 2.16 (Ktg = 4.32).
- Shigley 9th/10th ed., Fig. A-15-1 (from Peterson) as read in the 8th ed. Solutions Manual, Probs. 6-10 and 6-23:
  d/w = 0.2 -> Kt = 2.5.
- Shigley 9th/10th ed., Example 6-6: stepped shaft D = 38 mm, d = 32 mm, r = 3 mm in bending: Kt = 1.65 read
  from Fig. A-15-9 (Peterson chart); the fit must agree within chart-reading accuracy (2 %).
The axial and torsion shoulder fits and the groove fit have no published check value here yet.
"""

import pytest

from mechverify.errors import ValidityError
from mechverify.fatigue import notch


def test_plate_hole_small_hole_tends_to_kirsch_3():
    assert notch.kt_plate_hole("1000 mm", "1 mm").m == pytest.approx(3.0, abs=0.01)


def test_plate_hole_howland_half_width():
    assert notch.kt_plate_hole("100 mm", "50 mm").m == pytest.approx(2.16, abs=0.01)
    # gross-section value: Ktg = Ktn / (1 - d/W)
    assert notch.kt_plate_hole("100 mm", "50 mm").m / 0.5 == pytest.approx(4.32, abs=0.02)


def test_plate_hole_shigley_chart_a_15_1():
    assert notch.kt_plate_hole("60 mm", "12 mm").m == pytest.approx(2.5, abs=0.03)


def test_stepped_shaft_bending_shigley_example_6_6():
    assert notch.kt_shoulder_fillet("38 mm", "32 mm", "3 mm", "bending").m == pytest.approx(1.65, rel=0.02)


def test_fit_validity_range_enforced():
    with pytest.raises(ValidityError, match="t/r"):
        notch.kt_shoulder_fillet("40 mm", "32 mm", "0.1 mm", "bending")  # t/r = 40
    with pytest.raises(ValidityError):
        notch.kt_groove("40 mm", "32 mm", "0.5 mm")  # t/r = 8, outside the verified branch
