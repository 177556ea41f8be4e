"""Every value object pickles (Dask, multiprocessing, copy.deepcopy) and stays read-only.

The objects hold read-only views (``types.MappingProxyType``), which the standard library cannot
pickle on its own: ``pickle.dumps(solve(...))`` raised ``TypeError: cannot pickle 'mappingproxy'
object`` for a Solution, an OperatingPoint, a Transmission and its analysis, a SetGeometry, a
FittingReport and PlanetaryForces.
"""

from __future__ import annotations

import copy
import pickle
from types import MappingProxyType

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import SetGeometry, check_fitting, planetary_forces
from epicyclic.transmission.library import build


def _objects():
    p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=39, z_planet=49, z_ring=137,
                            planets=4, stationary_efficiency=0.97)
    op = OperatingPoint(speeds={"in": "3000 rpm"}, torques={"in": 100}, drives=["in"], loads=["out"])
    sol = solve(GearTrain([p, Brake("B", "ring")]), op)
    geometry = SetGeometry.create(p, module=2.0, face_width=20.0)
    zf = build("zf_8hp70", stationary_efficiency=0.97)
    return {"operating point": op, "solution": sol, "geometry": geometry, "fitting": check_fitting(geometry),
            "forces": planetary_forces(sol, "P", geometry), "transmission": zf, "analysis": zf.analyze_all()}


OBJECTS = _objects()


@pytest.mark.parametrize("name", list(OBJECTS))
def test_round_trip(name):
    value = OBJECTS[name]
    again = pickle.loads(pickle.dumps(value))
    assert repr(again) == repr(value)
    assert copy.deepcopy(value).__class__ is value.__class__


def test_an_unpickled_solution_equals_the_original_and_stays_read_only():
    sol = OBJECTS["solution"]
    again = pickle.loads(pickle.dumps(sol))
    assert again == sol and again.efficiency == sol.efficiency
    assert isinstance(again.shafts, MappingProxyType) and isinstance(again.elements["P"].torques, MappingProxyType)
    with pytest.raises(TypeError, match="does not support item assignment"):
        again.shafts["in"] = None
    analysis = pickle.loads(pickle.dumps(OBJECTS["analysis"]))
    assert analysis["3"].efficiency_drive == OBJECTS["analysis"]["3"].efficiency_drive
