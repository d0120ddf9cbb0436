"""Rule-based checks. Every check returns a :class:`CheckResult`; a design's results form a :class:`ResultSet`."""

from mechverify.checks.result import WARN_LEVEL, CheckResult, ResultSet, Verdict

__all__ = ["CheckResult", "ResultSet", "Verdict", "WARN_LEVEL"]
