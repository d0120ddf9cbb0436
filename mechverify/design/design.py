"""A loaded design: its components and load cases, and ``verify()`` that runs every check."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mechverify.checks import CheckResult, ResultSet
from mechverify.checks.registry import deprecation_note
from mechverify.design.loader import DesignData, DesignFileError, Entry, load_file
from mechverify.design.spec import CheckSpec
from mechverify.errors import MechverifyError, ValidityError
from mechverify.units import Q


@dataclass(frozen=True)
class CheckContext:
    """What a check adapter gets besides its component and loads."""

    component: str
    load_case: str
    required_sf: float
    requirements: dict[str, Any]
    design: Design


class Design:
    """A validated design file. ``verify()`` returns a :class:`~mechverify.checks.ResultSet`."""

    def __init__(self, data: DesignData):
        self.data = data
        self._check_plan()

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
        for spec in entry.type.checks:
            setting = entry.checks.get(spec.name, {})
            if setting.get("enabled", spec.default):
                yield spec, float(setting.get("required_sf", self.data.safety_factors[spec.sf_kind]))

    def _cases_for(self, entry: Entry, spec: CheckSpec) -> list[tuple[str, dict[str, Any]]]:
        out = []
        for case, comps in self.data.load_cases.items():
            loads = comps.get(entry.name)
            if loads is not None and all(any(a in loads for a in n.split("|")) for n in spec.needs):
                out.append((case, loads))
        return out

    def _check_plan(self) -> None:
        errors = []
        for entry in self.data.components.values():
            for spec, _ in self.enabled_checks(entry):
                if spec.needs and not self._cases_for(entry, spec):
                    needs = ", ".join(n.replace("|", " or ") for n in spec.needs)
                    errors.append((f"components.{entry.name}.checks.{spec.name}",
                                   f"needs {needs} from a load case, and no [load_cases.*."
                                   f"{entry.name}] gives it (give it, or disable the check with "
                                   f"checks.{spec.name} = false)"))
        if errors:
            raise DesignFileError(errors, str(self.path or ""))

    def verify(self, progress: Any = None) -> ResultSet:
        """Run every enabled check of every component over its load cases.

        Per check the governing load case (highest factored utilisation) is kept; the others are
        named in its notes. Errors raised while evaluating are collected and raised together as a
        :class:`DesignFileError` with the check's key path.
        """
        results: list[CheckResult] = []
        errors: list[tuple[str, str]] = []
        for entry in self.data.components.values():
            for spec, sf in self.enabled_checks(entry):
                path = f"components.{entry.name}.checks.{spec.name}"
                cases = self._cases_for(entry, spec) if spec.needs else [("", None)]
                found: dict[str, list[CheckResult]] = {}
                for case, loads in cases:
                    ctx = CheckContext(entry.name, case, sf, self.data.requirements, self)
                    try:
                        out = spec.run(entry.obj, loads, ctx)
                    except ValidityError as exc:  # an engineering limit of the method: a FAIL with the reason
                        out = _beyond_validity(spec, entry.name, case, exc)
                    except MechverifyError as exc:
                        errors.append((path + (f" [{case}]" if case else ""), str(exc)))
                        continue
                    for r in out if isinstance(out, list | tuple) else [out]:
                        r = dataclasses.replace(r, component=entry.name, required_sf=sf,
                                                load_case=case or r.load_case)
                        found.setdefault(r.check, []).append(r)
                    if progress is not None:
                        progress()
                alias = entry.checks.get(spec.name, {}).get("alias")
                for rs in found.values():
                    gov = max(rs, key=lambda r: r.factored_utilisation)
                    if alias:
                        gov = dataclasses.replace(gov, notes=(*gov.notes, deprecation_note(alias, spec.name)))
                    if len(rs) > 1:
                        others = ", ".join(f"{r.load_case}: u={r.utilisation:.3g}" for r in rs if r is not gov)
                        gov = dataclasses.replace(gov, notes=(*gov.notes, f"Governing of {len(rs)} load cases "
                                                                            f"(others: {others})."))
                    results.append(gov)
        if errors:
            raise DesignFileError(errors, str(self.path or ""))
        label = f"{self.name} rev {self.revision}" if self.revision else self.name
        return ResultSet(results, label)


def _beyond_validity(spec: CheckSpec, component: str, case: str, exc: ValidityError) -> CheckResult:
    """A check whose inputs lie beyond the validity range of its method fails: the design cannot be shown
    to meet it. Utilisation infinite (capacity zero); the reason is the error's message."""
    return CheckResult(check=spec.name, component=component, demand=Q(1.0), capacity=Q(0.0),
                       title=spec.title, load_case=case,
                       notes=(f"Not verifiable: {exc}. The inputs lie beyond the validity range of the method, "
                              "so the check fails; change the design or verify it another way.",))


def load(path: str | Path, allow_outside: bool = False) -> Design:
    """Read, validate and build a design file: ``mechverify.load("design.toml").verify()``."""
    from mechverify.design import adapters  # noqa: F401  (registers the built-in component types)

    return Design(load_file(path, allow_outside))
