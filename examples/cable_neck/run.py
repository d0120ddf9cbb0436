"""Reference project 001 (cable-driven neck): the document's Tabla 6 next to the spine model of the package.

The neck's statics live in :mod:`mechverify.mechanisms.cable_spine` (``CableSpine``: the spring as a
column with Timoshenko & Gere's rigidities, Sec. 2.18; one pulling cable as in the document's Sec. 3.2.2;
small-deflection beam-column = the document's Eqs. (3.9)-(3.19), or the large-deflection elastica), and
design.toml uses it through the ``cable_spine`` type. This script is the one-off comparison with the
document: the cable tension over the tilt with the document's wrong beta0 (0.554, Tabla 5), with the
correct one, and with the 1 kg head; linear model and elastica side by side.

Run ``python examples/cable_neck/run.py`` for the table in docs/examples/cable_neck.md.
"""

from __future__ import annotations

from mechverify.components.springs import CompressionSpring
from mechverify.mechanisms.cable_spine import CableSpine, UnreachableTiltError
from mechverify.units import Q, QuantityLike, as_quantity

G0 = 9.80665  # standard gravity [m/s^2]


def spine(**overrides: object) -> CompressionSpring:
    """The neck's spring as the document specifies it (Tabla 4; ends not stated, squared-ground assumed)."""
    kw: dict = dict(d="3.07 mm", D="30 mm", Na=15, L0="100 mm", end="squared-ground", material="A228",
                    G="79.3 GPa", E="206.8 GPa", name="spine")
    kw.update(overrides)
    return CompressionSpring(**kw)


def drum_torque(tension: QuantityLike, drum_diameter: QuantityLike = "20 mm", efficiency: float = 0.85):
    """Torque at the drum, M = (d1/2) F_L / eta (the document's Eq. (3.23), maxon 'crane' transmission)."""
    r = as_quantity(drum_diameter, "length", "drum_diameter") / 2
    return (r * as_quantity(tension, "force", "tension") / efficiency).to("N*m")


def tilt_table(weight: QuantityLike, angles_deg=(1, 2, 5, 10, 15, 20, 30, 40), beta0=None, method="linear"):
    """Rows (angle, state or None) over the tilt range; None where the model has no equilibrium."""
    model = CableSpine(spine(), weight=weight, beta0=beta0)
    rows = []
    for ang in angles_deg:
        try:
            rows.append((ang, model.at_tilt(Q(ang, "deg"), method)))
        except UnreachableTiltError:
            rows.append((ang, None))
    return rows


def main() -> None:
    s = spine()
    r = s.rigidities()
    print(f"spine: k = {s.rate.to('N/m'):.1f~P}, beta0 = {r.beta:.4f~P} (document: 0.554), "
          f"gamma0 = {r.gamma:.1f~P}, P_cr (fixed-free, with shear) = {CableSpine(s).critical_load():.2f} N")
    cases = [("platform only, W = 1.25 N (document's Tabla 6, its beta0 = 0.554)", Q(1.25, "N"), "0.554 N*m**2"),
             ("platform only, W = 1.25 N, correct beta0", Q(1.25, "N"), None),
             ("1 kg head, W = 9.81 N (design.toml), correct beta0", Q(9.81, "N"), None),
             ("1 kg head + platform, W = 11.06 N, correct beta0", Q(1.25 + G0, "N"), None)]
    for title, W, b0 in cases:
        print(f"\n{title}")
        print(f"{'tilt':>5} {'T lin [N]':>9} {'T ela [N]':>9} {'y_b ela [mm]':>12} {'P/Pcr':>6} {'M drum [N m]':>12}")
        for (ang, lin), (_a, ela) in zip(tilt_table(W, beta0=b0), tilt_table(W, beta0=b0, method="elastica")):
            tl = f"{lin.tension:9.3f}" if lin else f"{'-':>9}"
            if ela is None:
                print(f"{ang:>5} {tl} {'buckles before this tilt':>30}")
                continue
            M = drum_torque(Q(ela.tension, "N")).m_as("N*m")
            print(f"{ang:>5} {tl} {ela.tension:9.3f} {ela.lateral * 1e3:12.2f} {ela.buckling_ratio:6.3f} {M:12.4f}")


if __name__ == "__main__":
    main()
