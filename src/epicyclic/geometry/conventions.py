"""Sign conventions of an internal gear's profile shift: ISO 21771 (default) and KHK / SDP-SI.

ISO 21771 and DIN 3960 (and with them KISSsoft and REXS) write an internal gear
with z < 0, so its profile-shift coefficient keeps one formula for all pairs,
inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2): a *negative* x of an internal
gear enlarges its tip circle and the centre distance.  Handbooks in the KHK /
SDP-SI tradition write z > 0 and inv α_w = inv α + 2 tan α (x2 − x1)/(z2 − z1), so
x_KHK = −x_ISO.  A file says which it uses with
``geometry.internal_shift_convention = "iso" | "khk"`` (default ``"iso"``).

References
----------
ISO 21771:2007 (internal gears, z < 0); DIN 3960:1987; SDP/SI D785, Table 5-1 (KHK sign).
"""

from __future__ import annotations

from .errors import GeometryError

__all__ = ["SHIFT_CONVENTIONS", "iso_profile_shift"]


#: Sign conventions of an internal gear's profile shift: ISO 21771 (default) and KHK / SDP-SI.
SHIFT_CONVENTIONS = {
    "iso": "ISO 21771 / DIN 3960 (KISSsoft, REXS): x < 0 of an internal gear enlarges its tip circle",
    "khk": "KHK / SDP-SI: x > 0 of an internal gear enlarges its tip circle (x_KHK = -x_ISO)",
}


def iso_profile_shift(x: float, internal: bool, convention: str = "iso") -> float:
    """The ISO 21771 profile-shift coefficient of a gear given in ``convention``.

    External gears have one sign in both conventions; an internal gear's KHK value
    is the negative of its ISO value.

    Parameters
    ----------
    x : float
        The coefficient as given.
    internal : bool
        Whether the gear is internal.
    convention : {"iso", "khk"}
        The convention ``x`` is written in.

    Returns
    -------
    float
        x in the ISO 21771 sign.

    Raises
    ------
    GeometryError
        An unknown convention.

    Examples
    --------
    >>> iso_profile_shift(0.516, internal=True, convention="khk"), iso_profile_shift(0.5, internal=False, convention="khk")
    (-0.516, 0.5)

    References
    ----------
    ISO 21771:2007 (internal gears: z < 0, inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2));
    SDP/SI D785, Table 5-1 (inv α_w = 2 tan α (x2 − x1)/(z2 − z1) + inv α).
    """
    if convention not in SHIFT_CONVENTIONS:
        raise GeometryError(f"internal_shift_convention must be one of {', '.join(map(repr, SHIFT_CONVENTIONS))}, "
                            f"got {convention!r}.")
    return -x if (internal and convention == "khk") else x
