"""Per-mesh losses at a solved operating point: μ, H_V, rolling power, power loss and efficiency of every mesh.

For each mesh of an element with a mesh friction model, at the solution's port
torques and speeds:

* μ from the mesh's friction model (its own or the element's) at its load per face
  width and sum velocity (:meth:`~epicyclic.losses.mesh.MeshLoss.efficiency`);
* H_V and the form it was computed in (:func:`~epicyclic.losses.tooth_loss.tooth_loss_factor_method`);
* the rolling power through the mesh, P = |T_p (n_p − n_c)| π/30 for a set's mesh
  loaded at port p (carrier c), |T_first n_first| π/30 for a stage, W;
* the mesh efficiency η = 1 − μ H_V and the power lost, (1 − η) P, W;
* ε_α, ε_β = b sin β/(π m_n).

References
----------
Ohlendorf 1958 (P_V = μ H_V P); ISO/TR 14179-2:2001 (μ_mZ); Brandenberger 1952 (rolling power).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ..geometry._render import html_table, text_table
from ..geometry.contact import overlap_ratio
from .element import ElementLosses, friction_at_viscosity
from .tooth_loss import tooth_loss_factor_method

__all__ = ["MeshLossRow", "MeshLossTable", "mesh_loss_table"]

_RPM = math.pi / 30.0


@dataclass(frozen=True)
class MeshLossRow:
    """One mesh at the operating point (W, mm, dimensionless)."""

    element: str
    mesh: str
    model: str
    friction: float
    loss_factor: float
    loss_factor_method: str
    transverse_contact_ratio: float
    overlap_ratio: float
    rolling_power: float
    power_loss: float
    efficiency: float

    def to_dict(self) -> dict[str, Any]:
        """Every field; powers in W."""
        return {"element": self.element, "mesh": self.mesh, "model": self.model, "mu": self.friction,
                "H_V": self.loss_factor, "H_V_method": self.loss_factor_method,
                "eps_alpha": self.transverse_contact_ratio, "eps_beta": self.overlap_ratio,
                "rolling_power_W": self.rolling_power, "power_loss_W": self.power_loss,
                "efficiency": self.efficiency}


@dataclass(frozen=True)
class MeshLossTable:
    """The meshes of the elements with a mesh friction model at one operating point."""

    rows: tuple[MeshLossRow, ...]

    _HEAD = ["element", "mesh", "model", "mu", "H_V", "H_V from", "eps_alpha", "eps_beta", "P_roll [W]",
             "P_loss [W]", "eta_mesh"]

    def _rows(self) -> list[list[object]]:
        return [[r.element, r.mesh, r.model, r.friction, r.loss_factor, r.loss_factor_method,
                 r.transverse_contact_ratio, r.overlap_ratio, r.rolling_power, r.power_loss, r.efficiency]
                for r in self.rows]

    def table(self) -> str:
        """The meshes as a text table."""
        return text_table(self._HEAD, self._rows(), title="mesh losses (mu H_V of the rolling power)")

    def _repr_html_(self) -> str:
        return html_table(self._HEAD, self._rows(), title="mesh losses")

    def to_dict(self) -> list[dict[str, Any]]:
        """One dict per mesh (:meth:`MeshLossRow.to_dict`)."""
        return [r.to_dict() for r in self.rows]

    def __len__(self) -> int:
        return len(self.rows)

    def __repr__(self) -> str:
        return f"MeshLossTable({len(self.rows)} meshes)"


def mesh_loss_table(solution, losses: Mapping[str, ElementLosses]) -> MeshLossTable:
    """The per-mesh losses of every element with a mesh friction model at a solved point.

    Parameters
    ----------
    solution : Solution
        The solved operating point (with losses, :func:`~epicyclic.losses.solve_with_losses`).
    losses : mapping element name → ElementLosses
        The loss models (``TrainFile.losses``).

    Returns
    -------
    MeshLossTable
        Empty where no element has a mesh friction model.

    References
    ----------
    Ohlendorf 1958; ISO/TR 14179-2:2001.
    """
    rows = []
    for name, model in losses.items():
        if not model.has_mesh_model or name not in solution.elements:
            continue
        state = solution.elements[name]
        a, c = model._relative_port()
        speed = {p: (state.speeds[p] if p != "housing" else 0.0) for p in model.ports}
        relative = speed[a] - speed[c]
        for item in model.meshes:
            friction = item.friction if item.friction is not None else model.friction
            if solution.oil_viscosity is not None:  # the oil's at this point (thermal balance), not the nominal
                friction = friction_at_viscosity(friction, solution.oil_viscosity)
            torque = state.torques[item.force_port]
            eta, mu = item.efficiency(friction, torque, relative)
            if item.force_port == "first":
                power = abs(torque * speed["first"]) * _RPM
            else:
                power = abs(torque * (speed[item.force_port] - speed[c])) * _RPM
            eta, mu = float(eta), float(mu)
            rows.append(MeshLossRow(name, item.mesh.name, friction.label, mu, item.loss_factor,
                                    tooth_loss_factor_method(item.mesh), item.mesh.contact_ratio,
                                    overlap_ratio(item.mesh, item.face_width), power, (1.0 - eta) * power, eta))
    return MeshLossTable(tuple(rows))
