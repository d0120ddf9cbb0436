"""Studies on executors: the local process pool, retried batches, a dying worker, a Dask LocalCluster.

The result of a study must not depend on what runs it: the JSON of every executor is compared
byte for byte with the serial one.
"""

from __future__ import annotations

import concurrent.futures as cf
import os
import time
from pathlib import Path

import pytest

from mechverify.studies import SchedulerError, Study, dask_executor
from mechverify.studies import execution as ex

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"
VARY = {"components.lift.mass": "uniform:10 kg:20 kg", "profiles.raise.acceleration": "normal:0.1 m/s^2:0.02 m/s^2"}


@pytest.fixture(scope="module")
def serial_json() -> str:
    return Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3).run("serial").to_json()


def test_default_process_pool_equals_serial(serial_json):
    res = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3).run(workers=2)
    assert res.to_json() == serial_json


class _FlakyPool(cf.ThreadPoolExecutor):
    """Fails the first ``fails`` submissions of the batch starting at sample 0 (a lost worker)."""

    def __init__(self, fails: int):
        super().__init__(max_workers=2)
        self.fails = fails

    def submit(self, fn, /, *args, **kwargs):  # type: ignore[override]
        first = args[2][0]["components.lift.mass"]
        if first == self.first and self.fails > 0:
            self.fails -= 1
            f: cf.Future = cf.Future()
            f.set_exception(RuntimeError("worker lost"))
            return f
        return super().submit(fn, *args, **kwargs)


def test_a_failed_batch_is_retried_once(serial_json):
    study = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3)
    pool = _FlakyPool(fails=1)
    pool.first = study.overrides(study.inputs()[0])["components.lift.mass"]
    with pool:
        assert study.run(pool).to_json() == serial_json


def test_a_batch_failing_twice_reports_its_samples_failed():
    study = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3)
    pool = _FlakyPool(fails=2)
    pool.first = study.overrides(study.inputs()[0])["components.lift.mass"]
    with pool:
        res = study.run(pool)
    assert [s["status"] for s in res.samples] == ["error"] * 3 + ["ok"] * 9
    assert "worker failed 2 times" in res.samples[0]["message"] and "worker lost" in res.samples[0]["message"]


def _die_once(doc, path, overrides):
    """A task whose worker process dies (os._exit) the first time: a real crash, not an exception."""
    marker = Path(doc["design"]["description"])
    if not marker.exists():
        marker.write_text("died")
        os._exit(13)
    return ex.run_batch(doc, path, overrides)


def test_a_worker_that_dies_is_replaced_and_its_batch_rerun(tmp_path, monkeypatch, serial_json):
    study = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3)
    study.doc["design"]["description"] = str(tmp_path / "died")
    monkeypatch.setattr(Study, "batch_fn", staticmethod(_die_once))
    res = study.run(workers=2)
    assert (tmp_path / "died").exists()
    assert all(s["status"] == "ok" for s in res.samples)
    ref = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3)
    ref.doc["design"]["description"] = study.doc["design"]["description"]
    assert res.samples == ref.run("serial").samples


def test_unreachable_scheduler_is_a_clear_error_within_the_timeout():
    t = time.perf_counter()
    with pytest.raises(SchedulerError, match=r"cannot reach the Dask scheduler at tcp://127.0.0.1:9 within 2 s"):
        with dask_executor("tcp://127.0.0.1:9", timeout=2):
            pass
    assert time.perf_counter() - t < 15


@pytest.mark.slow
def test_local_dask_cluster_equals_serial_byte_for_byte(serial_json):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with dask_executor(cluster.scheduler_address, timeout=20) as executor:
            res = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3).run(executor)
    assert res.to_json() == serial_json


def test_workers_sized_by_memory(monkeypatch):
    """With memory_per_worker, no more workers than the available memory holds (at least one)."""
    from mechverify.errors import InputError

    monkeypatch.setattr(ex, "available_memory", lambda: 5e9)
    cores = ex.default_workers()
    assert ex.default_workers("2 GB") == min(cores, 2)
    assert ex.default_workers("8 GB") == 1
    assert ex.default_workers("100 MB") == cores
    with pytest.raises(InputError, match="memory size"):
        ex.default_workers("2 kg")
