"""Test dimensions of a cylindrical involute gear: span W_k, dimension over pins/balls M_d, chordal thickness.

The gear shop checks the tooth thickness indirectly. Every dimension here is a
function of the normal tooth thickness s_n at the reference circle, so the
allowances of s_n (upper A_sne, lower A_sni, DIN 3967) give the allowances of each
test dimension by evaluating it at s_n + A_sne and s_n + A_sni (exact, no
linearisation).  Units: mm; angles in rad inside, degrees where reported.

Formulas (ISO 21771:2007 / DIN 3960:1987; z, d > 0; ``x`` the ISO profile shift)::

    s_n   = m_n (π/2 + 2 x tan α_n)                       nominal normal tooth thickness
    W_k   = m_n cos α_n [(k − 1) π + s_n/m_n + z inv α_t]  (= m_n cos α_n [(k − ½) π + z inv α_t] + 2 x m_n sin α_n)
    k     = round( z/π [tan α_Mt / cos² β_b − 2 x tan α_n / z − inv α_t] + ½ ),
            cos α_Mt = d_b / (d + 2 x m_n)                 (anvils touch near d + 2 x m_n)
    inv α_Mt = inv α_t + D_M/(z m_n cos α_n) − π/z + s_n/(z m_n)           external gear
    inv α_Mt = inv α_t − D_M/(z m_n cos α_n) + (π m_n − s_n)/(z m_n)      internal gear
    d_M   = d_b / cos α_Mt;  M_d = d_M ± D_M (z even), d_M cos(90°/z) ± D_M (z odd)   (+ external, − internal)
    s̄_n  = d_n sin(s_n/d_n),  h̄_a = h_a + d_n/2 (1 − cos(s_n/d_n)),  d_n = d / cos² β_b   (external)

The ball's contact point lies at tan α_yt = tan α_Mt ∓ D_M cos β_b / d_b; the
standard ball diameter puts it on d + 2 x m_n (the middle of the tooth height,
as DIN 3960 recommends for the span).  The chordal thickness of a helical gear
is taken on its virtual spur gear of diameter d_n (ISO 21771's z_n = z/(cos² β_b cos β);
handbooks in the KHK tradition use z_v = z/cos³ β, a slightly different number).

References
----------
ISO 21771:2007, clause 5 (tooth thickness, span measurement W_k, dimension over
balls M_d, chordal tooth thickness); DIN 3960:1987, section 3.3 (Prüfmaße);
DIN 3967:1978 (tooth-thickness allowances); SDP/SI, *Elements of Metric Gear
Technology* (D785), section 10 (chordal thickness, span and over-pin methods).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.optimize import brentq

from .errors import GeometryError
from .gear import GearGeometry
from .involute import inv, inv_inverse

__all__ = ["nominal_thickness", "span_teeth", "base_tangent_length", "pin_dimension", "standard_pin_diameter",
           "chordal_thickness", "chordal_of_virtual_gear", "SpanMeasurement", "PinMeasurement",
           "ChordalThickness", "span_measurement", "pin_measurement", "chordal_measurement"]


def _cos_beta_b(gear: GearGeometry) -> float:
    rack = gear.rack
    return math.sqrt(1.0 - (math.sin(rack.beta) * math.cos(rack.alpha_n)) ** 2)


def nominal_thickness(gear: GearGeometry) -> float:
    """Nominal normal tooth thickness at the reference circle s_n = m_n (π/2 + 2 x tan α_n), mm (no allowance).

    Parameters
    ----------
    gear : GearGeometry

    Returns
    -------
    float
        s_n, mm.

    Examples
    --------
    SDP/SI D785 Table 10-1 (m = 10, x = +0.3): s = 17.8918 mm:

    >>> from epicyclic.geometry.gear import BasicRack
    >>> round(nominal_thickness(GearGeometry(12, BasicRack(10), 0.3)), 4)
    17.8918

    References
    ----------
    ISO 21771:2007, s_n = m_n (π/2 + 2 x tan α_n) (the same for an internal gear with x ISO).
    """
    return gear.rack.module * (math.pi / 2.0 + 2.0 * gear.profile_shift * math.tan(gear.rack.alpha_n))


def span_teeth(gear: GearGeometry) -> int:
    """The number of teeth k to span, chosen so that the anvils touch near d + 2 x m_n.

    Parameters
    ----------
    gear : GearGeometry
        An external gear.

    Returns
    -------
    int
        k ≥ 1 (and ≤ z − 1).

    Raises
    ------
    GeometryError
        An internal gear (its span is not measured with disc anvils; use :func:`pin_dimension`).

    Examples
    --------
    z = 20, x = 0, α = 20°: k = 3 (machinecalcs.com span calculator, printed k = 3):

    >>> from epicyclic.geometry.gear import BasicRack
    >>> span_teeth(GearGeometry(20, BasicRack(2.0)))
    3

    References
    ----------
    DIN 3960:1987, eq. (3.3.4): k = z/π (tan α_Mt / cos² β_b − 2 x tan α_n / z − inv α_t) + 0.5,
    cos α_Mt = d_b / (d + 2 x m_n); ISO 21771:2007, clause 5.
    """
    _external_only(gear, "span measurement W_k")
    rack, z = gear.rack, gear.teeth
    d_m = gear.reference_diameter + 2.0 * gear.profile_shift * rack.module
    alpha_m = math.acos(min(1.0, gear.base_diameter / d_m))
    k = z / math.pi * (math.tan(alpha_m) / _cos_beta_b(gear) ** 2 - 2.0 * gear.profile_shift
                       * math.tan(rack.alpha_n) / z - inv(rack.alpha_t)) + 0.5
    return int(min(max(round(k), 1), z - 1))


def _external_only(gear: GearGeometry, what: str) -> None:
    if not isinstance(gear, GearGeometry):
        raise GeometryError(f"{what}: expected a GearGeometry, got {type(gear).__name__}.")
    if gear.internal:
        raise GeometryError(f"{what}: defined here for external gears only; measure an internal gear "
                            "between balls (pin_dimension / M_d).")


def base_tangent_length(gear: GearGeometry, k: int | None = None, thickness: float | None = None) -> float:
    """Span measurement (base tangent length) W_k over k teeth, mm.

    Parameters
    ----------
    gear : GearGeometry
        An external gear.
    k : int, optional
        Teeth spanned (default :func:`span_teeth`).
    thickness : float, optional
        Normal tooth thickness s_n at the reference circle, mm (default the nominal one,
        :func:`nominal_thickness`; give s_n + A_sn for a limit).

    Returns
    -------
    float
        W_k, mm.

    Examples
    --------
    m = 2, z = 20, x = 0, α = 20°, k = 3: W = 15.321 mm (machinecalcs.com, printed):

    >>> from epicyclic.geometry.gear import BasicRack
    >>> round(base_tangent_length(GearGeometry(20, BasicRack(2.0))), 3)
    15.321

    References
    ----------
    ISO 21771:2007, clause 5: W_k = m_n cos α_n [(k − 0.5) π + z inv α_t] + 2 x m_n sin α_n;
    DIN 3960:1987, eq. (3.3.3).
    """
    _external_only(gear, "span measurement W_k")
    k = span_teeth(gear) if k is None else k
    if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k < gear.teeth:
        raise GeometryError(f"span measurement: k (teeth spanned) must be a whole number in 1 … z − 1 = "
                            f"{gear.teeth - 1}, got {k!r}.")
    rack = gear.rack
    s_n = nominal_thickness(gear) if thickness is None else thickness
    return rack.module * math.cos(rack.alpha_n) * ((k - 1) * math.pi + s_n / rack.module
                                                   + gear.teeth * inv(rack.alpha_t))


def _pin_angle(gear: GearGeometry, pin: float, s_n: float) -> float:
    """α_Mt of the ball centre, rad."""
    rack, z = gear.rack, gear.teeth
    term = pin / (z * rack.module * math.cos(rack.alpha_n))
    if gear.internal:
        value = inv(rack.alpha_t) - term + (math.pi * rack.module - s_n) / (z * rack.module)
    else:
        value = inv(rack.alpha_t) + term - math.pi / z + s_n / (z * rack.module)
    if value <= 0.0:
        raise GeometryError(f"dimension over balls: a ball of {pin:.4g} mm does not rest on the flanks of this "
                            f"{'internal' if gear.internal else 'external'} gear (inv α_M = {value:.4g} ≤ 0); "
                            "give a larger pin_diameter." if not gear.internal else
                            f"dimension between balls: a ball of {pin:.4g} mm does not fit the space "
                            f"(inv α_M = {value:.4g} ≤ 0); give a smaller pin_diameter.")
    return float(inv_inverse(value))


def pin_dimension(gear: GearGeometry, pin_diameter: float, thickness: float | None = None) -> float:
    """Dimension over (external) or between (internal) two balls or pins M_d, mm.

    Parameters
    ----------
    gear : GearGeometry
    pin_diameter : float
        Ball (pin) diameter D_M, mm.
    thickness : float, optional
        Normal tooth thickness s_n at the reference circle, mm (default nominal).

    Returns
    -------
    float
        M_d: over two balls in opposite spaces (z even) or in the nearest-to-opposite ones (z odd).

    Raises
    ------
    GeometryError
        A ball that cannot rest on both flanks of a space.

    Examples
    --------
    An unshifted gear measured with its standard ball reads close to d + D_M + a little:

    >>> from epicyclic.geometry.gear import BasicRack
    >>> g = GearGeometry(20, BasicRack(1.0))
    >>> 20.0 + 1.728 < pin_dimension(g, 1.728) < g.tip_diameter + 1.728
    True

    References
    ----------
    ISO 21771:2007, clause 5 (dimension over balls); DIN 3960:1987, eqs. (3.3.10)–(3.3.13):
    inv α_Mt = inv α_t ± D_M/(z m_n cos α_n) ∓ … ; M_d = d_M ± D_M (even z), d_M cos(90°/z) ± D_M (odd z).
    """
    if isinstance(pin_diameter, bool) or not isinstance(pin_diameter, (int, float)) \
            or not math.isfinite(pin_diameter) or pin_diameter <= 0:
        raise GeometryError(f"dimension over balls: pin_diameter must be a positive number of mm, "
                            f"got {pin_diameter!r}.")
    s_n = nominal_thickness(gear) if thickness is None else thickness
    alpha_m = _pin_angle(gear, pin_diameter, s_n)
    d_m = gear.base_diameter / math.cos(alpha_m)
    span = d_m if gear.teeth % 2 == 0 else d_m * math.cos(math.pi / (2 * gear.teeth))
    return span - pin_diameter if gear.internal else span + pin_diameter


def _contact_diameter(gear: GearGeometry, pin: float, s_n: float) -> float:
    """The diameter at which the ball touches the flank, mm."""
    alpha_m = _pin_angle(gear, pin, s_n)
    shift = pin * _cos_beta_b(gear) / gear.base_diameter
    tan_y = math.tan(alpha_m) + (shift if gear.internal else -shift)
    return gear.base_diameter * math.sqrt(1.0 + max(tan_y, 0.0) ** 2)


def standard_pin_diameter(gear: GearGeometry) -> float:
    """The ball diameter D_M that touches the flanks on d + 2 x m_n (d − 2 x m_n for an internal gear), mm.

    Parameters
    ----------
    gear : GearGeometry

    Returns
    -------
    float
        D_M, mm (round it to an available ball and pass that to :func:`pin_dimension`).

    Examples
    --------
    An unshifted spur gear's ball is close to π m / (2 cos α) = 1.672 m:

    >>> from epicyclic.geometry.gear import BasicRack
    >>> round(standard_pin_diameter(GearGeometry(2000, BasicRack(1.0))) , 3)
    1.672

    References
    ----------
    DIN 3960:1987, section 3.3 (measuring circle near d + 2 x m_n); ISO 21771:2007, clause 5;
    contact point tan α_yt = tan α_Mt ∓ D_M cos β_b / d_b (the flank normal lies in the base tangent plane).
    """
    s_n = nominal_thickness(gear)
    sign = -1.0 if gear.internal else 1.0
    target = gear.reference_diameter + sign * 2.0 * gear.profile_shift * gear.rack.module
    if target <= gear.base_diameter:
        target = 0.5 * (gear.base_diameter + gear.tip_diameter)
    m = gear.rack.module

    def miss(pin: float) -> float:
        return sign * (_contact_diameter(gear, pin, s_n) - target)

    rack, z = gear.rack, gear.teeth
    # the smallest external ball that rests on the flanks: inv α_M = 0 (below the base circle it would not)
    base_space = m * math.cos(rack.alpha_n) * (math.pi - s_n / m - z * inv(rack.alpha_t))
    low = max(0.05 * m, base_space * (1.0 + 1e-9)) if not gear.internal else 0.05 * m
    high = 4.0 * m
    if gear.internal:  # the largest internal ball that still touches the flanks: inv α_M = 0
        high = min(high, m * math.cos(rack.alpha_n) * (z * inv(rack.alpha_t) + math.pi - s_n / m) * (1 - 1e-9))
    try:
        return float(brentq(miss, low, high, xtol=1e-12))
    except (ValueError, GeometryError):
        raise GeometryError(f"standard ball diameter: no ball between {low:.3g} and {high:.3g} mm touches the "
                            f"flanks on d = {target:.4f} mm; give pin_diameter.") from None


def chordal_of_virtual_gear(thickness: float, virtual_diameter: float, addendum: float) -> tuple[float, float]:
    """Chordal thickness and chordal height of an arc thickness on a (virtual) spur gear of diameter d_n.

    Parameters
    ----------
    thickness : float
        Arc tooth thickness s_n on d_n, mm.
    virtual_diameter : float
        d_n, mm.
    addendum : float
        h_a (tip to reference circle), mm.

    Returns
    -------
    (float, float)
        s̄ = d_n sin(s/d_n), h̄ = h_a + d_n/2 (1 − cos(s/d_n)), mm.

    Examples
    --------
    SDP/SI D785 Table 10-1: m = 10, z = 12, x = +0.3: s̄ = 17.8256, h̄ = 13.6657 mm:

    >>> [round(v, 4) for v in chordal_of_virtual_gear(17.891843, 120.0, 13.0)]
    [17.8256, 13.6657]

    References
    ----------
    ISO 21771:2007, clause 5 (chordal tooth thickness); SDP/SI D785, Tables 10-1 and 10-3.
    """
    half = thickness / virtual_diameter
    return virtual_diameter * math.sin(half), addendum + virtual_diameter / 2.0 * (1.0 - math.cos(half))


def chordal_thickness(gear: GearGeometry, thickness: float | None = None) -> tuple[float, float]:
    """Chordal tooth thickness s̄_n and chordal height h̄_a at the reference circle, mm.

    Parameters
    ----------
    gear : GearGeometry
    thickness : float, optional
        s_n, mm (default nominal).

    Returns
    -------
    (float, float)
        (s̄_n, h̄_a).  For an internal gear the caliper rests on the tip corners of the
        tooth (the tip circle is concave): h̄_a = d_n/2 cos(s_n/d_n) − d_an/2 cos(s_an/d_an).

    References
    ----------
    ISO 21771:2007, clause 5 (virtual spur gear d_n = d / cos² β_b); DIN 3960:1987, eq. (3.3.16);
    SDP/SI D785, Table 10-1 (spur) and section 10.1 (internal gear, the tip-arc term).
    """
    s_n = nominal_thickness(gear) if thickness is None else thickness
    cos_bb = _cos_beta_b(gear)
    d_n = gear.reference_diameter / cos_bb ** 2
    if not gear.internal:
        return chordal_of_virtual_gear(s_n, d_n, (gear.tip_diameter - gear.reference_diameter) / 2.0)
    chord = d_n * math.sin(s_n / d_n)
    rack = gear.rack
    d, d_a = gear.reference_diameter, gear.tip_diameter
    alpha_a = math.acos(min(1.0, gear.base_diameter / d_a))
    s_at = d_a * (s_n / math.cos(rack.beta) / d - inv(rack.alpha_t) + inv(alpha_a))  # internal, x ISO
    s_an = s_at * math.cos(math.atan(math.tan(rack.beta) * d_a / d))
    d_an = d_n - (d - d_a)
    height = d_n / 2.0 * math.cos(s_n / d_n) - d_an / 2.0 * math.cos(max(s_an, 0.0) / d_an)
    return chord, height


@dataclass(frozen=True)
class SpanMeasurement:
    """W_k over k teeth with its limits from the tooth-thickness allowances, mm."""

    teeth_spanned: int
    nominal: float
    upper: float
    lower: float
    measuring_diameter: float

    @property
    def allowances(self) -> tuple[float, float]:
        """(A_Wke, A_Wki) = (A_sne, A_sni) cos α_n, mm."""
        return self.upper - self.nominal, self.lower - self.nominal


@dataclass(frozen=True)
class PinMeasurement:
    """M_d over (between) two balls of diameter D_M with its limits, mm."""

    pin_diameter: float
    nominal: float
    upper: float
    lower: float
    contact_diameter: float
    even: bool
    internal: bool

    @property
    def allowances(self) -> tuple[float, float]:
        """(A_Mde, A_Mdi), mm (for an internal gear a thinner tooth gives a larger M_d: signs swap)."""
        return self.upper - self.nominal, self.lower - self.nominal


@dataclass(frozen=True)
class ChordalThickness:
    """Chordal thickness s̄_n (nominal, upper, lower) at chordal height h̄_a, and the constant chord, mm."""

    nominal: float
    upper: float
    lower: float
    height: float
    constant_chord: float | None
    constant_chord_height: float | None


def _limits(gear: GearGeometry, lower_allowance: float) -> tuple[float, float, float]:
    s_n = nominal_thickness(gear)
    return s_n, s_n + gear.thickness_allowance, s_n + lower_allowance


def _check_lower(gear: GearGeometry, lower_allowance: float | None) -> float:
    if lower_allowance is None:
        return gear.thickness_allowance
    if isinstance(lower_allowance, bool) or not isinstance(lower_allowance, (int, float)) \
            or not math.isfinite(lower_allowance) or lower_allowance > gear.thickness_allowance:
        raise GeometryError(f"lower tooth-thickness allowance A_sni must be a number of mm ≤ the upper one "
                            f"A_sne = {gear.thickness_allowance:g}, got {lower_allowance!r}.")
    return float(lower_allowance)


def span_measurement(gear: GearGeometry, lower_allowance: float | None = None, k: int | None = None
                     ) -> SpanMeasurement:
    """W_k with the limits of the thickness allowances (upper: the gear's ``thickness_allowance``).

    Parameters
    ----------
    gear : GearGeometry
        An external gear.
    lower_allowance : float, optional
        A_sni ≤ A_sne, mm (default A_sne: no tolerance given).
    k : int, optional
        Teeth spanned (default :func:`span_teeth`).

    Returns
    -------
    SpanMeasurement

    References
    ----------
    ISO 21771:2007, clause 5; DIN 3960:1987 (A_Wk = A_sn cos α_n); DIN 3967:1978.
    """
    low = _check_lower(gear, lower_allowance)
    k = span_teeth(gear) if k is None else k
    s_n, s_up, s_low = _limits(gear, low)
    nominal = base_tangent_length(gear, k, s_n)
    diameter = math.hypot(gear.base_diameter, nominal * _cos_beta_b(gear))
    return SpanMeasurement(k, nominal, base_tangent_length(gear, k, s_up), base_tangent_length(gear, k, s_low),
                           diameter)


def pin_measurement(gear: GearGeometry, pin_diameter: float | None = None, lower_allowance: float | None = None
                    ) -> PinMeasurement:
    """M_d with its limits (upper: the gear's thickness allowance; lower: ``lower_allowance``).

    Parameters
    ----------
    gear : GearGeometry
    pin_diameter : float, optional
        D_M, mm (default :func:`standard_pin_diameter`).
    lower_allowance : float, optional
        A_sni, mm.

    Returns
    -------
    PinMeasurement
        ``upper`` belongs to the thickest tooth (s_n + A_sne), ``lower`` to the thinnest.

    References
    ----------
    ISO 21771:2007, clause 5; DIN 3960:1987, eqs. (3.3.10)–(3.3.13).
    """
    low = _check_lower(gear, lower_allowance)
    pin = standard_pin_diameter(gear) if pin_diameter is None else pin_diameter
    s_n, s_up, s_low = _limits(gear, low)
    return PinMeasurement(float(pin), pin_dimension(gear, pin, s_n), pin_dimension(gear, pin, s_up),
                          pin_dimension(gear, pin, s_low), _contact_diameter(gear, pin, s_n),
                          gear.teeth % 2 == 0, gear.internal)


def chordal_measurement(gear: GearGeometry, lower_allowance: float | None = None) -> ChordalThickness:
    """Chordal thickness at the reference circle (with limits) and the constant chord.

    Constant chord (external gears): s̄_c = s_n cos² α_n, h̄_c = h_a − s̄_c tan α_n / 2 (the
    rack touches the flanks on a chord independent of z); None for an internal gear.

    Parameters
    ----------
    gear : GearGeometry
    lower_allowance : float, optional
        A_sni, mm.

    Returns
    -------
    ChordalThickness

    References
    ----------
    ISO 21771:2007, clause 5; DIN 3960:1987, eqs. (3.3.16), (3.3.18) (constant chord).
    """
    low = _check_lower(gear, lower_allowance)
    s_n, s_up, s_low = _limits(gear, low)
    chord, height = chordal_thickness(gear, s_n)
    s_c = h_c = None
    if not gear.internal:
        alpha = gear.rack.alpha_n
        s_c = s_n * math.cos(alpha) ** 2
        h_c = (gear.tip_diameter - gear.reference_diameter) / 2.0 - 0.5 * s_c * math.tan(alpha)
    return ChordalThickness(chord, chordal_thickness(gear, s_up)[0], chordal_thickness(gear, s_low)[0], height,
                            s_c, h_c)
