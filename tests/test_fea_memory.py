"""What ``SolidModel.solve`` keeps alive while it solves (issue 23: memory per DOF stays <= 5 kB).

Peak memory itself is measured by ``benchmarks/fea_vs_calculix.py`` (a byte count at test size is fragile), so
these tests assert what is alive instead: the element stiffness blocks ``[(a,b), e, 9]`` (100 * 9 floats per
quadratic tetrahedron, 1.4 times the assembled K's data) must be freed as soon as K is assembled, before the
linear solve and the stress recovery. Commit a02e5c2 (curved elements) held them in a local of ``solve``:
the 47k-DOF lug's peak went from 288 MB to 357 MB (4.2 -> 5.7 kB/DOF above the process's start), measured
with ``SolidModel.solve`` in a fresh process, before and after.
"""

from __future__ import annotations

import dataclasses
import weakref

import pytest

from mechverify.fea import assembly, isoparametric, mesh, solid
from mechverify.fea import recovery as rc
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Named, Plane


def _model(curved: bool) -> solid.SolidModel:
    m = mesh.box(("60 mm", "10 mm", "10 mm"), (6, 2, 2))
    if curved:  # the isoparametric path, on straight mid-side nodes given as "curved" ones
        m = dataclasses.replace(m, curved=m.basis.doflocs.copy())
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Named("xmin")),),
                            loads=(Force(Plane(x="60 mm"), ("0 N", "0 N", "-100 N")),))


@pytest.mark.parametrize("curved", [False, True], ids=["straight", "curved"])
def test_element_blocks_are_freed_before_the_solve(monkeypatch, curved):
    refs: list[weakref.ref] = []
    module, name = (isoparametric, "stiffness_blocks") if curved else (assembly, "elasticity_blocks")
    make_blocks = getattr(module, name)

    def watched(*a, **k):
        out = make_blocks(*a, **k)
        refs.append(weakref.ref(out[0] if isinstance(out, tuple) else out))
        return out

    alive: dict[str, bool] = {}

    def during(label, fn):
        def wrapped(*a, **k):
            alive[label] = any(r() is not None for r in refs)
            return fn(*a, **k)
        return wrapped

    monkeypatch.setattr(module, name, watched)
    monkeypatch.setattr(solid, "solve", during("linear solve", solid.solve))
    monkeypatch.setattr(rc, "recover", during("recovery", rc.recover))
    monkeypatch.setattr(rc, "recover_curved", during("recovery", rc.recover_curved))
    model = _model(curved)
    assert model.is_curved is curved
    res = model.solve(method="direct", progress=False)
    assert len(refs) == 1, "the stiffness blocks were not built through the watched function"
    assert set(alive) == {"linear solve", "recovery"}
    assert not any(alive.values()), f"element blocks still alive during: {[k for k, v in alive.items() if v]}"
    assert res.u[:, 2].min() < 0  # the load bends the bar down: the solve ran on the assembled K
