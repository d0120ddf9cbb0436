"""The parse and conversion caches in front of the registry (mechverify/pint_cache.py, issue 19).

Source of truth: pint itself. Every conversion through the cached registry must give exactly (bit for bit)
what a plain pint registry gives, including offset units, contexts, arrays and the errors.
"""

from __future__ import annotations

import numpy as np
import pint
import pytest

from mechverify import pint_cache
from mechverify.units import Q, ureg

PAIRS = [("N", "kN"), ("kN", "N"), ("N*m", "mN*m"), ("mm", "m"), ("m/s^2", "mm/s**2"), ("rpm", "rad/s"),
         ("MPa*m/s", "Pa*m/s"), ("lbf", "N"), ("kg*m**2", "g*cm**2"), ("deg", "rad"), ("m", "m"), ("h", "s"),
         ("N/mm", "lbf/inch"), ("Mpsi", "GPa"), ("rev", "deg")]


@pytest.fixture(scope="module")
def plain() -> pint.UnitRegistry:
    """A registry without the caches, set up as mechverify's (offset units converted to base units)."""
    r = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    r.define("mega_psi = 1e6 * psi = Mpsi")
    r.define("@alias turn = rev")
    return r


def test_installed_once() -> None:
    assert ureg._mechverify_fast
    convert = ureg.convert
    pint_cache.install(ureg)
    assert ureg.convert is convert


@pytest.mark.parametrize(("src", "dst"), PAIRS)
def test_scalar_and_array_conversions_are_bit_identical(plain: pint.UnitRegistry, src: str, dst: str) -> None:
    for value in (1.0, 0.1, 350.0, -2.5e-7, 7, 1e300):
        ours = Q(value, src).to(dst).magnitude
        ref = plain.Quantity(value, src).to(dst).magnitude
        assert type(ours) is type(ref) and (ours == ref), (value, ours, ref)
    arr = np.array([0.1, 1.0, 3.3, -8.0])
    ours_a = Q(arr.copy(), src).to(dst).magnitude
    ref_a = plain.Quantity(arr.copy(), src).to(dst).magnitude
    assert np.array_equal(ours_a, ref_a) and ours_a.dtype == ref_a.dtype
    q = Q(arr.copy(), src)
    q.ito(dst)  # in place (pint multiplies the array in place)
    assert np.array_equal(q.magnitude, ref_a)


@pytest.mark.parametrize(("src", "dst", "value"), [("degC", "K", 20.0), ("degC", "degF", 100.0), ("K", "degC", 0.0),
                                                   ("delta_degC", "K", 5.0), ("degF", "degC", 32.0)])
def test_offset_units_take_pints_path(plain: pint.UnitRegistry, src: str, dst: str, value: float) -> None:
    ours = Q(value, src).to(dst).magnitude
    ref = plain.Quantity(value, src).to(dst).magnitude
    assert ours == ref
    if src == "degC" and dst == "K":
        assert ours == pytest.approx(293.15)  # not the multiplicative 20 * 1


def test_dimension_errors_are_pints(plain: pint.UnitRegistry) -> None:
    with pytest.raises(pint.DimensionalityError):
        Q(1.0, "N").to("m")
    with pytest.raises(pint.DimensionalityError):  # cached pairs are never the failing ones
        Q(1.0, "N").to("m")
    assert Q(1.0, "N").to("kN").magnitude == 1e-3


def test_context_conversions_still_work(plain: pint.UnitRegistry) -> None:
    """The spectroscopy context converts a wavelength to a frequency; the cache must step aside."""
    with ureg.context("sp"):
        ours = Q(500.0, "nm").to("THz").magnitude
    with plain.context("sp"):
        ref = plain.Quantity(500.0, "nm").to("THz").magnitude
    assert ours == ref and ours == pytest.approx(599.584916)
    with pytest.raises(pint.DimensionalityError):
        Q(500.0, "nm").to("THz")


def test_parsed_strings_are_reused_and_define_clears_them() -> None:
    a = ureg.parse_units_as_container("N*m/s**2")
    assert ureg.parse_units_as_container("N*m/s**2") is a
    with pytest.raises(pint.UndefinedUnitError):
        ureg.parse_units_as_container("mechverify_test_unit")
    ureg.define("mechverify_test_unit = 3 * m")  # a failed parse is not cached; define clears the cache
    assert Q(2.0, "mechverify_test_unit").to("m").magnitude == 6.0
    assert ureg.parse_units_as_container("N*m/s**2") == a


def test_quantities_built_fast_are_pints(plain: pint.UnitRegistry) -> None:
    """A quantity made from a float and a units container has the attributes pint's constructor sets."""
    plain.formatter.default_format = "~P"
    plain.formatter.default_sort_func = None  # as mechverify's registry (units as written)
    units = Q(1.0, "N*m")._units
    for value in (2.5, 3, np.float64(0.25), np.array([1.0, 2.0])):
        q = ureg.Quantity(value, units)
        assert q.magnitude is value and q.units == ureg.Unit("N*m") and type(q) is ureg.Quantity
        assert f"{q:~P}" == f"{plain.Quantity(value, 'N*m'):~P}"
    q = ureg.Quantity(2.5, ureg.Unit("mm"))  # a parsed unit (Q(v, "mm"))
    assert q._units == Q(1.0, "mm")._units and q.to("m").magnitude == plain.Quantity(2.5, "mm").to("m").magnitude
    with pytest.raises(TypeError):  # pint's own checks still apply to anything else
        ureg.Quantity(True, units)
    assert ureg.Quantity([1, 2], units).magnitude.tolist() == [1, 2]  # a list becomes an array (pint's path)
    assert ureg.Quantity("3 mm").to("m").magnitude == plain.Quantity("3 mm").to("m").magnitude


@pytest.mark.parametrize("unit", ["N*m", "m/s**2", "kg*m**2", "MPa", "rad/s", "1/s", "N*m*s/rad", "dimensionless"])
def test_unit_texts_are_pints(plain: pint.UnitRegistry, unit: str) -> None:
    plain.formatter.default_format = "~P"
    plain.formatter.default_sort_func = None
    ours, ref = ureg.Unit(unit), plain.Unit(unit)
    for spec in ("", "~P", "~C", "~D", "P", "~L"):
        for _ in range(2):  # the second answer comes from the cache
            assert format(ours, spec) == format(ref, spec)
    assert str(ours) == str(ref)


@pytest.mark.parametrize(("src", "dst"), PAIRS)
def test_to_and_m_as_by_unit_and_container_are_pints(plain: pint.UnitRegistry, src: str, dst: str) -> None:
    """``to``/``m_as`` look the target up in a dict (issue 19): a string, a unit or a units container as target
    gives pint's magnitude bit for bit and pint's units."""
    for value in (1.0, 350.0, -2.5e-7, 7, np.array([0.1, 3.3])):
        ref = plain.Quantity(value, src).to(dst)
        for target in (dst, ureg.Unit(dst), ureg.Unit(dst)._units):
            q = Q(value, src).to(target)
            assert np.array_equal(q.magnitude, ref.magnitude) and type(q.magnitude) is type(ref.magnitude)
            assert q.units == ureg.Unit(dst) and type(q) is ureg.Quantity
            m = Q(value, src).m_as(target)
            assert np.array_equal(m, ref.magnitude) and type(m) is type(ref.magnitude)


def test_to_steps_aside_for_contexts_and_follows_new_preprocessors() -> None:
    with ureg.context("sp"):
        assert Q(500.0, "nm").to("THz").magnitude == pytest.approx(599.584916)
    assert Q(500.0, "nm").to("THz", "sp").magnitude == pytest.approx(599.584916)  # a context passed to to()
    assert Q(2.0, "m").to("mm").magnitude == 2000.0
    ureg.preprocessors.append(lambda s: s.replace("mechverify_milli_test", "mm"))
    try:  # a preprocessor added later is applied to targets parsed after it
        assert Q(2.0, "m").to("mechverify_milli_test").magnitude == 2000.0
        assert Q(2.0, "m").m_as("mechverify_milli_test") == 2000.0
    finally:
        ureg.preprocessors.pop()


def test_quantities_from_unit_strings_are_pints(plain: pint.UnitRegistry) -> None:
    """``Quantity(v, "N*m")`` takes the container pint's parse_units gives, remembered per string; a preprocessor
    added later applies to strings parsed after it."""
    for value in (2.5, 3, np.float64(0.25), np.array([1.0, 2.0])):
        for unit in ("N*m", "dimensionless", "", "m/s**2", "%"):
            q, ref = ureg.Quantity(value, unit), plain.Quantity(value, unit)
            assert q.magnitude is value and q._units == ref._units and type(q) is ureg.Quantity
    ureg.preprocessors.append(lambda s: s.replace("mechverify_newton_test", "N"))
    try:
        assert ureg.Quantity(2.0, "mechverify_newton_test").units == ureg.Unit("N")
    finally:
        ureg.preprocessors.pop()
