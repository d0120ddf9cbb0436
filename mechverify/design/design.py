"""A loaded design: its components and load cases, and ``verify()`` that runs every check."""

from __future__ import annotations

import copy
import functools
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mechverify.checks import CheckResult, ResultSet
from mechverify.checks.registry import deprecation_note
from mechverify.design.loader import DesignData, DesignFileError, Entry, as_written, key_path, load_file, parse
from mechverify.design.spec import CheckSpec
from mechverify.errors import MechverifyError, ValidityError, suggest
from mechverify.units import Q


@dataclass(frozen=True)
class CheckContext:
    """What a check adapter gets besides its component and loads."""

    component: str
    load_case: str
    required_sf: float
    requirements: dict[str, Any]
    design: Design


class _Watched(CheckContext):
    """A :class:`CheckContext` that notes whether the check read ``design`` (the rest of the design file): a check
    without loads that did not reads only its component object, safety factor and the requirements, so a variant
    holding the same object may take its result (:meth:`Design.verify`)."""

    def __getattribute__(self, name: str) -> Any:
        if name == "design":
            object.__getattribute__(self, "__dict__")["read_design"] = True
        return object.__getattribute__(self, name)


class Design:
    """A validated design file. ``verify()`` returns a :class:`~mechverify.checks.ResultSet`.

    Variants without re-reading the file: :meth:`with_parameters` and :meth:`with_overrides`. A design pickles
    as its validated TOML data, base path and files, and is rebuilt on unpickling (worker processes).
    """

    def __init__(self, data: DesignData, overrides: Mapping[str, Any] | None = None, plan_from: Design | None = None):
        self.data = data
        #: key path -> value of every override applied since the file was read (see :meth:`with_overrides`)
        self.overrides: dict[str, Any] = dict(overrides or {})
        if plan_from is None or not self._take_plan(plan_from):
            self._check_plan()

    # ----------------------------------------------------------------- variants
    def with_overrides(self, overrides: Mapping[str, Any]) -> Design:
        """A new design with values replaced by key path, validated and built again (this one is unchanged).

        ``overrides`` maps key paths of the design file to values as the file would hold them (strings with
        units, numbers, tables) or quantities: ``{"components.lift.mass": "210 kg", "parameters.payload":
        "5 kg", "load_cases.raise.lift_screw.axial_force": Q(400, "N"), "components.d.transmission[0].diameter":
        "25 mm"}``. Every key on the way must exist except the last one; a bad path or value is a
        :class:`DesignFileError` with the key path.
        """
        doc = _copy_doc(self.data.raw, {})
        errors = []
        for key, value in overrides.items():
            try:
                _set_path(doc, key, _toml_value(value))
            except _PathError as exc:
                errors.append((key, str(exc)))
        if errors:
            raise DesignFileError(errors, str(self.path or ""))
        same_plan = all(_value_change(self.data.raw, k, v) for k, v in overrides.items())
        variant = _rebuild(doc, self.data.path, list(self.data.files), {**self.overrides, **overrides}, self.data,
                           changed=tuple(overrides), plan_from=self if same_plan else None)
        variant._reuse_base = self  # unchanged components take this design's results (mechverify/design/reuse.py)
        return variant

    def with_parameters(self, **values: Any) -> Design:
        """A new design with ``[parameters]`` values replaced: ``design.with_parameters(payload="5 kg")``.

        Values are strings with units, numbers, expressions or quantities; every name must be a parameter of the
        file (an unknown one is a :class:`DesignFileError` with a suggestion).
        """
        known = self.data.raw.get("parameters", {}) if isinstance(self.data.raw.get("parameters"), dict) else {}
        errors = []
        for k in values:
            if k not in known:
                hint = suggest(k, known, 1)
                more = f"; did you mean {hint[0]!r}?" if hint else f" (parameters: {', '.join(known) or 'none'})"
                errors.append((f"parameters.{k}", "no such parameter" + more))
        if errors:
            raise DesignFileError(errors, str(self.path or ""))
        return self.with_overrides({f"parameters.{k}": v for k, v in values.items()})

    @property
    def parameters(self) -> dict[str, Any]:
        """Parameter name -> resolved value (a quantity or a number)."""
        return dict(self.data.parameters)

    def __reduce__(self) -> tuple[Any, tuple[Any, ...]]:
        return _rebuild, (self.data.raw, self.data.path, list(self.data.files), self.overrides)

    # ----------------------------------------------------------------- access
    @property
    def name(self) -> str:
        return self.data.name

    @property
    def revision(self) -> str:
        return self.data.revision

    @property
    def path(self) -> Path | None:
        return self.data.path

    @property
    def files(self) -> list[Path]:
        return self.data.files

    @property
    def components(self) -> dict[str, Any]:
        """Component name -> the built component object."""
        return {k: e.obj for k, e in self.data.components.items()}

    @property
    def profiles(self) -> dict[str, Any]:
        return {k: e.obj for k, e in self.data.profiles.items()}

    def __getitem__(self, name: str) -> Any:
        return self.data.components[name].obj

    def __repr__(self) -> str:
        return (f"<Design {self.name!r} rev {self.revision or '-'}: {len(self.data.components)} components, "
                f"{len(self.data.load_cases)} load cases>")

    # ----------------------------------------------------------------- checks
    def enabled_checks(self, entry: Entry) -> Iterator[tuple[CheckSpec, float]]:
        memo = self.__dict__.setdefault("_enabled", {})  # (the plan and verify read it: found once per design)
        hit = memo.get(entry.name)
        if hit is None or hit[0] is not entry:
            hit = memo[entry.name] = (entry, list(self._enabled_checks(entry)))
        return iter(hit[1])

    def _enabled_checks(self, entry: Entry) -> Iterator[tuple[CheckSpec, float]]:
        left_out = self.left_out(entry)
        for spec in entry.type.checks:
            setting = entry.checks.get(spec.name, {})
            if setting.get("enabled", spec.default) and spec.name not in left_out:
                yield spec, float(setting.get("required_sf", self.data.safety_factors[spec.sf_kind]))

    def left_out(self, entry: Entry) -> tuple[str, ...]:
        """The checks that need loads and are on by default (the file does not name them under ``checks``) of a
        component that no load case names and that has a check without loads on: a modal-only study (a free-free
        solid, a frame's natural frequencies). They are left out of the plan, with a note on the component's results
        (:meth:`verify`), instead of one error each asking for ``checks.<name> = false``; a check the file turns on
        itself stays in the plan, and so an error without loads (issue 23)."""
        memo = self.__dict__.setdefault("_left_out", {})
        hit = memo.get(entry.name)
        if hit is not None and hit[0] is entry:
            return hit[1]
        out: tuple[str, ...] = ()
        if not any(entry.name in comps for comps in self.data.load_cases.values()):
            on = [s for s in entry.type.checks if entry.checks.get(s.name, {}).get("enabled", s.default)]
            if any(not s.needs for s in on):
                out = tuple(s.name for s in on if s.needs and s.name not in entry.checks)
        memo[entry.name] = (entry, out)
        return out

    @staticmethod
    def _needs_error(entry: Entry, spec: CheckSpec) -> tuple[str, str]:
        needs = ", ".join(n.replace("|", " or ") for n in spec.needs)
        return (f"components.{entry.name}.checks.{spec.name}",
                f"needs {needs} from a load case, and no [load_cases.*.{entry.name}] gives it (give it, or disable "
                f"the check with checks.{spec.name} = false)")

    def _cases_for(self, entry: Entry, spec: CheckSpec) -> list[tuple[str, dict[str, Any]]]:
        memo = self.__dict__.setdefault("_cases", {})  # (the plan and verify read it: found once per design)
        key = (entry.name, spec.needs)
        hit = memo.get(key)
        if hit is not None and hit[0] is entry:
            return list(hit[1])
        out = []
        alternatives = _alternatives(spec.needs)
        for case, comps in self.data.load_cases.items():
            loads = comps.get(entry.name)
            if loads is not None and all(any(a in loads for a in alt) for alt in alternatives):
                out.append((case, loads))
        memo[key] = (entry, out)
        return list(out)

    def _take_plan(self, base: Design) -> bool:
        """Take the check plan (enabled checks, each check's load cases) of ``base``, a design this one differs from in
        values only (:func:`_value_change`: no check settings, types, templates or keys changed), mapped onto this
        design's entries and loads; False (nothing taken) when the components or the safety factors differ."""
        if list(base.data.components) != list(self.data.components) or \
                base.data.safety_factors != self.data.safety_factors:
            return False
        enabled, cases = {}, {}
        for name, entry in self.data.components.items():
            hit = base.__dict__.get("_enabled", {}).get(name)
            if hit is None or hit[0].type is not entry.type:
                return False
            enabled[name] = (entry, hit[1])
        loads = self.data.load_cases
        for (name, needs), (_, found) in base.__dict__.get("_cases", {}).items():
            try:
                cases[(name, needs)] = (self.data.components[name], [(case, loads[case][name]) for case, _ in found])
            except KeyError:
                return False
        self.__dict__["_enabled"], self.__dict__["_cases"] = enabled, cases
        return True

    def _check_plan(self) -> None:
        errors = []
        for entry in self.data.components.values():
            for spec, _ in self.enabled_checks(entry):
                if spec.needs and not self._cases_for(entry, spec):
                    errors.append(self._needs_error(entry, spec))
        if errors:
            raise DesignFileError(errors, str(self.path or ""))

    def derived_notes(self, component: str, load_case: str = "") -> tuple[str, ...]:
        """Notes naming where the component's derived inputs came from (``axial_force = 350 N ← lifted_load``):
        its fields, and its loads in ``load_case`` (a drive's ``"raise (mu_max = 0.25)"`` matches ``raise``)."""
        trace = self.data.trace
        if not trace.entries:
            return ()
        cache = self.__dict__.setdefault("_derived_cache", {})
        if (component, load_case) not in cache:
            cache[(component, load_case)] = self._derived_notes(trace, component, load_case)
        return cache[(component, load_case)]

    def _derived_notes(self, trace: Any, component: str, load_case: str) -> tuple[str, ...]:
        lines = self.__dict__.setdefault("_trace_lines", {})

        def line(p: str, label: str) -> str:
            if p not in lines:
                lines[p] = trace.line(p, label)
            return lines[p]

        out = []
        prefix = f"components.{component}."
        for p in trace.entries:
            if p.startswith(prefix) and "." not in p[len(prefix):].split("[")[0]:
                out.append("derived input: " + line(p, p[len(prefix):]))
        for case in self.data.load_cases:
            if load_case == case or load_case.startswith(case + " ("):
                prefix = f"load_cases.{case}.{component}."
                for p in trace.entries:
                    if p.startswith(prefix) and p.count(".") == prefix.count("."):
                        out.append(f"derived input ({case}): " + line(p, p[len(prefix):]))
        return tuple(out)

    def verify(self, progress: Any = None) -> ResultSet:
        """Run every enabled check of every component over its load cases.

        Per check the governing load case (highest factored utilisation) is kept; the others are
        named in its notes. Errors raised while evaluating are collected and raised together as a
        :class:`DesignFileError` with the check's key path.
        """
        results: list[CheckResult] = []
        errors: list[tuple[str, str]] = []
        reusable = self._reusable()
        done: dict[str, tuple[list[CheckResult], int]] = {}  # component -> its results, progress steps
        before, loadfree = self._loadfree_before(), {}  # (component, check) -> (object, spec, sf, output)
        for entry in self.data.components.values():
            if entry.name in reusable:  # inputs as in the design this one was made from: its results
                rs_done, steps = reusable[entry.name]
                results.extend(rs_done)
                for _ in range(steps if progress is not None else 0):
                    progress()
                done[entry.name] = reusable[entry.name]
                loadfree.update((k, v) for k, v in before.items() if k[0] == entry.name)  # (for its own variants)
                continue
            start, n_err, steps = len(results), len(errors), 0
            for spec, sf in self.enabled_checks(entry):
                path = f"components.{entry.name}.checks.{spec.name}"
                cases = self._cases_for(entry, spec) if spec.needs else [("", None)]
                found: dict[str, list[CheckResult]] = {}
                for case, loads in cases:
                    ctx = (CheckContext if spec.needs else _Watched)(entry.name, case, sf, self.data.requirements, self)
                    try:
                        key = (entry.name, spec.name)
                        hit = None if spec.needs else before.get(key)
                        if hit is not None and hit[0] is entry.obj and hit[1] is spec and hit[2] == sf:
                            out = hit[3]  # a check without loads on the base design's (immutable) object
                        else:
                            out = spec.run(entry.obj, loads, ctx)
                        if not spec.needs and "read_design" not in ctx.__dict__:
                            loadfree[key] = (entry.obj, spec, sf, out)
                    except ValidityError as exc:  # an engineering limit of the method: a FAIL with the reason
                        out = _beyond_validity(spec, entry.name, case, exc)
                    except MechverifyError as exc:  # at the key it names (once), else at the check [case]
                        at = key_path(f"components.{entry.name}", str(exc),
                                      {*entry.raw, *(f.name for f in entry.type.fields)})
                        at = (at[0], as_written(*at, entry.raw, f"components.{entry.name}"))
                        if at[0] == f"components.{entry.name}" and case:  # a load's key: in its load case
                            at = key_path(f"load_cases.{case}.{entry.name}", str(exc),
                                          {f.name for f in entry.type.loads})
                        if at[0] in (f"components.{entry.name}", f"load_cases.{case}.{entry.name}"):
                            at = (path + (f" [{case}]" if case else ""), str(exc))
                        if at not in errors:
                            errors.append(at)
                        continue
                    for r in out if isinstance(out, (list, tuple)) else (out,):
                        lc = case or r.load_case
                        r = r.replace(component=entry.name, required_sf=sf, load_case=lc,  # (details stay lazy)
                                      notes=(*r.notes, *self.derived_notes(entry.name, lc)))
                        found.setdefault(r.check, []).append(r)
                    steps += 1
                    if progress is not None:
                        progress()
                alias = entry.checks.get(spec.name, {}).get("alias")
                for rs in found.values():
                    gov = rs[0] if len(rs) == 1 else max(rs, key=lambda r: r.factored_utilisation)
                    if alias:
                        gov = gov.replace(notes=(*gov.notes, deprecation_note(alias, spec.name)))
                    if len(rs) > 1:
                        others = ", ".join(f"{r.load_case}: u·SF={r.factored_utilisation:.3g}"  # as the verdict
                                           for r in rs if r is not gov)
                        gov = gov.replace(notes=(*gov.notes, f"Governing of {len(rs)} load cases "
                                                             f"(others: {others})."))
                    results.append(gov)
            left = self.left_out(entry)
            if left and len(errors) == n_err:  # a modal-only study: what was left out, on its results
                if len(results) == start:  # (no result at all: the checks that need loads are asked for after all)
                    errors.extend(self._needs_error(entry, s) for s in entry.type.checks if s.name in left)
                else:
                    note = (f"{', '.join(left)} left out: no load case loads {entry.name} (the checks that need loads "
                            f"run in the load cases that give them: add a [load_cases.<case>.{entry.name}])")
                    results[start:] = [r.replace(notes=(*r.notes, note)) for r in results[start:]]
            if len(errors) == n_err:
                done[entry.name] = (results[start:], steps)
        if errors:
            raise DesignFileError(errors, str(self.path or ""))
        self.__dict__["_results_by_component"] = done
        self.__dict__["_loadfree_results"] = loadfree
        label = f"{self.name} rev {self.revision}" if self.revision else self.name
        return ResultSet(results, label)

    def _wide(self) -> Any:
        """:func:`mechverify.design.reuse.design_wide` of this design (computed once)."""
        if "_wide_cache" not in self.__dict__:
            from mechverify.design.reuse import design_wide

            self.__dict__["_wide_cache"] = design_wide(self.data)
        return self.__dict__["_wide_cache"]

    def _fingerprints(self) -> dict[str, Any]:
        """(design-wide, component fingerprints) of this design, computed once, when it is a base of variants."""
        if "_fingerprints_cache" not in self.__dict__:
            from mechverify.design.reuse import fingerprints

            self.__dict__["_fingerprints_cache"] = (self._wide(), fingerprints(self.data))
        return self.__dict__["_fingerprints_cache"]

    def _loadfree_before(self) -> dict[tuple[str, str], tuple[Any, CheckSpec, float, Any]]:
        """(component, check) -> (object, spec, safety factor, output) of the checks without loads (``needs=()``)
        that ran in the design this variant was made from without reading the rest of the design: a component
        whose object the variant took over (design/reuse.py ``reused_object``: immutable, same build inputs) gets
        the same output, when the design-wide values (requirements) are unchanged too; empty otherwise."""
        base = self.__dict__.get("_reuse_base")
        before = getattr(base, "__dict__", {}).get("_loadfree_results")
        if not before or self._wide() != base._wide():
            return {}
        return before

    def _reusable(self) -> dict[str, tuple[list[CheckResult], int]]:
        """Component -> (results, progress steps) of the design this variant was made from, for the components
        whose inputs are unchanged (:mod:`mechverify.design.reuse`); empty when there is nothing to reuse."""
        base = self.__dict__.get("_reuse_base")
        before = getattr(base, "__dict__", {}).get("_results_by_component")
        if not before:
            return {}
        if self._wide() != base._wide():
            return {}
        from mechverify.design.reuse import reusable

        same = reusable(self.data, base._fingerprints()[1])  # (this design's own fingerprints: only when it is a base)
        return {k: v for k, v in before.items() if k in same}


def _beyond_validity(spec: CheckSpec, component: str, case: str, exc: ValidityError) -> CheckResult:
    """A check whose inputs lie beyond the validity range of its method fails: the design cannot be shown
    to meet it. Utilisation infinite (capacity zero); the reason is the error's message."""
    return CheckResult(check=spec.name, component=component, demand=Q(1.0), capacity=Q(0.0),
                       title=spec.title, load_case=case,
                       notes=(f"Not verifiable: {exc}. The inputs lie beyond the validity range of the method, "
                              "so the check fails; change the design or verify it another way.",))


@functools.lru_cache(maxsize=256)
def _alternatives(needs: tuple[str, ...]) -> tuple[tuple[str, ...], ...]:
    """A check's ``needs`` (``"axial_force|force"``: either) split once."""
    return tuple(tuple(n.split("|")) for n in needs)


class _PathError(Exception):
    pass


_KEY = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def _split_path(key: str) -> list[str | int]:
    return list(_split_path_cached(key))


@functools.lru_cache(maxsize=1024)
def _split_path_cached(key: str) -> tuple[str | int, ...]:
    """The parts of a key path (a study's samples set the same few paths: split once each)."""
    parts: list[str | int] = []
    pos = 0
    for m in _KEY.finditer(key):
        if m.start() != pos and key[pos:m.start()] != ".":
            raise _PathError("not a key path such as 'components.lift.mass' or 'components.d.transmission[0].diameter'")
        parts.append(m.group(1) if m.group(1) is not None else int(m.group(2)))
        pos = m.end()
    if not parts or pos != len(key):
        raise _PathError("not a key path such as 'components.lift.mass'")
    return tuple(parts)


def _set_path(doc: dict[str, Any], key: str, value: Any) -> None:
    parts = _split_path(key)
    node: Any = doc
    for i, part in enumerate(parts[:-1]):
        where = ".".join(str(p) for p in parts[:i + 1])
        if isinstance(part, int):
            if not isinstance(node, list) or not -len(node) <= part < len(node):
                raise _PathError(f"{where}: no item [{part}]")
            node = node[part]
        else:
            if not isinstance(node, dict):
                raise _PathError(f"{where}: not a table")
            if part not in node:
                if i == 0 and part in ("parameters", "load_cases", "requirements", "materials"):
                    node[part] = {}
                else:
                    hint = suggest(part, [k for k in node if isinstance(k, str)], 1)
                    raise _PathError(f"no key {part!r} in {'.'.join(str(p) for p in parts[:i]) or 'the design'}"
                                     + (f"; did you mean {hint[0]!r}?" if hint else ""))
            node = node[part]
    last = parts[-1]
    if isinstance(last, int):
        if not isinstance(node, list) or not -len(node) <= last < len(node):
            raise _PathError(f"no item [{last}]")
        node[last] = value
    elif not isinstance(node, dict):
        raise _PathError(f"{'.'.join(str(p) for p in parts[:-1])}: not a table")
    else:
        node[last] = value


_ATOMS = frozenset({str, int, float, bool, type(None)})


def _copy_doc(v: Any, memo: dict[int, Any]) -> Any:
    """``copy.deepcopy`` of TOML data, faster: its tables and arrays copied (a table reached twice copied once, as
    deepcopy does), strings, numbers and booleans shared (immutable), anything else through ``copy.deepcopy``."""
    t = type(v)
    if t in _ATOMS:
        return v
    hit = memo.get(id(v))
    if hit is not None:
        return hit
    if t is dict:
        out: Any = {}
        memo[id(v)] = out
        for k, x in v.items():
            out[k] = x if type(x) in _ATOMS else _copy_doc(x, memo)
        return out
    if t is list:
        out = []
        memo[id(v)] = out
        out.extend(x if type(x) in _ATOMS else _copy_doc(x, memo) for x in v)
        return out
    return copy.deepcopy(v, memo)


def _toml_value(v: Any) -> Any:
    """A value as the TOML data would hold it (quantities as exact strings)."""
    from mechverify.design.expressions import format_value
    from mechverify.units import Quantity

    if isinstance(v, Quantity):
        return format_value(v)
    if isinstance(v, Mapping):
        return {k: _toml_value(x) for k, x in v.items()}
    if isinstance(v, list | tuple):
        return [_toml_value(x) for x in v]
    return v


def _value_change(raw: Mapping[str, Any], key: str, value: Any) -> bool:
    """True when setting ``key`` to ``value`` replaces one existing value (a number, string or boolean) of a parameter,
    component, profile or load case by another such value, not a check setting, a type or a template: the design's
    check plan stays what it was (:meth:`Design._take_plan`)."""
    if isinstance(value, Mapping | list | tuple):
        return False
    try:
        parts = _split_path(key)
    except _PathError:
        return False
    if parts[0] not in ("parameters", "components", "profiles", "load_cases") or \
            any(p in ("checks", "type", "extends") for p in parts):
        return False
    node: Any = raw
    for p in parts:
        if isinstance(node, dict) and isinstance(p, str) and p in node:
            node = node[p]
        elif isinstance(node, list) and isinstance(p, int) and -len(node) <= p < len(node):
            node = node[p]
        else:
            return False
    return not isinstance(node, dict | list)


def _rebuild(doc: dict[str, Any], path: Path | None, files: list[Path], overrides: Mapping[str, Any],
             base: DesignData | None = None, changed: tuple[str, ...] | None = None,
             plan_from: Design | None = None) -> Design:
    """A design from its (merged) TOML data: the includes are already in ``doc``, so nothing is read. With ``base``
    (the design it is a variant of), its unchanged immutable components are taken over (design/reuse.py);
    ``changed``: the key paths where ``doc`` differs from ``base``'s data."""
    from mechverify.design import adapters  # noqa: F401  (registers the built-in component types)

    design = doc.get("design")
    if isinstance(design, dict) and "include" in design:
        doc = {**doc, "design": {k: v for k, v in design.items() if k != "include"}}
    data = parse(doc, path, base=base, changed=changed)
    data.files = files
    return Design(data, overrides, plan_from)


def load(path: str | Path, allow_outside: bool = False) -> Design:
    """Read, validate and build a design file: ``mechverify.load("design.toml").verify()``."""
    from mechverify.design import adapters  # noqa: F401  (registers the built-in component types)

    return Design(load_file(path, allow_outside))
