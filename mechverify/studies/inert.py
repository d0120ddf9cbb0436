"""Varied inputs that reach no check: found before a study runs, so that it does not run for nothing.

A study whose input no check reads (``--vary parameters.g=...`` where nothing in the design reads ``g``, or a
component field that no check of its type uses) evaluates every sample and prints a table of constant u·SF.
:func:`inert_inputs` finds such inputs in two ways, before any sample is sent:

1. **The design's dependency graph** (:func:`mechverify.design.parameters.dependency_graph`): a parameter that no
   derived value reads, directly or through other parameters, changes nothing (free: no evaluation).
2. **A probe**: the design with that one input moved to the value of the study farthest from the file's value
   (the other inputs as in the file), verified in this process and compared check by check with the design as
   written (whose results the study builds anyway). Equal ``u``, ``u·SF`` and verdict for every check: the input
   reaches no check. One evaluation per input; left out when the study has no more samples than twice its
   inputs (the probe would cost as much as the study).

A probe that fails (an invalid design at that value) decides nothing: the samples report their own errors.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np


class InertInputWarning(UserWarning):
    """A varied input changes no check's result (:func:`inert_inputs`)."""


def unread_parameters(design: Any) -> set[str]:
    """Names of the design's ``[parameters]`` that no derived value reads, directly or through other parameters."""
    from mechverify.design.parameters import dependency_graph

    data = getattr(design, "data", design)
    params = set((getattr(data, "parameters", None) or {}).keys())
    if not params:
        return set()
    graph = dependency_graph(data)
    read_by: dict[str, set[str]] = {}
    for target, names in graph.items():
        for n in names:
            read_by.setdefault(n, set()).add(target)
    used: set[str] = set()

    def reaches(name: str, seen: set[str]) -> bool:  # read by something that is not an unread parameter
        for target in read_by.get(name, ()):
            if not target.startswith("parameters."):
                return True
            p = target.split(".", 1)[1]
            if p not in seen and (p in used or reaches(p, seen | {p})):
                return True
        return False

    for p in params:
        if reaches(p, {p}):
            used.add(p)
    return params - used


def inert_inputs(study: Any) -> list[str]:
    """One message per varied input of ``study`` (:class:`~mechverify.studies.study.Study`) that reaches no check,
    naming the input and how it was found; empty when every input changes some check's result."""
    from mechverify.studies import execution

    out: list[str] = []
    probe: list[Any] = []
    design = None
    try:
        design = execution._base_design(study.doc, study.path)
        unread = unread_parameters(design)
    except Exception:  # (an invalid design: the samples say why)
        unread = set()
    for axis in study.axes:
        name = axis.name
        if name.startswith("parameters.") and name.split(".", 1)[1] in unread:
            out.append(f"{name}: no value of the design reads this parameter (dependency graph: no expression uses "
                       f"'{name.split('.', 1)[1]}'), so varying it changes no check; the study's results will be "
                       "constant in it")
        else:
            probe.append(axis)
    if not probe or design is None or study.n_samples <= 2 * len(study.axes):
        return out
    base = execution.evaluate(study.doc, study.path, {}, design)
    if base["status"] != "ok" or not base["checks"]:
        return out
    values = _values(study)
    for axis in probe:
        x = _farthest(values[axis.name], axis.param.base)
        if x is None:
            continue
        moved = execution.evaluate(study.doc, study.path, {axis.name: axis.param.text(x)}, design)
        if moved["status"] == "ok" and _same(moved["checks"], base["checks"]):
            out.append(f"{axis.name}: no check's result changes when it goes from {_shown(axis, axis.param.base)} (the "
                       f"file's value) to {_shown(axis, x)} (probe: the design verified at both values), so the "
                       "study's results will be constant in it; is it the input you meant to vary?")
    return out


def _values(study: Any) -> dict[str, np.ndarray]:
    """The values each input takes in the study (sweep grid values, or the Monte Carlo samples)."""
    if study.kind == "sweep":
        return {a.name: np.asarray(a.sweep_values(), float) for a in study.axes}
    xs = study.inputs()
    return {a.name: np.array([x[a.name] for x in xs], float) for a in study.axes}


def _farthest(values: np.ndarray, base: float) -> float | None:
    v = values[np.isfinite(values)]
    if v.size == 0:
        return None
    x = float(v[int(np.argmax(np.abs(v - base)))])
    return None if x == base else x


def _same(a: Mapping[str, Any], b: Mapping[str, Any]) -> bool:
    if a.keys() != b.keys():
        return False
    for k, ra in a.items():
        rb = b[k]
        if ra["verdict"] != rb["verdict"]:
            return False
        for key in ("u", "fu"):
            x, y = ra[key], rb[key]
            if (x is None) != (y is None) or (x is not None and not math.isclose(x, y, rel_tol=0.0, abs_tol=0.0)):
                return False
    return True


def _shown(axis: Any, x: float) -> str:
    unit = axis.param.unit
    return f"{x:.6g} {unit}" if unit else f"{x:.6g}"
