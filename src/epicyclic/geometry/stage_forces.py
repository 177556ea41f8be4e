"""Tooth forces of a fixed-axis gear stage at a solved operating point.

Mesh k of a stage is driven by the torque of the first shaft times the ratios of
the meshes before it (losses of the earlier meshes neglected in the split of
the stage's torque; the stage's own port torques are the solver's):
F_t = 2000 |T_k| / d_w,k, F_r = F_t tan α_wt, F_a = F_t tan β_w.

References
----------
Queitsch part I, eqs. (23)–(25), (30); ISO 21771:2007 (d_w, α_wt, β_w);
Drivetrain Hub, *Strength / Force Analysis* (F_t = 2T/d_w, F_r = F_t tan α_wt).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ._render import html_table, text_table
from .errors import GeometryError
from .forces import mesh_forces
from .stage_geometry import StageGeometry

__all__ = ["StageForces", "stage_forces"]


@dataclass(frozen=True)
class StageForces:
    """Forces of each mesh of a stage (N) and the torque driving it (N·m)."""

    stage_name: str
    rows: tuple[tuple[str, float, float, float, float, float], ...]  # mesh, torque, d_w, F_t, F_r, F_a

    _HEAD = ["mesh", "torque [N*m]", "d_w [mm]", "F_t [N]", "F_r [N]", "F_a [N]"]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: each mesh's driving torque (N·m), pitch diameter (mm) and forces (N).

        Returns
        -------
        dict
            ``stage``, ``units`` and ``meshes``: ``{mesh, torque, pitch_diameter,
            tangential, radial, axial}`` per mesh, from the first shaft to the second.
        """
        return {"stage": self.stage_name, "units": {"force": "N", "length": "mm", "torque": "N*m"},
                "meshes": [dict(zip(("mesh", "torque", "pitch_diameter", "tangential", "radial", "axial"), r))
                           for r in self.rows]}

    def table(self) -> str:
        """The forces of each mesh as a plain-text table (torque N·m, d_w mm, forces N).

        Returns
        -------
        str
        """
        return text_table(self._HEAD, [list(r) for r in self.rows], title=f"forces of stage {self.stage_name!r}")

    def _repr_html_(self) -> str:
        return html_table(self._HEAD, [list(r) for r in self.rows], title=f"forces of stage {self.stage_name}")


def stage_forces(solution, name: str, geometry: StageGeometry) -> StageForces:
    """Tooth forces of stage ``name`` in ``solution``.

    Mesh k is driven by |T_first| times the ratios z2/z1 of the meshes before it
    (the losses of earlier meshes are neglected in this split); each mesh's forces
    are :func:`~epicyclic.geometry.forces.mesh_forces` on the driving gear's
    operating pitch diameter.

    Parameters
    ----------
    solution : Solution
        A solved operating point (torques in N·m).
    name : str
        The gear stage's element name.
    geometry : StageGeometry
        The stage's gears and meshes (mm).

    Returns
    -------
    StageForces

    Raises
    ------
    GeometryError
        The solution has no element ``name``, or it is not a gear stage.

    References
    ----------
    Queitsch part I, eqs. (23)–(25), (30); ISO 21771:2007 (d_w, α_wt, β_w).

    Examples
    --------
    >>> from epicyclic import GearStage, GearTrain, OperatingPoint, solve
    >>> from epicyclic.geometry import BasicRack
    >>> stage = GearStage.from_teeth("G", "in", "out", [(20, 40, "external")])
    >>> sol = solve(GearTrain([stage]), OperatingPoint(speeds={"in": 1000}, torques={"in": 10},
    ...                                                 drives=["in"], loads=["out"]))
    >>> round(stage_forces(sol, "G", StageGeometry(stage, BasicRack(2.0))).rows[0][3], 3)  # 2000·10/40
    500.0
    """
    try:
        state = solution.elements[name]
    except KeyError:
        raise GeometryError(f"stage_forces: the solution has no element {name!r}.") from None
    if state.kind != "gear stage":
        raise GeometryError(f"stage_forces: element {name!r} is a {state.kind}, not a gear stage.")
    torque = abs(state.torques["first"])
    rows = []
    for k, ((z1, z2, _), mesh) in enumerate(zip(geometry.stage.meshes, geometry.meshes)):
        d_w = mesh.operating_pitch_diameters[0 if geometry.driving_is_gear1(k) else 1]
        ft, fr, fa = mesh_forces(torque, d_w, mesh)
        rows.append((mesh.name, torque, d_w, ft, fr, fa))
        torque *= z2 / z1
    return StageForces(name, tuple(rows))
