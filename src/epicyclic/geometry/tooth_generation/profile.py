"""The transverse profile of one tooth as its tool generates it: :class:`ToothProfile`.

The generated curves of every tool segment (:mod:`.envelope`) are joined into the tooth's boundary:
at each radius the material left is bounded by the farthest any tool point reached, so a curve part
that another segment cuts away (undercut, the protuberance's relief, the loops of a trochoid) is
dropped, and the flank ends at the tip circle.

References
----------
Litvin & Fuentes 2004, ch. 6, 10, 11; ISO 21771:2007 (tooth thickness, root and tip circles).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq

from .._render import html_table, text_table
from ..errors import GeometryError
from .envelope import Generation, Segment
from .tools import PinionCutter, RackTool

__all__ = ["FilletCurve", "SEGMENT_NAMES", "ToothProfile", "assemble"]

#: The segments a profile's points belong to, from the root to the tip.
SEGMENT_NAMES = ("root", "fillet", "protuberance", "involute", "tip")


def _rotate(points: np.ndarray, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.stack([c * points[..., 0] - s * points[..., 1], s * points[..., 0] + c * points[..., 1]], axis=-1)


@dataclass(frozen=True)
class FilletCurve:
    """The generated root fillet of the tooth's left flank as a closed-form curve of the tool parameter.

    Points are in the tooth frame (tooth centreline on the +y axis, the left flank at x < 0), mm.

    Attributes
    ----------
    generation : Generation
        The generating motion.
    segment : Segment
        The tool's tip round.
    low, high : float
        The parameter range that is part of the tooth (root side first).
    offset : float
        π/z, the rotation from the space-centred to the tooth-centred frame, rad.
    """

    generation: Generation
    segment: Segment
    low: float
    high: float
    offset: float

    def points(self, t) -> np.ndarray:
        """Fillet points at parameters ``t`` (array), tooth frame, mm."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        return _rotate(self.generation.curve(self.segment, t), self.offset)

    def _derivatives(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        h = 1e-4 * max(1.0, abs(self.high - self.low))
        p = self.points(np.array([t - h, t, t + h]))
        return (p[2] - p[0]) / (2 * h), (p[2] - 2 * p[1] + p[0]) / (h * h)

    def tangent_angle(self, t: float) -> float:
        """The angle between the fillet's tangent at ``t`` and the tooth centreline, rad (0 … π/2).

        Parameters
        ----------
        t : float
            Tool parameter.

        Returns
        -------
        float
        """
        d, _ = self._derivatives(t)
        return math.atan2(abs(d[0]), abs(d[1]))

    def curvature_radius(self, t: float) -> float:
        """The fillet's radius of curvature at ``t``, mm.

        Parameters
        ----------
        t : float
            Tool parameter.

        Returns
        -------
        float
        """
        d, dd = self._derivatives(t)
        cross = d[0] * dd[1] - d[1] * dd[0]
        return float(np.hypot(*d) ** 3 / abs(cross)) if cross else math.inf

    def at_tangent_angle(self, angle: float) -> float:
        """The parameter where the tangent makes ``angle`` (rad) with the tooth centreline.

        Parameters
        ----------
        angle : float
            0 < angle < π/2 (ISO 6336-3: 30° for external gears, 60° for internal gears).

        Returns
        -------
        float
            The tool parameter.

        Raises
        ------
        GeometryError
            No point of the fillet has that tangent (the fillet is too short: an undercut flank, or a
            tooth whose flank starts steeper).
        """
        f = lambda t: self.tangent_angle(t) - angle  # noqa: E731
        ts = np.linspace(self.low, self.high, 201)
        values = np.array([f(t) for t in ts])
        change = np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
        if not len(change):
            raise GeometryError(f"tooth profile: no point of the generated root fillet has its tangent at "
                                f"{math.degrees(angle):g}° to the tooth centreline (the fillet turns from "
                                f"{math.degrees(values.max() + angle):.1f}° to {math.degrees(values.min() + angle):.1f}°).")
        i = change[0]
        return brentq(f, ts[i], ts[i + 1], xtol=1e-14)


def _monotone_runs(radius: np.ndarray, theta: np.ndarray):
    """Pieces of a polyline along which the radius only grows or only falls (sorted by radius)."""
    ok = np.isfinite(radius) & np.isfinite(theta)
    if ok.sum() < 2:
        return
    radius, theta = radius[ok], theta[ok]
    step = np.sign(np.diff(radius))
    start = 0
    for i in range(1, len(step) + 1):
        if i == len(step) or (step[i] != step[start] and step[i] != 0):
            rr, tt = radius[start:i + 1], theta[start:i + 1]
            if rr[0] > rr[-1]:
                rr, tt = rr[::-1], tt[::-1]
            if rr[-1] > rr[0]:
                yield rr, tt
            start = i


def _reach(runs, radius: np.ndarray) -> np.ndarray:
    """The largest θ any run reaches at each radius (−∞ where none)."""
    out = np.full(radius.shape, -np.inf)
    for rr, tt in runs:
        inside = (radius >= rr[0]) & (radius <= rr[-1])
        if inside.any():
            out[inside] = np.maximum(out[inside], np.interp(radius[inside], rr, tt))
    return out


def assemble(generation: Generation, teeth: float, tip_radius: float, internal: bool):
    """The left half of one tooth, space centre to tip centre, and its fillet curve.

    Parameters
    ----------
    generation : Generation
    teeth : float
        z.
    tip_radius : float
        r_a, mm.
    internal : bool

    Returns
    -------
    points : numpy.ndarray
        (n, 2), tooth frame, mm.
    names : numpy.ndarray
        Segment name of each point.
    fillet : FilletCurve or None
        None where the fillet is cut away entirely.
    form_radius : float
        Where the involute begins (the root form circle), mm.

    Raises
    ------
    GeometryError
        Pointed teeth (no tooth thickness left at the tip circle).
    """
    pitch = math.pi / teeth
    curves = []
    for seg in generation.segments:
        t = np.linspace(seg.low, seg.high, seg.samples)
        g = generation.curve(seg, t)
        curves.append((seg, t, np.hypot(g[:, 0], g[:, 1]), np.arctan2(g[:, 0], g[:, 1])))
    runs = [run for seg, _, r, th in curves if seg.name != "root" for run in _monotone_runs(r, th)]
    scale = 1e-9
    pieces, fillet, form_radius = [], None, None
    beyond = (lambda r: r > tip_radius) if not internal else (lambda r: r < tip_radius)
    for seg, t, r, th in curves:
        ok = np.isfinite(r) & np.isfinite(th) & (th >= -scale)
        if seg.name != "root":
            ok &= th >= _reach(runs, r) - scale
        ok &= ~beyond(r)
        if not ok.any():
            continue
        index = np.nonzero(ok)[0]
        pieces.append((seg.name, r[index], th[index]))
        if seg.name == "fillet":
            fillet = FilletCurve(generation, seg, float(t[index[0]]), float(t[index[-1]]), pitch)
        if seg.name == "involute":
            form_radius = float(r[index[0]])
    flank = [(n, r, th) for n, r, th in pieces if n == "involute"]
    if not flank:
        raise GeometryError("tooth profile: the tool leaves no involute flank (the fillet reaches the tip); "
                            "the tooth is undercut up to its tip.")
    _, fr, fth = flank[0]
    order = np.argsort(fr)
    theta_tip = float(np.interp(tip_radius, fr[order], fth[order]))
    if theta_tip >= pitch:
        raise GeometryError(f"tooth profile: the teeth are pointed (no tooth thickness left at the tip circle "
                            f"d_a = {2 * tip_radius:.4f} mm); reduce the tip diameter or the profile shift.")
    tip_theta = np.linspace(theta_tip, pitch, 24)
    pieces.append(("tip", np.full(tip_theta.shape, tip_radius), tip_theta))
    names = np.concatenate([np.full(len(r), n, dtype="<U12") for n, r, _ in pieces])
    radius = np.concatenate([r for _, r, _ in pieces])
    theta = np.concatenate([th for _, _, th in pieces]) - pitch
    points = np.stack([radius * np.sin(theta), radius * np.cos(theta)], axis=1)
    if form_radius is None:
        form_radius = tip_radius
    return points, names, fillet, form_radius


@dataclass(frozen=True)
class ToothProfile:
    """One tooth's transverse profile as generated by its tool (mm, the gear's frame).

    The gear's centre is at the origin and the tooth's centreline on the +y axis; for an internal
    gear the tooth points toward the centre (its tip circle is the smaller).  ``points`` run from the
    middle of the tooth space on the left (on the root circle), over the left flank, the tip and the
    right flank, to the middle of the space on the right: rotated copies by 2π/z join into the
    whole gear (:meth:`gear_points`).

    Attributes
    ----------
    points : numpy.ndarray
        (n, 2) x, y in mm (read-only).
    segment : numpy.ndarray
        (n,) the segment of each point: ``root`` (root circle, the tool's tip), ``fillet`` (the
        trochoidal root fillet generated by the tool's tip round), ``protuberance`` (relief cut by a
        protuberance flank), ``involute``, ``tip`` (tip circle).
    teeth : float
        z (fractional for a virtual gear).
    module : float
        m_n, mm.
    pressure_angle, helix_angle : float
        α_n and β, degrees.
    profile_shift : float
        The generating profile shift x_E (ISO 21771 sign).
    internal : bool
    tip_diameter, root_diameter, form_diameter : float
        d_a, d_f as generated, and the root form diameter d_Ff where the involute begins, mm.
    tool : RackTool or PinionCutter
    fillet : FilletCurve or None
        The left flank's fillet in closed form (tangent angle, curvature radius), for the critical
        section of ISO 6336-3.
    cutting_pressure_angle : float
        α_w0 of the generating mesh, degrees (α_t for a rack-type tool).

    References
    ----------
    ISO 21771:2007; Litvin & Fuentes 2004, ch. 10–11.
    """

    points: np.ndarray = field(repr=False)
    segment: np.ndarray = field(repr=False)
    teeth: float
    module: float
    pressure_angle: float
    helix_angle: float
    profile_shift: float
    internal: bool
    tip_diameter: float
    root_diameter: float
    form_diameter: float
    tool: RackTool | PinionCutter
    fillet: FilletCurve | None = field(repr=False, compare=False, default=None)
    cutting_pressure_angle: float = 0.0

    def __post_init__(self) -> None:
        for key in ("points", "segment"):
            array = np.array(getattr(self, key))
            array.flags.writeable = False
            object.__setattr__(self, key, array)

    @property
    def transverse_module(self) -> float:
        """m_t, mm."""
        return self.module / math.cos(math.radians(self.helix_angle))

    @property
    def reference_diameter(self) -> float:
        """d = z m_t, mm."""
        return self.teeth * self.transverse_module

    @property
    def base_diameter(self) -> float:
        """d_b, mm."""
        a_t = math.atan(math.tan(math.radians(self.pressure_angle)) / math.cos(math.radians(self.helix_angle)))
        return self.reference_diameter * math.cos(a_t)

    def segment_points(self, name: str) -> np.ndarray:
        """The points of one segment (both flanks), mm.

        Parameters
        ----------
        name : str
            One of :data:`SEGMENT_NAMES`.

        Returns
        -------
        numpy.ndarray
        """
        if name not in SEGMENT_NAMES:
            raise GeometryError(f"ToothProfile: unknown segment {name!r}; the segments are {', '.join(SEGMENT_NAMES)}.")
        return self.points[self.segment == name]

    def half_angle(self, diameter) -> np.ndarray | float:
        """Half the tooth's angular thickness at ``diameter`` (mm; float or array), rad.

        Parameters
        ----------
        diameter : float or array_like
            Between root and tip diameter.

        Returns
        -------
        float or numpy.ndarray
        """
        left = self.points[: len(self.points) // 2 + 1]
        names = self.segment[: len(self.points) // 2 + 1]
        keep = (names != "root") & (names != "tip")
        radius = np.hypot(left[keep, 0], left[keep, 1])
        angle = -np.arctan2(left[keep, 0], left[keep, 1])
        order = np.argsort(radius)
        r = np.asarray(diameter, dtype=float) / 2
        low, high = sorted((self.root_diameter / 2, self.tip_diameter / 2))
        if np.any(r < low - 1e-9) or np.any(r > high + 1e-9):
            raise GeometryError(f"ToothProfile: diameter {diameter!r} lies outside the tooth "
                                f"({2 * low:.4f} ... {2 * high:.4f} mm).")
        out = np.interp(r, radius[order], angle[order])
        return float(out) if np.ndim(out) == 0 else out

    def tooth_thickness(self, diameter: float, normal: bool = False) -> float:
        """Arc tooth thickness at ``diameter``, transverse (or normal: × cos β_y), mm.

        Parameters
        ----------
        diameter : float
            mm.
        normal : bool, default False
            The normal thickness s_yn = s_yt cos β_y, tan β_y = tan β d_y/d (ISO 21771).

        Returns
        -------
        float
        """
        s = float(diameter * self.half_angle(diameter))
        if normal:
            beta_y = math.atan(math.tan(math.radians(self.helix_angle)) * diameter / self.reference_diameter)
            s *= math.cos(beta_y)
        return s

    def chordal_thickness(self, diameter: float) -> float:
        """The chord across the tooth at ``diameter``, transverse, mm.

        Parameters
        ----------
        diameter : float
            mm.

        Returns
        -------
        float
        """
        return float(diameter * math.sin(self.half_angle(diameter)))

    def gear_points(self) -> np.ndarray:
        """All teeth: the tooth's points rotated by 2π k/z, k = 0 … z − 1 (whole z only), (z n, 2) mm.

        Returns
        -------
        numpy.ndarray

        Raises
        ------
        GeometryError
            A virtual gear with a fractional number of teeth.
        """
        if abs(self.teeth - round(self.teeth)) > 1e-9:
            raise GeometryError(f"ToothProfile: a virtual gear of z = {self.teeth:g} teeth has no whole outline.")
        z = int(round(self.teeth))
        return np.concatenate([_rotate(self.points[:-1], -2 * math.pi * k / z) for k in range(z)])

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm, degrees; points as lists)."""
        return {"teeth": self.teeth, "module": self.module, "pressure_angle": self.pressure_angle,
                "helix_angle": self.helix_angle, "profile_shift": self.profile_shift, "internal": self.internal,
                "tip_diameter": self.tip_diameter, "root_diameter": self.root_diameter,
                "form_diameter": self.form_diameter, "cutting_pressure_angle": self.cutting_pressure_angle,
                "tool": self.tool.to_dict(), "points": self.points.tolist(), "segment": self.segment.tolist()}

    def _rows(self):
        return [["z", self.teeth, ""], ["m_n", self.module, "mm"], ["x_E", self.profile_shift, ""],
                ["d_a", self.tip_diameter, "mm"], ["d_Ff", self.form_diameter, "mm"],
                ["d_f", self.root_diameter, "mm"], ["tool", self.tool.describe(), ""],
                ["points", len(self.points), ""]]

    def __repr__(self) -> str:
        kind = "internal" if self.internal else "external"
        return text_table(["quantity", "value", "unit"], self._rows(), f"ToothProfile ({kind} gear)")

    def _repr_html_(self) -> str:
        kind = "internal" if self.internal else "external"
        return html_table(["quantity", "value", "unit"], self._rows(), f"ToothProfile ({kind} gear)")
