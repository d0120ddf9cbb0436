"""Component types a design file can declare, each adapting a component class and its checks.

Each adapter declares its fields (what the TOML table holds), the loads it reads from load cases,
how to build the component, and the checks it runs (functions of :mod:`mechverify.checks`).
"""

from __future__ import annotations
