"""Beams and frames: 3D frames and grillages of straight members (axial, biaxial bending, torsion).

A :class:`Frame` is a set of named nodes, straight :class:`Member` s between them (each with a
:class:`~mechverify.components.sections.Section` and a material, and optional end
:class:`Release` s), :class:`FrameSupport` s (rigid, springs, one-way springs), :class:`Hinge` s and
two-node :class:`Spring` s, declared at named nodes or at points, never at degree-of-freedom
numbers. ``Frame.solve(loads)`` takes :class:`FramePointLoad`, :class:`MemberPointLoad`,
:class:`DistributedLoad` (uniform, partial, trapezoidal; local or global axes), :class:`FrameSelfWeight`
and :class:`SupportDisplacement` (settlements) and returns :class:`FrameResults`: node
displacements and rotations, support reactions (global equilibrium is asserted), spring forces,
internal force and moment diagrams along every member, stresses at section fibres, exact extremes
(``ranges(member)``) and a report figure. ``Frame.analyse(cases, combinations)`` solves every load
case on one factorisation of the stiffness, forms :class:`LoadCombination` s by superposition and
gives envelopes (``FrameAnalysis.envelope()``). ``Frame.modes(n, masses=...)`` (:func:`frame_modes`) gives
natural frequencies and mode shapes with the consistent mass, ``Frame.buckling(loads, n)``
(:func:`frame_buckling`) linear buckling load factors (:mod:`mechverify.fea.frame.modal`).

The element is the two-node 3D beam with the exact (interdependent) stiffness of a prismatic
member: Euler-Bernoulli, or Timoshenko with the shear areas ``Asy``/``Asz`` of the section
(shear parameters ``Phi = 12 E I / (G A_s L^2)``, ref. 1 Sec. 5.6, ref. 2 Sec. 4.5). Loads along a
member enter as the fixed-end forces of linearly varying loads (exact for both theories), point
loads along a member split it, so nodal displacements are exact. Between the nodes the fields
follow from the end forces by integrating ``M = E I theta'`` and ``v' = theta + V / (G A_s)``
(exact polynomials), so deflections, diagrams and their extremes are exact along the members too.
End releases are condensed out of the member stiffness (ref. 2 Sec. 7.3); a release that leaves a
member unstable or that has no effect at its node is an error.

Conventions: member local axis x runs from its start to its end node; local z is the component of
``orientation`` (default global Z; global X for a vertical member) normal to x, and y = z × x.
The section's y-z plane is the local y-z plane (a rectangle's ``height`` lies along local z, so a
horizontal member bends about y under vertical loads with ``Iy``). A section with a product of
inertia is analysed about its principal axes (local loads and releases refer to them). Internal
resultants are those on the cut face whose outward normal is +x: ``N`` > 0 in tension,
``sigma = N/A + My z / Iy - Mz y / Iz``. Loads act at the centroidal axis (the shear-centre offset
of open sections is not modelled) and members are rigidly connected at shared nodes unless
released.

References
----------
1. J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968 (Dover 1985),
   Sec. 5.6 (beam element with shear deformation), Sec. 5.7 (fixed-end forces).
2. W. McGuire, R. H. Gallagher, R. D. Ziemian, *Matrix Structural Analysis*, 2nd ed., Wiley 2000,
   Sec. 4.3-4.5 (3D frame element, transformation, shear deformation), Sec. 7.3 (releases).
3. S. P. Timoshenko, J. M. Gere, *Mechanics of Materials*, 1st ed., Van Nostrand 1972, Sec. 7.8
   (deflection of beams due to shear), and Budynas & Nisbett, *Shigley's Mechanical Engineering
   Design*, 10th ed., Eq. 5-15 (von Mises stress of a beam fibre, ``sqrt(sigma^2 + 3 tau^2)``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from mechverify.errors import renamed
from mechverify.fea.frame.element import (
    fixed_end_forces,
    fixed_end_forces_linear,
    local_axes,
    local_stiffness,
)
from mechverify.fea.frame.model import (
    DOF_NAMES,
    RELEASE_NAMES,
    STANDARD_GRAVITY,
    SUPPORT_KINDS,
    THEORIES,
    DistributedLoad,
    FramePointLoad,
    FrameSelfWeight,
    FrameSupport,
    Hinge,
    Load,
    LoadCombination,
    Member,
    MemberPointLoad,
    Release,
    Spring,
    SupportDisplacement,
    Where,
    section_from_properties,
)
from mechverify.fea.frame.results import (
    EXTREME_QUANTITIES,
    Diagram,
    Envelope,
    FrameAnalysis,
    FrameExtreme,
    FrameResults,
    Range,
    section_fibres,
)

if TYPE_CHECKING:
    from mechverify.fea.frame.analysis import DENSE_CHECK_LIMIT, PROGRESS_THRESHOLD, Frame
    from mechverify.fea.frame.figure import frame_figure
    from mechverify.fea.frame.modal import FrameBuckling, FrameModes, PointMass, frame_buckling, frame_modes

# The solver (scipy.sparse) and the figure (matplotlib) are imported when first used, so that a design
# file's frame component can be parsed without them (issue 27: a fast cold start).
_LAZY = {"Frame": "analysis", "DENSE_CHECK_LIMIT": "analysis", "PROGRESS_THRESHOLD": "analysis",
         "frame_figure": "figure", "frame_modes": "modal", "frame_buckling": "modal", "PointMass": "modal",
         "FrameModes": "modal", "FrameBuckling": "modal"}


# Former names (issue 16: one meaning per public class name across the package), deprecated.
_renamed = renamed(__name__, {"PointLoad": "FramePointLoad", "Support": "FrameSupport",
                              "SelfWeight": "FrameSelfWeight", "Extreme": "FrameExtreme"}, stacklevel=3)


def __getattr__(name: str) -> Any:
    if name not in _LAZY:
        return _renamed(name)
    value = getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    globals()[name] = value
    return value


__all__ = ["DOF_NAMES", "RELEASE_NAMES", "STANDARD_GRAVITY", "SUPPORT_KINDS", "THEORIES", "DENSE_CHECK_LIMIT",
           "PROGRESS_THRESHOLD", "EXTREME_QUANTITIES", "DistributedLoad", "Hinge", "Load", "LoadCombination", "Member",
           "MemberPointLoad", "FramePointLoad", "Release", "FrameSelfWeight", "Spring", "FrameSupport",
           "SupportDisplacement", "Where",
           "section_from_properties", "fixed_end_forces", "fixed_end_forces_linear", "local_axes", "local_stiffness",
           "Diagram", "Envelope", "FrameExtreme", "FrameAnalysis", "FrameResults", "Range", "section_fibres", "Frame",
           "frame_figure", "frame_modes", "frame_buckling", "PointMass", "FrameModes", "FrameBuckling"]
