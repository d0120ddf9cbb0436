"""CalculiX cross-checks of the eigenvalue analyses: ``*FREQUENCY`` (natural frequencies) and ``*BUCKLE``
(linear buckling factors) on exactly the mesh, material, supports and loads of a mechverify model.

The deck is the static deck of :func:`mechverify.fea.calculix.write_inp` (same nodes, C3D10/CPS6/CPE6
elements, constrained DOFs, ``*CLOAD`` of mechverify's consistent load vector) with ``*DENSITY`` added to
the material and the ``*STATIC`` step replaced by ``*FREQUENCY`` (n eigenvalues) or ``*BUCKLE`` (n buckling
factors for the loads of the step). The eigenvalues are read from the ``.dat`` file's
"E I G E N V A L U E   O U T P U T" or "B U C K L I N G   F A C T O R   O U T P U T" tables.

References
----------
1. G. Dhondt, CalculiX CrunchiX User's Manual, version 2.20, sections 7 (``*FREQUENCY``, ``*BUCKLE``,
   ``*DENSITY``) and 11 (.dat output).
"""

from __future__ import annotations

import re
import resource
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from mechverify.errors import ModelError
from mechverify.fea import calculix as cx


def _deck(model: Any, work: Path, step: str, n: int, loads: bool) -> tuple[int, int]:
    mat = model.material
    E, nu = mat.E.m_as("Pa"), mat.nu.m_as("")
    rho = mat.require("density").m_as("kg/m**3")
    plane = hasattr(model, "plane")
    ed = model.basis.element_dofs if plane else model.mesh.basis.element_dofs
    held = model.held_dofs() if model.supports else np.empty(0, int)
    f = model.load_vector() if loads else np.zeros(model.nodes.size)
    element = ("CPS6" if model.plane == "stress" else "CPE6") if plane else "C3D10"
    cx.write_inp(work / "job.inp", model.nodes.T, ed.T, E, nu, held, f, element=element,
                 thickness=model.thickness_si if plane else None)
    text = (work / "job.inp").read_text()
    elastic = "*ELASTIC\n" + text.split("*ELASTIC\n", 1)[1].split("\n", 1)[0] + "\n"
    text = text.replace(elastic, elastic + "*DENSITY\n" + cx.fortran_field(rho) + "\n", 1)
    text = text.replace("*STATIC\n", f"{step}\n{n}\n", 1)
    text = text.replace("*NODE PRINT, NSET=NFIX, TOTALS=ONLY\nRF\n", "")
    (work / "job.inp").write_text(text)
    return model.nodes.shape[1], ed.shape[1]


#: CPU time [s] (user + system, all threads) of the last ccx run of this process (:func:`frequencies`,
#: :func:`buckling_factors`): on a loaded machine the wall times of two programs compare badly, their CPU
#: times better.
last_cpu_seconds: float = 0.0


def _run(model: Any, step: str, n: int, loads: bool, keep: str | Path | None,
         threads: int = 1) -> tuple[np.ndarray, float, float]:
    """ccx's eigenvalue table, wall time [s] and peak memory [bytes] (CPU time: :data:`last_cpu_seconds`)."""
    global last_cpu_seconds
    with tempfile.TemporaryDirectory(prefix="mv-ccx-") as tmp:
        work = Path(keep) if keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        nn, ne = _deck(model, work, step, n, loads)
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        res = cx.run_deck(work, nn, ne, threads=threads)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        last_cpu_seconds = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
        dat = (work / "job.dat").read_text()
    return _table(dat, step), res.wall_time, res.peak_memory


def _table(dat: str, step: str) -> np.ndarray:
    title = "E I G E N V A L U E   O U T P U T" if step == "*FREQUENCY" else "B U C K L I N G   F A C T O R"
    if title not in dat:
        raise ModelError(f"CalculiX wrote no {title!r} table")
    body = dat.split(title, 1)[1]
    rows = []
    for line in body.splitlines():
        nums = re.findall(r"[-+]?\d+\.?\d*(?:[EeDd][-+]?\d+)?", line)
        if len(nums) >= 2 and re.match(r"^\s*\d+\s", line):
            rows.append([float(x.replace("D", "E")) for x in nums])
        elif rows and not line.strip():
            break
    if not rows:
        raise ModelError(f"CalculiX's {title!r} table is empty")
    return np.array([r[:5] for r in rows if len(r) >= 2], dtype=object)


def frequencies(model: Any, n_modes: int, keep: str | Path | None = None, threads: int = 1,
                with_memory: bool = False) -> tuple[np.ndarray, float] | tuple[np.ndarray, float, float]:
    """CalculiX's first ``n_modes`` natural frequencies [Hz] of ``model`` and ccx's wall time [s] (``threads``
    for its equation solver; ``with_memory``: also ccx's peak memory [bytes])."""
    tab, wall, peak = _run(model, "*FREQUENCY", n_modes, False, keep, threads)
    # columns: mode, eigenvalue (rad²/s²), real part (rad/s), cycles/time (Hz), imaginary part
    f = np.array([float(r[3]) for r in tab])
    return (f, wall, peak) if with_memory else (f, wall)


def buckling_factors(model: Any, n_modes: int, keep: str | Path | None = None, threads: int = 1,
                     with_memory: bool = False) -> tuple[np.ndarray, float] | tuple[np.ndarray, float, float]:
    """CalculiX's first ``n_modes`` buckling factors of ``model``'s loads and ccx's wall time [s] (``threads``,
    ``with_memory`` as in :func:`frequencies`)."""
    tab, wall, peak = _run(model, "*BUCKLE", n_modes, True, keep, threads)
    mu = np.array([float(r[1]) for r in tab])
    return (mu, wall, peak) if with_memory else (mu, wall)
