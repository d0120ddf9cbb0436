"""FEA-lite on scikit-fem: solids (P2 tetrahedra), plane stress/strain (P2 triangles), thin-plate
bending (Morley triangles), beams and frames.

Submodules: :mod:`.mesh` / :mod:`.mesh2d` (meshes), :mod:`.regions` (where loads and supports act),
:mod:`.loads` (what acts there), :mod:`.solid`, :mod:`.plane`, :mod:`.plate`, :mod:`.frame`,
:mod:`.results` (one results object for the continuum models), :mod:`.calculix` (cross-check).
"""
