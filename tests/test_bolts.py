"""Bolted joints: ISO data files, named errors, the joint object and the bolt pattern (elastic method)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mechverify.components import bolts as b
from mechverify.errors import InputError, UnitError, UnknownNameError
from mechverify.units import Q

DATA = Path(b.__file__).parent / "data"


# ------------------------------------------------------------------------------------------- ISO data
def test_stress_area_against_iso_898_1_printed_values():
    """ISO 898-1 nominal stress areas As,nom (printed, M3-M39, the data file's `As`, verified against the table
    reproduced at usefastener.com) against pi/4 ((d2 + d3)/2)^2 with ISO 724's d2, d3: every size within the
    table's 3 significant figures (M10: 58.0, M12: 84.3 mm^2)."""
    rows = [r for r in tomllib.loads((DATA / "bolts_iso.toml").read_text())["thread"] if "As" in r]
    assert len(rows) >= 20
    for r in rows:
        th = b.metric_thread(f"M{r['d']:g}")
        assert th.As * 1e6 == pytest.approx(r["As"], rel=5e-3), r["d"]
    assert b.metric_thread("M10").As * 1e6 == pytest.approx(58.0, abs=0.05)
    assert b.metric_thread("M12").As * 1e6 == pytest.approx(84.3, abs=0.05)


@pytest.mark.parametrize(("name", "d", "Rm", "Rp", "Sp"), [
    ("4.6", 10, 400, 240, 225), ("4.8", 10, 420, 340, 310), ("5.6", 10, 500, 300, 280), ("5.8", 10, 520, 420, 380),
    ("6.8", 10, 600, 480, 440), ("8.8", 12, 800, 640, 580), ("8.8", 20, 830, 660, 600), ("9.8", 10, 900, 720, 650),
    ("10.9", 10, 1040, 940, 830), ("12.9", 10, 1220, 1100, 970),
])
def test_property_classes_iso_898_1_table_3(name, d, Rm, Rp, Sp):
    """ISO 898-1:2013 Table 3 (printed; as reproduced at pankajinternational.com): R_m,min, R_eL/R_p0.2/R_pf min,
    S_p,nom [MPa]; 8.8 changes at d = 16 mm."""
    g = b.property_class(name, f"{d} mm")
    assert (g.Rm / 1e6, g.Rp02 / 1e6, g.Sp / 1e6) == (Rm, Rp, Sp)
    assert g.verified


def test_proof_load_m12_8_8_iso_898_1():
    """ISO 898-1 proof load F_p = As,nom S_p: M12 class 8.8 = 48 900 N, 10.9 = 70 000 N (printed, optimas.com
    reproduction of EN ISO 898-1)."""
    for grade, printed in (("8.8", 48900), ("10.9", 70000)):
        g = b.property_class(grade, "12 mm")
        assert 84.3e-6 * g.Sp == pytest.approx(printed, rel=2e-3)


def test_head_nut_hole_tables():
    """ISO 4762 d_k, ISO 4032 m and d_w, ISO 273 holes (printed values of the sources named in the data file)."""
    m5 = b.metric_thread("M5")
    assert b.head_bearing_diameter(m5, "socket") == pytest.approx(8.5e-3)
    assert b.nut_dimensions(m5)["m"] == pytest.approx(4.7e-3)
    assert b.nut_dimensions(m5)["dw"] == pytest.approx(6.9e-3)
    assert [b.clearance_hole(m5, f) for f in ("fine", "medium", "coarse")] == pytest.approx([5.3e-3, 5.5e-3, 5.8e-3])
    # ISO 4014 grade A bearing face d_w min (printed table reproduced at scribd.com/document/367243871)
    for size, dw in (("M8", 11.63), ("M14", 19.37), ("M24", 33.61)):
        assert b.head_bearing_diameter(b.metric_thread(size), "hex") == pytest.approx(dw * 1e-3)


def test_every_data_row_has_source_and_flag():
    """Every data row names its source (a key of [references]) and says whether it was verified."""
    for name in ("bolts_iso.toml", "bolts_vdi2230.toml"):
        data = tomllib.loads((DATA / name).read_text())
        refs = data["references"]
        for table, rows in data.items():
            if table == "references":
                continue
            for r in rows:
                items = [v for v in r.values() if isinstance(v, dict) and "source" in v] or [r]
                for it in items:
                    assert it["source"] in refs, (name, table, r)
                    assert isinstance(it["verified"], bool), (name, table, r)


# ------------------------------------------------------------------------------------------- named errors
def test_unknown_size_suggests_nearest():
    with pytest.raises(UnknownNameError, match="M10.*M12|M12.*M10"):
        b.metric_thread("M11")
    with pytest.raises(UnknownNameError, match="M10x1.25"):
        b.metric_thread("M10x0.75")
    with pytest.raises(InputError):
        b.metric_thread("1/4-20")


def _joint(**kw):
    base = dict(name="j", thread="M8", grade="8.8", parts=[("8 mm", "S235JR"), ("8 mm", "S235JR")], length="35 mm")
    base.update(kw)
    return b.bolted_joint(**base)


def test_bad_input_named_errors():
    with pytest.raises(InputError, match="clamp length"):
        _joint(length="16 mm")                      # clamp length not shorter than the bolt
    with pytest.raises(InputError, match="thickness"):
        _joint(parts=[("0 mm", "S235JR")])           # clamp length 0
    with pytest.raises(InputError, match="hole"):
        _joint(d_W="8 mm", d_h="9 mm")               # head bearing diameter smaller than the hole
    with pytest.raises(InputError, match="mu_G"):
        _joint(mu_G=(-0.1, 0.12))                    # negative friction
    with pytest.raises(InputError, match="mu_T"):
        _joint(mu_T=-0.2)
    j = _joint()
    with pytest.raises(InputError, match="friction"):
        j.analyse("1 kN", F_Q="500 N")              # transverse load without friction data
    with pytest.raises(UnitError):
        j.analyse(1000)
    with pytest.raises(InputError, match="temperature change"):
        j.analyse("1 kN", dT=Q(20, "degC"))


def test_tapped_joint_engagement_and_stripping():
    """A screw into a tapped aluminium body: engagement = L - l_K; a short engagement strips before the bolt breaks."""
    j = b.bolted_joint("t", "M8", "10.9", [("10 mm", "S235JR")], "16 mm", tapped="Aluminium 6061-T6")
    assert j.engagement == pytest.approx(6e-3)
    a = j.analyse("2 kN")
    assert a.stripping_capacity < a.stripping_demand
    long = j.with_(length=0.030)
    assert long.analyse("2 kN").stripping_capacity > a.stripping_capacity


def test_torque_given_sets_preloads():
    """With a tightening torque M_A: F_M,max = M_A/K(mu_min), F_M,min = M_A/K(mu_max)/alpha_A (R13 inverted)."""
    j = _joint(tightening_torque="20 N*m", alpha_A=1.4)
    a = j.analyse("1 kN")
    assert a.F_M_max == pytest.approx(20 / j.torque_factor(0.10, 0.10))
    assert a.F_M_min == pytest.approx(20 / j.torque_factor(0.16, 0.16) / 1.4)
    assert a.M_A == 20


# ------------------------------------------------------------------------------------------- bolt pattern
def test_pattern_moment_about_centroid():
    """Four bolts on a 80 x 120 rectangle: a moment M_x = 480 N m gives +-480/(4 x 0.06^2) x 0.06 = +-2000 N
    (F_i = M v_i / sum v^2, closed form); a central force splits equally; equilibrium of force and moment holds."""
    pat = b.BoltPattern(_joint(), ((0.0, 0.0), (0.08, 0.0), (0.08, 0.12), (0.0, 0.12)))
    loads = pat.distribute(F_z=400.0, M_x=480.0)
    ax = [bl.axial for bl in loads]
    assert ax == pytest.approx([100 - 2000, 100 - 2000, 100 + 2000, 100 + 2000])
    xc, yc = pat.centroid
    assert sum(ax) == pytest.approx(400)
    assert sum(bl.axial * (bl.position[1] - yc) for bl in loads) == pytest.approx(480)


def test_pattern_eccentric_force_and_torque():
    """An in-plane force F_y at distance e from the centroid: direct F/n plus torque F e r_i/sum r^2 (Shigley Sec. 8-12);
    an axial force at a point gives the same as the force at the centroid plus its moment."""
    pos = ((-0.05, 0.0), (0.05, 0.0))
    pat = b.BoltPattern(_joint(), pos)
    loads = pat.distribute(F_y=1000.0, at=(0.1, 0.0))
    # torque M_z = 0.1 x 1000 = 100 N m, sum r^2 = 0.005: bolt at +x gets +1000, at -x -1000 in y, plus 500 direct
    assert loads[0].transverse == pytest.approx((0.0, 500 - 1000))
    assert loads[1].transverse == pytest.approx((0.0, 500 + 1000))
    ecc = pat.distribute(F_z=1000.0, at=(0.05, 0.0))
    assert [bl.axial for bl in ecc] == pytest.approx([0.0, 1000.0])
    with pytest.raises(InputError, match="line"):
        pat.distribute(M_x=10.0)          # both bolts on the x axis: no moment about it


def test_pattern_analyse_per_bolt():
    pat = b.BoltPattern(_joint(mu_T=0.15), ((0.0, 0.0), (0.1, 0.0), (0.1, 0.1), (0.0, 0.1)))
    res = pat.analyse(pat.distribute(F_z=2000.0, F_x=400.0, M_y=-50.0))
    assert len(res) == 4
    assert max(r.F_A_max for r in res) > 500
    assert all(r.F_Q == pytest.approx(100) for r in res)
    assert all(math.isfinite(r.sigma_red_B) for r in res)


_coord = st.floats(-0.2, 0.2, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(pts=st.lists(st.tuples(_coord, _coord), min_size=3, max_size=8),
       Fz=st.floats(-5e3, 5e3), Mx=st.floats(-200, 200), My=st.floats(-200, 200),
       Fx=st.floats(-1e3, 1e3), Fy=st.floats(-1e3, 1e3), Mz=st.floats(-100, 100))
def test_pattern_loads_are_in_equilibrium(pts, Fz, Mx, My, Fx, Fy, Mz):
    """The elastic method's bolt loads balance the applied force and moments about the centroid (statics), for any
    pattern that is not a line."""
    p = np.asarray(pts)
    u, v = p[:, 0] - p[:, 0].mean(), p[:, 1] - p[:, 1].mean()
    A = np.array([[u @ u, u @ v], [u @ v, v @ v]])
    assume(np.linalg.det(A) > 1e-8)
    pat = b.BoltPattern(_joint(), tuple(map(tuple, pts)))
    loads = pat.distribute(F_z=Fz, F_x=Fx, F_y=Fy, M_x=Mx, M_y=My, M_z=Mz)
    ax = np.array([bl.axial for bl in loads])
    tx = np.array([bl.transverse[0] for bl in loads])
    ty = np.array([bl.transverse[1] for bl in loads])
    tol = 1e-6 * (1 + abs(Fz) + abs(Mx) + abs(My) + abs(Fx) + abs(Fy) + abs(Mz))
    assert abs(ax.sum() - Fz) < tol
    assert abs((ax * v).sum() - Mx) < tol
    assert abs(-(ax * u).sum() - My) < tol
    assert abs(tx.sum() - Fx) < tol and abs(ty.sum() - Fy) < tol
    assert abs((u * ty - v * tx).sum() - Mz) < tol


def test_friction_classes_vdi_2230_table_a5():
    """VDI 2230 Table A5 friction classes (printed in the reproduction named in the data file): A 0.04-0.10,
    B 0.08-0.16, C 0.14-0.24, D 0.20-0.35, E >= 0.30."""
    assert [b.friction_class(c) for c in "ABCD"] == [(0.04, 0.10), (0.08, 0.16), (0.14, 0.24), (0.20, 0.35)]
    assert b.friction_class("e")[0] == 0.30
    with pytest.raises(UnknownNameError):
        b.friction_class("F")


def test_shigley_constant_of_a_joint():
    """BoltedJoint.shigley_constant: k_b by Eq. (8-17) over the grip (M12 x 60 hex bolt, 40 mm grip: shank
    60 - 30 = 30 mm, thread 10 mm), k_m equal to Eq. (8-22) for two equal steel plates with d_w = 1.5 d (hand
    calculation from the equations); the two methods' load factors are close for steel (C vs VDI Phi_K)."""
    j = b.bolted_joint("j", "M12", "8.8", [("20 mm", "S235JR"), ("20 mm", "S235JR")], "60 mm", d_W="18 mm",
                       E_S="210 GPa")
    kb, km, C = j.shigley_constant()
    Ad, At = math.pi / 4 * 12e-3**2, j.thread.As
    assert kb == pytest.approx(Ad * At * 210e9 / (Ad * 10e-3 + At * 30e-3))
    assert km == pytest.approx(b.member_stiffness_equal("210 GPa", "12 mm", "40 mm").m_as("N/m"), rel=1e-3)
    assert C == pytest.approx(kb / (kb + km))
    assert abs(C - j.analyse("1 kN").Phi_K) < 0.05


def test_size_without_head_tables_needs_dimensions():
    """A thread outside the head/nut/hole tables (M18) is an InputError naming what to give; with the bearing and
    hole diameters given, a tapped joint is calculated."""
    with pytest.raises(InputError, match="head_bearing_diameter"):
        b.bolted_joint("j", "M18", "8.8", [("20 mm", "S235JR")], "60 mm")
    j = b.bolted_joint("j", "M18", "8.8", [("20 mm", "S235JR")], "60 mm", d_W="25 mm", d_h="20 mm", tapped="S235JR")
    assert j.analyse("10 kN").sigma_red_B > 0
