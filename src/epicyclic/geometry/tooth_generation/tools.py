"""The tools that generate a gear's tooth: a rack-type tool (hob, rack cutter) and a pinion-type cutter.

Both are given in the normal section, as factors of the gear's normal module m_n; the
pressure angle is the gear's.  A rack-type tool's tooth (pointing toward the gear's centre)::

    tip line        at h_a0 m_n below the datum line (h_a0* = the gear's dedendum h_fP*)
    tip round       radius ρ_a0 m_n, tangent to the tip line and to the flank next to it
    protuberance    optional: a flank of pressure angle α_pr < α_n standing out pr m_n (measured
                    normal to the main flank, at the tip line) from the main flank; it rejoins the
                    main flank h_pr = pr m_n / (cos α_n (tan α_n − tan α_pr)) above the tip line
    main flank      a straight line of pressure angle α_n; tool tooth thickness π m_n/2 at the datum

A pinion-type (shaper) cutter is an external involute gear of z_0 teeth, profile shift x_0, tip
circle d_a0 = z_0 m_n + 2 m_n (h_a0* + x_0) and tip round ρ_a0 m_n tangent to tip circle and flank.

References
----------
ISO 53:1998 (basic rack, profiles A–D); ISO 6336-3:2006 / 2019, 6.2 and Figure 8 (basic rack with
protuberance: pr, α_pr, ρ_fP); ISO 21771:2007, 5.4 (generation by rack-type tools and pinion-type
cutters, cutting centre distance).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import GeometryError

__all__ = ["PinionCutter", "RackTool"]


def _factor(owner: str, key: str, value: object, *, positive: bool = False, allow_none: bool = False) -> Any:
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise GeometryError(f"{owner}: {key} must be a number, got {value!r}.")
    if value < 0 or (positive and value == 0):
        raise GeometryError(f"{owner}: {key} must be {'> 0' if positive else '>= 0'} (a factor of the normal "
                            f"module), got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class RackTool:
    """A rack-type tool (hob or rack cutter) in the normal section, factors of m_n.

    Parameters
    ----------
    addendum : float, optional
        h_a0* = the tool's tip depth below its datum line, which becomes the gear's dedendum
        h_fP*.  None (default): the dedendum of the gear's basic rack, so the generated root
        circle is the geometry's.
    tip_radius : float, default 0.38
        ρ_a0* (ISO 53:1998 profile A: 0.38; B: 0.30; C: 0.25; D: 0.39).
    protuberance : float, default 0
        pr*, the protuberance normal to the main flank at the tip line.
    protuberance_angle : float, optional
        α_pr in degrees, the pressure angle of the protuberance flank (0 ≤ α_pr < α_n);
        required with a protuberance.

    Raises
    ------
    GeometryError
        A negative or non-finite value, a protuberance without its angle.

    References
    ----------
    ISO 53:1998; ISO 6336-3:2019, 6.2, Figure 8 (pr, α_pr, ρ_fP).

    Examples
    --------
    >>> RackTool(tip_radius=0.3)
    RackTool(addendum=None, tip_radius=0.3, protuberance=0.0, protuberance_angle=None)
    """

    addendum: float | None = None
    tip_radius: float = 0.38
    protuberance: float = 0.0
    protuberance_angle: float | None = None

    def __post_init__(self) -> None:
        owner = "RackTool"
        object.__setattr__(self, "addendum", _factor(owner, "addendum", self.addendum, positive=True,
                                                     allow_none=True))
        object.__setattr__(self, "tip_radius", _factor(owner, "tip_radius", self.tip_radius))
        object.__setattr__(self, "protuberance", _factor(owner, "protuberance", self.protuberance))
        angle = _factor(owner, "protuberance_angle", self.protuberance_angle, allow_none=True)
        if self.protuberance > 0 and angle is None:
            raise GeometryError("RackTool: a protuberance needs its protuberance_angle (the pressure angle of the "
                                "protuberance flank, degrees, smaller than the gear's pressure angle).")
        object.__setattr__(self, "protuberance_angle", angle)

    @property
    def kind(self) -> str:
        """``"rack"``."""
        return "rack"

    def describe(self) -> str:
        """One line for reports."""
        h = "h_fP*" if self.addendum is None else f"{self.addendum:g}"
        pr = f", pr* = {self.protuberance:g} at {self.protuberance_angle:g}°" if self.protuberance else ""
        return f"rack-type tool (h_a0* = {h}, rho_a0* = {self.tip_radius:g}{pr})"

    def to_dict(self) -> dict[str, Any]:
        """Plain data (factors of m_n, degrees)."""
        return {"kind": "rack", "addendum": self.addendum, "tip_radius": self.tip_radius,
                "protuberance": self.protuberance, "protuberance_angle": self.protuberance_angle}


@dataclass(frozen=True)
class PinionCutter:
    """A pinion-type (shaper) cutter, the tool of internal gears, factors of m_n.

    Parameters
    ----------
    teeth : int
        z_0 (≥ 8).
    profile_shift : float, default 0
        x_0.
    addendum : float, optional
        h_a0*: tip circle d_a0 = z_0 m_t + 2 m_n (h_a0* + x_0).  None (default): the addendum
        that cuts the gear's root circle d_f of its basic rack at the cutting centre distance
        (as calculation programs do when the root diameter is given).
    tip_radius : float, default 0.25
        ρ_a0*.

    Raises
    ------
    GeometryError
        Fewer than 8 teeth, a negative tip radius or addendum.

    References
    ----------
    ISO 21771:2007, 5.4 (pinion-type cutter, cutting centre distance a_0).

    Examples
    --------
    >>> PinionCutter(36, tip_radius=0.3).describe()
    'pinion-type cutter (z0 = 36, x0 = 0, h_a0* = from d_f, rho_a0* = 0.3)'
    """

    teeth: int
    profile_shift: float = 0.0
    addendum: float | None = None
    tip_radius: float = 0.25

    def __post_init__(self) -> None:
        owner = "PinionCutter"
        z = self.teeth
        if isinstance(z, bool) or not isinstance(z, int) or z < 8:
            raise GeometryError(f"{owner}: teeth (z0) must be a whole number >= 8, got {z!r}.")
        x0 = self.profile_shift
        if isinstance(x0, bool) or not isinstance(x0, (int, float)) or not math.isfinite(x0) or abs(x0) > 2:
            raise GeometryError(f"{owner}: profile_shift (x0) must be a number in [-2, 2], got {x0!r}.")
        object.__setattr__(self, "profile_shift", float(x0))
        object.__setattr__(self, "addendum", _factor(owner, "addendum", self.addendum, positive=True,
                                                     allow_none=True))
        object.__setattr__(self, "tip_radius", _factor(owner, "tip_radius", self.tip_radius))

    @property
    def kind(self) -> str:
        """``"pinion-type cutter"``."""
        return "pinion-type cutter"

    def describe(self) -> str:
        """One line for reports."""
        h = "from d_f" if self.addendum is None else f"{self.addendum:g}"
        return (f"pinion-type cutter (z0 = {self.teeth}, x0 = {self.profile_shift:g}, h_a0* = {h}, "
                f"rho_a0* = {self.tip_radius:g})")

    def to_dict(self) -> dict[str, Any]:
        """Plain data (factors of m_n)."""
        return {"kind": "pinion-type cutter", "teeth": self.teeth, "profile_shift": self.profile_shift,
                "addendum": self.addendum, "tip_radius": self.tip_radius}
