"""The involute function and the quantities of a mesh that follow from it.

All angles are in radians inside this module; the value objects of
:mod:`epicyclic.geometry.gear` take and report degrees.  Lengths are in mm.

The involute function ``inv α = tan α − α`` links the profile shift of two
meshing gears to their operating (working) pressure angle and centre distance
(no-backlash condition):

.. math::

    \\operatorname{inv}\\alpha_{wt} = \\operatorname{inv}\\alpha_t
        + 2\\tan\\alpha_n\\,\\frac{x_1 \\pm x_2}{z_2 \\pm z_1},
    \\qquad a_w = a_0\\,\\frac{\\cos\\alpha_t}{\\cos\\alpha_{wt}}

(upper sign external, lower sign internal pair; for the internal pair the
internal gear is gear 2 and the fraction is ``(x2 − x1)/(z2 − z1)``).

References
----------
ISO 21771:2007, eqs. for inv α_wt and a_w (no-backlash mesh).
SDP/SI, *Elements of Metric Gear Technology* (D785), section 5.1 and Table 5-1.
Queitsch, Formelzeichen: a, a_0 (centre distance with and without profile
shift), α_0, α_b (pressure angle, operating pressure angle).
"""

from __future__ import annotations

import math

import numpy as np

from .errors import GeometryError

__all__ = [
    "inv",
    "inv_inverse",
    "transverse_pressure_angle",
    "operating_pressure_angle",
    "center_distance_from_angle",
    "profile_shift_sum",
]


def inv(alpha):
    """The involute function ``tan α − α`` (α in rad; floats or numpy arrays).

    >>> round(inv(math.radians(20.0)), 6)
    0.014904

    References
    ----------
    ISO 21771:2007, involute function; inv 20° = 0.014904 as printed in the
    KHK / SDP-SI profile-shifted spur gear example (z = 12/24, m = 3).
    """
    return np.tan(alpha) - alpha if isinstance(alpha, np.ndarray) else math.tan(alpha) - alpha


def inv_inverse(value, tol: float = 1e-15, max_iter: int = 60):
    """The angle α in [0, π/2) with ``inv α = value`` (Newton's method).

    Works on floats and numpy arrays (element-wise).  inv α = tan α − α.

    Parameters
    ----------
    value : float or numpy.ndarray
        inv α, ≥ 0 and finite.
    tol : float, default 1e-15
        Stop when every Newton step is smaller than this, rad.
    max_iter : int, default 60
        Most Newton steps.

    Returns
    -------
    float or numpy.ndarray
        α in rad, of the shape of ``value``.

    Raises
    ------
    GeometryError
        A negative or non-finite ``value`` (a ValueError, as every project error).

    Examples
    --------
    >>> round(math.degrees(inv_inverse(0.034317)), 4)
    26.0888

    References
    ----------
    KHK / SDP-SI profile-shifted spur gear example: inv α_w = 0.034317 gives
    α_w = 26.0888° (bolsover.com, "Profile Shifted External Spur Gears").
    """
    arr = np.asarray(value, dtype=float)
    if np.any(arr < 0) or not np.all(np.isfinite(arr)):
        raise GeometryError(f"inv_inverse: value (inv α = tan α − α) must be finite and >= 0, got {value!r}.")
    # Starting value from the series inverse alpha ≈ (3 v)^(1/3) (good for small v).
    alpha = np.cbrt(3.0 * arr)
    alpha = np.minimum(alpha, 1.5)
    for _ in range(max_iter):
        tan = np.tan(alpha)
        f = tan - alpha - arr
        step = f / np.where(tan == 0.0, 1e-300, tan * tan)
        alpha = np.clip(alpha - step, 0.0, 1.5707963)
        if np.all(np.abs(step) < tol):
            break
    return float(alpha) if np.ndim(value) == 0 else alpha


def transverse_pressure_angle(alpha_n: float, beta: float) -> float:
    """Transverse pressure angle ``α_t = atan(tan α_n / cos β)`` (rad).

    >>> round(math.degrees(transverse_pressure_angle(math.radians(20), math.radians(20))), 4)
    21.1728

    References
    ----------
    ISO 21771:2007, tan α_t = tan α_n / cos β.
    """
    return math.atan(math.tan(alpha_n) / math.cos(beta))


def operating_pressure_angle(x_sum, z_sum, alpha_n: float, alpha_t: float):
    """Operating transverse pressure angle from the profile-shift sum (rad).

    Parameters
    ----------
    x_sum : float or array
        ``x1 + x2`` for an external pair, ``x2 − x1`` for an internal pair
        (gear 2 internal).
    z_sum : float or array
        ``z1 + z2`` for an external pair, ``z2 − z1`` for an internal pair.
    alpha_n, alpha_t : float
        Normal and transverse pressure angle of the basic rack (rad).

    References
    ----------
    ISO 21771:2007: inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2);
    SDP/SI D785, Table 5-1 for the internal pair.
    """
    return inv_inverse(inv(alpha_t) + 2.0 * math.tan(alpha_n) * np.asarray(x_sum) / np.asarray(z_sum))


def center_distance_from_angle(a0, alpha_t: float, alpha_wt):
    """Operating centre distance ``a_w = a_0 cos α_t / cos α_wt`` (mm).

    References
    ----------
    ISO 21771:2007, a_w = a cos α_t / cos α_wt.
    """
    return a0 * math.cos(alpha_t) / np.cos(alpha_wt)


def profile_shift_sum(a_w: float, z_sum: float, m_n: float, alpha_n: float, beta: float = 0.0) -> float:
    """The profile-shift sum that makes a pair run at centre distance ``a_w``.

    Inverse of :func:`operating_pressure_angle`: returns ``x1 + x2``
    (external; ``z_sum = z1 + z2``) or ``x2 − x1`` (internal; ``z_sum = z2 − z1``).

    Parameters
    ----------
    a_w : float
        Operating centre distance, mm.
    z_sum : float
        ``z1 + z2`` (external) or ``z2 − z1`` (internal).
    m_n : float
        Normal module, mm.
    alpha_n, beta : float
        Normal pressure angle and helix angle, rad.

    Examples
    --------
    KHK / SDP-SI example: z = 12/24, m = 3, a = 56.5 mm needs x1 + x2 = 0.96:

    >>> round(profile_shift_sum(56.5, 36, 3.0, math.radians(20)), 3)
    0.96

    References
    ----------
    ISO 21771:2007: x1 + x2 = (z1 + z2)(inv α_wt − inv α_t)/(2 tan α_n).
    """
    alpha_t = transverse_pressure_angle(alpha_n, beta)
    a0 = m_n * z_sum / (2.0 * math.cos(beta))
    cos_wt = a0 * math.cos(alpha_t) / a_w
    if not 0.0 < cos_wt < 1.0:
        raise ValueError(
            f"centre distance {a_w!r} mm cannot be reached: a0·cos α_t / a_w = {cos_wt:.4f} must lie in (0, 1)"
        )
    alpha_wt = math.acos(cos_wt)
    return z_sum * (inv(alpha_wt) - inv(alpha_t)) / (2.0 * math.tan(alpha_n))
