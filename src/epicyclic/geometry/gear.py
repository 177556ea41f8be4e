"""Cylindrical involute gears and gear pairs: diameters, centre distance, contact ratio.

Units: lengths in mm, angles in degrees at the interface (radians inside).
Tooth counts and diameters are positive for internal gears too; an internal
gear is flagged ``internal=True``.

Profile shift of an internal gear: the ISO 21771 / DIN 3960 sign (also KISSsoft's
and REXS's).  ISO writes an internal gear with z < 0, so its coefficient keeps the
meaning "material added toward the tooth tip side of the rack": a *negative* x of
an internal gear enlarges its tip circle and the centre distance.  Handbooks in
the KHK / SDP-SI tradition use the opposite sign (x_KHK = −x_ISO);
:func:`iso_profile_shift` converts.  ``GearGeometry.profile_shift`` is always ISO.

Formulas (normal module m_n, helix angle β, transverse module
m_t = m_n / cos β, transverse pressure angle tan α_t = tan α_n / cos β):

============================  ==============================  ==============================
quantity                      external gear                   internal gear (x ISO)
============================  ==============================  ==============================
reference diameter d          z m_t                           z m_t
base diameter d_b             d cos α_t                       d cos α_t
tip diameter d_a              d + 2 m_n (h_a* + x − k)        d − 2 m_n (h_a* + x − k)
root diameter d_f             d − 2 m_n (h_f* − x)            d + 2 m_n (h_f* − x)
============================  ==============================  ==============================

References
----------
ISO 21771:2007 (cylindrical involute gears: concepts and geometry; internal gears
with z < 0); DIN 3960:1987.  SDP/SI, *Elements of Metric Gear Technology* (D785),
section 5.1, Table 5-1 (profile-shifted internal gear, KHK sign).  Queitsch,
Formelzeichen (d_0, r_g, r_b, h_k).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

from ..limits import MAX_TOOTH_HEIGHT_FACTOR, MODULE_RANGE
from .conventions import SHIFT_CONVENTIONS, iso_profile_shift
from .errors import GeometryError
from .involute import (
    center_distance_from_angle,
    operating_pressure_angle,
    profile_shift_sum,
    transverse_pressure_angle,
)

__all__ = ["BasicRack", "GearGeometry", "MeshGeometry", "SHIFT_CONVENTIONS", "iso_profile_shift"]

#: Largest |y| = |a_w − a|/m_n of a given centre distance (beyond it no tooth reaches across).
_MAX_Y = 5.0


def _positive(value: object, name: str, owner: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise GeometryError(f"{owner}: {name} must be a positive number (mm or factor), got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class BasicRack:
    """Module, pressure angle, helix angle and tooth-height factors of a gear.

    Parameters
    ----------
    module : float
        Normal module m_n, mm.
    pressure_angle : float, default 20
        Normal pressure angle α_n of the basic rack, degrees (0 < α_n < 45).
    helix_angle : float, default 0
        Helix angle β at the reference cylinder, degrees (0 ≤ β < 45); 0 for spur gears.
    addendum : float, default 1.0
        Addendum factor h_a* (addendum = h_a* m_n).
    dedendum : float, default 1.25
        Dedendum factor h_f* (dedendum = h_f* m_n).

    References
    ----------
    ISO 53:1998 (standard basic rack: α = 20°, h_a* = 1, h_f* = 1.25);
    ISO 21771:2007 (m_t = m_n / cos β, tan α_t = tan α_n / cos β).

    Examples
    --------
    >>> rack = BasicRack(2.5, helix_angle=20)
    >>> round(rack.transverse_module, 4), round(rack.transverse_pressure_angle, 4)
    (2.6604, 21.1728)
    """

    module: float
    pressure_angle: float = 20.0
    helix_angle: float = 0.0
    addendum: float = 1.0
    dedendum: float = 1.25

    def __post_init__(self) -> None:
        owner = "BasicRack"
        module = _positive(self.module, "module", owner)
        if not MODULE_RANGE[0] <= module <= MODULE_RANGE[1]:
            raise GeometryError(f"{owner}: module must lie within {MODULE_RANGE[0]:g} … {MODULE_RANGE[1]:g} mm, "
                                f"got {module!r} (see docs/limits.md).")
        object.__setattr__(self, "module", module)
        for name in ("addendum", "dedendum"):
            factor = _positive(getattr(self, name), name, owner)
            if factor > MAX_TOOTH_HEIGHT_FACTOR:
                raise GeometryError(f"{owner}: {name} must be at most {MAX_TOOTH_HEIGHT_FACTOR:g} × the module "
                                    f"(ISO 53: addendum 1, dedendum 1.25), got {factor!r}.")
            object.__setattr__(self, name, factor)
        alpha = self.pressure_angle
        if isinstance(alpha, bool) or not isinstance(alpha, (int, float)) or not 0.0 < alpha < 45.0:
            raise GeometryError(
                f"{owner}: pressure_angle must lie in (0, 45) degrees, got {alpha!r}. "
                "Use 20 for the ISO 53 standard rack."
            )
        beta = self.helix_angle
        if isinstance(beta, bool) or not isinstance(beta, (int, float)) or not 0.0 <= beta < 45.0:
            raise GeometryError(
                f"{owner}: helix_angle must lie in [0, 45) degrees, got {beta!r} (0 for spur gears; "
                "give the magnitude, the hand does not change the geometry)."
            )
        object.__setattr__(self, "pressure_angle", float(alpha))
        object.__setattr__(self, "helix_angle", float(beta))

    @property
    def alpha_n(self) -> float:
        """Normal pressure angle, rad."""
        return math.radians(self.pressure_angle)

    @property
    def beta(self) -> float:
        """Helix angle, rad."""
        return math.radians(self.helix_angle)

    @property
    def alpha_t(self) -> float:
        """Transverse pressure angle, rad."""
        return transverse_pressure_angle(self.alpha_n, self.beta)

    @property
    def transverse_pressure_angle(self) -> float:
        """Transverse pressure angle α_t, degrees."""
        return math.degrees(self.alpha_t)

    @property
    def transverse_module(self) -> float:
        """m_t = m_n / cos β, mm."""
        return self.module / math.cos(self.beta)

    def with_module(self, module: float) -> BasicRack:
        """The same rack with another normal module."""
        return replace(self, module=module)


@dataclass(frozen=True)
class GearGeometry:
    """One cylindrical involute gear (external or internal).

    Parameters
    ----------
    teeth : int
        Number of teeth z (positive, also for internal gears).
    rack : BasicRack
    profile_shift : float, default 0
        Profile-shift coefficient x, ISO 21771 sign (an internal gear's x < 0 enlarges
        its tip circle; :func:`iso_profile_shift` converts a KHK value).
    internal : bool, default False
    tip_shortening : float, default 0
        Tip-shortening coefficient k ≥ 0 (external gears; see
        :attr:`MeshGeometry.tip_shortening`).
    thickness_allowance : float, default 0
        Upper tooth-thickness allowance A_sn ≤ 0, mm (normal section; ISO 21771 /
        DIN 3967): the tool is fed in by A_sn/(2 tan α_n), so the gear is generated
        with x_E = x + A_sn/(2 m_n tan α_n) and the mesh gets backlash.

    References
    ----------
    ISO 21771:2007 (internal gear, x ISO: d_a2 = d_2 − 2 m (h_a* + x_2));
    SDP/SI D785, Table 5-1 (the same with x_KHK = −x_ISO: d_a2 = d_2 − 2 m (1 − x_2)).

    Examples
    --------
    Ring of the lecad "Analysis of Planetary Transmissions" test run (z = 108,
    m = 1.75, x = 0; printed d = 189.0000, d_a = 185.4992 mm):

    >>> ring = GearGeometry(108, BasicRack(1.75), internal=True)
    >>> round(ring.reference_diameter, 4), round(ring.tip_diameter, 2), ring.root_diameter
    (189.0, 185.5, 193.375)
    """

    teeth: int
    rack: BasicRack
    profile_shift: float = 0.0
    internal: bool = False
    tip_shortening: float = 0.0
    thickness_allowance: float = 0.0

    def __post_init__(self) -> None:
        z = self.teeth
        if isinstance(z, bool) or not isinstance(z, int) or z < 3:
            raise GeometryError(f"GearGeometry: teeth must be a whole number >= 3, got {z!r}.")
        if not isinstance(self.rack, BasicRack):
            raise GeometryError(f"GearGeometry: rack must be a BasicRack, got {type(self.rack).__name__}.")
        x = self.profile_shift
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or abs(x) > 3:
            raise GeometryError(
                f"GearGeometry: profile_shift must be a number in [-3, 3] (a coefficient, not mm), got {x!r}."
            )
        k = self.tip_shortening
        if isinstance(k, bool) or not isinstance(k, (int, float)) or not math.isfinite(k) or not 0 <= k <= 3:
            raise GeometryError(f"GearGeometry: tip_shortening must be a coefficient k in [0, 3] (k m_n off the tip), "
                                f"got {k!r}.")
        object.__setattr__(self, "profile_shift", float(x))
        object.__setattr__(self, "tip_shortening", float(k))
        allowance = self.thickness_allowance
        if isinstance(allowance, bool) or not isinstance(allowance, (int, float)) or not math.isfinite(allowance) \
                or allowance > 0 or allowance < -self.rack.module:
            raise GeometryError(f"GearGeometry: thickness_allowance (A_sn, mm) must lie in [-m_n, 0] "
                                f"(thinner teeth give backlash), got {allowance!r}.")
        object.__setattr__(self, "thickness_allowance", float(allowance))

    @property
    def generating_profile_shift(self) -> float:
        """x_E = x + A_sn / (2 m_n tan α_n), the shift the gear is cut with (ISO 21771, DIN 3960)."""
        return self.profile_shift + self.thickness_allowance / (2.0 * self.rack.module * math.tan(self.rack.alpha_n))

    @property
    def reference_diameter(self) -> float:
        """d = z m_t, mm."""
        return self.teeth * self.rack.transverse_module

    @property
    def base_diameter(self) -> float:
        """d_b = d cos α_t, mm."""
        return self.reference_diameter * math.cos(self.rack.alpha_t)

    @property
    def tip_diameter(self) -> float:
        """d_a, mm (for an internal gear the smaller, inner circle of its tips)."""
        m, r = self.rack.module, self.rack
        if self.internal:
            return self.reference_diameter - 2.0 * m * (r.addendum + self.profile_shift - self.tip_shortening)
        return self.reference_diameter + 2.0 * m * (r.addendum + self.profile_shift - self.tip_shortening)

    @property
    def root_diameter(self) -> float:
        """d_f, mm (for an internal gear the larger, outer circle of its roots)."""
        m, r = self.rack.module, self.rack
        if self.internal:
            return self.reference_diameter + 2.0 * m * (r.dedendum - self.profile_shift)
        return self.reference_diameter - 2.0 * m * (r.dedendum - self.profile_shift)

    @property
    def tip_pressure_angle(self) -> float:
        """Transverse pressure angle at the tip circle, rad (0 if the tip lies inside the base circle)."""
        ratio = self.base_diameter / self.tip_diameter
        return math.acos(min(1.0, ratio))

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm)."""
        return {
            "teeth": self.teeth,
            "internal": self.internal,
            "profile_shift": self.profile_shift,
            "tip_shortening": self.tip_shortening,
            "thickness_allowance": self.thickness_allowance,
            "reference_diameter": self.reference_diameter,
            "base_diameter": self.base_diameter,
            "tip_diameter": self.tip_diameter,
            "root_diameter": self.root_diameter,
        }


@dataclass(frozen=True)
class MeshGeometry:
    """A gear pair: gear 1 external, gear 2 external or internal.

    Parameters
    ----------
    gear1, gear2 : GearGeometry
        ``gear1`` must be external; ``gear2`` may be internal (a ring).  Both
        must share the basic rack (module, pressure angle, helix angle).
    name : str, optional
        A label such as ``"sun-planet"``.
    working_center_distance : float, optional
        The centre distance the pair is built at, mm.  Default: the backlash-free
        one that the profile shifts give.  Given, α_wt and the pitch circles follow
        from it (cos α_wt = a cos α_t / a_w) and :attr:`backlash` from the shifts
        and thickness allowances.

    Notes
    -----
    Without ``working_center_distance`` the pair runs without backlash at the operating
    centre distance that the profile shifts give (ISO 21771).  For an external pair the tip-shortening
    coefficient ``k = x1 + x2 − y`` with ``y = (a_w − a)/m_n`` is reported;
    apply it to the tips (``SetGeometry`` does) to keep the standard tip
    clearance.

    References
    ----------
    ISO 21771:2007 (a, a_w, α_wt, d_w, y, k, ε_α); SDP/SI D785, Table 5-1 and
    eqs. (5-1) for the internal pair.

    Examples
    --------
    KHK / SDP-SI profile-shifted spur pair z = 12/24, m = 3, x = 0.6/0.36:

    >>> rack = BasicRack(3)
    >>> mesh = MeshGeometry(GearGeometry(12, rack, 0.6), GearGeometry(24, rack, 0.36))
    >>> round(mesh.operating_pressure_angle, 4), round(mesh.center_distance, 3)
    (26.0886, 56.5)
    """

    gear1: GearGeometry
    gear2: GearGeometry
    name: str = ""
    working_center_distance: float | None = None
    # α_wt, a pure function of the frozen gears and centre distance: computed once in __post_init__ (it is
    # asked for by a_w, d_w, ε_α, k and the rating of every load case; the inverse involute is an iteration).
    _alpha_wt: float = field(init=False, repr=False, compare=False, default=float("nan"))

    def __post_init__(self) -> None:
        owner = f"MeshGeometry {self.name!r}" if self.name else "MeshGeometry"
        given = self.working_center_distance
        if given is not None and (isinstance(given, bool) or not isinstance(given, (int, float))
                                  or not math.isfinite(given) or given <= 0):
            raise GeometryError(f"{owner}: working_center_distance must be a positive number of mm, got {given!r}.")
        for label in ("gear1", "gear2"):
            if not isinstance(getattr(self, label), GearGeometry):
                raise GeometryError(f"{owner}: {label} must be a GearGeometry.")
        if self.gear1.internal:
            raise GeometryError(
                f"{owner}: gear1 must be the external gear of the pair; put the internal gear second."
            )
        r1, r2 = self.gear1.rack, self.gear2.rack
        if (r1.module, r1.pressure_angle, r1.helix_angle) != (r2.module, r2.pressure_angle, r2.helix_angle):
            raise GeometryError(
                f"{owner}: both gears must share module, pressure angle and helix angle, got "
                f"(m={r1.module}, α={r1.pressure_angle}°, β={r1.helix_angle}°) and "
                f"(m={r2.module}, α={r2.pressure_angle}°, β={r2.helix_angle}°)."
            )
        if self.internal and self.gear2.teeth <= self.gear1.teeth:
            raise GeometryError(
                f"{owner}: an internal gear must have more teeth than its pinion, got "
                f"z1={self.gear1.teeth}, z2={self.gear2.teeth}."
            )
        # Fail early if the profile shifts give no real operating pressure angle.
        try:
            if given is not None:  # the given centre distance decides: cos α_wt = a cos α_t / a_w
                ratio = self.reference_center_distance * math.cos(self.rack.alpha_t) / given
                if not 0.0 < ratio < 1.0:
                    raise ValueError("no operating pressure angle")
                alpha_wt = math.acos(ratio)
            else:
                alpha_wt = float(operating_pressure_angle(self._x_sum, self._z_sum, self.rack.alpha_n,
                                                          self.rack.alpha_t))
        except ValueError:
            alpha_wt = -1.0
        if given is not None and abs(given - self.reference_center_distance) > _MAX_Y * self.rack.module:
            raise GeometryError(
                f"{owner}: the centre distance {given!r} mm lies {abs(given - self.reference_center_distance) / self.rack.module:.3g} "
                f"modules from the reference a = {self.reference_center_distance:.4f} mm; a mesh runs within "
                f"±{_MAX_Y:g} modules of it (y = (a_w - a)/m_n)."
            )
        if not 0.0 < alpha_wt < math.pi / 2:
            if given is not None:
                raise GeometryError(
                    f"{owner}: the centre distance {given!r} mm is below a cos α_t = "
                    f"{self.reference_center_distance * math.cos(self.rack.alpha_t):.4f} mm; no involute mesh runs there."
                )
            raise GeometryError(
                f"{owner}: the profile-shift sum {self._x_sum:+.4f} gives no operating pressure angle for "
                f"z = {self.gear1.teeth}/{self.gear2.teeth} (inv α_wt would be negative); raise the shifts."
            )
        object.__setattr__(self, "_alpha_wt", alpha_wt)

    # ------------------------------------------------------------------ basics
    @classmethod
    def at_center_distance(
        cls,
        z1: int,
        z2: int,
        rack: BasicRack,
        center_distance: float,
        *,
        x1: float = 0.0,
        internal: bool = False,
        name: str = "",
    ) -> MeshGeometry:
        """The pair with gear 2's profile shift chosen so that it runs at ``center_distance``.

        Parameters
        ----------
        z1, z2 : int
            Tooth counts of gear 1 (the pinion or planet) and gear 2.
        rack : BasicRack
            Module, pressure and helix angle of both gears.
        center_distance : float
            Operating centre distance a_w, mm.
        x1 : float, default 0
            Profile shift of gear 1; gear 2 takes the rest of the needed sum.
        internal : bool, default False
            Gear 2 internal.
        name : str, default ""
            The mesh's name (e.g. ``"sun-planet"``).

        Returns
        -------
        MeshGeometry

        Raises
        ------
        GeometryError
            No profile shift sum gives that centre distance (inv α_wt < 0).

        References
        ----------
        ISO 21771:2007: inv α_wt = inv α_t + 2 (x1 ± x2) tan α_n / (z2 ± z1),
        a_w = a cos α_t / cos α_wt.

        Examples
        --------
        Drivetrain Hub force example: z = 15/45, m_n = 2.5, β = 20°, a = 80 mm:

        >>> mesh = MeshGeometry.at_center_distance(15, 45, BasicRack(2.5, helix_angle=20), 80.0)
        >>> round(mesh.operating_pitch_diameters[0], 3), round(mesh.operating_pressure_angle, 3)
        (40.0, 21.515)
        """
        z_sum = z2 - z1 if internal else z1 + z2
        try:
            total = profile_shift_sum(center_distance, z_sum, rack.module, rack.alpha_n, rack.beta)
        except ValueError as exc:
            raise GeometryError(f"MeshGeometry.at_center_distance: {exc}") from None
        x2 = -(total + x1) if internal else total - x1  # ISO sign of an internal gear 2
        return cls(GearGeometry(z1, rack, x1), GearGeometry(z2, rack, x2, internal=internal), name)

    @property
    def internal(self) -> bool:
        """Whether gear 2 is internal."""
        return self.gear2.internal

    @property
    def rack(self) -> BasicRack:
        return self.gear1.rack

    @property
    def _z_sum(self) -> int:
        return self.gear2.teeth - self.gear1.teeth if self.internal else self.gear1.teeth + self.gear2.teeth

    @property
    def _x_sum(self) -> float:
        # x2 − x1 in the KHK sign of the internal pair's formula = −(x1 + x2) with ISO's x2
        g1, g2 = self.gear1, self.gear2
        return -(g2.profile_shift + g1.profile_shift) if self.internal else g1.profile_shift + g2.profile_shift

    @property
    def reference_center_distance(self) -> float:
        """a = m_t (z2 ± z1)/2, mm (without profile shift)."""
        return self.rack.transverse_module * self._z_sum / 2.0

    @property
    def alpha_wt(self) -> float:
        """Operating transverse pressure angle, rad (from the given centre distance where there is one;
        computed once, at construction)."""
        return self._alpha_wt

    @property
    def operating_pressure_angle(self) -> float:
        """Operating transverse pressure angle α_wt, degrees."""
        return math.degrees(self.alpha_wt)

    @property
    def center_distance(self) -> float:
        """Operating centre distance a_w, mm (the given one, else the backlash-free one of the shifts)."""
        if self.working_center_distance is not None:
            return float(self.working_center_distance)
        return float(center_distance_from_angle(self.reference_center_distance, self.rack.alpha_t, self.alpha_wt))

    @property
    def backlash(self) -> float:
        """Normal backlash j_bn in the line of action, mm (< 0: the teeth jam at this centre distance).

        j_bn = 2 m_n sin α_n (Σx(a_w) − Σx_E), with Σx(a_w) the backlash-free shift sum
        at the centre distance and Σx_E the generating shifts (ISO 21771, z < 0 for an
        internal gear).  Zero for a pair at its own backlash-free distance without
        thickness allowances.

        References
        ----------
        ISO 21771:2007, eqs. (62), (63): Σx_E = Σx − j_bn / (2 m_n sin α_n).
        """
        rack, g1, g2 = self.rack, self.gear1, self.gear2
        need = profile_shift_sum(self.center_distance, self._z_sum, rack.module, rack.alpha_n, rack.beta)
        need = -need if self.internal else need  # ISO sum x1 + x2 with z2 < 0
        have = g1.generating_profile_shift + g2.generating_profile_shift
        return 2.0 * rack.module * math.sin(rack.alpha_n) * (need - have)

    @property
    def center_distance_modification(self) -> float:
        """y = (a_w − a)/m_n."""
        return (self.center_distance - self.reference_center_distance) / self.rack.module

    @property
    def tip_shortening(self) -> float:
        """Tip-shortening coefficient k = Σx − y ≥ 0 of an external pair (0 for an internal pair)."""
        if self.internal:
            return 0.0
        return max(0.0, self._x_sum - self.center_distance_modification)

    @property
    def operating_pitch_diameters(self) -> tuple[float, float]:
        """(d_w1, d_w2) = 2 a_w z_i / (z2 ± z1), mm."""
        a, zs = self.center_distance, self._z_sum
        return (2.0 * a * self.gear1.teeth / zs, 2.0 * a * self.gear2.teeth / zs)

    @property
    def operating_helix_angle(self) -> float:
        """β_w with tan β_w = tan β · d_w1/d_1, degrees (0 for spur gears)."""
        d_w1 = self.operating_pitch_diameters[0]
        return math.degrees(math.atan(math.tan(self.rack.beta) * d_w1 / self.gear1.reference_diameter))

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio ε_α.

        .. math:: \\varepsilon_\\alpha = \\frac{\\sqrt{r_{a1}^2 - r_{b1}^2} \\pm \\sqrt{r_{a2}^2 - r_{b2}^2}
                  \\mp a_w \\sin\\alpha_{wt}}{\\pi m_t \\cos\\alpha_t}

        (upper signs external, lower internal).

        References
        ----------
        ISO 21771:2007, ε_α = g_α / p_bt; SDP/SI D785, section 11 (contact ratio
        of external and internal pairs).
        """
        g1, g2 = self.gear1, self.gear2
        path1 = math.sqrt(max(0.0, (g1.tip_diameter / 2) ** 2 - (g1.base_diameter / 2) ** 2))
        path2 = math.sqrt(max(0.0, (g2.tip_diameter / 2) ** 2 - (g2.base_diameter / 2) ** 2))
        common = self.center_distance * math.sin(self.alpha_wt)
        length = path1 - path2 + common if self.internal else path1 + path2 - common
        base_pitch = math.pi * self.rack.transverse_module * math.cos(self.rack.alpha_t)
        return length / base_pitch

    def with_tip_shortening(self) -> MeshGeometry:
        """The pair with the tip shortening k applied to both gears (external pairs only)."""
        k = self.tip_shortening
        if k == 0.0:
            return self
        return replace(self, gear1=replace(self.gear1, tip_shortening=k), gear2=replace(self.gear2, tip_shortening=k))

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm, degrees)."""
        dw1, dw2 = self.operating_pitch_diameters
        return {
            "name": self.name,
            "internal": self.internal,
            "gear1": self.gear1.to_dict(),
            "gear2": self.gear2.to_dict(),
            "reference_center_distance": self.reference_center_distance,
            "center_distance": self.center_distance,
            "operating_pressure_angle": self.operating_pressure_angle,
            "operating_pitch_diameters": [dw1, dw2],
            "center_distance_modification": self.center_distance_modification,
            "tip_shortening": self.tip_shortening,
            "contact_ratio": self.contact_ratio,
            "operating_helix_angle": self.operating_helix_angle,
            "working_center_distance_given": self.working_center_distance is not None,
            "backlash": self.backlash,
        }

    def __repr__(self) -> str:
        kind = "internal" if self.internal else "external"
        return (
            f"MeshGeometry({self.name or kind!s}: z={self.gear1.teeth}/{self.gear2.teeth}, "
            f"a_w={self.center_distance:.4f} mm, α_wt={self.operating_pressure_angle:.4f}°, "
            f"ε_α={self.contact_ratio:.3f})"
        )

