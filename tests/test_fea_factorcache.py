"""One factorised plate stiffness per process while only the loads change (mechverify/fea/factorcache.py, issue 19).

Oracles: the same solves without the cache (bit-identical fields), linearity of the elastic plate (twice the
pressure, exactly twice the deflection and stresses: a closed-form property of K u = f), and Roark's printed
coefficient for one case: Roark's Formulas for Stress and Strain, 7th ed., Table 11.4 case 1a, a/b = 2,
alpha = 0.1110 (printed); y_max = alpha q b^4 / (E t^3) = 0.3964 mm for 400 x 200 x 4 mm, 10 kPa, E = 70 GPa
(hand calculation from the printed alpha).
"""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from mechverify.components import plates as pl
from mechverify.fea import factorcache
from mechverify.fea.plate import solve_plate
from mechverify.materials import default_library
from mechverify.units import Q

PLATE = {
    "design": {"name": "plate"},
    "materials": {"al": {"base": "Inventor Aluminum 6061", "E": "70 GPa", "nu": 0.3}},
    "components": {"p": {"type": "plate_fea", "width": "400 mm", "height": "200 mm", "thickness": "4 mm",
                         "material": "al", "supports": [{"edges": "all", "type": "pinned"}], "mesh_size": "20 mm",
                         "deflection_limit": "0.5 mm"}},
    "load_cases": {"q": {"p": {"pressure": "10 kPa"}}},
}


def _model(q_kpa: float, t_mm: float = 4.0) -> pl.PlateModel:
    al = default_library().get("Inventor Aluminum 6061").with_(E=Q(70, "GPa"), nu=Q(0.3))
    plate = pl.Plate.rectangle(Q(400, "mm"), Q(200, "mm"), thickness=Q(t_mm, "mm"), material=al)
    return pl.PlateModel(plate, supports=[pl.EdgeSupport("all", "pinned")], loads=[pl.PressureLoad(Q(q_kpa, "kPa"))])


def _fields(res):
    return [res.u, res.sigma, res.reaction, res.applied, *(res.extra[k] for k in sorted(res.extra))]


@pytest.fixture()
def cache():
    factorcache.CACHE.clear()
    yield factorcache.CACHE
    factorcache.CACHE.clear()


def test_load_only_changes_factorise_once_and_match_uncached_solves(cache, monkeypatch):
    loads = [5.0, 10.0, 12.5, 20.0]
    cached = [solve_plate(_model(q), Q(20, "mm")) for q in loads]
    assert (cache.builds, cache.hits) == (1, len(loads) - 1)
    monkeypatch.setattr(factorcache, "key_of", lambda *parts: None)  # every solve builds its own system
    for q, res in zip(loads, cached, strict=True):
        fresh = solve_plate(_model(q), Q(20, "mm"))
        for a, b in zip(_fields(res), _fields(fresh), strict=True):
            assert np.array_equal(a, b)
        assert res.info.residual == fresh.info.residual
    assert cache.builds == 1 + len(loads)


def test_cached_solves_are_linear_and_match_roark(cache):
    r10, r20 = solve_plate(_model(10.0), Q(10, "mm")), solve_plate(_model(20.0), Q(10, "mm"))
    assert cache.builds == 1 and cache.hits == 1
    np.testing.assert_allclose(r20.u, 2 * r10.u, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(r20.sigma, 2 * r10.sigma, rtol=1e-12, atol=1e-6)
    roark = 0.1110 * 1e4 * 0.2**4 / (70e9 * 0.004**3)  # [m], Table 11.4 case 1a
    assert float(np.max(np.abs(r10.u[:, 2]))) == pytest.approx(roark, rel=0.01)


def test_a_new_thickness_or_mesh_builds_a_new_system(cache):
    solve_plate(_model(10.0), Q(20, "mm"))
    solve_plate(_model(10.0, t_mm=5.0), Q(20, "mm"))  # stiffness changes
    solve_plate(_model(10.0), Q(25, "mm"))  # mesh changes
    solve_plate(_model(15.0), Q(20, "mm"))  # load only: reused
    assert (cache.builds, cache.hits) == (3, 1)


def test_a_study_over_the_pressure_factorises_once_per_worker(cache, monkeypatch):
    """A serial study is one worker: its base design and every sample share one factorisation; the study's
    result equals the same study with the cache off, byte for byte."""
    from mechverify.studies import Study

    vary = {"load_cases.q.p.pressure": "5 kPa:15 kPa:6"}
    # (check_inputs=False: the check for inputs that reach no check would add one probe solve, a 7th hit)
    res = Study(copy.deepcopy(PLATE), vary=vary).run("serial", check_inputs=False)
    assert cache.builds == 1 and cache.hits == 6  # base verify builds; 6 samples re-solve
    monkeypatch.setattr(factorcache, "key_of", lambda *parts: None)
    from mechverify.studies import execution

    execution._BASE.clear()  # the worker's base design is rebuilt without the cache
    off = Study(copy.deepcopy(PLATE), vary=vary).run("serial")
    assert res.to_json() == off.to_json()
    fu = [s["checks"]["p.plate_deflection_fea"]["fu"] for s in json.loads(res.to_json())["samples"]]
    assert fu == sorted(fu) and fu[-1] == pytest.approx(3 * fu[0], rel=1e-9)  # linear in the pressure


# ------------------------------------------------------------------------------------------------ frames (task 19b)

def _cantilever(theory: str = "euler"):
    from mechverify.components import sections
    from mechverify.fea.frame import Frame, FrameSupport, Member

    steel = default_library().get("Structural Steel").with_(E=Q(200, "GPa"))
    nodes = {"A": ["0 mm", "0 mm", "0 mm"], "B": ["400 mm", "0 mm", "0 mm"]}
    return Frame(nodes, [Member("A", "B", sections.rectangle("10 mm", "20 mm"), steel, "beam")],
                 [FrameSupport("A")], theory=theory)


def _frame_fields(res):
    return [res.u, res.ulocal, res.end_forces, res.q0, res.q1, *(a for k in sorted(res._reactions)
                                                                 for a in res._reactions[k])]


def test_a_frame_over_a_load_factorises_once_and_matches_uncached_solves(cache, monkeypatch):
    """A study over a frame's load magnitude: one stiffness, checks and factorisation for every solve (counters);
    the fields equal the uncached solves bit for bit. Oracle for the numbers: Euler-Bernoulli cantilever tip
    deflection P L^3 / (3 E I) (closed form; Gere & Goodno, Mechanics of Materials, Table G-1 case 4), hand
    calculation: 100 N, 400 mm, 10 x 20 mm (I = b h^3 / 12 about the 20 mm side), E = 200 GPa -> 4.8 mm."""
    from mechverify.fea.frame import FramePointLoad

    loads = [25.0, 50.0, 100.0, 75.0]
    solve = [lambda p=p: _cantilever().solve([FramePointLoad("B", force=["0 N", "0 N", f"{-p} N"])]) for p in loads]
    cached = [s() for s in solve]  # a new Frame object per sample, as a study builds one per variant
    assert (cache.builds, cache.hits) == (1, len(loads) - 1)
    monkeypatch.setattr(factorcache, "key_of", lambda *parts: None)
    for s, res in zip(solve, cached, strict=True):
        for a, b in zip(_frame_fields(res), _frame_fields(s()), strict=True):
            assert np.array_equal(a, b)
    assert cache.builds == 1 + len(loads)  # every uncached solve built its own system
    hand = 100.0 * 0.4**3 / (3 * 200e9 * 0.010 * 0.020**3 / 12)  # [m] = 4.8 mm
    assert -cached[2].displacement("B")[2].m_as("m") == pytest.approx(hand, rel=1e-9)


def test_a_frame_geometry_or_support_change_builds_a_new_system(cache):
    from mechverify.fea.frame import FramePointLoad

    down = [FramePointLoad("B", force=["0 N", "0 N", "-10 N"])]
    _cantilever().solve(down)
    _cantilever("timoshenko").solve(down)  # element stiffness changes
    _cantilever().solve([FramePointLoad(["200 mm", "0 mm", "0 mm"], force=["0 N", "0 N", "-10 N"])])  # mesh splits
    _cantilever().solve([FramePointLoad("B", force=["0 N", "5 N", "-10 N"])])  # load only: reused
    assert (cache.builds, cache.hits) == (3, 1)


FRAME = {
    "design": {"name": "frame study"},
    "components": {"f": {"type": "frame", "theory": "euler", "section": "rectangle", "width": "10 mm",
                         "height": "20 mm", "material": "Structural Steel",
                         "nodes": {"A": ["0 mm", "0 mm", "0 mm"], "B": ["400 mm", "0 mm", "0 mm"]},
                         "members": [{"name": "beam", "start": "A", "end": "B"}],
                         "supports": [{"at": "A", "type": "fixed"}], "deflection_limit": "20 mm"}},
    "load_cases": {"tip": {"f": {"point_loads": [{"at": "B", "force": ["0 N", "0 N", "-100 N"]}]}}},
}


def test_a_frame_study_over_a_load_factorises_once(cache, monkeypatch):
    """The design-file path: a serial study of a frame component over its tip load builds one system (the base
    design's) and re-solves it for every sample; its JSON equals the same study with the cache off."""
    from mechverify.studies import Study, execution

    vary = {"load_cases.tip.f.point_loads[0].force[2]": "-150 N:-50 N:5"}
    execution._BASE.clear()
    res = Study(copy.deepcopy(FRAME), vary=vary).run("serial")
    assert not any(s.get("error") for s in json.loads(res.to_json())["samples"])
    assert cache.builds == 1 and cache.hits >= 5
    monkeypatch.setattr(factorcache, "key_of", lambda *parts: None)
    execution._BASE.clear()
    off = Study(copy.deepcopy(FRAME), vary=vary).run("serial")
    assert res.to_json() == off.to_json()


# ------------------------------------------------------------------------------------ solid_fea (the lead, issue 19)

SOLID = {
    "design": {"name": "solid cantilever"},
    "parameters": {"P": "100 N"},
    "components": {"bar": {"type": "solid_fea", "box": "200, 10, 10", "mesh_size": "5 mm",
                           "material": "Structural Steel", "supports": [{"named": "xmin"}],
                           "deflection_limit": "2 mm", "min_frequency": "150 Hz", "modes": 2}},
    "load_cases": {"tip": {"bar": {"forces": [{"named": "xmax", "force": "0, 0, -P"}]}}},
}


def test_a_solid_study_over_a_load_meshes_and_factorises_once(cache, monkeypatch):
    """A study of a solid_fea design over its tip load: the base design and every sample share one mesh, one
    factorised stiffness and one modal solution (fea.factorcache.parts_of; fix19's audit counted 4 factorisations
    per sample before); the study's JSON equals the same study with the cache off, byte for byte. Oracle for the
    numbers: the cantilever is linear in P (tip deflection u(300 N) = 3 u(100 N) to round-off) and the natural
    frequency does not depend on the load."""
    from mechverify.fea import study as fea_study
    from mechverify.studies import Study, execution

    made = []
    real_of = fea_study.SharedSolve.of
    monkeypatch.setattr(fea_study.SharedSolve, "of", classmethod(lambda cls, m: made.append(1) or real_of(m)))
    vary = {"parameters.P": "100 N:300 N:3"}
    res = Study(copy.deepcopy(SOLID), vary=vary).run("serial", check_inputs=False)
    assert len(made) == 1
    samples = json.loads(res.to_json())["samples"]
    defl = [s["checks"]["bar.solid_deflection"]["fu"] for s in samples]
    assert defl[2] == pytest.approx(3 * defl[0], rel=1e-9)
    freq = {s["checks"]["bar.natural_frequency"]["fu"] for s in samples}
    assert len(freq) == 1
    monkeypatch.setattr(factorcache, "key_of", lambda *parts: None)  # every design builds its own
    execution._BASE.clear()
    off = Study(copy.deepcopy(SOLID), vary=vary).run("serial", check_inputs=False)
    assert res.to_json() == off.to_json()
    assert len(made) == 1 + 4  # the base and three samples, each its own factorisation


def test_an_edited_step_or_mesh_file_is_read_again(cache, tmp_path):
    """The key holds the files' size and modification time: a process that verifies a design, has its mesh file
    rewritten and verifies again reads the new file (never a stale cached mesh)."""
    f = tmp_path / "m.msh"
    f.write_text("a")
    a = factorcache.parts_of("solid_fea", {"mesh": str(f)}, (str(f),))
    a["mesh"] = "old"
    assert factorcache.parts_of("solid_fea", {"mesh": str(f)}, (str(f),)) is a
    f.write_text("bb")
    assert "mesh" not in factorcache.parts_of("solid_fea", {"mesh": str(f)}, (str(f),))
    assert factorcache.parts_of("solid_fea", {"mesh": str(tmp_path / "gone.msh")}, (str(tmp_path / "gone.msh"),)) == {}
