"""Tooth forces and bearing loads: published helical example and equilibrium against the solver."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.forces import default_load_sharing, mesh_forces, planetary_forces
from epicyclic.geometry.gear import BasicRack, MeshGeometry
from epicyclic.geometry.set_geometry import SetGeometry


def test_helical_force_example_drivetrainhub():
    # Drivetrain Hub, Strength / Force Analysis (after Maitra, Handbook of Gear Design):
    # z = 15/45, m_n = 2.5, alpha_n = beta = 20 deg, a = 80 mm, T = 100 N*m on the pinion
    # -> d_w1 = 40 mm, F_t = 5000.0 N, F_r = 1971.1 N, F_a = 1819.9 N (= F_t tan beta), F_N = 5674.2 N.
    # This package takes F_a = F_t tan beta_w (helix at the operating pitch cylinder, beta_w = 20.04 deg):
    # 0.23 % above the source's tan beta value, so F_a and F_N are checked to 0.3 %.
    mesh = MeshGeometry.at_center_distance(15, 45, BasicRack(2.5, helix_angle=20), 80.0)
    ft, fr, fa = mesh_forces(100.0, mesh.operating_pitch_diameters[0], mesh)
    assert ft == pytest.approx(5000.0, abs=0.05)
    assert fr == pytest.approx(1971.1, abs=0.05)
    assert fa == pytest.approx(1819.9, rel=3e-3)
    assert math.sqrt(ft ** 2 + fr ** 2 + fa ** 2) == pytest.approx(5674.2, rel=3e-3)


def solved(kind="simple", eta=0.97, planets=3, helix=0.0, three_shaft=False):
    if kind == "simple":
        pset = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                                   stationary_efficiency=eta, planets=planets)
        geom = SetGeometry.create(pset, module=2.0, helix_angle=helix)
    elif kind == "stepped":
        pset = PlanetarySet.stepped("P", sun="in", ring="ring", carrier="out", z_sun=20, z_planet_sun=30,
                                    z_planet_ring=18, z_ring=68, stationary_efficiency=eta, planets=planets)
        geom = SetGeometry.create(pset, module=2.0, helix_angle=helix)
    else:
        pset = PlanetarySet.double_planet("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet_sun=15,
                                          z_planet_ring=16, z_ring=78, stationary_efficiency=eta, planets=planets)
        geom = SetGeometry.create(pset, module=2.0, helix_angle=helix)
    if three_shaft:
        train = GearTrain([pset])
        op = OperatingPoint(speeds={"in": 3000.0, "ring": 500.0}, torques={"in": 100.0},
                            drives=["in"], loads=["out", "ring"])
    else:
        train = GearTrain([pset, Brake("B", "ring")])
        op = OperatingPoint(speeds={"in": 3000.0}, torques={"in": 100.0}, drives=["in"], loads=["out"])
    return solve(train, op), geom


def _check_equilibrium(forces, solution, geom):
    torques = solution.elements["P"].torques
    # 1. each planet: mesh forces + pin force = 0 (in-plane), by components
    for body in forces.bodies:
        fx = sum(m.force_on_planet[0] for m in body.meshes) + body.pin_force[0]
        fy = sum(m.force_on_planet[1] for m in body.meshes) + body.pin_force[1]
        assert (fx, fy) == pytest.approx((0.0, 0.0), abs=1e-9)
    # 2. forces x radii give back the solver's central torques (force on a central gear = -force on planet)
    for gear, mesh_name in (("sun", geom.sun_mesh.name), ("ring", geom.ring_mesh.name)):
        moment = 0.0
        for body in forces.bodies:
            for m in body.meshes:
                if m.mesh == mesh_name and (gear == "sun") == (m is body.meshes[0]):
                    moment += -(m.point[0] * m.force_on_planet[1] - m.point[1] * m.force_on_planet[0]) / 1000
        assert moment + torques[gear] == pytest.approx(0.0, abs=1e-9 * max(1.0, abs(torques[gear])))
    # 3. carrier: pin forces x radii + friction moments = solver carrier torque
    assert forces.carrier_torque_from_forces == pytest.approx(torques["carrier"], rel=1e-12, abs=1e-9)
    # 4. equally spaced planets: no net force on sun, ring or carrier; torques sum to zero
    for vec in forces.central_forces.values():
        assert vec == pytest.approx((0.0, 0.0), abs=1e-8)
    assert forces.housing_torque == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("kind", ["simple", "stepped", "double"])
@pytest.mark.parametrize("eta", [1.0, 0.95])
def test_equilibrium_against_solver(kind, eta):
    solution, geom = solved(kind, eta)
    forces = planetary_forces(solution, "P", geom)
    _check_equilibrium(forces, solution, geom)
    if eta == 1.0:  # lossless: no friction moment on any planet
        assert all(abs(b.friction_moment) < 1e-9 for b in forces.bodies)
    else:
        assert any(abs(b.friction_moment) > 1e-3 for b in forces.bodies)


def test_pitch_circles_consistent_and_tangential_force_per_planet():
    # Standard simple set: r_r - r_s = 2 r_p, F_t = 2000 T / (N d) at both meshes (lossless).
    solution, geom = solved("simple", 1.0)
    (ds, dp), (dp2, dr) = (m.operating_pitch_diameters for m in geom.meshes)
    assert dr / 2 - ds / 2 == pytest.approx(2 * dp / 2) and dp == pytest.approx(dp2)
    forces = planetary_forces(solution, "P", geom, load_sharing=1.0)
    sun_mesh, ring_mesh = forces.bodies[0].meshes
    assert sun_mesh.tangential == pytest.approx(2000 * 100 / (3 * ds))
    assert ring_mesh.tangential == pytest.approx(sun_mesh.tangential)  # Queitsch eq. 24: F_u2 = F_u4
    assert sun_mesh.radial == pytest.approx(sun_mesh.tangential * math.tan(math.radians(20)))
    assert forces.bodies[0].bearing_load == pytest.approx(2 * sun_mesh.tangential)  # radials cancel, F_u5 = -2 F_u2


def test_three_shaft_operation_no_housing_reaction():
    # Queitsch eq. 26: M2 + M4 + M5 = 0 in three-shaft operation, no reaction on the housing.
    solution, geom = solved("simple", 0.97, three_shaft=True)
    forces = planetary_forces(solution, "P", geom)
    _check_equilibrium(forces, solution, geom)
    assert solution.elements["P"].speeds["ring"] != 0.0


def test_load_sharing_and_helical_axial():
    solution, geom = solved("simple", 1.0, planets=4, helix=15.0)
    forces = planetary_forces(solution, "P", geom)
    assert forces.load_sharing_factor == 1.2  # default for 4 planets
    nominal = forces.bodies[0].meshes[0].tangential
    assert forces.design_tangential["sun-planet"] == pytest.approx(1.2 * nominal)
    assert forces.design_bearing_load == pytest.approx(1.2 * forces.bodies[0].bearing_load)
    m = forces.bodies[0].meshes[0]
    assert m.axial == pytest.approx(m.tangential * math.tan(math.radians(geom.sun_mesh.operating_helix_angle)))
    assert forces.bodies[0].bearing_axial == pytest.approx(0.0, abs=1e-9)  # equal, opposite mesh thrusts
    text = forces.table()
    assert "K_gamma = 1.2" in text and "<table>" in forces._repr_html_() and "PlanetaryForces" in repr(forces)
    assert forces.to_dict()["units"]["force"] == "N"


def test_unequal_spacing_leaves_net_radial_force_on_sun():
    solution, geom = solved("simple", 1.0)
    forces = planetary_forces(solution, "P", geom, angles=[0.0, 100.0, 240.0])
    _, _ = forces.central_forces["sun"]
    assert math.hypot(*forces.central_forces["sun"]) > 1.0
    assert forces.housing_torque == pytest.approx(0.0, abs=1e-9)


@settings(max_examples=25, deadline=None)
@given(st.floats(-500, 500).filter(lambda t: abs(t) > 1e-3), st.sampled_from([0.9, 0.97, 1.0]),
       st.integers(2, 6))
def test_equilibrium_invariant(torque, eta, planets):
    pset = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                               stationary_efficiency=eta, planets=planets)
    train = GearTrain([pset, Brake("B", "ring")])
    solution = solve(train, OperatingPoint(speeds={"in": 1500.0}, torques={"in": torque}, drives=["in"],
                                           loads=["out"]))
    geom = SetGeometry.create(pset, module=3.0, helix_angle=10.0)
    _check_equilibrium(planetary_forces(solution, "P", geom), solution, geom)


def test_default_load_sharing_and_errors():
    assert [default_load_sharing(n) for n in (1, 3, 4, 5, 6, 9)] == [1.0, 1.0, 1.2, 1.3, 1.4, 1.4]
    with pytest.raises(GeometryError, match="planets must be a whole number"):
        default_load_sharing(0)
    solution, geom = solved("simple", 1.0)
    with pytest.raises(GeometryError, match="has no element 'Q'"):
        planetary_forces(solution, "Q", geom)
    with pytest.raises(GeometryError, match="is a brake, not a planetary set"):
        planetary_forces(solution, "B", geom)
    with pytest.raises(GeometryError, match="load_sharing .* must be a number >= 1"):
        planetary_forces(solution, "P", geom, load_sharing=0.8)
    other = SetGeometry.create(PlanetarySet.simple("P", sun="a", ring="b", carrier="c", z_sun=20, z_planet=20,
                                                   z_ring=60), module=2)
    with pytest.raises(GeometryError, match="build SetGeometry from the same PlanetarySet"):
        planetary_forces(solution, "P", other)
    with pytest.raises(GeometryError, match="pitch_diameter must be > 0"):
        mesh_forces(1.0, 0.0, geom.sun_mesh)


def test_arguments_in_the_wrong_place_are_named():
    # regression: planetary_forces(sol, geometry, "P") raised "unhashable type: 'mappingproxy'",
    # planetary_forces(sol, "P", planetary_set) an AttributeError
    from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
    from epicyclic.geometry import GeometryError, SetGeometry, planetary_forces

    p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78)
    g = SetGeometry.create(p, module=2.0)
    sol = solve(GearTrain([p, Brake("B", "ring")]),
                OperatingPoint(speeds={"in": 3000}, torques={"in": 100}, drives=["in"], loads=["out"]))
    for args, match in [((sol, g, "P"), "set_name must be a str, got a SetGeometry"),
                        ((sol, "P", p), "geometry must be a SetGeometry, got a PlanetarySet"),
                        ((g, "P", sol), "solution must be a Solution, got a SetGeometry")]:
        with pytest.raises(GeometryError, match=f"planetary_forces: {match}"):
            planetary_forces(*args)
