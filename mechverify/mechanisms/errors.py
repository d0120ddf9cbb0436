"""Errors of the mechanism presets: a pose out of reach, a pose at (or too near) a singularity."""

from __future__ import annotations

from mechverify.errors import ModelError, ValidityError


class UnreachablePoseError(ValidityError):
    """The asked position or joint angles cannot be assembled (a leg or triangle cannot close)."""


class SingularPoseError(ModelError):
    """The pose is at (or within the tolerance of) a type-1 or type-2 singularity."""
