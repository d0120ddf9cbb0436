"""Property-based fuzzing of design files: whatever a user writes, no traceback reaches them.

Documents are generated from the real vocabulary (section names, registered component types and
their field names, unit strings of every dimension) mixed with junk, so the fuzzer reaches deep
into validation and building. The only acceptable outcomes are a verified design or a
``DesignFileError``; through the CLI, exit status 0, 1 or 2 (never 3, the internal-error status).
"""

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

