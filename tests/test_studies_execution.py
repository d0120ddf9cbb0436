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

from mechverify.cli import main
from mechverify.studies import SchedulerError, Study, dask_executor
from mechverify.studies import execution as ex
from tests.builders import LIFT

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


# ------------------------------------------------ review (round 2 session 3) findings 3, 4: a scheduler that is not one
class _FakePeer:
    """A TCP server on 127.0.0.1 that is not a Dask scheduler: it accepts and sends ``reply`` (or nothing)."""

    def __init__(self, reply: bytes):
        import socket
        import threading

        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.reply, self.conns = reply, []
        self.address = f"tcp://127.0.0.1:{self.sock.getsockname()[1]}"
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            self.conns.append(c)
            if self.reply:
                c.sendall(self.reply)

    def close(self) -> None:
        for c in self.conns:
            c.close()
        self.sock.close()


@pytest.mark.parametrize("reply", [b"", b"HTTP/1.0 400 Bad Request\r\n\r\n" + b"\xff" * 64],
                         ids=["silent", "garbage"])
def test_a_peer_that_is_not_a_dask_scheduler_is_a_named_error_within_the_timeout(reply, capsys):
    """Findings 3 and 4: a silent peer hung past --timeout; a peer sending bytes that are not Dask frames gave
    'internal error: MemoryError: Unable to allocate 3.07 EiB', exit 3. Now exit 2 within the deadline."""
    pytest.importorskip("distributed")
    import time

    peer = _FakePeer(reply)
    try:
        import distributed  # noqa: F401  (imported before the clock starts: its import takes seconds here)

        t = time.perf_counter()
        rc = main(["study", str(LIFT), "--vary", "parameters.lifted_load=normal:300 N:10 N", "--samples", "2",
                   "--scheduler", peer.address, "--timeout", "2", "--no-progress"])
        took = time.perf_counter() - t
    finally:
        peer.close()
    err = capsys.readouterr().err
    assert rc == 2 and f"cannot reach the Dask scheduler at {peer.address} within 2 s" in err
    assert "internal error" not in err
    assert took < 2 + 3  # the deadline plus loading the design


def test_a_half_made_client_is_closed_without_a_traceback():
    """Finding 4: 'nonsense' (no port) left a half-made Client whose __del__ waited 6 s at exit and printed
    'Exception ignored in: <function Client.__del__> ... TimeoutError'. Run in a fresh interpreter (the
    traceback comes at its exit)."""
    pytest.importorskip("distributed")
    import subprocess
    import sys
    import time

    code = ("import time\nfrom mechverify.studies import SchedulerError, dask_executor\n"
            "try:\n    with dask_executor('nonsense', timeout=3):\n        pass\n"
            "except SchedulerError as e:\n    print('named:', e)\n"
            "import atexit\nt = time.perf_counter()\natexit.register(lambda: print('exit', time.perf_counter() - t))\n")
    t = time.perf_counter()
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    took = time.perf_counter() - t
    assert "named: cannot reach the Dask scheduler at nonsense" in p.stdout, p.stdout + p.stderr
    assert "Exception ignored" not in p.stderr and "Traceback" not in p.stderr, p.stderr
    assert took < 15  # (the old half-made client alone waited 6 s at exit)


# ------------------------------------------------ review findings 28, 29: where a study runs
MC = ["--vary", "parameters.lifted_load=normal:300 N:10 N"]


def test_memory_per_worker_says_what_it_chose(capsys, monkeypatch):
    """Finding 28: '--memory-per-worker 100 GB' on a smaller box ran silently; now a note with the workers chosen
    and a warning that one sample may not fit."""
    from mechverify.studies import execution

    monkeypatch.setattr(execution, "available_memory", lambda: 16e9)
    monkeypatch.setattr(execution, "process_pool", lambda workers=None, task=None: execution.SerialExecutor())
    rc = main(["study", str(LIFT), *MC, "--samples", "2", "--memory-per-worker", "100 GB", "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 0 and "note: 1 local worker(s) for 100 GB per sample (16 GB of memory available)" in err
    assert "one sample may not fit" in err


@pytest.mark.parametrize("local", [["--serial"], ["--workers", "1"]])
def test_an_explicit_local_run_beats_dask_scheduler_address(local, capsys, monkeypatch):
    """Finding 29: with DASK_SCHEDULER_ADDRESS set, --serial was refused ('--serial and --scheduler: choose one')
    and --workers went to the cluster. The variable is a default; an explicit local choice wins."""
    from mechverify.studies import execution

    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", "tcp://127.0.0.1:9")
    monkeypatch.setattr(execution, "process_pool", lambda workers=None, task=None: execution.SerialExecutor())
    rc = main(["study", str(LIFT), *MC, "--samples", "2", "--no-progress", *local])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    assert "Monte Carlo study" in captured.out and "Dask" not in captured.err


# ------------------------------------------------ task fix19 (audit of issue 19): a batch that kills its worker every time
def _die_on_one_batch(doc, path, overrides):
    """A task whose worker process dies (os._exit) every time it runs one given batch (the one whose first lift mass
    is the design's description): a sample that always crashes its worker, not an exception."""
    if overrides[0]["components.lift.mass"] == doc["design"]["description"]:
        with open(os.environ["MECHVERIFY_TEST_RUNS"], "a") as fh:
            fh.write("run\n")
        os._exit(13)
    return ex.run_batch(doc, path, overrides)


@pytest.mark.parametrize("batch", [0, 2], ids=["first-batch", "third-batch"])
def test_a_batch_that_always_kills_its_worker_fails_alone(batch, monkeypatch, serial_json, tmp_path):
    """Issue 19, bad input: 'a worker that dies mid-study: its batch retried once, then its samples reported as
    failed'. A dead process breaks the local pool, and the pool fails every batch it holds (the running ones and the
    queued ones) with the same BrokenProcessPool: before, each was charged a run, so a batch that kills its worker
    every time (here the first of four, with 2 workers) took the whole study down: 12 of 12 samples 'failed'. Only
    its 3 samples may fail; the other 9 equal the serial study's."""
    study = Study(LIFT, vary=VARY, samples=12, seed=7, batch_size=3)
    study.doc["design"]["description"] = study.overrides(study.inputs()[3 * batch])["components.lift.mass"]
    monkeypatch.setattr(Study, "batch_fn", staticmethod(_die_on_one_batch))
    monkeypatch.setenv("MECHVERIFY_TEST_RUNS", str(tmp_path / "runs"))
    res = study.run(workers=2)
    assert (tmp_path / "runs").read_text() == "run\n" * 2  # retried once, then failed
    bad = set(range(3 * batch, 3 * batch + 3))
    assert [s["status"] for s in res.samples] == ["error" if i in bad else "ok" for i in range(12)]
    for i in bad:
        assert "worker failed 2 times on this batch" in res.samples[i]["message"]
        assert "BrokenProcessPool" in res.samples[i]["message"]
    import json

    ref = json.loads(serial_json)["samples"]
    assert [s for s in res.samples if s["index"] not in bad] == [s for s in ref if s["index"] not in bad]


def test_a_peer_answering_garbage_is_called_not_a_scheduler_not_a_memory_error(capsys):
    """Task fix19 (audit of issue 19's unreachable scheduler): an HTTP server answering on the scheduler's port (the
    sandbox's proxy at 10.255.255.1:8786 does) was reported as 'cannot reach ... (MemoryError: Unable to allocate
    3.07 EiB for an array ...)': Dask read the reply's first bytes as a frame length. The reason now says what
    happened: something answered that is not a Dask scheduler."""
    pytest.importorskip("distributed")
    peer = _FakePeer(b"HTTP/1.1 400 Bad Request\r\nconnection: close\r\ncontent-length: 0\r\n\r\n")
    try:
        rc = main(["study", str(LIFT), "--vary", "parameters.lifted_load=normal:300 N:10 N", "--samples", "2",
                   "--scheduler", peer.address, "--timeout", "3", "--no-progress"])
    finally:
        peer.close()
    err = capsys.readouterr().err
    assert rc == 2 and f"cannot reach the Dask scheduler at {peer.address} within 3 s" in err
    assert "MemoryError" not in err and "EiB" not in err, err
    assert "something answered there that is not a Dask scheduler" in err, err


@pytest.mark.parametrize("size", ["2", "2 %", "0.5"])
def test_a_memory_size_without_a_unit_is_refused(size, capsys):
    """Review 4 finding 10: '--memory-per-worker 2' was read as 2 bits (pint's information units are dimensionless,
    so a bare number converts): 'note: 2 local worker(s) for 2.5e-10 GB per sample'. A size needs a unit of
    information ('2 GB'), as '2 kg' is refused."""
    from mechverify.errors import InputError

    with pytest.raises(InputError, match="memory size"):
        ex.default_workers(size)
    rc = main(["study", str(LIFT), *MC, "--samples", "2", "--memory-per-worker", size, "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 2 and "memory size such as '2 GB'" in err and "GB per sample" not in err, err
    assert ex.default_workers("512 MiB") >= 1 and ex.default_workers("2 kbit") >= 1


SOLID = {
    "design": {"name": "solid cantilever"},
    "parameters": {"P": "100 N"},
    "components": {"bar": {"type": "solid_fea", "box": "200, 10, 10", "mesh_size": "5 mm",
                           "material": "Structural Steel", "supports": [{"named": "xmin"}],
                           "deflection_limit": "2 mm"}},
    "load_cases": {"tip": {"bar": {"forces": [{"named": "xmax", "force": "0, 0, -P"}]}}},
}


def test_an_fe_study_sizes_its_local_workers_by_a_measured_sample(monkeypatch):
    """Issue 19: "FEA studies size workers by memory". Without --memory-per-worker, a study of a design with FE
    components measures one verify of its base design in a fresh process (the interpreter's resident memory
    before, the peak after) and gives the pool no more workers than the available memory holds for
    interpreter + twice the FE part (a worker keeps its last model's factorisation while building the next).
    Oracles: a design without FE components is not measured; the measured figure lies between the bare
    interpreter with numpy/scipy (> 50 MB) and 2 GB for this 3k-DOF bar; a sample said to need more than the
    machine has leaves one worker (it had one per core before)."""
    if ex.default_workers() < 2:
        pytest.skip("one core: one worker whatever the memory")
    assert ex.fe_memory_per_worker({"components": {"s": {"type": "compression_spring"}}}, None) is None
    import numpy as np

    parent = np.ones(100_000_000)  # an 800 MB parent (a long pytest run): a fresh worker does not inherit its size
    per = ex.measured_sample_memory(SOLID, None)
    assert per is not None and 50e6 < per < 600e6 and parent[-1] == 1.0
    del parent
    seen = []
    monkeypatch.setattr(ex, "measured_sample_memory", lambda doc, path: 1e18)
    real = ex.run_batches
    monkeypatch.setattr(ex, "run_batches", lambda *a, **k: seen.append(k["workers"]) or real(*a, **k))
    Study(SOLID, vary={"parameters.P": "100 N:200 N:2"}).run(check_inputs=False)
    assert seen == [1]
    seen.clear()
    Study(SOLID, vary={"parameters.P": "100 N:200 N:2"}).run(check_inputs=False, memory_per_worker="1 MB")
    assert seen == [ex.default_workers()]  # a size the user gives is not measured again
