"""The outline of a gear as CAD curves: B-splines through the generated flank and fillet, arcs on tip and root.

The generated transverse profile (:func:`epicyclic.geometry.tooth_generation.generate_profile`) is
a dense point sequence of one tooth, each point labelled ``root``, ``fillet``, ``protuberance``,
``involute`` or ``tip``.  Here each run of one label becomes one curve: the tip and root runs
circular arcs about the gear centre, the others a cubic B-spline interpolating fit points taken
from the dense profile, as few as keep the spline within ``tolerance`` of every dense point
(doubling the fit points until it does; the deviation reached is kept with the curve).  Rotated
copies by 2π/z make the whole, closed outline.

References
----------
L. Piegl, W. Tiller, *The NURBS Book*, 2nd ed., Springer 1997, section 9.2.1 (global curve
interpolation, chord-length parameters); ISO 21771:2007 (the involute and the gear's circles).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry.errors import GeometryError

__all__ = ["Arc", "Spline", "GearOutline", "gear_outline", "DEFAULT_TOLERANCE"]

#: Largest distance (mm) between a B-spline and the generated profile it stands for: 0.1 µm.
DEFAULT_TOLERANCE = 1e-4


@dataclass(frozen=True)
class Arc:
    """A circular arc about ``centre`` from ``start`` to ``end`` (rad, counter-clockwise), mm."""

    centre: tuple[float, float]
    radius: float
    start: float
    end: float

    def points(self, count: int = 16) -> np.ndarray:
        """(count, 2) points along the arc."""
        t = np.linspace(self.start, self.end, count)
        return np.column_stack([self.centre[0] + self.radius * np.cos(t), self.centre[1] + self.radius * np.sin(t)])

    def moved(self, angle: float, offset: tuple[float, float]) -> Arc:
        """Rotated by ``angle`` (rad) about the origin, then shifted by ``offset``."""
        c, s = math.cos(angle), math.sin(angle)
        x, y = self.centre
        return Arc((c * x - s * y + offset[0], s * x + c * y + offset[1]), self.radius, self.start + angle,
                   self.end + angle)


@dataclass(frozen=True)
class Spline:
    """A cubic B-spline (control points, clamped knots) standing for a run of the profile, mm.

    ``deviation`` is the largest distance found between the spline and the dense profile points.
    """

    control_points: np.ndarray = field(repr=False)
    knots: tuple[float, ...] = field(repr=False)
    fit_points: np.ndarray = field(repr=False)
    degree: int = 3
    deviation: float = 0.0
    segment: str = ""

    def points(self, count: int = 64) -> np.ndarray:
        """(count, 2) points along the spline."""
        from ezdxf.math import BSpline

        curve = BSpline(self.control_points, order=self.degree + 1, knots=self.knots)
        return np.array([(p.x, p.y) for p in curve.approximate(count - 1)])

    def moved(self, angle: float, offset: tuple[float, float]) -> Spline:
        """Rotated by ``angle`` (rad) about the origin, then shifted by ``offset``."""
        rot = np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
        return Spline(self.control_points @ rot.T + offset, self.knots, self.fit_points @ rot.T + offset,
                      self.degree, self.deviation, self.segment)


@dataclass(frozen=True)
class GearOutline:
    """The closed outline of one gear (its curves in order), placed at ``centre`` turned by ``rotation``.

    Attributes
    ----------
    name : str
    teeth : int
    internal : bool
    curves : tuple of Arc or Spline
        Of the whole gear, counter-clockwise for an external gear, in the gear's frame.
    tip_diameter, root_diameter, base_diameter, reference_diameter : float
        mm.
    centre : (float, float)
        mm.
    rotation : float
        rad (counter-clockwise) of the gear's tooth 0 from the +y axis.
    tolerance : float
        The spline tolerance asked for, mm; ``max_deviation`` the largest reached.
    """

    name: str
    teeth: int
    internal: bool
    curves: tuple = field(repr=False)
    tip_diameter: float
    root_diameter: float
    base_diameter: float
    reference_diameter: float
    tolerance: float
    centre: tuple[float, float] = (0.0, 0.0)
    rotation: float = 0.0
    profile: object = field(default=None, repr=False, compare=False)

    @property
    def max_deviation(self) -> float:
        """The largest spline deviation from the generated profile, mm."""
        return max((c.deviation for c in self.curves if isinstance(c, Spline)), default=0.0)

    def placed(self, centre: tuple[float, float], rotation: float) -> GearOutline:
        """The same gear at ``centre`` turned by ``rotation``.

        Parameters
        ----------
        centre : (float, float)
            mm.
        rotation : float
            rad, counter-clockwise.

        Returns
        -------
        GearOutline
        """
        from dataclasses import replace

        return replace(self, centre=(float(centre[0]), float(centre[1])), rotation=float(rotation))

    def world_curves(self) -> list:
        """The curves moved to the gear's place."""
        return [c.moved(self.rotation, self.centre) for c in self.curves]

    def polygon(self, per_curve: int = 24) -> np.ndarray:
        """A closed point sequence along the placed outline (no repeated end point), mm."""
        chunks: list[np.ndarray] = []
        for curve in self.world_curves():
            pts = curve.points(per_curve)
            if chunks and np.hypot(*(pts[-1] - chunks[-1][-1])) < np.hypot(*(pts[0] - chunks[-1][-1])):
                pts = pts[::-1]
            chunks.append(pts)
        return np.concatenate([c[:-1] for c in chunks])

    def dense_polygon(self, spacing: float = 0.005) -> np.ndarray:
        """The exported outline sampled every ``spacing`` mm or closer, placed (for numerical checks), mm.

        Parameters
        ----------
        spacing : float, default 0.005
            Largest distance between samples along a curve, mm.

        Returns
        -------
        numpy.ndarray
            (n, 2), closed (no repeated end point).
        """
        per_tooth = len(self.curves) // self.teeth
        chunks = []
        for curve in self.curves[:per_tooth]:
            rough = curve.points(8)
            length = float(np.hypot(*np.diff(rough, axis=0).T).sum())
            pts = curve.points(max(8, int(length / spacing) + 2))
            if chunks and np.hypot(*(pts[-1] - chunks[-1][-1])) < np.hypot(*(pts[0] - chunks[-1][-1])):
                pts = pts[::-1]  # arcs are stored counter-clockwise; follow the outline's direction
            chunks.append(pts)
        tooth = np.concatenate([c[:-1] for c in chunks])
        teeth = [tooth @ _rotation(-2 * math.pi * k / self.teeth).T for k in range(self.teeth)]
        return np.concatenate(teeth) @ _rotation(self.rotation).T + np.asarray(self.centre)


def _rotation(angle: float) -> np.ndarray:
    return np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])


def _distance_to_polyline(points: np.ndarray, line: np.ndarray) -> np.ndarray:
    """Distance of each point to the polyline ``line`` (n, 2), mm."""
    from scipy.spatial import cKDTree

    nearest = cKDTree(line).query(points)[1]
    best = np.full(len(points), np.inf)
    for shift in (-1, 0):
        i = np.clip(nearest + shift, 0, len(line) - 2)
        a, b = line[i], line[i + 1]
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", points - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
        best = np.minimum(best, np.hypot(*(a + t[:, None] * ab - points).T))
    return best


def _spline(run: np.ndarray, tolerance: float, segment: str) -> Spline:
    from ezdxf.math import global_bspline_interpolation

    keep = np.concatenate([[True], np.hypot(*np.diff(run, axis=0).T) > 1e-9])  # repeated points: no chord
    run = run[keep]
    count = 6
    while True:
        index = np.unique(np.linspace(0, len(run) - 1, min(count, len(run))).round().astype(int))
        fit = run[index]
        curve = global_bspline_interpolation(fit, degree=min(3, len(fit) - 1), method="chord")
        samples = np.array([(p.x, p.y) for p in curve.approximate(8 * len(fit))])
        deviation = max(float(_distance_to_polyline(samples, run).max()),
                        float(_distance_to_polyline(run, samples).max()))
        if deviation <= tolerance or len(fit) == len(run):
            return Spline(np.array([(p.x, p.y) for p in curve.control_points]), tuple(curve.knots()), fit,
                          curve.degree, deviation, segment)
        count *= 2


def _joins(a: Arc, b: Arc) -> bool:
    """Whether ``b`` continues ``a`` clockwise on the same circle (b ends where a starts)."""
    gap = (a.start - b.end + math.pi) % (2 * math.pi) - math.pi
    return abs(a.radius - b.radius) < 1e-9 and abs(gap) < 1e-9


def _merge_arcs(curves: list) -> list:
    """Join the two root half-arcs of neighbouring teeth into one arc (one entity fewer per tooth)."""
    out: list = []
    for curve in curves:
        last = out[-1] if out else None
        if isinstance(curve, Arc) and isinstance(last, Arc) and _joins(last, curve):
            out[-1] = Arc(last.centre, last.radius, curve.start, curve.start + (last.end - last.start)
                          + (curve.end - curve.start))
        else:
            out.append(curve)
    if len(out) > 1 and isinstance(out[0], Arc) and isinstance(out[-1], Arc) and _joins(out[-1], out[0]):
        first, last = out[0], out.pop()
        out[0] = Arc(first.centre, first.radius, first.start, first.start + (first.end - first.start)
                     + (last.end - last.start))
    return out


def _tip_half_angle(profile) -> float:
    """ψ_a, half the angle the tooth spans on its tip circle (ISO 21771: s_y of the generating shift x_E), rad.

    The tip corner is where the involute meets the tip circle; taken from the closed form rather than
    from the profile's points, whose tip run may start a few µm off the involute.
    """
    from ..geometry.involute import inv, transverse_pressure_angle

    alpha_t = transverse_pressure_angle(math.radians(profile.pressure_angle), math.radians(profile.helix_angle))
    m_t = profile.module / math.cos(math.radians(profile.helix_angle))
    d = profile.teeth * m_t
    s_t = m_t * (math.pi / 2.0 + 2.0 * profile.profile_shift * math.tan(math.radians(profile.pressure_angle)))
    alpha_a = math.acos(min(1.0, d * math.cos(alpha_t) / profile.tip_diameter))
    if profile.internal:
        return s_t / d - inv(alpha_t) + inv(alpha_a)
    return s_t / d + inv(alpha_t) - inv(alpha_a)


def gear_outline(profile, name: str = "", tolerance: float = DEFAULT_TOLERANCE) -> GearOutline:
    """The CAD outline of a generated :class:`~epicyclic.geometry.tooth_generation.ToothProfile`.

    Parameters
    ----------
    profile : ToothProfile
        One tooth (whole number of teeth).
    name : str, optional
    tolerance : float, default 1e-4
        Largest distance between a spline and the dense profile, mm (0.1 µm).

    Returns
    -------
    GearOutline

    Raises
    ------
    GeometryError
        A non-positive tolerance, or a fractional number of teeth.

    References
    ----------
    Piegl & Tiller 1997, section 9.2.1 (interpolation); ISO 21771:2007.
    """
    if not (isinstance(tolerance, (int, float)) and math.isfinite(tolerance) and tolerance > 0):
        raise GeometryError(f"outline: tolerance must be a positive number of mm, got {tolerance!r}.")
    if abs(profile.teeth - round(profile.teeth)) > 1e-9:
        raise GeometryError(f"outline: a gear of z = {profile.teeth:g} teeth has no whole outline.")
    z = int(round(profile.teeth))
    points, labels = np.asarray(profile.points), np.asarray(profile.segment)
    runs, start = [], 0
    for i in range(1, len(points) + 1):
        if i == len(points) or labels[i] != labels[start]:
            runs.append((str(labels[start]), points[start:i]))
            start = i
    arc = [label in ("root", "tip") for label, _ in runs]
    corner = _tip_half_angle(profile)
    r_tip = profile.tip_diameter / 2.0
    for j, (label, run) in enumerate(runs):  # the tip runs from involute to involute on the tip circle
        if label == "tip" and 0 < j < len(runs) - 1 and runs[j - 1][0] == runs[j + 1][0] == "involute":
            ends = r_tip * np.array([[-math.sin(corner), math.cos(corner)], [math.sin(corner), math.cos(corner)]])
            inner = run[np.abs(np.arctan2(run[:, 0], run[:, 1])) < corner - 1e-12]
            runs[j] = (label, np.concatenate([ends[:1], inner, ends[1:]]))
    # the point where run j meets run j + 1: an arc's own end point, else the next run's first point
    joints = [runs[j][1][-1] if arc[j] else runs[j + 1][1][0] for j in range(len(runs) - 1)]
    tooth = []
    for j, (label, run) in enumerate(runs):
        if arc[j]:
            radius = float(np.hypot(run[:, 0], run[:, 1]).mean())
            angles = np.unwrap(np.arctan2(run[:, 1], run[:, 0]))
            a0, a1 = float(angles[0]), float(angles[-1])
            tooth.append(Arc((0.0, 0.0), radius, a0, a1) if a1 > a0 else Arc((0.0, 0.0), radius, a1, a0))
            continue
        parts = [run]
        if j > 0 and np.hypot(*(joints[j - 1] - run[0])) > 1e-12:
            parts.insert(0, joints[j - 1][None, :])
        if j < len(runs) - 1 and np.hypot(*(joints[j] - run[-1])) > 1e-12:
            parts.append(joints[j][None, :])
        tooth.append(_spline(np.concatenate(parts), tolerance, label))
    curves = []
    for k in range(z):
        angle = -2 * math.pi * k / z  # as ToothProfile.gear_points: tooth k at -2πk/z
        curves.extend(c.moved(angle, (0.0, 0.0)) for c in tooth)
    curves = _merge_arcs(curves)
    return GearOutline(name, z, bool(profile.internal), tuple(curves), float(profile.tip_diameter),
                       float(profile.root_diameter), float(profile.base_diameter), float(profile.reference_diameter),
                       float(tolerance), profile=profile)
