"""One meaning per public class name across the package (issue 16).

``PointLoad`` used to mean a frame load, a plate load and a planar-statics force; ``Support``,
``SelfWeight`` and ``Extreme`` two things each. A reader (and ``from ... import *``) could not tell
them apart. This test imports every module of the package and fails when two modules define a
public class of the same name. Renamed classes keep their former names as deprecated aliases where
they were documented public API; those aliases must still resolve, with a ``DeprecationWarning``.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys
from collections import defaultdict

import pytest

import mechverify

# Known duplicates waiting for their owner (each with the reason); the test fails when one disappears,
# so the list cannot go stale.
PENDING: dict[str, set[str]] = {}  # duplicates being renamed (none)


def _public_classes(extra: tuple[str, ...] = ()) -> dict[str, set[str]]:
    where: dict[str, set[str]] = defaultdict(set)
    names = [info.name for info in pkgutil.walk_packages(mechverify.__path__, "mechverify.")]
    for name in [*names, *extra]:
        if name.endswith("__main__"):
            continue
        module = importlib.import_module(name)
        for obj in vars(module).values():
            if inspect.isclass(obj) and obj.__module__ == module.__name__ and not obj.__name__.startswith("_"):
                where[obj.__name__].add(module.__name__)
    return where


def test_public_class_names_are_unique():
    dups = {name: mods for name, mods in _public_classes().items() if len(mods) > 1}
    unexpected = {n: sorted(m) for n, m in dups.items() if PENDING.get(n) != m}
    assert not unexpected, f"public class names defined in more than one module: {unexpected}"
    stale = sorted(set(PENDING) - set(dups))
    assert not stale, f"resolved, remove from PENDING: {stale}"


def test_the_detector_finds_a_duplicate(monkeypatch):
    """The test is not vacuous: a second module defining ``FramePointLoad`` is reported."""
    import types

    fake = types.ModuleType("mechverify.fake_dup")
    exec("class FramePointLoad:\n    pass\n", fake.__dict__)
    monkeypatch.setitem(sys.modules, "mechverify.fake_dup", fake)
    assert _public_classes(extra=("mechverify.fake_dup",))["FramePointLoad"] == {"mechverify.fea.frame.model", "mechverify.fake_dup"}


RENAMED = [
    ("mechverify.fea.frame", "PointLoad", "FramePointLoad"),
    ("mechverify.fea.frame", "Support", "FrameSupport"),
    ("mechverify.fea.frame", "SelfWeight", "FrameSelfWeight"),
    ("mechverify.fea.frame", "Extreme", "FrameExtreme"),
    ("mechverify.fea.frame.model", "PointLoad", "FramePointLoad"),
    ("mechverify.fea.frame.results", "Extreme", "FrameExtreme"),
    ("mechverify.fea.loads", "Support", "Restraint"),
    ("mechverify.fea.results", "Extreme", "FieldExtreme"),
    ("mechverify.components.plates", "PointLoad", "PlatePointLoad"),
    ("mechverify.components.plates", "SelfWeight", "PlateSelfWeight"),
    ("mechverify.mechanisms", "PointLoad", "AppliedForce"),
    ("mechverify.mechanisms.statics", "PointLoad", "AppliedForce"),
    ("mechverify.motion.profiles", "Segment", "JerkSegment"),
    ("mechverify.mechanisms", "RPJointMotion", "JointMotion"),
    ("mechverify.mechanisms", "RRJointMotion", "JointMotion"),
    ("mechverify.mechanisms", "FiveBarJointMotion", "JointMotion"),
    ("mechverify.mechanisms.paths", "RPJointMotion", "JointMotion"),
    ("mechverify.mechanisms.paths", "RRJointMotion", "JointMotion"),
    ("mechverify.mechanisms.paths", "FiveBarJointMotion", "JointMotion"),
]


@pytest.mark.parametrize("module,old,new", RENAMED)
def test_former_names_are_deprecated_aliases(module, old, new):
    mod = importlib.import_module(module)
    with pytest.deprecated_call(match=new):
        alias = getattr(mod, old)
    assert alias is getattr(mod, new)
    assert alias.__name__ == new


def test_unknown_names_still_raise_attribute_error():
    import mechverify.fea.loads as loads

    with pytest.raises(AttributeError, match="NoSuchThing"):
        loads.NoSuchThing  # noqa: B018
