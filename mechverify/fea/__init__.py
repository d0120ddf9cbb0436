"""FEA-lite on scikit-fem: solids (P2 tetrahedra), plane stress/strain, plate bending, beams and frames.

Submodules: :mod:`.mesh` (solid meshes), :mod:`.regions` (where loads and supports act),
:mod:`.loads` (what acts there), :mod:`.solid`, :mod:`.results`, :mod:`.calculix` (cross-check).
"""
