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

__all__ = ["basic_rack_factor", "mesh_stiffness", "single_stiffness", "lumped_mesh_stiffness", "mesh_stiffness_variation"]

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


def mesh_stiffness_variation(c_prime: float, contact_ratio: float, face_width: float, harmonics: int = 5):
    """The mesh stiffness over one mesh cycle of a spur pair: single and double tooth contact, and its harmonics.

    Over a mesh period the pair is in double contact for the fraction ε_α − 1 and in single contact
    for 2 − ε_α (1 < ε_α < 2).  With the single-contact stiffness c′ b and the mean c_γα b of ISO
    6336-1 (c_γα = c′(0.75 ε_α + 0.25)), the double-contact stiffness is 1.75 c′ b, whatever ε_α:
    (2 − ε_α) c′ + (ε_α − 1) k_d/b = c′(0.75 ε_α + 0.25) gives k_d = 1.75 c′ b.  The rectangular
    wave, double contact centred on the start of the cycle, has the Fourier amplitudes
    |k_l| = 2 (k_d − k_s) |sin(π l (ε_α − 1))|/(π l).

    Parameters
    ----------
    c_prime : float
        Single stiffness c′, N/(mm µm).
    contact_ratio : float
        ε_α, 1 < ε_α < 2.
    face_width : float
        b, mm.
    harmonics : int, default 5
        Harmonics l = 1 … returned (1 … 50).

    Returns
    -------
    dict
        ``single``, ``double``, ``mean`` (N/m), ``double_fraction`` (ε_α − 1) and ``harmonics``:
        the amplitudes |k_l|, N/m, of the mesh-frequency harmonics (the parametric excitation).

    Raises
    ------
    ValueError
        ε_α outside (1, 2), harmonics out of range (an ElasticError).

    References
    ----------
    ISO 6336-1:2006, 9.3 (c′ single, c_γα mean mesh stiffness); the rectangular single/double contact
    wave as in R. G. Parker, S. M. Vijayakar, T. Imajo, "Non-linear dynamic response of a spur gear
    pair", J. Sound Vib. 237 (2000) 435–455.

    Examples
    --------
    >>> v = mesh_stiffness_variation(14.0, 1.6, 20.0)
    >>> round(v["double"] / v["single"], 6), round(v["mean"] / 1e6, 3)
    (1.75, 406.0)
    """
    from .errors import ElasticError, positive

    c = positive(c_prime, "c_prime")
    eps = positive(contact_ratio, "contact_ratio")
    b = positive(face_width, "face_width")
    if not 1.0 < eps < 2.0:
        raise ElasticError(f"contact_ratio must lie between 1 and 2 for single/double contact, got {eps!r}.")
    if isinstance(harmonics, bool) or not isinstance(harmonics, int) or not 1 <= harmonics <= 50:
        raise ElasticError(f"harmonics must be a whole number 1 ... 50, got {harmonics!r}.")
    single = lumped_mesh_stiffness(c, b)
    double = 1.75 * single
    fraction = eps - 1.0
    mean = lumped_mesh_stiffness(float(mesh_stiffness(c, eps, 100.0)[1]), b)
    amplitudes = [2.0 * (double - single) * abs(math.sin(math.pi * l_ * fraction)) / (math.pi * l_)
                  for l_ in range(1, harmonics + 1)]
    return {"single": single, "double": double, "mean": mean, "double_fraction": fraction, "harmonics": amplitudes}
