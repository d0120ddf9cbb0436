"""The check registry, the bibliography and CheckSpec.of (issue 16)."""

from __future__ import annotations

import pytest

from mechverify.checks import registry
from mechverify.checks.registry import CHECKS, check, explain_text, get_check
from mechverify.design.spec import DEFAULT_SAFETY_FACTORS, CheckSpec, ComponentType
from mechverify.errors import UnknownNameError
from mechverify.references import bibliography, keys_in, ref, references


@pytest.fixture
def scratch():
    """Names registered by a test are removed again afterwards."""
    registry.load_all()
    before = dict(CHECKS), dict(registry._ALIASES)
    yield
    CHECKS.clear()
    CHECKS.update(before[0])
    registry._ALIASES.clear()
    registry._ALIASES.update(before[1])


def test_decorator_registers_and_keeps_plain_function(scratch):
    @check("zz_demo_check", title="Demo", sf_kind="buckling", source=ref("shigley10", "Eq. 4-43"),
           explain="Demo paragraph.", aliases=("demo_type.old_key",))
    def check_zz_demo_check(x: float) -> float:
        return 2 * x

    assert check_zz_demo_check(2.0) == 4.0
    d = get_check("zz_demo_check")
    assert d is check_zz_demo_check.check_def
    assert (d.title, d.sf_kind, d.source_keys) == ("Demo", "buckling", ("shigley10",))
    assert get_check("demo_type.old_key") is d
    assert d.local_aliases("demo_type") == ("old_key",)
    assert registry.is_alias("demo_type.old_key") and not registry.is_alias("zz_demo_check")
    text = explain_text("zz_demo_check")
    assert "Demo paragraph." in text and "10th ed." in text and "Eq. 4-43" in text


def test_names_are_unique_and_well_formed(scratch):
    @check("zz_unique", title="One", aliases=("zz_unique_old",))
    def check_zz_unique() -> None: ...

    with pytest.raises(ValueError, match="already used"):
        @check("zz_unique", title="Two")
        def check_other() -> None: ...
    with pytest.raises(ValueError, match="already used"):
        @check("zz_unique_old", title="Three")
        def check_third() -> None: ...
    with pytest.raises(ValueError, match="lower_snake_case"):
        check("Bad-Name", title="x")(lambda: None)
    with pytest.raises(ValueError, match="sf_kind"):
        check("zz_bad_kind", title="x", sf_kind="nonsense")(lambda: None)
    with pytest.raises(ValueError, match="title"):
        check("zz_no_title", title="")(lambda: None)


def test_unknown_check_suggests(scratch):
    @check("zz_screw_thing", title="x")
    def check_zz_screw_thing() -> None: ...

    with pytest.raises(UnknownNameError) as e:
        get_check("zz_screw_thin")
    assert "zz_screw_thing" in e.value.suggestions


def test_safety_factor_classes_have_one_source():
    """The design files' classes are the registry's (one dict, not a copy), and each has a positive default."""
    assert DEFAULT_SAFETY_FACTORS is registry.DEFAULT_SAFETY_FACTORS
    assert registry.SF_KINDS == tuple(DEFAULT_SAFETY_FACTORS)
    assert all(v > 0 for v in DEFAULT_SAFETY_FACTORS.values())


def test_checkspec_of_takes_identity_from_registry(scratch):
    @check("zz_spec_demo", title="Spec demo", sf_kind="fatigue", explain="Why.", aliases=("zz_type.demo",))
    def check_zz_spec_demo() -> None: ...

    spec = CheckSpec.of(check_zz_spec_demo, lambda c, loads, ctx: None, needs=("force",), default=False)
    assert (spec.name, spec.title, spec.sf_kind, spec.explain, spec.needs, spec.default) == (
        "zz_spec_demo", "Spec demo", "fatigue", "Why.", ("force",), False)
    ct = ComponentType("zz_type", "demo", (), build=lambda p, ctx: None, checks=(spec,))
    assert ct.check("demo") is ct.check("zz_spec_demo") is ct.checks[0]
    assert ct.checks[0].aliases == ("demo",)
    with pytest.raises(ValueError, match="not a registered check"):
        CheckSpec.of(lambda: None, lambda c, loads, ctx: None)


def test_references():
    refs = references()
    assert "shigley10" in refs and refs["shigley10"].edition == "10th"
    s = ref("shigley10", "Sec. 8-2, Eq. 8-1")
    assert s.endswith("Eq. 8-1") and "10th ed." in s
    assert set(keys_in(ref("iso281") + "; " + ref("roark8", "Table 11.2"))) == {"roark8", "iso281"}
    with pytest.raises(UnknownNameError):
        ref("shigley9")
    assert [k for k, _ in bibliography(["iso76", "iso76"])] == ["iso76"]
    # one edition per book: no title appears twice
    titles = [(r.authors, r.title, r.number) for r in refs.values()]
    assert len(titles) == len(set(titles))


LINK = """
[design]
name = "alias test"

[components.eye]
type = "link"
length = "200 mm"
section = "rectangle"
width = "20 mm"
height = "8 mm"
material = "S235JR"
hole_diameter = "10 mm"
{checks}

[load_cases.pull.eye]
axial_force = "2 kN"
"""


def _design(tmp_path, checks: str):
    from mechverify.design.design import load

    p = tmp_path / "design.toml"
    p.write_text(LINK.format(checks=checks))
    return load(p)


def test_former_design_keys_still_work_with_a_deprecation_note(tmp_path):
    """A former key (`buckling`, `lug`) sets the renamed check(s) and the result says so."""
    rs = _design(tmp_path, "checks = { body_strength = { required_sf = 3.0 }, lug = false }").verify()
    body = rs.get("eye", "member_body_strength")
    assert body.required_sf == 3.0
    assert any("Deprecated check key 'body_strength'" in n and "'member_body_strength'" in n for n in body.notes)
    assert not [r for r in rs if r.check.startswith("lug_")]  # `lug` turned all four BTH-1 checks off
    rs = _design(tmp_path, "checks = { member_body_strength = { required_sf = 3.0 } }").verify()
    body = rs.get("eye", "member_body_strength")
    assert body.required_sf == 3.0 and not any("Deprecated" in n for n in body.notes)
    assert {r.check for r in rs} >= {"lug_tension", "lug_fracture_beyond", "lug_shear_out", "lug_bearing"}


def test_report_lists_the_cited_references(tmp_path):
    """The report's reference list is built from the bibliography: the sources its checks cite, once each."""
    from mechverify.reports.render import render_html

    d = _design(tmp_path, "")
    html = render_html([(d, d.verify())])
    refs = html[html.index("<h3>References</h3>"):]
    refs = refs[:refs.index("</ol>")]
    assert refs.count("Shigley&#39;s Mechanical Engineering Design, 10th ed.") == 1
    assert "ASME BTH-1-2008" in refs
