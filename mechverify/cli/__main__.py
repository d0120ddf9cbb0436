"""``python -m mechverify.cli``."""

from mechverify.cli import entry

entry()
