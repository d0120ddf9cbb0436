"""Belt-conveyor drive drum shaft (examples/conveyor_drum/) from design file to results, against hand calculations.

Inputs of the design file: T1 = 900 N, T2 = 300 N horizontal (+y), drum 160 mm and 20 kg on hubs at x = 130 and
470 mm, bearings A at 75 and B at 525 mm, coupling journal d = 20 mm, seats 25 mm, body 30 mm, AISI 1045 CD.
Every expected number below is worked out here from statics and the formula named (not a printed value).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import mechverify.design
from mechverify.cli import main
from mechverify.fatigue import notch
from mechverify.materials.database import get
from mechverify.units import Q

DESIGN = Path(__file__).resolve().parents[2] / "examples" / "conveyor_drum" / "design.toml"
T1, T2, r, m_drum, g = 900.0, 300.0, 0.080, 20.0, 9.80665
xA, xB, xL, xR = 0.075, 0.525, 0.130, 0.470
T = (T1 - T2) * r  # 48 N m
Fy = (T1 + T2) / 2  # 600 N per hub
Fz = m_drum / 2 * g  # 98.07 N per hub
R = math.hypot(Fy, Fz)  # symmetric loads: each bearing carries one hub's load, 607.96 N


@pytest.fixture(scope="module")
def results() -> dict[str, object]:
    return {(x.component, x.check): x for x in mechverify.design.load(DESIGN).verify()}


def test_bearings_are_loaded_by_the_shaft_reactions(results: dict) -> None:
    """Statics: symmetric hubs about mid-span (300 mm) -> R_A = R_B = sqrt(600^2 + 98.07^2) = 607.96 N; the
    ball bearings read it through the connections drum_shaft.reaction_drive_end_radial / _tail_end_radial
    (outputs named after the shaft's supports)."""
    for b in ("bearing_A", "bearing_B"):
        res = results[(b, "bearing_static_safety")]
        assert res.demand.m_as("N") == pytest.approx(R, rel=1e-6)


def test_key_shear_and_crushing_din_6885(results: dict) -> None:
    """Coupling key, d = 20 mm: DIN 6885-1 6 x 6, t1 = 3.5 mm, l = 40 mm; F = 2T/d = 4800 N;
    tau = F/(b l) = 20.0 MPa; p = F/((h - t1) l) = 48.0 MPa."""
    F = 2 * T / 0.020
    assert results[("drum_shaft", "shaft_key_shear")].demand.m_as("MPa") == pytest.approx(F / (0.006 * 0.040) / 1e6)
    assert results[("drum_shaft", "shaft_key_crushing")].demand.m_as("MPa") == pytest.approx(
        F / (0.0025 * 0.040) / 1e6)


def test_fatigue_governs_at_the_coupling_keyseat(results: dict) -> None:
    """At the coupling keyseat the bending moment is zero (overhang without load) and the torque steady:
    sigma_a' = 0, sigma_m' = sqrt(3) Kfs 16 T/(pi d^3) with Kts = 3.0 (Shigley Table 7-1, end-mill keyseat),
    r = 0.02 d = 0.4 mm, Kfs = 1 + q_s (Kts - 1) (Eq. 6-32, q_s from Eqs. 6-34/6-35); DE-Goodman n = Sut/sigma_m'."""
    res = results[("drum_shaft", "shaft_fatigue")]
    Sut = get("AISI 1045 CD").require("ultimate_strength").m_as("Pa")
    qs = notch.notch_sensitivity(Q(0.4, "mm"), Q(Sut, "Pa"), "torsion").m
    Kfs = 1 + qs * (3.0 - 1)
    sm = math.sqrt(3) * Kfs * 16 * T / (math.pi * 0.020**3)
    assert "coupling key" in res.title
    assert res.safety_factor == pytest.approx(Sut / sm, rel=1e-6)


def test_hub_keyseat_section_hand_calculation(results: dict) -> None:
    """Hub keyseat at x = 130 mm, d = 30 mm: M = R (0.130 - 0.075) = 33.44 N m fully reversed, T = 48 N m steady,
    Kt = 2.14 / Kts = 3.0 (Table 7-1), r = 0.6 mm; Goodman n = 1/(sigma_a'/Se + sigma_m'/Sut) with Se from the
    Marin factors of the result's section list (the check's own Se is not re-derived here)."""
    res = results[("drum_shaft", "shaft_fatigue")]
    hub = next(s for s in res.details["sections"] if s["name"] == "hub key")
    Sut = get("AISI 1045 CD").require("ultimate_strength").m_as("Pa")
    Kf = 1 + notch.notch_sensitivity(Q(0.6, "mm"), Q(Sut, "Pa"), "bending").m * (2.14 - 1)
    assert hub["Kf"] == pytest.approx(Kf)
    M = R * (xL - xA)
    x = np.asarray(res.details["x"])
    assert np.max(np.asarray(res.details["M"])[np.abs(x - xL) < 1e-9]) == pytest.approx(M, rel=1e-9)


def test_slope_at_the_bearings_conjugate_beam(results: dict) -> None:
    """Slope at A of the stepped shaft by the conjugate beam (Euler-Bernoulli; Shigley Sec. 4-4 moment-area):
    theta_A = (1/l) * integral_A^B M(x) (x_B - x) / (E I(x)) dx, with M(x) the resultant (both planes have the
    same shape). Numeric integration of the closed-form M; the frame's Timoshenko elements agree within 1 %."""
    E = get("AISI 1045 CD").require("E").m_as("Pa")
    x = np.linspace(xA, xB, 200001)
    M = np.where(x < xL, R * (x - xA), np.where(x <= xR, R * (xL - xA), R * (xB - x)))
    d = np.where((x < 0.090) | (x > 0.510), 0.025, 0.030)
    f = M * (xB - x) / (E * math.pi * d**4 / 64)
    theta = float(np.sum((f[1:] + f[:-1]) / 2 * np.diff(x))) / (xB - xA)
    res = results[("drum_shaft", "shaft_bearing_slope")]
    assert res.demand.m_as("rad") == pytest.approx(theta, rel=0.01)


def test_critical_speed_margin(results: dict) -> None:
    """The capacity is the modal first frequency; Dunkerley's estimate is a lower bound below it and Rayleigh's
    (Shigley Sec. 7-6), and the modal and Rayleigh values agree within 2 %. A 30 mm shaft carrying 20 kg over 450 mm
    is far above 119 rpm (hand estimate: one 20 kg mass at mid-span of a 30 mm, 450 mm simply supported shaft,
    sqrt(48 E I / l^3 / m) = 816 rad/s = 7800 rpm; the hubs nearer the bearings raise it)."""
    res = results[("drum_shaft", "shaft_critical_speed")]
    ray, dunk = res.inputs["Rayleigh"].m_as("rpm"), res.inputs["Dunkerley"].m_as("rpm")
    modal = res.inputs["modal"].m_as("rpm")
    assert res.capacity.m_as("rpm") == pytest.approx(modal)
    assert dunk <= ray and dunk <= modal
    assert modal == pytest.approx(ray, rel=0.02)
    E = get("AISI 1045 CD").require("E").m_as("Pa")
    w1 = math.sqrt(48 * E * math.pi * 0.03**4 / 64 / 0.45**3 / 20.0) * 60 / (2 * math.pi)
    assert w1 < dunk < 3 * w1


def test_cli_check_runs(capsys: pytest.CaptureFixture[str]) -> None:
    """`mechverify check` on the example exits without failures (warnings: catalogue data of the 6205)."""
    code = main(["check", str(DESIGN)])
    assert code in (0, 1)
    assert "drum_shaft" in capsys.readouterr().out


def test_key_substituted_lines_evaluate_to_the_result(results: dict) -> None:
    """The report's substituted key lines (issue 25 format) evaluate back to the printed stress and the demand."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("subst", Path(__file__).parents[1] / "test_reports_substituted.py")
    mod = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    spec.loader.exec_module(mod)  # type: ignore[union-attr]
    for name in ("shaft_key_shear", "shaft_key_crushing", "shaft_static_yield"):
        r = results[("drum_shaft", name)]
        value, printed = mod.evaluate(r.substituted)
        assert value.m_as("MPa") == pytest.approx(printed.m_as("MPa"), rel=1e-3)
        assert printed.m_as("MPa") == pytest.approx(r.demand.m_as("MPa"), rel=1e-3)
    r = results[("drum_shaft", "shaft_fatigue")]
    value, printed = mod.evaluate(r.substituted)
    assert float(value) == pytest.approx(float(printed), rel=1e-3)
    assert float(printed) == pytest.approx(r.safety_factor, rel=1e-3)
    r = results[("drum_shaft", "shaft_bearing_slope")]
    value, printed = mod.evaluate(r.substituted)
    assert value.m_as("rad") == pytest.approx(printed.m_as("rad"), rel=1e-3)
    assert printed.m_as("rad") == pytest.approx(r.demand.m_as("rad"), rel=1e-3)
    assert results[("drum_shaft", "shaft_critical_speed")].substituted
