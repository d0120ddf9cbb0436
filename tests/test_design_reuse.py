"""A variant of a design (Design.with_overrides) reuses the results of components whose inputs are unchanged
(mechverify/design/reuse.py, issue 19).

Oracle: the same variant built from scratch (no base to reuse from) must give identical results, field by field
and in the JSON; the reused results are the base's own objects only for components whose inputs did not change.
"""

from __future__ import annotations

import copy
import dataclasses
import json
from collections.abc import Mapping
from pathlib import Path

import pytest

from mechverify.design import load
from mechverify.design.design import _rebuild

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


def _rows(rs):
    """Every field's repr; a lazy ``details`` mapping (checks/result.py) as the dict it computes (its repr says
    whether it has been read yet, which differs between a reused result and a fresh one)."""
    def value(v):
        return repr(dict(v)) if isinstance(v, Mapping) else repr(v)

    return [{f.name: value(getattr(r, f.name)) for f in dataclasses.fields(r)} for r in rs]


@pytest.fixture(scope="module")
def base():
    d = load(LIFT)
    d.verify()
    return d


def _reused(variant, base) -> set[str]:
    before = base._results_by_component
    return {k for k, (rs, _) in variant._results_by_component.items()
            if rs and k in before and before[k][0] and rs[0] is before[k][0][0]}


@pytest.mark.parametrize(("override", "recomputed"), [
    ({"components.lift.mass": "15.0 kg"}, {"lift"}),  # only the drive reads its mass
    ({"components.lift_screw.length": "400 mm"}, {"lift_screw", "lift"}),  # the drive turns that screw
    ({"load_cases.horizontal.screw_horizontal.transverse_load": "150 N"}, {"screw_horizontal"}),
    ({"parameters.lifted_load": "300 N"}, {"lift_screw", "screw_bearing", "lift"}),  # through the connections
    ({"requirements.bearing_life": "20000 h"}, None),  # design-wide: everything again
    ({"profiles.raise.acceleration": "0.2 m/s^2"}, {"lift"}),  # the drive names the profile
])
def test_variant_equals_a_fresh_build_and_reuses_only_unchanged_components(base, override, recomputed):
    variant = base.with_overrides(override)
    rs = variant.verify()
    fresh = _rebuild(copy.deepcopy(variant.data.raw), variant.data.path, list(variant.data.files),
                     variant.overrides).verify()
    assert _rows(rs) == _rows(fresh)
    assert rs.to_json() == fresh.to_json()
    known = {"lift_screw", "screw_horizontal", "screw_bearing", "lift"}  # (the example may grow components)
    with_results = {k for k, (r, _) in base._results_by_component.items() if r}
    reused = _reused(variant, base)
    if recomputed is None:
        assert reused == set()
    else:
        assert not reused & recomputed
        assert (known - recomputed) & with_results <= reused


def test_changed_values_change_the_results(base):
    """A reused result would hide the change: the drive's motor torque check must move with the mass."""
    light = base.with_overrides({"components.lift.mass": "5 kg"}).verify()
    heavy = base.with_overrides({"components.lift.mass": "30 kg"}).verify()
    key = {(r.component, r.check) for r in light if r.component == "lift"}
    assert key
    u_light = {(r.component, r.check): r.utilisation for r in light}
    u_heavy = {(r.component, r.check): r.utilisation for r in heavy}
    assert any(u_heavy[k] > u_light[k] for k in key)


def test_progress_steps_are_replayed(base):
    steps_fresh, steps_reused = [], []
    base.with_overrides({"components.lift.mass": "15 kg"}).verify()  # (no progress)
    fresh = _rebuild(copy.deepcopy(base.data.raw), base.data.path, list(base.data.files), {})
    fresh.verify(progress=lambda: steps_fresh.append(1))
    base.with_overrides({"components.lift.mass": "15 kg"}).verify(progress=lambda: steps_reused.append(1))
    assert len(steps_fresh) == len(steps_reused) > 0


def test_an_unverified_base_reuses_nothing():
    d = load(LIFT)
    v = d.with_overrides({"components.lift.mass": "15 kg"})
    assert v._reusable() == {}
    assert v.verify().to_json() == _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides).verify().to_json()


def test_values_written_as_expressions_outside_components_invalidate(tmp_path):
    """A parameter read by a material or a profile changes results although no component table changes."""
    text = LIFT.read_text()
    text = text.replace('[parameters]', '[parameters]\nmod = "200 GPa"\nacc = "0.1 m/s^2"', 1)
    text = text.replace('acceleration = "0.1 m/s^2"', 'acceleration = "acc"', 1)
    text += '\n[materials.steel_p]\nbase = "Inventor Steel"\nE = "mod"\n'
    text = text.replace('material = "Inventor Steel"', 'material = "steel_p"', 1)  # the lead screw's
    f = tmp_path / "lift.toml"
    f.write_text(text)
    d = load(f)
    d.verify()
    assert d.data.components["lift_screw"].params["material"].name == "steel_p"
    for ov in ({"parameters.mod": "150 GPa"}, {"parameters.acc": "0.2 m/s^2"}):
        v = d.with_overrides(ov)
        rs = v.verify()
        fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides).verify()
        assert rs.to_json() == fresh.to_json()
        assert rs.to_json() != d.verify().to_json()
    v = d.with_overrides({"parameters.mod": "150 GPa"})
    v.verify()
    assert "lift_screw" not in _reused(v, d)


_ARM = """
[design]
name = "RP arm"

[parameters]
m = "98 g"

[components.arm]
type = "planar_arm"
kind = "rp"
path = { curve = "polar", r = "8 cm - 1.5 cm * cos(4*phi)", centre = ["12.5 cm", "37.5 cm"], speed = "1.4 cm/s" }
carriage_mass = "m"
bodies = [{ name = "screw", shape = "rod", mass = "99 g", length = "25 cm" }]

[profiles.q1]
type = "joint_motion"
mechanism = "arm"
joint = "q1"

[components.revolute]
type = "drive"
motor = "maxon 6V 10.3 mNm"
gearhead = "GP 22 850:1"
inertia = "0 kg*m^2"
profile = "q1"
"""


def test_a_drive_fed_by_a_joint_motion_profile_depends_on_the_arm(tmp_path):
    """The drive names only its profile; the profile names the arm (``mechanism = "arm"``). Changing the arm's
    carriage mass must recompute the drive (review item 0: it kept the base's gearhead torque, 0.5496 instead of
    4.273). Oracle: the same variant built from scratch."""
    f = tmp_path / "arm.toml"
    f.write_text(_ARM)
    d = load(f)
    base_rs = d.verify()
    for ov in ({"parameters.m": "980 g"}, {"components.arm.path.speed": "3 cm/s"}):
        v = d.with_overrides(ov)
        rs = v.verify()
        fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides).verify()
        assert _rows(rs) == _rows(fresh)
        assert "revolute" not in _reused(v, d)
        g = [r.utilisation for r in rs if r.check == "gearhead_intermittent_torque"]
        g0 = [r.utilisation for r in base_rs if r.check == "gearhead_intermittent_torque"]
        assert g and g != g0


def test_a_study_sweep_moves_the_drive_fed_by_an_arm(tmp_path):
    """``mechverify study --vary parameters.m=98 g:980 g:3`` (review item 0): the gearhead check changes."""
    from mechverify.cli import main

    f = tmp_path / "arm.toml"
    f.write_text(_ARM)
    out = tmp_path / "study.json"
    code = main(["study", str(f), "--vary", "parameters.m=98 g:980 g:3", "--serial", "--quiet", "--json", str(out)])
    assert code == 0
    samples = json.loads(out.read_text())["samples"]
    fu = [s["checks"]["revolute.gearhead_intermittent_torque"]["fu"] for s in samples]
    assert len(fu) == 3 and fu[0] < fu[1] < fu[2], fu


def test_a_parameter_read_inside_a_path_expression_invalidates(tmp_path):
    """The arm's ``path.r = "r0 - 1.5 cm * cos(4*phi)"`` is a table the adapter evaluates itself: a change of r0
    changes no validated field of the arm, yet the drive's torque moves (the drive kept the base's result)."""
    f = tmp_path / "arm.toml"
    f.write_text(_ARM.replace('m = "98 g"', 'm = "98 g"\nr0 = "8 cm"').replace('"8 cm - 1.5 cm', '"r0 - 1.5 cm'))
    d = load(f)
    base_rs = d.verify()
    v = d.with_overrides({"parameters.r0": "9 cm"})
    rs = v.verify()
    fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides).verify()
    assert _rows(rs) == _rows(fresh)
    assert rs.to_json() != base_rs.to_json()
    assert "revolute" not in _reused(v, d)


# ------------------------------------------------------------------ built objects (task 19b): reuse.reused_object

@pytest.mark.parametrize(("override", "rebuilt"), [
    ({"components.lift.mass": "15.0 kg"}, {"lift"}),
    ({"parameters.lifted_load": "300 N"}, {"lift", "carriage"}),  # the carriage's fields read lifted_load
    ({"components.lift_screw.length": "400 mm"}, {"lift", "lift_screw"}),
    ({"profiles.raise.acceleration": "0.2 m/s^2"}, {"lift", "raise"}),
    ({"requirements.bearing_life": "20000 h"}, "all"),  # design-wide: nothing is taken over
])
def test_a_variant_takes_over_unchanged_immutable_objects(base, override, rebuilt):
    """Oracle: the same variant built without a base (every object built); its results are compared field by
    field in test_variant_equals_a_fresh_build_and_reuses_only_unchanged_components. Here: which objects are the
    base's own. Never shared: the drive (it memoises per design). The link (its section's dimensions read-only, its
    outline arrays read-only) and the profile (its samples memoised outside it) are (task 19c)."""
    from mechverify.design.reuse import shareable

    v = base.with_overrides(override)
    entries = {**v.data.components, **v.data.profiles}
    old = {**base.data.components, **base.data.profiles}
    shared = {k for k, e in entries.items() if e.obj is old[k].obj}
    assert "lift" not in shared
    assert shareable(old["screw_horizontal"].obj) and shareable(old["raise"].obj)
    expected = set() if rebuilt == "all" else {k for k in entries if shareable(old[k].obj)} - rebuilt
    assert shared == expected
    if rebuilt != "all":
        assert {"lift_screw", "screw_bearing"} - rebuilt <= shared  # (the example's immutable components)
    for k in entries:  # a rebuilt object equals a fresh build's
        fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, list(v.data.files), {})
        if shareable(entries[k].obj):
            assert repr(entries[k].obj) == repr(fresh.data.components.get(k, fresh.data.profiles.get(k)).obj)


def test_the_drive_turns_the_screw_of_its_own_design(base):
    """A rebuilt lead screw gives the drive a stage on the new screw (not the base's cached stage); an unchanged one
    gives the base's stages (drive_parsing._screw_stages), whose efficiencies equal a fresh computation."""
    from mechverify.components.transmissions import ScrewDrive

    longer = base.with_overrides({"components.lift_screw.length": "400 mm"})
    stage = longer["lift"].stage_variants[0][0][1]
    assert stage.screw is longer["lift_screw"].screw is not base["lift_screw"].screw
    heavier = base.with_overrides({"components.lift.mass": "20 kg"})
    assert heavier["lift_screw"] is base["lift_screw"]
    assert heavier["lift"].stage_variants == base["lift"].stage_variants
    s0 = heavier["lift"].stage_variants[0][0][1]
    fresh = ScrewDrive(s0.screw, s0.mu, inertia=s0.inertia, name=s0.name)
    assert (fresh.efficiency_forward, fresh.backdrive_efficiency) == (s0.efficiency_forward, s0.backdrive_efficiency)


def test_a_component_naming_a_rebuilt_one_is_rebuilt(base, monkeypatch):
    """An entry keeps the base's object only while every entry its table names is the same object in both designs.
    The lift has no immutable component naming another, so the bearing is made to name the screw: unchanged
    screw -> the bearing is the base's; rebuilt screw -> the bearing is built again (its own inputs unchanged)."""
    from mechverify.design import reuse

    real = reuse._named
    monkeypatch.setattr(reuse, "_named", lambda e, names: real(e, names) | (
        {"lift_screw"} & set(names) if e.name == "screw_bearing" else set()))
    base = load(LIFT)  # (a base of its own: a base keeps the names its entries' text holds, found with the real rule)
    base.verify()
    assert base.with_overrides({"components.lift.mass": "20 kg"})["screw_bearing"] is base["screw_bearing"]
    v = base.with_overrides({"components.lift_screw.length": "400 mm"})
    assert v["lift_screw"] is not base["lift_screw"]
    assert v["screw_bearing"] is not base["screw_bearing"]
    assert repr(v["screw_bearing"]) == repr(base["screw_bearing"])


def test_shareable_only_when_immutable_all_the_way_down():
    import numpy as np

    from mechverify.design.reuse import shareable
    from mechverify.materials import default_library
    from mechverify.units import Q

    @dataclasses.dataclass(frozen=True)
    class Leaf:
        x: object

    @dataclasses.dataclass
    class Loose:
        x: int = 1

    ro = np.zeros(3)
    ro.flags.writeable = False
    steel = default_library().get("Inventor Steel")
    assert shareable(Leaf((1, 2.0, "a", Q(3.0, "mm"), Leaf(None), frozenset({1}), ro, steel)))
    for bad in ({"memo": 1}, [1], {1}, np.zeros(3), Q(np.zeros(3), "mm"), Loose(), object(), Leaf({})):
        assert not shareable(Leaf(bad)), bad
    assert not shareable(Leaf((1, Leaf([]))))


def test_text_that_is_not_an_expression_is_parsed_once():
    """A motor's name is read as a possible expression by the loader on every variant: its error is cached, and a
    fresh error (same message) is raised each time."""
    from mechverify.design.expressions import ExpressionError, _parse_or_error, parse

    text = "NEMA 17 stepper 0.56 N·m (test)"
    with pytest.raises(ExpressionError) as first:
        parse(text)
    hits = _parse_or_error.cache_info().hits
    with pytest.raises(ExpressionError) as second:
        parse(text)
    assert str(first.value) == str(second.value) and first.value is not second.value
    assert _parse_or_error.cache_info().hits == hits + 1


def test_a_variant_takes_over_validated_tables_whose_inputs_are_unchanged(base, monkeypatch):
    """The tables a variant does not change (nor the parameters they read) are not validated again; what they
    traced (derived inputs) is recorded again, so the variant's trace and notes equal a fresh build's; the
    values are copies (resolving a connection in a variant never changes the base)."""
    from mechverify.design import loader

    seen = {}
    real = loader.validated_before

    def spy(path, *a):
        seen[path] = out = real(path, *a)
        return out

    monkeypatch.setattr(loader, "validated_before", spy)
    v = base.with_overrides({"parameters.lifted_load": "300 N"})
    monkeypatch.setattr(loader, "validated_before", real)
    taken = {p for p, hit in seen.items() if hit is not None}
    assert {"components.lift_screw", "components.screw_bearing", "load_cases.horizontal.screw_horizontal"} <= taken
    assert not taken & {"components.carriage", "load_cases.raise.lift_screw", "load_cases.raise.carriage"}
    fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, list(v.data.files), {})
    assert {k: (e[0], repr(e[1])) for k, e in v.data.trace.entries.items()} == \
           {k: (e[0], repr(e[1])) for k, e in fresh.data.trace.entries.items()}
    assert v.data.trace.edges == fresh.data.trace.edges
    for name, e in v.data.components.items():
        assert repr(e.params) == repr(fresh.data.components[name].params)
        assert e.params is not base.data.components[name].params
    tr = v.data.components["lift"].params["transmission"]
    assert tr is not base.data.components["lift"].params["transmission"]
    w = v.with_overrides({"components.lift.mass": "20 kg"})  # a variant of a variant
    assert repr(w.verify().to_json()) == repr(_rebuild(copy.deepcopy(w.data.raw), w.data.path, list(w.data.files),
                                                       {}).verify().to_json())


def test_derived_values_are_shown_as_before_when_remembered():
    """Trace lines format a scalar quantity once per (magnitude, unit); the text equals show()'s every time."""
    from mechverify.design.parameters import _shown, show
    from mechverify.units import Q

    for v in (Q(350.0, "N"), Q(350, "N"), Q(1.5, "N/(m/s**2)"), Q(0.1, "m/s**2"), Q(2.0, "mm") * 3, 4.5, "x"):
        assert _shown(v) == show(v) == _shown(v)


# ------------------------------------------------------------------ task 19c: shared profiles and links, load-free checks

def test_a_sampled_profile_stays_shareable_and_its_samples_are_kept_outside_it():
    """Profile.sample is memoised per profile and point count in motion.profiles._SAMPLES (not in the instance),
    so a sampled profile is still immutable all the way down (design/reuse.shareable); the samples equal a fresh
    computation (_sample) bit for bit and are read-only."""
    import numpy as np

    from mechverify.design.reuse import shareable
    from mechverify.motion import profiles
    from mechverify.motion.profiles import trapezoidal

    p = trapezoidal("450 mm", max_velocity="18 mm/s", acceleration="0.1 m/s^2")
    s = p.sample(41)
    assert p.sample(41) is s and p.sample(11) is not s
    assert shareable(p) and "_samples" not in p.__dict__
    fresh = p._sample(41)
    for k in ("t", "x", "v", "a", "j"):
        assert np.array_equal(getattr(s, k), getattr(fresh, k)) and not getattr(s, k).flags.writeable
    twin = trapezoidal("450 mm", max_velocity="18 mm/s", acceleration="0.1 m/s^2")  # an equal profile: its own entry (keyed by identity)
    assert twin.sample(41) is not s and np.array_equal(twin.sample(41).v, s.v)
    n = profiles._SAMPLES_MAX
    for _ in range(n + 1):  # bounded
        trapezoidal("10 mm", max_velocity="18 mm/s", acceleration="0.1 m/s^2").sample(5)
    assert len(profiles._SAMPLES) <= n


def test_a_section_is_immutable_so_a_link_is_shared(base):
    """A section's dimensions are a read-only mapping (equal to the dict, pickled as it) and its outline arrays are
    read-only, so the lift's link (screw_horizontal) is shareable and an unchanged one is taken over by a variant."""
    import pickle

    import numpy as np

    from mechverify.components.sections import circle
    from mechverify.design.reuse import shareable

    sec = circle("7.5 mm")
    assert dict(sec.dimensions) == {"diameter": sec.dimensions["diameter"]} and sec.dimensions == dict(sec.dimensions)
    with pytest.raises(TypeError):
        sec.dimensions["diameter"] = 1  # type: ignore[index]
    assert all(not r.flags.writeable for r in sec.outline)
    back = pickle.loads(pickle.dumps(sec))
    assert back == sec and repr(back) == repr(sec) and np.array_equal(back.outline[0], sec.outline[0])
    assert shareable(sec)
    _ = sec.geometry  # a cached shapely polygon (immutable) keeps it shareable
    assert shareable(circle("7.5 mm")) and shareable(base["screw_horizontal"])
    v = base.with_overrides({"components.lift.mass": "15.0 kg"})
    assert v["screw_horizontal"] is base["screw_horizontal"]


@pytest.fixture()
def self_locking(base):
    """The registry's self_locking spec (a frozen CheckSpec), its ``run`` restored after the test."""
    spec = next(s for s, _ in base.enabled_checks(base.data.components["lift_screw"]) if s.name == "self_locking")
    run = spec.run
    yield spec, run
    object.__setattr__(spec, "run", run)


def _count_runs(spec, run):
    calls = []

    def counted(c, loads, ctx):
        calls.append(ctx.component)
        return run(c, loads, ctx)

    object.__setattr__(spec, "run", counted)
    return calls


def test_a_check_without_loads_on_a_taken_over_object_is_not_run_again(base, self_locking):
    """lift_screw.self_locking (needs=()) on the base's screw object: a variant that changes the screw's loads
    (lifted_load) runs the loaded checks again but takes self_locking's output; the variant's results equal a fresh
    build's field by field (oracle) and in the JSON. A changed screw, a changed design-wide value (requirements) or
    a changed safety factor runs it again."""
    d = base.with_overrides({})
    d.verify()
    calls = _count_runs(*self_locking)
    v = d.with_overrides({"parameters.lifted_load": "300 N"})
    assert v["lift_screw"] is d["lift_screw"] and "lift_screw" not in v._reusable()
    rs = v.verify()
    assert calls == []
    fresh = _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides).verify()
    assert len(calls) == 1  # (the fresh build has no base: it runs)
    assert _rows(rs) == _rows(fresh) and rs.to_json() == fresh.to_json()
    vv = v.with_overrides({"parameters.lifted_load": "320 N"})  # a variant of a variant: still taken over
    vv.verify()
    assert len(calls) == 1
    for change in ({"components.lift_screw.nut_length": "12 mm"}, {"requirements.bearing_life": "20000 h"}):
        calls.clear()
        w = d.with_overrides(change)
        rs = w.verify()
        assert calls == ["lift_screw"], change
        assert _rows(rs) == _rows(_rebuild(copy.deepcopy(w.data.raw), w.data.path, [], w.overrides).verify())


def test_a_check_without_loads_that_reads_the_design_runs_again(base, self_locking):
    """A load-free check whose adapter reads ``ctx.design`` (the rest of the design file, as plate_fea's buckling
    reads the load cases) is never taken over: the context notes the read."""
    from mechverify.design.design import _Watched

    spec, run = self_locking
    calls = []

    def reads_design(c, loads, ctx):
        calls.append(len(ctx.design.data.load_cases))
        return run(c, loads, ctx)

    object.__setattr__(spec, "run", reads_design)
    d = load(LIFT)
    d.verify()
    assert len(calls) == 1
    d.with_overrides({"parameters.lifted_load": "300 N"}).verify()
    assert len(calls) == 2
    ctx = _Watched("c", "", 1.0, {}, None)
    assert "read_design" not in ctx.__dict__ and ctx.required_sf == 1.0 and "read_design" not in ctx.__dict__
    assert ctx.design is None and ctx.__dict__["read_design"]


def test_the_variant_copy_of_the_toml_data_equals_deepcopy():
    """Design.with_overrides copies the TOML data with design._copy_doc: equal to copy.deepcopy (tables and arrays
    new objects, a table reached twice copied once, other objects deep-copied) and independent of the original."""
    import datetime

    from mechverify.design.design import _copy_doc

    shared = {"x": "1 mm"}
    doc = {"a": [1, 2.5, True, None, {"b": "s"}], "t": shared, "u": shared, "d": datetime.date(2026, 1, 2),
           "n": {"m": [[1], [2]]}}
    out = _copy_doc(doc, {})
    assert out == copy.deepcopy(doc) == doc
    assert out["t"] is out["u"] and out["t"] is not shared and out["a"][4] is not doc["a"][4]
    out["n"]["m"][0].append(3)
    assert doc["n"]["m"][0] == [1]


_EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*/design.toml"))


def _single_value_overrides(d, limit: int = 12) -> list[dict]:
    """One override per scalar value of the design file (components, profiles, parameters, load cases), the value
    changed (a quantity scaled by 1.1, a number by 1.1, a bool flipped): each variant changes one input."""
    from mechverify.units import Q

    out = []

    def walk(v, path):
        if isinstance(v, dict):
            for k, x in v.items():
                walk(x, f"{path}.{k}" if path else k)
        elif isinstance(v, bool):
            out.append({path: not v})
        elif isinstance(v, int | float):
            out.append({path: v * 1.1 if isinstance(v, float) else v + 1})
        elif isinstance(v, str):
            try:
                q = Q(v)
            except Exception:  # (a name, an expression, free text: left as written)
                return
            if hasattr(q, "units") and not isinstance(q.magnitude, str):
                out.append({path: f"{float(q.magnitude) * 1.1!r} {q.units}"})

    for section in ("parameters", "components", "profiles", "load_cases"):
        walk(d.data.raw.get(section, {}), section)
    return out[:limit]


@pytest.mark.parametrize("example", _EXAMPLES, ids=lambda p: p.parent.name)
def test_reusable_equals_the_full_fingerprint_comparison(example):
    """reuse.reusable (part by part, early exit) decides exactly as comparing the full fingerprints (reuse.fingerprints)
    does, for a variant per scalar value of each example file (those that build and verify)."""
    from mechverify.design.reuse import fingerprints, reusable
    from mechverify.errors import MechverifyError

    if "solid" in example.parent.name:
        pytest.skip("FE models: slow; the rule is the same")
    d = load(example)
    theirs = fingerprints(d.data)
    checked = 0
    for ov in _single_value_overrides(d):
        try:
            v = d.with_overrides(ov)
        except MechverifyError:
            continue
        mine = fingerprints(v.data)
        expected = {k for k in v.data.components if k in theirs and mine[k] == theirs[k]}
        assert reusable(v.data, theirs) == expected, ov
        checked += 1
    assert checked >= 1  # (a value the design constrains elsewhere - a link length the arm fixes - makes no variant)


def test_touched_tables_by_hand():
    """The tables an override's key path changes (reuse.touched_tables): hand-listed."""
    from mechverify.design.reuse import touched_tables

    assert touched_tables(["components.lift.mass", "parameters.g", "profiles.raise.acceleration",
                           "load_cases.raise.lift_screw.axial_force", "components.d.transmission[0].diameter"]) == {
        "components.lift", "profiles.raise", "load_cases.raise.lift_screw", "components.d"}
    for anything in ("templates.t.mass", "load_cases.raise", "requirements.g", "materials.m.E", "components",
                     "parameters", "design.name"):
        assert touched_tables([anything]) is None, anything
    assert touched_tables([]) == frozenset()


@pytest.mark.parametrize("example", [p for p in _EXAMPLES if p.parent.name in ("lead_screw_lift", "lever_arm",
                                                                                "five_bar")],
                         ids=lambda p: p.parent.name)
def test_variants_and_variants_of_variants_equal_fresh_builds(example):
    """Tables no override touched take the base's reduction of their text (reuse.unchanged_table_key) and their
    built objects' keys (reused_object): every one-value variant, and a variant of each variant, equals the same
    design built from scratch (validated values, JSON of the results)."""
    from mechverify.errors import MechverifyError

    d = load(example)
    d.verify()
    ovs = _single_value_overrides(d, limit=10)
    checked = 0
    for i, ov in enumerate(ovs):
        try:
            v = d.with_overrides(ov)
        except MechverifyError:  # (a value the design constrains elsewhere: a link length the arm fixes)
            continue
        variants = [v]
        for other in (ovs[(i + 1) % len(ovs)], ov):
            try:
                variants.append(v.with_overrides(other))
            except MechverifyError:
                pass
        for variant in variants:
            fresh = _rebuild(copy.deepcopy(variant.data.raw), variant.data.path, list(variant.data.files),
                             variant.overrides)
            for name, e in variant.data.components.items():
                assert repr(e.params) == repr(fresh.data.components[name].params), (ov, name)
            assert variant.verify().to_json() == fresh.verify().to_json(), ov
        checked += 1
    assert checked >= 1


def test_only_the_changed_fields_of_a_table_are_read_again(monkeypatch):
    """A table whose text changed in one field (the drive's mass) re-reads that field only; its other fields take the
    base's values (reuse.field_reuse). A parameter change re-reads exactly the fields whose text names it (the
    carriage's load_offset and available_force read lifted_load). The trace (derived inputs, in order) and the
    results equal a fresh build's."""
    from mechverify.design import loader

    base = load(LIFT)
    base.verify()
    read: list[str] = []
    real = loader.validate_value
    monkeypatch.setattr(loader, "validate_value", lambda f, v, path, col, ctx: read.append(path) or real(
        f, v, path, col, ctx))
    v = base.with_overrides({"components.lift.mass": "16 kg"})
    assert [p for p in read if p.startswith("components.lift.")] == ["components.lift.mass"]
    read.clear()
    w = base.with_overrides({"parameters.lifted_load": "330 N"})
    assert sorted(p for p in read if p.startswith("components.carriage.")) == [
        "components.carriage.available_force", "components.carriage.load_offset"]
    monkeypatch.setattr(loader, "validate_value", real)
    for variant in (v, w):
        fresh = _rebuild(copy.deepcopy(variant.data.raw), variant.data.path, list(variant.data.files),
                         variant.overrides)
        assert list(variant.data.trace.entries) == list(fresh.data.trace.entries)
        assert repr(variant.data.trace.entries) == repr(fresh.data.trace.entries)
        assert variant.verify().to_json() == fresh.verify().to_json()


def test_a_variant_of_values_takes_the_check_plan(monkeypatch):
    """A variant that changes values only (no check setting, type, template or new key) takes its base's check plan
    (enabled checks, each check's load cases, mapped onto its own entries and loads); any other override plans again,
    and a plan that became invalid is still refused."""
    from mechverify.design.design import Design, DesignFileError, _value_change

    base = load(LIFT)
    base.verify()
    planned = []
    real = Design._check_plan
    monkeypatch.setattr(Design, "_check_plan", lambda self: planned.append(1) or real(self))
    v = base.with_overrides({"components.lift.mass": "16 kg", "parameters.lifted_load": "330 N"})
    assert planned == []
    assert v._cases_for(v.data.components["lift_screw"], v.data.components["lift_screw"].type.checks[0]) == \
        _rebuild(copy.deepcopy(v.data.raw), v.data.path, [], v.overrides)._cases_for(
            v.data.components["lift_screw"], v.data.components["lift_screw"].type.checks[0])
    planned.clear()
    base.with_overrides({"components.lift_screw.checks.holding_torque": False})
    base.with_overrides({"load_cases.raise.lift_screw.compressive": True})  # (a new key)
    assert len(planned) == 2
    assert not _value_change(base.data.raw, "components.lift.type", "drive")
    assert not _value_change(base.data.raw, "load_cases.raise.lift_screw", {"axial_force": "1 N"})
    assert _value_change(base.data.raw, "components.lift.transmission[0].screw", "lift_screw")
    with pytest.raises(DesignFileError, match="needs"):  # the bearing's load case replaced by one without loads
        base.with_overrides({"load_cases.raise.screw_bearing": {}})
