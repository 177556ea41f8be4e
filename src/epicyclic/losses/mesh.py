"""The meshes of a planetary set or gear stage: load, speed and efficiency from the element's state.

Each mesh of an element is loaded by the torque at one port and rolls with the
element's relative speed (sun − carrier for a set, the first shaft for a stage):

* base-circle load per planet F_bt = 1000 |T_port| · c_F (N), with
  c_F = 1/(N r_b) for a mesh of a central gear (r_b its base radius, mm, N
  planets sharing the load equally); the planet–planet mesh of a double set
  carries the ring mesh's F_bt (planet 2 is balanced);
* pitch-line speed v_t = |n_a − n_c| · c_v (m/s), c_v = (π/30) |k| r_w/1000 with
  k the planet gear's speed factor (n_p − n_c = k (n_a − n_c)) and r_w its
  operating pitch radius in that mesh;
* sum velocity at the pitch point v_ΣC = 2 v_t sin α_wt and the normal radius of
  relative curvature ρ_C = r_w1 r_w2 sin α_wt / ((r_w2 ± r_w1) cos β_b)
  (+ external, − internal);
* mesh efficiency η = 1 − μ H_V (:mod:`~epicyclic.losses.tooth_loss`) and the
  element's η0 = Π η over the meshes in its power path.

The meshes of a stage carry the torque of the first shaft times the ratios of
the meshes before them and turn at the first shaft's speed times those ratios.

References
----------
Queitsch part I, eqs. (23)–(25) (F_t = 2000 M/d per planet); ISO 21771:2007 (r_b, r_w, α_wt, β_b);
ISO/TR 14179-2:2001 (v_ΣC, ρ_C, F_bt/b in μ_mZ); Brandenberger 1952 (η0 = η1 η2 of the meshes).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from ..geometry.gear import MeshGeometry
from ..geometry.set_geometry import SetGeometry
from ..geometry.stage_geometry import StageGeometry
from ..results.solution import RPM_TO_RAD_S
from .errors import LossModelError
from .tooth_loss import base_helix_angle, tooth_loss_factor

__all__ = ["MeshLoss", "set_meshes", "stage_meshes", "meshes_efficiency"]


@dataclass(frozen=True)
class MeshLoss:
    """One mesh of an element with the factors that turn the element's state into its load and speed.

    Attributes
    ----------
    mesh : MeshGeometry
    face_width : float
        b, mm.
    force_port : str
        The port whose torque loads the mesh (``sun``, ``ring``, ``first``).
    force_factor : float
        F_bt (N, per planet) per N·m at ``force_port``.
    speed_factor : float
        Pitch-line speed v_t (m/s) per 1/min of the element's relative speed.
    loss_factor : float
        Ohlendorf's H_V.
    curvature_radius : float
        ρ_C, mm.
    friction : ConstantFriction or SchlenkFriction, optional
        This mesh's own friction model (its μ or its flanks' roughness); None takes
        the element's.
    """

    mesh: MeshGeometry
    face_width: float
    force_port: str
    force_factor: float
    speed_factor: float
    loss_factor: float
    curvature_radius: float
    friction: object = None

    @classmethod
    def create(cls, mesh: MeshGeometry, face_width: float, force_port: str, base_radius: float, shares: int,
               pitch_radius: float, speed_ratio: float) -> MeshLoss:
        """From the gear loaded at ``force_port`` (base radius, mm) and the gear turning at ``speed_ratio``.

        F_bt = 1000 T / (N r_b) per N·m at ``force_port``; v_t = ω r_w with ω =
        ``speed_ratio`` × the element's relative speed; ρ_C = r_w1 r_w2 sin α_wt /
        ((r_w2 ± r_w1) cos β_b) (− for an internal mesh).

        Parameters
        ----------
        mesh : MeshGeometry
            The mesh.
        face_width : float
            b, mm.
        force_port : str
            The port whose torque loads the mesh (``sun``, ``ring``, ``first``).
        base_radius : float
            Base radius of the gear on ``force_port`` (or the gear its torque reaches), mm.
        shares : int
            Number of planets (paths) that share the torque; 1 for a stage.
        pitch_radius : float
            Operating pitch radius of the gear whose speed gives the pitch-line speed, mm.
        speed_ratio : float
            That gear's speed per 1/min of the element's relative speed.

        Returns
        -------
        MeshLoss

        References
        ----------
        Queitsch part I, eqs. (23)–(25); ISO/TR 14179-2:2001 (v_ΣC, ρ_C, F_bt/b).
        """
        r_w1, r_w2 = (d / 2.0 for d in mesh.operating_pitch_diameters)
        sin_a = math.sin(mesh.alpha_wt)
        span = r_w2 - r_w1 if mesh.internal else r_w2 + r_w1
        rho = r_w1 * r_w2 * sin_a / (span * math.cos(base_helix_angle(mesh)))
        return cls(mesh, float(face_width), force_port, 1000.0 / (shares * base_radius),
                   RPM_TO_RAD_S * abs(speed_ratio) * pitch_radius / 1000.0, tooth_loss_factor(mesh), rho)

    def operating_state(self, torque, relative_speed):
        """(F_bt/b in N/mm, v_ΣC in m/s) for arrays of port torque (N·m) and relative speed (1/min).

        v_ΣC = 2 v_t sin α_wt (sum of the tangential velocities at the pitch point).

        Parameters
        ----------
        torque : array_like
            Torque at ``force_port``, N·m (sign ignored).
        relative_speed : array_like
            The element's speed relative to its carrier (housing for a stage), 1/min.

        Returns
        -------
        tuple of numpy.ndarray
            (load per face width N/mm, sum velocity m/s).

        References
        ----------
        ISO/TR 14179-2:2001 (F_bt/b and v_ΣC in μ_mZ).
        """
        load = self.force_factor * np.abs(np.asarray(torque, dtype=float)) / self.face_width
        sum_velocity = 2.0 * self.speed_factor * np.abs(np.asarray(relative_speed, dtype=float)) \
            * math.sin(self.mesh.alpha_wt)
        return load, sum_velocity

    def efficiency(self, friction, torque, relative_speed):
        """η = 1 − μ H_V with μ from ``friction`` at this load and speed (arrays).

        Parameters
        ----------
        friction : ConstantFriction or SchlenkFriction
            The friction model (μ from load per width, sum velocity, ρ_C).
        torque : array_like
            Torque at ``force_port``, N·m.
        relative_speed : array_like
            The element's relative speed, 1/min.

        Returns
        -------
        tuple of numpy.ndarray
            (η of the mesh, μ).

        References
        ----------
        Ohlendorf 1958 (P_loss = μ H_V P_in); ISO/TR 14179-2:2001.

        Raises
        ------
        LossModelError
            μ H_V ≥ 1 (or not finite) somewhere: a load per face width beyond any gear, for which the
            friction correlation gives no efficiency.
        """
        load, sum_velocity = self.operating_state(torque, relative_speed)
        mu = friction.coefficient(load, sum_velocity, self.curvature_radius)
        loss = np.asarray(mu * self.loss_factor)
        bad = ~(loss < 1.0)  # also NaN
        if np.any(bad):
            k = np.flatnonzero(bad.ravel())[0]
            raise LossModelError(
                f"mesh {self.mesh.name}: the coefficient of friction {np.ravel(mu)[k]:.4g} (load "
                f"{np.ravel(np.broadcast_to(load, bad.shape))[k]:.4g} N/mm per face width) times H_V "
                f"{self.loss_factor:.4g} leaves no efficiency (μ·H_V >= 1): the torque is far beyond what these "
                "teeth carry; check the operating torques and the face width."
            )
        return 1.0 - loss, mu


def _planet_pitch_radius(mesh: MeshGeometry, planet_is_gear1: bool) -> float:
    return mesh.operating_pitch_diameters[0 if planet_is_gear1 else 1] / 2.0


def set_meshes(geometry: SetGeometry) -> tuple[MeshLoss, ...]:
    """The meshes of a planetary set in its power path (sun side first).

    Raises
    ------
    GeometryError
        The geometry has no face width.
    """
    pset = geometry.planetary_set
    teeth = pset.teeth
    n = pset.planets
    k = teeth.planet_factors  # type: ignore[union-attr]
    gears = geometry.gears
    names = geometry.planet_gear_names
    out = []
    for mesh in geometry.meshes:
        a, b = geometry.mesh_gears(mesh)
        width = geometry.mesh_face_width(mesh.name)
        planet = b if a == "sun" else a  # every mesh of a set involves a planet gear
        # the internal gear of a mesh is its gear 2: a planet is gear 1 unless it meshes an external sun
        planet_is_gear1 = gears["sun"].internal if a == "sun" else True
        speed = k[names.index(planet)] if teeth.kind == "double" else k[0]  # type: ignore[union-attr]
        if a == "sun":
            port, base = "sun", gears["sun"].base_diameter / 2
        else:  # planet–ring, or planet1–planet2 (loaded like the ring mesh)
            port, base = "ring", gears["ring"].base_diameter / 2
        out.append(MeshLoss.create(mesh, width, port, base, n, _planet_pitch_radius(mesh, planet_is_gear1), speed))
    return tuple(out)


def stage_meshes(geometry: StageGeometry) -> tuple[MeshLoss, ...]:
    """The meshes of a gear stage, from the first shaft to the second."""
    out = []
    torque_ratio = 1.0  # |T at the driving gear of mesh k| / |T_first|
    speed_ratio = 1.0  # |n of the driving gear of mesh k| / |n_first|
    for index, ((z1, z2, _kind), mesh) in enumerate(zip(geometry.stage.meshes, geometry.meshes)):
        driving = mesh.gear1 if geometry.driving_is_gear1(index) else mesh.gear2
        r_w = mesh.operating_pitch_diameters[0 if geometry.driving_is_gear1(index) else 1] / 2.0
        item = MeshLoss.create(mesh, geometry.mesh_face_width(index), "first", driving.base_diameter / 2, 1,
                               r_w, speed_ratio)
        out.append(replace(item, force_factor=item.force_factor * torque_ratio))
        torque_ratio *= z2 / z1
        speed_ratio *= z1 / z2
    return tuple(out)


def meshes_efficiency(meshes: tuple[MeshLoss, ...], friction, torques: Mapping[str, np.ndarray],
                      relative_speed) -> tuple[np.ndarray, tuple[np.ndarray, ...]]:
    """η of the power path (product over the meshes) and μ per mesh, for arrays of the element's state.

    A mesh with its own friction model (:attr:`MeshLoss.friction`) uses it; the others use ``friction``.
    """
    eta = np.ones(np.shape(relative_speed))
    mus = []
    for item in meshes:
        e, mu = item.efficiency(item.friction if item.friction is not None else friction,
                                torques[item.force_port], relative_speed)
        eta = eta * e
        mus.append(mu)
    return eta, tuple(mus)
