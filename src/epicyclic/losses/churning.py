"""Churning loss of a gear dipped in the oil sump (dip lubrication): Changenet & Velex.

A gear of pitch radius R_p and face width b turning at ω with its lowest h
millimetres in an oil bath of volume V_0 loses the torque

.. math:: T_{ch} = \\tfrac{1}{2} \\rho \\omega^2 S_m R_p^3 C_m

with S_m the wetted (submerged) surface — both faces' circular segments and
the rim, S_m = R_p² (2θ − sin 2θ) + 2 θ R_p b with θ = arccos(1 − h/R_p) — and
the dimensionless torque from Changenet & Velex's tests, by the Reynolds number
Re_c = ω R_p b / ν:

.. math::

    C_m &= 1.366 \\left(\\frac{h}{D_p}\\right)^{0.45} \\left(\\frac{V_0}{D_p^3}\\right)^{0.1}
           Fr^{-0.6}\\, Re^{-0.21} \\quad (Re_c < 6000) \\\\
    C_m &= 3.644 \\left(\\frac{h}{D_p}\\right)^{0.1} \\left(\\frac{V_0}{D_p^3}\\right)^{-0.35}
           Fr^{-0.88} \\left(\\frac{b}{D_p}\\right)^{0.85} \\quad (Re_c > 9000)

with Fr = ω² R_p / g, Re = ω R_p² / ν, and between 6000 and 9000 the two
blended linearly in Re_c.  Validity (the tests behind the fits): spur and
helical gears of module 1.5 … 5 mm, pitch diameters about 70 … 290 mm, face
widths 14 … 60 mm, speeds up to 7000 1/min, immersion h/D_p up to 0.5 (the axis),
V_0/D_p³ about 3 … 12, mineral oils of 12 … 300 mm²/s at the bath temperature; the
fits reproduce the measurements within about ±20 %.

References
----------
Changenet, C., Velex, P.: *A model for the prediction of churning losses in geared transmissions —
preliminary results*, ASME J. Mech. Des. 129 (2007) 128–133, eqs. (4)–(6);
Changenet, C., Velex, P.: *Housing influence on churning losses in geared transmissions*, ASME J.
Mech. Des. 130 (2008) 062603 (the high-Reynolds fit).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..results.solution import RPM_TO_RAD_S
from ._checks import positive
from .errors import LossModelError

__all__ = ["ChurningGear", "GRAVITY", "LAMINAR_LIMIT", "TURBULENT_LIMIT"]

#: Standard gravity, m/s².
GRAVITY = 9.80665
#: Re_c up to which the low-Reynolds fit holds, and from which the high-Reynolds fit does.
LAMINAR_LIMIT, TURBULENT_LIMIT = 6000.0, 9000.0

#: Angular speeds below this (rad/s) are evaluated at it: the coefficients diverge at standstill while
#: the torque, ∝ ω², vanishes (no 0·∞).
_SLOWEST = 1e-6


@dataclass(frozen=True)
class ChurningGear:
    """A gear that dips into the sump, on one shaft (its torque reacts on the housing).

    Parameters
    ----------
    shaft : str
        The shaft the gear turns with.
    pitch_radius : float
        R_p, mm.
    face_width : float
        b, mm.
    immersion : float
        h, depth of the gear's lowest point below the oil level, mm (0 < h ≤ 2 R_p).
    oil_volume : float
        V_0, the sump's oil volume, litres.
    element : str or None
        The element the loss is reported under (None: reported under "housing").

    Examples
    --------
    >>> gear = ChurningGear("out", pitch_radius=72.0, face_width=24.0, immersion=36.0, oil_volume=1.5)
    >>> round(float(gear.torque(3000.0, 30.0, 870.0)), 3)  # N·m at 3000 1/min, ν = 30 mm²/s
    0.428
    """

    shaft: str
    pitch_radius: float
    face_width: float
    immersion: float
    oil_volume: float
    element: str | None = None

    def __post_init__(self) -> None:
        owner = f"churning gear on {self.shaft!r}"
        r = positive(self.pitch_radius, "pitch_radius (mm)", owner)
        b = positive(self.face_width, "face_width (mm)", owner)
        h = positive(self.immersion, "immersion (mm)", owner)
        if h > 2.0 * r:
            raise LossModelError(f"{owner}: immersion {h!r} mm is deeper than the gear ({2 * r!r} mm); "
                                 "give the depth of its lowest point below the oil level.")
        for name, value in (("pitch_radius", r), ("face_width", b), ("immersion", h),
                            ("oil_volume", positive(self.oil_volume, "oil_volume (l)", owner))):
            object.__setattr__(self, name, value)

    @property
    def submerged_area(self) -> float:
        """S_m = R_p² (2θ − sin 2θ) + 2 θ R_p b, m², with θ = arccos(1 − h/R_p) (faces and rim)."""
        r, b, h = self.pitch_radius * 1e-3, self.face_width * 1e-3, self.immersion * 1e-3
        theta = np.arccos(1.0 - h / r)
        return float(r ** 2 * (2 * theta - np.sin(2 * theta)) + 2 * theta * r * b)

    def coefficient(self, speed, kinematic_viscosity):
        """C_m of Changenet & Velex at ``speed`` (1/min) and ν (mm²/s), by the regime of Re_c.

        Parameters
        ----------
        speed : float or array_like
            1/min.
        kinematic_viscosity : float or array_like
            ν, mm²/s.

        Returns
        -------
        ndarray
            C_m (0 where the gear stands).

        References
        ----------
        Changenet & Velex 2007, eqs. (5), (6); 2008 (Re_c > 9000).
        """
        r, b, h = self.pitch_radius * 1e-3, self.face_width * 1e-3, self.immersion * 1e-3
        d = 2.0 * r
        volume = self.oil_volume * 1e-3 / d ** 3
        omega = np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
        nu = np.asarray(kinematic_viscosity, dtype=float) * 1e-6
        moving = omega > 0
        w = np.maximum(omega, _SLOWEST)  # the fits diverge at standstill, where the torque (∝ ω²) vanishes
        froude = w ** 2 * r / GRAVITY
        reynolds = w * r ** 2 / nu
        reynolds_c = w * r * b / nu
        low = 1.366 * (h / d) ** 0.45 * volume ** 0.1 * froude ** -0.6 * reynolds ** -0.21
        high = 3.644 * (h / d) ** 0.1 * volume ** -0.35 * froude ** -0.88 * (b / d) ** 0.85
        blend = np.clip((reynolds_c - LAMINAR_LIMIT) / (TURBULENT_LIMIT - LAMINAR_LIMIT), 0.0, 1.0)
        return np.where(moving, (1.0 - blend) * low + blend * high, 0.0)

    def torque(self, speed, kinematic_viscosity, density):
        """Churning torque magnitude, N·m: ½ ρ ω² S_m R_p³ C_m.

        Parameters
        ----------
        speed : float or array_like
            Speed of the gear against the housing, 1/min.
        kinematic_viscosity : float or array_like
            ν of the sump oil, mm²/s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray

        References
        ----------
        Changenet & Velex 2007, eq. (4).
        """
        omega = np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
        r = self.pitch_radius * 1e-3
        return (0.5 * np.asarray(density, dtype=float) * omega ** 2 * self.submerged_area * r ** 3
                * self.coefficient(speed, kinematic_viscosity)) + 0.0

    def loss(self, speed, kinematic_viscosity, density):
        """Power lost, W: T |ω|.

        Parameters
        ----------
        speed : float or array_like
            1/min.
        kinematic_viscosity : float or array_like
            ν, mm²/s.
        density : float or array_like
            ρ, kg/m³.

        Returns
        -------
        ndarray
        """
        return self.torque(speed, kinematic_viscosity, density) * np.abs(np.asarray(speed, dtype=float)) \
            * RPM_TO_RAD_S
