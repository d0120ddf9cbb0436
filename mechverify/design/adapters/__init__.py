"""Component types a design file can declare, each adapting a component class and its checks.

Each adapter module declares its fields (what the TOML table holds), the loads it reads from load
cases, how to build the component, and the checks it runs (functions of :mod:`mechverify.checks`).
Importing this package registers them all in :data:`mechverify.design.spec.REGISTRY`: every module of
the package is imported (found with :mod:`pkgutil`; a new adapter module needs no entry here), in
name order; ``common`` holds shared helpers and declares no type.
"""

import importlib
import pkgutil

for _m in sorted(m.name for m in pkgutil.iter_modules(__path__)):
    importlib.import_module(f"{__name__}.{_m}")
