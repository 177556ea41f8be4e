"""Sizing: the smallest ISO 54 module meeting the minimum safeties, within a stated bound."""

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.rating import RatingError, RatingSpec, smallest_module
from epicyclic.rating.sizing import ISO_54_MODULES

SET = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99)
SPEC = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=220.0)


def solved(torque):
    return solve(GearTrain([SET, Brake("B", "r")]), OperatingPoint(speeds={"in": 1500}, torques={"in": torque},
                                                                  drives=["in"], loads=["out"]))


def test_the_found_module_is_the_first_that_passes():
    result = smallest_module(solved(300.0), "P", SPEC, face_width_ratio=0.6)
    assert result.rating.ok
    assert all(min(s_h / SPEC.S_Hmin, s_f / SPEC.S_Fmin) < 1 for m, s_h, s_f in result.tried[:-1])
    assert result.face_width == pytest.approx(0.6 * 21 * result.module)
    assert result.bound == (0.5, 50.0)


def test_more_torque_needs_a_larger_module():
    small = smallest_module(solved(100.0), "P", SPEC, face_width=30.0).module
    large = smallest_module(solved(1000.0), "P", SPEC, face_width=30.0).module
    assert large > small and large in ISO_54_MODULES


def test_no_module_within_the_bound_is_an_error():
    with pytest.raises(RatingError, match=r"no module of 0\.5 \.\.\. 1\.5 mm meets"):
        smallest_module(solved(5000.0), "P", SPEC, face_width=20.0, max_module=1.5)
    with pytest.raises(RatingError, match="face_width"):
        smallest_module(solved(100.0), "P", SPEC)
