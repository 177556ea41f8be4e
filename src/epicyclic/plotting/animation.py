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
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from ..limits import SIZE_RANGE
from ._common import PlottingError, check_suffix, planetary_set
from ._gears import WILLIS_PHASES, GearShape, gear_outline, gear_shapes
from .context import FigureContext
from .speed_plan import SetLayout, set_layout
from .values import Scales, clean, fmt

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["GearShape", "PlanetaryAnimation", "planetary_animation", "gear_outline", "ANIMATION_SUFFIXES",
           "WILLIS_PHASES", "DEFAULT_SIZE"]

#: Files :meth:`PlanetaryAnimation.save` writes.
ANIMATION_SUFFIXES = (".svg", ".html", ".gif")
#: Width of the SVG and the GIF in pixels unless ``size`` says otherwise.
DEFAULT_SIZE = 480
#: Smallest and largest ``size`` in pixels (``epicyclic.limits.SIZE_RANGE``).
SIZE_LIMITS = SIZE_RANGE


@dataclass(frozen=True)
class PlanetaryAnimation:
    """Angles per frame of every member of a set, and their drawings.

    Members are the *drawn* gears: ``sun`` (the smaller central gear of the
    drawing), ``ring``, ``carrier``, ``planet`` (and ``planet2`` for a double
    planet); ``shafts`` names the port and shaft each one belongs to.

    Attributes
    ----------
    speeds : mapping member → 1/min
        The solved speeds (round-off shown as 0 by the zero rule).
    slowdown : float
        Real speed / shown speed (common to all members).
    fps : int
    frames : int
        Frames of one GIF loop (the SVG loops by itself).
    willis : bool
        Show the three superposed motions one after another.
    factors : mapping planet → k
        (n_planet − n_carrier)/(n_sun − n_carrier) of the drawn gears.
    i0 : float
        (n_sun − n_carrier)/(n_ring − n_carrier) of the drawn gears.
    shapes : tuple of GearShape
    planets : int
    schematic : str
        Empty for a set drawn with its own teeth, else what was chosen.
    schematic_planets : bool
        The planet speeds are those of the drawn teeth (a set given by i0 alone: the file gives
        no planet teeth, so no planet speed); the caption says so.
    size : int
        Width of the SVG and GIF in pixels.
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
    schematic: str = ""
    size: int = DEFAULT_SIZE
    context: FigureContext = field(default_factory=FigureContext)
    heading: str = ""
    schematic_planets: bool = False

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

    # ------------------------------------------------------------- words
    def caption(self) -> list[str]:
        """The lines under the drawing: speeds in the figure's unit, planets, slowdown, assumptions."""
        ctx = self.context
        unit = ctx.unit("speed")
        central = [f"{m} ({self.shafts[m]}): {fmt(ctx.convert(n, 'speed'), 5)} {unit}"
                   for m, n in self.speeds.items() if m in ("sun", "ring", "carrier")]
        # a set given by i0 alone has no planet teeth: its planet speed is that of the drawn (chosen) teeth
        made_up = " (schematic: of the drawn teeth, not in the file)" if self.schematic_planets else ""
        planets = [f"{m.replace('planet2', 'planet 2')}: {fmt(ctx.convert(n, 'speed'), 5)} {unit}{made_up}"
                   for m, n in self.speeds.items() if m.startswith("planet")]
        moving = any(self.speeds.values())
        motion = f"shown {self.pace}" if moving else "the set stands still in this state"
        lines = [", ".join(central), ", ".join(planets) + f"; {self.planets} planets; {motion}"]
        if self.schematic:
            lines.append(self.schematic)
        return lines

    # ------------------------------------------------------------- output
    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of the animation (speeds in 1/min, not the drawn shapes).

        Returns
        -------
        dict
            ``set``, ``speeds_1_per_min`` (member → speed), ``slowdown``, ``fps``, ``frames``,
            ``willis`` (phase mode), ``planets``, ``factors`` (planet speed per carrier-relative
            sun speed), ``i0``, ``schematic`` and ``size`` (pixels).
        """
        return {"set": self.set_name, "speeds_1_per_min": dict(self.speeds), "slowdown": self.slowdown,
                "fps": self.fps, "frames": self.frames, "willis": self.willis, "planets": self.planets,
                "factors": dict(self.factors), "i0": self.i0, "schematic": self.schematic, "size": self.size}

    def _repr_html_(self) -> str:
        return self.svg()

    @property
    def pace(self) -> str:
        """How the animation's time relates to the real one: ``"slowed down 705×"`` or, for a set slower than
        one turn per loop, ``"sped up 15×"`` (never "slowed down 0.0667×")."""
        if self.slowdown >= 1:
            return f"slowed down {fmt(self.slowdown, 3)}×"
        return f"sped up {fmt(1 / self.slowdown, 3)}×"

    def __repr__(self) -> str:
        speeds = ", ".join(f"{m} {fmt(n, 5)}" for m, n in self.speeds.items())
        return (f"<PlanetaryAnimation {self.set_name!r}: {speeds} 1/min, {self.pace}"
                f"{', Willis phases' if self.willis else ''}{', schematic' if self.schematic else ''}>")

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

    def gif(self, path: str | Path, *, dpi: int = 80) -> Path:
        """Write the animation as GIF (matplotlib PillowWriter), ``size`` pixels wide.

        Parameters
        ----------
        path : str or Path
            The file to write.
        dpi : int, default 80
            Resolution the frames are drawn at (the width stays ``size`` pixels; the text
            scales with it).

        Returns
        -------
        Path
            ``path``.
        """
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


def planetary_animation(
    solution: Solution,
    element: str | None = None,
    *,
    willis: bool = False,
    fps: int = 16,
    frames: int = 48,
    max_rev_per_s: float = 0.25,
    size: int = DEFAULT_SIZE,
    context: FigureContext | None = None,
) -> PlanetaryAnimation:
    """Build the animation of a planetary set at its solved speeds.

    A set given by i0 alone is drawn as the schematic set of
    :func:`~epicyclic.plotting.schematic.drawn_set`, and the caption says so.

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
    size : int, default 480
        Width of the SVG and GIF in pixels (120 … 2000).
    context : FigureContext, optional
        Title, gear, units of the caption.

    Raises
    ------
    PlottingError
        No planetary set of that name; fps, frames, size or max_rev_per_s out of range.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> anim = planetary_animation(solve(*brandenberger_1952()))
    >>> round(anim.step()["carrier"] * anim.fps * anim.slowdown / 6)  # 1/min
    5280
    """
    for name, value in (("fps", fps), ("frames", frames), ("size", size)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise PlottingError(f"animation: {name} must be a whole number ≥ 1, got {value!r}.")
    if not SIZE_LIMITS[0] <= size <= SIZE_LIMITS[1]:
        raise PlottingError(f"animation: size must be between {SIZE_LIMITS[0]} and {SIZE_LIMITS[1]} pixels, "
                            f"got {size}.")
    if isinstance(max_rev_per_s, bool) or not isinstance(max_rev_per_s, (int, float)) or not max_rev_per_s > 0:
        raise PlottingError(f"animation: max_rev_per_s must be a positive number, got {max_rev_per_s!r}.")
    if willis and frames < 3:
        raise PlottingError(f"animation: the Willis phases need frames ≥ 3, got {frames}.")
    pset = planetary_set(solution, element)
    state = solution.elements[pset.name]
    layout = set_layout(pset)
    drawn = layout.drawn
    assert drawn is not None
    scale = Scales.of(solution).speed
    n = {port: clean(v, scale) for port, v in state.speeds.items()}
    roles = {"sun": drawn.roles["sun"], "ring": drawn.roles["ring"], "carrier": "carrier"}
    speeds = {member: n[port] for member, port in roles.items()}
    planet_speeds = state.planet_speeds if state.planet_speeds else drawn.planet_speeds(n)
    members = ("planet", "planet2")[: len(drawn.teeth.planet_factors)]
    factors = dict(zip(members, drawn.teeth.planet_factors))
    for member, value in zip(members, planet_speeds):
        speeds[member] = clean(value, scale)
    top = max(abs(v) for v in speeds.values())
    fastest = top / 60.0  # rev/s
    slowdown = fastest / max_rev_per_s if fastest > 0 else 1.0
    i0 = pset.stationary_ratio if not drawn.swapped else 1.0 / pset.stationary_ratio
    shapes = gear_shapes(layout, drawn.teeth, pset.planets)
    shafts = {member: f"{port}: {state.ports[port]}" if port != member else state.ports[port]
              for member, port in roles.items()}
    note = ""
    if drawn.schematic:
        t = drawn.teeth
        teeth = "/".join(str(z) for z in (t.sun, *t.planet, t.ring))
        note = (f"schematic {t.kind} set {teeth}: the file gives i0 = {fmt(pset.stationary_ratio, 5)} only"
                + ("" if drawn.exact else " (nearest drawable teeth)"))
    context = context or FigureContext(title=solution.train.name)
    heading = context.heading(solution.train, f"set {pset.name}")
    return PlanetaryAnimation(pset.name, MappingProxyType(shafts), MappingProxyType(speeds), slowdown,
                              fps, frames, willis, MappingProxyType(factors), i0, shapes, pset.planets, layout,
                              note, size, context, heading, bool(drawn.schematic and not state.planet_speeds))
