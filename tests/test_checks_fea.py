"""Checks on solid FEA, modal and buckling results (mechverify.checks.fea): verdicts and orientation.

The numbers checked come from the analyses validated in tests/validation/test_blevins_cantilever_modes.py
(cantilever 203.8 Hz, Euler-Bernoulli hand calculation) and test_timoshenko_gere_euler_column.py
(Euler factor 10.28, hand calculation of Timoshenko & Gere sec. 2.1).
"""

from __future__ import annotations

import pytest

from mechverify.checks.fea import (
    check_buckling_load_factor,
    check_natural_frequency,
    check_solid_deflection,
    check_solid_stress,
)
from mechverify.checks.registry import CHECKS
from mechverify.errors import InputError
from mechverify.fea import buckling, mesh, modal, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane


@pytest.fixture(scope="module")
def bar():
    return solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (10, 1, 1)), "Structural Steel",
                            supports=(Fixed(Plane(x="0 mm")),),
                            loads=(Force(Plane(x="200 mm"), ("-1 kN", "0 N", "0 N")),))


def test_registered():
    for name in ("solid_stress", "solid_deflection", "natural_frequency", "buckling_load_factor"):
        assert name in CHECKS


def test_natural_frequency_minimum_and_band(bar):
    res = modal.modal(bar, 4)  # f1 = f2 ~ 206 Hz, f3 = f4 ~ 1283 Hz
    assert check_natural_frequency(res, minimum="150 Hz").verdict == "pass"
    assert check_natural_frequency(res, minimum="250 Hz").verdict == "fail"
    # a band between the pairs with 15 % margin: 206*1.15 < 300 and 1283/1.15 > 1000
    assert check_natural_frequency(res, band=("300 Hz", "1000 Hz")).verdict == "pass"
    r = check_natural_frequency(res, band=("190 Hz", "220 Hz"))
    assert r.verdict == "fail" and "governing mode" in " ".join(r.notes)
    # the band above every mode computed: a warning that more modes are needed
    r = check_natural_frequency(res, band=("2000 Hz", "3000 Hz"))
    assert r.warnings
    with pytest.raises(InputError, match="either minimum or band"):
        check_natural_frequency(res)


def test_buckling_factor_against_required_sf(bar):
    res = buckling.buckling(bar, 1)  # 10.4
    assert check_buckling_load_factor(res, required_sf=3.0).verdict == "pass"
    assert check_buckling_load_factor(res, required_sf=12.0).verdict == "fail"


def test_solid_stress_and_deflection(bar):
    res = bar.solve()  # 1 kN on 100 mm² -> 10 MPa axial compression (plus clamp effects)
    r = check_solid_stress(res, component="bar")
    assert r.demand.m_as("MPa") == pytest.approx(10, rel=0.3) and r.verdict == "pass"
    d = check_solid_deflection(res, "0.01 mm")  # PL/EA = 1e3*0.2/(200e9*1e-4) = 0.01 mm
    assert d.demand.m_as("mm") == pytest.approx(0.01, rel=0.05)
