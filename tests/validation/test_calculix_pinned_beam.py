"""Cross-check of the pin support (:class:`mechverify.fea.loads.PinSupport`) against CalculiX 2.20 (ccx) on the
identical mesh.

Source: G. Dhondt, CalculiX CrunchiX User's Manual 2.20 - the ``*TRANSFORM, TYPE=C`` keyword (a cylindrical local
system given by two points on its axis: local direction 1 radial, 2 tangential, 3 axial) with ``*BOUNDARY`` on
local DOF 1 (and 3 for ``axial = true``) on each pinned wall's nodes; C3D10 elements. This is the model the pin
support claims to be (a frictionless, bilateral pin: radial held, tangential free), solved by ccx itself on the same
nodes, elements, material and nodal loads (mechverify's consistent load vector written as ``*CLOAD``; the loads sit
away from the walls, so their axes do not matter). The axis written to ccx is mechverify's fitted one (for the
block's holes it is the hole's axis to round-off: ``tests/test_fea_solid_pin.py``). The same discrete problem must
give the same displacements, to ccx's output precision (measured 1.6e-6 of the largest displacement).
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest

from mechverify.fea import calculix, mesh, solid
from mechverify.fea.loads import Force, PinSupport
from mechverify.fea.regions import Box, Named
from mechverify.units import Q

pytestmark = [pytest.mark.ccx, pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) not installed")]


def _pinned_deck(model, work: Path) -> None:
    """The model's deck (``calculix.write_inp`` without held DOFs) with each pin's wall node set, its cylindrical
    ``*TRANSFORM`` and the radial (and axial) boundary conditions in that system."""
    m = model.mesh
    calculix.write_inp(work / "job.inp", model.nodes.T, m.basis.element_dofs.T, model.material.E.m_as("Pa"),
                       model.material.nu.m_as(""), np.empty(0, int), model.load_vector())
    sets, bc = model.dof_basis.calculix([getattr(s, "axial", False) for s in model.supports])
    bc = ["*BOUNDARY", *bc]
    text = (work / "job.inp").read_text()
    assert text.count("*MATERIAL") == 1 and text.count("*STEP\n*STATIC\n") == 1
    text = text.replace("*MATERIAL", "\n".join(sets) + "\n*MATERIAL")
    text = text.replace("*STEP\n*STATIC\n", "*STEP\n*STATIC\n" + "\n".join(bc) + "\n")
    (work / "job.inp").write_text(text)


def test_pinned_beam_displacements_agree_with_calculix_transform():
    """The review's beam (300 x 20 x 10 mm steel, 6 mm holes 280 mm apart, 1000 N at mid-span) on two pins: ccx's
    displacements equal mechverify's within 1e-5 of the largest (the same tolerance as the other ccx checks)."""
    pytest.importorskip("gmsh")
    m = mesh.block_with_holes((Q(300, "mm"), Q(20, "mm"), Q(10, "mm")),
                              [((Q(10, "mm"), Q(10, "mm")), "6 mm"), ((Q(290, "mm"), Q(10, "mm")), "6 mm")], "8 mm")
    model = solid.SolidModel(m, "Structural Steel",
                             supports=(PinSupport(Named("hole0"), axial=True), PinSupport(Named("hole1"))),
                             loads=(Force(Box(("140 mm", "19 mm", "-1 mm"), ("160 mm", "21 mm", "11 mm")),
                                          ("0 N", "-1000 N", "0 N")),))
    res = model.solve()
    with tempfile.TemporaryDirectory(prefix="mv-ccx-pin-") as tmp:
        work = Path(tmp)
        _pinned_deck(model, work)
        ccx = calculix.run_deck(work, model.nodes.shape[1], m.basis.element_dofs.shape[1])
    scale = np.abs(res.u).max()
    assert scale > 3e-4  # a pinned-pinned beam's 0.35 mm, not a clamped 0.1 mm
    assert np.abs(ccx.displacement - res.u).max() <= 1e-5 * scale
