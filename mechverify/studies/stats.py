"""Statistics of a study: failure probability with its Wilson score interval, rank correlation.

References
----------
1. E. B. Wilson, "Probable inference, the law of succession, and statistical inference",
   J. Am. Stat. Assoc. 22 (1927) 209-212.
2. R. G. Newcombe, "Two-sided confidence intervals for the single proportion: comparison of seven
   methods", Statistics in Medicine 17 (1998) 857-872 (method 3: the score interval).
3. C. Spearman, "The proof and measurement of association between two things", Am. J. Psychol. 15
   (1904) 72-101 (rank correlation; computed with :func:`scipy.stats.spearmanr`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from mechverify.errors import InputError

Z95 = 1.959963984540054  # standard normal quantile at 0.975


def wilson_interval(k: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval of a proportion k/n [1, 2]:

    ``(p + z²/2n ± z·sqrt(p(1-p)/n + z²/4n²)) / (1 + z²/n)``, p = k/n; the bounds are the two
    proportions at which the score statistic |p − π|/sqrt(π(1-π)/n) equals z. Defined for n ≥ 1,
    0 ≤ k ≤ n; stays within [0, 1] (0 and 1 exactly at k = 0 and k = n).
    """
    if not isinstance(n, int | np.integer) or n < 1:
        raise InputError(f"wilson_interval: n must be a positive integer, got {n!r}")
    if not 0 <= k <= n:
        raise InputError(f"wilson_interval: k must lie in 0..n, got k={k!r}, n={n!r}")
    p = k / n
    den = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / den
    half = z / den * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    lo, hi = centre - half, centre + half
    return (0.0 if k == 0 else max(0.0, lo), 1.0 if k == n else min(1.0, hi))


def spearman(x: Sequence[float], y: Sequence[float]) -> float | None:
    """Spearman rank correlation of x and y [3]; None when either is constant (to 1e-9 relative: values that
    differ by rounding only would rank by their rounding noise) or fewer than 3 pairs."""
    from scipy import stats

    xa, ya = np.asarray(x, float), np.asarray(y, float)
    ok = np.isfinite(xa) & np.isfinite(ya)
    xa, ya = xa[ok], ya[ok]

    def constant(v: np.ndarray) -> bool:
        return bool(np.ptp(v) <= 1e-9 * max(float(np.max(np.abs(v))), 1e-300))

    if len(xa) < 3 or constant(xa) or constant(ya):
        return None
    rho = float(stats.spearmanr(xa, ya).statistic)
    return None if math.isnan(rho) else rho
