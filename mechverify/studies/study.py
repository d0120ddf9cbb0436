"""Sweeps and Monte Carlo studies of a design: ``Study(design, vary=..., samples=..., method=...).run()``.

*Sweep*: every axis given as ``START:STOP:N``; the samples are the full factorial grid (first axis
slowest). *Monte Carlo*: every axis a distribution; ``samples`` points from a Latin hypercube
(``method="lhs"``, default; optimised against chance input correlation up to 1000 points), a
scrambled Sobol sequence (``"sobol"``, balanced for powers of two)
or plain pseudo-random numbers (``"random"``), all from :mod:`scipy.stats.qmc`/numpy with ``seed``,
mapped through each distribution's inverse CDF. The samples are built here, in the calling process,
so a study's result is the same whatever executor runs it.
"""

from __future__ import annotations

import copy
import csv
import io
import math
import re
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from mechverify.errors import InputError
from mechverify.studies import execution
from mechverify.studies.lhs import optimised_lhs
from mechverify.studies.params import Axis, apply_overrides, parse_vary, resolver
from mechverify.studies.stats import Z95, spearman, wilson_interval

METHODS = ("lhs", "sobol", "random")
#: Latin hypercubes up to this size are improved by random coordinate swaps (centred discrepancy, scipy's
#: ``optimization="random-cd"``): plain LHS pairs its columns at random, and a chance rank correlation of
#: ~1/sqrt(n) between two inputs (0.2 at n = 100) would show up in the sensitivity ranking.
LHS_OPTIMISE_MAX = 1000


def design_source(design: Any) -> tuple[dict[str, Any], str | None]:
    doc, path, _ = design_and_source(design)
    return doc, path


def design_and_source(design: Any) -> tuple[dict[str, Any], str | None, Any]:
    """(TOML data, path, the loaded design or None) of a :class:`~mechverify.design.Design`, a path or a dict.

    The data are the design's as loaded, with its includes merged in (``design.include`` removed),
    so a task needs no file but the design's own folder for messages.
    """
    from mechverify.design.design import Design, load

    if isinstance(design, str | Path):
        design = load(design)
    if isinstance(design, Design):
        doc = copy.deepcopy(design.data.raw)  # an independent copy
        path = str(design.path) if design.path else None
    elif isinstance(design, Mapping):
        doc, path, design = copy.deepcopy(dict(design)), None, None
    else:
        raise InputError(f"study: expected a Design, a design-file path or its TOML data, got {type(design).__name__}")
    if isinstance(doc.get("design"), dict) and "include" in doc["design"]:
        del doc["design"]["include"]
    if design is None:  # TOML data given: validate and build it now (a bad design is an error before any task)
        design = execution._base_design(doc, None)
    return doc, path, design


@dataclass
class StudyResult:
    """Every sample's inputs and per-check ``u``, ``u·SF`` and verdict, in sample order.

    ``samples[i]``: ``{"index", "inputs": {path: value}, "status": "ok"|"error", "message",
    "checks": {"component.check": {"u", "required_sf", "fu", "verdict"}}, "verdict", "governing",
    "max_fu"}``; ``fu``/``max_fu`` null: unbounded (zero capacity), or for an invalid sample none. Values
    are in the unit of each parameter in the design file (``axes``).
    """

    kind: str  # "sweep" or "monte_carlo"
    method: str
    seed: int | None
    axes: list[dict[str, Any]]
    samples: list[dict[str, Any]]
    design_name: str = ""
    doc: dict[str, Any] = field(default_factory=dict, repr=False)
    path: str | None = None
    #: what the study found before it ran: varied inputs that reach no check (:mod:`mechverify.studies.inert`)
    warnings: list[str] = field(default_factory=list)

    # ------------------------------------------------------------------ access
    @property
    def names(self) -> list[str]:
        return [a["name"] for a in self.axes]

    @property
    def checks(self) -> list[str]:
        out: dict[str, None] = {}
        for s in self.samples:
            for k in s["checks"]:
                out.setdefault(k, None)
        return list(out)

    @property
    def ok(self) -> list[dict[str, Any]]:
        return [s for s in self.samples if s["status"] == "ok"]

    @property
    def errors(self) -> list[dict[str, Any]]:
        return [s for s in self.samples if s["status"] != "ok"]

    def values(self, name: str, ok_only: bool = True) -> np.ndarray:
        return np.array([s["inputs"][name] for s in (self.ok if ok_only else self.samples)], float)

    def fu(self, check: str | None = None) -> np.ndarray:
        """u·SF of ``check`` (None: the governing one) over the valid samples (nan where it did not run)."""
        def one(s: dict[str, Any]) -> float:
            v = s["max_fu"] if check is None else s["checks"].get(check, {}).get("fu", math.nan)
            return math.inf if v is None else v
        return np.array([one(s) for s in self.ok], float)

    def unit(self, name: str) -> str:
        """The unit of input ``name`` as the study reads its values ('' for a bare number)."""
        return next((a["unit"] for a in self.axes if a["name"] == name), "")

    def label(self, name: str) -> str:
        """``name [unit]`` (the unit in the console's plain form, ``m/s²``), or the name of a unitless input."""
        u = self.unit(name)
        return f"{name} [{pretty_unit(u)}]" if u else name

    def value_text(self, name: str, x: float) -> str:
        """``15.82 kg``: an input value with its unit."""
        u = self.unit(name)
        return f"{x:.6g} {pretty_unit(u)}" if u else f"{x:.6g}"

    # ------------------------------------------------------------------ statistics
    def failure_probability(self, z: float = Z95) -> dict[str, dict[str, Any]]:
        """Per check and ``"overall"`` (any check fails): failures k of n valid samples, p = k/n and its
        Wilson score interval (95 % by default). Invalid samples (errors) are left out of n."""
        ok = self.ok
        n = len(ok)
        out: dict[str, dict[str, Any]] = {}
        if n == 0:
            return out
        for c in [*self.checks, "overall"]:
            if c == "overall":
                k = sum(1 for s in ok if s["verdict"] == "fail")
            else:
                k = sum(1 for s in ok if s["checks"].get(c, {}).get("verdict") == "fail")
            lo, hi = wilson_interval(k, n, z)
            out[c] = {"failures": k, "n": n, "p": k / n, "lo": lo, "hi": hi}
        return out

    def invalid_as_failures(self, z: float = Z95) -> dict[str, Any] | None:
        """Overall failure probability with the invalid samples counted as failures, or None when every sample is
        valid. :meth:`failure_probability` is over the valid samples only; a design that cannot be built for some
        inputs may be one that fails there (the cable neck's spine buckling under the head's weight alone is an
        error of the design file, review 4 finding 11), so this is its upper reading: k = failing + invalid of
        n = valid + invalid, the Wilson interval, and the range of each input over the invalid samples."""
        bad = [s for s in self.samples if s["status"] == "error"]
        if not bad:
            return None
        ok = self.ok
        k = sum(1 for s in ok if s["verdict"] == "fail") + len(bad)
        n = len(ok) + len(bad)
        lo, hi = wilson_interval(k, n, z)
        inputs = {name: [float(min(s["inputs"][name] for s in bad)), float(max(s["inputs"][name] for s in bad))]
                  for name in self.names}
        return {"invalid": len(bad), "failures": k, "n": n, "p": k / n, "lo": lo, "hi": hi, "inputs": inputs}

    def invalid_note(self) -> str:
        """One sentence for the console and the report when samples are invalid: what P_fail is over, the invalid
        samples' inputs, and what the row with them counted as failures means."""
        inv = self.invalid_as_failures()
        if inv is None:
            return ""
        spans = ", ".join(f"{name} {self.value_text(name, a)}" if a == b else
                          f"{name} {a:.6g}..{self.value_text(name, b)}" for name, (a, b) in inv["inputs"].items())
        return (f"P_fail is over the {len(self.ok)} valid samples; the {inv['invalid']} invalid ones ({spans}) are "
                "left out: the row 'overall, invalid counted as failures' counts them as failures, in case the "
                "design could not be built because it fails there")

    def worst(self) -> dict[str, Any] | None:
        """The valid sample with the highest governing u·SF."""
        ok = self.ok
        if not ok:
            return None
        return max(ok, key=lambda s: math.inf if s["max_fu"] is None else s["max_fu"])

    def sensitivity(self) -> dict[str, list[tuple[str, float]]]:
        """Per check (and ``"governing"``), the inputs by |Spearman rank correlation| with its u·SF, strongest
        first; inputs without a defined correlation (constant input or output) are left out."""
        out: dict[str, list[tuple[str, float]]] = {}
        for c in [*self.checks, "governing"]:
            y = self.fu(None if c == "governing" else c)
            ranks = []
            for name in self.names:
                rho = spearman(self.values(name), y)
                if rho is not None:
                    ranks.append((name, rho))
            out[c] = sorted(ranks, key=lambda t: -abs(t[1]))
        return out

    def changing_checks(self) -> list[str]:
        """Checks whose u·SF changes over the valid samples, by their highest u·SF (highest first). A spread within
        1e-9 of the u·SF's size is rounding, not a change (a bolt load that scales exactly with a plate's thickness
        came out 0.8692159734470266 and ...295; the tolerance of :func:`~mechverify.studies.stats.spearman`)."""
        out = []
        for c in self.checks:
            v = self.fu(c)
            v = v[~np.isnan(v)]
            w = np.where(np.isinf(v), 1e300, v)  # (an infinite u·SF among finite ones is a change)
            if v.size and np.ptp(w) > 1e-9 * float(np.max(np.abs(w))):
                out.append((float(np.max(v)), c))
        return [c for _, c in sorted(out, key=lambda t: -t[0])]

    def most_influential(self) -> str | None:
        r = self.sensitivity().get("governing") or []
        return r[0][0] if r else (self.names[0] if self.names else None)

    # ------------------------------------------------------------------ output
    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {"design": self.design_name, "kind": self.kind, "method": self.method, "seed": self.seed,
                             "axes": self.axes, "checks": self.checks, "samples": self.samples}
        if self.kind == "monte_carlo":
            d["failure_probability"] = self.failure_probability()
            d["sensitivity"] = {k: [[n, r] for n, r in v] for k, v in self.sensitivity().items()}
            w = self.worst()
            d["worst"] = None if w is None else w["index"]
            inv = self.invalid_as_failures()
            if inv is not None:
                d["invalid_as_failures"] = inv
        if self.warnings:
            d["warnings"] = list(self.warnings)
        return d

    def to_json(self, indent: int | None = 1) -> str:
        from mechverify.fileio import json_text

        return json_text(self.to_dict(), indent=indent, ensure_ascii=False)

    def to_csv(self) -> str:
        checks = self.checks
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(["index", *self.names, "status", "verdict", "governing", "max_fu",
                    *[f"{c} fu" for c in checks], *[f"{c} verdict" for c in checks], "message"])
        for s in self.samples:
            row = [s["index"], *[repr(s["inputs"][n]) for n in self.names], s["status"], s["verdict"], s["governing"],
                   _full(s["max_fu"]) if s["status"] == "ok" else ""]
            row += [_full(s["checks"].get(c, {}).get("fu", math.nan)) for c in checks]
            row += [s["checks"].get(c, {}).get("verdict", "") for c in checks]
            w.writerow([*row, s["message"]])
        return buf.getvalue()

    def write(self, path: str | Path) -> Path:
        """Write ``.json`` or ``.csv`` by the file's extension."""
        from mechverify.fileio import atomic_write

        p = Path(path)
        if p.suffix.lower() == ".json":
            return atomic_write(p, self.to_json() + "\n")
        if p.suffix.lower() == ".csv":
            return atomic_write(p, self.to_csv())
        raise InputError(f"{path}: write a study as .json or .csv")

    def overrides(self, i: int) -> dict[str, Any]:
        """The design-file values of sample ``i`` (key path -> value as written in the file)."""
        if not 0 <= i < len(self.samples):
            raise InputError(f"sample {i} does not exist (0..{len(self.samples) - 1})")
        s = self.samples[i]
        return {a["name"]: _text(a, s["inputs"][a["name"]]) for a in self.axes}

    def reproduce(self, i: int, path: str | Path) -> Path:
        """Write sample ``i`` as a design file that ``mechverify check`` reads."""
        from mechverify.fileio import atomic_write
        from mechverify.studies.tomlout import dumps

        doc = rebase_files(apply_overrides(self.doc, self.overrides(i)),
                           Path(self.path).resolve().parent if self.path else Path.cwd(), Path(path).resolve().parent)
        body = self._rewritten_source(doc, i) or dumps(doc)
        head = (f"# Sample {i} of a {self.kind.replace('_', ' ')} study of {self.design_name!r}"
                + (f" ({self.path})" if self.path else "") + ":\n"
                + "".join(f"#   {k} = {v!r}\n" for k, v in self.overrides(i).items()))
        return atomic_write(Path(path), head + body)

    def _rewritten_source(self, doc: dict[str, Any], i: int) -> str | None:
        """The source design file's text with only the changed values rewritten on their lines (its comments,
        the sources and assumptions they record, and its layout kept), when that text reads back as exactly
        ``doc``; None otherwise (includes, a value from a template or a default, a value in an inline table)."""
        import tomllib

        from mechverify.studies.params import get_path, split_path
        from mechverify.studies.tomlout import rewrite_values

        if not self.path:
            return None
        try:
            source = Path(self.path).read_text(encoding="utf-8")
            original = tomllib.loads(source)
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
            return None
        values: dict[tuple[str, ...], Any] = {}
        for k in self.overrides(i):
            steps = split_path(k)
            if any(isinstance(x, int) for x in steps):
                return None
            values[tuple(str(x) for x in steps)] = get_path(doc, k)
        for section in ("components", "templates"):  # file names rebased for another folder
            for name, table in (doc.get(section) or {}).items():
                for key in table_file_keys(doc, table) if isinstance(table, dict) else ():
                    if key in table:
                        was = ((original.get(section) or {}).get(name) or {}).get(key)
                        if was != table[key]:
                            values[(section, name, key)] = table[key]
        text = rewrite_values(source, values)
        if text is None:
            return None
        try:
            same = tomllib.loads(text) == doc
        except tomllib.TOMLDecodeError:
            return None
        return text if same else None

    def summary(self) -> str:
        """A plain-text summary: counts, the failure probabilities or the sweep table."""
        label = {"monte_carlo": "Monte Carlo study", "sweep": "sweep"}.get(self.kind, self.kind)
        lines = [f"{label} of {self.design_name!r}: {len(self.samples)} samples"
                 + (f" ({self.method}, seed {self.seed})" if self.kind == "monte_carlo" else "")
                 + (f", {len(self.errors)} invalid" if self.errors else "")]
        if self.kind == "monte_carlo":
            fp = self.failure_probability()
            if fp:
                lines.append(f"{'check':44s} {'fail':>6s} {'P_fail':>8s}  95 % interval (Wilson)")
                for c, v in fp.items():
                    lines.append(f"{c:44s} {v['failures']:6d} {v['p']:8.4f}  [{v['lo']:.4f}, {v['hi']:.4f}]")
            inv = self.invalid_as_failures()
            if inv is not None:
                lines.append(f"{'overall, invalid counted as failures':44s} {inv['failures']:6d} {inv['p']:8.4f}  "
                             f"[{inv['lo']:.4f}, {inv['hi']:.4f}]")
                lines.append(f"({self.invalid_note()})")
            w = self.worst()
            if w is not None:
                lines.append(f"worst sample {w['index']}: {w['governing']} u·SF = {_num(w['max_fu'])}  "
                             + ", ".join(f"{k} = {self.value_text(k, v)}" for k, v in w["inputs"].items()))
            sens = {c: v for c, v in self.sensitivity().items() if v}
            if sens:
                lines.append("sensitivity: Spearman rank correlation of u·SF with each input, strongest first")
                for c, v in sens.items():
                    lines.append(f"  {c:42s} " + ", ".join(f"{n} {r:+.3f}" for n, r in v))
        else:
            changing = self.changing_checks()
            shown = changing[:3]
            heads = [self.label(n) for n in self.names]
            lines.append("  ".join(heads) + "  " + "  ".join(shown) + "  governing (u·SF)  verdict")
            for s in self.samples:
                ins = "  ".join(f"{s['inputs'][n]:>{len(h)}.6g}" for n, h in zip(self.names, heads))
                if s["status"] == "ok":
                    fus = "  ".join(f"{_num(s['checks'].get(c, {}).get('fu')):>{len(c)}s}" for c in shown)
                    lines.append(f"{ins}  {fus}  {s['governing']} ({_num(s['max_fu'])})  {s['verdict']}")
                else:
                    why = _last_line(s["message"])
                    lines.append(f"{ins}  invalid: " + (why if len(why) <= 60 else why[:59] + "… (below)"))
            if len(changing) > len(shown):
                lines.append(f"(u·SF of the {len(shown)} highest of the {len(changing)} checks that change over the "
                             "sweep, highest first; all of them in the --json and --csv outputs)")
            elif shown:
                lines.append("(u·SF of the checks that change over the sweep, highest first)")
        for s in self.errors[:5]:
            lines.append(f"sample {s['index']} invalid: {_last_line(s['message'])}")
        return "\n".join(lines)


def file_keys() -> tuple[str, ...]:
    """Keys whose value is a file name relative to the design file: the fields the component types declare with
    ``Field(..., file=True)`` (design/spec.py; solid_fea's step, stl and mesh), so a new one is rebased without a
    list to keep here. A design file written to another folder (``reproduce``) gets them relative to its own
    folder."""
    from mechverify.design.spec import REGISTRY

    return tuple(sorted({f.name for t in REGISTRY.types.values() for f in t.fields if f.file}))


def table_file_keys(doc: Mapping[str, Any], table: Mapping[str, Any]) -> tuple[str, ...]:
    """The file-name keys of one component or template table: those its type (``type``, or its template's through
    ``extends``) declares ``file=True``; every type's (:func:`file_keys`) when the type is not known. By type, since
    a key name can be a file in one type and a number in another: the lever arm sweep's ``step = "10 deg"`` was
    rebased as a file name, "../ex/lever_arm/10 deg" (review 4 finding 12)."""
    from mechverify.design.spec import REGISTRY

    kind, seen = table.get("type"), set()
    while kind is None and isinstance(table.get("extends"), str) and table["extends"] not in seen:
        seen.add(table["extends"])
        table = (doc.get("templates") or {}).get(table["extends"]) or {}
        kind = table.get("type") if isinstance(table, Mapping) else None
    ct = REGISTRY.types.get(kind) if isinstance(kind, str) else None
    if ct is None:
        return file_keys()
    return tuple(sorted(f.name for f in ct.fields if f.file))


def rebase_files(doc: dict[str, Any], source_dir: Path, out_dir: Path) -> dict[str, Any]:
    """``doc`` with every relative file name of a component or template (:func:`table_file_keys`) rewritten from
    ``source_dir`` to ``out_dir`` (relative when both are on one drive, else absolute); in place, returned."""
    import os

    for section in ("components", "templates"):
        for table in (doc.get(section) or {}).values():
            if not isinstance(table, dict):
                continue
            for k in table_file_keys(doc, table):
                v = table.get(k)
                if isinstance(v, str) and v and not Path(v).is_absolute():
                    target = (source_dir / v).resolve()
                    try:
                        table[k] = Path(os.path.relpath(target, out_dir)).as_posix()
                    except ValueError:  # (another drive on Windows)
                        table[k] = str(target)
    return doc


def pretty_unit(unit: str) -> str:
    """A unit string as printed (``m/s**2`` -> ``m/s²``, ``N*m`` -> ``N·m``); the input's own text otherwise."""
    if not unit:
        return ""
    try:
        from mechverify.units import Q

        return format(Q(1.0, unit).units, "~P")
    except Exception:  # (pint raises several types; the text is still right)
        return unit


_ERRORS_HEAD = re.compile(r"(\d+) errors? in the design file:$")


def _last_line(message: str) -> str:
    """The error itself, for one console line: of a design file's error list (``N errors in the design file:``)
    the FIRST error (the cause; later ones are often its cascade, 'lift_screw is invalid (see its own errors)') and
    how many there are; otherwise the last non-empty line of the message (after a header line)."""
    lines = [x.strip() for x in message.splitlines() if x.strip()]
    if not lines:
        return ""
    m = _ERRORS_HEAD.search(lines[0])
    if m and len(lines) > 1:
        n = len(lines) - 1
        return lines[1] + (f" (first of {n} errors)" if n > 1 else "")
    return lines[-1]


def _full(v: float | None) -> str:
    """A value for CSV: every digit (repr), 'inf' for an unbounded u·SF, '' where the check did not run."""
    if v is None:
        return "inf"
    return "" if math.isnan(v) else repr(v)


def _num(v: float | None) -> str:
    return "inf" if v is None else f"{v:.4g}"


def _text(axis: Mapping[str, Any], x: float) -> Any:
    if axis.get("integer"):
        return int(round(x))
    return f"{x!r} {axis['unit']}" if axis["unit"] else float(x)


def _finish(record: dict[str, Any], index: int, inputs: dict[str, float]) -> dict[str, Any]:
    checks = record["checks"]
    gov, max_fu = "", 0.0
    for k, c in checks.items():
        f = math.inf if c["fu"] is None else c["fu"]
        if not gov or f > max_fu:
            gov, max_fu = k, f
    if record["status"] != "ok":
        verdict = "error"
    elif any(c["verdict"] == "fail" for c in checks.values()):
        verdict = "fail"
    elif any(c["verdict"] == "warn" for c in checks.values()):
        verdict = "warn"
    else:
        verdict = "pass"
    # null in JSON: an unbounded u·SF of a valid sample, or no u·SF at all for an invalid one (see its status)
    out_fu = None if (not checks or math.isinf(max_fu)) else max_fu
    return {"index": index, "inputs": inputs, "status": record["status"], "message": record["message"],
            "verdict": verdict, "governing": gov, "max_fu": out_fu, "checks": checks}


class Study:
    """A sweep or a Monte Carlo study of a design.

    ``vary``: ``{"components.lift.mass": "20 kg:60 kg:9"}`` (sweep) or
    ``{"components.lift.mass": "normal:35.7 kg:1 kg", ...}`` (Monte Carlo), or ``NAME=SPEC`` strings.
    ``samples``: the number of Monte Carlo samples (a sweep has the grid's). ``method``: ``lhs``,
    ``sobol`` or ``random``; ``seed`` makes the samples reproducible.
    """

    #: the task function (module level, so workers import it by name); tests may replace it
    batch_fn: Callable[..., list[dict[str, Any]]] = staticmethod(execution.run_batch)

    def __init__(self, design: Any, vary: Any, samples: int | None = None, method: str = "lhs",
                 seed: int | None = 0, batch_size: int | None = None):
        self.doc, self.path, loaded = design_and_source(design)
        self.design_name = str(self.doc.get("design", {}).get("name", ""))
        self.axes: list[Axis] = parse_vary(self.doc, vary, None if loaded is None else resolver(loaded))
        sweeps = [a for a in self.axes if a.is_sweep]
        if sweeps and len(sweeps) != len(self.axes):
            raise InputError("vary: give either sweep axes (START:STOP:N) or distributions, not both in one study")
        self.kind = "sweep" if sweeps else "monte_carlo"
        if self.kind == "sweep" and samples is not None:
            grid = " x ".join(str(int(a.args[2])) for a in sweeps)
            raise InputError(f"samples: a sweep has as many samples as its grid ({grid}); the number of samples "
                             "is for distributions (Monte Carlo)")
        if method not in METHODS:
            raise InputError(f"method: expected one of {', '.join(METHODS)}, got {method!r}")
        self.method = method if self.kind == "monte_carlo" else "grid"
        self.seed = seed
        if self.kind == "monte_carlo":
            if samples is None:
                raise InputError("samples: a Monte Carlo study (distributions in vary) needs the number of samples")
            if isinstance(samples, bool) or not isinstance(samples, int | np.integer):
                raise InputError(f"samples: expected a whole number of samples, got {samples!r}")
            if samples < 1:
                raise InputError("samples: zero samples; give at least 1" if samples == 0 else
                                 f"samples: expected at least 1 sample, got {samples}")
        self.n_samples = int(samples) if self.kind == "monte_carlo" else int(np.prod([a.args[2] for a in sweeps]))
        if batch_size is not None and not (isinstance(batch_size, int) and batch_size >= 1):
            raise InputError(f"batch_size: expected a positive integer, got {batch_size!r}")
        self.batch_size = batch_size

    # ------------------------------------------------------------------ samples
    def inputs(self) -> list[dict[str, float]]:
        """The input values of every sample, in sample order (unit of each parameter in the file)."""
        names = [a.name for a in self.axes]
        if self.kind == "sweep":
            grids = np.meshgrid(*[a.sweep_values() for a in self.axes], indexing="ij")
            cols = [g.ravel() for g in grids]
        else:
            u = self._unit_samples()
            cols = [a.ppf(u[:, j]) for j, a in enumerate(self.axes)]
        return [{n: float(c[i]) for n, c in zip(names, cols)} for i in range(self.n_samples)]

    def _unit_samples(self) -> np.ndarray:
        from scipy.stats import qmc

        d, n = len(self.axes), self.n_samples
        if self.method == "lhs":  # up to 1000 points: optimised against chance correlation of the inputs
            if d > 1 and n <= LHS_OPTIMISE_MAX:  # (SciPy's random-cd result, bit for bit, 4-6 x faster)
                return optimised_lhs(d, n, self.seed)
            return qmc.LatinHypercube(d, seed=self.seed).random(n)
        if self.method == "sobol":
            with warnings.catch_warnings():  # balance properties need 2^m points; any n still works
                warnings.simplefilter("ignore", UserWarning)
                return qmc.Sobol(d, scramble=True, seed=self.seed).random(n)
        return np.random.default_rng(self.seed).random((n, d))

    def overrides(self, inputs: Mapping[str, float]) -> dict[str, Any]:
        return {a.name: a.param.text(inputs[a.name]) for a in self.axes}

    def result_skeleton(self) -> StudyResult:
        """A result with the inputs only (no sample evaluated): what :meth:`reproduce` needs."""
        axes = [{**a.to_dict(), "integer": a.param.integer} for a in self.axes]
        samples = [{"index": i, "inputs": x, "status": "not run", "message": "", "verdict": "", "governing": "",
                    "max_fu": None, "checks": {}} for i, x in enumerate(self.inputs())]
        return StudyResult(self.kind, self.method, self.seed if self.kind == "monte_carlo" else None, axes, samples,
                           self.design_name, self.doc, self.path)

    def reproduce(self, i: int, path: str | Path) -> Path:
        """Write sample ``i`` as a design file (the samples are rebuilt from the seed; nothing is evaluated)."""
        return self.result_skeleton().reproduce(i, path)

    # ------------------------------------------------------------------ running
    def run(self, executor: Any = None, *, workers: int | None = None, memory_per_worker: Any = None,
            progress: bool | Any = False, retries: int = 1, check_inputs: bool = True) -> StudyResult:
        """Evaluate every sample. ``executor``: any :class:`concurrent.futures.Executor` (default: a local
        process pool with one worker per core, or fewer when ``memory_per_worker``, e.g. ``"2 GB"`` for an
        FEA model, times the workers would exceed the available memory - for a design with FE components it is
        measured when not given: :func:`~mechverify.studies.execution.fe_memory_per_worker`; ``"serial"``: in
        this process).
        ``progress``: True for a rich progress bar on the console, or a callable taking the number of
        samples just finished. ``check_inputs``: first look for varied inputs that reach no check
        (:func:`mechverify.studies.inert.inert_inputs`: the dependency graph, then one probe evaluation per
        input) and warn (:class:`~mechverify.studies.inert.InertInputWarning`) naming each; the result keeps
        the messages (``warnings``)."""
        if workers is not None and not (isinstance(workers, int) and workers >= 1):
            raise InputError(f"workers: expected a positive integer, got {workers!r}")
        notes: list[str] = []
        if check_inputs:
            from mechverify.studies.inert import InertInputWarning, inert_inputs

            notes = inert_inputs(self)
            for text in notes:
                warnings.warn(text, InertInputWarning, stacklevel=2)
        inputs = self.inputs()
        ovs = [self.overrides(x) for x in inputs]
        if executor == "serial":
            executor = execution.SerialExecutor()
        elif executor is None:
            execution.build_base_before_fork(self.doc, self.path)
            if memory_per_worker is None and workers is None:  # an FE study: a sample's memory measured once
                memory_per_worker = execution.fe_memory_per_worker(self.doc, self.path)
        n_workers = workers or execution.default_workers(memory_per_worker)
        sizes = [self.batch_size] * math.ceil(len(ovs) / self.batch_size) if self.batch_size else \
            batch_sizes(len(ovs), n_workers)
        starts = np.cumsum([0, *sizes[:-1]]).tolist()
        batches = [ovs[i:i + k] for i, k in zip(starts, sizes)]
        bar, on_done = _progress(progress, len(ovs))
        try:
            out = execution.run_batches(type(self).batch_fn, self.doc, self.path, batches, executor,
                                        workers=n_workers, retries=retries, on_done=on_done)
        finally:
            if bar is not None:
                bar.stop()
        records = [r for batch in out for r in batch]
        samples = [_finish(r, i, x) for i, (r, x) in enumerate(zip(records, inputs))]
        axes = [{**a.to_dict(), "integer": a.param.integer} for a in self.axes]
        return StudyResult(self.kind, self.method, self.seed if self.kind == "monte_carlo" else None, axes, samples,
                           self.design_name, self.doc, self.path, warnings=notes)


def batch_sizes(n: int, workers: int, largest: int = 50, smallest: int = 4) -> list[int]:
    """Batch sizes for ``n`` samples on ``workers``: guided self-scheduling (Polychronopoulos & Kuck 1987), each batch
    a third of the remaining samples per worker, between ``smallest`` and ``largest``: few tasks while much is
    left, small ones at the end so that no worker waits long for the last one (equal batches of 50 left a worker
    idle for up to a batch, ~0.15 s of a 0.6 s lift study of 400 samples on two cores)."""
    out, left = [], n
    smallest = max(1, min(smallest, math.ceil(n / (4 * workers))))  # (a few samples: one or two per worker)
    while left > 0:
        k = min(left, largest, max(smallest, math.ceil(left / (3 * workers))))
        out.append(k)
        left -= k
    return out


def _progress(progress: Any, total: int) -> tuple[Any, Callable[[int], None] | None]:
    if callable(progress):
        return None, progress
    if not progress:
        return None, None
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    bar = Progress(TextColumn("samples"), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                   console=Console(stderr=True), transient=False)
    task = bar.add_task("study", total=total)

    def advance(n: int) -> None:  # started at the first result: the pool's processes exist by then
        if not bar.live.is_started:
            bar.start()
        bar.advance(task, n)

    return bar, advance


def run_serial(design: Any, overrides: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """Evaluate a few override sets in this process (plain records, as a worker returns them)."""
    doc, path = design_source(design)
    return execution.run_batch(doc, path, overrides)
