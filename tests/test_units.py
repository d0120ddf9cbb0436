"""Units: datasheet conversions against exact defining factors, and every error a user can meet.

Sources of the exact factors: kgf = 9.80665 N (standard gravity, 3rd CGPM 1901; NIST SP 811, B.8);
avoirdupois pound = 0.45359237 kg, ounce = 1/16 lb, inch = 0.0254 m (international yard and pound
agreement 1959; NIST SP 811, B.8); psi = lbf/in^2.
"""

import math

import numpy as np
import pytest

from mechverify import Q, UnitError, ureg
from mechverify.errors import InputError, MechverifyError
from mechverify.units import DIMENSIONS, as_quantity, from_si, require_positive, si_function, to_si

G0 = 9.80665
LB = 0.45359237
INCH = 0.0254


def test_kgf_cm_to_newton_metre():
    assert Q("4 kgf*cm").m_as("N*m") == pytest.approx(4 * G0 * 0.01, rel=1e-15)


def test_oz_in_to_millinewton_metre():
    assert Q(40, "ozf*in").m_as("mN*m") == pytest.approx(40 * LB / 16 * G0 * INCH * 1e3, rel=1e-12)


def test_lbf_ksi_mpsi():
    lbf = LB * G0
    assert Q("1 lbf").m_as("N") == pytest.approx(lbf, rel=1e-12)
    assert Q("1 ksi").m_as("MPa") == pytest.approx(1000 * lbf / INCH**2 / 1e6, rel=1e-12)
    assert Q("30 Mpsi").m_as("GPa") == pytest.approx(30e6 * lbf / INCH**2 / 1e9, rel=1e-12)


def test_rpm_g_cm2_n_mm():
    assert Q("60 rpm").m_as("rad/s") == pytest.approx(2 * math.pi, rel=1e-15)
    assert Q("1 g*cm**2").m_as("kg*m**2") == pytest.approx(1e-7, rel=1e-12)
    assert Q("1500 N*mm").m_as("N*m") == pytest.approx(1.5, rel=1e-15)


def test_q_forms_agree():
    assert Q("10 mm") == Q(10, "mm")
    assert Q(Q("3 N")) == Q(3, "N")


def test_one_registry():
    assert Q("1 m")._REGISTRY is ureg


def test_to_si_accepts_string_and_array():
    assert to_si("350 N", "force", "F") == 350.0
    np.testing.assert_allclose(to_si(Q(np.array([1.0, 2.0]), "mm"), "length", "x"), [1e-3, 2e-3])


@pytest.mark.parametrize(
    ("value", "dim", "message"),
    [
        (350, "length", "length: expected a length, got the bare number 350"),
        ("350 N", "length", "length: expected a length, got 350 N"),
        (Q(350, "N"), "length", "length: expected a length, got 350 N"),
        (Q(float("nan"), "mm"), "length", "expected a finite length"),
        (Q(float("inf"), "N"), "force", "expected a finite force"),
        ("12 furlongs per fortnight bananas", "velocity", "cannot read"),
        ("30", "angle", "give a unit"),
        (30.0, "angle", "give a unit"),
        ([1, 2], "length", "expected a length, got list"),
    ],
)
def test_unit_errors_name_parameter_and_expectation(value, dim, message):
    with pytest.raises(UnitError, match=message.split(":")[0]) as info:
        as_quantity(value, dim, "length")
    assert message.split(": ", 1)[-1] in str(info.value)
    assert isinstance(info.value, MechverifyError)


def test_dimensionless_accepts_bare_number_but_not_nan():
    assert to_si(0.15, "dimensionless", "mu") == 0.15
    with pytest.raises(UnitError, match="mu"):
        to_si(float("nan"), "dimensionless", "mu")


def test_si_function_converts_and_wraps():
    @si_function(returns="pressure", F="force", A="area")
    def stress(F, A):
        return F / A

    assert stress("2 kN", Q(40, "mm**2")).m_as("MPa") == pytest.approx(50.0)
    assert stress.si(2000.0, 40e-6) == pytest.approx(50e6)
    with pytest.raises(UnitError, match="A: expected an area, got 40 mm"):
        stress("2 kN", "40 mm")


def test_require_positive():
    assert require_positive(1.0, "d") == 1.0
    with pytest.raises(InputError, match="d: must be positive"):
        require_positive(0.0, "d")
    with pytest.raises(InputError, match="d: must be positive"):
        require_positive(-1.0, "d")
    assert require_positive(0.0, "d", allow_zero=True) == 0.0


def test_require_positive_shows_the_unit_with_dim():
    """A Python API user who passed a quantity sees the value in its SI unit, not a bare number marked (SI)."""
    from mechverify.components import columns, power_screw

    with pytest.raises(InputError, match=r"^d: must be positive, got -0\.002 m$"):
        require_positive(-0.002, "d", dim="length")
    with pytest.raises(InputError, match=r"^F: must be zero or positive, got -5 N$"):
        require_positive(-5.0, "F", allow_zero=True, dim="force")
    with pytest.raises(InputError, match=r"^d: must be positive, got -1\.0 \(SI\)$"):
        require_positive(-1.0, "d")  # no dimension known: the bare SI number
    with pytest.raises(InputError, match=r"^nut_length: must be positive, got -0\.01 m$"):
        power_screw.engaged_threads("-10 mm", "2 mm")
    with pytest.raises(InputError, match=r"^engaged_threads: must be positive, got -3$"):
        power_screw.flank_pressure("1 kN", "10 mm", "1 mm", -3)
    with pytest.raises(InputError, match=r"^A: must be positive, got -1e-06 m²$"):
        columns.radius_of_gyration("-1 mm^2", "1 mm^4")


def test_from_si_unit():
    assert from_si(2.0, "torque").m_as("N*mm") == pytest.approx(2000.0)


def test_si_function_fast_binding_equals_the_signature_binding():
    """The wrapper binds simple calls itself (issue 19: ``inspect.Signature.bind`` cost ~10 us a call): the SI
    function must receive exactly what ``sig.bind`` + ``apply_defaults`` + the conversion give, in every form of
    call, and a wrong call must raise the TypeError of the signature binding."""
    import inspect

    seen = []

    def raw(F, A="2 mm**2", *, k=1.0, L=None, tag="x"):
        seen.append((F, A, k, L, tag))
        return F / (A or 1.0) * k

    f = si_function(returns="pressure", F="force", A="area", L="length")(raw)
    sig = inspect.signature(raw)
    dims = {"F": "force", "A": "area", "L": "length"}

    def expected(*args, **kwargs):
        b = sig.bind(*args, **kwargs)
        b.apply_defaults()
        for p, d in dims.items():
            if b.arguments.get(p) is not None:
                b.arguments[p] = to_si(b.arguments[p], d, p)
        return (b.arguments["F"], b.arguments["A"], b.arguments["k"], b.arguments["L"], b.arguments["tag"])

    calls = [((Q(2.0, "kN"),), {}), (("2 kN", Q(4.0, "mm**2")), {}), ((Q(1.0, "N"),), {"A": "3 cm**2", "k": 2.0}),
             ((), {"F": "5 N", "A": Q(1.0, "m**2"), "L": "3 mm"}), ((Q(7.0, "lbf"), "1 inch**2"), {"tag": "y"}),
             ((Q(1.0, "N"), None), {})]
    for args, kwargs in calls:
        seen.clear()
        out = f(*args, **kwargs)
        assert seen == [expected(*args, **kwargs)], (args, kwargs)
        assert type(out.magnitude) is float
    for args, kwargs in [((), {}), ((1, 2, 3), {}), ((Q(1.0, "N"),), {"F": Q(1.0, "N")}),
                         ((Q(1.0, "N"),), {"nope": 1})]:
        with pytest.raises(TypeError):
            sig.bind(*args, **kwargs)
        with pytest.raises(TypeError):
            f(*args, **kwargs)
    with pytest.raises(UnitError, match="A: expected an area"):
        f("1 N", "1 mm")


def test_the_fast_unit_checks_still_reject_bad_magnitudes():
    """as_quantity/to_si remember units a quantity passed with; a later value in them is still bound-checked:
    NaN, infinite and out-of-range magnitudes raise as on the first call, and the SI value is the same float."""
    assert to_si(Q(350.0, "N"), "force") == 350.0 and to_si(Q(2.0, "kN"), "force") == 2000.0
    assert type(to_si(Q(2.0, "kN"), "force")) is float
    assert as_quantity(Q(3.0, "mm"), "length").m_as("m") == 0.003
    for bad in (float("nan"), float("inf"), -float("inf")):
        with pytest.raises(UnitError, match="F: expected a finite force"):
            to_si(Q(bad, "kN"), "force", "F")
        with pytest.raises(UnitError, match="F: expected a finite force"):
            as_quantity(Q(bad, "kN"), "force", "F")
    with pytest.raises(InputError, match="physically meaningful range"):
        to_si(Q(1e10, "kN"), "force", "F")
    with pytest.raises(UnitError, match="expected a length"):
        to_si(Q(1.0, "kN"), "length", "F")  # the same units, another dimension
    for value, unit in [(0.1, "mm"), (3.3, "rpm"), (7.25, "MPa*m/s"), (1e-7, "g*cm**2"), (12.0, "deg")]:
        dim = {"mm": "length", "rpm": "angular_velocity", "MPa*m/s": "pv", "g*cm**2": "inertia", "deg": "angle"}[unit]
        q = Q(value, unit)
        assert to_si(q, dim) == float(q.to(DIMENSIONS[dim][1]).magnitude)


def test_exceeds_compares_as_pint():
    """units.exceeds(a, b) == (a > b) as pint decides it: same units, other units (root units), offset units and
    arrays (pint's path), and a dimension error from pint."""
    import pint

    from mechverify.units import exceeds

    pairs = [(Q(540.0, "rpm"), Q(34000.0, "rpm")), (Q(540.0, "rpm"), Q(56.5, "rad/s")), (Q(1.0, "kN"), Q(1000.0, "N")),
             (Q(1000.0000000001, "N"), Q(1.0, "kN")), (Q(0.342, "kN"), Q(342.0, "N")), (Q(25.0, "degC"), Q(290.0, "K")),
             (Q(3.0, "mm"), Q(0.003, "m")), (Q(7, "N"), Q(6.5, "N"))]
    for a, b in pairs:
        assert exceeds(a, b) == (a > b) and exceeds(b, a) == (b > a), (a, b)
    with pytest.raises(pint.DimensionalityError):
        exceeds(Q(1.0, "N"), Q(1.0, "m"))


def test_si_to_equals_from_si_then_to():
    """units.si_to(v, dim, unit) is from_si(v, dim).to(unit) bit for bit (floats, arrays, offset units)."""
    from mechverify.units import si_to

    for v in (1.0, 0.1, 350.0, -2.5e-7, 1e300, 12.345678901234567):
        for dim, unit in (("pressure", "MPa"), ("angular_velocity", "rpm"), ("time", "hour"), ("length", "m"),
                          ("torque", "mN*m"), ("temperature", "degC"), ("inertia", "g*cm**2")):
            a, b = si_to(v, dim, unit), from_si(v, dim).to(unit)
            assert a.magnitude == b.magnitude and type(a.magnitude) is type(b.magnitude) and a.units == b.units
    arr = np.array([1.0, 2.0])
    assert np.array_equal(si_to(arr, "pressure", "MPa").magnitude, from_si(arr, "pressure").to("MPa").magnitude)


def test_fmt_positional_text_is_numpys():
    """fmt's positional numbers come from numpy's formatter without its argument checks: the same text."""
    import random

    from mechverify import units

    rng = random.Random(4)
    values = [10 ** rng.uniform(-3, 7) * rng.choice((1, -1)) for _ in range(3000)] + [0.1, 2526.0, 9999.95, 1e-3]
    for v in values:
        for d in (2, 4, 6):
            assert units._positional(v, d) == np.format_float_positional(v, precision=d, unique=False,
                                                                         fractional=False, trim="-")


def test_number_and_unit_text_parse_as_pint_does():
    """The fast path of units._parse_cached ("<number> <unit>", a study's drawn values) gives pint's own parse: the same
    magnitude, of the same type (pint divides by a unit: "1 mm/s" is 1.0), and the same unit; offset units and
    anything else go to pint (oracle: pint's ureg.Quantity(text), issue 19)."""
    from mechverify.units import _parse_cached, ureg

    texts = ["14.751431137084994 kg", "320.7938649155673 N", "0.08929600587547441 m/s^2", "15 kg", "-5 N", "1e3 N",
             "1.5e-3 m", ".5 mm", "5. mm", "2 m/s**2", "3 N*m", "3 N * m", "10 kgf*cm", "66 ozf*in", "540 rpm",
             "9 Hz", "2 kg*m^2", "7850 kg/m^3", "200 GPa", "1 mm/s", "12 mm / s", "0.3 N/mm", "4 µm", "20 degC",
             "5 delta_degC", "100 kN/m", "3 m^2", "1 inch", "2 lbf", "+4 mm", "1E-3 m", "2 N/mm**2", "1 rad/s",
             "10 deg", "1 m/s/s", "2 kg m", "5 N m", "1 kWh", "60 1/min", "1 N*m/rad", "3.0 s", "2 N*m/A"]
    for text in texts:
        q = ureg.Quantity(text)
        mag, units = _parse_cached.__wrapped__(text)
        assert type(mag) is type(q.magnitude) and mag == q.magnitude and units == q.units, text
