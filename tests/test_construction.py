"""One construction path for frozen dataclasses (issue 16, ``mechverify/frozen.py``).

Inputs are normalised at construction with ``frozen.set_fields`` (fields only, from ``__post_init__``
or ``__init__`` only); derived values are ``functools.cached_property``. These tests enforce the rule
on the source and check what it must keep working: pickling (process pools, Dask), ``==``, ``hash``,
``dataclasses.replace`` and errors raised at construction.
"""

from __future__ import annotations

import ast
import dataclasses
import pickle
from functools import cached_property
from pathlib import Path

import pytest

from mechverify.errors import InputError
from mechverify.frozen import set_fields

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "mechverify"

#: Modules allowed to write frozen instances with ``object.__setattr__`` directly (a conversion in
#: progress). The test fails when one of them no longer does, so the list only shrinks.
NOT_YET: set[str] = set()  # empty: every module is converted


def _calls(tree: ast.AST, dotted: str) -> list[ast.Call]:
    return [n for n in ast.walk(tree) if isinstance(n, ast.Call) and ast.unparse(n.func) == dotted]


def _sources() -> list[Path]:
    return sorted(p for p in PKG.rglob("*.py") if p.name != "frozen.py")


def test_frozen_instances_are_written_only_by_set_fields():
    bad, done = [], []
    for p in _sources():
        rel = str(p.relative_to(ROOT))
        n = len(_calls(ast.parse(p.read_text(encoding="utf-8")), "object.__setattr__"))
        if n and rel not in NOT_YET:
            bad.append(f"{rel}: {n} object.__setattr__ call(s); use mechverify.frozen.set_fields or cached_property")
        if not n and rel in NOT_YET:
            done.append(rel)
    assert not bad, bad
    assert not done, f"converted, remove from NOT_YET: {done}"


CONSTRUCTING = ("__post_init__", "__init__")  # and private ``_normalise*`` helpers they call


def test_set_fields_is_called_only_while_constructing():
    bad = []
    for p in _sources():
        tree = ast.parse(p.read_text(encoding="utf-8"))
        allowed = {id(c) for fn in ast.walk(tree) if isinstance(fn, ast.FunctionDef)
                   and (fn.name in CONSTRUCTING or fn.name.startswith("_normalise")) for c in ast.walk(fn)}
        bad += [f"{p.relative_to(ROOT)}:{c.lineno}" for c in _calls(tree, "set_fields") if id(c) not in allowed]
    assert not bad, f"set_fields outside __post_init__/__init__/_normalise*: {bad}"


def test_set_fields_accepts_fields_only():
    @dataclasses.dataclass(frozen=True)
    class Box:
        width: object

        def __post_init__(self) -> None:
            set_fields(self, width=float(str(self.width).removesuffix(" m")))

    assert Box("2 m").width == 2.0
    with pytest.raises(TypeError, match="cached_property"):
        set_fields(Box(1.0), area=1.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        Box(1.0).width = 3.0  # type: ignore[misc]


def _springs():
    from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring

    return [CompressionSpring(d="2 mm", D="20 mm", Na=8, L0="60 mm", name="c"),
            ExtensionSpring(d="1 mm", D="8 mm", Nb=10, Fi="2 N", name="e"),
            TorsionSpring(d="1.5 mm", OD="12 mm", Nb=5, l1="20 mm", name="t")]


def _objects():
    from mechverify.components.plates import Plate
    from mechverify.components.power_screw import LeadScrew
    from mechverify.components.transmissions import BeltDrive
    from mechverify.components.transmissions import ScrewDrive as ScrewStage
    from mechverify.mechanisms.cable_spine import CableSpine
    from mechverify.motion.drive_train import LinearLoad, RotaryLoad

    screw = LeadScrew(thread="Tr10x2", length="450 mm", material="Inventor Steel")
    return [*_springs(), screw, ScrewStage(screw, mu=0.1), BeltDrive(20, 40, efficiency=0.95),
            Plate.rectangle("100 mm", "60 mm", "3 mm", "Structural Steel"),
            LinearLoad("2 kg", incline="90 deg"), RotaryLoad("0.01 kg*m**2", gravity_torque="1 N*m"),
            CableSpine(_springs()[0])]


def _hash(obj):
    try:
        return hash(obj)
    except TypeError:  # a field is a list or dict: unhashable before and after, like any such dataclass
        return None


@pytest.mark.parametrize("obj", _objects(), ids=lambda o: type(o).__name__)
def test_pickle_equality_hash_and_replace(obj):
    """What studies rely on: a component crosses a process boundary unchanged (cached values too)."""
    for name in dir(type(obj)):  # fill the caches
        if not name.startswith("_") and isinstance(getattr(type(obj), name, None), property | cached_property):
            getattr(obj, name, None)
    back = pickle.loads(pickle.dumps(obj))
    assert back == obj and _hash(back) == _hash(obj)
    assert repr(vars(back)) == repr(vars(obj))  # cached values travel too (repr: NaN != NaN)
    fresh = dataclasses.replace(obj)
    assert fresh == obj and _hash(fresh) == _hash(obj)


def test_spring_caches_are_not_compared_and_are_public():
    """Two springs equal by their inputs are equal whether or not their caches were filled; the SI values
    and the wire class are public (``si``, ``wire_class``), shared by the three classes (one base)."""
    from mechverify.components.spring_formulas import HelicalSpring

    a, b = _springs()[0], _springs()[0]
    b.__dict__.pop("si")
    assert a == b and repr(a) == repr(b)
    assert b.si == a.si and a.si["d"] == pytest.approx(0.002)
    assert all(isinstance(s, HelicalSpring) for s in _springs())
    assert {s.wire_class for s in _springs()} == {"cold_drawn"}
    for s in _springs():  # the shared accessors, in mm
        assert s.wire_diameter.units == s.mean_diameter.units


def test_construction_errors_are_raised_at_construction():
    from mechverify.components.springs import CompressionSpring, TorsionSpring

    with pytest.raises(InputError, match="solid length"):
        CompressionSpring(d="2 mm", D="20 mm", Na=8, L0="10 mm")
    with pytest.raises(InputError, match="leg lengths"):
        TorsionSpring(d="1.5 mm", OD="12 mm", Nb=5, l1="-1 mm")


def test_plate_geometry_survives_replace():
    """A normalised plate, hole or point support states its unit ("m"), so ``dataclasses.replace`` re-reads the
    SI values as metres (it used to re-read them as bare numbers and fail)."""
    from mechverify.components.plates import Hole, Plate, PointSupport

    plate = Plate.rectangle("100 mm", "60 mm", "3 mm", "Structural Steel")
    thicker = dataclasses.replace(plate, thickness="4 mm")
    assert thicker.outline == plate.outline and thicker.thickness == pytest.approx(0.004)
    assert thicker.region.area == pytest.approx(plate.region.area)
    for obj in (Hole(("10 mm", "10 mm"), "5 mm"), PointSupport(("1 mm", "2 mm"))):
        assert dataclasses.replace(obj) == obj


def test_plane_model_survives_replace():
    """``fea.study.solve_cases`` builds each case with ``dataclasses.replace(model, loads=...)``: the normalised
    thickness is a quantity, so a plane model re-reads it (as a bare SI float it was a UnitError)."""
    from mechverify.fea import mesh2d
    from mechverify.fea.loads import Fixed
    from mechverify.fea.plane import PlaneModel
    from mechverify.fea.regions import Plane

    model = PlaneModel(mesh2d.rectangle(0.1, 0.02, 4, 2), "5 mm", "Structural Steel", supports=(Fixed(Plane(x="0 m")),))
    again = dataclasses.replace(model, loads=())
    assert again.thickness_si == model.thickness_si == pytest.approx(0.005)
    with pytest.raises(InputError, match="thickness"):
        PlaneModel(mesh2d.rectangle(0.1, 0.02, 4, 2), "0 mm", "Structural Steel")
