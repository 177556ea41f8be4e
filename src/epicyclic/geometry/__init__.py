"""Gear geometry, fitting conditions, tooth forces and tooth-count search of planetary sets.

A :class:`~epicyclic.model.PlanetarySet` keeps tooth counts only;
:class:`SetGeometry` adds module, pressure angle, helix angle, tooth-height
factors and profile shifts.  From it: :func:`check_fitting` (coaxiality,
assembly and phasing, neighbours, undercut, internal interference),
:func:`planetary_forces` (tooth, bearing and pin forces of a solved operating
point) and :func:`search_teeth` (vectorised tooth-count search).  Lengths in
mm, angles in degrees, forces in N, torques in N·m.  See ``docs/geometry.md``.

>>> from epicyclic import PlanetarySet
>>> from epicyclic.geometry import SetGeometry, check_fitting
>>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=4)
>>> check_fitting(SetGeometry.create(p, module=2)).passed
True
"""

from .errors import FittingError, GeometryError
from .fitting import (
    AssemblyCheck,
    Check,
    CoaxialityCheck,
    FittingReport,
    InterferenceCheck,
    NeighbourCheck,
    UndercutCheck,
    assembly_ticks,
    check_assembly,
    check_coaxiality,
    check_fitting,
    check_interference,
    check_neighbours,
    max_planets,
    mesh_phasing,
)
from .forces import (MeshForce, PlanetaryForces, PlanetLoad, SharedPlanet, default_load_sharing, mesh_forces,
                     planetary_forces)
from .gear import BasicRack, GearGeometry, MeshGeometry
from .involute import inv, inv_inverse, profile_shift_sum
from .search import Candidate, ToothSearch, search_teeth, search_teeth_loops, two_shaft_ratio
from .set_geometry import SetGeometry
from .shared_planets import share_planets
from .stage_forces import StageForces, stage_forces
from .stage_geometry import StageGeometry
from .load_sharing import LoadSharing, load_sharing_factor, tabulated_load_sharing
from .tooth_counts import check_tooth_counts
from .undercut import check_undercut, min_profile_shift, undercut_limit

__all__ = [
    "AssemblyCheck", "BasicRack", "Candidate", "Check", "CoaxialityCheck", "FittingError", "FittingReport",
    "GearGeometry", "GeometryError", "InterferenceCheck", "MeshForce", "MeshGeometry", "NeighbourCheck",
    "PlanetLoad", "PlanetaryForces", "SetGeometry", "SharedPlanet", "StageForces", "StageGeometry", "ToothSearch", "UndercutCheck", "assembly_ticks",
    "check_assembly", "check_coaxiality", "check_fitting", "check_interference", "check_neighbours",
    "check_tooth_counts", "check_undercut", "default_load_sharing", "inv", "inv_inverse", "max_planets", "mesh_forces",
    "mesh_phasing", "min_profile_shift", "planetary_forces", "profile_shift_sum", "search_teeth",
    "search_teeth_loops", "share_planets", "stage_forces", "two_shaft_ratio", "undercut_limit",
    "LoadSharing", "load_sharing_factor", "tabulated_load_sharing",
]
