"""Builders the test modules share: design files written to a temporary folder, loaded, verified or refused,
the example designs' paths, and gmsh-made meshes of a bar (for the mesh-import tests).

Not a test module (pytest collects ``test_*.py`` only); import as ``from tests.builders import ...``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import mechverify
from mechverify.design.loader import DesignFileError

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
LIFT = EXAMPLES / "lead_screw_lift" / "design.toml"


def write(tmp_path: Path, text: str, name: str = "d.toml") -> Path:
    """``text`` written to ``tmp_path/name``; the path."""
    f = tmp_path / name
    f.write_text(text)
    return f


def load(tmp_path: Path, text: str, name: str = "d.toml") -> Any:
    """The design of ``text`` (written to ``tmp_path/name`` first)."""
    return mechverify.load(write(tmp_path, text, name))


def results(tmp_path: Path, text: str, check: str = "") -> list[Any]:
    """The verified results of ``text``; only those of ``check`` when given."""
    return [r for r in load(tmp_path, text).verify() if not check or r.check == check]


def by_check(tmp_path: Path, text: str) -> dict[str, Any]:
    """The verified results of ``text`` by check name (the last of each name)."""
    return {r.check: r for r in load(tmp_path, text).verify()}


def by_check_and_case(res: list[Any]) -> dict[tuple[str, str], Any]:
    """Results by (check, load case)."""
    return {(r.check, r.load_case): r for r in res}


def refusal(tmp_path: Path, text: str) -> str:
    """The message of the :class:`DesignFileError` that loading and verifying ``text`` raises."""
    with pytest.raises(DesignFileError) as exc:
        load(tmp_path, text).verify()
    return str(exc.value)


def gmsh_bar(tmp_path: Path, order: int = 2, fmt: str = "4.1", suffix: str = ".msh", name: str = "") -> tuple[Path, Any]:
    """A bar 100 x 10 x 10 mm meshed by gmsh's Python API (element size 4 mm), physical surfaces 'fixed' (x = 0)
    and 'loaded' (x = 100 mm) and the volume 'body'; written by gmsh itself to ``name`` (default
    ``bar_<order>_<fmt><suffix>``): ``.msh`` in format ``fmt``, or ``.inp`` (Abaqus: C3D10 with CPS6 boundary
    triangles at order 2, groups of nodes saved). Returns the path and the same model read directly
    (mechverify.fea.mesh.from_gmsh_model, linear tetrahedra)."""
    from mechverify.fea import mesh as fmesh

    L, B = 0.1, 0.01
    gmsh = fmesh.import_gmsh()
    fmesh.gmsh_session(gmsh, 0.004)
    try:
        occ = gmsh.model.occ
        vol = occ.addBox(0, 0, 0, L, B, B)
        occ.synchronize()
        faces = {round(occ.getCenterOfMass(2, t)[0], 9): t for _, t in gmsh.model.getEntities(2)}
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [faces[0.0]]), "fixed")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [faces[L]]), "loaded")
        gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [vol]), "body")
        gmsh.model.mesh.generate(3)
        direct = fmesh.from_gmsh_model(gmsh)  # (the direct path reads linear tetrahedra)
        gmsh.model.mesh.setOrder(order)
        if suffix == ".inp":
            gmsh.option.setNumber("Mesh.SaveGroupsOfNodes", 1)
        else:
            gmsh.option.setNumber("Mesh.MshFileVersion", float(fmt))
        path = tmp_path / (name or f"bar_{order}_{fmt}{suffix}")
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path, direct


def two_rods(name: str, revision: str, thin_area: str = "5 mm^2") -> str:
    """Two ``test_rod`` components (the type tests/conftest.py's ``rod_type`` fixture registers), 350 mm of
    structural steel: ``rod`` of 20 mm² and ``thin_rod`` of ``thin_area``, both under 2 kN in load case hold."""
    return f"""
[design]
name = "{name}"
revision = "{revision}"

[components.rod]
type = "test_rod"
length = "350 mm"
area = "20 mm^2"
material = "Structural Steel"

[components.thin_rod]
type = "test_rod"
length = "350 mm"
area = "{thin_area}"
material = "Structural Steel"

[load_cases.hold.rod]
force = "2 kN"

[load_cases.hold.thin_rod]
force = "2 kN"
"""


def run_module(path: Path, name: str) -> Any:
    """The Python file ``path`` (an example's run.py) executed as the module ``name`` (registered in sys.modules
    first: dataclasses look their module up while a class is created)."""
    import importlib.util
    import sys

    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None, path
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod
