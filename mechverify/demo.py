"""``make demo``: verify the bundled example design and print its summary.

Until the lead-screw-lift example and the reports land, this prints the material data and the
result model on a minimal example so that the set-up is exercised end to end.
"""

from __future__ import annotations

from mechverify import Q, materials
from mechverify.checks import CheckResult, ResultSet


def main() -> int:
    steel = materials.get("Structural Steel")
    # Tension bar, 10 mm x 4 mm, 2 kN: sigma = F/A (Shigley 10th ed., Eq. 3-22).
    area = Q(10, "mm") * Q(4, "mm")
    stress = (Q(2, "kN") / area).to("MPa")
    results = ResultSet([CheckResult("static_strength", "demo bar", stress, steel.yield_strength, required_sf=2.0,
                                     title="Axial stress vs yield", formula=r"\sigma = F/A",
                                     source="Shigley 10th ed., Eq. 3-22")], name="demo")
    print(results.table())
    return 0 if results.passed else 1


if __name__ == "__main__":
    raise SystemExit(main())
