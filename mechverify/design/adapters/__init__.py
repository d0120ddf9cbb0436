"""Component types a design file can declare, each adapting a component class and its checks.

Each adapter module declares its fields (what the TOML table holds), the loads it reads from load
cases, how to build the component, and the checks it runs (functions of :mod:`mechverify.checks`).
Importing this package registers them all in :data:`mechverify.design.spec.REGISTRY`.
"""

from mechverify.design.adapters import bearings, bolts, drives, frame, members, plate_fea, screws, springs  # noqa: F401
