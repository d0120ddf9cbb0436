"""What a design file may contain: typed fields, and the registry of component types.

A :class:`ComponentType` declares its parameters (:class:`Field`), the loads it reads from each
load case, how to build the component, and its checks. The loader validates a design file
against these declarations (every error with its key path), the JSON Schema is generated from
them, and ``Design.verify()`` runs the checks. Adapters for the built-in component types live in
:mod:`mechverify.design.adapters`.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from mechverify.checks.registry import DEFAULT_SAFETY_FACTORS  # noqa: F401  (the design's safety-factor classes)
from mechverify.frozen import set_fields
from mechverify.units import DIMENSIONS

#: Field kinds besides the dimension names of :data:`mechverify.units.DIMENSIONS`.
PLAIN_KINDS = ("str", "int", "float", "bool", "material", "choice", "list", "table", "ref")


@dataclass(frozen=True)
class Field:
    """One key of a design-file table.

    ``kind`` is a dimension name (``"length"``: the value is a string with units such as
    ``"350 mm"``) or one of :data:`PLAIN_KINDS`. ``ref`` names another section of the design
    (e.g. ``"profiles"``) whose entry the value must name. ``item`` is the kind of a list's items.
    ``file``: the value is a file name relative to the design file (a design written to another folder,
    ``study --reproduce --out``, gets it rebased: :func:`mechverify.studies.study.file_keys`).
    """

    name: str
    kind: str
    doc: str = ""
    required: bool = False
    default: Any = None
    choices: tuple[str, ...] = ()
    item: str = ""
    ref: str = ""
    file: bool = False

    def __post_init__(self) -> None:
        for k in (self.kind, *([self.item] if self.item else [])):
            if k not in DIMENSIONS and k not in PLAIN_KINDS:
                raise ValueError(f"Field {self.name}: unknown kind {k!r}")


@dataclass(frozen=True)
class CheckSpec:
    """A check a component type offers.

    ``run(component, loads, context) -> CheckResult | list[CheckResult]``; ``loads`` is the mapping of
    this component's load fields in one load case (``None`` when the check needs no loads, i.e.
    ``needs`` is empty); ``context`` gives requirements and the check's required safety factor.
    ``needs`` lists load names every case must give for the check to run there; ``"a|b"`` accepts
    either. ``sf_kind`` names the project-wide safety-factor class it uses by default (``static``,
    ``buckling``, ``fatigue``, ...). ``reads`` names the load keys a check without ``needs`` reads itself from
    every load case that gives them (plate_fea's buckling: ``in_plane``), for ``mechverify explain``.
    """

    name: str
    run: Callable[..., Any]
    title: str = ""
    needs: tuple[str, ...] = ()
    sf_kind: str = "static"
    default: bool = True
    explain: str = ""
    #: former design-file keys of this check under its component type (accepted with a deprecation note)
    aliases: tuple[str, ...] = ()
    #: the registry's :class:`~mechverify.checks.registry.CheckDef` (set by :meth:`of`)
    definition: Any = field(default=None, compare=False, repr=False)
    reads: tuple[str, ...] = ()

    @classmethod
    def of(cls, fn: Callable[..., Any], run: Callable[..., Any], needs: tuple[str, ...] = (),
           default: bool = True, aliases: tuple[str, ...] = (), reads: tuple[str, ...] = ()) -> CheckSpec:
        """The spec of the registered check function ``fn`` (see :mod:`mechverify.checks.registry`).

        Name, title, safety-factor class and explanation come from the registry, never restated;
        ``run(component, loads, context)`` adapts the design file's component and loads to ``fn``.
        The component type adds the registry's ``"<type>.<key>"`` aliases to :attr:`aliases`; give
        ``aliases`` for a former key that several checks share (``lug`` for the four BTH-1 lug checks).

        Raises:
            ValueError: ``fn`` is not decorated with :func:`mechverify.checks.registry.check`.
        """
        d = getattr(fn, "check_def", None)
        if d is None:
            raise ValueError(f"{getattr(fn, '__qualname__', fn)!r} is not a registered check "
                             "(decorate it with @check from mechverify.checks.registry)")
        return cls(name=d.name, run=run, title=d.title, needs=tuple(needs), sf_kind=d.sf_kind,
                   default=default, explain=d.explain, aliases=tuple(aliases), definition=d, reads=tuple(reads))


@dataclass(frozen=True)
class Output:
    """A value a component type offers to other components of the design (a connection point).

    ``fn(component, loads) -> Quantity``: ``component`` is the built providing component, ``loads``
    its resolved loads in the current load case (``None`` when the value is asked outside a load
    case, e.g. by another component's field). ``kind`` is a dimension name of
    :data:`mechverify.units.DIMENSIONS`; the result is checked against it. A design file refers to
    it as ``"<component>.<name>"`` in any load value, component field or parameter expression; the
    loader resolves the references per load case in dependency order (cycles are errors).
    ``needs`` lists the providing component's loads the value reads (``"a|b"`` accepts either): an
    output with ``needs`` only exists in load cases that give them.
    """

    name: str
    kind: str
    doc: str = ""
    fn: Callable[[Any, Mapping[str, Any] | None], Any] | None = None
    needs: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.kind not in DIMENSIONS:
            raise ValueError(f"Output {self.name}: kind must be a dimension name, got {self.kind!r}")
        if self.fn is None:
            raise ValueError(f"Output {self.name}: fn(component, loads) is required")


@dataclass(frozen=True)
class ComponentType:
    """A kind of component a design file can declare with ``type = "<name>"``."""

    name: str
    doc: str
    fields: tuple[Field, ...]
    build: Callable[[Mapping[str, Any], Any], Any]
    loads: tuple[Field, ...] = ()
    checks: tuple[CheckSpec, ...] = ()
    section: str = "components"
    #: ``figures(component, results) -> [(caption, matplotlib Figure), ...]`` for the report.
    figures: Callable[[Any, Any], list[tuple[str, Any]]] | None = None
    #: values other components may reference as ``"<component>.<output>"`` (see :class:`Output`).
    outputs: tuple[Output, ...] = ()

    def __post_init__(self) -> None:
        from mechverify.checks.registry import CHECKS

        specs = []
        for c in self.checks:
            d = c.definition or CHECKS.get(c.name)
            local = d.local_aliases(self.name) if d is not None else ()
            specs.append(replace(c, aliases=tuple(dict.fromkeys((*c.aliases, *local)))) if local else c)
        set_fields(self, checks=tuple(specs))

    def checks_named(self, key: str) -> list[CheckSpec]:
        """The checks a design file's ``checks.<key>`` sets: the one named ``key``, or those with ``key``
        as a former key (alias)."""
        return [c for c in self.checks if key == c.name or key in c.aliases]

    def check(self, key: str) -> CheckSpec | None:
        """The check named ``key`` in a design file: its name, or a former key (alias) of it."""
        return next(iter(self.checks_named(key)), None)

    def field(self, name: str) -> Field:
        return {f.name: f for f in self.fields}[name]

    def output(self, name: str) -> Output | None:
        return next((o for o in self.outputs if o.name == name), None)


class Registry:
    """The component types a design file may name, by name.

    The built-in types are registered by the adapter modules of :mod:`mechverify.design.adapters`,
    imported on demand: :meth:`get` and :meth:`section` import only the adapter of a type asked for
    (through the adapters' cached index), :attr:`types` and :meth:`in_section` import them all.
    """

    def __init__(self) -> None:
        self._types: dict[str, ComponentType] = {}
        self._module: dict[str, str] = {}  # type name -> the module that registered it
        self._all_loaded = False

    def register(self, ct: ComponentType) -> ComponentType:
        if ct.name in self._types:
            raise ValueError(f"component type {ct.name!r} registered twice")
        self._types[ct.name] = ct
        self._module[ct.name] = sys._getframe(1).f_globals.get("__name__", "")
        return ct

    @property
    def types(self) -> dict[str, ComponentType]:
        """Every registered type (imports every built-in adapter first), in a fixed order: the adapter modules'
        name order, then the order each module registers its types, then types registered elsewhere (so the
        JSON Schema and listings do not depend on which adapters a design had imported before)."""
        if not self._all_loaded:
            from mechverify.design import adapters

            adapters.load_all()
            rank = {m: i for i, m in enumerate(adapters.modules())}
            seq = {name: i for i, name in enumerate(self._types)}
            order = sorted(self._types, key=lambda n: (rank.get(self._module.get(n, ""), len(rank)), seq[n]))
            reordered = {n: self._types[n] for n in order}
            self._types.clear()
            self._types.update(reordered)  # the same dict object, re-ordered
            self._all_loaded = True
        return self._types

    def get(self, name: str) -> ComponentType | None:
        """The type called ``name``, importing only its adapter; None when no type has that name."""
        ct = self._types.get(name)
        if ct is not None:
            return ct
        from mechverify.design import adapters

        where = adapters.index().get(name)
        if where is not None:
            importlib.import_module(where[0])
            ct = self._types.get(name)
            if ct is None:  # a stale index: the module no longer registers it
                adapters.forget_index()
                return self.types.get(name)
            return ct
        return None

    def names(self, section: str) -> list[str]:
        """The names of the types of ``section`` (without importing their adapters)."""
        from mechverify.design import adapters

        names = {k for k, (_, sec) in adapters.index().items() if sec == section}
        return sorted(names | {k for k, v in self._types.items() if v.section == section})

    def section(self, section: str) -> Mapping[str, ComponentType]:
        """The types of ``section`` as a mapping that imports an adapter when its type is looked up."""
        return _Section(self, section)

    def in_section(self, section: str) -> dict[str, ComponentType]:
        return {k: v for k, v in self.types.items() if v.section == section}


class _Section(Mapping[str, ComponentType]):
    def __init__(self, registry: Registry, section: str) -> None:
        self._registry, self._section = registry, section

    def __getitem__(self, name: str) -> ComponentType:
        ct = self._registry.get(name) if isinstance(name, str) else None
        if ct is None or ct.section != self._section:
            raise KeyError(name)
        return ct

    def __contains__(self, name: object) -> bool:
        try:
            self[name]  # type: ignore[index]
        except KeyError:
            return False
        return True

    def __iter__(self) -> Iterator[str]:
        return iter(self._registry.names(self._section))

    def __len__(self) -> int:
        return len(self._registry.names(self._section))


REGISTRY = Registry()
