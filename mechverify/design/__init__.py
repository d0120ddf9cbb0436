"""Design files: TOML descriptions of a design, validated with key-path errors, verified in one call."""

from mechverify.design.design import CheckContext, Design, load
from mechverify.design.loader import DesignFileError
from mechverify.design.parameters import dependency_graph, parameters_report
from mechverify.design.spec import REGISTRY, CheckSpec, ComponentType, Field, Output

__all__ = ["load", "Design", "DesignFileError", "CheckContext", "ComponentType", "CheckSpec", "Field", "Output",
           "REGISTRY", "parameters_report", "dependency_graph"]
