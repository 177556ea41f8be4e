"""Every mesh of a train: loads per planet, speeds relative to the carrier, load cycles, batches."""

import math

import numpy as np
import pytest

from epicyclic import Brake, GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import BasicRack, SetGeometry, StageGeometry
from epicyclic.io import load_train_file
from epicyclic.rating import (
    RatingError,
    RatingSpec,
    mesh_inputs,
    rate_batch,
    rate_solution,
)
from epicyclic.solver.batch import solve_batch

SPEC = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=100.0)
SET = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99, planets=3)
TRAIN = GearTrain([SET, Brake("B", "r")])
POINT = OperatingPoint(speeds={"in": 1500}, torques={"in": 600}, drives=["in"], loads=["out"])
GEOMETRY = {"P": SetGeometry.create(SET, 3.0, face_width=40.0, load_sharing=1.1)}


def test_loads_and_speeds_of_a_simple_set():
    rating = rate_solution(solve(TRAIN, POINT), GEOMETRY, SPEC)
    sun, ring = rating.mesh("P", "sun-planet"), rating.mesh("P", "planet-ring")
    d_sun = 21 * 3.0
    assert sun["F_t"] == pytest.approx(2000 * 600 / 3 / d_sun, rel=1e-9)   # per planet at the reference circle
    n_rel = 1500 - 1500 * 21 / (21 + 99)                                 # sun relative to the carrier
    assert sun["v"] == pytest.approx(math.pi * d_sun * n_rel / 60000, rel=1e-9)
    assert sun["K_gamma"] == 1.1
    # load cycles: the sun meets 3 planets per relative revolution, a planet one contact per mesh
    assert sun.gears[0]["N_L"] == pytest.approx(60 * 20000 * n_rel * 3, rel=1e-9)
    assert sun.gears[1]["N_L"] == pytest.approx(60 * 20000 * n_rel * 21 / 39, rel=1e-9)
    # the planet is an idler: reversed bending; sun and ring are not
    assert sun.gears[1]["Y_M"] == 0.7 and sun.gears[0]["Y_M"] == 1.0 and ring.gears[1]["Y_M"] == 1.0
    # the ring mesh carries the same tangential force (lossless), the ring internal
    assert ring["F_t"] * 39 * 3.0 / 2000 == pytest.approx(
        600 * 99 / 21 / 3 * 39 / 99, rel=1e-9)  # torque on the planet = T_ring/N · z_p/z_r
    assert ring.internal and ring.gears[1].gear == "ring"


def test_stage_meshes_follow_the_chain():
    stage = GearStage.from_teeth("G", "in", "mid", [(20, 40, "external"), (18, 54, "external")])
    train = GearTrain([stage])
    point = OperatingPoint(speeds={"in": 1000}, torques={"in": 100}, drives=["in"], loads=["mid"])
    geometry = {"G": StageGeometry(stage, BasicRack(2.0), face_width=25.0)}
    rating = rate_solution(solve(train, point), geometry, SPEC)
    first, second = rating.meshes
    assert first["F_t"] == pytest.approx(2000 * 100 / 40)
    assert second["F_t"] == pytest.approx(2000 * 100 * 2 / 36)              # torque × 40/20 on 18 teeth
    assert second["v"] == pytest.approx(math.pi * 36 * 500 / 60000)


def test_batch_equals_one_point_at_a_time():
    torques = np.linspace(100.0, 900.0, 5)
    batch = solve_batch(TRAIN, speeds={"in": np.full(5, 1500.0)}, torques={"in": torques}, drives=["in"],
                        loads=["out"])
    many = rate_batch(batch, GEOMETRY, SPEC)
    for k, t in enumerate(torques):
        one = rate_solution(solve(TRAIN, OperatingPoint(speeds={"in": 1500}, torques={"in": t}, drives=["in"],
                                                        loads=["out"])), GEOMETRY, SPEC)
        for mb, mo in zip(many.meshes, one.meshes):
            assert mb.S_H[k] == pytest.approx(float(mo.S_H), rel=1e-9)
            assert mb.S_F[k] == pytest.approx(float(mo.S_F), rel=1e-9)


def test_the_8hp_example_in_every_gear():
    f = load_train_file("examples/zf_8hp70_geometry.toml")
    spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=35.0)
    planned = mesh_inputs(f.geometry, spec)
    assert len(planned[0]) == 8                                            # 4 sets × (sun-planet, planet-ring)
    for gear in f.transmission.schedule:
        sol = solve(f.transmission.train_in_gear(f.train, gear), f.operating_point.__class__(
            speeds={"in": 2000}, torques={"in": 200}, drives=["in"], loads=["out"]))
        rating = rate_solution(sol, f.geometry, spec, gear=gear, planned=planned)
        assert all(np.all(np.asarray(m.S_H) > 0) for m in rating.meshes)


def test_geometry_without_face_width_is_refused():
    with pytest.raises(RatingError, match="face width"):
        mesh_inputs({"P": SetGeometry.create(SET, 3.0)}, SPEC)


def test_double_planet_set_has_three_meshes_with_one_force_and_one_velocity():
    # lossless, unshifted: every mesh carries F_t = 2000 T_sun/(N d_sun) at one pitch line velocity
    p = PlanetarySet.double_planet("D", sun="in", ring="r", carrier="out", z_sun=30, z_planet_sun=17,
                                   z_planet_ring=18, z_ring=90, planets=3)
    sol = solve(GearTrain([p, Brake("B", "out")]), OperatingPoint(speeds={"in": 1000}, torques={"in": 100},
                                                                 drives=["in"], loads=["r"]))
    rating = rate_solution(sol, {"D": SetGeometry.create(p, 2.0, face_width=20.0)}, SPEC)
    assert [m.mesh for m in rating.meshes] == ["sun-planet1", "planet1-planet2", "planet2-ring"]
    for m in rating.meshes:
        assert m["F_t"] == pytest.approx(2000 * 100 / 3 / 60, rel=1e-9)
        assert m["v"] == pytest.approx(math.pi * 60 * 1000 / 60000, rel=1e-9)
    assert [g["Y_M"] for g in rating.meshes[1].gears] == [0.7, 0.7]     # both planets are idlers


def test_internal_stage_mesh_and_a_ring_that_drives():
    # a ring (driving, 60 teeth) drives a pinion (20): gear 1 of the mesh is the pinion, its torque 1/3
    stage = GearStage.from_teeth("G", "in", "out", [(60, 20, "internal")])
    point = OperatingPoint(speeds={"in": 600}, torques={"in": 300}, drives=["in"], loads=["out"])
    rating = rate_solution(solve(GearTrain([stage]), point),
                           {"G": StageGeometry(stage, BasicRack(2.0), face_width=25.0)}, SPEC)
    (mesh,) = rating.meshes
    assert mesh.internal and [g.gear for g in mesh.gears] == ["driven", "driving"]
    assert mesh["F_t"] == pytest.approx(2000 * 300 / 120)                   # at the ring's pitch circle
    assert mesh["v"] == pytest.approx(math.pi * 120 * 600 / 60000)


def test_a_stage_takes_tip_diameters_and_tip_shortening_per_gear():
    # ISO/TR 6336-30:2017, Annex A, Example 1 as a [[gear]] stage: its printed tip diameters d_a = 159.66 and
    # 872.35 mm give the printed ε_α = 1.549 (the nominal tips 159.664/872.355 mm give 1.5495; see
    # tests/rating/test_published_examples.py).  Before, a stage took no tip per gear.
    from epicyclic.geometry import MeshGeometry

    rack = BasicRack(8.0, pressure_angle=20.0, helix_angle=15.8, addendum=1.0, dedendum=1.4)
    x1 = MeshGeometry.at_center_distance(103, 17, rack, 500.0).gear2.profile_shift
    stage = GearStage.from_teeth("G", "in", "out", [(17, 103, "external")])
    geometry = StageGeometry(stage, rack, [(x1, 0.0)], 100.0, center_distance=500.0,
                             tip_diameter=[(159.66, 872.35)])
    mesh = geometry.meshes[0]
    assert (mesh.gear1.tip_diameter, mesh.gear2.tip_diameter) == pytest.approx((159.66, 872.35), abs=1e-9)
    assert mesh.contact_ratio == pytest.approx(1.549, abs=5e-4)
    (planned,), _ = mesh_inputs({"G": geometry}, SPEC)
    assert planned.input.mesh.gear1.tip_diameter == pytest.approx(159.66)
    # per gear k (driving, driven); "none" in a file keeps a gear's own
    shortened = StageGeometry(stage, rack, [(x1, 0.0)], 100.0, tip_shortening=[(0.1, 0.0)], center_distance=500.0)
    assert shortened.meshes[0].gear1.tip_shortening == 0.1 and shortened.meshes[0].gear2.tip_shortening == 0.0
    from epicyclic.geometry import GeometryError

    with pytest.raises(GeometryError, match="lies beyond the uncut tip"):
        StageGeometry(stage, rack, [(x1, 0.0)], 100.0, tip_diameter=[(170.0, None)])
    with pytest.raises(GeometryError, match="one pair"):
        StageGeometry(stage, rack, tip_shortening=[(0.1,)])


def test_a_stage_file_takes_tip_diameters():
    from epicyclic.io import loads_train_file

    text = """
[[gear]]
name = "G"
first = "in"
second = "out"
meshes = [[20, 40, "external"], [18, 54, "external"]]
[gear.geometry]
module = 2.0
face_width = 25.0
tip_diameter = [[43.5, "none"], ["none", 110.0]]
"""
    geometry = loads_train_file(text).geometry["G"]
    assert geometry.meshes[0].gear1.tip_diameter == pytest.approx(43.5)
    assert geometry.meshes[1].gear2.tip_diameter == pytest.approx(110.0)
    assert geometry.meshes[0].gear2.tip_diameter == pytest.approx(84.0)  # uncut: 40·2 + 2·2
