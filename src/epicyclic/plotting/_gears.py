"""Gears to draw: outlines with trapezoidal teeth, and the gears of a set placed to interlock.

Shared by the animation's data (:mod:`.animation`) and its drawing
(:mod:`._svg`); neither imports the other's module, so both import this one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ..model.planetary import Teeth
    from .speed_plan import SetLayout

__all__ = ["GearShape", "gear_outline", "gear_shapes", "WILLIS_PHASES", "extent"]

#: Names of the three Willis phases.
WILLIS_PHASES = ("1: carrier turns, planets locked to it", "2: planets turn about their own axes",
                 "3: carrier held, sun turns")


def gear_outline(z: int | None, radius: float, internal: bool = False, points_per_tooth: int = 4) -> list[tuple[float, float]]:
    """Outline of a gear centred at the origin: z trapezoidal teeth on the pitch circle.

    Addendum m, dedendum 1.25 m with m = 2·radius/z; an internal gear's teeth
    point inwards.  Without a tooth count a plain circle (72 points).
    """
    if not z:
        return [(radius * math.cos(2 * math.pi * k / 72), radius * math.sin(2 * math.pi * k / 72)) for k in range(72)]
    m = 2 * radius / z
    tip, root = (radius - m, radius + 1.25 * m) if internal else (radius + m, radius - 1.25 * m)
    pitch = 2 * math.pi / z
    pts = []
    for k in range(z):
        c = k * pitch
        for angle, r in ((c - 0.5 * pitch, root), (c - 0.3 * pitch, root), (c - 0.13 * pitch, tip),
                         (c + 0.13 * pitch, tip), (c + 0.3 * pitch, root)):
            pts.append((r * math.cos(angle), r * math.sin(angle)))
    return pts


@dataclass(frozen=True)
class GearShape:
    """A gear to draw: its member, tooth count, pitch radius, centre and start angle.

    ``axis`` is the distance of its centre from the central axis (0 for sun
    and ring), ``offset`` the angle (deg) of its centre about the carrier,
    ``phase`` its start rotation (deg) chosen so that the teeth interlock;
    ``step`` marks the second gear of a stepped planet.
    """

    member: str
    teeth: int | None
    radius: float
    internal: bool
    axis: float = 0.0
    offset: float = 0.0
    phase: float = 0.0
    step: bool = False

    @property
    def module(self) -> float:
        """Module of the drawn teeth (same length unit as the radius)."""
        return 2 * self.radius / self.teeth if self.teeth else 0.05 * self.radius


def extent(shapes: tuple[GearShape, ...]) -> float:
    """Radius of a circle holding every gear, with its teeth and the ring's rim."""
    r = 0.0
    for s in shapes:
        rim = 3.5 * s.module if s.member == "ring" and s.internal else 1.5 * s.module
        r = max(r, s.axis + s.radius + rim)
    return r * 1.04


def _phase(direction: float, rotation: float, z: int) -> float:
    """Tooth phase (0 = tooth centre, 0.5 = gap) of a gear at a direction, angles in rad."""
    return ((direction - rotation) * z / (2 * math.pi)) % 1.0


def gear_shapes(layout: SetLayout, teeth: Teeth, planets: int) -> tuple[GearShape, ...]:
    """Gears of a set to draw, in drawing roles (``sun`` = the drawn sun), teeth interlocking.

    ``layout`` gives the radii by port; for a set drawn with swapped roles
    (its "sun" port the larger, internal gear) the drawn sun is the ``ring``
    port's gear.
    """
    roles = layout.drawn.roles if layout.drawn is not None else {"sun": "sun", "ring": "ring"}
    zs, zr, zp = teeth.sun, teeth.ring, teeth.planet
    rs, sun_internal = layout.central[roles["sun"]]
    rr, ring_internal = layout.central[roles["ring"]]
    shapes = [GearShape("sun", zs, rs, sun_internal), GearShape("ring", zr, rr, ring_internal)]
    bodies = layout.bodies
    for j in range(planets):
        theta = 360.0 * j / planets
        if len(bodies) == 2:  # double planet: planet 2 beside planet 1, centre distance (z1 + z2)·m/2
            b1, b2 = bodies  # planet 1 meshes the drawn sun, planet 2 the drawn ring
            r1, r2 = b1.axis - rs, rr - b2.axis
            cos_d = (b1.axis ** 2 + b2.axis ** 2 - (r1 + r2) ** 2) / (2 * b1.axis * b2.axis)
            delta = math.degrees(math.acos(max(-1.0, min(1.0, cos_d))))
            shapes.append(GearShape("planet", zp[0], r1, False, b1.axis, theta))
            shapes.append(GearShape("planet2", zp[1], r2, False, b2.axis, theta + delta))
            continue
        body = bodies[0]
        r_sun_side = abs(body.axis - body.contacts[roles["sun"]])
        r_ring_side = abs(body.contacts[roles["ring"]] - body.axis)
        z1, z2 = zp[0], zp[-1]
        phase = 0.0
        if z1 and zs and not sun_internal:
            th = math.radians(theta)
            f_s = _phase(th, 0.0, zs)
            phase = math.degrees((th + math.pi) - (2 * math.pi / z1) * (0.5 - f_s))
        shapes.append(GearShape("planet", z1, r_sun_side, False, body.axis, theta, phase))
        if teeth.kind == "stepped":
            shapes.append(GearShape("planet", z2, r_ring_side, False, body.axis, theta, phase, step=True))
    # the ring's start angle interlocks with the first planet (internal ring of a simple set)
    first = shapes[2]
    if teeth.kind == "simple" and ring_internal and first.teeth and zr:
        th = math.radians(first.offset)
        f_p = _phase(th, math.radians(first.phase), first.teeth)
        shapes[1] = GearShape("ring", zr, rr, True, 0.0, 0.0, math.degrees(th - (2 * math.pi / zr) * (f_p - 0.5)))
    if ring_internal:  # drawing order: an internal ring behind everything, an external 2nd gear over the sun
        shapes[0], shapes[1] = shapes[1], shapes[0]
    return tuple(shapes)
