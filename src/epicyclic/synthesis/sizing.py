"""Module and face width of each set from the torque it carries: a Lewis pre-dimensioning.

Until the load-capacity rating (ISO 6336) sizes the sets, every synthesised
candidate gets a module and a face width from its own torques, so that its
train file carries real geometry (``epicyclic fit`` checks it, ``analyze``
solves it).  For each simple set:

* the largest sun torque T_sun over all gears (drive, from the project's
  solver, × the given input torque) is shared by the N planets, so the
  tangential force at the sun mesh is F_t = 2·T_sun / (N·m·z_sun); the planet
  passes the same force on to the ring;
* the face width is b = k·m (k = ``face_width_factor``; Shigley's rule of thumb
  3p ≤ b ≤ 5p is k = 9.4 … 15.7);
* the Lewis bending stress σ = F_t / (b·m·Y) (Lewis 1892; Budynas & Nisbett,
  *Shigley's Mechanical Engineering Design*, eq. 14-3) on the weaker of sun and
  planet (the smaller form factor Y of Table 14-2, 20° full depth) must not
  exceed the allowable stress, so m³ ≥ 2·T_sun / (N·k·Y·z_sun·σ_allow);
* the module is the smallest of ISO 54 series I that meets it.

It is a pre-dimensioning: no dynamic, load-distribution or life factors, no
contact stress, internal teeth (stronger in bending) not checked.  The
allowable stress stands for all of them; the default, 200 MPa, is about half
the bending endurance of case-hardened gear steel.

References
----------
Lewis, W. (1892), "Investigation of the strength of gear teeth", Proc. Engineers Club of
Philadelphia; Budynas, R. G.; Nisbett, J. K., *Shigley's Mechanical Engineering Design*,
eq. (14-3), Table 14-2 (Lewis form factor, 20°, full depth) and Example 14-1; ISO 54:1996
(modules, series I).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["LEWIS_FORM_FACTORS", "MODULES", "SetSize", "lewis_form_factor", "lewis_stress", "minimum_module",
           "size_set"]

#: Lewis form factor Y by number of teeth, 20° pressure angle, full-depth teeth (Shigley Table 14-2).
LEWIS_FORM_FACTORS: tuple[tuple[int, float], ...] = (
    (12, 0.245), (13, 0.261), (14, 0.277), (15, 0.290), (16, 0.296), (17, 0.303), (18, 0.309), (19, 0.314),
    (20, 0.322), (21, 0.328), (22, 0.331), (24, 0.337), (26, 0.346), (28, 0.353), (30, 0.359), (34, 0.371),
    (38, 0.384), (43, 0.397), (50, 0.409), (60, 0.422), (75, 0.435), (100, 0.447), (150, 0.460), (300, 0.472),
    (400, 0.480))

#: Modules of ISO 54 series I, mm.
MODULES: tuple[float, ...] = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0,
                              32.0, 40.0, 50.0)


def lewis_form_factor(teeth: int) -> float:
    """Y of Table 14-2 (Shigley), linear between its rows; 0.480 past 400 teeth.

    Parameters
    ----------
    teeth : int
        At least 12 (the table's first row).

    Raises
    ------
    ValueError
        Fewer than 12 teeth.

    >>> lewis_form_factor(16), round(lewis_form_factor(23), 4)
    (0.296, 0.334)
    """
    if teeth < LEWIS_FORM_FACTORS[0][0]:
        raise ValueError(f"the Lewis form factor table starts at 12 teeth, got {teeth}")
    for (z0, y0), (z1, y1) in zip(LEWIS_FORM_FACTORS, LEWIS_FORM_FACTORS[1:]):
        if z0 <= teeth <= z1:
            return y0 + (y1 - y0) * (teeth - z0) / (z1 - z0)
    return LEWIS_FORM_FACTORS[-1][1]


def lewis_stress(force: float, face_width: float, module: float, form_factor: float) -> float:
    """Lewis bending stress σ = F_t / (b·m·Y) (Shigley eq. 14-3 in modules), MPa for N and mm.

    Parameters
    ----------
    force : float
        Tangential force F_t, N.
    face_width, module : float
        b and m, mm.
    form_factor : float
        Lewis Y.
    """
    return force / (face_width * module * form_factor)


@dataclass(frozen=True)
class SetSize:
    """Module and face width of one set, and the figures they come from.

    Attributes
    ----------
    module, face_width : float
        mm.
    sun_torque : float
        Largest sun torque over the gears, N·m.
    stress : float
        Lewis bending stress at this module, MPa (≤ the allowable stress).
    """

    module: float
    face_width: float
    sun_torque: float
    stress: float

    def to_dict(self) -> dict:
        """``module`` and ``face_width`` (mm), ``sun_torque`` (N·m), ``stress`` (MPa)."""
        return {"module": self.module, "face_width": self.face_width, "sun_torque": self.sun_torque,
                "stress": self.stress}


def size_set(sun_torque: float, z_sun: int, z_planet: int, planets: int, allowable_stress: float = 200.0,
             face_width_factor: float = 10.0) -> SetSize:
    """The smallest ISO 54 series I module whose Lewis stress stays within ``allowable_stress``.

    Parameters
    ----------
    sun_torque : float
        N·m (its magnitude is used).
    z_sun, z_planet, planets : int
        Teeth and number of planets.
    allowable_stress : float, default 200
        MPa.
    face_width_factor : float, default 10
        b / m.

    Returns
    -------
    SetSize

    Raises
    ------
    ValueError
        No module of the series is large enough (a torque beyond this pre-dimensioning).

    Examples
    --------
    >>> s = size_set(300.0, 40, 20, 3)   # F_t = 2·300 000 N·mm / (3·m·40)
    >>> s.module, s.face_width, round(s.stress, 1)
    (2.0, 20.0, 194.1)
    """
    y = min(lewis_form_factor(z_sun), lewis_form_factor(z_planet))
    torque = abs(sun_torque) * 1000.0  # N·mm
    for m in MODULES:
        force = 2.0 * torque / (planets * m * z_sun)
        stress = lewis_stress(force, face_width_factor * m, m, y)
        if stress <= allowable_stress * (1 + 1e-12):
            return SetSize(m, face_width_factor * m, abs(sun_torque), stress)
    raise ValueError(f"a sun torque of {abs(sun_torque):.4g} N·m needs a module above {MODULES[-1]:g} mm")


def minimum_module(sun_torque: float, z_sun: int, z_planet: int, planets: int, allowable_stress: float,
                   face_width_factor: float) -> float:
    """The exact (not rounded) module m = (2·T / (N·k·Y·z_sun·σ))^(1/3), mm.

    Parameters
    ----------
    sun_torque : float
        N·m.
    z_sun, z_planet, planets : int
    allowable_stress : float
        MPa.
    face_width_factor : float
        b / m.
    """
    y = min(lewis_form_factor(z_sun), lewis_form_factor(z_planet))
    return (2.0 * abs(sun_torque) * 1000.0 / (planets * face_width_factor * y * z_sun * allowable_stress)) ** (1 / 3)

