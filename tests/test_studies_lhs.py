"""The optimised Latin hypercube of a Monte Carlo study (mechverify/studies/lhs.py, issue 19).

Oracle: SciPy's own implementation, ``scipy.stats.qmc.LatinHypercube(d, seed=s, optimization="random-cd")``
(Jin, Chen & Sudjianto 2005, the centred-discrepancy swap search), which :func:`optimised_lhs` must reproduce bit
for bit: a study's draws, and so its JSON, are the same as before the faster code. Not a printed value: the
reference is SciPy's result for the same seed.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import qmc

from mechverify.studies import lhs
from mechverify.studies.lhs import optimised_lhs


@pytest.mark.parametrize(("d", "n", "seed"), [(2, 5, 0), (3, 37, 1), (3, 120, 2), (5, 60, 3), (8, 30, 5),
                                               (12, 25, 7), (2, 2, 4), (1, 9, 1)])
def test_equals_scipy_random_cd_bit_for_bit(d: int, n: int, seed: int) -> None:
    """Same array, byte for byte, as SciPy's random-cd for the same (d, n, seed)."""
    expected = qmc.LatinHypercube(d, seed=seed, optimization="random-cd").random(n)
    got = optimised_lhs(d, n, seed)
    assert got.shape == (n, d)
    assert got.tobytes() == expected.tobytes()


def test_optimisation_ran_and_lowered_the_discrepancy() -> None:
    """The swaps happened (the result differs from the plain hypercube of the same seed), each column is still a
    Latin hypercube (one point per 1/n stratum), and the centred discrepancy fell."""
    d, n, seed = 3, 80, 11
    plain = qmc.LatinHypercube(d, seed=seed).random(n)
    got = optimised_lhs(d, n, seed)
    assert got.tobytes() != plain.tobytes()
    for k in range(d):
        assert sorted(np.floor(got[:, k] * n).astype(int)) == list(range(n))
    assert qmc.discrepancy(got) < qmc.discrepancy(plain)


def test_study_draws_unchanged(tmp_path) -> None:
    """A Monte Carlo study's unit samples are SciPy's optimised LHS (what the study drew before this module)."""
    from mechverify.studies import Study

    doc = {"design": {"name": "bar"}, "parameters": {"F": "10 N", "A": "5 mm^2"},
           "components": {"s": {"type": "link", "length": "100 mm", "section": "circle", "diameter": "A / 1 mm",
                                "material": "Structural Steel", "end": "pinned-pinned"}},
           "load_cases": {"c": {"s": {"axial_force": "F"}}}}
    study = Study(doc, vary={"parameters.F": "uniform:5 N:15 N", "parameters.A": "normal:5 mm^2:0.2 mm^2"},
                  samples=40, seed=3)
    expected = qmc.LatinHypercube(2, seed=3, optimization="random-cd").random(40)
    assert study._unit_samples().tobytes() == expected.tobytes()


def test_settings_are_scipys() -> None:
    """The stopping rules copied from SciPy's engine (``n_nochange``, ``n_iters``)."""
    engine = qmc.LatinHypercube(2, seed=0, optimization="random-cd")
    kw = engine.optimization_method.keywords
    assert (kw["n_nochange"], kw["n_iters"]) == (lhs.N_NOCHANGE, lhs.N_ITERS)
