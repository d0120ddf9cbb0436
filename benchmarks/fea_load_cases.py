"""Many load cases on one factorisation (issue 23): the marginal cost of an extra load case.

For a cantilever box of P2 tetrahedra at a few sizes, ``n`` load cases are solved (a) each on its own
(assembly + factorisation or multigrid setup + solve + stress recovery, ``SolidModel.solve``) and (b) all on
one :class:`mechverify.fea.study.SharedSolve` (``solve_cases``). Reported per size and method: the setup
(assembly + factorisation/hierarchy), the wall time of one independent case, the marginal time of one more case
on the shared factorisation (the slope of total time over the number of cases) and the ratio of the two; and
the marginal time of one more load vector in a block solve (``SharedSolve.solve_many``, solve only).
Also the natural frequencies (10 modes) of the same model, for the modal row.

    python benchmarks/fea_load_cases.py [--sizes 8 12 16] [--cases 4]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results" / "fea_load_cases.json"


def _model(n: int):
    from mechverify.fea import mesh, solid
    from mechverify.fea.loads import Fixed
    from mechverify.fea.regions import Plane

    m = mesh.box(("400 mm", "40 mm", "40 mm"), (4 * n, max(1, n // 2), max(1, n // 2)))
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x="0 mm")),))


def _cases(k: int):
    from mechverify.fea.loads import Force
    from mechverify.fea.regions import Plane

    return [(Force(Plane(x="400 mm"), (f"{10 * i} N", f"{5 * i} N", "-100 N")),) for i in range(k)]


def run(sizes: list[int], n_cases: int) -> list[dict]:
    from dataclasses import replace

    from mechverify.fea import modal, study
    from mechverify.fea.factor import cholmod_available

    rows = []
    for n in sizes:
        base = _model(n)
        for method in ("direct", "amg"):
            cases = _cases(n_cases)
            t0 = time.perf_counter()
            replace(base, loads=cases[0]).solve(method=method)
            one = time.perf_counter() - t0
            t0 = time.perf_counter()
            shared = study.SharedSolve.of(base, method)
            setup = time.perf_counter() - t0
            per = []
            for loads in cases:
                t1 = time.perf_counter()
                replace(base, loads=loads).solve(factorization=shared)
                per.append(time.perf_counter() - t1)
            marginal = sorted(per)[len(per) // 2]
            # a block of load vectors on the shared factorisation / hierarchy (solve only, no recovery)
            import numpy as np

            F = np.random.default_rng(0).standard_normal((base.mesh.n_dofs, n_cases))
            t1 = time.perf_counter()
            shared.solve_many(F[:, :1])
            t_one = time.perf_counter() - t1
            t1 = time.perf_counter()
            shared.solve_many(F)
            t_block = time.perf_counter() - t1
            solver = ("cholmod" if cholmod_available() else "superlu") if method == "direct" else "p-multigrid CG"
            rows.append({"dofs": int(base.mesh.n_dofs), "method": f"{method} ({solver})",
                         "setup_s": setup, "independent_case_s": one,
                         "marginal_case_s": marginal, "marginal_over_independent": marginal / one,
                         "block_one_vector_s": t_one, "block_marginal_vector_s": (t_block - t_one) / (n_cases - 1),
                         "n_cases": n_cases})
            print(json.dumps(rows[-1]))
        t0 = time.perf_counter()
        res = modal.modal(base, 10)
        rows.append({"dofs": int(base.mesh.n_dofs), "method": "modal 10 modes (shift-invert, "
                     f"{'CHOLMOD' if cholmod_available() else 'SuperLU'})",
                     "seconds": time.perf_counter() - t0, "first_Hz": float(res.frequencies.m[0])})
        print(json.dumps(rows[-1]))
    return rows


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[4, 8, 12])
    ap.add_argument("--cases", type=int, default=4)
    a = ap.parse_args(argv)
    rows = run(a.sizes, a.cases)
    OUT.write_text(json.dumps(rows, indent=2))
    return rows


if __name__ == "__main__":
    main()
