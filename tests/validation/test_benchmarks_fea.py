"""Published linear-elasticity benchmarks on small meshes (the full sequences are in
``benchmarks/verification.py`` and ``docs/verification.md``).

Sources (reference values; the models are in :mod:`mechverify.fea.verification`):
- [TG] Timoshenko & Goodier, Theory of Elasticity, 3rd ed., sec. 35 (Kirsch): σxx = 3σ at the top
  of a circular hole in an infinite plate; the model carries Kirsch's exact tractions on its outer
  edges, so the closed form is the exact solution of the modelled domain.
- [Shigley] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., eq. (3-50): Lamé,
  σθ(ri) = p (ro² + ri²)/(ro² - ri²) = 83.33 MPa for ri = 20 mm, ro = 40 mm, p = 50 MPa (hand
  calculation from the formula).
- [NAFEMS] The Standard NAFEMS Benchmarks, TNSB Rev. 3 (1990), LE1: σyy at D = 92.7 MPa (printed
  value; quoted identically by the NAFEMS LE1 pages of Altair OptiStruct's verification manual and
  Seamplex's FEA cases, found with the search tool).

The errors asserted are the measured ones of these meshes with a margin (the recovery method is
chosen by them: superconvergent patch recovery is several times closer than extrapolate-and-average
or L2 projection on each benchmark).
"""

import numpy as np
import pytest

pytest.importorskip("gmsh")

from mechverify.errors import InputError
from mechverify.fea import verification as V


@pytest.fixture(scope="module")
def coarse():
    return {"kirsch": V.kirsch(0.01, 0.002), "lame": V.lame(0.004), "le1": V.le1(0.3, 0.1)}


def err(b, res):
    return b.component(res.stress_at([b.point]).m[0]) / b.reference - 1


@pytest.mark.parametrize(("name", "spr_tol", "others_min"), [("kirsch", 0.003, 0.015), ("lame", 0.003, 0.005),
                                                             ("le1", 0.006, 0.015)])
def test_patch_recovery_beats_average_and_projection(coarse, name, spr_tol, others_min):
    """Measured on these meshes: Kirsch +0.07 % (SPR) vs -1.9 % (average) and -2.3 % (projection);
    Lamé -0.11 % vs -0.77 % and -0.88 %; LE1 -0.33 % vs -1.8 % and -2.1 %."""
    b = coarse[name]
    spr = b.model.solve()
    assert spr.recovery == "spr"
    assert abs(err(b, spr)) <= spr_tol
    for method in ("average", "projection"):
        assert abs(err(b, b.model.solve(recovery=method))) >= others_min
    assert spr.warnings == ()


def test_exact_field_everywhere_and_zz_indicator(coarse):
    """Kirsch and Lamé are exact everywhere: over all nodes the recovered field's error (relative to the peak)
    measured 0.36 % rms / 2.9 % max (Kirsch, 8 edges on the quarter hole) and 0.45 % rms / 1.9 % max (Lamé),
    better in rms than average (0.45 / 0.66 %) and projection (0.47 / 0.68 %); the ZZ estimate (relative
    energy-norm error) is small and falls when the mesh is refined."""
    for name in ("kirsch", "lame"):
        b = coarse[name]
        res = b.model.solve()
        ex = b.exact(res.points.T[:2])
        d = np.abs(res.sigma[:, :2, :2] - ex[:, :2, :2]).max(axis=(1, 2))
        assert d.max() <= 0.035 * b.reference and np.sqrt((d**2).mean()) <= 0.005 * b.reference
        assert 0 < res.error_estimate < 0.02
        assert res.element_error.shape == (b.model.mesh.nelements,)
    fine = V.lame(0.002).model.solve()
    assert fine.error_estimate < 0.5 * coarse["lame"].model.solve().error_estimate


def test_integration_point_stress_and_stress_at(coarse):
    b = coarse["lame"]
    res = b.model.solve()
    ip = res.integration_point_stress.m_as("Pa")
    assert ip.shape == (b.model.mesh.nelements, 3, 3, 3) and res.ip_points.shape == (b.model.mesh.nelements, 3, 3)
    exact = b.exact(res.ip_points.reshape(-1, 3).T[:2]).reshape(ip.shape)
    assert np.abs(ip[..., :2, :2] - exact[..., :2, :2]).max() <= 0.05 * b.reference
    # plane strain: σzz = ν(σxx + σyy) at the integration points too
    assert ip[..., 2, 2] == pytest.approx(0.3 * (ip[..., 0, 0] + ip[..., 1, 1]))
    s = res.stress_at([("30 mm", "0 mm"), (0.0, 0.03)]).m_as("Pa")
    want = b.exact(np.array([[0.03, 0.0], [0.0, 0.03]]))
    # 5 elements through the wall: -0.84 % measured at mid-wall on the symmetry line
    assert s[0, 1, 1] == pytest.approx(want[0, 1, 1], rel=0.01) and s[1, 0, 0] == pytest.approx(want[1, 0, 0], rel=0.01)
    with pytest.raises(InputError, match="outside the mesh"):
        res.stress_at([(0.0, 0.0)])


# ------------------------------------------------------------------------------------- curved elements
LAME = dict(ri=0.02, ro=0.04, p=50e6, E=200e9, nu=0.3)


def lame_ur(r):
    """Radial displacement of the Lamé cylinder in plane strain: u = r εθ, εθ = (1+ν)/E ((1-ν)σθ - νσr)
    with [Shigley] eq. (3-50) stresses (hand calculation from the formulas)."""
    ri, ro, p, E, nu = LAME["ri"], LAME["ro"], LAME["p"], LAME["E"], LAME["nu"]
    k = p * ri**2 / (ro**2 - ri**2)
    sr, st = k * (1 - ro**2 / r**2), k * (1 + ro**2 / r**2)
    return r * (1 + nu) / E * ((1 - nu) * st - nu * sr)


@pytest.fixture(scope="module")
def lame_curved():
    from dataclasses import replace

    from mechverify.units import Q

    b = V.lame(0.004, order=2)
    straight = replace(b.model, thickness=Q(1.0, "m"), curved=False)
    return b, b.model, straight


def test_curved_elements_follow_the_bore(lame_curved):
    """Same gmsh second-order mesh (5 elements through the wall), mid-side nodes on the circles or on the
    chords: measured u_r error 0.062 % curved against 0.87 % straight; hoop stress at the bore by
    extrapolate-and-average (CalculiX's method) -0.23 % against -0.77 %."""
    b, curved, straight = lame_curved
    assert curved.is_curved and not straight.is_curved
    errs = {}
    for name, model in (("curved", curved), ("straight", straight)):
        res = model.solve()
        r = np.hypot(res.points[:, 0], res.points[:, 1])
        u_r = (res.u[:, 0] * res.points[:, 0] + res.u[:, 1] * res.points[:, 1]) / r
        errs[name] = np.abs(u_r - lame_ur(r)).max() / lame_ur(LAME["ri"])
        avg = model.solve(recovery="average")
        errs[name + " avg"] = abs(b.component(avg.stress_at([b.point]).m[0]) / b.reference - 1)
    assert errs["curved"] < 0.001 < 0.005 < errs["straight"]
    assert errs["curved avg"] < 0.004 < 0.006 < errs["straight avg"]
    bore = curved.region_reports()[0]
    assert bore.measure == pytest.approx(np.pi * LAME["ri"] / 2, rel=1e-5)  # the arc (1.5e-6), not its chords (1.6e-3)
    assert bore.resultant == pytest.approx((LAME["p"] * LAME["ri"], LAME["p"] * LAME["ri"]), rel=1e-9)


def test_curved_mesh_matches_calculix(lame_curved):
    """CalculiX's CPE6 is isoparametric too: on the same curved nodes the displacements agree (2e-5 measured;
    ccx integrates the expanded wedges with its own rule)."""
    import shutil

    from mechverify.fea import calculix

    if shutil.which("ccx") is None:
        pytest.skip("CalculiX (ccx) not installed")
    _, curved, _ = lame_curved
    res = curved.solve()
    ccx = calculix.run_model(curved)
    assert np.abs(ccx.displacement[:, :2] - res.u[:, :2]).max() <= 1e-4 * np.abs(res.u).max()


def test_inverted_curved_element_is_a_named_error(lame_curved):
    from mechverify.fea import mesh2d
    from mechverify.fea.isoparametric import InvertedElementError
    from mechverify.fea.plane import PlaneModel

    _, curved, _ = lame_curved
    m = curved.mesh
    bad = m.curved.copy()
    e0 = curved.basis.element_dofs[:, 0]
    bad[:, e0[3]] = m.p[:, e0[2]] + 2.0 * (m.p[:, e0[2]] - (m.p[:, e0[0]] + m.p[:, e0[1]]) / 2)  # mid node beyond
    broken = mesh2d.NamedMeshTri(m.p, m.t, sort_t=False, curved=bad)
    with pytest.raises(InvertedElementError, match="inverted"):
        PlaneModel(broken, "1 m", curved.material, supports=curved.supports[:1]).solve()


def test_curved_tetrahedra_on_the_lame_ring():
    """The Lamé cylinder as a quarter ring of quadratic tetrahedra (gmsh second order, 812 nodes), plane
    strain by z-rollers on both ends. Measured on the same mesh: u_r error 0.27 % curved against 1.25 %
    straight; hoop stress at the bore +0.35 % against +2.6 % (the faceted bore concentrates stress);
    CalculiX's C3D10 on the same curved nodes agrees to 1e-4."""
    import shutil
    from dataclasses import replace

    from mechverify.fea import calculix

    model, hoop = V.lame_solid(0.006)
    straight = replace(model, curved=False)
    assert model.is_curved and not straight.is_curved
    out = {}
    for name, mdl in (("curved", model), ("straight", straight)):
        res = mdl.solve()
        r = np.hypot(res.points[:, 0], res.points[:, 1])
        u_r = (res.u[:, 0] * res.points[:, 0] + res.u[:, 1] * res.points[:, 1]) / r
        hoop_fe = res.stress_at([(LAME["ri"], 0.0, 0.005)]).m_as("Pa")[0, 1, 1]  # σyy = σθ on y = 0
        out[name] = (np.abs(u_r - lame_ur(r)).max() / lame_ur(LAME["ri"]), abs(hoop_fe / hoop - 1), res)
    assert out["curved"][0] < 0.004 < 0.01 < out["straight"][0]
    assert out["curved"][1] < 0.01 < out["straight"][1]
    rep = out["curved"][2].regions[0]
    assert rep.measure == pytest.approx(np.pi * LAME["ri"] / 2 * 0.01, rel=1e-4)  # CAD area, not faceted
    if shutil.which("ccx"):
        ccx = calculix.run_model(model)
        u = out["curved"][2].u
        assert np.abs(ccx.displacement - u).max() <= 2e-4 * np.abs(u).max()


def test_inverted_curved_tetrahedron_is_a_named_error():
    from dataclasses import replace

    from mechverify.fea.isoparametric import InvertedElementError

    model, _ = V.lame_solid(0.008)
    m = model.mesh
    bad = m.curved.copy()
    ed = m.basis.element_dofs[:, 0]
    # move the first element's mid-edge node (0,1) far beyond vertex 1: the mapping folds over
    bad[:, ed[4]] = m.mesh.p[:, ed[1]] + 3.0 * (m.mesh.p[:, ed[1]] - m.mesh.p[:, ed[0]])
    with pytest.raises(InvertedElementError, match="inverted"):
        replace(model, mesh=replace(m, curved=bad)).solve()
