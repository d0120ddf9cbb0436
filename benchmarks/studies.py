"""Study throughput on the lead-screw lift (issue 19): samples per second per core, and Dask's overhead.

Measured: a warm ``verify()`` of the lift (same design object, repeated), one study sample
(``Design.with_overrides`` + ``verify``, what a worker does: one input changed, then a Monte Carlo draw of
the three inputs of VARY), the marginal cost of a plate-FEA sample that changes only the pressure and of a frame
sample (a grillage) that changes only its load, with and without the reused factorisation
(mechverify/fea/factorcache.py), a Monte Carlo study on the local
process pool (one worker per core) and the same study on a Dask ``LocalCluster`` with as many
single-threaded worker processes. Dask overhead per sample = (t_dask - t_pool) / n. Also the cost
of a unit conversion by string (``q.to("kN")``) against a parsed unit, the share the issue names.
The draws of a Monte Carlo study (the optimised Latin hypercube, in the calling process before any worker
starts: mechverify/studies/lhs.py against SciPy's own, the same array), the garbage collector's CPU and the Python
calls per Monte Carlo sample (a count the load does not change). Target (issue 19): >= 200 samples/s per core.
On a shared machine the wall-clock rates depend on the
load; the CPU seconds per sample (this process's for the serial runs, the reaped worker processes'
for the pool and the cluster) do not, and are printed too.
"""

from __future__ import annotations

import json
import resource
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LIFT = ROOT / "examples" / "lead_screw_lift" / "design.toml"
OUT = ROOT / "benchmarks" / "results" / "studies.json"
VARY = {"components.lift.mass": "normal:15 kg:1 kg", "parameters.lifted_load": "uniform:300 N:400 N",
        "profiles.raise.acceleration": "triangular:0.05 m/s^2:0.1 m/s^2:0.2 m/s^2"}


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _cpu_per_call(f, n: int) -> float:
    t0 = time.process_time()
    for _ in range(n):
        f()
    return (time.process_time() - t0) / n


def _per_call(f, n: int, repeat: int = 3) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(n):
            f()
        best = min(best, (time.perf_counter() - t0) / n)
    return best


def _load() -> float:
    import os

    return os.getloadavg()[0]


PLATE = {
    "design": {"name": "plate"},
    "materials": {"al": {"base": "Inventor Aluminum 6061", "E": "70 GPa", "nu": 0.3}},
    "components": {"p": {"type": "plate_fea", "width": "400 mm", "height": "200 mm", "thickness": "4 mm",
                         "material": "al", "supports": [{"edges": "all", "type": "pinned"}], "mesh_size": "5 mm",
                         "deflection_limit": "0.5 mm"}},
    "load_cases": {"q": {"p": {"pressure": "10 kPa"}}},
}


def _plate_rows(samples: int = 12) -> dict:
    """Marginal CPU per sample of a plate-FEA study whose samples vary only the pressure: with the factorised
    system reused (mechverify/fea/factorcache.py) and with the cache off (every sample meshes, assembles and
    factorises)."""
    import copy

    from mechverify.fea import factorcache
    from mechverify.studies import Study, execution

    vary = {"load_cases.q.p.pressure": f"5 kPa:15 kPa:{samples}"}

    def run() -> float:
        execution._BASE.clear()
        factorcache.CACHE.clear()
        study = Study(copy.deepcopy(PLATE), vary=vary)
        t0 = time.process_time()
        study.run("serial")
        return (time.process_time() - t0) / samples

    cached = min(run() for _ in range(3))
    builds = factorcache.CACHE.builds
    key_of = factorcache.key_of
    factorcache.key_of = lambda *parts: None
    try:
        uncached = min(run() for _ in range(2))
    finally:
        factorcache.key_of = key_of
    from mechverify.design.design import Design
    from mechverify.design.loader import parse

    d = Design(parse(copy.deepcopy(PLATE)))
    d.verify()
    dofs = d["p"].solved["q"][1].info.unknowns
    return {"plate_samples": samples, "plate_builds": builds, "plate_dofs": dofs,
            "plate_sample_cpu_ms": cached * 1e3, "plate_sample_uncached_cpu_ms": uncached * 1e3}


def _frame_grid(n: int = 4, divisions: int = 4) -> dict:
    """A grillage of n x n cells (2 n (n + 1) steel members of a 20 x 12 mm hollow rectangle, each in
    ``divisions`` elements), its four corners fixed, a load at the centre node: the design of the frame row."""
    nodes = {f"N{i}_{j}": [f"{100 * i} mm", f"{100 * j} mm", "0 mm"] for i in range(n + 1) for j in range(n + 1)}
    members = [{"start": f"N{i}_{j}", "end": f"N{i + 1}_{j}", "divisions": divisions}
               for i in range(n) for j in range(n + 1)]
    members += [{"start": f"N{i}_{j}", "end": f"N{i}_{j + 1}", "divisions": divisions}
                for i in range(n + 1) for j in range(n)]
    c = n // 2
    return {"design": {"name": "grillage"},
            "components": {"g": {"type": "frame", "section": "hollow_rectangle", "width": "20 mm", "height": "12 mm",
                                 "thickness": "1.5 mm", "material": "Structural Steel", "nodes": nodes,
                                 "members": members, "deflection_limit": "20 mm",
                                 "supports": [{"at": f"N{i}_{j}", "type": "fixed"} for i in (0, n) for j in (0, n)]}},
            "load_cases": {"q": {"g": {"point_loads": [{"at": f"N{c}_{c}", "force": ["0 N", "0 N", "-500 N"]}]}}}}


def _frame_rows(samples: int = 7) -> dict:
    """Marginal CPU per solve of a frame (the grillage of :func:`_frame_grid`) whose load changes from one solve
    to the next, as in a study over a load: ``Frame.analyse`` with the stiffness, its checks and factorisation
    reused (mechverify/fea/factorcache.py) and with the cache off. (A design-file sample of this frame spends most
    of its time after the solve, in the stress and deflection recovery of the frame checks.)"""
    import copy

    from mechverify.design.design import Design
    from mechverify.design.loader import parse
    from mechverify.fea import factorcache
    from mechverify.fea.frame import FramePointLoad

    doc = _frame_grid()
    fr = Design(parse(copy.deepcopy(doc)))["g"].frame
    c = doc["load_cases"]["q"]["g"]["point_loads"][0]["at"]
    loads = [FramePointLoad(c, force=["0 N", "0 N", f"{-200 - 50 * k} N"]) for k in range(samples)]

    def run() -> float:
        factorcache.CACHE.clear()
        fr.analyse({"q": loads[:1]})  # (a study's base design: the first solve builds)
        t0 = time.process_time()
        for ld in loads[1:]:
            fr.analyse({"q": [ld]})
        return (time.process_time() - t0) / (samples - 1)

    from mechverify.fea.reproducible import one_blas_thread

    with one_blas_thread():  # as in a study worker (the dense mechanism check is an eigh)
        cached = min(run() for _ in range(3))
        builds = factorcache.CACHE.builds
        key_of = factorcache.key_of
        factorcache.key_of = lambda *parts: None
        try:
            uncached = min(run() for _ in range(2))
        finally:
            factorcache.key_of = key_of
    dofs = fr.analyse({"q": loads[:1]}).results["q"].mesh.ndof
    return {"frame_samples": samples, "frame_builds": builds, "frame_dofs": dofs,
            "frame_solve_cpu_ms": cached * 1e3, "frame_solve_uncached_cpu_ms": uncached * 1e3}


def _gc_and_calls(f, n: int) -> tuple[float, float]:
    """CPU seconds the garbage collector spends per call of ``f`` (``gc.callbacks``), and the Python function calls
    per call (cProfile: a count the machine's load does not change)."""
    import cProfile
    import gc
    import pstats

    spent, start = [0.0], [0.0]

    def cb(phase: str, info: dict) -> None:
        if phase == "start":
            start[0] = time.process_time()
        else:
            spent[0] += time.process_time() - start[0]

    gc.callbacks.append(cb)
    try:
        for _ in range(n):
            f()
    finally:
        gc.callbacks.remove(cb)
    prof = cProfile.Profile()
    prof.enable()
    for _ in range(n):
        f()
    prof.disable()
    return spent[0] / n, pstats.Stats(prof).total_calls / n


def _lhs_rows(n: int) -> dict:
    """CPU seconds of a Monte Carlo study's draws (the optimised Latin hypercube, done in the calling process before
    any worker starts) for ``n`` and 1000 samples: mechverify.studies.lhs against SciPy's own random-cd (the same
    array, bit for bit)."""
    from scipy.stats import qmc

    from mechverify.studies.lhs import optimised_lhs

    out = {}
    for k in sorted({n, 1000}):
        t0 = time.process_time()
        ours = optimised_lhs(len(VARY), k, 1)
        t1 = time.process_time()
        theirs = qmc.LatinHypercube(len(VARY), seed=1, optimization="random-cd").random(k)
        t2 = time.process_time()
        assert ours.tobytes() == theirs.tobytes()
        out[f"lhs_{k}_cpu_s"], out[f"lhs_{k}_scipy_cpu_s"] = t1 - t0, t2 - t1
    return out


def main(argv: list[str]) -> dict:
    from mechverify.design import load
    from mechverify.studies import Study
    from mechverify.studies.execution import default_workers
    from mechverify.units import Q, ureg

    n = int(argv[0]) if argv else 400
    cores = default_workers()
    d = load(LIFT)
    d.verify()
    warm = _per_call(d.verify, 20)
    one = lambda: d.with_overrides({"components.lift.mass": "15.0 kg"}).verify()  # noqa: E731
    sample = _per_call(one, 20)
    sample_cpu = min(_cpu_per_call(one, 40) for _ in range(5))
    # a Monte Carlo sample: the three inputs of VARY drawn (mass, lifted load, the profile's acceleration),
    # so that only the horizontal screw's check is unchanged (design/reuse.py)
    draws = Study(LIFT, vary=VARY, samples=40, seed=3)
    mc_ovs = [draws.overrides(x) for x in draws.inputs()]
    mc_iter = iter(mc_ovs * 100)
    mc = lambda: d.with_overrides(next(mc_iter)).verify()  # noqa: E731
    mc_cpu = min(_cpu_per_call(mc, 40) for _ in range(5))
    override_cpu = min(_cpu_per_call(lambda: d.with_overrides(mc_ovs[0]), 40) for _ in range(5))
    # what a study's sample costs: every draw a new value string (the 40 draws above repeat, so their strings are
    # parsed once); best of three passes over 200 distinct draws each
    fresh_cpu = float("inf")
    for k in range(3):
        f = Study(LIFT, vary=VARY, samples=200, seed=100 + k)
        fresh_ovs = iter([f.overrides(x) for x in f.inputs()])
        fresh_cpu = min(fresh_cpu, _cpu_per_call(lambda it=fresh_ovs: d.with_overrides(next(it)).verify(), 200))
    gc_s, calls = _gc_and_calls(mc, 40)
    load_start = _load()
    lhs = _lhs_rows(n)
    plate = _plate_rows()
    frame = _frame_rows()
    q, unit = Q(1234.0, "N"), ureg.Unit("kN")
    to_str = _per_call(lambda: q.to("kN"), 2000)
    to_unit = _per_call(lambda: q.to(unit), 2000)

    study = Study(LIFT, vary=VARY, samples=n, seed=1)
    Study(LIFT, vary=VARY, samples=2 * cores, seed=1).run(workers=cores)  # warm the OS caches
    c0, t0, m0 = _children_cpu(), time.perf_counter(), time.process_time()
    pool = study.run(workers=cores)
    t_pool, cpu_pool = time.perf_counter() - t0, _children_cpu() - c0
    main_pool = time.process_time() - m0  # this process: draws, batches, collecting, statistics
    row = {"samples": n, "cores": cores, "warm_verify_ms": warm * 1e3, "sample_ms": sample * 1e3,
           "serial_samples_per_s": 1 / sample,
           "sample_cpu_ms": sample_cpu * 1e3, "samples_per_cpu_s": 1 / sample_cpu,
           "mc_sample_cpu_ms": mc_cpu * 1e3, "mc_samples_per_cpu_s": 1 / mc_cpu,
           "mc_override_cpu_ms": override_cpu * 1e3, "mc_gc_cpu_ms": gc_s * 1e3, "mc_python_calls": calls,
           "mc_fresh_sample_cpu_ms": fresh_cpu * 1e3, "mc_fresh_samples_per_cpu_s": 1 / fresh_cpu,
           **lhs, **plate, **frame,
           "pool_cpu_ms_per_sample": cpu_pool / n * 1e3, "pool_main_process_cpu_s": main_pool, "pool_s": t_pool,
           "pool_samples_per_s_per_core": n / t_pool / cores, "load_average": _load(),
           "load_average_start": load_start,
           "to_string_unit_us": to_str * 1e6, "to_parsed_unit_us": to_unit * 1e6, "target_per_core": 200}
    try:
        from distributed import LocalCluster
    except ImportError:
        row["dask"] = "not installed (pip install 'mechverify[cluster]')"
    else:
        from distributed import Client

        with LocalCluster(n_workers=cores, threads_per_worker=1, processes=True, dashboard_address=None) as cl:
            with Client(cl) as client:
                ex = client.get_executor(pure=False)
                Study(LIFT, vary=VARY, samples=2 * cores, seed=1).run(ex)  # workers import mechverify
                w0, m0 = client.run(time.process_time), time.process_time()
                t0 = time.perf_counter()
                dask = study.run(ex)
                t_dask = time.perf_counter() - t0
                w1, m1 = client.run(time.process_time), time.process_time()
        # CPU seconds, independent of the machine's load: workers (tasks, Dask's worker machinery) and this
        # process (client, scheduler and its event loop, result collection)
        row["dask_worker_cpu_ms_per_sample"] = sum(w1[k] - w0[k] for k in w1) / n * 1e3
        row["dask_client_scheduler_cpu_ms_per_sample"] = (m1 - m0) / n * 1e3
        row.update({"dask_s": t_dask, "dask_samples_per_s_per_core": n / t_dask / cores,
                    "dask_overhead_ms_per_sample": (t_dask - t_pool) / n * 1e3,
                    "dask_equals_pool": dask.to_json() == pool.to_json()})
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(row, indent=1) + "\n")
    print(f"lift: warm verify {warm * 1e3:.1f} ms, one sample (override + verify) {sample * 1e3:.1f} ms "
          f"= {1 / sample:.0f} samples/s on one core (target 200)")
    print(f"  CPU per sample: {sample_cpu * 1e3:.1f} ms in this process = {1 / sample_cpu:.0f} samples per CPU-second")
    print(f"  Monte Carlo sample (3 inputs drawn): {mc_cpu * 1e3:.1f} ms CPU = {1 / mc_cpu:.0f} samples per "
          f"CPU-second (with_overrides alone {override_cpu * 1e3:.1f} ms; garbage collector {gc_s * 1e3:.2f} ms; "
          f"{calls:.0f} Python calls)")
    print(f"  the same with a new draw every sample (as in a study: new value strings): {fresh_cpu * 1e3:.1f} ms CPU "
          f"= {1 / fresh_cpu:.0f} samples per CPU-second")
    print(f"draws (optimised LHS, this process): {n} samples {lhs[f'lhs_{n}_cpu_s']:.3f} s CPU (SciPy's own "
          f"{lhs[f'lhs_{n}_scipy_cpu_s']:.3f} s), 1000 samples {lhs['lhs_1000_cpu_s']:.3f} s "
          f"({lhs['lhs_1000_scipy_cpu_s']:.3f} s)")
    print(f"plate FEA study over a pressure ({plate['plate_dofs']} DOF): {plate['plate_sample_cpu_ms']:.1f} ms CPU per "
          f"sample with the factorisation reused, {plate['plate_sample_uncached_cpu_ms']:.1f} ms without "
          f"({plate['plate_builds']} build for {plate['plate_samples']} samples)")
    print(f"frame analysis over a load ({frame['frame_dofs']} DOF): {frame['frame_solve_cpu_ms']:.1f} ms CPU per solve "
          f"with the stiffness and factorisation reused, {frame['frame_solve_uncached_cpu_ms']:.1f} ms without "
          f"({frame['frame_builds']} build for {frame['frame_samples']} solves)")
    print(f"process pool, {cores} workers, {n} samples: {t_pool:.2f} s = {row['pool_samples_per_s_per_core']:.1f} "
          f"samples/s per core (wall; load average {_load():.1f}); worker CPU {cpu_pool / n * 1e3:.1f} ms per sample, "
          f"main process {main_pool:.2f} s CPU")
    if "dask_s" in row:
        print(f"Dask LocalCluster, {cores} workers: {row['dask_s']:.2f} s = {row['dask_samples_per_s_per_core']:.1f} "
              f"samples/s per core; overhead {row['dask_overhead_ms_per_sample']:+.2f} ms per sample against the "
              f"pool (wall); same result: {row['dask_equals_pool']}")
        print(f"  CPU per sample: workers {row['dask_worker_cpu_ms_per_sample']:.1f} ms "
              f"(pool: {cpu_pool / n * 1e3:.1f} ms), client and scheduler "
              f"{row['dask_client_scheduler_cpu_ms_per_sample']:.2f} ms")
    print(f"unit conversion: q.to('kN') {to_str * 1e6:.1f} us, with a parsed unit {to_unit * 1e6:.1f} us")
    return row


if __name__ == "__main__":
    main(sys.argv[1:])
