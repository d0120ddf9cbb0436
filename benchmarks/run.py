"""Run every benchmark (``make bench``). Each writes its results under ``benchmarks/results/``."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import design_parameters
import fea_vs_calculix
import report_generation
import startup
import studies
import verification


def main() -> None:
    fea_vs_calculix.main([])
    report_generation.main([])
    startup.main([])
    design_parameters.main([])
    studies.main([])
    verification.main([])


if __name__ == "__main__":
    main()
