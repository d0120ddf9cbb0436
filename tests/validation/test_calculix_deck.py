"""The CalculiX deck says what the model says, and the cross-check fails loudly when ccx ran another model.

Source: G. Dhondt, CalculiX CrunchiX User's Manual 2.20, sec. 7 (free-format input: numbers are read
from fields of at most 20 characters). The three numbers below are the cases measured with ccx 2.20
in issue 26 (written with ``"%.17g"``): a coordinate of a plain ``mesh.box`` with origin -0.1 m,
-1.3877787807814457e-17 (23 characters: ccx stopped); 7.5e-14 m (``"%.17g"`` gives 22 characters);
a nodal load of -1.23456789012345e-05 N (21 characters: its exponent's last digit was cut off and the
load applied 1e5 times too large, silently). Expected values here are the model's own numbers: the
deck, read back field by field as ccx reads it, must reproduce them to 5e-14 relative.
"""

import shutil

import numpy as np
import pytest

from mechverify.errors import ModelError
from mechverify.fea import calculix, mesh, solid
from mechverify.fea.loads import Fixed, Force
from mechverify.fea.regions import Plane

needs_ccx = [pytest.mark.ccx, pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) not installed")]

CASES = [-1.3877787807814457e-17, 7.5e-14, -1.23456789012345e-05]


@pytest.mark.parametrize("value", CASES)
def test_every_number_fits_its_field_and_reads_back(value):
    text = calculix.fortran_field(value)
    assert len(text) <= calculix.FIELD_WIDTH
    assert calculix._ccx_float(text) == pytest.approx(value, rel=5e-14, abs=0)
    # the old "%.17g" text is what ccx misread: the 21-character load loses its exponent's last digit
    if len(f"{value:.17g}") == 21:
        assert calculix._ccx_float(f"{value:.17g}") == pytest.approx(value * 1e5, rel=1e-12)


def test_field_extremes():
    for v in (-1.2345678901234567e-300, 1.2345678901234567e300, -5e-324, 0.1 + 0.2, -0.0, 123456789.0):
        text = calculix.fortran_field(v)
        assert len(text) <= 20
        assert calculix._ccx_float(text) == pytest.approx(v, rel=5e-13, abs=1e-320)


def tiny_model(x0=-0.1):
    """A 0.3 x 0.02 x 0.02 m steel bar from x0 (x0 = -0.1 m: np.linspace(-0.1, 0.2, 4) holds
    -1.3877787807814457e-17 where 0 is meant), clamped at x0, -1.23456789012345e-05 N at the far end."""
    m = mesh.box(("0.3 m", "0.02 m", "0.02 m"), (3, 1, 1), origin=(f"{x0} m", "0 m", "0 m"))
    return solid.SolidModel(m, "Structural Steel", supports=(Fixed(Plane(x=f"{x0} m")),),
                            loads=(Force(Plane(x=f"{x0 + 0.3} m"), ("0 N", "0 N", "-1.23456789012345e-05 N")),))


def test_deck_read_back_is_the_model(tmp_path):
    model = tiny_model()
    pts = model.mesh.points.T
    assert np.any(pts == -1.3877787807814457e-17)  # the coordinate of the issue is in this mesh
    loads = model.load_vector()
    loads[loads != 0] = -1.23456789012345e-05  # the load of the issue at every loaded DOF
    pts = pts.copy()
    pts[-1, 2] = 7.5e-14
    calculix.write_inp(tmp_path / "job.inp", pts, model.mesh.basis.element_dofs.T, 2e11, 0.3, model.held_dofs(), loads)
    deck = calculix.read_inp(tmp_path / "job.inp")
    assert max(len(f.strip()) for line in (tmp_path / "job.inp").read_text().splitlines()
               if line[:1].isdigit() for f in line.split(",")) <= 20
    assert np.array_equal(deck.elements, model.mesh.basis.element_dofs.T)
    assert np.array_equal(deck.fixed_dofs, np.sort(model.held_dofs()))
    assert np.allclose(deck.nodes, pts, rtol=5e-14, atol=0)
    assert np.allclose(deck.loads, loads, rtol=5e-14, atol=0)




@pytest.fixture
def ccx_dir(tmp_path):
    if shutil.which("ccx") is None:
        pytest.skip("CalculiX (ccx) not installed")
    return tmp_path


@pytest.mark.ccx
def test_ccx_runs_the_model_it_is_given(ccx_dir):
    """The mesh with the -1.39e-17 coordinate and the 21-character load: ccx ran it (the old writer
    stopped ccx or applied 1e5 x the load); support reaction = -applied load, read from ccx's .dat."""
    model = tiny_model()
    res = model.solve()
    out = calculix.run_model(model, keep=ccx_dir)
    assert out.support_force[2] == pytest.approx(1.23456789012345e-05, rel=1e-5)
    assert np.abs(out.displacement - res.u).max() <= 1e-5 * np.abs(res.u).max()


def _doctor(work, pick, text):
    """Replace the last field of the first deck line ``pick`` selects by ``text``."""
    lines = (work / "job.inp").read_text().splitlines()
    i = next(k for k, line in enumerate(lines) if pick(k, line, lines))
    lines[i] = ", ".join(lines[i].split(", ")[:-1] + [text])
    (work / "job.inp").write_text("\n".join(lines) + "\n")


@pytest.mark.ccx
def test_cross_check_fails_loudly_on_a_misread_load(ccx_dir):
    model = tiny_model(0.0)
    model = solid.SolidModel(model.mesh, "Structural Steel", supports=(Fixed(Plane(x="0 m")),),
                             loads=(Force(Plane(x="0.3 m"), ("0 N", "0 N", "-1 N")),))
    b = model.mesh.basis
    args = (b.doflocs.T, b.element_dofs.T, 2e11, 0.3, model.held_dofs(), model.load_vector())
    calculix.write_inp(ccx_dir / "job.inp", *args)
    # a 21-character load as "%.17g" wrote it: ccx reads -1.23456789012345 (exponent cut off)
    first_cload = None

    def pick(k, line, lines):
        nonlocal first_cload
        if line == "*CLOAD":
            first_cload = k
        return first_cload is not None and k == first_cload + 1

    _doctor(ccx_dir, pick, "-1.23456789012345e-05")
    with pytest.raises(ModelError, match="different model: its supports carry"):
        calculix.run_deck(ccx_dir, args[0].shape[0], args[1].shape[0], check=(args[0], args[4], args[5], 3))


@pytest.mark.ccx
def test_cross_check_fails_loudly_on_a_misread_coordinate(ccx_dir):
    model = tiny_model(0.0)
    b = model.mesh.basis
    pts = b.doflocs.T.copy()
    args = (pts, b.element_dofs.T, 2e11, 0.3, model.held_dofs(), model.load_vector())
    calculix.write_inp(ccx_dir / "job.inp", *args)
    # every z > 0 written in 21 characters ("%.15e"): ccx drops the exponent's last digit, so
    # 2.000000000000000e-02 m is read as 2.0 m - a bar 100 x as deep, with positive Jacobians: no ccx error
    lines = (ccx_dir / "job.inp").read_text().splitlines()
    start = lines.index("*NODE, NSET=NALL") + 1
    for k in range(start, start + pts.shape[0]):
        f = lines[k].split(", ")
        if float(f[3]) > 0:
            lines[k] = ", ".join(f[:3] + [f"{float(f[3]):.15e}"])
    (ccx_dir / "job.inp").write_text("\n".join(lines) + "\n")
    with pytest.raises(ModelError, match="different model: node [0-9]+ is at"):
        calculix.run_deck(ccx_dir, pts.shape[0], args[1].shape[0], check=(pts, args[4], args[5], 3))
