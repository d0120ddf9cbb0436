"""Published linear-elasticity benchmarks as ready models: geometry (gmsh, exact CAD curves), loads,
supports and the reference value with its source. Used by ``benchmarks/verification.py`` (the table in
``docs/verification.md``) and, on small meshes, by ``tests/validation/test_benchmarks_fea.py``.

- :func:`kirsch` - quarter of a square plate with a circular hole, loaded on its outer edges by the
  exact tractions of Kirsch's infinite-plate solution, so the closed form holds everywhere: σxx = 3σ at
  the top of the hole (ref. 1).
- :func:`lame` - quarter of a thick cylinder under internal pressure, plane strain: σθ at the bore
  = p (ro² + ri²)/(ro² - ri²) (ref. 2).
- :func:`le1` - NAFEMS LE1 elliptic membrane: σyy at D (2 m, 0) = 92.7 MPa (ref. 3, a converged
  reference, not a closed form).

References
----------
1. S. P. Timoshenko & J. N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill 1970, sec. 35
   (Kirsch's solution: stresses around a circular hole in a plate under uniaxial tension).
2. Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015, eq. (3-50)
   (thick-walled cylinder, Lamé).
3. NAFEMS, The Standard NAFEMS Benchmarks, TNSB Rev. 3, 1990, test LE1 (elliptic membrane: inner
   ellipse semi-axes 2 m x 1 m, outer 3.25 m x 2.75 m, thickness 0.1 m, E = 210 GPa, ν = 0.3,
   10 MPa outward normal traction on the outer edge; σyy at D = 92.7 MPa).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from mechverify.fea import mesh2d
from mechverify.fea.loads import Pressure, Restraint, Traction
from mechverify.fea.mesh import gmsh_session, import_gmsh
from mechverify.fea.plane import PlaneModel
from mechverify.fea.regions import Named
from mechverify.materials.material import Material
from mechverify.units import Q


@dataclass(frozen=True)
class Benchmark:
    """A model, the point and stress component the reference is for, the reference value [Pa] and its
    source, and the exact stress field where a closed form exists."""

    name: str
    model: PlaneModel
    point: tuple[float, float]  # m
    component: Callable[[np.ndarray], float]  # stress tensor [3, 3] -> the compared value [Pa]
    reference: float  # Pa
    source: str
    exact: Callable[[np.ndarray], np.ndarray] | None = None  # points [2, k] -> σ [k, 3, 3]


def _material(E: float, nu: float) -> Material:
    return Material(name=f"linear elastic E = {E / 1e9:g} GPa", category="metal", E=Q(E, "Pa"), nu=Q(nu, ""))


def _mesh(build: Callable[[Any], None], h: float, h_fine: float, fine_curves: Callable[[Any], list[int]],
          order: int = 1) -> Any:
    """Run a gmsh 2D build (OCC), grade to ``h_fine`` on the curves ``fine_curves`` selects, mesh."""
    from mechverify.fea.mesh import refine_near

    gmsh = import_gmsh()
    gmsh_session(gmsh, h)
    try:
        build(gmsh)
        curves = fine_curves(gmsh)
        if h_fine < h and curves:
            refine_near(gmsh, "CurvesList", curves, h_fine, h, 6 * h, sampling=200)
            gmsh.option.setNumber("Mesh.MeshSizeMin", h_fine / 2)
            gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.model.mesh.generate(2)
        if order == 2:
            from mechverify.fea.mesh import second_order

            second_order(gmsh)
        return mesh2d.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()


def _name_curves(gmsh: Any, rules: dict[str, Callable[[np.ndarray], bool]]) -> dict[str, list[int]]:
    """Physical curves named by a test on each curve's centre of mass."""
    groups: dict[str, list[int]] = {k: [] for k in rules}
    for _, tag in gmsh.model.getEntities(1):
        c = np.array(gmsh.model.occ.getCenterOfMass(1, tag))
        for name, rule in rules.items():
            if rule(c):
                groups[name].append(tag)
                break
    for name, tags in groups.items():
        if tags:
            gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, tags), name)
    gmsh.model.addPhysicalGroup(2, [t for _, t in gmsh.model.getEntities(2)])
    return groups


def kirsch_stress(points: np.ndarray, sigma: float, a: float) -> np.ndarray:
    """Kirsch's stresses ``[k, 3, 3]`` around a hole of radius ``a`` under remote σxx = ``sigma`` (ref. 1)."""
    x, y = points[0], points[1]
    r2 = x**2 + y**2
    th = np.arctan2(y, x)
    c2, s2 = np.cos(2 * th), np.sin(2 * th)
    q, q2 = a**2 / r2, a**4 / r2**2
    srr = sigma / 2 * (1 - q) + sigma / 2 * (1 - 4 * q + 3 * q2) * c2
    stt = sigma / 2 * (1 + q) - sigma / 2 * (1 + 3 * q2) * c2
    srt = -sigma / 2 * (1 + 2 * q - 3 * q2) * s2
    c, s = np.cos(th), np.sin(th)
    out = np.zeros((x.size, 3, 3))
    out[:, 0, 0] = srr * c**2 + stt * s**2 - 2 * srt * s * c
    out[:, 1, 1] = srr * s**2 + stt * c**2 + 2 * srt * s * c
    out[:, 0, 1] = out[:, 1, 0] = (srr - stt) * s * c + srt * (c**2 - s**2)
    return out


def kirsch(h: float, h_hole: float | None = None, order: int = 1, a: float = 0.01, L: float = 0.05,
           sigma: float = 100e6) -> Benchmark:
    """Quarter plate ``L x L`` with a hole of radius ``a`` at the origin, exact Kirsch tractions on x = L and
    y = L, symmetry on the axes; plane strain (the 2D stresses do not depend on the elastic constants)."""
    def build(gmsh: Any) -> None:
        occ = gmsh.model.occ
        plate = occ.addRectangle(0, 0, 0, L, L)
        hole = occ.addDisk(0, 0, 0, a, a)
        occ.cut([(2, plate)], [(2, hole)])
        occ.synchronize()
        _name_curves(gmsh, {"hole": lambda c: np.hypot(c[0], c[1]) < 1.5 * a,
                            "right": lambda c: abs(c[0] - L) < 1e-9, "top": lambda c: abs(c[1] - L) < 1e-9,
                            "left": lambda c: abs(c[0]) < 1e-9, "bottom": lambda c: abs(c[1]) < 1e-9})

    m = _mesh(build, h, h_hole or h,
              lambda g: [int(t) for t in g.model.getEntitiesForPhysicalGroup(1, _group(g, "hole"))], order)

    def traction(points: np.ndarray, normal: tuple[float, float]) -> np.ndarray:
        s = kirsch_stress(points, sigma, a)
        n = np.array(normal)
        return np.einsum("kij,j->ik", s[:, :2, :2], n)

    model = PlaneModel(m, "1 m", _material(200e9, 0.3), plane="strain",
                       supports=(Restraint(Named("left"), x=True), Restraint(Named("bottom"), y=True)),
                       loads=(Traction(Named("right"), lambda p: traction(p, (1.0, 0.0))),
                              Traction(Named("top"), lambda p: traction(p, (0.0, 1.0)))))
    return Benchmark("Kirsch: hole in a plate, σxx at (0, a)", model, (0.0, a), lambda s: s[0, 0], 3 * sigma,
                     "Timoshenko & Goodier, Theory of Elasticity, 3rd ed., sec. 35 (Kirsch): 3σ",
                     lambda p: kirsch_stress(p, sigma, a))


def _group(gmsh: Any, name: str) -> int:
    for dim, tag in gmsh.model.getPhysicalGroups(1):
        if gmsh.model.getPhysicalName(dim, tag) == name:
            return tag
    raise KeyError(name)


def lame_stress(points: np.ndarray, p: float, ri: float, ro: float, nu: float) -> np.ndarray:
    """Lamé stresses ``[k, 3, 3]`` of a thick cylinder under internal pressure, plane strain (ref. 2)."""
    x, y = points[0], points[1]
    r2 = x**2 + y**2
    k = p * ri**2 / (ro**2 - ri**2)
    srr, stt = k * (1 - ro**2 / r2), k * (1 + ro**2 / r2)
    th = np.arctan2(y, x)
    c, s = np.cos(th), np.sin(th)
    out = np.zeros((x.size, 3, 3))
    out[:, 0, 0] = srr * c**2 + stt * s**2
    out[:, 1, 1] = srr * s**2 + stt * c**2
    out[:, 0, 1] = out[:, 1, 0] = (srr - stt) * s * c
    out[:, 2, 2] = nu * (srr + stt)
    return out


def lame(h: float, order: int = 1, ri: float = 0.02, ro: float = 0.04, p: float = 50e6) -> Benchmark:
    """Quarter of a thick cylinder, bore ``ri``, outside ``ro``, internal pressure ``p``, plane strain;
    σyy at (ri, 0) is the hoop stress at the bore."""
    def build(gmsh: Any) -> None:
        occ = gmsh.model.occ
        outer = occ.addDisk(0, 0, 0, ro, ro)
        inner = occ.addDisk(0, 0, 0, ri, ri)
        ring, _ = occ.cut([(2, outer)], [(2, inner)])
        box = occ.addRectangle(0, 0, 0, ro, ro)
        occ.intersect(ring, [(2, box)])
        occ.synchronize()
        _name_curves(gmsh, {"bore": lambda c: 0.5 * ri < np.hypot(c[0], c[1]) < (ri + ro) / 2 and c[0] > 1e-9
                            and c[1] > 1e-9,
                            "outside": lambda c: np.hypot(c[0], c[1]) >= (ri + ro) / 2 and c[0] > 1e-9 and c[1] > 1e-9,
                            "left": lambda c: abs(c[0]) < 1e-9, "bottom": lambda c: abs(c[1]) < 1e-9})

    m = _mesh(build, h, h, lambda g: [], order)
    model = PlaneModel(m, "1 m", _material(200e9, 0.3), plane="strain",
                       supports=(Restraint(Named("left"), x=True), Restraint(Named("bottom"), y=True)),
                       loads=(Pressure(Named("bore"), Q(p, "Pa")),))
    return Benchmark("Lamé: thick cylinder, σθ at the bore", model, (ri, 0.0), lambda s: s[1, 1],
                     p * (ro**2 + ri**2) / (ro**2 - ri**2),
                     "Shigley, 10th ed., eq. (3-50): p (ro² + ri²)/(ro² - ri²)",
                     lambda pts: lame_stress(pts, p, ri, ro, 0.3))


def le1(h: float, h_d: float | None = None, order: int = 1) -> Benchmark:
    """NAFEMS LE1 (ref. 3): quarter elliptic membrane, plane stress, 0.1 m thick, 10 MPa outward traction on
    the outer ellipse; σyy at D = (2 m, 0)."""
    def build(gmsh: Any) -> None:
        occ = gmsh.model.occ
        outer = occ.addDisk(0, 0, 0, 3.25, 2.75)
        inner = occ.addDisk(0, 0, 0, 2.0, 1.0)
        ring, _ = occ.cut([(2, outer)], [(2, inner)])
        box = occ.addRectangle(0, 0, 0, 4, 4)
        occ.intersect(ring, [(2, box)])
        occ.synchronize()

        def on_ellipse(c: np.ndarray, A: float, B: float) -> bool:
            return c[0] > 1e-9 and c[1] > 1e-9 and abs((c[0] / A) ** 2 + (c[1] / B) ** 2 - 1) < 0.2

        _name_curves(gmsh, {"outer": lambda c: on_ellipse(c, 3.25, 2.75),
                            "inner": lambda c: on_ellipse(c, 2.0, 1.0),
                            "left": lambda c: abs(c[0]) < 1e-9, "bottom": lambda c: abs(c[1]) < 1e-9})

    m = _mesh(build, h, h_d or h,
              lambda g: [int(t) for t in g.model.getEntitiesForPhysicalGroup(1, _group(g, "inner"))], order)
    model = PlaneModel(m, "0.1 m", _material(210e9, 0.3), plane="stress",
                       supports=(Restraint(Named("left"), x=True), Restraint(Named("bottom"), y=True)),
                       loads=(Pressure(Named("outer"), "-10 MPa"),))
    return Benchmark("NAFEMS LE1: elliptic membrane, σyy at D", model, (2.0, 0.0), lambda s: s[1, 1], 92.7e6,
                     "NAFEMS TNSB Rev. 3 (1990), LE1: 92.7 MPa")


def lame_solid(h: float, order: int = 2, ri: float = 0.02, ro: float = 0.04, length: float = 0.01,
               p: float = 50e6) -> tuple[Any, float]:
    """A quarter ring slice (bore ``ri``, outside ``ro``, ``length`` along z) of quadratic tetrahedra with
    symmetry rollers on x = 0 and y = 0 and both end faces held along z (plane strain), internal pressure
    ``p`` on the named surface ``bore``: the Lamé solution of :func:`lame_stress` (ref. 2). Returns the
    :class:`~mechverify.fea.solid.SolidModel` and the exact hoop stress at the bore."""
    from mechverify.fea import mesh
    from mechverify.fea.regions import Plane
    from mechverify.fea.solid import SolidModel

    gmsh = import_gmsh()
    gmsh_session(gmsh, h)
    try:
        occ = gmsh.model.occ
        outer = occ.addCylinder(0, 0, 0, 0, 0, length, ro)
        inner = occ.addCylinder(0, 0, 0, 0, 0, length, ri)
        ring, _ = occ.cut([(3, outer)], [(3, inner)])
        occ.intersect(ring, [(3, occ.addBox(0, 0, 0, ro, ro, length))])
        occ.synchronize()
        cyl = [t for _, t in gmsh.model.getEntities(2) if gmsh.model.getType(2, t) == "Cylinder"]
        bore = min(cyl, key=lambda t: occ.getMass(2, t))
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [bore]), "bore")
        gmsh.model.addPhysicalGroup(3, [t for _, t in gmsh.model.getEntities(3)])
        gmsh.model.mesh.generate(3)
        if order == 2:
            mesh.second_order(gmsh)
        m = mesh.from_gmsh_model(gmsh)
    finally:
        gmsh.finalize()
    model = SolidModel(m, _material(200e9, 0.3),
                       supports=(Restraint(Plane(x="0 m"), x=True), Restraint(Plane(y="0 m"), y=True),
                                 Restraint(Plane(z="0 m"), z=True), Restraint(Plane(z=Q(length, "m")), z=True)),
                       loads=(Pressure(Named("bore"), Q(p, "Pa")),))
    return model, p * (ro**2 + ri**2) / (ro**2 - ri**2)
