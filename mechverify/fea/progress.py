"""Progress of long solves: a rich status line on stderr, shown only for big models."""

from __future__ import annotations

import time
from types import TracebackType


class Steps:
    """Context manager: ``with Steps(enabled) as st: st("assembling")`` updates one status line."""

    def __init__(self, enabled: bool, title: str = "mechverify FEA"):
        self.enabled = enabled
        self.title = title
        self._status = None
        self._t0 = time.perf_counter()

    def __enter__(self) -> Steps:
        if self.enabled:
            from rich.console import Console

            self._status = Console(stderr=True).status(f"{self.title}: starting")
            self._status.__enter__()
        return self

    def __call__(self, message: str) -> None:
        if self._status is not None:
            self._status.update(f"{self.title}: {message} ({time.perf_counter() - self._t0:.1f} s)")

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        if self._status is not None:
            self._status.__exit__(exc_type, exc, tb)
