"""Mass moments of inertia of standard bodies (mechverify.components.mass_properties).

Sources: the closed forms of Meriam & Kraige, Dynamics, Table D/4 and Hibbeler, Dynamics (inside back cover).
Worked numbers: Young & Freedman, University Physics 13th ed., Exercise 9.31 (a 2.50 kg rod of 75.0 cm;
an 8.00 kg cylinder of 12.0 cm diameter): the published worked solution gives 0.469 kg m² (about the end)
and 0.117 kg m² (about the centre) for the rod; the cylinder values below are hand calculations from the
formula (not printed values). Other limit cases: a hollow cylinder with r_i = 0 is the solid one; the
parallel-axis theorem takes the rod about its centre to the rod about its end.
"""

from __future__ import annotations

import pytest

from mechverify.components import mass_properties as mp
from mechverify.errors import InputError, UnitError


def test_rod_of_young_freedman_9_31():
    """Exercise 9.31(a): worked solution 0.469 kg m² (end), 0.117 kg m² (centre); hand: 2.5 x 0.75² / 3 and / 12."""
    assert mp.rod_about_end("2.5 kg", "75 cm").m_as("kg*m**2") == pytest.approx(0.469, abs=5e-4)
    assert mp.rod_about_centre("2.5 kg", "75 cm").m_as("kg*m**2") == pytest.approx(0.117, abs=5e-4)
    assert mp.rod_about_end("2.5 kg", "75 cm").m_as("kg*m**2") == pytest.approx(2.5 * 0.75**2 / 3, rel=1e-12)


def test_cylinder_of_young_freedman_9_31c():
    """Exercise 9.31(c)(ii), solid 8.00 kg cylinder of 12.0 cm diameter about its axis: m r²/2 = 8 x 0.06²/2 =
    0.0144 kg m² (hand calculation from the formula); thin-walled: m r² = 0.0288 (the hollow form at r_i -> r_o)."""
    assert mp.solid_cylinder_axial("8 kg", "6 cm").m_as("kg*m**2") == pytest.approx(0.0144, rel=1e-12)
    assert mp.hollow_cylinder_axial("8 kg", "6 cm", "5.99999 cm").m_as("kg*m**2") == pytest.approx(0.0288, rel=1e-5)


def test_limits_and_parallel_axis():
    """Hollow with r_i = 0 = solid (axial and transverse); a cylinder with r -> 0 is the rod m L²/12;
    parallel axis: m L²/12 + m (L/2)² = m L²/3; a square plate about its normal = 2 x the rod about its centre."""
    m, r, L = "3 kg", "20 mm", "400 mm"
    assert mp.hollow_cylinder_axial(m, r, "0 mm").m_as("kg*m**2") == pytest.approx(
        mp.solid_cylinder_axial(m, r).m_as("kg*m**2"), rel=1e-12)
    assert mp.hollow_cylinder_transverse(m, r, "0 mm", L).m_as("kg*m**2") == pytest.approx(
        mp.solid_cylinder_transverse(m, r, L).m_as("kg*m**2"), rel=1e-12)
    assert mp.solid_cylinder_transverse(m, "1e-9 m", L).m_as("kg*m**2") == pytest.approx(
        mp.rod_about_centre(m, L).m_as("kg*m**2"), rel=1e-9)
    end = mp.parallel_axis(mp.rod_about_centre(m, L), m, "200 mm")
    assert end.m_as("kg*m**2") == pytest.approx(mp.rod_about_end(m, L).m_as("kg*m**2"), rel=1e-12)
    assert mp.rectangular_plate_normal(m, L, L).m_as("kg*m**2") == pytest.approx(
        2 * mp.rod_about_centre(m, L).m_as("kg*m**2"), rel=1e-12)


def test_bad_input_named():
    with pytest.raises(InputError, match="inner_radius"):
        mp.hollow_cylinder_axial("1 kg", "10 mm", "12 mm")
    with pytest.raises(InputError, match="mass"):
        mp.rod_about_end("-1 kg", "1 m")
    with pytest.raises(UnitError):
        mp.rod_about_end("1 kg", "1 s")
