"""Shafts (issue 21): modal critical speeds against closed forms, reactions at every support by name as outputs
for the bearings, substituted formula lines of every shaft check, and data provenance (unverified rows WARN).

Every expected number is a closed form or a hand calculation from statics, named in the test's docstring; the
substituted lines are consistency checks of the report line against the check's own result (as in
tests/test_reports_substituted.py), not published values.
"""

from __future__ import annotations

import importlib.util
import math
import tomllib
from pathlib import Path

import pytest

from mechverify.checks import shafts as cs
from mechverify.components import shafts as s
from mechverify.components.shafts import Feature, Segment, Shaft, Support, force_load, gear_load
from mechverify.errors import MechverifyError, ModelError
from mechverify.fea.shafts import analyse, critical_speed, frame_critical_speeds, modal_critical_speeds
from mechverify.materials.database import get
from mechverify.units import Q

M = get("AISI 1045 CD")
E = M.require("E").m_as("Pa")
RHO = M.require("density").m_as("kg/m**3")

_spec = importlib.util.spec_from_file_location("subst", Path(__file__).with_name("test_reports_substituted.py"))
SUBST = importlib.util.module_from_spec(_spec)  # type: ignore[arg-type]
_spec.loader.exec_module(SUBST)  # type: ignore[union-attr]


def _uniform(d: float = 0.05, L: float = 1.0) -> tuple[float, float]:
    return math.pi * d**4 / 64, RHO * math.pi / 4 * d**2


# ------------------------------------------------------------------------------------------ modal critical speed
def test_modal_uniform_simply_supported_shaft_closed_form() -> None:
    """Uniform simply supported shaft (Shigley 10th ed. Eq. 7-22; Timoshenko, Vibration Problems in Engineering):
    omega_n = (n pi / l)^2 sqrt(E I / (rho A)). Consistent-mass Euler-Bernoulli elements converge as h^4: with 80
    elements the first three agree within 1e-6."""
    I, mA = _uniform()
    sh = Shaft("u", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)))
    w = modal_critical_speeds(sh, n_modes=3)
    for n, wn in enumerate(w.omegas, start=1):
        assert wn == pytest.approx((n * math.pi) ** 2 * math.sqrt(E * I / mA), rel=1e-6)
    assert w.first == pytest.approx(s.critical_speed_uniform(1.0, E, I, mA), rel=1e-6)


def test_modal_and_rayleigh_dunkerley_bracket_the_closed_form() -> None:
    """The same shaft: Rayleigh (Eq. 7-23) on the shaft lumped in pieces is within 1 % of the closed form and
    Dunkerley (Eq. 7-24) below it (a lower bound); the modal solution lies between Dunkerley and 1.001 x exact."""
    I, mA = _uniform()
    exact = s.critical_speed_uniform(1.0, E, I, mA)
    sh = Shaft("u", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)))
    c, w = critical_speed(sh), modal_critical_speeds(sh)
    assert c.rayleigh == pytest.approx(exact, rel=0.01)
    assert c.dunkerley < w.first < 1.001 * exact


def test_modal_single_mass_on_massless_shaft_is_sqrt_k_over_m() -> None:
    """A 20 kg disc at mid-span of a massless 50 mm x 1 m shaft: omega = sqrt(48 E I / (l^3 m)) (one degree of
    freedom; the singular mass matrix is handled by solving M phi = (1/omega^2) K phi)."""
    I, _ = _uniform()
    sh = Shaft("m", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)),
               (force_load("disc", 0.5, mass=20.0),), shaft_mass=False)
    w = modal_critical_speeds(sh, n_modes=3)
    assert w.omegas == pytest.approx((math.sqrt(48 * E * I / 20.0),), rel=1e-9)
    assert critical_speed(sh).rayleigh == pytest.approx(w.first, rel=0.005)  # Timoshenko statics: shear < 0.5 %


def test_modal_cantilever_and_timoshenko() -> None:
    """Cantilever on a fixed support: omega_1 = 1.87510^2 sqrt(E I / (rho A l^4)) (Euler-Bernoulli). Timoshenko
    elements lower it slightly (shear flexibility; d/l = 0.05: < 0.5 %)."""
    I, mA = _uniform()
    sh = Shaft("c", (Segment(1.0, 0.05),), M, (Support("A", 0.0, kind="fixed"),))
    w = modal_critical_speeds(sh).first
    assert w == pytest.approx(1.875104**2 * math.sqrt(E * I / mA), rel=1e-6)
    wt = modal_critical_speeds(sh, theory="timoshenko").first
    assert 0.995 * w < wt < w


def test_modal_named_errors() -> None:
    """One pinned bearing leaves the shaft free to tilt: a ModelError naming the bearing; an unknown theory is an
    input error."""
    sh = Shaft("c", (Segment(1.0, 0.05),), M, (Support("A", 0.0),))
    with pytest.raises(ModelError, match="free to tilt about bearing A"):
        modal_critical_speeds(sh)
    with pytest.raises(MechverifyError, match="theory"):
        modal_critical_speeds(Shaft("u", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0))),
                              theory="rayleigh")


def test_frame_modal_uniform_shaft_closed_form() -> None:
    """The frame's modal solution (fea.frame.modal, issue 23) on the shaft's frame model: Euler-Bernoulli members,
    uniform simply supported shaft, omega_n = (n pi/l)^2 sqrt(E I/(rho A)) for n = 1, 2, 3 within 1e-5, 5e-4, 1e-3
    (10 elements in the one member; the consistent mass converges from above). The y/z whirl pair counts once and
    the torsional/axial modes of the 3D frame are skipped."""
    I, mA = _uniform()
    sh = Shaft("u", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)))
    w = frame_critical_speeds(sh, theory="euler").omegas
    exact = [(n * math.pi) ** 2 * math.sqrt(E * I / mA) for n in (1, 2, 3)]
    for wn, ex, tol in zip(w, exact, (1e-5, 5e-4, 1e-3), strict=True):
        assert ex <= wn <= ex * (1 + tol)


def test_frame_modal_equals_the_shafts_own_eigenproblem_on_a_stepped_shaft() -> None:
    """A stepped shaft with an overhang and two discs (the conveyor drum's proportions): the frame's modal
    solution (10 elements per member, its default) and the shaft's own planar consistent-mass eigenproblem
    (independent code, Euler-Bernoulli in both, 200 elements: converged to 1e-7) agree within 1e-4 for the first
    two lateral modes; the first lies between Dunkerley and 1.02 x Rayleigh."""
    sh = Shaft("d", (Segment(0.06, 0.02), Segment(0.03, 0.025), Segment(0.42, 0.03), Segment(0.03, 0.025)), M,
               (Support("A", 0.075), Support("B", 0.525)),
               (force_load("L", 0.13, mass=10.0), force_load("R", 0.47, mass=10.0), force_load("cpl", 0.03, mass=1.5)))
    wf = frame_critical_speeds(sh, theory="euler").omegas
    wo = modal_critical_speeds(sh, theory="euler", elements=200).omegas
    assert wf[0] == pytest.approx(wo[0], rel=1e-4)
    assert wf[1] == pytest.approx(wo[1], rel=1e-4)
    c = critical_speed(sh, theory="euler")
    assert c.dunkerley < wf[0] < 1.02 * c.rayleigh


def test_critical_speed_check_uses_the_modal_solution() -> None:
    """With the modal solution the check's capacity is its first frequency; Rayleigh/Dunkerley are inputs, and the
    substituted Rayleigh line (Eq. 7-23 with the sums) evaluates to the Rayleigh value."""
    sh = Shaft("u", (Segment(1.0, 0.05),), M, (Support("A", 0.0), Support("B", 1.0)), speed=100.0)
    c, w = critical_speed(sh), frame_critical_speeds(sh)
    r = cs.check_shaft_critical_speed(sh, c, modal=w)
    assert r.capacity.m_as("rad/s") == pytest.approx(w.first)
    value, printed = SUBST.evaluate(r.substituted)
    assert value.m_as("rad/s") == pytest.approx(printed.m_as("rad/s"), rel=2e-3)
    assert printed.m_as("rad/s") == pytest.approx(c.rayleigh, rel=1e-3)
    assert cs.check_shaft_critical_speed(sh, c).capacity.m_as("rad/s") == pytest.approx(min(c.rayleigh, c.dunkerley))


# ------------------------------------------------------------------------------------------ substituted lines
def _test_shaft(keyseat: str = "profile") -> Shaft:
    return Shaft("c", (Segment(0.3, 0.03), Segment(0.4, 0.04, bore=0.01), Segment(0.3, 0.03)), M,
                 (Support("A", 0.15), Support("B", 0.85)),
                 (gear_load("G", 0.5, 0.1, -100.0, module=0.002, mass=4.0), force_load("in", 0.0, torque=100.0)),
                 (Feature("shoulder", 0.3, radius=0.002, name="sh"),
                  Feature("keyseat", 0.05, keyseat=keyseat, length=0.04, name="key"),
                  Feature("shoulder", 0.7, radius=0.002, name="sh2")), speed=150.0, torque_alternating_fraction=0.1)


def _evaluates(r: object, target: float, unit: str) -> None:
    value, printed = SUBST.evaluate(r.substituted)  # type: ignore[attr-defined]
    value, printed = Q(value).to(unit or ""), Q(printed).to(unit or "")  # a safety factor evaluates to a number
    assert value.m == pytest.approx(printed.m, rel=3e-3), r.substituted  # type: ignore[attr-defined]
    assert printed.m == pytest.approx(target, rel=1e-3), r.substituted  # type: ignore[attr-defined]


@pytest.mark.parametrize("criterion", cs.CRITERIA)
def test_fatigue_substituted_line_evaluates_to_the_safety_factor(criterion: str) -> None:
    """DE-Goodman/Gerber/elliptic/Soderberg with the governing section's sigma_a', sigma_m', Se and Sut or Sy
    substituted evaluate to the check's safety factor."""
    sh = _test_shaft()
    r = cs.check_shaft_fatigue(sh, analyse(sh), criterion=criterion)
    _evaluates(r, r.safety_factor, "")


def test_yield_slope_gear_deflection_key_substituted_lines() -> None:
    """sigma'_max (Eq. 7-15, hollow section modulus where the governing section is bored), the resultant slope at
    the governing bearing, the resultant deflection at the gear and the key stresses evaluate to their demands."""
    sh = _test_shaft()
    a = analyse(sh)
    r = cs.check_shaft_static_yield(sh, a)
    _evaluates(r, r.demand.m_as("MPa"), "MPa")
    r = cs.check_shaft_bearing_slope(sh, a)
    _evaluates(r, r.demand.m_as("rad"), "rad")
    (r,) = cs.check_shaft_gear_deflection(sh, a)
    _evaluates(r, r.demand.m_as("mm"), "mm")
    for r in (*cs.check_shaft_key_shear(sh, a), *cs.check_shaft_key_crushing(sh, a)):
        _evaluates(r, r.demand.m_as("MPa"), "MPa")


def test_hollow_section_yield_line_uses_the_tube_modulus() -> None:
    """A bored section at the largest moment: the substituted line carries W = pi (D^4 - d^4)/(32 D) and
    evaluates to sigma'_max of that section (hand: Kf = Kfs = 1 at a plain section)."""
    sh = Shaft("h", (Segment(1.0, 0.04, bore=0.02),), M, (Support("A", 0.0), Support("B", 1.0)),
               (force_load("P", 0.5, (0, 0, -4000.0)),))
    r = cs.check_shaft_static_yield(sh, analyse(sh))
    W = math.pi * (0.04**4 - 0.02**4) / (32 * 0.04)
    assert r.demand.m_as("Pa") == pytest.approx(1000.0 / W, rel=1e-6)  # M = P l / 4 = 1000 N m
    _evaluates(r, r.demand.m_as("MPa"), "MPa")


# ------------------------------------------------------------------------------------------ provenance
def test_every_verified_row_names_its_source_and_unverified_rows_say_why() -> None:
    """shafts.toml: a table or row marked verified names what it was checked against; one marked unverified
    gives the reason. Table 7-2 and the DIN 6885-1 rows are verified (public tables named in the file)."""
    with s.DATA.open("rb") as f:
        d = tomllib.load(f)
    for name, tab in d.items():
        rows = [v for v in tab.values() if isinstance(v, dict)] + list(tab.get("rows", []))
        for row in rows or [tab]:
            v = row.get("verified", tab.get("verified"))
            assert v is not None, name
            if v:
                assert row.get("checked_against") or tab.get("checked_against"), (name, row)
            else:
                assert row.get("unverified_reason") or tab.get("unverified_reason"), (name, row)
    assert d["slope_allowance"]["verified"] and d["gear_deflection_allowance_in"]["verified"]
    assert all(r["verified"] for r in d["din6885"]["rows"])
    assert not d["kt_first_iteration"]["keyseat_sled_runner"]["verified"]


def test_unverified_table_row_makes_the_check_warn() -> None:
    """A sled-runner keyseat takes Kt from the unverified Table 7-1 row: the fatigue and yield checks carry the
    caveat as a warning (verdict at least WARN); a profile keyseat (verified row) carries none."""
    sh = _test_shaft("sled_runner")
    a = analyse(sh)
    r = cs.check_shaft_fatigue(sh, a)
    assert any("not verified" in w and "sled_runner" in w for w in r.warnings)
    assert r.verdict.value in ("warn", "fail")
    sh = _test_shaft("profile")
    assert not cs.check_shaft_fatigue(sh, analyse(sh)).warnings
    assert not cs.check_shaft_key_shear(sh, analyse(sh))[0].warnings


# ------------------------------------------------------------------------------------------ connections
def _design(tmp_path: Path, load: str) -> object:
    import mechverify.design

    text = f'''
[design]
name = "three bearings"
[components.s]
type = "shaft"
material = "AISI 1045 CD"
speed = "100 rpm"
segments = [{{ length = "600 mm", diameter = "30 mm" }}]
supports = [{{ name = "left", at = "0 mm" }}, {{ name = "middle", at = "300 mm" }}, {{ name = "right", at = "600 mm" }}]
elements = [{{ kind = "force", name = "P", at = "150 mm", force = "1000 N", angle = "90 deg" }}]
[components.b]
type = "ball_bearing"
model = "6205"
[load_cases.run.s]
torque = "0 N*m"
[load_cases.run.b]
radial_force = "{load}"
speed = "100 rpm"
'''
    p = tmp_path / "d.toml"
    p.write_text(text)
    return mechverify.design.load(p)


def _two_span_reactions(shear: bool) -> dict[str, float]:
    """Force method for the two-span beam (hand calculation): the middle reaction R_m makes the mid-span deflection
    of the simply supported 600 mm beam zero; bending deflections from Table A-9 (case 6 and the centre load),
    shear deflections P a (L - x)/(L G A_s) and R L/(4 G A_s) with A_s = 6/7 A of a solid circle (the shear area
    the frame's Timoshenko elements use)."""
    E, G = M.require("E").m_as("Pa"), M.require("G").m_as("Pa")
    I, A = math.pi * 0.03**4 / 64, math.pi / 4 * 0.03**2
    As = 6 / 7 * A if shear else math.inf
    P, L, a, x = 1000.0, 0.6, 0.15, 0.3
    num = P * a * (L - x) * (2 * L * x - x * x - a * a) / (6 * E * I * L) + P * a * (L - x) / (L * G * As)
    Rm = num / (L**3 / (48 * E * I) + L / (4 * G * As))
    Rl = (P * (L - a) - Rm * (L - x)) / L
    return {"left": Rl, "middle": Rm, "right": abs(P - Rm - Rl)}


@pytest.mark.parametrize(("support", "share"), [("left", 13 / 32), ("middle", 22 / 32), ("right", 3 / 32)])
def test_reaction_of_every_support_by_name(tmp_path: Path, support: str, share: float) -> None:
    """Two-span continuous beam, spans l = 300 mm, load P = 1000 N at the middle of the first span: Euler-Bernoulli
    reactions 13P/32, 22P/32 and -3P/32 (three-moment equation). The bearing reads each through
    s.reaction_<support>_radial (the magnitude); the design file's Timoshenko elements give the force-method
    result with shear deflection (_two_span_reactions), Euler-Bernoulli elements the fractions."""
    assert _two_span_reactions(False)[support] == pytest.approx(1000 * share, rel=1e-12)
    res = {(r.component, r.check): r for r in _design(tmp_path, f"s.reaction_{support}_radial").verify()}
    assert res[("b", "bearing_static_safety")].demand.m_as("N") == pytest.approx(_two_span_reactions(True)[support],
                                                                                 rel=1e-6)
    sh = Shaft("s", (Segment(0.6, 0.03),), M, (Support("left", 0.0), Support("middle", 0.3), Support("right", 0.6)),
               (force_load("P", 0.15, (0, 0, 1000.0)),))
    assert analyse(sh, theory="euler").reactions[support].radial == pytest.approx(1000 * share, rel=1e-9)


def test_reaction_of_a_support_the_shaft_does_not_have_is_a_named_error(tmp_path: Path) -> None:
    """A bearing naming a support the shaft lacks: the error names the support, lists the shaft's supports and
    points at the load-case key."""
    with pytest.raises(MechverifyError, match=r"(?s)load_cases\.run\.b\.radial_force.*no support named 'tail'.*"
                                              r"left, middle, right"):
        _design(tmp_path, "s.reaction_tail_radial").verify()


def test_shaft_torque_read_from_another_components_torque_output(tmp_path: Path) -> None:
    """A drive pulley shaft turning a Tr10x2 lift screw: the shaft's torque is the screw's output
    ``lift_screw.drive_torque`` (raise torque at mu_max, Hamrock 3rd ed. Eq. 16.10) through a connection. Hand
    calculation of the torque: T = F d2/2 (l + pi mu d2 sec(alpha_n)) / (pi d2 - mu l sec(alpha_n)) with
    tan(alpha_n) = tan(15 deg) cos(lambda), F = 350 N, d2 = 9 mm, l = 2 mm, mu = 0.25; the shaft's key shear then is
    2T/(d b l) with the DIN 6885-1 key of the 12 mm journal (4 x 4, t1 = 2.5 mm) and l = 15 mm."""
    import mechverify.design

    text = '''
[design]
name = "screw input shaft"
[components.lift_screw]
type = "lead_screw"
thread = "Tr10x2"
length = "450 mm"
material = "Structural Steel"
nut_length = "20 mm"
mu_min = 0.09
mu_max = 0.25
nut_p_allow = "23 MPa"
nut_pv_allow = "0.27 MPa*m/s"
[components.s]
type = "shaft"
material = "AISI 1045 CD"
speed = "540 rpm"
segments = [{ length = "30 mm", diameter = "12 mm" }, { length = "100 mm", diameter = "15 mm" }]
supports = [{ name = "front", at = "40 mm" }, { name = "rear", at = "120 mm" }]
features = [{ kind = "keyseat", at = "15 mm", length = "15 mm", name = "pulley key" }]
elements = [{ kind = "pulley", at = "15 mm", diameter = "60 mm", ratio = 3, torque_share = 1 },
            { kind = "coupling", at = "130 mm", torque_share = -1 }]
[load_cases.raise.lift_screw]
axial_force = "350 N"
speed = "18 mm/s"
[load_cases.raise.s]
torque = "lift_screw.drive_torque"
'''
    p = tmp_path / "d.toml"
    p.write_text(text)
    res = {(r.component, r.check): r for r in mechverify.design.load(p).verify()}
    lam = math.atan(2 / (math.pi * 9))
    sec = 1 / math.cos(math.atan(math.tan(math.radians(15)) * math.cos(lam)))
    T = 350 * 0.009 / 2 * (0.002 + math.pi * 0.25 * 0.009 * sec) / (math.pi * 0.009 - 0.25 * 0.002 * sec)
    tau = res[("s", "shaft_key_shear")].demand.m_as("Pa")
    assert tau == pytest.approx(2 * T / (0.012 * 0.004 * 0.015), rel=1e-6)


def test_modal_two_masses_equals_the_influence_coefficient_eigenproblem() -> None:
    """The shaft of Shigley's Sec. 7-6 example (1 in steel shaft, E = 30 Mpsi, 31 in span, 35 and 55 lbf gears at
    7 and 20 in, shaft mass neglected; inputs as in tests/validation/test_shigley10_shafts.py). Hand calculation,
    not a printed value: influence coefficients from Table A-9-6, delta_ij = b_j x_i (l^2 - b_j^2 - x_i^2)/(6 E I l)
    (x_i <= a_j, else by symmetry), and the exact 2-degree-of-freedom frequencies from det(delta m - I/omega^2) = 0.
    The modal solution equals them (Euler-Bernoulli) within 1e-6; Dunkerley <= omega_1 <= Rayleigh (Sec. 7-6)."""
    import numpy as np

    inch, lbf = 0.0254, 4.4482216
    E_ = 30e6 * 6894.757
    I = math.pi * (1 * inch) ** 4 / 64
    L = 31 * inch
    xs, ms = (7 * inch, 20 * inch), (35 * lbf / 9.80665, 55 * lbf / 9.80665)

    def delta(x: float, a: float) -> float:
        if x > a:  # mirror: the load at l - a, the point at l - x
            x, a = L - x, L - a
        b = L - a
        return b * x * (L**2 - b**2 - x**2) / (6 * E_ * I * L)

    D = np.array([[delta(xi, aj) for aj in xs] for xi in xs])
    mu = np.sort(np.linalg.eigvals(D @ np.diag(ms)).real)[::-1]  # 1/omega^2
    exact = 1 / np.sqrt(mu)
    m = M.with_(E=Q(30e6, "psi"))
    sh = Shaft("ex", (Segment(L, 1 * inch),), m, (Support("A", 0.0), Support("B", L)),
               tuple(force_load(f"w{i}", x, mass=mm) for i, (x, mm) in enumerate(zip(xs, ms, strict=True))),
               shaft_mass=False)
    w = modal_critical_speeds(sh, n_modes=2).omegas
    assert w == pytest.approx(tuple(exact), rel=1e-6)
    c = critical_speed(sh, theory="euler")
    assert c.dunkerley <= w[0] <= c.rayleigh


def test_drive_output_torque_becomes_the_shaft_torque(tmp_path: Path) -> None:
    """A belt-and-drum linear axis (the drive example of tests/test_design_drives.py: 0.5 kg, mu = 0.1, a = 2 m/s^2,
    drum D = 20 mm, eta_drum = 0.9, belt 20:40): the drive's output ``output_torque_peak`` is the torque on the drum
    shaft, T = (m a + mu m g) (D/2) / eta_drum (hand calculation; drum inertia 0), and the shaft reads it as its
    ``torque``: the pulley key's shear 2T/(d b l) (DIN 6885-1 4 x 4 key for d = 12 mm, l = 15 mm)."""
    import mechverify.design

    text = '''
[design]
name = "drum axis"
[profiles.move]
type = "trapezoidal"
distance = "300 mm"
max_velocity = "0.2 m/s"
acceleration = "2 m/s^2"
[components.slide]
type = "drive"
motor = "maxon 6V 10.3 mNm"
transmission = [{ type = "belt", driver = 20, driven = 40, efficiency = 0.95 },
                { type = "drum", diameter = "20 mm", efficiency = 0.9 }]
mass = "0.5 kg"
friction_coefficient = 0.1
profile = "move"
[components.s]
type = "shaft"
material = "AISI 1045 CD"
segments = [{ length = "30 mm", diameter = "12 mm" }, { length = "60 mm", diameter = "15 mm" }]
supports = [{ name = "front", at = "40 mm" }, { name = "rear", at = "80 mm" }]
features = [{ kind = "keyseat", at = "15 mm", length = "15 mm", name = "pulley key" }]
elements = [{ kind = "pulley", at = "15 mm", diameter = "50 mm", ratio = 3, torque_share = 1 },
            { kind = "coupling", at = "90 mm", torque_share = -1 }]
[load_cases.run.s]
torque = "slide.output_torque_peak"
'''
    p = tmp_path / "d.toml"
    p.write_text(text)
    res = {(r.component, r.check): r for r in mechverify.design.load(p).verify()}
    T = (0.5 * 2 + 0.1 * 0.5 * 9.80665) * 0.010 / 0.9
    tau = res[("s", "shaft_key_shear")].demand.m_as("Pa")
    assert tau == pytest.approx(2 * T / (0.012 * 0.004 * 0.015), rel=1e-6)


def test_shaft_under_balanced_torques_only() -> None:
    """A shaft loaded by torques alone (5 N m in at x = 0, 2 N m out at 50 mm, 3 N m out at 100 mm): statics gives
    |T| = 5 N m on (0, 50) mm and 3 N m on (50, 100) mm, no bending and no reactions; the same torque diagram as
    the frame with a negligible transverse load added (the frame's equilibrium check cannot scale a purely
    self-equilibrated moment set, so the shaft solves this case directly). One pinned bearing is a named error."""
    import numpy as np

    loads = (force_load("in", 0.0, torque=5.0), force_load("mid", 0.05, torque=-2.0), force_load("out", 0.1, torque=-3.0))
    sups = (Support("A", 0.02), Support("B", 0.08))
    a = analyse(Shaft("t", (Segment(0.1, 0.02),), M, sups, loads))
    assert a.at(0.025)["T"] == pytest.approx(5.0) and a.at(0.075)["T"] == pytest.approx(3.0)
    assert a.M.max() == 0 and all(r.radial == 0 for r in a.reactions.values())
    b = analyse(Shaft("t", (Segment(0.1, 0.02),), M, sups, (force_load("w", 0.0, (0, 0, -1e-2)), *loads)))
    assert np.allclose(a.x, b.x) and np.allclose(a.T, b.T, atol=1e-12)
    with pytest.raises(ModelError, match="free to tilt"):
        analyse(Shaft("t", (Segment(0.1, 0.02),), M, (Support("A", 0.02),), loads))
