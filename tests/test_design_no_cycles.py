"""A study sample leaves no reference cycles behind (issue 19: samples per second).

A cycle through a variant design (a drive's memo holding its design, a recursive closure holding the parse context)
made every Monte Carlo sample of the lead-screw lift ~1 000 objects of cyclic garbage, freed only by the garbage
collector, whose collections then cost 0.6-0.8 ms of a ~4 ms sample (measured with ``gc.callbacks``, task 19e).
Reference counting frees an acyclic sample at once. Oracle: ``gc.collect()`` finds nothing unreachable.
"""

from __future__ import annotations

import gc
from pathlib import Path

from mechverify.design import load
from mechverify.studies import execution

LIFT = Path(__file__).resolve().parents[1] / "examples" / "lead_screw_lift" / "design.toml"


def _garbage_of(run) -> int:
    gc.collect()
    was = gc.isenabled()
    gc.disable()
    try:
        run()
        return gc.collect()
    finally:
        if was:
            gc.enable()


def test_variant_and_verify_leave_no_cycles() -> None:
    """with_overrides + verify (what a study worker does per sample), and a fresh parse + verify, free every object
    by reference counting."""
    d = load(LIFT)
    d.verify()
    ovs = {"components.lift.mass": "14.5 kg", "parameters.lifted_load": "340 N",
           "profiles.raise.acceleration": "0.15 m/s^2"}
    d.with_overrides(ovs).verify()  # (warm: caches filled once are not garbage)
    assert _garbage_of(lambda: [d.with_overrides(ovs).verify() for _ in range(3)]) == 0
    assert _garbage_of(lambda: load(LIFT).verify()) == 0


def test_study_batch_leaves_no_cycles() -> None:
    """A worker's batch (evaluate on the base design) leaves no cyclic garbage."""
    d = load(LIFT)
    doc, path = d.data.raw, str(LIFT)
    ovs = [{"parameters.lifted_load": f"{f} N", "components.lift.mass": "15 kg"} for f in (320, 350, 380)]
    execution.run_batch(doc, path, ovs)  # (warm: the per-process base design is built once)
    assert _garbage_of(lambda: execution.run_batch(doc, path, ovs)) == 0
