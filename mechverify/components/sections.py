"""Cross-section properties of beams, links and columns.

The section lies in the local **y-z plane**; the beam axis is **x** (the convention of the FEA
beam model). Every constructor returns a frozen :class:`Section` whose attributes are quantities:

=====================  ==============================================================================
``area``               A [m^2]
``centroid_y/_z``      centroid in the coordinates the shape was drawn in [m] (``centroid`` = both)
``Iy, Iz, Iyz``        centroidal second moments ``Iy = ∫z² dA`` (bending about y), ``Iz = ∫y² dA``,
                       product ``Iyz = ∫yz dA`` [m^4]
``I1, I2``             principal second moments (``I1 >= I2``) [m^4]; ``principal_angle`` from +y to
                       the axis of ``I1``, counter-clockwise [rad]
``J``                  Saint-Venant torsion constant [m^4] (equal to the polar moment only for round
                       sections); ``Wt`` torsion modulus, ``tau_max = T / Wt`` [m^3]
``Asy, Asz``           shear areas for shear forces along y and z (Timoshenko beam) [m^2]
``Wel_y, Wel_z``       elastic section moduli, the smaller of the two fibres: ``Iy / c_z``, ``Iz / c_y`` [m^3]
``Wpl_y, Wpl_z``       plastic section moduli about axes parallel to y and z [m^3]
``c_y_pos`` ...        distances from the centroid to the extreme fibres in +y, -y, +z, -z (all >= 0);
                       ``c_y``/``c_z`` the larger of each pair [m]
``ry, rz, r_min``      radii of gyration [m]; ``I_min`` the least principal second moment
``shear_center_y/_z``  shear centre [m] (same coordinates as the centroid)
=====================  ==============================================================================

Solid rectangles and round sections use closed forms (exact); the torsion constant of a rectangle
is the exact series of Saint-Venant's solution. Hollow rectangles and I/T/L/C profiles (with their
fillets) need no extra package: area, centroid, second moments and plastic moduli are exact integrals
of the outline (Green's theorem; fillet arcs as 48 chords, area error ~3e-5), the torsion constant is
the thin-walled sum of strips with the junction terms of El Darwish & Johnston (Roark Table 10.7;
EN 10219-2 Annex B for the hollow rectangle), the shear centre the thin-walled one, and the shear
areas Cowper's (I, box), the thin-walled shear flow's (T, C) or Jourawski's strip integral (L). Their agreement with
sectionproperties' warping analysis is measured in ``tests/test_sections.py`` (J within 1-4 %,
14 % for a T with fillets; IPE 200 J = 7.02 cm^4 against the catalogue's 6.98). Arbitrary polygons
with holes are analysed with *sectionproperties* (the optional extra ``mechverify[sections]``;
Saint-Venant warping analysis by finite elements). Shear areas are evaluated at ν = 0
(:data:`NU_SHEAR`): Cowper's coefficients then give the classical 5/6 for a rectangle, 6/7 for a
solid circle and 1/2 for a thin tube, and sectionproperties agrees with them.

References
----------
1. S. P. Timoshenko, J. N. Goodier, *Theory of Elasticity*, 3rd ed., McGraw-Hill, 1970, Sec. 109
   (torsion of rectangular bars: series for J and tau_max, table of k1, k2).
2. W. C. Young, R. G. Budynas, A. M. Sadegh, *Roark's Formulas for Stress and Strain*, 8th ed.,
   McGraw-Hill, 2012, Table 10.7 (torsion constants K of sections).
3. G. R. Cowper, "The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335-340.
4. R. van Leeuwen, *sectionproperties* 3 (https://github.com/robbievanleeuwen/section-properties).
5. I. A. El Darwish, B. G. Johnston, "Torsion of structural shapes", J. Struct. Div. ASCE 91 (ST1), 1965
   (the junction terms alpha D^4 that Roark Table 10.7 tabulates).
6. W. D. Pilkey, *Formulas for Stress, Strain, and Structural Matrices*, 2nd ed., Wiley, 2005,
   Sec. 2.8 (shear correction factors), Sec. 2.11 (shear centres of thin-walled sections).
7. EN 10219-2:2006, Annex B (torsion constant It and modulus Ct of hollow sections).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache, cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import pint

from mechverify.errors import InputError, ModelError, UnknownNameError, install_hint, suggest
from mechverify.references import ref
from mechverify.units import Q, QuantityLike, from_si, to_si

if TYPE_CHECKING:
    from shapely.geometry import Polygon as ShapelyPolygon

SECTIONS_HINT = ("arbitrary polygon sections need sectionproperties, an optional extra: "
                 + install_hint("sections", "sectionproperties"))
_ARC_POINTS = 48  # straight segments per fillet arc of the closed-form outlines

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


class Dimensions(Mapping[str, pint.Quantity]):
    """A section's dimensions by name: a read-only mapping (a :class:`Section` is immutable all the way down, so
    the designs of a study may share it: ``mechverify.design.reuse.shareable``); pickles and compares like a dict."""

    __slots__ = ("_values",)

    def __init__(self, values: Mapping[str, pint.Quantity] = ()) -> None:  # type: ignore[assignment]
        self._values = dict(values)

    def __getitem__(self, key: str) -> pint.Quantity:
        return self._values[key]

    def __iter__(self) -> Any:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return repr(self._values)

    def __reduce__(self) -> tuple[Any, ...]:
        return (Dimensions, (self._values,))


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
    outline: tuple[np.ndarray, ...] = field(default=(), repr=False, compare=False)  # rings (k, 2) in metres

    @cached_property
    def geometry(self) -> ShapelyPolygon | None:
        """The outline as a shapely polygon in metres (holes included), built when first asked for."""
        if not self.outline:
            return None
        from shapely.geometry import Polygon

        return Polygon(self.outline[0], list(self.outline[1:]))

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
def _dim(value: QuantityLike, name: str, *, allow_zero: bool = False) -> float:
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
           rings: Sequence[np.ndarray]) -> Section:
    I1, I2, phi = _principal(v["Iy"], v["Iz"], v["Iyz"])
    vals = dict(v, I1=I1, I2=I2, principal_angle=phi)
    vals.setdefault("shear_center_y", vals["centroid_y"])
    vals.setdefault("shear_center_z", vals["centroid_z"])
    q = {name: from_si(vals[name], dim) for name, dim in _FIELDS.items()}
    outline = tuple(np.array(r, dtype=float) for r in rings)
    for ring in outline:  # (read-only, as the dimensions: the section may be shared)
        ring.setflags(write=False)
    return Section(kind=kind, dimensions=Dimensions({k: Q(x, "m").to("mm") for k, x in dims.items()}),
                   method=method, source=source, outline=outline, **q)


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


def _rect_geometry(b: float, h: float) -> list[np.ndarray]:
    return [np.array([[0.0, 0.0], [b, 0.0], [b, h], [0.0, h]])]


def _circle_geometry(D: float, d: float = 0.0, n: int = 64) -> list[np.ndarray]:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    outer = np.c_[D / 2 * np.cos(t), D / 2 * np.sin(t)]
    return [outer, np.c_[d / 2 * np.cos(t), d / 2 * np.sin(t)][::-1]] if d > 0 else [outer]


# ------------------------------------------------------------------------------ closed forms
def rectangle(width: QuantityLike, height: QuantityLike) -> Section:
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


def tube(outer_diameter: QuantityLike, thickness: QuantityLike | None = None, *,
         inner_diameter: QuantityLike | None = None) -> Section:
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


def circle(diameter: QuantityLike) -> Section:
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
    import shapely.errors

    try:
        from sectionproperties.analysis.section import Section as SPSection
    except ImportError as exc:
        raise ModelError(f"{kind}: {SECTIONS_HINT} [{exc}]") from None
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
    rings = [np.asarray(poly.exterior.coords)[:-1] * mm, *(np.asarray(h.coords)[:-1] * mm for h in poly.interiors)]
    return _build(kind, dims, v, f"sectionproperties warping analysis ({n_el} 6-node triangles)",
                  source or "sectionproperties 3 (van Leeuwen)", rings)


def _bounds_xy(poly: Any) -> tuple[float, float, float, float]:
    minx, miny, maxx, maxy = poly.bounds
    return minx, maxx, miny, maxy


# ---------------------------------------------------------------- outlines and exact polygon integrals
def _filleted(vertices: Sequence[tuple[float, float, float]], n_arc: int = _ARC_POINTS) -> np.ndarray:
    """Closed ring (k, 2) from sharp vertices ``(y, z, radius)``: each corner with radius > 0 becomes a
    circular arc tangent to both edges (convex or re-entrant alike)."""
    pts = np.array([(v[0], v[1]) for v in vertices], dtype=float)
    out: list[np.ndarray] = []
    n = len(pts)
    for i, (_, _, r) in enumerate(vertices):
        P, A, B = pts[i], pts[i - 1], pts[(i + 1) % n]
        if r <= 0:
            out.append(P[None, :])
            continue
        u1, u2 = (A - P) / np.linalg.norm(A - P), (B - P) / np.linalg.norm(B - P)
        half = 0.5 * math.acos(float(np.clip(u1 @ u2, -1.0, 1.0)))
        d = r / math.tan(half)
        if d > min(np.linalg.norm(A - P), np.linalg.norm(B - P)) * (1 + 1e-9):
            raise InputError(f"a corner radius of {r * 1e3:g} mm does not fit the adjacent edges")
        bis = (u1 + u2) / np.linalg.norm(u1 + u2)
        C = P + bis * r / math.sin(half)
        T1, T2 = P + d * u1, P + d * u2
        a1, a2 = math.atan2(*(T1 - C)[::-1]), math.atan2(*(T2 - C)[::-1])
        da = (a2 - a1 + math.pi) % (2 * math.pi) - math.pi  # the short way round (< 180 deg)
        a = a1 + da * np.linspace(0.0, 1.0, n_arc + 1)
        out.append(np.c_[C[0] + r * np.cos(a), C[1] + r * np.sin(a)])
    ring = np.vstack(out)
    keep = np.r_[True, np.any(np.abs(np.diff(ring, axis=0)) > 1e-15, axis=1)]  # drop repeated points
    return ring[keep]


def _ring_moments(P: np.ndarray) -> np.ndarray:
    """Signed [A, ∫y, ∫z, ∫y², ∫z², ∫yz] of a closed polygon ring by Green's theorem (exact for the polygon;
    counter-clockwise rings count positive, clockwise rings - holes - negative)."""
    y0, z0 = P[:, 0], P[:, 1]
    y1, z1 = np.roll(y0, -1), np.roll(z0, -1)
    c = y0 * z1 - y1 * z0
    return np.array([c.sum() / 2, ((y0 + y1) * c).sum() / 6, ((z0 + z1) * c).sum() / 6,
                     ((y0 * y0 + y0 * y1 + y1 * y1) * c).sum() / 12, ((z0 * z0 + z0 * z1 + z1 * z1) * c).sum() / 12,
                     ((y0 * z1 + 2 * y0 * z0 + 2 * y1 * z1 + y1 * z0) * c).sum() / 24])


def _moments(rings: Sequence[np.ndarray]) -> np.ndarray:
    return sum((_ring_moments(r) for r in rings), np.zeros(6))


def _clip_ring(P: np.ndarray, axis: int, s: float) -> np.ndarray:
    """The part of a ring with coordinate ``axis`` >= s (Sutherland-Hodgman against one half-plane; the
    bridges it may leave along the cut line have zero area, so the integrals of the result are exact)."""
    Q = np.roll(P, -1, axis=0)
    a, b = P[:, axis], Q[:, axis]
    inside, crosses = a >= s, (a >= s) != (b >= s)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = P + (Q - P) * ((s - a) / (b - a))[:, None]
    cand = np.stack([P, x], axis=1).reshape(-1, 2)  # per edge: its start point, then the crossing
    out = cand[np.stack([inside, crosses], axis=1).ravel()]
    return out if len(out) >= 3 else np.zeros((0, 2))


def _half_moments(rings: Sequence[np.ndarray], axis: int, s: float) -> np.ndarray:
    return sum((_ring_moments(c) for r in rings if len(c := _clip_ring(r, axis, s))), np.zeros(6))


def _plastic_modulus(rings: Sequence[np.ndarray], axis: int, area: float) -> float:
    """``Wpl = ∫|u - u_p| dA`` about the equal-area (plastic neutral) axis ``u = u_p`` normal to ``axis``."""
    lo = min(r[:, axis].min() for r in rings)
    hi = max(r[:, axis].max() for r in rings)
    for _ in range(80):  # bisection on the area above the axis, monotone in u_p
        mid = 0.5 * (lo + hi)
        if _half_moments(rings, axis, mid)[0] > area / 2:
            lo = mid
        else:
            hi = mid
    up = 0.5 * (lo + hi)
    top = _half_moments(rings, axis, up)
    total = _moments(rings)
    first_top, area_top = top[1 + axis], top[0]
    first_bot, area_bot = total[1 + axis] - first_top, total[0] - area_top
    return (first_top - up * area_top) + (up * area_bot - first_bot)


def _chord(rings: Sequence[np.ndarray], axis: int, s: np.ndarray) -> np.ndarray:
    """Width of the section cut by the lines ``u = s`` (u = coordinate ``axis``), holes subtracted."""
    other = 1 - axis
    width = np.zeros_like(s)
    for P in rings:
        Q = np.roll(P, -1, axis=0)
        a, b = P[:, axis][None, :], Q[:, axis][None, :]
        ss = s[:, None]
        cross = ((a <= ss) & (b > ss)) | ((b <= ss) & (a > ss))
        with np.errstate(divide="ignore", invalid="ignore"):
            w = P[:, other][None, :] + (Q[:, other] - P[:, other])[None, :] * (ss - a) / (b - a)
            # counter-clockwise ring: edges going up in u lie on the side of larger `other`; holes reverse
            sign = np.sign(b - a) * (1 if axis == 1 else -1)
            width += np.where(cross, sign * w, 0.0).sum(axis=1)
    return width


def _shear_area(rings: Sequence[np.ndarray], axis: int, I: float, centroid: float) -> float:
    """Shear area for a shear force along ``axis`` (Jourawski): ``As = I² / ∫ Q(u)² / b(u) du``.

    Q is the first moment, about the centroidal axis, of the part beyond the cut at u, and b the cut's
    width (Pilkey, Formulas for Stress, Strain and Structural Matrices, Sec. 2.8 - the shear correction
    factor ``alpha_s = (A / I²) ∫ (Q / b)² dA`` - with the shear stress uniform across each cut).
    """
    levels = np.unique(np.concatenate([r[:, axis] for r in rings]))
    g, w = np.polynomial.legendre.leggauss(6)
    total = 0.0
    q_above = 0.0  # first moment of everything beyond the current interval's upper end
    for lo, hi in zip(levels[::-1][1:], levels[::-1][:-1]):  # from the top down
        h = hi - lo
        # the chord is linear on an interval between vertex levels (straight edges); sample inside it
        b1, b2 = _chord(rings, axis, np.array([lo + 0.25 * h, lo + 0.75 * h]))
        slope = (b2 - b1) / (0.5 * h)

        def b_at(u: np.ndarray, b1: float = b1, slope: float = slope, lo: float = lo, h: float = h) -> np.ndarray:
            return b1 + slope * (u - (lo + 0.25 * h))

        u = lo + (g + 1) / 2 * h
        # Q(u) = q_above + ∫_u^hi b(x)(x - c) dx, integrated exactly (cubic) by 3-point Gauss per point
        g3, w3 = np.polynomial.legendre.leggauss(3)
        x = u[:, None] + (g3[None, :] + 1) / 2 * (hi - u)[:, None]
        Qu = q_above + ((b_at(x) * (x - centroid)) * w3[None, :]).sum(axis=1) * (hi - u) / 2
        bu = b_at(u)
        total += float((np.where(bu > 0, Qu**2 / np.where(bu > 0, bu, 1.0), 0.0) * w).sum() * h / 2)
        xs = lo + (g3 + 1) / 2 * h
        q_above += float((b_at(xs) * (xs - centroid) * w3).sum() * h / 2)
    return I * I / total if total > 0 else 0.0


def _thin_shear_area(paths: Sequence[Sequence[tuple[tuple[float, float], tuple[float, float], float]]],
                     axis: int) -> float:
    """Shear area of a thin-walled open section for a shear force along ``axis`` (0: y, 1: z), from its shear
    flow: ``As = I² / ∫ Q(s)² / t ds`` with ``Q(s) = ∫ t (u - u_c) ds`` from a free end (Pilkey Sec. 2.8, the
    shear correction factor of thin-walled sections). ``paths`` are chains of mid-line segments
    ``(start, end, t)``, each starting at a free end; chains meet at one junction or run free end to free
    end. Valid for shear along an axis of symmetry or normal to it (T, C); I, centroid and Q are mid-line
    (thin-walled) values, so fillets are not counted.
    """
    g, w = np.polynomial.legendre.leggauss(4)  # Q is quadratic along a segment: Q² / t integrated exactly
    segs = [seg for path in paths for seg in path]
    A = sum(t * math.dist(p0, p1) for p0, p1, t in segs)
    c = sum(t * math.dist(p0, p1) * (p0[axis] + p1[axis]) / 2 for p0, p1, t in segs) / A
    I = sum(t * math.dist(p0, p1) * ((p0[axis] - c) ** 2 + (p0[axis] - c) * (p1[axis] - c) + (p1[axis] - c) ** 2) / 3
            for p0, p1, t in segs)
    total = 0.0
    for path in paths:
        q0 = 0.0
        for p0, p1, t in path:
            L = math.dist(p0, p1)
            a, b = p0[axis] - c, p1[axis] - c
            sg = (g + 1) / 2 * L
            Q = q0 + t * (a * sg + (b - a) * sg * sg / (2 * L))
            total += float((Q * Q / t * w).sum() * L / 2)
            q0 += t * L * (a + b) / 2
    return I * I / total if total > 0 else 0.0


def _strip(length: float, t: float, free_ends: int) -> float:
    """Torsion constant of a rectangular strip ``length x t`` with 0, 1 or 2 free short ends (Roark Table 10.7:
    ``K1 = a b³ [1/3 - 0.21 (b/a)(1 - b⁴/(12 a⁴))]`` for two free ends, 0.105 and 192 for one, 1/3 for none)."""
    if length <= 0:
        return 0.0
    if free_ends == 2:
        return length * t**3 * (1 / 3 - 0.21 * t / length * (1 - t**4 / (12 * length**4)))
    if free_ends == 1:
        return length * t**3 * (1 / 3 - 0.105 * t / length * (1 - t**4 / (192 * length**4)))
    return length * t**3 / 3


def _tee_junction(tf: float, tw: float, r: float) -> float:
    """``alpha D⁴`` of a T junction (web tw meeting a flange tf, fillets r): Roark Table 10.7 (I and T sections;
    from El Darwish & Johnston 1965, ref. 5),
    ``alpha = (t/t1)(0.15 + 0.10 r/b)``, ``D = ((b + r)² + t_w (r + t_w/4)) / (2r + b)`` with b = tf."""
    t, t1 = min(tf, tw), max(tf, tw)
    alpha = t / t1 * (0.15 + 0.10 * r / tf)
    return alpha * _tee_diameter(tf, tw, r) ** 4


def _tee_diameter(tf: float, tw: float, r: float) -> float:
    """Diameter D of the largest circle inscribed in a T junction (Roark Table 10.7)."""
    return ((tf + r) ** 2 + tw * (r + tw / 4)) / (2 * r + tf)


def _corner_diameter(b: float, d: float, r: float) -> float:
    """Diameter D of the largest circle inscribed in an L corner (Roark Table 10.7)."""
    return 2 * ((b + d + 3 * r) - math.sqrt(2 * (2 * r + b) * (2 * r + d)))


def _corner_junction(b: float, d: float, r: float) -> float:
    """``alpha D⁴`` of an L corner (legs b >= d thick, root fillet r): Roark Table 10.7 (L section),
    ``alpha = (d/b)(0.07 + 0.076 r/b)``, ``D = 2[(b + d + 3r) - sqrt(2 (2r + b)(2r + d))]``."""
    b, d = max(b, d), min(b, d)
    alpha = d / b * (0.07 + 0.076 * r / b)
    return alpha * _corner_diameter(b, d, r) ** 4


def _cowper_thin(m: float, n: float, nu: float = NU_SHEAR) -> float:
    """Shear coefficient of a thin-walled I or box section (Cowper 1966, Table 1), m = flange area / web area,
    n = flange width / web depth (mid-lines): ``k = 10(1+nu)(1+3m)² / [(12 + 72m + 150m² + 90m³)
    + nu(11 + 66m + 135m² + 90m³) + 30n²(m + m²) + 5 nu n²(8m + 9m²)]``."""
    num = 10 * (1 + nu) * (1 + 3 * m) ** 2
    den = (12 + 72 * m + 150 * m**2 + 90 * m**3 + nu * (11 + 66 * m + 135 * m**2 + 90 * m**3)
           + 30 * n**2 * (m + m**2) + 5 * nu * n**2 * (8 * m + 9 * m**2))
    return num / den


def _thin_walled(kind: str, dims: Mapping[str, float], rings: list[np.ndarray], J: float, Wt: float,
                 shear_centre: tuple[float, float], source: str,
                 shear_areas: tuple[float, float] | None = None) -> Section:
    """Section from its outline (exact polygon integrals) and the torsion/shear-centre formulas of its kind.

    Shear areas: ``shear_areas`` (y, z) where the kind has its own (Cowper's coefficients, the thin-walled
    shear flow), else Jourawski's strip integral :func:`_shear_area`.
    """
    A, Sy, Sz, Iyy0, Izz0, Iyz0 = _moments(rings)
    if A <= 0:
        raise InputError(f"{kind}: the section has no area")
    cy, cz = Sy / A, Sz / A
    Iy, Iz, Iyz = Izz0 - A * cz * cz, Iyy0 - A * cy * cy, Iyz0 - A * cy * cz  # Iy = ∫z² dA about the centroid
    pts = np.vstack(rings)
    ymin, zmin = pts.min(axis=0)
    ymax, zmax = pts.max(axis=0)
    v = dict(area=A, centroid_y=cy, centroid_z=cz, Iy=Iy, Iz=Iz, Iyz=Iyz, J=J, Wt=Wt,
             Asy=shear_areas[0] if shear_areas else _shear_area(rings, 0, Iz, cy),
             Asz=shear_areas[1] if shear_areas else _shear_area(rings, 1, Iy, cz),
             Wel_y=Iy / max(zmax - cz, cz - zmin), Wel_z=Iz / max(ymax - cy, cy - ymin),
             Wpl_y=_plastic_modulus(rings, 1, A), Wpl_z=_plastic_modulus(rings, 0, A),
             c_y_pos=ymax - cy, c_y_neg=cy - ymin, c_z_pos=zmax - cz, c_z_neg=cz - zmin,
             shear_center_y=shear_centre[0], shear_center_z=shear_centre[1])
    return _build(kind, dims, v, "closed form (exact polygon integrals; thin-walled torsion and shear centre)",
                  source, rings)


def hollow_rectangle(width: QuantityLike, height: QuantityLike, thickness: QuantityLike,
                     outer_radius: QuantityLike = "0 mm") -> Section:
    """Rectangular hollow section (RHS/SHS), ``width`` along y, ``height`` along z, uniform wall; lower-left origin.

    Sharp corners unless ``outer_radius`` is given (inner radius = outer - thickness, or sharp).
    Area, second moments and plastic moduli are exact integrals of the outline. Torsion: EN 10219-2
    Annex B (Bredt's thin-walled cell plus the open-wall term), ``It = t³ h/3 + 2 K Ah``,
    ``K = 2 Ah t / h``, ``Ct = It / (t + K/t)`` with the mid-line perimeter
    ``h = 2[(B - t) + (H - t)] - 2 Rc (4 - pi)``, enclosed area ``Ah = (B - t)(H - t) - Rc² (4 - pi)``,
    ``Rc`` the mean corner radius; for thin walls this is Bredt's ``4 Ah² t / h`` (Roark Table 10.7).
    """
    b, h, t = _dim(width, "width"), _dim(height, "height"), _dim(thickness, "thickness")
    r = _dim(outer_radius, "outer_radius", allow_zero=True)
    if 2 * t >= min(b, h):
        raise InputError(f"hollow_rectangle: wall thickness {t * 1e3:g} mm leaves no hollow in "
                         f"{b * 1e3:g} x {h * 1e3:g} mm (use rectangle)")
    if r > min(b, h) / 2:
        raise InputError("hollow_rectangle: outer_radius exceeds half the smaller side")
    ri = max(r - t, 0.0)
    outer = _filleted([(0, 0, r), (b, 0, r), (b, h, r), (0, h, r)])
    inner = _filleted([(t, t, ri), (t, h - t, ri), (b - t, h - t, ri), (b - t, t, ri)])  # clockwise: a hole
    rc = (r + ri) / 2 if r > 0 else 0.0
    p = 2 * ((b - t) + (h - t)) - 2 * rc * (4 - math.pi)
    Ah = (b - t) * (h - t) - rc**2 * (4 - math.pi)
    K = 2 * Ah * t / p
    It = t**3 * p / 3 + 2 * K * Ah
    dims = {"width": b, "height": h, "thickness": t, **({"outer_radius": r} if r else {})}
    A = _moments([outer, inner])[0]
    bm, hm = b - t, h - t  # mid-line box
    shear = (_cowper_thin(hm / bm, hm / bm) * A, _cowper_thin(bm / hm, bm / hm) * A)
    return _thin_walled("hollow_rectangle", dims, [outer, inner], It, It / (t + K / t), (b / 2, h / 2),
                        f"{ref('en10219_2', 'Annex B (It, Ct)')}; {ref('roark8', 'Table 10.7 (Bredt)')}; "
                        f"{ref('cowper1966', 'Table 1 (thin-walled box)')}", shear)


def _profile_check(kind: str, h: float, b: float, tw: float, tf: float, n_flanges: int) -> None:
    if tw >= b:
        raise InputError(f"{kind}: web_thickness must be smaller than the width")
    if n_flanges * tf >= h:
        raise InputError(f"{kind}: flanges ({n_flanges} x {tf * 1e3:g} mm) do not fit in height {h * 1e3:g} mm")


def _profile_dims(height: QuantityLike, width: QuantityLike, web_thickness: QuantityLike,
                  flange_thickness: QuantityLike, root_radius: QuantityLike) -> tuple[float, ...]:
    h, b = _dim(height, "height"), _dim(width, "width")
    tw, tf = _dim(web_thickness, "web_thickness"), _dim(flange_thickness, "flange_thickness")
    return h, b, tw, tf, _dim(root_radius, "root_radius", allow_zero=True)


def i_section(height: QuantityLike, width: QuantityLike, web_thickness: QuantityLike, flange_thickness: QuantityLike,
              root_radius: QuantityLike = "0 mm") -> Section:
    """Doubly symmetric I/H profile (IPE, HEA, ...): web along z, flanges along y; lower-left origin.

    Torsion constant (Roark Table 10.7, I-section; El Darwish & Johnston): ``J = 2 K1 + K2 + 2 alpha D⁴``
    with the flanges as strips with two free ends, the web ``(h - 2 tf) tw³ / 3`` and the junction
    term of :func:`_tee_junction`; ``Wt = J / max(tf, tw)``. Shear centre = centroid.
    """
    h, b, tw, tf, r = _profile_dims(height, width, web_thickness, flange_thickness, root_radius)
    _profile_check("i_section", h, b, tw, tf, 2)
    yl, yr = (b - tw) / 2, (b + tw) / 2
    ring = _filleted([(0, 0, 0), (b, 0, 0), (b, tf, 0), (yr, tf, r), (yr, h - tf, r), (b, h - tf, 0), (b, h, 0),
                      (0, h, 0), (0, h - tf, 0), (yl, h - tf, r), (yl, tf, r), (0, tf, 0)])
    J = 2 * _strip(b, tf, 2) + (h - 2 * tf) * tw**3 / 3 + 2 * _tee_junction(tf, tw, r)
    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    A = _moments([ring])[0]
    hm = h - tf  # between flange mid-lines
    shear = (5 / 6 * 2 * b * tf, _cowper_thin(2 * b * tf / (hm * tw), b / hm) * A)
    return _thin_walled("i_section", dims, [ring], J, J / max(tf, tw, _tee_diameter(tf, tw, r)), (b / 2, h / 2),
                        f"{ref('roark8', 'Table 10.7 (I-section: K = 2K1 + K2 + 2 alpha D^4)')}; "
                        f"{ref('cowper1966', 'Table 1 (thin-walled I)')}", shear)


def t_section(height: QuantityLike, width: QuantityLike, web_thickness: QuantityLike, flange_thickness: QuantityLike,
              root_radius: QuantityLike = "0 mm") -> Section:
    """Tee: flange on top (along y), web downwards (along z); lower-left origin.

    ``J = K1 + K2 + alpha D⁴`` (Roark Table 10.7, T-section): flange with two free ends, web with one.
    Shear centre at the intersection of the flange and web mid-lines (Pilkey Sec. 2.11: the shear
    flows of a section of two walls meet there).
    """
    h, b, tw, tf, r = _profile_dims(height, width, web_thickness, flange_thickness, root_radius)
    _profile_check("t_section", h, b, tw, tf, 1)
    yl, yr = (b - tw) / 2, (b + tw) / 2
    ring = _filleted([(yl, 0, 0), (yr, 0, 0), (yr, h - tf, r), (b, h - tf, 0), (b, h, 0), (0, h, 0), (0, h - tf, 0),
                      (yl, h - tf, r)])
    J = _strip(b, tf, 2) + _strip(h - tf, tw, 1) + _tee_junction(tf, tw, r)
    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    zf = h - tf / 2  # flange mid-line; the web mid-line is y = b/2
    paths = [[((0.0, zf), (b / 2, zf), tf)], [((b, zf), (b / 2, zf), tf)], [((b / 2, 0.0), (b / 2, zf), tw)]]
    shear = (_thin_shear_area(paths, 0), _thin_shear_area(paths, 1))
    return _thin_walled("t_section", dims, [ring], J, J / max(tf, tw, _tee_diameter(tf, tw, r)), (b / 2, h - tf / 2),
                        f"{ref('roark8', 'Table 10.7 (T-section)')}; {ref('pilkey_formulas', 'Sec. 2.8, 2.11')}",
                        shear)


def l_section(height: QuantityLike, width: QuantityLike, thickness: QuantityLike, root_radius: QuantityLike = "0 mm",
              toe_radius: QuantityLike = "0 mm") -> Section:
    """Angle: vertical leg ``height`` (z), horizontal leg ``width`` (y), corner at the origin.

    Unsymmetric: ``Iyz != 0`` and the principal axes (``I1``, ``I2``, ``principal_angle``) differ from y, z.
    ``J = K1 + K2 + alpha D⁴`` (Roark Table 10.7, L-section): the horizontal leg a strip with two free
    ends, the rest of the vertical leg one, the corner term of :func:`_corner_junction`; the toe
    radii change the outline but not J. Shear centre at the intersection of the leg mid-lines (t/2, t/2).
    """
    h, b, t = _dim(height, "height"), _dim(width, "width"), _dim(thickness, "thickness")
    rr = _dim(root_radius, "root_radius", allow_zero=True)
    rt = _dim(toe_radius, "toe_radius", allow_zero=True)
    if t >= min(h, b):
        raise InputError("l_section: thickness must be smaller than both legs")
    ring = _filleted([(0, 0, 0), (b, 0, 0), (b, t, rt), (t, t, rr), (t, h, rt), (0, h, 0)])
    J = _strip(b, t, 2) + _strip(h - t, t, 1) + _corner_junction(t, t, rr)
    dims = {"height": h, "width": b, "thickness": t, **({"root_radius": rr} if rr else {}),
            **({"toe_radius": rt} if rt else {})}
    return _thin_walled("l_section", dims, [ring], J, J / max(t, _corner_diameter(t, t, rr)), (t / 2, t / 2),
                        f"{ref('roark8', 'Table 10.7 (L-section)')}; {ref('pilkey_formulas', 'Sec. 2.11')}")


def c_section(height: QuantityLike, width: QuantityLike, web_thickness: QuantityLike, flange_thickness: QuantityLike,
              root_radius: QuantityLike = "0 mm") -> Section:
    """Channel with parallel flanges (UPE/PFC type): web along z at y = 0, flanges pointing to +y.

    ``J = 2 K1 + K2 + 2 alpha D⁴``: each flange a strip with one free end, the web between the flanges
    ``(h - 2 tf) tw³ / 3``, and at each web-flange corner the L-corner term of Roark Table 10.7
    (:func:`_corner_junction`). Shear centre on the web side, at ``e = 3 b'² tf / (6 b' tf + h' tw)``
    from the web mid-line (``b' = b - tw/2``, ``h' = h - tf``): the thin-walled result
    ``e = b'² h'² tf / (4 I')`` with ``I' = tw h'³/12 + b' tf h'²/2`` (Pilkey Sec. 2.11; Timoshenko & Gere,
    Mechanics of Materials, shear centres of thin-walled open sections).
    """
    h, b, tw, tf, r = _profile_dims(height, width, web_thickness, flange_thickness, root_radius)
    _profile_check("c_section", h, b, tw, tf, 2)
    ring = _filleted([(0, 0, 0), (b, 0, 0), (b, tf, 0), (tw, tf, r), (tw, h - tf, r), (b, h - tf, 0), (b, h, 0),
                      (0, h, 0)])
    J = 2 * _strip(b, tf, 1) + (h - 2 * tf) * tw**3 / 3 + 2 * _corner_junction(tf, tw, r)
    bp, hp = b - tw / 2, h - tf
    e = 3 * bp**2 * tf / (6 * bp * tf + hp * tw)
    dims = {"height": h, "width": b, "web_thickness": tw, "flange_thickness": tf, **({"root_radius": r} if r else {})}
    yw, zb, zt = tw / 2, tf / 2, h - tf / 2  # mid-lines of the web and the flanges
    paths = [[((b, zt), (yw, zt), tf), ((yw, zt), (yw, zb), tw), ((yw, zb), (b, zb), tf)]]
    shear = (_thin_shear_area(paths, 0), _thin_shear_area(paths, 1))
    return _thin_walled("c_section", dims, [ring], J, J / max(tf, tw, _corner_diameter(tf, tw, r)), (tw / 2 - e, h / 2),
                        f"{ref('roark8', 'Table 10.7 (L corner)')}; {ref('pilkey_formulas', 'Sec. 2.8, 2.11')}",
                        shear)


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
    import shapely
    from shapely.geometry import Polygon as ShapelyPolygon

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
    """Arbitrary polygon with polygonal holes, points (y, z). Analysed by sectionproperties (the optional
    extra ``mechverify[sections]``; without it a :class:`ModelError` names the install command).

    ``outline``/``holes``: quantity arrays of shape (n, 2), sequences of (y, z) quantities/strings,
    or sequences of numbers with ``unit`` (e.g. ``unit="mm"``).
    """
    import shapely.affinity

    region = polygon_region(outline, holes, unit, "polygon")
    try:
        from sectionproperties.pre.geometry import Geometry
    except ImportError as exc:
        raise ModelError(f"polygon: {SECTIONS_HINT} [{exc}]") from None
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
