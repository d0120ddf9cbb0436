"""Studies of a design: sizing (solve for a limit), sweeps and Monte Carlo, locally or on a Dask cluster.

``size(design, vary=..., until=...)`` finds the value at which a check's u·SF reaches 1;
``Study(design, vary=..., samples=..., method=...).run(executor=None)`` evaluates many variants.
Tasks carry the design file's TOML data and key-path overrides (never live objects), so any
:class:`concurrent.futures.Executor` runs them, and the result is the same whatever runs them.
See ``docs/studies.md``.
"""

from mechverify.studies.execution import SchedulerError, SerialExecutor, dask_executor, process_pool
from mechverify.studies.params import Axis, Parameter, apply_overrides, get_path, parse_vary, set_path
from mechverify.studies.sizing import SizingError, SizingResult, size
from mechverify.studies.stats import spearman, wilson_interval
from mechverify.studies.study import Study, StudyResult

__all__ = ["Study", "StudyResult", "size", "SizingResult", "SizingError", "SchedulerError", "SerialExecutor",
           "dask_executor", "process_pool", "Axis", "Parameter", "apply_overrides", "get_path", "set_path",
           "parse_vary", "wilson_interval", "spearman"]
