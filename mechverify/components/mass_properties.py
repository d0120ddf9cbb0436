"""Mass moments of inertia of standard homogeneous bodies from their mass and dimensions.

One function per closed form, each returning kg·m² (a quantity). Inputs are quantities or strings.
Formulas are the standard table ones (integrals of r² dm over the body):

References:
    [1] J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Dynamics*, Appendix B, Table D/4
        ("Properties of homogeneous solids").
    [2] R. C. Hibbeler, *Engineering Mechanics: Dynamics*, inside back cover ("Geometric properties
        of line and area elements" / "Mass moment of inertia of homogeneous solids").
"""

from __future__ import annotations

from mechverify.errors import InputError
from mechverify.units import Q, Quantity, QuantityLike, to_si

__all__ = ["solid_cylinder_axial", "solid_cylinder_transverse", "hollow_cylinder_axial", "hollow_cylinder_transverse",
           "rod_about_centre", "rod_about_end", "rectangular_plate_normal", "parallel_axis"]


def _pos(value: QuantityLike, dim: str, name: str, *, zero: bool = False) -> float:
    v = to_si(value, dim, name)
    if v < 0 or (v == 0 and not zero):
        raise InputError(f"{name} must be {'>= 0' if zero else '> 0'}, got {value!r}")
    return v


def _I(x: float) -> Quantity:
    return Q(x, "kg*m**2")


def solid_cylinder_axial(mass: QuantityLike, radius: QuantityLike) -> Quantity:
    """Solid cylinder (or disc) about its axis: I = m r²/2 [kg·m²] ([1] Table D/4, [2])."""
    m, r = _pos(mass, "mass", "mass"), _pos(radius, "length", "radius")
    return _I(m * r * r / 2)


def solid_cylinder_transverse(mass: QuantityLike, radius: QuantityLike, length: QuantityLike) -> Quantity:
    """Solid cylinder about a diameter through its centre of mass: I = m (3 r² + L²)/12 [kg·m²] ([1], [2])."""
    m, r = _pos(mass, "mass", "mass"), _pos(radius, "length", "radius")
    L = _pos(length, "length", "length", zero=True)
    return _I(m * (3 * r * r + L * L) / 12)


def _radii(outer: QuantityLike, inner: QuantityLike) -> tuple[float, float]:
    ro, ri = _pos(outer, "length", "outer_radius"), _pos(inner, "length", "inner_radius", zero=True)
    if ri >= ro:
        raise InputError(f"inner_radius {inner!r} must be below outer_radius {outer!r}")
    return ro, ri


def hollow_cylinder_axial(mass: QuantityLike, outer_radius: QuantityLike, inner_radius: QuantityLike) -> Quantity:
    """Hollow cylinder (tube) about its axis: I = m (r_o² + r_i²)/2 [kg·m²] ([1] Table D/4)."""
    m = _pos(mass, "mass", "mass")
    ro, ri = _radii(outer_radius, inner_radius)
    return _I(m * (ro * ro + ri * ri) / 2)


def hollow_cylinder_transverse(mass: QuantityLike, outer_radius: QuantityLike, inner_radius: QuantityLike,
                               length: QuantityLike) -> Quantity:
    """Hollow cylinder about a diameter through its centre: I = m (3 (r_o² + r_i²) + L²)/12 [kg·m²] ([1])."""
    m = _pos(mass, "mass", "mass")
    ro, ri = _radii(outer_radius, inner_radius)
    L = _pos(length, "length", "length", zero=True)
    return _I(m * (3 * (ro * ro + ri * ri) + L * L) / 12)


def rod_about_centre(mass: QuantityLike, length: QuantityLike) -> Quantity:
    """Slender rod about a transverse axis through its centre: I = m L²/12 [kg·m²] ([1], [2])."""
    m, L = _pos(mass, "mass", "mass"), _pos(length, "length", "length")
    return _I(m * L * L / 12)


def rod_about_end(mass: QuantityLike, length: QuantityLike) -> Quantity:
    """Slender rod about a transverse axis through one end: I = m L²/3 [kg·m²] ([1], [2])."""
    m, L = _pos(mass, "mass", "mass"), _pos(length, "length", "length")
    return _I(m * L * L / 3)


def rectangular_plate_normal(mass: QuantityLike, a: QuantityLike, b: QuantityLike) -> Quantity:
    """Thin rectangular plate a × b about the axis normal to it through its centre: I = m (a² + b²)/12
    [kg·m²] ([1], [2]); about an in-plane centroidal axis parallel to b use ``rod_about_centre(m, a)``."""
    m = _pos(mass, "mass", "mass")
    x, y = _pos(a, "length", "a"), _pos(b, "length", "b")
    return _I(m * (x * x + y * y) / 12)


def parallel_axis(I_centre: QuantityLike, mass: QuantityLike, distance: QuantityLike) -> Quantity:
    """Parallel-axis theorem: I = I_G + m d² [kg·m²] ([1] Eq. B/2)."""
    Ig = Q(I_centre).m_as("kg*m**2")
    if Ig < 0:
        raise InputError(f"I_centre must be >= 0, got {I_centre!r}")
    m, d = _pos(mass, "mass", "mass"), _pos(distance, "length", "distance", zero=True)
    return _I(Ig + m * d * d)
