"""The vectorised bearing loads (four unit-torque evaluations per set) against planetary_forces per case."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, PlanetarySet
from epicyclic.geometry import SetGeometry, planetary_forces
from epicyclic.rating.bearing_loads import set_loads, solution_view

SETS = {
    "simple": PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78),
    "double": PlanetarySet.double_planet("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=19,
                                         z_planet_ring=19, z_ring=90),
    "stepped": PlanetarySet.stepped("P", sun="s", ring="r", carrier="c", z_sun=24, z_planet_sun=36,
                                    z_planet_ring=18, z_ring=78),
    "two rings": PlanetarySet.two_rings("P", first="s", second="r", carrier="c", z_first=81, z_planet_first=27,
                                        z_planet_second=24, z_second=78),
}


@pytest.mark.parametrize("kind", list(SETS))
@settings(max_examples=8, deadline=None)
@given(torques=st.lists(st.tuples(st.floats(-500.0, 500.0), st.floats(-2000.0, 2000.0)), min_size=1, max_size=6),
       helix=st.sampled_from([0.0, 15.0]))
def test_set_loads_equal_planetary_forces_case_by_case(kind, torques, helix):
    # the force model is |T_s| H(sgn T_s) + |T_r| G(sgn T_r) per body (module text of bearing_loads):
    # any torques, either sign, spur and helical (axial forces), every arrangement
    pset = SETS[kind]
    train = GearTrain([pset, Brake("B", "r")])
    geometry = SetGeometry.create(pset, module=2.0, helix_angle=helix)
    t_s = np.array([t[0] for t in torques])
    t_r = np.array([t[1] for t in torques])
    loads = set_loads(train, "P", geometry, t_s, t_r)
    for k, (ts, tr) in enumerate(torques):
        view = solution_view(train, {"P": {"sun": ts, "ring": tr, "carrier": -(ts + tr)}})
        expected = planetary_forces(view, "P", geometry)
        for b, body in enumerate(expected.bodies):
            assert loads.bearing[b, k] == pytest.approx(body.bearing_force, rel=1e-9, abs=1e-9)
            assert loads.axial[b, k] == pytest.approx(body.bearing_axial, rel=1e-9, abs=1e-9)
        for role in ("sun", "ring", "carrier"):
            assert loads.central[role][k] == pytest.approx(expected.central_forces[role], rel=1e-9, abs=1e-7)
