"""A plate too thick for Kirchhoff theory (span/thickness < 10) WARNs loudly, with the Mindlin deflection factor.

The factor is a hand calculation (mechverify.fea.plate.thick_plate_warning: the Kirchhoff-Mindlin relationship
for simply supported plates, w_M = w_K + M/(κGt), with Timoshenko & Woinowsky-Krieger's Table 8 centre values of
the uniformly loaded square plate): 1 + 5.19 (t/a)² at ν = 0.3, i.e. 1.052 at a/t = 10 and 1.207 at a/t = 5 (not
printed values; Reddy's shear-deformable plate tables give ratios of the same size, not checked here).
The issue's case: a 50 mm plate over an 80 mm span (span/t 1.6) passed with only a note.
"""

from __future__ import annotations

import pytest

from mechverify.checks.plates import check_plate_deflection_fea, check_plate_stress_fea
from mechverify.components import plates as P
from mechverify.fea.plate import solve_plate, thick_plate_warning


def test_factor_hand_values():
    for a_t, expected in ((10, 1.052), (5, 1.207), (1.6, 3.03)):
        text = thick_plate_warning(a_t * 0.01, 0.01, 0.3)
        assert f"{expected:.3g}x" in text


def test_thick_plate_warns_in_both_checks():
    plate = P.Plate.rectangle("80 mm", "80 mm", "50 mm", "Inventor Aluminum 6061")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all"),), loads=(P.PressureLoad("-1 MPa"),))
    res = solve_plate(model, mesh_size="10 mm")
    assert any("THICK PLATE" in w and "3.12x" in w for w in res.warnings)  # ν = 0.33: 1 + 18.15 / 3.35 / 1.6²
    assert check_plate_stress_fea(model, res).verdict == "warn"
    r = check_plate_deflection_fea(model, res, "10 mm")
    assert r.verdict == "warn" and any("solid_fea" in w for w in r.warnings)


def test_thin_plate_has_no_warning():
    plate = P.Plate.rectangle("200 mm", "200 mm", "4 mm", "Inventor Aluminum 6061")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all"),), loads=(P.PressureLoad("-1 kPa"),))
    assert not solve_plate(model, mesh_size="25 mm").warnings


@pytest.mark.parametrize("nu", [0.25, 0.33])
def test_factor_depends_on_poisson(nu):
    assert thick_plate_warning(0.05, 0.01, nu) != thick_plate_warning(0.05, 0.01, 0.3)
