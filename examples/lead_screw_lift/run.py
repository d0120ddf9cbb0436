"""Reference project 004: lead-screw lift for two wearable robotic arms (worked example).

``design.toml`` holds the lift as the document specifies it (Tr10x2 screw with its iglidur R nut, the
608 bearings, the stepper drive) and is checked by ``mechverify check``. This script adds what a design
file cannot hold yet, with the Python API:

1. The thread selection over the document's Tabla 1 (19 trapezoidal threads): lead angle, self-locking
   at the nut's lowest friction, raising torque and efficiency at both ends of the nut's friction range
   (0.09..0.25), mean flank pressure and pv at the required 18 mm/s, next to the document's Tablas 2-6
   (``document_tables.csv``).
2. Screw bending in the horizontal posture (torso bent 90°): 120 N at mid-span between the end
   supports, Shigley 10th ed. Table A-9 cases 5 (pinned ends: what two single-row ball bearings give)
   and 14 (clamped ends), for Tr8x1.5 and Tr10x2, with the root section (d3) for strength and the
   root/pitch/major diameters bracketing the stiffness, next to the document's Inventor figures; the
   design file checks the pinned Tr10x2 case (``screw_horizontal``, a ``link``). The FEA beam model is
   not in mechverify yet (see docs/examples/lead_screw_lift.md). Also the load shared by the screw and
   the two guide rods in proportion to their bending stiffness.
3. The arm plate (4 vs 6 mm) and the base plate (8 vs 6 mm): plate-bending FEA in ``design_plates.toml``
   (type ``plate_fea``, checked and in the report), with :func:`plate_fea_table` next to the document's
   Inventor figures; the closed-form estimates (:func:`arm_plate`, :func:`base_plate`) stay as a cross-check.

``python examples/lead_screw_lift/run.py`` prints the tables and writes ``report.html`` and
``report.pdf`` next to this file (``--out DIR`` elsewhere, ``--no-pdf`` to skip the PDF); it exits 1
because the design as specified fails checks.
``mechverify.demo`` (``make demo``) calls :func:`verify` and :func:`write_reports` of this file; the
report is the same as ``mechverify check design.toml --report report.html`` writes.
"""

from __future__ import annotations

import argparse
import csv
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mechverify.checks import screws as sc
from mechverify.checks.result import ResultSet
from mechverify.components.links import Link, beam_max_deflection, beam_max_moment
from mechverify.components.plates import roark_rectangular_plate
from mechverify.components.power_screw import LeadScrew, Nut
from mechverify.components.sections import circle, rectangle
from mechverify.materials import get as get_material
from mechverify.units import Q

HERE = Path(__file__).resolve().parent
DESIGN = HERE / "design.toml"
PLATES = HERE / "design_plates.toml"

# ---------------------------------------------------------------- document data (reference project 004)
LOAD = Q(350, "N")  # lifted load (2.2.1, under Formula 5)
MIN_SPEED = Q(18, "mm/s")  # minimum lifting speed (2.1.1)
NUT_MATERIAL = "iglidur R"  # Tabla 3
SCREW_MATERIAL = "Inventor Steel"  # "acero"; the Inventor studies used the default library steel
SPAN = Q(450, "mm")  # screw length (2.2.3), span between the bearings
SIDE_LOAD = Q(120, "N")  # horizontal posture: "350 N ... repartida entre ambas varillas y el husillo"
ROD_OD, ROD_T = Q(12, "mm"), Q(1, "mm")  # hollow guide rods (2.2.1)
PLATE_MATERIAL = "Inventor Aluminum 6061"  # "aluminio"; Inventor's default aluminium
ARM_LOAD, ARM_LEVER = Q(120, "N"), Q(400, "mm")  # arm + gripper weight at half the 800 mm arm (2.2.2)
PAYLOAD, PAYLOAD_LEVER = Q(30, "N"), Q(800, "mm")  # 3 kg at the arm's tip
ARM_PLATE_HEIGHT = Q(160, "mm")  # 335 mm x 160 mm front face (2.2.2)
BASE_A, BASE_B = Q(450, "mm"), Q(400, "mm")  # base plate (2.2.2)
BASE_LOAD = 2 * (ARM_LOAD + PAYLOAD) + Q(80, "N")  # both arms, payloads and the rest of the lift: 380 N
# The document's Inventor results, for the comparison tables.
DOC_SCREW = {"Tr8x1.5": (0.45, 1.6), "Tr10x2": (1.2, 0.8)}  # (safety factor, max displacement mm), Figs. 11-14
DOC_ARM_PLATE = {4: (1.4, 1.5), 6: (2.75, 0.44)}  # Figs. 26-29
DOC_BASE_PLATE = {8: (4.0, 0.17), 6: (2.9, 0.39)}  # Figs. 30-33 ("superior a 4")


# ---------------------------------------------------------------- 1. thread table
@dataclass(frozen=True)
class ThreadRow:
    """One thread of Tabla 1, computed with mechverify (angles in rad as the document prints them)."""

    designation: str
    d2: float  # mm
    lead_angle: float  # rad, atan(l / (pi d2))
    friction_angle: float  # rad, atan(mu_min / cos alpha_n)
    self_locking: bool
    torque_min: float  # N m, raising 350 N at mu_min
    torque_max: float  # N m, raising 350 N at mu_max
    efficiency_min: float  # at mu_min
    efficiency_max: float  # at mu_max
    pressure: float  # MPa, nut length = d (the document's assumption)
    pv: float  # MPa m/s at 18 mm/s, nut length = d
    rpm: float  # screw speed for 18 mm/s
    doc: dict[str, str]


def document_rows() -> list[dict[str, str]]:
    """Tablas 2, 4, 5 and 6 of the document, one dict per thread (strings as printed)."""
    with (HERE / "document_tables.csv").open(encoding="utf-8") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def thread_table(load: Any = LOAD, speed: Any = MIN_SPEED) -> list[ThreadRow]:
    """Every thread of Tabla 1 with the iglidur R nut, its length taken as d as the document does."""
    rows = []
    for doc in document_rows():
        screw = LeadScrew(doc["designation"], SPAN, SCREW_MATERIAL, "pinned-pinned", name=doc["designation"])
        th = screw.thread
        nut = Nut(NUT_MATERIAL, length=th.d, name=f"{th.designation} nut")
        mu_lo, mu_hi = nut.require_mu()
        lock = sc.check_self_locking(screw, nut)
        p = sc.check_nut_flank_pressure(screw, nut, load)
        pv = sc.check_nut_pv(screw, nut, load, speed=speed)
        rows.append(ThreadRow(
            designation=th.designation, d2=th.d2.m_as("mm"), lead_angle=th.lead_angle.m_as("rad"),
            friction_angle=screw.friction_angle(mu_lo).m_as("rad"), self_locking=lock.passed,
            torque_min=screw.raise_torque(load, mu_lo).m_as("N*m"),
            torque_max=screw.raise_torque(load, mu_hi).m_as("N*m"),
            efficiency_min=screw.efficiency(mu_lo).m_as(""), efficiency_max=screw.efficiency(mu_hi).m_as(""),
            pressure=p.demand.m_as("MPa"), pv=pv.demand.m_as("MPa*m/s"),
            rpm=screw.rotational_speed(speed).m_as("rpm"), doc=doc))
    return rows


def thread_table_markdown(rows: list[ThreadRow]) -> str:
    head = ("| thread | λ doc / mv [rad] | ρ' doc / mv [rad] | self-locking doc / mv | T raise doc / mv μ 0.09 / "
            "mv μ 0.25 [N·m] | η doc / mv 0.09 / 0.25 | p doc / mv [MPa] | pv at 18 mm/s [MPa·m/s] |\n"
            "|---|---|---|---|---|---|---|---|")
    lines = [head]
    for r in rows:
        d = r.doc
        lines.append(
            f"| {r.designation} | {float(d['alpha_rad']):.5f} / {r.lead_angle:.5f} | {float(d['delta_rad']):.5f} / "
            f"{r.friction_angle:.5f} | {d['self_locking']} / {'yes' if r.self_locking else 'no'} | "
            f"{float(d['M_Nm']):.3f} / {r.torque_min:.3f} / {r.torque_max:.3f} | {float(d['efficiency']):.3f} / "
            f"{r.efficiency_min:.3f} / {r.efficiency_max:.3f} | {float(d['p_MPa']):.2f} / {r.pressure:.2f} | "
            f"{r.pv:.2f}{' > 0.27' if r.pv > 0.27 else ''} |")
    return "\n".join(lines)


# ---------------------------------------------------------------- 2. screw bending, horizontal posture
BEAM_CASES = {"pinned": "simply_supported_center_load", "clamped": "fixed_fixed_center_load"}


@dataclass(frozen=True)
class BendingRow:
    thread: str
    ends: str
    stress_root: float  # MPa, M / (pi d3^3 / 32)
    safety_factor: float  # Sy / stress
    deflection: dict[str, float]  # mm, for the d3, d2 and d cylinders


def screw_bending(designation: str, ends: str, load: Any = SIDE_LOAD, span: Any = SPAN) -> BendingRow:
    """Mid-span load on the screw between its end supports (Shigley 10th ed., Table A-9, cases 5 and 14)."""
    screw = LeadScrew(designation, span, SCREW_MATERIAL)
    th, mat = screw.thread, screw.material
    case = BEAM_CASES[ends]
    m = beam_max_moment(case, load, span)
    sigma = (m / circle(th.d3).Wel_y).to("MPa")
    ys = {name: beam_max_deflection(case, load, span, mat.E, circle(getattr(th, name)).Iy).m_as("mm")
          for name in ("d3", "d2", "d")}
    return BendingRow(th.designation, ends, sigma.m_as("MPa"), (mat.yield_strength / sigma).m_as(""), ys)


def bending_markdown() -> str:
    lines = ["| thread | ends | σ at d3 [MPa] | SF (Sy 207 MPa) doc / mv | deflection d3 / d2 / d [mm] (doc) |",
             "|---|---|---|---|---|"]
    for des, (sf_doc, y_doc) in DOC_SCREW.items():
        for ends in BEAM_CASES:
            r = screw_bending(des, ends)
            y = r.deflection
            lines.append(f"| {des} | {ends} | {r.stress_root:.0f} | {sf_doc} / {r.safety_factor:.2f} | "
                         f"{y['d3']:.2f} / {y['d2']:.2f} / {y['d']:.2f} ({y_doc}) |")
    return "\n".join(lines)


def load_sharing(designation: str = "Tr10x2", total: Any = LOAD) -> dict[str, Any]:
    """Share of a mid-span load taken by the screw and by each guide rod when all three deflect alike.

    The three members span the same length with the same supports and meet at the carriage, so the load
    divides in proportion to E I (deflection compatibility, Shigley 10th ed. Sec. 4-10); rods of the
    same steel as the screw, screw taken at its root diameter.
    """
    screw = LeadScrew(designation, SPAN, SCREW_MATERIAL)
    i_screw = circle(screw.thread.d3).Iy
    rod = Link(SPAN, {"kind": "tube", "outer_diameter": ROD_OD, "thickness": ROD_T}, SCREW_MATERIAL, name="guide rod")
    i_rod = rod.section.Iy
    share = (i_screw / (i_screw + 2 * i_rod)).m_as("")
    f_rod = Q(total) * (1 - share) / 2
    m_rod = beam_max_moment(BEAM_CASES["pinned"], f_rod, SPAN)
    return {"screw_share": share, "screw_force": Q(total) * share, "rod_force": f_rod,
            "rod_stress": (m_rod / rod.section.Wel_y).to("MPa")}


# ---------------------------------------------------------------- 3. plates (closed-form estimates)
def arm_plate(thickness_mm: float, with_payload: bool = True) -> dict[str, float]:
    """Nominal stress in the arm plate beside the carriage: the arm's moment twists the plate strip.

    The arm sticks out 400/800 mm in front of the plate, so its weight puts a moment about the plate's
    horizontal axis at each arm anchor; between the carriage and the anchor the 160 mm high plate strip
    carries it in torsion: tau = T / Wt (Saint-Venant, Timoshenko & Goodier Sec. 109; Roark 8th ed.
    Table 10.7 case 4), von Mises sqrt(3) tau. Holes and the fixture edges are not in it.
    """
    t = ARM_LOAD * ARM_LEVER + (PAYLOAD * PAYLOAD_LEVER if with_payload else Q(0, "N*m"))
    sec = rectangle(ARM_PLATE_HEIGHT, Q(thickness_mm, "mm"))
    tau = (t / sec.Wt).to("MPa")
    sy = get_material(PLATE_MATERIAL).yield_strength
    vm = math.sqrt(3) * tau
    return {"torque": t.m_as("N*m"), "tau": tau.m_as("MPa"), "von_mises": vm.m_as("MPa"),
            "safety_factor": (sy / vm).m_as("")}


def base_plate(thickness_mm: float) -> dict[str, float]:
    """Base plate bolted at its 4 corners, 380 N near its centre, aluminium.

    * Mean bending stress across the mid-section: with four symmetric corner supports each takes P/4,
      so the moment across either centre line is exactly M = P a/4 (statics); sigma = 6 M/(b t^2)
      over the full width (the lightening cut-out only raises it). A lower bound on the peak stress.
    * Roark 8th ed. Table 11.4 case 1b (all edges simply supported, load on a 20 mm circle): edge
      supports are stiffer than corner bolts, so this stress and deflection are lower bounds as well.
    """
    t = Q(thickness_mm, "mm")
    mat = get_material(PLATE_MATERIAL)
    out = {}
    for a, b, key in ((BASE_A, BASE_B, "mean_a"), (BASE_B, BASE_A, "mean_b")):
        m = BASE_LOAD * a / 4
        out[key] = (6 * m / (b * t**2)).m_as("MPa")
    est = roark_rectangular_plate(BASE_A, BASE_B, t, mat.E, BASE_LOAD, edges="simply_supported",
                                  loading="central", load_radius="10 mm")
    out["roark_stress"] = est.max_stress.m_as("MPa")
    out["roark_deflection"] = est.max_deflection.m_as("mm")
    return out


def plates_markdown() -> str:
    lines = ["| plate | t [mm] | estimate | σ_vM or σ [MPa] | SF = 275 MPa / σ | document (Inventor): SF, max. "
             "displacement |",
             "|---|---|---|---|---|---|"]
    for t, (sf, y) in DOC_ARM_PLATE.items():
        for wp in (False, True):
            a = arm_plate(t, wp)
            what = "arm + payload, 72 N·m" if wp else "arm only, 48 N·m"
            lines.append(f"| arm plate | {t} | strip torsion, {what} | {a['von_mises']:.0f} | {a['safety_factor']:.2f} "
                         f"| {sf}, {y} mm |")
    for t, (sf, y) in DOC_BASE_PLATE.items():
        b = base_plate(t)
        sy = get_material(PLATE_MATERIAL).yield_strength.m_as("MPa")
        worst = max(b["mean_a"], b["mean_b"])
        lines.append(f"| base plate | {t} | mean σ at mid-section, 380 N, corners | {worst:.1f} | {sy / worst:.1f} "
                     f"| {sf}, {y} mm |")
        lines.append(f"| base plate | {t} | Roark 11.4 case 1b (SS edges) | {b['roark_stress']:.1f} "
                     f"(y = {b['roark_deflection']:.2f} mm) | {sy / b['roark_stress']:.1f} | {sf}, {y} mm |")
    return "\n".join(lines)


def plate_fea_table(run: tuple[Any, ResultSet] | None = None) -> str:
    """The FEA plate results of ``design_plates.toml`` next to the document's Inventor figures (markdown)."""
    design, rs = run or verify(PLATES)
    sy = get_material(PLATE_MATERIAL).yield_strength.m_as("MPa")
    doc = {**{f"arm_plate_{t}": v for t, v in DOC_ARM_PLATE.items()},
           **{f"base_plate_{t}": v for t, v in DOC_BASE_PLATE.items()}}
    lines = ["| plate | σ_vM max [MPa] | SF = 275 MPa / σ | max. deflection [mm] | document (Inventor): SF, "
             "deflection |",
             "|---|---|---|---|---|"]
    for name, (sf, y) in doc.items():
        s, d = rs.get(name, "plate_stress_fea"), rs.get(name, "plate_deflection_fea")
        vm = s.demand.m_as("MPa")
        lines.append(f"| {name} | {vm:.1f} | {sy / vm:.2f} | {d.demand.m_as('mm'):.3f} | "
                     f"{'> ' if name == 'base_plate_8' else ''}{sf}, {y} mm |")
    return "\n".join(lines)


# ---------------------------------------------------------------- design + extras, reports
def verify(design_path: str | Path = DESIGN) -> tuple[Any, ResultSet]:
    """Verify ``design.toml``: (design, results), as ``mechverify check`` does."""
    from mechverify.design import load

    design = load(design_path)
    return design, design.verify()


def write_reports(out_dir: str | Path = HERE, pdf: bool = True, run: tuple[Any, ResultSet] | None = None,
                  plates_run: tuple[Any, ResultSet] | None = None, detail: str = "all") -> list[Path]:
    """Write report.html (and report.pdf) of the verified example (design.toml, then design_plates.toml).

    ``detail``: ``"all"`` (every check in detail, the committed report) or ``"problems"`` (the failing
    and warning checks, what ``mechverify check --report`` and the demo write).
    """
    from mechverify.reports import render_html, write_report

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    runs = [run or verify(), plates_run or verify(PLATES)]
    html = render_html(runs, detail=detail)  # once for both files
    paths = [write_report(runs, out / "report.html", html=html)]
    if pdf:
        paths.append(write_report(runs, out / "report.pdf", html=html))
    return paths


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(HERE), help="folder for report.html/report.pdf (default: this folder)")
    ap.add_argument("--no-pdf", action="store_true", help="write the HTML report only")
    args = ap.parse_args(argv)
    print("## Thread table (350 N, iglidur R nut of length d, mu 0.09..0.25)\n")
    print(thread_table_markdown(thread_table()))
    print("\n## Screw bending, horizontal posture (120 N at mid-span, 450 mm)\n")
    print(bending_markdown())
    s = load_sharing()
    print(f"\nLoad sharing by E I (350 N): screw {s['screw_share']:.1%} = {s['screw_force']:.3g~P}, "
          f"each rod {s['rod_force']:.3g~P}, rod stress {s['rod_stress']:.3g~P}")
    plates = verify(PLATES)
    print("\n## Plates, plate-bending FEA (design_plates.toml)\n")
    print(plate_fea_table(plates))
    print("\n## Plates, closed-form cross-check (nominal stresses, lower bounds on the peak)\n")
    print(plates_markdown())
    run = verify()
    print()
    print(run[1].table())
    print(plates[1].table())
    for p in write_reports(args.out, pdf=not args.no_pdf, run=run, plates_run=plates):
        print(f"wrote {p}")
    return 0 if run[1].passed else 1


if __name__ == "__main__":
    raise SystemExit(main())
