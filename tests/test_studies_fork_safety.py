"""A study's default process pool after gmsh was used in the same process (issue 19, task 19f).

gmsh's OpenCASCADE kernel keeps a pool of worker threads made by its first parallel call; a process forked
after that inherits the pool but not the threads, and its first mesh waited for them forever (a process-pool
study after a serial solid_fea study hung at 0 % CPU; mechverify/fea/gmshstate.py). The default pool now
starts its workers fresh (spawn) once gmsh is loaded, without re-running the caller's script, and forks
otherwise. No published numbers here: the pool's result is compared with the serial one, bit for bit.
"""

from __future__ import annotations

import json
import multiprocessing
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from mechverify.studies import execution

ROOT = Path(__file__).resolve().parents[1]

BRACKET = """
[design]
name = "solid bracket, coarse"

[requirements.safety_factors]
static = 1.5

[components.bracket]
type = "solid_fea"
box = "120, 40, 10"
holes = [{ center = "15, 10", diameter = "8.5 mm" }, { center = "15, 30", diameter = "8.5 mm" }]
material = "Inventor Aluminum 6061"
mesh_size = "8 mm"
supports = [{ named = "hole0" }, { named = "hole1" }]
deflection_limit = "1 mm"

[load_cases.service.bracket]
forces = [{ named = "xmax", force = "-2000, 0, -300" }]
"""

# A script as a user writes it: the study at the top level, no ``if __name__ == "__main__"`` guard (spawn or a
# fork server would run it again in every worker), a serial solid_fea study first, then the default pool.
SCRIPT = """
import json, sys
from mechverify.studies import Study
vary = {{"components.bracket.deflection_limit": "0.8 mm:1 mm:2"}}
serial = Study({design!r}, vary=vary).run("serial")
pooled = Study({design!r}, vary=vary).run(workers=2)
print(json.dumps({{"serial": serial.to_json(), "pooled": pooled.to_json(), "gmsh": "gmsh" in sys.modules}}))
"""


def test_pool_study_after_a_serial_solid_study_in_one_process(tmp_path):
    """Before the fix the pool's workers hung in gmsh.model.mesh.generate (the timeout fails the test instead of
    hanging the suite); now the pool's JSON equals the serial one."""
    pytest.importorskip("gmsh")
    design = tmp_path / "bracket.toml"
    design.write_text(BRACKET)
    script = tmp_path / "study.py"
    script.write_text(SCRIPT.format(design=str(design)))
    try:
        run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=240,
                             cwd=tmp_path)
    except subprocess.TimeoutExpired:
        pytest.fail("the process-pool study after a serial solid_fea study hung (workers forked after gmsh)")
    assert run.returncode == 0, run.stderr[-2000:]
    out = json.loads(run.stdout.strip().splitlines()[-1])
    assert out["gmsh"]
    serial = json.loads(out["serial"])
    assert [s["status"] for s in serial["samples"]] == ["ok", "ok"]
    assert "bracket.solid_deflection" in serial["checks"]
    assert out["pooled"] == out["serial"]


def test_start_method_follows_gmsh(monkeypatch):
    """Without gmsh in the process the pool forks (fast; workers inherit the built designs); with it, a fresh
    interpreter that does not import the caller's __main__ (unless the task itself lives there)."""
    if multiprocessing.get_start_method() != "fork":
        pytest.skip("the platform's default start method is not fork")
    monkeypatch.delitem(sys.modules, "gmsh", raising=False)
    assert execution.fork_is_safe()
    pool = execution.process_pool(1)
    try:
        assert pool._mp_context.get_start_method() == "fork"
    finally:
        pool.shutdown()
    monkeypatch.setitem(sys.modules, "gmsh", object())
    assert not execution.fork_is_safe()
    pool = execution.process_pool(1, task=execution.run_batch)
    try:
        assert pool._mp_context.get_start_method() == "spawn"
        assert pool._mp_context.Process is execution._MainlessProcess
        assert pool.submit(execution.one_blas_thread).result(timeout=120) is None  # a worker starts and answers
    finally:
        pool.shutdown()

    def task() -> None:  # (a task defined in the caller's script keeps that script importable)
        return None

    task.__module__ = "__main__"
    pool = execution.process_pool(1, task=task)
    try:
        assert pool._mp_context.Process is multiprocessing.context.SpawnProcess
    finally:
        pool.shutdown()


def test_mainless_spawn_does_not_run_the_callers_script(tmp_path):
    """A guard-less script that starts the spawn pool: the workers must not run the script again (with Python's
    own spawn each worker re-imports it as __mp_main__: the marker file would get three lines)."""
    marker = tmp_path / "ran.txt"
    script = tmp_path / "guardless.py"
    script.write_text(textwrap.dedent(f"""
        import concurrent.futures as cf, os
        from mechverify.studies import execution
        with open({str(marker)!r}, "a") as fh:
            fh.write(str(os.getpid()) + "\\n")
        with cf.ProcessPoolExecutor(2, mp_context=execution.MainlessSpawnContext()) as pool:
            print(list(pool.map(abs, [-1, -2, -3])))
    """))
    run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-2000:]
    assert run.stdout.strip() == "[1, 2, 3]"
    assert len(marker.read_text().split()) == 1
