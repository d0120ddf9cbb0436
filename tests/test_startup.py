"""A fast cold start (issue 27): what importing mechverify and its command line pull in, checked in a fresh
interpreter (sys.modules), and the lazily imported entry points of the package. Not timed: the timings are
in benchmarks/startup.py and docs/performance.md."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

HEAVY = ["scipy.sparse", "scipy.linalg", "scipy.optimize", "scipy.interpolate", "scipy.integrate", "scipy.spatial",
         "matplotlib", "shapely", "trimesh", "skfem", "meshio", "sectionproperties", "weasyprint"]


def _modules_after(code: str, env: dict | None = None) -> set[str]:
    probe = f"{code}\nimport json, sys\nprint(json.dumps(sorted(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, env=env)
    return set(json.loads(out.stdout.splitlines()[-1]))


@pytest.mark.parametrize("code", ["import mechverify", "import mechverify.cli",
                                  "import mechverify.cli; mechverify.cli.build_parser()"])
def test_no_numpy_pint_or_heavy_modules_at_start(code):
    """``mechverify --help`` builds the parser: it must need neither numpy nor pint (target ratio <= 0.6)."""
    loaded = _modules_after(code)
    unwanted = {*HEAVY, "numpy", "pint", "scipy", "rich", "jinja2"}
    assert not loaded & unwanted, sorted(loaded & unwanted)


def test_units_and_components_import_no_heavy_modules():
    """The units and the components' formulas need numpy and pint only: no scipy sub-packages (pint itself imports
    the top-level ``scipy`` package when it is installed, and dask - with jinja2 - when the ``cluster`` extra is),
    no shapely, matplotlib, trimesh or the FEA."""
    loaded = _modules_after("import mechverify.units, mechverify.components, mechverify.components.sections\n"
                            "mechverify.components.sections.i_section('100 mm', '50 mm', '4 mm', '6 mm')")
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))
    assert not any(m.startswith("mechverify.fea") for m in loaded)


def test_checking_the_lift_imports_no_scipy_subpackage():
    """``mechverify check`` of the lead-screw lift (target ratio <= 2.0) loads every adapter and check module: none
    may pull in scipy's sub-packages at import (cable_spine's scipy.integrate once cost 0.3 s of a 1 s check).
    shapely is still imported (components/plates.py through the members adapter), noted in issue 27."""
    lift = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"
    loaded = _modules_after(f"import mechverify.design as d\nd.load({str(lift)!r}).verify()")
    heavy = {m for m in loaded & set(HEAVY) if m.startswith("scipy")}
    assert not heavy, sorted(heavy)


def test_lazy_entry_points_work(tmp_path):
    """Every documented entry point of the package resolves and works."""
    import mechverify

    assert str(mechverify.Q("3 mm").to("m")) == "0.003 m"
    assert mechverify.ureg is mechverify.Q("1 N")._REGISTRY
    assert isinstance(mechverify.Q("1 N"), mechverify.Quantity)
    assert mechverify.QuantityLike is not None
    assert mechverify.materials.get("PLA").name
    assert mechverify.components.make_section("rectangle", width="10 mm", height="20 mm").area.m_as("mm**2") == 200
    assert mechverify.checks.CheckResult.__name__ == "CheckResult"
    assert mechverify.SolidModel.__name__ == "SolidModel"
    assert mechverify.PlaneModel.__name__ == "PlaneModel"
    assert mechverify.Frame.__name__ == "Frame"
    assert mechverify.PlateModel.__name__ == "PlateModel"
    assert mechverify.fea.__name__ == "mechverify.fea"
    assert isinstance(mechverify.__version__, str)
    from pathlib import Path

    import mechverify.design

    assert mechverify.load is mechverify.design.load
    root = Path(__file__).resolve().parents[1]
    design = mechverify.load(root / "examples" / "lever_arm" / "design.toml")
    assert type(design).__name__ == "Design" and design.components
    with pytest.raises(AttributeError, match="no attribute 'nonexistent'"):
        _ = mechverify.nonexistent


def test_unit_strings_parsed_once():
    """Design files repeat unit strings: the string -> (magnitude, unit) parse is cached, and each call still
    returns a new quantity (callers may modify theirs)."""
    from mechverify.units import Q, _parse_cached

    _parse_cached.cache_clear()
    a, b = Q("12.5 mm"), Q("12.5 mm")
    assert a == b and a is not b
    info = _parse_cached.cache_info()
    assert info.hits >= 1 and info.misses == 1


def test_pint_registry_cache_folder(tmp_path):
    """The registry is built from pint's cached definitions under MECHVERIFY_CACHE_DIR (or the user cache dir);
    ``off`` disables the cache; an unwritable folder is skipped, never an error."""
    import os

    env = {**os.environ, "MECHVERIFY_CACHE_DIR": str(tmp_path)}
    code = "from mechverify.units import Q; assert str(Q('1 Mpsi').to('psi')) == '1000000.0 psi'"
    subprocess.run([sys.executable, "-c", code], check=True, env=env)
    assert any((tmp_path).rglob("*")), "no cache files written"
    subprocess.run([sys.executable, "-c", code], check=True, env=env)  # from the cache
    for value in ("off", "/proc/cannot-write-here"):
        subprocess.run([sys.executable, "-c", code], check=True, env={**os.environ, "MECHVERIFY_CACHE_DIR": value})



def test_catalogues_and_materials_build_only_what_is_looked_up():
    """Issue 27: a lookup builds one catalogue row / one material, yet every row of the data is valid.

    Building rows lazily moves a data error from the first lookup to the lookup of that row, so this
    test builds every row of the motor and gearhead catalogues and every built-in material.
    """
    from mechverify.components import gearheads, motors
    from mechverify.materials import database

    cat = motors._CATALOGUE
    cat.__dict__.pop("_built", None)
    motors.motor(motors.motor_names()[0])
    assert len(cat._built) == 1
    assert all(motors.motor(n).name == n for n in motors.motor_names())
    assert all(gearheads.gearhead(n).name == n for n in gearheads.gearhead_names())
    lib = database.default_library()
    assert all(isinstance(m, database.Material) for m in lib)  # builds each pending material
    assert not any(isinstance(m, database._Pending) for m in lib._own)


def test_unit_fast_path_matches_pint():
    """The cached SI factor of ``to_si`` gives pint's own conversion, bit for bit; offsets take pint's path."""
    from mechverify.units import Q, to_si

    for text, dim in [("350 N", "force"), ("12.5 mm", "length"), ("3 kgf*cm", "torque"), ("1500 rpm", "angular_velocity"),
                      ("7 lbf", "force"), ("0.3 in", "length"), ("2 g*cm**2", "inertia"), ("40 degC", "temperature")]:
        si = Q(text).to_base_units().magnitude if dim != "angular_velocity" else Q(text).to("rad/s").magnitude
        assert to_si(text, dim) == si, text


def test_checking_the_lift_imports_only_its_adapters(tmp_path):
    """Issue 27: the adapters of types the design does not name (springs, cable spine, frame, shafts,
    solid FEA) are not imported; the type index is written to the cache folder and read from it."""
    env = {**os.environ, "MECHVERIFY_CACHE_DIR": str(tmp_path)}
    code = ("import sys, mechverify.design as d; d.load(sys.argv[1]).verify(); "
            "print(' '.join(sorted(m for m in sys.modules if m.startswith('mechverify.'))))")
    lift = str(Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml")
    for _ in range(2):  # the first run makes the index, the second reads it
        out = subprocess.run([sys.executable, "-c", code, lift], env=env, capture_output=True, text=True, check=True)
    loaded = set(out.stdout.split())
    assert "mechverify.design.adapters.screws" in loaded
    for absent in ("mechverify.design.adapters.springs", "mechverify.design.adapters.cable_spine",
                   "mechverify.design.adapters.frame", "mechverify.design.adapters.solid_fea",
                   "mechverify.mechanisms.cable_spine", "mechverify.components.springs"):
        assert absent not in loaded, absent
    assert len(list((tmp_path / "adapters").glob("index-*.json"))) == 1


def test_adapter_index_names_every_registered_type():
    """The cached index and a full import agree: every built-in type, with its module and section."""
    from mechverify.design import REGISTRY, adapters

    index = adapters.index()
    full = {k: (REGISTRY._module[k], v.section) for k, v in REGISTRY.types.items()
            if REGISTRY._module[k].startswith("mechverify.design.adapters.")}
    assert index == full
    assert set(REGISTRY.names("components")) >= {"lead_screw", "ball_bearing", "drive", "compression_spring"}


def test_type_order_does_not_depend_on_what_was_loaded_first(tmp_path):
    """With adapters imported on demand, a design that loads one adapter first must not reorder the registry:
    the JSON Schema made afterwards equals the published one (it listed five_bar first after a five_bar design)."""
    design = tmp_path / "fb.toml"
    design.write_text('[design]\nname = "fb"\n[components.fb]\ntype = "five_bar"\nbase = "100 mm"\nproximal_left = "100 mm"\n'
                      'distal_left = "100 mm"\ndistal_right = "100 mm"\nproximal_right = "100 mm"\n'
                      'x_range = ["0 mm", "100 mm"]\ny_range = ["100 mm", "180 mm"]\nsamples = 5\n'
                      'payload = "1 N"\nmotor_torque = "1 N*m"\n', encoding="utf-8")
    published = Path(__file__).resolve().parents[1] / "docs" / "design.schema.json"
    code = ("import json, sys; import mechverify.design as d; d.load(sys.argv[1]); "
            "from mechverify.design.schema import design_schema; "
            "print(json.loads(json.dumps(design_schema())) == json.loads(open(sys.argv[2]).read()))")
    out = subprocess.run([sys.executable, "-c", code, str(design), str(published)], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "True"


def test_command_table_names_every_command_of_its_module():
    """``mechverify.cli.COMMANDS`` (a run of one command imports only that module) is what the modules register."""
    import argparse

    import mechverify.cli as cli

    parser = cli.build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    registered = {name: p.get_default("run").__module__.rsplit(".", 1)[1] for name, p in sub.choices.items()}
    assert registered == cli.COMMANDS
    for name, module in cli.COMMANDS.items():  # the one-command parser: that command's module only
        one = cli.build_parser(name)
        choices = next(a for a in one._actions if isinstance(a, argparse._SubParsersAction)).choices
        assert set(choices) == {n for n, m in cli.COMMANDS.items() if m == module}


def test_a_command_imports_only_its_own_module():
    lift = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"
    loaded = _modules_after(f"from mechverify.cli import main\nmain(['check', {str(lift)!r}])")
    commands = {m for m in loaded if m.startswith("mechverify.cli.") and not m.split(".")[-1].startswith("_")}
    assert commands == {"mechverify.cli.check"}
    assert "importlib.metadata" not in _modules_after("import mechverify.cli; mechverify.cli.build_parser()")


def test_the_command_exits_fast_with_its_status_output_and_exit_handlers(tmp_path):
    """``mechverify`` (cli.entry) ends with os._exit once its output is flushed: the status, every line of the
    output and the atexit handlers must survive it."""
    lift = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"
    out = tmp_path / "out.txt"
    with out.open("w") as f:
        proc = subprocess.run([sys.executable, "-m", "mechverify.cli", "check", str(lift)], stdout=f,
                              stderr=subprocess.PIPE, text=True, env={**os.environ, "COLUMNS": "200"})
    assert proc.returncode == 1, proc.stderr  # the lift fails three checks
    assert out.read_text().rstrip().splitlines()[-1].startswith("FAIL Lead-screw lift")
    marker = tmp_path / "atexit.txt"
    code = (f"import atexit, sys; atexit.register(lambda: open({str(marker)!r}, 'w').write('ran'))\n"
            "sys.argv = ['mechverify', '--version']\nfrom mechverify.cli import entry\nentry()")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stdout.startswith("mechverify ")
    assert marker.read_text() == "ran"


def test_the_command_waits_for_a_running_thread(tmp_path):
    """With another (non-daemon) thread still running, the exit is the normal one, which waits for it."""
    marker = tmp_path / "thread.txt"
    code = ("import sys, threading, time\n"
            f"def late():\n    time.sleep(0.3)\n    open({str(marker)!r}, 'w').write('done')\n"
            "threading.Thread(target=late).start()\n"
            "sys.argv = ['mechverify', '--version']\nfrom mechverify.cli import entry\nentry()")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert marker.read_text() == "done"
