"""Property-based fuzzing of design files: whatever a user writes, no traceback reaches them.

Documents are generated from the real vocabulary (section names, registered component types and
their field names, unit strings of every dimension) mixed with junk, so the fuzzer reaches deep
into validation and building. The only acceptable outcomes are a verified design or a
``DesignFileError``; through the CLI, exit status 0, 1 or 2 (never 3, the internal-error status).
"""

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mechverify.design.adapters  # noqa: F401  (registers the real component types)
from mechverify.cli import main
from mechverify.design import REGISTRY, Design, DesignFileError
from mechverify.design.loader import parse

UNIT_STRINGS = ["350 mm", "350 N", "-5 mm", "0 mm", "12", "3 kN*m", "2 MPa", "nan mm", "inf N", "10 rpm",
                "30 deg", "1e9 m", "abc", "", "5 kg", "0.2", "1 h", "7850 kg/m^3", "1 A", "24 V"]
NAMES = ["Structural Steel", "PLA", "A228", "unobtainium", "Tr10x2", "608", "x"]

scalar = st.one_of(st.sampled_from(UNIT_STRINGS), st.sampled_from(NAMES), st.integers(-5, 10**6),
                   st.floats(allow_nan=True, allow_infinity=True), st.booleans(), st.text(max_size=8))
value = st.recursive(scalar, lambda c: st.one_of(st.lists(c, max_size=4), st.dictionaries(st.text(max_size=6), c,
                                                                                            max_size=3)), max_leaves=8)


@st.composite
def component(draw):
    types = sorted(REGISTRY.in_section("components"))
    t = draw(st.sampled_from(types + ["nonsense"]))
    body = {"type": t}
    fields = [f.name for f in REGISTRY.types[t].fields] if t in REGISTRY.types else []
    for name in draw(st.lists(st.sampled_from(fields + ["junk", "checks"]), max_size=len(fields) + 2)):
        body[name] = draw(value)
    return body


@st.composite
def document(draw):
    doc = {}
    if draw(st.booleans()):
        doc["design"] = {"name": draw(st.one_of(st.text(max_size=10), st.integers())), "revision": draw(scalar)}
    comps = draw(st.dictionaries(st.sampled_from(["a", "b", "screw", "motor"]), component(), max_size=3))
    if comps:
        doc["components"] = comps
    if draw(st.booleans()):
        doc["requirements"] = draw(st.dictionaries(st.sampled_from(["g", "bearing_life", "safety_factors", "x"]),
                                                   value, max_size=3))
    if draw(st.booleans()):
        doc["materials"] = draw(st.dictionaries(st.text(max_size=5), st.dictionaries(
            st.sampled_from(["base", "E", "yield_strength", "category", "name", "junk"]), value, max_size=3),
            max_size=2))
    if draw(st.booleans()) and comps:
        doc["load_cases"] = {"c": {k: draw(st.dictionaries(st.text(max_size=12), value, max_size=3))
                                   for k in comps}}
    if draw(st.booleans()):
        doc[draw(st.text(max_size=6))] = draw(value)
    return doc


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(document())
def test_parse_never_raises_anything_but_design_errors(doc):
    try:
        Design(parse(doc)).verify()
    except DesignFileError as exc:
        assert exc.errors and all(isinstance(m, str) and m for _, m in exc.errors)


@settings(max_examples=60, deadline=None)
@given(st.binary(max_size=200))
def test_cli_on_arbitrary_bytes_exits_cleanly(tmp_path_factory, data):
    p = tmp_path_factory.mktemp("fuzz") / "design.toml"
    p.write_bytes(data)
    assert main(["check", str(p), "-q"]) in (0, 1, 2)



# --- the CLI on generated design files and argument lists (issue 17) --------------------------------------

import hashlib  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
from pathlib import Path  # noqa: E402

from hypothesis import assume  # noqa: E402


def toml_value(v) -> str:
    """A TOML inline representation (the test writes the generated documents as files)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return "{" + ", ".join(f"{json.dumps(k)} = {toml_value(x)}" for k, x in v.items()) + "}"


def toml_text(doc: dict) -> str:
    return "".join(f"{json.dumps(k)} = {toml_value(v)}\n" for k, v in doc.items())


def test_toml_writer_round_trips():
    import tomllib

    doc = {"design": {"name": "x", "n": [1, 2.5, "a", True, {"b": float("inf")}]}, "a b": {}}
    back = tomllib.loads(toml_text(doc))
    assert back["design"]["n"][:4] == [1, 2.5, "a", True] and back["a b"] == {}


def snapshot(folder: Path) -> dict[str, str]:
    """Hash of every regular file (links and FIFOs are not followed) and the set of entries."""
    out = {}
    for p in sorted(folder.rglob("*")):
        if p.is_symlink():
            out[str(p)] = "link->" + os.readlink(p)
        elif p.is_file():
            out[str(p)] = hashlib.sha256(p.read_bytes()).hexdigest()
        else:
            out[str(p)] = "other"
    return out


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(document())
def test_cli_on_generated_design_files(tmp_path_factory, doc):
    """Generated documents written as files: exit 0/1/2, no traceback, the file unchanged."""
    folder = tmp_path_factory.mktemp("gen")
    p = folder / "design.toml"
    try:
        p.write_text(toml_text(doc), encoding="utf-8")
    except UnicodeEncodeError:  # lone surrogates cannot be written as UTF-8
        assume(False)
    before = snapshot(folder)
    code = main(["check", str(p), "-q", "--json", str(folder / "r.json")])
    assert code in (0, 1, 2)
    after = snapshot(folder)
    after.pop(str(folder / "r.json"), None)
    assert after == before


RIG = """
[design]
name = "rig"
include = ["parts.toml"]

[components.rod]
type = "test_rod"
length = "350 mm"
area = "20 mm^2"
material = "steel2"

[load_cases.hold.rod]
force = "2 kN"
"""
PARTS = '[materials.steel2]\nbase = "Structural Steel"\n'

#: output-path candidates: inputs, a link to an input, a FIFO, a folder, missing folders, devices, fresh files
PATHS = ["design.toml", "parts.toml", "link.toml", "dangling.json", "fifo", "sub", "sub/r.json", "nope/r.json",
         "r.json", "r.xml", "r2.json", "r.html", "null", "/proc/r.json", ""]
OPTIONS = ["--json", "--junit", "--report", "-o", "--output", "--fail-on", "-q", "--quiet", "--force",
           "--base-ref", "--allow-outside-includes", "--no-allow-outside-includes", "--bogus"]


@st.composite
def argv(draw):
    """Mostly well-formed command lines (so that the output paths are reached), sometimes junk."""
    cmd = draw(st.sampled_from(["check", "check", "check", "diff", "schema", "init"]))
    path = st.sampled_from(PATHS)
    args = [cmd]
    if cmd == "check":
        args += draw(st.lists(st.sampled_from(["design.toml"] * 6 + PATHS), min_size=1, max_size=2))
        for opt in ("--json", "--junit", "--report"):
            if draw(st.booleans()):
                value = draw(path)
                args += [opt, value + ".html" if opt == "--report" and draw(st.booleans()) else value]
        args += draw(st.sampled_from([[], ["-q"], ["--fail-on", "warn"]]))
    elif cmd == "diff":
        args += draw(st.sampled_from([["design.toml", "design.toml"], ["design.toml", "--base-ref", "HEAD"],
                                      ["design.toml"], ["parts.toml", "link.toml"]]))
        if draw(st.booleans()):
            args += ["--json", draw(path)]
    elif cmd == "schema":  # no inputs: an existing regular file is a legitimate output, so not the rig's files
        args += ["-o", draw(path.filter(lambda p: p not in ("design.toml", "parts.toml")))] if draw(st.booleans()) \
            else []
    else:
        args.append(draw(path))  # without --force: refuses every existing path
    if draw(st.integers(0, 4)) == 0:  # junk somewhere
        args.insert(draw(st.integers(1, len(args))), draw(st.sampled_from([*OPTIONS, *PATHS])))
    return args


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    folder = tmp_path_factory.mktemp("rig")
    (folder / "design.toml").write_text(RIG)
    (folder / "parts.toml").write_text(PARTS)
    (folder / "link.toml").symlink_to(folder / "design.toml")
    (folder / "dangling.json").symlink_to(folder / "nowhere.json")
    os.mkfifo(folder / "fifo")
    (folder / "sub").mkdir()
    _device_or_fifo(folder / "null")
    return folder


def _device_or_fifo(path):
    """A character device like /dev/null made in the temp folder (root), else a FIFO: a regression in the
    output-path guard then replaces this node, never the system's /dev/null."""
    import stat

    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))
    except (PermissionError, OSError):
        os.mkfifo(path)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(args=argv())
def test_cli_argument_lists_never_touch_inputs(rig, rod_type, args, monkeypatch):
    """Whatever the arguments: exit 0/1/2, no traceback, no input changed, no link or FIFO replaced,
    no temporary file left; new files appear only where an output option named them."""
    monkeypatch.chdir(rig)
    before = snapshot(rig)
    code = main(args)
    assert code in (0, 1, 2), args
    after = snapshot(rig)
    for path, digest in before.items():
        assert after.get(path) == digest, (args, path)  # inputs, links, FIFO, folder: untouched
    new = set(after) - set(before)
    assert not [p for p in new if p.endswith(".tmp")], args
    for p in new:  # clean up what a valid run wrote, for the next example
        Path(p).unlink() if Path(p).is_file() else None
    assert (rig / "design.toml").read_text() == RIG
