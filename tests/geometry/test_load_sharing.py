"""Load-sharing factor K_γ by number of planets and mounting (issue 19)."""

from __future__ import annotations

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import SetGeometry, planetary_forces
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.load_sharing import default_load_sharing, load_sharing_factor, tabulated_load_sharing
from epicyclic.io import InputFileError, loads_train_file


@pytest.mark.parametrize(("planets", "k_gamma"), [(1, 1.0), (2, 1.0), (3, 1.10), (4, 1.25), (5, 1.35), (6, 1.44),
                                                  (7, 1.47)])
def test_iec_61400_4_table(planets, k_gamma):
    # IEC 61400-4:2012 / AGMA 6123-B06 K_gamma for a floating member, as quoted in the literature
    assert load_sharing_factor(planets) == k_gamma
    assert load_sharing_factor(planets, mounting="flexible_pins") == k_gamma  # the table is the upper bound
    assert "IEC 61400-4" in tabulated_load_sharing(planets).source


def test_abs_rules_and_limits():
    # FVA-Workbench documentation, PMID 6051 (ABS rules): up to 3 -> 1.0, 4 -> 1.2, 5 -> 1.3, 6 and more -> 1.4
    assert [load_sharing_factor(n, "abs") for n in (3, 4, 5, 6, 9)] == [1.0, 1.2, 1.3, 1.4, 1.4]
    assert [default_load_sharing(n) for n in (3, 4, 5, 6, 9)] == [1.0, 1.2, 1.3, 1.4, 1.4]
    with pytest.raises(GeometryError, match=r"1 … 7 planets, not 8; give a measured"):
        load_sharing_factor(8)
    with pytest.raises(GeometryError, match="mounting must be one of"):
        load_sharing_factor(3, "rigid")
    with pytest.raises(GeometryError, match="whole number >= 1"):
        load_sharing_factor(0)


def _solved(planets: int = 4, load_sharing=None):
    p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                            planets=planets)
    geometry = SetGeometry.create(p, module=2, load_sharing=load_sharing)
    solution = solve(GearTrain([p, Brake("B", "ring")]),
                     OperatingPoint(speeds={"in": 1000.0}, torques={"in": 100.0}, drives=["in"], loads=["out"]))
    return solution, geometry


def test_forces_state_the_source_beside_the_users_value():
    solution, geometry = _solved(4, 1.15)
    forces = planetary_forces(solution, "P", geometry)
    assert forces.load_sharing_factor == 1.15
    assert forces.load_sharing_source == "given; IEC 61400-4:2012 / AGMA 6123-B06, floating central member: 1.25"
    assert "given; IEC 61400-4" in forces.table() and forces.to_dict()["load_sharing_source"].startswith("given")
    tabulated = planetary_forces(solution, "P", SetGeometry.create(geometry.planetary_set, module=2,
                                                                   load_sharing="floating_sun"))
    assert tabulated.load_sharing_factor == 1.25
    # the design tangential force is K_gamma times the mean per planet (F_t = 2000 T / (N d_w))
    mean = 2000 * 100.0 / (4 * geometry.sun_mesh.operating_pitch_diameters[0])
    assert tabulated.design_tangential["sun-planet"] == pytest.approx(1.25 * mean, rel=1e-9)
    default = planetary_forces(solution, "P", SetGeometry.create(geometry.planetary_set, module=2))
    assert default.load_sharing_factor == 1.2 and default.load_sharing_source.startswith("ABS rules default")


def test_file_load_sharing_by_mounting():
    text = """
[[planetary]]
name = "P"
sun = "in"
ring = "housing"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
planets = 4
[planetary.geometry]
module = 2
load_sharing = "%s"
"""
    assert loads_train_file(text % "flexible_pins").geometry["P"].load_sharing == "flexible_pins"
    with pytest.raises(InputFileError, match=r"key 'geometry.load_sharing': expected K_gamma >= 1 or a mounting"):
        loads_train_file(text % "stiff")
