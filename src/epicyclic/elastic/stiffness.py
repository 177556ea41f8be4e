"""Mesh stiffness of ISO 6336-1, 9.3: single stiffness c' and mesh stiffness c_γα, c_γβ.

* c' = c'_th C_M C_R C_B cos β with 1/c'_th = q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1
  + C6 x2 + C7 x2/z_n2 + C8 x1² + C9 x2² (z_n2 → ∞ for internal gears), reduced by (K_A F_t/b)/100
  below 100 N/mm;
* c_γα = c' (0.75 ε_α + 0.25), c_γβ = 0.85 c_γα.

The rating (:mod:`epicyclic.rating.load_factors`) and the elastic models of a planetary set
(:mod:`epicyclic.elastic.lumped`: mesh stiffness k = c_γα b) take them from here.

References
----------
ISO 6336-1:2006 and :2019, 9.3 (eqs. (70)–(79), Table 8).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["basic_rack_factor", "mesh_stiffness", "single_stiffness", "lumped_mesh_stiffness"]

_Q = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


def basic_rack_factor(dedendum: float, pressure_angle_deg: float) -> float:
    """C_B = [1 + 0.5 (1.2 − h_fP/m_n)] [1 − 0.02 (20° − α_n)] (ISO 6336-1, eq. (79)).

    Parameters
    ----------
    dedendum : float
        h_fP/m_n of the basic rack.
    pressure_angle_deg : float
        α_n, degrees.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-1:2006, 9.3.1, eq. (79).

    Examples
    --------
    >>> round(basic_rack_factor(1.25, 20.0), 3)
    0.975
    """
    return (1 + 0.5 * (1.2 - dedendum)) * (1 - 0.02 * (20.0 - pressure_angle_deg))


def single_stiffness(z_n1: float, z_n2: float, x1: float, x2: float, beta: float, *, dedendum: float = 1.25,
                     pressure_angle_deg: float = 20.0, internal: bool = False, gear_blank: float = 0.8) -> float:
    """Single stiffness c' at K_A F_t/b ≥ 100 N/mm, N/(mm µm).

    Parameters
    ----------
    z_n1, z_n2 : float
        Virtual tooth numbers (z_n2 ignored for an internal gear: → ∞).
    x1, x2 : float
        Profile shifts.
    beta : float
        Helix angle, rad.
    dedendum : float
        h_fP* for C_B.
    pressure_angle_deg : float
        α_n for C_B.
    internal : bool
        Gear 2 is internal.
    gear_blank : float, default 0.8
        C_M (0.8 for solid discs).

    Returns
    -------
    float

    References
    ----------
    ISO 6336-1:2006, 9.3.1, eqs. (70)–(79), Table 8 (C1 … C9); C_R = 1 (solid blanks).

    Examples
    --------
    >>> round(single_stiffness(19, 104, 0.5, 0.15, 0.0), 3)
    14.892
    """
    c1, c2, c3, c4, c5, c6, c7, c8, c9 = _Q
    inv2 = 0.0 if internal else 1.0 / z_n2
    q = c1 + c2 / z_n1 + c3 * inv2 + c4 * x1 + c5 * x1 / z_n1 + c6 * x2 + c7 * x2 * inv2 + c8 * x1 ** 2 + c9 * x2 ** 2
    return (1.0 / q) * gear_blank * basic_rack_factor(dedendum, pressure_angle_deg) * math.cos(beta)


def mesh_stiffness(c_prime: float, contact_ratio: float, line_load):
    """(c', c_γα, c_γβ) for the line load K_A F_t/b (N/mm), reduced below 100 N/mm.

    Parameters
    ----------
    c_prime : float
        :func:`single_stiffness`, N/(mm µm).
    contact_ratio : float
        ε_α.
    line_load : float or ndarray
        K_A F_t / b, N/mm.

    Returns
    -------
    tuple of float or ndarray

    References
    ----------
    ISO 6336-1:2006, 9.3.1 (eq. 70, low loads) and 9.3.2 (c_γα = c'(0.75 ε_α + 0.25), c_γβ = 0.85 c_γα).
    """
    scale = np.clip(np.asarray(line_load, dtype=float) / 100.0, 1e-9, 1.0)  # no zero stiffness at zero load
    c = c_prime * scale
    c_ga = c * (0.75 * contact_ratio + 0.25)
    return c, c_ga, 0.85 * c_ga


def lumped_mesh_stiffness(c_gamma_alpha: float, face_width: float) -> float:
    """Mean mesh stiffness of a lumped model, k = c_γα b, N/m.

    Parameters
    ----------
    c_gamma_alpha : float
        Mesh stiffness per unit face width, N/(mm µm) (:func:`mesh_stiffness`).
    face_width : float
        Common face width b, mm.

    Returns
    -------
    float
        N/m (1 N/(mm µm) · 1 mm = 1 N/µm = 10⁶ N/m).

    References
    ----------
    ISO 6336-1:2006, 9.3.2 (c_γα is the mean mesh stiffness per unit face width).

    Examples
    --------
    >>> lumped_mesh_stiffness(20.0, 25.0)
    500000000.0
    """
    return float(c_gamma_alpha) * float(face_width) * 1e6
