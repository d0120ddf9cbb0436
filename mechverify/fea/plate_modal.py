"""Natural frequencies and mode shapes of thin (Kirchhoff) plates: the plate model of
:mod:`mechverify.fea.plate` (Morley triangles) with the consistent mass ``M = ∫ ρ t w v dA``.

    >>> from mechverify.components import plates as P
    >>> from mechverify.fea.plate_modal import plate_modes
    >>> plate = P.Plate.rectangle("300 mm", "200 mm", "3 mm", "Structural Steel")
    >>> res = plate_modes(P.PlateModel(plate, supports=(P.EdgeSupport("all"),)), 3, mesh_size="10 mm")
    >>> round(float(res.first_frequency.m))   # π²(1/a² + 1/b²) √(D/(ρt)) / 2π = 259.9 Hz (simply supported)
    259

- :func:`plate_mass_matrix` - the consistent mass of the Morley element (the deflection's quadratic
  interpolation; ref. 2). Rotary inertia of the plate's cross-section is neglected (Kirchhoff theory,
  ref. 1 Sec. 4.2), as are membrane (in-plane) modes.
- :func:`plate_modes` - the first ``n_modes`` eigenpairs of ``K φ = ω² M φ`` on the plate's supports
  (simply supported: deflection held; clamped: slope held as well), by ARPACK shift-invert Lanczos on
  one sparse factorisation (:func:`mechverify.fea.factor.factorize`: CHOLMOD when installed, else SuperLU;
  dense ``eigh`` for small models). Results are
  :class:`~mechverify.fea.modal.ModalResults` (shapes: deflection along z at the vertices, mass-normalised;
  effective mass along z; VTU export).

The Morley element is non-conforming: its frequencies converge (from below for the stiffness, so not
bounded from either side in general) with the square of the element size.

References
----------
1. A. W. Leissa, *Vibration of Plates*, NASA SP-160, 1969, Sec. 4.1 (simply supported rectangle:
   ω_mn = π² (m²/a² + n²/b²) √(D/(ρh))), Sec. 4.2.
2. L. S. D. Morley, "The constant-moment plate-bending element", J. Strain Analysis 6 (1971) 20-24.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from skfem import BilinearForm, asm

from mechverify.errors import InputError
from mechverify.fea.modal import ModalResults
from mechverify.units import QuantityLike

#: Largest number of free unknowns solved by the dense symmetric eigensolver.
DENSE_LIMIT = 1500
#: The most modes a plate mesh resolves: free unknowns / MODES_PER_UNKNOWNS (at least :data:`MODES_FLOOR`, at most
#: :data:`MODES_CEILING`). Review 3 measured mode 30 of the default mesh of a clamped square (about 960 free unknowns,
#: so mode n/32) 21 % low; modes beyond n/20 are mesh artefacts rather than the plate's (review 4 finding 27: modes up
#: to n - 1 were accepted, 400 took 112 s and 1536 ran over 6 min).
MODES_PER_UNKNOWNS = 20
MODES_FLOOR = 12
#: An absolute ceiling for the time: eigsh's cost grows about as modes² (measured on 27k free unknowns: 50 / 100 / 200
#: modes 3.6 / 6.9 / 16.8 s CPU, and the frequencies' convergence estimate solves a mesh 1.5x finer as well).
MODES_CEILING = 200


def max_modes(free: int) -> int:
    """The most natural frequencies :func:`plate_modes` computes on a mesh of ``free`` unknowns (fewer than
    ``free``): :data:`MODES_PER_UNKNOWNS`, :data:`MODES_FLOOR`, :data:`MODES_CEILING`."""
    return min(MODES_CEILING, max(MODES_FLOOR, free // MODES_PER_UNKNOWNS), free - 1)


def plate_mass_matrix(sys_: Any, rho: float) -> sp.csr_matrix:
    """Consistent mass ``∫ ρ t w v dA`` [kg] of the plate system's Morley basis."""
    t = sys_.t

    @BilinearForm
    def mass(u: Any, v: Any, w: Any) -> Any:
        return rho * t * u * v

    return asm(mass, sys_.basis).tocsr()


def plate_modes(model: Any, n_modes: int = 6, mesh_size: QuantityLike | None = None,
                hole_mesh_size: QuantityLike | None = None, refine: float = 1.0) -> ModalResults:
    """The first ``n_modes`` natural frequencies and mode shapes of a
    :class:`mechverify.components.plates.PlateModel` (its loads are ignored; its supports hold the plate).

    ``mesh_size`` (default: shorter side / 16), ``hole_mesh_size`` and ``refine`` (every element size divided by
    it) as for :func:`mechverify.fea.plate.solve_plate`. Supports that leave a rigid motion free are a
    :class:`ModelError` naming it; asking for as many modes as free unknowns, or more than the mesh resolves
    (:func:`max_modes`), is an :class:`InputError`.
    """
    from mechverify.components import plates as P
    from mechverify.fea.plate import _PlateSystem, _stiffness, _supports, check_plate_supported, plate_mesh
    from mechverify.units import to_si

    if not isinstance(model, P.PlateModel):
        raise InputError(f"plate_modes: expected a mechverify.components.plates.PlateModel, got {model!r}")
    n_modes = int(n_modes)
    if n_modes < 1:
        raise InputError(f"n_modes: ask for at least one mode, got {n_modes}")
    mat = model.plate.material
    if mat.density is None:
        raise InputError(f"plate modal analysis needs the density of material {mat.name!r}")
    rho = mat.density.m_as("kg/m**3")
    h = None if mesh_size is None else to_si(mesh_size, "length", "mesh_size")
    hh = None if hole_mesh_size is None else to_si(hole_mesh_size, "length", "hole_mesh_size")
    mesh = plate_mesh(model.plate, h, hh, refine)
    sys_ = _PlateSystem(model, mesh)
    K = _stiffness(sys_).tocsr()
    M = plate_mass_matrix(sys_, rho)
    held, held_pts, normals, _ = _supports(sys_)
    check_plate_supported(held_pts, normals)
    free = np.setdiff1d(np.arange(K.shape[0]), held)
    if n_modes >= free.size:
        raise InputError(f"n_modes: {n_modes} modes asked, but the plate mesh has only {free.size} free unknowns; "
                         "refine the mesh or ask fewer")
    if n_modes > max_modes(free.size):
        raise InputError(f"n_modes: {n_modes} modes asked, but a plate mesh of {free.size} free unknowns resolves at "
                         f"most {max_modes(free.size)} (free unknowns / {MODES_PER_UNKNOWNS}, at most {MODES_CEILING}: "
                         "higher modes would be the mesh's, and their eigensolution takes minutes); "
                         "refine the mesh or ask fewer")
    Kf, Mf = K[free][:, free], M[free][:, free]
    if free.size <= DENSE_LIMIT:
        w, V = sla.eigh(Kf.toarray(), Mf.toarray(), subset_by_index=[0, n_modes - 1])
    else:
        from mechverify.fea.factor import factorize

        op = factorize(Kf, what="the plate's bending stiffness (check the supports)").operator()
        v0 = np.random.default_rng(0).standard_normal(free.size)
        w, V = spl.eigsh(Kf.tocsc(), k=n_modes, M=Mf.tocsc(), sigma=0.0, which="LM", OPinv=op, v0=v0, tol=1e-10)
        order = np.argsort(w)
        w, V = w[order], V[:, order]
    V = V / np.sqrt(np.einsum("ik,ik->k", V, Mf @ V))[None, :]
    full = np.zeros((K.shape[0], n_modes))
    full[free] = V
    vd = sys_.basis.nodal_dofs[0]
    n = mesh.nvertices
    shapes = np.zeros((n_modes, n, 3))
    shapes[:, :, 2] = full[vd].T
    r = np.zeros(K.shape[0])
    r[vd] = 1.0  # a rigid translation along z: unit vertex deflections, zero normal slopes
    eff = np.zeros((n_modes, 3))
    eff[:, 2] = (V.T @ (Mf @ r[free])) ** 2
    tot = np.array([0.0, 0.0, float(r @ (M @ r))])
    pts = np.column_stack([mesh.p.T, np.zeros(n)])
    return ModalResults("plate", w, shapes, pts, [("triangle", mesh.t.T.copy())], eff, tot, 0, int(free.size))
