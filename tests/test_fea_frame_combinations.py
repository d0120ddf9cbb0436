"""Frames: support settlements, load combinations on one factorisation, envelopes, sections from
tabulated properties, scale of the node lookup.

Closed forms (hand calculations, slope-deflection): a fixed-fixed beam whose end B settles by Δ has
end moments 6EIΔ/l² and shears 12EIΔ/l³; a propped cantilever whose prop settles has M = 3EIΔ/l²
(McGuire, Gallagher & Ziemian, Matrix Structural Analysis 2nd ed., Sec. 2.8 for prescribed
displacements). Uniform load on the fixed-fixed beam: wl²/12 (AISC Table 3-23 case 15).
"""

import time

import numpy as np
import pytest

from mechverify.components import sections
from mechverify.errors import InputError, UnknownNameError
from mechverify.fea.frame import (
    DistributedLoad,
    Frame,
    FramePointLoad,
    FrameSupport,
    LoadCombination,
    Member,
    SupportDisplacement,
    section_from_properties,
)
from mechverify.materials.database import get

STEEL = get("Structural Steel")
E = 200e9
SEC = sections.rectangle("20 mm", "40 mm")
I = 0.020 * 0.040**3 / 12
L, W, D = 2.0, 1500.0, 0.004
NODES = {"A": ["0 m", "0 m", "0 m"], "B": [f"{L} m", "0 m", "0 m"]}


def fixed_fixed(**kw):
    return Frame(NODES, [Member("A", "B", SEC, STEEL, "beam", **kw)], [FrameSupport("A"), FrameSupport("B")], theory="euler")


def test_settlement_of_a_fixed_fixed_beam():
    res = fixed_fixed().solve([SupportDisplacement("B", {"z": f"-{D * 1e3} mm"})])
    assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(6 * E * I * D / L**2, rel=1e-12)
    assert abs(res.reactions["B"][0].m_as("N")[2]) == pytest.approx(12 * E * I * D / L**3, rel=1e-12)
    assert res.displacement("B").m_as("m")[2] == pytest.approx(-D, rel=1e-12)


def test_settlement_of_a_propped_cantilever_prop_and_errors():
    fr = Frame(NODES, [Member("A", "B", SEC, STEEL, "beam")], [FrameSupport("A"), FrameSupport("B", "roller")], theory="euler")
    res = fr.solve([SupportDisplacement("B", {"z": f"-{D} m"})])
    assert abs(res.reactions["A"][1].m_as("N*m")[1]) == pytest.approx(3 * E * I * D / L**2, rel=1e-12)
    with pytest.raises(InputError, match="rotation about y is not held"):
        fr.solve([SupportDisplacement("B", {"ry": "0.01 rad"})])


def test_combinations_superpose_on_one_factorisation_and_envelope():
    """ULS = 1.35 dead + 1.5 settle: M_A = 1.35 wl²/12 + 1.5 * 6EIΔ/l² (superposition of the two closed forms);
    the envelope over two combinations names the governing one and is exact along the member."""
    fr = fixed_fixed()
    cases = {"dead": [DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{W} N/m"])],
             "settle": [SupportDisplacement("B", {"z": f"-{D} m"})]}
    combos = [LoadCombination("ULS", {"dead": 1.35, "settle": 1.5}), LoadCombination("SLS", {"dead": 1.0})]
    an = fr.analyse(cases, combos)
    mA = 1.35 * W * L**2 / 12 + 1.5 * 6 * E * I * D / L**2
    assert an["ULS"].reactions["A"][1].m_as("N*m")[1] == pytest.approx(-mA, rel=1e-12)  # both hog at A
    direct = fr.solve([DistributedLoad("beam", ["0 N/m", "0 N/m", f"-{1.35 * W} N/m"]),
                       SupportDisplacement("B", {"z": f"-{1.5 * D} m"})])
    assert an["ULS"].ranges("beam")["My"].max.m_as("N*m") == pytest.approx(
        direct.ranges("beam")["My"].max.m_as("N*m"), rel=1e-12)
    env = an.envelope()
    assert env.cases == ("ULS", "SLS")
    my = env.members["beam"]["My"]
    assert my.case_max == "ULS" and my.max.m_as("N*m") == pytest.approx(mA, rel=1e-12)
    assert env.reactions["A.Fz"].case_max == "ULS"
    assert env.nodes["B.uz"].min.m_as("m") == pytest.approx(-1.5 * D, rel=1e-12)
    with pytest.raises(UnknownNameError, match="live"):
        fr.analyse(cases, [LoadCombination("bad", {"live": 1.0})])


def test_section_from_tabulated_properties():
    """A section built from A, Iy, Iz, J and fibre distances gives the same answers as the closed-form
    rectangle with those properties (Euler: shear areas not needed); stresses use c_y, c_z."""
    s = SEC.si()
    tab = section_from_properties(f"{s['area']} m**2", f"{s['Iy']} m**4", f"{s['Iz']} m**4", f"{s['J']} m**4",
                                  c_y="10 mm", c_z="20 mm")
    load = [FramePointLoad("B", force=["0 N", "0 N", "-100 N"])]
    a = Frame(NODES, [Member("A", "B", SEC, STEEL, "beam")], [FrameSupport("A")], theory="euler").solve(load)
    b = Frame(NODES, [Member("A", "B", tab, STEEL, "beam")], [FrameSupport("A")], theory="euler").solve(load)
    assert b.displacement("B").m_as("mm") == pytest.approx(a.displacement("B").m_as("mm"), rel=1e-12)
    sigma = 100 * L * 0.020 / I
    assert np.max(b.diagram("beam").normal_stress.m_as("Pa")) == pytest.approx(sigma, rel=1e-12)
    # Timoshenko without shear areas: shear deformation neglected (stated), the same Euler answer
    c = Frame(NODES, [Member("A", "B", tab, STEEL, "beam")], [FrameSupport("A")]).solve(load)
    assert c.displacement("B").m_as("mm") == pytest.approx(a.displacement("B").m_as("mm"), rel=1e-12)
    bare = section_from_properties("800 mm**2", "1e5 mm**4", "2e4 mm**4", "5e4 mm**4")
    r = Frame(NODES, [Member("A", "B", bare, STEEL, "beam")], [FrameSupport("A")], theory="euler").solve(load)
    assert r.max_displacement.value.m_as("mm") > 0
    with pytest.raises(InputError, match="no extreme-fibre distances"):
        _ = r.max_von_mises


def test_node_lookup_scales_linearly():
    """A grid of 20 x 20 columns and beams (1,240 members) builds and solves in seconds (hashing, not the
    former quadratic search)."""
    n = 20
    nodes, members = {}, []
    for i in range(n + 1):
        for j in range(2):
            nodes[f"N{i}_{j}"] = [f"{i} m", "0 m", f"{j * 3} m"]
    for i in range(n + 1):
        members.append(Member(f"N{i}_0", f"N{i}_1", SEC, STEEL, f"C{i}"))
    for i in range(n):
        members.append(Member(f"N{i}_1", f"N{i + 1}_1", SEC, STEEL, f"B{i}"))
    t0 = time.perf_counter()
    fr = Frame(nodes, members, [FrameSupport(f"N{i}_0") for i in range(n + 1)])
    res = fr.solve([FramePointLoad(f"N{i}_1", force=["0 N", "0 N", "-10 N"]) for i in range(n + 1)])
    assert time.perf_counter() - t0 < 5.0
    assert sum(r[0].m_as("N")[2] for r in res.reactions.values()) == pytest.approx(10 * (n + 1), rel=1e-12)


def test_loads_outside_their_member_are_named_errors():
    fr = fixed_fixed()
    with pytest.raises(InputError, match="start 2000 mm is not before the member's end"):
        fr.solve([DistributedLoad("beam", ["0 N/m", "0 N/m", "-1 N/m"], start="2 m")])
    with pytest.raises(InputError, match="3000 mm lies beyond the member's end"):
        fr.solve([DistributedLoad("beam", ["0 N/m", "0 N/m", "-1 N/m"], end="3 m")])
