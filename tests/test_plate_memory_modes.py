"""plate_fea refuses meshes the memory cannot hold (review 4 finding 13) and more modes than its mesh resolves
(finding 27), before any solve, with errors at the design-file keys.

No book: the unknowns are counted on the meshes the code makes (Morley: a deflection per vertex, a slope per edge;
structured rectangle exactly (nx+1)(ny+1) + nx(ny+1) + ny(nx+1) + nx ny, hand count) and the ceilings are
:mod:`mechverify.fea.plate_memory` / :func:`mechverify.fea.plate_modal.max_modes`, whose constants are measured
(their docstrings). Before: mesh_size 0.01 mm ran 1 min 45 s into "internal error: MemoryError"; 400 modes took
112 s, 1536 over 6 minutes.
"""

from __future__ import annotations

import textwrap
import time

import pytest

from mechverify.components import plates as P
from mechverify.design import DesignFileError, load
from mechverify.errors import InputError
from mechverify.fea.plate import solve_plate
from mechverify.fea.plate_memory import estimate_unknowns, plate_bytes, require_plate_memory
from mechverify.fea.plate_modal import max_modes, plate_modes

PLATE = """
[design]
name = "plate"
[components.p]
type = "plate_fea"
width = "300 mm"
height = "300 mm"
thickness = "3 mm"
material = "Structural Steel"
supports = [{{ edges = "all", type = "pinned" }}]
{extra}
[load_cases.q.p]
pressure = "-1 kPa"
"""


def _load(tmp_path, extra):
    f = tmp_path / "d.toml"
    f.write_text(textwrap.dedent(PLATE.format(extra=extra)))
    return load(f)


def test_structured_rectangle_count_is_exact():
    plate = P.Plate.rectangle("300 mm", "300 mm", "3 mm", "Structural Steel")
    nx = ny = 76  # round(300 / 4) = 75, made even
    hand = (nx + 1) * (ny + 1) + nx * (ny + 1) + ny * (nx + 1) + nx * ny
    assert estimate_unknowns(plate, 0.004) == hand == 23409
    res = solve_plate(P.PlateModel(plate, [P.EdgeSupport()], [P.PressureLoad("-1 kPa")]), "4 mm")
    # the free unknowns: all but the held edge vertices' deflections (4 nx) and edge slopes are kept
    assert res.info.unknowns == hand - 4 * nx


@pytest.mark.parametrize("h, hh", [(15, 4), (25, None)])
def test_estimate_with_graded_rims_is_close_and_not_low(h, hh):
    """A plate with holes and a rounded cut-out (gmsh, rims graded): the estimate lies 0 to +25 % above the
    mesh's free unknowns (measured +21 % and +8 %; without the rim terms it would be 5-10x low)."""
    cut = P.rectangle_cutout((150, 100), (80, 60), 10, unit="mm")
    plate = P.Plate.rectangle("300 mm", "200 mm", "6 mm", "Structural Steel", cutouts=[cut],
                              holes=[P.Hole(c, 6.6, unit="mm") for c in [(15, 15), (285, 15), (285, 185), (15, 185)]])
    res = solve_plate(P.PlateModel(plate, [P.HoleSupport("all")], [P.PressureLoad("-1 kPa")]), f"{h} mm",
                      None if hh is None else f"{hh} mm")
    est = estimate_unknowns(plate, h / 1e3, None if hh is None else hh / 1e3)
    assert 1.0 <= est / res.info.unknowns <= 1.25


def test_refusal_names_the_estimate_and_a_size_that_fits():
    plate = P.Plate.rectangle("300 mm", "300 mm", "3 mm", "Structural Steel")
    with pytest.raises(InputError, match=r"^mesh_size: a mesh of 0\.5 mm elements would have about 1,442,401 "
                                         r"unknowns and need about 5\.05 GB.*mesh_size >= ") as e:
        require_plate_memory(plate, 0.0005, None, memory=1e9)  # 0.8 GB usable; (601² + 3 600² + ...) x 3.5 kB
    h = float(str(e.value).rsplit(">= ", 1)[1].split()[0]) / 1e3
    assert plate_bytes(estimate_unknowns(plate, h)) <= 0.8e9 < plate_bytes(estimate_unknowns(plate, 0.9 * h))
    assert require_plate_memory(plate, h, None, memory=1e9) == estimate_unknowns(plate, h)
    with pytest.raises(InputError, match="^hole_mesh_size: .*coarser hole_mesh_size"):
        holed = P.Plate.rectangle("300 mm", "300 mm", "3 mm", "Structural Steel", holes=[P.Hole((150, 150), 20,
                                                                                               unit="mm")])
        require_plate_memory(holed, 0.01, 1e-7, memory=1e9)


def test_convergence_check_and_modes_count():
    n = 100_000
    assert plate_bytes(n) == n * 3500
    assert plate_bytes(n, convergence=True) == pytest.approx(n * 3500 * (1 + 2.25 + 5.0625))
    assert plate_bytes(n, modes=10) == pytest.approx(n * 3500 * 3.25 + 8 * 21 * n * 2.25)


def test_design_file_refuses_a_huge_mesh_before_meshing(tmp_path):
    t = time.process_time()
    with pytest.raises(DesignFileError, match=r"components\.p\.mesh_size: a mesh of 0\.01 mm elements would have "
                                              r"about 3,600,120,001 unknowns"):
        _load(tmp_path, 'mesh_size = "0.01 mm"')
    assert time.process_time() - t < 5  # was 1 min 45 s into a MemoryError


def test_modes_ceiling():
    assert max_modes(1537) == 76 and max_modes(100) == 12 and max_modes(10) == 9 and max_modes(10**6) == 200
    model = P.PlateModel(P.Plate.rectangle("300 mm", "200 mm", "3 mm", "Structural Steel"), [P.EdgeSupport()])
    with pytest.raises(InputError, match=r"400 modes asked, but a plate mesh of 1537 free unknowns resolves at most "
                                         r"76 \(free unknowns / 20"):
        plate_modes(model, 400)
    assert len(plate_modes(model, 76).frequencies) == 76


def test_design_file_modes_ceiling_names_the_key(tmp_path):
    d = _load(tmp_path, 'min_frequency = "10 Hz"\nmodes = 400')
    t = time.process_time()
    with pytest.raises(DesignFileError, match=r"components\.p\.modes: 400 modes asked, but a plate mesh of 1025 free "
                                              r"unknowns resolves at most 51 .*lower mesh_size"):
        d.verify()
    assert time.process_time() - t < 20  # was 112 s
