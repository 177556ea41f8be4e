"""The stresses below a loaded flank: the Hertzian line contact along the depth.

Two cylinders pressed together along a line (the flanks at a contact point, radius of relative
curvature ρ_red) carry the elliptical pressure p(x) = p_0 √(1 − x²/b²) over the half width b.
Below the centre of the contact, at the depth y, the stresses of the elastic half space are
(Johnson 1985, §4.6, the stresses along the axis of symmetry of a two-dimensional Hertz contact;
McEwen 1949)::

    σ_x = −(p_0/b) [(b² + 2y²)(b² + y²)^(−1/2) − 2y]
    σ_y = −p_0 b (b² + y²)^(−1/2)
    τ_1 = (σ_x − σ_y)/2 = (p_0/b) [y − y² (b² + y²)^(−1/2)]

(σ_y normal to the surface; τ_1 the principal shear stress in the plane of the profile).  τ_1 is
zero at the surface, has its maximum 0.300 p_0 at y = 0.786 b and falls as b/(2y) far below — the
"maximum shear stress 0.30 p_0 at 0.78 b" of the textbooks.  The half width follows from the
pressure and the reduced modulus E_r = 2 / ((1 − ν_1²)/E_1 + (1 − ν_2²)/E_2) of ISO/TS 6336-22
(twice Johnson's E*)::

    b_H = 4 ρ_red p_0 / E_r                    (Johnson 1985, §4.2: b = 2 R p_0 / E*)

References
----------
K. L. Johnson, Contact Mechanics, Cambridge University Press 1985, §4.2 (b = 2 R p_0 / E*) and §4.6;
J. McEwen, "Stresses in elastic cylinders in contact along a generatrix", Phil. Mag. 40 (1949);
ISO/TS 6336-4:2019, 6.2 (the local Hertzian contact stress p_dyn,CP, the radius ρ_red,CP and
E_r the local equivalent stress is built on).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import minimize_scalar

__all__ = ["axis_stresses", "half_width", "principal_shear", "principal_shear_peak"]


def half_width(pressure, rho_red, E_r: float):
    """Half the Hertzian contact width b_H = 4 ρ_red p_0 / E_r, mm.

    Parameters
    ----------
    pressure : float or ndarray
        Maximum Hertzian pressure p_0 (p_dyn), N/mm².
    rho_red : float or ndarray
        Radius of relative curvature in the normal section, mm.
    E_r : float
        Reduced modulus 2 / ((1 − ν_1²)/E_1 + (1 − ν_2²)/E_2), N/mm².

    Returns
    -------
    float or ndarray

    References
    ----------
    Johnson 1985, Contact Mechanics, §4.2 (b = 2 R p_0 / E*, E* = E_r / 2).

    Examples
    --------
    >>> round(float(half_width(1500.0, 20.0, 226373.6)), 4)
    0.5301
    """
    return 4.0 * np.asarray(rho_red, dtype=float) * np.asarray(pressure, dtype=float) / E_r


def axis_stresses(depth, pressure, b):
    """(σ_x, σ_y) below the centre of a line contact at ``depth`` (mm), N/mm² (compressive < 0).

    Parameters
    ----------
    depth : float or ndarray
        y ≥ 0, mm.
    pressure : float or ndarray
        p_0, N/mm².
    b : float or ndarray
        Half width, mm (> 0).

    Returns
    -------
    (ndarray, ndarray)
        σ_x (along the surface) and σ_y (normal to it), broadcast.

    References
    ----------
    Johnson 1985, Contact Mechanics, §4.6; McEwen 1949.

    Examples
    --------
    >>> sx, sy = axis_stresses(0.0, 1000.0, 0.5)
    >>> float(sx), float(sy)
    (-1000.0, -1000.0)
    """
    y = np.asarray(depth, dtype=float)
    p = np.asarray(pressure, dtype=float)
    b = np.asarray(b, dtype=float)
    root = np.sqrt(b * b + y * y)
    sx = -(p / b) * ((b * b + 2.0 * y * y) / root - 2.0 * y)
    sy = -p * b / root
    return sx, sy


def principal_shear(depth, pressure, b):
    """τ_1 = (p_0/b)[y − y²/√(b² + y²)] below the centre of a line contact, N/mm².

    Parameters
    ----------
    depth, pressure, b : float or ndarray
        As :func:`axis_stresses`.

    Returns
    -------
    ndarray

    References
    ----------
    Johnson 1985, Contact Mechanics, §4.6 (τ_1 = ½ |σ_x − σ_y|).

    Examples
    --------
    >>> round(float(principal_shear(0.786, 1.0, 1.0)), 3)
    0.3
    """
    y = np.asarray(depth, dtype=float)
    b = np.asarray(b, dtype=float)
    zeta = y / b
    return np.asarray(pressure, dtype=float) * (zeta - zeta * zeta / np.sqrt(1.0 + zeta * zeta))


def principal_shear_peak() -> tuple[float, float]:
    """(τ_1,max / p_0, its depth / b) of the line contact, found numerically (≈ 0.3003, 0.7862).

    Returns
    -------
    (float, float)

    References
    ----------
    Johnson 1985, Contact Mechanics, §4.6 ("τ_1,max = 0.30 p_0 at z = 0.78 b").

    Examples
    --------
    >>> tau, y = principal_shear_peak()
    >>> round(tau, 4), round(y, 4)
    (0.3003, 0.7862)
    """
    res = minimize_scalar(lambda z: -float(principal_shear(z, 1.0, 1.0)), bounds=(0.1, 2.0), method="bounded",
                          options={"xatol": 1e-10})
    return float(-res.fun), float(res.x)
