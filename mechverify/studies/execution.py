"""Running samples: one design evaluation, batches of them, and the executors that run the batches.

A task is ``run_batch(doc, path, overrides_list)``: the design file's data (a plain dict) and one
dict of key-path overrides per sample; it returns one plain record per sample (JSON-ready). No live
objects cross a process boundary, so any :class:`concurrent.futures.Executor` works: the default
local process pool, a thread pool, or a Dask cluster through ``distributed.Client(...).get_executor()``.
A sample whose design is invalid or whose checks raise is recorded with its message; a batch whose
worker dies is retried once, then its samples are reported failed.
"""

from __future__ import annotations

import concurrent.futures as cf
import copy
import json
import math
import multiprocessing
import multiprocessing.context
import os
import shutil
import sys
import tempfile
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from mechverify.errors import MechverifyError, install_hint

_LIMITED = False


def one_blas_thread() -> None:
    """Limit BLAS/OpenMP to one thread in this process (several workers share the cores)."""
    global _LIMITED
    if _LIMITED:
        return
    _LIMITED = True
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # the env vars still reach BLAS libraries loaded later
        return
    threadpool_limits(1)


def _finite(x: float) -> float | None:
    return x if math.isfinite(x) else None


_BASE: dict[str, Any] = {}  # per process: the last few base designs built, by their TOML data
_BASE_LOCK = threading.Lock()  # a Dask worker may run several tasks in threads


def _base_design(doc: Mapping[str, Any], path: str | None) -> Any:
    """The design of ``doc`` (no overrides), built once per process and reused by every batch of a study."""
    from mechverify.design import adapters  # noqa: F401  (registers the component types)
    from mechverify.design.design import Design
    from mechverify.design.loader import parse

    key = json.dumps([doc, path], sort_keys=True, default=str)
    with _BASE_LOCK:
        design = _BASE.get(key)
    if design is None:
        design = Design(parse(copy.deepcopy(dict(doc)), Path(path) if path else None))
        try:  # its results: a sample reuses those of every component whose inputs it leaves unchanged
            design.verify()
        except Exception:  # (the samples report their own errors)
            pass
        with _BASE_LOCK:
            while len(_BASE) >= 4:
                _BASE.pop(next(iter(_BASE)))
            _BASE[key] = design
    return design


#: Component types whose build or verify runs native threads (gmsh meshing, BLAS, SuperLU/CHOLMOD): a process forked
#: after one of them ran in the parent may hang (task 19f), so their base designs are built in each worker instead.
NATIVE_THREAD_TYPES = frozenset({"solid_fea", "plate_fea", "frame"})


def build_base_before_fork(doc: Mapping[str, Any], path: str | None) -> None:
    """Build and verify the base design in this process before a local process pool forks it, so that every worker
    inherits it (one build instead of one per worker: ~50 ms of CPU each for the lift). Nothing with another start
    method (the workers would not inherit it) or for a design with FE components (:data:`NATIVE_THREAD_TYPES`); a
    design that fails is left to the samples to report."""
    import multiprocessing

    if fe_component_types(doc) or doc.get("templates"):  # (a template may give the type)
        return
    if multiprocessing.get_start_method(allow_none=False) != "fork" or not fork_is_safe():  # (process_pool spawns)
        return
    try:
        _base_design(doc, path)
    except Exception:  # (each sample reports it)
        pass


def evaluate(doc: Mapping[str, Any], path: str | None, overrides: Mapping[str, Any],
             design: Any = None) -> dict[str, Any]:
    """Verify the design with ``overrides`` applied (:meth:`Design.with_overrides`); a plain record that
    never raises for a bad sample. ``doc`` is the design's merged TOML data (no ``design.include``); ``design``
    its base design when the caller has it (:func:`run_batch`: looked up once per batch, not per sample)."""
    try:
        design = _base_design(doc, path) if design is None else design
        rs = (design.with_overrides(dict(overrides)) if overrides else design).verify()
    except MechverifyError as exc:
        return {"status": "error", "message": str(exc), "checks": {}}
    except Exception as exc:  # (a study never stops for one sample)
        return {"status": "error", "message": f"{type(exc).__name__}: {exc}", "checks": {}}
    checks: dict[str, dict[str, Any]] = {}
    for r in rs:
        u = r.utilisation
        checks[f"{r.component}.{r.check}"] = {"u": _finite(u), "required_sf": r.required_sf,
                                              "fu": _finite(u * r.required_sf), "verdict": r.verdict.value}
    return {"status": "ok", "message": "", "checks": checks}


def run_batch(doc: Mapping[str, Any], path: str | None, overrides: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The task sent to a worker: evaluate each sample of the batch."""
    one_blas_thread()
    try:  # once per batch: the lookup key is the design's data as JSON (0.15 ms for the lift)
        design = _base_design(doc, path)
    except Exception:  # (each sample reports it)
        design = None
    return [evaluate(doc, path, ov, design) for ov in overrides]


def _proc_bytes(file: str, key: str) -> float | None:
    """The ``key:`` line of a Linux /proc file (``... kB``) in bytes, or None (not Linux, no such line)."""
    try:
        with open(file) as fh:
            for line in fh:
                if line.startswith(key + ":"):
                    return float(line.split()[1]) * 1024
    except OSError:
        pass
    return None


def available_memory() -> float:
    """Memory available to new processes [bytes]: :func:`mechverify.fea.study.available_memory` (MemAvailable of
    /proc/meminfo, else the physical memory), the figure the FE models' own memory checks use."""
    from mechverify.fea.study import available_memory as fea_available

    return fea_available()


def default_workers(memory_per_worker: Any = None) -> int:
    """One worker per core; with ``memory_per_worker`` (e.g. ``"2 GB"``, an FEA sample's peak) no more
    than the available memory holds."""
    try:
        n = max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        n = max(1, os.cpu_count() or 1)
    if memory_per_worker is not None:
        from mechverify.errors import InputError
        from mechverify.units import Q, ureg

        try:
            q = Q(memory_per_worker)
            if q.to_root_units().units != ureg.bit:  # (pint's information units are dimensionless: '2' was 2 bits)
                raise ValueError("no unit of information")
            per = float(q.to("byte").magnitude)
        except MechverifyError as exc:
            raise InputError(f"memory_per_worker: {exc}") from None
        except Exception:  # (pint: not a memory size)
            raise InputError(f"memory_per_worker: expected a memory size such as '2 GB', got "
                             f"{memory_per_worker!r}") from None
        if not per > 0:
            raise InputError(f"memory_per_worker: must be positive, got {memory_per_worker!r}")
        n = max(1, min(n, int(available_memory() // per)))
    return n


def fe_component_types(doc: Mapping[str, Any]) -> set[str]:
    """The FE component types (:data:`NATIVE_THREAD_TYPES`) the design file's components declare."""
    comps = doc.get("components")
    if not isinstance(comps, Mapping):
        return set()
    return {t.get("type") for t in comps.values() if isinstance(t, Mapping)} & NATIVE_THREAD_TYPES


def _base_peak(doc: Mapping[str, Any], path: str | None) -> tuple[float, float]:
    """(In a fresh worker process) its resident memory before and its peak after one verify of the base design
    [bytes]: Linux's VmHWM, the peak of this process image since its exec (not ``ru_maxrss``, which keeps the
    forking parent's resident size: a spawned worker of a 5 GB pytest process read 5.3 GB); 0 where unknown."""

    def peak() -> float:
        return _proc_bytes("/proc/self/status", "VmHWM") or 0.0

    from mechverify.design import adapters  # noqa: F401  (the imports a worker has before its first sample)
    before = peak()
    _base_design(doc, path)
    return before, peak()


def measured_sample_memory(doc: Mapping[str, Any], path: str | None) -> float | None:
    """Memory a local worker of an FE study needs [bytes], measured: the base design verified once in a fresh
    process, as a worker starts. A worker keeps its last FE model's mesh and factorisation (fea.factorcache)
    while it builds the next one's, so it may hold the FE part twice: interpreter + 2 x (peak - interpreter).
    None where the peak cannot be read (not Linux) or the measuring process fails."""
    try:
        with cf.ProcessPoolExecutor(1, mp_context=MainlessSpawnContext(), initializer=one_blas_thread) as ex:
            before, after = ex.submit(_base_peak, dict(doc), path).result()
    except Exception:  # (the samples report a design that fails; a platform without ru_maxrss: no sizing)
        return None
    return after + max(after - before, 0.0) if after > 0 else None


def fe_memory_per_worker(doc: Mapping[str, Any], path: str | None) -> str | None:
    """``memory_per_worker`` for a local pool running an FE study (issue 19: "FEA studies size workers by memory"):
    :func:`measured_sample_memory` as text ("412000000 byte"), or None for a design without FE components, on a
    single core (one worker either way) or where it cannot be measured."""
    if not fe_component_types(doc) or default_workers() < 2:
        return None
    per = measured_sample_memory(doc, path)
    return None if per is None else f"{per:.0f} byte"


def memory_note(memory_per_worker: Any, workers: int) -> str:
    """What ``memory_per_worker`` did to the local worker count, for the console: the workers chosen, the
    available memory, and a warning when even one sample may not fit."""
    from mechverify.units import Q

    per = float(Q(memory_per_worker).to("byte").magnitude)  # (validated by default_workers)
    avail = available_memory()
    text = (f"{workers} local worker(s) for {per / 1e9:.3g} GB per sample ({avail / 1e9:.3g} GB of memory "
            "available)")
    if per > avail:
        text += ": one sample may not fit in the available memory"
    return text


def process_pool(workers: int | None = None, *, task: Callable[..., Any] | None = None) -> cf.ProcessPoolExecutor:
    """A local process pool, one BLAS thread per worker. Its workers are forked (the platform's default on
    Linux: fast, and they inherit the designs built so far) while that is safe; once gmsh is loaded in this
    process (a solid_fea study, any mesh) they are started fresh instead (:func:`fork_is_safe`), without
    re-running the caller's script (:class:`MainlessSpawnContext`: a script without an ``if __name__ ==
    "__main__"`` guard keeps working). ``task``: the function the pool will run; one defined in the caller's
    script (``__main__``) keeps that script importable in the workers."""
    ctx: Any = None
    if not fork_is_safe() and multiprocessing.get_start_method() == "fork":
        ctx = MainlessSpawnContext(keep_main=getattr(task, "__module__", None) == "__main__")
    return cf.ProcessPoolExecutor(max_workers=workers or default_workers(), mp_context=ctx,
                                  initializer=one_blas_thread)


def fork_is_safe() -> bool:
    """Whether a process forked from this one can run a study's samples: not once gmsh is loaded. gmsh's
    OpenCASCADE kernel keeps a process-wide pool of worker threads (created by its first parallel call, e.g.
    the triangulation of the hole walls for a mesh-size field); a forked child inherits the pool but not its
    threads, and its first mesh waits for them forever (issue 19: a process-pool study after a serial
    solid_fea study in the same process hung at 0 % CPU; see :mod:`mechverify.fea.gmshstate`)."""
    return "gmsh" not in sys.modules


_SPAWN_LOCK = threading.Lock()


class MainlessSpawnContext(multiprocessing.context.BaseContext):
    """The "spawn" start method without re-running the caller's main script in each new process.

    Python's spawn (and forkserver) imports the parent's ``__main__`` file in every child, so a script that
    runs a study at its top level, without an ``if __name__ == "__main__"`` guard (docs/studies.md's own Monte
    Carlo block), would run the study again in every worker, which fails. A study's tasks are functions of
    this package, so the children need no ``__main__``: its path is left out of the data the child prepares
    itself from. ``keep_main``: leave it in (a task defined in the script). POSIX only (the default pool uses
    it where the default is fork)."""

    _name = "spawn"

    def __init__(self, keep_main: bool = False):
        self.Process = multiprocessing.context.SpawnProcess if keep_main else _MainlessProcess  # type: ignore[misc]


class _MainlessProcess(multiprocessing.context.SpawnProcess):
    """A spawned process that does not import the parent's ``__main__`` (module level: it is pickled)."""

    _start_method = "spawn"

    @staticmethod
    def _Popen(process_obj: Any) -> Any:
        return _mainless_popen(process_obj)


def _mainless_popen(process_obj: Any) -> Any:
    from multiprocessing import popen_spawn_posix, spawn

    with _SPAWN_LOCK:
        original = spawn.get_preparation_data

        def prepared(name: str) -> dict[str, Any]:
            data = original(name)
            data.pop("init_main_from_path", None)
            data.pop("init_main_from_name", None)
            return data

        spawn.get_preparation_data = prepared  # (read by Popen._launch; put back at once)
        try:
            return popen_spawn_posix.Popen(process_obj)
        finally:
            spawn.get_preparation_data = original


class SerialExecutor(cf.Executor):
    """Runs each task at once in this process (debugging, sizing, tiny studies)."""

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> cf.Future:
        f: cf.Future = cf.Future()
        try:
            f.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # (handed to the caller through the future)
            f.set_exception(exc)
        return f


class SchedulerError(MechverifyError):
    """The Dask scheduler cannot be reached (or ``distributed`` is not installed)."""


@contextmanager
def dask_executor(address: str, timeout: float = 10.0) -> Iterator[cf.Executor]:
    """An executor on the Dask cluster at ``address`` (``tcp://host:8786``), closed on exit.

    The connection (the client's handshake and a first request to the scheduler) runs under a hard deadline
    of ``timeout`` seconds: an address that does not answer, or answers but is not a Dask scheduler (a web
    server, the dashboard's port 8787), is a :class:`SchedulerError` within the deadline, whatever the
    client raised or however it hung; the half-made client is closed."""
    client = connect_dask(address, timeout)
    try:
        yield client.get_executor(pure=False)
    finally:
        client.close()


def connect_dask(address: str, timeout: float = 10.0) -> Any:
    """A ``distributed.Client`` connected to ``address`` within ``timeout`` s, or a :class:`SchedulerError`."""
    try:
        from distributed import Client
    except ImportError:
        raise SchedulerError("running on a Dask cluster needs the 'cluster' extra: "
                             + install_hint("cluster")) from None
    if not (isinstance(timeout, int | float) and math.isfinite(timeout) and timeout > 0):
        raise SchedulerError(f"--timeout: expected a positive number of seconds, got {timeout!r}")
    made: list[Any] = []

    class _Client(Client):  # (keeps a reference to the client before it connects: a failed one is closed)
        def start(self, **kwargs: Any) -> Any:
            made.append(self)
            return super().start(**kwargs)

    box: dict[str, Any] = {}

    def connect() -> None:
        try:
            c = _Client(address, timeout=timeout, set_as_default=False)
            box["client"] = c
            c.ncores()  # a first round trip: the scheduler answers requests, not only the handshake
            box["ok"] = True
        except BaseException as exc:  # (a non-Dask peer gives anything: MemoryError for a garbage frame size)
            box["error"] = exc

    t = threading.Thread(target=connect, name="mechverify-dask-connect", daemon=True)
    t.start()
    t.join(timeout)
    if box.get("ok"):
        return box["client"]
    exc = box.get("error")
    for c in made:
        _discard(c)
    why = "no answer" if exc is None else _not_dask(exc) or f"{type(exc).__name__}: {exc}"
    raise SchedulerError(f"cannot reach the Dask scheduler at {address} within {timeout:g} s ({why[:300]}); give the "
                         "scheduler's address, e.g. tcp://host:8786 (8787 is its dashboard), or run locally "
                         "(--serial, --workers N)")


def _not_dask(exc: BaseException) -> str | None:
    """The reason to print when ``exc`` comes from reading a reply that is no Dask message, else None. Dask reads a
    message's first 8 bytes as a frame length: an HTTP server's "HTTP/1.1" asks for 3.07 EiB (a MemoryError that
    used to be the whole reason given); other bytes fail in msgpack, struct or pickle."""
    import pickle
    import struct

    module = type(exc).__module__ or ""
    if isinstance(exc, MemoryError | struct.error | UnicodeDecodeError | pickle.UnpicklingError) \
            or module.split(".")[0] == "msgpack":
        return "something answered there that is not a Dask scheduler: its reply is not a Dask message"
    return None


def _discard(client: Any) -> None:
    """Close a client that never connected, in the background and briefly; its ``__del__`` is disarmed (it
    would block for twice the timeout and print a traceback at exit)."""
    def close() -> None:
        try:
            client.close(timeout=1)
        except BaseException:  # (nothing to report: the connection failed already)
            pass

    threading.Thread(target=close, name="mechverify-dask-close", daemon=True).start()
    try:
        client._Client__loop = None  # Client.__del__ closes only a client that has a loop
    except AttributeError:
        pass


def _marked(batch_fn: Callable[..., list[dict[str, Any]]], marks: str, i: int, doc: Mapping[str, Any],
            path: str | None, overrides: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The task of a local process pool: leaves the file ``marks/i`` when batch ``i`` starts in a worker, so that
    after a worker's death :func:`run_batches` knows which batches were running (the suspects) and which were only
    queued (the broken pool fails them all alike)."""
    Path(marks, str(i)).touch()
    return batch_fn(doc, path, overrides)


def run_batches(batch_fn: Callable[..., list[dict[str, Any]]], doc: Mapping[str, Any], path: str | None,
                batches: Sequence[Sequence[Mapping[str, Any]]], executor: cf.Executor | None = None, *,
                workers: int | None = None, retries: int = 1,
                on_done: Callable[[int], None] | None = None) -> list[list[dict[str, Any]]]:
    """Run every batch; results in batch order. A batch whose future fails (worker died, pool broken) is
    resubmitted ``retries`` times, then each of its samples is recorded as failed with the reason.

    On the local process pool (``executor`` None) a dead worker breaks the whole pool, which then fails every batch
    it holds with the same error. A new pool is started; the batches that were queued but not yet running (a file
    per batch started, :func:`_marked`, tells them apart) are resubmitted as they were, uncharged; those that were
    running (with others: which one killed the worker is unknown) are charged a run and rerun one at a time, each
    alone in the pool, where a death is the batch's own. A batch that kills its worker every time is so reported
    failed after two runs, and it is the only one (it took every batch of the study with it before)."""
    own = executor is None
    ex = process_pool(workers, task=batch_fn) if own else executor
    results: list[list[dict[str, Any]] | None] = [None] * len(batches)
    attempts = [0] * len(batches)
    marks = tempfile.mkdtemp(prefix="mechverify-study-") if own else None
    solo: list[int] = []  # batches to rerun alone: they were running, with others, when a worker died
    later: list[int] = []  # batches to (re)submit when no batch is running alone
    alone = False  # the batch in flight runs alone

    def submit(i: int) -> None:
        if marks is None:
            pending[ex.submit(batch_fn, doc, path, list(batches[i]))] = i
            return
        Path(marks, str(i)).unlink(missing_ok=True)
        pending[ex.submit(_marked, batch_fn, marks, i, doc, path, list(batches[i]))] = i

    def failed(i: int, exc: BaseException, retry: list[int]) -> None:
        """A run of batch ``i`` failed and the failure is its own: retry it (in ``retry``: ``later``, or ``solo``
        for a batch whose worker died), or record its samples as failed."""
        attempts[i] += 1
        if attempts[i] <= retries:
            retry.append(i)
            return
        msg = f"worker failed {attempts[i]} times on this batch: {type(exc).__name__}: {exc}"
        results[i] = [{"status": "error", "message": msg, "checks": {}} for _ in batches[i]]
        if on_done is not None:
            on_done(len(batches[i]))

    pending: dict[cf.Future, int] = {}
    try:
        for i in range(len(batches)):
            submit(i)
        while True:
            if not pending and solo:
                submit(solo.pop(0))
                alone = True
            elif later and not solo and not (pending and alone):
                for i in sorted(set(later)):
                    submit(i)
                later.clear()
                alone = False
            if not pending:
                break
            only = len(pending) == 1
            done, _ = cf.wait(list(pending), return_when=cf.FIRST_COMPLETED)
            if own and any(isinstance(f.exception(), cf.BrokenExecutor) for f in done):
                done, _ = cf.wait(list(pending))  # a broken pool fails every future it holds: take them all
            broken: list[tuple[int, BaseException]] = []
            for f in done:
                i = pending.pop(f)
                exc = f.exception()
                if exc is None:
                    results[i] = f.result()
                    if on_done is not None:
                        on_done(len(batches[i]))
                elif own and isinstance(exc, cf.BrokenExecutor):
                    broken.append((i, exc))
                else:  # the task raised, or another executor lost it: the failure is this batch's
                    failed(i, exc, later)
            if not broken:
                continue
            ex.shutdown(wait=False, cancel_futures=True)
            ex = process_pool(workers, task=batch_fn)
            assert marks is not None
            ran = {i for i, _ in broken if Path(marks, str(i)).exists()}
            if only:  # its own death: it was alone in the pool; retried alone
                failed(*broken[0], solo)
            elif not ran:  # a pool that dies before running anything: every batch is charged (this ends)
                for i, exc in sorted(broken, key=lambda b: b[0]):
                    failed(i, exc, later)
            else:  # each batch that was running is charged a run and reruns alone, where a death is its own
                for i in sorted(ran):
                    attempts[i] += 1
                    solo.append(i)
                later.extend(i for i, _ in broken if i not in ran)
    finally:
        if own:
            ex.shutdown(wait=True, cancel_futures=True)
            shutil.rmtree(marks, ignore_errors=True)  # type: ignore[arg-type]
    return [r if r is not None else [] for r in results]
