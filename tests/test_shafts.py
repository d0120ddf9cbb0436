"""Shaft model, analysis and checks: closed-form beam cases, gear and belt forces, named errors.

Sources: Shigley 10th ed. Table A-9 (beam cases 5 and 10: simply supported with a centre/intermediate load,
overhang), Eq. 13-36 (gear force components), Sec. 17-2 (belt tensions); hand calculations, not printed values.
"""

from __future__ import annotations

import math

import pytest

from mechverify.checks import shafts as cs
from mechverify.components.shafts import (
    Feature,
    Segment,
    Shaft,
    Support,
    belt_tensions,
    force_load,
    gear_load,
    key_stresses,
)
from mechverify.errors import InputError, ModelError
from mechverify.fea.shafts import analyse, critical_speed
from mechverify.materials.database import get

M = get("AISI 1045 CD")
E = M.require("E").m_as("Pa")


def _ss(P: float = 1000.0, a: float = 0.4, L: float = 1.0, d: float = 0.05, **kw: object) -> Shaft:
    return Shaft("t", (Segment(L, d),), M, (Support("A", 0.0), Support("B", L)), (force_load("P", a, (0, 0, -P)),),
                 **kw)  # type: ignore[arg-type]


def test_simply_supported_intermediate_load_table_a9_case_6() -> None:
    """Table A-9-6: R1 = P b/l, M_max = P a b/l, end slope theta_A = P a b (l + b)/(6 E I l) (Euler; the
    Timoshenko shear deflection does not change the end slopes of this case)."""
    a = analyse(_ss())
    I = math.pi * 0.05**4 / 64
    assert a.reactions["A"].radial == pytest.approx(600.0)
    assert a.reactions["B"].radial == pytest.approx(400.0)
    assert a.max_moment() == pytest.approx((0.4, 240.0))
    assert a.slopes["A"] == pytest.approx(1000 * 0.4 * 0.6 * 1.6 / (6 * E * I), rel=1e-6)


def test_overhang_reactions_and_three_bearings() -> None:
    """Overhang (Table A-9-10): load P at x = l + a on supports at 0 and l: R1 = -P a/l, R2 = P (l + a)/l.
    Three equal-span bearings with a uniform... here a centre-span load on a two-span continuous beam gives the
    middle reaction 11/16 P (three-moment equation, hand calculation)."""
    sh = Shaft("o", (Segment(1.2, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)), (force_load("P", 1.2, (0, 0, -1e3)),))
    a = analyse(sh)
    assert a.reactions["A"].force[2] == pytest.approx(-200.0)
    assert a.reactions["B"].force[2] == pytest.approx(1200.0)
    sh3 = Shaft("c", (Segment(2.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0), Support("C", 2.0)),
                (force_load("P", 0.5, (0, 0, -1e3)),))
    r = analyse(sh3).reactions
    # Euler value 11/16 P; Timoshenko shear flexibility shifts it by < 0.5 % for this slender shaft
    assert r["B"].force[2] == pytest.approx(1e3 * 11 / 16, rel=5e-3)


def test_gear_forces_eq_13_36() -> None:
    """Spur gear, T = 100 N m, d = 0.2 m, phi = 20 deg: Wt = 1000 N, Wr = 364.0 N; helical psi = 30 deg:
    Wr = Wt tan(20)/cos(30) = 420.3 N, Wa = Wt tan(30) = 577.4 N. Mesh point on +y: tangential along +z."""
    g = gear_load("g", 0.1, 0.2, 100.0, angle=0.0)
    assert g.force[2] == pytest.approx(1000.0)
    assert g.force[1] == pytest.approx(-1000 * math.tan(math.radians(20)))
    h = gear_load("h", 0.1, 0.2, 100.0, helix_angle=30.0, angle=0.0)
    assert h.force[1] == pytest.approx(-1000 * math.tan(math.radians(20)) / math.cos(math.radians(30)))
    assert h.force[0] == pytest.approx(1000 * math.tan(math.radians(30)))
    assert h.moment[2] == pytest.approx(-0.1 * h.force[0])


def test_belt_tensions() -> None:
    """T1 - T2 = 2T/D, T1/T2 = 3: T = 150 N m, D = 0.3 m -> T1 - T2 = 1000, T2 = 500, T1 = 1500 N."""
    assert belt_tensions(150.0, 0.3, 3.0) == pytest.approx((1500.0, 500.0))


def test_key_stresses_hand() -> None:
    """T = 200 N m, d = 40 mm -> F = 10 kN; b = 12, h = 8, t1 = 5, l = 40 mm: tau = 20.8 MPa, p = 83.3 MPa."""
    tau, p = key_stresses(200.0, 0.04, 0.012, 0.008, 0.005, 0.04)
    assert tau == pytest.approx(10e3 / (0.012 * 0.04))
    assert p == pytest.approx(10e3 / (0.003 * 0.04))


def test_named_errors() -> None:
    seg = (Segment(0.5, 0.04), Segment(0.5, 0.05))
    sup = (Support("A", 0.0), Support("B", 1.0))
    with pytest.raises(InputError, match="larger than the step height"):
        Shaft("f", seg, M, sup, features=(Feature("shoulder", 0.5, radius=0.006),))
    with pytest.raises(InputError, match="not less than the radius"):
        Shaft("k", seg, M, sup, features=(Feature("keyseat", 0.2, depth=0.02),))
    with pytest.raises(InputError, match="outside the shaft"):
        Shaft("l", seg, M, sup, loads=(force_load("P", 1.5, (0, 0, -1.0)),))
    with pytest.raises(InputError, match="do not balance"):
        Shaft("t", seg, M, sup, loads=(force_load("P", 0.5, torque=10.0),))
    with pytest.raises(ModelError, match="free rotation"):
        analyse(Shaft("s", seg, M, (Support("A", 0.0),), loads=(force_load("P", 0.5, (0, 0, -1.0)),)))


def test_checks_run_and_criteria_order() -> None:
    """Soderberg is the most conservative and Gerber the least of the DE criteria (Shigley Sec. 7-4)."""
    sh = Shaft("c", (Segment(0.3, 0.03), Segment(0.4, 0.04), Segment(0.3, 0.03)), M,
               (Support("A", 0.15), Support("B", 0.85)),
               (force_load("P", 0.5, (0, 0, -2000.0), mass=5.0), force_load("in", 0.0, torque=100.0),
                force_load("out", 1.0, torque=-100.0)),
               (Feature("shoulder", 0.3, radius=0.002, name="sh"),
                Feature("keyseat", 0.05, keyseat="profile", length=0.04, name="key")), speed=150.0)
    a = analyse(sh)
    n = {c: cs.check_shaft_fatigue(sh, a, criterion=c).safety_factor for c in cs.CRITERIA}
    assert n["soderberg"] < n["goodman"] < n["asme_elliptic"]
    assert n["goodman"] < n["gerber"]
    assert cs.check_shaft_static_yield(sh, a).safety_factor > 1
    assert cs.check_shaft_bearing_slope(sh, a).demand.m > 0
    assert cs.check_shaft_critical_speed(sh, critical_speed(sh)).capacity.m > 0
    assert len(cs.check_shaft_key_shear(sh, a)) == 1


def _design(tmp_path, extra: str = "", features: str = "", bearing_load: str = "reaction_A_radial"):  # type: ignore[no-untyped-def]
    import mechverify.design

    text = f'''
[design]
name = "t"
[components.s]
type = "shaft"
material = "AISI 1045 CD"
speed = "100 rpm"
segments = [{{ length = "100 mm", diameter = "20 mm" }}, {{ length = "300 mm", diameter = "25 mm" }}]
supports = [{{ at = "50 mm" }}, {{ at = "380 mm" }}]
features = [{features}]
elements = [{{ kind = "coupling", at = "20 mm", torque_share = 1 }},
            {{ kind = "gear", at = "250 mm", pitch_diameter = "100 mm", module = "2 mm", torque_share = -1 }}]
{extra}
[components.b]
type = "ball_bearing"
model = "6204"
[load_cases.run.s]
torque = "20 N*m"
[load_cases.run.b]
radial_force = "s.{bearing_load}"
speed = "100 rpm"
'''
    p = tmp_path / "d.toml"
    p.write_text(text)
    return mechverify.design.load(p)


def test_design_file_gear_shaft_reaction_flows_to_the_bearing(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """Spur gear T = 20 N m on d = 100 mm: Wt = 400 N, Wr = 145.6 N (mesh at +z: Wt along -y, Wr along -z);
    supports at 50 and 380 mm, gear at 250 mm: R_A = W (380 - 250)/330 with W = sqrt(400^2 + 145.6^2) = 425.7 N
    -> 167.7 N (statics, hand calculation); the bearing's static check reads it through the connection."""
    res = {(r.component, r.check): r for r in _design(tmp_path).verify()}
    W = math.hypot(400.0, 400.0 * math.tan(math.radians(20)))
    assert res[("b", "bearing_static_safety")].demand.m_as("N") == pytest.approx(W * 130 / 330, rel=1e-6)
    assert ("s", "shaft_gear_deflection") in res


def test_design_file_named_errors(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """A fillet larger than the step and an output of a support the shaft does not have are named errors."""
    from mechverify.errors import MechverifyError

    with pytest.raises(MechverifyError, match="larger than the step height"):
        _design(tmp_path, features='{ kind = "shoulder", at = "100 mm", radius = "5 mm" }').verify()
    with pytest.raises(MechverifyError, match="reaction_C"):
        _design(tmp_path, bearing_load="reaction_C_radial").verify()


def test_report_figure_draws() -> None:
    """The shaft_fatigue figure (layout, M/T, deflection, n bars) is produced from the result details."""
    from mechverify.reports.plots.shafts import shaft_figure

    sh = Shaft("f", (Segment(0.3, 0.03), Segment(0.4, 0.04)), M, (Support("A", 0.05), Support("B", 0.65)),
               (force_load("P", 0.4, (0, 0, -2000.0)),), (Feature("shoulder", 0.3, radius=0.002, name="sh"),))
    fig = shaft_figure(cs.check_shaft_fatigue(sh, analyse(sh)))
    assert len(fig.axes) == 4


def test_ansi_square_key_table_7_6() -> None:
    """Shigley Table 7-6 (printed rows, checked against the 9th-ed. reproduction): a 1 7/16 in shaft (over 1 3/8
    to 1 3/4 in) takes a 3/8 in square key with a 3/16 in keyway depth; DIN 6885-1 for 40 mm: 12 x 8, t1 = 5 mm."""
    from mechverify.components.shafts import standard_key

    k = standard_key(1.4375 * 0.0254, "ansi")
    assert (k["b"], k["h"], k["t1"]) == pytest.approx((0.375 * 0.0254, 0.375 * 0.0254, 0.1875 * 0.0254))
    assert standard_key(0.040) == pytest.approx({"b": 0.012, "h": 0.008, "t1": 0.005})
    with pytest.raises(InputError):
        standard_key(0.04, "iso")


def test_helical_gear_axial_force_goes_to_the_locating_bearing() -> None:
    """Helical gear, T = 100 N m, d = 0.2 m, psi = 20 deg: Wa = Wt tan(psi) = 364.0 N, carried by the locating
    bearing alone (the floating one holds no axial motion); statics with the moment Wa d/2 of the axial force:
    radial reactions in the gear's mesh plane change by +-Wa (d/2)/l (hand calculation)."""
    g = gear_load("g", 0.3, 0.2, 100.0, helix_angle=20.0, angle=90.0)
    sh = Shaft("h", (Segment(0.6, 0.04),), M, (Support("A", 0.0, locating=True), Support("B", 0.6)),
               (g, force_load("in", 0.6, torque=-100.0)))
    r = analyse(sh).reactions
    Wa = 1000.0 * math.tan(math.radians(20))
    assert r["A"].axial == pytest.approx(Wa)
    assert r["B"].axial == pytest.approx(0.0, abs=1e-9)
    # mesh point at +z: radial force -Wr along z, tangential -Wt along y; the axial force at z = +r makes
    # My = r Fa about y; z-reactions: R_Az = Wr/2 + My/l, R_Bz = Wr/2 - My/l
    Wr = 1000.0 * math.tan(math.radians(20)) / math.cos(math.radians(20))
    assert r["A"].force[2] + r["B"].force[2] == pytest.approx(Wr)
    assert abs(r["A"].force[2] - r["B"].force[2]) == pytest.approx(2 * 0.1 * Wa / 0.6)


def test_spring_bearing_adds_its_compliance() -> None:
    """Two radial springs k under a centre load P on a statically determinate shaft: the reactions are P/2 and the
    centre deflection is P L^3/(48 E I) (Euler) + (P/2)/k (rigid-body sag of the bearings), hand calculation."""
    k, P, L, d = 2e7, 1000.0, 1.0, 0.05
    sh = Shaft("k", (Segment(L, d),), M, (Support("A", 0.0, kind="spring", stiffness=k, locating=True),
                                         Support("B", L, kind="spring", stiffness=k)),
               (force_load("P", L / 2, (0, 0, -P)),))
    a = analyse(sh, theory="euler")
    I = math.pi * d**4 / 64
    assert a.reactions["A"].radial == pytest.approx(P / 2)
    assert a.at(L / 2)["deflection"] == pytest.approx(P * L**3 / (48 * E * I) + P / 2 / k, rel=1e-9)


def test_cantilever_on_a_fixed_support_and_non_rotating_fatigue() -> None:
    """One fixed support (an overhung stub): reaction P, wall moment P L, tip deflection P L^3/(3 E I) (Table A-9-1,
    Euler). Non-rotating with steady loads: the bending stress is a mean stress, sigma_a' = 0, so DE-Goodman gives
    n = Sut/sigma_m' (hand calculation)."""
    P, L, d = 500.0, 0.2, 0.03
    sh = Shaft("c", (Segment(L, d),), M, (Support("A", 0.0, kind="fixed"),), (force_load("P", L, (0, 0, -P)),),
               rotating=False)
    a = analyse(sh, theory="euler")
    I = math.pi * d**4 / 64
    assert a.reactions["A"].radial == pytest.approx(P)
    assert a.max_moment() == pytest.approx((0.0, P * L))
    assert a.at(L)["deflection"] == pytest.approx(P * L**3 / (3 * E * I), rel=1e-9)
    r = cs.check_shaft_fatigue(sh, a)
    Sut = M.require("ultimate_strength").m_as("Pa")
    assert r.safety_factor == pytest.approx(Sut / (32 * P * L / (math.pi * d**3)), rel=1e-9)


def test_unnamed_features_are_labelled_in_words() -> None:
    """An unnamed feature's section is "shoulder at 300 mm" (was "shoulder@300"); a named one keeps its name, and
    the feature's own errors name it the same way."""
    feats = (Feature("shoulder", 0.3, radius=0.002), Feature("cross_hole", 0.15, Kt=2.0, Kts=1.5),
             Feature("groove", 0.32, radius=0.0005, depth=0.0005, name="ring groove"))
    sh = Shaft("f", (Segment(0.3, 0.03), Segment(0.4, 0.04)), M, (Support("A", 0.05), Support("B", 0.65)),
               (force_load("P", 0.4, (0, 0, -2000.0)),), feats)
    names = [s["name"] for s in cs.check_shaft_fatigue(sh, analyse(sh)).details["sections"]]
    assert names[:3] == ["shoulder at 300 mm", "cross hole at 150 mm", "ring groove"]
    with pytest.raises(InputError, match="^feature shoulder at 300 mm: radius must not be negative$"):
        Feature("shoulder", 0.3, radius=-0.001)
