"""mechverify.fea.factor: one factorisation, many right-hand sides; CHOLMOD and SuperLU agree; named errors."""

import numpy as np
import pytest
import scipy.sparse as sp

from mechverify.errors import InputError, ModelError
from mechverify.fea import mesh, modal, solid
from mechverify.fea.factor import cholmod_available, factorize
from mechverify.fea.loads import Fixed
from mechverify.fea.regions import Plane


def stiffness():
    model = solid.SolidModel(mesh.box(("60 mm", "10 mm", "10 mm"), (6, 1, 1)), "Structural Steel",
                             supports=(Fixed(Plane(x="0 mm")),))
    K = modal.stiffness_matrix(model).tocsr()
    free = modal.free_dofs(model)
    return K[free][:, free].tocsc()


@pytest.mark.parametrize("method", ["superlu", "cholmod"])
def test_block_solve_matches_single_solves(method):
    """K X = B for eight columns at once equals eight single solves, to round-off (residual < 1e-10)."""
    if method == "cholmod" and not cholmod_available():
        pytest.skip("scikit-sparse (mechverify[direct]) not installed")
    K = stiffness()
    F = factorize(K, method)
    assert F.method == method
    B = np.random.default_rng(0).standard_normal((K.shape[0], 8))
    X = F.solve(B)
    assert np.linalg.norm(K @ X - B) / np.linalg.norm(B) < 1e-10
    assert X[:, 3] == pytest.approx(F.solve(B[:, 3]), rel=1e-9, abs=1e-18)


def test_cholmod_and_superlu_agree():
    if not cholmod_available():
        pytest.skip("scikit-sparse (mechverify[direct]) not installed")
    K = stiffness()
    b = np.ones(K.shape[0])
    assert factorize(K, "cholmod").solve(b) == pytest.approx(factorize(K, "superlu").solve(b), rel=1e-8)


def test_named_errors():
    A = sp.diags([1.0, -1.0, 2.0]).tocsc()  # indefinite
    with pytest.raises(InputError, match="method"):
        factorize(A, "umfpack")
    if cholmod_available():
        with pytest.raises(ModelError, match="not positive definite"):
            factorize(A, "cholmod", what="the test matrix")
    with pytest.raises(ModelError, match="singular"):
        factorize(sp.csc_matrix((3, 3)), "superlu")
    with pytest.raises(InputError, match="length"):
        factorize(sp.eye(3).tocsc(), "superlu").solve(np.ones(4))
