"""Cross-check with CalculiX (``ccx``): write an input deck for the same mesh, run it, read the results.

The deck uses C3D10 elements on exactly the nodes and elements of a mechverify solid model, the
same material, the same constrained DOFs and the same nodal load vector (mechverify's consistent
loads written as ``*CLOAD``), so both programs solve the same discrete problem.

Node ordering: CalculiX C3D10 numbers corners 1-4, then mid-edge nodes 5:(1,2), 6:(2,3), 7:(3,1),
8:(1,4), 9:(2,4), 10:(3,4) (CalculiX 2.20 User's Manual, sec. 6.2.6). scikit-fem's
``ElementTetP2`` numbers its local DOFs 0-3 at the corners and 4:(0,1), 5:(1,2), 6:(0,2), 7:(0,3),
8:(1,3), 9:(2,3) - the same edges in the same order, so the map is the identity once every tet is
positively oriented (mechverify meshes are, see ``mesh.orient``).

References
----------
1. G. Dhondt, CalculiX CrunchiX User's Manual, version 2.20, sections 6.2.6 (C3D10), 7 (input
   deck keywords) and 11 (.frd result format).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from mechverify.errors import ModelError


@dataclass(frozen=True)
class CalculixResult:
    """Nodal results read from a ``.frd`` file (SI units, node order of the model).

    ``ip_stress[e, q, 6]`` are the stresses at the 4 integration points of each element in
    CalculiX order (xx, yy, zz, xy, xz, yz) read from the ``.dat`` file, when requested.
    """

    displacement: np.ndarray  # [n, 3] m
    stress: np.ndarray  # [n, 6] Pa: xx yy zz xy yz zx (frd order)
    ip_stress: np.ndarray | None
    wall_time: float  # s
    peak_memory: float  # bytes (max RSS of the ccx process)


def ccx_path() -> str:
    """Path of the ``ccx`` executable, or a :class:`ModelError` saying how to install it."""
    path = shutil.which("ccx")
    if path is None:
        raise ModelError("CalculiX (ccx) is not installed; install it with `apt-get install calculix-ccx`")
    return path


def write_inp(path: Path, nodes: np.ndarray, elements: np.ndarray, E: float, nu: float,
              fixed_dofs: np.ndarray, loads: np.ndarray, ip_stress: bool = False) -> None:
    """Write a linear static C3D10 deck.

    ``nodes[n, 3]`` (m), ``elements[e, 10]`` (0-based, CalculiX order), ``fixed_dofs`` (0-based
    global DOFs 3*node+component, held at zero), ``loads[3n]`` nodal forces (N).
    """
    n = nodes.shape[0]
    with open(path, "w") as fh:
        fh.write("*HEADING\nmechverify cross-check\n*NODE, NSET=NALL\n")
        ids = np.arange(1, n + 1)
        np.savetxt(fh, np.column_stack([ids, nodes]), fmt=["%d", "%.17g", "%.17g", "%.17g"], delimiter=", ")
        fh.write("*ELEMENT, TYPE=C3D10, ELSET=EALL\n")
        eids = np.arange(1, elements.shape[0] + 1)
        np.savetxt(fh, np.column_stack([eids, elements + 1]), fmt="%d", delimiter=", ")
        fh.write(f"*MATERIAL, NAME=MAT\n*ELASTIC\n{E:.17g}, {nu:.17g}\n")
        fh.write("*SOLID SECTION, ELSET=EALL, MATERIAL=MAT\n")
        fh.write("*STEP\n*STATIC\n*BOUNDARY\n")
        fd = np.asarray(fixed_dofs, int)
        np.savetxt(fh, np.column_stack([fd // 3 + 1, fd % 3 + 1, fd % 3 + 1]), fmt="%d", delimiter=", ")
        nz = np.flatnonzero(loads)
        if nz.size:
            fh.write("*CLOAD\n")
            for d in nz:
                fh.write(f"{d // 3 + 1}, {d % 3 + 1}, {loads[d]:.17g}\n")
        fh.write("*NODE FILE\nU\n*EL FILE\nS\n")
        if ip_stress:
            fh.write("*EL PRINT, ELSET=EALL\nS\n")
        fh.write("*END STEP\n")


def read_frd(path: Path, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Displacements ``[n,3]`` and nodal stresses ``[n,6]`` from an ASCII ``.frd`` file (ref. 1, sec. 11)."""
    disp = np.zeros((n, 3))
    stress = np.zeros((n, 6))
    block = None
    with open(path) as fh:
        for line in fh:
            if line.startswith(" -4"):
                name = line[5:13].strip()
                block = {"DISP": disp, "STRESS": stress}.get(name)
            elif line.startswith(" -1") and block is not None:
                node = int(line[3:13])
                if node > n:  # nodes CalculiX added itself (expanded shells, knots)
                    continue
                vals = [float(line[13 + 12 * k: 25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
                block[node - 1, : len(vals)] = vals[: block.shape[1]]
            elif line.startswith(" -3"):
                block = None
    return disp, stress


def read_frd_expanded(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """All nodes of an ASCII ``.frd`` with coordinates: ``(xyz[m, 3], disp[m, 3], stress[m, 6])``.

    Shell elements are written on the nodes CalculiX expands them to (bottom, middle and top
    surface, ref. 1 sec. 6.2.12), which do not exist in the input deck; match them by coordinates.
    """
    ids: dict[int, int] = {}
    xyz: list[list[float]] = []
    disp: dict[int, list[float]] = {}
    stress: dict[int, list[float]] = {}
    block = None
    with open(path) as fh:
        for line in fh:
            if line.startswith("    2C"):
                block = "nodes"
            elif line.startswith(" -4"):
                block = {"DISP": disp, "STRESS": stress}.get(line[5:13].strip())
            elif line.startswith(" -3"):
                block = None
            elif line.startswith(" -1") and block is not None:
                node = int(line[3:13])
                vals = [float(line[13 + 12 * k: 25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
                if block == "nodes":
                    ids[node] = len(xyz)
                    xyz.append(vals[:3])
                else:
                    block[node] = vals
    order = sorted(ids, key=ids.get)
    D = np.array([disp.get(k, [np.nan] * 3)[:3] for k in order])
    S = np.array([stress.get(k, [np.nan] * 6)[:6] for k in order])
    return np.array(xyz), D, S


def read_dat_stress(path: Path, ne: int) -> np.ndarray:
    """Integration-point stresses ``[e, 4, 6]`` (xx yy zz xy xz yz) from the ``.dat`` file."""
    out = np.full((ne, 4, 6), np.nan)
    with open(path) as fh:
        for line in fh:
            parts = line.split()
            if len(parts) == 8:
                try:
                    e, q = int(parts[0]), int(parts[1])
                    out[e - 1, q - 1] = [float(v) for v in parts[2:]]
                except ValueError:
                    continue
    return out


def run(nodes: np.ndarray, elements: np.ndarray, E: float, nu: float, fixed_dofs: np.ndarray,
        loads: np.ndarray, ip_stress: bool = False, threads: int = 1, keep: str | Path | None = None) -> CalculixResult:
    """Write the deck, run ``ccx`` in a temporary directory and read its results.

    ``wall_time`` covers the ccx process alone (reading the deck, assembly, SPOOLES solve, stress
    recovery, writing results); ``peak_memory`` is its maximum resident set size.
    """
    exe = ccx_path()
    with tempfile.TemporaryDirectory(prefix="mv-ccx-") as tmp:
        work = Path(keep) if keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        write_inp(work / "job.inp", nodes, elements, E, nu, fixed_dofs, loads, ip_stress)
        env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_EQUATION_SOLVER=str(threads),
                   CCX_NPROC_STIFFNESS=str(threads), CCX_NPROC_RESULTS=str(threads))
        with open(work / "ccx.log", "w") as logfh:
            t0 = time.perf_counter()
            proc = subprocess.Popen([exe, "-i", "job"], cwd=work, env=env, stdout=logfh, stderr=subprocess.STDOUT)
            _, _, ru = os.wait4(proc.pid, 0)
            wall = time.perf_counter() - t0
            proc.returncode = 0
        log = (work / "ccx.log").read_text(errors="replace")
        frd = work / "job.frd"
        if not frd.exists() or "*ERROR" in log:
            tail = "\n".join(line for line in log.splitlines() if "ERROR" in line)[:2000]
            raise ModelError(f"CalculiX failed: {tail or log[-2000:]}")
        disp, stress = read_frd(frd, nodes.shape[0])
        ips = read_dat_stress(work / "job.dat", elements.shape[0]) if ip_stress else None
    peak = ru.ru_maxrss * 1024.0  # Linux reports kilobytes
    return CalculixResult(disp, stress, ips, wall, peak)


def run_model(model: Any, ip_stress: bool = False, threads: int = 1) -> CalculixResult:
    """Run a :class:`mechverify.fea.solid.SolidModel` through CalculiX on the same mesh and loads."""
    mesh = model.mesh
    mat = model.material
    return run(mesh.points.T, mesh.basis.element_dofs.T, mat.E.m_as("Pa"), mat.nu.m_as(""), model.held_dofs(),
               model.load_vector(), ip_stress=ip_stress, threads=threads)
