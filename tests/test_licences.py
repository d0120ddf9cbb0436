"""The base install is free software (issue 27): the licence metadata of every installed distribution in the
dependency closure of mechverify's base requirements (extras excluded) is read with importlib.metadata; a
non-free licence (e.g. Triangle's "Other/Proprietary License", bundled by cytriangle through sectionproperties)
or one the test cannot classify fails it. Optional extras may differ (gmsh is GPL, sectionproperties brings
Triangle): they are named in the README."""

from __future__ import annotations

import re
from importlib import metadata

import pytest
from packaging.requirements import Requirement

# SPDX identifiers / classifier words of free licences (OSI-approved or FSF-free).
FREE = re.compile(r"\b(MIT|BSD|Apache|PSF|Python Software Foundation|ISC|MPL|Mozilla|LGPL|GPL|Zlib|Unlicense|"
                  r"CC0|HPND|Public Domain|OSI Approved|Historical Permission)\b", re.I)
NON_FREE = re.compile(r"Other/Proprietary|non-?commercial|may not be sold|proprietary", re.I)


def _name(n: str) -> str:
    return re.sub(r"[-_.]+", "-", n).lower()


def base_closure(root: str = "mechverify") -> dict[str, metadata.Distribution]:
    """Installed distributions reachable from ``root``'s requirements without extras (markers evaluated)."""
    seen: dict[str, metadata.Distribution] = {}
    todo = [root]
    while todo:
        name = _name(todo.pop())
        if name in seen:
            continue
        try:
            dist = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            continue  # an optional dependency not installed here
        seen[name] = dist
        for line in dist.requires or ():
            req = Requirement(line)
            if req.marker is not None and not req.marker.evaluate({"extra": ""}):
                continue  # only for an extra, or another platform/Python
            todo.append(req.name)
    seen.pop(_name(root), None)
    return seen


def licence_texts(dist: metadata.Distribution) -> list[str]:
    md = dist.metadata
    texts = [md.get("License-Expression") or "", (md.get("License") or "")[:300]]
    texts += [c for c in md.get_all("Classifier") or () if c.startswith("License ::")]
    return [t for t in texts if t.strip()]


def verdict(dist: metadata.Distribution) -> str:
    """``free``, ``non-free`` or ``unknown`` from the distribution's licence metadata."""
    texts = licence_texts(dist)
    if any(NON_FREE.search(t) for t in texts):
        return "non-free"
    if any(FREE.search(t) for t in texts):
        return "free"
    return "unknown"


def test_base_install_has_only_free_licences():
    closure = base_closure()
    assert {"numpy", "pint", "scipy"} <= set(closure), "mechverify is not installed with its dependencies"
    bad = {name: (verdict(d), licence_texts(d)) for name, d in closure.items() if verdict(d) != "free"}
    assert not bad, f"non-free or unclassified licences in the base install: {bad}"
    assert "sectionproperties" not in closure and "cytriangle" not in closure


def test_the_check_can_fail():
    """The classifier recognises Triangle's licence (cytriangle, installed here as a test dependency)."""
    try:
        dist = metadata.distribution("cytriangle")
    except metadata.PackageNotFoundError:
        pytest.skip("cytriangle is not installed (sectionproperties, the 'sections' extra, absent)")
    assert verdict(dist) == "non-free", licence_texts(dist)
