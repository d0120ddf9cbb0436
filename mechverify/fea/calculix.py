"""Cross-check with CalculiX (``ccx``): write an input deck for the same mesh, run it, read the results,
and prove from ccx's own output that it solved the same model.

The deck uses C3D10 elements (solids) or CPS6/CPE6 (plane stress/strain) on exactly the nodes and
elements of a mechverify model, the same material, the same constrained DOFs and the same nodal load
vector (mechverify's consistent loads written as ``*CLOAD``), so both programs solve the same discrete
problem.

Numbers in the deck: CalculiX reads at most 20 characters per field (ref. 1, sec. 7: free-format
fields; measured with ccx 2.20: a 21-character ``-1.23456789012345e-05`` loses its last exponent digit
and is read as -1.23456789012345, a 22-character coordinate stops ccx with an error). Every float is
written by :func:`fortran_field`: the shortest text that reads back to the same double, or, when that
is longer than 20 characters, the most significant digits that fit (at least 13: relative error
below 5e-14).

Same model, proven: after the run, :func:`verify_same_model` compares what ccx reports - the node
count and every node's coordinates in the ``.frd`` file, and the total force the supports carry
(``*NODE PRINT, TOTALS=ONLY`` of RF over the supported nodes in the ``.dat`` file) - with the
mechverify model, and raises :class:`ModelError` on any difference beyond ccx's output precision.

Node ordering: CalculiX C3D10 numbers corners 1-4, then mid-edge nodes 5:(1,2), 6:(2,3), 7:(3,1),
8:(1,4), 9:(2,4), 10:(3,4) (ref. 1, sec. 6.2.6); scikit-fem's ``ElementTetP2`` numbers 0-3 at the
corners and 4:(0,1), 5:(1,2), 6:(0,2), 7:(0,3), 8:(1,3), 9:(2,3) - the same edges in the same order,
so the map is the identity once every tet is positively oriented (``mesh.orient``). CPS6/CPE6: corners
1-3 counter-clockwise, then 4:(1,2), 5:(2,3), 6:(3,1) (ref. 1, sec. 6.2.3/6.2.5); scikit-fem's
``ElementTriP2`` has 3:(0,1), 4:(1,2), 5:(0,2), again the identity on counter-clockwise triangles
(``mesh2d.orient_triangles``).

References
----------
1. G. Dhondt, CalculiX CrunchiX User's Manual, version 2.20, sections 6.2.3 (CPS6), 6.2.5 (CPE6),
   6.2.6 (C3D10), 7 (input deck keywords: ``*NODE``, ``*CLOAD``,
   ``*NODE PRINT``) and 11 (.frd result format).
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

from mechverify.errors import InputError, ModelError

#: Widest field CalculiX reads (characters).
FIELD_WIDTH = 20

#: Element types the writer knows: nodes per element and displacement components per node.
ELEMENTS = {"C3D10": (10, 3), "CPS6": (6, 2), "CPE6": (6, 2)}


@dataclass(frozen=True)
class CalculixResult:
    """Nodal results read from a ``.frd`` file (SI units, node order of the model).

    ``ip_stress[e, q, 6]`` are the stresses at the integration points of each element in CalculiX
    order (xx, yy, zz, xy, xz, yz) read from the ``.dat`` file, when requested. ``frd_points`` are the
    node coordinates ccx wrote back (5 significant digits), ``support_force`` the total force ccx
    found in the supported nodes (RF totals), both used by :func:`verify_same_model`.
    """

    displacement: np.ndarray  # [n, 3] m
    stress: np.ndarray  # [n, 6] Pa: xx yy zz xy yz zx (frd order)
    ip_stress: np.ndarray | None
    wall_time: float  # s
    peak_memory: float  # bytes (max RSS of the ccx process)
    frd_points: np.ndarray | None = None  # [n, 3] m
    support_force: np.ndarray | None = None  # [3] N


def ccx_path() -> str:
    """Path of the ``ccx`` executable, or a :class:`ModelError` saying how to install it."""
    path = shutil.which("ccx")
    if path is None:
        raise ModelError("CalculiX (ccx) is not installed; install it with `apt-get install calculix-ccx`")
    return path


def fortran_field(value: float, width: int = FIELD_WIDTH) -> str:
    """``value`` as text of at most ``width`` characters that CalculiX reads back exactly or, when the
    exact shortest form is wider, to the most significant digits that fit.

    >>> fortran_field(-1.3877787807814457e-17)
    '-1.3877787807814e-17'
    >>> fortran_field(7.5e-14)
    '7.5e-14'
    """
    v = float(value)
    if not np.isfinite(v):
        raise InputError(f"CalculiX deck: a number is not finite ({v!r})")
    text = repr(v)
    if len(text) <= width:
        return text
    for digits in range(16, 0, -1):
        text = f"{v:.{digits}e}"
        mant, exp = text.split("e")
        mant = mant.rstrip("0").rstrip(".") if "." in mant else mant
        text = f"{mant}e{int(exp)}"
        if len(text) <= width:
            return text
    raise InputError(f"CalculiX deck: {v!r} does not fit a {width}-character field")  # pragma: no cover


def _row(values: Any) -> str:
    return ", ".join(str(v) if isinstance(v, int | np.integer) else fortran_field(v) for v in values)


def write_inp(path: Path, nodes: np.ndarray, elements: np.ndarray, E: float, nu: float,
              fixed_dofs: np.ndarray, loads: np.ndarray, ip_stress: bool = False, *,
              element: str = "C3D10", thickness: float | None = None) -> None:
    """Write a linear static deck.

    ``nodes[n, d]`` (m, d = 2 or 3), ``elements[e, k]`` (0-based, CalculiX order), ``fixed_dofs`` (0-based
    global DOFs ``c*node + component`` with ``c`` = 3 for C3D10, 2 for CPS6/CPE6, held at zero),
    ``loads[c*n]`` nodal forces (N), ``thickness`` (m) of plane elements.
    """
    if element not in ELEMENTS:
        raise InputError(f"CalculiX deck: element type {element!r} is not one of {sorted(ELEMENTS)}")
    nen, c = ELEMENTS[element]
    if elements.shape[1] != nen:
        raise InputError(f"CalculiX deck: {element} has {nen} nodes, the elements have {elements.shape[1]}")
    if c == 2 and (thickness is None or thickness <= 0):
        raise InputError(f"CalculiX deck: {element} needs a positive thickness")
    n = nodes.shape[0]
    xyz = np.zeros((n, 3))
    xyz[:, : nodes.shape[1]] = nodes
    fd = np.asarray(fixed_dofs, int)
    lines = ["*HEADING", "mechverify cross-check", "*NODE, NSET=NALL"]
    lines += [f"{i + 1}, {_row(xyz[i])}" for i in range(n)]
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    lines += [", ".join(str(int(k)) for k in (e + 1, *(elements[e] + 1))) for e in range(elements.shape[0])]
    if fd.size:
        fixed_nodes = np.unique(fd // c) + 1
        lines.append("*NSET, NSET=NFIX")
        lines += [", ".join(str(k) for k in fixed_nodes[i:i + 8]) for i in range(0, fixed_nodes.size, 8)]
    lines += ["*MATERIAL, NAME=MAT", "*ELASTIC", _row((float(E), float(nu)))]
    lines.append("*SOLID SECTION, ELSET=EALL, MATERIAL=MAT")
    if c == 2:
        lines.append(fortran_field(float(thickness)))
    lines += ["*STEP", "*STATIC", "*BOUNDARY"]
    lines += [f"{d // c + 1}, {d % c + 1}, {d % c + 1}" for d in fd]
    loads = np.asarray(loads, float)
    nz = np.flatnonzero(loads)
    if nz.size:
        lines.append("*CLOAD")
        lines += [f"{d // c + 1}, {d % c + 1}, {fortran_field(loads[d])}" for d in nz]
    lines += ["*NODE FILE", "U", "*EL FILE", "S"]
    if fd.size:
        lines += ["*NODE PRINT, NSET=NFIX, TOTALS=ONLY", "RF"]
    if ip_stress:
        lines += ["*EL PRINT, ELSET=EALL", "S"]
    lines.append("*END STEP")
    Path(path).write_text("\n".join(lines) + "\n")


def _ccx_float(text: str) -> float:
    """A number as CalculiX reads it: the first 20 characters of the field, Fortran style (an exponent
    cut to ``e`` or ``e-`` counts as zero)."""
    s = text.strip()[:FIELD_WIDTH].lower().replace("d", "e")
    if s.endswith(("e", "e-", "e+")):
        s = s[: s.index("e")]
    return float(s)


@dataclass(frozen=True)
class Deck:
    """What a CalculiX deck says, read back field by field as ccx reads it (:func:`read_inp`)."""

    nodes: np.ndarray  # [n, 3] m
    elements: np.ndarray  # [e, k] 0-based
    element: str
    fixed_dofs: np.ndarray
    loads: np.ndarray  # [c*n] N


def read_inp(path: Path) -> Deck:
    """Read the keyword blocks this module writes (``*NODE``, ``*ELEMENT``, ``*BOUNDARY``, ``*CLOAD``) back from a deck,
    each number through the 20-character field rule of CalculiX (:func:`_ccx_float`)."""
    nodes: dict[int, list[float]] = {}
    elements: list[list[int]] = []
    fixed: list[tuple[int, int]] = []
    cload: list[tuple[int, int, float]] = []
    element, block = "", ""
    for raw in Path(path).read_text().splitlines():
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            key = line.split(",")[0].upper()
            block = key
            if key == "*ELEMENT":
                element = next(p.split("=")[1].strip() for p in line.split(",") if p.strip().upper().startswith("TYPE"))
            continue
        parts = [p for p in line.split(",") if p.strip()]
        if block == "*NODE":
            nodes[int(parts[0])] = [_ccx_float(p) for p in parts[1:4]]
        elif block == "*ELEMENT":
            elements.append([int(p) - 1 for p in parts[1:]])
        elif block == "*BOUNDARY":
            nd, first, last = int(parts[0]), int(parts[1]), int(parts[2] if len(parts) > 2 else parts[1])
            fixed += [(nd, k) for k in range(first, last + 1)]
        elif block == "*CLOAD":
            cload.append((int(parts[0]), int(parts[1]), _ccx_float(parts[2])))
    c = ELEMENTS.get(element, (0, 3))[1]
    n = max(nodes)
    xyz = np.array([nodes[k] for k in range(1, n + 1)])
    f = np.zeros(c * n)
    for nd, k, v in cload:
        f[c * (nd - 1) + k - 1] += v
    fd = np.array(sorted(c * (nd - 1) + k - 1 for nd, k in fixed), dtype=np.int64)
    return Deck(xyz, np.array(elements, dtype=np.int64), element, fd, f)


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
    xyz, ids = _frd_nodes(path)
    disp: dict[int, list[float]] = {}
    stress: dict[int, list[float]] = {}
    block = None
    with open(path) as fh:
        for line in fh:
            if line.startswith(" -4"):
                block = {"DISP": disp, "STRESS": stress}.get(line[5:13].strip())
            elif line.startswith(" -3"):
                block = None
            elif line.startswith(" -1") and block is not None:
                node = int(line[3:13])
                block[node] = [float(line[13 + 12 * k: 25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
    D = np.array([disp.get(k, [np.nan] * 3)[:3] for k in ids])
    S = np.array([stress.get(k, [np.nan] * 6)[:6] for k in ids])
    return xyz, D, S


def _frd_nodes(path: Path) -> tuple[np.ndarray, list[int]]:
    """Node coordinates ``[m, 3]`` of the ``2C`` block of an ``.frd`` file and their node numbers."""
    ids: list[int] = []
    xyz: list[list[float]] = []
    inside = False
    with open(path) as fh:
        for line in fh:
            if line.startswith("    2C"):
                inside = True
            elif inside and line.startswith(" -3"):
                break
            elif inside and line.startswith(" -1"):
                ids.append(int(line[3:13]))
                xyz.append([float(line[13 + 12 * k: 25 + 12 * k]) for k in range(3)])
    return np.array(xyz).reshape(-1, 3), ids


def read_support_force(path: Path) -> np.ndarray | None:
    """The total reaction force ``[3]`` (N) of ``*NODE PRINT, NSET=NFIX, TOTALS=ONLY`` in a ``.dat`` file."""
    lines = Path(path).read_text(errors="replace").splitlines() if Path(path).exists() else []
    for i, line in enumerate(lines):
        if line.strip().startswith("total force") and "NFIX" in line.upper():
            for nxt in lines[i + 1:]:
                if nxt.strip():
                    return np.array([float(v) for v in nxt.split()[:3]])
    return None


def read_dat_stress(path: Path, ne: int, nq: int = 4) -> np.ndarray:
    """Integration-point stresses ``[e, nq, 6]`` (xx yy zz xy xz yz) from the ``.dat`` file."""
    out = np.full((ne, nq, 6), np.nan)
    with open(path) as fh:
        for line in fh:
            parts = line.split()
            if len(parts) == 8:
                try:
                    e, q = int(parts[0]), int(parts[1])
                    if e <= ne and q <= nq:
                        out[e - 1, q - 1] = [float(v) for v in parts[2:]]
                except ValueError:
                    continue
    return out


def verify_same_model(nodes: np.ndarray, fixed_dofs: np.ndarray, loads: np.ndarray, components: int,
                      result: CalculixResult) -> None:
    """Raise :class:`ModelError` unless ccx's output describes the model that was meant.

    Compared: the number of nodes ccx wrote, every node's coordinates (to the 5 significant digits of
    the ``.frd`` file: tolerance 1e-5 of the model size plus 1e-5 of the coordinate), the bounding box,
    and the total force carried by the supported nodes. That force balances the loads applied to
    the nodes outside the supports (Σ of all nodal internal forces is zero), so it checks what ccx
    read of every load, to the 6-7 digits of the ``.dat`` file.
    """
    pts = np.zeros((nodes.shape[0], 3))
    pts[:, : nodes.shape[1]] = nodes
    size = float(np.linalg.norm(np.ptp(pts, axis=0)))
    got = result.frd_points
    if got is None or got.shape[0] < pts.shape[0]:
        raise ModelError(f"CalculiX ran a different model: it wrote {0 if got is None else got.shape[0]} nodes, "
                         f"the model has {pts.shape[0]}")
    got = got[: pts.shape[0]]
    dev = np.abs(got - pts)
    bad = dev > 1e-5 * size + 1e-5 * np.abs(pts)
    if np.any(bad):
        i = int(np.argmax(np.where(bad, dev, 0).max(axis=1)))
        lo, hi = got.min(axis=0), got.max(axis=0)
        raise ModelError(
            f"CalculiX ran a different model: node {i + 1} is at {got[i].tolist()} m in ccx, {pts[i].tolist()} m in "
            f"the model ({int(bad.any(axis=1).sum())} nodes differ; ccx bounding box {lo.tolist()}-{hi.tolist()} m, "
            f"model {pts.min(axis=0).tolist()}-{pts.max(axis=0).tolist()} m)")
    fd = np.asarray(fixed_dofs, int)
    if fd.size == 0:
        return
    F = np.asarray(loads, float).reshape(-1, components)
    held = np.zeros(F.shape[0], bool)
    held[np.unique(fd // components)] = True
    want = np.zeros(3)
    want[:components] = -F[~held].sum(axis=0)
    R = result.support_force
    scale = max(float(np.abs(F).sum()), 1e-300)
    if R is None:
        raise ModelError("CalculiX ran a different model: its .dat file holds no reaction totals of the supports")
    if np.max(np.abs(R - want)) > 1e-5 * scale:
        raise ModelError(f"CalculiX ran a different model: its supports carry {R.tolist()} N, the model's loads "
                         f"need {want.tolist()} N (loads read wrongly from the deck?)")


def run(nodes: np.ndarray, elements: np.ndarray, E: float, nu: float, fixed_dofs: np.ndarray,
        loads: np.ndarray, ip_stress: bool = False, threads: int = 1, keep: str | Path | None = None, *,
        element: str = "C3D10", thickness: float | None = None, verify: bool = True) -> CalculixResult:
    """Write the deck, run ``ccx`` in a temporary directory, read its results and (``verify``) prove
    with :func:`verify_same_model` that ccx solved this model.

    ``wall_time`` covers the ccx process alone (reading the deck, assembly, SPOOLES solve, stress
    recovery, writing results); ``peak_memory`` is its maximum resident set size.
    """
    ccx_path()
    with tempfile.TemporaryDirectory(prefix="mv-ccx-") as tmp:
        work = Path(keep) if keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        write_inp(work / "job.inp", nodes, elements, E, nu, fixed_dofs, loads, ip_stress, element=element,
                  thickness=thickness)
        return run_deck(work, nodes.shape[0], elements.shape[0], ip_stress, threads, check=(
            (nodes, fixed_dofs, loads, ELEMENTS[element][1]) if verify else None),
            nq=4 if element == "C3D10" else 3)


def run_deck(work: Path, n: int, ne: int, ip_stress: bool = False, threads: int = 1,
             check: tuple[np.ndarray, np.ndarray, np.ndarray, int] | None = None, nq: int = 4) -> CalculixResult:
    """Run ccx on ``work/job.inp`` and read its results (``check``: nodes, fixed DOFs, loads, components
    per node of the model meant, for :func:`verify_same_model`)."""
    exe = ccx_path()
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
    disp, stress = read_frd(frd, n)
    xyz, _ = _frd_nodes(frd)
    ips = read_dat_stress(work / "job.dat", ne, nq) if ip_stress else None
    out = CalculixResult(disp, stress, ips, wall, ru.ru_maxrss * 1024.0, xyz, read_support_force(work / "job.dat"))
    if check is not None:
        verify_same_model(*check, out)
    return out


def run_model(model: Any, ip_stress: bool = False, threads: int = 1, keep: str | Path | None = None) -> CalculixResult:
    """Run a :class:`mechverify.fea.solid.SolidModel` or :class:`mechverify.fea.plane.PlaneModel` through
    CalculiX on the same mesh and loads (C3D10, or CPS6/CPE6 of the model's thickness), verified to be
    the same model (:func:`verify_same_model`)."""
    mat = model.material
    E, nu = mat.E.m_as("Pa"), mat.nu.m_as("")
    if hasattr(model, "plane"):  # PlaneModel
        b = model.basis
        return run(model.nodes.T, b.element_dofs.T, E, nu, model.held_dofs(), model.load_vector(), ip_stress=ip_stress,
                   threads=threads, keep=keep, element="CPS6" if model.plane == "stress" else "CPE6",
                   thickness=model.thickness_si)
    mesh = model.mesh
    return run(model.nodes.T, mesh.basis.element_dofs.T, E, nu, model.held_dofs(), model.load_vector(),
               ip_stress=ip_stress, threads=threads, keep=keep)
