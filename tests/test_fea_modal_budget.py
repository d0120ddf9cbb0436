"""``modal(method="auto")`` under a memory budget per unknown (issue 23: "memory per DOF stays <= 5 kB"): the
factorisation only when its predicted peak stays within the budget, else LOBPCG; the results say which ran and why.

Sources: the two eigensolvers solve the same discrete eigenproblem, so their frequencies must agree to the
eigensolvers' tolerance (issue 23 asks 1e-6; the shift-invert path is checked against CalculiX *FREQUENCY in
tests/validation/test_calculix_modal.py and Blevins' cantilever in tests/validation/test_blevins_cantilever_modes.py).
The budget's figures (5 kB per unknown, the 100k-unknown floor, the interpreter's 82 MB, 5.3 kB per unknown beside
the factor) are the issue's target and this project's own measurements (benchmarks/results/fea_modal.json,
docs/performance.md), not published values. No timed tests.
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.errors import InputError
from mechverify.fea import mesh, modal, solid
from mechverify.fea.factor import cholmod_available
from mechverify.fea.loads import Fixed
from mechverify.fea.regions import Plane


def _clamped(div=(12, 3, 2)):
    return solid.SolidModel(mesh.box(("120 mm", "30 mm", "20 mm"), div), "Structural Steel",
                            supports=(Fixed(Plane(x="0 mm")),))


DIRECT = "cholmod" if cholmod_available() else "superlu"


def test_small_model_factorises_within_the_floor_and_lobpcg_below_a_forced_budget():
    """The same small clamped block: the default budget (5 kB per unknown, counted for at least 100k unknowns:
    0.5 GB) takes the factorisation; a budget forced to 10 bytes per unknown (1 MB in all) takes LOBPCG; the
    frequencies agree to 1e-6 and each result's note says which eigensolver ran and why."""
    model = _clamped()
    fast = modal.modal(model, 6)
    lean = modal.modal(model, 6, memory_per_dof=10)
    assert fast.method == DIRECT and lean.method == "lobpcg"
    np.testing.assert_allclose(lean.frequencies.m, fast.frequencies.m, rtol=1e-6)
    assert fast.solver_note.startswith(modal._NAMES[DIRECT] + ": the factorisation's predicted peak")
    assert "within the budget of 0.5 GB (5 kB per unknown, counted for at least 100,000 unknowns)" in fast.solver_note
    assert lean.solver_note.startswith(f"LOBPCG: the {modal._NAMES[DIRECT]} factorisation would need")
    assert "above the budget of 0.001 GB (0.01 kB per unknown" in lean.solver_note
    if cholmod_available():  # the decision is the symbolic count's, and says so
        assert "counted by CHOLMOD's symbolic analysis" in fast.solver_note
    # a budget in kB as text, and None (no budget: the factorisation wherever it fits)
    assert modal.modal(model, 6, memory_per_dof="0.01 kB").method == "lobpcg"
    free = modal.modal(model, 6, memory_per_dof=None)
    assert free.method == DIRECT and "no memory budget (memory_per_dof=None)" in free.solver_note
    np.testing.assert_allclose(free.frequencies.m, fast.frequencies.m, rtol=1e-12)


def test_the_choice_flips_where_the_predicted_peak_crosses_the_budget():
    """With CHOLMOD's factor counted as ``fb`` bytes, the factorisation is taken exactly while
    82 MB + fb + 5.3 kB x n <= budget: a budget a hair above the predicted peak factorises, a hair below does not
    (hand calculation from factorisation_peak)."""
    n, fb = 150_000, 0.3e9
    peak = modal.factorisation_peak(n, 10, fb)
    assert peak == pytest.approx(82e6 + 0.3e9 + 5300 * 150_000)
    above, below = peak / n * 1.001, peak / n * 0.999
    assert modal.auto_choice(n, 3, 10, memory=1e12, memory_per_dof=above, factor_bytes=fb, direct="cholmod")[0] \
        == "cholmod"
    method, note = modal.auto_choice(n, 3, 10, memory=1e12, memory_per_dof=below, factor_bytes=fb, direct="cholmod")
    assert method == "lobpcg" and f"{peak / n / 1e3:.3g} kB per unknown" in note
    # the outer limit still holds with no budget at all: a factor that does not fit in memory is not taken
    method, note = modal.auto_choice(n, 3, 10, memory=fb, memory_per_dof=None, factor_bytes=fb, direct="cholmod")
    assert method == "lobpcg" and "more than the" in note and "available" in note


def test_budget_floor_and_the_measured_lug():
    """The budget is 5 kB per unknown counted for at least 100k unknowns; on the benchmark's lug (CHOLMOD's symbolic
    count with METIS: 203 MB of factor at 46 356 unknowns, 1.74 GB at 199 188) the default budget takes LOBPCG at
    both sizes, and the predicted peaks bracket the measured 529 MB and 2.75 GB from above by less than 5 %
    (benchmarks/results/fea_modal.json, the previous rule's ``auto`` runs: this project's measurement)."""
    assert modal.memory_budget(1_000) == modal.memory_budget(100_000) == pytest.approx(0.5e9)
    assert modal.memory_budget(200_000) == pytest.approx(1.0e9)
    assert modal.memory_budget(200_000, 8000.0) == pytest.approx(1.6e9)
    assert modal.memory_budget(200_000, None) == float("inf")
    for n, fb, measured in ((46_356, 202_865_610.0, 529_162_240), (199_188, 1_741_187_610.0, 2_751_275_008)):
        peak = modal.factorisation_peak(n, 10, fb)
        assert measured <= peak <= 1.05 * measured
        assert modal.auto_choice(n, 3, 10, memory=1e12, factor_bytes=fb, direct="cholmod")[0] == "lobpcg"
        assert modal.auto_choice(n, 3, 10, memory=1e12, memory_per_dof=None, factor_bytes=fb,
                                 direct="cholmod")[0] == "cholmod"


def test_superlu_without_cholmod_follows_the_same_budget(monkeypatch):
    """Without CHOLMOD the factor is estimated (SuperLU's fill, 4 x CHOLMOD's): small models still factorise within
    the floor, a forced budget takes LOBPCG; the frequencies agree to 1e-6."""
    monkeypatch.setattr(modal, "cholmod_available", lambda: False)
    model = _clamped()
    slu = modal.modal(model, 6)
    assert slu.method == "superlu" and "estimated" in slu.solver_note
    lob = modal.modal(model, 6, memory_per_dof=10)
    assert lob.method == "lobpcg" and "SuperLU factorisation would need" in lob.solver_note
    np.testing.assert_allclose(lob.frequencies.m, slu.frequencies.m, rtol=1e-6)
    # the estimate's cut-off on the default budget lies between 10k and 20k unknowns
    assert modal.choose_method(10_000) == "superlu" and modal.choose_method(20_000) == "lobpcg"


def test_shift_and_many_modes_still_factorise_and_say_why():
    """LOBPCG finds the lowest modes only, with a block under a fifth of the unknowns: a shift, or more modes than
    the block allows, take the factorisation whatever the budget, and the note says so."""
    model = _clamped((4, 1, 1))
    shifted = modal.modal(model, 2, shift="100 Hz", memory_per_dof=10)
    assert shifted.method == "superlu" and "shift" in shifted.solver_note
    many = modal.modal(model, 30, memory_per_dof=10)  # 216 free DOFs: a block of 45 + 6 columns is too many
    assert many.method == DIRECT and "too many for LOBPCG's block" in many.solver_note
    asked = modal.modal(model, 2, method="superlu")
    assert asked.solver_note == "SuperLU: method='superlu' asked"


@pytest.mark.parametrize("bad", [0, -5000, True, "5 m", "lots", float("nan"), float("inf")])
def test_bad_memory_per_dof_is_named(bad):
    with pytest.raises(InputError, match="memory_per_dof"):
        modal.modal(_clamped((4, 1, 1)), 2, memory_per_dof=bad)


def test_symbolic_analysis_skipped_when_the_factorisation_path_alone_is_over_budget(monkeypatch):
    """82 MB + 5.3 kB per unknown is over any budget below that, whatever the factor: the symbolic analysis is then
    not run (its memory would count against LOBPCG's peak); within the budget it is (CHOLMOD installed)."""
    if not cholmod_available():
        pytest.skip("CHOLMOD (scikit-sparse) not installed: no symbolic analysis")
    calls = []
    real = modal.symbolic_cost
    monkeypatch.setattr(modal, "symbolic_cost", lambda *a, **k: calls.append(1) or real(*a, **k))
    model = _clamped()
    assert modal.modal(model, 6, memory_per_dof=10).method == "lobpcg" and calls == []
    res = modal.modal(model, 6)
    assert res.method == "cholmod" and calls == [1] and "symbolic analysis" in res.solver_note
    # the documented consequence at the default budget: from 100k unknowns up no factor can be within it
    assert modal.factorisation_peak(100_000, 10, 0.0) > modal.memory_budget(100_000)
