"""Shared helpers of the FEA benchmarks against CalculiX (``fea_vs_calculix.py``, ``fea_thin_plate.py``,
``fea_modal.py``): the gmsh block-with-a-hole parts, a mesh near a target DOF count, the mesh hand-over to a
child process (so each side's peak memory is its own), and CalculiX runs with 1 and 2 threads, the faster counts.

- :data:`LUG` - 120 x 40 x 30 mm steel block, 16 mm through-hole at (100, 20) mm, 5 kN down on the hole's wall.
- :data:`PLATE` - 200 x 100 x 6 mm steel plate, 20 mm hole at (150, 50) mm, 500 N down on the hole's wall.

Both are clamped at x = 0 (named region ``clamp``; the load acts on ``hole``).
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"


@dataclass(frozen=True)
class Part:
    """A box ``size`` [m] with a through-hole along z (centre ``hole[:2]``, radius ``hole[2]``) [m], clamped at
    x = 0 and loaded by ``force`` on the hole's wall; ``h_of(target)`` is the first element size tried for a
    target DOF count, ``tolerance`` the accepted relative miss of the DOF count."""

    name: str
    size: tuple[float, float, float]
    hole: tuple[float, float, float]
    force: tuple[str, str, str]
    h_of: Any
    tolerance: float


LUG = Part("lug", (0.12, 0.04, 0.03), (0.1, 0.02, 0.008), ("0 N", "0 N", "-5 kN"),
           lambda target: 0.12 * (target / 3.0 / 4.0) ** (-1 / 3) * 0.9, 0.08)
PLATE = Part("plate", (0.2, 0.1, 0.006), (0.15, 0.05, 0.01), ("0 N", "0 N", "-500 N"),
             lambda target: (0.2 * 0.1 * 0.006 * 40 / target) ** (1 / 3), 0.1)


def part_mesh(part: Part, h: float):
    """gmsh P2 mesh of ``part`` with element size ``h`` [m]; named regions ``clamp`` and ``hole``."""
    from mechverify.fea import mesh

    gmsh = mesh.import_gmsh()
    mesh.gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        (sx, sy, sz), (cx, cy, r) = part.size, part.hole
        block = occ.addBox(0, 0, 0, sx, sy, sz)
        hole = occ.addCylinder(cx, cy, -0.01, 0, 0, sz + 0.02, r)
        occ.cut([(3, block)], [(3, hole)])
        occ.synchronize()
        clamp, wall = [], []
        for _, tag in gmsh.model.getEntities(2):
            com = occ.getCenterOfMass(2, tag)
            if abs(com[0]) < 1e-9:
                clamp.append(tag)
            elif abs(com[0] - cx) < 1e-6 and abs(com[1] - cy) < 1e-6:
                wall.append(tag)
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, clamp), "clamp")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, wall), "hole")
        gmsh.model.addPhysicalGroup(3, [e[1] for e in gmsh.model.getEntities(3)])
        gmsh.model.mesh.generate(3)
        return mesh.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def mesh_for(part: Part, target: int):
    """Mesh of ``part`` whose DOF count is within ``part.tolerance`` of ``target`` (up to four tries)."""
    return sized_mesh(part, target)[0]


def sized_mesh(part: Part, target: int) -> tuple[Any, dict]:
    """:func:`mesh_for` and the :func:`timed_mesh` record of the mesh it kept."""
    h = part.h_of(target)
    for _ in range(4):
        m, info = timed_mesh(part, h)
        ratio = m.n_dofs / target
        if abs(ratio - 1) < part.tolerance:
            break
        h *= ratio ** (1 / 3)
    return m, info


def timed_mesh(part: Part, h: float) -> tuple[Any, dict]:
    """:func:`part_mesh` with element size ``h`` [m] and what it cost: CPU seconds of gmsh and of the sliver repair
    (``fea.meshquality.remove_slivers``, timed again on gmsh's raw tetrahedra), the slivers removed, the worst
    quality before and after."""
    import time

    from mechverify.fea.meshquality import remove_slivers

    c0 = time.process_time()
    m = part_mesh(part, h)
    total = time.process_time() - c0
    info = {"h_mm": h * 1e3, "mesh_cpu": total, "slivers_removed": m.slivers_removed,
            "worst_quality": m.worst_quality}
    if m.slivers_removed:
        raw = part_mesh_raw(part, h)
        c0 = time.process_time()
        fixed = remove_slivers(raw.mesh.p, raw.mesh.t)
        info.update(repair_cpu=time.process_time() - c0, worst_quality_gmsh=fixed.worst_before,
                    dofs_gmsh=raw.n_dofs)
    return m, info


def part_mesh_raw(part: Part, h: float):
    """:func:`part_mesh` read without the sliver repair (gmsh's own tetrahedra)."""
    from mechverify.fea import mesh

    original = mesh.from_gmsh_model
    mesh.from_gmsh_model = lambda gmsh: original(gmsh, repair=False)
    try:
        return part_mesh(part, h)
    finally:
        mesh.from_gmsh_model = original


def model_of(part: Part, m):
    """The static model: steel, ``clamp`` fixed, ``part.force`` on ``hole``."""
    from mechverify.fea.loads import Fixed, Force
    from mechverify.fea.regions import Named
    from mechverify.fea.solid import SolidModel

    return SolidModel(m, "Structural Steel", supports=(Fixed(Named("clamp")),),
                      loads=(Force(Named("hole"), part.force),))


def save_mesh(m, path: str | Path) -> None:
    """Write the mesh (points, tets, named regions) for a child process."""
    np.savez(path, points=m.mesh.p.T, tets=m.mesh.t.T, **{f"named_{k}": v for k, v in m.named.items()})


def load_mesh(path: str | Path):
    """The mesh written by :func:`save_mesh`, with its P2 numbering built (not timed by the callers)."""
    from mechverify.fea import mesh

    data = np.load(path, allow_pickle=False)
    named = {k[6:]: data[k] for k in data.files if k.startswith("named_")}
    m = mesh.from_arrays(data["points"], data["tets"], named)
    _ = m.basis  # P2 numbering is mesh bookkeeping shared with the writer of the ccx deck
    return m


def peak_rss() -> int:
    """This process's peak resident memory [bytes]."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def run_child(script: str | Path, *args: str) -> dict:
    """Run ``python script --child args...`` and return the JSON of its last output line."""
    r = subprocess.run([sys.executable, str(script), "--child", *map(str, args)], capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError(f"{Path(script).name} child failed:\n{r.stderr[-3000:]}")
    return json.loads(r.stdout.strip().splitlines()[-1])


def children_cpu() -> float:
    """CPU seconds (user + system) of this process's finished children so far."""
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def ccx_static(model, threads: list[int], u: np.ndarray | None = None) -> dict:
    """CalculiX on the model's deck with each thread count: ``{"calculix": {threads: {wall, cpu, peak}},
    "ccx_threads": best, "best": {...}, "max_displacement_difference": ...}`` (the last against ``u``; ``cpu`` the
    ccx process's user + system seconds, all threads: on the loaded shared box the steadier measure)."""
    from mechverify.fea import calculix

    runs, diff = {}, None
    for t in threads:
        c0 = children_cpu()
        r = calculix.run_model(model, threads=t)
        runs[t] = {"wall": r.wall_time, "cpu": children_cpu() - c0, "peak": r.peak_memory}
        if u is not None:
            diff = float(np.abs(r.displacement - u).max() / np.abs(u).max())
    best = min(runs, key=lambda k: runs[k]["wall"])
    return {"calculix": runs, "ccx_threads": best, "best": runs[best], "max_displacement_difference": diff}


def load_average() -> float:
    """The 1-minute load average (timings on the shared box are noisy: record it with every row)."""
    return os.getloadavg()[0]


def write_rows(rows: list[dict], out: str | Path) -> None:
    """Write the benchmark's rows as JSON (after every row, so a long run keeps what it measured)."""
    Path(out).parent.mkdir(parents=True, exist_ok=True)
    Path(out).write_text(json.dumps(rows, indent=2, default=str))
