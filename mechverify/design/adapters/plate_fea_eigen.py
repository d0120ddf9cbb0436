"""``plate_fea``'s eigenvalue checks (split from :mod:`mechverify.design.adapters.plate_fea`, which parses the
component): ``natural_frequency`` on two or three meshes with the frequencies extrapolated per mode
(:func:`mechverify.fea.plate_convergence.modal_convergence`) and ``buckling_load_factor`` per in-plane load case.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from mechverify.checks import fea as feac
from mechverify.checks.result import CheckResult
from mechverify.components import plates as pl
from mechverify.errors import MechverifyError

#: The convergence meshes have elements this many times smaller each (as solid_fea's two-mesh check).
REFINE = 1.5


def frequency(c: Any, loads: Any, ctx: Any) -> CheckResult | list[CheckResult]:
    """natural_frequency on the design's mesh and meshes REFINE (and, with convergence_check, REFINE²) times finer:
    the frequencies extrapolated per mode (fea.plate_convergence.modal_convergence); the more critical of the finest
    mesh's and the extrapolated frequencies decides (review 3 finding 2: clamped plates 4-21 % low by default)."""
    if c.modal is None:  # natural_frequency runs when min_frequency or excitation_band is given
        return []
    from mechverify.fea.plate_convergence import modal_convergence
    from mechverify.fea.plate_modal import plate_modes

    model = pl.PlateModel(c.plate, c.supports)
    runs = [c.modal.solve(plate_modes, model, c.mesh_size, c.hole_mesh_size, refine=REFINE**k,
                          hint="lower mesh_size (finer mesh) or ask fewer modes")
            for k in range(2 if c.convergence is None else 3)]
    ext, notes, warns = modal_convergence(runs, REFINE, c.tolerance, deciding=deciding_modes(c.modal, runs[-1],
                                                                                            c.tolerance))
    fine, best = c.modal.check(runs[-1], c.name), c.modal.check(ext, c.name)
    r, which = (best, "extrapolated") if best.utilisation >= fine.utilisation else (fine, "finest mesh's")
    return dataclasses.replace(r, notes=(f"the {which} frequencies decide (the more critical of the finest mesh's "
                                         "and the extrapolated)", *notes, *r.notes),
                               warnings=(*r.warnings, *warns))


def deciding_modes(modal: Any, res: Any, tolerance: float) -> set[int]:
    """The mode numbers (1-based, rigid-body modes counted) the natural_frequency verdict of ``res`` depends on:
    the first elastic mode for a minimum; for an excitation band the modes within the band widened by the margin
    and, for the mesh error, by the tolerance on each side, the nearest mode below and above it, and the highest
    computed one (it says whether more modes are needed)."""
    rb = res.rigid_body_modes
    f = np.asarray(res.frequencies.m_as("Hz"), dtype=float)
    if modal.band is None or len(f) <= rb:
        return {rb + 1}
    lo, hi = (b.m_as("Hz") for b in modal.band)
    below, above = lo / (1 + modal.margin) * (1 - tolerance), hi * (1 + modal.margin) * (1 + tolerance)
    k = np.arange(rb, len(f))
    near = {int(i) + 1 for i in k[(f[rb:] >= below) & (f[rb:] <= above)]}
    under, over = k[f[rb:] < below], k[f[rb:] > above]
    near |= {int(under[-1]) + 1} if len(under) else set()
    near |= {int(over[0]) + 1} if len(over) else set()
    return near | {len(f)}


def buckling(c: Any, loads: Any, ctx: Any) -> list[CheckResult]:
    """buckling_load_factor of every load case that gives in_plane edge loads (lateral loads cause no membrane
    force); none: the check does not run. A case whose in-plane load compresses nothing passes with a note."""
    from mechverify.fea.frame.modal import NoCompressionError
    from mechverify.fea.plate_buckling import plate_buckling

    out = []
    for case, comps in ctx.design.data.load_cases.items():
        if "in_plane" in (comps.get(c.name) or {}):
            path = f"load_cases.{case}.{c.name}.in_plane"
            load = c.in_plane(comps[c.name], case)
            try:
                res = plate_buckling(pl.PlateModel(c.plate, c.supports), load, 3, c.mesh_size, c.hole_mesh_size,
                                     in_plane_supports=c.in_plane_supports)
            except NoCompressionError as exc:  # a pull: the envelope is governed by the compressive cases
                out.append(feac.no_buckling_result(float("inf"), str(exc), component=c.name, load_case=case))
                continue
            except MechverifyError as exc:
                raise type(exc)(f"{path}: {exc}") from None
            r = feac.check_buckling_load_factor(res, component=c.name, load_case=case)
            bound = [n for n in res.notes if n.startswith("LOWER BOUND")]  # fea.plate_buckling._lower_bound
            out.append(dataclasses.replace(r, notes=(*bound, *r.notes)) if bound else r)
    return out
