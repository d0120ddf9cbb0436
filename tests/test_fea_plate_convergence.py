"""mechverify.fea.plate_convergence: observed order and Richardson extrapolation on manufactured sequences.

Every expected number is a hand calculation from the formulas (Roache, Verification and Validation in Computational
Science and Engineering, ch. 5): values f(h) = f0 + C h^p on h, h/r, h/r² give p = ln((a - b)/(b - c)) / ln r exactly
and f0 = c + (c - b) / (r^p - 1) exactly.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from mechverify.errors import InputError
from mechverify.fea.plate_convergence import MeshSequence


def _seq(f0: float, c: float, p: float, r: float = 1.5, n: int = 3) -> MeshSequence:
    return MeshSequence(tuple(f0 + c * (1.0 / r**k) ** p for k in range(n)), r)


@given(f0=st.floats(1.0, 1e3), c=st.floats(-0.5, 0.5), p=st.floats(0.6, 3.9))
def test_manufactured_sequence_recovers_order_and_limit(f0, c, p):
    assume(abs(c) > 1e-3)
    s = _seq(f0, c * f0, p)
    assert s.monotone and s.asymptotic
    assert s.observed_order == pytest.approx(p, rel=1e-6)
    assert s.extrapolated == pytest.approx(f0, rel=1e-9)
    assert s.error(0) == pytest.approx(abs(c), rel=1e-6)


def test_refinement_needed_from_the_observed_order():
    """f = 100 + 10 h^1 (h = 1, 1/1.5, 1/2.25): error of the design mesh 10 %; for 2 % the elements must be
    (10/2)^(1/1) = 5x smaller (an assumed order 2 would have said sqrt(5) = 2.24x: the old advice, review 3 #9b)."""
    s = _seq(100.0, 10.0, 1.0)
    assert s.error(0) == pytest.approx(0.10, rel=1e-9)
    assert s.refinement_needed(0.02) == pytest.approx(5.0, rel=1e-6)
    assert "observed order 1" in s.words("MPa")


def test_non_monotone_and_wild_orders_give_no_estimate():
    """The review's pair that moved away (26.90 -> 26.43) followed by a rise: not monotone -> no extrapolation;
    a nearly stalled then jumping sequence has an order outside 0.5-4 -> none either."""
    s = MeshSequence((26.90, 26.43, 27.10), 1.5)
    assert not s.monotone and not s.asymptotic and s.extrapolated is None and s.error(0) is None
    assert math.isnan(s.refinement_needed(0.05))
    assert "NOT in the asymptotic range (not monotone)" in s.words("MPa")
    wild = MeshSequence((10.0, 10.001, 11.0), 1.5)  # order ln(0.001/0.999)/ln 1.5 < 0
    assert wild.monotone and wild.observed_order is not None and wild.observed_order < 0.5
    assert not wild.asymptotic and wild.extrapolated is None


def test_two_meshes_use_the_assumed_order_and_converged_is_not_extrapolated():
    s = MeshSequence((279.21, 285.83), 1.5, 2.0)  # the clamped square's mode 1 (code results), order 2 assumed
    assert s.observed_order is None and s.asymptotic
    assert s.extrapolated == pytest.approx(285.83 + 6.62 / 1.25, rel=1e-9)  # hand: c + (c - b)/(1.5^2 - 1)
    flat = MeshSequence((5.0, 5.0, 5.0), 1.5)
    assert flat.converged and flat.extrapolated == 5.0 and flat.error(0) == 0.0


def test_bad_sequences_are_named():
    with pytest.raises(InputError, match="two or three meshes"):
        MeshSequence((1.0,), 1.5)
    with pytest.raises(InputError, match="ratio > 1"):
        MeshSequence((1.0, 2.0), 1.0)
