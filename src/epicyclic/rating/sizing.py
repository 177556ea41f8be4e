"""The smallest module (and face width) that meets S_Hmin and S_Fmin for a set's torque and life.

:func:`smallest_module` rates a planetary set of a solved train with each module of a
series in increasing order — the preferred modules of ISO 54 (series I and II) from
``min_module`` to ``max_module`` (the search bound, 0.5 … 50 mm by default) — and
returns the first that can be built — every error-level fitting condition of
:func:`~epicyclic.geometry.check_fitting` met: coaxiality, assembly, neighbours, undercut,
tip thickness, ε_α ≥ 1 (the one path of ``epicyclic fit``) — and whose every mesh meets
S_Hmin and S_Fmin (ISO 6336 Method B, :func:`~epicyclic.rating.mesh_rating.rate_mesh`).
The face width is either given (mm) or follows the module as ``face_width_ratio`` × the
sun's reference diameter (b/d1).  The profile shifts are the given ones (default 0) or,
with ``profile_shifts="balanced"``, those of
:func:`~epicyclic.geometry.balanced_shifts.balanced_shifts` (coaxial, buildable, balanced
specific sliding; the same for every module).  Tooth counts, torques and speeds stay those
of the set and the solution; the life is the spec's.  If no module of the series up to the
bound can be built or suffices, :class:`~epicyclic.rating.errors.RatingError` says so with
the conditions that fail or the best safeties reached — a set that cannot be built or
cannot carry the load is never reported as sized.

References
----------
ISO 54:1996 (preferred modules); ISO 6336-2:2019 and ISO 6336-3:2019 (S_H, S_F).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..geometry._render import html_table, text_table
from ..geometry.errors import GeometryError
from ..geometry.fitting import check_fitting
from ..geometry.set_geometry import SetGeometry
from .errors import RatingError
from .results import TrainRating
from .spec import RatingSpec

__all__ = ["ISO_54_MODULES", "SizingResult", "smallest_module"]

#: ISO 54 preferred normal modules, mm (series I and II merged, ascending).
ISO_54_MODULES = (0.5, 0.55, 0.6, 0.7, 0.8, 0.9, 1.0, 1.125, 1.25, 1.375, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0, 3.5,
                  4.0, 4.5, 5.0, 5.5, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 25.0,
                  28.0, 32.0, 36.0, 40.0, 45.0, 50.0)


@dataclass(frozen=True)
class SizingResult:
    """The module found and the rating with it.

    Attributes
    ----------
    module : float
        m_n, mm.
    face_width : float
        b, mm.
    geometry : SetGeometry
    rating : TrainRating
        The set's meshes rated with that module.
    tried : tuple of (float, float, float)
        (module, lowest S_H, lowest S_F) of every module rated, in order.
    bound : (float, float)
        The searched module range, mm.
    fitting : FittingReport, optional
        The fitting conditions of the set found (every error-level one passes).
    shifts : ShiftChoice, optional
        The profile shifts chosen (``profile_shifts="balanced"``).
    """

    module: float
    face_width: float
    geometry: SetGeometry
    rating: TrainRating
    tried: tuple[tuple[float, float, float], ...]
    bound: tuple[float, float]
    fitting: Any = None
    shifts: Any = None

    @property
    def profile_shifts(self) -> dict[str, float]:
        """x of sun, planet(s) and ring (the ring's in the ISO 21771 sign)."""
        return {name: float(gear.profile_shift) for name, gear in self.geometry.gears.items()}

    def _sections(self) -> list[tuple[str, list[str], list[list[object]]]]:
        s_h = min(float(np.min(m.S_H)) for m in self.rating.meshes)
        s_f = min(float(np.min(m.S_F)) for m in self.rating.meshes)
        a_w = self.geometry.meshes[0].center_distance
        shifts = self.profile_shifts
        summary = [["normal module", "m_n", "mm", f"{self.module:g}"], ["face width", "b", "mm", f"{self.face_width:.4g}"],
                   *[[f"profile shift of the {g}", f"x_{g}", "1", f"{x:+.4f}"] for g, x in shifts.items()],
                   ["working centre distance", "a_w", "mm", f"{a_w:.4f}"],
                   ["lowest safety for pitting", "S_H", "1", f"{s_h:.4g}"],
                   ["lowest safety for bending", "S_F", "1", f"{s_f:.4g}"],
                   ["fitting conditions", "", "", "pass" if self.fitting is None or self.fitting.passed else "FAIL"]]
        if self.shifts is not None:
            summary.append(["specific sliding at the roots (sun, planet)", "zeta", "1",
                            f"{self.shifts.sliding[0]:.4f}, {self.shifts.sliding[1]:.4f}"])
        tried = [[f"{m:g}", f"{h:.4g}", f"{f:.4g}"] for m, h, f in self.tried]
        return [(f"smallest module of {self.geometry.planetary_set.name!r}: searched {self.bound[0]:g} ... "
                 f"{self.bound[1]:g} mm (ISO 54)", ["quantity", "symbol", "unit", "value"], summary),
                ("modules rated (each set buildable)", ["m_n [mm]", "min S_H", "min S_F"], tried)]

    def table(self) -> str:
        """The module, face width, profile shifts and safeties, and every module rated, as text."""
        return "\n\n".join(text_table(h, r, title=t) for t, h, r in self._sections())

    def markdown(self) -> str:
        """The same tables in Markdown."""
        parts = []
        for title, head, rows in self._sections():
            parts.append(f"## {title}\n\n| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n"
                         + "\n".join("| " + " | ".join(str(v).replace("|", "\\|") for v in r) + " |" for r in rows))
        return "\n\n".join(parts) + "\n"

    def _repr_html_(self) -> str:
        return "".join(html_table(h, r, title=t) for t, h, r in self._sections())

    def __repr__(self) -> str:
        return f"<SizingResult m_n {self.module:g} mm, b {self.face_width:.4g} mm, shifts {self.profile_shifts}>"

    def to_dict(self) -> dict:
        """Plain data: module, face width (mm), profile shifts, bound, tried modules, fitting, the rating."""
        return {"module": self.module, "face_width": self.face_width, "profile_shifts": self.profile_shifts,
                "shift_choice": None if self.shifts is None else self.shifts.to_dict(), "bound": list(self.bound),
                "tried": [list(t) for t in self.tried],
                "fitting": None if self.fitting is None else self.fitting.to_dict(), "rating": self.rating.to_dict()}


def smallest_module(solution, set_name: str, spec: RatingSpec, *, face_width: float | None = None,
                    face_width_ratio: float | None = None, min_module: float = 0.5, max_module: float = 50.0,
                    modules: Sequence[float] | None = None, profile_shifts: str = "given",
                    **geometry) -> SizingResult:
    """The smallest module of a series for which every mesh of ``set_name`` meets S_Hmin and S_Fmin.

    Parameters
    ----------
    solution : Solution
        The solved operating point (the set's torques and speeds).
    set_name : str
        A planetary set of the train with tooth counts.
    spec : RatingSpec
        Materials, roughness, lubricant, life, minimum safeties.
    face_width : float, optional
        b in mm for every module; or
    face_width_ratio : float, optional
        b = ratio · d_sun (b/d1), growing with the module.  One of the two is required.
    min_module, max_module : float, default 0.5, 50
        The search bound, mm.
    modules : sequence of float, optional
        The series to search (default :data:`ISO_54_MODULES`).
    profile_shifts : {"given", "balanced"}, default "given"
        The shifts of ``geometry`` (x_sun, x_planet, x_ring; default 0), or those of
        :func:`~epicyclic.geometry.balanced_shifts.balanced_shifts` (a simple set).
    **geometry
        Further :meth:`~epicyclic.geometry.SetGeometry.create` arguments (pressure_angle,
        helix_angle, x_sun, x_planet, x_ring, load_sharing ...).

    Returns
    -------
    SizingResult

    Raises
    ------
    RatingError
        Neither or both of face_width and face_width_ratio; no module up to the bound
        gives a set that can be built (the message names the failing fitting conditions) or
        suffices (the message gives the best safeties and the bound).

    References
    ----------
    ISO 54:1996; ISO 6336-2:2019, eq. (4); ISO 6336-3:2019, eq. (5).

    Examples
    --------
    >>> from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve, Brake
    >>> from epicyclic.rating import RatingSpec
    >>> p = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99)
    >>> sol = solve(GearTrain([p, Brake("B", "r")]), OperatingPoint(speeds={"in": 1500}, torques={"in": 300},
    ...             drives=["in"], loads=["out"]))
    >>> spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3, root_roughness=10, viscosity_40=220)
    >>> result = smallest_module(sol, "P", spec, face_width_ratio=0.6)
    >>> result.module, [m for m, *_ in result.tried]
    (2.25, [0.5, 0.55, 0.6, 0.7, 0.8, 0.9, 1.0, 1.125, 1.25, 1.375, 1.5, 1.75, 2.0, 2.25])
    """
    from .train import _set_meshes

    if (face_width is None) == (face_width_ratio is None):
        raise RatingError("smallest_module: give face_width (mm) or face_width_ratio (b/d of the sun), not both "
                          "nor neither.")
    element = next((e for e in solution.train.elements if e.name == set_name), None)
    if element is None or getattr(element, "teeth", None) is None:
        raise RatingError(f"smallest_module: {set_name!r} is not a planetary set with tooth counts in the train.")
    series = sorted(m for m in (modules or ISO_54_MODULES) if min_module <= m <= max_module)
    if not series:
        raise RatingError(f"smallest_module: no module of the series lies in the bound {min_module:g} ... "
                          f"{max_module:g} mm.")
    choice = _shifts(element, profile_shifts, geometry)
    state = solution.elements[set_name]
    torques, speeds = dict(state.torques), dict(state.speeds)
    tried, modes_short = [], ""
    unbuildable: dict[str, str] = {}
    for m in series:
        b = face_width if face_width is not None else face_width_ratio * element.teeth.sun * m
        try:
            shape = SetGeometry.create(element, m, face_width=b, **geometry)
        except GeometryError as exc:
            unbuildable.setdefault("geometry", str(exc))
            continue
        report = check_fitting(shape)
        if not report.passed:  # a set that cannot be built is never rated as sized
            for c in report.failures:
                unbuildable.setdefault(c.condition, c.message)
            continue
        try:
            meshes = [rate_one(item, torques, speeds) for item in _set_meshes(set_name, shape, spec)]
        except GeometryError:
            continue
        rating = TrainRating(tuple(meshes), None, f"ISO 6336:{spec.standard}", spec.life)
        s_h = min(float(np.min(x.S_H)) for x in meshes)
        s_f = min(float(np.min(x.S_F)) for x in meshes)
        tried.append((m, s_h, s_f))
        if rating.ok:
            return SizingResult(m, float(b), shape, rating, tuple(tried), (series[0], series[-1]), report, choice)
        modes_short = "; ".join(f"{x.mesh}: {s}" for x in meshes for s in (y.below_minimum() for y in x.modes) if s)
    if not tried and unbuildable:
        reasons = "; ".join(f"{k}: {v}" for k, v in unbuildable.items())
        raise RatingError(f"smallest_module: no module of {series[0]:g} ... {series[-1]:g} mm gives a set "
                          f"{set_name!r} that can be built ({reasons}). Give profile shifts that fit, or "
                          "profile_shifts='balanced' (epicyclic size --shifts balanced) to find coaxial, "
                          "undercut-free ones.")
    best = max(tried, key=lambda t: min(t[1] / spec.S_Hmin, t[2] / spec.S_Fmin), default=None)
    detail = (f"; the best was m = {best[0]:g} mm with S_H {best[1]:.3f}, S_F {best[2]:.3f}" if best else
              "; no module gave a valid geometry")
    raise RatingError(f"smallest_module: no module of {series[0]:g} ... {series[-1]:g} mm meets S_Hmin "
                      f"{spec.S_Hmin:g} and S_Fmin {spec.S_Fmin:g} for {set_name!r}{detail}"
                      + (f" (and the failure modes rated: at m = {series[-1]:g} mm {modes_short})" if modes_short
                         else "") + ". Raise max_module, the face width, or the material.")


def _shifts(element, mode: str, geometry: dict):
    """The balanced shifts put into ``geometry`` (mode "balanced"), or None (mode "given")."""
    if mode == "given":
        return None
    if mode != "balanced":
        raise RatingError(f"smallest_module: profile_shifts must be 'given' or 'balanced', got {mode!r} "
                          "(default 'given').")
    given = [k for k in ("x_sun", "x_planet", "x_ring") if k in geometry]
    if given:
        raise RatingError(f"smallest_module: profile_shifts='balanced' chooses the shifts; leave out "
                          f"{', '.join(given)}.")
    from ..geometry.balanced_shifts import balanced_shifts

    rack = {k: geometry[k] for k in ("pressure_angle", "helix_angle", "addendum", "dedendum") if k in geometry}
    try:
        choice = balanced_shifts(element, **rack)
    except GeometryError as exc:
        raise RatingError(f"smallest_module: {exc}") from None
    geometry.update(x_sun=choice.x_sun, x_planet=choice.x_planet, x_ring=choice.x_ring)
    return choice


def rate_one(item, torques, speeds):
    """Rate one planned mesh at an element's port torques and speeds.

    Parameters
    ----------
    item : PlannedMesh
        From :func:`~epicyclic.rating.train.mesh_inputs`.
    torques, speeds : mapping port → float or ndarray
        The element's port torques (N·m) and speeds (1/min).

    Returns
    -------
    MeshRating

    References
    ----------
    ISO 6336-1:2019, 6.1.
    """
    from .mesh_rating import rate_mesh

    torque, speed = item.loads(torques, speeds)
    return rate_mesh(item.input, torque, speed)
