"""The one rule for "numerically zero".

Floating-point arithmetic leaves round-off where the exact answer is zero: a
braked shaft at 2e-13 1/min, an idle set with 1e-13 N·m, "−0" at the housing.
The solver decides once, before any result object is built, which values are
zero, and stores those as exactly ``0.0``; reports, JSON files, figures and
labels then never see the noise.

The rule: a computed value ``x`` is numerically zero when

    |x| ≤ ZERO_TOLERANCE · scale,

where ``scale`` is the magnitude of the terms ``x`` was computed from, i.e.
the train's own scale at that place, never an absolute number of units:

* a shaft speed: the magnitudes of the given speeds it is made of (a speed
  that the train holds at zero, by a brake, a clutch to the housing or a stage
  from such a shaft, is exactly zero by construction, not by this test);
* an element's relative speed (rolling, locked): the largest speed at its ports;
* an element's torques (idle): the largest torque acting at its shafts;
* a power, loss or rolling power: the product of a cleaned torque and a cleaned
  speed, so it is zero exactly when one of them is.

Every value also loses its sign when zero (``-0.0`` becomes ``0.0``); an
infinite or NaN value is never zero (the solver reports it as an error).

The tolerance is far above the round-off of the equilibrated solve (a few
units of 1e-16) and far below anything physical: a speed 1e-12 of the speeds
it is made of is 1e-9 1/min at 1000 1/min.

Plotting and report code that derives new numbers from results (differences,
ratios, sums) use :func:`clean` with the scale of the terms they combined.

Examples
--------
>>> clean(2.2e-13, scale=1338.2), clean(-0.0), clean(1e-3, scale=1338.2)
(0.0, 0.0, 0.001)
>>> clean_array([1e-14, -0.0, 2.0], scale=2.0).tolist()
[0.0, 0.0, 2.0]
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

__all__ = ["ZERO_TOLERANCE", "clean", "clean_array", "is_zero", "scale_of"]

#: Relative size below which a computed value is round-off of zero.
ZERO_TOLERANCE = 1e-12


def is_zero(value: float, scale: float = 0.0) -> bool:
    """Whether ``value`` is numerically zero relative to ``scale`` (same unit as ``value``).

    Parameters
    ----------
    value : float
        The computed value (any unit).
    scale : float, default 0
        Magnitude of the terms ``value`` was computed from (same unit); with 0,
        only an exact zero is zero.

    Returns
    -------
    bool
    """
    return math.isfinite(value) and abs(value) <= ZERO_TOLERANCE * abs(scale)


def clean(value: float, scale: float = 0.0) -> float:
    """``value`` as a float, or exactly ``0.0`` when it is numerically zero; never ``-0.0``.

    Parameters
    ----------
    value : float
        The computed value (any unit).
    scale : float, default 0
        Magnitude of the terms ``value`` was computed from (same unit as ``value``).

    Returns
    -------
    float
    """
    value = float(value)
    return 0.0 if is_zero(value, scale) else value + 0.0


def clean_array(values: Iterable[float] | np.ndarray, scale: float | np.ndarray = 0.0) -> np.ndarray:
    """Element-wise :func:`clean` (``scale`` broadcasts against ``values``).

    Parameters
    ----------
    values : array_like
    scale : float or array_like, default 0

    Returns
    -------
    ndarray of float
    """
    array = np.asarray(values, dtype=float)
    with np.errstate(invalid="ignore", over="ignore"):
        zero = (np.abs(array) <= ZERO_TOLERANCE * np.abs(np.asarray(scale, dtype=float))) & np.isfinite(array)
    return np.where(zero, 0.0, array) + 0.0


def scale_of(*values: float) -> float:
    """The largest magnitude among ``values`` (0 for none): the scale of a combination of them."""
    return max([abs(float(v)) for v in values], default=0.0)
