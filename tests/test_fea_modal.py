"""Modal and buckling analyses: behaviour and bad input (mechverify.fea.modal, mechverify.fea.buckling).

Numbers against published values are in tests/validation/test_blevins_cantilever_modes.py,
test_timoshenko_gere_euler_column.py and test_calculix_modal.py; here: rigid-body modes of a free body,
mass bookkeeping and the named errors.
"""

from __future__ import annotations

import numpy as np
import pytest

from mechverify.errors import InputError, ModelError
from mechverify.fea import buckling, mesh, modal, solid
from mechverify.fea.loads import Fixed, Force, Restraint
from mechverify.fea.regions import Plane
from mechverify.materials.material import Material
from mechverify.units import Q


def _bar(div=(10, 1, 1), **kw):
    return solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), div), "Structural Steel", **kw)


def test_free_block_has_six_rigid_body_modes():
    """A free solid has six rigid-body motions (3 translations, 3 rotations): six zero eigenvalues, then
    the first elastic mode (a property of K's null space, Zienkiewicz-Taylor-Zhu 7th ed. sec. 16.2)."""
    res = modal.modal(solid.SolidModel(mesh.box(("100 mm", "10 mm", "10 mm"), (10, 1, 1)), "Structural Steel"),
                      n_modes=8)
    assert res.rigid_body_modes == 6
    f = res.frequencies.m
    assert np.all(f[:6] < 1e-5 * f[6])
    assert f[6] > 1000  # free-free bending of a 100 mm steel bar: kHz
    assert res.first_frequency.m == pytest.approx(f[6])


def test_mass_matrix_total_mass_and_effective_mass():
    """The consistent mass matrix carries the body's mass ρV along each axis (r·M·r), and the effective
    masses of all modes of a tiny model add up to it (Chopra, Dynamics of Structures, sec. 13.2)."""
    model = _bar((2, 1, 1), supports=(Fixed(Plane(x="0 mm")),))
    M = modal.mass_matrix(model)
    r = np.zeros(M.shape[0])
    r[0::3] = 1.0
    assert r @ (M @ r) == pytest.approx(7850 * 0.2 * 0.01 * 0.01, rel=1e-12)
    n_free = modal.free_dofs(model).size
    res = modal.modal(model, n_modes=n_free - 1)
    frac = res.effective_mass_fraction().sum(axis=0)
    assert np.all(frac > 0.95) and np.all(frac <= 1 + 1e-9)


def test_mode_request_larger_than_model_is_named():
    model = _bar((1, 1, 1), supports=(Fixed(Plane(x="0 mm")),))
    n = modal.free_dofs(model).size
    with pytest.raises(InputError, match=f"only {n} free degrees of freedom"):
        modal.modal(model, n_modes=n)
    with pytest.raises(InputError, match="at least one mode"):
        modal.modal(model, n_modes=0)


def test_partly_supported_model_names_the_free_motion():
    model = _bar(supports=(Restraint(Plane(x="0 mm"), x=True),))
    with pytest.raises(ModelError, match="translation along"):
        modal.modal(model, 3)


def test_material_without_density_is_named():
    mat = Material(name="no density", category="steel", E=Q(200, "GPa"), nu=Q(0.3, ""))
    model = solid.SolidModel(mesh.box(("200 mm", "10 mm", "10 mm"), (4, 1, 1)), mat,
                             supports=(Fixed(Plane(x="0 mm")),))
    with pytest.raises(InputError, match="density"):
        modal.modal(model, 2)


def test_shift_finds_modes_near_a_frequency_and_vtu(tmp_path):
    model = _bar(supports=(Fixed(Plane(x="0 mm")),))
    low = modal.modal(model, 6).frequencies.m
    near = modal.modal(model, 2, shift="1200 Hz").frequencies.m
    assert near == pytest.approx(low[2:4], rel=1e-8)  # the pair of second bending modes (~1283 Hz)
    path = modal.modal(model, 2).to_vtu(tmp_path / "modes.vtu")
    text = path.read_text(errors="replace") if path.stat().st_size < 5_000_000 else ""
    assert "mode_1_" in text and "mode_2_" in text


def test_buckling_bad_input():
    with pytest.raises(InputError, match="needs loads"):
        buckling.buckling(_bar(supports=(Fixed(Plane(x="0 mm")),)), 1)
    with pytest.raises(InputError, match="n_modes"):
        buckling.buckling(_bar((1, 1, 1), supports=(Fixed(Plane(x="0 mm")),),
                               loads=(Force(Plane(x="200 mm"), ("-1 kN", "0 N", "0 N")),)), 500)


def test_tension_does_not_buckle_like_compression():
    """Pulled, the bar buckles only through the local lateral compression at the clamp (Poisson contraction
    held by the fixed face): a factor far above the Euler factor of the same load pushing (10.4)."""
    tension = _bar(supports=(Fixed(Plane(x="0 mm")),), loads=(Force(Plane(x="200 mm"), ("1 kN", "0 N", "0 N")),))
    try:
        mu = buckling.buckling(tension, 1).first_factor
    except ModelError as exc:
        assert "no buckling" in str(exc)
    else:
        assert mu > 100 * 10.4
