"""Batches of a study (issue 19): guided self-scheduling, and a study's result whatever the batches.

Oracle for the sizes: the rule as stated (Polychronopoulos & Kuck 1987, guided self-scheduling: each batch a
fraction of the remaining work per worker, bounded); for the result: the serial run of the same study.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mechverify.studies import Study
from mechverify.studies.study import batch_sizes

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


@pytest.mark.parametrize(("n", "workers"), [(400, 2), (1000, 2), (12, 2), (1, 1), (7, 8), (1000, 16), (30, 2),
                                            (53, 3)])
def test_sizes_cover_the_samples_and_shrink(n: int, workers: int) -> None:
    sizes = batch_sizes(n, workers)
    assert sum(sizes) == n and all(k >= 1 for k in sizes)
    assert sizes == sorted(sizes, reverse=True)  # large first, small at the end (the tail)
    assert max(sizes) <= 50


def test_sizes_by_hand() -> None:
    """400 samples on 2 workers: ceil(400/6) = 67 -> 50 (cap), ..., ceil(250/6) = 42, ceil(208/6) = 35, then
    down to 4 and the last single sample; 7 samples on 8 workers: one each (hand calculation of the rule)."""
    sizes = batch_sizes(400, 2)
    assert sizes[:6] == [50, 50, 50, 42, 35, 29]
    assert sizes[-2:] == [4, 1]
    assert batch_sizes(7, 8) == [1] * 7


def test_pool_with_guided_batches_equals_serial() -> None:
    vary = {"components.lift.mass": "normal:15 kg:1 kg", "parameters.lifted_load": "uniform:300 N:400 N"}
    serial = Study(LIFT, vary=vary, samples=30, seed=2).run("serial").to_json()
    assert Study(LIFT, vary=vary, samples=30, seed=2).run(workers=2).to_json() == serial


def _had_base(doc, path, overrides):
    """A batch that notes whether its worker found the base design already built (inherited from the parent)."""
    import json

    from mechverify.studies import execution

    had = json.dumps([doc, path], sort_keys=True, default=str) in execution._BASE
    return [{**r, "message": f"inherited={had}"} for r in execution.run_batch(doc, path, overrides)]


def test_forked_workers_inherit_the_base_design(monkeypatch) -> None:
    """The local pool forks after the parent built and verified the base design: no worker builds it again."""
    import multiprocessing

    from mechverify.studies import execution

    if multiprocessing.get_start_method(allow_none=False) != "fork" or not execution.fork_is_safe():
        pytest.skip("workers inherit the parent's memory only when forked (not once gmsh is loaded: spawned)")

    monkeypatch.setattr(execution, "_BASE", {})  # (nothing built by earlier tests in this process)
    monkeypatch.setattr(Study, "batch_fn", staticmethod(_had_base))
    res = Study(LIFT, vary={"parameters.lifted_load": "uniform:300 N:400 N"}, samples=8, seed=1).run(workers=2)
    assert {s["message"] for s in res.samples} == {"inherited=True"}
