"""[parameters] in solid_fea region planes (review 4 finding 24): a solid whose length is a parameter could not keep its
load on the moving end face by `plane` ("forces[0].plane: expected a length, got L"). Supports take "x = L" (the
adapter substitutes it), every region takes the table form plane = { x = "L" } (the loader substitutes table values),
and a text plane with a name in a load case says how to write it.

Numbers: a 300 x 10 x 10 mm steel cantilever, 100 N across at its free end: P L^3 / (3 E I) + P L / (kappa G A) =
5.400 + 0.005 mm (Timoshenko & Gere, Mechanics of Materials, Table G-1 case 4 and sec. 10.8: hand)."""

from __future__ import annotations

import textwrap

import pytest

from mechverify.design import load
from mechverify.design.loader import DesignFileError

pytest.importorskip("gmsh")

DESIGN = """
    [design]
    name = "parametric length"
    [parameters]
    L = "300 mm"
    [components.beam]
    type = "solid_fea"
    outline = ["0, 0", "L, 0", "L, 10", "0, 10"]
    thickness = "10 mm"
    mesh_size = "5 mm"
    material = "Structural Steel"
    supports = [{{ plane = {support} }}]
    deflection_limit = "20 mm"
    [load_cases.tip.beam]
    forces = [{{ plane = {load}, force = "0, -100, 0" }}]
    """
HAND = 100 * 0.3**3 / (3 * 200e9 * 0.01**4 / 12) + 100 * 0.3 / (5 / 6 * 200e9 / 2.6 * 1e-4)  # m


def _run(tmp_path, support: str, load_at: str):
    p = tmp_path / "d.toml"
    p.write_text(textwrap.dedent(DESIGN.format(support=support, load=load_at)))
    return load(p).verify().get("beam", "solid_deflection").demand.m_as("m")


@pytest.mark.parametrize(("support", "load_at"), [
    ('"x = 0"', '{ x = "L" }'),        # the table form in a load case
    ('"x = L"', '{ x = "0 mm" }'),     # the text form in supports: the mirror image, the same deflection
    ('{ x = "L" }', '"x = 0"'),
])
def test_planes_take_parameters(tmp_path, support, load_at):
    assert _run(tmp_path, support, load_at) == pytest.approx(HAND, rel=0.03)


def test_a_text_plane_with_a_name_in_a_load_case_says_how(tmp_path):
    with pytest.raises(DesignFileError) as exc:
        _run(tmp_path, '"x = 0"', '"x = L"')
    (key, msg), = exc.value.errors
    assert key == "load_cases.tip.beam.forces[0].plane" and 'plane = { x = "L" }' in msg
