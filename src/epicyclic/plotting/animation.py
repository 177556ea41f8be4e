"""Animation of a planetary set: real tooth counts and planet count, solved speeds.

Sun, ring, carrier and planets turn at the solved speeds, slowed down by one
common factor so the eye can follow (``slowdown`` = real speed / shown
speed, the same for every member, so the *relative* speeds are exact).  The
angle of member k after frame f is

.. math:: \\varphi_k(f) = \\varphi_{k,0} + 6\\,n_k\\,\\frac{f}{\\mathrm{fps}\\cdot\\mathrm{slowdown}}
   \\quad [°,\\ n_k \\text{ in } 1/\\mathrm{min}].

With ``willis=True`` the motion over one period is split into the three
superposed motions of the Willis derivation, shown one after another:
(1) the carrier turns by φ_T with the planets locked to it (the whole set
turns as one); (2) the planets turn about their own axes by −k·φ_T (rolling
on the sun); (3) with the carrier held the sun turns by φ_S and the planets by
k·φ_S; k = (n_p − n_c)/(n_s − n_c) = −z_s/z_p for a simple set.  The
second central member follows from i0 in each phase.  The three phases add up
to the real motion: φ_P = φ_T + (z_s/z_p)·φ_T − (z_s/z_p)·φ_S.

Output: a self-contained SVG (SMIL ``animateTransform``, plays offline in a
browser, no scripts or external URLs), the same wrapped in an HTML page, or a
GIF (matplotlib ``PillowWriter``).

References
----------
tec-science, "Willis-Gleichung", "Superposition der Bewegungen" (φ_P = φ_T + (d_S/d_P)·φ_T −
(d_S/d_P)·φ_S) and the animations of the planetary gear; Queitsch eq. 12.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from ._common import PlottingError, check_suffix, fmt, planetary_set
from .speed_plan import SetLayout, set_layout

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["GearShape", "PlanetaryAnimation", "planetary_animation", "gear_outline", "ANIMATION_SUFFIXES"]

#: Files :meth:`PlanetaryAnimation.save` writes.
ANIMATION_SUFFIXES = (".svg", ".html", ".gif")
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
    ``phase`` its start rotation (deg) chosen so that the teeth interlock.
    """

    member: str
    teeth: int | None
    radius: float
    internal: bool
    axis: float = 0.0
    offset: float = 0.0
    phase: float = 0.0
    step: bool = False


@dataclass(frozen=True)
class PlanetaryAnimation:
    """Angles per frame of every member of a set, and their drawings.

    Attributes
    ----------
    speeds : mapping member → 1/min
        ``sun``, ``ring``, ``carrier``, ``planet`` (and ``planet2`` for a
        double-planet set): the solved speeds.
    slowdown : float
        Real speed / shown speed (common to all members).
    fps : int
    frames : int
        Frames of one GIF loop (the SVG loops by itself).
    willis : bool
        Show the three superposed motions one after another.
    factors : mapping planet → k
        (n_planet − n_carrier)/(n_sun − n_carrier).
    i0 : float
    shapes : tuple of GearShape
    planets : int
    """

    set_name: str
    shafts: Mapping[str, str]
    speeds: Mapping[str, float]
    slowdown: float
    fps: int
    frames: int
    willis: bool
    factors: Mapping[str, float]
    i0: float
    shapes: tuple[GearShape, ...]
    planets: int
    layout: SetLayout

    # ------------------------------------------------------------- kinematics
    def degrees_per_second(self, member: str) -> float:
        """Shown angular speed (deg/s) of a member in continuous mode: 6·n/slowdown."""
        return 6.0 * self.speeds[member] / self.slowdown

    @property
    def phase_frames(self) -> int:
        """Frames per Willis phase (a third of the loop)."""
        return max(1, self.frames // 3)

    def angles(self, frame: float) -> dict[str, float]:
        """Absolute angle (deg) of every member after ``frame`` frames (start phases excluded).

        Continuous mode: 6·n·t/slowdown with t = frame/fps.  Willis mode: the
        real motion over one phase duration, split into the three phases.
        """
        members = list(self.speeds)
        if not self.willis:
            t = frame / self.fps
            return {m: self.degrees_per_second(m) * t for m in members}
        period = self.phase_frames / self.fps  # shown seconds whose real motion is decomposed
        phi_t = self.degrees_per_second("carrier") * period
        phi_s = self.degrees_per_second("sun") * period
        u = [min(max(frame / self.phase_frames - k, 0.0), 1.0) for k in range(3)]
        out = {"carrier": phi_t * u[0], "sun": phi_s * u[2],
               "ring": phi_t * u[0] + (-phi_t * u[1] + phi_s * u[2]) / self.i0}
        for planet, k in self.factors.items():
            out[planet] = phi_t * u[0] - k * phi_t * u[1] + k * phi_s * u[2]
        return out

    def step(self, frame: int = 0) -> dict[str, float]:
        """Angle change (deg) of every member from ``frame`` to ``frame + 1``."""
        a, b = self.angles(frame), self.angles(frame + 1)
        return {m: b[m] - a[m] for m in a}

    # ------------------------------------------------------------- output
    def to_dict(self) -> dict[str, Any]:
        return {"set": self.set_name, "speeds_1_per_min": dict(self.speeds), "slowdown": self.slowdown,
                "fps": self.fps, "frames": self.frames, "willis": self.willis, "planets": self.planets,
                "factors": dict(self.factors), "i0": self.i0}

    def _repr_html_(self) -> str:
        return self.svg()

    def __repr__(self) -> str:
        speeds = ", ".join(f"{m} {fmt(n, 5)}" for m, n in self.speeds.items())
        return (f"<PlanetaryAnimation {self.set_name!r}: {speeds} 1/min, slowed down {fmt(self.slowdown, 3)}×"
                f"{', Willis phases' if self.willis else ''}>")

    def svg(self) -> str:
        """A self-contained animated SVG (SMIL); plays offline in a browser."""
        from ._svg import animation_svg

        return animation_svg(self)

    def html(self) -> str:
        """A self-contained HTML page holding the animated SVG."""
        title = html.escape(f"{self.set_name}: planetary set animation")
        return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}</title></head>"
                f"<body style=\"font-family:sans-serif\"><h1 style=\"font-size:1.2em\">{title}</h1>\n"
                f"{self.svg()}\n</body></html>\n")

    def gif(self, path: str | Path, *, dpi: int = 60) -> Path:
        """Write the animation as GIF (matplotlib PillowWriter)."""
        from ._svg import write_gif

        return write_gif(self, Path(path), dpi)

    def save(self, path: str | Path) -> Path:
        """Write .svg, .html or .gif by suffix."""
        path = check_suffix(path, ANIMATION_SUFFIXES, "animation")
        path.parent.mkdir(parents=True, exist_ok=True)
        if path.suffix.lower() == ".gif":
            return self.gif(path)
        path.write_text(self.svg() if path.suffix.lower() == ".svg" else self.html(), encoding="utf-8")
        return path


def _phase(direction: float, rotation: float, z: int) -> float:
    """Tooth phase (0 = tooth centre, 0.5 = gap) of a gear at a direction, angles in rad."""
    return ((direction - rotation) * z / (2 * math.pi)) % 1.0


def _shapes(layout: SetLayout, teeth: Any, planets: int) -> tuple[GearShape, ...]:
    """Gears to draw, with start angles that make the teeth interlock (simple and stepped sets)."""
    zs = teeth.sun if teeth is not None else None
    zr = teeth.ring if teeth is not None else None
    zp = teeth.planet if teeth is not None else (None, None)
    rs, sun_internal = layout.central["sun"]
    rr, ring_internal = layout.central["ring"]
    shapes = [GearShape("sun", zs, rs, sun_internal), GearShape("ring", zr, rr, ring_internal)]
    bodies = layout.bodies
    for j in range(planets):
        theta = 360.0 * j / planets
        if len(bodies) == 2:  # double planet: planet 2 beside planet 1, centre distance (z1 + z2)·m/2
            b1, b2 = bodies
            r1, r2 = b1.axis - rs, rr - b2.axis
            cos_d = (b1.axis ** 2 + b2.axis ** 2 - (r1 + r2) ** 2) / (2 * b1.axis * b2.axis)
            delta = math.degrees(math.acos(max(-1.0, min(1.0, cos_d))))
            shapes.append(GearShape("planet", zp[0], r1, False, b1.axis, theta))
            shapes.append(GearShape("planet2", zp[1], r2, False, b2.axis, theta + delta))
            continue
        body = bodies[0]
        r_sun_side = abs(body.axis - body.contacts["sun"])
        r_ring_side = abs(body.contacts["ring"] - body.axis)
        z1 = zp[0] if teeth is not None else None
        z2 = (zp[1] if len(zp) > 1 else zp[0]) if teeth is not None else None
        phase = 0.0
        if z1 and zs and not sun_internal:
            th = math.radians(theta)
            f_s = _phase(th, 0.0, zs)
            phase = math.degrees((th + math.pi) - (2 * math.pi / z1) * (0.5 - f_s))
        shapes.append(GearShape("planet", z1, r_sun_side, False, body.axis, theta, phase))
        if abs(r_ring_side - r_sun_side) > 1e-9:
            shapes.append(GearShape("planet", z2, r_ring_side, False, body.axis, theta, phase, step=True))
    # the ring's start angle interlocks with the first planet (internal ring of a simple set)
    first = shapes[2]
    if teeth is not None and teeth.kind == "simple" and ring_internal and first.teeth and zr:
        th = math.radians(first.offset)
        f_p = _phase(th, math.radians(first.phase), first.teeth)
        shapes[1] = GearShape("ring", zr, rr, True, 0.0, 0.0, math.degrees(th - (2 * math.pi / zr) * (f_p - 0.5)))
    if ring_internal:  # drawing order: an internal ring behind everything, an external 2nd gear over the sun
        shapes[0], shapes[1] = shapes[1], shapes[0]
    return tuple(shapes)


def planetary_animation(
    solution: Solution,
    element: str | None = None,
    *,
    willis: bool = False,
    fps: int = 16,
    frames: int = 48,
    max_rev_per_s: float = 0.25,
) -> PlanetaryAnimation:
    """Build the animation of a planetary set at its solved speeds.

    Parameters
    ----------
    solution : Solution
    element : str, optional
        The planetary set (default: the first).
    willis : bool, default False
        Show the three superposed motions of the Willis derivation in turn.
    fps : int, default 16
    frames : int, default 48
        Frames of one GIF loop (three phases of frames/3 in Willis mode).
    max_rev_per_s : float, default 0.25
        Shown speed of the fastest member (sets the common slowdown).

    Raises
    ------
    PlottingError
        No planetary set of that name; fps, frames or max_rev_per_s not positive.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> anim = planetary_animation(solve(*brandenberger_1952()))
    >>> round(anim.step()["carrier"] * anim.fps * anim.slowdown / 6)  # 1/min
    5280
    """
    for name, value in (("fps", fps), ("frames", frames)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise PlottingError(f"animation: {name} must be a whole number ≥ 1, got {value!r}.")
    if isinstance(max_rev_per_s, bool) or not isinstance(max_rev_per_s, (int, float)) or not max_rev_per_s > 0:
        raise PlottingError(f"animation: max_rev_per_s must be a positive number, got {max_rev_per_s!r}.")
    if willis and frames < 3:
        raise PlottingError(f"animation: the Willis phases need frames ≥ 3, got {frames}.")
    pset = planetary_set(solution, element)
    state = solution.elements[pset.name]
    layout = set_layout(pset)
    n = state.speeds
    if state.planet_speeds:
        factors = dict(zip(("planet", "planet2"), pset.teeth.planet_factors))  # type: ignore[union-attr]
    else:
        body = layout.bodies[0]
        rs = body.contacts["sun"]
        factors = {"planet": rs / (rs - body.axis)}
    speeds = {"sun": n["sun"], "ring": n["ring"], "carrier": n["carrier"]}
    for planet, k in factors.items():
        speeds[planet] = n["carrier"] + k * (n["sun"] - n["carrier"])
    top = max(abs(v) for v in speeds.values())
    speeds = {m: (0.0 if abs(v) <= 1e-9 * top else v) for m, v in speeds.items()}  # round-off shown as rest
    fastest = top / 60.0  # rev/s
    slowdown = fastest / max_rev_per_s if fastest > 0 else 1.0
    shapes = _shapes(layout, pset.teeth, pset.planets)
    return PlanetaryAnimation(pset.name, MappingProxyType(dict(state.ports)), MappingProxyType(speeds), slowdown,
                              fps, frames, willis, MappingProxyType(factors), pset.stationary_ratio, shapes,
                              pset.planets, layout)


