"""Natural frequencies of simply supported rectangular plates (mechverify.fea.plate_modal) against the closed form.

Source: A. W. Leissa, *Vibration of Plates*, NASA SP-160, 1969, Sec. 4.1 (and Leissa, J. Sound Vib. 31 (1973)
257-293, case SS-SS-SS-SS): for a plate simply supported on all four edges the modes are w = sin(mπx/a) sin(nπy/b)
and ω_mn = π² (m²/a² + n²/b²) √(D/(ρh)), D = E h³ / (12 (1 - ν²)). Every number below is a hand calculation
from that formula (not a printed table value). The first mode's effective mass along z is (8/π²)² = 0.657 of the
plate's mass (hand calculation: (∫ sin sin)² / (∫ sin² sin² · a b) = (4ab/π²)² / (ab/4 · ab)).
"""

import math

import numpy as np
import pytest

from mechverify.components import plates as P
from mechverify.errors import InputError, ModelError
from mechverify.fea.plate_modal import plate_modes

E, NU, RHO = 200e9, 0.3, 7850.0  # the database's Structural Steel


def closed_form(a, b, t, count=6):
    D = E * t**3 / (12 * (1 - NU**2))
    f = sorted(math.pi**2 * (m * m / a**2 + n * n / b**2) * math.sqrt(D / (RHO * t)) / (2 * math.pi)
               for m in range(1, 6) for n in range(1, 6))
    return np.array(f[:count])


def ss_plate(a_mm, b_mm, t_mm):
    plate = P.Plate.rectangle(f"{a_mm} mm", f"{b_mm} mm", f"{t_mm} mm", "Structural Steel")
    return P.PlateModel(plate, supports=(P.EdgeSupport("all"),))


def test_simply_supported_rectangle_first_six_modes():
    """300 x 200 x 3 mm steel plate: f_11 = 259.93 Hz, then 499.86, 799.77, 899.75, 1039.71, 1439.59 Hz (hand
    calculation); the Morley mesh at 10 mm (2401 unknowns, sparse shift-invert) is within 0.5 % on mode 1 and 2.5 %
    on mode 6, converging with h² (5 mm: 0.12 %)."""
    hand = closed_form(0.3, 0.2, 0.003)
    assert hand[0] == pytest.approx(259.93, abs=0.01)
    res = plate_modes(ss_plate(300, 200, 3), 6, mesh_size="10 mm")
    f = res.frequencies.m_as("Hz")
    assert res.unknowns > 1500  # the sparse (ARPACK) path
    assert f[0] == pytest.approx(hand[0], rel=5e-3)
    assert f == pytest.approx(hand, rel=2.5e-2)
    err10 = abs(f[0] / hand[0] - 1)
    f20 = plate_modes(ss_plate(300, 200, 3), 1, mesh_size="20 mm").frequencies.m_as("Hz")  # dense path
    err20 = abs(f20[0] / hand[0] - 1)
    assert 3.0 < err20 / err10 < 5.5  # second-order convergence of the Morley element
    assert res.effective_mass_fraction()[0, 2] == pytest.approx((8 / math.pi**2) ** 2, rel=0.02)
    assert res.effective_mass_fraction()[1, 2] == pytest.approx(0.0, abs=1e-9)  # antisymmetric mode


def test_square_plate_double_frequency():
    """200 mm square, 2 mm: modes (1, 2) and (2, 1) share f = 5π²/(2πa²)√(D/ρh) (hand calculation)."""
    hand = closed_form(0.2, 0.2, 0.002, 3)
    f = plate_modes(ss_plate(200, 200, 2), 3, mesh_size="10 mm").frequencies.m_as("Hz")
    assert f[0] == pytest.approx(hand[0], rel=1e-2)  # a/20 elements: 0.65 % low
    assert f[1] == pytest.approx(f[2], rel=1e-6)
    assert f[1] == pytest.approx(hand[1], rel=2e-2)  # 1.8 % low at a/20


def test_bad_plate_modal_requests(tmp_path):
    """A plate held at one point only, too many modes: named errors; VTU export of the modes."""
    plate = P.Plate.rectangle("100 mm", "100 mm", "2 mm", "Structural Steel")
    one_point = P.PlateModel(plate, supports=(P.PointSupport(("0 mm", "0 mm")),))
    with pytest.raises(ModelError, match="not fully supported"):
        plate_modes(one_point, 2)
    with pytest.raises(InputError, match="free unknowns"):
        plate_modes(ss_plate(100, 100, 2), 10_000, mesh_size="50 mm")
    res = plate_modes(ss_plate(100, 100, 2), 2, mesh_size="20 mm")
    assert "mode_2_" in res.to_vtu(tmp_path / "plate_modes.vtu").read_text()


def test_clamped_square_default_mesh_accuracy_as_documented():
    """The default-mesh accuracy of clamped plates stated in docs/design-files.md (review 3 finding 2): 300 x 300 x
    3 mm steel, all edges clamped. Leissa's frequency parameters lambda = omega a^2 sqrt(rho h / D) for the CCCC
    square, 35.99, 73.39, 108.2 (modes 1, 2-3, 4; NASA SP-160 as quoted by review 3 and the issue, NOT checked
    against the printed table here), give 291.64, 594.71, 876.79 Hz (hand calculation). The default mesh (side / 16)
    is below them (code results 279.2, 552.3, 799.0 Hz: -4.3, -7.1, -8.9 %) and converges from below (10 mm: 287.9 Hz,
    -1.3 %)."""
    a, t = 0.3, 0.003
    D = E * t**3 / (12 * (1 - NU**2))
    leissa = np.array([35.99, 73.39, 73.39, 108.2]) / (2 * math.pi * a**2) * math.sqrt(D / (RHO * t))
    assert leissa[0] == pytest.approx(291.64, abs=0.01)
    plate = P.Plate.rectangle("300 mm", "300 mm", "3 mm", "Structural Steel")
    model = P.PlateModel(plate, supports=(P.EdgeSupport("all", "clamped"),))
    err = plate_modes(model, 4).frequencies.m_as("Hz") / leissa - 1
    assert -0.06 < err[0] < -0.03  # docs: about -4 % on mode 1
    assert -0.10 < err[1] < -0.05 and -0.10 < err[3] < -0.07  # higher modes worse
    f10 = plate_modes(model, 1, mesh_size="10 mm").frequencies.m_as("Hz")[0]
    assert -0.02 < f10 / leissa[0] - 1 < 0.0  # converges from below


# Leissa's CCCC square parameters, checked against a second printed source: Harris, Shock and Vibration Handbook, as
# printed on engineersedge.com ("Thin Flat Plates Uniform Thickness Natural Frequency", all edges clamped:
# omega = B sqrt(E t^2 / (rho a^4 (1 - nu^2))), B = 10.40, 21.21, 31.29): lambda = B sqrt(12) = 36.03, 73.47, 108.4,
# 0.1-0.2 % above Leissa's 35.99, 73.39, 108.2 (B printed to four digits) - so Leissa's values are verified to that.
HARRIS_B = (10.40, 21.21, 31.29)
LEISSA_CCCC = (35.99, 73.39, 108.2)

CCCC = """
[design]
name = "clamped square plate modes"
[components.p]
type = "plate_fea"
width = "300 mm"
height = "300 mm"
thickness = "3 mm"
material = "Structural Steel"
supports = [{{ edges = "all", type = "fixed" }}]
{extra}
[components.p.checks]
plate_stress_fea = false
plate_deflection_fea = false
"""


def _cccc_hz(lam):
    a, t = 0.3, 0.003
    D = E * t**3 / (12 * (1 - NU**2))
    return lam / (2 * math.pi * a**2) * math.sqrt(D / (RHO * t))


def test_leissa_cccc_parameters_agree_with_harris():
    for b, lam in zip(HARRIS_B, LEISSA_CCCC, strict=True):
        assert b * math.sqrt(12) == pytest.approx(lam, rel=0.003)


def _frequency_result(tmp_path, extra):
    import mechverify

    f = tmp_path / "cccc.toml"
    f.write_text(CCCC.format(extra=extra))
    return next(r for r in mechverify.load(f).verify() if r.check == "natural_frequency")


def test_clamped_band_check_uses_extrapolated_frequencies_and_warns(tmp_path):
    """Review 3 #2 (cccc_band4.toml): band 980-1100 Hz, margin 15 % -> no mode in 852.2-1265 Hz. Leissa's (2,2) mode
    (lambda 108.2) is at 876.8 Hz (hand), inside: FAIL. The default mesh alone gave 799.0 Hz, WARN u 0.938 (wrong
    side); now the frequencies are extrapolated from two meshes (code: 291.1, 592.1, 592.1, 870.2 Hz, within 1 % of
    Leissa's 291.6, 594.7, 594.7, 876.8), the check FAILs and a WARN names the design mesh's error (8.2 % on mode 4)."""
    r = _frequency_result(tmp_path, 'excitation_band = ["980 Hz", "1100 Hz"]\nmodes = 4')
    hand = np.array([_cccc_hz(x) for x in (35.99, 73.39, 73.39, 108.2)])
    assert hand[3] == pytest.approx(876.79, abs=0.05) and 980 / 1.15 < hand[3] < 1100 * 1.15
    f = r.details["frequencies"].m_as("Hz")
    assert f == pytest.approx(hand, rel=0.01)
    assert r.verdict.name.lower() == "fail"
    w = [x for x in r.warnings if x.startswith("mesh convergence of the frequencies")]
    assert len(w) == 1 and "mode 4 is 799" in w[0], r.warnings
    assert any(n.startswith("two-mesh check of the frequencies") for n in r.notes)


def test_clamped_minimum_frequency_with_convergence_check(tmp_path):
    """min_frequency 280 Hz, convergence_check: three meshes, observed order per mode about 2 (Morley), the
    extrapolated mode 1 within 0.5 % of Leissa's 291.6 Hz (code 291.8); the check takes the more critical of the
    finest mesh's (289.0 Hz) and the extrapolated frequencies, so it passes on 289.0 Hz."""
    r = _frequency_result(tmp_path, 'min_frequency = "280 Hz"\nmodes = 2\nconvergence_check = true')
    note = next(n for n in r.notes if n.startswith("three-mesh check of the frequencies"))
    p = float(note.split("observed order ")[2].split(",")[0])
    assert 1.5 < p < 2.5
    ext = float(note.split("extrapolated ")[1].split(" Hz")[0])
    assert ext == pytest.approx(_cccc_hz(35.99), rel=0.005)
    assert r.capacity.m_as("Hz") < ext and r.verdict.name.lower() == "warn"  # u = 280/289 = 0.97: near the limit
    assert not [w for w in r.warnings if w.startswith("mesh convergence")]  # only mode 1 decides a minimum
    assert any(n.startswith("modes that do not decide this check") and "mode 2" in n for n in r.notes)


def test_convergence_of_modes_that_do_not_decide_is_noted_not_warned(tmp_path):
    """Review 4 #26: min_frequency 20 Hz with modes = 4 on the clamped square (f1 = 285.8 Hz on the finer mesh,
    Leissa 291.6 Hz by hand from lambda 35.99): only mode 1 decides a minimum. Mode 4 (799.0 Hz on the design's
    mesh, 870.2 extrapolated: 8.2 % > the 5 % tolerance) WARNed the check before; now it is a note and the check
    passes. An excitation band near mode 4 still warns (test above)."""
    r = _frequency_result(tmp_path, 'min_frequency = "20 Hz"\nmodes = 4')
    assert r.verdict.name.lower() == "pass", r.warnings
    assert not [w for w in r.warnings if w.startswith("mesh convergence")]
    note = next(n for n in r.notes if n.startswith("modes that do not decide this check"))
    assert "mode 4 8.18 %" in note
    assert r.capacity.m_as("Hz") == pytest.approx(_cccc_hz(35.99), rel=0.025)
