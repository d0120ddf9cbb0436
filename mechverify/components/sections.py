"""Cross-section properties of beams, links and columns.

The section lies in the local **y-z plane**; the beam axis is **x** (the convention of the FEA
beam model). Every constructor returns a frozen :class:`Section` whose attributes are quantities:

=================  ==============================================================================
``area``           A [m^2]
``centroid_y/_z``  centroid in the coordinates the shape was drawn in [m] (``centroid`` = both)
``Iy, Iz, Iyz``    centroidal second moments ``Iy = ∫z² dA`` (bending about y), ``Iz = ∫y² dA``,
                   product ``Iyz = ∫yz dA`` [m^4]
``I1, I2``         principal second moments (``I1 >= I2``) [m^4]; ``principal_angle`` from +y to
                   the axis of ``I1``, counter-clockwise [rad]
``J``              Saint-Venant torsion constant [m^4] (equal to the polar moment only for round
                   sections); ``Wt`` torsion modulus, ``tau_max = T / Wt`` [m^3]
``Asy, Asz``       shear areas for shear forces along y and z (Timoshenko beam) [m^2]
``Wel_y, Wel_z``   elastic section moduli, the smaller of the two fibres: ``Iy / c_z``, ``Iz / c_y`` [m^3]
``Wpl_y, Wpl_z``   plastic section moduli about axes parallel to y and z [m^3]
``c_y_pos`` ...    distances from the centroid to the extreme fibres in +y, -y, +z, -z (all >= 0);
                   ``c_y``/``c_z`` the larger of each pair [m]
``ry, rz, r_min``  radii of gyration [m]; ``I_min`` the least principal second moment
``shear_center_y/_z``  shear centre [m] (same coordinates as the centroid)
=================  ==============================================================================

Solid rectangles and round sections use closed forms (exact); the torsion constant of a rectangle
is the exact series of Saint-Venant's solution. Hollow rectangles, I/T/L/C profiles and arbitrary
polygons with holes are analysed with *sectionproperties* (Saint-Venant warping analysis by finite
elements; geometric and plastic properties of a polygon are exact). Shear areas are evaluated at
ν = 0 (:data:`NU_SHEAR`) in both paths: Cowper's coefficients then give the classical 5/6 for a
rectangle, 6/7 for a solid circle and 1/2 for a thin tube, and sectionproperties agrees with them.

References
----------
1. S. P. Timoshenko, J. N. Goodier, *Theory of Elasticity*, 3rd ed., McGraw-Hill, 1970, Sec. 109
   (torsion of rectangular bars: series for J and tau_max, table of k1, k2).
2. W. C. Young, R. G. Budynas, A. M. Sadegh, *Roark's Formulas for Stress and Strain*, 8th ed.,
   McGraw-Hill, 2012, Table 10.7 (torsion constants K of sections).
3. G. R. Cowper, "The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335-340.
4. R. van Leeuwen, *sectionproperties* 3 (https://github.com/robbievanleeuwen/section-properties).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache
from typing import Any

import numpy as np
import pint
import shapely
import shapely.affinity
import shapely.errors
from shapely.geometry import Polygon as ShapelyPolygon

from mechverify.errors import InputError, ModelError, UnknownNameError, suggest
from mechverify.units import Q, from_si, to_si

NU_SHEAR = 0.0  # Poisson ratio for shear areas: 5/6 A for a rectangle in both the closed form and sectionproperties

_FIELDS = {  # attribute -> dimension
    "area": "area", "centroid_y": "length", "centroid_z": "length",
    "Iy": "second_moment", "Iz": "second_moment", "Iyz": "second_moment",
    "I1": "second_moment", "I2": "second_moment", "principal_angle": "angle",
    "J": "second_moment", "Wt": "volume", "Asy": "area", "Asz": "area",
    "Wel_y": "volume", "Wel_z": "volume", "Wpl_y": "volume", "Wpl_z": "volume",
    "c_y_pos": "length", "c_y_neg": "length", "c_z_pos": "length", "c_z_neg": "length",
    "shear_center_y": "length", "shear_center_z": "length",
}


@dataclass(frozen=True)
class Section:
    """Properties of a cross-section (see the module docstring for every attribute)."""

    kind: str
    dimensions: Mapping[str, pint.Quantity]
    area: pint.Quantity
    centroid_y: pint.Quantity
    centroid_z: pint.Quantity
    Iy: pint.Quantity
    Iz: pint.Quantity
    Iyz: pint.Quantity
    I1: pint.Quantity
    I2: pint.Quantity
    principal_angle: pint.Quantity
    J: pint.Quantity
    Wt: pint.Quantity
    Asy: pint.Quantity
    Asz: pint.Quantity
    Wel_y: pint.Quantity
    Wel_z: pint.Quantity
    Wpl_y: pint.Quantity
    Wpl_z: pint.Quantity
    c_y_pos: pint.Quantity
    c_y_neg: pint.Quantity
    c_z_pos: pint.Quantity
    c_z_neg: pint.Quantity
    shear_center_y: pint.Quantity
    shear_center_z: pint.Quantity
    method: str = "closed form"
    source: str = ""
    geometry: Any = field(default=None, repr=False, compare=False)  # shapely polygon in metres

    @property
    def centroid(self) -> tuple[pint.Quantity, pint.Quantity]:
        return self.centroid_y, self.centroid_z

    @property
    def c_y(self) -> pint.Quantity:
        return max(self.c_y_pos, self.c_y_neg)

    @property
    def c_z(self) -> pint.Quantity:
        return max(self.c_z_pos, self.c_z_neg)

    @property
    def ry(self) -> pint.Quantity:
        return (self.Iy / self.area) ** 0.5

    @property
    def rz(self) -> pint.Quantity:
        return (self.Iz / self.area) ** 0.5

    @property
    def I_min(self) -> pint.Quantity:
        return self.I2

    @property
    def r_min(self) -> pint.Quantity:
        return (self.I2 / self.area) ** 0.5

    @property
    def polar_moment(self) -> pint.Quantity:
        """``Ip = Iy + Iz`` about the centroid (not the torsion constant, except for round sections)."""
        return self.Iy + self.Iz

    def si(self) -> dict[str, float]:
        """All quantity attributes as SI floats (for FEA assembly loops)."""
        return {name: to_si(getattr(self, name), dim, name) for name, dim in _FIELDS.items()}

    def __repr__(self) -> str:
        dims = ", ".join(f"{k}={v:~P}" for k, v in self.dimensions.items()) if self.dimensions else ""
        return (f"<Section {self.kind}({dims}) A={self.area.to('mm**2'):.4g~P} Iy={self.Iy.to('mm**4'):.4g~P} "
                f"Iz={self.Iz.to('mm**4'):.4g~P} J={self.J.to('mm**4'):.4g~P}>")


# ----------------------------------------------------------------------------------- helpers
def _dim(value: Any, name: str, *, allow_zero: bool = False) -> float:
    v = to_si(value, "length", name)
    if v < 0 or (v == 0 and not allow_zero):
        raise InputError(f"{name}: must be {'zero or ' if allow_zero else ''}positive, got {Q(v, 'm').to('mm'):~P}")
    return v


def _principal(Iy: float, Iz: float, Iyz: float) -> tuple[float, float, float]:
    """Principal second moments and the angle from +y to the axis of I1 (Mohr's circle)."""
    mean, half = 0.5 * (Iy + Iz), 0.5 * (Iy - Iz)
    R = math.hypot(half, Iyz)
    phi = 0.5 * math.atan2(-2.0 * Iyz, Iy - Iz) if R > 1e-14 * max(abs(mean), 1e-300) else 0.0
    return mean + R, mean - R, phi


def _build(kind: str, dims: Mapping[str, float], v: Mapping[str, float], method: str, source: str,
           geometry: Any) -> Section:
    I1, I2, phi = _principal(v["Iy"], v["Iz"], v["Iyz"])
    vals = dict(v, I1=I1, I2=I2, principal_angle=phi)
    vals.setdefault("shear_center_y", vals["centroid_y"])
    vals.setdefault("shear_center_z", vals["centroid_z"])
    q = {name: from_si(vals[name], dim) for name, dim in _FIELDS.items()}
    return Section(kind=kind, dimensions={k: Q(x, "m").to("mm") for k, x in dims.items()}, method=method,
                   source=source, geometry=geometry, **q)


def _cowper_tube(m: float, nu: float = NU_SHEAR) -> float:
    """Shear coefficient of a circular tube, m = inner/outer radius (Cowper 1966, Table 1)."""
    a = (1 + m * m) ** 2
    return 6 * (1 + nu) * a / ((7 + 6 * nu) * a + (20 + 12 * nu) * m * m)


def rectangle_torsion_constant(b: float, h: float, terms: int = 30) -> float:
    """Saint-Venant ``J`` of a solid ``b x h`` rectangle [m^4], exact series (Timoshenko & Goodier, Sec. 109).

    ``J = (1/3) h b^3 [1 - (192/pi^5)(b/h) sum_{n odd} tanh(n pi h/(2b))/n^5]``, ``b <= h``.
    """
    b, h = min(b, h), max(b, h)
    s = sum(math.tanh(n * math.pi * h / (2 * b)) / n**5 for n in range(1, 2 * terms, 2))
    return h * b**3 / 3 * (1 - 192 / math.pi**5 * b / h * s)


def rectangle_torsion_modulus(b: float, h: float, terms: int = 30) -> float:
    """``Wt = T / tau_max`` of a solid rectangle [m^3]; ``tau_max`` at the middle of the long side.

    ``tau_max = (T/J) b [1 - (8/pi^2) sum_{n odd} 1/(n^2 cosh(n pi h/(2b)))]`` (Timoshenko & Goodier, Sec. 109).
    """
    b, h = min(b, h), max(b, h)
    x = [n * math.pi * h / (2 * b) for n in range(1, 2 * terms, 2)]
    s = sum(2 * math.exp(-xi) / (1 + math.exp(-2 * xi)) / (2 * i + 1) ** 2 for i, xi in enumerate(x))  # 1/cosh
    return rectangle_torsion_constant(b, h, terms) / (b * (1 - 8 / math.pi**2 * s))


def _rect_geometry(b: float, h: float) -> ShapelyPolygon:
    return shapely.box(0.0, 0.0, b, h)


def _circle_geometry(D: float, d: float = 0.0, n: int = 64) -> ShapelyPolygon:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    outer = np.c_[D / 2 * np.cos(t), D / 2 * np.sin(t)]
    holes = [np.c_[d / 2 * np.cos(t), d / 2 * np.sin(t)][::-1]] if d > 0 else []
    return ShapelyPolygon(outer, holes)


# ------------------------------------------------------------------------------ closed forms
def rectangle(width: Any, height: Any) -> Section:
    """Solid rectangle, ``width`` along y, ``height`` along z; origin at the lower-left corner.

    ``Iy = b h^3/12``, ``Wel_y = b h^2/6``, ``Wpl_y = b h^2/4``; J and Wt from the exact series
    (Timoshenko & Goodier Sec. 109; Roark 8th ed. Table 10.7 case 4 gives the same to <1 %);
    shear areas ``k A`` with Cowper's ``k = 10(1+nu)/(12+11 nu)`` (5/6 at nu = NU_SHEAR = 0).
    """
    b, h = _dim(width, "width"), _dim(height, "height")
    A = b * h
    k = 10 * (1 + NU_SHEAR) / (12 + 11 * NU_SHEAR)
    v = dict(area=A, centroid_y=b / 2, centroid_z=h / 2, Iy=b * h**3 / 12, Iz=h * b**3 / 12, Iyz=0.0,
             J=rectangle_torsion_constant(b, h), Wt=rectangle_torsion_modulus(b, h), Asy=k * A, Asz=k * A,
             Wel_y=b * h**2 / 6, Wel_z=h * b**2 / 6, Wpl_y=b * h**2 / 4, Wpl_z=h * b**2 / 4,
             c_y_pos=b / 2, c_y_neg=b / 2, c_z_pos=h / 2, c_z_neg=h / 2)
    return _build("rectangle", {"width": b, "height": h}, v, "closed form",
                  "Timoshenko & Goodier, Theory of Elasticity 3rd ed. Sec. 109; Cowper 1966", _rect_geometry(b, h))


def tube(outer_diameter: Any, thickness: Any = None, *, inner_diameter: Any = None) -> Section:
    """Circular tube (give ``thickness`` or ``inner_diameter``); centred on the origin. Exact closed forms.

    ``I = pi (D^4 - d^4)/64``, ``J = 2I``, ``Wt = J/(D/2)``, ``Wpl = (D^3 - d^3)/6``; shear
    area ``k A`` with Cowper's coefficient for a hollow circle (6/7 solid, 1/2 thin, at nu = 0).
    """
    D = _dim(outer_diameter, "outer_diameter")
    if (thickness is None) == (inner_diameter is None):
        raise InputError("tube: give exactly one of thickness or inner_diameter")
    if thickness is not None:
        t = _dim(thickness, "thickness")
        d = D - 2 * t
    else:
        d = _dim(inner_diameter, "inner_diameter", allow_zero=True)
    if not 0 <= d < D:
        raise InputError(f"tube: the wall must be thinner than the radius (D = {D * 1e3:g} mm, "
                         f"inner diameter would be {d * 1e3:g} mm)")
    return _round("tube" if d > 0 else "circle", D, d)


def circle(diameter: Any) -> Section:
    """Solid circle of ``diameter``, centred on the origin (exact closed forms; see :func:`tube`)."""
    return _round("circle", _dim(diameter, "diameter"), 0.0)


def _round(kind: str, D: float, d: float) -> Section:
    A = math.pi / 4 * (D**2 - d**2)
    I = math.pi / 64 * (D**4 - d**4)
    k = _cowper_tube(d / D)
    v = dict(area=A, centroid_y=0.0, centroid_z=0.0, Iy=I, Iz=I, Iyz=0.0, J=2 * I, Wt=4 * I / D, Asy=k * A, Asz=k * A,
             Wel_y=2 * I / D, Wel_z=2 * I / D, Wpl_y=(D**3 - d**3) / 6, Wpl_z=(D**3 - d**3) / 6,
             c_y_pos=D / 2, c_y_neg=D / 2, c_z_pos=D / 2, c_z_neg=D / 2)
    dims = {"diameter": D} if d == 0 else {"outer_diameter": D, "inner_diameter": d}
    return _build(kind, dims, v, "closed form", "exact; shear coefficient Cowper 1966", _circle_geometry(D, d))


# ------------------------------------------------------------------------ sectionproperties
def _sp_material():
    from sectionproperties.pre.pre import Material

    return Material("unit", elastic_modulus=1.0, poissons_ratio=NU_SHEAR, yield_strength=1.0, density=1.0,
                    color="lightgrey")


def _analyse(kind: str, dims: Mapping[str, float], make_geometry: Callable[[Any], Any], mesh_divisions: int = 250,
             source: str = "") -> Section:
    """Run sectionproperties on a geometry built in millimetres; return SI properties."""
    from sectionproperties.analysis.section import Section as SPSection

    try:
        geom = make_geometry(_sp_material())
    except (ValueError, TypeError, shapely.errors.ShapelyError) as exc:  # degenerate dimensions
        raise InputError(f"{kind}: cannot build the section ({exc})") from None
    poly = geom.geom
    area_mm2 = poly.area
    if not poly.is_valid or area_mm2 <= 0:
        raise InputError(f"{kind}: the section outline is not a valid region (self-intersecting or empty)")
    geom.create_mesh(mesh_sizes=[area_mm2 / mesh_divisions])
    sec = SPSection(geom)
    try:
        sec.calculate_geometric_properties()
        sec.calculate_warping_properties()
        sec.calculate_plastic_properties()
        tau = np.abs(sec.calculate_stress(mzz=1.0).get_stress()[0]["sig_zxy_mzz"]).max()
    except Exception as exc:  # sectionproperties raises plain exceptions on unsolvable geometry
        raise ModelError(f"{kind}: section analysis failed ({exc})") from None
    mm = 1e-3
    A = sec.get_ea()
    Ixx, Iyy, Ixy = sec.get_eic()
    cx, cy = sec.get_c()
    zxx_p, zxx_m, zyy_p, zyy_m = sec.get_ez()
    sxx, syy = sec.get_mp()
    asx, asy = sec.get_eas()
    scx, scy = sec.get_sc()
    minx, maxx, miny, maxy = _bounds_xy(poly)
    v = dict(area=A * mm**2, centroid_y=cx * mm, centroid_z=cy * mm, Iy=Ixx * mm**4, Iz=Iyy * mm**4, Iyz=Ixy * mm**4,
             J=sec.get_ej() * mm**4, Wt=(1.0 / tau) * mm**3, Asy=asx * mm**2, Asz=asy * mm**2,
             Wel_y=min(zxx_p, zxx_m) * mm**3, Wel_z=min(zyy_p, zyy_m) * mm**3, Wpl_y=sxx * mm**3, Wpl_z=syy * mm**3,
             c_y_pos=(maxx - cx) * mm, c_y_neg=(cx - minx) * mm, c_z_pos=(maxy - cy) * mm, c_z_neg=(cy - miny) * mm,
             shear_center_y=scx * mm, shear_center_z=scy * mm)
    n_el = len(sec.elements)
    geometry = shapely.affinity.scale(poly, mm, mm, origin=(0, 0))
    return _build(kind, dims, v, f"sectionproperties warping analysis ({n_el} 6-node triangles)",
                  source or "sectionproperties 3 (van Leeuwen)", geometry)


def _bounds_xy(poly: Any) -> tuple[float, float, float, float]:
    minx, miny, maxx, maxy = poly.bounds
    return minx, maxx, miny, maxy


def _mm(d: Mapping[str, float]) -> dict[str, float]:
    return {k: v * 1e3 for k, v in d.items()}


def _nr(r: float) -> int:
    return 8 if r > 0 else 1


def hollow_rectangle(width: Any, height: Any, thickness: Any, outer_radius: Any = "0 mm") -> Section:
    """Rectangular hollow section (RHS/SHS), ``width`` along y, ``height`` along z, uniform wall.

    Sharp corners unless ``outer_radius`` is given (inner radius = outer - thickness). Analysed by
    sectionproperties; for thin walls J agrees with Bredt's ``4 Am^2 t / p`` (Roark 8th ed. Table 10.7).
    """
    b, h, t = _dim(width, "width"), _dim(height, "height"), _dim(thickness, "thickness")
    r = _dim(outer_radius, "outer_radius", allow_zero=True)
    if 2 * t >= min(b, h):
        raise InputError(f"hollow_rectangle: wall thickness {t * 1e3:g} mm leaves no hollow in "
                         f"{b * 1e3:g} x {h * 1e3:g} mm (use rectangle)")
    if r > min(b, h) / 2:
        raise InputError("hollow_rectangle: outer_radius exceeds half the smaller side")
    from sectionproperties.pre.library import rectangular_hollow_section

    dims = {"width": b, "height": h, "thickness": t, **({"outer_radius": r} if r else {})}
    m = _mm(dims)
    return _analyse("hollow_rectangle", dims, lambda mat: rectangular_hollow_section(
        d=m["height"], b=m["width"], t=m["thickness"], r_out=r * 1e3, n_r=_nr(r), material=mat))


def _profile_check(kind: str, h: float, b: float, tw: float, tf: float, n_flanges: int) -> None:
    if tw >= b:
        raise InputError(f"{kind}: web_thickness must be smaller than the width")
    if n_flanges * tf >= h:
        raise InputError(f"{kind}: flanges ({n_flanges} x {tf * 1e3:g} mm) do not fit in height {h * 1e3:g} mm")


def i_section(height: Any, width: Any, web_thickness: Any, flange_thickness: Any, root_radius: Any = "0 mm") -> Section:
    """Doubly symmetric I/H profile (IPE, HEA, ...): web along z, flanges along y; lower-left origin."""
    h, b = _dim(height, "height"), _dim(width, "width")
    tw, tf = _dim(web_thickness, "web_thickness"), _dim(flange_thickness, "flange_thickness")
    r = _dim(root_radius, "root_radius", allow_zero=True)
    _profile_check("i_section", h, b, tw, tf, 2)
    from sectionproperties.pre.library import i_section as sp_i

    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    return _analyse("i_section", dims, lambda mat: sp_i(d=h * 1e3, b=b * 1e3, t_f=tf * 1e3, t_w=tw * 1e3, r=r * 1e3,
                                                        n_r=_nr(r), material=mat))


def t_section(height: Any, width: Any, web_thickness: Any, flange_thickness: Any, root_radius: Any = "0 mm") -> Section:
    """Tee: flange on top (along y), web downwards (along z); lower-left origin."""
    h, b = _dim(height, "height"), _dim(width, "width")
    tw, tf = _dim(web_thickness, "web_thickness"), _dim(flange_thickness, "flange_thickness")
    r = _dim(root_radius, "root_radius", allow_zero=True)
    _profile_check("t_section", h, b, tw, tf, 1)
    from sectionproperties.pre.library import tee_section

    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    return _analyse("t_section", dims, lambda mat: tee_section(d=h * 1e3, b=b * 1e3, t_f=tf * 1e3, t_w=tw * 1e3,
                                                               r=r * 1e3, n_r=_nr(r), material=mat))


def l_section(height: Any, width: Any, thickness: Any, root_radius: Any = "0 mm", toe_radius: Any = "0 mm") -> Section:
    """Angle: vertical leg ``height`` (z), horizontal leg ``width`` (y), corner at the origin.

    Unsymmetric: ``Iyz != 0`` and the principal axes (``I1``, ``I2``, ``principal_angle``) differ from y, z.
    """
    h, b, t = _dim(height, "height"), _dim(width, "width"), _dim(thickness, "thickness")
    rr = _dim(root_radius, "root_radius", allow_zero=True)
    rt = _dim(toe_radius, "toe_radius", allow_zero=True)
    if t >= min(h, b):
        raise InputError("l_section: thickness must be smaller than both legs")
    from sectionproperties.pre.library import angle_section

    dims = {"height": h, "width": b, "thickness": t, **({"root_radius": rr} if rr else {}),
            **({"toe_radius": rt} if rt else {})}
    return _analyse("l_section", dims, lambda mat: angle_section(d=h * 1e3, b=b * 1e3, t=t * 1e3, r_r=rr * 1e3,
                                                                 r_t=rt * 1e3, n_r=_nr(max(rr, rt)), material=mat))


def c_section(height: Any, width: Any, web_thickness: Any, flange_thickness: Any, root_radius: Any = "0 mm") -> Section:
    """Channel with parallel flanges (UPE/PFC type): web along z at y = 0, flanges pointing to +y."""
    h, b = _dim(height, "height"), _dim(width, "width")
    tw, tf = _dim(web_thickness, "web_thickness"), _dim(flange_thickness, "flange_thickness")
    r = _dim(root_radius, "root_radius", allow_zero=True)
    _profile_check("c_section", h, b, tw, tf, 2)
    from sectionproperties.pre.library import channel_section

    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    return _analyse("c_section", dims, lambda mat: channel_section(d=h * 1e3, b=b * 1e3, t_f=tf * 1e3, t_w=tw * 1e3,
                                                                   r=r * 1e3, n_r=_nr(r), material=mat))


def _points(pts: Any, name: str, unit: str | None) -> np.ndarray:
    """(n, 2) SI array from a quantity array, pairs of quantities/strings, or numbers with ``unit``."""
    if isinstance(pts, pint.Quantity):
        arr = np.atleast_2d(np.asarray(to_si(pts, "length", name), dtype=float))
    else:
        rows = []
        for i, p in enumerate(pts):
            if len(p) != 2:
                raise InputError(f"{name}[{i}]: expected a point (y, z), got {p!r}")
            if unit is not None and all(isinstance(c, int | float) for c in p):
                rows.append([Q(float(c), unit).m_as("m") for c in p])
            else:
                rows.append([to_si(c, "length", f"{name}[{i}]") for c in p])
        arr = np.asarray(rows, dtype=float)
    if arr.ndim != 2 or arr.shape[1] != 2 or len(arr) < 3:
        raise InputError(f"{name}: a polygon needs at least 3 points (y, z), got shape {arr.shape}")
    return arr


def polygon_region(outline: Any, holes: Sequence[Any] = (), unit: str | None = None, what: str = "polygon"
                   ) -> ShapelyPolygon:
    """A validated shapely polygon (metres) from an outline and holes; clear errors for degenerate input.

    Raises :class:`InputError` for a self-intersecting outline or hole, a hole not strictly inside
    the outline, overlapping holes, or zero area. Shared by sections and plates.
    """
    outer = _points(outline, f"{what}.outline", unit)
    centred = outer - outer.mean(axis=0)
    if np.abs(centred).max() == 0 or np.linalg.matrix_rank(centred / np.abs(centred).max(), tol=1e-12) < 2:
        raise InputError(f"{what}.outline: the outline encloses no area (its points are collinear)")
    ring = shapely.LinearRing(outer)
    if not ring.is_simple:
        raise InputError(f"{what}.outline: the outline crosses itself (self-intersecting polygon)")
    shell = ShapelyPolygon(outer)
    if shell.area <= 0:
        raise InputError(f"{what}.outline: the outline encloses no area")
    hole_polys = []
    for i, hole in enumerate(holes):
        hp = ShapelyPolygon(_points(hole, f"{what}.holes[{i}]", unit))
        if not hp.exterior.is_simple or hp.area <= 0:
            raise InputError(f"{what}.holes[{i}]: the hole outline crosses itself or encloses no area")
        if not shell.contains(hp):
            raise InputError(f"{what}.holes[{i}]: the hole is not inside the outline "
                             "(it lies outside or cuts the edge)")
        for j, other in enumerate(hole_polys):
            if hp.intersects(other):
                raise InputError(f"{what}.holes[{i}]: the hole overlaps or touches hole {j}")
        hole_polys.append(hp)
    region = ShapelyPolygon(shell.exterior.coords, [h.exterior.coords for h in hole_polys])
    if not region.is_valid:
        raise InputError(f"{what}: invalid region ({shapely.is_valid_reason(region)})")
    return region


def polygon(outline: Any, holes: Sequence[Any] = (), unit: str | None = None, mesh_divisions: int = 300) -> Section:
    """Arbitrary polygon with polygonal holes, points (y, z). Analysed by sectionproperties.

    ``outline``/``holes``: quantity arrays of shape (n, 2), sequences of (y, z) quantities/strings,
    or sequences of numbers with ``unit`` (e.g. ``unit="mm"``).
    """
    from sectionproperties.pre.geometry import Geometry

    region = polygon_region(outline, holes, unit, "polygon")
    mm_region = shapely.affinity.scale(region, 1e3, 1e3, origin=(0, 0))
    return _analyse("polygon", {}, lambda mat: Geometry(mm_region, material=mat), mesh_divisions)


# ----------------------------------------------------------------------------- by name
_KINDS: dict[str, Callable[..., Section]] = {
    "rectangle": rectangle, "circle": circle, "tube": tube, "hollow_rectangle": hollow_rectangle,
    "i_section": i_section, "t_section": t_section, "l_section": l_section, "c_section": c_section,
    "polygon": polygon,
}
_ALIASES = {"rect": "rectangle", "bar": "rectangle", "flat": "rectangle", "round": "circle", "rod": "circle",
            "pipe": "tube", "chs": "tube", "rhs": "hollow_rectangle", "shs": "hollow_rectangle",
            "box": "hollow_rectangle",
            "i": "i_section", "ipe": "i_section", "h": "i_section", "t": "t_section", "tee": "t_section",
            "l": "l_section", "angle": "l_section", "c": "c_section", "channel": "c_section", "u": "c_section"}


def section_kinds() -> list[str]:
    return list(_KINDS)


def make_section(kind: str, **kwargs: Any) -> Section:
    """Build a section by kind name, as design files do.

    ``make_section("tube", outer_diameter="20 mm", thickness="2 mm")``; results are cached.
    """
    key = kind.strip().lower().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key, key)
    if key not in _KINDS:
        raise UnknownNameError("section kind", kind, [*_KINDS, *_ALIASES])
    try:
        return _cached(key, tuple(sorted((k, _freeze(v)) for k, v in kwargs.items())))
    except TypeError as exc:
        hint = suggest(str(exc).split("'")[-2] if "'" in str(exc) else "", _KINDS[key].__code__.co_varnames)
        raise InputError(f"section {key}: {exc}" + (f"; did you mean {hint[0]!r}?" if hint else "")) from None


def _freeze(v: Any) -> Any:
    if isinstance(v, list | tuple):
        return tuple(_freeze(x) for x in v)
    if isinstance(v, pint.Quantity):
        return str(v) if np.ndim(v.magnitude) == 0 else ("__q__", tuple(np.asarray(v.magnitude).ravel()),
                                                         np.shape(v.magnitude), str(v.units))
    return v


def _thaw(v: Any) -> Any:
    if isinstance(v, tuple) and len(v) == 4 and v[0] == "__q__":
        return Q(np.asarray(v[1]).reshape(v[2]), v[3])
    if isinstance(v, tuple):
        return [_thaw(x) for x in v]
    return v


@cache
def _cached(key: str, kw: tuple[tuple[str, Any], ...]) -> Section:
    return _KINDS[key](**{k: _thaw(v) for k, v in kw})


__all__ = ["Section", "rectangle", "circle", "tube", "hollow_rectangle", "i_section", "t_section", "l_section",
           "c_section", "polygon", "polygon_region", "make_section", "section_kinds", "rectangle_torsion_constant",
           "rectangle_torsion_modulus", "NU_SHEAR"]
