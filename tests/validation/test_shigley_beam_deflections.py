"""Beam cases of Shigley 10th ed. Table A-9 against an independent solution of the beam equation.

Source: Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed., Table A-9 (cases 1, 3,
4, 5, 7, 11, 13, 14, 16): closed forms such as F l^3/(3EI), 5 w l^4/(384 EI), w l^4/(185 EI).
Independent check: E I y'''' = q(x) solved numerically (scipy.integrate.solve_bvp) with the
case's boundary conditions; a point load enters as a jump of the shear force at mid-span, modelled
by solving the two halves with matching conditions.
"""

import numpy as np
import pytest
from scipy.integrate import solve_bvp

from mechverify import Q
from mechverify.components.links import beam_max_deflection, beam_max_moment

L, EI = 1.0, 1.0


def _solve(bc_left, bc_right, w=0.0, F=0.0, M_end=0.0):
    """Deflection and moment fields of E I y'''' = -w on [0, L] with a point load F at L/2 (two segments)."""
    # state per segment: y, y', y'' (= M/EI), y''' (= V/EI); segment 1 on [0, L/2], segment 2 mapped on s
    def rhs(s, u):
        return np.vstack([u[1], u[2], u[3], -w * np.ones_like(s), u[5], u[6], u[7], -w * np.ones_like(s)])

    def bc(ua, ub):
        left, right = ua[:4], ub[4:]
        jump = [ub[0] - ua[4], ub[1] - ua[5], ub[2] - ua[6], ub[3] - ua[7] + F]
        return np.array([*bc_left(left), *bc_right(right, M_end), *jump])

    s = np.linspace(0, L / 2, 101)
    sol = solve_bvp(lambda x, u: rhs(x, u), bc, s, np.zeros((8, s.size)), tol=1e-10, max_nodes=100000)
    assert sol.success
    ss = np.linspace(0, L / 2, 2001)
    u = sol.sol(ss)
    y = np.concatenate([u[0], u[4]])
    m = np.concatenate([u[2], u[6]])
    return np.abs(y).max(), np.abs(m).max()


fixed = lambda u: [u[0], u[1]]  # noqa: E731
pinned = lambda u: [u[0], u[2]]  # noqa: E731
free_r = lambda u, M: [u[2] - M, u[3]]  # noqa: E731
fixed_r = lambda u, M: [u[0], u[1]]  # noqa: E731
pinned_r = lambda u, M: [u[0], u[2]]  # noqa: E731

CASES = [
    ("cantilever_end_load", dict(bc_left=fixed, bc_right=lambda u, M: [u[2], u[3] + 1.0])),
    ("cantilever_uniform", dict(bc_left=fixed, bc_right=free_r, w=1.0)),
    ("cantilever_end_moment", dict(bc_left=fixed, bc_right=free_r, M_end=1.0)),
    ("simply_supported_center_load", dict(bc_left=pinned, bc_right=pinned_r, F=1.0)),
    ("simply_supported_uniform", dict(bc_left=pinned, bc_right=pinned_r, w=1.0)),
    ("fixed_pinned_center_load", dict(bc_left=fixed, bc_right=pinned_r, F=1.0)),
    ("fixed_pinned_uniform", dict(bc_left=fixed, bc_right=pinned_r, w=1.0)),
    ("fixed_fixed_center_load", dict(bc_left=fixed, bc_right=fixed_r, F=1.0)),
    ("fixed_fixed_uniform", dict(bc_left=fixed, bc_right=fixed_r, w=1.0)),
]
LOAD = {"cantilever_end_load": "1 N", "cantilever_end_moment": "1 N*m"}


@pytest.mark.parametrize(("case", "kw"), CASES, ids=[c for c, _ in CASES])
def test_table_a9_against_beam_equation(case, kw):
    y_num, m_num = _solve(**kw)
    load = LOAD.get(case, "1 N" if "load" in case else "1 N/m")
    y = beam_max_deflection(case, load, f"{L} m", f"{EI} Pa", f"{EI} m**4")
    m = beam_max_moment(case, load, f"{L} m")
    assert y.m_as("m") == pytest.approx(y_num, rel=1e-4)
    assert m.m_as("N*m") == pytest.approx(m_num, rel=1e-4)


def test_shigley_numbers():
    """Table A-9 case 7 written out: 5 w l^4/(384 E I) for w = 2 N/mm, l = 500 mm, E = 207 GPa, I = 1e5 mm^4."""
    y = beam_max_deflection("simply_supported_uniform", "2 N/mm", "500 mm", "207 GPa", Q(1e5, "mm**4"))
    assert y.m_as("mm") == pytest.approx(5 * 2 * 500**4 / (384 * 207e3 * 1e5), rel=1e-12)
