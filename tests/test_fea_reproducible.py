"""The solid FEA gives the same bits on every run, whatever runs it (issue 19: a study's output is identical whatever
the executor; mechverify/fea/reproducible.py).

Two causes were found: OpenBLAS's dgemm (numpy's einsum/matmul in the element integrals) rounds differently with
one and with two threads (the CLI used one per core, a study's pool worker and the test suite one), and pyamg's
smoothed aggregation starts a spectral-radius estimate from numpy's global, unseeded random generator. These tests
compare bits, not tolerances: the published-number validation of the solid FEA is in tests/validation/. Each one
failed before the fix (a different last digit of the stress, or of the displacements).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

threadpoolctl = pytest.importorskip("threadpoolctl")
from threadpoolctl import threadpool_info, threadpool_limits  # noqa: E402

from mechverify.fea import mesh  # noqa: E402
from mechverify.fea.loads import Fixed, Force  # noqa: E402
from mechverify.fea.regions import Named  # noqa: E402
from mechverify.fea.reproducible import one_blas_thread, seeded_global_rng  # noqa: E402
from mechverify.fea.solid import SolidModel  # noqa: E402
from mechverify.units import Q  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

# examples/solid_bracket at a coarser mesh (the same path: a gmsh block with holes, curved P2 tetrahedra, CHOLMOD,
# modal and buckling), so that two CLI runs stay short.
BRACKET = """
[design]
name = "solid bracket, coarse"

[requirements.safety_factors]
static = 1.5
buckling = 3.0

[components.bracket]
type = "solid_fea"
box = "120, 40, 10"
holes = [{{ center = "15, 10", diameter = "8.5 mm" }}, {{ center = "15, 30", diameter = "8.5 mm" }}]
material = "Inventor Aluminum 6061"
mesh_size = "{h}"
supports = [{{ named = "hole0" }}, {{ named = "hole1" }}]
deflection_limit = "1 mm"
{extra}

[load_cases.service.bracket]
forces = [{{ named = "xmax", force = "-2000, 0, -300" }}]
"""


def _bracket_model(h: str = "8 mm") -> SolidModel:
    m = mesh.block_with_holes((Q(0.12, "m"), Q(0.04, "m"), Q(0.01, "m")),
                              [((Q(0.015, "m"), Q(0.01, "m")), "8.5 mm"), ((Q(0.015, "m"), Q(0.03, "m")), "8.5 mm")],
                              h)
    return SolidModel(m, "Inventor Aluminum 6061", supports=(Fixed(Named("hole0")), Fixed(Named("hole1"))),
                      loads=(Force(Named("xmax"), ("-2000 N", "0 N", "-300 N")),))


def _blas_threads() -> set[int]:
    return {i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"}


def _blas_settings() -> dict[str, int]:
    return {i["filepath"]: i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"}


def test_solid_solve_same_bits_with_one_or_two_blas_threads():
    """Before the fix the curved elements' Jacobians (einsum -> OpenBLAS dgemm) already differed in the last bits."""
    model = _bracket_model()
    with threadpool_limits(2):
        two = model.solve()
    with threadpool_limits(1):
        one = model.solve()
    assert np.array_equal(one.u, two.u)
    assert np.array_equal(one.sigma, two.sigma)


def test_amg_solve_same_bits_whatever_the_global_random_state():
    """pyamg's spectral-radius estimate drew from np.random: three fresh processes gave three displacement hashes.
    The caller's random stream is left as it was. At 6 mm the linear-element system (2.4k unknowns) is above pyamg's
    max_coarse (1500), so smoothed aggregation builds a level (at 8 mm it solves it directly: nothing random)."""
    model = _bracket_model("6 mm")
    np.random.seed(1)
    a = model.solve(method="amg")
    after = np.random.rand()
    np.random.seed(2)
    b = model.solve(method="amg")
    assert "amg" in a.info.method and np.array_equal(a.u, b.u)
    np.random.seed(1)
    assert np.random.rand() == after  # the solve did not consume or reset the caller's stream


def test_seeded_global_rng_restores_the_state():
    np.random.seed(5)
    expected = np.random.rand(3)
    np.random.seed(5)
    with seeded_global_rng(0):
        inside = np.random.rand()
    np.random.seed(0)
    assert inside == np.random.rand()
    np.random.seed(5)
    with seeded_global_rng(0):
        np.random.rand(10)
    assert np.array_equal(np.random.rand(3), expected)


def test_one_blas_thread_nested_and_across_threads():
    """The limit holds while any block is open, in any thread, and the process's setting comes back after."""
    with one_blas_thread():  # loads every BLAS it limits (CHOLMOD's too), so that the setting below covers them all
        pass
    with threadpool_limits(2):
        before = _blas_settings()
        entered, leave = threading.Event(), threading.Event()
        seen: list[set[int]] = []

        def other() -> None:
            with one_blas_thread():
                entered.set()
                leave.wait(10)
                seen.append(_blas_threads())

        with one_blas_thread():
            t = threading.Thread(target=other)
            t.start()
            entered.wait(10)
            with one_blas_thread():
                assert _blas_threads() == {1}
            assert _blas_threads() == {1}
        # this thread left; the other one is still inside its block: still one thread
        assert _blas_threads() == {1}
        leave.set()
        t.join(10)
        assert seen == [{1}]
        assert _blas_settings() == before and set(before.values()) == {2}


def _check_json(design: Path, out: Path, threads: str) -> bytes:
    env = dict(os.environ, OPENBLAS_NUM_THREADS=threads, OMP_NUM_THREADS=threads, MKL_NUM_THREADS=threads)
    subprocess.run([sys.executable, "-m", "mechverify.cli", "check", str(design), "--json", str(out)], env=env,
                   check=False, capture_output=True, timeout=300, cwd=ROOT)
    return out.read_bytes()


def test_solid_bracket_json_identical_in_fresh_processes(tmp_path):
    """`mechverify check --json` of examples/solid_bracket in two fresh processes, one started with one BLAS thread (a
    study worker, the test suite) and one with two (the CLI on a 2-core machine): the same bytes. Before the fix the
    stress demand differed in the 12th digit (81.37694512174657 vs 81.37694512172219 MPa), and with the guard but
    scipy's OpenBLAS missing from its controller the buckling factor (27.096692442685608 vs 27.096692442677195:
    ARPACK on two threads; a coarser mesh did not show it)."""
    design = ROOT / "examples" / "solid_bracket" / "design.toml"
    one = _check_json(design, tmp_path / "one.json", "1")
    two = _check_json(design, tmp_path / "two.json", "2")
    checks = {r["check"] for r in json.loads(one)["designs"][0]["results"]}
    assert {"solid_stress", "solid_deflection", "natural_frequency", "buckling_load_factor"} <= checks
    assert one == two


def test_solid_study_process_pool_equals_serial(tmp_path):
    """A Study over a solid_fea parameter: serial in this process with two BLAS threads (as the CLI runs it) and on
    a process pool whose workers the study pins to one BLAS thread give the same JSON.

    This one passed before the fix too (a regression guard): ``studies.execution.run_batch`` already pins one BLAS
    thread in the serial run as in the workers; the thread count showed in ``mechverify check`` (test above), the
    random AMG hierarchy in solids large enough for CG (test_amg_...). The pool is the default one: gmsh is loaded
    here, so its workers are spawned, not forked (a pool forked from a process that had meshed with gmsh hung:
    tests/test_studies_fork_safety.py)."""
    from mechverify.studies import Study

    design = tmp_path / "bracket.toml"
    design.write_text(BRACKET.format(h="6 mm", extra=""))
    vary = {"components.bracket.deflection_limit": "0.8 mm:1 mm:2", "components.bracket.mesh_size": "6 mm:7 mm:2"}
    with threadpool_limits(2):
        serial = Study(design, vary=vary, batch_size=2).run("serial").to_json()
    pooled = Study(design, vary=vary, batch_size=2).run(workers=2).to_json()
    assert "solid_stress" in serial and "solid_deflection" in serial
    assert pooled == serial


def test_frame_modes_same_bits_with_one_or_two_blas_threads():
    """The frame's eigenvalue analyses (fea/frame/modal.py: ARPACK's shift-invert on OpenBLAS) gave the conveyor's
    drum-shaft critical speed as 9653.451577149817 rad/s with one BLAS thread and 9653.45157715028 with two
    (`mechverify check examples/conveyor_drum --json` under OPENBLAS_NUM_THREADS=1 and =2); frame_modes and
    frame_buckling are @reproducible now. Measured alongside, not varying (no wrapping): plate solve, plate modes
    (their ARPACK start vector is fixed), plate buckling, plane solve (straight and curved elements; direct)."""
    from mechverify.design.design import load

    def speeds() -> list[float]:
        return [r.utilisation for r in load(ROOT / "examples" / "conveyor_drum" / "design.toml").verify()]

    with threadpool_limits(1):
        one = speeds()
    with threadpool_limits(2):
        two = speeds()
    assert one == two
