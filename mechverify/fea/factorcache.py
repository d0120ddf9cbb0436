"""One factorised stiffness matrix per model geometry, reused while only the loads change (issue 19).

A study that varies loads only (a Monte Carlo over a plate's load, a sweep of a frame's payload) solves
``K u = f`` again and again with the same ``K``: meshing, assembling and factorising are the same work every
time. :data:`CACHE` keeps the last few systems of this process (a study worker), keyed on the inputs that
determine the mesh, the stiffness and the supports (their pickled bytes: equal bytes, equal inputs); a solver
stores what it built under that key and re-solves with each new right-hand side. The counters say how many
systems were built (factorised) and how many solves reused one, so tests and benchmarks can count them.

Users: :func:`mechverify.fea.plate.solve_plate` (key: the plate, its supports and the mesh sizes; parts: mesh,
stiffness, checked supports, and the factorisation of :func:`mechverify.fea.factor.factorize`, CHOLMOD when
installed) and :meth:`mechverify.fea.frame.Frame.analyse` (key: the mesh's node positions, elements, local element
stiffnesses, releases and springs, and the restraints; parts: the assembled stiffness after the support, release
and mechanism checks - a dense eigenvalue check below 3000 unknowns - and its SuperLU factorisation).

and :class:`mechverify.design.adapters.solid_fea.SolidStudy` (:func:`parts_of`, key: the solid's design-file
table - geometry, mesh sizes, material, supports, analysis settings - and the size and modification time of its
STEP/STL/mesh files; parts: the mesh, the factorised stiffness (:class:`mechverify.fea.study.SharedSolve`) and the
natural frequencies, which no load changes; one solid kept per process, the last one).

Results are bit-identical to a solve without the cache: the same matrices and the same factorisation solve
the same right-hand side.
"""

from __future__ import annotations

import pickle
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any


class FactorCache:
    """A small least-recently-used store of built systems (mesh, stiffness, factorisation ...)."""

    def __init__(self, size: int = 8):
        self.size = size
        self._items: OrderedDict[Hashable, dict[str, Any]] = OrderedDict()
        self._lock = threading.Lock()
        self._last: dict[str, Hashable] = {}  # kind -> the key of its one kept entry (latest)
        self.builds = 0  # systems built (meshed, assembled, factorised)
        self.hits = 0  # solves that reused a system

    def entry(self, key: Hashable | None) -> tuple[dict[str, Any], bool]:
        """The stored parts of ``key`` (a dict the solver fills on first use) and whether they were there.
        ``key=None`` (inputs that cannot be compared) gives a fresh dict that is not stored."""
        if key is None:
            with self._lock:
                self.builds += 1
            return {}, False
        with self._lock:
            item = self._items.get(key)
            if item is not None:
                self._items.move_to_end(key)
                self.hits += 1
                return item, True
            self.builds += 1
            item = {}
            self._items[key] = item
            while len(self._items) > self.size:
                self._items.popitem(last=False)
            return item, False

    def part(self, item: dict[str, Any], name: str, build: Callable[[], Any]) -> Any:
        """``item[name]``, built by ``build()`` on first use (an error is raised again next time, never stored)."""
        if name not in item:
            item[name] = build()
        return item[name]

    def forget(self, key: Hashable | None) -> None:
        """Drop ``key`` (a build that failed half-way must not leave parts behind)."""
        if key is not None:
            with self._lock:
                self._items.pop(key, None)

    def latest(self, kind: str, key: Hashable) -> tuple[dict[str, Any], bool]:
        """:meth:`entry` of ``key``, keeping only the last key of each ``kind`` (the previous one is dropped)."""
        with self._lock:
            old = self._last.get(kind)
            self._last[kind] = key
        if old is not None and old != key:
            self.forget(old)
        return self.entry(key)

    def clear(self) -> None:
        with self._lock:
            self._items.clear()
            self._last.clear()
            self.builds = self.hits = 0


#: The cache of this process (study workers each have their own).
CACHE = FactorCache()


def key_of(*parts: Any) -> bytes | None:
    """A key for ``parts``: their pickled bytes (equal bytes mean equal inputs), or None when they cannot be
    pickled (no caching then)."""
    try:
        return pickle.dumps(parts, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # an unpicklable input: solve without the cache
        return None


def parts_of(kind: str, inputs: Any, files: tuple[str, ...] = ()) -> dict[str, Any]:
    """The parts this process built for ``inputs`` (any picklable description of what the parts depend on) and
    the files they were read from (their size and modification time join the key, so an edited STEP file is read
    again). Only the last ``kind`` entry is kept: a process verifying other solids one after the other does not
    hold each one's factorisation. Unpicklable inputs or a missing file: a fresh dict, not stored."""
    import os

    try:
        stats = tuple((f, st.st_size, st.st_mtime_ns) for f in files for st in (os.stat(f),))
    except OSError:
        return {}
    key = key_of(kind, inputs, stats)
    return {} if key is None else CACHE.latest(kind, key)[0]
