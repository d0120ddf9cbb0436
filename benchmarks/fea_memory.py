"""Benchmark: memory per DOF of the static solid solve (issue 23: <= 5 kB per DOF at every size).

For each part (``ccx_common.LUG``, the compact lug; ``ccx_common.PLATE``, the 6 mm plate with a hole) and each
target DOF count, the gmsh mesh is made here and handed to fresh child processes that each run
``SolidModel.solve()`` once:

- ``rss`` child: peak resident set (``getrusage`` max RSS, the figure issue 23's target is about), RSS after the
  imports and after the mesh (so the solve's own share is known), and the largest RSS sampled (every 2 ms by a
  thread reading ``/proc/self/statm``) inside each phase: P2 pattern, element stiffness + assembly, loads and
  supports, free-DOF extraction, solver choice, the direct path's lower triangle and factorisation, multigrid
  setup, CG, stress recovery, equilibrium and region reports, results.
- ``budget`` child (with ``--budget``): the same solve under ``tracemalloc`` (NumPy registers its buffers with
  it, so this is the Python-side array memory, not RSS): bytes alive at each phase's end and the peak inside
  it, and an itemised count of the big objects (mesh and P2 numbering, block pattern, K, Kff, the p-multigrid
  hierarchy, CG vectors).

Writes ``benchmarks/results/fea_memory.json`` (rows written as they come). Usage::

    python benchmarks/fea_memory.py [--parts lug plate] [--dofs 50000 200000] [--method auto] [--budget]
        [--mesh-dir DIR] [--shared] [--out path.json]

``--mesh-dir`` keeps the saved meshes (``<part>-<target>.npz``) and reuses them on the next run, so two versions
of the code are compared on the same meshes; ``--code-dir`` runs the children with another checkout's mechverify
(a git worktree of an older commit); ``--shared`` solves through ``study.SharedSolve`` (what every design-file
``solid_fea`` solve and a pinned model go through) instead of ``SolidModel.solve``'s own path.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import threading
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from ccx_common import (  # noqa: E402
    LUG,
    PLATE,
    load_average,
    load_mesh,
    mesh_for,
    model_of,
    peak_rss,
    save_mesh,
    write_rows,
)

PARTS = {"lug": LUG, "plate": PLATE}
PAGE = os.sysconf("SC_PAGE_SIZE")


def rss_now() -> int:
    """This process's resident set now [bytes]."""
    with open("/proc/self/statm") as fh:
        return int(fh.read().split()[1]) * PAGE


class Phases:
    """The phase the solve is in (set by wrapped functions) and the largest RSS sampled inside each."""

    def __init__(self, trace: bool = False):
        self.name = "start"
        self.peak: dict[str, int] = {}
        self.trace = trace
        self.traced: dict[str, dict[str, int]] = {}
        self._stop = threading.Event()
        self._thread = None if trace else threading.Thread(target=self._sample, daemon=True)

    def _sample(self) -> None:
        while not self._stop.is_set():
            r = rss_now()
            if r > self.peak.get(self.name, 0):
                self.peak[self.name] = r
            time.sleep(0.002)

    def start(self) -> None:
        if self._thread is not None:
            self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        self.enter("end")

    def enter(self, name: str) -> str:
        """Switch to phase ``name``; returns the previous one."""
        prev = self.name
        if self.trace:
            import tracemalloc

            cur, pk = tracemalloc.get_traced_memory()
            rec = self.traced.setdefault(prev, {"alive_at_end": 0, "peak": 0})
            rec["alive_at_end"], rec["peak"] = cur, max(rec["peak"], pk)
            tracemalloc.reset_peak()
        else:
            r = rss_now()
            self.peak[prev] = max(self.peak.get(prev, 0), r)
        self.name = name
        return prev

    def wrap(self, owner, attr: str, name: str, after: str | None = None) -> None:
        """Run ``owner.attr`` as phase ``name`` (then back to the caller's phase, or to ``after``)."""
        fn = getattr(owner, attr)

        def wrapped(*a, **k):
            prev = self.enter(name)
            try:
                return fn(*a, **k)
            finally:
                self.enter(after or prev)

        setattr(owner, attr, wrapped)


def nbytes(obj, seen: set[int] | None = None, depth: int = 0) -> int:
    """Bytes of the NumPy arrays reachable from ``obj`` (sparse matrices, lists, dicts, objects, closures), each
    array counted once."""
    import scipy.sparse as sp

    seen = set() if seen is None else seen
    if id(obj) in seen or depth > 12:
        return 0
    seen.add(id(obj))
    if isinstance(obj, np.ndarray):
        return obj.nbytes if obj.base is None else nbytes(obj.base, seen, depth + 1)
    if sp.issparse(obj):
        return sum(nbytes(getattr(obj, a, None), seen, depth + 1) for a in ("data", "indices", "indptr", "row",
                                                                              "col", "offsets"))
    if isinstance(obj, (list, tuple, set)):
        return sum(nbytes(v, seen, depth + 1) for v in obj)
    if isinstance(obj, dict):
        return sum(nbytes(v, seen, depth + 1) for v in obj.values())
    if callable(obj) and getattr(obj, "__closure__", None):
        return sum(nbytes(c.cell_contents, seen, depth + 1) for c in obj.__closure__ if c.cell_contents is not None)
    if hasattr(obj, "__dict__") and type(obj).__module__.split(".")[0] in ("pyamg", "scipy", "mechverify", "skfem"):
        return sum(nbytes(v, seen, depth + 1) for v in vars(obj).values())
    return 0


def child(path: str, part: str, method: str, mode: str, shared: str = "") -> None:
    """Solve the saved mesh once in this fresh process; print the measurements as JSON. ``shared``: through
    ``study.SharedSolve.of`` then ``solve(factorization=...)``, the path of every design-file ``solid_fea`` solve."""
    from mechverify.fea import assembly, factor, linsolve, recovery, solid, study

    trace = mode == "budget"
    if trace:
        import tracemalloc

        tracemalloc.start()
    ph = Phases(trace)
    start = rss_now()
    ph.start()
    ph.enter("mesh")
    m = load_mesh(path)
    _ = m.mesh.boundary_facets(), m.mesh.edges
    after_mesh = rss_now()
    items: dict[str, int] = {}
    if trace:
        items["mesh and P2 numbering"] = nbytes(m.mesh) + nbytes(m.basis) + nbytes(m)
    ph.enter("model")
    model = model_of(PARTS[part], m)
    ph.wrap(assembly, "block_pattern", "P2 pattern")
    ph.wrap(solid.SolidModel, "_stiffness", "stiffness")
    # linsolve.solve is not wrapped (a wrapper's frame would hold K, which SolidModel.solve hands over to it to be
    # freed once Kff exists): its first call, the supports check, starts the phase
    ph.wrap(linsolve, "check_supported", "free DOFs, Kff", after="free DOFs, Kff")
    ph.wrap(linsolve, "choose_solver", "solver choice")
    ph.wrap(assembly, "node_graph", "solver choice")
    # the direct path (task thinperf): the permuted lower triangle read from K, then CHOLMOD on it
    ph.wrap(assembly, "free_lower_permuted", "lower triangle", after="lower triangle")
    ph.wrap(factor, "factorize_lower", "factorisation", after="after CG")
    ph.wrap(linsolve, "pmg_preconditioner", "multigrid setup", after="CG")
    ph.wrap(linsolve, "pcg", "CG", after="after CG")
    ph.wrap(factor, "factorize", "factorisation", after="after CG")
    ph.wrap(recovery, "recover", "recovery, reports", after="recovery, reports")
    ph.wrap(recovery, "recover_curved", "recovery, reports", after="recovery, reports")
    if trace:  # the big objects, counted where they are made
        pattern_of, stiffness, pmg, pcg = (assembly.block_pattern, solid.SolidModel._stiffness,
                                           linsolve.pmg_preconditioner, linsolve.pcg)

        def count_pattern(*a, **k):
            out = pattern_of(*a, **k)
            items["block pattern (summation matrix)"] = nbytes(out)
            return out

        def count_k(self, *a, **k):
            out = stiffness(self, *a, **k)
            items["K (BSR)"] = nbytes(out[0])
            return out

        def count_pmg(A, *a, **k):
            items["Kff (CSR)"] = nbytes(A)
            out = pmg(A, *a, **k)
            items["p-multigrid (P, Pt, P1 hierarchy)"] = nbytes(out, {id(A)})
            return out

        def count_pcg(A, b, *a, **k):
            items["CG vectors (x, r, z, p, Ap, b)"] = 6 * b.nbytes
            return pcg(A, b, *a, **k)

        lower_of = assembly.free_lower_permuted

        def count_lower(*a, **k):
            out = lower_of(*a, **k)
            items["lower triangle of the permuted Kff (CSC)"] = nbytes(out)
            return out

        assembly.free_lower_permuted = count_lower
        assembly.block_pattern, solid.SolidModel._stiffness = count_pattern, count_k
        linsolve.pmg_preconditioner, linsolve.pcg = count_pmg, count_pcg
    ph.enter("loads, supports")
    t0, c0 = time.perf_counter(), time.process_time()
    if shared:
        res = model.solve(factorization=study.SharedSolve.of(model, method), progress=False)
    else:
        res = model.solve(method=method, progress=False)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    ph.stop()
    out = {"mode": mode, "dofs": int(m.n_dofs), "wall": wall, "cpu": cpu, "method": res.info.method,
           "iterations": res.info.iterations, "peak": peak_rss(), "rss_start": start, "rss_after_mesh": after_mesh,
           "max_displacement": float(np.abs(res.u).max()),
           "max_von_mises_MPa": float(res.max_von_mises.value.m_as("MPa"))}
    if trace:
        import tracemalloc

        tracemalloc.stop()
        out["traced_peak"] = max(v["peak"] for v in ph.traced.values())
        out["phases_traced"], out["items"] = ph.traced, items
    else:
        out["phases_rss"] = ph.peak
        np.save(path + ".u.npy", res.u)
    print(json.dumps(out))


def run_child(*args: str, code_dir: str | None = None, shared: bool = False) -> dict:
    """``python fea_memory.py --child args...`` (with ``code_dir``'s mechverify first on the path: another version
    of the code on the same mesh) and the JSON of its last output line."""
    import subprocess

    env = dict(os.environ)
    if code_dir:
        env["PYTHONPATH"] = os.pathsep.join([str(code_dir), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    r = subprocess.run([sys.executable, __file__, "--child", *map(str, args), *(["shared"] if shared else [])],
                       capture_output=True, text=True,
                       env=env)
    if r.returncode:
        raise RuntimeError(f"fea_memory.py child failed:\n{r.stderr[-3000:]}")
    return json.loads(r.stdout.strip().splitlines()[-1])


def run_case(part: str, target: int, method: str, budget: bool, mesh_dir: str | None,
             code_dir: str | None = None, shared: bool = False) -> dict:
    import tempfile

    folder = mesh_dir or tempfile.mkdtemp(prefix="mv-mem-")
    path = os.path.join(folder, f"{part}-{target}.npz")
    if not os.path.exists(path):
        save_mesh(mesh_for(PARTS[part], target), path)
    row = {"part": part, "target": target, "method": method, "load_average": load_average(), "code": code_dir or ".",
           "path": "SharedSolve" if shared else "SolidModel.solve"}
    row["rss"] = run_child(path, part, method, "rss", code_dir=code_dir, shared=shared)
    if budget:
        row["budget"] = run_child(path, part, method, "budget", code_dir=code_dir, shared=shared)
    row["dofs"] = row["rss"]["dofs"]
    row["kB_per_dof"] = row["rss"]["peak"] / row["dofs"] / 1e3
    row["kB_per_dof_above_mesh"] = (row["rss"]["peak"] - row["rss"]["rss_after_mesh"]) / row["dofs"] / 1e3
    if not mesh_dir:
        for f in os.listdir(folder):
            os.remove(os.path.join(folder, f))
        os.rmdir(folder)
    return row


def show(row: dict) -> None:
    r, n = row["rss"], row["dofs"]
    print(f"{row['part']:>6} {n:>8} DOF  peak {r['peak'] / 1e6:7.0f} MB = {row['kB_per_dof']:.2f} kB/DOF "
          f"(start {r['rss_start'] / 1e6:.0f} MB, mesh {r['rss_after_mesh'] / 1e6:.0f} MB; "
          f"{row['kB_per_dof_above_mesh']:.2f} kB/DOF above the mesh)  {r['method']}, {r['iterations']} it., "
          f"{r['cpu']:.1f} s CPU, load {row['load_average']:.1f}")
    for k, v in r["phases_rss"].items():
        print(f"        {k:<22} RSS max {v / 1e6:7.0f} MB  ({v / n / 1e3:.2f} kB/DOF)")
    if "budget" in row:
        b = row["budget"]
        print(f"        tracemalloc peak {b['traced_peak'] / 1e6:.0f} MB ({b['traced_peak'] / n / 1e3:.2f} kB/DOF)")
        for k, v in b["phases_traced"].items():
            print(f"        {k:<22} traced alive at end {v['alive_at_end'] / 1e6:7.0f} MB, "
                  f"peak {v['peak'] / 1e6:7.0f} MB ({v['peak'] / n / 1e3:.2f} kB/DOF)")
        for k, v in b["items"].items():
            print(f"        item {k:<36} {v / 1e6:7.1f} MB  ({v / n:.0f} B/DOF)")


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--parts", nargs="+", default=["lug", "plate"], choices=sorted(PARTS))
    ap.add_argument("--dofs", type=int, nargs="+", default=[50_000, 200_000])
    ap.add_argument("--method", default="auto", choices=["auto", "amg", "direct"])
    ap.add_argument("--budget", action="store_true", help="also the tracemalloc budget (a second child per size)")
    ap.add_argument("--mesh-dir", help="keep and reuse the saved meshes here")
    ap.add_argument("--code-dir", help="run the solves with the mechverify of this checkout (an older version, a "
                    "git worktree) on the same meshes")
    ap.add_argument("--shared", action="store_true", help="solve through study.SharedSolve (the design-file solid_fea "
                    "path) instead of SolidModel.solve's own")
    ap.add_argument("--out", default=str(HERE / "results" / "fea_memory.json"))
    args = ap.parse_args(argv)
    if args.mesh_dir:
        os.makedirs(args.mesh_dir, exist_ok=True)
    rows = []
    for part in args.parts:
        for t in args.dofs:
            rows.append(run_case(part, t, args.method, args.budget, args.mesh_dir, args.code_dir, args.shared))
            write_rows(rows, args.out)
            show(rows[-1])
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(*sys.argv[2:7])
    else:
        main()
