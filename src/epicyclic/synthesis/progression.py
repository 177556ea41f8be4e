"""Ratio series of a transmission: forward ratios from spread, gear count and progression.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W. (2011). *Automotive Transmissions*, 2nd ed., Springer,
section 6.3, eq. 6.9 (progressive gear steps).
"""

from __future__ import annotations

import math

__all__ = ["progression_range", "progressive_ratios"]


def progressive_ratios(spread: float, gears: int, first: float, progression: float = 1.0) -> tuple[float, ...]:
    """Forward ratios from spread, number of gears, first ratio and the progression factor φ2.

    Steps φ_k = i_k / i_(k+1) = φ1 · φ2^(z − 1 − k) (k = 1 … z − 1); φ2 = 1 gives a
    geometric series, φ2 > 1 larger steps in the low gears (Naunheimer et al. 2011, eq. 6.9).

    >>> [round(r, 4) for r in progressive_ratios(4.0, 3, 4.0)]
    [4.0, 2.0, 1.0]
    """
    z = gears
    # product of steps = spread: φ1^(z-1) · φ2^((z-1)(z-2)/2) = spread; in logarithms, so that no power
    # overflows or vanishes (φ2^3081 for 80 gears)
    log_phi2 = math.log(progression)
    log_phi1 = (math.log(spread) - log_phi2 * (z - 1) * (z - 2) / 2) / (z - 1)
    out, log_ratio = [first], math.log(first)
    for k in range(1, z):
        log_ratio -= log_phi1 + log_phi2 * (z - 1 - k)
        out.append(math.exp(log_ratio))
    return tuple(out)


def progression_range(spread: float, gears: int) -> tuple[float, float]:
    """Open range of the progression φ2 whose every step φ_k exceeds 1 (falling ratios).

    The smallest step is φ1 (φ2 ≥ 1) or φ1·φ2^(z−2) (φ2 < 1); both exceed 1 exactly when
    |ln φ2| < 2 ln(spread) / ((z − 1)(z − 2)) (from eq. 6.9 of Naunheimer et al. 2011).
    Two gears have a single step (the spread): any progression.

    >>> [round(v, 4) for v in progression_range(4.0, 3)]
    [0.25, 4.0]
    """
    if gears <= 2:
        return 0.0, math.inf
    limit = 2 * math.log(spread) / ((gears - 1) * (gears - 2))
    return math.exp(-limit), math.exp(limit)
