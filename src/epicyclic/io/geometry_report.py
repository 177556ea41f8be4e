"""Fitting and forces of the elements of a train file that have a ``geometry`` table.

Used by ``epicyclic analyze`` (all formats), ``epicyclic fit`` and
``epicyclic forces``: one entry per element with geometry, in file order, with
the set's :class:`~epicyclic.geometry.FittingReport` and the forces at the
solved operating point (:class:`~epicyclic.geometry.PlanetaryForces` for a set,
:class:`~epicyclic.geometry.StageForces` for a stage).  Planets that several sets
share (a Wolfrom drive's, a Ravigneaux set's long planet) get the bearing load of
the whole body (:func:`~epicyclic.geometry.share_planets`).

JSON layout (the ``"geometry"`` key of the report, null without geometry)::

    {element: {"kind": "planetary set" | "gear stage",
               "geometry": SetGeometry.to_dict() | StageGeometry.to_dict(),
               "fitting": FittingReport.to_dict() | null,      # sets only
               "forces": PlanetaryForces.to_dict() | StageForces.to_dict() | null,
               "mesh_losses": [MeshLossRow.to_dict(), ...] | null}}      # with a mesh friction model

Lengths in mm, angles in degrees, forces in N, torques in N·m (whatever the
file's ``[units]``).
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from ..geometry import SetGeometry, check_fitting, planetary_forces, share_planets, stage_forces
from ..geometry.working import check_stage

__all__ = ["GeometryResult", "geometry_results", "tooth_count_results", "geometry_dict", "geometry_text", "geometry_markdown",
           "geometry_html"]


@dataclass(frozen=True)
class GeometryResult:
    """Geometry, fitting (sets) and forces (when solved) of one element."""

    name: str
    geometry: Any
    fitting: Any = None
    forces: Any = None
    mesh_losses: Any = None

    @property
    def kind(self) -> str:
        if self.geometry is None:
            return "planetary set (tooth counts only)"
        return "planetary set" if isinstance(self.geometry, SetGeometry) else "gear stage"


def geometry_results(geometry: Mapping[str, Any], solution=None, *, planets: int | None = None,
                     allow_unequal: bool = False, min_clearance: float = 0.0,
                     undercut: str = "theoretical", losses: Mapping[str, Any] | None = None
                     ) -> tuple[GeometryResult, ...]:
    """Fitting of every set and, with a solution, the forces of every element with geometry.

    Parameters
    ----------
    geometry : mapping element → SetGeometry or StageGeometry
        ``TrainFile.geometry``.
    solution : Solution, optional
        The solved operating point (forces need it).
    planets, allow_unequal, min_clearance, undercut
        As in :func:`~epicyclic.geometry.check_fitting` (``planets`` overrides every set's).
    losses : mapping element → ElementLosses, optional
        ``TrainFile.losses``: with a solution, the per-mesh losses of the elements with a mesh
        friction model (:func:`~epicyclic.losses.mesh_table.mesh_loss_table`).
    """
    out = []
    for name, shape in geometry.items():
        fitting = forces = None
        if isinstance(shape, SetGeometry):
            fitting = check_fitting(shape, planets, allow_unequal=allow_unequal, min_clearance=min_clearance,
                                    undercut=undercut)  # type: ignore[arg-type]
            if solution is not None and name in solution.elements:
                angles = fitting.checks[1].angles if not fitting.checks[1].equally_spaced and \
                    fitting.checks[1].passed else None
                forces = planetary_forces(solution, name, shape, angles=angles)
        else:
            fitting = check_stage(shape)
            if solution is not None and name in solution.elements:
                forces = stage_forces(solution, name, shape)
        out.append(GeometryResult(name, shape, fitting, forces))
    # a planet that several sets share is one body: its bearing carries the meshes of all of them
    set_forces = {r.name: r.forces for r in out if r.kind == "planetary set" and r.forces is not None}
    shared = share_planets(set_forces, {name: geometry[name] for name in set_forces})
    tables = {}
    if solution is not None and losses:
        from ..losses.mesh_table import MeshLossTable, mesh_loss_table

        table = mesh_loss_table(solution, losses)
        for row in table.rows:
            tables.setdefault(row.element, []).append(row)
        tables = {k: MeshLossTable(tuple(v)) for k, v in tables.items()}
    return tuple(replace(r, forces=shared.get(r.name, r.forces), mesh_losses=tables.get(r.name)) for r in out)


def tooth_count_results(train, *, planets: int | None = None,
                        allow_unequal: bool = False) -> tuple[GeometryResult, ...]:
    """Coaxiality of standard gears and assembly of every set with tooth counts (no geometry table).

    Parameters
    ----------
    train : Train
        The file's train.
    planets, allow_unequal
        As in :func:`~epicyclic.geometry.check_tooth_counts`.

    Returns
    -------
    tuple of GeometryResult
        ``geometry`` None, ``fitting`` the tooth-count report, one per set with tooth counts.
    """
    from ..geometry import check_tooth_counts
    from ..model import PlanetarySet

    return tuple(GeometryResult(e.name, None, check_tooth_counts(e, planets, allow_unequal=allow_unequal))
                 for e in train.elements if isinstance(e, PlanetarySet) and e.teeth is not None)


def geometry_dict(results: tuple[GeometryResult, ...]) -> dict[str, Any] | None:
    """The ``"geometry"`` section of the JSON report (None without geometry)."""
    if not results:
        return None
    return {r.name: {"kind": r.kind, "geometry": None if r.geometry is None else r.geometry.to_dict(),
                     "fitting": None if r.fitting is None else r.fitting.to_dict(),
                     "forces": None if r.forces is None else r.forces.to_dict(),
                     "mesh_losses": None if r.mesh_losses is None else r.mesh_losses.to_dict()} for r in results}


def geometry_text(results: tuple[GeometryResult, ...], *, show_geometry: bool = True) -> str:
    """Gears, meshes, fitting and forces as text tables (mm, degrees, N); ``show_geometry=False``: no gear and
    mesh tables (``epicyclic forces``)."""
    blocks = []
    for r in results:
        if show_geometry and r.geometry is not None:
            blocks.append(r.geometry.table())
        if r.fitting is not None:
            blocks.append(r.fitting.table())
        if r.forces is not None:
            blocks.append(r.forces.table())
        if r.mesh_losses is not None:
            blocks.append(r.mesh_losses.table())
    return "\n\n".join(blocks)


def _markdown_table(text: str) -> str:
    """A fixed-width text table as a Markdown code block (keeps alignment; no | or HTML to escape)."""
    return "```text\n" + text + "\n```"


def geometry_markdown(results: tuple[GeometryResult, ...], *, show_geometry: bool = True,
                      heading: str = "Geometry, fitting and forces") -> str:
    """A ``## Geometry, fitting and forces`` section (``heading``)."""
    if not results:
        return ""
    parts = [f"## {heading}"]
    for r in results:
        parts.append(f"### {r.kind} {r.name}".replace("<", "&lt;"))
        if show_geometry and r.geometry is not None:
            parts.append(_markdown_table(r.geometry.table()))
        if r.fitting is not None:
            parts.append(_markdown_table(r.fitting.table()))
        if r.forces is not None:
            parts.append(_markdown_table(r.forces.table()))
        if r.mesh_losses is not None:
            parts.append(_markdown_table(r.mesh_losses.table()))
    return "\n\n".join(parts) + "\n"


def geometry_html(results: tuple[GeometryResult, ...], *, show_geometry: bool = True,
                  heading: str = "Geometry, fitting and forces") -> str:
    """The same as an HTML section (escaped tables)."""
    if not results:
        return ""
    parts = [f"<h2>{html.escape(heading)}</h2>"]
    for r in results:
        parts.append(f"<h3>{html.escape(r.kind)} {html.escape(r.name)}</h3>")
        if show_geometry and r.geometry is not None:
            parts.append(r.geometry._repr_html_())
        if r.fitting is not None:
            parts.append(r.fitting._repr_html_())
        if r.forces is not None:
            parts.append(r.forces._repr_html_())
        if r.mesh_losses is not None:
            parts.append(r.mesh_losses._repr_html_())
    return "\n".join(parts)
