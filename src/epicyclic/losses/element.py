"""All losses of one planetary set or gear stage, evaluated at its state (arrays of points).

:class:`ElementLosses` combines

* the mesh friction (η = Π (1 − μ H_V) over the meshes, μ given or Schlenk's),
* the planet-bearing friction (a constant factor η_bearing, SKF),
* drag torques on members (load-independent, functions of speed),

and evaluates them at arrays of the element's port speeds and torques: the
factors by source multiply into the element's η0, applied by the solver in the
direction of the rolling power (Brandenberger's rule); the drag torques act on
the members' shafts.

References
----------
Brandenberger 1952, eqs. 3' and 7 (η0 in the direction of the rolling power);
Ohlendorf 1958 (H_V); ISO/TR 14179-2:2001 (μ_mZ); SKF, *Rolling bearings*, "Friction".
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from ..geometry.set_geometry import SetGeometry
from ..geometry.stage_geometry import StageGeometry
from ..model.elements import HOUSING, GearStage
from ..model.planetary import PlanetarySet
from .bearing import PlanetBearing
from .drag import DragTorque
from .errors import LossModelError
from .friction import ConstantFriction, SchlenkFriction
from .mesh import MeshLoss, meshes_efficiency, set_meshes, stage_meshes

__all__ = ["ElementLosses", "LossState", "SOURCES", "friction_at_viscosity"]

#: Names of the loss sources, in report order.
SOURCES = ("mesh", "bearing", "drag")

Friction = ConstantFriction | SchlenkFriction


@dataclass(frozen=True, eq=False)
class LossState:
    """The losses of one element at arrays of operating points.

    Attributes
    ----------
    factors : mapping source → ndarray
        Efficiency factors (``mesh``, ``bearing``) whose product is the
        element's η0 at each point (same in both directions of power flow).
    torques : mapping shaft → ndarray
        Drag torques acting on shafts, N·m (opposing the relative speeds;
        the reactions on the housing or the other member included).
    drag_loss : ndarray
        Power lost to drag, W (≥ 0).
    friction : tuple of ndarray
        μ of each mesh (empty without a mesh model).
    """

    factors: Mapping[str, np.ndarray]
    torques: Mapping[str, np.ndarray]
    drag_loss: np.ndarray
    friction: tuple[np.ndarray, ...] = ()

    @property
    def efficiency(self) -> np.ndarray:
        """η0 = product of the factors."""
        out = np.ones_like(self.drag_loss)
        for value in self.factors.values():
            out = out * value
        return out


@dataclass(frozen=True)
class ElementLosses:
    """The loss model of one element.

    Parameters
    ----------
    element : PlanetarySet or GearStage
    meshes : tuple of MeshLoss
        The meshes in the power path (from :func:`~epicyclic.losses.mesh.set_meshes`
        or :func:`~epicyclic.losses.mesh.stage_meshes`).
    friction : ConstantFriction or SchlenkFriction, optional
        μ of the meshes; without it the element's own η0 (``stationary_efficiency``
        or ``efficiency``) is the mesh factor.
    bearing_efficiency : float, default 1.0
        η_bearing of the planet bearings (:meth:`PlanetBearing.efficiency`).
    drag : tuple of DragTorque

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> from epicyclic.geometry import SetGeometry
    >>> p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78)
    >>> model = ElementLosses.for_set(SetGeometry.create(p, module=2.0, face_width=20.0),
    ...                               friction=ConstantFriction(0.05))
    >>> state = model.evaluate({"sun": np.array([3000.0]), "ring": np.array([0.0]), "carrier": np.array([833.3])},
    ...                        {"sun": np.array([100.0]), "ring": np.array([260.0]), "carrier": np.array([-360.0])})
    >>> round(float(state.efficiency[0]), 4)  # (1 - 0.05 H_V,sun)(1 - 0.05 H_V,ring)
    0.9875
    """

    element: PlanetarySet | GearStage
    meshes: tuple[MeshLoss, ...] = ()
    friction: Friction | None = None
    bearing_efficiency: float = 1.0
    drag: tuple[DragTorque, ...] = ()
    ports: Mapping[str, str] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        element = self.element
        if isinstance(element, PlanetarySet):
            ports = {"sun": element.sun, "ring": element.ring, "carrier": element.carrier}
        elif isinstance(element, GearStage):
            ports = {"first": element.first, "second": element.second, HOUSING: HOUSING}
        else:
            raise LossModelError(
                f"ElementLosses: element must be a PlanetarySet or GearStage, got {type(element).__name__}."
            )
        owner = f"losses of {element.name!r}"
        if self.friction is not None and not isinstance(self.friction, (ConstantFriction, SchlenkFriction)):
            raise LossModelError(f"{owner}: friction must be ConstantFriction or SchlenkFriction, got {self.friction!r}.")
        if self.friction is not None and not self.meshes:
            raise LossModelError(f"{owner}: a friction model needs the meshes (give the gear geometry).")
        without = [m.mesh.name for m in self.meshes if m.friction is None]
        if self.friction is None and self.meshes and without:
            raise LossModelError(f"{owner}: mesh {without[0]!r} has no friction model; give the element's "
                                 "friction or one for every mesh.")
        for m in self.meshes:
            if m.friction is not None and not isinstance(m.friction, (ConstantFriction, SchlenkFriction)):
                raise LossModelError(f"{owner}: the friction of mesh {m.mesh.name!r} must be ConstantFriction or "
                                     f"SchlenkFriction, got {m.friction!r}.")
        eta = self.bearing_efficiency
        if isinstance(eta, bool) or not isinstance(eta, (int, float)) or not 0.0 < eta <= 1.0:
            raise LossModelError(f"{owner}: bearing_efficiency must lie in (0, 1], got {eta!r}.")
        drag = tuple(self.drag)
        for term in drag:
            if not isinstance(term, DragTorque):
                raise LossModelError(f"{owner}: drag terms must be DragTorque, got {term!r}.")
            for port in (term.member, term.relative_to):
                if port not in ports and port != HOUSING:
                    raise LossModelError(
                        f"{owner}: a drag torque acts on {port!r}, which is not a member of the element; "
                        f"members are {', '.join(p for p in ports if p != HOUSING)} (or 'housing')."
                    )
        object.__setattr__(self, "drag", drag)
        object.__setattr__(self, "meshes", tuple(self.meshes))
        object.__setattr__(self, "ports", MappingProxyType(ports))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def for_set(cls, geometry: SetGeometry, *, friction: Friction | None = None,
                bearing: PlanetBearing | None = None, drag: Sequence[DragTorque] = (),
                mesh_friction: Mapping[str, Friction] | None = None) -> ElementLosses:
        """The loss model of a planetary set from its geometry (face width needed for a friction model).

        Parameters
        ----------
        geometry : SetGeometry
            The set's gears and meshes (with face widths for a friction model).
        friction : ConstantFriction or SchlenkFriction, optional
            Mesh friction; ``None`` keeps the set's own η0 for the mesh loss.
        bearing : PlanetBearing, optional
            Planet-bearing friction, as an efficiency factor of the set.
        drag : sequence of DragTorque, default ()
            Drag torques on the set's members (N·m against their relative speeds).
        mesh_friction : mapping mesh name → friction model, optional
            Per-mesh friction (``"sun-planet"``, ``"planet-ring"``, ...): its own μ or roughness;
            the other meshes use ``friction``.

        Returns
        -------
        ElementLosses

        Raises
        ------
        LossModelError
            An unknown friction model, a drag term on a member the set does not
            have, or a bearing efficiency outside (0, 1].
        """
        meshes = _with_friction(set_meshes(geometry), mesh_friction) if (friction is not None or mesh_friction) \
            else ()
        eta_b = bearing.efficiency(geometry) if bearing is not None else 1.0
        return cls(geometry.planetary_set, meshes, friction, eta_b, tuple(drag))

    @classmethod
    def for_stage(cls, geometry: StageGeometry, *, friction: Friction | None = None,
                  drag: Sequence[DragTorque] = (), mesh_friction: Mapping[str, Friction] | None = None
                  ) -> ElementLosses:
        """The loss model of a gear stage from its geometry.

        Parameters
        ----------
        geometry : StageGeometry
            The stage's gears and meshes (with face widths for a friction model).
        friction : ConstantFriction or SchlenkFriction, optional
            Mesh friction; ``None`` keeps the stage's own efficiency.
        drag : sequence of DragTorque, default ()
            Drag torques on ``first``/``second`` (N·m against their speeds).
        mesh_friction : mapping mesh name → friction model, optional
            Per-mesh friction by mesh name (``"mesh 1 (20/31)"``, ...).

        Returns
        -------
        ElementLosses

        Raises
        ------
        LossModelError
            An unknown friction model or a drag term on a member the stage does not have.
        """
        meshes = _with_friction(stage_meshes(geometry), mesh_friction) if (friction is not None or mesh_friction) \
            else ()
        return cls(geometry.stage, meshes, friction, 1.0, tuple(drag))

    # ------------------------------------------------------------------ evaluation
    @property
    def name(self) -> str:
        return self.element.name

    @property
    def has_mesh_model(self) -> bool:
        return self.friction is not None or any(m.friction is not None for m in self.meshes)

    def _relative_port(self) -> tuple[str, str]:
        return ("sun", "carrier") if isinstance(self.element, PlanetarySet) else ("first", HOUSING)

    def evaluate(self, speeds: Mapping[str, Any], torques: Mapping[str, Any], viscosity=None) -> LossState:
        """The losses at arrays of port speeds (1/min) and port torques (N·m; torque of a shaft on the port).

        The mesh factor is Π (1 − μ H_V) over the meshes at each point's load and
        rolling speed (relative to the carrier, or to the housing for a stage), or the
        element's own η0 without a friction model; the bearing factor is constant;
        each drag torque opposes its member's speed relative to ``relative_to``.

        Parameters
        ----------
        speeds : mapping port → array_like
            Speed of each port (``sun``/``ring``/``carrier`` or ``first``/``second``), 1/min.
        torques : mapping port → array_like
            Torque of the shaft on each port, N·m (from a lossless or previous solve).
        viscosity : float or array_like, optional
            The oil's dynamic viscosity at its temperature, mPa·s (one per point): replaces the
            lubricant's of Schlenk's friction (:meth:`SchlenkFriction.at_viscosity`).

        Returns
        -------
        LossState
            Efficiency factors by source, drag torques on shafts, drag loss (W) and μ
            of each mesh.

        Raises
        ------
        LossModelError
            μ H_V ≥ 1 at some point (a load far beyond what the teeth carry).

        References
        ----------
        Ohlendorf 1958 (H_V); ISO/TR 14179-2:2001 (μ_mZ at the mesh's load and speed).
        """
        a, c = self._relative_port()
        speed = {p: np.asarray(speeds[p], dtype=float) if p != HOUSING else 0.0 for p in self.ports}
        relative = speed[a] - speed[c]
        shape = np.shape(relative)
        factors: dict[str, np.ndarray] = {}
        mus: tuple[np.ndarray, ...] = ()
        if self.has_mesh_model:
            friction, meshes = self.friction, self.meshes
            if viscosity is not None:  # Schlenk's μ at the oil's viscosity of each point, per mesh too
                at = np.broadcast_to(np.asarray(viscosity, dtype=float), shape)
                friction = friction_at_viscosity(friction, at)
                meshes = tuple(replace(m, friction=friction_at_viscosity(m.friction, at)) if m.friction is not None else m
                               for m in meshes)
            factors["mesh"], mus = meshes_efficiency(meshes, friction,
                                                     {p: np.asarray(torques[p], dtype=float) for p in self.ports
                                                      if p != HOUSING}, relative)
        else:
            own = (self.element.stationary_efficiency if isinstance(self.element, PlanetarySet)
                   else self.element.efficiency)
            factors["mesh"] = np.full(shape, own)
        if self.bearing_efficiency != 1.0:
            factors["bearing"] = np.full(shape, self.bearing_efficiency)
        shaft_torques: dict[str, np.ndarray] = {}
        drag_loss = np.zeros(shape)
        for term in self.drag:
            n_rel = speed[term.member] - (speed[term.relative_to] if term.relative_to != HOUSING else 0.0)
            n_rel = np.broadcast_to(n_rel, shape)
            magnitude = term.torque(n_rel)
            on_member = -magnitude * np.sign(n_rel)
            for port, value in ((term.member, on_member), (term.relative_to, -on_member)):
                shaft = self.ports.get(port, HOUSING)
                shaft_torques[shaft] = shaft_torques.get(shaft, np.zeros(shape)) + value
            drag_loss = drag_loss + term.loss(n_rel)
        return LossState(MappingProxyType(factors), MappingProxyType(shaft_torques), drag_loss, mus)

    def describe(self) -> dict[str, Any]:
        """Plain data for reports: the model's parts and their parameters."""
        return {
            "element": self.name,
            "friction": None if self.friction is None else self.friction.label,
            "meshes": [{"mesh": m.mesh.name, "H_V": m.loss_factor, "face_width": m.face_width,
                        "rho_C": m.curvature_radius,
                        "friction": (m.friction or self.friction).label if (m.friction or self.friction) else None}
                       for m in self.meshes],
            "bearing_efficiency": self.bearing_efficiency,
            "drag": [{"member": d.member, "relative_to": d.relative_to, "coefficients": list(d.coefficients)}
                     for d in self.drag],
        }


def _with_friction(meshes: tuple[MeshLoss, ...], mesh_friction: Mapping[str, Friction] | None) -> tuple[MeshLoss, ...]:
    """The meshes with their own friction models attached (by mesh name); an unknown name is an error."""
    if not mesh_friction:
        return meshes
    names = [m.mesh.name for m in meshes]
    unknown = [k for k in mesh_friction if k not in names]
    if unknown:
        raise LossModelError(f"mesh friction: no mesh {unknown[0]!r}; the meshes are {', '.join(map(repr, names))}.")
    return tuple(replace(m, friction=mesh_friction.get(m.mesh.name)) for m in meshes)


def friction_at_viscosity(friction, viscosity):
    """Schlenk's friction at the given oil viscosity (an array over the points); other models unchanged."""
    return friction.at_viscosity(viscosity) if isinstance(friction, SchlenkFriction) else friction
