"""A screw stage's friction as a study variable (issue 19, task 19f; mechverify/studies/params.py).

The lift's screw stage writes no ``mu``: the drive is checked at both ends of the nut's friction range (iglidur R
0.09..0.25). A study may now vary ``components.lift.transmission[0].mu`` all the same (``uniform`` alone: over that
range), and a range outside it is warned about.

Hand calculation (not a printed value): the motor's torque demand at the peak instant is the inertia torque plus
the screw's raising torque, T = T_in + F k(mu) with Hamrock 3rd ed. Eq. 16.10,
k(mu) = d2/2 (cos(alpha_n) tan(lambda) + mu) / (cos(alpha_n) - mu tan(lambda)), for the Tr10x2 screw of the lift
(ISO 2904: d2 = 9 mm, lead 2 mm, alpha = 15 deg, tan(alpha_n) = tan(alpha) cos(lambda), tan(lambda) = l/(pi d2)).
The motor's capacity at that speed does not depend on mu, so u(mu) is affine in k(mu):
(u3 - u1)/(u2 - u1) = (k3 - k1)/(k2 - k1), whatever F, T_in and the capacity are.
"""

from __future__ import annotations

import copy
import math
import warnings
from pathlib import Path

import pytest

from mechverify.errors import InputError
from mechverify.studies import Study
from mechverify.studies.params import OutsideRangeWarning, Parameter

ROOT = Path(__file__).resolve().parents[1]
LIFT = ROOT / "examples" / "lead_screw_lift" / "design.toml"
MU = "components.lift.transmission[0].mu"


def k_raise(mu: float, d2: float = 9e-3, lead: float = 2e-3, alpha: float = math.radians(15)) -> float:
    """Raising torque per newton [m], Hamrock 3rd ed. Eq. 16.10 (no collar)."""
    tan_l = lead / (math.pi * d2)
    alpha_n = math.atan(math.tan(alpha) * math.cos(math.atan(tan_l)))
    return d2 / 2 * (math.cos(alpha_n) * tan_l + mu) / (math.cos(alpha_n) - mu * tan_l)


def test_mu_left_to_the_nut_can_be_varied():
    """Uniform over the nut's range (0.09..0.25 of iglidur R, the lift's nut) when the spec is 'uniform' alone; the
    axis starts from the range's upper end (the drive's governing end)."""
    study = Study(LIFT, vary={MU: "uniform"}, samples=6, seed=2)
    (axis,) = study.axes
    assert (axis.kind, axis.args, axis.param.base) == ("uniform", (0.09, 0.25), 0.25)
    mus = [x[MU] for x in study.inputs()]
    assert all(0.09 <= m <= 0.25 for m in mus) and len(set(mus)) == 6
    assert study.overrides(study.inputs()[0]) == {MU: mus[0]}


def test_drawn_mu_against_the_hand_calculation():
    """A sweep 0.10..0.25: the motor's peak-torque u is affine in Hamrock's k(mu) (see the module docstring), and a
    sample equals the design file with that mu written into it (bit for bit)."""
    result = Study(LIFT, vary={MU: "0.1:0.25:4"}).run("serial", check_inputs=False)
    assert [s["status"] for s in result.samples] == ["ok"] * 4
    u = [s["checks"]["lift.motor_peak_torque"]["u"] for s in result.samples]
    mus = [s["inputs"][MU] for s in result.samples]
    k = [k_raise(m) for m in mus]
    for j in (2, 3):
        assert (u[j] - u[0]) / (u[1] - u[0]) == pytest.approx((k[j] - k[0]) / (k[1] - k[0]), rel=1e-9)
    assert u[0] < u[1] < u[2] < u[3]
    # the same sample from a file that writes the value
    from mechverify.design.design import Design, load
    from mechverify.design.loader import parse

    doc = copy.deepcopy(load(LIFT).data.raw)
    doc["components"]["lift"]["transmission"][0]["mu"] = mus[2]
    written = {f"{r.component}.{r.check}": r.utilisation for r in Design(parse(doc, LIFT)).verify()}
    assert written["lift.motor_peak_torque"] == u[2]
    assert {k: v["u"] for k, v in result.samples[2]["checks"].items()} == written


def test_a_range_outside_the_nuts_is_warned_about():
    with pytest.warns(OutsideRangeWarning, match=r"outside the nut friction range of lead screw 'lift_screw', "
                                                 r"0\.09\.\.0\.25"):
        Study(LIFT, vary={MU: "uniform:0.05:0.3"}, samples=4)
    with pytest.warns(OutsideRangeWarning, match=r"mean ± 3 SD spans 0\.08\.\.0\.26"):
        Study(LIFT, vary={MU: "normal:0.17:0.03"}, samples=4)
    with warnings.catch_warnings():
        warnings.simplefilter("error", OutsideRangeWarning)
        Study(LIFT, vary={MU: "triangular:0.09:0.2:0.25"}, samples=4)
        Study(LIFT, vary={MU: "0.09:0.25:3"})


def test_without_a_design_the_old_error_stays():
    """TOML data without the built design (no nut to ask): the error says to write mu into the file."""
    from mechverify.design.design import load

    doc = load(LIFT).data.raw
    with pytest.raises(InputError, match=r"write the key into the file"):
        Parameter.of(doc, MU)
