"""Shared fixtures.

``rod_type`` registers a minimal design-file component type (a rod in tension: sigma = F/A against
yield, Shigley 10th ed., Eq. 3-22) so the design-file and report machinery can be tested
independently of the real component adapters.
"""

import os

# One BLAS thread for the test run: the problems here are small, and on a 2-core machine shared with other
# processes OpenBLAS's busy-waiting threads made a 540-unknown dense eigenproblem 13 times slower (0.23 s ->
# 3.1 s) and a shaft's modal check 20 times slower. Set before numpy is imported; threadpoolctl (test extras)
# also limits a BLAS that a plugin loaded earlier.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
try:
    from threadpoolctl import threadpool_limits

    threadpool_limits(1)
except ImportError:  # pragma: no cover - the env vars above still apply
    pass

import pytest  # noqa: E402

from mechverify import Q  # noqa: E402
from mechverify.checks import CheckResult  # noqa: E402
from mechverify.design import REGISTRY, CheckSpec, ComponentType, Field  # noqa: E402
from mechverify.units import to_si  # noqa: E402


def _stress(rod, loads, ctx):
    sigma = Q(to_si(loads["force"], "force") / to_si(rod["area"], "area"), "Pa").to("MPa")
    return CheckResult("stress", "", sigma, rod["material"].yield_strength, title="Axial stress",
                       formula=r"\sigma = F/A", source="Shigley 10th ed., Eq. 3-22")


ROD = ComponentType(
    "test_rod", "a straight rod in tension",
    fields=(Field("length", "length", required=True), Field("area", "area", required=True),
            Field("material", "material", required=True), Field("finish", "choice", choices=("ground", "machined"))),
    build=lambda p, ctx: p,
    loads=(Field("force", "force", required=True),),
    checks=(CheckSpec("stress", _stress, "Axial stress", needs=("force",)),),
)


@pytest.fixture
def rod_type():
    REGISTRY.types["test_rod"] = ROD
    yield
    REGISTRY.types.pop("test_rod", None)


#: a one-rod design of the ``test_rod`` type (fixture ``rod_type``), formatted with ``rev`` and ``area`` [mm²]
ROD_DESIGN = """
[design]
name = "rig"
revision = "{rev}"

[components.rod]
type = "test_rod"
length = "350 mm"
area = "{area} mm^2"
material = "Structural Steel"

[load_cases.hold.rod]
force = "2 kN"
"""


#: The linkage of the tests' `five_bar` designs: equal 100 mm links, one definition for every test module.
FIVE_BAR_LINKS = """type = "five_bar"
base = "100 mm"
proximal_left = "100 mm"
distal_left = "100 mm"
distal_right = "100 mm"
proximal_right = "100 mm"
"""
