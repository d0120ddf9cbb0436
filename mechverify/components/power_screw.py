"""Power screws and their nuts: torque, efficiency, self-locking, flank pressure, pv, stresses, whirling.

Formula functions take quantities (or strings) and return quantities; each has an SI-float twin as
``f.si``. :class:`LeadScrew` and :class:`Nut` bundle them for a design (the motor/drive-train
modules wrap a :class:`LeadScrew` as a transmission element).

Thread friction with a flank angle is treated in the plane normal to the thread:
``tan(alpha_n) = tan(alpha) cos(lambda)`` and the effective friction coefficient is ``mu / cos(alpha_n)``.
For ``alpha = 0`` every formula reduces to the square-thread equations of Shigley (Eqs. 8-1, 8-2);
with ``sec(alpha)`` in place of ``1/cos(alpha_n)`` they are Shigley's Acme form (Eq. 8-5). Ball
screws use the same equations with ``alpha = 0`` and their rolling friction coefficient (THK).

Sign convention: :func:`lower_torque` is the torque the drive must apply to lower the load; a
negative value means the load back-drives the screw, and ``-T_L`` is the torque needed to hold it.

References
----------
1. R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed., McGraw-Hill Education, 2015,
   Sec. 8-2
   (Eqs. 8-1 to 8-6; body and thread stresses, pp. 418-419; Example 8-1).
2. Hamrock, Schmid & Jacobson, Fundamentals of Machine Elements, 3rd ed., CRC 2014, Sec. 16.3
   (normal-plane flank angle theta_n, Eqs. 16.8-16.12).
3. R. L. Mott, Machine Elements in Mechanical Design, 4th ed., 2004, Sec. 17-2 (Eqs. 17-7, 17-10, 17-11).
4. DIN 103 / Roloff-Matek, Maschinenelemente: mean flank pressure p = F / (pi d2 H1 n), n = m/P.
5. R. D. Blevins, Formulas for Natural Frequency and Mode Shape, 1979, Table 8-1 (whirling eigenvalues).
6. THK General Catalog, Ball Screw: permissible rotational speed (lambda factors, 0.8 safety),
   efficiency and friction coefficient (0.003..0.01).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import cache, cached_property
from pathlib import Path
from typing import Any

import pint

from mechverify.components.columns import ColumnBuckling, column_buckling, end_condition
from mechverify.components.threads import Thread, thread
from mechverify.errors import InputError, ValidityError
from mechverify.frozen import set_fields
from mechverify.materials.material import Material
from mechverify.units import (
    BOUNDS,
    QuantityLike,
    as_quantity,
    fmt,
    from_si,
    require_positive,
    si_function,
    si_to,
    to_si,
)

_DATA = Path(__file__).parent / "data" / "power_screw_factors.toml"

# Lead-screw mounting names met in catalogues -> the column end-case names of columns.py.
_END_ALIASES = {
    "supported-supported": "pinned-pinned", "simply-supported": "pinned-pinned",
    "fixed-supported": "fixed-pinned", "supported-fixed": "fixed-pinned",
    "free-supported": "fixed-free",
}


def end_case(name: str) -> str:
    """The column end-case name (``"fixed-free"``, ``"pinned-pinned"``, ``"fixed-pinned"``, ``"fixed-fixed"``)
    for a mounting name; ``"supported"`` is read as ``"pinned"`` (a single radial bearing)."""
    if not isinstance(name, str):
        raise InputError(f"end_supports: expected a name, got {type(name).__name__}")
    key = name.strip().lower().replace(" ", "-").replace("_", "-")
    return end_condition(_END_ALIASES.get(key, key)).name


@cache
def _factors() -> dict[str, Any]:
    with _DATA.open("rb") as fh:
        return tomllib.load(fh)


def whirl_factor(end: str) -> float:
    """First-mode eigenvalue ``lambda_1`` of a uniform shaft for a mounting (Blevins 1979, Table 8-1)."""
    table = _factors()["whirl"]
    name = end_case(end)
    return float(table[name])


# ---------------------------------------------------------------------- angles
def _lam(lead: float, d2: float) -> float:
    require_positive(lead, "lead", dim="length")
    require_positive(d2, "d2", dim="length")
    return math.atan(lead / (math.pi * d2))


def _cos_an(flank: float, lam: float) -> float:
    if not 0 <= flank < math.pi / 4:
        raise InputError(f"flank_angle: must lie in [0, 45) deg, got {math.degrees(flank):.4g} deg")
    return math.cos(math.atan(math.tan(flank) * math.cos(lam)))


def _mu(mu: float, name: str = "mu") -> float:
    if not 0 <= mu < 1.5:
        raise InputError(f"{name}: friction coefficient must lie in [0, 1.5), got {mu!r}")
    return mu


@si_function(returns="angle", lead="length", d2="length")
def lead_angle(lead: float, d2: float) -> float:
    """Lead angle ``lambda = atan(l / (pi d2))`` [rad] (Shigley 10th ed., Sec. 8-2)."""
    return _lam(lead, d2)


@si_function(returns="angle", flank_angle="angle", lead_angle="angle")
def normal_flank_angle(flank_angle: float, lead_angle: float) -> float:
    """Flank angle in the normal plane, ``alpha_n = atan(tan(alpha) cos(lambda))`` [rad] (Hamrock 3rd ed., Eq. 16.8)."""
    return math.acos(_cos_an(flank_angle, lead_angle))


@si_function(returns="angle", mu="dimensionless", normal_flank_angle="angle")
def friction_angle(mu: float, normal_flank_angle: float = 0.0) -> float:
    """Effective friction angle ``rho' = atan(mu / cos(alpha_n))`` [rad]; the thread self-locks while
    ``lambda < rho'`` (Shigley 10th ed., Sec. 8-2; Roloff-Matek)."""
    _mu(mu)
    return math.atan(mu / math.cos(normal_flank_angle))


# ---------------------------------------------------------------------- torque and efficiency
def _thread_ratio_raise(lead: float, d2: float, mu: float, flank: float) -> float:
    """T_R/F of the thread alone [m]."""
    lam = _lam(lead, d2)
    c, t = _cos_an(flank, lam), math.tan(lam)
    den = c - _mu(mu) * t
    if den <= 0:
        raise ValidityError(f"mu = {mu:g} with lead angle {math.degrees(lam):.3g} deg: the thread wedges and cannot "
                            "be driven (cos(alpha_n) - mu tan(lambda) <= 0)")
    return d2 / 2 * (c * t + mu) / den


def _thread_ratio_lower(lead: float, d2: float, mu: float, flank: float) -> float:
    """T_L/F of the thread alone [m] (negative: the load back-drives the screw)."""
    lam = _lam(lead, d2)
    c, t = _cos_an(flank, lam), math.tan(lam)
    return d2 / 2 * (_mu(mu) - c * t) / (c + mu * t)


def _collar(mu_collar: float, d_collar: float | None) -> float:
    if not mu_collar:
        return 0.0
    if d_collar is None:
        raise InputError("d_collar: a collar friction coefficient needs the collar's mean friction diameter")
    require_positive(d_collar, "d_collar", dim="length")
    return _mu(mu_collar, "mu_collar") * d_collar / 2


@si_function(returns="torque", F="force", mu_collar="dimensionless", d_collar="length")
def collar_torque(F: float, mu_collar: float, d_collar: float) -> float:
    """Thrust-collar friction torque ``T_c = F mu_c d_c / 2`` [N m] (Shigley 10th ed., Sec. 8-2, collar torque)."""
    return F * _collar(mu_collar, d_collar)


@si_function(returns="torque", F="force", d2="length", lead="length", mu="dimensionless", flank_angle="angle",
             mu_collar="dimensionless", d_collar="length")
def raise_torque(F: float, d2: float, lead: float, mu: float, flank_angle: float,
                 mu_collar: float = 0.0, d_collar: float | None = None) -> float:
    """Torque to move the load against its force (raise) [N m].

    ``T_R = F d2/2 (cos(alpha_n) tan(lambda) + mu) / (cos(alpha_n) - mu tan(lambda)) + F mu_c d_c/2``
    (Hamrock 3rd ed., Eq. 16.10; for alpha = 0 Shigley 10th ed., Sec. 8-2, raising torque with
    the collar torque).
    """
    return F * (_thread_ratio_raise(lead, d2, mu, flank_angle) + _collar(mu_collar, d_collar))


@si_function(returns="torque", F="force", d2="length", lead="length", mu="dimensionless", flank_angle="angle",
             mu_collar="dimensionless", d_collar="length")
def lower_torque(F: float, d2: float, lead: float, mu: float, flank_angle: float,
                 mu_collar: float = 0.0, d_collar: float | None = None) -> float:
    """Torque to move the load with its force (lower) [N m]; negative when the load back-drives the screw.

    ``T_L = F d2/2 (mu - cos(alpha_n) tan(lambda)) / (cos(alpha_n) + mu tan(lambda)) + F mu_c d_c/2``
    (Hamrock 3rd ed., Eq. 16.12; for alpha = 0 Shigley 10th ed., Sec. 8-2, lowering torque with
    the collar torque).
    """
    return F * (_thread_ratio_lower(lead, d2, mu, flank_angle) + _collar(mu_collar, d_collar))


@si_function(returns="dimensionless", d2="length", lead="length", mu="dimensionless", flank_angle="angle",
             mu_collar="dimensionless", d_collar="length")
def efficiency(d2: float, lead: float, mu: float, flank_angle: float,
               mu_collar: float = 0.0, d_collar: float | None = None) -> float:
    """Efficiency of driving the screw against the load, ``e = F l / (2 pi T_R)`` [-] (Shigley 10th ed., Sec. 8-2).

    Without collar friction ``e = tan(lambda) (cos(alpha_n) - mu tan(lambda)) / (cos(alpha_n) tan(lambda) + mu)``.
    """
    return lead / (2 * math.pi * (_thread_ratio_raise(lead, d2, mu, flank_angle) + _collar(mu_collar, d_collar)))


@si_function(returns="dimensionless", d2="length", lead="length", mu="dimensionless", flank_angle="angle",
             mu_collar="dimensionless", d_collar="length")
def backdrive_efficiency(d2: float, lead: float, mu: float, flank_angle: float,
                         mu_collar: float = 0.0, d_collar: float | None = None) -> float:
    """Efficiency of the load driving the screw, ``e' = 2 pi T_out / (F l)`` [-]; 0 when it cannot (self-locking).

    Without collar friction ``e' = (cos(alpha_n) tan(lambda) - mu) / (tan(lambda) (cos(alpha_n) + mu tan(lambda)))``;
    for alpha = 0 this is THK's reverse efficiency ``(1 - mu/tan(lambda)) / (1 + mu tan(lambda))``.
    """
    out = -_thread_ratio_lower(lead, d2, mu, flank_angle) - _collar(mu_collar, d_collar)
    return max(0.0, 2 * math.pi * out / lead)


@si_function(returns="dimensionless", d2="length", lead="length", flank_angle="angle")
def self_locking_mu(d2: float, lead: float, flank_angle: float) -> float:
    """Friction coefficient below which the load back-drives the thread, ``mu* = cos(alpha_n) tan(lambda)`` [-].

    The thread alone self-locks for ``mu > mu*`` (Hamrock 3rd ed., Sec. 16.3.3; Shigley 10th ed., Sec. 8-2,
    self-locking condition
    for alpha = 0: ``mu > tan(lambda)``). Collar friction is not counted: it is not present in every
    holding situation.
    """
    lam = _lam(lead, d2)
    return _cos_an(flank_angle, lam) * math.tan(lam)


@si_function(returns="force", torque="torque", d2="length", lead="length", mu="dimensionless", flank_angle="angle",
             mu_collar="dimensionless", d_collar="length")
def axial_force_from_torque(torque: float, d2: float, lead: float, mu: float, flank_angle: float,
                            mu_collar: float = 0.0, d_collar: float | None = None) -> float:
    """Axial force a drive torque produces against the load, ``F = T / (T_R/F)`` [N].

    The inverse of :func:`raise_torque`.
    """
    require_positive(torque, "torque", allow_zero=True, dim="torque")
    return torque / (_thread_ratio_raise(lead, d2, mu, flank_angle) + _collar(mu_collar, d_collar))


# ---------------------------------------------------------------------- nut: pressure, pv, shear
@si_function(returns="dimensionless", nut_length="length", pitch="length")
def engaged_threads(nut_length: float, pitch: float) -> float:
    """Thread turns carrying the load, ``n = m / P`` [-] (nut length m over the pitch, all starts together)."""
    require_positive(nut_length, "nut_length", dim="length")
    require_positive(pitch, "pitch", dim="length")
    return nut_length / pitch


@si_function(returns="pressure", F="force", d2="length", H1="length", engaged_threads="dimensionless")
def flank_pressure(F: float, d2: float, H1: float, engaged_threads: float) -> float:
    """Mean flank pressure ``p = F / (pi d2 H1 n)`` [Pa] (DIN 103 / Roloff-Matek; Shigley 10th ed. bearing
    stress ``2F/(pi d_m n_t p)`` with ``H1 = p/2``)."""
    require_positive(F, "F", allow_zero=True, dim="force")
    for v, n, dim in ((d2, "d2", "length"), (H1, "H1", "length"),
                      (engaged_threads, "engaged_threads", "dimensionless")):
        require_positive(v, n, dim=dim)
    return F / (math.pi * d2 * H1 * engaged_threads)


@si_function(returns="velocity", rotational_speed="angular_velocity", d2="length", lead="length")
def sliding_speed(rotational_speed: float, d2: float, lead: float) -> float:
    """Sliding speed on the flanks at the pitch diameter, ``v = pi d2 n / cos(lambda)`` [m/s]."""
    lam = _lam(lead, d2)
    return abs(rotational_speed) * d2 / 2 / math.cos(lam)


@si_function(returns="pv", pressure="pressure", speed="velocity")
def pv_value(pressure: float, speed: float) -> float:
    """Product of flank pressure and sliding speed ``pv`` [Pa m/s], compared with the nut material's limit."""
    require_positive(pressure, "pressure", allow_zero=True, dim="pressure")
    return pressure * abs(speed)


@si_function(returns="length", F="force", d2="length", H1="length", pitch="length", p_allow="pressure",
             pv_allow="pv", speed="velocity")
def nut_length_required(F: float, d2: float, H1: float, pitch: float, p_allow: float,
                        pv_allow: float | None = None, speed: float | None = None) -> float:
    """Nut length meeting both the flank-pressure limit and (with a speed) the pv limit [m].

    ``m = P F / (pi d2 H1 p_lim)`` with ``p_lim = min(p_allow, pv_allow / v)`` (inverse of :func:`flank_pressure`).
    """
    require_positive(F, "F", allow_zero=True, dim="force")
    require_positive(p_allow, "p_allow", dim="pressure")
    p_lim = p_allow
    if pv_allow is not None and speed:
        require_positive(pv_allow, "pv_allow", dim="pv")
        p_lim = min(p_lim, pv_allow / abs(speed))
    return pitch * F / (math.pi * d2 * H1 * p_lim)


@si_function(returns="pressure", F="force", diameter="length", tooth_width="length", engaged_threads="dimensionless")
def thread_shear_stress(F: float, diameter: float, tooth_width: float, engaged_threads: float) -> float:
    """Mean shear stress on the cylinder where the thread teeth root, ``tau = F / (pi D w n)`` [Pa].

    Screw: ``D = d3`` with the tooth width at d3; nut: ``D = D4`` with the nut tooth width at D4
    (:meth:`Thread.tooth_width`). Mott 4th ed., Sec. 17-2 (thread shear area per nut length). Load
    shared equally by the ``n`` engaged turns; Shigley notes the first turn carries about 0.38 F.
    """
    for v, n, dim in ((diameter, "diameter", "length"), (tooth_width, "tooth_width", "length"),
                      (engaged_threads, "engaged_threads", "dimensionless")):
        require_positive(v, n, dim=dim)
    return abs(F) / (math.pi * diameter * tooth_width * engaged_threads)


@si_function(returns="pressure", F="force", d3="length", root_width="length", height="length",
             engaged_threads="dimensionless")
def thread_bending_stress(F: float, d3: float, root_width: float, height: float, engaged_threads: float = 1.0) -> float:
    """Bending stress at the thread root, cantilever loaded at mid-height: ``3 F h / (pi d3 n w^2)`` [Pa].

    For the square thread (``w = h = p/2``) this is Shigley's ``6F/(pi d_r n_t p)`` (10th ed., Sec. 8-2).
    """
    for v, n, dim in ((d3, "d3", "length"), (root_width, "root_width", "length"), (height, "height", "length"),
                      (engaged_threads, "engaged_threads", "dimensionless")):
        require_positive(v, n, dim=dim)
    return 3 * abs(F) * height / (math.pi * d3 * engaged_threads * root_width**2)


@dataclass(frozen=True)
class ScrewStresses:
    """Nominal stresses in the screw body at the minor diameter."""

    axial: pint.Quantity  # 4F/(pi d3^2), magnitude
    torsion: pint.Quantity  # 16T/(pi d3^3)
    von_mises: pint.Quantity  # sqrt(sigma^2 + 3 tau^2)


def screw_stresses(F: QuantityLike, torque: QuantityLike, d3: QuantityLike) -> ScrewStresses:
    """Axial ``4F/(pi d3^2)``, torsional ``16T/(pi d3^3)`` and von Mises ``sqrt(s^2 + 3 t^2)`` stress [Pa]
    at the minor diameter (Shigley 10th ed., Secs. 8-2 and 5-5)."""
    f, t, d = to_si(F, "force", "F"), to_si(torque, "torque", "torque"), to_si(d3, "length", "d3")
    require_positive(d, "d3", dim="length")
    s = 4 * abs(f) / (math.pi * d**2)
    tau = 16 * abs(t) / (math.pi * d**3)
    return ScrewStresses(axial=si_to(s, "pressure", "MPa"), torsion=si_to(tau, "pressure", "MPa"),
                         von_mises=si_to(math.sqrt(s**2 + 3 * tau**2), "pressure", "MPa"))


@si_function(returns="pressure", sigma_x="pressure", sigma_y="pressure", tau_yz="pressure")
def thread_root_von_mises(sigma_x: float, sigma_y: float, tau_yz: float) -> float:
    """Von Mises stress at the thread root with ``sigma_z = tau_xy = tau_zx = 0`` [Pa]:
    ``(1/sqrt2) sqrt((sx - sy)^2 + sy^2 + sx^2 + 6 tyz^2)`` (Shigley 10th ed., Sec. 5-5; the power-screw
    example of Sec. 8-2)."""
    return math.sqrt(((sigma_x - sigma_y) ** 2 + sigma_y**2 + sigma_x**2 + 6 * tau_yz**2) / 2)


# ---------------------------------------------------------------------- kinematics and dynamics
@si_function(returns="velocity", rotational_speed="angular_velocity", lead="length")
def linear_speed(rotational_speed: float, lead: float) -> float:
    """Nut speed ``v = n l`` [m/s] (``n`` in revolutions per second)."""
    require_positive(lead, "lead", dim="length")
    return rotational_speed / (2 * math.pi) * lead


@si_function(returns="angular_velocity", speed="velocity", lead="length")
def rotational_speed(speed: float, lead: float) -> float:
    """Screw speed for a nut speed, ``n = v / l`` [rad/s]; convert with ``.to("rpm")``."""
    require_positive(lead, "lead", dim="length")
    return 2 * math.pi * speed / lead


@si_function(returns="length", lead="length", step_angle="angle")
def resolution_per_step(lead: float, step_angle: float = math.radians(1.8), microsteps: int = 1) -> float:
    """Nut travel per (micro)step, ``l * step_angle / (2 pi) / microsteps`` [m]."""
    require_positive(lead, "lead", dim="length")
    require_positive(step_angle, "step_angle", dim="angle")
    if isinstance(microsteps, bool) or not isinstance(microsteps, int) or microsteps < 1:
        raise InputError(f"microsteps: must be a whole number >= 1, got {microsteps!r}")
    return lead * step_angle / (2 * math.pi) / microsteps


@si_function(returns="inertia", mass="mass", lead="length")
def reflected_inertia(mass: float, lead: float) -> float:
    """Inertia of a translating mass seen at the screw shaft, ``J = m (l / 2 pi)^2`` [kg m^2].

    Kinetic-energy equivalence ``m v^2/2 = J w^2/2`` with ``v = w l/(2 pi)``. Thread friction is not an
    inertia: account for it in the torque (``T_acc = J alpha / eta``), not by dividing J by eta.
    """
    require_positive(mass, "mass", allow_zero=True, dim="mass")
    require_positive(lead, "lead", dim="length")
    return mass * (lead / (2 * math.pi)) ** 2


@si_function(returns="inertia", density="density", diameter="length", length="length")
def shaft_inertia(density: float, diameter: float, length: float) -> float:
    """Polar mass moment of inertia of a solid round shaft, ``pi rho L D^4 / 32`` [kg m^2]."""
    for v, n, dim in ((density, "density", "density"), (diameter, "diameter", "length"), (length, "length", "length")):
        require_positive(v, n, dim=dim)
    return math.pi * density * length * diameter**4 / 32


def critical_speed(E: QuantityLike, density: QuantityLike, d3: QuantityLike, length: QuantityLike,
                   end: str = "pinned-pinned") -> pint.Quantity:
    """First whirling (critical) speed of a screw shaft [rad/s; ``.to("rpm")``].

    ``w_c = lambda_1^2 / L^2 sqrt(E I / (rho A))`` with ``I/A = d3^2 / 16`` (the root section), the
    first bending natural frequency of a uniform Euler-Bernoulli beam (Blevins 1979, Table 8-1;
    THK General Catalog, Ball Screw, permissible rotational speed, before its 0.8 factor).
    ``lambda_1`` = 1.875 (fixed-free), pi (pinned-pinned), 3.927 (fixed-pinned), 4.730 (fixed-fixed).
    """
    e, rho = to_si(E, "pressure", "E"), to_si(density, "density", "density")
    d, L = to_si(d3, "length", "d3"), to_si(length, "length", "length")
    for v, n, dim in ((e, "E", "pressure"), (rho, "density", "density"), (d, "d3", "length"), (L, "length", "length")):
        require_positive(v, n, dim=dim)
    lam = whirl_factor(end)
    return from_si(lam**2 / L**2 * math.sqrt(e * d**2 / (16 * rho)), "angular_velocity")


# ---------------------------------------------------------------------- components
def _material(m: Material | str | None, name: str) -> Material | None:
    if m is None or isinstance(m, Material):
        return m
    if isinstance(m, str):
        from mechverify.materials.database import get
        return get(m)
    raise InputError(f"{name}.material: expected a Material or a name, got {type(m).__name__}")


def _dimensionless(v: Any, name: str) -> float:
    """A friction coefficient or ratio as a float; a plain finite number within the dimensionless bounds is
    returned as :func:`to_si` returns it (without its quantity round trip: every torque call passes mu and the
    collar's mu), anything else goes through :func:`to_si` (its checks and messages)."""
    if type(v) is float or type(v) is int:
        f = float(v)
        if math.isfinite(f) and abs(f) <= _DIMENSIONLESS_MAX:
            return f
    return to_si(v, "dimensionless", name)


_DIMENSIONLESS_MAX = BOUNDS["dimensionless"][1]


@dataclass(frozen=True)
class Nut:
    """A lead-screw nut: material, engaged length, friction range against the screw and its limits.

    Give ``length`` (nut thread length m) or ``engaged_threads``; the friction coefficient as a range
    ``mu_min..mu_max`` (or one ``mu`` for both); ``p_allow`` [Pa] and ``pv_allow`` [Pa m/s] are the
    allowable flank pressure and pv. Missing values are taken from the material
    (``mu_min``/``mu_max``/``p_max``/``pv_max``) when it has them.
    """

    material: Material | str | None = None
    length: QuantityLike | None = None
    engaged_threads: float | None = None
    mu_min: Any = None
    mu_max: Any = None
    mu: Any = None
    p_allow: Any = None
    pv_allow: Any = None
    name: str = "nut"

    def __post_init__(self) -> None:
        mat = _material(self.material, self.name)
        set_fields(self, material=mat)
        if self.length is not None:
            q = as_quantity(self.length, "length", f"{self.name}.length")
            if q.magnitude <= 0:
                raise InputError(f"{self.name}.length: must be positive, got {fmt(q)}")
            set_fields(self, length=q)
        if self.engaged_threads is not None:
            n = _dimensionless(self.engaged_threads, f"{self.name}.engaged_threads")
            if n <= 0:
                raise InputError(f"{self.name}.engaged_threads: must be positive, got {n:g}")
            set_fields(self, engaged_threads=n)
        if self.mu is not None:
            if self.mu_min is not None or self.mu_max is not None:
                raise InputError(f"{self.name}: give either mu or the range mu_min..mu_max, not both")
            set_fields(self, mu_min=self.mu, mu_max=self.mu)
        for attr in ("mu_min", "mu_max"):
            v = getattr(self, attr)
            if v is None and mat is not None and getattr(mat, attr) is not None:
                v = getattr(mat, attr)
            if v is not None:
                f = _dimensionless(v, f"{self.name}.{attr}")
                if not 0 <= f < 1.5:
                    raise InputError(f"{self.name}.{attr}: friction coefficient must lie in [0, 1.5), got {f:g}")
                v = f
            set_fields(self, **{attr: v})
        if (self.mu_min is None) != (self.mu_max is None):
            raise InputError(f"{self.name}: give both ends of the friction range mu_min..mu_max")
        if self.mu_min is not None and self.mu_min > self.mu_max:
            raise InputError(f"{self.name}: friction range reversed: mu_min = {self.mu_min:g} > "
                             f"mu_max = {self.mu_max:g}")
        for attr, dim, mprop in (("p_allow", "pressure", "p_max"), ("pv_allow", "pv", "pv_max")):
            v = getattr(self, attr)
            if v is None and mat is not None:
                v = getattr(mat, mprop)
            if v is not None:
                v = as_quantity(v, dim, f"{self.name}.{attr}")
                if v.magnitude <= 0:
                    raise InputError(f"{self.name}.{attr}: must be positive, got {fmt(v)}")
            set_fields(self, **{attr: v})

    def require_mu(self) -> tuple[float, float]:
        if self.mu_min is None:
            raise InputError(f"{self.name}: no friction coefficient; give mu_min and mu_max "
                             "(or a material that has them)")
        return float(self.mu_min), float(self.mu_max)

    def engaged(self, th: Thread | str) -> float:
        """Engaged thread turns ``n``: as given, or nut length / pitch."""
        if self.engaged_threads is not None:
            return float(self.engaged_threads)
        if self.length is None:
            raise InputError(f"{self.name}: give the nut length or the number of engaged threads")
        return engaged_threads.si(to_si(self.length, "length"), to_si(thread(th).pitch, "length"))


def ball_nut(name: str = "ball nut", **kw: Any) -> Nut:
    """A ball nut with the rolling friction range of the THK catalogue (mu = 0.003..0.01) unless given."""
    f = _factors()["ball_screw"]
    kw.setdefault("mu_min", f["mu_min"])
    kw.setdefault("mu_max", f["mu_max"])
    return Nut(name=name, **kw)


@dataclass(frozen=True)
class LeadScrew:
    """A lead screw: thread (designation or :class:`Thread`), length between its supports, material and
    end supports (``"fixed-free"``, ``"pinned-pinned"``/``"supported-supported"``,
    ``"fixed-pinned"``/``"fixed-supported"``, ``"fixed-fixed"``).

    Methods take the axial force ``F`` and a friction coefficient ``mu`` (pick it from the nut's range:
    ``mu_max`` for motor torque, ``mu_min`` for self-locking and holding). ``collar_mu`` and
    ``collar_diameter`` add a thrust-collar friction torque.
    """

    thread: Thread | str
    length: QuantityLike
    material: Material | str | None = None
    end_supports: str = "fixed-pinned"
    name: str = "lead screw"

    def __post_init__(self) -> None:
        set_fields(self, thread=thread(self.thread))
        q = as_quantity(self.length, "length", f"{self.name}.length")
        if q.magnitude <= 0:
            raise InputError(f"{self.name}.length: must be positive, got {fmt(q)}")
        set_fields(self, length=q, material=_material(self.material, self.name),
                   end_supports=end_case(self.end_supports))

    # geometry -----------------------------------------------------------
    @property
    def lead(self) -> pint.Quantity:
        return self.thread.lead

    @property
    def lead_angle(self) -> pint.Quantity:
        return self.thread.lead_angle

    def _g(self) -> tuple[float, float, float]:
        return self._geometry

    @cached_property
    def _geometry(self) -> tuple[float, float, float]:
        """d2, lead, flank angle [SI] (the thread is immutable: computed once)."""
        t = self.thread
        return to_si(t.d2, "length"), to_si(t.lead, "length"), to_si(t.flank_angle, "angle")

    def _collar(self, collar_mu: Any, collar_diameter: Any) -> tuple[float, float | None]:
        mc = _dimensionless(collar_mu, "collar_mu")
        dc = None if collar_diameter is None else to_si(collar_diameter, "length", "collar_diameter")
        return mc, dc

    # friction -----------------------------------------------------------
    def friction_angle(self, mu: Any) -> pint.Quantity:
        """Effective friction angle ``atan(mu / cos(alpha_n))`` [deg]."""
        return friction_angle(mu, self.thread.normal_flank_angle).to("deg")

    def self_locking_mu(self) -> pint.Quantity:
        """Friction coefficient below which the load back-drives the screw."""
        return from_si(self_locking_mu.si(*self._g()), "dimensionless")

    def raise_torque(self, F: QuantityLike, mu: Any, collar_mu: Any = 0.0,
                     collar_diameter: Any = None) -> pint.Quantity:
        """Torque to drive against the load [N m]."""
        d2, l, a = self._g()
        mc, dc = self._collar(collar_mu, collar_diameter)
        return from_si(raise_torque.si(to_si(F, "force", "F"), d2, l, _dimensionless(mu, "mu"), a, mc, dc), "torque")

    def lower_torque(self, F: QuantityLike, mu: Any, collar_mu: Any = 0.0,
                     collar_diameter: Any = None) -> pint.Quantity:
        """Torque to drive with the load [N m]; negative: the load back-drives the screw."""
        d2, l, a = self._g()
        mc, dc = self._collar(collar_mu, collar_diameter)
        return from_si(lower_torque.si(to_si(F, "force", "F"), d2, l, _dimensionless(mu, "mu"), a, mc, dc), "torque")

    def holding_torque(self, F: Any, mu: Any, collar_mu: Any = 0.0, collar_diameter: Any = None) -> pint.Quantity:
        """Torque needed to keep the load from back-driving the screw, ``max(0, -T_L)`` [N m]."""
        t = self.lower_torque(F, mu, collar_mu, collar_diameter)
        return from_si(max(0.0, -to_si(t, "torque")), "torque")

    def efficiency(self, mu: Any, collar_mu: Any = 0.0, collar_diameter: Any = None) -> pint.Quantity:
        """Efficiency of driving against the load."""
        d2, l, a = self._g()
        mc, dc = self._collar(collar_mu, collar_diameter)
        return from_si(efficiency.si(d2, l, _dimensionless(mu, "mu"), a, mc, dc), "dimensionless")

    def backdrive_efficiency(self, mu: Any, collar_mu: Any = 0.0, collar_diameter: Any = None) -> pint.Quantity:
        """Efficiency of the load driving the screw (0 when self-locking)."""
        d2, l, a = self._g()
        mc, dc = self._collar(collar_mu, collar_diameter)
        return from_si(backdrive_efficiency.si(d2, l, _dimensionless(mu, "mu"), a, mc, dc), "dimensionless")

    def axial_force(self, torque: QuantityLike, mu: Any, collar_mu: Any = 0.0,
                    collar_diameter: Any = None) -> pint.Quantity:
        """Axial force a drive torque produces against the load [N]."""
        d2, l, a = self._g()
        mc, dc = self._collar(collar_mu, collar_diameter)
        return from_si(axial_force_from_torque.si(to_si(torque, "torque", "torque"), d2, l,
                                                  _dimensionless(mu, "mu"), a, mc, dc), "force")

    # kinematics ---------------------------------------------------------
    def linear_speed(self, rotational_speed_: Any) -> pint.Quantity:
        """Nut speed for a screw speed (``"540 rpm"`` -> m/s)."""
        return linear_speed(rotational_speed_, self.lead)

    def rotational_speed(self, speed: Any) -> pint.Quantity:
        """Screw speed [rpm] for a nut speed."""
        return rotational_speed(speed, self.lead).to("rpm")

    def sliding_speed(self, rotational_speed_: Any) -> pint.Quantity:
        """Flank sliding speed at d2 [m/s]."""
        return sliding_speed(rotational_speed_, self.thread.d2, self.lead)

    def resolution(self, step_angle: Any = "1.8 deg", microsteps: int = 1) -> pint.Quantity:
        """Nut travel per motor (micro)step [mm]."""
        return resolution_per_step(self.lead, step_angle, microsteps).to("mm")

    def reflected_inertia(self, mass: Any) -> pint.Quantity:
        """Inertia of a translating mass at the screw shaft, ``m (l/2pi)^2`` [kg m^2]."""
        return reflected_inertia(mass, self.lead)

    def rotor_inertia(self) -> pint.Quantity:
        """The screw's own inertia, as a solid cylinder of the pitch diameter [kg m^2] (needs the density)."""
        rho = self._mat("density")
        return shaft_inertia(rho, self.thread.d2, self.length)

    # strength -----------------------------------------------------------
    def material_property(self, prop: str) -> pint.Quantity:
        """A property of the screw material (``"yield_strength"``, ``"E"``, ``"density"``, ...).

        Raises:
            InputError: the screw has no material, or the material lacks the property.
        """
        return self._mat(prop)

    def _mat(self, prop: str) -> pint.Quantity:
        if self.material is None:
            raise InputError(f"{self.name}: no material; give one to compute {prop.replace('_', ' ')}")
        return self.material.require(prop)

    def stresses(self, F: Any, torque: Any) -> ScrewStresses:
        """Body stresses at the minor diameter d3 for an axial force and a torque."""
        return screw_stresses(F, torque, self.thread.d3)

    def buckling(self, length: Any = None, basis: str = "recommended") -> ColumnBuckling:
        """Column buckling of the root section (Euler or Johnson, Shigley Table 4-2 end constant)."""
        L = self.length if length is None else length
        return column_buckling(self._mat("E"), self._mat("yield_strength"), self.thread.minor_area,
                               self.thread.minor_second_moment, L, self.end_supports, basis)

    def critical_speed(self, length: Any = None) -> pint.Quantity:
        """First whirling speed [rpm] of the root section between the supports."""
        L = self.length if length is None else length
        return critical_speed(self._mat("E"), self._mat("density"), self.thread.d3, L, self.end_supports).to("rpm")


__all__ = ["LeadScrew", "Nut", "ball_nut", "ScrewStresses", "end_case", "whirl_factor", "lead_angle",
           "normal_flank_angle", "friction_angle", "collar_torque", "raise_torque", "lower_torque", "efficiency",
           "backdrive_efficiency", "self_locking_mu", "axial_force_from_torque", "engaged_threads", "flank_pressure",
           "sliding_speed", "pv_value", "nut_length_required", "thread_shear_stress", "thread_bending_stress",
           "screw_stresses", "thread_root_von_mises", "linear_speed", "rotational_speed", "resolution_per_step",
           "reflected_inertia", "shaft_inertia", "critical_speed"]
